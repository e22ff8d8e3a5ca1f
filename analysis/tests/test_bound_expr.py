import math
import unittest

from polydecomp_analysis import bound_expr


class TimeBoundTest(unittest.TestCase):
    def check(self, text, n, r, expected):
        f = bound_expr.parse_time_bound(text)
        self.assertIsNotNone(f, text)
        self.assertAlmostEqual(f(n, r), expected, places=6, msg=text)

    def test_registry_forms(self):
        self.check("n^4", 10, 3, 1e4)
        self.check("n^2", 1000, 0, 1e6)
        self.check("n*log(n)", 1024, 0, 1024 * 10)
        self.check("n*r^2", 100, 10, 1e4)
        self.check("n*r^2*log(r)", 100, 16, 100 * 256 * 4)
        self.check("n+r^3", 100, 10, 1100)
        self.check("n+r^5*log(n/r)", 64, 2, 64 + 32 * 5)
        self.check("n+min(n*r^2,r^4)", 100, 20, 100 + min(100 * 400, 20 ** 4))
        self.check("n*log*(n)", 65536, 0, 65536 * 4)
        self.check("n*log^2(n)", 1024, 0, 1024 * 100)
        self.check("O(n^2)", 10, 0, 100)

    def test_cost_mode_keeps_every_factor_at_least_one(self):
        self.check("n*r^2", 100, 0, 100)  # a convex polygon still costs n, not 0
        self.check("n*log(n)", 1, 0, 2)
        self.check("n+r^5*log(n/r)", 8, 8, 8 + 8 ** 5)

    def test_unknown_forms_are_no_claim(self):
        for text in ("n log n", "expected n", "", "n^", "log n", "m*n", "n*log*n", "min()"):
            self.assertIsNone(bound_expr.parse_time_bound(text), text)


class PieceBoundTest(unittest.TestCase):
    def test_relations(self):
        tri = bound_expr.parse_piece_bound("== n-2")
        self.assertTrue(tri.holds(8, 10, 3))
        self.assertFalse(tri.holds(9, 10, 3))
        approx = bound_expr.parse_piece_bound("<= 4*OPT")
        self.assertTrue(approx.uses_opt)
        self.assertTrue(approx.holds(20, 50, 9, 5))
        self.assertFalse(approx.holds(21, 50, 9, 5))
        lower = bound_expr.parse_piece_bound(">= ceil(r/2)+1")
        self.assertFalse(lower.uses_opt)
        self.assertEqual(lower.value(50, 7), 5)
        self.assertTrue(lower.holds(5, 50, 7))
        self.assertFalse(lower.holds(4, 50, 7))
        strict = bound_expr.parse_piece_bound("< 4.333*OPT")
        self.assertTrue(strict.holds(12, 0, 0, 3))
        self.assertFalse(strict.holds(13, 0, 0, 3))
        self.assertEqual(bound_expr.parse_piece_bound("== r+1").value(10, 4), 5)

    def test_unknown_forms_are_no_claim(self):
        for text in ("n-2", "about OPT", "<= 4*OPTS", ""):
            self.assertIsNone(bound_expr.parse_piece_bound(text), text)
        self.assertTrue(math.isclose(bound_expr.parse_piece_bound("<= n").value(7, 0), 7))


if __name__ == "__main__":
    unittest.main()
