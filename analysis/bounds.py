#!/usr/bin/python3
"""Checks every algorithm's claimed bounds against a sweep's results; writes results/bounds.md.

What is checked and how: polydecomp_analysis/bounds.py.

usage: bounds.py RESULTS.json [--polydecomp build/polydecomp | --registry LIST.json] [-o results/bounds.md]
"""

import argparse
import sys

from polydecomp_analysis import bounds, plugins


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results", help="an assembled results file, e.g. results/quick.json")
    parser.add_argument("--polydecomp", default="build/polydecomp", help="the command line, for the claims")
    parser.add_argument("--registry", help="a saved `polydecomp list --json` output, instead of running it")
    plugins.add_plugins_argument(parser)
    parser.add_argument("-o", "--output", default="results/bounds.md")
    args = parser.parse_args(argv)
    plugins.use_plugins(args.plugins)
    try:
        registry = bounds.load_registry(args.polydecomp, args.registry)
    except ValueError as e:
        print("error: " + str(e), file=sys.stderr)
        return 1
    bounds.write_bounds(args.results, registry, args.output)
    print("wrote " + args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
