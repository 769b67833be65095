#!/usr/bin/env bash
# The browser test of web/ (a stage of tests/run_all.sh): builds erd as WebAssembly (make web),
# drives Debian's chromium with playwright-core (web/test/page_test.mjs) through one visit to the
# page, and compares every mesh the page shows and offers with the native erd's for the same PNG:
# - opening: the built-in picture, meshed with no user action (erdgpi 0.5%, colour);
# - slider: one keyboard step of the density slider (0.6%): a new vertex count;
# - drop: lena dropped on the picture, 1%, with two of the form's ERD flags off their defaults
#   (edges hard, wedge fit 3: the flags reach the library; hard edges take the point
#   reconstruction);
# - file: kodim03 (IMAGES/color/kodim03.ppm) through the file chooser, 1%, the defaults (soft
#   edges: the 4x4 colour reconstruction), meshed in colour as `erd generate` meshes it;
# - paste: the opening picture pasted, 0.5%.
# For each: same vertex count and PSNR to 4 decimals (RGB-PSNR for colour, as `erd psnr`), the
# downloaded model the native one but for the last digit of a few doubles (|difference| <= 1e-12
# relative; the two builds' floating point differs by an ulp), the downloaded reconstruction PNG
# the native reconstruction exactly, the downloaded SVG the native `erd render --vector` of the
# page's model, and the progress bar past 90%. The page test itself checks the rest (a running job
# cancelled, the error line for a file that is not an image, zoom keys, labels, 390 px width) and
# takes the screenshots.
#   tests/web_test.sh IMAGES_DIR [SHOTS_DIR]   (SHOTS_DIR: web-1280.png and web-390.png; make web-shots)
# Exit: 0 same; 1 different, broken or an input missing; 77 chromium (or node/npm) missing: a
# skip, never a pass.
set -u
cd "$(dirname "$0")/.."
IMAGES=$1; SHOTS=${2:-}
command -v chromium >/dev/null || { echo "SKIP: chromium not installed"; exit 77; }
command -v node >/dev/null && command -v npm >/dev/null || { echo "SKIP: node/npm not installed"; exit 77; }
for f in lena.pgm color/kodim03.ppm; do [[ -f $IMAGES/$f ]] || { echo "FAIL: $IMAGES/$f missing"; exit 1; }; done
# -j2: one em++ per source (Makefile web/build/obj), on both cores.
make -s -j2 web >/dev/null || { echo "FAIL: make web"; exit 1; }
if [[ ! -d web/node_modules/playwright-core ]]; then
    (cd web && npm ci --no-audit --no-fund >/dev/null 2>&1) || { echo "SKIP: npm ci could not install playwright-core (web/package-lock.json)"; exit 77; }
fi
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
[[ -n $SHOTS ]] || SHOTS=$dir

# The inputs as PNG (the page decodes PNG/JPEG with the browser): lena drawn gray by erd render
# --over, kodim03 by web/test/ppm_png.mjs (erd render --over draws a colour image gray).
build/erd generate -q -m gpi -i "$IMAGES/lena.pgm" -n 4 -o "$dir/corners.model" &&
build/erd render "$dir/corners.model" --no-edges --over "$IMAGES/lena.pgm" -o "$dir/lena.png" &&
node web/test/ppm_png.mjs "$IMAGES/color/kodim03.ppm" "$dir/kodim03.png" || { echo "FAIL: the input PNGs"; exit 1; }

out=$(node web/test/page_test.mjs "$dir" "$SHOTS" "$dir/lena.png" "$dir/kodim03.png")
rc=$?
grep -v ' page: ' <<<"$out"
[[ $rc -eq 0 ]] || { echo "FAIL: the page test"; exit 1; }

# STEP IMAGE DENSITY CHANNELS FLAGS (the form's ids and values, comma-separated). The opening
# picture is the one the page offers for download (opening.png).
cases=("opening $dir/opening.png 0.5 3 " "slider $dir/opening.png 0.6 3 " "drop $dir/lena.png 1 1 edges=2,wedge-fit=3"
       "file $dir/kodim03.png 1 3 " "paste $dir/opening.png 0.5 3 ")
bad_cases=0
for c in "${cases[@]}"; do
    read -r name png density channels flags <<<"$c"
    line=$(grep "^$name page: " <<<"$out") || { echo "FAIL: $name: the page reported no mesh"; bad_cases=$((bad_cases + 1)); continue; }
    echo "$line"
    read -r _ _ _ vertices _ psnr _ bytes _ _ _ ms _ progress _ page_channels _ files_ms <<<"$line"
    cli_flags=$(tr ',' '\n' <<<"$flags" | sed -n 's/^edges=2$/--edges hard/p; s/^wedge-fit=\(.*\)/--wedge-fit \1/p' | tr '\n' ' ')
    native=$dir/$name.native.erd
    # shellcheck disable=SC2086
    build/erd generate -q -m erdgpi -i "$png" -d "$density" -x 1 $cli_flags -o "$native" 2>/dev/null &&
    build/erd reconstruct "$native" -o "$dir/$name.native.png" -q || { echo "FAIL: native erd on $name"; bad_cases=$((bad_cases + 1)); continue; }
    native_psnr=$(build/erd psnr "$png" "$dir/$name.native.png" 2>/dev/null)
    native_vertices=$(build/erd info --json "$native" | sed -n 's/.*"vertices":\([0-9]*\).*/\1/p')
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
        echo "PASS: $name: the page's mesh, reconstruction and SVG are the native erd's (erdgpi $density%${flags:+ $flags}, ${channels} channel(s), ${ms} ms in the page and ${files_ms} ms for the files, progress bar to ${progress}%)"
    else
        echo "FAIL: $name: page and native erd differ"; bad_cases=$((bad_cases + 1))
    fi
done
# The slider's step must change the mesh.
v_open=$(sed -n 's/^opening page: vertices \([0-9]*\).*/\1/p' <<<"$out"); v_slider=$(sed -n 's/^slider page: vertices \([0-9]*\).*/\1/p' <<<"$out")
[[ -n $v_open && $v_open != "$v_slider" ]] || { echo "FAIL: the slider did not change the vertex count ($v_open -> $v_slider)"; bad_cases=$((bad_cases + 1)); }
[[ $bad_cases -eq 0 ]]
