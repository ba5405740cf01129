# Sourced by the hvm scripts (not run on their own): the parts of their command lines they share.
# Bad input is one line naming the script and the option, and exit 2, as in every jmclbench command;
# a failure (a build, a tool, a run) is exit 1. Each script's --help lists its exit codes.
me=$(basename "$0" .sh)

# Ends the script: bad input, one line.
bad() { echo "$me: $*" >&2; exit 2; }

# Prints the script's --help: its header comment, from the second line to the first that is no comment.
header_help() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }

# Why PATH cannot be a folder to write into, or nothing when it can: it is a folder, or is absent
# below one, that can be written. A file in its place or above it, or a read-only folder, failed
# the script at its end (mkdir's or mv's words, exit 1), after the build or the runs.
why_not_writable() {
    local p=$1
    while [ ! -e "$p" ]; do p=$(dirname "$p"); done
    if [ ! -d "$p" ]; then echo "$p is not a folder"; elif [ ! -w "$p" ]; then echo "$p cannot be written"; fi
}

# Ends the script (bad input) when OPTION's folder FOLDER (default: the value VALUE) cannot be written.
writable_folder() { # writable_folder OPTION VALUE [FOLDER]
    local why
    why=$(why_not_writable "${3:-$2}")
    [ -z "$why" ] || bad "$1: $2: $why"
}

# Ends the script (a failure, exit 1) when a tool it runs is not installed: it was bash's
# "command not found" mid-way, exit 127.
need_tools() { # need_tools TOOL...
    local missing=() t
    for t in "$@"; do command -v "$t" >/dev/null || missing+=("$t"); done
    [ ${#missing[@]} -eq 0 ] || { echo "$me: not installed: ${missing[*]}" >&2; exit 1; }
}
