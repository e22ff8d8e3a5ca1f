#!/usr/bin/python3
"""Builds the DCW corpus: every country outline of the Digital Chart of the World, as Debian's gmt-dcw
package ships it, one polygon file per part, and its manifest (docs/corpora.md).

gmt-dcw's dcw-gmt.nc holds, per country code CC, the variables CC_lon and CC_lat: 16-bit integers on
the country's own lattice (lon = min + value / scale). A value 65535 in CC_lon separates the rings; the
CC_lat value beside it is 1 when the ring after it is a hole of the ring before. Each outer ring and
its holes are written as one WKT POLYGON in the lattice's integers: an affine image of the outline
(positive scales), so every orientation, and so simplicity, the reflex vertices and every piece
count, is exactly the outline's on the lon/lat plane.

Then `polydecomp corpus --dir OUT --json` reads every file through the checked door, and the manifest
(OUT.manifest.json, beside the folder) lists every part: country, part, file, vertices written, holes,
and n, r and h or why it was refused; the summary goes to stderr and to OUT.manifest.md.

usage: build_dcw_corpus.py [--netcdf FILE] [--out DIR] [--build DIR]
"""

import argparse
import collections
import json
import os
import shutil
import subprocess
import sys

DCW_FOLDER = "/usr/share/gmt-dcw"
SEPARATOR = 65535
HOLE_FLAG = 1


def countries(folder):
    """{code: name} of dcw-countries.txt (lines "CONTINENT CODE NAME")."""
    names = {}
    with open(os.path.join(folder, "dcw-countries.txt"), encoding="utf-8") as f:
        for line in f:
            fields = line.split(None, 2)
            if len(fields) == 3 and not line.startswith("#"):
                names[fields[1]] = fields[2].strip()
    return names


def parts_of(lon, lat):
    """The country's parts, each [outer ring, hole, ...], a ring a list of (x, y) lattice points."""
    parts, ring, hole = [], None, False
    for x, y in zip(lon.tolist(), lat.tolist()):
        if x == SEPARATOR:
            if ring:
                (parts[-1].append(ring) if hole and parts else parts.append([ring]))
            ring, hole = [], y == HOLE_FLAG
        elif ring is not None:
            ring.append((x, y))
    if ring:
        (parts[-1].append(ring) if hole and parts else parts.append([ring]))
    return parts


def wkt(part):
    rings = []
    for ring in part:
        closed = ring if ring[0] == ring[-1] else ring + [ring[0]]
        rings.append("(" + ", ".join("{} {}".format(x, y) for x, y in closed) + ")")
    return "POLYGON (" + ", ".join(rings) + ")\n"


def write_parts(netcdf, names, out):
    """Writes every part's file; returns the manifest rows (without the check)."""
    import netCDF4  # python3-netcdf4, installed by make deps
    data = netCDF4.Dataset(netcdf)
    data.set_auto_maskandscale(False)
    rows = []
    for code in sorted(names):
        if code + "_lon" not in data.variables:
            continue
        parts = parts_of(data.variables[code + "_lon"][:], data.variables[code + "_lat"][:])
        for k, part in enumerate(parts):
            name = "{}-{:05d}.wkt".format(code, k)
            with open(os.path.join(out, name), "w", encoding="utf-8") as f:
                f.write(wkt(part))
            rows.append({"file": name, "country": code, "name": names[code], "part": k,
                         "rings": len(part), "vertices": sum(len(r) for r in part)})
    return rows


def summary(rows):
    accepted = [r for r in rows if "refused" not in r]
    reasons = collections.Counter(r["refused"].split(":")[0] for r in rows if "refused" in r)
    largest = max(accepted, key=lambda r: r["n"]) if accepted else None
    lines = ["# The DCW corpus", "",
             "{} parts of {} countries read ({} rings); {} accepted, {} refused.".format(
                 len(rows), len({r["country"] for r in rows}), sum(r["rings"] for r in rows), len(accepted),
                 len(rows) - len(accepted))]
    if largest:
        lines.append("The largest accepted: {} ({} part {}), n = {}, r = {}, h = {}.".format(
            largest["file"], largest["name"], largest["part"], largest["n"], largest["r"], largest["h"]))
    lines += ["", "| refused because | parts |", "|---|---|"]
    lines += ["| {} | {} |".format(why, count) for why, count in reasons.most_common()]
    return "\n".join(lines) + "\n"


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--netcdf", default=os.path.join(DCW_FOLDER, "dcw-gmt.nc"))
    parser.add_argument("--out", default="corpora/dcw")
    parser.add_argument("--build", default="build")
    args = parser.parse_args(argv)
    if not os.path.exists(args.netcdf):
        print("error: {} is missing; install Debian's gmt-dcw (make deps)".format(args.netcdf), file=sys.stderr)
        return 1
    if os.path.isdir(args.out):
        shutil.rmtree(args.out)
    os.makedirs(args.out)
    rows = write_parts(args.netcdf, countries(os.path.dirname(args.netcdf)), args.out)
    listing = subprocess.run([os.path.join(args.build, "polydecomp"), "corpus", "--dir", args.out, "--json"],
                             check=True, stdout=subprocess.PIPE).stdout
    checked = {f["file"]: f for f in json.loads(listing)["files"]}
    for row in rows:
        f = checked[row["file"]]
        row.update({"refused": f["refused"]} if "refused" in f else {"n": f["n"], "r": f["reflex"], "h": f["holes"]})
    with open(args.out.rstrip("/") + ".manifest.json", "w", encoding="utf-8") as f:
        json.dump({"source": args.netcdf, "parts": rows}, f, indent=0)
        f.write("\n")
    text = summary(rows)
    with open(args.out.rstrip("/") + ".manifest.md", "w", encoding="utf-8") as f:
        f.write(text)
    print(text, file=sys.stderr, end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
