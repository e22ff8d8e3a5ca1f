"""The HTML report of a sweep's results, DIR/index.html (analysis/report.py is its command line), and the
comparison of two results files (analysis/compare.py). A report is one file that needs no network:

  provenance  where the numbers come from: the run's commits, compiler, CGAL, build type, machine, dates
  time        per family, time against n on each reflex rule and against r at each n, log-log, one line
              per algorithm (the median over seeds) and its fitted power law dashed over the points it was
              fitted on only; the legend gives the fitted slope beside the claimed one (bounds.CurveCheck,
              the fit bounds.md checks), and clicking an entry hides or shows that algorithm
  bounds      every verdict of bounds.md (summary, time, operation counters, pieces) with its reason, in
              one table filtered by a text box
  pieces      each algorithm's pieces over the best valid count of its rules on the same polygon, per family
  keys        the gallery figure (plots/gallery.png, linked, not inlined) and every key's status, pieces,
              time and counters, searched by a text box; a key clicked (or named in the address, #key=NAME)
              shows its decomposition drawn (drawings.py: the keys of up to DRAW_MAX_N vertices) and the
              commands that draw it with `polydecomp run --svg`

plotly.js is the Debian package's (python3-plotly), inline. That copy is not minified: it is 8.7 MB of
the page, so the data is kept compact (numbers rounded to DIGITS, names interned, the keys' rows built
by the page's script): the reference run's 32,000 keys, 31 plots and 3,150 verdicts take under 3 MB.
An algorithm has the colour and marker plots.styles gives it in the figures of results/plots/.
"""

import collections
import html
import json
import math
import os
import re
import statistics

import matplotlib.colors
import plotly.offline

from . import bound_expr, bounds, drawings, fit, plots, results

MIN_POINTS = 3  # as in the figures: fewer points show no trend
DIGITS = 4  # significant digits of the times in the page (one call's time jitters more than that)
KEYS_SHOWN = 200  # rows the key and comparison tables show at once: the search narrows them down
PLOT_HEIGHT = 420  # pixels of a plot with few algorithms; the legend's rows add to it
LEGEND_ROW = 20  # pixels of a legend entry
CORPUS_CURVES = bounds.CORPUS_CURVES  # one real polygon a point: drawn as markers, no line through them

# plots.styles' matplotlib markers as plotly's symbols
SYMBOLS = {"o": "circle", "s": "square", "^": "triangle-up", "v": "triangle-down", "D": "diamond", "P": "cross",
           "<": "triangle-left", ">": "triangle-right", "X": "x", "p": "pentagon", "h": "hexagon", "*": "star"}

# The run's provenance as the results file's context holds it: (field, label); a merged context (several
# invocations or shards) joins differing values with " | ".
PROVENANCE = [("sweep", "sweep"), ("sweep_description", "description"), ("git_versions", "commits"),
              ("compiler", "compiler"), ("cgal_version", "CGAL"), ("boost_version", "Boost"),
              ("build_type", "build type"), ("cpu", "CPU"), ("cores", "cores"), ("num_cpus", "CPUs seen"),
              ("mhz_per_cpu", "MHz per CPU"), ("host", "host"), ("host_name", "host name"), ("date", "dates"),
              ("invocations", "invocations")]


def rounded(value, digits=DIGITS):
    return float("{:.{}g}".format(value, digits))


def slug(text):
    return re.sub(r"[^A-Za-z0-9]+", "-", text).strip("-")


def plotly_styles(names):
    """{algorithm: (hex colour, plotly symbol)}: plots.styles' colour and marker, as the figures have them."""
    return {name: (matplotlib.colors.to_hex(colour), SYMBOLS.get(marker, "circle"))
            for name, (colour, marker) in plots.styles(names).items()}


# --- provenance --------------------------------------------------------------------------------------------

def commits(context):
    """The run's commits, abbreviated and marked (dirty) where the tree had changes: a merged context lists
    them in git_versions, a single invocation's has git_commit and git_dirty."""
    if "git_versions" in context:
        return context["git_versions"]
    return context.get("git_commit", "?")[:12] + (" (dirty)" if context.get("git_dirty") == "true" else "")


def provenance_rows(context):
    """[(label, [values])] of the context's provenance fields that are present; the dates as the first and
    the last (a long sweep resumed many times has dozens)."""
    rows = []
    for field, label in PROVENANCE:
        value = commits(context) if field == "git_versions" else context.get(field)
        if value is None or value == "":
            continue
        values = str(value).split(" | ")
        if field == "date" and len(values) > 2:
            values = ["{} to {} ({} invocations)".format(values[0], values[-1], len(values))]
        elif field == "sweep_description" and len(values) > 1:
            # the sweep was resumed after its definition was edited: the last invocation's is shown
            values = ["{} (the last of {} versions)".format(values[-1], len(values))]
        rows.append((label, values))
    return rows


# --- time against n and r ----------------------------------------------------------------------------------

class Axis:
    """What a curve's plot draws along x: n on a curve of a reflex rule ("vs-n ..."), r on a curve of an n
    ("vs-r ..."); index is the size's place in a fit's points (n, r, y), exponent its name in the fit."""

    def __init__(self, prefix, title, index, exponent, other):
        self.prefix, self.title, self.index, self.exponent, self.other = prefix, title, index, exponent, other


AXES = [Axis("vs-n ", "n (vertices)", 0, "a", "r"), Axis("vs-r ", "r (reflex vertices)", 1, "b", "n")]


def curve_runs(runs):
    """{(family, curve label): [timed runs on it]} of the curves against n and r."""
    out = collections.defaultdict(list)
    for run in runs:
        if run.timed and run.seconds > 0:
            for label in run.curves:
                if any(label.startswith(axis.prefix) for axis in AXES):
                    out[(run.family, label)].append(run)
    return out


def median_points(mine, axis):
    """[(x, median seconds, median of the other size, seeds)] over the seeds at each x, sorted by x; x = 0
    (r = 0 on a curve against r) is left out: a log axis has no place for it."""
    groups = collections.defaultdict(list)
    for run in mine:
        size = (run.n, run.r)
        if size[axis.index] > 0:
            groups[size[axis.index]].append((run.seconds, size[1 - axis.index]))
    return [(x, statistics.median(s for s, _ in g), statistics.median(o for _, o in g), len(g))
            for x, g in sorted(groups.items())]


def curve_fit(label, mine, claim):
    """(fit, claimed slope, verdict) of one algorithm along one curve, as bounds.md checks it
    (bounds.CurveCheck: each seed's point, the larger half of the sizes); the claim's parts None when there
    is no claim understood, all None when the points cannot be fitted."""
    points = [(run.n, run.r, run.seconds) for run in mine]
    if claim is None:
        return fit.fit_exponents(points, along_curve=True), None, None
    check = bounds.CurveCheck(label, points, claim)
    if not check.fit:
        return None, None, None
    return check.fit, fit.claim_along(check.claims, {check.fit.names[0]: 1.0}), check.verdict


def fitted_line(f, axis):
    """(xs, ys) of the fitted power law y = c x^e at the fitted points' sizes, so over the fitted range and no
    further: the least-squares line of a one-exponent fit, whose log c is the mean of log y - e log x."""
    e = f.value(axis.exponent)
    log_c = statistics.fmean(math.log(p[2]) - e * math.log(p[axis.index]) for p in f.points)
    xs = sorted({p[axis.index] for p in f.points})
    return xs, [rounded(math.exp(log_c) * x ** e) for x in xs]


def exponent_text(value):
    """Two decimals, without a minus sign on zero (bounds.md writes them so)."""
    return "{:.2f}".format(round(value, 2) + 0.0)


def claim_label(claimed):
    return "claimed " + exponent_text(claimed) if claimed is not None else "no claim understood"


def slope_text(f, axis, claimed):
    return "{}={}, {}".format(axis.exponent, exponent_text(f.value(axis.exponent)), claim_label(claimed))


def algorithm_traces(algorithm, mine, label, claim_text, style, axis):
    """The plotly traces of one algorithm on one curve: its medians, and its fit dashed where the curve's
    larger sizes can be fitted along this axis, both in one legend group (a legend click hides both). No
    trace under MIN_POINTS sizes."""
    points = median_points(mine, axis)
    if len(points) < MIN_POINTS:
        return []
    colour, symbol = style[algorithm]
    claim = bound_expr.parse_time_bound(claim_text) if claim_text else None
    f, claimed, verdict = curve_fit(label, mine, claim)
    if f and f.names != [axis.exponent]:
        f = None  # a fit along the other size (n varying on a curve against r) has no line on this axis
    measured = {
        "name": algorithm + (": " + slope_text(f, axis, claimed) if f else ""), "legendgroup": algorithm,
        "x": [p[0] for p in points], "y": [rounded(p[1]) for p in points],
        "customdata": [[_number(rounded(p[2], 3)), p[3]] for p in points],
        "mode": "markers" if label in CORPUS_CURVES else "lines+markers",
        "line": {"color": colour, "width": 1.5}, "marker": {"color": colour, "symbol": symbol, "size": 6}}
    if not f:
        return [measured]
    xs, ys = fitted_line(f, axis)
    fitted = {
        "name": algorithm + " fit", "legendgroup": algorithm, "showlegend": False, "x": xs, "y": ys,
        "mode": "lines", "line": {"color": colour, "width": 1.2, "dash": "dash"},
        "hovertemplate": "{}: fitted {}={} ± {:.2f} ({}) on {} points, {} {:g}..{:g}<br>{}<extra></extra>".format(
            algorithm, axis.exponent, exponent_text(f.value(axis.exponent)), f.half_width({axis.exponent: 1.0}),
            claim_label(claimed), len(f.points), axis.title[0], xs[0], xs[-1], html.escape(verdict or "no verdict"))}
    return [measured, fitted]


MEDIAN_HOVER = "%{{fullData.name}}<br>{}=%{{x}}, {}=%{{customdata[0]}}<br>%{{y:.3g}} s (median of %{{customdata[1]}} " \
               "runs)<extra></extra>"


def figure(family, label, traces, axis):
    """One plot: its div id, title and plotly figure."""
    entries = sum(1 for t in traces if t.get("showlegend", True))
    layout = {
        "title": {"text": "{}, {}".format(family, label[len(axis.prefix):]), "x": 0.02},
        "xaxis": {"type": "log", "title": {"text": axis.title}, "exponentformat": "power"},
        "yaxis": {"type": "log", "title": {"text": "CPU time per call (s)"}, "exponentformat": "power"},
        # no gap between legend groups (one per algorithm, its line and its fit): every entry fits the height
        "legend": {"title": {"text": "fitted slope (claimed)"}, "font": {"size": 11}, "tracegroupgap": 0},
        "height": max(PLOT_HEIGHT, 120 + LEGEND_ROW * entries), "margin": {"l": 60, "r": 10, "t": 40, "b": 50},
        "hovermode": "closest",
        # the medians' hover, once per plot rather than once per trace (a fit's trace has its own)
        "template": {"data": {"scatter": [{"hovertemplate": MEDIAN_HOVER.format(axis.title[0], axis.other)}]}}}
    return {"id": "fig-{}-{}".format(slug(family), slug(label)), "family": family, "data": traces, "layout": layout}


def time_figures(runs, registry, style):
    """The plots of every family's curves against n then r, in family order; a curve with no algorithm of
    MIN_POINTS sizes has none."""
    figures = []
    by_curve = curve_runs(runs)
    for family in sorted({family for family, _ in by_curve}):
        for axis in AXES:
            for label in sorted(label for f, label in by_curve if f == family and label.startswith(axis.prefix)):
                mine = collections.defaultdict(list)
                for run in by_curve[(family, label)]:
                    mine[run.algorithm].append(run)
                traces = [t for algorithm in sorted(mine) for t in algorithm_traces(
                    algorithm, mine[algorithm], label, registry.get(algorithm, {}).get("time_bound"), style, axis)]
                if traces:
                    figures.append(figure(family, label, traces, axis))
    return figures


# --- the verdicts ------------------------------------------------------------------------------------------

VERDICT_COLUMNS = ["table", "algorithm", "family", "counter", "claimed", "measured", "verdict"]


def summary_rows(registry, times, pieces):
    """One row per algorithm, as bounds.md's summary: its worst family's fit, its worst piece ratio and the
    summary verdict."""
    rows = []
    for s in bounds.summaries(times, pieces):
        claims = "time {}; pieces {}".format(registry[s.name]["time_bound"], registry[s.name]["pieces_bound"])
        measured = "time: {}; worst piece ratio to best: {}".format(s.worst_time, s.worst_ratio)
        rows.append(["summary", s.name, "", "", claims, measured, s.verdict])
    return rows


def _fit_measured(row):
    return "fitted {}; claim on these points {}; points {}".format(row.fitted_text(), row.claimed_text(),
                                                                   row.points_text())


def verdict_rows(registry, times, ops, pieces):
    """Every verdict bounds.md gives, as rows of VERDICT_COLUMNS: the summary, time per family, operation
    counters per family, pieces per algorithm."""
    rows = summary_rows(registry, times, pieces)
    rows += [["time", t.algorithm, t.family, "", t.claim_text, _fit_measured(t), t.verdict] for t in times]
    rows += [["counter", o.algorithm, o.family, o.counter, o.claim_text, _fit_measured(o), o.verdict] for o in ops]
    for p in pieces:
        counts = ", ".join("{} {}".format(s, p.counts[s]) for s in ("ok", "invalid", "failed", "skipped"))
        ratio = "{:.3f}".format(p.worst_ratio) if p.worst_ratio else "-"
        rows.append(["pieces", p.algorithm, "", "", p.claim_text, "{}; worst ratio to best {}".format(counts, ratio),
                     p.verdict])
    return rows


def verdict_class(verdict):
    """The row's colour: red for a contradiction, yellow for a verdict with a caveat, none for consistent."""
    if verdict.startswith("CONTRADICTED"):
        return "bad"
    if verdict.startswith("consistent") and "(note:" not in verdict:
        return ""
    return "note"


# --- pieces against the best -------------------------------------------------------------------------------

def piece_ratios(runs, registry):
    """{(algorithm, family): [(pieces / best, key)]} of every valid run whose polygon has a best valid count
    among the algorithms of its rules (bounds.best_pieces: its kind, diagonal-only or not)."""
    best = bounds.best_pieces(runs, registry)
    ratios = collections.defaultdict(list)
    for run in runs:
        algo = registry.get(run.algorithm)
        if algo and run.status == "ok" and run.pieces is not None:
            opt = bounds.reference(run, algo, best)
            if opt:
                ratios[(run.algorithm, run.family)].append((run.pieces / opt, run.name))
    return ratios


def ratio_cell(values):
    """(text, tooltip, ratio to shade by) of one table cell: the mean; the median and the worst key beside."""
    if not values:
        return "-", "", None
    mean = statistics.fmean(v for v, _ in values)
    worst = max(values, key=lambda v: v[0])  # the first of equals, in sweep order
    tip = "mean {:.3f}, median {:.3f} over {} polygons; worst {:.3f} ({})".format(
        mean, statistics.median(v for v, _ in values), len(values), worst[0], worst[1])
    return "{:.3f}".format(mean), tip, mean


def piece_ratio_table(runs, registry):
    """(families, rows): per algorithm with a ratio, [algorithm, kind, cell of every family..., cell of all]."""
    ratios = piece_ratios(runs, registry)
    families = sorted({family for _, family in ratios})
    names = sorted({name for name, _ in ratios}, key=lambda name: (registry[name]["kind"], name))
    rows = []
    for name in names:
        cells = [ratio_cell(ratios.get((name, family), [])) for family in families]
        cells.append(ratio_cell([v for family in families for v in ratios.get((name, family), [])]))
        rows.append([name, registry[name]["kind"]] + cells)
    return families, rows


def shade(ratio):
    """A cell's background: white at ratio 1, a deeper orange up to ratio 2 and beyond."""
    if ratio is None:
        return ""
    lightness = 100 - 40 * min(1.0, max(0.0, ratio - 1.0))
    return "background:hsl(30,90%,{:.0f}%)".format(lightness)


# --- the keys ----------------------------------------------------------------------------------------------

def _number(value):
    return int(value) if float(value).is_integer() else rounded(value)


def key_table(runs, drawn=None, corpora=None):
    """Every key as compact JSON for the page's script to search: the key's algorithm and polygon (the rest of
    its name, shared by all algorithms), status and reason as indices into lists of their distinct values,
    pieces, seconds (DIGITS digits) and counters as values in the order of the algorithm's own list of counter
    names. {"algorithms", "polygons", "statuses", "reasons", "counters": {algorithm: [names]}, "rows": [[
    algorithm, polygon, status, reason, pieces, seconds, [counter values], drawing]]}: a third the size of plain
    rows. drawn ({name: drawing or why not}, drawings.draw's) adds the drawings: "shapes" (each polygon's
    vertices, once), "drawings" ([shape, Steiner points, pieces]), "notes" (why a key is not drawn); a row's
    drawing is an index into "drawings", or -1 - an index into "notes", or None. "sources" (per polygon, the
    command that makes it and the file it is read from) lets the page show the commands that draw any key."""
    drawn = drawn or {}
    lists = {kind: {} for kind in ("algorithms", "polygons", "statuses", "reasons", "shapes", "notes")}

    def index(kind, value):
        return lists[kind].setdefault(value, len(lists[kind]))

    counters = collections.defaultdict(set)
    for run in runs:
        counters[run.algorithm].update(run.ops)
    counters = {name: sorted(names) for name, names in counters.items()}
    rows, pictures, sources = [], [], {}
    for run in runs:
        polygon = run.name[len(run.algorithm) + 1:]
        drawing = drawn.get(run.name)
        if polygon not in sources or isinstance(drawing, dict):  # a drawn key knows how its polygon was made
            sources[polygon] = drawings.polygon_source(run, corpora or {},
                                                       drawing.get("made_by") if isinstance(drawing, dict) else None)
        rows.append([index("algorithms", run.algorithm), index("polygons", polygon), index("statuses", run.status),
                     index("reasons", run.reason), run.pieces, rounded(run.seconds) if run.timed else None,
                     [_number(run.ops[c]) if c in run.ops else None for c in counters[run.algorithm]]
                     if run.ops else [], picture(drawing, pictures, index)])
    table = {kind: list(values) for kind, values in lists.items()}
    table["shapes"] = [list(shape) for shape in table["shapes"]]
    table["counters"] = {name: counters.get(name, []) for name in table["algorithms"]}
    table["sources"] = [sources[polygon] for polygon in table["polygons"]]
    table["drawings"] = pictures
    table["rows"] = rows
    return table


def picture(drawing, pictures, index):
    """A key row's drawing field (key_table's): appends the drawing to `pictures`, its polygon to the shapes."""
    if drawing is None:
        return None
    if isinstance(drawing, str):
        return -1 - index("notes", drawing)
    pictures.append([index("shapes", tuple(drawing["vertices"])), drawing["steiner"], drawing["pieces"]])
    return len(pictures) - 1


# --- comparing two results files ---------------------------------------------------------------------------

Comparison = collections.namedtuple("Comparison", "rows only_old only_new untimed")


def compare_runs(old_runs, new_runs):
    """The keys timed in both files (status ok or invalid, a time above 0), [(key, algorithm, old seconds, new
    seconds)] in the new file's order, and the counts of keys only in the old file, only in the new one, and
    in both but timed in one at most (skipped or failed)."""
    old = {run.name: run for run in old_runs}
    new_names = {run.name for run in new_runs}
    rows, untimed = [], 0
    for run in new_runs:
        before = old.get(run.name)
        if before is None:
            continue
        if before.timed and run.timed and before.seconds > 0 and run.seconds > 0:
            rows.append((run.name, run.algorithm, before.seconds, run.seconds))
        else:
            untimed += 1
    only_old = sum(1 for name in old if name not in new_names)
    only_new = sum(1 for run in new_runs if run.name not in old)
    return Comparison(rows, only_old, only_new, untimed)


def geometric_mean(values):
    return math.exp(statistics.fmean(math.log(v) for v in values))


def compare_summary(comparison):
    """[(algorithm, keys, geometric mean of new/old, keys faster, keys slower)], then the overall row
    ("OVERALL_GEOMEAN", as Google Benchmark's compare.py names it)."""
    ratios = collections.defaultdict(list)
    for _, algorithm, old, new in comparison.rows:
        ratios[algorithm].append(new / old)
    out = []
    for name, values in sorted(ratios.items()) + [("OVERALL_GEOMEAN", [v for vs in ratios.values() for v in vs])]:
        if values:
            out.append((name, len(values), geometric_mean(values), sum(1 for v in values if v < 1),
                        sum(1 for v in values if v > 1)))
    return out


def duration(seconds):
    """A time in the unit that gives it at least one digit before the point, as Google Benchmark prints."""
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("us", 1e-6)):
        if seconds >= scale:
            return "{:.4g} {}".format(seconds / scale, unit)
    return "{:.4g} ns".format(seconds / 1e-9)


def counts_text(comparison):
    return "{} keys compared; {} only in the old file, {} only in the new, {} in both but skipped or failed in " \
           "one or both".format(len(comparison.rows), comparison.only_old, comparison.only_new, comparison.untimed)


def compare_text(old_path, new_path, comparison, summary_only=False):
    """Google Benchmark compare.py's layout: per common key the old and new CPU time of one call, their ratio
    (new over old: below 1 is faster) and the relative change, then per algorithm the geometric mean of the
    ratios."""
    lines = ["Comparing {} to {} (CPU time of one call; ratio = new / old, below 1 is faster)".format(
        old_path, new_path)]
    if not summary_only:
        width = max([len("Benchmark")] + [len(row[0]) for row in comparison.rows])
        columns = ("Benchmark", "CPU Old", "CPU New", "Ratio", "Change")
        header = "{:<{w}} {:>12} {:>12} {:>9} {:>9}".format(*columns, w=width)
        lines += [header, "-" * len(header)]
        row = "{:<{w}} {:>12} {:>12} {:>9.4f} {:>+9.4f}"
        lines += [row.format(name, duration(old), duration(new), new / old, (new - old) / old, w=width)
                  for name, _, old, new in comparison.rows]
        lines.append("")
    summary = compare_summary(comparison)
    width = max([len("OVERALL_GEOMEAN")] + [len(row[0]) for row in summary])
    columns = ("Algorithm", "keys", "geomean ratio", "faster", "slower")
    header = "{:<{w}} {:>7} {:>14} {:>7} {:>7}".format(*columns, w=width)
    lines += [header, "-" * len(header)]
    lines += ["{:<{w}} {:>7} {:>14.4f} {:>7} {:>7}".format(*row, w=width) for row in summary]
    lines += ["", counts_text(comparison)]
    return "\n".join(lines) + "\n"


# --- the page ----------------------------------------------------------------------------------------------

STYLE = """
body{font-family:system-ui,sans-serif;margin:0 2em 4em;color:#222}
h1{margin-top:.6em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:1.6em}
table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ddd;padding:2px 6px;vertical-align:top}
th{background:#f3f3f3;position:sticky;top:0}tr.bad td{background:#fde2e2}tr.note td{background:#fff6d6}
.plots{display:grid;grid-template-columns:repeat(auto-fill,minmax(880px,1fr));gap:12px}
.pd-plot{border:1px solid #eee;min-height:200px}.scroll{overflow:auto;max-height:640px}
input.filter{font-size:14px;padding:4px;width:28em;margin:.4em 0}.count{color:#666;margin-left:1em}
.muted{color:#666}nav a{margin-right:1em}td.num{text-align:right;white-space:nowrap}
#pd-keys td:first-child,#pd-compare td:first-child{white-space:nowrap}figure img{max-width:100%;width:1200px}
#pd-keys tbody tr{cursor:pointer}#pd-keys tbody tr:hover td{background:#eef4ff}
#pd-drawing svg{width:640px;max-width:100%;max-height:640px;border:1px solid #eee}
#pd-drawing .piece{stroke:#555;stroke-width:1}#pd-drawing .boundary{stroke:#000;stroke-width:2.5;fill:none}
#pd-drawing .steiner{fill:#d00}
"""

# The page's own script: the plots drawn from the figures' JSON, a text box filtering the rows of a table,
# and the keys' and comparisons' tables built from their JSON, showing at most KEYS_SHOWN matches. Plain
# JavaScript, so the page needs nothing but plotly.js.
SCRIPT = """
(function () {
  function data(id) { var e = document.getElementById(id); return e ? JSON.parse(e.textContent) : null; }
  var figures = data("pd-figures") || [];
  figures.forEach(function (f) {
    Plotly.newPlot(f.id, f.data, f.layout, {responsive: true, displaylogo: false});
  });
  document.querySelectorAll("input[data-table]").forEach(function (box) {
    var rows = Array.prototype.slice.call(document.querySelectorAll("#" + box.dataset.table + " tbody tr"));
    var texts = rows.map(function (r) { return r.textContent.toLowerCase(); });
    var count = document.getElementById(box.dataset.table + "-count");
    function apply() {
      var q = box.value.toLowerCase(), shown = 0;
      rows.forEach(function (r, i) {
        var hit = texts[i].indexOf(q) >= 0; r.style.display = hit ? "" : "none"; if (hit) shown++;
      });
      count.textContent = shown + " of " + rows.length + " rows";
    }
    box.addEventListener("input", apply); apply();
  });
  function time(s) {
    if (s === null) return "";
    var units = [["s", 1], ["ms", 1e-3], ["us", 1e-6]];
    for (var i = 0; i < units.length; i++) {
      if (s >= units[i][1]) return (s / units[i][1]).toPrecision(4) + " " + units[i][0];
    }
    return (s / 1e-9).toPrecision(4) + " ns";
  }
  function keyRows(t) {
    return t.rows.map(function (r) {
      var algorithm = t.algorithms[r[0]], names = t.counters[algorithm], counters = [];
      r[6].forEach(function (v, i) { if (v !== null) counters.push(names[i] + "=" + v); });
      return [algorithm + "/" + t.polygons[r[1]], t.statuses[r[2]], r[4] === null ? "" : String(r[4]),
              time(r[5]), counters.join(", "), t.reasons[r[3]]];
    });
  }
  function compareRows(t) {
    return t.rows.map(function (r) {
      return [r[0], time(r[1]), time(r[2]), (r[2] / r[1]).toFixed(4), ((r[2] - r[1]) / r[1] * 100).toFixed(1) + "%"];
    });
  }
  function esc(text) { return text.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/"/g, "&quot;"); }
  function searchable(tableId, rows, onPick) {
    var table = document.getElementById(tableId), body = table.querySelector("tbody");
    var box = document.getElementById(tableId + "-search"), count = document.getElementById(tableId + "-count");
    var texts = null, numeric = JSON.parse(table.dataset.numeric);
    function apply() {
      var terms = box.value.toLowerCase().split(/\\s+/).filter(function (w) { return w; });
      if (terms.length && texts === null) texts = rows.map(function (r) { return r.join(" ").toLowerCase(); });
      var html = [], matches = 0;
      for (var i = 0; i < rows.length; i++) {
        if (terms.length && !terms.every(function (w) { return texts[i].indexOf(w) >= 0; })) continue;
        if (++matches > KEYS_SHOWN) continue;
        html.push("<tr data-i=" + i + ">" + rows[i].map(function (c, j) {
          return (numeric.indexOf(j) >= 0 ? "<td class=num>" : "<td>") + esc(c) + "</td>";
        }).join("") + "</tr>");
      }
      body.innerHTML = html.join("");
      count.textContent = matches + " of " + rows.length + " match" +
        (matches > KEYS_SHOWN ? "; the first KEYS_SHOWN shown" : "");
    }
    box.addEventListener("input", apply); apply();
    if (onPick) body.addEventListener("click", function (event) {
      var row = event.target.closest("tr"); if (row) onPick(Number(row.dataset.i));
    });
  }
  function decodePieces(text) {
    var base = ALPHABET.length, pieces = [], at = 0;
    function next() {
      var c = text[at++];
      if (c !== ESCAPE) return ALPHABET.indexOf(c);
      at += 2; return ALPHABET.indexOf(text[at - 2]) * base + ALPHABET.indexOf(text[at - 1]);
    }
    while (at < text.length) {
      var size = next(), piece = [];
      for (var k = 0; k < size; k++) piece.push(next());
      pieces.push(piece);
    }
    return pieces;
  }
  var COLOURS = ["#fbb4ae", "#b3cde3", "#ccebc5", "#decbe4", "#fed9a6", "#ffffcc", "#e5d8bd", "#fddaec", "#f2f2f2"];
  function svgOf(t, picture) {
    // coordinates scaled into a 1000-unit box, y upwards; the boundary is the edges one piece has alone
    var v = t.shapes[picture[0]].concat(picture[1]), nv = t.shapes[picture[0]].length / 2;
    var pieces = decodePieces(picture[2]), x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (var i = 0; i < v.length; i += 2) {
      x0 = Math.min(x0, v[i]); x1 = Math.max(x1, v[i]); y0 = Math.min(y0, v[i + 1]); y1 = Math.max(y1, v[i + 1]);
    }
    var scale = 1000 / (Math.max(x1 - x0, y1 - y0) || 1);
    function at(k) { return ((v[2 * k] - x0) * scale).toFixed(1) + "," + ((y1 - v[2 * k + 1]) * scale).toFixed(1); }
    var shapes = [], edges = {};
    pieces.forEach(function (piece, p) {
      shapes.push('<polygon class="piece" fill="' + COLOURS[p % COLOURS.length] + '" points="' +
                  piece.map(at).join(" ") + '"/>');
      piece.forEach(function (a, k) {
        var b = piece[(k + 1) % piece.length], edge = Math.min(a, b) + " " + Math.max(a, b);
        edges[edge] = (edges[edge] || 0) + 1;
      });
    });
    Object.keys(edges).forEach(function (edge) {
      if (edges[edge] === 1) {
        shapes.push('<polyline class="boundary" points="' + edge.split(" ").map(Number).map(at).join(" ") + '"/>');
      }
    });
    for (var s = nv; s < v.length / 2; s++) {
      var xy = at(s).split(",");
      shapes.push('<circle class="steiner" r="5" cx="' + xy[0] + '" cy="' + xy[1] + '"/>');
    }
    var w = Math.ceil((x1 - x0) * scale), h = Math.ceil((y1 - y0) * scale);
    return '<svg xmlns="http://www.w3.org/2000/svg" viewBox="-10 -10 ' + (w + 20) + " " + (h + 20) + '">' +
           shapes.join("") + "</svg>";
  }
  function quoted(word) {  // as Python's shlex.quote
    return /^[A-Za-z0-9_.\\/:=-]+$/.test(word) ? word : "'" + word.replace(/'/g, "'\\"'\\"'") + "'";
  }
  function showKey(t, i) {
    var r = t.rows[i], algorithm = t.algorithms[r[0]], name = algorithm + "/" + t.polygons[r[1]];
    var source = t.sources[r[1]], picture = r[7];
    var commands = (source[0] ? source[0] + " && " : "") + "polydecomp run --algorithm " + quoted(algorithm) +
                   " --input " + source[1] + " --svg " + quoted(algorithm + ".svg");
    var body = picture === null ? "<p class=muted>Not drawn: a skipped or failed run, or over " + DRAW_MAX_N +
               " vertices.</p>" : picture < 0 ? "<p class=muted>" + esc(t.notes[-1 - picture]) + "</p>" :
               svgOf(t, t.drawings[picture]);
    document.getElementById("pd-drawing").innerHTML = "<h3>" + esc(name) + "</h3><p>" + esc(t.statuses[r[2]]) +
      (r[4] === null ? "" : ", " + r[4] + " pieces") + (t.reasons[r[3]] ? ": " + esc(t.reasons[r[3]]) : "") +
      "</p>" + body + "<p>Draw it: <code>" + esc(commands) +
      "</code></p>";
  }
  var keys = data("pd-keys-data"), compared = data("pd-compare-data");
  if (keys) {
    var names = keys.rows.map(function (r) { return keys.algorithms[r[0]] + "/" + keys.polygons[r[1]]; });
    var pick = function (i) {
      showKey(keys, i);
      try { history.replaceState(null, "", "#key=" + encodeURIComponent(names[i])); } catch (e) { /* file: */ }
    };
    searchable("pd-keys", keyRows(keys), pick);
    var wanted = -1;
    try {
      if (location.hash.indexOf("#key=") === 0) wanted = names.indexOf(decodeURIComponent(location.hash.slice(5)));
    } catch (e) { /* a malformed address names no key */ }
    if (wanted >= 0) {
      showKey(keys, wanted); document.getElementById("pd-drawing").scrollIntoView();
    } else {
      wanted = keys.rows.findIndex(function (r) { return r[7] !== null && r[7] >= 0; });
      if (wanted >= 0) showKey(keys, wanted);
    }
  }
  if (compared) searchable("pd-compare", compareRows(compared));
})();
""".replace("KEYS_SHOWN", str(KEYS_SHOWN)).replace("DRAW_MAX_N", str(drawings.DRAW_MAX_N)).replace(
    "ALPHABET", json.dumps(drawings.ALPHABET)).replace("ESCAPE", json.dumps(drawings.ESCAPE))


def e(text):
    return html.escape(str(text), quote=True)


def json_script(element_id, value):
    """Data for the page's script: JSON in a script element that the browser does not run; "</" is escaped
    so that no string in the data can close the element."""
    text = json.dumps(value, separators=(",", ":"), allow_nan=False).replace("</", "<\\/")
    return '<script type="application/json" id="{}">{}</script>'.format(element_id, text)


def html_table(header, rows, table_id=None, row_classes=None, numeric=()):
    """A table of escaped cells; a cell may be (text, tooltip, style) instead of text."""
    out = ['<table{}>'.format(' id="{}"'.format(table_id) if table_id else ""),
           "<thead><tr>" + "".join("<th>{}</th>".format(e(h)) for h in header) + "</tr></thead><tbody>"]
    for i, row in enumerate(rows):
        css = row_classes[i] if row_classes else ""
        cells = []
        for j, cell in enumerate(row):
            text, tip, style = cell if isinstance(cell, tuple) else (cell, "", "")
            attrs = (' class="num"' if j in numeric else "") + (' title="{}"'.format(e(tip)) if tip else "") + (
                ' style="{}"'.format(style) if style else "")
            cells.append("<td{}>{}</td>".format(attrs, e(text)))
        out.append('<tr{}>{}</tr>'.format(' class="{}"'.format(css) if css else "", "".join(cells)))
    out.append("</tbody></table>")
    return "\n".join(out)


def filter_box(table_id, hint):
    return ('<input class="filter" type="search" data-table="{0}" placeholder="{1}">'
            '<span class="count" id="{0}-count"></span>').format(table_id, e(hint))


def search_table(table_id, header, numeric, hint):
    """An empty table that the page's script fills from its JSON, with its search box."""
    return ('<input class="filter" type="search" id="{0}-search" placeholder="{1}"><span class="count" '
            'id="{0}-count"></span>\n<div class="scroll"><table id="{0}" data-numeric="{2}"><thead><tr>{3}</tr>'
            '</thead><tbody></tbody></table></div>').format(
                table_id, e(hint), e(json.dumps(list(numeric))), "".join("<th>{}</th>".format(e(h)) for h in header))


def section(section_id, title, *parts):
    return '<section id="{}">\n<h2>{}</h2>\n{}\n</section>'.format(section_id, e(title), "\n".join(parts))


def provenance_section(context, runs, files, refused):
    rows = [(label, "; ".join(values)) for label, values in provenance_rows(context)]
    statuses = collections.Counter(run.status for run in runs)
    rows.append(("keys", "{} ({})".format(len(runs), ", ".join(
        "{} {}".format(s, statuses[s]) for s in ("ok", "invalid", "failed", "skipped") if statuses[s]))))
    if refused:
        rows.append(("corpus files refused", str(len(refused))))
    links = " ".join('<a href="{}">{}</a>'.format(e(href), e(name)) for name, href in files)
    return section("provenance", "Provenance", html_table(["", ""], rows),
                   '<p>Files: {}</p>'.format(links) if links else "")


def time_section(figures):
    families = []
    for f in figures:
        if f["family"] not in families:
            families.append(f["family"])
    parts = ['<p>CPU time of one call, log-log: one line per algorithm (the median over seeds), its fitted power '
             'law dashed over the points it was fitted on only (the larger half of the sizes, every seed, as in '
             'bounds.md), the fitted slope and the claimed one in the legend. Click a legend entry to hide or show '
             'an algorithm, double-click one to show it alone; drag to zoom, double-click the plot to zoom out. '
             'Curves of fewer than {} sizes are not drawn; on the curves against r, r = 0 has no place on the log '
             'axis. The real polygons of a corpus are points, not lines.</p>'.format(MIN_POINTS),
             "<nav>" + " ".join('<a href="#family-{}">{}</a>'.format(slug(f), e(f)) for f in families) + "</nav>"]
    for family in families:
        divs = "".join('<div class="pd-plot" id="{}"></div>'.format(f["id"]) for f in figures if f["family"] == family)
        parts.append('<h3 id="family-{}">{}</h3>\n<div class="plots">{}</div>'.format(slug(family), e(family), divs))
    if not figures:
        parts.append("<p>No curve against n or r with {} sizes in these results.</p>".format(MIN_POINTS))
    return section("time", "Time against n and r", *parts)


def bounds_section(rows, bounds_link):
    link = ' (<a href="{}">bounds.md</a> has them as tables)'.format(e(bounds_link)) if bounds_link else ""
    return section("bounds", "Claimed bounds against measurements",
                   "<p>Every verdict of the bounds module{}: the summary per algorithm, time and each operation "
                   "counter per family, pieces per algorithm. Red: contradicted; yellow: a verdict with a caveat "
                   "(too few points, inconclusive, a note). Type to filter the rows (e.g. CONTRADICTED, an "
                   "algorithm, a family).</p>".format(link),
                   filter_box("pd-bounds", "filter: any text in a row"),
                   '<div class="scroll">' + html_table(VERDICT_COLUMNS, rows, "pd-bounds",
                                                       [verdict_class(r[-1]) for r in rows]) + "</div>")


def pieces_section(families, rows):
    if not rows:
        return section("pieces", "Pieces against the best", "<p>No valid run with pieces in these results.</p>")
    cells = [[name, kind] + [(text, tip, shade(ratio)) for text, tip, ratio in row_cells]
             for name, kind, *row_cells in rows]
    return section("pieces", "Pieces against the best",
                   "<p>Each algorithm's pieces over the fewest any valid run of its kind and rules (diagonal-only "
                   "or not) returned on the same polygon: the mean per family, the median and the worst key in "
                   "the cell's tooltip. Where no optimal algorithm ran, that best is only an upper bound on OPT. "
                   "Deeper orange is further from the best.</p>",
                   '<div class="scroll">' + html_table(["algorithm", "kind"] + families + ["all"], cells,
                                                       numeric=range(2, len(families) + 3)) + "</div>")


def keys_section(gallery_link, table):
    gallery = ('<figure><img src="{}" alt="the gallery polygon decomposed by every algorithm"><figcaption '
               'class="muted">One polygon decomposed by every algorithm (plots/gallery.png of analysis/plots.py).'
               '</figcaption></figure>'.format(e(gallery_link))
               if gallery_link else '<p class="muted">No gallery figure (plots/gallery.png) beside these results.</p>')
    drawn = ("Click a key to see its decomposition (the polygon made again and decomposed again by the same "
             "build; keys of up to {} vertices that ran) and the commands that draw it with <code>polydecomp run "
             "--svg</code>; the page's address then names the key (<code>#key=...</code>).".format(
                 drawings.DRAW_MAX_N) if table["drawings"] else
             "Click a key to see the commands that draw its decomposition (<code>polydecomp run --svg</code>); "
             "this report was written without drawings.")
    return section("keys", "Decompositions and keys", gallery,
                   "<p>Every key of the sweep: its status, pieces, CPU time of one call, operation counters and "
                   "the reason of an invalid, failed or skipped run. Type words to search (all must match, e.g. "
                   "<code>monotone comb n:1000/</code> or <code>invalid</code>). {}</p>".format(drawn),
                   json_script("pd-keys-data", table),
                   search_table("pd-keys", ["key", "status", "pieces", "CPU time", "counters", "reason"], [2, 3],
                                "search keys: words of the key, status or reason"),
                   '<div id="pd-drawing"></div>')


def compare_note_section():
    return section("compare", "Comparing runs",
                   "<p><code>analysis/compare.py OLD.json NEW.json</code> prints, per key of both files, the old "
                   "and new CPU time and their ratio, and per algorithm the geometric mean of the ratios; "
                   "<code>--html OUT</code> writes it as a page too.</p>")


def page(title, sections, with_plotly):
    """The whole document: plotly.js inline (from python3-plotly) when the page has plots."""
    plotly_js = "<script>{}</script>".format(plotly.offline.get_plotlyjs()) if with_plotly else ""
    return "\n".join(["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
                      "<title>{}</title>".format(e(title)), "<style>{}</style>".format(STYLE), plotly_js,
                      "</head><body>", "<h1>{}</h1>".format(e(title))] + sections +
                     ["<script>{}</script>".format(SCRIPT), "</body></html>", ""])


def relative_link(path, out_path):
    """path as a link from the page at out_path, or None when there is no such file."""
    if not path or not os.path.exists(path):
        return None
    return os.path.relpath(path, os.path.dirname(os.path.abspath(out_path))).replace(os.sep, "/")


def render_report(context, runs, registry, refused=(), links=None, drawn=None, corpora=None):
    """The report's HTML. links: {"files": [(name, href)], "bounds": href or None, "gallery": href or None};
    drawn: drawings.draw's, or None for a page without drawings; corpora: drawings.corpus_folders'."""
    links = links or {}
    style = plotly_styles({run.algorithm for run in runs} | set(registry))
    known = [run for run in runs if run.algorithm in registry]  # the claims and kinds are the registry's
    figures = time_figures(known, registry, style)
    times, ops = bounds.time_rows(known, registry)
    pieces = bounds.piece_rows(known, registry)
    families, ratio_rows = piece_ratio_table(known, registry)
    sections = [
        "<nav>" + " ".join('<a href="#{}">{}</a>'.format(i, t) for i, t in (
            ("provenance", "provenance"), ("time", "time"), ("bounds", "bounds"), ("pieces", "pieces"),
            ("keys", "keys"), ("compare", "comparing runs"))) + "</nav>",
        provenance_section(context, runs, links.get("files", []), refused),
        json_script("pd-figures", [{k: f[k] for k in ("id", "data", "layout")} for f in figures]),
        time_section(figures),
        bounds_section(verdict_rows(registry, times, ops, pieces), links.get("bounds")),
        pieces_section(families, ratio_rows),
        keys_section(links.get("gallery"), key_table(runs, drawn, corpora)),
        compare_note_section(),
    ]
    return page("polydecomp sweep {}".format(context.get("sweep", "?")), sections, with_plotly=bool(figures))


def write_report(results_path, registry, out_path, bounds_path=None, gallery_path=None, polydecomp=None):
    """Writes the report of one results file to out_path; bounds_path (bounds.md) and gallery_path
    (plots/gallery.png) default to those beside the results file, linked when they exist; with polydecomp
    (the command line) the small keys are drawn (drawings.draw). Returns the page's size in bytes."""
    refused = []
    context, runs = results.load(results_path, refused)
    here = os.path.dirname(os.path.abspath(results_path))
    bounds_path = bounds_path or os.path.join(here, "bounds.md")
    gallery_path = gallery_path or os.path.join(here, "plots", "gallery.png")
    stem = os.path.splitext(results_path)[0]
    files = [(os.path.basename(p), relative_link(p, out_path)) for p in (results_path, stem + ".csv", bounds_path)]
    links = {"files": [(name, href) for name, href in files if href],
             "bounds": relative_link(bounds_path, out_path), "gallery": relative_link(gallery_path, out_path)}
    corpora = drawings.corpus_folders(context)
    drawn = drawings.draw(runs, polydecomp, corpora) if polydecomp else None
    text = render_report(context, runs, registry, refused, links, drawn, corpora)
    os.makedirs(os.path.dirname(os.path.abspath(out_path)), exist_ok=True)
    results.write_atomic(out_path, text)
    return len(text.encode("utf-8"))


def compare_page(old_path, new_path, old_context, new_context, comparison):
    """The comparison as a page: both runs' provenance side by side, the summary per algorithm, and every
    common key in a searchable table."""
    fields = [label for _, label in PROVENANCE]
    old_rows, new_rows = dict(provenance_rows(old_context)), dict(provenance_rows(new_context))
    provenance = [(label, "; ".join(old_rows.get(label, ["-"])), "; ".join(new_rows.get(label, ["-"])))
                  for label in fields if label in old_rows or label in new_rows]
    summary = [(name, keys, "{:.4f}".format(ratio), faster, slower)
               for name, keys, ratio, faster, slower in compare_summary(comparison)]
    counts = counts_text(comparison) + "."
    sections = [
        section("provenance", "The two runs", html_table(["", "old: " + old_path, "new: " + new_path], provenance)),
        section("summary", "Per algorithm",
                "<p>Ratio = new CPU time / old (below 1 is faster): the geometric mean over the keys both files "
                "timed. {}</p>".format(e(counts)),
                html_table(["algorithm", "keys", "geomean ratio", "faster", "slower"], summary, numeric=(1, 2, 3, 4))),
        section("keys", "Per key", json_script("pd-compare-data", {"rows": [
            [name, rounded(old), rounded(new)] for name, _, old, new in comparison.rows]}),
                search_table("pd-compare", ["key", "CPU old", "CPU new", "ratio", "change"], [1, 2, 3, 4],
                             "search keys: words of the key")),
    ]
    return page("polydecomp: {} against {}".format(new_path, old_path), sections, with_plotly=False)
