#!/usr/bin/env bash
# Renders `erd render --vector` SVGs 1:1 in real renderers (chromium headless, librsvg's
# rsvg-convert, Inkscape when installed) and prints their PSNR against the original beside erd's
# own point reconstruction (`erd reconstruct --no-aa`) and its default one (`erd reconstruct`:
# 4x4 supersampled for a soft-edged ERD model, point evaluation otherwise). Fails when a renderer
# is more than TOL dB (default 0.3) below either (docs/DECISIONS.md "Vector SVG").
#   tools/svg_browser_psnr.sh ERD_BINARY IMAGE... (env: METHODS="erdgpi gpi", DENSITY=1, SEAMS=layered,
#   RAMP=levels, RENDERERS="chromium rsvg inkscape", TOL=0.3, KEEP=dir to keep the files)
# Exit: 0 all within TOL; 1 a renderer missed it; 77 chromium not installed (a skip, never a pass).
set -u
ERD=$1; shift
METHODS=${METHODS:-erdgpi gpi}; DENSITY=${DENSITY:-1}; SEAMS=${SEAMS:-layered}; RAMP=${RAMP:-levels}; TOL=${TOL:-0.3}
RENDERERS=${RENDERERS:-chromium rsvg inkscape}
dir=${KEEP:-$(mktemp -d)}; mkdir -p "$dir"
[[ -z ${KEEP:-} ]] && trap 'rm -rf "$dir"' EXIT
have() {
    case $1 in
        chromium) command -v chromium >/dev/null ;;
        rsvg) command -v rsvg-convert >/dev/null ;;
        inkscape) command -v inkscape >/dev/null ;;
    esac
}
# render RENDERER SVG PNG W H
render() {
    case $1 in
        chromium) chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --force-device-scale-factor=1 \
                      --user-data-dir="$dir/chromium-profile" --screenshot="$3" --window-size="$4,$5" "file://$2" >/dev/null 2>&1 ;;
        rsvg) rsvg-convert -b white -o "$3" "$2" ;;
        inkscape) inkscape --export-type=png --export-background=white --export-background-opacity=1 --export-filename="$3" "$2" >/dev/null 2>&1 ;;
    esac
}
# PNG width and height from its IHDR.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{printf "%d %d", $1*16777216+$2*65536+$3*256+$4, $5*16777216+$6*65536+$7*256+$8}'; }
active=""
for r in $RENDERERS; do if have "$r"; then active="$active $r"; else echo "SKIP $r: not installed"; fi; done
[[ -z $active ]] && { echo "SKIP: no SVG renderer installed (chromium, rsvg-convert, inkscape)"; exit 77; }
fail=0
printf '%-10s %-7s %6s %8s %6s %9s' image method faces bytes/face point point-aa
for r in $active; do printf ' %9s' "$r"; done; echo
for img in "$@"; do
    name=$(basename "${img%.*}")
    for m in $METHODS; do
        ext=erd; [[ $m == gpi || $m == ed ]] && ext=model
        base="$dir/${name}_$m"
        "$ERD" generate -m "$m" -i "$img" -d "$DENSITY" -o "$base.$ext" -q -x 2 || { echo "FAIL generate $img $m"; fail=1; continue; }
        "$ERD" render "$base.$ext" -o "$base.svg" --vector --seams "$SEAMS" --ramp "$RAMP" || { echo "FAIL render $img $m"; fail=1; continue; }
        "$ERD" reconstruct "$base.$ext" --no-aa -o "$base.point.pgm" -q
        "$ERD" reconstruct "$base.$ext" -o "$base.aa.pgm" -q
        point=$("$ERD" psnr "$img" "$base.point.pgm" 2>/dev/null); aa=$("$ERD" psnr "$img" "$base.aa.pgm" 2>/dev/null)
        faces=$(grep -oE '[0-9]+ faces</desc>' "$base.svg" | grep -oE '^[0-9]+'); bytes=$(wc -c <"$base.svg")  # colour: 3 paths a face
        read -r W H < <("$ERD" info "$img" | grep -oE '[0-9]+ ?x ?[0-9]+' | head -1 | tr -d ' ' | tr x ' ')
        printf '%-10s %-7s %6d %8.1f %6s %9s' "$name" "$m" "$faces" "$(echo "$bytes / $faces" | bc -l)" "$point" "$aa"
        for r in $active; do
            png="$base.$r.png"
            if ! render "$r" "$base.svg" "$png" "$W" "$H" || [[ ! -s $png ]]; then printf ' %9s' FAIL; fail=1; continue; fi
            if [[ $(png_size "$png") != "$W $H" ]]; then printf ' %9s' "size:$(png_size "$png" | tr ' ' x)"; fail=1; continue; fi
            p=$("$ERD" psnr "$img" "$png" 2>/dev/null)
            printf ' %9s' "$p"
            awk -v p="$p" -v q="$aa" -v r="$point" -v t="$TOL" 'BEGIN { exit !(p + t >= q && p + t >= r) }' || fail=1
        done
        echo
    done
done
if [[ $fail -eq 0 && " $active " != *" chromium "* ]]; then
    echo "SKIP: chromium not installed: the browser measurement was not done (the other renderers were within $TOL dB)"; exit 77
fi
[[ $fail -eq 0 ]] && echo "PASS: every renderer within $TOL dB of erd's point reconstruction and of erd reconstruct's image" || echo "FAIL: a renderer is more than $TOL dB below erd's point reconstruction or erd reconstruct's image (or failed)"
exit $fail
