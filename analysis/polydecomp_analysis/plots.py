"""Paper-style figures from a sweep's results, as PNG and PDF in results/plots/ (analysis/plots.py is
its command line).

  time-vs-n_FAMILY_CURVE    time against n on log-log axes, one line per algorithm (median over seeds),
                            the fitted power law dashed and the claimed bound dotted, both over the sizes
                            fitted only (the larger half, as in bounds.md)
  time-vs-n_real_KIND       each algorithm of a kind on the real polygons (the corpora's, hollow markers)
                            beside its `random` curve (line, median over seeds)
  time-vs-r_FAMILY_n-N      time against r at fixed n (r = 0 on the linear part of a symlog axis)
  pieces-vs-r_FAMILY_n-N    pieces of the convex decompositions against r, with r+1 and ceil(r/2)+1
  approximation-ratio       pieces / best valid count on the same polygon, per non-optimal algorithm
  gallery                   one polygon decomposed by every algorithm, side by side (drawn from
                            `polydecomp run --json`)

Every figure is sized for a two-column paper: one panel is a column wide (COLUMN_WIDTH), a figure of
several panels the full width (FULL_WIDTH), in the fonts of PAPER_RC; each panel's legend, below it,
says what its line styles mean. An algorithm has the same colour and marker in every figure (styles).
A curve of fewer than MIN_POINTS points is not drawn, and a figure left with no curve is not written
(an earlier run's file of that name is removed). A panel of more than MAX_SERIES algorithms is split
into groups (groups): the figure keeps its name and shows every group as a panel of its own, and each
group is written alone too, as NAME_GROUP (e.g. time-vs-n_random_r-default_triangulation).
"""

import collections
import glob
import json
import math
import os
import re
import statistics
import subprocess
import tempfile
import zlib
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")  # files only, no display: before pyplot is imported
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.font_manager import FontProperties  # noqa: E402
from matplotlib.textpath import TextToPath  # noqa: E402
from matplotlib.ticker import LogFormatterSciNotation  # noqa: E402

from . import bound_expr, bounds, fit, results  # noqa: E402

GALLERY_TIMEOUT = 120  # seconds per algorithm on the gallery polygon

COLUMN_WIDTH = 3.5  # inches: one column of a two-column paper
FULL_WIDTH = 7.0  # inches: both columns
PLOT_HEIGHT = 2.4  # inches of one panel's axes, with their title and tick labels
AXES_DECORATION = 0.75  # inches of PLOT_HEIGHT the title, tick labels and axis label take
LEGEND_FONT = 7  # points
LEGEND_ROW = 0.15  # inches a row of the legend takes at LEGEND_FONT
SMALL_FONT = 6  # points: the gallery's panel titles, where six panels share a line
PNG_DPI = 200  # the PNGs are for the README and the web: 700 pixels for a column
MIN_POINTS = 3  # a curve of fewer points shows no trend, and a one-point "curve" looks like a missing one
MAX_SERIES = 10  # a panel of more algorithms is split (groups): tab10 has ten colours

# The figures' rcParams, set here once for every figure: one font family and size, and TrueType fonts
# in the PDF (Type 3 fonts are refused by some publishers). Constrained layout, not bbox_inches="tight"
# at saving, so that the files have exactly the size asked for.
PAPER_RC = {
    "font.family": "DejaVu Sans", "font.size": 8, "axes.titlesize": 8, "axes.labelsize": 8,
    "figure.titlesize": 8, "xtick.labelsize": 7, "ytick.labelsize": 7, "legend.fontsize": LEGEND_FONT,
    "legend.title_fontsize": LEGEND_FONT, "legend.frameon": False, "legend.handlelength": 2.5,
    "legend.columnspacing": 1.0, "lines.linewidth": 1.0, "lines.markersize": 3.5, "axes.linewidth": 0.6,
    "grid.linewidth": 0.4, "grid.alpha": 0.35, "xtick.major.width": 0.6, "ytick.major.width": 0.6,
    "pdf.fonttype": 42, "ps.fonttype": 42, "figure.constrained_layout.use": True, "savefig.dpi": PNG_DPI,
}
plt.rcParams.update(PAPER_RC)
_TEXT_TO_PATH = TextToPath()
_LEGEND_FONT_PROPERTIES = FontProperties(family=PAPER_RC["font.family"], size=LEGEND_FONT)

COLOURS = [plt.get_cmap("tab10")(i) for i in range(10)]
MARKERS = "os^DvP<>Xph*"
# The committed algorithms' styles, fixed by name so that adding an algorithm moves none of them: the
# marker is the group (triangulations, optimal and other convex decompositions, partitions), and within
# a group every algorithm has its own colour (COLOURS, in this order), so no panel of a group repeats one.
# Any other name gets a free (colour, marker) from a hash of the name (style_of).
KNOWN_STYLES = {
    "o": ("monotone", "seidel", "cutting-tri", "ear-n2", "ear-n3", "diagonal-n3", "diagonal-n4", "cgal-cdt",
          "earcut", "geos-cdt"),
    "s": ("keil", "keil-snoeyink", "keil-snoeyink-reduced", "greene-dp", "chazelle-dobkin", "chazelle-dobkin-n5",
          "cgal-optimal", "poly-decomp-optimal"),
    "^": ("hertel-mehlhorn", "greene-sweep", "cutting-convex", "min-ink", "naive", "naive-chains",
          "cgal-hertel-mehlhorn", "cgal-greene", "poly-decomp-quick"),
    "D": ("y-monotone", "cgal-y-monotone"),
}
_KNOWN_SLOTS = {name: (i, MARKERS.index(marker)) for marker, names in KNOWN_STYLES.items()
                for i, name in enumerate(names)}
_FREE_SLOTS = [(c, m) for m in range(len(MARKERS)) for c in range(len(COLOURS)) if (c, m) not in _KNOWN_SLOTS.values()]

# How each kind of line is drawn, and what the legend says of it; "upper" and "lower" are the reference
# lines of pieces-vs-r (in black, labelled with what they are). Dotted is a bound, dashed a fit.
ROLE_STYLE = {
    "measured": {"linestyle": "-", "linewidth": 1.0, "marker": True, "zorder": 3},
    "fit": {"linestyle": "--", "linewidth": 0.8, "zorder": 2},
    "claim": {"linestyle": ":", "linewidth": 1.1, "zorder": 2},
    "real": {"linestyle": "none", "marker": True, "markerfacecolor": "none", "markeredgewidth": 0.7, "zorder": 3},
    "upper": {"linestyle": ":", "linewidth": 1.0, "zorder": 1},
    "lower": {"linestyle": "-.", "linewidth": 0.8, "zorder": 1},
}
KEY_TEXT = {
    "measured": "solid: measured (median over seeds)",
    "fit": "dashed: fitted c n^a, over the sizes fitted",
    "claim": "dotted: claimed bound, over the same sizes",
    "real": "hollow: one real polygon",
}
TIME_LEGEND_TITLE = "a = fitted exponent of n (claimed)"


def slug(text):
    return re.sub(r"[^A-Za-z0-9]+", "-", text).strip("-")


def save(fig, out_dir, name, formats=("png", "pdf")):
    """Writes NAME in each of formats, and removes an earlier run's NAME in the other one."""
    for ext in ("png", "pdf"):
        path = os.path.join(out_dir, "{}.{}".format(name, ext))
        if ext not in formats:
            if os.path.exists(path):
                os.remove(path)
            continue
        # no creation date in the PDF: figures made again from the same results are the same files
        fig.savefig(path, dpi=PNG_DPI, metadata={"CreationDate": None} if ext == "pdf" else None)
        fig.set_layout_engine("none")  # the layout is done, in inches: the PDF keeps it (a third of the time)
    plt.close(fig)


def discard(out_dir, name):
    """Removes NAME.png and NAME.pdf, an earlier run's figure that is not drawn now."""
    for ext in ("png", "pdf"):
        path = os.path.join(out_dir, "{}.{}".format(name, ext))
        if os.path.exists(path):
            os.remove(path)


def discard_groups(out_dir, name, keep=()):
    """Removes the group files NAME_GROUP.* an earlier run wrote, but those in keep: a figure's groups
    change with its algorithms. A figure's own name has at most two underscores, a group's one more."""
    for path in glob.glob(os.path.join(glob.escape(out_dir), glob.escape(name) + "_*.*")):
        stem, ext = os.path.splitext(os.path.basename(path))
        if ext in (".png", ".pdf") and "_" not in stem[len(name) + 1:] and stem not in keep:
            os.remove(path)


def style_of(name, taken=()):
    """(colour, marker) of an algorithm: the one KNOWN_STYLES fixes, or else the first slot KNOWN_STYLES
    leaves free and taken does not hold, from a hash of the name (crc32: the same in every process, unlike
    hash())."""
    if name in _KNOWN_SLOTS:
        c, m = _KNOWN_SLOTS[name]
        return COLOURS[c], MARKERS[m]
    start = zlib.crc32(name.encode("utf-8")) % len(_FREE_SLOTS)
    for k in range(len(_FREE_SLOTS)):
        c, m = _FREE_SLOTS[(start + k) % len(_FREE_SLOTS)]
        if (COLOURS[c], MARKERS[m]) not in taken:
            return COLOURS[c], MARKERS[m]
    return COLOURS[start % len(COLOURS)], MARKERS[start % len(MARKERS)]  # more names than slots


def styles(names):
    """{name: (colour, marker)}, distinct, and for each name the same whatever the other names (unless two
    names outside KNOWN_STYLES hash to one slot: the later in sorted order then takes the next free one)."""
    out = {name: style_of(name) for name in names if name in _KNOWN_SLOTS}
    for name in sorted(set(names) - set(out)):
        out[name] = style_of(name, set(out.values()))
    return out


def medians(runs, x_of):
    """[(x, median seconds, r)] over seeds, sorted by x."""
    groups = collections.defaultdict(list)
    for run in runs:
        groups[x_of(run)].append(run)
    return [(x, statistics.median(r.seconds for r in g), g[0].r) for x, g in sorted(groups.items())]


def _by_algorithm(runs):
    """[(algorithm, its runs)], sorted by algorithm."""
    mine = collections.defaultdict(list)
    for run in runs:
        mine[run.algorithm].append(run)
    return sorted(mine.items())


def curve_labels(runs, prefix):
    return sorted({label for run in runs for label in run.curves if label.startswith(prefix)})


# --- what a panel draws: series of role-tagged lines ------------------------------------------------------

Line = collections.namedtuple("Line", "xs ys role")
# One algorithm's lines in a panel (name the algorithm), or a reference line (name None) drawn in black
# in every panel of its figure.
Series = collections.namedtuple("Series", "name label lines")


# Splitting a crowded panel: by kind first, then optimal or not, then polydecomp's own against the peers.
GROUPINGS = (
    lambda algo: algo.get("kind", "unregistered"),
    lambda algo: "optimal" if algo.get("optimal") else "non-optimal",
    lambda algo: "peers" if algo.get("peer") else "polydecomp",
)


def groups(names, registry):
    """[(label, names)]: one group of every name, label (), when there are at most MAX_SERIES; else the
    groups of these names among those that splitting every registered name gives, so that an algorithm is
    in the same group in every figure: by the GROUPINGS, as far as needed, and in alphabetical chunks in the
    end. A label is a tuple of the groupings' values, less the leading ones all the groups share
    (pieces-vs-r draws convex decompositions only)."""
    names = sorted(names)
    if len(names) <= MAX_SERIES:
        return [((), names)]
    label_of = {name: label for label, members in _split(sorted(set(registry) | set(names)), registry, 0)
                for name in members}
    parts = collections.defaultdict(list)
    for name in names:
        parts[label_of[name]].append(name)
    labels = sorted(parts)
    if len(labels) == 1:
        return [((), names)]
    shared = 0
    while all(len(label) > shared + 1 and label[shared] == labels[0][shared] for label in labels):
        shared += 1
    return [(label[shared:], parts[label]) for label in labels]


def _split(names, registry, depth):
    if len(names) <= MAX_SERIES:
        return [((), names)]
    if depth == len(GROUPINGS):
        chunks = math.ceil(len(names) / MAX_SERIES)
        size = math.ceil(len(names) / chunks)
        return [(("part {}".format(i + 1),), names[i * size:(i + 1) * size]) for i in range(chunks)]
    parts = collections.defaultdict(list)
    for name in names:
        parts[GROUPINGS[depth](registry.get(name, {}))].append(name)
    if len(parts) == 1:
        return _split(names, registry, depth + 1)
    return [((key,) + label, members) for key in sorted(parts) for label, members in
            _split(parts[key], registry, depth + 1)]


class Panel:
    """One panel's series and the two legends below its axes: the key (what the line styles the panel uses
    mean, KEY_TEXT, and the reference lines), then the algorithms, each in as many columns as fit."""

    def __init__(self, series, style, key_text, legend_title=None):
        self.series, self.style = series, style
        self.legend_title = legend_title if any(s.label != s.name for s in series if s.name) else None
        roles = {line.role for s in series if s.name for line in s.lines}
        self.key = [(_handle(role, "black", "o"), key_text.get(role, KEY_TEXT[role]))
                    for role in ("measured", "fit", "claim", "real") if role in roles]
        self.key += [(_handle(s.lines[0].role, "black", None), s.label) for s in series if s.name is None]
        self.algorithms = [(_handle(s.lines[0].role, *style[s.name]), s.label) for s in series if s.name]
        self.heights = (_legend_height(self.key), _legend_height(self.algorithms, self.legend_title))

    @property
    def height(self):
        return PLOT_HEIGHT + sum(self.heights)

    def draw(self, container, setup, title, heights=None):
        """Draws into a Figure or SubFigure: the axes, set up by setup(ax), over the legends, given heights
        (inches) or their own (the panels of a row share the tallest)."""
        heights = heights or self.heights
        # the ratios share what the decorations leave: the legends get the height they need, the axes the rest
        ratios = [PLOT_HEIGHT - AXES_DECORATION] + [max(h, 0.01) for h in heights]
        grid = container.add_gridspec(3, 1, height_ratios=ratios)
        ax = container.add_subplot(grid[0])
        for s in self.series:
            colour, marker = self.style[s.name] if s.name else ("black", None)
            for line in s.lines:
                ax.plot(line.xs, line.ys, color=colour, **_role_style(line.role, marker))
        setup(ax)
        ax.set_title(title)
        for row, (entries, legend_title) in enumerate([(self.key, None), (self.algorithms, self.legend_title)]):
            below = container.add_subplot(grid[1 + row])
            below.axis("off")
            if entries:
                below.legend(*zip(*entries), loc="upper center", ncol=_legend_columns([e[1] for e in entries]),
                             borderaxespad=0, title=legend_title)
        return ax


def _handle(role, colour, marker):
    return Line2D([], [], color=colour, **_role_style(role, marker))


def _role_style(role, marker):
    kwargs = dict(ROLE_STYLE[role])
    if kwargs.pop("marker", False) and marker:
        kwargs["marker"] = marker
    return kwargs


def _legend_columns(labels):
    """As many columns (up to 3) as the longest label leaves room for in a column-wide panel."""
    def width(text):  # inches, from the font's metrics
        return _TEXT_TO_PATH.get_text_width_height_descent(text, _LEGEND_FONT_PROPERTIES, ismath=False)[0] / 72

    handle = (PAPER_RC["legend.handlelength"] + 0.8 + PAPER_RC["legend.columnspacing"]) * LEGEND_FONT / 72
    return max(1, min(3, int((COLUMN_WIDTH - 0.1) / (max(width(label) for label in labels) + handle))))


def _legend_height(entries, title=None):
    """Inches of a legend of entries [(handle, label)] below a panel."""
    if not entries:
        return 0.0
    rows = math.ceil(len(entries) / _legend_columns([e[1] for e in entries])) + (1 if title else 0)
    return 0.05 + LEGEND_ROW * rows


def write_figures(out_dir, name, title, series, registry, style, setup, key_text=None, legend_title=None):
    """Writes the figure NAME from series (those of fewer than MIN_POINTS points left out already): one
    column-wide panel, or, over MAX_SERIES algorithms, a full-width figure of one panel per group and
    each group alone, column-wide, as NAME_GROUP (PDF only). Returns the names written: none when no
    algorithm has a curve, and then an earlier run's NAME is removed, as are the groups it no longer has."""
    drawn = [s for s in series if s.name]
    references = [s for s in series if not s.name]
    parts = groups([s.name for s in drawn], registry) if drawn else []
    panels = [Panel(references + [s for s in drawn if s.name in members], style, key_text or {}, legend_title)
              for _, members in parts]
    made = []
    if len(parts) == 1:
        _write_column(out_dir, name, title, panels[0], setup)
        made.append(name)
    elif parts:
        _write_split(out_dir, name, title, [(", ".join(label), panel) for (label, _), panel in zip(parts, panels)],
                     setup)
        made.append(name)
        for (label, _), panel in zip(parts, panels):
            group_name = "{}_{}".format(name, slug("-".join(label)))
            # a group alone is for a paper's column: PDF only (the full-width figure has the PNG)
            _write_column(out_dir, group_name, "{}: {}".format(title, ", ".join(label)), panel, setup, ("pdf",))
            made.append(group_name)
    else:
        discard(out_dir, name)
    discard_groups(out_dir, name, keep=made)
    return made


def _write_column(out_dir, name, title, panel, setup, formats=("png", "pdf")):
    fig = plt.figure(figsize=(COLUMN_WIDTH, panel.height))
    panel.draw(fig, setup, title)
    save(fig, out_dir, name, formats)


def _write_split(out_dir, name, title, titled_panels, setup):
    """The full-width figure NAME: every group's panel, two a row, under the figure's title."""
    rows = [titled_panels[i:i + 2] for i in range(0, len(titled_panels), 2)]
    legends = [[max(panel.heights[i] for _, panel in row) for i in (0, 1)] for row in rows]
    heights = [PLOT_HEIGHT + sum(legend) for legend in legends]
    fig = plt.figure(figsize=(FULL_WIDTH, sum(heights) + 0.25))
    fig.suptitle(title)
    cells = fig.subfigures(len(rows), 2, height_ratios=heights, squeeze=False)
    for row, row_cells, legend in zip(rows, cells, legends):
        for (panel_title, panel), cell in zip(row, row_cells):
            panel.draw(cell, setup, panel_title, legend)
    save(fig, out_dir, name)


# --- the figures ------------------------------------------------------------------------------------------

def _time_axis(ax):
    """A log axis of CPU time; over less than two decades some minor ticks are labelled too, so that the
    axis has two labels at least (matplotlib's default labels none between 1 and 2 decades)."""
    ax.set_yscale("log")
    ax.yaxis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(2, 0.5)))
    ax.set_ylabel("CPU time per run (s)")
    ax.grid(True, which="major")


def _log_log_time(xlabel):
    def setup(ax):
        ax.set_xscale("log")
        ax.set_xlabel(xlabel)
        _time_axis(ax)
    return setup


def fitted_line(f):
    """(ns, ts) of the fitted power law t = c n^a at the fitted points' sizes, so from the smallest size
    fitted to the largest and no further: the least-squares line itself, whose intercept is the mean of
    log t less a times the mean of log n over the points (a one-exponent fit, names ["a"])."""
    a = f.value("a")
    log_c = statistics.fmean(math.log(p[2]) - a * math.log(p[0]) for p in f.points)
    ns = sorted({p[0] for p in f.points})
    return ns, [math.exp(log_c) * n ** a for n in ns]


def claim_line(f, claim):
    """(ns, ts) of the claimed bound over the same sizes as fitted_line: the term of the claim that grows
    fastest along n there (what the claim allows, fit.claim_along), its unknown constant fitted to the
    same points in log space, at each size's median r."""
    claims = fit.term_claims(f, claim)
    term = claim.terms()[max(range(len(claims)), key=lambda i: claims[i]["a"])]
    log_k = statistics.fmean(math.log(p[2]) - math.log(term(p[0], p[1])) for p in f.points)
    ns = sorted({p[0] for p in f.points})
    rs = {n: statistics.median(p[1] for p in f.points if p[0] == n) for n in ns}
    return ns, [math.exp(log_k) * term(n, rs[n]) for n in ns]


def time_series(algorithm, mine, claim_text):
    """The Series of one algorithm's time against n (runs mine, one curve), or None under MIN_POINTS
    sizes: the medians, and, where the curve's larger sizes can be fitted as in bounds.md, the fit and the
    claim over those sizes, with their exponents in the label."""
    points = medians(mine, lambda r: r.n)
    if len(points) < MIN_POINTS:
        return None
    lines = [Line([p[0] for p in points], [p[1] for p in points], "measured")]
    f = fit.fit_exponents([(r.n, r.r, r.seconds) for r in mine], along_curve=True)
    claim = bound_expr.parse_time_bound(claim_text)
    label = algorithm
    if f and f.names == ["a"]:
        lines.append(Line(*fitted_line(f), "fit"))
        label += " a={:.2f}".format(f.value("a"))
        if claim:
            lines.append(Line(*claim_line(f, claim), "claim"))
            label += " ({:.2f})".format(fit.claim_along(fit.term_claims(f, claim), {"a": 1.0}))
    return Series(algorithm, label, lines)


def time_vs_n(runs, registry, out_dir, style):
    made = []
    for family in sorted({r.family for r in runs}):
        in_family = [r for r in runs if r.family == family and r.timed]
        for label in curve_labels(in_family, "vs-n"):
            on_curve = [r for r in in_family if label in r.curves]
            curve = label[len("vs-n "):]
            series = [time_series(a, mine, registry.get(a, {}).get("time_bound", ""))
                      for a, mine in _by_algorithm(on_curve)]
            made += write_figures(out_dir, "time-vs-n_{}_{}".format(slug(family), slug(curve)),
                                  "{}, {}".format(family, curve), [s for s in series if s], registry,
                                  style, _log_log_time("n (vertices)"), legend_title=TIME_LEGEND_TITLE)
    return made


SYNTHETIC_BESIDE_REAL = ("random", "vs-n r=default")  # the synthetic curve the real polygons are drawn beside


def real_beside_synthetic(runs, registry, out_dir, style):
    """Per kind of algorithm, the real polygons' times beside the synthetic curve's: an algorithm is drawn
    when its synthetic curve has MIN_POINTS sizes or it has MIN_POINTS real polygons, its curve only in the
    first case."""
    real = [r for r in runs if r.file is not None and r.timed and r.algorithm in registry]
    family, curve = SYNTHETIC_BESIDE_REAL
    key_text = {"measured": "line: {}, {} (median over seeds)".format(family, curve[len("vs-n "):])}
    made = []
    for kind in sorted({registry[r.algorithm]["kind"] for r in real}):
        series = []
        for algorithm in sorted({r.algorithm for r in real if registry[r.algorithm]["kind"] == kind}):
            synthetic = medians([r for r in runs if r.algorithm == algorithm and r.family == family
                                 and curve in r.curves and r.timed], lambda r: r.n)
            mine = [r for r in real if r.algorithm == algorithm]
            lines = [Line([p[0] for p in synthetic], [p[1] for p in synthetic], "measured")]
            if len(synthetic) < MIN_POINTS:
                lines = []
            if lines or len(mine) >= MIN_POINTS:
                lines.append(Line([r.n for r in mine], [r.seconds for r in mine], "real"))
                series.append(Series(algorithm, algorithm, lines))
        made += write_figures(out_dir, "time-vs-n_real_{}".format(slug(kind)),
                              "real polygons, {}".format(kind), series, registry, style,
                              _log_log_time("n (vertices)"), key_text)
    return made


def _measured_series(algorithm, points):
    """The Series of one algorithm's medians [(x, y)], or None under MIN_POINTS points."""
    if len(points) < MIN_POINTS:
        return None
    return Series(algorithm, algorithm, [Line([p[0] for p in points], [p[1] for p in points], "measured")])


def _time_vs_r_axes(ax):
    ax.set_xscale("symlog", linthresh=1)
    ax.set_xlabel("r (reflex vertices)")
    _time_axis(ax)


def time_vs_r(runs, out_dir, style, registry=None):
    """registry groups a crowded panel by kind (groups); without it, alphabetically."""
    made = []
    for family in sorted({r.family for r in runs}):
        in_family = [r for r in runs if r.family == family and r.timed]
        for label in curve_labels(in_family, "vs-r"):
            on_curve = [r for r in in_family if label in r.curves]
            curve = label[len("vs-r "):]
            series = [_measured_series(a, [p[:2] for p in medians(mine, lambda r: r.r)])
                      for a, mine in _by_algorithm(on_curve)]
            made += write_figures(out_dir, "time-vs-r_{}_{}".format(slug(family), slug(curve)),
                                  "{}, {}".format(family, curve), [s for s in series if s],
                                  registry or {}, style, _time_vs_r_axes)
    return made


def _pieces_axes(ax):
    ax.set_xlabel("r (reflex vertices)")
    ax.set_ylabel("pieces (median over seeds)")
    ax.grid(True)


def _median_pieces(runs):
    groups = collections.defaultdict(list)
    for run in runs:
        groups[run.r].append(run.pieces)
    return [(r, statistics.median(groups[r])) for r in sorted(groups)]


def pieces_vs_r(runs, registry, out_dir, style):
    made = []
    convex = [r for r in runs if registry.get(r.algorithm, {}).get("kind") == "convex" and r.status == "ok"]
    for family in sorted({r.family for r in convex}):
        in_family = [r for r in convex if r.family == family]
        for label in curve_labels(in_family, "vs-r"):
            on_curve = [r for r in in_family if label in r.curves]
            curve = label[len("vs-r "):]
            series = [_measured_series(a, _median_pieces(mine)) for a, mine in _by_algorithm(on_curve)]
            series = [s for s in series if s]
            rs = sorted({x for s in series for x in s.lines[0].xs})
            references = [Series(None, "dotted: r+1 (upper bound)", [Line(rs, [r + 1 for r in rs], "upper")]),
                          Series(None, "dash-dot: ceil(r/2)+1 (lower bound)",
                                 [Line(rs, [(r + 1) // 2 + 1 for r in rs], "lower")])]
            made += write_figures(out_dir, "pieces-vs-r_{}_{}".format(slug(family), slug(curve)),
                                  "{}, {}".format(family, curve),
                                  references + series if series else [], registry, style, _pieces_axes)
    return made


def approximation_ratio(runs, registry, out_dir, style=None):
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
        discard(out_dir, "approximation-ratio")
        return []
    names = sorted(ratios)
    style = style or styles(names)
    width = COLUMN_WIDTH if len(names) <= MAX_SERIES else FULL_WIDTH
    fig, ax = plt.subplots(figsize=(width, PLOT_HEIGHT + 0.6))
    boxes = ax.boxplot([ratios[n] for n in names], labels=names, patch_artist=True, widths=0.6,
                       flierprops={"markersize": 2, "markeredgewidth": 0.5},
                       medianprops={"color": "black", "linewidth": 1.0})
    for box, flier, name in zip(boxes["boxes"], boxes["fliers"], names):
        colour, marker = style[name]
        box.set(facecolor=colour[:3] + (0.35,), edgecolor=colour, linewidth=0.8)
        flier.set(marker=marker, markeredgecolor=colour)
    ax.set_ylabel("pieces / best valid on the same polygon")
    ax.set_title("Approximation ratio of the convex heuristics")
    ax.grid(True, axis="y")
    plt.setp(ax.get_xticklabels(), rotation=35, ha="right", rotation_mode="anchor")
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


GALLERY_COLUMNS = 6  # panels a row across FULL_WIDTH


def gallery(polydecomp, registry, out_dir, spec):
    family, n, r, seed = spec.split(":")
    with tempfile.TemporaryDirectory() as tmp:
        polygon_file = os.path.join(tmp, "polygon.txt")
        subprocess.run([polydecomp, "generate", "--family", family, "--n", n, "--reflex", r, "--seed", seed,
                        "-o", polygon_file], check=True, capture_output=True)
        names = [a for a in sorted(registry) if registry[a].get("size_ceiling", int(n)) >= int(n)]
        decompositions = {a: _decompose(polydecomp, a, polygon_file) for a in names}
    cols = min(GALLERY_COLUMNS, len(names))
    rows = math.ceil(len(names) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(FULL_WIDTH, FULL_WIDTH / cols * rows + 0.2), squeeze=False)
    for ax, name in zip(axes.flat, names):
        _draw_decomposition(ax, name, decompositions[name])
    for ax in list(axes.flat)[len(names):]:
        ax.axis("off")
    fig.suptitle("{} polygon, n={}, r={}, seed {}".format(family, n, r, seed))
    save(fig, out_dir, "gallery")
    return ["gallery"]


def _panel_name(name):
    """A panel's title line(s) for an algorithm: a variant's base on a line of its own, since
    "hertel-mehlhorn[diagonal-n3]" is wider than a sixth of the full width at SMALL_FONT."""
    return name.replace("[", "\n[", 1)


def _draw_decomposition(ax, name, d):
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    for spine in ax.spines.values():
        spine.set_visible(False)
    if "error" in d:
        ax.set_title(_panel_name(name), fontsize=SMALL_FONT)
        ax.text(0.5, 0.5, d["error"][:80], ha="center", va="center", wrap=True, fontsize=SMALL_FONT,
                transform=ax.transAxes)
        return
    points = [(_coordinate(x), _coordinate(y)) for x, y in d["points"]]
    cmap = plt.get_cmap("Pastel1")
    for i, piece in enumerate(d["pieces"]):
        xs = [points[k][0] for k in piece]
        ys = [points[k][1] for k in piece]
        ax.fill(xs, ys, facecolor=cmap(i % 9), edgecolor="black", linewidth=0.3)
    n = d["n"]
    if len(points) > n:
        ax.plot([p[0] for p in points[n:]], [p[1] for p in points[n:]], "r.", markersize=2)
    outline = points[:n] + points[:1]
    ax.plot([p[0] for p in outline], [p[1] for p in outline], "k-", linewidth=0.6)
    verdict = "" if d.get("valid", True) else " INVALID"
    ax.set_title("{}\n{} pieces{}".format(_panel_name(name), d["piece_count"], verdict), fontsize=SMALL_FONT,
                 color="red" if verdict else "black")


def make_plots(results_path, registry, out_dir, polydecomp=None, gallery_spec=None):
    os.makedirs(out_dir, exist_ok=True)
    _, runs = results.load(results_path)
    style = styles({r.algorithm for r in runs} | set(registry))
    made = time_vs_n(runs, registry, out_dir, style)
    made += real_beside_synthetic(runs, registry, out_dir, style)
    made += time_vs_r(runs, out_dir, style, registry)
    made += pieces_vs_r(runs, registry, out_dir, style)
    made += approximation_ratio(runs, registry, out_dir, style)
    if polydecomp and gallery_spec:
        made += gallery(polydecomp, registry, out_dir, gallery_spec)
    return made
