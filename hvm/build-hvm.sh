#!/usr/bin/env bash
# Builds the icecap HVM tool chain (the Java-to-C compiler, its SCJ library and our patched VM
# sources) into a cache outside the tree and prints the tool chain's folder on stdout.
#
#   hvm/build-hvm.sh [--unpatched] [--check]
#
# Source: HVM_SRC (an hvm-scj folder or the hvm-scj-4d31e23 tarball); without it, with network
# access, a clone of github.com/scj-devel/hvm-scj at the pinned commit.
# JDK 8 class library (HVM translates JDK 8's java.lang): $JAVA8_HOME's rt.jar, else the
# PyPI wheel pysemgenjar-packr==0.1.0 (OpenJDK 1.8.0_191).
# Jars: bcel 6.0 and seven Eclipse jars (compile time only) from Maven Central, see
# toolchain-deps.pom.xml.
# Cache: ${JMCLBENCH_CACHE:-~/.cache/jmclbench}/hvm/toolchain-<key>, key = hash of the source
# (the pinned commit's, for its clone and its tarball alike), our patches and this script;
# --unpatched builds the upstream VM (to show what the patches fix).
# --check says whether the tool chain can be built here (exit 0) or why not (exit 1), building
# nothing. An HVM_SRC that is not an hvm-scj folder or tarball is bad input: one line, exit 2
# (with or without --check).
# The folder holds: src/ (the hvm-scj tree, patched), lib/ (jars), rt.jar, tools/ (compiled
# compiler), sdk/ (compiled icecapSDK), KEY.
# Exit codes: 0 built (or cached); 1 the build failed, or this machine cannot build it (a line says
# what failed: a missing tool, the clone, a step); 2 bad usage (an unknown option, a bad HVM_SRC).
set -euo pipefail

HERE=$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)
. "$HERE/script-options.sh"
HVM_COMMIT=4d31e231688a7fdaddd464d21a3923b435d11683
HVM_REPO=https://github.com/scj-devel/hvm-scj
# The pinned commit's tarball (../shared/vendor/README.md): its build is the clone's, one cache entry.
HVM_TARBALL_SHA256=07e4964499f7c85a7649e302c5f7b9fe8cdfa7df80928eb4549b06704c56f2fb
WHEEL=pysemgenjar-packr==0.1.0
RT_JAR_SHA256=4994e9fa2877deada22c102eb8d234454a236bd37d32c0ce88c3609fc047c385
CACHE=${JMCLBENCH_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/jmclbench}/hvm

patched=1
check=0
for a in "$@"; do
    case "$a" in
        --unpatched) patched=0 ;;
        --check) check=1 ;;
        -h|--help) header_help; exit 0 ;;
        *) bad "unknown option: $a" ;;
    esac
done

log() { echo "build-hvm: $*" >&2; }
fail() { echo "build-hvm: $*" >&2; exit 1; }

# ---- what is missing on this machine (also the answer of --check) ----
problems=()
for tool in javac java gcc mvn tar patch sha256sum; do
    command -v "$tool" >/dev/null || problems+=("$tool is not installed")
done
if [ "$(uname -m)" != x86_64 ] || [ "$(uname -s)" != Linux ]; then
    problems+=("icecap's only 64-bit POSIX target is x86_64 Linux (this is $(uname -s) $(uname -m))")
fi
# HVM_SRC is checked first and alone: a wrong path is the user's input, not this machine's lack.
if [ -n "${HVM_SRC:-}" ]; then
    bad_src() { bad "HVM_SRC=$HVM_SRC: $*"; }
    if [ -d "$HVM_SRC" ]; then
        [ -d "$HVM_SRC/icecapvm/src" ] || bad_src "not an hvm-scj folder (no icecapvm/src)"
    elif [ -f "$HVM_SRC" ]; then
        # the pinned tarball is known good; another is listed (a second or so) before it is keyed
        if [ "$(sha256sum "$HVM_SRC" | cut -c1-64)" != "$HVM_TARBALL_SHA256" ]; then
            listing=$(tar -tzf "$HVM_SRC" 2>/dev/null) || bad_src "not a gzip tarball"
            grep -q '^hvm-scj/icecapvm/src/' <<< "$listing" || bad_src "not an hvm-scj tarball (no hvm-scj/icecapvm/src)"
            unset listing
        fi
    elif [ -e "$HVM_SRC" ]; then
        bad_src "neither a folder nor a tarball"
    else
        bad_src "no such file or folder"
    fi
else
    command -v git >/dev/null || problems+=("HVM_SRC is not set and git is not installed to clone $HVM_REPO")
fi
# A cache that cannot be written failed the build with mkdir's words after --check said it could be
# built: the user's JMCLBENCH_CACHE is bad input, the default one this machine's lack.
cache_why=$(why_not_writable "$CACHE")
if [ -n "$cache_why" ]; then
    [ -z "${JMCLBENCH_CACHE:-}" ] || bad "JMCLBENCH_CACHE=$JMCLBENCH_CACHE: cannot write there ($cache_why)"
    problems+=("the cache $CACHE cannot be written ($cache_why)")
fi
rt_jar_of_java8() {
    local h=${JAVA8_HOME:-}
    [ -n "$h" ] || return 1
    for f in "$h/jre/lib/rt.jar" "$h/lib/rt.jar"; do
        [ -f "$f" ] && { echo "$f"; return 0; }
    done
    return 1
}
if [ -n "${JAVA8_HOME:-}" ] && ! rt_jar_of_java8 >/dev/null; then
    problems+=("JAVA8_HOME=$JAVA8_HOME has no jre/lib/rt.jar")
fi
if [ -z "${JAVA8_HOME:-}" ] && [ ! -f "$CACHE/deps/rt.jar" ]; then
    command -v pip3 >/dev/null || command -v pip >/dev/null || python3 -m pip --version >/dev/null 2>&1 \
        || problems+=("no JAVA8_HOME and no pip to fetch the JDK 8 class library ($WHEEL)")
fi
if [ ${#problems[@]} -gt 0 ]; then
    printf 'build-hvm: cannot build the icecap HVM: %s\n' "${problems[@]}" >&2
    exit 1
fi

# ---- the source and its key ----
src_kind= src_id=
if [ -n "${HVM_SRC:-}" ]; then
    HVM_SRC=$(readlink -f "$HVM_SRC")
    if [ -d "$HVM_SRC" ]; then
        src_kind=dir
        src_id=$(cd "$HVM_SRC" && find icecaptools/src icecaptoolstest/src icecapSDK/src icecapvm/src -type f -print0 \
            | sort -z | xargs -0 sha256sum | sha256sum | cut -c1-64)
    else
        src_kind=tar
        src_id=$(sha256sum "$HVM_SRC" | cut -c1-64)
        [ "$src_id" != "$HVM_TARBALL_SHA256" ] || src_id=$HVM_COMMIT
    fi
else
    src_kind=git
    src_id=$HVM_COMMIT
fi
patch_id=none
if [ $patched = 1 ]; then
    patch_id=$(cat "$HERE"/patches/*.patch | sha256sum | cut -c1-64)
fi
key=$(printf '%s\n' "$src_id" "$patch_id" "$(sha256sum "$HERE/build-hvm.sh" "$HERE/toolchain-deps.pom.xml")" \
    | sha256sum | cut -c1-16)
[ $patched = 1 ] || key=unpatched-$key
out=$CACHE/toolchain-$key
if [ $check = 1 ]; then
    if [ -f "$out/KEY" ]; then log "can be built (cached: $out)"; else log "can be built (not cached yet: $out)"; fi
    exit 0
fi
if [ -f "$out/KEY" ]; then
    echo "$out"
    exit 0
fi

mkdir -p "$CACHE"
tmp=$(mktemp -d "$CACHE/.build.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# ---- 1. the hvm-scj tree, patched ----
log "unpacking the icecap sources ($src_kind)"
# Each step's own words go to a log, and its last line into ours: a failed step is one line naming
# it (under set -e, `a && b` went on past a failed a, to a misleading "no icecapvm/src").
said() { local l; l=$(grep -v '^[[:space:]]*$' "$tmp/step.log" | tail -n1) || true; echo "${l:-no message}"; }
case $src_kind in
    dir) { mkdir "$tmp/src" && (cd "$HVM_SRC" && tar cf - icecaptools icecaptoolstest icecapSDK icecapvm) \
           | tar xf - -C "$tmp/src"; } 2> "$tmp/step.log" || fail "cannot copy the HVM source from $HVM_SRC: $(said)" ;;
    tar) { tar xzf "$HVM_SRC" -C "$tmp" && mv "$tmp/hvm-scj" "$tmp/src"; } 2> "$tmp/step.log" \
           || fail "cannot unpack $HVM_SRC: $(said)" ;;
    git) git clone -q "$HVM_REPO" "$tmp/src" 2> "$tmp/step.log" || fail "cannot clone $HVM_REPO: $(said)"
         git -C "$tmp/src" checkout -q "$HVM_COMMIT" 2> "$tmp/step.log" \
             || fail "cannot check out commit $HVM_COMMIT of $HVM_REPO: $(said)" ;;
esac
rm -f "$tmp/step.log"
[ -d "$tmp/src/icecapvm/src" ] || fail "no icecapvm/src in the HVM source"
if [ $patched = 1 ]; then
    for p in "$HERE"/patches/*.patch; do
        patch -s -p1 -d "$tmp/src" < "$p" || fail "patch $(basename "$p") does not apply to this HVM source"
    done
fi

# ---- 2. jars from Maven Central and the JDK 8 class library (shared between keys) ----
deps=$CACHE/deps
mkdir -p "$deps"
if [ ! -f "$deps/lib/bcel-6.0.jar" ] || [ "$(ls "$deps/lib" | wc -l)" -lt 8 ]; then
    log "fetching bcel and the Eclipse compile-time jars from Maven Central"
    rm -rf "$deps/lib.tmp"
    mvn -B -ntp -q -Dstyle.color=never -f "$HERE/toolchain-deps.pom.xml" dependency:copy-dependencies \
        -DexcludeTransitive=true -DoutputDirectory="$deps/lib.tmp" >&2 || fail "could not fetch the jars from Maven Central"
    rm -rf "$deps/lib" && mv "$deps/lib.tmp" "$deps/lib"
fi
cp -r "$deps/lib" "$tmp/lib"
if rt=$(rt_jar_of_java8); then
    log "JDK 8 class library from JAVA8_HOME: $rt"
    cp "$rt" "$tmp/rt.jar"
else
    if [ ! -f "$deps/rt.jar" ]; then
        log "fetching the JDK 8 class library (PyPI wheel $WHEEL)"
        pip=(python3 -m pip)
        "${pip[@]}" --version >/dev/null 2>&1 || pip=(pip3)
        rm -rf "$deps/wheel"
        "${pip[@]}" download -q --no-deps --only-binary=:all: --python-version 3.6 --platform manylinux1_x86_64 \
            --implementation cp --abi none -d "$deps/wheel" "$WHEEL" >&2 || fail "could not download $WHEEL"
        python3 - "$deps/wheel" "$deps/rt.jar.tmp" <<'EOF' || fail "no semgenjar/jre/lib/rt.jar in the $WHEEL wheel"
import glob, shutil, sys, zipfile
wheel = glob.glob(sys.argv[1] + "/*.whl")[0]
with zipfile.ZipFile(wheel) as z, z.open("semgenjar/jre/lib/rt.jar") as src, open(sys.argv[2], "wb") as dst:
    shutil.copyfileobj(src, dst)
EOF
        [ "$(sha256sum "$deps/rt.jar.tmp" | cut -c1-64)" = "$RT_JAR_SHA256" ] \
            || fail "the rt.jar of $WHEEL is not the one expected (sha256 differs)"
        mv "$deps/rt.jar.tmp" "$deps/rt.jar"
        rm -rf "$deps/wheel"
    fi
    cp "$deps/rt.jar" "$tmp/rt.jar"
fi

# ---- 3. the compiler (headless entry point main.CompilationManager) ----
log "compiling the icecap compiler"
S=$tmp/src
javac_quiet() { # javac without its deprecation notes; its errors still go to stderr
    local rc=0
    javac -nowarn -encoding ISO-8859-1 "$@" 2>"$tmp/javac.log" || rc=$?
    grep -v '^Note: ' "$tmp/javac.log" >&2 || true
    return $rc
}
mkdir "$tmp/tools"
javac_quiet -source 8 -target 8 -d "$tmp/tools" -cp "$(ls "$tmp"/lib/*.jar | tr '\n' ':')" \
    -sourcepath "$S/icecaptools/src:$S/icecaptoolstest/src:$S/icecapSDK/src" \
    "$S/icecaptoolstest/src/main/CompilationManager.java" || fail "the icecap compiler does not compile"

# ---- 4. the SCJ library (all of it: the compiler substitutes classes no source names) ----
log "compiling the icecap SDK"
mkdir "$tmp/sdk"
(cd "$S/icecapSDK/src" && find . -name '*.java' -not -path './test/*' -not -path './minicdj/*') \
    | sed "s|^\./|$S/icecapSDK/src/|" > "$tmp/sdk.list"
javac_quiet -source 8 -target 8 -bootclasspath "$tmp/rt.jar" -sourcepath "$S/icecapSDK/src" -d "$tmp/sdk" @"$tmp/sdk.list" \
    || fail "the icecap SDK does not compile"

rm -f "$tmp/sdk.list" "$tmp/javac.log"
printf 'source %s %s\npatches %s\n' "$src_kind" "$src_id" "$patch_id" > "$tmp/KEY"
trap - EXIT
if ! mv -T "$tmp" "$out" 2>/dev/null; then
    rm -rf "$tmp" # another build finished first
fi
log "tool chain ready: $out"
echo "$out"
