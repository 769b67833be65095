#!/usr/bin/env bash
# `make bench`: whole-process benchmarks (load, compute, write), medians of RUNS runs, peak RSS.
# Usage: bench/run.sh ERD_BINARY IMAGES_DIR        RUNS (default 7), CALLGRIND=1 adds instruction
# counts (valgrind --tool=callgrind, one run each; repeatable where wall times on a shared machine
# are not).
#
# Each helper adds its own clearly separated block below, calling bench_case.
#
# The tables users read are rewritten in place in docs/RESULTS.md, each in its own marked section
# (tools/results_section.sh; the rest of the file is left alone): "speed" (the scale block, beside
# hmm), "equal-quality" (beside hmm), "memory", "colour-cost", "terrain" (issue 47), and "heightmaps" when HEIGHTMAP_SIZES is given. A block that did
# not run leaves its section as it was. RESULTS=FILE writes them elsewhere, RESULTS=none nowhere.
set -u
ERD=${1:-build/erd}
IMAGES=${2:-../shared/images}
RUNS=${RUNS:-7}
CALLGRIND=${CALLGRIND:-0}
[[ $ERD == */* && $ERD != /* ]] && ERD=$PWD/$ERD
[[ $IMAGES != /* ]] && IMAGES=$PWD/$IMAGES
[[ -n ${RESULTS:-} && $RESULTS != none && $RESULTS != /* ]] && RESULTS=$PWD/$RESULTS
cd "$(dirname "$0")/.."
RESULTS=${RESULTS:-docs/RESULTS.md}
. tools/results_section.sh
# results_section MARK TITLE: reads the section's body on stdin and puts it, under its heading and
# the line saying when and where it was measured, in $RESULTS.
results_section() {
    [[ $RESULTS == none ]] && { cat >/dev/null; return; }
    {
        echo "<!-- $1: written by make bench (bench/run.sh); do not edit by hand -->"
        echo "## $2"
        echo
        echo "Written by \`make bench\` on $(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git rev-parse --short HEAD 2>/dev/null || echo '?');"
        echo "$(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg) at the end of the block."
        if awk -v l="$(cut -d' ' -f1 /proc/loadavg)" -v n="$(nproc)" 'BEGIN { exit !(l > n) }'; then
            echo "**A busy machine**: the load was above the core count, so other jobs shared it; times are slower"
            echo "and noisier than on a quiet machine. Compare the ratios measured side by side in this run."
        else
            echo "A quiet machine (load below the core count)."
        fi
        echo
        cat
        echo "<!-- /$1 -->"
    } >"$OUT/$1.section"
    put_section "$1" "$OUT/$1.section" "$RESULTS"
    echo "bench: wrote the $1 section of $RESULTS"
}
# Outputs go to tmpfs when there is one (BENCH_OUT overrides): the atomic writer fsyncs, and on
# a disk an fsync can cost more than the work being measured.
if [[ -n ${BENCH_OUT:-} ]]; then OUT=$BENCH_OUT
elif [[ -d /dev/shm && -w /dev/shm ]]; then OUT=$(mktemp -d /dev/shm/erd-bench-XXXXXX); trap 'rm -rf "$OUT"' EXIT
else OUT=out/bench; fi
mkdir -p "$OUT"
if [[ ! -x $ERD ]]; then echo "bench: $ERD is not built (try: make)"; exit 1; fi
# Whole-process cases are timed by bench/timeit.cpp (fork, exec, wait4: microsecond CPU times
# from the child's own rusage, no shell or /usr/bin/time in the measured interval).
TIMEIT=$(dirname "$ERD")/timeit
if ! ${CXX:-g++} -O2 -std=c++17 bench/timeit.cpp -o "$TIMEIT"; then echo "bench: bench/timeit.cpp did not build"; exit 1; fi

# bench_case NAME TARGET_MS -- COMMAND...   (one warm-up run, then RUNS timed runs; output discarded)
# Prints: name, median wall ms, median CPU ms (user+sys), peak RSS, target, and with CALLGRIND=1
# the instruction count of one run.
bench_case() {
    local name=$1 target=$2
    shift 3
    local wall cpu rss verdict ir=""
    read -r wall cpu rss < <("$TIMEIT" "$RUNS" "$@" || echo "- - -")
    verdict=$(awk -v w="$wall" -v t="$target" 'BEGIN { print (w != "-" && w <= t) ? "ok" : "over" }')
    if [[ $CALLGRIND == 1 ]] && command -v valgrind >/dev/null; then
        # erd at one thread: callgrind would count the greedy helper's spinning (kernel/step_helper.h).
        local one=(); [[ $1 == "$ERD" ]] && one=(-j 1)
        ir=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" "${one[@]}" 2>&1 >/dev/null |
             sed -n 's/.*Collected : \([0-9]*\).*/\1/p' | awk '{ printf "  %.0fM instr", $1 / 1e6 }')
    fi
    printf '%-34s wall %8s ms  cpu %6s ms  rss %7s KB  target %5s ms %-4s%s\n' "$name" "$wall" "$cpu" "$rss" "$target" "$verdict" "$ir"
}

echo "bench: $RUNS runs per case, medians; $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); outputs in $OUT"

# ---------------------------------------------------------------------------------------------
# basic (issue 5): ED and GPI, whole process: read the PGM, mesh, write the .model.
# Targets: gpi lena 1% <= 25 ms, gpi bull 1% <= 50 ms, ed bull 1% <= 40 ms.
if [[ -f $IMAGES/lena.pgm && -f $IMAGES/bull.pgm ]]; then
    bench_case "generate gpi lena 1%" 25 -- "$ERD" generate --method gpi -q -x 2 -d 1 -i "$IMAGES/lena.pgm" -o "$OUT/lena.gpi.model"
    bench_case "generate gpi bull 1%" 50 -- "$ERD" generate --method gpi -q -x 2 -d 1 -i "$IMAGES/bull.pgm" -o "$OUT/bull.gpi.model"
    bench_case "generate ed bull 1%" 40 -- "$ERD" generate --method ed -q -x 2 -d 1 -i "$IMAGES/bull.pgm" -o "$OUT/bull.ed.model"
else
    echo "basic: lena.pgm or bull.pgm missing in $IMAGES; skipped"
fi
# ---------------------------------------------------------------------------------------------
# ---------------------------------------------------------------------------------------------
# imaging (issue 4): edge detection through simplified polylines on bull (target <= 60 ms) and
# error diffusion with the exact-count search, K = 1% (target <= 30 ms); in-process medians of
# thread CPU time (bench/imaging_bench.cpp, built here against the library next to $ERD).
if [[ -f $IMAGES/bull.pgm && -f $(dirname "$ERD")/liberd.a ]]; then
    IMB=$(dirname "$ERD")/imaging_bench
    if ${CXX:-g++} -O2 -std=c++17 -I. bench/imaging_bench.cpp "$(dirname "$ERD")/liberd.a" -o "$IMB"; then
        "$IMB" "$IMAGES/bull.pgm" "$RUNS"
        if [[ $CALLGRIND == 1 ]] && command -v valgrind >/dev/null; then
            for c in edges ed; do
                valgrind --tool=callgrind --callgrind-out-file=/dev/null "$IMB" "$IMAGES/bull.pgm" 1 "$c" 2>&1 >/dev/null |
                    sed -n "s/.*Collected : \([0-9]*\).*/imaging $c: \1 instructions (one run, includes reading bull)/p"
            done
        fi
    else
        echo "imaging: bench/imaging_bench.cpp did not build; skipped"
    fi
else
    echo "imaging: bull.pgm or $(dirname "$ERD")/liberd.a missing; skipped"
fi
# ---------------------------------------------------------------------------------------------
# kernel (issue 3): the constrained Delaunay triangulation on 26,214 random distinct points of the
# 1023x1023 doubled lattice (a 512x512 image): batch Hilbert-order insertion (target <= 300 ns/point),
# one-by-one random order (< 2 us/point), 500 constraints of length ~30 (< 5 us each). In-process
# medians of thread CPU time (bench/kernel_bench.cpp, built here against the library next to $ERD).
if [[ -f $(dirname "$ERD")/liberd.a ]]; then
    KB=$(dirname "$ERD")/kernel_bench
    if ${CXX:-g++} -O2 -std=c++17 -I. bench/kernel_bench.cpp "$(dirname "$ERD")/liberd.a" -o "$KB"; then
        "$KB" "$RUNS"
        if [[ $CALLGRIND == 1 ]] && command -v valgrind >/dev/null; then
            for c in batch random constraints; do
                valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect="*phase_$c*" "$KB" 1 "$c" 2>&1 >/dev/null |
                    sed -n "s/.*Collected : \([0-9]*\).*/kernel $c: \1 instructions (one run of the phase)/p"
            done
        fi
    else
        echo "kernel: bench/kernel_bench.cpp did not build; skipped"
    fi
else
    echo "kernel: $(dirname "$ERD")/liberd.a missing; skipped"
fi
# ---------------------------------------------------------------------------------------------
# ---------------------------------------------------------------------------------------------
# remove (issue 45): vertex removal beside CGAL's Delaunay_triangulation_2::remove on the same
# points in the same order (bench/remove_bench.cpp): 1e5 and 1e6 random lattice points, a random
# half removed; medians of REMOVE_RUNS (default 5) of the thread CPU time per removed vertex, the
# two alternating, and their ratio (target erd <= 0.5x CGAL). CGAL (make deps-cgal installs it) is
# only ever linked into this benchmark and the tests; its glue is compiled here at -O2, once (about
# a minute; the tests' is -O1). With CALLGRIND=1, instructions per removed vertex at 1e5 as well.
if [[ -f $(dirname "$ERD")/liberd.a ]] && make -s deps-cgal >/dev/null 2>&1; then
    RB=$(dirname "$ERD")/remove_bench
    GLUE=$(dirname "$ERD")/bench/cgal_glue.o
    mkdir -p "$(dirname "$GLUE")"
    if [[ ! -f $GLUE || third_party/cgal_glue.cpp -nt $GLUE || third_party/cgal_glue.h -nt $GLUE ]]; then
        # CGAL checks the FPU's rounding modes at start-up, which valgrind does not emulate.
        ${CXX:-g++} -O2 -std=c++17 -I. -DCGAL_DISABLE_ROUNDING_MATH_CHECK -c third_party/cgal_glue.cpp -o "$GLUE" || rm -f "$GLUE"
    fi
    if [[ -f $GLUE ]] && ${CXX:-g++} -O2 -std=c++17 -I. bench/remove_bench.cpp "$GLUE" "$(dirname "$ERD")/liberd.a" -lgmp -lmpfr -o "$RB"; then
        "$RB" "${REMOVE_RUNS:-5}"
        if [[ $CALLGRIND == 1 ]] && command -v valgrind >/dev/null; then
            for side in erd cgal; do
                valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect="*phase_${side}_remove*" "$RB" 1 $side 100000 2>&1 >/dev/null |
                    sed -n "s/.*Collected : \([0-9]*\).*/\1/p" | awk -v s=$side '{ printf "remove %s: %.0f instructions per removed vertex (1e5 points, callgrind)\n", s, $1 / 50000 }'
            done
        fi
    else
        echo "remove: bench/remove_bench.cpp or the CGAL glue did not build; skipped"
    fi
else
    echo "remove: $(dirname "$ERD")/liberd.a or libcgal-dev (make deps-cgal) missing; skipped"
fi
# ---------------------------------------------------------------------------------------------
# erdmodel (issue 6): ERDGPI and ERDED, whole process: read the PGM, mesh, write the .erd.
# Targets: erdgpi lena 1% <= 75 ms, erdgpi bull 1% <= 150 ms, erded lena 1% <= 60 ms;
# peak RSS <= 64 bytes per pixel (lena 16384 KB, bull 49152 KB).
if [[ -f $IMAGES/lena.pgm && -f $IMAGES/bull.pgm ]]; then
    bench_case "generate erdgpi lena 1%" 75 -- "$ERD" generate --method erdgpi -q -x 2 -d 1 -i "$IMAGES/lena.pgm" -o "$OUT/lena.erdgpi.erd"
    bench_case "generate erdgpi bull 1%" 150 -- "$ERD" generate --method erdgpi -q -x 2 -d 1 -i "$IMAGES/bull.pgm" -o "$OUT/bull.erdgpi.erd"
    bench_case "generate erded lena 1%" 60 -- "$ERD" generate --method erded -q -x 2 -d 1 -i "$IMAGES/lena.pgm" -o "$OUT/lena.erded.erd"
    echo "erdmodel: RSS limits (64 B/pixel): lena 16384 KB, bull 49152 KB"
else
    echo "erdmodel: lena.pgm or bull.pgm missing in $IMAGES; skipped"
fi
# ---------------------------------------------------------------------------------------------
# removal (issue 45): the recommended ERDGPR beside 531d603's default (its ERDGPI, which this
# build's erdgpi reproduces byte for byte) at equal N. Target: ERDGPR <= 2.0x its CPU time, judged
# by callgrind instructions (repeatable) and the CPU medians, both at -j 1 (a second thread only
# adds CPU time). BASE_ERD: that commit's binary (default /work/base/erd-531d603, else this
# build's erdgpi).
BASE_ERD=${BASE_ERD:-/work/base/erd-531d603}
[[ -x $BASE_ERD ]] || BASE_ERD=$ERD
if [[ -f $IMAGES/lena.pgm && -f $IMAGES/bull.pgm ]]; then
    for c in "lena 1" "bull 0.25" "peppers 3"; do
        read -r name d <<<"$c"
        [[ -f $IMAGES/$name.pgm ]] || continue
        bench_case "generate erdgpr $name $d%" 1000 -- "$ERD" generate --method erdgpr -j 1 -q -x 2 -d "$d" -i "$IMAGES/$name.pgm" -o "$OUT/$name.erdgpr.erd"
        bench_case "base erdgpi $name $d%" 1000 -- "$BASE_ERD" generate --method erdgpi -j 1 -q -x 2 -d "$d" -i "$IMAGES/$name.pgm" -o "$OUT/$name.base.erd"
        if command -v valgrind >/dev/null; then
            a=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$ERD" generate --method erdgpr -j 1 -q -x 2 -d "$d" -i "$IMAGES/$name.pgm" -o "$OUT/$name.erdgpr.erd" 2>&1 >/dev/null | sed -n 's/.*Collected : \([0-9]*\).*/\1/p' | head -1)
            b=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$BASE_ERD" generate --method erdgpi -j 1 -q -x 2 -d "$d" -i "$IMAGES/$name.pgm" -o "$OUT/$name.base.erd" 2>&1 >/dev/null | sed -n 's/.*Collected : \([0-9]*\).*/\1/p' | head -1)
            awk -v a="$a" -v b="$b" -v c="$name $d%" 'BEGIN { if (a && b) printf "removal: erdgpr / base erdgpi %s: %.0fM / %.0fM instructions = %.2fx (target <= 2.0)\n", c, a / 1e6, b / 1e6, a / b }'
        fi
    done
fi
# ---------------------------------------------------------------------------------------------
# ---------------------------------------------------------------------------------------------
# raster (issue 6): reconstruct, whole process: read the model, rasterise, write the PGM.
# Target: 4x4 supersampled reconstruct of bull at 1% (ERDGPI model) <= 40 ms. Also point
# evaluation of the GPI model of bull at 1% (no target). The models are made once, untimed.
if [[ -f $IMAGES/bull.pgm ]] &&
   "$ERD" generate --method erdgpi -q -x 2 -d 1 -i "$IMAGES/bull.pgm" -o "$OUT/raster.bull.erd" >/dev/null 2>&1 &&
   "$ERD" generate --method gpi -q -x 2 -d 1 -i "$IMAGES/bull.pgm" -o "$OUT/raster.bull.model" >/dev/null 2>&1; then
    bench_case "reconstruct aa bull 1% (erdgpi)" 40 -- "$ERD" reconstruct "$OUT/raster.bull.erd" -o "$OUT/raster.bull.aa.pgm"
    bench_case "reconstruct bull 1% (gpi)" 40 -- "$ERD" reconstruct "$OUT/raster.bull.model" -o "$OUT/raster.bull.pgm"
else
    echo "raster: bull.pgm missing or erd generate failed; skipped"
fi
# ---------------------------------------------------------------------------------------------
# ---------------------------------------------------------------------------------------------
# scale (issue 18): whole process at -d 1 on `erd synth` images (8-bit with noise; a 16-bit
# heightmap without noise), and on the photos, side by side with fogleman/hmm when HMM_SRC names
# a local checkout of it (default: ../hmm beside the repository, when it holds hmm's Makefile;
# built here, outside the repository, into $OUT; nothing is downloaded), else against our GPI.
# hmm meshes to the same vertex count (-p N -e 0) and writes STL; the 16-bit heightmap is a PNG,
# which both read (hmm's reader takes 16 bits from PNG only). Targets: erdgpi and erded
# <= 1.0x hmm's CPU time, within 2x GPI; peak RSS <= 32 bytes per pixel for every method. erd
# runs at -j 1 here, as hmm: CPU time beside a one-thread program (a second thread only adds it).
# SCALE_SIZES (default "512 1024 2048") adds 4096 8192; SCALE_RUNS (default 3) runs per case.
# Each line has the CPU time per pixel, so the sizes make the growth table (docs/DECISIONS.md
# "Speed and growth"), and with CALLGRIND=1 the instructions per pixel up to SCALE_CALLGRIND_MAX.
# Writes the "speed" section of docs/RESULTS.md.
SCALE_SIZES=${SCALE_SIZES:-512 1024 2048}
SCALE_RUNS=${SCALE_RUNS:-3}
[[ -z ${HMM_SRC+set} && -f ../hmm/Makefile ]] && HMM_SRC=$(cd ../hmm && pwd)
HMM="" hmm_note="hmm: not available (HMM_SRC names no checkout of fogleman/hmm, and there is none at ../hmm)."
if [[ -n ${HMM_SRC:-} ]]; then
    if [[ -f $HMM_SRC/Makefile ]] && cp -r "$HMM_SRC" "$OUT/hmm-src" && make -s -C "$OUT/hmm-src" >/dev/null 2>&1 &&
       [[ -x $OUT/hmm-src/bin/release/hmm ]]; then
        HMM=$OUT/hmm-src/bin/release/hmm
        hmm_note="hmm: built by its own Makefile from the checkout in $HMM_SRC."
    else
        hmm_note="hmm: did not build from $HMM_SRC (it needs libglm-dev)."
        echo "scale: hmm did not build from $HMM_SRC (needs libglm-dev); comparing against gpi only"
    fi
fi
echo "scale: $hmm_note"
speed_rows=$OUT/speed.rows
: >"$speed_rows"
# scale_case LABEL IMAGE: one line per method: CPU ms, peak RSS in bytes per pixel, the ratio to
# hmm (or to GPI), and the B/px verdict.
# Extra generate flags after IMAGE (the ERD methods take them; e.g. --edges soft: synth is measured
# hard, and its noise under Canny is the heaviest step 1 there is).
scale_case() {
    local label=$1 img=$2 w h px n m wall cpu rss gcpu="" hcpu="" ref bpx verdict extra
    shift 2
    read -r w h < <("$ERD" info "$img" | awk '/^size:/ { print $2, $4 }')
    px=$((w * h)); n=$(( (px + 50) / 100 ))
    if [[ -n $HMM ]]; then
        read -r wall hcpu rss < <("$TIMEIT" "$SCALE_RUNS" "$HMM" -z 1 -e 0 -p "$n" -q "$img" "$OUT/scale.stl" || echo "- - -")
        if [[ $hcpu == - ]]; then hcpu=""; echo "scale $label: hmm could not mesh it"
        else
            printf 'scale %-16s %-7s cpu %8s ms  %6s B/px\n' "$label" hmm "$hcpu" "$(awk -v r="$rss" -v p="$px" 'BEGIN { printf "%.1f", r * 1024 / p }')"
            echo "$label|$w x $h|hmm|$hcpu|" >>"$speed_rows"
        fi
    fi
    for m in gpi ed erded erdgpi; do
        extra=(); [[ $m == erd* ]] && extra=("$@")
        read -r wall cpu rss < <("$TIMEIT" "$SCALE_RUNS" "$ERD" generate --method "$m" "${extra[@]}" -j 1 -q -x 2 -n "$n" -i "$img" -o "$OUT/scale.$m" || echo "- - -")
        [[ $m == gpi ]] && gcpu=$cpu
        ref=${hcpu:-$gcpu}
        echo "$label|$w x $h|$m|$cpu|$(awk -v c="$cpu" -v r="$ref" 'BEGIN { if (c != "-" && r > 0) printf "%.2fx", c / r }')" >>"$speed_rows"
        bpx=$(awk -v r="$rss" -v p="$px" 'BEGIN { printf "%.1f", r * 1024 / p }')
        verdict=$(awk -v b="$bpx" 'BEGIN { print (b <= 32) ? "ok" : "over" }')
        # The growth columns: CPU ns per pixel, and with CALLGRIND=1 instructions per pixel (sizes
        # up to SCALE_CALLGRIND_MAX, default 1024: callgrind runs about 50 times slower).
        ipx=""
        if [[ $CALLGRIND == 1 && $w -le ${SCALE_CALLGRIND_MAX:-1024} ]] && command -v valgrind >/dev/null; then
            ipx=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$ERD" generate --method "$m" "${extra[@]}" -j 1 -q -x 2 -n "$n" -i "$img" \
                      -o "$OUT/scale.$m" 2>&1 | sed -n 's/.*Collected : \([0-9]*\).*/\1/p' | sort -n | tail -1)
            ipx=$(awk -v i="$ipx" -v p="$px" 'BEGIN { if (i > 0) printf "  %.0f instr/px", i / p }')
        fi
        printf 'scale %-16s %-7s cpu %8s ms  %6s ns/px  %6s B/px %-4s  %s%s\n' "$label" "$m" "$cpu" \
            "$(awk -v c="$cpu" -v p="$px" 'BEGIN { printf "%.0f", c * 1e6 / p }')" "$bpx" "$verdict" \
            "$(awk -v c="$cpu" -v r="$ref" -v h="$hcpu" -v g="$gcpu" 'BEGIN { if (r > 0) printf "%.2fx %s", c / r, (h != "" ? "hmm" : "gpi");
                                                                     if (h != "" && g > 0) printf "  %.2fx gpi", c / g }')" "$ipx"
    done
}
for s in $SCALE_SIZES; do
    "$ERD" synth -q -W "$s" -H "$s" -o "$OUT/synth$s.pgm" && scale_case "synth $s" "$OUT/synth$s.pgm" &&
        scale_case "synth $s soft" "$OUT/synth$s.pgm" --edges soft &&
        scale_case "synth $s soft, l" "$OUT/synth$s.pgm" --edges soft --lower-beta 0
    "$ERD" synth -q -W "$s" -H "$s" --bits 16 --no-noise -o "$OUT/height$s.png" && scale_case "height16 $s" "$OUT/height$s.png"
done
for f in lena bull; do [[ -f $IMAGES/$f.pgm ]] && scale_case "$f" "$IMAGES/$f.pgm"; done
rm -f "$OUT"/synth*.pgm "$OUT"/height*.png "$OUT"/scale.*
# The table: one row per image, CPU ms of each program with its ratio to hmm (or to gpi) beside it.
if [[ -s $speed_rows ]]; then
    {
        echo "Whole \`erd generate -j 1\` process (read, mesh, write; one thread, as hmm) at 1% of the pixels as vertices, CPU milliseconds,"
        echo "medians of $SCALE_RUNS runs after a warm-up, each program on the same image one after the other in one"
        echo "run. synth = \`erd synth\` (8-bit, noise; its edges measure hard), \"soft\" = the same with"
        echo "\`--edges soft\` for the ERD methods (Canny on noise: the heaviest step 1 there is), \"soft, l\" = that with"
        echo "\`--lower-beta 0\` (the parameter loop on one detection), height16 = a 16-bit heightmap without noise (PNG)."
        if [[ -n $HMM ]]; then echo "hmm meshes to the same vertex count (\`hmm -z 1 -e 0 -p N\`, STL out). In brackets: the ratio to hmm's CPU time."
        else echo "In brackets: the ratio to erd gpi's CPU time."; fi
        echo "$hmm_note"
        echo
        if [[ -n $HMM ]]; then echo "| image | size | hmm | gpi | ed | erdgpi | erded |"; echo "|---|---|---:|---:|---:|---:|---:|"
        else echo "| image | size | gpi | ed | erdgpi | erded |"; echo "|---|---|---:|---:|---:|---:|"; fi
        awk -F'|' -v hmm="$HMM" '
            !($1 in seen) { seen[$1] = 1; order[++n] = $1; size[$1] = $2 }
            { cell[$1, $3] = ($5 != "" ? $4 " (" $5 ")" : $4) }
            END {
                split(hmm != "" ? "hmm gpi ed erdgpi erded" : "gpi ed erdgpi erded", ms, " ")
                for (i = 1; i <= n; ++i) {
                    row = "| " order[i] " | " size[order[i]]
                    for (j = 1; j in ms; ++j) row = row " | " ((order[i], ms[j]) in cell ? cell[order[i], ms[j]] : "-")
                    print row " |"
                }
            }' "$speed_rows"
        echo
        echo "Targets (issue 18): erdgpi and erded at or below 1.0x hmm, within 2x gpi; peak memory in the"
        echo "memory section."
    } | results_section speed "Speed beside hmm (make bench, scale block)"
fi
# Equal quality beside hmm (issue 46): bench/equal_quality.sh (hmm's PSNR at 1%, the erdgpi count
# that reaches it by --psnr, both timed). Writes the "equal-quality" section of docs/RESULTS.md.
if [[ -n $HMM ]]; then
    eq_table=$(bench/equal_quality.sh "$HMM" "$ERD" "$IMAGES" "$OUT" "$SCALE_RUNS")
    echo "$eq_table" | sed 's/^/quality /'
    {
        echo "hmm meshes 1% of the pixels (\`hmm -z 1 -e 0 -p N\`); its PSNR is its STL evaluated at every pixel"
        echo "(bench/stl_psnr.py); erdgpi's count is the fewest points whose model reaches that PSNR"
        echo "(\`erd generate -m erdgpi -d 1 --psnr P\`, found within 2%). Whole process CPU ms (erd at -j 1), medians of"
        echo "$SCALE_RUNS runs after a warm-up, one program after the other; ratio = erdgpi / hmm. synth 2048 soft:"
        echo "\`erd synth\` 2048^2 with \`--edges soft\` for erdgpi; \", --lower-beta 0\": erdgpi with the parameter loop"
        echo "on one detection. Targets (issue 46): equal quality <= 0.5x, equal points <= 1.0x."
        echo
        echo "$eq_table"
    } | results_section equal-quality "Equal quality beside hmm (make bench, issue 46)"
fi
# ---------------------------------------------------------------------------------------------
# ---------------------------------------------------------------------------------------------
# memory (issues 18, 19): the peak memory of every method at -d 1 and 0.1, one run per case,
# whole process (getrusage from --stats), on `erd synth` images (hard by measurement, and soft
# with --edges soft: its noise under Canny is the edge-richest step 1 there is), 16-bit
# heightmaps and the photos. Targets: peak <= 32 bytes per pixel; the estimate the memory cap
# compares (memory_estimate_bytes) within 25% of the peak. MEM_SIZES (default "512 1024 2048";
# "4096 8192" for the issue's whole range), MEM_DENSITIES (default "1 0.1"). Writes the "memory"
# section of docs/RESULTS.md.
MEM_SIZES=${MEM_SIZES:-512 1024 2048}
MEM_DENSITIES=${MEM_DENSITIES:-1 0.1}
mem_over=0 mem_off=0 mem_cases=0
mem_rows=$OUT/memory.rows
: >"$mem_rows"
# mem_case LABEL IMAGE [ERD FLAGS...]: one line per method and density.
mem_case() {
    local label=$1 img=$2 w h px d m peak est extra bpx err
    shift 2
    read -r w h < <("$ERD" info "$img" | awk '/^size:/ { print $2, $4 }')
    px=$((w * h))
    for d in $MEM_DENSITIES; do
        for m in gpi ed erded erdgpi; do
            [[ $# -gt 0 && $m != erd* ]] && continue  # the flags are the ERD methods': gpi and ed ran already
            extra=(); [[ $m == erd* ]] && extra=("$@")
            rm -f "$OUT/mem.json"
            if ! "$ERD" generate --method "$m" "${extra[@]}" -q -x 2 -d "$d" -i "$img" -o "$OUT/mem.$m" --stats "$OUT/mem.json" >/dev/null 2>&1; then
                echo "memory $label $m -d $d: erd generate failed"; mem_over=$((mem_over + 1)); continue
            fi
            peak=$(sed -n 's/.*"peak_memory_bytes":\([0-9]*\).*/\1/p' "$OUT/mem.json")
            est=$(sed -n 's/.*"memory_estimate_bytes":\([0-9]*\).*/\1/p' "$OUT/mem.json")
            bpx=$(awk -v r="$peak" -v p="$px" 'BEGIN { printf "%.1f", r / p }')
            err=$(awk -v e="$est" -v r="$peak" 'BEGIN { printf "%+.0f", 100 * (e / r - 1) }')
            awk -v b="$bpx" 'BEGIN { exit !(b > 32) }' && mem_over=$((mem_over + 1))
            awk -v e="$err" 'BEGIN { exit !(e > 25 || e < -25) }' && mem_off=$((mem_off + 1))
            mem_cases=$((mem_cases + 1))
            echo "$label|$d|$m|$(awk -v r="$peak" 'BEGIN { printf "%.1f", r / 1048576 }'), $bpx, $err%" >>"$mem_rows"
            printf 'memory %-16s -d %-4s %-7s peak %8.1f MB %6s B/px %-4s  estimate %8.1f MB %5s%% %s\n' "$label" "$d" "$m" \
                "$(awk -v r="$peak" 'BEGIN { printf "%.1f", r / 1048576 }')" "$bpx" \
                "$(awk -v b="$bpx" 'BEGIN { print (b <= 32) ? "ok" : "over" }')" \
                "$(awk -v e="$est" 'BEGIN { printf "%.1f", e / 1048576 }')" "$err" \
                "$(awk -v e="$err" 'BEGIN { print (e <= 25 && e >= -25) ? "ok" : "off" }')"
        done
    done
}
for s in $MEM_SIZES; do
    if "$ERD" synth -q -W "$s" -H "$s" -o "$OUT/msynth$s.pgm"; then
        mem_case "synth $s" "$OUT/msynth$s.pgm"
        mem_case "synth $s soft" "$OUT/msynth$s.pgm" --edges soft
    fi
    "$ERD" synth -q -W "$s" -H "$s" --bits 16 --no-noise -o "$OUT/mheight$s.pgm" && mem_case "height16 $s" "$OUT/mheight$s.pgm"
    rm -f "$OUT/msynth$s.pgm" "$OUT/mheight$s.pgm"
done
for f in lena peppers bull; do [[ -f $IMAGES/$f.pgm ]] && mem_case "$f" "$IMAGES/$f.pgm"; done
rm -f "$OUT"/mem.*
echo "memory: $mem_cases cases: $mem_over above 32 B/px, $mem_off with the estimate more than 25% off the peak"
if [[ -s $mem_rows ]]; then
    {
        echo "Peak resident memory of the whole \`erd generate\` process (getrusage, from \`--stats\`), one run a"
        echo "case: MB, bytes per pixel, and the error of the estimate the memory cap compares"
        echo "(\`memory_estimate_bytes\`, from the image read) against that peak. Images as in the speed section"
        echo "(the heightmaps as 16-bit PGM) and peppers; \"soft\" rows run the ERD methods with \`--edges soft\` only."
        echo
        echo "| image | -d | gpi | ed | erded | erdgpi |"
        echo "|---|---:|---:|---:|---:|---:|"
        awk -F'|' '
            !(($1, $2) in seen) { seen[$1, $2] = 1; order[++n] = $1 SUBSEP $2 }
            { cell[$1, $2, $3] = $4 }
            END {
                split("gpi ed erded erdgpi", ms, " ")
                for (i = 1; i <= n; ++i) {
                    split(order[i], k, SUBSEP); row = "| " k[1] " | " k[2]
                    for (j = 1; j <= 4; ++j) row = row " | " ((k[1], k[2], ms[j]) in cell ? cell[k[1], k[2], ms[j]] : "-")
                    print row " |"
                }
            }' "$mem_rows"
        echo
        echo "$mem_cases cases: $mem_over above 32 B/px, $mem_off with the estimate more than 25% off the peak"
        echo "(targets, issues 18 and 19: none of either)."
    } | results_section memory "Peak memory and its estimate (make bench, memory block)"
fi
# ---------------------------------------------------------------------------------------------
# heightmaps (issue 18; only with HEIGHTMAP_SIZES, e.g. "4096 9490": hmm's headline case is
# 9490 x 9490, and hmm takes minutes there): a 16-bit `erd synth --no-noise` heightmap meshed to
# hmm's default error, 0.001 of the range (hmm -z 1 -e 0.001; erd --max-error 65.535 with -d 5 as
# the upper bound), and to 1% of the pixels as vertices. One run each (no warm-up): triangles,
# CPU time, peak RSS. Writes the "heightmaps" section of docs/RESULTS.md.
if [[ -n ${HEIGHTMAP_SIZES:-} ]]; then
    hm_rows=$OUT/heightmaps.rows
    : >"$hm_rows"
    # hm_run LABEL PROGRAM COMMAND...: one row "label|program|triangles|CPU s|peak MB".
    hm_run() {
        local label=$1 prog=$2 wall cpu rss tri=-
        shift 2
        rm -f "$OUT/hm.json" "$OUT/hm.stl"
        read -r wall cpu rss < <(TIMEIT_WARMUP=0 "$TIMEIT" 1 "$@" || echo "- - -")
        if [[ $prog == hmm && -f $OUT/hm.stl ]]; then tri=$(od -An -tu4 -j80 -N4 "$OUT/hm.stl" | tr -d ' ')
        elif [[ -f $OUT/hm.json ]]; then tri=$(sed -n 's/.*"faces":\([0-9]*\).*/\1/p' "$OUT/hm.json"); fi
        echo "$label|$prog|$tri|$(awk -v c="$cpu" 'BEGIN { if (c != "-") printf "%.1f", c / 1000; else print "-" }')|$(awk -v r="$rss" 'BEGIN { if (r != "-") printf "%.0f", r / 1024; else print "-" }')" | tee -a "$hm_rows"
    }
    for s in $HEIGHTMAP_SIZES; do
        "$ERD" synth -q -W "$s" -H "$s" --bits 16 --no-noise -o "$OUT/hm$s.png" || continue
        n=$(( (s * s + 50) / 100 ))
        [[ -n $HMM ]] && hm_run "$s error" hmm "$HMM" -z 1 -e 0.001 -q "$OUT/hm$s.png" "$OUT/hm.stl"
        for m in gpi erdgpi; do
            hm_run "$s error" "$m" "$ERD" generate -q -m "$m" -d 5 --max-error 65.535 --count-search 0 -x 2 -i "$OUT/hm$s.png" -o "$OUT/hm.$m" --stats "$OUT/hm.json"
        done
        [[ -n $HMM ]] && hm_run "$s 1%" hmm "$HMM" -z 1 -e 0 -p "$n" -q "$OUT/hm$s.png" "$OUT/hm.stl"
        for m in gpi erdgpi erded; do
            hm_run "$s 1%" "$m" "$ERD" generate -q -m "$m" -x 2 -n "$n" -i "$OUT/hm$s.png" -o "$OUT/hm.$m" --stats "$OUT/hm.json"
        done
        rm -f "$OUT/hm$s.png" "$OUT"/hm.*
    done
    {
        echo "A 16-bit heightmap made by \`erd synth -W S -H S --bits 16 --no-noise\` (sharp steps and discs on"
        echo "smooth slopes), as PNG, meshed (a) to a maximum error of 0.001 of the 65535 range, hmm's default"
        echo "(\`hmm -z 1 -e 0.001\`; \`erd generate -d 5 --max-error 65.535 --count-search 0 -x 2\`: one run, as hmm), and (b) to 1% of the pixels as"
        echo "vertices (\`hmm -z 1 -e 0 -p N\`; \`erd generate -n N\`). One run each: triangles, CPU seconds, peak MB."
        echo "$hmm_note"
        echo
        echo "| size, target | hmm | erd gpi | erd erdgpi | erd erded |"
        echo "|---|---:|---:|---:|---:|"
        awk -F'|' '
            !($1 in seen) { seen[$1] = 1; order[++n] = $1 }
            { cell[$1, $2] = $3 " tri, " $4 " s, " $5 " MB" }
            END {
                split("hmm gpi erdgpi erded", ms, " ")
                for (i = 1; i <= n; ++i) {
                    split(order[i], k, " "); row = "| " k[1] " x " k[1] ", " (k[2] == "error" ? "max error 0.001" : "1% vertices")
                    for (j = 1; j <= 4; ++j) row = row " | " ((order[i], ms[j]) in cell ? cell[order[i], ms[j]] : "-")
                    print row " |"
                }
            }' "$hm_rows"
    } | results_section heightmaps "Heightmaps at hmm's sizes (make bench with HEIGHTMAP_SIZES)"
else
    echo "heightmaps: HEIGHTMAP_SIZES not given (e.g. \"4096 9490\"); skipped"
fi
# ---------------------------------------------------------------------------------------------
# colour (issue 17): each method on the seven colour images (Kodak kodim01-06, house) at 0.5, 1
# and 2%, `erd generate` on the PPM beside `erd generate` on a PGM of its luma (BT.601, written by
# tools/eval_colour.cpp --write-luma), alternating within one run: CPU medians of COLOUR_RUNS
# (default 3) runs and peak RSS per case, then per method the median and the worst of the 21
# ratios. With CALLGRIND=1 also the instruction ratio of each 1% case (the parent process: erd
# forks its output commit). Targets: colour <= 1.6x the CPU time and <= 1.5x the peak memory of
# gray (medians).
COLOUR_DIR=$IMAGES/color
EVC=$(dirname "$ERD")/eval_colour
if [[ -d $COLOUR_DIR && -f $(dirname "$ERD")/liberd.a ]] &&
   ${CXX:-g++} -O2 -std=c++17 -I. tools/eval_colour.cpp "$(dirname "$ERD")/liberd.a" -o "$EVC"; then
    colour_rows=$OUT/colour.rows
    : >"$colour_rows"
    for f in kodim01 kodim02 kodim03 kodim04 kodim05 kodim06 house_color; do
        img=$COLOUR_DIR/$f.ppm
        [[ -f $img ]] || continue
        "$EVC" --write-luma "$OUT/luma.pgm" gpi 1 "$img" || continue
        for m in gpi ed erdgpi erded; do
            out=$OUT/c.model; [[ $m == erd* ]] && out=$OUT/c.erd
            for d in 0.5 1 2; do
                read -r _ gcpu grss < <("$TIMEIT" "${COLOUR_RUNS:-3}" "$ERD" generate -q -m "$m" -d "$d" -i "$OUT/luma.pgm" -o "$out" || echo "- - -")
                read -r _ ccpu crss < <("$TIMEIT" "${COLOUR_RUNS:-3}" "$ERD" generate -q -m "$m" -d "$d" -i "$img" -o "$out" || echo "- - -")
                gi=- ci=-
                if [[ $CALLGRIND == 1 && $d == 1 ]] && command -v valgrind >/dev/null; then
                    for side in gray colour; do
                        src=$img; [[ $side == gray ]] && src=$OUT/luma.pgm
                        n=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$ERD" generate -q -m "$m" -d "$d" -i "$src" -o "$out" 2>&1 >/dev/null |
                            sed -n 's/.*Collected : \([0-9]*\).*/\1/p' | head -1)
                        if [[ $side == gray ]]; then gi=$n; else ci=$n; fi
                    done
                fi
                echo "$m $f $d $gcpu $ccpu $grss $crss $gi $ci" >>"$colour_rows"
            done
        done
    done
    rm -f "$OUT/luma.pgm" "$OUT/c.model" "$OUT/c.erd"
    awk '
        $4 != "-" && $5 != "-" && $4 > 0 && $6 > 0 {
            t = $5 / $4; r = $7 / $6
            printf "colour %-6s %-7s %3s%%: cpu gray %7.1f ms colour %7.1f ms = %.2fx  rss gray %6d KB colour %6d KB = %.2fx%s\n",
                $1, $2, $3, $4, $5, t, $6, $7, r, ($8 != "-" && $9 != "-" && $8 > 0) ? sprintf("  instr %.0fM / %.0fM = %.2fx", $9 / 1e6, $8 / 1e6, $9 / $8) : ""
            n[$1]++; T[$1, n[$1]] = t; R[$1, n[$1]] = r
        }
        function median(A, m, k,   i, j, v, x) {
            for (i = 1; i <= k; ++i) v[i] = A[m, i]
            for (i = 2; i <= k; ++i) for (j = i; j > 1 && v[j - 1] > v[j]; --j) { x = v[j]; v[j] = v[j - 1]; v[j - 1] = x }
            return k % 2 ? v[(k + 1) / 2] : (v[k / 2] + v[k / 2 + 1]) / 2
        }
        function worst(A, m, k,   i, w) { w = 0; for (i = 1; i <= k; ++i) if (A[m, i] > w) w = A[m, i]; return w }
        END {
            split("gpi ed erdgpi erded", ms, " ")
            for (i = 1; i <= 4; ++i) if (n[ms[i]])
                printf "colour %-6s %d cases: cpu median %.2fx worst %.2fx (target 1.6x)  rss median %.2fx worst %.2fx (target 1.5x)\n",
                    ms[i], n[ms[i]], median(T, ms[i], n[ms[i]]), worst(T, ms[i], n[ms[i]]), median(R, ms[i], n[ms[i]]), worst(R, ms[i], n[ms[i]])
        }' "$colour_rows" | tee "$OUT/colour.out"
    # The medians go to the "colour-cost" section of docs/RESULTS.md.
    if grep -q ' cases: ' "$OUT/colour.out"; then
        {
            echo "\`erd generate\` on each colour PPM beside the same method on a PGM of its luma, whole process,"
            echo "default threads (the CPU time counts them all), the colour images (Kodak kodim01-06, house) at 0.5,"
            echo "1 and 2% ($(awk '/ cases: / { print $3; exit }' "$OUT/colour.out") cases a method), CPU medians of ${COLOUR_RUNS:-3} runs and peak RSS per case; the"
            echo "table gives the median and the worst of the ratios."
            echo
            echo "| method | CPU time median | worst | peak RSS median | worst |"
            echo "|---|---:|---:|---:|---:|"
            awk '/ cases: / { printf "| %s | %s | %s | %s | %s |\n", $2, $7, $9, $14, $16 }' "$OUT/colour.out"
            echo
            echo "Targets: CPU time <= 1.6x and peak memory <= 1.5x (medians)."
        } | results_section colour-cost "Colour cost (issue 17): colour over gray on the luma"
    fi
else
    echo "colour: $COLOUR_DIR or tools/eval_colour.cpp (against $(dirname "$ERD")/liberd.a) missing; skipped"
fi
# ---------------------------------------------------------------------------------------------
# terrain (issue 47): real elevation data to a bound in metres, beside hmm. Debian's two real DEMs
# (python-matplotlib-data, written by tests/dem_data.py as float32 GeoTIFF and 16-bit PNG) and a
# TERRAIN_SIZE^2 (default 8192) `erd synth --kind dem` model (float32 with nodata lakes; its PNG
# has the holes filled with the nearest height), each meshed to E = TERRAIN_FRACTION (default
# 0.005) of its range: erd's ERD method (`erdgpi --max-error E`) and GPI on the float GeoTIFF, hmm
# (`hmm -z 1 -e E/range`) on the 16-bit PNG, its only input. One line per program: triangles, CPU
# seconds and peak memory (medians of TERRAIN_RUNS, default 3; 1 for the large model), and erd's
# largest error over the valid pixels measured by numpy on its reconstruction (tests/raster_check.py;
# hmm's is its own bound on the 16-bit data). Targets: erdgpi has fewer triangles and less CPU time
# than hmm. TERRAIN_SIZE=0 leaves the large model out. Writes the "terrain" section.
TERRAIN_SIZE=${TERRAIN_SIZE:-8192}
TERRAIN_FRACTION=${TERRAIN_FRACTION:-0.005}
TERRAIN_RUNS=${TERRAIN_RUNS:-3}
if mkdir -p "$OUT/dem" && /usr/bin/python3 tests/dem_data.py "$OUT/dem" >"$OUT/dem/ranges"; then
    terrain_rows=$OUT/terrain.rows
    : >"$terrain_rows"
    dems="jacksboro topobathy"
    if [[ $TERRAIN_SIZE -gt 0 ]]; then
        "$ERD" synth -q --kind dem -W "$TERRAIN_SIZE" -H "$TERRAIN_SIZE" -o "$OUT/dem/synth.tif" &&
            "$ERD" synth -q --kind dem -W "$TERRAIN_SIZE" -H "$TERRAIN_SIZE" -o "$OUT/dem/synth.pfm" &&
            "$ERD" synth -q --kind dem -W "$TERRAIN_SIZE" -H "$TERRAIN_SIZE" -o "$OUT/dem/synth.png" &&
            "$ERD" info --json "$OUT/dem/synth.tif" | /usr/bin/python3 -c "import json, sys; d = json.load(sys.stdin); print('synth', d['width'], d['height'], d['min'], d['max'])" >>"$OUT/dem/ranges" &&
            dems="$dems synth"
    fi
    for dem in $dems; do
        read -r _ w h lo hi < <(awk -v n=$dem '$1 == n' "$OUT/dem/ranges")
        E=$(awk -v a="$lo" -v b="$hi" -v f="$TERRAIN_FRACTION" 'BEGIN { printf "%.6g", (b - a) * f }')
        e=$(awk -v a="$lo" -v b="$hi" -v E="$E" 'BEGIN { printf "%.9g", E / (b - a) }')
        runs=$TERRAIN_RUNS; [[ $dem == synth ]] && runs=1
        orig=$OUT/dem/$dem.npy; [[ $dem == synth ]] && orig=$OUT/dem/synth.pfm
        label="$dem $w x $h, E $E m"
        if [[ -n $HMM ]]; then
            read -r _ cpu rss < <("$TIMEIT" "$runs" "$HMM" -z 1 -e "$e" -q "$OUT/dem/$dem.png" "$OUT/dem/hmm.stl" || echo "- - -")
            tri=$("$HMM" -z 1 -e "$e" "$OUT/dem/$dem.png" "$OUT/dem/hmm.stl" 2>&1 | awk '/triangles =/ { print $3 }')
            echo "$label|hmm|$tri|$cpu|$rss|<= $E (its bound on the 16-bit PNG)" | tee -a "$terrain_rows"
        fi
        for m in erdgpi gpi; do
            ext=model; [[ $m == erd* ]] && ext=erd
            # N a cap only: every pixel for the small models, 5% of the large one (which needs 0.04%).
            dens=100; [[ $dem == synth ]] && dens=5
            args=(generate -m $m -i "$OUT/dem/$dem.tif" -d $dens -x 2 --max-error "$E" --max-memory 0 -j 1 -q -o "$OUT/dem/t.$ext")
            read -r _ cpu rss < <("$TIMEIT" "$runs" "$ERD" "${args[@]}" || echo "- - -")
            "$ERD" "${args[@]}" --stats "$OUT/dem/t.json" && "$ERD" reconstruct -q "$OUT/dem/t.$ext" -o "$OUT/dem/t.pfm" || continue
            tri=$(/usr/bin/python3 -c "import json; print(json.load(open('$OUT/dem/t.json'))['faces'])")
            err=$(/usr/bin/python3 tests/raster_check.py maxerr "$orig" "$OUT/dem/t.pfm" "$E" | awk '/^max error/ { print $3; exit }')
            echo "$label|erd $m|$tri|$cpu|$rss|$err" | tee -a "$terrain_rows"
        done
        rm -f "$OUT"/dem/t.* "$OUT/dem/hmm.stl"
    done
    if [[ -s $terrain_rows ]]; then
        {
            echo "Each model meshed to a largest error E of $TERRAIN_FRACTION of its range (metres): erd on the float32 GeoTIFF"
            echo "(\`erd generate -m erdgpi|gpi -d 100 -x 2 --max-error E\`; -d 5 for synth: N only a cap), hmm on the same model quantised to a 16-bit PNG"
            echo "(\`hmm -z 1 -e E/range\`; the synthetic model's nodata filled with the nearest height there). jacksboro and"
            echo "topobathy: Debian's python-matplotlib-data DEMs (tests/dem_data.py); synth: \`erd synth --kind dem\`"
            echo "(faults, a mesa, nodata lakes and corner). CPU seconds and peak memory of the whole process, medians of"
            echo "$TERRAIN_RUNS runs (1 for synth). erd's largest error is numpy's, over the valid pixels of its"
            echo "reconstruction (float32 rounding aside). ${hmm_note:-}"
            echo
            echo "| DEM | program | triangles | CPU s | peak MB | largest error |"
            echo "|---|---|---:|---:|---:|---|"
            awk -F'|' '{ printf "| %s | %s | %s | %.2f | %.0f | %s |\n", $1, $2, $3, $4 / 1000, $5 / 1024, $6 }' "$terrain_rows"
            echo
            # The verdict per DEM: erdgpi / hmm in triangles and in CPU time (< 1 meets the target).
            awk -F'|' '$2 == "hmm" { tri[$1] = $3; cpu[$1] = $4 }
                       $2 == "erd erdgpi" && ($1 in tri) && tri[$1] > 0 && cpu[$1] > 0 {
                           printf "- %s: erdgpi / hmm triangles %.2f, CPU %.2f (%s)\n", $1, $3 / tri[$1], $4 / cpu[$1],
                                  ($3 < tri[$1] && $4 < cpu[$1]) ? "met" : "not met" }' "$terrain_rows"
            echo
            echo "Targets (issue 47): erdgpi within E everywhere, with fewer triangles and less CPU time than hmm."
        } | results_section terrain "Terrain beside hmm (issue 47; make bench, terrain block)"
    fi
    rm -rf "$OUT/dem"
else
    echo "terrain: tests/dem_data.py failed (python3-numpy, python-matplotlib-data?); skipped"
fi
# ---------------------------------------------------------------------------------------------
# threads (issue 18, "Two cores"): the image stages (MMSODD, density, reconstruction, PSNR, edge
# detection's gradient pass, the refit; kernel/row_parallel.h) and the greedy's re-scans
# (kernel/step_helper.h) at -j 1 and -j 2, whole process. The two alternate run by run (one
# warm-up each first), so both see the same load; medians of THREADS_RUNS (default 3) wall and
# CPU times, the speed-up (wall at -j 1 / wall at -j 2) and the CPU time -j 2 adds. Each method
# at -d 1 on lena and on `erd synth` images of THREADS_SIZES (default 2048; 4096 adds a minute
# or more), then erd reconstruct (4x4, the ERDGPI model) and erd psnr. Issue 46's target: a
# speed-up >= 1.54x (-j 2 <= 0.65x of -j 1) at 2048^2 for every method, on a quiet machine; on
# 2 cores shared with others the speed-up is what the load leaves.
THREADS_SIZES=${THREADS_SIZES:-2048}
THREADS_RUNS=${THREADS_RUNS:-3}
# threads_pair LABEL ERD_ARGS...: one line, -j 1 beside -j 2.
threads_pair() {
    local label=$1 r j w c x
    shift
    local -a w1=() c1=() w2=() c2=()
    for j in 1 2; do "$ERD" "$@" -j "$j" >/dev/null 2>&1 || { echo "threads $label: erd $* -j $j failed"; return; }; done
    for ((r = 0; r < THREADS_RUNS; ++r)); do
        for j in 1 2; do
            read -r w c x < <(TIMEIT_WARMUP=0 "$TIMEIT" 1 "$ERD" "$@" -j "$j" || echo "- - -")
            if [[ $j == 1 ]]; then w1+=("$w"); c1+=("$c"); else w2+=("$w"); c2+=("$c"); fi
        done
    done
    med() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
    local mw1 mc1 mw2 mc2
    mw1=$(med "${w1[@]}"); mc1=$(med "${c1[@]}"); mw2=$(med "${w2[@]}"); mc2=$(med "${c2[@]}")
    printf 'threads %-32s -j 1 wall %8s cpu %8s ms   -j 2 wall %8s cpu %8s ms   speed-up %s\n' "$label" "$mw1" "$mc1" "$mw2" "$mc2" \
        "$(awk -v a="$mw1" -v b="$mw2" -v c="$mc1" -v d="$mc2" 'BEGIN { if (b > 0 && c > 0) printf "%.2fx (cpu %+.0f%%)", a / b, 100 * (d / c - 1) }')"
}
echo "threads: load $(cut -d' ' -f1-3 /proc/loadavg) before"
threads_images=()
[[ -f $IMAGES/lena.pgm ]] && threads_images+=("lena:$IMAGES/lena.pgm")
for s in $THREADS_SIZES; do
    "$ERD" synth -q -W "$s" -H "$s" -o "$OUT/threads$s.pgm" && threads_images+=("synth$s:$OUT/threads$s.pgm")
done
for entry in "${threads_images[@]}"; do
    label=${entry%%:*} img=${entry#*:}
    for m in ed gpi erded erdgpi erdgpr; do
        ext=model; [[ $m == erd* ]] && ext=erd
        threads_pair "$m $label 1%" generate -m "$m" -q -x 2 -d 1 -i "$img" -o "$OUT/threads.$m.$ext"
    done
    # The ERDGPI model just written (soft edges for the 4x4 reconstruction: synth's are hard).
    "$ERD" generate -m erdgpi -q -x 2 -d 1 --edges soft -i "$img" -o "$OUT/threads.soft.erd" -j 2 &&
        threads_pair "reconstruct 4x4 $label" reconstruct "$OUT/threads.soft.erd" -o "$OUT/threads.rec.pgm" &&
        threads_pair "reconstruct point $label" reconstruct --no-aa "$OUT/threads.soft.erd" -o "$OUT/threads.rec.pgm" &&
        threads_pair "psnr $label" psnr "$img" "$OUT/threads.rec.pgm"
done
echo "threads: load $(cut -d' ' -f1-3 /proc/loadavg) after"
rm -f "$OUT"/threads*
# ---------------------------------------------------------------------------------------------
# codec (issue 24): .erdz decode, file bytes -> model -> image, in process (bench/erdz_decode_bench.cpp):
# lena ERDGPI 3% and bull ERDGPI 0.125% at step 2, medians of RUNS. Target: a 512x512 model decoded
# into its image in <= 20 ms (the "+own" column: 4x4 supersampled for the soft-edged ERD model).
if [[ -f $IMAGES/lena.pgm && -f $IMAGES/bull.pgm && -f $(dirname "$ERD")/liberd.a ]]; then
    EDB=$(dirname "$ERD")/erdz_decode_bench
    if ${CXX:-g++} -O2 -std=c++17 -I. bench/erdz_decode_bench.cpp "$(dirname "$ERD")/liberd.a" -o "$EDB"; then
        "$ERD" generate -q --method erdgpi -d 3 --step 2 -i "$IMAGES/lena.pgm" -o "$OUT/lena3.erdz"
        "$ERD" generate -q --method erdgpi -d 0.125 --step 2 -i "$IMAGES/bull.pgm" -o "$OUT/bull0125.erdz"
        echo "codec: FILE W H  decode median best  +point median best  +own median best (ms; target +own <= 20 for 512x512)"
        echo "codec: one thread (-j 1)"
        "$EDB" -j 1 "$RUNS" "$OUT/lena3.erdz" "$OUT/bull0125.erdz"
        echo "codec: one thread per processor (-j 0, erd reconstruct's default)"
        "$EDB" -j 0 "$RUNS" "$OUT/lena3.erdz" "$OUT/bull0125.erdz"
        # The same file to image as a whole process: exec, read, decode, reconstruct, write the PGM.
        bench_case "codec: erd reconstruct lena 3% .erdz" 20 -- "$ERD" reconstruct "$OUT/lena3.erdz" -o "$OUT/lena3.pgm"
        bench_case "codec: erd reconstruct bull 0.125% .erdz" 60 -- "$ERD" reconstruct "$OUT/bull0125.erdz" -o "$OUT/bull0125.pgm"
        if [[ $CALLGRIND == 1 ]] && command -v valgrind >/dev/null; then
            valgrind --tool=callgrind --callgrind-out-file=/dev/null "$EDB" 1 "$OUT/lena3.erdz" 2>&1 >/dev/null |
                sed -n 's/.*Collected : \([0-9]*\).*/codec lena3: \1 instructions (one run of decode, +point, +own)/p'
        fi
    else
        echo "codec: bench/erdz_decode_bench.cpp did not build; skipped"
    fi
else
    echo "codec: lena.pgm, bull.pgm or $(dirname "$ERD")/liberd.a missing; skipped"
fi
# ---------------------------------------------------------------------------------------------
# quality (issue 16): the default ERDGPI and ERDED on the 12 thesis cases, whole process, side by
# side with QUALITY_BASE (an erd binary built from the commit before issue 16, 78877d8, or any
# build to compare with) in the same run, runs alternating case by case. Target: CPU time
# <= 1.5x the base's in every case. Without QUALITY_BASE: skipped (there is nothing to divide by).
if [[ -n ${QUALITY_BASE:-} && -x ${QUALITY_BASE:-} ]]; then
    echo "quality: CPU ms medians of $RUNS, this build / QUALITY_BASE=$QUALITY_BASE (target <= 1.5x); load $(cut -d' ' -f1-3 /proc/loadavg)"
    ratios=()
    for m in erdgpi erded; do
        for c in "bull 0.125" "bull 0.25" "bull 0.5" "bull 1" "lena 0.5" "lena 1" "lena 2" "lena 3" \
                 "peppers 0.5" "peppers 1" "peppers 2" "peppers 3"; do
            set -- $c
            [[ -f $IMAGES/$1.pgm ]] || { echo "quality: $IMAGES/$1.pgm missing"; continue; }
            read -r _ cpu_new _ < <("$TIMEIT" "$RUNS" "$ERD" generate -m $m -i "$IMAGES/$1.pgm" -d $2 -o "$OUT/q.erd")
            read -r _ cpu_base _ < <("$TIMEIT" "$RUNS" "$QUALITY_BASE" generate -m $m -i "$IMAGES/$1.pgm" -d $2 -o "$OUT/q.erd")
            r=$(awk -v a="$cpu_new" -v b="$cpu_base" 'BEGIN { printf "%.3f", a / b }')
            ratios+=("$m $r")
            printf 'quality %-7s %-8s %5s%%  cpu %7s ms  base %7s ms  %sx\n' $m $1 $2 "$cpu_new" "$cpu_base" "$r"
        done
    done
    for m in erdgpi erded; do
        printf '%s\n' "${ratios[@]}" | awk -v m=$m '$1 == m { print $2 }' | sort -g | awk -v m=$m '{ r[++n] = $1 } END {
            med = n % 2 ? r[(n + 1) / 2] : (r[n / 2] + r[n / 2 + 1]) / 2
            printf "quality %s: median %.3fx, worst %.3fx of the base (target <= 1.5x)\n", m, med, r[n] }'
    done
    rm -f "$OUT/q.erd"
else
    echo "quality: QUALITY_BASE (an erd binary of the commit before issue 16) not given; skipped"
fi
