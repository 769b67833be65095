# Sourced by the eval scripts. put_section MARK SECTION_FILE RESULTS_FILE replaces the block
# between "<!-- MARK..." and "<!-- /MARK -->" in RESULTS_FILE with SECTION_FILE (which holds both
# marker lines), or appends it when the block is not there yet.
put_section() {
    local mark=$1 section=$2 results=$3
    if [[ -f $results ]] && grep -q "^<!-- $mark" "$results"; then
        awk -v f="$section" -v m="$mark" '
            index($0, "<!-- " m) == 1 { while ((getline l < f) > 0) print l; skip = 1; next }
            $0 == "<!-- /" m " -->" { skip = 0; next }
            !skip' "$results" >"$results.tmp" && mv "$results.tmp" "$results"
    else
        { [[ -f $results ]] && echo; cat "$section"; } >>"$results"
    fi
}

# eval_setup NAME SUBDIR ERD IMAGES: the start of an eval script: ERD and IMAGES made absolute, JOBS
# (default 2), the repository as the working directory, OUT=out/eval/SUBDIR and docs/ made,
# RESULTS=docs/RESULTS.md; one line and status 1 when ERD is not built.
eval_setup() {
    local name=$1
    ERD=$3
    IMAGES=$4
    JOBS=${JOBS:-2}
    [[ $IMAGES != /* ]] && IMAGES=$PWD/$IMAGES
    [[ $ERD == */* && $ERD != /* ]] && ERD=$PWD/$ERD
    cd "$(dirname "${BASH_SOURCE[0]}")/.." || return 1
    OUT=out/eval/$2
    RESULTS=docs/RESULTS.md
    mkdir -p "$OUT" docs
    [[ -x $ERD ]] || { echo "$name: $ERD is not built (try: make)"; return 1; }
}
