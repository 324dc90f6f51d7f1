#!/usr/bin/env bash
# Re-runs a measured variant that was not kept: a change to the code, tried, measured and left out, whose figures the
# README or a comment quotes. Each is a patch in Headless/experiments/NAME.patch whose first lines say
#   Experiment: what was changed and why it was tried
#   Base:       the commit it was measured at (the patch applies to that tree)
#   Run:        the command that prints the figures, run in the copy's root
#   Show:       an extended regex of the output lines that hold them
# The command runs in a copy of the Base commit under a temporary folder, with the patch applied, and with --baseline
# first in a copy without it; the checkout is never touched, and the copies are removed at the end. Needs the
# repository's history (a shallow clone may lack the Base commit).
#   Headless/tools/experiment.sh [--baseline] NAME      (NAME: a file of Headless/experiments without .patch)
#   Headless/tools/experiment.sh --list
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/../env.sh"
experiments="$root/Headless/experiments"

field() { sed -n "s/^$1: *//p" "$2" | head -n 1; }

if [ "${1:-}" = --list ]; then
    for patch in "$experiments"/*.patch; do
        printf '%-28s %s\n' "$(basename "$patch" .patch)" "$(field Experiment "$patch")"
    done
    exit 0
fi
baseline=0
if [ "${1:-}" = --baseline ]; then baseline=1; shift; fi
name=${1:-}
patch="$experiments/$name.patch"
if [ -z "$name" ] || [ $# -ne 1 ] || [ ! -f "$patch" ]; then
    echo "experiment: give one experiment's name (was '${*:-}'); Headless/tools/experiment.sh --list names them" >&2
    exit 2
fi
base=$(field Base "$patch") run=$(field Run "$patch") show=$(field Show "$patch")
for f in Base Run Show; do
    [ -n "$(field "$f" "$patch")" ] || { echo "experiment: $patch has no '$f:' line" >&2; exit 2; }
done
git -C "$root" cat-file -e "$base^{commit}" 2>/dev/null ||
    { echo "experiment: the Base commit $base of $patch is not in this repository's history (a shallow clone?)" >&2; exit 3; }

copies=$(mktemp -d)
trap 'rm -rf "$copies"' EXIT

# Runs the experiment's command in a fresh copy of Base, patched when $1 is 'patched', and prints the lines it shows.
measure() {
    local label=$1 copy="$copies/$1"
    mkdir "$copy"
    git -C "$root" archive "$base" | tar -x -C "$copy"
    if [ "$label" = patched ]; then (cd "$copy" && git apply "$patch"); fi
    echo "== $name, $label (at $base): $run"
    local code=0
    (cd "$copy" && bash -c "$run") > "$copies/$label.log" 2>&1 || code=$?
    if ! grep -E -- "$show" "$copies/$label.log" | sed "s/^ *//"; then
        echo "experiment: no line of its output matches '$show' (exit code $code); its last lines:" >&2
        tail -n 20 "$copies/$label.log" >&2
        exit 1
    fi
    if [ "$code" -ne 0 ]; then echo "(the command exited with code $code)"; fi
}

if [ "$baseline" = 1 ]; then measure baseline; fi
measure patched
