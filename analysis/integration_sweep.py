#!/usr/bin/python3
"""End-to-end checks of the sweep driver against the real polydecomp-bench (a ctest entry; needs a build):

  - killing a sweep in the middle and running the same command again loses no finished key, runs no
    finished key again, and ends with the same keys and piece counts as an uninterrupted run;
  - two shards merged with merge.py equal one unsharded run in keys, statuses and piece counts;
  - an algorithm's own budget ("budget_seconds_for") replaces the sweep's for that algorithm only;
  - an unknown sweep or family is refused as such (exit 2), without the advice to resume;
  - a user's folder of polygon files, named in a sweeps file of their own (--sweep-file) as
    "dir:PATH", runs every algorithm on each file it accepts, each result validated, and lists the
    files it refuses once, with the reason;
  - the report of a sweep draws every key of up to drawings.DRAW_MAX_N vertices that ran, with its pieces,
    and gives the commands that make each polygon again (the page stays in DIR/report-drawn/ for the
    browser test).

usage: integration_sweep.py --build DIR
"""

import argparse
import collections
import json
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

from polydecomp_analysis import bounds, drawings, report, results

HERE = os.path.dirname(os.path.abspath(__file__))

BUILD = None

# Three algorithms on two families, small polygons: about 50 keys, each a few milliseconds long.
TINY_SWEEPS = {
    "tiny": {
        "description": "integration test",
        "algorithms": ["ear-n2", "hertel-mehlhorn", "naive"],
        "seeds": [1, 2],
        "min_time": 0.005,
        "budget_seconds": 5,
        "timeout_seconds": 60,
        "curves": [
            {"vs": "n", "families": ["random", "comb"], "r": ["default"], "n": [20, 40, 80, 160]},
            {"vs": "r", "families": ["random"], "n": [64], "r": [0, "n/8", "n/4"]},
        ],
    }
}


def sweep_command(workdir, *extra):
    return [sys.executable, os.path.join(HERE, "sweep.py"), "--sweep", "tiny", "--sweeps",
            os.path.join(workdir, "sweeps.json"), "--build", BUILD, "--results", os.path.join(workdir, "results"),
            "--no-analysis", *extra]


def pieces_by_key(path):
    with open(path, encoding="utf-8") as f:
        runs = json.load(f)["benchmarks"]
    return {run["name"]: (run.get("status"), run.get("pieces")) for run in runs}


def finished_lines(journal):
    """The journal's finished-key lines, verbatim, by key name."""
    lines = {}
    with open(journal, encoding="utf-8") as f:
        for line in f:
            obj = json.loads(line)
            if "name" in obj:
                lines.setdefault(obj["name"], []).append(line)
    return lines


class SweepIntegration(unittest.TestCase):
    def setUp(self):
        self.root = tempfile.mkdtemp(prefix="pd-sweep-")

    def tearDown(self):
        shutil.rmtree(self.root)

    def workdir(self, name, sweeps=None):
        path = os.path.join(self.root, name)
        os.makedirs(os.path.join(path, "results"))
        with open(os.path.join(path, "sweeps.json"), "w", encoding="utf-8") as f:
            json.dump(sweeps or TINY_SWEEPS, f)
        return path

    def run_sweep(self, workdir, *extra, expect_ok=True):
        done = subprocess.run(sweep_command(workdir, *extra), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              text=True, check=False)
        if expect_ok:
            self.assertEqual(done.returncode, 0, done.stderr[-2000:])
        return done

    def test_an_unknown_sweep_or_family_is_refused_without_advice_to_resume(self):
        unknown_family = {"tiny": dict(TINY_SWEEPS["tiny"], curves=[
            {"vs": "n", "families": ["nosuch"], "r": ["default"], "n": [20]}])}
        for sweeps, sweep_name in ((None, "nosuch"), (unknown_family, "tiny")):
            workdir = self.workdir("unknown-" + sweep_name, sweeps)
            command = sweep_command(workdir)
            command[command.index("--sweep") + 1] = sweep_name
            done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, check=False)
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn("nosuch", done.stderr)
            self.assertIn("sweep: not run", done.stderr)
            self.assertNotIn("resume", done.stderr)

    def reference(self):
        whole = self.workdir("whole")
        self.run_sweep(whole)
        keys = pieces_by_key(os.path.join(whole, "results", "tiny.json"))
        self.assertGreater(len(keys), 40)
        self.assertTrue(all(status == "ok" for status, _ in keys.values()), keys)
        return keys

    def test_killed_sweep_resumes_without_losing_or_rerunning_keys(self):
        expected = self.reference()
        killed = self.workdir("killed")
        journal = os.path.join(killed, "results", "tiny.journal.jsonl")
        process = subprocess.Popen(sweep_command(killed), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                   start_new_session=True)
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and len(self._finished(journal)) < 10:
            time.sleep(0.05)
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
        before = finished_lines(journal)
        self.assertGreaterEqual(len(before), 10)
        self.assertLess(len(before), len(expected), "the sweep ended before it could be killed")

        self.run_sweep(killed)
        after = finished_lines(journal)
        for name, lines in before.items():
            self.assertEqual(after[name], lines, "{} ran again after the resume".format(name))
        resumed = pieces_by_key(os.path.join(killed, "results", "tiny.json"))
        self.assertEqual(resumed, expected)

    def test_two_shards_merged_equal_one_run(self):
        expected = self.reference()
        sharded = self.workdir("sharded")
        self.run_sweep(sharded, "--shard", "1/2")
        self.run_sweep(sharded, "--shard", "2/2")
        first = pieces_by_key(os.path.join(sharded, "results", "tiny.shard-1-of-2.json"))
        second = pieces_by_key(os.path.join(sharded, "results", "tiny.shard-2-of-2.json"))
        self.assertTrue(first and second)
        self.assertFalse(set(first) & set(second), "a key ran in both shards")
        merge = subprocess.run([sys.executable, os.path.join(HERE, "merge.py"), "--sweep", "tiny", "--results",
                                os.path.join(sharded, "results")], stderr=subprocess.PIPE, text=True, check=False)
        self.assertEqual(merge.returncode, 0, merge.stderr)
        merged_path = os.path.join(sharded, "results", "tiny.json")
        self.assertEqual(pieces_by_key(merged_path), expected)
        with open(merged_path, encoding="utf-8") as f:
            names = [run["name"] for run in json.load(f)["benchmarks"]]
        with open(os.path.join(self.root, "whole", "results", "tiny.json"), encoding="utf-8") as f:
            self.assertEqual(names, [run["name"] for run in json.load(f)["benchmarks"]], "keys out of sweep order")

    def test_an_algorithms_own_budget_replaces_the_sweeps(self):
        sweeps = json.loads(json.dumps(TINY_SWEEPS))
        sweeps["tiny"]["budget_seconds"] = 1e-9
        sweeps["tiny"]["budget_seconds_for"] = {"naive": 60}
        own = self.workdir("own", sweeps)
        self.run_sweep(own)
        statuses = collections.defaultdict(collections.Counter)
        for name, (status, _) in pieces_by_key(os.path.join(own, "results", "tiny.json")).items():
            statuses[name.split("/")[0]][status] += 1
        self.assertEqual(set(statuses["naive"]), {"ok"}, statuses["naive"])
        for other in ("ear-n2", "hertel-mehlhorn"):
            self.assertGreater(statuses[other]["skipped"], 0, statuses[other])

        sweeps["tiny"]["budget_seconds_for"] = {"no-such-algorithm": 60}
        done = self.run_sweep(self.workdir("unknown", sweeps), expect_ok=False)
        self.assertNotEqual(done.returncode, 0)
        self.assertIn("budget_seconds_for: unknown algorithm no-such-algorithm", done.stderr)

    def test_a_users_folder_is_swept_and_its_bad_files_listed_once(self):
        workdir = self.workdir("folder")
        folder = os.path.join(workdir, "my polygons")
        os.makedirs(folder)
        polydecomp = os.path.join(BUILD, "polydecomp")
        for name, args in (("comb.txt", ["--family", "comb", "--n", "30"]),
                           ("holes.wkt", ["--family", "convex-holes", "--n", "40", "--holes", "2", "--format", "wkt"])):
            subprocess.run([polydecomp, "generate", *args, "-o", os.path.join(folder, name)], check=True)
        bad = {"bowtie.txt": "0 0\n1 1\n0 1\n1 0\n", "garbage.json": "garbage\n",
               "two.wkt": "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((5 5, 6 5, 6 6, 5 5)))\n"}
        for name, text in bad.items():
            with open(os.path.join(folder, name), "w", encoding="utf-8") as f:
                f.write(text)
        with open(os.path.join(folder, "README.md"), "w", encoding="utf-8") as f:
            f.write("not a polygon file: not read\n")
        own = os.path.join(workdir, "mine.json")
        with open(own, "w", encoding="utf-8") as f:
            json.dump({"mine": {"description": "a user's folder", "algorithms": ["monotone", "hertel-mehlhorn", "keil"],
                                "seeds": [1], "min_time": 0.001, "budget_seconds": 5, "timeout_seconds": 60,
                                "curves": [{"vs": "n", "families": ["dir:my polygons"]}]}}, f)
        command = [sys.executable, os.path.join(HERE, "sweep.py"), "--sweep", "mine", "--sweep-file", own,
                   "--build", BUILD, "--results", os.path.join(workdir, "results"), "--no-analysis"]
        for _ in range(2):  # the second run resumes: nothing to run, the refusals still listed once
            done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            self.assertEqual(done.returncode, 0, done.stderr)
        with open(os.path.join(workdir, "results", "mine.json"), encoding="utf-8") as f:
            doc = json.load(f)
        self.assertEqual(doc["refused"], [
            {"file": "my polygons/bowtie.txt", "reason": "not simple: edge 0-1 crosses edge 2-3"},
            {"file": "my polygons/garbage.json", "reason": "line 1: 'garbage' is not a number"},
            {"file": "my polygons/two.wkt", "reason": "a multipolygon of 2 parts; a corpus file holds one polygon"}])
        statuses = {run["name"]: (run["status"], run.get("valid")) for run in doc["benchmarks"]}
        self.assertEqual(statuses, {
            "monotone/my polygons/comb.txt/n:30/r:12/h:0": ("ok", 1),
            "hertel-mehlhorn/my polygons/comb.txt/n:30/r:12/h:0": ("ok", 1),
            "keil/my polygons/comb.txt/n:30/r:12/h:0": ("ok", 1),
            "monotone/my polygons/holes.wkt/n:40/r:20/h:2": ("ok", 1),
            "hertel-mehlhorn/my polygons/holes.wkt/n:40/r:20/h:2": ("ok", 1),
            "keil/my polygons/holes.wkt/n:40/r:20/h:2": ("skipped", None)})
        _, runs = results.load(os.path.join(workdir, "results", "mine.json"))
        self.assertEqual({(run.family, run.file) for run in runs},
                         {("my polygons", "comb.txt"), ("my polygons", "holes.wkt")})

    def test_a_report_draws_every_small_key_as_it_ran(self):
        workdir = self.workdir("drawn")
        folder = os.path.join(workdir, "my polygons")
        os.makedirs(folder)
        polydecomp = os.path.join(BUILD, "polydecomp")
        subprocess.run([polydecomp, "generate", "--family", "convex-holes", "--n", "40", "--holes", "2", "--format",
                        "wkt", "-o", os.path.join(folder, "holes.wkt")], check=True)
        own = os.path.join(workdir, "drawn.json")
        with open(own, "w", encoding="utf-8") as f:
            json.dump({"drawn": dict(TINY_SWEEPS["tiny"], algorithms=["monotone", "hertel-mehlhorn", "keil"], curves=[
                {"vs": "n", "families": ["random", "star"], "r": ["default"], "n": [20, 40, 80, 160]},
                {"vs": "r", "families": ["comb"], "n": [64], "r": [4, 16]},
                {"vs": "n", "families": ["comb-holes"], "r": ["default"], "h": [2], "n": [40]},
                {"vs": "h", "families": ["convex-holes"], "n": [40], "r": ["default"], "h": [0, 2]},
                {"vs": "r", "families": ["star"], "n": [30], "r": ["default"]},
                {"vs": "n", "families": ["dir:my polygons"]}])}, f)
        command = [sys.executable, os.path.join(HERE, "sweep.py"), "--sweep", "drawn", "--sweep-file", own,
                   "--build", BUILD, "--results", os.path.join(workdir, "results"), "--no-analysis"]
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        results_file = os.path.join(workdir, "results", "drawn.json")
        page = os.path.join(BUILD, "report-drawn", "index.html")
        report.write_report(results_file, bounds.load_registry(polydecomp), page, polydecomp=polydecomp)
        with open(page, encoding="utf-8") as f:
            table = json.loads(re.search(r'<script type="application/json" id="pd-keys-data">(.*?)</script>',
                                         f.read()).group(1))
        _, runs = results.load(results_file)
        by_name = {run.name: run for run in runs}
        self.assertEqual(table["notes"], [])
        for row in table["rows"]:
            run = by_name[table["algorithms"][row[0]] + "/" + table["polygons"][row[1]]]
            if not (run.timed and run.n <= drawings.DRAW_MAX_N):
                self.assertIsNone(row[7], run.name)
                continue
            shape, steiner, pieces = table["drawings"][row[7]]
            self.assertEqual(len(table["shapes"][shape]), 2 * run.n, run.name)
            self.assertEqual(len(drawings.decode_pieces(pieces)), run.pieces, run.name)
            self.assertEqual(steiner, [], run.name)
        sources = {table["polygons"][row[1]]: table["sources"][row[1]] for row in table["rows"]}
        self.assertEqual(sources["my polygons/holes.wkt/n:40/r:20/h:2"],
                         ["", shlex.quote(os.path.join(folder, "holes.wkt"))])
        self.assertEqual(sources["comb/n:64/r:16/seed:1"][0], "polydecomp generate --family comb --n 64 --reflex 16 "
                                                              "--seed 1 --format wkt -o polygon.wkt")
        for prefix in ("star/n:20/", "star/n:30/"):  # r is an outcome of the family, on any curve
            star = next(polygon for polygon in sources if polygon.startswith(prefix))
            self.assertNotIn("--reflex", sources[star][0])
        no_holes = next(polygon for polygon in sources
                        if polygon.startswith("convex-holes/n:40/") and "/h:0/" in polygon)
        self.assertIn("--holes 0", sources[no_holes][0])
        drawn = sum(1 for row in table["rows"] if row[7] is not None)
        self.assertGreater(drawn, 20)

    @staticmethod
    def _finished(journal):
        if not os.path.exists(journal):
            return {}
        _, runs, _ = results.read_journal(journal)
        return runs


def main():
    global BUILD
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build", required=True, help="the build directory holding polydecomp-bench")
    args, rest = parser.parse_known_args()
    BUILD = os.path.abspath(args.build)
    unittest.main(argv=[sys.argv[0]] + rest)


if __name__ == "__main__":
    main()
