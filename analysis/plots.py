#!/usr/bin/python3
"""Paper-style figures from a sweep's results, as PNG and PDF in results/plots/.

The figures: polydecomp_analysis/plots.py.

usage: plots.py RESULTS.json [--polydecomp build/polydecomp | --registry LIST.json] [-o results/plots]
                [--gallery FAMILY:N:R:SEED]
"""

import argparse
import sys

from polydecomp_analysis import bounds, plots, plugins


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("results", help="an assembled results file, e.g. results/quick.json")
    parser.add_argument("--polydecomp", default="build/polydecomp")
    parser.add_argument("--registry", help="a saved `polydecomp list --json` output, instead of running it")
    plugins.add_plugins_argument(parser)
    parser.add_argument("-o", "--output", default="results/plots")
    parser.add_argument("--gallery", default="random:40:12:1", help="FAMILY:N:R:SEED, or 'none'")
    args = parser.parse_args(argv)
    plugins.use_plugins(args.plugins)
    try:
        registry = bounds.load_registry(args.polydecomp, args.registry)
    except ValueError as e:
        print("error: " + str(e), file=sys.stderr)
        return 1
    gallery_spec = None if args.gallery == "none" else args.gallery
    made = plots.make_plots(args.results, registry, args.output, args.polydecomp, gallery_spec)
    print("wrote {} figures to {}".format(len(made), args.output))
    return 0


if __name__ == "__main__":
    sys.exit(main())
