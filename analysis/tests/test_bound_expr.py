import json
import math
import os
import unittest

from polydecomp_analysis import bound_expr

# The time-bound vectors shared with the C++ BoundExpr (tests/test_bound_expr.cpp).
VECTORS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data",
                       "bound_expr_vectors.json")


def shared_vectors():
    with open(VECTORS, encoding="utf-8") as f:
        return json.load(f)


class TimeBoundTest(unittest.TestCase):
    def check(self, text, n, r, expected):
        f = bound_expr.parse_time_bound(text)
        self.assertIsNotNone(f, text)
        self.assertAlmostEqual(f(n, r), expected, places=6, msg=text)

    def test_shared_vectors(self):
        vectors = shared_vectors()
        self.assertTrue(vectors["time_bounds"] and vectors["no_claim"])
        for v in vectors["time_bounds"]:
            with self.subTest(text=v["text"], n=v["n"], r=v["r"]):
                self.check(v["text"], v["n"], v["r"], v["value"])
        for text in vectors["no_claim"]:
            with self.subTest(text=text):
                self.assertIsNone(bound_expr.parse_time_bound(text), text)

    def test_an_O_around_the_bound_is_dropped(self):
        # Python only: the C++ BoundExpr has no O(...) and gives nothing for it; the registry's time_bound
        # strings never carry one.
        self.check("O(n^2)", 10, 0, 100)


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

    def test_holes(self):
        tri = bound_expr.parse_piece_bound("== n+2*h-2")
        self.assertTrue(tri.holds(8, 10, 3))
        self.assertTrue(tri.holds(12, 10, 3, h=2))
        self.assertFalse(tri.holds(8, 10, 3, h=2))
        self.assertEqual(bound_expr.parse_piece_bound("<= r+1-h").value(10, 6, h=2), 5)

    def test_unknown_forms_are_no_claim(self):
        for text in ("n-2", "about OPT", "<= 4*OPTS", ""):
            self.assertIsNone(bound_expr.parse_piece_bound(text), text)
        self.assertTrue(math.isclose(bound_expr.parse_piece_bound("<= n").value(7, 0), 7))


if __name__ == "__main__":
    unittest.main()
