#!/usr/bin/env bash
# `make eval`: PSNR of every registered method on the thesis's test images and densities, beside
# the thesis's Tables 3.5 and 3.6, written to docs/RESULTS.md.
# Usage: tools/eval.sh ERD_BINARY IMAGES_DIR
#
# Cases: bull at 0.125, 0.25, 0.5, 1%; lena and peppers at 0.5, 1, 2, 3% (the thesis's rows).
# Each case: erd generate -x 2 (a missed N does not abort; the count is reported), erd reconstruct
# (imgsyn for .model, imgsyn_aa for .erd), erd psnr. Methods missing from the build's registry
# are skipped, so the table grows as methods land. JOBS (default 2) cases run at once; METHODS
# (space separated) restricts the methods.
# ERDED and ERDGPI run twice: "thesis method" (generate --thesis: the thesis's wedge values, line
# search alpha in [1, 1.5], density zeroed on edge pixels only, ERDGPI errors against the
# supersampled approximation) for the reproduction targets, and
# "erd default" (our least-squares wedge refit, alpha in [0.75, 1], edge radius 1 pixel).
# Variant names: METHOD (erd default) and METHOD+thesis. The removal methods of issue 45 (gpr,
# gprfs, id: basic model; erdgpr: ERD model, the recommended default) have no thesis table; every
# method also runs with "+bpr" (--bpr 1, bad-point replacement), and the section "Every method"
# puts all variants side by side with their CPU seconds (user + system of erd generate).
# tools/eval_startup.sh (Table 3.4) and
# tools/eval_hard.sh (hard-edged pictures, issue 15), tools/eval_colour.sh (colour images,
# issue 17) and tools/eval_graphics.sh (anti-aliased graphics and mixed pictures, issue 44) run last.
set -u
ERD=${1:-build/erd}
IMAGES=${2:-../shared/images}
JOBS=${JOBS:-2}
[[ $ERD == */* && $ERD != /* ]] && ERD=$PWD/$ERD
[[ $IMAGES != /* ]] && IMAGES=$PWD/$IMAGES
cd "$(dirname "$0")/.."
OUT=out/eval
RESULTS=docs/RESULTS.md
mkdir -p "$OUT" docs

if [[ ! -x $ERD ]]; then echo "eval: $ERD is not built (try: make)"; exit 1; fi

# Thesis PSNR (dB): method image -> values at the image's four densities.
declare -A THESIS=(
    [ed.bull]="14.66 17.36 27.79 34.16"     [ed.lena]="17.60 22.45 26.90 28.54"     [ed.peppers]="17.53 22.42 27.10 29.06"
    [gpi.bull]="30.56 35.30 38.72 40.95"    [gpi.lena]="24.22 26.96 29.74 31.36"    [gpi.peppers]="24.66 27.49 29.99 31.19"
    [erded.bull]="24.68 28.86 35.15 39.02"  [erded.lena]="20.56 25.82 29.28 31.31"  [erded.peppers]="22.14 25.97 29.00 30.18"
    [erdgpi.bull]="35.47 38.33 40.16 41.39" [erdgpi.lena]="25.58 28.35 30.79 32.30" [erdgpi.peppers]="25.99 28.40 30.42 31.50"
)
declare -A DENSITIES=([bull]="0.125 0.25 0.5 1" [lena]="0.5 1 2 3" [peppers]="0.5 1 2 3")
# Tolerance of the quality targets (issues 5 and 6): ours >= thesis - TOL counts as met.
declare -A TOL=([ed]=1.5 [gpi]=0.5 [erded]=0.5 [erdgpi]=0.3)
declare -A TABLE=([ed]="3.5" [gpi]="3.6" [erded]="3.5" [erdgpi]="3.6")
BPR=${BPR:-1}  # rounds of the +bpr variants

registered=$("$ERD" generate --help 2>/dev/null | sed -n '/^Methods:/,$p' | awk 'NR > 1 {print $1}')
methods=()
for m in ${METHODS:-ed gpi gpr gprfs id erded erdgpi erdgpr}; do
    grep -qx "$m" <<<"$registered" && methods+=("$m")
done
if [[ ${#methods[@]} -eq 0 ]]; then echo "eval: no methods registered in $ERD"; exit 1; fi
variants=()
for m in "${methods[@]}"; do
    case $m in
        erded|erdgpi) variants+=("$m+thesis" "$m+previous" "$m" "$m+bpr") ;;
        ed|gpi) variants+=("$m" "$m+optimize" "$m+bpr") ;;
        *) variants+=("$m" "$m+bpr") ;;
    esac
done
# Flags of each variant suffix. "+previous" is the default before issue 16 (no flips, plain
# least-squares refit), byte for byte; "+optimize" the ED/GPI option of issue 16.
declare -A VFLAGS=([thesis]="--thesis" [previous]="--flips 0 --wedge-prior 0 --wedge-bounds -1" [optimize]="--optimize")  # as in run_case
# Section title of a variant.
title() {
    local v=$1 M
    M=$(tr a-z A-Z <<<"${v%%+*}")
    case $v in
        *+thesis) echo "$M, thesis method (--thesis)" ;;
        *+previous) echo "$M, previous default (no flips, plain refit: ${VFLAGS[previous]})" ;;
        *+optimize) echo "$M --optimize (least-squares values, flips)" ;;
        *+bpr) echo "$M --bpr $BPR (bad-point replacement)" ;;
        erded|erdgpi) echo "$M, erd default (regularised wedge refit, flips, moves, alpha 0.75-1, edge radius 1)" ;;
        *) echo "$M" ;;
    esac
}

# One case -> one line "method image density N_requested N_got psnr seconds" on stdout.
run_case() {
    local v=$1 img=$2 d=$3 ext=model m=${1%%+*} flags=()
    case $m in erd*) ext=erd ;; esac
    # (run_case runs under xargs, where VFLAGS, an associative array, is not exported.)
    case $v in
        *+thesis) flags=(--thesis) ;;
        *+previous) flags=(--flips 0 --wedge-prior 0 --wedge-bounds -1) ;;
        *+optimize) flags=(--optimize) ;;
        *+bpr) flags=(--bpr "$BPR") ;;
    esac
    local base=$OUT/$img.$v.$d mesh log start end psnr got req
    mesh=$base.$ext
    log=$base.log
    # CPU seconds (user + system) of erd generate: what a shared machine measures fairly.
    if ! /usr/bin/time -o "$base.cpu" -f "%U %S" "$ERD" generate --method "$m" "${flags[@]}" -i "$IMAGES/$img.pgm" -d "$d" -x 1 -o "$mesh" -t "$base.tri" >"$log" 2>&1; then
        echo "$v $img $d - - failed 0"; return
    fi
    "$ERD" reconstruct "$mesh" -o "$base.pgm" >>"$log" 2>&1 || { echo "$v $img $d - - noreconstruct 0"; return; }
    psnr=$("$ERD" psnr "$IMAGES/$img.pgm" "$base.pgm" 2>>"$log") || psnr=failed
    req=$(sed -n 's/.*requested \([0-9]*\) but got \([0-9]*\).*/\1/p' "$log" | head -1)
    got=$(sed -n 's/.*requested \([0-9]*\) but got \([0-9]*\).*/\2/p' "$log" | head -1)
    if [[ -z $req ]]; then
        # N reached exactly: the vertex count is the model file's second number.
        got=$(awk 'NR == 2 {print $1; exit}' "$mesh"); req=$got
    fi
    echo "$v $img $d $req $got $psnr $(awk '{printf "%.3f", $1 + $2}' "$base.cpu")"
}
export -f run_case
export ERD IMAGES OUT BPR

cases=()
for m in "${variants[@]}"; do
    for img in bull lena peppers; do
        [[ -f $IMAGES/$img.pgm ]] || continue
        for d in ${DENSITIES[$img]}; do cases+=("$m $img $d"); done
    done
done
echo "eval: ${#cases[@]} cases (${variants[*]}), $JOBS at a time; outputs under $OUT/"
printf '%s\n' "${cases[@]}" | xargs -P "$JOBS" -L 1 bash -c 'run_case "$@"' _ >"$OUT/raw.txt"

# ---- docs/RESULTS.md ----
# eval writes the thesis tables at the top; every marked section below them ("<!-- NAME: ..." to
# "<!-- /NAME -->": make codec-bench's, make bench's, the eval_* scripts', the measured-by-hand
# ones) is kept in its place: saved here, put back after the rewrite, then the eval_* scripts
# replace their own.
kept=$OUT/kept_sections.md
: >"$kept"
[[ -f $RESULTS ]] && awk '
    !on && match($0, /^<!-- [A-Za-z0-9_-]+:/) { on = 1; m = substr($0, 6, RLENGTH - 6); if (n++) print "" }
    on { print }
    on && $0 == "<!-- /" m " -->" { on = 0 }' "$RESULTS" >"$kept"
{
    echo "# Results"
    echo
    echo "Written by \`make eval\` (tools/eval.sh) on $(date -u '+%Y-%m-%d %H:%M UTC'), commit"
    echo "$(git rev-parse --short HEAD 2>/dev/null || echo unknown). PSNR in dB of the reconstruction (imgsyn for"
    echo "ED/GPI models, 4x4-supersampled imgsyn_aa for ERD models) against the original, beside the thesis's"
    echo "Tables 3.5 (ED, ERDED) and 3.6 (GPI, ERDGPI). diff = ours - thesis. \"met\" = ours >= thesis - tol"
    echo "(tol: ED 1.5, GPI 0.5, ERDED 0.5, ERDGPI 0.3 dB, the targets of issues 5 and 6). time = CPU"
    echo "seconds (user + system) of \`erd generate\` (load, mesh, write), $JOBS cases at once on a shared machine."
    echo "Misses of the targets and their likely causes: docs/DECISIONS.md \"ED and GPI\", \"ERD model and methods\"."
    echo "The sections after the thesis tables are written by the command each one names (make codec-bench,"
    echo "make bench, tools/eval_*.sh) and kept when another command rewrites the file."
    echo "ERDED and ERDGPI appear twice: \"thesis method\" is \`erd generate --thesis\` (the thesis's wedge"
    echo "values, line search alpha in [1, 1.5] px, ERDED density zeroed on edge pixels only, ERDGPI refined"
    echo "against the supersampled approximation; this is what the reproduction targets are judged on),"
    echo "\"erd default\" is what \`erd generate\` does without flags (our least-squares wedge refit, alpha in"
    echo "[0.75, 1] px, edge radius 1 px, point-evaluated ERDGPI errors; docs/DECISIONS.md \"ERD model and methods\")."
    echo
    # Every variant side by side (issue 45): PSNR and CPU seconds per case, medians at the foot.
    echo "## Every method: PSNR dB / CPU s on the thesis's 12 cases (issue 45)"
    echo
    echo "Basic model: ED, GPI (the thesis's), GPR, GPRFS, ID (the removal methods, docs/DECISIONS.md"
    echo "\"Point removal\"); ERD model: ERDED, ERDGPI, ERDGPR (ERDGPI to 1.5N, then removal to N: the"
    echo "recommended default). +bpr: \`--bpr $BPR\`; +optimize: \`--optimize\`; +thesis: \`--thesis\`."
    echo
    printf '| variant |'; for img in bull lena peppers; do for d in ${DENSITIES[$img]}; do printf ' %s %s |' "$img" "$d"; done; done
    printf ' median PSNR | median gain over GPI | CPU s (sum) |\n'
    printf '|---|'; for img in bull lena peppers; do for d in ${DENSITIES[$img]}; do printf -- '---:|'; done; done; printf -- '---:|---:|---:|\n'
    for v in "${variants[@]}"; do
        awk -v v="$v" -v order="bull 0.125 bull 0.25 bull 0.5 bull 1 lena 0.5 lena 1 lena 2 lena 3 peppers 0.5 peppers 1 peppers 2 peppers 3" '
            function median(a, n,    i, j, x) {  # sorts a[1..n] in place (mawk has no asort)
                if (!n) return 0
                for (i = 2; i <= n; i++) { x = a[i]; for (j = i - 1; j >= 1 && a[j] > x; j--) a[j + 1] = a[j]; a[j + 1] = x }
                return (n % 2) ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
            }
            $6 ~ /^[0-9.]+$/ { p[$1 " " $2 " " $3] = $6; t[$1 " " $2 " " $3] = $7 }
            END {
                n = split(order, o, " "); line = "| " v " |"; k = 0; cpu = 0
                for (i = 1; i < n; i += 2) {
                    c = o[i] " " o[i + 1]
                    if ((v " " c) in p) {
                        line = line sprintf(" %.2f / %.2f |", p[v " " c], t[v " " c]); ps[++k] = p[v " " c]; cpu += t[v " " c]
                        if (("gpi " c) in p) gs[++kg] = p[v " " c] - p["gpi " c]
                    } else line = line " - |"
                }
                med = median(ps, k); gm = median(gs, kg)
                printf "%s %.2f | %+.2f | %.2f |\n", line, med, gm, cpu
            }' "$OUT/raw.txt"
    done
    echo
    for v in "${variants[@]}"; do
        m=${v%%+*}
        [[ -n ${TABLE[$m]:-} ]] || continue
        echo "## $(title "$v") (thesis Table ${TABLE[$m]})"
        echo
        echo "| image | density % | N | ours | thesis | diff | met | time s |"
        echo "|---|---:|---:|---:|---:|---:|:-:|---:|"
        for img in bull lena peppers; do
            read -r -a th <<<"${THESIS[$m.$img]}"
            i=0
            for d in ${DENSITIES[$img]}; do
                line=$(awk -v m="$v" -v im="$img" -v d="$d" '$1 == m && $2 == im && $3 == d' "$OUT/raw.txt")
                [[ -n $line ]] || { i=$((i + 1)); continue; }
                read -r _ _ _ req got psnr secs <<<"$line"
                n=$got; [[ $req == "$got" ]] || n="$got of $req"
                awk -v img="$img" -v d="$d" -v n="$n" -v p="$psnr" -v t="${th[$i]}" -v tol="${TOL[$m]}" -v s="$secs" 'BEGIN {
                    if (p ~ /^[0-9.]+$/ || p == "inf") {
                        diff = p - t; met = (p == "inf" || diff >= -tol) ? "yes" : "no"
                        printf "| %s | %s | %s | %.2f | %.2f | %+.2f | %s | %s |\n", img, d, n, p, t, diff, met, s
                    } else printf "| %s | %s | %s | %s | %.2f | | no | %s |\n", img, d, n, p, t, s
                }'
                i=$((i + 1))
            done
        done
        echo
        # Summary: cases met, cases within +-tol, median diff.
        for img in bull lena peppers; do
            read -r -a th <<<"${THESIS[$m.$img]}"
            i=0
            for d in ${DENSITIES[$img]}; do
                awk -v m="$v" -v im="$img" -v d="$d" -v t="${th[$i]}" '$1 == m && $2 == im && $3 == d && $6 ~ /^[0-9.]+$/ {print $6 - t}' "$OUT/raw.txt"
                i=$((i + 1))
            done
        done | sort -g | awk -v tol="${TOL[$m]}" '
            { d[NR] = $1; if ($1 >= -tol) met++; if ($1 >= -tol && $1 <= tol) within++ }
            END {
                if (NR == 0) { print "No results.\n"; exit }
                med = (NR % 2) ? d[(NR + 1) / 2] : (d[NR / 2] + d[NR / 2 + 1]) / 2
                printf "Met (ours >= thesis - %.1f dB): %d of %d; within +-%.1f dB: %d of %d; median diff %+.2f dB.\n\n", tol, met, NR, tol, within, NR, med
            }'
    done
    # Gains of the ERD methods over our own baselines (issue 6; targets: ERDGPI - GPI median >= 1.0 dB,
    # ERDED - ED >= 3.0 dB), for both variants, and of our default over the thesis method.
    for pair in "erdgpi+thesis gpi" "erdgpi gpi" "erded+thesis ed" "erded ed" "erdgpi erdgpi+thesis" "erded erded+thesis" \
                "erdgpi erdgpi+previous" "erded erded+previous" "gpi+optimize gpi" "ed+optimize ed" \
                "gpr gpi" "gprfs gpi" "id gpi" "erdgpr erdgpi" "erdgpr gpr" "erdgpr id" "erdgpr gpi+optimize"; do
        read -r a b <<<"$pair"
        grep -q "^$a " "$OUT/raw.txt" && grep -q "^$b " "$OUT/raw.txt" || continue
        A=$(title "$a"); B=$(title "$b")
        case $pair in
            "erdgpi"*" gpi") target=" (target: median >= +1.0 dB)" ;;
            "gpr gpi"|"gprfs gpi"|"id gpi") target=" (issue 45: the best removal method >= +0.7 dB median)" ;;
            "erdgpr erdgpi") target=" (issue 45: the default against 531d603's (ERDGPI's, byte-identical): >= +0.5 dB median)" ;;
            "erdgpr gpr"|"erdgpr id"|"erdgpr gpi+optimize") target=" (issue 45: >= +1.5 dB median over the best basic-model method)" ;;
            "erded"*" ed") target=" (target: median >= +3.0 dB)" ;;
            *) target="" ;;
        esac
        echo "## $A minus our $B$target"
        echo
        awk -v a="$a" -v b="$b" '
            $6 ~ /^[0-9.]+$/ { p[$1 " " $2 " " $3] = $6; k[$2 " " $3] = 1 }
            END { for (c in k) if ((a " " c) in p && (b " " c) in p) print c, p[a " " c] - p[b " " c] }' "$OUT/raw.txt" |
            sort -k1,1 -k2,2g >"$OUT/gain.$a.$b.txt"
        echo "| image | density % | gain dB |"
        echo "|---|---:|---:|"
        awk '{ printf "| %s | %s | %+.2f |\n", $1, $2, $3 }' "$OUT/gain.$a.$b.txt"
        sort -k3,3g "$OUT/gain.$a.$b.txt" | awk -v A="$A" -v B="$B" '
            { g[NR] = $3 }
            END { if (NR) printf "\nMedian gain of %s over %s: %+.2f dB over %d cases.\n\n", A, B, (NR % 2) ? g[(NR + 1) / 2] : (g[NR / 2] + g[NR / 2 + 1]) / 2, NR }'
    done
} >"$RESULTS"
[[ -s $kept ]] && cat "$kept" >>"$RESULTS"
echo "eval: wrote $RESULTS"
# Table 3.4 (ERDED start-up modes): its own marked section, so it must run after the file is written.
[[ -x tools/eval_startup.sh || -f tools/eval_startup.sh ]] && bash tools/eval_startup.sh "$ERD" "$IMAGES"
# The hard-edged table (issue 15): its own marked section too.
bash tools/eval_hard.sh "$ERD" "$IMAGES"
# The colour table (issue 17): its own marked section too.
bash tools/eval_colour.sh "$(dirname "$ERD")" "$IMAGES"
# The anti-aliased graphics table (issue 44): its own marked section too.
bash tools/eval_graphics.sh "$ERD" "$IMAGES"
grep -E "^(## |Met|Median)" "$RESULTS"
