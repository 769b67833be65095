#!/usr/bin/env bash
# The tiles stage of `make test` (issue 48): `erd tiles` on a 1025^2 16-bit heightmap (erd synth
# --kind dem --solid) in 4 x 4 tiles. Each PASS or FAIL line counts as one test:
#   - seams: the merged mesh of gpi and of erdgpi is a valid triangulation of the whole rectangle
#     (tests/tiles_check.py: every face counter-clockwise, areas summing to the rectangle, every
#     edge one face on the boundary or two opposite faces inside: no crack, no T-junction, no
#     overlap, Euler V - E + F = 1), and --finish found every tile's sides equal to the plan's;
#   - the budget: the merged mesh has exactly N = D W H / 100 vertices;
#   - ERD crossings: a step across a tile side ends a discontinuity at the planned side vertex in
#     both tiles, with the same values on either side of it at the seam;
#   - the same bytes however the tasks run: one run; --plan, the tasks in reverse order, --finish;
#     GNU parallel -j 2 when installed (else SKIP); the Dask run is python/tests/test_tiles.py's;
#   - a 16-bit PNG read by rows gives the tiles of the PGM of the same samples;
#   - the merged .glb through the Khronos validator (when tools/gltf has it installed);
#   - refusals: a method that cannot fix the sides, a task out of range, a missing plan.
#   tests/tiles_test.sh [ERD_BIN]
set -u
cd "$(dirname "$0")/.."
ERD=$(realpath "${1:-build/erd}")
PY=/usr/bin/python3
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
. tests/check_lines.sh  # check LABEL COMMAND...
same() {  # LABEL DIR1 DIR2 [FILE...]: the folders' files (and the files) byte for byte
    local label=$1 a=$2 b=$3
    shift 3
    if diff -r -q "$a" "$b" >/dev/null && { [[ $# -eq 0 ]] || cmp -s "$1" "$2"; }; then echo "PASS: $label"
    else echo "FAIL: $label: $(diff -r -q "$a" "$b" | head -2 | tr '\n' ' ')"; fi
}

"$ERD" synth -q --kind dem --solid -W 1025 -H 1025 -o "$d/dem.pgm" || { echo "FAIL: erd synth --kind dem"; exit 1; }
N=$(( (1025 * 1025 + 50) / 100 ))  # -d 1: round(W H / 100)

for m in gpi erdgpi; do
    check "$m 4x4 tiles, one run" "$ERD" tiles -q -m $m -i "$d/dem.pgm" --tile 256 -d 1 -o "$d/$m" --merge "$d/$m.ply"
    check "$m merged mesh is a triangulation of the rectangle" $PY tests/tiles_check.py "$d/$m.ply" 1025 1025
    v=$(grep -o '"vertices":[0-9]*' "$d/$m/index.json" | head -1 | cut -d: -f2)
    check "$m total vertices = N ($N)" test "$v" = "$N"
    # The tasks as a cluster runs them: plan, any order, finish.
    "$ERD" tiles -q -m $m -i "$d/dem.pgm" --tile 256 -d 1 -o "$d/$m.b" --plan
    for k in $(seq 15 -1 0); do "$ERD" tiles -q -o "$d/$m.b" --task "$k"; done
    "$ERD" tiles -q -o "$d/$m.b" --finish --merge "$d/$m.b.ply"
    same "$m plan + tasks in reverse order + finish = one run" "$d/$m" "$d/$m.b" "$d/$m.ply" "$d/$m.b.ply"
done

# A hard step crossing two tile sides (x = 60 + 0.6 y on 257^2, 2 x 2 tiles of 128): the plan puts a
# crossing where it meets each inner line, both tiles end a discontinuity at that vertex with the
# same two values on the seam (tests/tiles_crossing.py), and the merged mesh is still a triangulation.
$PY -c "
import sys
px = bytes(200 if x > 0.6 * y + 60 else 40 for y in range(257) for x in range(257))
sys.stdout.buffer.write(b'P5\n257 257\n255\n' + px)" >"$d/step.pgm"
check "erdgpi: a step across two tile sides" "$ERD" tiles -q -m erdgpi -i "$d/step.pgm" --tile 128 -d 2 -o "$d/step" --merge "$d/step.ply"
check "erdgpi: the plan's crossings are the step's (y 113.5 on x = 128, x 136.5 on y = 128)" \
    test "$(grep cross "$d/step/plan.txt" | tr '\n' ' ')" = "vcross 1 0 1 113 hcross 1 1 1 8 "
check "erdgpi: each crossing ends a discontinuity at the same vertex in both tiles" $PY tests/tiles_crossing.py "$d/step"
check "erdgpi: the step's merged mesh is a triangulation" $PY tests/tiles_check.py "$d/step.ply" 257 257
check "erdgpi: the heightmap's crossings end a discontinuity in both tiles" $PY tests/tiles_crossing.py "$d/erdgpi"
check "gpi plans no crossing" bash -c "! grep -q cross '$d/gpi/plan.txt'"

if command -v parallel >/dev/null && parallel --version 2>/dev/null | grep -q GNU; then
    "$ERD" tiles -q -m gpi -i "$d/dem.pgm" --tile 256 -d 1 -o "$d/gpi.p" --plan
    seq 0 15 | parallel -j 2 "$ERD" tiles -q -o "$d/gpi.p" --task {}
    "$ERD" tiles -q -o "$d/gpi.p" --finish --merge "$d/gpi.p.ply"
    same "gpi GNU parallel -j 2 = one run" "$d/gpi" "$d/gpi.p" "$d/gpi.ply" "$d/gpi.p.ply"
else
    echo "SKIP: GNU parallel not installed"
fi

# A PNG read by rows: the same tiles as the PGM of the same samples.
"$ERD" synth -q --kind dem -W 513 -H 513 -o "$d/p.png" && "$ERD" synth -q --kind dem -W 513 -H 513 -o "$d/p.pgm"
"$ERD" tiles -q -m gpi -i "$d/p.png" --tile 128 -d 1 -o "$d/png" --merge "$d/png.ply"
"$ERD" tiles -q -m gpi -i "$d/p.pgm" --tile 128 -d 1 -o "$d/pgm" --merge "$d/pgm.ply"
rm -f "$d/png/plan.txt" "$d/pgm/plan.txt" "$d/png/index.json" "$d/pgm/index.json"  # they name the raster
same "PNG by rows = PGM" "$d/png" "$d/pgm" "$d/png.ply" "$d/pgm.ply"

# The merged mesh in every format; .obj checked like .ply; .glb by the Khronos validator.
check "erdgpi merged .obj is a triangulation" bash -c "'$ERD' tiles -q -o '$d/erdgpi' --finish --merge '$d/m.obj' && $PY tests/tiles_check.py '$d/m.obj' 1025 1025"
check "merged .stl and .glb" "$ERD" tiles -o "$d/gpi" --finish --merge "$d/m.stl"
"$ERD" tiles -q -o "$d/gpi" --finish --merge "$d/m.glb"
stl_facets=$($PY -c "import struct,sys; print(struct.unpack('<I', open(sys.argv[1],'rb').read()[80:84])[0])" "$d/m.stl")
check "STL facets = the faces of the .ply" test "$stl_facets" = "$(grep -o 'element face [0-9]*' "$d/gpi.ply" | cut -d' ' -f3)"
if command -v node >/dev/null && [[ -d tools/gltf/node_modules/gltf-validator ]]; then
    out=$(node tools/gltf/validate.mjs "$d/m.glb")
    case $out in *": 0 errors"*) echo "PASS: glTF validator: merged .glb" ;; *) echo "FAIL: glTF validator: $out" ;; esac
else
    echo "SKIP: gltf-validator not installed (tools/gltf: npm ci)"
fi

# Refusals: one line, exit 2, nothing written.
refused() {  # LABEL COMMAND...: exit 2 and one line on stderr
    local label=$1 err rc
    shift
    err=$("$@" 2>&1 >/dev/null); rc=$?
    if [[ $rc -eq 2 && $(wc -l <<<"$err") -eq 1 ]]; then echo "PASS: refused: $label: $err"; else echo "FAIL: refused: $label: exit $rc: $err"; fi
}
refused "ed cannot fix the sides" "$ERD" tiles -m ed -i "$d/dem.pgm" --tile 256 -o "$d/ed"
refused "task out of range" "$ERD" tiles -o "$d/gpi" --task 16
refused "no plan" "$ERD" tiles -o "$d/none" --task 0
refused "generate's options with --task" "$ERD" tiles -o "$d/gpi" --task 0 -d 2
