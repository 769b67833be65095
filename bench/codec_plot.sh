#!/usr/bin/env bash
# PSNR against bpp per codec, one panel per image (four to a row), from bench/codec.sh's rd.tsv
# (gnuplot, PNG).
# Usage: bench/codec_plot.sh RD.tsv OUT.png
set -eu
rd=$1; out=$2
imgs=$(awk -F'\t' 'NR > 1 { print $1 }' "$rd" | awk '!seen[$0]++')
n=$(echo "$imgs" | wc -l)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for img in $imgs; do
    for codec in erd-erdgpi erd-gpi erd-choose jpeg jpeg2000 webp; do
        awk -F'\t' -v i="$img" -v c="$codec" '$1 == i && $2 == c { print $4, $5 }' "$rd" | sort -g >"$tmp/$img.$codec"
    done
done
{
    cols=$(( n < 4 ? n : 4 )); rows=$(( (n + 3) / 4 ))
    echo "set terminal pngcairo size $((480 * cols)),$((420 * rows)) font ',10'"
    echo "set output '$out'"
    echo "set multiplot layout $rows,$cols"
    echo "set logscale x; set xlabel 'bits per pixel'; set ylabel 'PSNR (dB)'; set grid; set key top left"
    for img in $imgs; do
        echo "set title '$img' noenhanced"
        echo "plot '$tmp/$img.erd-erdgpi' with points pt 7 ps 0.6 lc rgb '#c00000' title 'erd ERDGPI .erdz', \\"
        echo "     '$tmp/$img.erd-gpi' with points pt 6 ps 0.6 lc rgb '#ff7f0e' title 'erd GPI .erdz', \\"
        echo "     '$tmp/$img.erd-choose' with points pt 12 ps 0.9 lc rgb '#000000' title 'erd ERDGPI --choose-density', \\"
        echo "     '$tmp/$img.jpeg' with linespoints pt 5 ps 0.5 lc rgb '#1f77b4' title 'JPEG', \\"
        echo "     '$tmp/$img.jpeg2000' with linespoints pt 9 ps 0.6 lc rgb '#2ca02c' title 'JPEG 2000', \\"
        echo "     '$tmp/$img.webp' with linespoints pt 13 ps 0.6 lc rgb '#9467bd' title 'WebP'"
    done
    echo "unset multiplot"
} >"$tmp/plot.gp"
gnuplot "$tmp/plot.gp"
