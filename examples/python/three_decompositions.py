#!/usr/bin/python3
"""Generates a polygon, decomposes it with three algorithms and draws the pieces side by side.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/three_decompositions.py [-o FIGURE]

(or, after `pip install --no-build-isolation .`, without PYTHONPATH). Writes three_decompositions.pdf
by default; any extension matplotlib knows (.png, .svg) works.
"""

import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import Polygon as Patch  # noqa: E402

import polydecomp  # noqa: E402

ALGORITHMS = ["monotone", "hertel-mehlhorn", "keil-snoeyink"]


def draw(axes, ring, result):
    colours = plt.get_cmap("tab20")
    for k, piece in enumerate(result.pieces):
        axes.add_patch(Patch(result.points_float[piece], closed=True, facecolor=colours(k % 20),
                             edgecolor="black", linewidth=0.6))
    axes.plot(*ring[list(range(len(ring))) + [0]].T, color="black", linewidth=1.2)
    axes.set_title(f"{result.algorithm}: {len(result.pieces)} pieces", fontsize=9)
    axes.set_aspect("equal")
    axes.axis("off")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-o", "--output", default="three_decompositions.pdf")
    parser.add_argument("--family", default="random")
    parser.add_argument("--n", type=int, default=30)
    args = parser.parse_args()
    ring = polydecomp.generate(args.family, args.n, seed=1)
    figure, panels = plt.subplots(1, len(ALGORITHMS), figsize=(7.0, 2.6))
    for axes, name in zip(panels, ALGORITHMS):
        result = polydecomp.decompose(ring, name)
        if not result.valid:
            raise SystemExit(f"error: {name}'s result is not valid: {result.reason}")
        draw(axes, ring, result)
    figure.suptitle(f"{args.family}, n = {args.n}, r = {result.reflex}", fontsize=10)
    figure.tight_layout()
    figure.savefig(args.output)
    print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
