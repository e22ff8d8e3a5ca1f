"""The drawings of the report's keys (polydecomp_analysis/drawings.py) without a build: the commands that
make a key's polygon, the corpus folders, the pieces' text, and the keys table's drawing fields. The
drawings made by a real build are tested in analysis/integration_sweep.py."""

import json
import os
import tempfile
import unittest

from polydecomp_analysis import drawings, report
from polydecomp_analysis.results import Run


def run(name, curves=("vs-n r=default",), status="ok", pieces=3):
    return Run({"name": name, "status": status, "pieces": pieces, "cpu_time": 1.0, "time_unit": "us",
                "curves": list(curves)})


class Commands(unittest.TestCase):
    def test_a_default_r_key_is_made_without_reflex_and_others_with_it(self):
        self.assertEqual(drawings.generate_arguments(run("monotone/star/n:20/r:7/seed:3")),
                         ["--family", "star", "--n", "20", "--seed", "3", "--format", "wkt"])
        self.assertEqual(drawings.generate_arguments(run("keil/comb/n:64/r:16/seed:1", ["vs-r n=64"])),
                         ["--family", "comb", "--n", "64", "--reflex", "16", "--seed", "1", "--format", "wkt"])
        self.assertEqual(drawings.generate_arguments(run("keil/comb-holes/n:40/r:30/h:2/seed:1",
                                                         ["vs-n r=default h=2"])),
                         ["--family", "comb-holes", "--n", "40", "--holes", "2", "--seed", "1", "--format", "wkt"])

    def test_a_family_with_holes_gets_its_h_even_when_it_is_0(self):
        self.assertEqual(drawings.generate_arguments(run("keil/convex-holes/n:50/r:0/h:0/seed:1", ["vs-h n=50"])),
                         ["--family", "convex-holes", "--n", "50", "--reflex", "0", "--holes", "0", "--seed", "1",
                          "--format", "wkt"])

    def test_the_commands_are_those_that_made_the_polygon_again(self):
        key = run("monotone/star/n:20/r:8/seed:3", ["vs-r n=20"])  # star refuses --reflex
        made_by = drawings.generate_arguments(key, with_reflex=False)
        self.assertNotIn("--reflex", made_by)
        drawn = {key.name: {"vertices": [0, 0, 1, 0, 0, 1], "steiner": [],
                            "pieces": drawings.encode_pieces([[0, 1, 2]]), "made_by": made_by}}
        table = report.key_table([run("ear-n2/star/n:20/r:8/seed:3", ["vs-r n=20"], status="skipped"), key], drawn, {})
        self.assertEqual(table["sources"], [("polydecomp generate " + " ".join(made_by) + " -o polygon.wkt",
                                             "polygon.wkt")])

    def test_a_corpus_key_is_read_from_its_folder_in_the_sweeps_file(self):
        with tempfile.TemporaryDirectory() as root:
            sweeps = os.path.join(root, "harness", "sweeps.json")
            os.makedirs(os.path.dirname(sweeps))
            with open(sweeps, "w", encoding="utf-8") as f:
                json.dump({"paper": {"curves": [{"vs": "n", "families": ["dir:../corpora/dcw"]},
                                                {"vs": "n", "families": "all"}]}}, f)
            corpora = drawings.corpus_folders({"sweeps_file": sweeps, "sweep": "paper"})
            self.assertEqual(corpora, {"dcw": os.path.join(root, "corpora", "dcw")})
            key = run("monotone/dcw/AE 1.wkt/n:10/r:1/h:0", ["vs-n nearest"])
            self.assertEqual(drawings.polygon_source(key, corpora),
                             ("", "'{}'".format(os.path.join(root, "corpora", "dcw", "AE 1.wkt"))))
        self.assertEqual(drawings.corpus_folders({"sweeps_file": "/no/such/file", "sweep": "paper"}), {})
        self.assertEqual(drawings.polygon_source(key, {}), ("", "'dcw/AE 1.wkt'"))

    def test_the_pieces_text_reads_back_with_indices_past_one_character(self):
        base = len(drawings.ALPHABET)
        pieces = [[0, 1, 2], [base - 1, base, 3 * base + 7, 5], list(range(base + 2))]
        text = drawings.encode_pieces(pieces)
        self.assertEqual(drawings.decode_pieces(text), pieces)
        self.assertEqual(len(drawings.encode_pieces([[0, 1, 2]])), 4)
        self.assertFalse(set(text) & set("\"\\<>&'"))
        with self.assertRaises(ValueError):
            drawings.encode_pieces([[0, 1, base * base]])


class KeyTable(unittest.TestCase):
    def test_rows_point_at_their_drawing_or_why_none(self):
        runs = [run("a/comb/n:10/r:2/seed:1"), run("b/comb/n:10/r:2/seed:1"), run("c/comb/n:10/r:2/seed:1"),
                run("a/comb/n:1000/r:2/seed:1", status="skipped")]
        square = {"vertices": [0, 0, 1, 0, 1, 1, 0, 1], "steiner": [], "pieces": drawings.encode_pieces([[0, 1, 2, 3]])}
        drawn = {"a/comb/n:10/r:2/seed:1": square, "b/comb/n:10/r:2/seed:1": dict(square, steiner=[0.5, 0.5]),
                 "c/comb/n:10/r:2/seed:1": "not drawn: unknown algorithm"}
        table = report.key_table(runs, drawn, {})
        self.assertEqual([row[7] for row in table["rows"]], [0, 1, -1, None])
        self.assertEqual(table["shapes"], [square["vertices"]])  # one polygon, held once
        self.assertEqual(table["drawings"][1], [0, [0.5, 0.5], square["pieces"]])
        self.assertEqual(table["notes"], ["not drawn: unknown algorithm"])
        self.assertEqual(table["sources"][0][0], "polydecomp generate --family comb --n 10 --seed 1 --format wkt "
                                                 "-o polygon.wkt")


if __name__ == "__main__":
    unittest.main()
