import math
import unittest

from polydecomp_analysis import bound_expr, fit


def power_law(a, b, sizes, reflexes, noise=0.0):
    points = []
    for i, n in enumerate(sizes):
        for j, r in enumerate(reflexes(n)):
            jitter = 1 + noise * ((i * 7 + j * 3) % 5 - 2)
            points.append((n, r, 1e-9 * n ** a * max(r, 1) ** b * jitter))
    return points


SIZES = [100, 200, 400, 800, 1600, 3200, 6400]


class FitTest(unittest.TestCase):
    def test_t_quantiles(self):
        self.assertEqual(fit.t975(1), 12.706)
        self.assertEqual(fit.t975(30), 2.042)
        self.assertAlmostEqual(fit.t975(60), 2.000, places=2)
        self.assertAlmostEqual(fit.t975(10 ** 6), 1.960, places=3)

    def test_recovers_both_exponents_when_n_and_r_vary_independently(self):
        points = power_law(1.0, 2.0, SIZES, lambda n: [8, n // 8, n // 4])
        f = fit.fit_exponents(points)
        self.assertEqual(f.names, ["a", "b"])
        self.assertAlmostEqual(f.value("a"), 1.0, places=6)
        self.assertAlmostEqual(f.value("b"), 2.0, places=6)

    def test_fits_only_a_when_r_is_constant_or_proportional(self):
        for reflexes in (lambda n: [0], lambda n: [16], lambda n: [n // 4]):
            f = fit.fit_exponents(power_law(2.0, 0.0, SIZES, reflexes))
            self.assertEqual(f.names, ["a"])
            self.assertAlmostEqual(f.value("a"), 2.0, places=6)

    def test_a_curve_with_r_capped_is_fitted_along_itself(self):
        # Time n^4 along n with r = min(16, n/2) and three seeds (noise): one exponent, the slope along
        # the curve; a and b apart would be judged along r = n too, where the curve has no points.
        capped = power_law(4.0, 0.0, [10, 20, 50, 100], lambda n: [min(16, n // 2)] * 3, noise=0.05)
        f = fit.fit_exponents(capped, along_curve=True)
        self.assertEqual(f.names, ["a"])
        self.assertAlmostEqual(f.value("a"), 4.0, delta=0.1)
        claims = fit.term_claims(f, bound_expr.parse_time_bound("n^4"))
        self.assertTrue(fit.verdict(f, claims).startswith("consistent"))

    def test_fits_only_b_at_one_size(self):
        f = fit.fit_exponents(power_law(1.0, 3.0, [1000], lambda n: [1, 2, 4, 8, 16, 32]))
        self.assertEqual(f.names, ["b"])
        self.assertAlmostEqual(f.value("b"), 3.0, places=6)

    def test_uses_the_larger_half_of_the_sizes(self):
        points = fit.large_sizes([(n, 0, 1.0) for n in SIZES])
        self.assertEqual(sorted({p[0] for p in points}), [800, 1600, 3200, 6400])
        self.assertEqual(len(fit.large_sizes([(n, 0, 1.0) for n in (10, 20, 40)])), 3)

    def test_interval_covers_the_truth_under_noise(self):
        f = fit.fit_exponents(power_law(1.5, 0.0, SIZES, lambda n: [0], noise=0.03))
        half = f.half_width({"a": 1.0})
        self.assertGreater(half, 0)
        self.assertLess(abs(f.value("a") - 1.5), half)

    def test_too_few_points(self):
        self.assertIsNone(fit.fit_exponents([(100, 0, 1.0), (200, 0, 2.0)]))
        self.assertIsNone(fit.fit_exponents([(100, 0, 1.0)] * 5))

    def verdict(self, a, b, claim, reflexes):
        f = fit.fit_exponents(power_law(a, b, SIZES, reflexes, noise=0.01))
        return fit.verdict(f, fit.term_claims(f, bound_expr.parse_time_bound(claim)))

    def test_verdicts(self):
        self.assertEqual(self.verdict(2, 0, "n^2", lambda n: [n // 4]), "consistent")
        self.assertEqual(self.verdict(1, 0, "n*log(n)", lambda n: [0]), "consistent")
        self.assertEqual(self.verdict(1, 0, "n^2", lambda n: [0]), "consistent (grows slower than claimed)")
        self.assertTrue(self.verdict(2.9, 0, "n^2", lambda n: [0]).startswith("CONTRADICTED: fitted a=2.90"))
        # n*r^2 measured against a claim of n*r: the excess shows along r proportional to n.
        verdict = self.verdict(1, 2, "n*r", lambda n: [8, n // 8, n // 4])
        self.assertTrue(verdict.startswith("CONTRADICTED: fitted a+b=3.00"), verdict)

    def test_a_narrow_range_is_inconclusive(self):
        f = fit.fit_exponents(power_law(4.5, 0.0, [30, 40, 50, 60, 70, 80, 90, 100], lambda n: [0]))
        text = fit.verdict(f, fit.term_claims(f, bound_expr.parse_time_bound("n^4")))
        self.assertTrue(text.startswith("inconclusive: fitted a=4.50"), text)
        self.assertIn("spanning only a factor 1.4", text)  # the larger half: 70..100

    def test_growth_in_r_bounded_by_n_is_not_a_contradiction(self):
        # t = n^1.5 r^0.5 <= n^2 since r <= n: b > 0 alone must not contradict "n^2".
        self.assertTrue(self.verdict(1.5, 0.5, "n^2", lambda n: [8, n // 8, n // 4]).startswith("consistent"))

    def test_any_term_of_a_sum_may_dominate(self):
        # t = n at r = 16 against n*r + r^5: the sum with unit constants barely grows in n there, but the
        # n*r term allows slope 1.
        self.assertEqual(self.verdict(1, 0, "n*r+r^5", lambda n: [16]), "consistent")
        self.assertTrue(self.verdict(2, 0, "n*r+r^5", lambda n: [16]).startswith("CONTRADICTED: fitted a=2.00"))
        self.assertEqual(self.verdict(1, 0, "min(n*r^2, r^4)", lambda n: [16]), "consistent")

    def test_claimed_exponents_include_log_factors(self):
        f = fit.fit_exponents(power_law(1, 0, SIZES, lambda n: [0]))
        a = fit.claimed_exponents(f, bound_expr.parse_time_bound("n*log(n)"))["a"]
        self.assertTrue(1.05 < a < 1.2, a)
        self.assertFalse(math.isnan(a))


if __name__ == "__main__":
    unittest.main()
