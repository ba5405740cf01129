#!/usr/bin/env bash
# Compiles core-immortal and scj-mission against the icecap SDK's own javax.safetycritical and
# javax.realtime (SCJ draft 0.111, from source), not against rtsj-compat: the mission must be
# plain SCJ; so does rtsj-compat's probe program. Then compiles a seeded source that uses an rtsj-compat-only method and expects that
# to FAIL, so that the check cannot pass vacuously (e.g. by reaching rtsj-compat after all).
#
#   HVM_SRC=/path/to/hvm-scj-4d31e23.tar.gz scripts/check-icecap-api.sh
#   HVM_SRC=/path/to/hvm-scj scripts/check-icecap-api.sh      (a folder holding icecapSDK/src)
#
# A tarball is unpacked once into a cache outside the tree (${XDG_CACHE_HOME:-~/.cache}/jmclbench).
set -euo pipefail
home=$(cd "$(dirname "$0")/.." && pwd)
src=${HVM_SRC:-}
if [ -z "$src" ]; then
    echo "check-icecap-api: HVM_SRC is not set (the hvm-scj folder or its tarball)" >&2
    exit 2
fi
if [ -f "$src" ]; then
    sum=$(sha256sum "$src" | cut -c1-16)
    cache=${XDG_CACHE_HOME:-$HOME/.cache}/jmclbench/hvm-scj-$sum
    if [ ! -d "$cache/hvm-scj/icecapSDK/src/javax/safetycritical" ]; then
        rm -rf "$cache.tmp"
        mkdir -p "$cache.tmp"
        tar -xzf "$src" -C "$cache.tmp" hvm-scj/icecapSDK/src \
            || { echo "check-icecap-api: HVM_SRC=$src: not an hvm-scj tarball" >&2; rm -rf "$cache.tmp"; exit 2; }
        rm -rf "$cache"
        mv "$cache.tmp" "$cache"
    fi
    sdk=$cache/hvm-scj/icecapSDK/src
elif [ -d "$src/icecapSDK/src/javax/safetycritical" ]; then
    sdk=$src/icecapSDK/src
elif [ -d "$src/src/javax/safetycritical" ]; then
    sdk=$src/src
elif [ -d "$src/javax/safetycritical" ]; then
    sdk=$src
else
    echo "check-icecap-api: HVM_SRC=$src: no icecapSDK/src/javax/safetycritical there" >&2
    exit 2
fi
command -v ant >/dev/null || { echo "check-icecap-api: needs ant (scripts/install-deps.sh)" >&2; exit 1; }

echo "check-icecap-api: scj-mission against $sdk"
# icecap's sources call Thread-like yield(): JDK 17 warns; the warnings are icecap's, not ours.
ant -q -f "$home/build.xml" -Dscj.api="$sdk" jars

# The probe program, which rtsj-compat's ProbeProgramTest compiles and runs, compiles against icecap too.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/probe" "$tmp/src/seeded" "$tmp/out"
javac --release 8 -nowarn -implicit:none -d "$tmp/probe" -sourcepath "$sdk" \
    "$home/rtsj-compat/src/test/scj-probe/probe/ProbeSafelet.java" \
    || { echo "check-icecap-api: FAILED: the probe program does not compile against $sdk" >&2; exit 1; }

# The seeded source: ImmortalMemory.instance() exists in rtsj-compat (and RTSJ) but not in
# icecap's javax.realtime, so compiling it against icecap must fail.
cat > "$tmp/src/seeded/NotIcecap.java" <<'JAVA'
package seeded;

final class NotIcecap {
    Object area() {
        return javax.realtime.ImmortalMemory.instance();
    }
}
JAVA
if javac --release 8 -nowarn -implicit:none -d "$tmp/out" -sourcepath "$sdk" "$tmp/src/seeded/NotIcecap.java" \
        >"$tmp/seeded.log" 2>&1; then
    echo "check-icecap-api: FAILED: a source using a method icecap lacks compiled against $sdk" >&2
    exit 1
fi
grep -q "cannot find symbol" "$tmp/seeded.log" || { cat "$tmp/seeded.log" >&2; exit 1; }
echo "check-icecap-api: ok (core-immortal, scj-mission and the probe program compile against icecap's SCJ API; the seeded misuse is caught)"
