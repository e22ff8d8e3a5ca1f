import csv
import io
import json
import os
import re
import tempfile
import unittest

from polydecomp_analysis import merge, rejournal, results

from . import synthetic


def write_lines(path, objects, torn=""):
    with open(path, "w", encoding="utf-8") as f:
        for obj in objects:
            f.write(json.dumps(obj) + "\n")
        f.write(torn)


class JournalTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.runs = synthetic.runs()[:6]

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def test_torn_lines_are_ignored_and_later_runs_win(self):
        retried = dict(self.runs[1], status="failed", error_occurred=True, error_message="failed: boom")
        write_lines(self.path("j.jsonl"), [{"context": {"sweep": "s"}}, {"started": self.runs[0]["name"]}, self.runs[0],
                                           self.runs[1], retried, {"started": self.runs[2]["name"], "key_index": 2}],
                    torn='{"name": "half a line')
        contexts, runs, unfinished = results.read_journal(self.path("j.jsonl"))
        self.assertEqual(contexts, [{"sweep": "s"}])
        self.assertEqual(sorted(runs), sorted([self.runs[0]["name"], self.runs[1]["name"]]))
        self.assertEqual(runs[self.runs[1]["name"]]["status"], "failed")
        self.assertEqual([u["started"] for u in unfinished], [self.runs[2]["name"]])

    def test_crash_record_keeps_the_key_index(self):
        record = results.crash_record({"started": "a/b/n:1/r:0/seed:1", "key_index": 7, "curves": ["vs-n r=0"]},
                                      "died (SIGSEGV)")
        self.assertEqual((record["status"], record["key_index"]), ("failed", 7))
        self.assertEqual(record["error_message"], "failed: died (SIGSEGV)")

    def test_assemble_orders_by_key_index_and_writes_csv(self):
        write_lines(self.path("j.jsonl"), [{"context": {"sweep": "s", "date": "d1"}}] + list(reversed(self.runs)) +
                    [{"context": {"sweep": "s", "date": "d2"}}])
        self.assertEqual(results.assemble([self.path("j.jsonl")], self.path("s")), 6)
        with open(self.path("s.json"), encoding="utf-8") as f:
            doc = json.load(f)
        self.assertEqual([b["key_index"] for b in doc["benchmarks"]], list(range(6)))
        self.assertEqual(doc["context"]["date"], "d1 | d2")
        self.assertEqual(doc["context"]["invocations"], "2")
        with open(self.path("s.csv"), encoding="utf-8") as f:
            rows = list(csv.DictReader(f))
        first = self.runs[0]
        self.assertEqual(rows[0]["name"], first["name"])
        self.assertEqual(rows[0]["algorithm"], first["name"].split("/")[0])
        self.assertEqual(int(rows[0]["pieces"]), first["pieces"])
        self.assertAlmostEqual(float(rows[0]["real_time_s"]), first["real_time"] * 1e-9)
        self.assertIn("op_steps", rows[0])
        self.assertFalse(os.path.exists(self.path("s.json.tmp")))

    def test_csv_of_a_skipped_key_takes_n_and_r_from_the_name(self):
        skipped = [r for r in synthetic.runs() if r["status"] == "skipped"][0]
        row = next(csv.DictReader(io.StringIO(results.to_csv([skipped]))))
        self.assertEqual((row["status"], row["n"], row["pieces"]), ("skipped", "800", ""))
        self.assertTrue(row["reason"].startswith("skipped (ceiling)"))


class KeyTest(unittest.TestCase):
    def test_keys_of_families_with_holes_carry_h(self):
        self.assertEqual(results.parse_key("monotone/convex-holes/n:100/r:50/h:4/seed:2"),
                         {"algorithm": "monotone", "family": "convex-holes", "file": None, "n": 100, "r": 50, "h": 4,
                          "seed": 2})
        self.assertEqual(results.parse_key("monotone/comb/n:100/r:49/seed:2")["h"], 0)
        self.assertIsNone(results.parse_key("monotone/comb/n:100/h:4/seed:2"))

    def test_keys_of_corpora_name_the_file(self):
        self.assertEqual(results.parse_key("keil/dcw/FR-00003.wkt/n:120/r:40/h:0"),
                         {"algorithm": "keil", "family": "dcw", "file": "FR-00003.wkt", "n": 120, "r": 40, "h": 0,
                          "seed": 0})
        self.assertIsNone(results.parse_key("keil/dcw/FR-00003.wkt/n:120/r:40"))

    def test_the_latest_refusals_are_listed_once_in_the_results_and_kept_by_rejournal(self):
        with tempfile.TemporaryDirectory() as tmp:
            journal = os.path.join(tmp, "s.journal.jsonl")
            run = {"name": "keil/mine/a.txt/n:4/r:0/h:0", "status": "ok", "key_index": 0}
            lines = [{"context": {}}, {"refusals": [{"file": "mine/c.txt", "reason": "garbage"}]}, run,
                     {"context": {}}, {"refusals": [{"file": "mine/b.txt", "reason": "not simple"}]}]
            with open(journal, "w", encoding="utf-8") as f:
                f.write("".join(json.dumps(line) + "\n" for line in lines))
            self.assertEqual(results.assemble([journal], os.path.join(tmp, "s")), 1)
            refused = []
            results.load(os.path.join(tmp, "s.json"), refused)
            self.assertEqual(refused, [{"file": "mine/b.txt", "reason": "not simple"}])
            with open(os.path.join(tmp, "s.csv"), encoding="utf-8") as f:
                row = next(csv.DictReader(f))
            self.assertEqual((row["family"], row["file"], row["seed"]), ("mine", "a.txt", ""))
            os.remove(journal)
            rejournal.rejournal(tmp, "s", None)
            results.assemble([journal], os.path.join(tmp, "s"))
            refused = []
            results.load(os.path.join(tmp, "s.json"), refused)
            self.assertEqual(refused, [{"file": "mine/b.txt", "reason": "not simple"}])


class RejournalTest(unittest.TestCase):
    """A journal written back from assembled results, some keys left out, then those keys measured again."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.stem = os.path.join(self.tmp.name, "s")
        self.runs = synthetic.runs()[:6]
        write_lines(self.stem + ".journal.jsonl",
                    [{"context": {"sweep": "s", "date": "d1", "git_commit": "a" * 40, "git_dirty": "true"}}] +
                    self.runs[:3] + [{"context": {"sweep": "s", "date": "d2", "git_commit": "b" * 40}}] +
                    self.runs[3:])
        results.assemble([self.stem + ".journal.jsonl"], self.stem)
        os.remove(self.stem + ".journal.jsonl")

    def tearDown(self):
        self.tmp.cleanup()

    def test_leaves_out_the_keys_to_measure_again_and_keeps_the_provenance(self):
        left_out = self.runs[4]["name"]
        self.assertEqual(rejournal.rejournal(self.tmp.name, "s", "^" + re.escape(left_out) + "$"), (5, 1))
        _, runs, _ = results.read_journal(self.stem + ".journal.jsonl")
        self.assertEqual(sorted(runs), sorted(r["name"] for r in self.runs if r["name"] != left_out))
        remeasured = dict(self.runs[4], cpu_time=1.0)
        results.append_line(self.stem + ".journal.jsonl",
                            {"context": {"sweep": "s", "date": "d3", "git_commit": "c" * 40}})
        results.append_line(self.stem + ".journal.jsonl", remeasured)
        self.assertEqual(results.assemble([self.stem + ".journal.jsonl"], self.stem), 6)
        with open(self.stem + ".json", encoding="utf-8") as f:
            doc = json.load(f)
        self.assertEqual([b["key_index"] for b in doc["benchmarks"]], list(range(6)))
        self.assertEqual(doc["benchmarks"][4]["cpu_time"], 1.0)
        self.assertEqual(doc["context"]["invocations"], "3")
        self.assertEqual(doc["context"]["git_versions"], "aaaaaaaaaaaa (dirty) | bbbbbbbbbbbb | cccccccccccc")
        self.assertEqual(doc["context"]["date"], "d1 | d2 | d3")

    def test_a_results_file_without_context_or_versions(self):
        with open(self.stem + ".json", "w", encoding="utf-8") as f:
            json.dump({"benchmarks": self.runs[:2]}, f)
        self.assertEqual(rejournal.rejournal(self.tmp.name, "s", None), (2, 0))
        results.append_line(self.stem + ".journal.jsonl", {"context": {"sweep": "s", "git_commit": "c" * 40}})
        merged = results.merge_contexts([{"invocations": "0", "git_versions": ""}, {"git_commit": "c" * 40}])
        self.assertEqual((merged["invocations"], merged["git_versions"]), ("1", "cccccccccccc"))
        self.assertEqual(results.assemble([self.stem + ".journal.jsonl"], self.stem), 2)

    def test_refuses_to_replace_a_journal(self):
        write_lines(self.stem + ".journal.jsonl", [])
        with self.assertRaisesRegex(ValueError, "exists"):
            rejournal.rejournal(self.tmp.name, "s", None)


class MergeTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        runs = synthetic.runs()
        for i in (1, 2, 3):
            write_lines(os.path.join(self.tmp.name, "s.shard-{}-of-3.journal.jsonl".format(i)),
                        [{"context": {"sweep": "s", "host": "h{}".format(i)}}] + runs[i - 1::3])
        self.count = len(runs)

    def tearDown(self):
        self.tmp.cleanup()

    def test_merges_every_shard_in_sweep_order(self):
        self.assertEqual(merge.merge_shards(self.tmp.name, "s"), (self.count, 3))
        with open(os.path.join(self.tmp.name, "s.json"), encoding="utf-8") as f:
            doc = json.load(f)
        self.assertEqual([b["key_index"] for b in doc["benchmarks"]], list(range(self.count)))
        self.assertEqual(doc["context"]["host"], "h1 | h2 | h3")
        self.assertEqual(doc["context"]["shard"], "merged from 3 shards")

    def test_refuses_a_missing_shard(self):
        os.remove(os.path.join(self.tmp.name, "s.shard-2-of-3.journal.jsonl"))
        with self.assertRaisesRegex(ValueError, "missing shard"):
            merge.shard_journals(self.tmp.name, "s")

    def test_refuses_mixed_splits(self):
        write_lines(os.path.join(self.tmp.name, "s.shard-1-of-2.journal.jsonl"), [])
        with self.assertRaisesRegex(ValueError, "different splits"):
            merge.shard_journals(self.tmp.name, "s")


if __name__ == "__main__":
    unittest.main()
