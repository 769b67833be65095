#!/usr/bin/env bash
# Builds every fuzz/fuzz_*.cpp with libFuzzer + ASan + UBSan and runs each for SECONDS.
# Prints "PASS name execs corpus" or "FAIL name" per target.
# Usage: fuzz/run.sh SECONDS [fuzz_NAME...]   (no names: every target). Targets, corpora and
# findings go to build-asan/, whose objects (make asan) the targets link.
# FUZZ_SHORT_SECONDS=S caps the targets named in FUZZ_SHORT (default fuzz_framing fuzz_erdz) at S seconds.
# FUZZ_BUILD_ONLY=1 builds the targets and prints "BUILT name" for each (fuzz/campaign.sh).
set -u
cd "$(dirname "$0")/.."
SECONDS_EACH=${1:-300}
shift || true
B=build-asan
SAN="-fsanitize=address,undefined -fno-sanitize-recover=all"
FLAGS="-O1 -g -std=c++17 -I. -fno-omit-frame-pointer $SAN"
if ! command -v clang++ >/dev/null; then echo "fuzz: clang++ not found, skipped"; exit 0; fi
mkdir -p $B
# The sanitizer build's library and CLI objects (all but main), with the coverage hooks; rebuilt
# when sources change. FUZZ_NOBUILD=1: use the objects already there (lets two runs share them).
cli_objs=$(ls cli/*.cpp | grep -v main.cpp | sed "s|^|$B/|; s|\.cpp$|.o|" | tr '\n' ' ')  # one line: make's goals
[[ -n ${FUZZ_NOBUILD:-} ]] || make -s -j2 asan ASAN_GOALS="$B/liberd.a $B/liberd_imageio.a $cli_objs" || { echo "FAIL build"; exit 1; }
# make does not rebuild for changed flags: a build-asan from before the hooks would fuzz blind.
if ! nm $B/liberd.a 2>/dev/null | grep -q __sanitizer_cov_8bit_counters_init; then
    echo "FAIL build: $B/liberd.a has no coverage hooks (made before make asan had them: rm -rf $B and run again)"; exit 1
fi
objs="$cli_objs $B/liberd_imageio.a $B/liberd.a -ltiff -lz"
status=0
if [[ $# -gt 0 ]]; then targets=$(printf 'fuzz/%s.cpp ' "$@"); else targets=$(ls fuzz/fuzz_*.cpp); fi
for src in $targets; do
    name=$(basename "$src" .cpp)
    # A target comparing with CGAL links the CGAL glue: g++'s object from the unit-test build (the
    # one slow CGAL compile, shared; CGAL itself need not be instrumented), installing libcgal-dev.
    extra=""
    if grep -q 'third_party/cgal_glue.h' "$src"; then
        if ! make -s build/third_party/cgal_glue.o >$B/$name.build.log 2>&1; then
            echo "FAIL $name (CGAL glue build)"; head -20 $B/$name.build.log; status=1; continue
        fi
        extra="build/third_party/cgal_glue.o -lgmp -lmpfr"
    fi
    if ! clang++ $FLAGS -fsanitize=fuzzer "$src" $objs $extra -o $B/$name 2>$B/$name.build.log; then
        echo "FAIL $name (build)"; cat $B/$name.build.log | head -20; status=1; continue
    fi
    # FUZZ_BUILD_ONLY=1: build the targets, run none (fuzz/campaign.sh runs them itself).
    [[ -n ${FUZZ_BUILD_ONLY:-} ]] && { echo "BUILT $name"; continue; }
    corpus=$B/corpus/$name
    mkdir -p "$corpus"
    seeds=fuzz/corpus/$name
    dict=""; [[ -f fuzz/$name.dict ]] && dict="-dict=fuzz/$name.dict"
    secs=$SECONDS_EACH
    # FUZZ_SHORT_SECONDS caps the targets of FUZZ_SHORT (make test's smoke runs keep them short).
    [[ " ${FUZZ_SHORT:-fuzz_framing fuzz_erdz} " == *" $name "* && -n ${FUZZ_SHORT_SECONDS:-} ]] && (( secs > FUZZ_SHORT_SECONDS )) && secs=$FUZZ_SHORT_SECONDS
    if $B/$name "$corpus" $( [[ -d $seeds ]] && echo "$seeds") $dict -max_total_time="$secs" \
        -artifact_prefix=$B/ -malloc_limit_mb=2048 -rss_limit_mb=4096 -timeout=10 -print_final_stats=1 >$B/$name.log 2>&1; then
        execs=$(grep -E 'stat::number_of_executed_units' $B/$name.log | awk '{print $2}')
        echo "PASS $name execs=$execs corpus=$(ls "$corpus" | wc -l) seconds=$secs"
    else
        echo "FAIL $name"; grep -E 'ERROR|SUMMARY|Test unit written' $B/$name.log | head -5; status=1
    fi
done
exit $status
