import os
import tempfile
import unittest

from polydecomp_analysis import bounds

from . import synthetic


def row(markdown, section, first_cells):
    """The cells of the first table row in `section` that starts with first_cells."""
    text = markdown.split("## " + section, 1)[1].split("\n## ", 1)[0]
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
        if cells[:len(first_cells)] == first_cells:
            return cells
    raise AssertionError("no row {} in {}".format(first_cells, section))


class BoundsTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        results_path = os.path.join(cls.tmp.name, "synthetic.json")
        registry_path = os.path.join(cls.tmp.name, "registry.json")
        synthetic.write(results_path, registry_path)
        out = os.path.join(cls.tmp.name, "bounds.md")
        bounds.write_bounds(results_path, bounds.load_registry(registry_file=registry_path), out)
        with open(out, encoding="utf-8") as f:
            cls.md = f.read()

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_consistent_time_bound(self):
        cells = row(self.md, "Time, per family", ["quad", "random"])
        self.assertEqual(cells[2], "n^2")
        self.assertTrue(cells[3].startswith("a=2.00 ±"), cells[3])
        self.assertEqual(cells[-1], "consistent")

    def test_contradicted_time_bound(self):
        cells = row(self.md, "Summary", ["liar"])
        self.assertTrue(cells[-1].startswith("CONTRADICTED: time on 2 of 2 families (worst "), cells[-1])
        self.assertIn(": fitted a=2.00 ±", cells[-1])
        self.assertIn("vs claimed 1.1", cells[-1])
        cells = row(self.md, "Time, per family", ["liar", "random"])
        self.assertTrue(cells[-1].startswith("CONTRADICTED: vs-n r=default: fitted a=2.00 ±"), cells[-1])

    def test_both_exponents_where_the_design_separates_them(self):
        cells = row(self.md, "Time, per family", ["opt", "random"])
        self.assertTrue(cells[3].startswith("a=1.00 ±") and ", b=" in cells[3], cells[3])
        self.assertEqual(cells[-1], "consistent (grows slower than claimed)")

    def test_operation_counts_are_fitted(self):
        cells = row(self.md, "Operation counts, per family", ["liar", "random", "steps"])
        self.assertTrue(cells[-1].startswith("CONTRADICTED"), cells[-1])
        cells = row(self.md, "Operation counts, per family", ["quad", "comb", "steps"])
        self.assertEqual(cells[-1], "consistent")

    def test_piece_bounds_and_ratios(self):
        approx = row(self.md, "Pieces", ["approx"])
        self.assertEqual(approx[7], "{:.3f}".format(401 / 101))  # 2r+1 against ceil(r/2)+1 at r=200
        self.assertEqual(approx[-1], "consistent")
        greedy = row(self.md, "Pieces", ["greedy"])
        self.assertTrue(greedy[-1].startswith("CONTRADICTED: 12 of 36 runs break == r+1"), greedy[-1])
        self.assertEqual(row(self.md, "Pieces", ["tri"])[-1], "consistent")

    def test_invalid_and_skipped_runs_are_reported(self):
        opt = row(self.md, "Pieces", ["opt"])
        self.assertEqual(opt[3:7], ["23", "1", "0", "12"])
        self.assertEqual(row(self.md, "Invalid and failed runs", ["opt", "invalid", synthetic.INVALID_KEY])[-1],
                         "piece 3 is not convex at vertex 17")

    def test_each_algorithm_of_the_peers_kind_against_the_peer_on_the_same_polygons(self):
        _, runs = bounds.results.load(os.path.join(self.tmp.name, "synthetic.json"))
        registry = bounds.load_registry(registry_file=os.path.join(self.tmp.name, "registry.json"))
        rows = bounds.peer_rows(runs, registry, peer="liar", sizes=(1600, 3200))
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
        slow = bounds.peer_rows(runs, registry, peer="tri", sizes=(3200,))
        self.assertEqual(bounds.peer_summary(slow)[0][:3], ["liar", 2, 2])

    def test_an_invalid_result_is_not_a_reference(self):
        best = bounds.best_pieces(bounds.results.load(os.path.join(self.tmp.name, "synthetic.json"))[1],
                                  bounds.load_registry(registry_file=os.path.join(self.tmp.name, "registry.json")))
        self.assertEqual(best[(("random", 200, 50, 1), "convex", False)], 101)  # opt's 26 was invalid
        self.assertEqual(best[(("random", 200, 50, 2), "convex", False)], 26)


if __name__ == "__main__":
    unittest.main()
