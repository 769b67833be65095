#!/usr/bin/env bash
# make docs-images: the README pictures, made by erd itself.
#   bull at a sampling density of 0.125%, meshed with each method of $METHODS that exists
#   (default "erdgpi gpi", the README pair; a missing method is skipped with a note): for each, the reconstruction and the
#   triangulation (constrained edges thick and red) at half size, a 2x detail of the head with the
#   mesh over the reconstruction, and the error map of the detail. PNGs go to docs/img/.
#   Hard edges (issue 15): the `erd synth` drawing and cartoon at 320 x 240 and 1%, ERDGPI before
#   (--edges soft) and after (the default, auto: hard), mesh over the reconstruction and error map.
#   Mesh optimisation (issue 16, part "quality"): ERDGPI on bull 0.125% and lena 1%, before (the
#   previous default: --flips 0 --wedge-prior 0 --wedge-bounds -1) and after (the default): a
#   detail of the mesh over the reconstruction and its error map.
#   Colour (issue 17, part "colour"): kodim03 (colour/) at 1%, ERDGPI beside GPI at the same point
#   count: the reconstruction and the mesh over it, at half size.
#   Anti-aliased graphics (issue 44, part "graphics"): flag-chevron and mixed-text of
#   tools/graphics_svg.py rendered by rsvg-convert, ERDGPI (flag 1%, mixed-text 2%: a detail of its
#   title and logo) before (--edges soft: what auto chose for them before per-edge kinds) and after
#   (the default), mesh over the reconstruction (constrained edges red) and error map, the original.
#   Point removal (issue 45, part "removal"): bull 0.125% and lena 1%, the recommended ERDGPR beside
#   ERDGPI (531d603's default, byte-identical): a detail of the mesh over the reconstruction and
#   its error map.
#   PARTS (default "bull hard quality colour graphics removal") picks the parts.
# usage: tools/docs_images.sh ERD_BIN IMAGES_DIR [OUT_DIR]
set -euo pipefail
erd=${1:-build/erd}
images=${2:-../shared/images}
out=${3:-docs/img}
img="$images/bull.pgm"
density=0.125
crop="260,40,320,240"   # the bull's head (pixels): edges meeting smooth shading

if [ ! -x "$erd" ]; then echo "docs_images: no erd binary at $erd (run make first)" >&2; exit 1; fi
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
parts=${PARTS:-bull hard quality colour graphics removal}

if [[ " $parts " == *" colour "* ]]; then
    src="$images/color/kodim03.ppm"
    if [ ! -f "$src" ]; then echo "docs_images: $src not found" >&2; exit 1; fi
    for method in erdgpi gpi; do
        case $method in erd*) ext=erd ;; *) ext=model ;; esac
        model="$tmp/kodim03_$method.$ext"
        "$erd" generate -m "$method" -i "$src" -d 1 -q -o "$model"
        "$erd" reconstruct "$model" -q -o "$tmp/kodim03_$method.ppm"
        echo "docs_images: kodim03 $method: PSNR $("$erd" psnr "$src" "$tmp/kodim03_$method.ppm") dB" >&2
        "$erd" render "$model" -q --over-reconstruction --no-edges --scale 0.5 -o "$out/colour_kodim03_${method}_reconstruction.png"
        "$erd" render "$model" -q --over-reconstruction --scale 0.5 -o "$out/colour_kodim03_${method}_mesh.png"
    done
    "$erd" render "$model" -q --over "$src" --no-edges --scale 0.5 -o "$out/colour_kodim03_original.png"
fi

# mesh_pictures PART NAME D BOX TAG LABEL GENERATE-ARGS...: NAME meshed at D%, its PSNR said, and
# the mesh over the reconstruction and the error picture of BOX as docs/img/PART_NAME_TAG_*.png.
mesh_pictures() {
    local part=$1 name=$2 d=$3 box=$4 tag=$5 label=$6
    shift 6
    local model="$tmp/${part}_${name}_$tag.erd" rec="$tmp/${part}_${name}_$tag.pgm"
    "$erd" generate "$@" -i "$images/$name.pgm" -d "$d" -x 1 -q -o "$model"
    "$erd" reconstruct "$model" -q -o "$rec"
    echo "docs_images: $name $d% $label: PSNR $("$erd" psnr "$images/$name.pgm" "$rec") dB" >&2
    "$erd" render "$model" -q --over-reconstruction --crop "$box" --scale 2 -o "$out/${part}_${name}_${tag}_mesh.png"
    "$erd" render "$model" -q --error "$images/$name.pgm" --no-edges --crop "$box" --scale 2 -o "$out/${part}_${name}_${tag}_error.png"
}

if [[ " $parts " == *" quality "* ]]; then
    for c in "bull 0.125 260,40,320,240" "lena 1 200,180,200,200"; do
        read -r name d box <<<"$c"
        [ -f "$images/$name.pgm" ] || { echo "docs_images: $images/$name.pgm not found" >&2; exit 1; }
        for when in before after; do
            flags=(); [ "$when" = before ] && flags=(--flips 0 --wedge-prior 0 --wedge-bounds -1)
            mesh_pictures quality "$name" "$d" "$box" "$when" "ERDGPI $when" -m erdgpi "${flags[@]}"
        done
    done
fi

if [[ " $parts " == *" removal "* ]]; then
    for c in "bull 0.125 260,40,320,240" "lena 1 200,180,200,200"; do
        read -r name d box <<<"$c"
        [ -f "$images/$name.pgm" ] || { echo "docs_images: $images/$name.pgm not found" >&2; exit 1; }
        for method in erdgpi erdgpr; do
            mesh_pictures removal "$name" "$d" "$box" "$method" "$method" -m "$method"
        done
    done
fi

if [[ " $parts " == *" graphics "* ]]; then
    command -v rsvg-convert >/dev/null || { echo "docs_images: rsvg-convert missing (make graphics-deps)" >&2; exit 1; }
    python3 "$(dirname "$0")/graphics_svg.py" "$tmp/svg" "$images" >/dev/null
    # name density crop (the title and logo of mixed-text, at twice the size)
    for c in "flag-chevron 1 -" "mixed-text 2 180,0,332,96"; do
        read -r name d box <<<"$c"
        view=(); [ "$box" = - ] || view=(--crop "$box" --scale 2)
        rsvg-convert "$tmp/svg/$name.svg" -o "$tmp/$name.png"
        for when in before after; do
            flags=(); [ "$when" = before ] && flags=(--edges soft)
            model="$tmp/${name}_$when.erd"
            "$erd" generate -m erdgpi "${flags[@]}" -i "$tmp/$name.png" -d "$d" -x 1 -q -o "$model"
            "$erd" reconstruct "$model" -q -o "$tmp/${name}_$when.png"
            echo "docs_images: $name $d% ERDGPI $when: PSNR $("$erd" psnr "$tmp/$name.png" "$tmp/${name}_$when.png") dB" >&2
            "$erd" render "$model" -q --over-reconstruction "${view[@]}" -o "$out/graphics_${name}_${when}_mesh.png"
            "$erd" render "$model" -q --error "$tmp/$name.png" --no-edges "${view[@]}" -o "$out/graphics_${name}_${when}_error.png"
        done
        "$erd" render "$model" -q --over "$tmp/$name.png" --no-edges "${view[@]}" -o "$out/graphics_${name}_original.png"
    done
fi

if [[ " $parts " == *" hard "* ]]; then
    for kind in drawing cartoon; do
        "$erd" synth -q --kind "$kind" -W 320 -H 240 -o "$tmp/$kind.pgm"
        for when in before after; do
            flags=(); [ "$when" = before ] && flags=(--edges soft)
            model="$tmp/${kind}_$when.erd"
            "$erd" generate -m erdgpi "${flags[@]}" -i "$tmp/$kind.pgm" -d 1 -x 1 -q -o "$model"
            "$erd" reconstruct "$model" -q -o "$tmp/${kind}_$when.pgm"
            echo "docs_images: $kind ERDGPI $when: PSNR $("$erd" psnr "$tmp/$kind.pgm" "$tmp/${kind}_$when.pgm") dB" >&2
            "$erd" render "$model" -q --over-reconstruction -o "$out/hard_${kind}_${when}_mesh.png"
            "$erd" render "$model" -q --error "$tmp/$kind.pgm" --no-edges -o "$out/hard_${kind}_${when}_error.png"
        done
        "$erd" render "$model" -q --over "$tmp/$kind.pgm" --no-edges -o "$out/hard_${kind}_original.png"
    done
fi
[[ " $parts " == *" bull "* ]] || exit 0
if [ ! -f "$img" ]; then echo "docs_images: $img not found (set IMAGES=...)" >&2; exit 1; fi

made=()
first=""
for method in ${METHODS:-erdgpi gpi}; do
    case $method in erd*) ext=erd ;; *) ext=model ;; esac
    model="$tmp/bull_$method.$ext"
    if ! "$erd" generate -m "$method" -i "$img" -d "$density" -x 1 -q -o "$model" 2>"$tmp/err"; then
        echo "docs_images: skipping $method: $(head -n 1 "$tmp/err")" >&2
        continue
    fi
    "$erd" reconstruct "$model" -q -o "$tmp/bull_$method.pgm"
    psnr=$("$erd" psnr "$img" "$tmp/bull_$method.pgm")
    echo "docs_images: $method: $(sed -n 2p "$model") vertices, PSNR $psnr dB" >&2
    "$erd" render "$model" -q --over-reconstruction --no-edges --scale 0.5 -o "$out/bull_${method}_reconstruction.png"
    "$erd" render "$model" -q --scale 0.5 -o "$out/bull_${method}_mesh.png"
    "$erd" render "$model" -q --over-reconstruction --crop "$crop" --scale 2 -o "$out/bull_${method}_detail.png"
    "$erd" render "$model" -q --error "$img" --no-edges --crop "$crop" --scale 1 -o "$out/bull_${method}_error.png"
    made+=("$method")
    [ -n "$first" ] || first=$model
done
if [ -z "$first" ]; then echo "docs_images: no method could mesh $img" >&2; exit 1; fi
# The original, through the same scaling (render with no edges over the image).
"$erd" render "$first" -q --over "$img" --no-edges --scale 0.5 -o "$out/bull_original.png"
"$erd" render "$first" -q --over "$img" --no-edges --crop "$crop" --scale 2 -o "$out/bull_original_detail.png"
echo "docs_images: made ${made[*]} in $out" >&2
for m in "${made[@]}" original; do ls -l "$out"/bull_"$m"*.png >&2; done
