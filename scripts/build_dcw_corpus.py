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


def write_parts(netcdf4, netcdf, names, out):
    """Writes every part's file; returns the manifest rows (without the check)."""
    data = netcdf4.Dataset(netcdf)
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


def fail(message):
    print("error: " + message, file=sys.stderr)
    return 1


def write_atomic(path, text):
    with open(path + ".tmp", "w", encoding="utf-8") as f:
        f.write(text)
    os.replace(path + ".tmp", path)


def main(argv=None):
    """Builds the corpus beside OUT and puts it in place only when it is complete, so that a failure
    leaves the corpus that was there (and its manifest) as it was."""
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--netcdf", default=os.path.join(DCW_FOLDER, "dcw-gmt.nc"))
    parser.add_argument("--out", default="corpora/dcw")
    parser.add_argument("--build", default="build")
    args = parser.parse_args(argv)
    out = os.path.normpath(args.out)
    if not os.path.exists(args.netcdf):
        return fail("{} is missing; install Debian's gmt-dcw (make deps)".format(args.netcdf))
    try:
        import netCDF4
    except ImportError:
        return fail("python3-netcdf4 is missing; it reads {} (make deps installs it)".format(args.netcdf))
    if os.path.isdir(out) and any(not name.endswith(".wkt") for name in os.listdir(out)):
        return fail("{} holds files that are not the corpus's; it would be replaced".format(out))
    building = out + ".building"
    shutil.rmtree(building, ignore_errors=True)
    os.makedirs(building)
    rows = write_parts(netCDF4, args.netcdf, countries(os.path.dirname(args.netcdf)), building)
    listing = subprocess.run([os.path.join(args.build, "polydecomp"), "corpus", "--dir", building, "--json"],
                             stdout=subprocess.PIPE)
    if listing.returncode != 0:
        return fail("polydecomp corpus could not read {} (exit status {})".format(building, listing.returncode))
    checked = {f["file"]: f for f in json.loads(listing.stdout)["files"]}
    for row in rows:
        f = checked[row["file"]]
        row.update({"refused": f["refused"]} if "refused" in f else {"n": f["n"], "r": f["reflex"], "h": f["holes"]})
    shutil.rmtree(out, ignore_errors=True)
    os.rename(building, out)
    write_atomic(out + ".manifest.json", json.dumps({"source": args.netcdf, "parts": rows}, indent=0) + "\n")
    text = summary(rows)
    write_atomic(out + ".manifest.md", text)
    print(text, file=sys.stderr, end="")
    return 0


if __name__ == "__main__":
    sys.exit(main())
