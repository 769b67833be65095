#!/usr/bin/env bash
# make codec-bench: erd as an image codec against JPEG (cjpeg), JPEG 2000 (opj_compress) and
# WebP (cwebp), all from Debian packages (installed here with apt-get when missing).
#
# For each image and density: ERDGPI and GPI (METHODS=) make the mesh, `erd convert` writes it
# as .erdz at steps 1 .. 32 (the RD points of erd) and at the coarsest step within 0.25 dB of
# step 1's PSNR (`--step-psnr`, the table's rows). Each other codec is swept over its quality / rate, decoded,
# and measured with `erd psnr`; its bpp at erd's PSNR is interpolated linearly in (PSNR, log bpp)
# between the two sweep points around it ("<" / ">" when outside the sweep).
# For each row, erd's own search at the row's PSNR (ERDGPI --step-psnr P --choose-density, codec
# "erd-choose" in rd.tsv) adds the point a user asking erd for that quality gets.
# Outputs: OUT/rd.tsv (every point), OUT/table.md (the RESULTS.md table), OUT/rd.png (the plot).
# Usage: bench/codec.sh [OUT]   (ERD=build/erd, IMAGES=../shared/images, CASES="bull:0.125 ...",
# REUSE=1 keeps the JPEG / JPEG 2000 / WebP sweeps already in OUT/rd.tsv)
set -eu
cd "$(dirname "$0")/.."
ERD=${ERD:-build/erd}
IMAGES=${IMAGES:-../shared/images}
OUT=${1:-out/codec}
COLOUR_CASES=$(for k in kodim01 kodim02 kodim03 kodim04 kodim05 kodim06 house_color; do printf '%s:0.25 %s:0.5 %s:1 %s:2 ' $k $k $k $k; done)
CASES=${CASES:-"bull:0.125 bull:0.25 bull:0.5 bull:1 lena:0.25 lena:0.5 lena:1 lena:2 lena:3 peppers:0.25 peppers:0.5 peppers:1 peppers:2 peppers:3 $COLOUR_CASES"}
mkdir -p "$OUT/work"
need=()
command -v cjpeg >/dev/null || need+=(libjpeg-turbo-progs)
command -v opj_compress >/dev/null || need+=(libopenjp2-tools)
command -v cwebp >/dev/null || need+=(webp)
command -v gnuplot >/dev/null || need+=(gnuplot-nox)
if [[ ${#need[@]} -gt 0 ]]; then
    echo "codec-bench: installing ${need[*]}"
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${need[@]}" >/dev/null
fi
[[ -x $ERD ]] || { echo "codec-bench: $ERD not built (make build/erd)"; exit 1; }

W=$OUT/work
rd=$OUT/rd.tsv
declare -A swept
# REUSE=1: keep the other codecs' sweeps of an earlier run (they do not depend on erd).
if [[ -n ${REUSE:-} && -f $rd ]]; then
    awk -F'\t' 'NR == 1 || $2 !~ /^erd/' "$rd" >"$rd.keep"
    for img in $(awk -F'\t' 'NR > 1 && $2 == "webp" { print $1 }' "$rd.keep" | sort -u); do swept[$img]=1; done
    mv "$rd.keep" "$rd"
else
    printf "image\tcodec\tsetting\tbpp\tpsnr\n" >"$rd"
fi
psnr_of() { "$ERD" psnr "$1" "$2"; }
bits_of() { echo $(( $(stat -c %s "$1") * 8 )); }
pixels_of() { "$ERD" info --json "$1" | python3 -c 'import json,sys; j=json.load(sys.stdin); print(j["width"]*j["height"])'; }
bpp() { python3 -c "print('%.5f' % ($1 / $2))"; }

rows=$OUT/rows.tsv
: >"$rows"
for c in $CASES; do
    img=${c%%:*}; d=${c##*:}
    # A gray image at the top level, a colour one in color/ (RGB PSNR over the three channels).
    src=$IMAGES/$img.pgm; ext_img=pgm
    [[ -f $src ]] || { src=$IMAGES/color/$img.ppm; ext_img=ppm; }
    px=$(pixels_of "$src")
    if [[ -z ${swept[$img]:-} ]]; then
        swept[$img]=1
        for q in 2 4 6 8 10 12 15 20 25 30 40 50 60 70 80 90; do
            cjpeg -quality $q -optimize -outfile "$W/$img.jpg" "$src" 2>/dev/null
            djpeg -pnm -outfile "$W/$img.jpg.$ext_img" "$W/$img.jpg"
            printf "%s\tjpeg\tq%s\t%s\t%s\n" "$img" $q "$(bpp $(bits_of "$W/$img.jpg") $px)" "$(psnr_of "$src" "$W/$img.jpg.$ext_img")" >>"$rd"
        done
        for r in 400 300 200 150 100 80 60 50 40 30 20 15 10 8 6; do
            opj_compress -i "$src" -o "$W/$img.j2k" -I -r $r >/dev/null 2>&1
            opj_decompress -i "$W/$img.j2k" -o "$W/$img.j2k.$ext_img" >/dev/null 2>&1
            printf "%s\tjpeg2000\tr%s\t%s\t%s\n" "$img" $r "$(bpp $(bits_of "$W/$img.j2k") $px)" "$(psnr_of "$src" "$W/$img.j2k.$ext_img")" >>"$rd"
        done
        for q in 0 2 5 10 15 20 30 40 50 60 70 80 90; do
            cwebp -quiet -q $q -m 6 "$src" -o "$W/$img.webp"
            dwebp -quiet "$W/$img.webp" -ppm -o "$W/$img.webp.ppm"
            # WebP decodes to RGB; a gray source comes back with R = G = B up to rounding: keep G.
            [[ $ext_img == pgm ]] && python3 - "$W/$img.webp.ppm" "$W/$img.webp.pgm" <<'PY'
import sys
d = open(sys.argv[1], 'rb').read()
magic, size, maxval, body = d.split(b'\n', 3)
w, h = map(int, size.split())
open(sys.argv[2], 'wb').write(b'P5\n%d %d\n255\n' % (w, h) + body[1: 3 * w * h: 3])
PY
            printf "%s\twebp\tq%s\t%s\t%s\n" "$img" $q "$(bpp $(bits_of "$W/$img.webp") $px)" "$(psnr_of "$src" "$W/$img.webp.$ext_img")" >>"$rd"
        done
    fi
    for meth in ${METHODS:-erdgpi gpi}; do
        ext=erd; [[ $meth == gpi || $meth == ed ]] && ext=model
        base=$W/$img-$d-$meth
        "$ERD" generate -q --method $meth -i "$src" -d "$d" -o "$base.$ext"
        for s in 1 2 3 4 6 8 11 16 23 32; do
            "$ERD" convert -q "$base.$ext" "$base-s$s.erdz" --step $s
            "$ERD" reconstruct "$base-s$s.erdz" -o "$base-s$s.$ext_img"
            printf "%s\terd-%s\td%s-s%s\t%s\t%s\n" "$img" $meth "$d" $s "$(bpp $(bits_of "$base-s$s.erdz") $px)" \
                "$(psnr_of "$src" "$base-s$s.$ext_img")" >>"$rd"
        done
        p1=$(psnr_of "$src" "$base-s1.$ext_img")
        target=$(python3 -c "print('%.4f' % ($p1 - 0.25))")
        "$ERD" convert -q "$base.$ext" "$base.erdz" --step-psnr "$target" -i "$src"
        "$ERD" reconstruct "$base.erdz" -o "$base.$ext_img"
        "$ERD" info --json "$base.erdz" >"$base.json"
        row_psnr=$(psnr_of "$src" "$base.$ext_img")
        # erd's own answer at the row's PSNR (CHOOSE=0: none): ERDGPI with --step-psnr and
        # --choose-density, the point count traded against the step by erd's search rather than
        # read off the grid above; a file written and measured like the others.
        chosen=-
        if [[ ${CHOOSE:-1} != 0 ]] &&
            "$ERD" generate -v --method erdgpi -i "$src" --step-psnr "$row_psnr" --choose-density -o "$base-cd.erdz" >"$base-cd.log" 2>&1; then
            cd_d=$(sed -n 's/.*erdz: density \([0-9.]*\)% .*/\1/p' "$base-cd.log" | tail -1)
            cd_s=$("$ERD" info --json "$base-cd.erdz" | python3 -c 'import json,sys; print("%g" % json.load(sys.stdin)["step"])')
            "$ERD" reconstruct "$base-cd.erdz" -o "$base-cd.$ext_img"
            cd_bpp=$(bpp $(bits_of "$base-cd.erdz") $px)
            cd_psnr=$(psnr_of "$src" "$base-cd.$ext_img")
            printf "%s\terd-choose\td%s-s%s\t%s\t%s\n" "$img" "$cd_d" "$cd_s" "$cd_bpp" "$cd_psnr" >>"$rd"
            chosen="d$cd_d-s$cd_s:$cd_bpp:$cd_psnr"
        fi
        printf "%s\t%s\t%s\t%s\t%s\t%s\n" "$img" "$d" $meth "$row_psnr" "$base.json" "$chosen" >>"$rows"
    done
done

python3 bench/codec_table.py "$rd" "$rows" >"$OUT/table.md"
cat "$OUT/table.md"
bash bench/codec_plot.sh "$rd" "$OUT/rd.png"
# docs/RESULTS.md's codec section and the plot in docs/img (RESULTS=none: neither).
RESULTS=${RESULTS:-docs/RESULTS.md}
if [[ $RESULTS != none ]]; then
    cp "$OUT/rd.png" docs/img/codec_rd.png
    sec=$OUT/section.md
    {
        echo "<!-- codec: written by make codec-bench (bench/codec.sh) -->"
        echo "## erd as a codec: bits per pixel at equal PSNR"
        echo
        echo "Written by \`make codec-bench\` on $(date -u '+%Y-%m-%d %H:%M') UTC, commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown);"
        echo "$(cjpeg -version 2>&1 | head -1 | sed 's/ (build.*//'), OpenJPEG $(opj_compress -h 2>&1 | grep -o 'openjp2 library v[0-9.]*' | head -1 | sed 's/.* v//'), cwebp $(cwebp -version 2>&1 | head -1)."
        echo "erd: ERDGPI and GPI (default options, so ERDGPI with its data-dependent flips) at the thesis's densities and 0.25% (the colour images at 0.25-2%, PSNR over the three channels) written as .erdz at the coarsest step on"
        echo "the grid 2^(i/4) within 0.25 dB of step 1 (\`erd convert --step-psnr\`); PSNR of its reconstruction"
        echo "(4x4 supersampled). The other codecs at that PSNR: JPEG \`cjpeg -optimize\` (quality 2-90),"
        echo "JPEG 2000 \`opj_compress -I -r\` (the irreversible 9/7 wavelet, JPEG 2000's lossy one; without -I OpenJPEG takes the reversible 5/3, 0.9-1.4 dB lower on bull at equal size; ratio 6-400, .j2k codestream), WebP \`cwebp -m 6\` (quality 0-90),"
        echo "interpolated in (PSNR, log bpp) between the sweep points around it; \"<x\": the codec's lowest setting"
        echo "already beats the PSNR at x bpp, \">x\": its highest does not reach it. (erd +N%) = erd's bpp relative to that codec's (negative: erd smaller). erd envelope: the cheapest erd point at that PSNR over both methods, all densities and steps (interpolated); the next column names the cheapest measured point that reaches it (the point count traded against the step). erd's search: the file \`erd generate -m erdgpi --step-psnr P --choose-density\` writes for the row's PSNR P (density and step its choice), measured like the others; it is one of the envelope's points."
        echo
        cat "$OUT/table.md"
        echo
        echo "![PSNR against bpp](img/codec_rd.png)"
        echo
        echo "<!-- /codec -->"
    } >"$sec"
    source tools/results_section.sh
    put_section codec "$sec" "$RESULTS"
fi
echo "codec-bench: $OUT/table.md, $OUT/rd.tsv, $OUT/rd.png"
