#!/usr/bin/env bash
# Installs the Debian packages polydecomp needs, if any is missing. Idempotent; silent when all is there.
set -euo pipefail
packages=(build-essential cmake git libcgal-dev libgmp-dev libmpfr-dev libboost-dev
          libboost-program-options-dev libbenchmark-dev libgtest-dev googletest
          python3 python3-matplotlib python3-numpy)
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
