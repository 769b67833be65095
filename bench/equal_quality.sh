#!/usr/bin/env bash
# Equal quality and equal points beside fogleman/hmm (issue 46), a block of `make bench` that also
# runs alone:  bench/equal_quality.sh HMM ERD IMAGES_DIR OUT_DIR [RUNS]
#
# For lena, bull and the soft-edged 2048^2 `erd synth` (--edges soft): hmm meshes 1% of the pixels
# (`hmm -z 1 -e 0 -p N`); its PSNR is measured by bench/stl_psnr.py (its STL evaluated at every
# pixel, rounded, erd's peak); `erd generate -m erdgpi -d 1 --psnr P` finds the fewest points whose
# model reaches it (algorithms/methods/quality_target.h); then hmm at N, erdgpi at that count and
# erdgpi at N are timed one after the other (bench/timeit: CPU ms, medians of RUNS after a warm-up;
# erd at -j 1, as hmm runs: a second thread only adds CPU time). The same again with
# `--lower-beta 0` (the parameter loop on one detection).
# Prints the markdown table on stdout (run.sh puts it in docs/RESULTS.md, section "equal-quality").
set -u
HMM=$1 ERD=$2 IMAGES=$3 OUT=$4 RUNS=${5:-5}
TIMEIT=$(dirname "$ERD")/timeit
PY=/usr/bin/python3
[[ $ERD == */* && $ERD != /* ]] && ERD=$PWD/$ERD
cd "$(dirname "$0")/.." || exit 1
[[ -x $TIMEIT ]] || ${CXX:-g++} -O2 -std=c++17 bench/timeit.cpp -o "$TIMEIT" || exit 1
"$ERD" synth -q -W 2048 -H 2048 -o "$OUT/eq_synth2048.pgm" || exit 1
cases=("lena|$IMAGES/lena.pgm|" "bull|$IMAGES/bull.pgm|" "synth 2048 soft|$OUT/eq_synth2048.pgm|--edges soft"
       "lena, --lower-beta 0|$IMAGES/lena.pgm|--lower-beta 0" "bull, --lower-beta 0|$IMAGES/bull.pgm|--lower-beta 0"
       "synth 2048 soft, --lower-beta 0|$OUT/eq_synth2048.pgm|--edges soft --lower-beta 0")
echo "| image | N (1%) | hmm PSNR | hmm ms | erdgpi points for it | erdgpi ms | ratio | erdgpi at N ms | ratio |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for c in "${cases[@]}"; do
    IFS='|' read -r label img extra <<<"$c"
    [[ -f $img ]] || continue
    read -r w h < <("$ERD" info "$img" | awk '/^size:/ { print $2, $4 }')
    n=$(( (w * h + 50) / 100 ))
    "$HMM" -z 1 -e 0 -p "$n" -q "$img" "$OUT/eq.stl" || { echo "| $label | $n | hmm failed | | | | | | |"; continue; }
    p=$($PY bench/stl_psnr.py "$img" "$OUT/eq.stl") || { echo "| $label | $n | PSNR failed | | | | | | |"; continue; }
    # shellcheck disable=SC2086
    k=$("$ERD" generate -m erdgpi $extra -d 1 --psnr "$p" -x 2 -v -i "$img" -o "$OUT/eq.erd" 2>&1 |
        sed -n 's/.*quality search: \([0-9]*\) points.*(the largest.*/\1/p')
    read -r _ hcpu _ < <("$TIMEIT" "$RUNS" "$HMM" -z 1 -e 0 -p "$n" -q "$img" "$OUT/eq.stl")
    if [[ -z $k ]]; then
        kcpu="-" k="not reached at N"
    else
        # shellcheck disable=SC2086
        read -r _ kcpu _ < <("$TIMEIT" "$RUNS" "$ERD" generate -m erdgpi $extra -n "$k" -j 1 -x 2 -q -i "$img" -o "$OUT/eq.erd")
    fi
    # shellcheck disable=SC2086
    read -r _ ncpu _ < <("$TIMEIT" "$RUNS" "$ERD" generate -m erdgpi $extra -n "$n" -j 1 -x 2 -q -i "$img" -o "$OUT/eq.erd")
    ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a != "-" && b > 0) printf "%.2fx", a / b; else print "-" }'; }
    echo "| $label | $n | $p | $hcpu | $k | $kcpu | $(ratio "$kcpu" "$hcpu") | $ncpu | $(ratio "$ncpu" "$hcpu") |"
done
rm -f "$OUT/eq_synth2048.pgm" "$OUT/eq.stl" "$OUT/eq.erd"
