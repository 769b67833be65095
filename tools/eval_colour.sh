#!/usr/bin/env bash
# The colour table of `make eval` (issue 17): RGB-PSNR of the four methods on the colour images
# (../shared/images/color: Kodak kodim01-06, house) at 0.5, 1 and 2%, the ERD gains, and ERDGPI
# against "mesh the luma, then fit the colours" (ColourChoices::greedy_on_luma). Runs
# tools/eval_colour.cpp (the library, channel by channel reconstruction) until the erd program
# reads colour. Every mesh is verified (eval_colour --verify). CHOICES=1 also measures the alternatives of docs/DECISIONS.md "Colour methods"
# (at 1%; the edge detector's input and the flips at every density), written to
# out/eval/colour_choices.txt with the defaults' rows, not to RESULTS.md.
# Usage: tools/eval_colour.sh BUILD_DIR IMAGES_DIR
set -u
BUILD=${1:-build}
IMAGES=${2:-../shared/images}
JOBS=${JOBS:-2}
[[ $BUILD != /* ]] && BUILD=$PWD/$BUILD
[[ $IMAGES != /* ]] && IMAGES=$PWD/$IMAGES
cd "$(dirname "$0")/.."
source tools/results_section.sh
OUT=out/eval
RESULTS=docs/RESULTS.md
mkdir -p "$OUT"
EVAL=$BUILD/eval_colour
if [[ ! -f $BUILD/liberd.a ]]; then echo "eval_colour: $BUILD/liberd.a is not built"; exit 1; fi
${CXX:-g++} -O2 -std=c++17 -I. tools/eval_colour.cpp "$BUILD/liberd.a" -o "$EVAL" || { echo "eval_colour: tools/eval_colour.cpp did not build"; exit 1; }
imgs=()
for f in "$IMAGES"/color/*.ppm; do [[ -f $f ]] && imgs+=("$(basename "$f" .ppm)"); done
if [[ ${#imgs[@]} -eq 0 ]]; then echo "eval_colour: no colour images in $IMAGES/color"; exit 1; fi

# One case "VARIANT IMAGE DENSITY" -> "VARIANT IMAGE DENSITY PSNR N".
run_case() {
    local v=$1 img=$2 d=$3 m=${1%%+*} flags=()
    case $v in
        *+luma) flags=(--luma-greedy) ;;
        *+sum) flags=(--sum-channels) ;;
        *+dmax) flags=(--density max) ;;
        *+dluma) flags=(--density luma) ;;
        *+shared) flags=(--shared) ;;
        *+nofit) flags=(--fit 0) ;;
        *+noflips) flags=(--flips 0) ;;
        *+dizenzo) flags=(--edges dizenzo) ;;
        *+emax) flags=(--edges max) ;;
    esac
    echo "$v $img $d $("$EVAL" --verify "${flags[@]}" "$m" "$d" "$IMAGES/color/$img.ppm" 2>/dev/null || echo "failed -")"
}
export -f run_case
export EVAL IMAGES
cases=()
# The removal methods of issue 45 (tools/eval.sh "Every method"): METHODS45= (empty) leaves them out.
METHODS45=${METHODS45-gpr gprfs id erdgpr}
for v in gpi ed erdgpi erded erdgpi+luma $METHODS45; do
    for img in "${imgs[@]}"; do for d in 0.5 1 2; do cases+=("$v $img $d"); done; done
done
echo "eval_colour: ${#cases[@]} cases, $JOBS at a time"
printf '%s\n' "${cases[@]}" | xargs -P "$JOBS" -L 1 bash -c 'run_case "$@"' _ >"$OUT/colour_raw.txt"
if [[ ${CHOICES:-0} == 1 ]]; then
    cases=()
    for v in gpi+sum erdgpi+sum ed+dmax ed+dluma erded+dmax erded+dluma erdgpi+shared erded+shared erdgpi+nofit erded+nofit; do
        for img in "${imgs[@]}"; do cases+=("$v $img 1"); done
    done
    # The edge detector's input and the flips at every density.
    for v in erdgpi+dizenzo erded+dizenzo erdgpi+emax erded+emax erdgpi+noflips erded+noflips; do
        for img in "${imgs[@]}"; do for d in 0.5 1 2; do cases+=("$v $img $d"); done; done
    done
    printf '%s\n' "${cases[@]}" | xargs -P "$JOBS" -L 1 bash -c 'run_case "$@"' _ >"$OUT/colour_choices.txt"
    cat "$OUT/colour_raw.txt" >>"$OUT/colour_choices.txt"
fi

# Median of column 1 of stdin.
median() { sort -g | awk '{ v[NR] = $1 } END { if (NR) printf "%+.2f", (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
section=$OUT/colour_section.md
{
    echo "<!-- colour: written by tools/eval_colour.sh -->"
    echo "## Colour (issue 17): RGB-PSNR on the colour images"
    echo
    echo "RGB-PSNR in dB: the MSE averaged over the three channels and all pixels, peak 255, of the"
    echo "reconstruction (ERD models 4x4 supersampled). One mesh and one set of constrained edges for"
    echo "the three channels, a value per channel at each vertex or wedge; erd defaults. \"luma mesh\""
    echo "= ERDGPI's greedy loop on the luma, then every wedge given its colour values and the"
    echo "least-squares refit and flips on that final mesh (the cheap alternative). The ERD methods flip"
    echo "edges on the error summed over the channels (one round, as gray)."
    echo
    echo "| image | density % | N | GPI | ERDGPI | ERDGPI - GPI | ED | ERDED | ERDED - ED | luma mesh | ERDGPI - luma mesh |"
    echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    awk '{ p[$1 " " $2 " " $3] = $4; n[$2 " " $3] = $5; k[$2 " " $3] = 1 }
         END { for (c in k) {
                 split(c, f, " ")
                 a = p["gpi " c]; b = p["erdgpi " c]; e = p["ed " c]; r = p["erded " c]; l = p["erdgpi+luma " c]
                 printf "| %s | %s | %s | %.2f | %.2f | %+.2f | %.2f | %.2f | %+.2f | %.2f | %+.2f |\n", f[1], f[2], n[c], a, b, b - a, e, r, r - e, l, b - l
               } }' "$OUT/colour_raw.txt" | sort -t'|' -k2,2 -k3,3g
    echo
    g1=$(awk '{ p[$1 " " $2 " " $3] = $4 } END { for (c in p) if (c ~ /^erdgpi /) { split(c, f, " "); print p[c] - p["gpi " f[2] " " f[3]] } }' "$OUT/colour_raw.txt" | median)
    g2=$(awk '{ p[$1 " " $2 " " $3] = $4 } END { for (c in p) if (c ~ /^erded /) { split(c, f, " "); print p[c] - p["ed " f[2] " " f[3]] } }' "$OUT/colour_raw.txt" | median)
    g3=$(awk '{ p[$1 " " $2 " " $3] = $4 } END { for (c in p) if (c ~ /^erdgpi /) { split(c, f, " "); print p[c] - p["erdgpi+luma " f[2] " " f[3]] } }' "$OUT/colour_raw.txt" | median)
    echo "Medians over the ${#imgs[@]} images x 3 densities: ERDGPI - GPI $g1 dB (target >= +2.0),"
    echo "ERDED - ED $g2 dB (target >= +3.0), ERDGPI - luma mesh $g3 dB. Meshes that verify (--verify: the"
    echo "triangulation of their points and constraints, with the flips that give their faces, is valid and"
    echo "has their faces; each wedge one value per channel):"
    echo "$(awk '$4 != "failed"' "$OUT/colour_raw.txt" | wc -l) of $(wc -l <"$OUT/colour_raw.txt")."
    if [[ -n $METHODS45 ]]; then
        echo
        echo "Every method on the colour images (issue 45): RGB-PSNR dB per image and density, the median"
        echo "of the 21 cases, and its gain over ERDGPI (531d603's default, byte-identical)."
        echo
        cols="gpi ed $METHODS45 erded erdgpi"
        printf '%s' '| image | density % |'; for v in $cols; do printf ' %s |' "$v"; done; printf '\n|---|---:|'
        for v in $cols; do printf -- '---:|'; done; echo
        awk -v cols="$cols" '{ p[$1 " " $2 " " $3] = $4; k[$2 " " $3] = 1 }
             END { n = split(cols, c, " "); for (x in k) { split(x, f, " "); line = "| " f[1] " | " f[2] " |"
                   for (i = 1; i <= n; i++) line = line " " ((c[i] " " x) in p ? sprintf("%.2f", p[c[i] " " x]) : "-") " |"
                   print line } }' "$OUT/colour_raw.txt" | sort -t'|' -k2,2 -k3,3g
        echo
        for v in $cols; do
            m=$(awk -v v="$v" '$1 == v && $4 ~ /^[0-9.]+$/ {print $4}' "$OUT/colour_raw.txt" | median | tr -d +)
            g=$(awk -v v="$v" '{ p[$1 " " $2 " " $3] = $4 } END { for (c in p) { split(c, f, " "); if (f[1] == v && ("erdgpi " f[2] " " f[3]) in p) print p[c] - p["erdgpi " f[2] " " f[3]] } }' "$OUT/colour_raw.txt" | median)
            echo "- $v: median $m dB, $g dB over ERDGPI"
        done
    fi
    echo "<!-- /colour -->"
} >"$section"
put_section colour "$section" "$RESULTS"
grep -A1 "^Medians over" "$section"
