# Sourced by the benchmark scripts here (not run on its own): a bad command line is bad input,
# as in every jmclbench command: one line naming the script and the option, and exit 2.
me=$(basename "$0" .sh)

# Run on its own rather than sourced, it did nothing and exited 0 whatever it was given.
if [ "${BASH_SOURCE[0]}" = "$0" ]; then
    case "${1:-}" in
        -h|--help) sed -n '1,2s/^# //p' "$0"; exit 0 ;;
        '') echo "$me: sourced by the benchmark scripts here, not run on its own (see --help)" >&2 ;;
        *) echo "$me: $1: unknown option (see --help)" >&2 ;;
    esac
    exit 2
fi

# The value given to option $1 (the script's "$@" from that option on). Missing or empty ends
# the script: call it as  var=$(value_of "$@")  under set -e, which exits with its status.
value_of() {
    [ $# -ge 2 ] && [ -n "$2" ] || { echo "$me: $1: needs a value" >&2; exit 2; }
    printf '%s' "$2"
}

# Ends the script unless option $1's value $2 is a count (digits only), at most 2147483647: the
# Java programs the scripts hand counts to read them as an int, and would refuse a larger one only
# after the build, naming their own argument rather than the script's option.
require_count() {
    [[ "$2" =~ ^[0-9]+$ ]] && [ ${#2} -le 10 ] && (( 10#$2 <= 2147483647 )) ||
        { echo "$me: $1: $2: not a count (0 to 2147483647)" >&2; exit 2; }
}

# The same, and not 0 (a loop count of 0 is no measurement; cyclictest reads -l 0 as "forever").
require_positive() {
    [[ "$2" =~ ^[0-9]+$ ]] && [ ${#2} -le 10 ] && (( 10#$2 >= 1 && 10#$2 <= 2147483647 )) ||
        { echo "$me: $1: $2: not a positive count (1 to 2147483647)" >&2; exit 2; }
}

# Ends the script unless option $1's value $2 is a list of positive counts separated by $3 ("," or
# " "), such as --particles 100,400: checked here rather than by the first run after a build.
require_counts() {
    local n parts
    IFS="$3" read -ra parts <<< "$2"
    [ ${#parts[@]} -gt 0 ] || { echo "$me: $1: '$2': no count in it" >&2; exit 2; }
    for n in "${parts[@]}"; do
        [[ "$n" =~ ^[0-9]+$ ]] && [ ${#n} -le 10 ] && (( 10#$n >= 1 && 10#$n <= 2147483647 )) ||
            { echo "$me: $1: '$n': not a positive count (in '$2')" >&2; exit 2; }
    done
}

# The overrun policies in code order, '|'-separated, as the C baseline's policy.h defines them (a
# test holds it equal to core-immortal's OverrunPolicy): the choices of a script's --policy.
POLICY_CHOICES=$(sed -n 's/^#define JM_POLICY_LABELS "\(.*\)"$/\1/p' \
    "$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/native/src/policy.h")

# Ends the script unless each word of option $1's value $2 (one or several, separated by $4: ","
# or " ") is one of the '|'-separated $3.
require_choice() {
    local v parts
    IFS="$4" read -ra parts <<< "$2"
    [ ${#parts[@]} -gt 0 ] || { echo "$me: $1: '$2': none of $3" >&2; exit 2; }
    for v in "${parts[@]}"; do
        [[ "$v" != *"|"* && "|$3|" == *"|$v|"* ]] || { echo "$me: $1: '$v': not one of $3" >&2; exit 2; }
    done
}

# Ends the script unless option $1's value $2 is a decimal number >= 0 (digits, an optional
# fraction and exponent), such as the workload's --warmup takes.
require_number() {
    [[ "$2" =~ ^[0-9]+(\.[0-9]*)?([eE][+-]?[0-9]+)?$|^\.[0-9]+([eE][+-]?[0-9]+)?$ ]] ||
        { echo "$me: $1: $2: not a number >= 0" >&2; exit 2; }
}

# Ends the script unless the folder of option $1, $2, exists or can be created: its nearest
# existing ancestor is a writable folder. Checked before the build, and creates nothing.
require_creatable() {
    local d=$2
    while [ ! -e "$d" ] && [ "$d" != / ] && [ "$d" != . ]; do d=$(dirname "$d"); done
    [ -d "$d" ] && [ -w "$d" ] ||
        { echo "$me: $1: $2: cannot be created ($d is not a writable folder)" >&2; exit 2; }
}

# Sets c_warmup, c_iterations and c_time (seconds) of a C timing loop from the JMH options "$@"
# (-wi, -i, -r as 1s or 500ms), defaulting to JMH's short run of these scripts: 3, 5 and 1.
c_loop_shape() {
    c_warmup=3 c_iterations=5 c_time=1
    while [ $# -ge 2 ]; do
        case "$1" in
            -wi) c_warmup=$2 ;;
            -i) c_iterations=$2 ;;
            -r) case "$2" in *ms) c_time=$(awk "BEGIN{print ${2%ms}/1000}") ;; *s) c_time=${2%s} ;; *) c_time=$2 ;; esac ;;
        esac
        shift
    done
}

# Ends the script when --java names no java ($1).
require_java() {
    command -v "$1" >/dev/null || { echo "$me: --java: $1: not found" >&2; exit 2; }
}

# Builds the JMH jar (bench/target/benchmarks.jar) and the C timing loops given ($@: targets of
# native/Makefile, e.g. build/kernel-jobs), from the tree at $home.
build_benchmarks() {
    echo "$me: building the benchmarks..." >&2
    (cd "$home" && mvn -q -B -ntp -pl bench -am package -DskipTests >&2)
    if [ $# -gt 0 ]; then
        make -s -C "$home/native" "$@" >&2
    fi
}

# The defaults of a Java/C comparison (kernel-ratio, record-cost) whose results go to
# results/$1/<time>: the JVM of JAVA_HOME (else java on the PATH), a build first, a short JMH run.
java_c_defaults() {
    java=${JAVA_HOME:+$JAVA_HOME/bin/java}
    java=${java:-java}
    out=$home/results/$1/$(date -u +%Y%m%dT%H%M%SZ)
    build=1
    jmh_opts=(-f 1 -wi 3 -i 5 -w 1s -r 1s)
}

# One option every Java/C comparison takes, from the script's "$@" at that option: --java PATH,
# --out DIR, --no-build, -- and the JMH options (all the rest), --help; any other is unknown.
# Sets what it reads and taken, the count of arguments it used (shift "$taken").
java_c_option() {
    case "$1" in
        --java) java=$(value_of "$@"); taken=2 ;;
        --out) out=$(value_of "$@"); require_creatable --out "$out"; taken=2 ;;
        --no-build) build=0; taken=1 ;;
        --) shift; jmh_opts=("$@"); taken=$(($# + 1)) ;;
        -h|--help) usage ;;
        *) unknown_option "$1" ;;
    esac
}

# The set-up of a Java/C comparison (kernel-ratio, record-cost), once its options are read: checks
# $java, builds the JMH jar and the C timing loop $1 (a native/Makefile target) unless $build is 0,
# makes $out, notes the load average in load_before, and gives the C loop the JMH options'
# iteration shape (c_loop_shape "${jmh_opts[@]}"), so that both sides measure alike.
start_java_c_comparison() {
    require_java "$java"
    if [ "$build" = 1 ]; then
        build_benchmarks "$1"
    fi
    mkdir -p "$out"
    load_before=$(cut -d' ' -f1-3 /proc/loadavg)
    c_loop_shape "${jmh_opts[@]}"
}

# Ends the script on a leftover argument $1 that is not an option, as the jmclbench commands do.
unexpected_argument() {
    echo "$me: $1: unexpected argument (see --help)" >&2
    exit 2
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
