#!/usr/bin/env bash
# Hard-edged images (issue 15): GPI, ERDGPI before (--edges soft: the thesis's edges and 4x4
# supersampled reconstruction, what erd did before hard edges) and ERDGPI after (the default,
# --edges auto) on every `erd synth --kind` picture at 320 x 240 and densities 0.5, 1, 2, 3 %,
# plus the edge kind that auto measured on each picture and on its blurred version (--blur 2).
# Writes its own marked section of docs/RESULTS.md (run by tools/eval.sh after the main tables).
# Usage: tools/eval_hard.sh ERD_BINARY [IMAGES_DIR]   (the photos there: the kind auto picks)
set -u
source "$(dirname "$0")/results_section.sh"
eval_setup eval_hard hard "${1:-build/erd}" "${2:-../shared/images}" || exit 1
KINDS=${KINDS:-$("$ERD" synth --help | sed -n 's/.*hard-edged picture: \(.*\)$/\1/p' | tr -d ',')}
DENS="0.5 1 2 3"

for k in $KINDS; do
    "$ERD" synth -q --kind "$k" -W 320 -H 240 -o "$OUT/$k.pgm" || exit 1
    "$ERD" synth -q --kind "$k" --blur 2 -W 320 -H 240 -o "$OUT/$k.soft.pgm" || exit 1
done

# One case -> "variant kind density psnr edges" (edges: what the .erd header says, - for GPI).
run_case() {
    local v=$1 k=$2 d=$3 flags=() m=erdgpi ext=erd base=$OUT/$2.$1.$3
    case $v in gpi) m=gpi ext=model ;; before) flags=(--edges soft) ;; esac
    # -x 1: a greedy method stops early when no pixel has an error left (PSNR inf), which -x 0 refuses.
    if ! "$ERD" generate -x 1 --method "$m" "${flags[@]}" -i "$OUT/$k.pgm" -d "$d" -o "$base.$ext" >"$base.log" 2>&1 ||
        ! "$ERD" reconstruct "$base.$ext" -o "$base.pgm" >>"$base.log" 2>&1; then
        echo "$v $k $d failed -"; return
    fi
    local edges=-
    [[ $ext == erd ]] && { edges=soft; grep -q '^edges hard' <(head -3 "$base.$ext") && edges=hard; }
    echo "$v $k $d $("$ERD" psnr "$OUT/$k.pgm" "$base.pgm" 2>>"$base.log" || echo failed) $edges"
}
# The kind auto picks for an image (no mesh is kept: 0.5 % is enough to read the header).
kind_of() {
    "$ERD" generate -q --method erdgpi -i "$1" -d 0.5 -o "$OUT/kind.$2.erd" >/dev/null 2>&1 || { echo failed; return; }
    head -3 "$OUT/kind.$2.erd" | grep -q '^edges hard' && echo hard || echo soft
}
export -f run_case
export ERD OUT
cases=()
for k in $KINDS; do for d in $DENS; do for v in gpi before after; do cases+=("$v $k $d"); done; done; done
echo "eval_hard: ${#cases[@]} cases, $JOBS at a time; outputs under $OUT/"
printf '%s\n' "${cases[@]}" | xargs -P "$JOBS" -L 1 bash -c 'run_case "$@"' _ >"$OUT/raw.txt"

section=$(mktemp)
trap 'rm -f "$section"' EXIT
{
    echo "<!-- hard-edges: written by tools/eval_hard.sh; do not edit by hand -->"
    echo "## Hard-edged images (issue 15)"
    echo
    echo "\`erd synth --kind K -W 320 -H 240\` pictures (no anti-aliasing: every edge a step between two"
    echo "pixels; docs/manual.md). PSNR in dB of each model's own reconstruction: GPI (imgsyn), ERDGPI"
    echo "before = \`--edges soft\` (Canny's half-pixel edges, 4x4 supersampled imgsyn_aa: erd's behaviour"
    echo "before hard edges), ERDGPI after = the default \`--edges auto\` (the kind of edge measured from"
    echo "the image; \"edges\" is what it chose). after - GPI is the target column (>= -0.2 on every row)."
    echo
    echo "| image | density % | GPI | ERDGPI before | ERDGPI after | edges | after - GPI |"
    echo "|---|---:|---:|---:|---:|:-:|---:|"
    for k in $KINDS; do
        for d in $DENS; do
            awk -v k="$k" -v d="$d" '
                $2 == k && $3 == d { p[$1] = $4; if ($1 == "after") e = $5 }
                END {
                    g = p["gpi"]; b = p["before"]; a = p["after"]
                    diff = (g ~ /^[0-9.]+$/ && a ~ /^[0-9.]+$/) ? sprintf("%+.2f", a - g) : (a == "inf" ? "inf" : "-")
                    printf "| %s | %s | %s | %s | %s | %s | %s |\n", k, d, g, b, a, e, diff
                }' "$OUT/raw.txt"
        done
    done
    echo
    awk '$4 ~ /^[0-9.]+$|^inf$/ { p[$1 " " $2 " " $3] = ($4 == "inf" ? 999 : $4); k[$2 " " $3] = 1 }
        END {
            for (c in k) if (("gpi " c) in p && ("after " c) in p) { n++; g[n] = p["after " c] - p["gpi " c]; if (g[n] < -0.2) miss++ }
            for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (g[j] < g[i]) { t = g[i]; g[i] = g[j]; g[j] = t }
            med = n ? ((n % 2) ? g[(n + 1) / 2] : (g[n / 2] + g[n / 2 + 1]) / 2) : 0
            printf "ERDGPI after - GPI: median %+.2f dB over %d cases (target > +1); lowest %+.2f; below -0.2 dB: %d (target 0).\n\n", med, n, g[1], miss + 0
        }' "$OUT/raw.txt"
    echo "Edge kind chosen by \`--edges auto\` on each picture and on its blurred version (\`--blur 2\`):"
    echo
    echo "| image | hard-edged picture | blurred picture |"
    echo "|---|:-:|:-:|"
    for k in $KINDS; do echo "| $k | $(kind_of "$OUT/$k.pgm" "$k") | $(kind_of "$OUT/$k.soft.pgm" "$k.soft") |"; done
    echo
    echo "And on the test images (IMAGES_DIR: photos, scans; a soft choice leaves erd's output unchanged):"
    echo
    echo "| image | edges |"
    echo "|---|:-:|"
    for f in "$IMAGES"/*.pgm; do [[ -f $f ]] && echo "| $(basename "$f" .pgm) | $(kind_of "$f" "photo.$(basename "$f" .pgm)") |"; done
    echo
    echo "The photos of the thesis's cases: ERDGPI and ERDED default with \`--edges soft\` (before) and"
    echo "\`--edges auto\` (after); identical files give a change of exactly 0."
    echo
    echo "| method | image | density % | before | after | change | files |"
    echo "|---|---|---:|---:|---:|---:|:-:|"
    for m in erdgpi erded; do
        for c in "bull 0.125" "bull 0.25" "bull 0.5" "bull 1" "lena 0.5" "lena 1" "lena 2" "lena 3" \
                 "peppers 0.5" "peppers 1" "peppers 2" "peppers 3"; do
            read -r img d <<<"$c"
            [[ -f $IMAGES/$img.pgm ]] || continue
            b=$OUT/photo.$m.$img.$d
            "$ERD" generate -q -x 1 -m "$m" --edges soft -i "$IMAGES/$img.pgm" -d "$d" -o "$b.soft.erd" &&
                "$ERD" generate -q -x 1 -m "$m" -i "$IMAGES/$img.pgm" -d "$d" -o "$b.auto.erd" &&
                "$ERD" reconstruct -q "$b.soft.erd" -o "$b.soft.pgm" && "$ERD" reconstruct -q "$b.auto.erd" -o "$b.auto.pgm" || continue
            same=differ; cmp -s "$b.soft.erd" "$b.auto.erd" && same=same
            awk -v m="$m" -v i="$img" -v d="$d" -v p="$("$ERD" psnr "$IMAGES/$img.pgm" "$b.soft.pgm")" \
                -v q="$("$ERD" psnr "$IMAGES/$img.pgm" "$b.auto.pgm")" -v s="$same" \
                'BEGIN { printf "| %s | %s | %s | %.4f | %.4f | %+.4f | %s |\n", m, i, d, p, q, q - p, s }'
        done
    done
    echo "<!-- /hard-edges -->"
} >"$section"

source tools/results_section.sh
put_section hard-edges "$section" "$RESULTS"
echo "eval_hard: wrote the hard-edges section of $RESULTS"
grep -E '^ERDGPI after - GPI' "$RESULTS"
