# Sourced by the scans, which print a line or two of each run they make: scan_report LABEL PATTERN PICK DIR COMMAND...
# runs COMMAND in DIR and prints the lines of its output that match the extended regex PATTERN, each after LABEL; PICK
# is "first" (the first such line) or a number N (the last N). A run that printed no such line says so, with its exit
# code and its last lines, where a scan used to print nothing for it; either way the scan goes on to its next run.
scan_report() {
    local label=$1 pattern=$2 pick=$3 dir=$4 code=0 log picked
    shift 4
    log=$(mktemp)
    (cd "$dir" && "$@") > "$log" 2>&1 || code=$?
    if [ "$pick" = first ]; then
        picked=$(grep -E -m 1 -- "$pattern" "$log" || true)
    else
        picked=$(grep -E -- "$pattern" "$log" | tail -n "$pick" || true)
    fi
    if [ -n "$picked" ]; then
        echo "$picked" | awk -v label="$label" '{ sub(/^ */, ""); print label $0 }'
    else
        echo "${label}no line of the run matched '$pattern' (exit code $code); its last lines:"
        tail -n 8 "$log" | sed 's/^/    /'
    fi
    rm -f "$log"
}
