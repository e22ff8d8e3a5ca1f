#!/usr/bin/env bash
# Installs the Debian packages polydecomp needs, if any is missing, then the npm packages of the
# JavaScript peers (peers/npm). Idempotent; silent when all is there.
set -euo pipefail
# clang and its sanitizer and libFuzzer runtimes (libclang-rt-14-dev, only recommended by clang) build
# the sanitizer build of `make test` and `make fuzz`, against the same libstdc++ as g++.
packages=(build-essential clang libclang-rt-14-dev cmake git libcgal-dev libgeos-dev libgmp-dev libmpfr-dev
          libboost-dev libboost-program-options-dev libbenchmark-dev libgtest-dev googletest nlohmann-json3-dev
          python3 python3-matplotlib python3-numpy python3-flake8
          gmt-dcw python3-netcdf4   # the DCW corpus (make corpus: scripts/build_dcw_corpus.py)
          pybind11-dev python3-pybind11 python3-pytest python3-shapely   # the Python module (python/)
          python3-venv python3-pip python3-setuptools python3-wheel      # its pip install (pyproject.toml)
          procps   # pgrep, with which the orphan test finds a killed run's child
          python3-plotly chromium   # the HTML report (analysis/report.py) and its browser test
          nodejs)  # node runs the JavaScript peers (peers/*.json); any installed nodejs package counts
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "deps: installing ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "error: missing packages ${missing[*]}; install them as root" >&2; exit 1; }
    sudo="sudo"
  fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq >/dev/null
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The JavaScript peers' packages, at the versions peers/npm/package-lock.json pins, into
# peers/npm/node_modules (not committed): again when its stamp, written once `npm ci` has succeeded, is
# missing or older than the lock file (an interrupted `npm ci` leaves a folder, not the stamp).
npm_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/peers/npm"
stamp="$npm_dir/node_modules/.installed"
if [ ! -f "$stamp" ] || [ "$npm_dir/package-lock.json" -nt "$stamp" ]; then
  command -v npm >/dev/null || { echo "error: npm is missing; it installs the JavaScript peers in $npm_dir (Debian: apt-get install npm)" >&2; exit 1; }
  echo "deps: npm ci in $npm_dir" >&2
  (cd "$npm_dir" && npm ci --no-audit --no-fund --loglevel=error >/dev/null)
  touch "$stamp"
fi
