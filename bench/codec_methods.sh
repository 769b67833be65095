#!/usr/bin/env bash
# make codec-methods: erd's default ERD method (ERDGPR) against ERDGPI (531d603's default) as
# codecs, .erdz bits per pixel at equal PSNR (issue 45), on the 12 thesis cases and the 7 colour
# images at 1%. bench/codec.sh makes the points (METHODS="erdgpi erdgpr", no other codec is compared
# here, so CHOOSE=0), bench/codec_methods.py reads them; the table goes to docs/RESULTS.md.
# Usage: bench/codec_methods.sh [OUT]   (ERD=build/erd, IMAGES=../shared/images; RESULTS=none: no RESULTS.md)
set -eu
cd "$(dirname "$0")/.."
OUT=${1:-out/codec-methods}
COLOUR=$(for k in kodim01 kodim02 kodim03 kodim04 kodim05 kodim06 house_color; do printf '%s:1 ' $k; done)
mkdir -p "$OUT"
CASES="bull:0.125 bull:0.25 bull:0.5 bull:1 lena:0.5 lena:1 lena:2 lena:3 peppers:0.5 peppers:1 peppers:2 peppers:3 $COLOUR"
METHODS="erdgpi erdgpr" CHOOSE=0 RESULTS=none CASES=$CASES bash bench/codec.sh "$OUT" >"$OUT.log" 2>&1 ||
    { echo "codec-methods: bench/codec.sh failed (see $OUT.log)"; exit 1; }
python3 bench/codec_methods.py "$OUT/rd.tsv" "$OUT/rows.tsv" erdgpi erdgpr >"$OUT/methods.md"
cat "$OUT/methods.md"
RESULTS=${RESULTS:-docs/RESULTS.md}
if [[ $RESULTS != none ]]; then
    sec=$OUT/section.md
    {
        echo "<!-- codec-methods: written by make codec-methods (bench/codec_methods.sh) -->"
        echo "## ERDGPR against ERDGPI as codecs: .erdz bits per pixel at equal PSNR (issue 45)"
        echo
        echo "Written by \`make codec-methods\` on $(date -u '+%Y-%m-%d %H:%M') UTC, commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)."
        echo "Both methods at their defaults, written as .erdz at steps 1 .. 32 as in \`make codec-bench\`. Each row: ERDGPI's"
        echo "row of the codec table (its coarsest step within 0.25 dB of step 1), and the bpp each method needs for that PSNR on its own"
        echo "envelope over the image's densities and steps (interpolated in PSNR and log bpp)."
        echo
        cat "$OUT/methods.md"
        echo
        echo "<!-- /codec-methods -->"
    } >"$sec"
    source tools/results_section.sh
    put_section codec-methods "$sec" "$RESULTS"
fi
