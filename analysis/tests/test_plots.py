import os
import tempfile
import unittest

from polydecomp_analysis import bounds, plots

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
