import unittest

from polydecomp_analysis import door


def entry(name, seconds, peak=None, aggregate="median"):
    e = {"name": name + "_" + aggregate, "run_name": name, "run_type": "aggregate", "aggregate_name": aggregate,
         "cpu_time": seconds * 1e9, "real_time": seconds * 1e9, "time_unit": "ns"}
    if peak is not None:
        e["peak_bytes"] = peak
    return e


class DoorTableTest(unittest.TestCase):
    """The table takes the medians, divides each part by what its target names, and marks what is over."""

    def table(self):
        benchmarks = [entry("scan/random", 0.04), entry("read-txt/random", 0.05, 16e6),
                      entry("read-txt/random", 9.0, aggregate="mean"), entry("read-wkt/random", 0.08),
                      entry("check/random", 0.3), entry("monotone/random", 0.2),
                      entry("validate-monotone/random", 0.3), entry("seidel/random", 0.5),
                      entry("validate-seidel/random", 1.5),
                      {**entry("run-monotone/random/real_time", 0.5), "cpu_time": 1}]
        return door.door_table({"context": {"git_commit": "abc"}, "benchmarks": benchmarks})

    def test_ratios_and_marks(self):
        row = [line for line in self.table().splitlines() if line.startswith("| random")][0]
        cells = [c.strip() for c in row.strip("|").split("|")]
        self.assertEqual(cells[1], "0.040")
        self.assertEqual(cells[2], "0.050 (1.25x)")
        self.assertEqual(cells[3], "0.080 (**2.00x**)")
        self.assertEqual(cells[5], "16.0")
        self.assertEqual(cells[6], "0.300 (**1.50x**)")
        self.assertEqual(cells[7], "0.200 / 0.300 (1.50x)")
        self.assertEqual(cells[8], "0.500 / 1.500 (**3.00x**)")
        self.assertEqual(cells[9], "-")
        self.assertEqual(cells[11], "0.500 (2.50x)")
        self.assertIn("commit abc", self.table())


if __name__ == "__main__":
    unittest.main()
