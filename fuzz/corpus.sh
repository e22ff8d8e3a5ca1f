#!/usr/bin/env bash
# Writes the fuzz targets' seed corpus into DIR: small polygons of every family (in every input format),
# the earcut fixtures, and the inputs the fuzzers found (data/fuzz-regressions); creates the targets'
# working and findings directories beside it.
# Usage: fuzz/corpus.sh POLYDECOMP DIR
set -euo pipefail
polydecomp=$1
dir=$2
source_dir="$(cd "$(dirname "$0")/.." && pwd)"
rm -rf "$dir"
mkdir -p "$dir" "$(dirname "$dir")/fuzz-findings"
for target in "$source_dir"/fuzz/*.cpp; do
  name=$(basename "$target" .cpp)
  mkdir -p "$(dirname "$dir")/fuzz-work/${name//_/-}"
done
# The families, named by the generator's own refusal of an unknown one.
families=$({ "$polydecomp" generate --family '?' --n 3 2>&1 || true; } | sed -n 's/.*families: //p' | tr -d ',')
[ -n "$families" ] || { echo "error: no families named by $polydecomp" >&2; exit 1; }
formats=(txt wkt geojson)
for family in $families; do
  k=0
  for n in 6 8 12 16 24 32; do
    for seed in 1 2; do
      format=${formats[$((k % 3))]}
      k=$((k + 1))
      "$polydecomp" generate --family "$family" --n "$n" --seed "$seed" --format "$format" \
        -o "$dir/$family-$n-$seed.$format" 2>/dev/null || true
    done
  done
done
cp "$source_dir"/data/earcut-fixtures/*.json "$dir/"
rm -f "$dir/expected.json"
cp "$source_dir"/data/fuzz-regressions/* "$dir/" 2>/dev/null || true
ls "$dir" | wc -l | sed 's/$/ seed inputs/'
