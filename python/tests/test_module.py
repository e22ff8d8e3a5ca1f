"""The Python module against the command line: every algorithm on every family gives what
`polydecomp run --json` prints, the generators the same polygons, bad input the same error line.

Run by ctest (`python` test) with PYTHONPATH at the build's python/ folder and POLYDECOMP_CLI naming
the build's polydecomp.
"""

import json
import math
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from fractions import Fraction

import numpy as np
import pytest
from shapely.geometry import MultiPolygon, Polygon
from shapely.ops import unary_union

import polydecomp

CLI = os.environ.get("POLYDECOMP_CLI", "polydecomp")
N, N_HOLES = 24, 40
FAMILIES = polydecomp.families()
ALGORITHMS = polydecomp.algorithms()
COMB = [[0, 0], [9, 0], [9, 5], [7, 5], [6, 1], [5, 5], [3, 5], [2, 1], [1, 5], [0, 5]]


def cli(*args, stdin=None):
    return subprocess.run([CLI, *map(str, args)], input=stdin, capture_output=True, text=True)


def polygon_file(tmp_path_factory, family, n):
    """The family's polygon as the CLI writes it, and the rings the module generates."""
    path = tmp_path_factory.mktemp("polygons") / f"{family['name']}.wkt"
    done = cli("generate", "--family", family["name"], "--n", n, "--format", "wkt", "-o", path)
    assert done.returncode == 0, done.stderr
    generated = polydecomp.generate(family["name"], n)
    rings = generated if family["holes"] else [generated]
    return path, rings


def without_seconds(report):
    return {key: value for key, value in report.items() if key != "seconds"}


@pytest.fixture(scope="module")
def polygons(tmp_path_factory):
    """The polygon of (family, n), made once."""
    made = {}

    def polygon(family, n):
        if (family["name"], n) not in made:
            made[family["name"], n] = polygon_file(tmp_path_factory, family, n)
        return made[family["name"], n]
    return polygon


@pytest.mark.parametrize("algorithm", [a["name"] for a in ALGORITHMS])
def test_every_algorithm_on_every_family_is_the_clis_result(algorithm, polygons):
    ceiling = next(a["size_ceiling"] for a in ALGORITHMS if a["name"] == algorithm)
    for family in FAMILIES:
        n = N_HOLES if family["holes"] else min(N, ceiling)  # poly-decomp-optimal's search: n <= 12
        if n < family["min_n"]:
            continue
        path, rings = polygons(family, n)
        done = cli("run", "--algorithm", algorithm, "--input", path, "--json")
        if done.returncode == 3:
            with pytest.raises(ValueError) as refused:
                polydecomp.decompose(rings[0], algorithm, holes=rings[1:])
            assert "error: " + str(refused.value) + "\n" == done.stderr
            continue
        assert done.returncode in (0, 5), (family["name"], done.stderr)  # 5: a peer's invalid result
        result = polydecomp.decompose(rings[0], algorithm, holes=rings[1:])
        assert without_seconds(result.report) == without_seconds(json.loads(done.stdout)), family["name"]
        if done.returncode == 5:
            assert "error: the result of " + algorithm + " is not valid: " + result.reason + "\n" == done.stderr
        assert result.valid is (done.returncode == 0)
        kind = next(a["kind"] for a in ALGORITHMS if a["name"] == algorithm)
        verdict = polydecomp.validate(rings[0], result.pieces, kind, result.points[result.n:], holes=rings[1:])
        assert verdict == (result.valid, result.reason), family["name"]


def test_the_registry_is_the_clis_list():
    done = cli("list", "--json")
    assert polydecomp.algorithms() == json.loads(done.stdout)


@pytest.mark.parametrize("family", FAMILIES, ids=lambda f: f["name"])
def test_generate_makes_the_clis_polygon(family):
    n = N_HOLES if family["holes"] else 100
    for seed in (1, 7):
        done = cli("generate", "--family", family["name"], "--n", n, "--seed", seed, "--format", "geojson")
        generated = polydecomp.generate(family["name"], n, seed=seed)
        rings = generated if family["holes"] else [generated]
        written = json.loads(done.stdout)["coordinates"]
        assert [ring.tolist() for ring in rings] == [ring[:-1] for ring in written]
        assert all(ring.dtype == np.float64 and ring.shape[1] == 2 for ring in rings)


def test_generate_takes_the_clis_options():
    comb = polydecomp.generate("comb", 60, reflex=10, seed=3)
    done = cli("generate", "--family", "comb", "--n", 60, "--reflex", 10, "--seed", 3, "--format", "geojson")
    assert comb.tolist() == json.loads(done.stdout)["coordinates"][0][:-1]
    collinear = polydecomp.generate("random", 50, collinear=5)
    assert len(collinear) == 50
    holes = polydecomp.generate("convex-holes", 60, holes=2)
    assert len(holes) == 3
    with pytest.raises(ValueError, match="cannot make"):
        polydecomp.generate("comb", 10, reflex=9)
    with pytest.raises(ValueError, match="unknown family"):
        polydecomp.generate("no-such-family", 10)
    with pytest.raises(ValueError, match="0 to 2\\^64"):
        polydecomp.generate("comb", -3)


def test_the_exact_rationals():
    steiner = next(a["name"] for a in ALGORITHMS if a["steiner"] and a["kind"] == "convex" and not a["peer"])
    result = polydecomp.decompose(COMB, steiner)
    added = result.points[len(COMB):]
    assert added and all(isinstance(c, Fraction) for point in result.points for c in point)
    assert any(c.denominator > 1 for point in added for c in point)
    assert np.array_equal(result.points_float, [[float(x), float(y)] for x, y in result.points])
    done = cli("run", "--algorithm", steiner, "--input", "-", "--json", stdin="\n".join(f"{x} {y}" for x, y in COMB))
    assert [[Fraction(c) for c in p] for p in json.loads(done.stdout)["points"]] == [list(p) for p in result.points]
    assert polydecomp.validate(COMB, result.pieces, "convex", added).valid
    nudged = [(x, y + Fraction(1, 10**30)) for x, y in added]  # off the boundary by 10^-30
    assert not polydecomp.validate(COMB, result.pieces, "convex", nudged).valid


def test_validate_gives_the_reason():
    result = polydecomp.decompose(COMB, "hertel-mehlhorn")
    assert polydecomp.validate(COMB, result.pieces, "convex") == (True, None)
    valid, reason = polydecomp.validate(COMB, result.pieces[1:], "convex")
    assert not valid and "vertex" in reason
    assert not polydecomp.validate(COMB, [[0, 1, 99]], "triangulation").valid
    assert not polydecomp.validate(COMB, result.pieces, "triangulation").valid
    with pytest.raises(ValueError, match="unknown kind"):
        polydecomp.validate(COMB, result.pieces, "squares")


def test_shapely_round_trips():
    outer = [(0, 0), (10, 0), (10, 10), (0, 10)]
    hole = [(3, 3), (3, 6), (6, 6), (6, 3)]
    polygon = Polygon(outer, [hole])
    result = polydecomp.decompose(polygon, "cgal-cdt")
    pieces = result.to_shapely()
    assert result.holes == 1 and math.isclose(sum(p.area for p in pieces), polygon.area)
    assert unary_union(pieces).symmetric_difference(polygon).area == 0
    with_z = Polygon([(x, y, 7.0) for x, y in COMB])
    flat = polydecomp.decompose(COMB, "monotone")
    assert without_seconds(polydecomp.decompose(with_z, "monotone").report) == without_seconds(flat.report)
    two = MultiPolygon([Polygon(outer), Polygon([(20, 0), (24, 0), (22, 3)])])
    parts = polydecomp.decompose(two, "monotone")
    assert len(parts.report["parts"]) == 2 and len(parts.pieces) == 3


def run_error(polygon_text):
    done = cli("run", "--algorithm", "monotone", "--input", "-", stdin=polygon_text)
    assert done.returncode == 3
    return done.stderr


@pytest.mark.parametrize("ring", [
    [[0, 0], [1, 1], [1, 0], [0, 1]],         # not simple
    [[0, 0], [1, 0]],                          # too few vertices
    [[0, 0], [1, 0], [2, 0]],                  # no area
    [[0, 0], [4, 0], [4, 4], [2, -1], [0, 4]],  # crossing edges
])
def test_a_bad_polygon_is_the_clis_error(ring):
    message = run_error("\n".join(f"{x} {y}" for x, y in ring))
    with pytest.raises(ValueError) as refused:
        polydecomp.decompose(ring, "monotone")
    assert "error: " + str(refused.value) + "\n" == message


@pytest.mark.parametrize("ring, words", [
    ([[0, 0], [1, "a"], [0, 1]], "not 'a'"),
    ([[0, 0], [1, 0, 3], [0, 1]], "pair"),
    ([[0, 0], [2**53 + 1, 0], [0, 1]], "not exactly a double"),
    (np.array([[0, 0], [2**53 + 1, 0], [0, 1]], dtype=np.int64), "not exactly a pair of doubles"),
    ([[0, 0], [10**400, 0], [0, 1]], "too large"),
    ([[0, 0], [float("nan"), 0], [0, 1]], "not finite"),
    ([[0, 0], [math.inf, 0], [0, 1]], "not finite"),
    (np.array([["0", "0"], ["1", "0"], ["0", "1"]]), "numbers"),
    (np.zeros((3, 3)), "shape"),
])
def test_bad_input_is_a_value_error(ring, words):
    with pytest.raises(ValueError, match=words):
        polydecomp.decompose(ring, "monotone")


def test_bad_calls_are_value_errors():
    with pytest.raises(ValueError, match="unknown algorithm"):
        polydecomp.decompose(COMB, "no-such-algorithm")
    with pytest.raises(ValueError, match="max_seconds"):
        polydecomp.decompose(COMB, "monotone", max_seconds=-1)
    with pytest.raises(ValueError, match="not a polygon"):
        polydecomp.decompose(Polygon(COMB).exterior, "monotone")
    with pytest.raises(ValueError, match="multipolygon"):
        polydecomp.validate(MultiPolygon([Polygon(COMB), Polygon([(20, 0), (24, 0), (22, 3)])]), [], "convex")


def test_threads_give_the_sequential_results():
    keys = [(f["name"], a) for f in FAMILIES if not f["holes"] for a in ("monotone", "hertel-mehlhorn", "earcut")]
    rings = {name: polydecomp.generate(name, 2000 if name != "2-opt" else 300) for name, _ in keys}
    alone = [without_seconds(polydecomp.decompose(rings[name], a).report) for name, a in keys]
    with ThreadPoolExecutor(max_workers=4) as pool:
        together = list(pool.map(lambda key: without_seconds(polydecomp.decompose(rings[key[0]], key[1]).report), keys))
    assert together == alone


def write_plugin(folder, name, body, accepts="{}"):
    (folder / f"{name}.py").write_text("import json, sys, time\nfor line in sys.stdin:\n"
                                       "    n = len(json.loads(line)['points'])\n" + body)
    (folder / f"{name}.json").write_text(json.dumps({
        "name": name, "kind": "triangulation", "accepts": json.loads(accepts),
        "command": ["/usr/bin/python3", f"{name}.py"]}))


def in_fresh_python(code, plugins):
    """Runs `code` in a new interpreter whose import of polydecomp registers the plug-ins in `plugins`."""
    environment = dict(os.environ, POLYDECOMP_PLUGINS=str(plugins))
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=environment, timeout=120)


def test_an_invalid_result_and_a_stopped_run(tmp_path):
    answer = "    print(json.dumps({'pieces': [[0, i, i + 1] for i in range(1, n - 1)], 'steiner': []}), flush=True)\n"
    write_plugin(tmp_path, "any-fan", answer)
    write_plugin(tmp_path, "sleeper", "    time.sleep(60)\n")
    ring = "\n".join(f"{x} {y}" for x, y in COMB)
    done = subprocess.run([CLI, "run", "--algorithm", "any-fan", "--input", "-", "--plugins", str(tmp_path)],
                          input=ring, capture_output=True, text=True)
    assert done.returncode == 5
    code = f"""
import polydecomp
result = polydecomp.decompose({COMB}, "any-fan")
print(result.valid)
print("error: the result of any-fan is not valid: " + result.reason)
try:
    polydecomp.decompose({COMB}, "sleeper", max_seconds=0.5)
except RuntimeError as e:
    print(e)
print(len(polydecomp.decompose({COMB}, "any-fan", max_seconds=30).pieces))
"""
    printed = in_fresh_python(code, tmp_path)
    assert printed.returncode == 0, printed.stderr
    lines = printed.stdout.splitlines()
    assert lines[0] == "False"
    assert lines[1] + "\n" == done.stderr
    assert lines[2] == "sleeper stopped after 0.5 s (--max-seconds)"
    assert lines[3] == str(len(COMB) - 2)


def test_plug_ins_from_several_threads_and_a_deadline_beside_them(tmp_path):
    write_plugin(tmp_path, "garbage", "    print('not json', flush=True)\n")
    fan = "    print(json.dumps({'pieces': [[0, i, i + 1] for i in range(1, n - 1)], 'steiner': []}), flush=True)\n"
    write_plugin(tmp_path, "slow-fan", "    time.sleep(1.5)\n" + fan)
    code = f"""
import threading, time
from concurrent.futures import ThreadPoolExecutor
import polydecomp

def garbage(_):
    try:
        polydecomp.decompose({COMB}, "garbage")
    except RuntimeError as e:
        return str(e)

with ThreadPoolExecutor(4) as pool:
    errors = set(pool.map(garbage, range(40)))
print(len(errors))
print(errors.pop())
holder = threading.Thread(target=lambda: polydecomp.decompose({COMB}, "slow-fan"))
holder.start()
time.sleep(0.3)  # the holder's call now holds slow-fan's turn, in this process
start = time.time()
result = polydecomp.decompose({COMB}, "slow-fan", max_seconds=30)  # the child starts its own slow-fan
print(len(result.pieces), time.time() - start < 15)
holder.join()
"""
    printed = in_fresh_python(code, tmp_path)
    assert printed.returncode == 0, printed.stderr
    lines = printed.stdout.splitlines()
    assert lines[0] == "1", lines  # every call fails the same way: none sees another's half-stopped command
    assert "garbage" in lines[1] and "not JSON" in lines[1], lines[1]
    assert lines[2] == f"{len(COMB) - 2} True"


def test_numbers_of_every_numpy_type_are_read_exactly_or_refused():
    ring = np.array(COMB, dtype=np.float32)
    assert polydecomp.decompose(ring, "monotone").points[:len(COMB)] == [(x, y) for x, y in COMB]
    precise = np.array(COMB, dtype=np.longdouble)
    precise[1, 0] += np.longdouble(2) ** -60
    with pytest.raises(ValueError, match="not exactly a pair of doubles"):
        polydecomp.decompose(precise, "monotone")
    scalars = [(np.int64(x), np.float32(y)) for x, y in COMB]
    assert len(polydecomp.decompose(scalars, "monotone").pieces) == len(COMB) - 2
    with pytest.raises(ValueError, match="not exactly a double"):
        polydecomp.decompose([(np.longdouble(1) + np.longdouble(2) ** -60, 0), (2, 0), (0, 1)], "monotone")
    hm = polydecomp.decompose(COMB, "hertel-mehlhorn")
    assert polydecomp.validate(COMB, hm.pieces, "convex", [(np.float32(0.5), np.int16(1))]).valid  # unused
    with pytest.raises(ValueError, match="0 to 2\\^64"):
        polydecomp.generate("comb", 2**64)
    with pytest.raises(ValueError, match="point indices"):
        polydecomp.validate(COMB, [[0, 1, 2**70]], "convex")
    assert isinstance(polydecomp.generate("convex-holes", 60, holes=0), list)
    with pytest.raises(ValueError) as unknown:
        polydecomp.decompose(COMB, "comb\n")
    assert str(unknown.value) + "\n" == cli("run", "--algorithm", "comb\n", "--input", "-").stderr[len("error: "):]
