#!/usr/bin/python3
"""Writes the door's table (results/door.md) from polydecomp-door-bench's JSON (results/door.json).

usage: door.py [--json results/door.json] [--out results/door.md]
"""

import argparse
import json
import sys

from polydecomp_analysis import door


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--json", default="results/door.json")
    parser.add_argument("--out", default="results/door.md")
    args = parser.parse_args(argv)
    try:
        with open(args.json, encoding="utf-8") as f:
            document = json.load(f)
        table = door.door_table(document)
    except (OSError, ValueError, KeyError) as e:
        print("error: {}: {}".format(args.json, e), file=sys.stderr)
        return 1
    try:
        with open(args.out, "w", encoding="utf-8") as f:
            f.write("# The door: reading, checking and validating a million vertices\n\n" + table)
    except OSError as e:
        print("error: cannot write {}: {}".format(args.out, e), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
