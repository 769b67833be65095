#!/usr/bin/env bash
# make docs-images: the README pictures, made by erd itself.
#   bull at a sampling density of 0.125%, meshed with ERDGPI and GPI (and, when present, ERDED
#   and ED): the reconstruction and the triangulation (constrained edges thick and red) of each,
#   the whole image at half size plus a 2x detail, and the error map. PNGs go to docs/img/.
# usage: tools/docs_images.sh ERD_BIN IMAGES_DIR [OUT_DIR]
set -euo pipefail
erd=${1:-build/erd}
images=${2:-../shared/images}
out=${3:-docs/img}
img="$images/bull.pgm"
density=0.125
# A detail window (pixels) across the bull's head, where edges meet smooth shading.
crop="520,120,256,192"

if [ ! -x "$erd" ]; then echo "docs_images: no erd binary at $erd (run make first)" >&2; exit 1; fi
if [ ! -f "$img" ]; then echo "docs_images: $img not found (set IMAGES=...)" >&2; exit 1; fi
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

made=()
for method in erdgpi gpi erded ed; do
    case $method in erd*) ext=erd ;; *) ext=model ;; esac
    model="$tmp/bull_$method.$ext"
    if ! "$erd" generate --method "$method" -i "$img" -d "$density" -x 1 -q -o "$model" 2>"$tmp/err"; then
        echo "docs_images: skipping $method: $(head -n 1 "$tmp/err")" >&2
        continue
    fi
    psnr=$("$erd" reconstruct "$model" -o "$tmp/bull_$method.pgm" -q && "$erd" psnr "$img" "$tmp/bull_$method.pgm" 2>/dev/null | tr -d '\n' || true)
    echo "docs_images: $method: $(grep -c . "$model" | tr -d '\n') lines, PSNR ${psnr:-?}" >&2
    "$erd" render "$model" --over-reconstruction --no-edges --scale 0.5 -o "$out/bull_${method}_reconstruction.png"
    "$erd" render "$model" --scale 0.5 -o "$out/bull_${method}_mesh.png"
    "$erd" render "$model" --over-reconstruction --crop "$crop" --scale 2 -o "$out/bull_${method}_detail.png"
    "$erd" render "$model" --error "$img" --no-edges --scale 0.5 -o "$out/bull_${method}_error.png"
    made+=("$method")
done
"$erd" render "$tmp/bull_${made[0]}.$( [[ ${made[0]} == erd* ]] && echo erd || echo model)" --over "$img" --no-edges --scale 0.5 \
    -o "$out/bull_original.png"
"$erd" render "$tmp/bull_${made[0]}.$( [[ ${made[0]} == erd* ]] && echo erd || echo model)" --over "$img" --no-edges \
    --crop "$crop" --scale 2 -o "$out/bull_original_detail.png"
echo "docs_images: made ${made[*]} in $out:" >&2
ls -l "$out"/bull_*.png >&2
