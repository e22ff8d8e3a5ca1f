"""Paper-style figures from a sweep's results, as PNG and PDF in results/plots/ (analysis/plots.py is
its command line).

  time-vs-n_FAMILY_CURVE    time against n on log-log axes, one line per algorithm (median over seeds),
                            the fitted slope dashed, the claimed bound dotted through the largest point
  time-vs-n_real_KIND       each algorithm of a kind on the real polygons (the corpora's, hollow markers)
                            beside its `random` curve (line, median over seeds)
  time-vs-r_FAMILY_n-N      time against r at fixed n (r = 0 on the linear part of a symlog axis)
  pieces-vs-r_FAMILY_n-N    pieces of the convex decompositions against r, with r+1 and ceil(r/2)+1
  approximation-ratio       pieces / best valid count on the same polygon, per non-optimal algorithm
  gallery                   one polygon decomposed by every algorithm, side by side (drawn from
                            `polydecomp run --json`)
"""

import collections
import json
import math
import os
import re
import statistics
import subprocess
import tempfile
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")  # files only, no display: before pyplot is imported
import matplotlib.pyplot as plt  # noqa: E402

from . import bound_expr, bounds, fit, results  # noqa: E402

GALLERY_TIMEOUT = 120  # seconds per algorithm on the gallery polygon


def slug(text):
    return re.sub(r"[^A-Za-z0-9]+", "-", text).strip("-")


def save(fig, out_dir, name):
    for ext in ("png", "pdf"):
        fig.savefig(os.path.join(out_dir, "{}.{}".format(name, ext)), dpi=130, bbox_inches="tight")
    plt.close(fig)


def styles(names):
    """A distinct colour and marker per algorithm, stable across figures."""
    cmap = plt.get_cmap("tab20")
    markers = "os^vD<>phX*P"
    return {name: (cmap(i % 20), markers[i % len(markers)]) for i, name in enumerate(sorted(names))}


def medians(runs, x_of):
    """[(x, median seconds, r)] over seeds, sorted by x."""
    groups = collections.defaultdict(list)
    for run in runs:
        groups[x_of(run)].append(run)
    return [(x, statistics.median(r.seconds for r in g), g[0].r) for x, g in sorted(groups.items())]


def curve_labels(runs, prefix):
    return sorted({label for run in runs for label in run.curves if label.startswith(prefix)})


def _legend(ax):
    ax.legend(fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False)


def time_vs_n(runs, registry, out_dir, style):
    made = []
    for family in sorted({r.family for r in runs}):
        in_family = [r for r in runs if r.family == family and r.timed]
        for label in curve_labels(in_family, "vs-n"):
            on_curve = [r for r in in_family if label in r.curves]
            if not on_curve:
                continue
            fig, ax = plt.subplots(figsize=(8, 5))
            for algorithm in sorted({r.algorithm for r in on_curve}):
                mine = [r for r in on_curve if r.algorithm == algorithm]
                _plot_with_slopes(ax, mine, registry.get(algorithm, {}).get("time_bound", ""), algorithm, style)
            ax.set_xscale("log")
            ax.set_yscale("log")
            ax.set_xlabel("n (vertices)")
            ax.set_ylabel("CPU time per run (s)")
            ax.set_title("{}: time against n, {}".format(family, label[len("vs-n "):]))
            ax.grid(True, which="major", alpha=0.3)
            _legend(ax)
            name = "time-vs-n_{}_{}".format(slug(family), slug(label[len("vs-n "):]))
            save(fig, out_dir, name)
            made.append(name)
    return made


SYNTHETIC_BESIDE_REAL = ("random", "vs-n r=default")  # the synthetic curve the real polygons are drawn beside


def real_beside_synthetic(runs, registry, out_dir, style):
    """Per kind of algorithm, the real polygons' times beside the synthetic curve's."""
    real = [r for r in runs if r.file is not None and r.timed and r.algorithm in registry]
    family, curve = SYNTHETIC_BESIDE_REAL
    made = []
    for kind in sorted({registry[r.algorithm]["kind"] for r in real}):
        fig, ax = plt.subplots(figsize=(8, 5))
        for algorithm in sorted({r.algorithm for r in real if registry[r.algorithm]["kind"] == kind}):
            colour, marker = style[algorithm]
            synthetic = [r for r in runs if r.algorithm == algorithm and r.family == family and curve in r.curves
                         and r.timed]
            points = medians(synthetic, lambda r: r.n)
            ax.plot([p[0] for p in points], [p[1] for p in points], marker=marker, color=colour, label=algorithm,
                    linewidth=1.0, markersize=3)
            mine = [r for r in real if r.algorithm == algorithm]
            ax.scatter([r.n for r in mine], [r.seconds for r in mine], marker=marker, s=16, facecolors="none",
                       edgecolors=[colour], linewidths=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n (vertices)")
        ax.set_ylabel("CPU time per run (s)")
        ax.set_title("{}: real polygons (hollow) beside {}, {} (lines)".format(kind, family, curve[len("vs-n "):]))
        ax.grid(True, which="major", alpha=0.3)
        _legend(ax)
        name = "time-vs-n_real_{}".format(slug(kind))
        save(fig, out_dir, name)
        made.append(name)
    return made


def _plot_with_slopes(ax, mine, claim_text, algorithm, style):
    colour, marker = style[algorithm]
    points = medians(mine, lambda r: r.n)
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    f = fit.fit_exponents([(r.n, r.r, r.seconds) for r in mine])
    claim = bound_expr.parse_time_bound(claim_text)
    label = algorithm
    if f and "a" in f.names:
        label += " (a={:.2f}".format(f.value("a"))
        if claim:
            label += ", claim {:.2f}".format(fit.claim_along(fit.term_claims(f, claim), {"a": 1.0}))
        label += ")"
    ax.plot(xs, ys, marker=marker, color=colour, label=label, linewidth=1.2, markersize=4)
    if f and f.names == ["a"]:
        fitted_ns = sorted({p[0] for p in f.points})
        anchor_n, anchor_t = fitted_ns[-1], dict(zip(xs, ys))[fitted_ns[-1]]
        ax.plot(fitted_ns, [anchor_t * (n / anchor_n) ** f.value("a") for n in fitted_ns], "--", color=colour,
                linewidth=0.8)
    if claim and len(points) >= 2:
        n_last, t_last, r_last = points[-1]
        ax.plot(xs, [t_last * claim(n, r) / claim(n_last, r_last) for n, _, r in points], ":", color=colour,
                linewidth=0.9)


def time_vs_r(runs, out_dir, style):
    made = []
    for family in sorted({r.family for r in runs}):
        in_family = [r for r in runs if r.family == family and r.timed]
        for label in curve_labels(in_family, "vs-r"):
            on_curve = [r for r in in_family if label in r.curves]
            fig, ax = plt.subplots(figsize=(8, 5))
            for algorithm in sorted({r.algorithm for r in on_curve}):
                colour, marker = style[algorithm]
                points = medians([r for r in on_curve if r.algorithm == algorithm], lambda r: r.r)
                ax.plot([p[0] for p in points], [p[1] for p in points], marker=marker, color=colour, label=algorithm,
                        linewidth=1.2, markersize=4)
            ax.set_xscale("symlog", linthresh=1)
            ax.set_yscale("log")
            ax.set_xlabel("r (reflex vertices)")
            ax.set_ylabel("CPU time per run (s)")
            ax.set_title("{}: time against r, {}".format(family, label[len("vs-r "):]))
            ax.grid(True, which="major", alpha=0.3)
            _legend(ax)
            name = "time-vs-r_{}_{}".format(slug(family), slug(label[len("vs-r "):]))
            save(fig, out_dir, name)
            made.append(name)
    return made


def pieces_vs_r(runs, registry, out_dir, style):
    made = []
    convex = [r for r in runs if registry.get(r.algorithm, {}).get("kind") == "convex" and r.status == "ok"]
    for family in sorted({r.family for r in convex}):
        in_family = [r for r in convex if r.family == family]
        for label in curve_labels(in_family, "vs-r"):
            on_curve = [r for r in in_family if label in r.curves]
            fig, ax = plt.subplots(figsize=(8, 5))
            rs = sorted({r.r for r in on_curve})
            ax.plot(rs, [r + 1 for r in rs], "k-", linewidth=0.8, label="r+1")
            ax.plot(rs, [(r + 1) // 2 + 1 for r in rs], "k--", linewidth=0.8, label="ceil(r/2)+1")
            for algorithm in sorted({r.algorithm for r in on_curve}):
                colour, marker = style[algorithm]
                groups = collections.defaultdict(list)
                for run in on_curve:
                    if run.algorithm == algorithm:
                        groups[run.r].append(run.pieces)
                xs = sorted(groups)
                ax.plot(xs, [statistics.median(groups[x]) for x in xs], marker=marker, color=colour, label=algorithm,
                        linewidth=1.0, markersize=4)
            ax.set_xlabel("r (reflex vertices)")
            ax.set_ylabel("pieces (median over seeds)")
            ax.set_title("{}: convex pieces against r, {}".format(family, label[len("vs-r "):]))
            ax.grid(True, alpha=0.3)
            _legend(ax)
            name = "pieces-vs-r_{}_{}".format(slug(family), slug(label[len("vs-r "):]))
            save(fig, out_dir, name)
            made.append(name)
    return made


def approximation_ratio(runs, registry, out_dir):
    best = bounds.best_pieces(runs, registry)
    ratios = collections.defaultdict(list)
    for run in runs:
        algo = registry.get(run.algorithm)
        if not algo or algo["optimal"] or algo["kind"] != "convex" or run.status != "ok":
            continue
        opt = bounds.reference(run, algo, best)
        if opt:
            ratios[run.algorithm].append(run.pieces / opt)
    if not ratios:
        return []
    names = sorted(ratios)
    fig, ax = plt.subplots(figsize=(max(5, 1.2 * len(names)), 4.5))
    ax.boxplot([ratios[n] for n in names], labels=names, showfliers=True)
    ax.set_ylabel("pieces / best valid on the same polygon")
    ax.set_title("Approximation ratio of the convex heuristics")
    ax.grid(True, axis="y", alpha=0.3)
    plt.setp(ax.get_xticklabels(), rotation=30, ha="right")
    save(fig, out_dir, "approximation-ratio")
    return ["approximation-ratio"]


def _coordinate(v):
    return float(Fraction(v)) if isinstance(v, str) else float(v)


def _decompose(polydecomp, algorithm, polygon_file):
    """The `run --json` object, or an {"error": ...} object; `run --max-seconds` stops a slow algorithm,
    and its panel says it was skipped."""
    command = [polydecomp, "run", "--algorithm", algorithm, "--input", polygon_file, "--json",
               "--max-seconds", str(GALLERY_TIMEOUT)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=2 * GALLERY_TIMEOUT)
    except subprocess.TimeoutExpired:
        return {"error": "skipped (timeout)"}
    if done.returncode != 0:
        why = done.stderr.strip() or "exit status {}".format(done.returncode)
        return {"error": "skipped (timeout): " + why if why.endswith("(--max-seconds)") else why}
    return json.loads(done.stdout)


def gallery(polydecomp, registry, out_dir, spec):
    family, n, r, seed = spec.split(":")
    with tempfile.TemporaryDirectory() as tmp:
        polygon_file = os.path.join(tmp, "polygon.txt")
        subprocess.run([polydecomp, "generate", "--family", family, "--n", n, "--reflex", r, "--seed", seed,
                        "-o", polygon_file], check=True, capture_output=True)
        names = [a for a in sorted(registry) if registry[a].get("size_ceiling", int(n)) >= int(n)]
        decompositions = {a: _decompose(polydecomp, a, polygon_file) for a in names}
    cols = math.ceil(math.sqrt(len(names)))
    rows = math.ceil(len(names) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.2 * cols, 3.2 * rows), squeeze=False)
    for ax, name in zip(axes.flat, names):
        _draw_decomposition(ax, name, decompositions[name])
    for ax in list(axes.flat)[len(names):]:
        ax.axis("off")
    fig.suptitle("{} polygon, n={}, r={}, seed {}".format(family, n, r, seed))
    fig.tight_layout()
    save(fig, out_dir, "gallery")
    return ["gallery"]


def _draw_decomposition(ax, name, d):
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    if "error" in d:
        ax.set_title(name, fontsize=8)
        ax.text(0.5, 0.5, d["error"][:80], ha="center", va="center", wrap=True, fontsize=6, transform=ax.transAxes)
        return
    points = [(_coordinate(x), _coordinate(y)) for x, y in d["points"]]
    cmap = plt.get_cmap("Pastel1")
    for i, piece in enumerate(d["pieces"]):
        xs = [points[k][0] for k in piece]
        ys = [points[k][1] for k in piece]
        ax.fill(xs, ys, facecolor=cmap(i % 9), edgecolor="black", linewidth=0.4)
    n = d["n"]
    if len(points) > n:
        ax.plot([p[0] for p in points[n:]], [p[1] for p in points[n:]], "r.", markersize=3)
    outline = points[:n] + points[:1]
    ax.plot([p[0] for p in outline], [p[1] for p in outline], "k-", linewidth=0.8)
    verdict = "" if d.get("valid", True) else " INVALID"
    ax.set_title("{}: {} pieces{}".format(name, d["piece_count"], verdict), fontsize=8,
                 color="red" if verdict else "black")


def make_plots(results_path, registry, out_dir, polydecomp=None, gallery_spec=None):
    os.makedirs(out_dir, exist_ok=True)
    _, runs = results.load(results_path)
    style = styles({r.algorithm for r in runs} | set(registry))
    made = time_vs_n(runs, registry, out_dir, style)
    made += real_beside_synthetic(runs, registry, out_dir, style)
    made += time_vs_r(runs, out_dir, style)
    made += pieces_vs_r(runs, registry, out_dir, style)
    made += approximation_ratio(runs, registry, out_dir)
    if polydecomp and gallery_spec:
        made += gallery(polydecomp, registry, out_dir, gallery_spec)
    return made
