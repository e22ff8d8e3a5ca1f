"""Every algorithm's claimed bounds checked against a sweep's results: the tables of results/bounds.md
(analysis/bounds.py is its command line).

Time: per algorithm and family, log t = c + a log n + b log r (t the CPU time of one call) is fitted
(see fit.py) and compared with the claimed bound from `polydecomp list --json` fitted on the same
points; the same is done for each operation counter, which does not jitter with the machine.

Pieces: each valid run is checked against its claimed piece bound ("== n-2", "== r+1", "<= 4*OPT",
...) and, for convex decompositions, against the lower bound ceil(r/2)+1-h (h the holes; at least 1;
docs/holes.md). OPT is taken as the best valid piece count on the same polygon (same family, n, r, h
and seed, or the same corpus file) among algorithms of the same kind
that play by the same rules: a diagonal-only algorithm is compared with diagonal-only ones, an algorithm
that may add Steiner points with all. Where no optimal algorithm ran on a polygon, that best is only an
upper bound on OPT, so ratios are then lower than the true approximation ratios.

Against the peer: every other triangulation of polydecomp's own is timed against CGAL's constrained
Delaunay triangulation (cgal-cdt) on the same polygons at n = 10^5 and 10^6, median over the seeds both
ran. Which algorithms are peers (another library's code) the registry says in its "peer" field.

Beside the peers: every peer (CGAL's, GEOS's, earcut, poly-decomp, ...) against each of polydecomp's own
algorithms of its kind, per family on the polygons of the largest n at which both have valid runs, with
each peer's own outcomes (valid, invalid, failed, skipped) counted.
"""

import collections
import json
import statistics
import subprocess

from . import bound_expr, fit, results

MAX_LISTED = 10  # invalid or failed keys listed per algorithm


def load_registry(polydecomp=None, registry_file=None):
    """{name: algorithm} from `polydecomp list --json` or from a saved copy of its output. Raises
    ValueError when an entry lacks the "peer" field: the copy was saved by an older build."""
    if registry_file:
        with open(registry_file, encoding="utf-8") as f:
            entries = json.load(f)
    else:
        out = subprocess.run([polydecomp, "list", "--json"], check=True, capture_output=True, text=True).stdout
        entries = json.loads(out)
    unmarked = [a["name"] for a in entries if "peer" not in a]
    if unmarked:
        raise ValueError("the registry {} has no \"peer\" field (on {}): save `polydecomp list --json` again".format(
            registry_file or polydecomp, ", ".join(unmarked)))
    return {a["name"]: a for a in entries}


def is_peer(algo):
    """Whether a registered algorithm is another library's code ("peer": "CGAL 5.5"), not polydecomp's
    own ("peer": null)."""
    return algo["peer"] is not None


def best_pieces(runs, registry):
    """{(polygon, kind, steiner_allowed): fewest pieces of a valid run} where steiner_allowed False
    counts diagonal-only algorithms and True counts all."""
    best = {}
    for run in runs:
        algo = registry.get(run.algorithm)
        if not algo or run.status != "ok" or run.pieces is None:
            continue
        for allowed in (True, False):
            if allowed or not algo["steiner"]:
                key = (run.polygon, algo["kind"], allowed)
                best[key] = min(best.get(key, run.pieces), run.pieces)
    return best


def lower_bound(run):
    """Every convex decomposition's: ceil(r/2) + 1 - h pieces, and at least 1 (docs/holes.md)."""
    return max(1, (run.r + 1) // 2 + 1 - run.h)


def reference(run, algo, best):
    return best.get((run.polygon, algo["kind"], algo["steiner"]))


def _exponent(v):
    """Two decimals, without a minus sign on zero."""
    return "{:.2f}".format(round(v, 2) + 0.0)


class CurveCheck:
    """The claim checked along one curve of the sweep: a fit on that curve's points alone."""

    def __init__(self, label, points, claim):
        self.label = label
        self.fit = fit.fit_exponents(points, along_curve=label != "all")
        self.claims = fit.term_claims(self.fit, claim) if self.fit else None
        self.verdict = fit.verdict(self.fit, self.claims) if self.fit else None

    def excess(self):
        return max(self.fit.combination(w) - fit.claim_along(self.claims, w)
                   for _, w in fit.directions(self.fit.names))


CORPUS_CURVES = ("vs-n corpus", "vs-n nearest")  # the curves of real polygons (harness/sweep.h)


class TimeRow:
    """One algorithm on one family (or one operation counter of it): the exponents fitted on all its
    points, and the verdict.

    The verdict comes from the curves along which inputs grow without limit, each fitted alone: time
    against n at a fixed r, or with r a function of n. Fitting them pooled would extrapolate: where a
    family's points at large n all have r close to n, the pooled a (n at fixed r) rests on no data.
    Growth faster than claimed along r at a fixed n is only noted: r <= n bounds it, so it cannot
    contradict an asymptotic bound by itself. So is growth on a corpus's real polygons (curves
    "vs-n corpus" and "vs-n nearest"), whose r varies from polygon to polygon: the fit there is a
    measurement, not a test of the claim. Results without curve labels are checked as one curve."""

    def __init__(self, algorithm, family, claim_text, points, counter=None):
        """points: [(n, r, y, curve labels)]."""
        self.algorithm, self.family, self.claim_text, self.counter = algorithm, family, claim_text, counter
        self.fit = fit.fit_exponents([p[:3] for p in points])
        claim = bound_expr.parse_time_bound(claim_text)
        self.claimed = fit.claimed_exponents(self.fit, claim) if self.fit and claim else None
        self.checks, self.notes = [], []
        self.real_only = all(label in CORPUS_CURVES for p in points for label in p[3]) and any(p[3] for p in points)
        if claim:
            labels = sorted({label for p in points for label in p[3]}) or ["all"]
            for label in labels:
                check = CurveCheck(label, [p[:3] for p in points if label in p[3] or label == "all"], claim)
                if not check.fit:
                    continue
                if check.verdict.startswith("inconclusive"):
                    self.notes.append("{} {}".format(label, check.verdict))
                elif label in CORPUS_CURVES:
                    if check.verdict.startswith("CONTRADICTED"):
                        self.notes.append("{} grows faster than claimed on these real polygons: {}".format(
                            label, check.verdict[len("CONTRADICTED: "):]))
                elif not label.startswith("vs-r"):
                    self.checks.append(check)
                elif check.verdict.startswith("CONTRADICTED"):
                    self.notes.append("{} grows faster in r than claimed: {}".format(
                        label, check.verdict[len("CONTRADICTED: "):]))
        self.contradictions = ["{}: {}".format(c.label, c.verdict[len("CONTRADICTED: "):]) for c in self.checks
                               if c.verdict.startswith("CONTRADICTED")]
        self.verdict = self._verdict(claim) + "".join(" (note: {})".format(n) for n in self.notes)

    def _verdict(self, claim):
        if not claim:
            return "no claim (bound not understood)"
        if not self.checks:
            return "measured on real polygons (no verdict)" if self.real_only else "too few points"
        if self.contradictions:
            return "CONTRADICTED: " + "; ".join(self.contradictions)
        if all(c.verdict != "consistent" for c in self.checks):
            return "consistent (grows slower than claimed)"
        return "consistent"

    @property
    def contradicted(self):
        return self.verdict.startswith("CONTRADICTED")

    def excess(self):
        """How far the growth exceeds the claim on the worst curve (for ranking)."""
        return max((c.excess() for c in self.checks), default=-float("inf"))

    def fitted_text(self):
        if not self.fit:
            return "-"
        return ", ".join("{}={} ± {:.2f}".format(n, _exponent(self.fit.value(n)), self.fit.half_width({n: 1.0}))
                         for n in self.fit.names)

    def claimed_text(self):
        if not self.claimed:
            return "-"
        return ", ".join("{}={}".format(n, _exponent(v)) for n, v in self.claimed.items())

    def points_text(self):
        if not self.fit:
            return "-"
        ns = [p[0] for p in self.fit.points]
        return "{} (n {}..{})".format(len(ns), min(ns), max(ns))


def _on_n_or_r_curve(run):
    """Whether the run lies on a curve against n or r: the fits are in n and r, and a curve against
    the number of holes (vs-h, at one n and r) would only add its scatter in h to them."""
    return any(not label.startswith("vs-h") for label in run.curves) or not run.curves


def time_rows(runs, registry):
    by_key = collections.defaultdict(list)
    for run in runs:
        if run.timed and run.algorithm in registry and _on_n_or_r_curve(run):
            by_key[(run.algorithm, run.family)].append(run)
    rows, op_rows = [], []
    for (algorithm, family), group in sorted(by_key.items()):
        claim = registry[algorithm]["time_bound"]
        rows.append(TimeRow(algorithm, family, claim, [(r.n, r.r, r.seconds, r.curves) for r in group]))
        for counter in sorted({c for r in group for c in r.ops}):
            points = [(r.n, r.r, r.ops[counter], r.curves) for r in group if counter in r.ops]
            op_rows.append(TimeRow(algorithm, family, claim, points, counter))
    return rows, op_rows


class PieceRow:
    """One algorithm's piece counts against its claimed bound and the convex lower bound."""

    def __init__(self, name, algo, runs, best):
        self.algorithm, self.claim_text, self.kind = name, algo["pieces_bound"], algo["kind"]
        self.counts = collections.Counter(r.status for r in runs)
        claim = bound_expr.parse_piece_bound(self.claim_text)
        valid = [r for r in runs if r.status == "ok" and r.pieces is not None]
        self.worst_ratio = None
        self.violations, self.below_lower = [], []
        for run in valid:
            opt = reference(run, algo, best)
            ratio = run.pieces / opt if opt else None
            if ratio is not None and (self.worst_ratio is None or ratio > self.worst_ratio):
                self.worst_ratio = ratio
            if claim and not (claim.uses_opt and opt is None) and not claim.holds(run.pieces, run.n, run.r, opt, run.h):
                self.violations.append((run, opt))
            if self.kind == "convex" and run.pieces < lower_bound(run):
                self.below_lower.append(run)
        self.checked = len(valid)
        if not claim:
            self.verdict = "no claim (bound not understood)"
        elif self.violations or self.below_lower:
            self.verdict = "CONTRADICTED: " + "; ".join(self._violation_texts())
        else:
            self.verdict = "consistent" if valid else "no valid runs"

    def _violation_texts(self):
        texts = []
        if self.violations:
            run, opt = self.violations[0]
            texts.append("{} of {} runs break {} (e.g. {}: {} pieces, best {})".format(
                len(self.violations), self.checked, self.claim_text, run.name, run.pieces, opt))
        if self.below_lower:
            run = self.below_lower[0]
            texts.append("{} runs below ceil(r/2)+1-h (e.g. {}: {} pieces)".format(
                len(self.below_lower), run.name, run.pieces))
        return texts

    @property
    def contradicted(self):
        return self.verdict.startswith("CONTRADICTED")


def piece_rows(runs, registry):
    best = best_pieces(runs, registry)
    by_algorithm = collections.defaultdict(list)
    for run in runs:
        by_algorithm[run.algorithm].append(run)
    return [PieceRow(name, registry[name], group, best) for name, group in sorted(by_algorithm.items())
            if name in registry]


def corpus_rows(runs, refused):
    """Per corpus (a family whose keys name files): [corpus, polygons swept, n range, with holes, files
    refused]."""
    polygons = collections.defaultdict(set)
    for run in runs:
        if run.file is not None:
            polygons[run.family].add(run.polygon)
    refused_by = collections.Counter(item["file"].split("/")[0] for item in refused)
    rows = []
    for corpus in sorted(set(polygons) | set(refused_by)):
        ps = polygons[corpus]
        sizes = "{}..{}".format(min(p[1] for p in ps), max(p[1] for p in ps)) if ps else "-"
        rows.append([corpus, len(ps), sizes, sum(1 for p in ps if p[3] > 0), refused_by[corpus]])
    return rows


def optimum_ratio_rows(runs, registry):
    """On the real polygons (corpus keys), every convex decomposition's pieces against the optimum of
    its rules: diagonal-only algorithms against the fewest pieces of polydecomp's own optimal
    diagonal-only programs, the others against its optimal programs with Steiner points (peers' optimal
    programs are not taken as OPT: CGAL's has known bugs). Per algorithm: [algorithm, polygons,
    mean ratio, median, worst (where)], only on polygons where such an optimum finished validly."""
    real = [run for run in runs if run.file is not None and run.status == "ok" and run.pieces is not None]
    optimum = {}
    for run in real:
        algo = registry.get(run.algorithm)
        if algo and algo["kind"] == "convex" and algo["optimal"] and not is_peer(algo):
            key = (run.polygon, algo["steiner"])
            optimum[key] = min(optimum.get(key, run.pieces), run.pieces)
    ratios = collections.defaultdict(list)
    for run in real:
        algo = registry.get(run.algorithm)
        if not algo or algo["kind"] != "convex" or (algo["optimal"] and not is_peer(algo)):
            continue
        opt = optimum.get((run.polygon, algo["steiner"]))
        if opt:
            ratios[run.algorithm].append((run.pieces / opt, run.name))
    rows = []
    for name, values in sorted(ratios.items()):
        worst = max(values)
        rows.append([name, len(values), "{:.3f}".format(statistics.mean(v for v, _ in values)),
                     "{:.3f}".format(statistics.median(v for v, _ in values)),
                     "{:.3f} ({})".format(worst[0], worst[1])])
    return rows


def _real_polygons_section(runs, registry, refused):
    corpora = corpus_rows(runs, refused)
    if not corpora:
        return "No corpus in these results."
    ratios = optimum_ratio_rows(runs, registry)
    return "\n".join([
        "The corpora's polygons are real outlines (docs/corpora.md); their time fits are in the tables",
        "above, a corpus as a family. The files a corpus refused (listed in the results file's \"refused\")",
        "never ran.",
        "",
        _table(["corpus", "polygons", "n", "with holes", "files refused"], corpora),
        "",
        "Convex pieces against the optimum, on the real polygons where an optimal program of",
        "polydecomp's own finished in its budget (diagonal-only algorithms against the optimal",
        "diagonal-only programs, the others against Chazelle-Dobkin's with Steiner points; no optimal",
        "program takes holes, so polygons with holes are not here):",
        "",
        _table(["algorithm", "polygons", "mean ratio", "median", "worst"], ratios) if ratios else "None.",
    ])


HM = "hertel-mehlhorn"


def is_hm_variant(name):
    """Hertel-Mehlhorn's removal over some triangulation: hertel-mehlhorn, its variants
    hertel-mehlhorn[T] and hertel-mehlhorn-greedy, and CGAL's approx_convex_partition_2."""
    return name == HM or name.startswith(HM + "[") or name.startswith(HM + "-") or name == "cgal-" + HM


def _mean_cell(values):
    return "{:.3f} ({})".format(statistics.mean(values), len(values)) if values else "-"


def hm_variant_tables(runs, registry):
    """The Hertel-Mehlhorn variants' pieces, per family (corpora included): against the fewest of any
    variant on the same polygon, and against the optimum where an optimal diagonal-only program of
    polydecomp's own finished on it. Returns (families, rows against the best, rows against OPT); a
    row is [variant, its cell per family, its cell over all], a cell "mean ratio (polygons)"."""
    ok = [run for run in runs if run.status == "ok" and run.pieces is not None and run.algorithm in registry]
    best, optimum = {}, {}
    for run in ok:
        algo = registry[run.algorithm]
        if is_hm_variant(run.algorithm):
            best[run.polygon] = min(best.get(run.polygon, run.pieces), run.pieces)
        elif algo["kind"] == "convex" and algo["optimal"] and not algo["steiner"] and not is_peer(algo):
            optimum[run.polygon] = min(optimum.get(run.polygon, run.pieces), run.pieces)
    to_best = collections.defaultdict(lambda: collections.defaultdict(list))
    to_opt = collections.defaultdict(lambda: collections.defaultdict(list))
    for run in ok:
        if not is_hm_variant(run.algorithm):
            continue
        to_best[run.algorithm][run.family].append(run.pieces / best[run.polygon])
        if run.polygon in optimum:
            to_opt[run.algorithm][run.family].append(run.pieces / optimum[run.polygon])
    families = sorted({run.family for run in ok if is_hm_variant(run.algorithm)})

    def rows(table):
        return [[name] + [_mean_cell(table[name][f]) for f in families] +
                [_mean_cell([v for f in families for v in table[name][f]])] for name in sorted(table)]
    return families, rows(to_best), rows(to_opt)


def _hm_variants_section(runs, registry):
    families, to_best, to_opt = hm_variant_tables(runs, registry)
    if not to_best:
        return "No Hertel-Mehlhorn variant in these results."
    header = ["variant"] + families + ["all"]
    return "\n".join([
        "Hertel-Mehlhorn's diagonal removal over each triangulation (`hertel-mehlhorn[T]`; `hertel-mehlhorn` is",
        "the one over `monotone`, `hertel-mehlhorn-greedy` the same with the greedy removal order, and",
        "`cgal-hertel-mehlhorn` CGAL's own). Each cell is the mean ratio of the variant's pieces to a",
        "reference on the same polygon, with the number of polygons: a variant is compared only where it ran",
        "(the slow triangulations stop at small n).",
        "",
        "Against the fewest pieces of any variant on the polygon:",
        "",
        _table(header, to_best),
        "",
        "Against the optimum, where an optimal diagonal-only program of polydecomp's own finished (no",
        "polygons with holes):",
        "",
        _table(header, to_opt) if to_opt else "None.",
    ])


PEER = "cgal-cdt"  # the CGAL peer every triangulation is timed against, polygon by polygon
PEER_SIZES = (100000, 1000000)  # the sizes of the comparison (issue 4: "at n = 10^5 and 10^6")


def peer_rows(runs, registry, peer=PEER, sizes=PEER_SIZES):
    """Every other algorithm of the peer's kind (other peers excepted) against the peer on the same
    polygons, at the given sizes: per family, n and r, [algorithm, family, n, r,
    seeds, median seconds, the peer's median seconds, speed-up (the peer's median over the
    algorithm's), seeds on which the algorithm was faster]. Medians are over the seeds both ran."""
    ok = [run for run in runs if run.status == "ok"]
    peer_seconds = {run.polygon: run.seconds for run in ok if run.algorithm == peer}
    kind = registry[peer]["kind"]
    pairs = collections.defaultdict(list)
    for run in ok:
        algo = registry.get(run.algorithm)
        if (algo and algo["kind"] == kind and run.algorithm != peer and not is_peer(algo)
                and run.n in sizes and run.polygon in peer_seconds):
            pairs[(run.algorithm, run.family, run.n, run.r)].append((run.seconds, peer_seconds[run.polygon]))
    rows = []
    for (name, family, n, r), times in sorted(pairs.items()):
        mine, theirs = statistics.median(t for t, _ in times), statistics.median(t for _, t in times)
        faster = sum(1 for t, u in times if t < u)
        rows.append([name, family, n, r, len(times), mine, theirs, theirs / mine if mine > 0 else float("inf"), faster])
    return rows


def peer_summary(rows):
    """Per algorithm: [algorithm, keys compared, keys where its median is slower, the key of the lowest
    speed-up]."""
    by_algorithm = collections.defaultdict(list)
    for row in rows:
        by_algorithm[row[0]].append(row)
    summary = []
    for name, mine in sorted(by_algorithm.items()):
        slower = [row for row in mine if row[7] < 1]
        worst = min(mine, key=lambda row: row[7])
        summary.append([name, len(mine), len(slower),
                        "{:.2f}x ({}, n = {}, r = {})".format(worst[7], worst[1], worst[2], worst[3])])
    return summary


def _peer_section(rows, peer=PEER):
    if not rows:
        return "No other algorithm of {}'s kind ran beside it at n = {}.".format(
            peer, " or ".join(str(n) for n in PEER_SIZES))
    return "\n".join([
        "Each other algorithm of {0}'s kind against the CGAL peer {0} on the same polygons, at n = {1}:".format(
            peer, " and ".join(str(n) for n in PEER_SIZES)),
        "medians of the CPU time of one call over the seeds both ran; the speed-up is",
        "{0}'s median over the algorithm's (above 1 the algorithm is faster); the last column counts the".format(peer),
        "seeds on which the algorithm was the faster. One call per key: on a shared or virtual machine a",
        "difference of a few percent is within the run-to-run noise.",
        "",
        _table(["algorithm", "keys", "slower (median)", "lowest speed-up"], peer_summary(rows)),
        "",
        _table(["algorithm", "family", "n", "r", "seeds", "median (s)", "{} median (s)".format(peer), "speed-up",
                "faster on seeds"],
               [[a, f, n, r, k, "{:.4g}".format(m), "{:.4g}".format(t), "{:.2f}".format(x), w]
                for a, f, n, r, k, m, t, x, w in rows]),
    ])


def peer_outcomes(runs, registry):
    """Per peer: [name, library, kind, ok, invalid, failed, skipped, largest n of a valid run]."""
    rows = []
    for name in sorted(a for a in registry if is_peer(registry[a])):
        mine = [run for run in runs if run.algorithm == name]
        if not mine:
            continue
        counts = collections.Counter(run.status for run in mine)
        largest = max((run.n for run in mine if run.status == "ok"), default="-")
        rows.append([name, registry[name]["peer"], registry[name]["kind"], counts["ok"], counts["invalid"],
                     counts["failed"], counts["skipped"], largest])
    return rows


def beside_peer_rows(runs, registry):
    """Each peer against each of polydecomp's own algorithms of its kind, per family, on the polygons of
    the largest n at which both have valid runs: [peer, algorithm, family, n, the r range, polygons,
    the algorithm's median seconds, the peer's, speed-up (the peer's median over the algorithm's)]."""
    seconds = collections.defaultdict(dict)  # algorithm -> polygon -> seconds of a valid run
    for run in runs:
        if run.status == "ok":
            seconds[run.algorithm][run.polygon] = run.seconds
    rows = []
    for peer in sorted(a for a in registry if is_peer(registry[a])):
        kind = registry[peer]["kind"]
        for name in sorted(a for a in registry if not is_peer(registry[a]) and registry[a]["kind"] == kind):
            common = collections.defaultdict(list)  # family -> polygons both ran validly
            for polygon in seconds[peer].keys() & seconds[name].keys():
                common[polygon[0]].append(polygon)
            for family, polygons in sorted(common.items()):
                n = max(p[1] for p in polygons)
                at_n = [p for p in polygons if p[1] == n]
                mine = statistics.median(seconds[name][p] for p in at_n)
                theirs = statistics.median(seconds[peer][p] for p in at_n)
                r_low, r_high = min(p[2] for p in at_n), max(p[2] for p in at_n)
                rows.append([peer, name, family, n, str(r_low) if r_low == r_high else "{}-{}".format(r_low, r_high),
                             len(at_n), mine, theirs, theirs / mine if mine > 0 else float("inf")])
    return rows


def beside_peer_summary(rows):
    """Per (peer, algorithm): [peer, algorithm, families, largest common n, lowest speed-up (where),
    highest speed-up (where)]."""
    pairs = collections.defaultdict(list)
    for row in rows:
        pairs[(row[0], row[1])].append(row)
    summary = []
    for (peer, name), mine in sorted(pairs.items()):
        low, high = min(mine, key=lambda row: row[8]), max(mine, key=lambda row: row[8])
        summary.append([peer, name, len(mine), max(row[3] for row in mine),
                        "{:.3g}x ({}, n = {})".format(low[8], low[2], low[3]),
                        "{:.3g}x ({}, n = {})".format(high[8], high[2], high[3])])
    return summary


def _machines_caveat(context):
    """A warning when the results were measured on more than one machine: a ratio of two keys' times
    is then only as good as the two machines are alike."""
    machines = sorted(set(context.get("cpu", "").split(" | ")))
    if len(machines) < 2:
        return []
    return ["These results were measured on more than one machine ({}): a speed-up between keys measured".format(
                ", ".join(machines)),
            "on different machines is only indicative (results/README.md says which keys were measured where).",
            ""]


def _beside_peers_section(runs, registry, context):
    outcomes = peer_outcomes(runs, registry)
    if not outcomes:
        return "No peer ran in this sweep."
    rows = beside_peer_rows(runs, registry)
    return "\n".join(_machines_caveat(context) + [
        "Each peer's outcomes in this sweep (a peer keeps its own behaviour: its invalid results are",
        "recorded as returned), then each peer against polydecomp's own algorithms of its kind, per family",
        "on the polygons of the largest n at which both returned valid results: medians of the CPU time of",
        "one call (an external peer's own timing of its algorithm), and the speed-up, the peer's median over",
        "the algorithm's (above 1 polydecomp's algorithm is faster).",
        "",
        _table(["peer", "library", "kind", "ok", "invalid", "failed", "skipped", "largest valid n"], outcomes),
        "",
        _table(["peer", "algorithm", "families", "largest common n", "lowest speed-up", "highest speed-up"],
               beside_peer_summary(rows)) if rows else "No algorithm of polydecomp's own ran beside a peer.",
        "",
        _table(["peer", "algorithm", "family", "n", "r", "polygons", "median (s)", "peer median (s)", "speed-up"],
               [[p, a, f, n, r, k, "{:.4g}".format(m), "{:.4g}".format(t), "{:.3g}".format(x)]
                for p, a, f, n, r, k, m, t, x in rows]) if rows else "",
    ])


def _table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c).replace("|", "\\|") for c in row) + " |" for row in rows]
    return "\n".join(lines)


def summary_verdict(times, pieces):
    """One line per algorithm: time contradictions (how many families, and the worst), piece ones. The
    corpora's rows are measurements without a verdict, and not counted as families here."""
    times = [t for t in times if not t.real_only]
    bad = []
    contradicted = [t for t in times if t.contradictions]
    if contradicted:
        worst = max(contradicted, key=TimeRow.excess)
        bad.append("time on {} of {} families (worst {}, {})".format(
            len(contradicted), len(times), worst.family, worst.contradictions[0]))
    if pieces and pieces.contradicted:
        bad.append("pieces: " + pieces.verdict[len("CONTRADICTED: "):])
    if bad:
        return "CONTRADICTED: " + "; ".join(bad)
    if times and all(t.verdict.startswith("no claim") for t in times):
        return "no time claim understood"
    if not any(t.checks for t in times):
        return "too few points for a time fit"
    return "consistent"


def _commits(context):
    """The commits of the run, abbreviated, each marked (dirty) when its tree had changes: a merged
    context (several invocations or shards) lists them in git_versions, a single one has one commit."""
    versions = context.get("git_versions")
    if versions is None:
        versions = context.get("git_commit", "?")[:12] + (" (dirty)" if context.get("git_dirty") == "true" else "")
    return " and ".join(versions.split(" | "))


def _date_range(text):
    """The first and last of a merged context's dates."""
    dates = text.split(" | ")
    return dates[0] if len(dates) == 1 else "{} to {}".format(dates[0], dates[-1])


Summary = collections.namedtuple("Summary", "name worst_time worst_ratio verdict")


def summaries(times, pieces):
    """Per algorithm, as bounds.md's summary table: its worst family's time fit ("fit (family)" or "-"),
    its worst piece ratio to the best ("-" when none) and the summary verdict."""
    by_algorithm = collections.defaultdict(list)
    for row in times:
        by_algorithm[row.algorithm].append(row)
    piece_by_algorithm = {p.algorithm: p for p in pieces}
    out = []
    for name in sorted(set(by_algorithm) | set(piece_by_algorithm)):
        rows = by_algorithm.get(name, [])
        checked = [row for row in rows if row.checks]  # a corpus's fit is no verdict, so never the worst
        worst = max(checked, key=TimeRow.excess) if checked else None
        p = piece_by_algorithm.get(name)
        out.append(Summary(name, "{} ({})".format(worst.fitted_text(), worst.family) if worst and worst.fit else "-",
                           "{:.3f}".format(p.worst_ratio) if p and p.worst_ratio else "-", summary_verdict(rows, p)))
    return out


def render(context, registry, times, ops, pieces, runs, source, refused=()):
    summary = [[s.name, registry[s.name]["time_bound"], s.worst_time, registry[s.name]["pieces_bound"], s.worst_ratio,
                s.verdict] for s in summaries(times, pieces)]
    failed = [r for r in runs if r.status in ("invalid", "failed")]
    parts = [
        "# Claimed bounds against measurements",
        "",
        "Generated by analysis/bounds.py from `{}` (sweep `{}`, commit {}, {}, {}).".format(
            source, context.get("sweep", "?"), _commits(context), context.get("cpu", "?"),
            _date_range(context.get("date", "?"))),
        "",
        "Time (t, the CPU time of one call) exponents are fitted as log t = c + a log n + b log r on the larger",
        "half of the sizes, with 95% confidence intervals; the claim is fitted on the same points, so its",
        "exponents include log factors.",
        "The verdict checks each curve along n of the sweep alone (n at a fixed r, or r a function of n):",
        "an upper bound is contradicted only when time grows faster than claimed there, beyond the interval",
        "plus {:.2f}. Small sizes see caches and constant costs, so the quick sweep's verdicts are a smoke".format(
            fit.TOLERANCE),
        "test; the paper sweep's are the ones to quote. Piece ratios are to the best",
        "valid count of the same kind on the same polygon (diagonal-only algorithms against diagonal-only",
        "ones); where no optimal algorithm ran, that best is only an upper bound on OPT.",
        "",
        "## Summary",
        "",
        _table(["algorithm", "claimed time", "fitted exponents (worst family)", "claimed pieces",
                "worst ratio to best", "verdict"], summary),
        "",
        "## Time, per family",
        "",
        _table(["algorithm", "family", "claimed", "fitted (95% CI)", "claim on these points", "points", "verdict"],
               [[t.algorithm, t.family, t.claim_text, t.fitted_text(), t.claimed_text(), t.points_text(), t.verdict]
                for t in times]),
        "",
        "## Operation counts, per family",
        "",
        _table(["algorithm", "family", "counter", "claimed", "fitted (95% CI)", "claim on these points", "verdict"],
               [[o.algorithm, o.family, o.counter, o.claim_text, o.fitted_text(), o.claimed_text(), o.verdict]
                for o in ops]) if ops else "No operation counters in these results.",
        "",
        "## Pieces",
        "",
        _table(["algorithm", "kind", "claimed", "ok", "invalid", "failed", "skipped", "worst ratio to best", "verdict"],
               [[p.algorithm, p.kind, p.claim_text, p.counts["ok"], p.counts["invalid"], p.counts["failed"],
                 p.counts["skipped"], "{:.3f}".format(p.worst_ratio) if p.worst_ratio else "-", p.verdict]
                for p in pieces]),
        "",
        "## Real polygons",
        "",
        _real_polygons_section(runs, registry, refused),
        "",
        "## Hertel-Mehlhorn over every triangulation",
        "",
        _hm_variants_section(runs, registry),
        "",
        "## Against {}".format(PEER),
        "",
        _peer_section(peer_rows(runs, registry)) if PEER in registry else "{} is not registered.".format(PEER),
        "",
        "## Beside the peers",
        "",
        _beside_peers_section(runs, registry, context),
        "",
        "## Invalid and failed runs",
        "",
        _failures_table(failed) if failed else "None.",
        "",
    ]
    return "\n".join(parts)


def _failures_table(failed):
    listed = collections.Counter()
    rows = []
    for run in failed:
        listed[run.algorithm] += 1
        if listed[run.algorithm] <= MAX_LISTED:
            rows.append([run.algorithm, run.status, run.name, run.reason])
    more = {a: c - MAX_LISTED for a, c in listed.items() if c > MAX_LISTED}
    table = _table(["algorithm", "status", "key", "reason"], rows)
    if more:
        table += "\n\n" + "; ".join("{}: {} more".format(a, c) for a, c in sorted(more.items()))
    return table


def write_bounds(results_path, registry, out_path):
    refused = []
    context, runs = results.load(results_path, refused)
    times, ops = time_rows(runs, registry)
    pieces = piece_rows(runs, registry)
    results.write_atomic(out_path, render(context, registry, times, ops, pieces, runs, results_path, refused))
    return times, ops, pieces
