"""polydecomp from Python: the algorithms, the generators and the exact validator (docs/python.md).

    import polydecomp
    ring = polydecomp.generate("comb", 40)
    result = polydecomp.decompose(ring, "hertel-mehlhorn")
    result.valid, len(result.pieces), result.to_shapely()

The work is done by the same code as the command line (polydecomp._core), so `decompose` returns what
`polydecomp run --json` prints, and a bad polygon raises ValueError with the CLI's `error:` message.
"""

import json
from collections import namedtuple
from fractions import Fraction
from numbers import Integral, Real

import numpy as np

from . import _core

__all__ = ["algorithms", "families", "generate", "decompose", "validate", "Decomposition", "Validation"]

Validation = namedtuple("Validation", "valid reason")
Validation.__doc__ = "The exact validator's verdict: valid (bool) and, when not valid, the reason (else None)."


def algorithms():
    """The registry, one dictionary per algorithm, with the fields of `polydecomp list --json`."""
    return json.loads(_core.algorithms_json())


def families():
    """The polygon families: name, shape, range (the feasible n, r, h), min_n, holes, r_is_outcome."""
    return _core.families()


def generate(family, n, reflex=None, seed=1, holes=None, collinear=None):
    """A polygon of `family` with n vertices, as `polydecomp generate` makes it.

    Returns an (n, 2) float64 array (the ring counter-clockwise), or, for a family with holes, a list of
    arrays: the outer ring, then the holes. Infeasible (n, r, h) raises ValueError naming the range.
    """
    rings = _core.generate(family, _count(n, "n"), _optional_count(reflex, "reflex"),
                           _optional_count(holes, "holes"), _optional_count(collinear, "collinear"),
                           _count(seed, "seed"))
    arrays = [np.frombuffer(ring, dtype=np.float64).reshape(-1, 2).copy() for ring in rings]
    with_holes = any(f["name"] == family and f["holes"] for f in families())
    return arrays if with_holes else arrays[0]


class Decomposition:
    """What `decompose` returns: the fields of `polydecomp run --json`.

    points: every point as a pair of fractions.Fraction, exact (the input vertices in input order, then
    the Steiner points); points_float: the same as an (m, 2) float64 array; pieces: each piece a
    counter-clockwise list of indices into points; valid: the exact validator's verdict (None when not
    validated) and reason when it is False; seconds: the algorithm's time alone; counters: its own
    operation counts; report: the whole `run --json` object.
    """

    def __init__(self, report, reason):
        self.report = report
        self.algorithm = report["algorithm"]
        self.n = report["n"]
        self.reflex = report["reflex"]
        self.holes = report.get("holes", 0)
        self.points = [(_fraction(x), _fraction(y)) for x, y in report["points"]]
        self.points_float = np.array([[float(x), float(y)] for x, y in self.points], dtype=np.float64).reshape(-1, 2)
        self.pieces = report["pieces"]
        self.steiner_count = report["steiner_count"]
        self.valid = report.get("valid")
        self.reason = reason or None
        self.seconds = report["seconds"]
        self.counters = report["counters"]

    def to_shapely(self):
        """The pieces as a list of shapely Polygons (float coordinates)."""
        from shapely.geometry import Polygon
        return [Polygon(self.points_float[piece]) for piece in self.pieces]

    def __repr__(self):
        return (f"Decomposition({self.algorithm}: n={self.n}, pieces={len(self.pieces)}, "
                f"steiner={self.steiner_count}, valid={self.valid})")


def decompose(polygon, algorithm, validate=True, max_seconds=None, holes=None):
    """Runs `algorithm` on `polygon`, as `polydecomp run --algorithm A --json` does.

    polygon: an (n, 2) array or a list of (x, y) pairs (with `holes`, a list of such rings), or a
    shapely Polygon or MultiPolygon. validate: check the result exactly (`valid`, `reason`).
    max_seconds: run in a child process and stop it after this many seconds (RuntimeError), as
    `--max-seconds` does. The algorithm runs without the GIL, so threads can run calls in parallel.
    """
    text, reason = _core.decompose(_parts_of(polygon, holes), str(algorithm), bool(validate),
                                   None if max_seconds is None else float(max_seconds))
    return Decomposition(json.loads(text), reason)


def validate(polygon, pieces, kind, steiner=(), holes=None):
    """The exact validator on `pieces` (lists of indices into the input vertices in input order, then
    into `steiner`, exact (x, y) pairs: ints, floats or Fractions) of one polygon: Validation(valid,
    reason). kind: "triangulation", "partition" (y-monotone pieces), "convex" or "cut".
    """
    parts = _parts_of(polygon, holes)
    if len(parts) != 1:
        raise ValueError(f"validate takes one polygon, not a multipolygon of {len(parts)} parts")
    exact = [(_rational_text(x), _rational_text(y)) for x, y in steiner]
    lists = [[_index(v) for v in piece] for piece in pieces]
    valid, reason = _core.validate(parts[0], lists, str(kind), exact)
    return Validation(valid, reason or None)


def _fraction(coordinate):
    """A `run --json` coordinate, exact: a JSON number is exactly a double, a string is "p/q"."""
    return Fraction(coordinate)


def _rational_text(value):
    exact = _exact_value(value, "a Steiner coordinate")
    if exact is None:
        raise ValueError(f"a Steiner coordinate is finite, not {value!r}")
    return str(exact.numerator), str(exact.denominator)


def _exact_value(value, what):
    """The exact rational a real number is (numpy scalars included), or None for NaN and infinities."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (Real, Fraction, np.integer, np.floating)):
        raise ValueError(f"{what} is a number, not {value!r}")
    if isinstance(value, np.integer):
        return Fraction(int(value))
    if isinstance(value, (float, np.floating)):
        return Fraction(*value.as_integer_ratio()) if np.isfinite(value) else None
    return Fraction(value)


def _index(value):
    if isinstance(value, bool) or not isinstance(value, (Integral, np.integer)) or not -2**63 <= value < 2**63:
        raise ValueError(f"a piece lists point indices (integers), not {value!r}")
    return int(value)


def _count(value, name):
    if isinstance(value, bool) or not isinstance(value, (Integral, np.integer)) or not 0 <= value < 2**64:
        raise ValueError(f"{name} takes an integer from 0 to 2^64 - 1, not {value!r}")
    return int(value)


def _optional_count(value, name):
    return None if value is None else _count(value, name)


def _parts_of(polygon, holes):
    """The polygon as parts of rings, each ring the bytes of its float64 (x, y) pairs."""
    if hasattr(polygon, "geom_type"):
        if holes is not None:
            raise ValueError("holes= goes with a ring of points; a shapely Polygon carries its own")
        return _shapely_parts(polygon)
    rings = [polygon] + list(holes or [])
    return [[_ring_bytes(ring) for ring in rings]]


def _shapely_parts(geometry):
    if geometry.geom_type == "Polygon":
        rings = [geometry.exterior] + list(geometry.interiors)
        return [[_ring_bytes(np.asarray(ring.coords)[:, :2]) for ring in rings]]  # z dropped, as WKT's
    if geometry.geom_type == "MultiPolygon":
        return [part for polygon in geometry.geoms for part in _shapely_parts(polygon)]
    raise ValueError(f"a shapely {geometry.geom_type} is not a polygon; decompose takes Polygon or MultiPolygon")


def _ring_bytes(ring):
    """A ring's float64 pairs; refuses what is not exactly a pair of real numbers per vertex."""
    if isinstance(ring, np.ndarray):
        array = _array_of_doubles(ring)
    else:
        array = np.array([_vertex(v) for v in ring], dtype=np.float64).reshape(-1, 2)
    return np.ascontiguousarray(array, dtype=np.float64).tobytes()


def _array_of_doubles(array):
    if array.ndim != 2 or array.shape[1] != 2:
        raise ValueError(f"a ring is an array of (x, y) pairs; this one has shape {array.shape}")
    if array.dtype.kind == "f":
        as_double = array.astype(np.float64)
        inexact = np.nonzero((as_double.astype(array.dtype) != array).any(axis=1))[0]
        if inexact.size:  # a long double no double equals
            raise ValueError(f"vertex {inexact[0]}: {array[inexact[0]].tolist()} is not exactly a pair of doubles")
        return as_double
    if array.dtype.kind in "iu":
        as_double = array.astype(np.float64)
        inexact = np.nonzero((as_double.astype(array.dtype) != array).any(axis=1))[0]
        if inexact.size:
            raise ValueError(f"vertex {inexact[0]}: {array[inexact[0]].tolist()} is not exactly a pair of doubles")
        return as_double
    if array.dtype.kind == "O":
        return np.array([_vertex(v) for v in array], dtype=np.float64).reshape(-1, 2)
    raise ValueError(f"a ring's coordinates are numbers, not {array.dtype}")


def _vertex(vertex):
    try:
        x, y = vertex
    except (TypeError, ValueError):
        raise ValueError(f"a vertex is an (x, y) pair, not {vertex!r}") from None
    return _exact_double(x), _exact_double(y)


def _exact_double(value):
    """A coordinate as the double it is exactly; a number no double equals is refused, not rounded."""
    if type(value) is float:
        return value
    exact = _exact_value(value, "a coordinate")
    if exact is None:
        return float(value)  # NaN or an infinity: the checked constructor names it
    try:
        double = float(exact)
    except OverflowError:
        raise ValueError(f"coordinate {value!r} is too large for a double") from None
    if Fraction(double) != exact:
        raise ValueError(f"coordinate {value!r} is not exactly a double")
    return double
