import json
import os
import subprocess
import sys
import tempfile
import unittest

from . import synthetic

ANALYSIS = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SCRIPTS = ("bounds.py", "door.py", "integration_sweep.py", "merge.py", "plots.py", "rejournal.py", "sweep.py")


def run_script(name, *args):
    """Runs analysis/NAME as a script, python3 analysis/NAME ARGS, from another directory: the package is
    found beside the script, not in the working directory."""
    return subprocess.run([sys.executable, os.path.join(ANALYSIS, name), *args], cwd=tempfile.gettempdir(),
                          capture_output=True, text=True, check=False)


class ScriptsTest(unittest.TestCase):
    """The command lines: each imports the package beside it, and reports a refusal as an error and exit
    status 1."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def test_every_script_starts(self):
        for name in SCRIPTS:
            done = run_script(name, "--help")
            self.assertEqual(done.returncode, 0, name + ": " + done.stderr)
            self.assertIn("usage:", done.stdout, name)

    def test_bounds_writes_the_tables(self):
        synthetic.write(self.path("s.json"), self.path("registry.json"))
        done = run_script("bounds.py", self.path("s.json"), "--registry", self.path("registry.json"),
                          "-o", self.path("bounds.md"))
        self.assertEqual((done.returncode, done.stdout), (0, "wrote {}\n".format(self.path("bounds.md"))), done.stderr)
        with open(self.path("bounds.md"), encoding="utf-8") as f:
            self.assertTrue(f.read().startswith("# Claimed bounds against measurements\n"))

    def test_bounds_refuses_a_registry_without_peer_fields(self):
        synthetic.write(self.path("s.json"), self.path("registry.json"))
        with open(self.path("registry.json"), "w", encoding="utf-8") as f:
            json.dump([{k: v for k, v in a.items() if k != "peer"} for a in synthetic.REGISTRY], f)
        done = run_script("bounds.py", self.path("s.json"), "--registry", self.path("registry.json"),
                          "-o", self.path("bounds.md"))
        self.assertEqual(done.returncode, 1)
        self.assertTrue(done.stderr.startswith("error: the registry "), done.stderr)
        self.assertFalse(os.path.exists(self.path("bounds.md")))

    def test_door_refuses_a_missing_file(self):
        done = run_script("door.py", "--json", self.path("none.json"), "--out", self.path("door.md"))
        self.assertEqual(done.returncode, 1)
        self.assertTrue(done.stderr.startswith("error: " + self.path("none.json")), done.stderr)
        self.assertFalse(os.path.exists(self.path("door.md")))

    def test_merge_refuses_a_missing_shard(self):
        with open(self.path("s.shard-1-of-2.journal.jsonl"), "w", encoding="utf-8"):
            pass
        done = run_script("merge.py", "--sweep", "s", "--results", self.tmp.name)
        self.assertEqual((done.returncode, done.stderr), (1, "error: missing shard(s) 2 of 2\n"))

    def test_rejournal_refuses_to_replace_a_journal(self):
        with open(self.path("s.journal.jsonl"), "w", encoding="utf-8"):
            pass
        done = run_script("rejournal.py", "--sweep", "s", "--results", self.tmp.name)
        self.assertEqual(done.returncode, 1)
        self.assertTrue(done.stderr.startswith("error: ") and "exists" in done.stderr, done.stderr)


if __name__ == "__main__":
    unittest.main()
