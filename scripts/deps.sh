#!/usr/bin/env bash
# Installs the Debian packages polydecomp needs, if any is missing. Idempotent; silent when all is there.
set -euo pipefail
# clang and its sanitizer and libFuzzer runtimes (libclang-rt-14-dev, only recommended by clang) build
# the sanitizer build of `make test` and `make fuzz`, against the same libstdc++ as g++.
packages=(build-essential clang libclang-rt-14-dev cmake git libcgal-dev libgmp-dev libmpfr-dev libboost-dev
          libboost-program-options-dev libbenchmark-dev libgtest-dev googletest nlohmann-json3-dev
          python3 python3-matplotlib python3-numpy python3-flake8)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "deps: installing ${missing[*]}" >&2
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "error: missing packages ${missing[*]}; install them as root" >&2; exit 1; }
  sudo="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq >/dev/null
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
