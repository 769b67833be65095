#!/usr/bin/env bash
# The browser test of web/ (a stage of tests/run_all.sh): builds erd as WebAssembly (make web),
# drives Debian's chromium with playwright-core (web/test/page_test.mjs) through the page on two
# images at 1% with erdgpi, and compares what the page shows and offers with the native erd's for
# the same PNG file:
# - gray: lena with two of the form's ERD flags off their defaults (edges hard, wedge fit 3: the
#   flags reach the library; hard edges take the point reconstruction);
# - colour: kodim03 (IMAGES/color/kodim03.ppm) with the defaults (soft edges: the 4x4 colour
#   reconstruction), meshed in colour as `erd generate` meshes it.
# For each: same vertex count and PSNR to 4 decimals (RGB-PSNR for colour, as `erd psnr`), the
# downloaded model the native one but for the last digit of a few doubles (|difference| <= 1e-12
# relative; the two builds' floating point differs by an ulp), the downloaded reconstruction PNG
# the native reconstruction exactly, the downloaded SVG the native `erd render --vector` of the
# page's model, and the progress bar past 90%.
#   tests/web_test.sh IMAGES_DIR [SHOT.png]   (SHOT: the page after the colour run)
# Exit: 0 same; 1 different, broken or an input missing; 77 chromium (or node/npm) missing: a
# skip, never a pass.
set -u
cd "$(dirname "$0")/.."
IMAGES=$1; SHOT=${2:-}
command -v chromium >/dev/null || { echo "SKIP: chromium not installed"; exit 77; }
command -v node >/dev/null && command -v npm >/dev/null || { echo "SKIP: node/npm not installed"; exit 77; }
for f in lena.pgm color/kodim03.ppm; do [[ -f $IMAGES/$f ]] || { echo "FAIL: $IMAGES/$f missing"; exit 1; }; done
# -j2: one em++ per source (Makefile web/build/obj), on both cores.
make -s -j2 web >/dev/null || { echo "FAIL: make web"; exit 1; }
if [[ ! -d web/node_modules/playwright-core ]]; then
    (cd web && npm ci --no-audit --no-fund >/dev/null 2>&1) || { echo "SKIP: npm ci could not install playwright-core (web/package-lock.json)"; exit 77; }
fi
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT

# The images as PNG (the page decodes PNG/JPEG with the browser), then both sides mesh that file.
# NAME SOURCE CHANNELS FLAGS (the form's ids and values, comma-separated)
cases=("lena $IMAGES/lena.pgm 1 edges=2,wedge-fit=3" "kodim03 $IMAGES/color/kodim03.ppm 3 ")
jobs=()
for c in "${cases[@]}"; do
    read -r name src _ flags <<<"$c"
    if [[ $src == *.ppm ]]; then  # erd render --over draws a colour image gray
        node web/test/ppm_png.mjs "$src" "$dir/$name.png"
    else
        build/erd generate -q -m gpi -i "$src" -n 4 -o "$dir/$name.corners.model" &&
        build/erd render "$dir/$name.corners.model" --no-edges --over "$src" -o "$dir/$name.png"
    fi || { echo "FAIL: $name.png"; exit 1; }
    cli_flags=$(tr ',' '\n' <<<"$flags" | sed -n 's/^edges=2$/--edges hard/p; s/^wedge-fit=\(.*\)/--wedge-fit \1/p' | tr '\n' ' ')
    # shellcheck disable=SC2086
    build/erd generate -q -m erdgpi -i "$dir/$name.png" -d 1 -x 1 $cli_flags -o "$dir/$name.native.erd" 2>/dev/null &&
    build/erd reconstruct "$dir/$name.native.erd" -o "$dir/$name.native.png" -q || { echo "FAIL: native erd on $name"; exit 1; }
    jobs+=("$dir/$name.png,erdgpi,1,$dir/$name.page.erd,svg=$dir/$name.page.svg,png=$dir/$name.page.png${flags:+,$flags}")
done
out=$(node web/test/page_test.mjs "${SHOT:-$dir/page.png}" "${jobs[@]}") || { echo "FAIL: $out"; exit 1; }

bad_cases=0
i=0
while read -r line; do
    read -r name _ channels flags <<<"${cases[$i]}"; i=$((i + 1))
    echo "$name $line"
    read -r _ _ vertices _ psnr _ bytes _ _ _ ms _ progress _ page_channels _ files_ms <<<"$line"
    native=$dir/$name.native.erd
    native_psnr=$(build/erd psnr "$dir/$name.png" "$dir/$name.native.png" 2>/dev/null)
    # The vertex count: the body's second line (past the header block "erd-header 1" ... "end", if any).
    native_vertices=$(awk 'NR == 1 && $1 == "erd-header" { h = 1 } h { if ($1 == "end") h = 0; next } ++n == 2 { print $1; exit }' "$native")
    echo "$name native: vertices $native_vertices psnr $native_psnr model-bytes $(wc -c <"$native") channels $channels"
    close=$(paste -d' ' <(tr -s ' \n' '\n\n' <"$dir/$name.page.erd") <(tr -s ' \n' '\n\n' <"$native") | awk '
        $1 != $2 { d = $1 - $2; if (d < 0) d = -d; m = $2 < 0 ? -$2 : $2; if (m < 1) m = 1; if (d > 1e-12 * m) bad++; else ulp++ }
        END { printf "%d %d", bad + 0, ulp + 0 }')
    read -r bad ulp <<<"$close"
    [[ $(wc -l <"$dir/$name.page.erd") == $(wc -l <"$native") ]] || bad=$((bad + 1))
    echo "$name model: $ulp values differ in the last digit, $bad tokens differ more"
    # The page's reconstruction PNG (RGBA from a canvas: erd drops the alpha) against the native one.
    recon_psnr=$(build/erd psnr "$dir/$name.native.png" "$dir/$name.page.png" 2>/dev/null)
    [[ $recon_psnr == inf ]] || { echo "FAIL: $name: the page's reconstruction PNG is not the native one (PSNR ${recon_psnr:-error})"; bad=$((bad + 1)); }
    build/erd render "$dir/$name.page.erd" --vector -o "$dir/$name.native.svg" &&
    cmp -s "$dir/$name.native.svg" "$dir/$name.page.svg" || { echo "FAIL: $name: the page's SVG is not erd render --vector of its model"; bad=$((bad + 1)); }
    if [[ $channels == 3 ]] && ! grep -q 'mix-blend-mode:screen' "$dir/$name.page.svg"; then echo "FAIL: $name: the SVG is not in colour"; bad=$((bad + 1)); fi
    [[ $page_channels == "$channels" ]] || { echo "FAIL: $name: the page meshed $page_channels channel(s), erd $channels"; bad=$((bad + 1)); }
    [[ $progress -ge 90 ]] || { echo "FAIL: $name: the progress bar reached only ${progress}%"; bad=$((bad + 1)); }
    if [[ $vertices == "$native_vertices" && $psnr == "$native_psnr" && $bad -eq 0 ]]; then
        echo "PASS: $name: the page's mesh, reconstruction and SVG are the native erd's (erdgpi 1%${flags:+ $flags}, ${channels} channel(s), ${ms} ms in the page and ${files_ms} ms for the files, progress bar to ${progress}%)"
    else
        echo "FAIL: $name: page and native erd differ"; bad_cases=$((bad_cases + 1))
    fi
done <<<"$out"
[[ $i -eq ${#cases[@]} ]] || { echo "FAIL: the page reported $i of ${#cases[@]} runs"; exit 1; }
[[ $bad_cases -eq 0 ]]
