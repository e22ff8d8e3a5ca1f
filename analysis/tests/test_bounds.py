import json
import os
import re
import unittest

from polydecomp_analysis import bounds, fit, results

from . import synthetic, synthetic_case


def row(markdown, section, first_cells):
    """The cells of the first table row in `section` that starts with first_cells."""
    text = markdown.split("## " + section, 1)[1].split("\n## ", 1)[0]
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if cells[:len(first_cells)] == first_cells:
            return cells
    raise AssertionError("no row {} in {}".format(first_cells, section))


def time_row(rows, algorithm, family, counter=None):
    return next(t for t in rows if (t.algorithm, t.family, t.counter) == (algorithm, family, counter))


def curve(checked, label):
    """The check of a time row along one curve of the sweep."""
    return next(c for c in checked.checks if c.label == label)


class SyntheticSweep(synthetic_case.SyntheticCase):
    """bounds.md of the synthetic sweep, whose truth is known, and the rows it is rendered from."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        out = os.path.join(cls.tmp.name, "bounds.md")
        cls.times, cls.ops, pieces = bounds.write_bounds(cls.results_path, cls.registry, out)
        cls.pieces = {p.algorithm: p for p in pieces}
        with open(out, encoding="utf-8") as f:
            cls.md = f.read()


class BoundsTest(SyntheticSweep):
    """The verdicts and figures bounds.py computes."""

    def test_consistent_time_bound(self):
        quad = time_row(self.times, "quad", "random")
        self.assertEqual(quad.claim_text, "n^2")
        self.assertEqual(quad.fit.names, ["a"])
        self.assertAlmostEqual(quad.fit.value("a"), 2.0, places=2)
        self.assertEqual(quad.verdict, "consistent")

    def test_contradicted_time_bound(self):
        liar = [t for t in self.times if t.algorithm == "liar"]
        self.assertEqual([(t.family, t.contradicted) for t in liar], [("comb", True), ("random", True)])
        on_random = curve(time_row(liar, "liar", "random"), "vs-n r=default")
        self.assertAlmostEqual(on_random.fit.value("a"), 2.0, places=2)
        self.assertAlmostEqual(fit.claim_along(on_random.claims, {"a": 1.0}), 1.14, places=2)
        self.assertTrue(time_row(liar, "liar", "random").contradictions[0].startswith(
            "vs-n r=default: fitted a=2.00 ±"))
        verdict = bounds.summary_verdict(liar, self.pieces["liar"])
        self.assertTrue(verdict.startswith("CONTRADICTED: time on 2 of 2 families (worst "), verdict)
        self.assertIn(": fitted a=2.00 ±", verdict)
        self.assertIn("vs claimed 1.1", verdict)

    def test_both_exponents_where_the_design_separates_them(self):
        opt = time_row(self.times, "opt", "random")
        self.assertEqual(opt.fit.names, ["a", "b"])
        self.assertAlmostEqual(opt.fit.value("a"), 1.0, places=2)
        self.assertEqual(opt.verdict, "consistent (grows slower than claimed)")

    def test_operation_counts_are_fitted(self):
        liar = time_row(self.ops, "liar", "random", "steps")
        self.assertTrue(liar.contradicted, liar.verdict)
        self.assertAlmostEqual(liar.fit.value("a"), 2.0, places=2)
        self.assertEqual(time_row(self.ops, "quad", "comb", "steps").verdict, "consistent")

    def test_piece_bounds_and_ratios(self):
        approx = self.pieces["approx"]
        self.assertAlmostEqual(approx.worst_ratio, 401 / 101)  # 2r+1 against ceil(r/2)+1 at r=200
        self.assertEqual(approx.verdict, "consistent")
        greedy = self.pieces["greedy"]
        self.assertEqual((len(greedy.violations), greedy.checked), (12, 36))
        self.assertEqual({run.family for run, _ in greedy.violations}, {"comb"})
        self.assertTrue(greedy.verdict.startswith("CONTRADICTED: 12 of 36 runs break == r+1"), greedy.verdict)
        self.assertEqual(self.pieces["tri"].verdict, "consistent")

    def test_invalid_and_skipped_runs_are_counted(self):
        counts = self.pieces["opt"].counts
        self.assertEqual([counts[s] for s in ("ok", "invalid", "failed", "skipped")], [23, 1, 0, 12])
        invalid = [(run.name, run.reason) for run in self.runs if run.status == "invalid"]
        self.assertEqual(invalid, [(synthetic.INVALID_KEY, "piece 3 is not convex at vertex 17")])

    def test_each_algorithm_of_the_peers_kind_against_the_peer_on_the_same_polygons(self):
        rows = bounds.peer_rows(self.runs, self.registry, peer="liar", sizes=(1600, 3200))
        self.assertEqual(sorted({(r[0], r[1], r[2]) for r in rows}),
                         [(a, f, n) for a in ("quad", "tri") for f in ("comb", "random") for n in (1600, 3200)])
        tri = [r for r in rows if r[0] == "tri" and r[1] == "random" and r[2] == 3200][0]
        self.assertEqual(tri[3:5], [800, 2])
        self.assertAlmostEqual(tri[7], 3200)  # n^2 against n, the same jitter on each polygon
        self.assertEqual(tri[8], 2)
        quad = [r for r in rows if r[0] == "quad"]
        self.assertTrue(all(abs(r[7] - 1) < 1e-12 and r[8] == 0 for r in quad))
        summary = bounds.peer_summary(rows)
        self.assertEqual([s[:3] for s in summary], [["quad", 4, 0], ["tri", 4, 0]])
        self.assertTrue(summary[1][3].startswith("1600.00x ("), summary[1][3])  # the lowest, at n = 1600
        slow = bounds.peer_rows(self.runs, self.registry, peer="tri", sizes=(3200,))
        self.assertEqual(bounds.peer_summary(slow)[0][:3], ["liar", 2, 2])

    def test_other_peers_are_not_set_against_the_peer(self):
        registry = dict(self.registry, quad=dict(self.registry["quad"], peer="Synthetic 1.0"))
        self.assertTrue(bounds.is_peer(registry["quad"]))
        self.assertFalse(bounds.is_peer(registry["tri"]))
        rows = bounds.peer_rows(self.runs, registry, peer="liar", sizes=(1600, 3200))
        self.assertEqual({r[0] for r in rows}, {"tri"})

    def test_each_peer_beside_each_own_algorithm_of_its_kind_at_the_largest_common_n(self):
        registry = dict(self.registry, opt=dict(self.registry["opt"], peer="Synthetic 1.0"))
        self.assertEqual(bounds.peer_outcomes(self.runs, registry),
                         [["opt", "Synthetic 1.0", "convex", 23, 1, 0, 12, 400]])
        rows = bounds.beside_peer_rows(self.runs, registry)
        self.assertEqual(sorted({(r[0], r[1]) for r in rows}), [("opt", a) for a in ("approx", "greedy", "nr2")])
        approx = {r[2]: r for r in rows if r[1] == "approx"}
        # opt is skipped above n = 400: the comparison is at 400, every r the family has there, both seeds
        # (random at n = 400: r 0-200 on the vs-r curve, 7 polygons a seed; comb: r = 8).
        self.assertEqual(approx["random"][3:6], [400, "0-200", 14])
        self.assertEqual(approx["comb"][3:6], [400, "8", 2])
        self.assertAlmostEqual(approx["random"][8], 1)  # the same time law and jitter
        nr2 = {r[2]: r for r in rows if r[1] == "nr2"}
        self.assertLess(nr2["comb"][8], 1 / 60)  # nr2 takes n r^2 (64 times more at r = 8), opt n
        summary = bounds.beside_peer_summary(rows)
        self.assertEqual([s[:4] for s in summary], [["opt", a, 2, 400] for a in ("approx", "greedy", "nr2")])
        self.assertIn("## Beside the peers", bounds.render({}, registry, [], [], [], self.runs, "x.json"))
        self.assertNotIn("more than one machine", bounds.render({"cpu": "A"}, registry, [], [], [], self.runs, "x"))
        mixed = bounds.render({"cpu": "B | A | B"}, registry, [], [], [], self.runs, "x")
        self.assertIn("These results were measured on more than one machine (A, B)", mixed)

    def test_a_sweep_without_peers_says_so(self):
        self.assertEqual(bounds.peer_outcomes(self.runs, self.registry), [])
        self.assertIn("No peer ran in this sweep.", self.md)

    def test_a_registry_without_peer_fields_is_refused(self):
        with open(self.registry_path, encoding="utf-8") as f:
            entries = json.load(f)
        old = os.path.join(self.tmp.name, "old-registry.json")
        with open(old, "w", encoding="utf-8") as f:
            json.dump(entries[:1] + [{k: v for k, v in a.items() if k != "peer"} for a in entries[1:]], f)
        with self.assertRaisesRegex(ValueError, r'no "peer" field \(on liar, nr2, '):
            bounds.load_registry(registry_file=old)

    def test_an_invalid_result_is_not_a_reference(self):
        best = bounds.best_pieces(self.runs, self.registry)
        self.assertEqual(best[(("random", 200, 50, 0, 1, None), "convex", False)], 101)  # opt's 26 was invalid
        self.assertEqual(best[(("random", 200, 50, 0, 2, None), "convex", False)], 26)


class RenderingTest(SyntheticSweep):
    """The markdown of bounds.md: each table's cells are the rows' figures, formatted."""

    def test_time_table(self):
        quad = time_row(self.times, "quad", "random")
        self.assertEqual(row(self.md, "Time, per family", ["quad", "random"]),
                         [quad.algorithm, quad.family, quad.claim_text, quad.fitted_text(), quad.claimed_text(),
                          quad.points_text(), quad.verdict])
        self.assertRegex(quad.fitted_text(), r"^a=2\.00 ± \d\.\d\d$")

    def test_summary_table(self):
        liar = [t for t in self.times if t.algorithm == "liar"]
        cells = row(self.md, "Summary", ["liar"])
        self.assertEqual(cells[1], "n*log(n)")
        self.assertEqual(cells[-1], bounds.summary_verdict(liar, self.pieces["liar"]))

    def test_pieces_table(self):
        approx = row(self.md, "Pieces", ["approx"])
        self.assertEqual(approx[1:], ["convex", "<= 4*OPT", "36", "0", "0", "0", "3.970", "consistent"])

    def test_failures_table(self):
        self.assertEqual(row(self.md, "Invalid and failed runs", ["opt", "invalid", synthetic.INVALID_KEY])[-1],
                         "piece 3 is not convex at vertex 17")
        self.assertRegex(self.md, re.compile(r"^\| algorithm \| status \| key \| reason \|$", re.MULTILINE))


if __name__ == "__main__":
    unittest.main()


class LowerBoundTest(unittest.TestCase):
    def test_holes_lower_the_convex_lower_bound(self):
        def run(r, h):
            return results.Run({"name": "a/convex-holes/n:100/r:{}/h:{}/seed:1".format(r, h), "status": "ok"})
        self.assertEqual(bounds.lower_bound(run(9, 0)), 6)
        self.assertEqual(bounds.lower_bound(run(9, 4)), 2)
        self.assertEqual(bounds.lower_bound(run(9, 40)), 1)


class RealPolygonsTest(unittest.TestCase):
    """Convex pieces against the optimum of their rules on corpus polygons, and the corpora's counts."""

    @staticmethod
    def key_run(algorithm, file, pieces, h=0, status="ok"):
        return results.Run({"name": "{}/real/{}/n:10/r:4/h:{}".format(algorithm, file, h), "status": status,
                            "pieces": pieces})

    def test_each_convex_decomposition_against_the_optimum_of_its_rules(self):
        registry = {a["name"]: a for a in synthetic.REGISTRY}
        runs = [self.key_run("opt", "a.wkt", 3), self.key_run("approx", "a.wkt", 6), self.key_run("greedy", "a.wkt", 5),
                self.key_run("opt", "b.wkt", 4), self.key_run("approx", "b.wkt", 4),
                self.key_run("approx", "c.wkt", 9),  # no optimum finished: not counted
                self.key_run("opt", "d.wkt", 2, status="invalid"), self.key_run("approx", "d.wkt", 9),
                results.Run({"name": "approx/random/n:10/r:4/seed:1", "status": "ok", "pieces": 99})]
        self.assertEqual(bounds.optimum_ratio_rows(runs, registry),
                         [["approx", 2, "1.500", "1.500", "2.000 (approx/real/a.wkt/n:10/r:4/h:0)"]])
        refused = [{"file": "real/e.wkt", "reason": "not simple"}, {"file": "other/f.wkt", "reason": "garbage"}]
        runs.append(self.key_run("approx", "g.wkt", 3, h=1))
        self.assertEqual(bounds.corpus_rows(runs, refused), [["other", 0, "-", 0, 1], ["real", 5, "10..10", 1, 1]])


class RealPolygonsAreMeasuredNotJudgedTest(unittest.TestCase):
    def test_a_corpus_fit_is_a_note_never_a_contradiction(self):
        points = [(n, n // 3, 1e-9 * n ** 3, ["vs-n nearest"]) for n in (100, 200, 400, 800, 1600)]
        row = bounds.TimeRow("a", "dcw", "n", points)
        self.assertEqual(row.checks, [])
        self.assertFalse(row.contradicted)
        self.assertTrue(row.verdict.startswith("measured on real polygons (no verdict) (note: vs-n nearest grows"),
                        row.verdict)
        self.assertEqual(bounds.summary_verdict([row], None), "too few points for a time fit")


class CurvesAgainstHTest(unittest.TestCase):
    def test_runs_only_on_a_curve_against_h_stay_out_of_the_fits(self):
        def run(n, h, curves):
            return results.Run({"name": "a/convex-holes/n:{}/r:{}/h:{}/seed:1".format(n, n // 2, h), "status": "ok",
                                "cpu_time": n, "time_unit": "ns", "curves": curves})
        along_n = [run(n, 4, ["vs-n r=default h=4"]) for n in (100, 200, 400, 800)]
        along_h = [run(400, h, ["vs-h n=400 r=n/2"]) for h in (1, 2, 8)]
        registry = {"a": {"time_bound": "n"}}
        both, _ = bounds.time_rows(along_n + along_h, registry)
        alone, _ = bounds.time_rows(along_n, registry)
        self.assertEqual(both[0].fit.points, alone[0].fit.points)


class HertelMehlhornVariantsTest(unittest.TestCase):
    """Each Hertel-Mehlhorn variant's pieces against the best variant and the optimum, per family."""

    def test_ratios_per_family_and_over_all(self):
        convex = {"kind": "convex", "steiner": False, "optimal": False, "peer": None}
        registry = {"hertel-mehlhorn": convex, "hertel-mehlhorn[ear-n2]": convex,
                    "ear-n2": dict(convex, kind="triangulation"), "keil": dict(convex, optimal=True),
                    "cgal-optimal": dict(convex, optimal=True, peer="CGAL 5.5")}

        def run(algorithm, family, seed, pieces, status="ok"):
            return results.Run({"name": "{}/{}/n:100/r:10/seed:{}".format(algorithm, family, seed), "status": status,
                                "pieces": pieces})
        runs = [run("hertel-mehlhorn", "comb", 1, 8), run("hertel-mehlhorn[ear-n2]", "comb", 1, 6),
                run("keil", "comb", 1, 6), run("cgal-optimal", "comb", 1, 3),  # a peer's optimum is no reference
                run("hertel-mehlhorn", "comb", 2, 5), run("hertel-mehlhorn[ear-n2]", "comb", 2, 4, status="invalid"),
                run("hertel-mehlhorn", "star", 1, 9), run("hertel-mehlhorn[ear-n2]", "star", 1, 12),
                run("ear-n2", "star", 1, 98)]
        families, to_best, to_opt = bounds.hm_variant_tables(runs, registry)
        self.assertEqual(families, ["comb", "star"])
        self.assertEqual(to_best, [["hertel-mehlhorn", "1.167 (2)", "1.000 (1)", "1.111 (3)"],
                                   ["hertel-mehlhorn[ear-n2]", "1.000 (1)", "1.333 (1)", "1.167 (2)"]])
        self.assertEqual(to_opt, [["hertel-mehlhorn", "1.333 (1)", "-", "1.333 (1)"],
                                  ["hertel-mehlhorn[ear-n2]", "1.000 (1)", "-", "1.000 (1)"]])
        self.assertTrue(bounds.is_hm_variant("cgal-hertel-mehlhorn"))
        self.assertFalse(bounds.is_hm_variant("hertel"))
