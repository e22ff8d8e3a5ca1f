import json
import os
import re
import subprocess
import sys
import tempfile
import unittest

import browser_test
from polydecomp_analysis import bounds, plots, report, results

from . import synthetic, synthetic_case

ANALYSIS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_script(name, *args):
    return subprocess.run([sys.executable, os.path.join(ANALYSIS, name), *args], cwd=tempfile.gettempdir(),
                          capture_output=True, text=True, check=False)


def json_data(page, element_id):
    """The JSON a page holds for its script in <script type="application/json" id=element_id>."""
    match = re.search(r'<script type="application/json" id="{}">(.*?)</script>'.format(element_id), page, re.S)
    return json.loads(match.group(1))


def traces(figures, figure_id, algorithm):
    figure = next(f for f in figures if f["id"] == figure_id)
    return [t for t in figure["data"] if t["legendgroup"] == algorithm]


class SyntheticReport(synthetic_case.SyntheticCase):
    """The report of the synthetic sweep, whose growth and piece counts are known."""

    @classmethod
    def setUpClass(cls):
        super().setUpClass()
        cls.style = report.plotly_styles({r.algorithm for r in cls.runs} | set(cls.registry))
        cls.figures = report.time_figures(cls.runs, cls.registry, cls.style)

    def path(self, name):
        return os.path.join(self.tmp.name, name)


class TimeFiguresTest(SyntheticReport):

    def test_one_plot_per_family_and_curve_against_n_then_r(self):
        self.assertEqual([f["id"] for f in self.figures],
                         ["fig-comb-vs-n-r-8", "fig-random-vs-n-r-default", "fig-random-vs-r-n-400"])
        self.assertEqual(self.figures[2]["layout"]["xaxis"], {"type": "log", "title": {"text": "r (reflex vertices)"},
                                                              "exponentformat": "power"})
        self.assertEqual(self.figures[2]["layout"]["yaxis"]["type"], "log")

    def test_the_fitted_slope_beside_the_claimed_one(self):
        quad, liar = (traces(self.figures, "fig-random-vs-n-r-default", a)[0] for a in ("quad", "liar"))
        self.assertEqual(quad["name"], "quad: a=2.00, claimed 2.00")
        self.assertEqual(liar["name"], "liar: a=2.00, claimed 1.14")
        nr2 = traces(self.figures, "fig-random-vs-r-n-400", "nr2")[0]
        self.assertEqual(nr2["name"], "nr2: b=2.00, claimed 2.00")

    def test_the_fit_is_drawn_over_the_points_it_was_fitted_on_only(self):
        measured, fitted = traces(self.figures, "fig-random-vs-n-r-default", "quad")
        self.assertEqual(measured["x"], synthetic.SIZES)
        self.assertEqual(fitted["x"], [800, 1600, 3200])  # the larger half of the sizes (fit.large_sizes)
        self.assertEqual((fitted["line"]["dash"], fitted["showlegend"], fitted["legendgroup"]), ("dash", False, "quad"))
        for x, y in zip(fitted["x"], fitted["y"]):
            self.assertAlmostEqual(y / (1e-9 * x * x), 1.0, delta=0.05)
        self.assertIn("consistent", fitted["hovertemplate"])
        liar = traces(self.figures, "fig-random-vs-n-r-default", "liar")[1]
        self.assertIn("CONTRADICTED", liar["hovertemplate"])

    def test_medians_over_seeds_and_no_r_of_zero_on_a_log_axis(self):
        measured = traces(self.figures, "fig-random-vs-r-n-400", "quad")[0]
        self.assertEqual(measured["x"], [6, 12, 25, 50, 100, 200])
        self.assertEqual([c[1] for c in measured["customdata"]], [2] * 6)  # two seeds a point
        self.assertEqual(measured["mode"], "lines+markers")

    def test_curves_of_fewer_than_three_sizes_are_not_drawn(self):
        small = [r for r in self.runs if r.n <= 200]
        self.assertEqual(report.time_figures(small, self.registry, self.style), [])
        three = [r for r in self.runs if r.n <= 400]
        measured = traces(report.time_figures(three, self.registry, self.style), "fig-comb-vs-n-r-8", "quad")[0]
        self.assertEqual(measured["x"], [100, 200, 400])

    def test_an_algorithm_has_the_colour_and_marker_of_the_figures(self):
        expected = plots.styles({r.algorithm for r in self.runs} | set(self.registry))
        for figure in self.figures:
            for trace in figure["data"]:
                colour, marker = expected[trace["legendgroup"]]
                self.assertEqual(trace["line"]["color"], report.matplotlib.colors.to_hex(colour))
                if "marker" in trace:
                    self.assertEqual(trace["marker"]["symbol"], report.SYMBOLS[marker])


class TablesTest(SyntheticReport):

    def test_every_verdict_with_its_reason(self):
        times, ops = bounds.time_rows(self.runs, self.registry)
        pieces = bounds.piece_rows(self.runs, self.registry)
        rows = report.verdict_rows(self.registry, times, ops, pieces)
        self.assertEqual(len(rows), len(self.registry) + len(times) + len(ops) + len(pieces))
        self.assertEqual(sorted(r[-1] for r in rows if r[0] == "time"), sorted(t.verdict for t in times))
        liar = next(r for r in rows if r[:3] == ["time", "liar", "random"])
        self.assertTrue(liar[-1].startswith("CONTRADICTED: vs-n r=default: fitted a=2.00"), liar)
        self.assertEqual(report.verdict_class(liar[-1]), "bad")
        greedy = next(r for r in rows if r[:2] == ["pieces", "greedy"])
        self.assertTrue(greedy[-1].startswith("CONTRADICTED: "), greedy)
        self.assertEqual(report.verdict_class("consistent"), "")
        self.assertEqual(report.verdict_class("too few points"), "note")

    def test_piece_ratios_to_the_best_per_family(self):
        families, rows = report.piece_ratio_table(self.runs, self.registry)
        self.assertEqual(families, ["comb", "random"])
        by_name = {row[0]: row for row in rows}
        self.assertEqual(by_name["approx"][1], "convex")
        # on comb (r = 8), 2r+1 = 17 pieces against opt's ceil(r/2)+1 = 5 where opt ran (n <= 400), against
        # itself (and nr2's 17) above: a mean of (3.4 + 1) / 2
        self.assertEqual(by_name["approx"][2][0], "2.200")
        self.assertIn("worst 3.400 (approx/comb/n:100/r:8/seed:1)", by_name["approx"][2][1])
        self.assertAlmostEqual(by_name["approx"][2][2], 2.2)
        self.assertEqual(by_name["greedy"][2][0], "1.500")  # r+2 = 10 against 5, then its own 10
        self.assertEqual(by_name["quad"][2][0], "1.000")

    def test_key_table_decodes_to_every_key(self):
        table = json.loads(json.dumps(report.key_table(self.runs)))
        self.assertEqual(len(table["rows"]), len(self.runs))
        for run, row in zip(self.runs, table["rows"]):
            algorithm = table["algorithms"][row[0]]
            self.assertEqual(algorithm + "/" + table["polygons"][row[1]], run.name)
            self.assertEqual(table["statuses"][row[2]], run.status)
            self.assertEqual(table["reasons"][row[3]], run.reason)
            self.assertEqual(row[4], run.pieces)
            self.assertEqual(dict(zip(table["counters"][algorithm], row[6])), run.ops)
        skipped = next(row for run, row in zip(self.runs, table["rows"]) if run.status == "skipped")
        self.assertEqual((skipped[4], skipped[5], skipped[6]), (None, None, []))

    def test_provenance(self):
        rows = dict(report.provenance_rows(self.context))
        self.assertEqual(rows["commits"], ["0123456789ab"])
        self.assertEqual(rows["CPU"], ["test cpu"])
        merged = dict(report.provenance_rows({"date": "d1 | d2 | d3", "git_versions": "a | b (dirty)"}))
        self.assertEqual(merged["dates"], ["d1 to d3 (3 invocations)"])
        self.assertEqual(merged["commits"], ["a", "b (dirty)"])


class PageTest(SyntheticReport):

    def test_a_self_contained_page(self):
        os.makedirs(self.path("plots"), exist_ok=True)
        with open(self.path("plots/gallery.png"), "wb") as f:
            f.write(b"\x89PNG")
        with open(self.path("bounds.md"), "w", encoding="utf-8") as f:
            f.write("# bounds\n")
        out = self.path("site/index.html")
        size = report.write_report(self.results_path, self.registry, out)
        with open(out, encoding="utf-8") as f:
            page = f.read()
        self.assertEqual(size, len(page.encode("utf-8")))
        self.assertIn("plotly.js v", page[:20000])  # inline, from python3-plotly
        self.assertIsNone(re.search(r"<script[^>]* src=|<link[^>]* href=", page), "a file the page would fetch")
        self.assertTrue('<img src="../plots/gallery.png"' in page)  # linked, not inlined
        self.assertTrue('<a href="../bounds.md">' in page)
        figures = json_data(page, "pd-figures")
        self.assertEqual([f["id"] for f in figures], [f["id"] for f in self.figures])
        for f in figures:
            self.assertTrue('<div class="pd-plot" id="{}">'.format(f["id"]) in page, f["id"])
        self.assertEqual(len(json_data(page, "pd-keys-data")["rows"]), len(self.runs))
        self.assertEqual(page.count("<tr"), page.count("</tr>"))
        self.assertTrue('<table id="pd-bounds">' in page)

    def test_no_gallery_no_link(self):
        out = self.path("alone/index.html")
        report.write_report(self.results_path, self.registry, out, gallery_path=self.path("none.png"))
        with open(out, encoding="utf-8") as f:
            self.assertNotIn("<img", f.read())

    def test_data_cannot_close_its_script_element(self):
        text = report.json_script("x", {"s": "</script><script>alert(1)"})
        self.assertEqual(text.count("</script>"), 1)
        self.assertEqual(json.loads(text[text.index(">") + 1:-len("</script>")]), {"s": "</script><script>alert(1)"})


class CompareTest(SyntheticReport):

    def changed(self):
        """The synthetic runs again, quad twice as fast, tri twice as slow, one key gone."""
        with open(self.results_path, encoding="utf-8") as f:
            doc = json.load(f)
        for run in doc["benchmarks"]:
            run["cpu_time"] *= {"quad": 0.5, "tri": 2.0}.get(run["name"].split("/")[0], 1.0)
        doc["benchmarks"] = doc["benchmarks"][1:]
        path = self.path("changed.json")
        with open(path, "w", encoding="utf-8") as f:
            json.dump(doc, f)
        return path

    def test_geometric_means_per_algorithm(self):
        _, new_runs = results.load(self.changed())
        comparison = report.compare_runs(self.runs, new_runs)
        self.assertEqual((comparison.only_old, comparison.only_new), (1, 0))
        summary = {row[0]: row for row in report.compare_summary(comparison)}
        self.assertAlmostEqual(summary["quad"][2], 0.5)
        self.assertAlmostEqual(summary["tri"][2], 2.0)
        self.assertAlmostEqual(summary["liar"][2], 1.0)
        self.assertEqual(summary["quad"][3:], (summary["quad"][1], 0))
        self.assertAlmostEqual(summary["OVERALL_GEOMEAN"][2], 1.0, delta=0.01)
        skipped = sum(1 for r in new_runs if not r.timed)
        self.assertEqual(comparison.untimed, skipped)

    def test_the_command_prints_and_writes_a_page(self):
        changed = self.changed()
        done = run_script("compare.py", self.results_path, changed, "--html", self.path("compare.html"))
        self.assertEqual(done.returncode, 0, done.stderr)
        lines = done.stdout.splitlines()
        self.assertTrue(lines[0].startswith("Comparing {} to {}".format(self.results_path, changed)))
        self.assertEqual(lines[1].split(), ["Benchmark", "CPU", "Old", "CPU", "New", "Ratio", "Change"])
        quad = next(line for line in lines if line.startswith("quad/comb/n:100/r:8/seed:2 "))
        self.assertEqual(quad.split()[-2:], ["0.5000", "-0.5000"])
        self.assertRegex(done.stdout, r"\nquad +35 +0\.5000 +35 +0\n")  # its first key is gone
        with open(self.path("compare.html"), encoding="utf-8") as f:
            page = f.read()
        self.assertNotIn("plotly.js v", page)  # no plot: no plotly
        self.assertEqual(len(json_data(page, "pd-compare-data")["rows"]), len(self.runs) - 1 - (
            sum(1 for r in self.runs if not r.timed)))

    def test_summary_only(self):
        done = run_script("compare.py", self.results_path, self.results_path, "--summary")
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertNotIn("Benchmark", done.stdout)
        self.assertIn("OVERALL_GEOMEAN", done.stdout)


class CommandTest(SyntheticReport):

    def test_every_command_starts(self):
        for name in ("report.py", "compare.py", "browser_test.py"):
            done = run_script(name, "--help")
            self.assertEqual(done.returncode, 0, name + ": " + done.stderr)
            self.assertIn("usage:", done.stdout, name)

    def test_report_of_a_results_folder_and_sweep(self):
        done = run_script("report.py", "--results", self.tmp.name, "--sweep", "synthetic", "--registry",
                          self.registry_path)
        self.assertEqual(done.returncode, 0, done.stderr)
        self.assertTrue(done.stdout.startswith("wrote {} (".format(self.path("index.html"))), done.stdout)
        self.assertTrue(os.path.exists(self.path("index.html")))

    def test_report_refuses_both_or_neither_source(self):
        for args in ([], [self.results_path, "--results", self.tmp.name, "--sweep", "synthetic"],
                     ["--results", self.tmp.name]):
            done = run_script("report.py", *args, "--registry", self.registry_path)
            self.assertEqual(done.returncode, 2, args)
            self.assertIn("give either RESULTS.json or both", done.stderr)

    def test_report_of_a_missing_file(self):
        done = run_script("report.py", self.path("none.json"), "--registry", self.registry_path)
        self.assertEqual(done.returncode, 1)
        self.assertTrue(done.stderr.startswith("error: "), done.stderr)


RENDERED = """<html><body><div class="plots"><div class="pd-plot js-plotly-plot" id="fig-a"><div class="plot-container">
<svg class="main-svg"><g class="scatterlayer"><path class="js-line" d="M0,0L1,1"></path><g class="points">
<path class="point" d="M1,1"></path></g></g></svg></div></div>{second}</div>
<table id="pd-bounds"><thead><tr><th>t</th></tr></thead><tbody>{bounds}</tbody></table><input class="filter">
<table id="pd-keys"><thead><tr><th>k</th></tr></thead><tbody><tr><td>x</td></tr></tbody></table></body></html>"""


class BrowserCheckTest(unittest.TestCase):
    """browser_test's reading of a dumped DOM (its Chromium runs are ctest's report-browser tests)."""

    SECOND = '<div class="pd-plot" id="fig-b"><svg class="main-svg"><path class="point"></path></svg></div>'

    def dom(self, second=SECOND, bounds_rows="<tr><td>row</td></tr>"):
        return RENDERED.format(second=second, bounds=bounds_rows)

    def test_a_rendered_report_passes(self):
        self.assertEqual(browser_test.check_dom(self.dom()),
                         "2 plots rendered (2 points), 1 bounds rows, 1 key rows shown")

    def test_a_plot_without_its_svg_fails(self):
        with self.assertRaisesRegex(browser_test.Failure, "plot fig-b was not rendered"):
            browser_test.check_dom(self.dom(second='<div class="pd-plot" id="fig-b"></div>'))

    def test_a_plot_without_data_fails(self):
        with self.assertRaisesRegex(browser_test.Failure, "plot fig-b shows no data"):
            browser_test.check_dom(self.dom(second='<div class="pd-plot" id="fig-b"><svg class="main-svg">'
                                                   '<path class="js-line" d=""></path></svg></div>'))

    def test_an_empty_bounds_table_fails(self):
        with self.assertRaisesRegex(browser_test.Failure, "bounds table"):
            browser_test.check_dom(self.dom(bounds_rows=""))

    def test_console_lines(self):
        err = "[1:1:INFO:CONSOLE:4] \"Uncaught TypeError: x\", source: file:///r.html (4)\n[1:1:ERROR:dbus] no bus\n"
        self.assertEqual(browser_test.console_lines(err), ['[1:1:INFO:CONSOLE:4] "Uncaught TypeError: x", source: '
                                                           'file:///r.html (4)'])


if __name__ == "__main__":
    unittest.main()
