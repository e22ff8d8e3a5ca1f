import os
import tempfile
import unittest

from polydecomp_analysis import bounds, plots, results

from . import synthetic


class PlotsTest(unittest.TestCase):
    def test_makes_every_figure_as_png_and_pdf(self):
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
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots()
        plots._draw_decomposition(ax, "x", {"n": 4, "points": [[0, 0], [2, 0], [2, 2], [0, 2], ["1/3", 1]],
                                            "pieces": [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]],
                                            "piece_count": 4, "valid": False})
        self.assertEqual(len(ax.patches), 4)
        self.assertEqual(ax.get_title(), "x: 4 pieces INVALID")
        plt.close(fig)


if __name__ == "__main__":
    unittest.main()
