#!/usr/bin/env bash
# `make fuzz-campaign`: every fuzz target (or the ones named) for SECONDS of its own CPU time each
# (so a campaign on a shared machine fuzzes as long as on a quiet one; the wall time is printed
# beside it), on a corpus kept from run to run, two targets at a time with -j 2. Per target it prints the executions, the kept
# corpus's size, the findings (crash, leak, timeout and out-of-memory inputs) and the seeds it
# merged back; at the end a table for docs/HOSTILE.md.
#
# Usage: fuzz/campaign.sh [-j JOBS] SECONDS [fuzz_NAME...]
#
# Where things go (docs/DECISIONS.md "Testing"):
#   kept corpus   $FUZZ_CORPUS/NAME, default ${XDG_CACHE_HOME:-~/.cache}/erd-fuzz/NAME: outside
#                 the checkout (no tracked file, kept by `make clean` and by a new work tree on
#                 the same machine), shared by the checkouts of the machine, reused by every run
#   seeds         fuzz/corpus/NAME (committed), read, never written by the fuzzer; after the run
#                 the kept corpus's inputs that reach coverage the seeds do not (libFuzzer's
#                 -merge=1) are copied there as campaign-SHA1 files, the smallest first: at most
#                 FUZZ_MERGE_FILES (default 8) a target and run, each of at most
#                 FUZZ_MERGE_BYTES (default 8192) bytes, and none once the target's seeds hold
#                 FUZZ_SEED_BYTES (default 524288): `git add fuzz/corpus` keeps them
#   findings      build-fuzz/campaign/NAME/ (crash-*, leak-*, timeout-*, oom-*), with the log
#   the record    fuzz/campaign.tsv (committed): a line per target and run (date, commit fuzzed,
#                 target, CPU s, wall s, executions, corpus, findings); docs/HOSTILE.md's
#                 "Fuzz campaign" table sums it per target (tools/hostile_table.sh)
#   targets       build-asan/NAME, built as fuzz/run.sh builds them (ASan + UBSan + libFuzzer)
#
# A target that finds something is started again on the same corpus for the time left (at most
# 20 starts), so one crash does not end its campaign; the finding's input is kept for replay
# (fuzz/replay.cpp) and becomes a regression seed once fixed. Exit status 1 when any target
# found something or failed to build.
set -u
cd "$(dirname "$0")/.."
jobs=1
if [[ ${1:-} == -j ]]; then jobs=${2:?-j needs a number}; shift 2
elif [[ ${1:-} == -j* ]]; then jobs=${1#-j}; shift; fi
[[ $jobs =~ ^[1-9][0-9]*$ ]] || { echo "fuzz-campaign: -j '$jobs' is not a positive number" >&2; exit 2; }
SECONDS_EACH=${1:?usage: fuzz/campaign.sh [-j JOBS] SECONDS [fuzz_NAME...]}
[[ $SECONDS_EACH =~ ^[1-9][0-9]*$ ]] || { echo "fuzz-campaign: SECONDS '$SECONDS_EACH' is not a positive number" >&2; exit 2; }
shift
KEPT=${FUZZ_CORPUS:-${XDG_CACHE_HOME:-$HOME/.cache}/erd-fuzz}
OUT=build-fuzz/campaign
MERGE_FILES=${FUZZ_MERGE_FILES:-8}
MERGE_BYTES=${FUZZ_MERGE_BYTES:-8192}
SEED_BYTES=${FUZZ_SEED_BYTES:-524288}
B=build-asan
if [[ $# -gt 0 ]]; then names=("$@"); else names=($(ls fuzz/fuzz_*.cpp | xargs -n1 basename | sed 's/\.cpp$//')); fi
for n in "${names[@]}"; do
    [[ -f fuzz/$n.cpp ]] || { echo "fuzz-campaign: no target fuzz/$n.cpp" >&2; exit 2; }
done
mkdir -p "$OUT" "$KEPT" || exit 1

# The targets, built once by fuzz/run.sh (FUZZ_BUILD_ONLY: build, do not run).
FUZZ_BUILD_ONLY=1 bash fuzz/run.sh 0 "${names[@]}" >"$OUT/build.log" 2>&1
# The record's commit: the one the targets were built from ("+" when the work tree differed from
# it), taken now: the tree may change while the campaign runs.
FUZZED=$(git rev-parse --short=7 HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- . ':!fuzz/campaign.*' ':!fuzz/corpus' 2>/dev/null || FUZZED+="+"
status=0
built=()
for n in "${names[@]}"; do
    if grep -q "^BUILT $n\$" "$OUT/build.log"; then built+=("$n"); continue; fi
    echo "FAIL $n (build)"; grep -A20 "FAIL $n\|FAIL build" "$OUT/build.log" | head -20
    status=1
done
names=("${built[@]}")

# One target's campaign: its lines to $OUT/NAME/result (one line: execs corpus findings merged
# starts seconds), its libFuzzer output to $OUT/NAME/log.
campaign() {
    local n=$1 dir=$OUT/$1 corpus=$KEPT/$1 seeds=fuzz/corpus/$1
    rm -rf "$dir"; mkdir -p "$dir" "$corpus"
    local dict=""; [[ -f fuzz/$n.dict ]] && dict="-dict=fuzz/$n.dict"
    local seed_dirs=(); [[ -d $seeds ]] && seed_dirs=("$seeds")
    # The CPU clock: a start runs for the CPU seconds left as wall seconds (wall >= CPU, so it never
    # overshoots), then what it used is counted, and the next start takes the rest.
    local t0=$SECONDS left=$SECONDS_EACH execs=0 starts=0 e before findings=0 cpu=0 used
    while (( left > 0 && starts < 100 )); do
        starts=$((starts + 1))
        before=$findings
        /usr/bin/time -f "%U %S" -o "$dir/start.cpu" \
            $B/$n "$corpus" "${seed_dirs[@]}" $dict -max_total_time="$left" -artifact_prefix="$dir/" \
            -malloc_limit_mb=2048 -rss_limit_mb=4096 -timeout=10 -print_final_stats=1 >"$dir/start.log" 2>&1
        # Executions: the final statistics (printed on a crash too), else the last status line.
        e=$(grep -E '^stat::number_of_executed_units' "$dir/start.log" | tail -1 | awk '{print $2}')
        [[ -z $e ]] && e=$(grep -oE '^#[0-9]+' "$dir/start.log" | tail -1 | tr -d '#')
        execs=$((execs + ${e:-0}))
        { cat "$dir/start.log"; echo "== start $starts ended (${e:-0} executions)"; } >>"$dir/log"
        rm -f "$dir/start.log"
        used=$(tail -1 "$dir/start.cpu" 2>/dev/null | awk '{ printf "%d", $1 + $2 }')  # a status line may come first
        cpu=$((cpu + ${used:-0}))
        rm -f "$dir/start.cpu"
        left=$((SECONDS_EACH - cpu))
        findings=$(ls "$dir" | grep -cE '^(crash|leak|timeout|oom)-')
        (( findings > 20 )) && break  # one bug found over and over: fix it first
        (( findings == before && ${used:-0} < 1 )) && break  # it could not run: see the log
        (( left < 30 )) && break  # the rest is start-up
    done
    local fuzzed=$cpu wall=$((SECONDS - t0))
    # Inputs of the kept corpus that reach coverage the seeds do not: merged into a copy of the
    # seeds, the new files are the ones merge added.
    local merged=0
    if [[ -d $seeds ]]; then
        local m=$dir/merge
        mkdir -p "$m"; cp "$seeds"/* "$m"/ 2>/dev/null
        ls "$m" | sort >"$dir/seeds.list"
        $B/$n -merge=1 "$m" "$corpus" $dict -timeout=10 -rss_limit_mb=4096 -malloc_limit_mb=2048 >"$dir/merge.log" 2>&1
        local f
        while read -r f; do
            (( merged >= MERGE_FILES )) && break
            (( $(du -sb "$seeds" | cut -f1) + $(stat -c %s "$m/$f") > SEED_BYTES )) && break
            local sha; sha=$(sha1sum "$m/$f" | cut -c1-16)
            [[ -e $seeds/campaign-$sha ]] && continue
            cp "$m/$f" "$seeds/campaign-$sha" && merged=$((merged + 1))
        done < <(cd "$m" && ls | sort | comm -13 "../seeds.list" - | while read -r f; do
                     s=$(stat -c %s "$f"); (( s <= MERGE_BYTES )) && echo "$s $f"; done | sort -n | cut -d' ' -f2-)
        rm -rf "$m" "$dir/seeds.list"
    fi
    echo "$execs $(ls "$corpus" | wc -l) $findings $merged $starts $fuzzed $wall" >"$dir/result"
    printf '%s\t%s\t%s\t%d\t%d\t%d\t%d\t%d\n' "$(date -u +%F)" "$FUZZED" "$n" "$fuzzed" "$wall" "$execs" \
        "$(ls "$corpus" | wc -l)" "$findings" >>fuzz/campaign.tsv
}

echo "fuzz campaign: ${#names[@]} targets, $SECONDS_EACH CPU s each, $jobs at a time; kept corpus $KEPT"
running=0
for n in "${names[@]}"; do
    [[ -z $n ]] && continue
    if (( running >= jobs )); then wait -n; running=$((running - 1)); fi
    campaign "$n" &
    running=$((running + 1))
done
wait

table="| target | CPU hours | wall hours | executions | corpus | findings |"$'\n'"| --- | --- | --- | --- | --- | --- |"
for n in "${names[@]}"; do
    [[ -z $n ]] && continue
    if [[ ! -f $OUT/$n/result ]]; then echo "FAIL $n (no result; see $OUT/$n/log)"; status=1; continue; fi
    read -r execs corpus findings merged starts secs wall <"$OUT/$n/result"
    line="$n: $secs CPU s ($wall s wall), $execs executions, corpus $corpus, $findings findings, $merged new seeds"
    if (( findings > 0 )); then
        status=1
        echo "FOUND $line"
        ls "$OUT/$n" | grep -E '^(crash|leak|timeout|oom)-' | sed "s|^|    $OUT/$n/|"
        grep -E '^(==[0-9]+==ERROR|SUMMARY|.*runtime error)' "$OUT/$n/log" | sort -u | head -5 | sed 's/^/    /'
    else
        echo "PASS $line"
    fi
    what=$findings; (( findings == 0 )) && what=0
    table+=$'\n'"| $n | $(awk -v s="$secs" 'BEGIN { printf "%.2f", s / 3600 }') | $(awk -v s="$wall" 'BEGIN { printf "%.2f", s / 3600 }') | $execs | $corpus | $what |"
done
echo "$table" >"$OUT/table.md"
echo
echo "$table"
echo
echo "(table in $OUT/table.md; new seeds, if any: git status fuzz/corpus)"
exit $status
