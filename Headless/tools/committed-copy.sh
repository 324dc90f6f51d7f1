# Sourced by the scans that edit a constant of the code to measure it: a copy of the committed tree in a temporary
# folder, $work, removed when the script exits, so the checkout is never touched. Needs $root (env.sh).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git -C "$root" archive HEAD | tar -x -C "$work"
