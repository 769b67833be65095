# Sourced by the test scripts whose lines are each a test (raster_test.sh, tiles_test.sh; run_all.sh
# counts their PASS, FAIL and SKIP lines).
# shellcheck shell=bash
check() {  # LABEL COMMAND...: PASS or FAIL with the command's last line
    local label=$1 out
    shift
    if out=$("$@" 2>&1); then echo "PASS: $label: $(tail -1 <<<"$out")"; else echo "FAIL: $label: $(tail -3 <<<"$out" | tr '\n' ' ')"; fi
}
