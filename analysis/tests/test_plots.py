import csv
import os
import re
import tempfile
import unittest

import matplotlib.pyplot as plt

from polydecomp_analysis import bounds, plots, results

from . import synthetic

COMMITTED_CSV = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))),
                             "results", "paper.csv")


def run(algorithm, n, seconds, curve="vs-n r=default", family="random", r=None, seed=1, pieces=None):
    obj = {"name": "{}/{}/n:{}/r:{}/seed:{}".format(algorithm, family, n, n // 4 if r is None else r, seed),
           "status": "ok", "cpu_time": seconds * 1e9, "time_unit": "ns", "curves": [curve]}
    if pieces is not None:
        obj["pieces"] = pieces
    return results.Run(obj)


def quadratic(algorithm, sizes, curve="vs-n r=default"):
    """Runs of time 1e-9 n^2 at sizes, two seeds each."""
    return [run(algorithm, n, 1e-9 * n * n * (1 + 0.01 * seed), curve, seed=seed) for n in sizes for seed in (1, 2)]


def registry_of(triangulations, convex):
    """A registry of that many triangulations t1.. and optimal convex decompositions c1.."""
    entries = [{"name": "t{}".format(i + 1), "kind": "triangulation", "optimal": False, "peer": None,
                "time_bound": "n^2"} for i in range(triangulations)]
    entries += [{"name": "c{}".format(i + 1), "kind": "convex", "optimal": True, "peer": None,
                 "time_bound": "n^2"} for i in range(convex)]
    return {a["name"]: a for a in entries}


def pdf_width(path):
    """The page width of a matplotlib PDF, in points."""
    with open(path, "rb") as f:
        return float(re.search(rb"/MediaBox \[ 0 0 ([0-9.]+) ", f.read()).group(1))


def touch(directory, *names):
    for name in names:
        with open(os.path.join(directory, name), "w", encoding="utf-8") as f:
            f.write("stale")


class PlotsTest(unittest.TestCase):
    def test_makes_every_figure_as_png_and_pdf_a_column_wide(self):
        with tempfile.TemporaryDirectory() as tmp:
            results_path = os.path.join(tmp, "synthetic.json")
            registry_path = os.path.join(tmp, "registry.json")
            synthetic.write(results_path, registry_path)
            out = os.path.join(tmp, "plots")
            made = plots.make_plots(results_path, bounds.load_registry(registry_file=registry_path), out)
            self.assertEqual(sorted(made), sorted([
                "time-vs-n_comb_r-8", "time-vs-n_random_r-default", "time-vs-r_random_n-400",
                "pieces-vs-r_random_n-400", "approximation-ratio"]))
            for name in made:
                for ext in ("png", "pdf"):
                    self.assertGreater(os.path.getsize(os.path.join(out, name + "." + ext)), 1000)
                self.assertEqual(pdf_width(os.path.join(out, name + ".pdf")), 72 * plots.COLUMN_WIDTH, name)

    def test_real_polygons_beside_the_synthetic_curve_one_figure_per_kind(self):
        registry = {a["name"]: a for a in synthetic.REGISTRY}
        runs = [results.Run({"name": "{}/random/n:{}/r:{}/seed:1".format(a, n, n // 4), "status": "ok",
                             "cpu_time": n, "time_unit": "ns", "curves": ["vs-n r=default"]})
                for a in ("tri", "approx") for n in (100, 200, 400)]
        runs += [results.Run({"name": "{}/real/{}.wkt/n:{}/r:3/h:0".format(a, n, n), "status": "ok", "cpu_time": n,
                              "time_unit": "ns", "curves": ["vs-n corpus"]})
                 for a in ("tri", "approx") for n in (50, 300)]
        with tempfile.TemporaryDirectory() as out:
            made = plots.real_beside_synthetic(runs, registry, out, plots.styles(registry))
            self.assertEqual(made, ["time-vs-n_real_convex", "time-vs-n_real_triangulation"])
            self.assertGreater(os.path.getsize(os.path.join(out, made[0] + ".png")), 1000)
        self.assertEqual(plots.real_beside_synthetic(runs[:6], registry, out, plots.styles(registry)), [])

    def test_draws_a_decomposition_with_rational_steiner_points(self):
        fig, ax = plt.subplots()
        plots._draw_decomposition(ax, "x", {"n": 4, "points": [[0, 0], [2, 0], [2, 2], [0, 2], ["1/3", 1]],
                                            "pieces": [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
                                            "piece_count": 4, "valid": False})
        self.assertEqual(len(ax.patches), 4)
        self.assertEqual(ax.get_title(), "x\n4 pieces INVALID")
        plt.close(fig)


class StyleTest(unittest.TestCase):
    def drawn_style(self, algorithm, names):
        """(colour, marker) of algorithm's line in a panel of names, each styled over names alone."""
        style = plots.styles(names)
        series = [plots.time_series(a, quadratic(a, [100, 200, 400]), "") for a in sorted(names)]
        fig = plt.figure()
        ax = plots.Panel(series, style, {}).draw(fig, lambda ax: None, "")
        line = [line for line in ax.lines if line.get_linestyle() == "-"][sorted(names).index(algorithm)]
        plt.close(fig)
        return line.get_color(), line.get_marker()

    def test_an_algorithm_looks_the_same_in_figures_of_other_algorithms(self):
        for name, others in (("seidel", {"monotone"}), ("greedy", {"tri", "opt"}), ("keil", {"x", "y", "z"})):
            self.assertEqual(self.drawn_style(name, {name} | others), self.drawn_style(name, {name}))
            self.assertEqual(plots.styles({name} | others)[name], plots.style_of(name))
        everything = {a["name"] for a in synthetic.REGISTRY} | set(plots._KNOWN_SLOTS)
        self.assertEqual(plots.styles(everything)["tri"], plots.styles({"tri"})["tri"])

    def test_no_two_committed_algorithms_look_the_same(self):
        names = set(plots._KNOWN_SLOTS) | {a["name"] for a in synthetic.REGISTRY}
        if os.path.exists(COMMITTED_CSV):
            with open(COMMITTED_CSV, encoding="utf-8") as f:
                names |= {row["algorithm"] for row in csv.DictReader(f)}
        style = plots.styles(names)
        self.assertEqual(len(set(style.values())), len(names))
        for name in names:
            self.assertIn(style[name][0], plots.COLOURS)

    def test_a_group_of_the_known_algorithms_repeats_no_colour(self):
        for marker, names in plots.KNOWN_STYLES.items():
            self.assertLessEqual(len(names), len(plots.COLOURS))
            self.assertEqual({plots.style_of(n)[1] for n in names}, {marker})
            self.assertEqual(len({plots.style_of(n)[0] for n in names}), len(names))


class FitLineTest(unittest.TestCase):
    def test_fit_and_claim_span_the_sizes_fitted_and_no_further(self):
        sizes = [100, 200, 400, 800, 1600, 3200]
        series = plots.time_series("quad", quadratic("quad", sizes), "n^2")
        lines = {line.role: line for line in series.lines}
        self.assertEqual(lines["measured"].xs, sizes)
        for role in ("fit", "claim"):
            self.assertEqual(lines[role].xs, [800, 1600, 3200], role)  # the larger half, as bounds.md fits
            for n, t in zip(lines[role].xs, lines[role].ys):
                self.assertAlmostEqual(t / (1e-9 * n * n), 1.015, delta=0.02)  # through the data, not below
        self.assertEqual(series.label, "quad a=2.00 (2.00)")

    def test_the_figure_draws_the_fit_over_its_range_and_says_what_the_styles_mean(self):
        sizes = [100, 200, 400, 800, 1600, 3200]
        series = [plots.time_series("quad", quadratic("quad", sizes), "n*log(n)")]
        fig = plt.figure()
        ax = plots.Panel(series, plots.styles({"quad"}), {}, plots.TIME_LEGEND_TITLE).draw(fig, lambda ax: None, "")
        dashed = [line for line in ax.lines if line.get_linestyle() == "--"]
        dotted = [line for line in ax.lines if line.get_linestyle() == ":"]
        self.assertEqual([(min(d.get_xdata()), max(d.get_xdata())) for d in dashed + dotted], [(800, 3200)] * 2)
        texts = [t.get_text() for legend in fig.legends + [a.get_legend() for a in fig.axes] if legend
                 for t in legend.get_texts()]
        self.assertEqual(texts[:3], [plots.KEY_TEXT["measured"], plots.KEY_TEXT["fit"], plots.KEY_TEXT["claim"]])
        self.assertEqual([t.split(":")[0] for t in texts[:3]], ["solid", "dashed", "dotted"])
        plt.close(fig)


class FewPointsTest(unittest.TestCase):
    def test_a_curve_of_two_points_is_not_drawn(self):
        self.assertIsNone(plots.time_series("quad", quadratic("quad", [100, 200]), "n^2"))
        self.assertIsNotNone(plots.time_series("quad", quadratic("quad", [100, 200, 400]), "n^2"))

    def test_a_figure_of_short_curves_only_is_not_written_and_its_old_file_goes(self):
        registry = registry_of(2, 0)
        runs = quadratic("t1", [100, 200]) + quadratic("t2", [100, 200, 400]) + quadratic("t1", [100], "vs-n r=16")
        with tempfile.TemporaryDirectory() as out:
            touch(out, "time-vs-n_random_r-16.png", "time-vs-n_random_r-16.pdf", "time-vs-n_random_r-16_x.png")
            made = plots.time_vs_n(runs, registry, out, plots.styles(registry))
            self.assertEqual(made, ["time-vs-n_random_r-default"])
            self.assertEqual(sorted(os.listdir(out)), ["time-vs-n_random_r-default.pdf",
                                                       "time-vs-n_random_r-default.png"])

    def test_pieces_and_time_against_r_of_one_r_are_not_written(self):
        registry = registry_of(0, 2)
        runs = [run("c{}".format(i), 400, 1e-3, "vs-r n=400", r=r, pieces=r + 1, seed=s)
                for i in (1, 2) for r in (10, 10) for s in (1, 2)]
        with tempfile.TemporaryDirectory() as out:
            self.assertEqual(plots.pieces_vs_r(runs, registry, out, plots.styles(registry)), [])
            self.assertEqual(plots.time_vs_r(runs, out, plots.styles(registry), registry), [])
            self.assertEqual(os.listdir(out), [])


class GroupsTest(unittest.TestCase):
    def test_few_algorithms_stay_in_one_panel(self):
        self.assertEqual(plots.groups(["b", "a"], {}), [((), ["a", "b"])])

    def test_many_algorithms_split_by_kind_then_optimality_the_same_in_every_figure(self):
        registry = registry_of(8, 5)
        registry.update({"h{}".format(i): {"name": "h{}".format(i), "kind": "convex", "optimal": False, "peer": None}
                         for i in range(6)})
        self.assertEqual(plots.groups(registry, registry), [
            (("convex", "non-optimal"), ["h{}".format(i) for i in range(6)]),
            (("convex", "optimal"), ["c1", "c2", "c3", "c4", "c5"]),
            (("triangulation",), ["t1", "t2", "t3", "t4", "t5", "t6", "t7", "t8"])])
        # convex decompositions alone (pieces-vs-r): the same groups, without the shared "convex"
        convex = [n for n in registry if n[0] in "ch"]
        self.assertEqual([label for label, _ in plots.groups(convex, registry)], [("non-optimal",), ("optimal",)])
        # more than MAX_SERIES names without a registry: alphabetical chunks
        names = ["a{:02d}".format(i) for i in range(12)]
        self.assertEqual([len(members) for _, members in plots.groups(names, {})], [6, 6])

    def test_a_split_figure_keeps_its_name_and_writes_each_group(self):
        registry = registry_of(8, 5)
        runs = [r for a in sorted(registry) for r in quadratic(a, [100, 200, 400])]
        with tempfile.TemporaryDirectory() as out:
            touch(out, "time-vs-n_random_r-default_partition.png")
            made = plots.time_vs_n(runs, registry, out, plots.styles(registry))
            self.assertEqual(made, ["time-vs-n_random_r-default", "time-vs-n_random_r-default_convex",
                                    "time-vs-n_random_r-default_triangulation"])
            touch(out, "time-vs-n_random_r-default_convex.png")  # an earlier run's: groups are PDF only now
            made = plots.time_vs_n(runs, registry, out, plots.styles(registry))
            expected = [made[0] + ".png"] + [n + ".pdf" for n in made]
            self.assertEqual(sorted(os.listdir(out)), sorted(expected))
            self.assertEqual(pdf_width(os.path.join(out, made[0] + ".pdf")), 72 * plots.FULL_WIDTH)
            self.assertEqual(pdf_width(os.path.join(out, made[1] + ".pdf")), 72 * plots.COLUMN_WIDTH)


if __name__ == "__main__":
    unittest.main()
