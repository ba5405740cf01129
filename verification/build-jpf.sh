#!/usr/bin/env bash
# Builds Java PathFinder (jpf-core, branch java-17) with plain javac into a cache outside the
# tree and prints the JPF home it built (a folder with jpf.properties, site.properties and
# build/{jpf,jpf-classes,jpf-annotations,RunJPF}.jar), the layout jpf-core's own Gradle build
# gives. Gradle is not used: its wrapper downloads a distribution, which this machine cannot.
#
# Source, in this order:
#   JPF_CORE_SRC   a jpf-core folder or a tarball that unpacks into one (jpf-core-7ea25de.tar.gz)
#   otherwise      git clone of branch java-17 at the pinned commit (needs network access)
# Patches: verification/jpf-patches/*.patch are applied to the sources (a copy of a JPF_CORE_SRC
# folder, never the folder itself) before the build: model methods jpf-core lacks (README.md).
# Cache: ${JMCLBENCH_CACHE:-~/.cache/jmclbench}/jpf/<key>, where key names the commit (when known)
# and a hash of the patched sources, so another source never reuses a stale build. Without
# JPF_CORE_SRC, a build of the pinned commit's own sources with these patches is used as it is,
# with no clone.
#
# Usage: build-jpf.sh [--quiet] [--link PATH]
#   prints the JPF home on stdout (progress on stderr), points <cache>/current at it, and
#   --link PATH also points PATH at it. A JPF_CORE_SRC that is no jpf-core folder or tarball
#   is bad input: one line naming it, exit 2; no JPF_CORE_SRC and no clone to be had (no network,
#   no git): one line saying how to get the source, exit 3; a build that fails: exit 1.
# JPF runs on JDK 17 only: JPF_JAVA_HOME, else JAVA_HOME when it is 17, else the Debian JDK 17.
set -euo pipefail

PINNED_COMMIT=7ea25de453111be77d09e12eb196fecf2dc6d365
PINNED_TARBALL_SHA256=0bed4e365b7f8f220917fd1acd552e6b22ad374f7d57a77d24de3f2c7d73a2aa
UPSTREAM=https://github.com/javapathfinder/jpf-core

quiet=false
link=""
while [ $# -gt 0 ]; do
    case "$1" in
        --quiet) quiet=true; shift ;;
        --link) [ $# -ge 2 ] || { echo "build-jpf: --link: needs a path" >&2; exit 2; }
                link=$2; shift 2 ;;
        -h|--help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
        *) echo "build-jpf: unknown option $1 (usage: build-jpf.sh [--quiet] [--link PATH])" >&2; exit 2 ;;
    esac
done
# <cache>/current always names the last home built or found (the Maven module's default
# jpf.home); --link PATH also makes PATH a symbolic link to it.
finish() {
    ln -sfn "$1" "$cache/current"
    if [ -n "$link" ]; then
        mkdir -p "$(dirname "$link")"
        ln -sfn "$1" "$link"
    fi
    echo "$1"
}
say() { $quiet || echo "build-jpf: $*" >&2; }
die() { echo "build-jpf: $*" >&2; exit 1; }
bad_src() { echo "build-jpf: JPF_CORE_SRC=$JPF_CORE_SRC: $*" >&2; exit 2; }
# JPF's source cannot be had: the one line says why and what to set (the launcher adds none of its own)
no_src() {
    echo "build-jpf: no Java PathFinder: JPF_CORE_SRC is not set${damaged:+, the build at $damaged is damaged,} and $*;" \
        "set JPF_CORE_SRC to a jpf-core folder or" \
        "tarball (jpf-core-${PINNED_COMMIT:0:7}.tar.gz)" >&2
    exit 3
}

java17_home() {
    local h
    for h in "${JPF_JAVA_HOME:-}" "${JAVA_HOME:-}" /usr/lib/jvm/java-17-openjdk-amd64 /usr/lib/jvm/java-17-openjdk; do
        [ -n "$h" ] && [ -x "$h/bin/javac" ] || continue
        if "$h/bin/java" -XshowSettings:properties -version 2>&1 | grep -q 'java.specification.version = 17$'; then
            echo "$h"; return 0
        fi
    done
    die "JPF (branch java-17) builds and runs on JDK 17 only; set JPF_JAVA_HOME to a JDK 17"
}

cache=${JMCLBENCH_CACHE:-$HOME/.cache/jmclbench}/jpf
patches=$(cd "$(dirname "$0")" && pwd)/jpf-patches
patch_files=()
for f in "$patches"/*.patch; do [ -f "$f" ] && patch_files+=("$f"); done
# A home built from the pinned commit's own sources (the clone or the pinned tarball) says so in
# PINNED, with a hash of the patches applied, so that without JPF_CORE_SRC a build that exists
# is used without cloning again, and a build with other patches (or none) is not.
patch_hash=$(cat /dev/null "${patch_files[@]}" | sha256sum | cut -c1-12)
pinned_mark="$PINNED_COMMIT patches $patch_hash"
# A whole jar ends with the zip end record (jar writes no comment): a build cut short (a full disk,
# a copy killed midway) is no build; Maven's compile of verification failed on it in 400 lines.
whole_jar() { [ "$(tail -c 22 "$1" 2>/dev/null | head -c 4 | od -An -tx1 | tr -d ' \n')" = 504b0506 ]; }
built() { whole_jar "$1/build/jpf.jar" && whole_jar "$1/build/jpf-classes.jar" && [ -f "$1/site.properties" ]; }
damaged=""
if [ -z "${JPF_CORE_SRC:-}" ]; then
    for h in "$cache"/"${PINNED_COMMIT:0:7}"-*; do
        if [ "$(cat "$h/PINNED" 2>/dev/null)" = "$pinned_mark" ]; then
            if built "$h"; then
                say "cached (the pinned commit): $h"
                finish "$h"; exit 0
            fi
            damaged=$h
        fi
    done
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pristine=false

# --- 1. the source tree and what we know of its commit
commit=""
if [ -n "${JPF_CORE_SRC:-}" ]; then
    if [ -d "$JPF_CORE_SRC" ]; then
        src=$(cd "$JPF_CORE_SRC" && pwd)
        commit=$(git -C "$src" rev-parse HEAD 2>/dev/null || true)
    elif [ -f "$JPF_CORE_SRC" ]; then
        tar -xzf "$JPF_CORE_SRC" -C "$work" 2>/dev/null || bad_src "not a readable .tar.gz"
        src=$(find "$work" -mindepth 1 -maxdepth 2 -name jpf.properties -printf '%h\n' | head -1)
        [ -n "$src" ] || bad_src "no jpf-core folder (jpf.properties) inside"
        if [ "$(sha256sum "$JPF_CORE_SRC" | cut -d' ' -f1)" = "$PINNED_TARBALL_SHA256" ]; then
            commit=$PINNED_COMMIT
            pristine=true
        fi
    else
        bad_src "no such folder or file"
    fi
else
    command -v git >/dev/null || no_src "there is no git to clone $UPSTREAM"
    # git's own lines would precede ours: its last one goes into ours
    git clone -q -b java-17 "$UPSTREAM" "$work/jpf-core" 2> "$work/git.log" \
        || no_src "$UPSTREAM cannot be cloned ($(sed -n '/[^[:space:]]/h; ${x;p}' "$work/git.log"))"
    say "no JPF_CORE_SRC: cloned $UPSTREAM (branch java-17)"
    git -C "$work/jpf-core" -c advice.detachedHead=false checkout -q "$PINNED_COMMIT" 2> "$work/git.log" \
        || no_src "commit $PINNED_COMMIT is not in $UPSTREAM"
    src=$work/jpf-core
    commit=$PINNED_COMMIT
    pristine=true
fi
for d in src/main src/peers src/classes/modules src/annotations jpf.properties; do
    if [ ! -e "$src/$d" ]; then
        [ -z "${JPF_CORE_SRC:-}" ] || bad_src "not a jpf-core tree (no $d)"
        die "$src: not a jpf-core tree (no $d)"
    fi
done
if [ ${#patch_files[@]} -gt 0 ]; then
    if [ -d "${JPF_CORE_SRC:-}" ]; then   # the user's folder stays as it is
        mkdir "$work/src"
        cp -R "$src/." "$work/src/"
        src=$work/src
    fi
    command -v patch >/dev/null || die "no patch program to apply $patches"
    for f in "${patch_files[@]}"; do
        patch -s -p1 -d "$src" < "$f" > "$work/patch.log" 2>&1 \
            || { cat "$work/patch.log" >&2; die "$(basename "$f") does not apply to $src"; }
    done
fi

# --- 2. the cache key: the commit (when known) plus a hash of every source file
srchash=$(cd "$src" && find jpf.properties src/main src/peers src/classes src/annotations -type f -print0 \
    | sort -z | xargs -0 sha256sum | sha256sum | cut -c1-12)
key=${commit:+${commit:0:7}-}$srchash
home=$cache/$key
if built "$home"; then
    say "cached: $home"
    ! $pristine || echo "$pinned_mark" > "$home/PINNED"
    finish "$home"; exit 0
fi

jdk=$(java17_home)
javac_=("$jdk/bin/javac" -nowarn -XDsuppressNotes -encoding UTF-8 -g -proc:none -J-Xmx1g)
# javac's many warnings on JPF's model classes go to a log that is shown only when it fails.
javac() { "${javac_[@]}" "$@" >> "$work/javac.log" 2>&1 || { cat "$work/javac.log" >&2; die "javac failed (above)"; }; }
jar=$jdk/bin/jar
say "building jpf-core ${commit:-(commit unknown)} with $jdk/bin/javac into $home"
start=$(date +%s)
out=$work/out
b=$out/build
mkdir -p "$b"/{annotations,main,peers,classes/modules}
sources() { find "$@" -name '*.java' > "$work/list"; echo "@$work/list"; }

# Same source sets and compiler flags as jpf-core's gradle/source-sets.gradle.
say "  annotations, main"
javac -d "$b/annotations" "$(sources "$src/src/annotations")"
javac -cp "$b/annotations" -d "$b/main" "$(sources "$src/src/main")"
say "  peers"
javac -cp "$b/main:$b/annotations" -d "$b/peers" \
    --add-exports java.base/jdk.internal.access=ALL-UNNAMED \
    --add-exports java.base/jdk.internal.misc=ALL-UNNAMED \
    "$(sources "$src/src/peers")"
mods=$src/src/classes/modules
patch=()
for m in "$mods"/*/; do m=$(basename "$m"); patch+=(--patch-module "$m=$mods/$m"); done
say "  model classes (gov, org, and the patched modules $(cd "$mods" && echo *))"
javac -cp "$b/main:$b/annotations" -d "$b/classes" "${patch[@]}" \
    --add-exports java.base/sun.net.www.protocol.http=ALL-UNNAMED --add-reads java.base=ALL-UNNAMED \
    "$(sources "$src/src/classes/gov" "$src/src/classes/org")"
javac -cp "$b/annotations:$b/classes:$b/main" -d "$b/classes/modules" "${patch[@]}" \
    --add-exports java.base/sun.net.www.protocol.http=ALL-UNNAMED --add-reads java.base=ALL-UNNAMED \
    --module-source-path "$mods" "$(sources "$mods")"

# Jars with the contents jpf-core's build.gradle gives them.
say "  jars"
printf 'revision=%s\n' "${commit:-unknown}" > "$b/main/gov/nasa/jpf/build.properties"
"$jar" cf "$b/jpf-annotations.jar" -C "$b/annotations" .
"$jar" cf "$b/jpf.jar" -C "$b/main" . -C "$b/peers" . -C "$b/annotations" . \
    $(cd "$b/classes" && find org/junit -maxdepth 1 -name '*.class' -printf '-C '"$b/classes"' %p\n')
"$jar" cf "$b/jpf-classes.jar" -C "$b/classes" . -C "$b/annotations" . \
    $(cd "$b/main" && for c in gov/nasa/jpf/JPFShell gov/nasa/jpf/vm/Verify gov/nasa/jpf/util/TypeRef \
        gov/nasa/jpf/util/test/TestJPF gov/nasa/jpf/util/test/TestMultiProcessJPF gov/nasa/jpf/util/test/TestJPFHelper; do
        [ -f "$c.class" ] && echo "-C $b/main $c.class"; done)
runjpf=()
for c in tool/Run tool/RunJPF Config ConfigChangeListener 'Config$MissingRequiredKeyException' JPFClassLoader \
        JPFShell JPFException JPFConfigException JPFTargetException util/JPFSiteUtils util/FileUtils \
        util/StringMatcher util/Pair; do
    [ -f "$b/main/gov/nasa/jpf/$c.class" ] && runjpf+=(-C "$b/main" "gov/nasa/jpf/$c.class")
done
printf 'Main-Class: gov.nasa.jpf.tool.RunJPF\n' > "$work/manifest"
"$jar" cfm "$b/RunJPF.jar" "$work/manifest" "${runjpf[@]}"
rm -rf "$b"/{annotations,main,peers,classes}

# jpf.properties finds the jars under ${jpf-core}/build; site.properties names this home, so
# no site.properties in the user's home or working directory is needed (pass +site=).
cp "$src/jpf.properties" "$out/"
cp "$src/LICENSE-2.0.txt" "$out/" 2>/dev/null || true
cat > "$out/site.properties" <<EOF
# written by jmclbench verification/build-jpf.sh
jpf-core = $home
extensions = \${jpf-core}
EOF
printf 'commit=%s\nsource=%s\npatches=%s\nbuilt=%s\njava=%s\n' "${commit:-unknown}" "${JPF_CORE_SRC:-$UPSTREAM}" \
    "$(cd "$patches" 2>/dev/null && ls *.patch 2>/dev/null | tr '\n' ' ')" "$(date -u +%FT%TZ)" "$jdk" > "$out/BUILD-INFO"
! $pristine || echo "$pinned_mark" > "$out/PINNED"
mkdir -p "$cache"
rm -rf "$home.tmp.$$"
mv "$out" "$home.tmp.$$"
# a damaged build under this key (never one in progress: that is a $home.tmp.PID) is replaced;
# a whole one that another build made meanwhile is kept
if [ -e "$home" ] && ! built "$home"; then rm -rf "$home"; fi
mv -T "$home.tmp.$$" "$home" 2>/dev/null || { rm -rf "$home.tmp.$$"; }   # another build won the race
say "done in $(( $(date +%s) - start )) s: $(cd "$home/build" && ls *.jar | tr '\n' ' ')"
finish "$home"
