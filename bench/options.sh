# Sourced by the benchmark scripts here (not run on its own): a bad command line is bad input,
# as in every jmclbench command: one line naming the script and the option, and exit 2.
me=$(basename "$0" .sh)

# The value given to option $1 (the script's "$@" from that option on). Missing or empty ends
# the script: call it as  var=$(value_of "$@")  under set -e, which exits with its status.
value_of() {
    [ $# -ge 2 ] && [ -n "$2" ] || { echo "$me: $1: needs a value" >&2; exit 2; }
    printf '%s' "$2"
}

# Ends the script unless option $1's value $2 is a count (digits only).
require_count() {
    [[ "$2" =~ ^[0-9]+$ ]] || { echo "$me: $1: $2: not a count" >&2; exit 2; }
}

# --help: prints the script's header comment (from line 2 to the first line that is not a
# comment) without its "# ", and exits 0; read from the script, so it cannot drift from it.
usage() {
    awk 'NR > 1 { if (!/^#/) exit; sub(/^# ?/, ""); print }' "$0"
    exit 0
}

# Ends the script on an option $1 it does not know, as the jmclbench commands do.
unknown_option() {
    echo "$me: $1: unknown option (see --help)" >&2
    exit 2
}
