"""Fitting measured growth against claimed bounds.

A fit is ordinary least squares of log y = c + a log n + b log r over the points of one algorithm on
one family, with 95% confidence intervals from Student's t. Only the larger half of the sizes is used
(at least three distinct n), because small inputs measure constant overheads, not growth. Which
exponents are fitted depends on what the points vary:
  - n and r both vary, independently: a and b, on the points with r > 0 (log 0 has no meaning);
  - r is constant, zero, or proportional to n (a sweep along n at r = n/4): a alone, on all points;
  - n is constant (a sweep along r only): b alone, on the points with r > 0.

The claim is fitted on the same points (log f(n, r) in place of log y), term by term (the terms of a
sum, of a min or of a max), which gives the exponents each term predicts there, log factors included;
the fastest term along a direction is what the claim allows. An upper bound O(f) is contradicted when y/f grows
along a direction in which inputs can grow without limit: n at fixed r (a), and n and r together, r
proportional to n (a+b). Growing more slowly than claimed is consistent: the claim is an upper bound.
bounds.py applies the verdict to each curve of a sweep separately, where the data lie along one such
direction.
"""

import math

import numpy as np

TOLERANCE = 0.15  # exponent excess tolerated beyond the confidence interval (cache and memory effects)
MIN_SPAN = 4.0  # a contradiction needs the fitted sizes to span at least this factor (see verdict)
SLOWER_MARGIN = 0.5  # an exponent this far under the claim is reported as "grows slower than claimed"

# Two-sided 95% quantiles of Student's t for 1..30 degrees of freedom.
_T975 = [12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160, 2.145,
         2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048,
         2.045, 2.042]


def t975(dof):
    """The 97.5% quantile of Student's t (exact table to 30, Cornish-Fisher expansion beyond)."""
    if dof <= 0:
        return math.inf
    if dof <= len(_T975):
        return _T975[dof - 1]
    z = 1.959964
    return z + (z ** 3 + z) / (4 * dof) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * dof ** 2)


class Fit:
    """Exponents named "a" (of n) and/or "b" (of r) with 95% half-widths, on a chosen set of points."""

    def __init__(self, names, points, coef, cov, dof):
        self.names = names
        self.points = points  # (n, r, y)
        self._coef = coef  # intercept first
        self._cov = cov
        self.dof = dof

    def value(self, name):
        return self._coef[1 + self.names.index(name)]

    def half_width(self, weights):
        """95% half-width of the combination sum(weights[name] * exponent)."""
        w = np.array([0.0] + [weights.get(name, 0.0) for name in self.names])
        return t975(self.dof) * math.sqrt(max(0.0, float(w @ self._cov @ w)))

    def combination(self, weights):
        return sum(weights.get(name, 0.0) * self.value(name) for name in self.names)


def _columns(names, points):
    cols = [[1.0] * len(points)]
    if "a" in names:
        cols.append([math.log(p[0]) for p in points])
    if "b" in names:
        cols.append([math.log(p[1]) for p in points])
    return np.array(cols).T


def _regress(names, points, ys):
    x = _columns(names, points)
    coef, _, rank, _ = np.linalg.lstsq(x, np.log(ys), rcond=None)
    dof = len(points) - x.shape[1]
    if rank < x.shape[1]:
        return None
    residual = np.log(ys) - x @ coef
    s2 = float(residual @ residual) / dof if dof > 0 else math.inf
    return coef, s2 * np.linalg.inv(x.T @ x), dof


def large_sizes(points):
    """The points at the larger half of the distinct sizes n (at least three sizes when there are)."""
    sizes = sorted({p[0] for p in points})
    keep = max(3, math.ceil(len(sizes) / 2))
    cutoff = sizes[-keep] if len(sizes) >= keep else sizes[0]
    return [p for p in points if p[0] >= cutoff]


def _varies(values):
    return len(set(values)) >= 2


def _independent(points):
    """Whether log n and log r are not (nearly) proportional over the points."""
    ln = np.log([p[0] for p in points])
    lr = np.log([p[1] for p in points])
    if np.std(ln) == 0 or np.std(lr) == 0:
        return False
    return abs(np.corrcoef(ln, lr)[0, 1]) < 0.99


def design(points):
    """(names, points) for the exponents these points can tell apart; names is empty when none."""
    points = [p for p in points if p[2] > 0]
    with_r = [p for p in points if p[1] > 0]
    if len(with_r) >= 4 and _varies([p[0] for p in with_r]) and _independent(with_r):
        return ["a", "b"], with_r
    if _varies([p[0] for p in points]):
        return ["a"], points
    if _varies([p[1] for p in with_r]):
        return ["b"], with_r
    return [], points


def design_along_curve(points):
    """(names, points) for one curve of a sweep, whose points lie along a single direction: the exponent
    of n when n varies (at a fixed r, or with r any function of n; the claim is fitted on the same
    points, so both are slopes along the curve), else that of r. Splitting a curve's growth into a and
    b would extrapolate off the curve: along n with r = min(16, n/2), a + b is no slope it has."""
    points = [p for p in points if p[2] > 0]
    if _varies([p[0] for p in points]):
        return ["a"], points
    with_r = [p for p in points if p[1] > 0]
    if _varies([p[1] for p in with_r]):
        return ["b"], with_r
    return [], points


def fit_exponents(points, along_curve=False):
    """The Fit of log y on the larger sizes of points [(n, r, y)], or None when too few points can
    tell the exponents apart (two more points than exponents, so the interval has a meaning). With
    along_curve, the points are one curve of a sweep (design_along_curve)."""
    points = [p for p in points if p[2] > 0]
    if not points:
        return None
    chosen_names, chosen = (design_along_curve if along_curve else design)(large_sizes(points))
    if not chosen_names or len(chosen) < len(chosen_names) + 2:
        return None
    result = _regress(chosen_names, chosen, [p[2] for p in chosen])
    if result is None:
        return None
    coef, cov, dof = result
    return Fit(chosen_names, chosen, coef, cov, dof)


def claimed_exponents(fit, bound):
    """The claim's exponents on the fit's own points: {"a": .., "b": ..}."""
    result = _regress(fit.names, fit.points, [bound(p[0], p[1]) for p in fit.points])
    coef = result[0]
    return {name: float(coef[1 + i]) for i, name in enumerate(fit.names)}


def term_claims(fit, bound):
    """The exponents of each additive term of the claim (bound.terms()) on the fit's points. The
    constants of an O() bound are unknown, so any term may be the one that dominates the measured
    range: growth is an excess only beyond the fastest term along the direction looked at. Fitting the
    sum with unit constants instead would make n*r + r^5 claim almost no growth in n at r = 16."""
    return [claimed_exponents(fit, term) for term in bound.terms()]


def claim_along(claims, weights):
    """The fastest growth any term allows along a direction."""
    return max(sum(weights[k] * c[k] for k in weights) for c in claims)


def directions(names):
    """The directions of unbounded growth the fit can see, as weights on its exponents."""
    if names == ["a", "b"]:
        return [("a", {"a": 1.0}), ("a+b", {"a": 1.0, "b": 1.0})]
    return [(names[0], {names[0]: 1.0})]


def span(fit):
    """The factor between the largest and smallest size the fit varies: n, or r for a fit along r."""
    sizes = [p[1] if fit.names == ["b"] else p[0] for p in fit.points]
    return max(sizes) / min(sizes)


def verdict(fit, claims):
    """"consistent", "consistent (grows slower than claimed)", "CONTRADICTED: fitted a=2.90 ± 0.10
    vs claimed 2.00", or "inconclusive: ..." when the growth is over the claim but the sizes span less
    than MIN_SPAN: an O() bound is asymptotic, and lower-order terms (an exact count such as (n-3)^4)
    or a bound not yet tight at small sizes make the local slope steeper than the claim's over a
    narrow range."""
    slower = True
    for label, weights in directions(fit.names):
        measured = fit.combination(weights)
        claim = claim_along(claims, weights)
        half = fit.half_width(weights)
        if measured - claim > half + TOLERANCE:
            text = "fitted {}={:.2f} ± {:.2f} vs claimed {:.2f}".format(label, measured, half, round(claim, 2) + 0.0)
            if span(fit) < MIN_SPAN:
                return "inconclusive: {} over sizes spanning only a factor {:.1f}".format(text, span(fit))
            return "CONTRADICTED: " + text
        slower = slower and measured + half < claim - SLOWER_MARGIN
    return "consistent (grows slower than claimed)" if slower else "consistent"
