#!/usr/bin/env bash
# The browser test of web/ (a stage of tests/run_all.sh): builds erd as WebAssembly (make web),
# drives Debian's chromium with playwright-core (web/test/page_test.mjs) through the page on
# lena at 1% with erdgpi and two of the form's ERD flags set off their defaults (edges hard, wedge
# fit 3: the flags reach the library, hard edges take the point reconstruction), checks that the
# progress bar moved, and compares the page's vertex count, PSNR and downloaded .erd with the
# native erd's for the same image: same PSNR to 4 decimals, same file but for the last digit of a
# few doubles (|difference| <= 1e-12 relative; the two builds' floating point differs by an ulp).
#   tests/web_test.sh IMAGES_DIR [SHOT.png]
# Exit: 0 same; 1 different or broken; 77 chromium (or node/npm) missing: a skip, never a pass.
set -u
cd "$(dirname "$0")/.."
IMAGES=$1; SHOT=${2:-}
command -v chromium >/dev/null || { echo "SKIP: chromium not installed"; exit 77; }
command -v node >/dev/null && command -v npm >/dev/null || { echo "SKIP: node/npm not installed"; exit 77; }
[[ -f $IMAGES/lena.pgm ]] || { echo "FAIL: $IMAGES/lena.pgm missing"; exit 1; }
make -s web >/dev/null || { echo "FAIL: make web"; exit 1; }
if [[ ! -d web/node_modules/playwright-core ]]; then
    (cd web && npm ci --no-audit --no-fund >/dev/null 2>&1) || { echo "SKIP: npm ci could not install playwright-core (web/package-lock.json)"; exit 77; }
fi
dir=$(mktemp -d); trap 'rm -rf "$dir"' EXIT
# lena as a gray PNG (the page decodes PNG/JPEG with the browser), then both sides mesh that file.
build/erd generate -q -m gpi -i "$IMAGES/lena.pgm" -n 4 -o "$dir/corners.model" &&
build/erd render "$dir/corners.model" --no-edges --over "$IMAGES/lena.pgm" -o "$dir/lena.png" || { echo "FAIL: lena.png"; exit 1; }
build/erd generate -q -m erdgpi -i "$dir/lena.png" -d 1 -x 1 --edges hard --wedge-fit 3 -o "$dir/native.erd" 2>/dev/null &&
build/erd reconstruct "$dir/native.erd" -o "$dir/native.pgm" -q || { echo "FAIL: native erd"; exit 1; }
native_psnr=$(build/erd psnr "$dir/lena.png" "$dir/native.pgm" 2>/dev/null)
# The vertex count: the body's second line (past the header block "erd-header 1" ... "end", if any).
native_vertices=$(awk 'NR == 1 && $1 == "erd-header" { h = 1 } h { if ($1 == "end") h = 0; next } ++n == 2 { print $1; exit }' "$dir/native.erd")
out=$(node web/test/page_test.mjs "${SHOT:-$dir/page.png}" "$dir/lena.png,erdgpi,1,$dir/page.erd,edges=2,wedge-fit=3") || { echo "FAIL: $out"; exit 1; }
echo "$out"
read -r _ _ vertices _ psnr _ bytes _ _ _ ms _ progress <<<"$out"
echo "native: vertices $native_vertices psnr $native_psnr model-bytes $(wc -c <"$dir/native.erd")"
close=$(paste -d' ' <(tr -s ' \n' '\n\n' <"$dir/page.erd") <(tr -s ' \n' '\n\n' <"$dir/native.erd") | awk '
    $1 != $2 { d = $1 - $2; if (d < 0) d = -d; m = $2 < 0 ? -$2 : $2; if (m < 1) m = 1; if (d > 1e-12 * m) bad++; else ulp++ }
    END { printf "%d %d", bad + 0, ulp + 0 }')
read -r bad ulp <<<"$close"
[[ $(wc -l <"$dir/page.erd") == $(wc -l <"$dir/native.erd") ]] || bad=$((bad + 1))
echo "model: $ulp values differ in the last digit, $bad tokens differ more"
[[ $progress -ge 90 ]] || { echo "FAIL: the progress bar reached only ${progress}%"; bad=$((bad + 1)); }
if [[ $vertices == "$native_vertices" && $psnr == "$native_psnr" && $bad -eq 0 ]]; then
    echo "PASS: the page's mesh is the native erd's (lena 1% erdgpi --edges hard --wedge-fit 3, ${ms} ms in the page, progress bar to ${progress}%)"; exit 0
fi
echo "FAIL: page and native erd differ"; exit 1
