# Sourced by the eval scripts: put_section MARK SECTION_FILE RESULTS_FILE replaces the block
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
