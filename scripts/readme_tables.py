#!/usr/bin/python3
"""The tables README.md and docs/*.md copy from the code, generated, and a check that they are current.

A generated table sits between two comment lines,

    <!-- generated: NAME -->
    ...
    <!-- end generated -->

and NAME says what it holds:

    algorithms  `BUILD/polydecomp list --markdown`, exactly (the registered algorithms)
    families    the polygon families, from the Python module's polydecomp.families()
    sweeps      the sweeps of harness/sweeps.json, one row per sweep and one per curve

    scripts/readme_tables.py [--check] [--build DIR]   exit 1, naming each stale file and block
    scripts/readme_tables.py --write [--build DIR]     rewrite the stale blocks

DIR is the build folder (default `build`), which holds `polydecomp` and the Python module (DIR/python).
Exit status 2 for a malformed block or a build that cannot answer. Standard library only.
"""

import argparse
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BEGIN = re.compile(r"^<!-- generated: ([a-z-]+) -->$")
END = "<!-- end generated -->"

# tests/test_cli.cpp (Cli.ReadmeAlgorithmTableIsCurrent) reads README's algorithm table between these
# two lines; the block keeps them around the table so that both checks read the same rows.
LIST_BEGIN = "<!-- polydecomp list --markdown -->"
LIST_END = "<!-- end of list -->"


class Failure(Exception):
    """A malformed block or a build that cannot give a table: exit status 2."""


def cell(value):
    """A value as the text of one Markdown table cell."""
    return str(value).replace("|", "\\|").replace("\n", " ")


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(cell(v) for v in row) + " |" for row in rows]
    return "\n".join(lines) + "\n"


def algorithms(build):
    program = os.path.join(build, "polydecomp")
    # Only the registered algorithms: the user's plug-in folders would add rows of their own.
    env = {k: v for k, v in os.environ.items() if k != "POLYDECOMP_PLUGINS"}
    try:
        done = subprocess.run([program, "list", "--markdown"], capture_output=True, text=True, env=env)
    except OSError as e:
        raise Failure(f"cannot run {program}: {e.strerror}")
    if done.returncode != 0:
        raise Failure(f"{program} list --markdown: exit status {done.returncode}: {done.stderr.strip()}")
    return LIST_BEGIN + "\n" + done.stdout + LIST_END + "\n"


def families(build):
    sys.path.insert(0, os.path.join(os.path.abspath(build), "python"))
    try:
        import polydecomp
    except ImportError as e:
        raise Failure(f"cannot import polydecomp from {build}/python: {e}")
    rows = []
    for f in polydecomp.families():
        r = "an outcome of the method" if f["r_is_outcome"] else "chosen (`--reflex`)"
        rows.append([f"`{f['name']}`", f["shape"], f["range"], r, "yes" if f["holes"] else "no"])
    return table(["family", "shape", "feasible n and r (h)", "r", "holes"], rows)


def size(value):
    """1000000 as 10^6, other sizes as they are."""
    if isinstance(value, int) and value >= 10000 and str(value).rstrip("0") == "1":
        return f"10^{len(str(value)) - 1}"
    return str(value)


def values(items, what):
    if len(items) <= 7:
        return ", ".join(size(v) for v in items)
    return f"{size(items[0])}..{size(items[-1])} ({len(items)} {what})"


def sweep_families(families):
    if isinstance(families, str):
        return f"`{families}`"
    return ", ".join(f"`{f}`" for f in families)


def sweeps(_build):
    with open(os.path.join(ROOT, "harness", "sweeps.json"), encoding="utf-8") as f:
        defined = json.load(f)
    per_sweep, per_curve = [], []
    for name, sweep in defined.items():
        budget = f"{sweep['budget_seconds']:g} s"
        own = sweep.get("budget_seconds_for", {})
        if own:
            budget += " (" + ", ".join(f"`{a}` {s:g} s" for a, s in own.items()) + ")"
        chosen = sweep["algorithms"]
        chosen = chosen if isinstance(chosen, str) else ", ".join(f"`{a}`" for a in chosen)
        per_sweep.append([f"`{name}`", chosen, ", ".join(str(s) for s in sweep["seeds"]),
                          f"{sweep['min_time']:g} s", budget, f"{sweep['timeout_seconds']:g} s"])
        for curve in sweep["curves"]:
            corpus = not isinstance(curve["families"], str) and all(
                str(f).startswith("dir:") for f in curve["families"])
            if "n" in curve:
                n = values(curve["n"], "sizes")
                if corpus:
                    n = "the files nearest to n = " + n
            else:
                n = "every file" if corpus else "-"
            own_value = "the file's" if corpus else "-"
            r = values(curve["r"], "values") if "r" in curve else own_value
            h = values(curve["h"], "values") if "h" in curve else own_value
            per_curve.append([f"`{name}`", curve["vs"], sweep_families(curve["families"]), n, r, h])
    return (table(["sweep", "algorithms", "seeds", "min time per key", "budget per key", "timeout per key"],
                  per_sweep)
            + "\n"
            + table(["sweep", "against", "families", "n", "r", "h"], per_curve))


GENERATORS = {"algorithms": algorithms, "families": families, "sweeps": sweeps}


def documents():
    docs = os.path.join(ROOT, "docs")
    names = sorted(n for n in os.listdir(docs) if n.endswith(".md"))
    return [os.path.join(ROOT, "README.md")] + [os.path.join(docs, n) for n in names]


def blocks(path, lines):
    """(name, first line of the body, line of the end marker) of every generated block in lines."""
    found, at = [], 0
    relative = os.path.relpath(path, ROOT)
    while at < len(lines):
        begin = BEGIN.match(lines[at].rstrip("\n"))
        if not begin:
            if lines[at].rstrip("\n") == END:
                raise Failure(f"{relative}:{at + 1}: {END} without a block")
            at += 1
            continue
        name = begin.group(1)
        if name not in GENERATORS:
            raise Failure(f"{relative}:{at + 1}: unknown generated block {name!r} "
                          f"(known: {', '.join(sorted(GENERATORS))})")
        end = at + 1
        while end < len(lines) and lines[end].rstrip("\n") != END:
            if BEGIN.match(lines[end].rstrip("\n")):
                raise Failure(f"{relative}:{end + 1}: a block inside block {name!r}")
            end += 1
        if end == len(lines):
            raise Failure(f"{relative}:{at + 1}: block {name!r} has no {END}")
        found.append((name, at + 1, end))
        at = end + 1
    return found


def main(argv):
    parser = argparse.ArgumentParser(description="Generate or check the tables of README.md and docs/*.md.")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="exit 1 when a table is stale (the default)")
    mode.add_argument("--write", action="store_true", help="rewrite the stale tables")
    parser.add_argument("--build", default="build", help="the build folder (default: build)")
    args = parser.parse_args(argv)

    generated = {}
    stale, seen = [], set()
    try:
        for path in documents():
            with open(path, encoding="utf-8") as f:
                lines = f.readlines()
            relative = os.path.relpath(path, ROOT)
            here = []
            # From the last block up, so that rewriting one leaves the line numbers of the others.
            for name, body, end in reversed(blocks(path, lines)):
                seen.add(name)
                if name not in generated:
                    generated[name] = GENERATORS[name](args.build)
                want = generated[name].splitlines(keepends=True)
                if lines[body:end] != want:
                    here.insert(0, f"{relative}: block {name!r} (line {body}) is stale")
                    lines[body:end] = want
            stale += here
            if here and args.write:
                with open(path + ".tmp", "w", encoding="utf-8") as f:
                    f.writelines(lines)
                os.replace(path + ".tmp", path)
    except Failure as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    missing = sorted(set(GENERATORS) - seen)
    for name in missing:
        print(f"error: no block {name!r} in README.md or docs/*.md", file=sys.stderr)
    if args.write:
        for line in stale:
            print(line.replace(" is stale", " rewritten"))
        return 1 if missing else 0
    for line in stale:
        print(f"error: {line}: run /usr/bin/python3 scripts/readme_tables.py --write --build {args.build}",
              file=sys.stderr)
    return 1 if stale or missing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
