#!/usr/bin/env bash
# `make test`: the layer and map checks, the unit tests, the same tests under ASan+UBSan, the
# thread tests under ThreadSanitizer, the kernel against CGAL (build/cgal_tests), and a short run
# of every fuzz target. Counts test cases (a fuzz target and each check count as one) and ends with
# "N passed, M failed". A missing binary or image fails its tests here: skipping
# (ERD_ALLOW_SKIP=1, tests/erd_run.h) is never allowed in this run.
set -u
unset ERD_ALLOW_SKIP ERD_REGENERATE
cd "$(dirname "$0")/.."
IMAGES=${IMAGES:-../shared/images}
passed=0
failed=0
skipped=0
log=$(mktemp -d)
trap 'rm -rf "$log"' EXIT

# Adds the counts from a Catch2 run's last lines to the totals.
count_catch() {
    local out=$1 rc=$2 line p f
    line=$(grep -E '^(test cases:|All tests passed)' "$out" | tail -1)
    if [[ $line =~ All\ tests\ passed.*\ ([0-9]+)\ test\ case ]]; then
        p=${BASH_REMATCH[1]}; f=0
    elif [[ $line =~ test\ cases:\ +([0-9]+)\ \|\ +([0-9]+)\ passed\ \|\ +([0-9]+)\ failed ]]; then
        p=${BASH_REMATCH[2]}; f=${BASH_REMATCH[3]}
    elif [[ $line =~ test\ cases:\ +([0-9]+)\ \|\ +([0-9]+)\ failed ]]; then
        p=0; f=${BASH_REMATCH[2]}
    else
        p=0; f=1   # crashed before reporting
    fi
    [[ $rc -ne 0 && $f -eq 0 ]] && f=1
    passed=$((passed + p)); failed=$((failed + f))
}

stage_start=$SECONDS
stage() { echo "   ($(( SECONDS - stage_start )) s)"; stage_start=$SECONDS; }
echo "== layer check (tools/check_layers.sh, counts as one test)"
if bash tools/check_layers.sh; then passed=$((passed + 1)); else failed=$((failed + 1)); fi
echo "== map check: every source file in docs/architecture.md's room table (tools/check_map.sh, counts as one test)"
if bash tools/check_map.sh; then passed=$((passed + 1)); else failed=$((failed + 1)); fi

stage
echo "== build"
if ! make -s -j2 build/erd_tests build/erd; then
    echo "build failed"; echo "$passed passed, $((failed + 1)) failed"; exit 1
fi

stage
# The unit tests use one core: the sanitizer build starts beside them and uses the rest.
asan_build_pid=""
if command -v clang++ >/dev/null; then
    ( make -s -j2 asan >"$log/asan-build" 2>&1; echo $? >"$log/asan-build.rc" ) &
    asan_build_pid=$!
else
    echo "clang++ missing" >"$log/asan-build"; echo 1 >"$log/asan-build.rc"
fi
echo "== unit tests (the ASan+UBSan build runs beside them)"
ERD_BIN=build/erd ERD_IMAGES=$IMAGES build/erd_tests 2>&1 | tee "$log/unit" | tail -3
count_catch "$log/unit" "${PIPESTATUS[0]}"
stage

# The stages after the unit tests, as functions: each prints its lines and adds to passed /
# failed / skipped. run_job runs one in a subshell of its own (its lines to $log/NAME.out, its
# counts and seconds to $log/NAME.count), so that jobs can run side by side; show_job prints a
# finished job's lines under its heading and adds its counts, in the order the stages are listed.
stage_asan() {
    if [[ $(cat "$log/asan-build.rc" 2>/dev/null) != 0 ]]; then
        tail -20 "$log/asan-build"; echo "sanitizer build failed"; failed=$((failed + 1)); return
    fi
    # ERD_BIN_OTHER: the determinism test (tests/test_robustness.cpp) compares this clang -O1
    # sanitized binary's bytes with g++ -O2's build/erd: two compilers and two optimisation levels.
    # ERD_CHILD_ASAN_OPTIONS: the erd runs of the tests check no leaks (35 ms each at exit), but
    # those of tests/test_leaks.cpp, a chosen set over every subcommand and error path, and the
    # test process itself do.
    ASAN_OPTIONS=detect_leaks=1 ERD_CHILD_ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 ERD_BIN_OTHER=build/erd \
        ERD_BIN=build-asan/erd ERD_IMAGES=$IMAGES ERD_SANITIZED=1 build-asan/erd_tests >"$log/asan" 2>&1
    local rc=$?
    tail -3 "$log/asan"
    count_catch "$log/asan" "$rc"
}

# The thread-equality tests under ThreadSanitizer (make tsan: build-tsan/erd_tsan_tests, the ASan
# build's Catch2 main reused; in the foreground chain, after the fuzz smoke runs): the library's
# stages at 1 and 3 threads (ERD_SANITIZED) and two API calls on two threads; a race report fails
# it (exit 66). The [cli] case runs the erd binary, which this build has not.
stage_tsan() {
    local t0=$SECONDS
    if ! make -s -j2 tsan >"$log/tsan-build" 2>&1; then
        tail -20 "$log/tsan-build"; echo "ThreadSanitizer build failed"; failed=$((failed + 1)); return
    fi
    echo "built in $(( SECONDS - t0 )) s"
    ERD_SANITIZED=1 build-tsan/erd_tsan_tests "~[cli]" >"$log/tsan" 2>&1
    local rc=$?
    grep -E '^(WARNING: ThreadSanitizer|SUMMARY: ThreadSanitizer)' "$log/tsan" | head -10
    tail -3 "$log/tsan"
    count_catch "$log/tsan" "$rc"
}

stage_embedded() {
    if make -s -j2 embedded >"$log/embedded" 2>&1; then
        grep -E '^(library|example|estimated|erdgpi)' "$log/embedded" || true
        passed=$((passed + 1))
    else
        tail -20 "$log/embedded"; echo "embedded build or example failed"; failed=$((failed + 1))
    fi
}

stage_python() {
    if ! make -s python >"$log/python-build" 2>&1; then
        tail -20 "$log/python-build"; echo "python package build failed (pybind11, numpy or pytest missing?)"; failed=$((failed + 1))
        return
    fi
    grep '^python: built' "$log/python-build" || true
    local images_abs rc line p=0 f=0
    images_abs=$(cd "$IMAGES" 2>/dev/null && pwd)
    (cd python && ERD_BIN=$PWD/../build/erd ERD_IMAGES=$images_abs PYTHONPATH=$PWD \
        /usr/bin/python3 -m pytest -q -p no:cacheprovider tests) >"$log/pytest" 2>&1
    rc=$?
    # A failure's assertion lines too: the summary line alone is cut at 80 columns.
    [[ $rc -ne 0 ]] && grep -E '^(E  |[^ ]+\.py:[0-9]+: )' "$log/pytest" | head -20
    tail -3 "$log/pytest"
    line=$(tail -1 "$log/pytest")   # "1 failed, 54 passed in 9.1s", "2 errors in ..."
    [[ $line =~ ([0-9]+)\ passed ]] && p=${BASH_REMATCH[1]}
    [[ $line =~ ([0-9]+)\ failed ]] && f=${BASH_REMATCH[1]}
    [[ $line =~ ([0-9]+)\ error ]] && f=$((f + BASH_REMATCH[1]))
    [[ $rc -ne 0 && $f -eq 0 ]] && f=1   # pytest crashed, collected nothing or could not start
    passed=$((passed + p)); failed=$((failed + f))
    # pip install into a fresh venv made with --system-site-packages (reuses make python's objects).
    if make -s python-venv-check >"$log/venv" 2>&1; then
        grep '^python-venv-check' "$log/venv"; passed=$((passed + 1))
    else
        tail -20 "$log/venv"; echo "pip install into a venv failed"; failed=$((failed + 1))
    fi
}

# Runs one browser stage (a script whose exit 77 means "skipped") and counts it once.
browser_stage() {
    local name=$1; shift
    "$@" >"$log/$name" 2>&1
    local rc=$?
    cat "$log/$name"
    case $rc in
        0) passed=$((passed + 1)) ;;
        77) echo "SKIPPED: the $name stage did not run (see the SKIP line)"; skipped=$((skipped + 1)) ;;
        *) failed=$((failed + 1)) ;;
    esac
}

stage_vector() {
    if [[ -f $IMAGES/bull.pgm && -f $IMAGES/lena.pgm && -f $IMAGES/color/kodim03.ppm ]]; then
        browser_stage vector tools/svg_browser_psnr.sh build/erd "$IMAGES/bull.pgm" "$IMAGES/lena.pgm" "$IMAGES/color/kodim03.ppm"
    else
        echo "FAILED: $IMAGES/bull.pgm, lena.pgm or color/kodim03.ppm missing"; failed=$((failed + 1))
    fi
}

stage_web() { browser_stage web tests/web_test.sh "$IMAGES"; }

stage_lines() {  # NAME SCRIPT...: a script whose PASS, FAIL and SKIP lines are each a test
    local name=$1 p f s
    shift
    bash "$@" >"$log/$name" 2>&1
    grep -E '^(FAIL|SKIP)' "$log/$name" | head -20
    p=$(grep -c '^PASS' "$log/$name"); f=$(grep -c '^FAIL' "$log/$name"); s=$(grep -c '^SKIP' "$log/$name")
    echo "$p $name checks passed, $f failed"
    [[ $p -eq 0 && $f -eq 0 ]] && f=1  # the script ran nothing
    passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + s))
}
# Real elevation data (issue 47): --max-error bounds measured by numpy, precision, TIFF round
# trips, every .glb through the Khronos validator; each PASS line is a test.
stage_raster() { stage_lines raster tests/raster_test.sh build/erd; }

# Tiles (issue 48): seams of merged meshes checked by numpy, the same bytes however the tasks run,
# the merged .glb validated, refusals; each PASS line is a test (the Dask run is pytest's).
stage_tiles() { stage_lines tiles tests/tiles_test.sh build/erd; }

run_job() {
    local name=$1 fn=$2 t0=$SECONDS
    ( passed=0; failed=0; skipped=0; $fn; echo "$passed $failed $skipped $(( SECONDS - t0 ))" >"$log/$name.count" ) >"$log/$name.out" 2>&1
}

show_job() {
    local name=$1 heading=$2 p=0 f=1 s=0 t=?
    echo "== $heading"
    cat "$log/$name.out" 2>/dev/null
    [[ -f $log/$name.count ]] && read -r p f s t <"$log/$name.count"
    [[ -f $log/$name.count ]] || echo "the $name stage did not finish"
    passed=$((passed + p)); failed=$((failed + f)); skipped=$((skipped + s))
    echo "   ($t s)"
}

# Installs chromium, librsvg2-bin and GNU parallel (the tiles stage) when missing (as the Makefile installs its packages); without
# any renderer the browser stages are counted as skipped, never as passed.
for pkg in chromium:chromium rsvg-convert:librsvg2-bin parallel:parallel; do
    command -v "${pkg%%:*}" >/dev/null || DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${pkg#*:}" >/dev/null 2>&1 || true
done
# The Python and web stages' packages too, here and one after the other: the stages run side by
# side, and two apt-gets at once would fight over dpkg's lock. A failure shows in its stage.
make -s python-deps /usr/bin/em++ >"$log/stage-deps" 2>&1 || true

# Two chains on the two cores: the sanitized unit tests, then the embedded build and the Python
# package, in the background; the fuzz smoke runs (one core: a target at a time for a fixed time,
# linked against the sanitizer build's objects), the web page and the vector SVG renderers in the
# foreground. Each chain is about 4-5 minutes on a quiet machine.
echo "== unit tests under ASan+UBSan, embedded build, python (in the background, beside the fuzz smoke runs, the web page and the vector SVG renderers; printed below)"
[[ -n $asan_build_pid ]] && wait "$asan_build_pid"
stage
( run_job asan stage_asan; run_job embedded stage_embedded; run_job python stage_python ) &
chain_pid=$!

# erd's CDT against CGAL's (tests/cgal/, its own binary so that erd_tests never needs CGAL);
# the build installs libcgal-dev when missing (Makefile, deps-cgal).
echo "== CGAL differential tests (build/cgal_tests)"
if make -s -j2 build/cgal_tests >"$log/cgal-build" 2>&1; then
    build/cgal_tests 2>&1 | tee "$log/cgal" | tail -3
    count_catch "$log/cgal" "${PIPESTATUS[0]}"
else
    tail -20 "$log/cgal-build"; echo "CGAL differential tests: build failed"; failed=$((failed + 1))
fi
stage

echo "== fuzz smoke runs"
if [[ -x fuzz/run.sh || -f fuzz/run.sh ]] && ls fuzz/fuzz_*.cpp >/dev/null 2>&1; then
    FUZZ_SHORT_SECONDS=${FUZZ_SHORT_SECONDS:-3} bash fuzz/run.sh "${FUZZ_SMOKE_SECONDS:-10}" >"$log/fuzz" 2>&1
    cat "$log/fuzz" | grep -E "^(fuzz|PASS|FAIL)|ERROR|SUMMARY|Test unit written" || true
    p=$(grep -c '^PASS' "$log/fuzz"); f=$(grep -c '^FAIL' "$log/fuzz")
    passed=$((passed + p)); failed=$((failed + f))
fi
stage
# ThreadSanitizer in this chain: the other one is the longer (asan 501 s + embedded 77 s + python
# 260 s against fuzz 147 s + vector 146 s + web 297 s on a loaded machine).
run_job tsan stage_tsan
run_job web stage_web
run_job vector stage_vector
run_job raster stage_raster
run_job tiles stage_tiles
wait "$chain_pid"
show_job asan "unit tests under ASan+UBSan: result"
show_job embedded "embedded build (-Os -fno-exceptions -fno-rtti) and its example (counts as one test)"
show_job python "python package (make python, pytest python/tests: each test counts; pip install into a venv: one)"
show_job tsan "thread tests under ThreadSanitizer (build-tsan/erd_tsan_tests: every -j stage, two API calls on two threads)"
show_job vector "vector SVG in real renderers (chromium headless, rsvg-convert): PSNR within 0.3 dB of erd's point reconstruction and of erd reconstruct's image"
show_job web "web page (web/, WebAssembly) in chromium via playwright-core: opens meshed, slider, cancel, drop, file, paste, bad file; each mesh the native erd's"
show_job raster "rasters (tests/raster_test.sh): real DEMs' --max-error bounds checked by numpy, precision, TIFF round trips, glTF validator (each check counts)"
show_job tiles "tiles (tests/tiles_test.sh): merged meshes valid triangulations, N kept, the same bytes in any task order and under GNU parallel, .glb validated (each check counts)"

stage
[[ $skipped -gt 0 ]] && echo "$skipped skipped (not counted as passed): see SKIPPED above"
echo "$passed passed, $failed failed"
[[ $failed -eq 0 ]]
