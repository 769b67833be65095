#!/usr/bin/env bash
# The raster stage of `make test` (issue 47), on real elevation data: Debian's
# python-matplotlib-data DEMs written as GeoTIFF, PFM and 16-bit PNG by tests/dem_data.py, and
# `erd synth --kind dem` (faults, a mesa, nodata lakes). Each line PASS or FAIL counts as one test;
# the checks are numpy's (tests/raster_check.py), not erd's own metrics:
#   - --max-error E: every method's model, reconstructed, is within E of the data at every valid
#     pixel (float32 rounding of the written raster aside), with its holes exactly where the
#     data has none;
#   - precision: a DEM of range 0.001 m and one of 10 km mesh to E = range/100 without
#     collapsing onto a few levels;
#   - round trips: TIFF float32 and int16 (GDAL_NODATA) in, reconstruct, TIFF out: the same size,
#     type, georeferencing, nodata value and nodata count (erd info --json);
#   - glTF: every model exported as .glb passes the Khronos validator with 0 errors (npm
#     gltf-validator, installed from tools/gltf/package-lock.json; without node or npm those lines
#     say SKIP and do not count as passed).
#   tests/raster_test.sh [ERD_BIN]
set -u
cd "$(dirname "$0")/.."
ERD=${1:-build/erd}
PY=/usr/bin/python3
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
. tests/check_lines.sh  # check LABEL COMMAND...

$PY tests/dem_data.py "$d" >"$d/ranges" || { echo "FAIL: tests/dem_data.py (python3-numpy, python-matplotlib-data?)"; exit 1; }
"$ERD" synth -q --kind dem -W 640 -H 512 -o "$d/synth.tif" && "$ERD" synth -q --kind dem -W 640 -H 512 -o "$d/synth.pfm" &&
    "$ERD" synth -q --kind dem -W 640 -H 512 -o "$d/synth.png" || { echo "FAIL: erd synth --kind dem"; exit 1; }
# A small colour raster (float RGB as PFM) for the vertex colours of glTF.
$PY -c "
import numpy as np
y, x = np.mgrid[0:48, 0:64].astype(np.float32)
rgb = np.stack([x / 64, y / 48, ((x - 32) ** 2 + (y - 24) ** 2 < 200).astype(np.float32)], axis=2)
open('$d/rgb.pfm', 'wb').write(b'PF\\n64 48\\n-1.0\\n' + np.flipud(rgb).astype('<f4').tobytes())" || { echo "FAIL: colour PFM"; exit 1; }
range() { awk -v n="$1" '$1 == n { print $5 - $4 }' "$d/ranges"; }

# --max-error: E a half percent of the range (4.2 m on Jacksboro, 18 m on topobathy, 4.3 m on
# the synthetic model), every method. The greedy methods at -d 100 (N never stops them first), ED
# and ERDED at -d 5 (their points, then insertions until the bound holds).
for dem in jacksboro topobathy synth jacksboro16; do
    case $dem in
        synth) orig=$d/synth.pfm; E=4.3 ;;
        *) orig=$d/$dem.npy; E=$($PY -c "print(round($(range $dem) * 0.005, 3))") ;;
    esac
    for m in erdgpi gpi erded ed; do
        ext=model; [[ $m == erd* ]] && ext=erd
        out=$d/$dem.$m
        dens=100; [[ $m == ed || $m == erded ]] && dens=5
        if ! "$ERD" generate -q -m $m -i "$d/$dem.tif" -d $dens -x 2 --max-error "$E" -o "$out.$ext" ||
           ! "$ERD" reconstruct -q "$out.$ext" -o "$out.pfm"; then
            echo "FAIL: $dem $m --max-error $E: erd generate or reconstruct failed"; continue
        fi
        check "$dem $m --max-error $E" $PY tests/raster_check.py maxerr "$orig" "$out.pfm" "$E"
    done
done

# Precision: the Jacksboro model rescaled onto 0..0.001 m and onto -5000..5000 m.
for r in "tiny 0 0.001" "wide -5000 5000"; do
    read -r name lo hi <<<"$r"
    $PY tests/raster_check.py scale "$d/jacksboro.npy" "$d/$name.pfm" "$lo" "$hi"
    E=$($PY -c "print(($hi - ($lo)) / 100)")
    for m in erdgpi gpi; do
        ext=model; [[ $m == erd* ]] && ext=erd
        if "$ERD" generate -q -m $m -i "$d/$name.pfm" -d 100 -x 2 --max-error "$E" -o "$d/$name.$m.$ext" &&
           "$ERD" reconstruct -q "$d/$name.$m.$ext" -o "$d/$name.$m.pfm"; then
            check "precision: range $lo..$hi m, $m --max-error $E" $PY tests/raster_check.py maxerr "$d/$name.npy" "$d/$name.$m.pfm" "$E"
            check "precision: range $lo..$hi m, $m keeps many levels" $PY tests/raster_check.py levels "$d/$name.$m.pfm" 1000
        else
            echo "FAIL: precision: range $lo..$hi m, $m: erd generate or reconstruct failed"
        fi
    done
done

# Round trips: TIFF in, model, reconstruct, TIFF out.
for dem in jacksboro jacksboro16 synth; do
    for m in erdgpi gpi; do
        ext=model; [[ $m == erd* ]] && ext=erd
        if "$ERD" reconstruct -q "$d/$dem.$m.$ext" -o "$d/$dem.$m.tif" && "$ERD" info --json "$d/$dem.tif" >"$d/a.json" &&
           "$ERD" info --json "$d/$dem.$m.tif" >"$d/b.json"; then
            check "round trip $dem.tif -> $m -> TIFF" $PY tests/raster_check.py same "$d/a.json" "$d/b.json"
        else
            echo "FAIL: round trip $dem.tif -> $m: reconstruct or info failed"
        fi
    done
done

# glTF: every model written above, exported and validated.
glbs=()
for f in "$d"/*.model "$d"/*.erd; do
    [[ $f == */synth16.* || $f == */rgb.* ]] && continue
    "$ERD" export -q "$f" -o "${f%.*}.$(basename "${f##*.}").glb" && glbs+=("${f%.*}.$(basename "${f##*.}").glb")
done
for m in erdgpi gpi; do
    ext=model; [[ $m == erd* ]] && ext=erd
    "$ERD" generate -q -m $m -i "$d/synth.png" -d 2 -x 2 -o "$d/synth16.$m.$ext" && "$ERD" export -q "$d/synth16.$m.$ext" -o "$d/synth16.$m.glb" &&
        glbs+=("$d/synth16.$m.glb")
    "$ERD" generate -q -m $m -i "$d/rgb.pfm" -d 20 -x 2 -o "$d/rgb.$m.$ext" && "$ERD" export -q "$d/rgb.$m.$ext" -o "$d/rgb.$m.glb" &&
        glbs+=("$d/rgb.$m.glb")
done
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    echo "SKIP: node/npm missing: ${#glbs[@]} .glb files not validated"
    exit 0
fi
if [[ ! -d tools/gltf/node_modules/gltf-validator ]]; then
    (cd tools/gltf && npm ci --no-audit --no-fund >/dev/null 2>&1) || { echo "SKIP: npm ci could not install gltf-validator (tools/gltf/package-lock.json)"; exit 0; }
fi
node tools/gltf/validate.mjs "${glbs[@]}" | while read -r line; do
    case $line in
        *": 0 errors"*) echo "PASS: glTF validator: ${line##*/}" ;;
        "  "*) echo "$line" ;;
        *) echo "FAIL: glTF validator: ${line##*/}" ;;
    esac
done
