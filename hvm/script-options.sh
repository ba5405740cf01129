# Sourced by the hvm scripts (not run on their own): the parts of their command lines they share.
# Bad input is one line naming the script and the option, and exit 2, as in every jmclbench command;
# a failure (a build, a tool, a run) is exit 1. Each script's --help lists its exit codes.
me=$(basename "$0" .sh)

# Ends the script: bad input, one line.
bad() { echo "$me: $*" >&2; exit 2; }

# Prints the script's --help: its header comment, from the second line to the first that is no comment.
header_help() { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; }
