"""A small synthetic sweep for the analysis tests: results whose true growth and piece counts are known.

Algorithms (registry as `polydecomp list --json` prints it):
  quad      time 1e-9 n^2, claims "n^2"                 -> consistent
  liar      time 1e-9 n^2, claims "n*log(n)"            -> CONTRADICTED (a = 2 against about 1.1)
  nr2       time 1e-9 n r^2, claims "n*r^2"             -> consistent, a and b both fitted
  tri       n-2 triangles, claims "== n-2"              -> consistent
  approx    convex, 2r+1 pieces, claims "<= 4*OPT"      -> consistent, worst ratio (2r+1)/(r/2+1)
  opt       convex, optimal, ceil(r/2)+1 pieces, "== OPT"; invalid on one polygon
  greedy    convex, claims "== r+1" but returns r+2 on the comb family -> CONTRADICTED
Families: "random" (r = n/4, and r from 0 to n/2 at n = 400) and "comb" (r = 8).
"""

import json
import os
import sys

REGISTRY = [
    {"name": "quad", "kind": "triangulation", "steiner": False, "optimal": False, "time_bound": "n^2",
     "pieces_bound": "== n-2", "source": "synthetic", "peer": None, "size_ceiling": 100000},
    {"name": "liar", "kind": "triangulation", "steiner": False, "optimal": False, "time_bound": "n*log(n)",
     "pieces_bound": "== n-2", "source": "synthetic", "peer": None, "size_ceiling": 100000},
    {"name": "nr2", "kind": "convex", "steiner": False, "optimal": False, "time_bound": "n*r^2",
     "pieces_bound": "<= 4*OPT", "source": "synthetic", "peer": None, "size_ceiling": 100000},
    {"name": "tri", "kind": "triangulation", "steiner": False, "optimal": False, "time_bound": "n",
     "pieces_bound": "== n-2", "source": "synthetic", "peer": None, "size_ceiling": 100000},
    {"name": "approx", "kind": "convex", "steiner": False, "optimal": False, "time_bound": "n",
     "pieces_bound": "<= 4*OPT", "source": "synthetic", "peer": None, "size_ceiling": 100000},
    {"name": "opt", "kind": "convex", "steiner": False, "optimal": True, "time_bound": "n^4",
     "pieces_bound": "== OPT", "source": "synthetic", "peer": None, "size_ceiling": 400},
    {"name": "greedy", "kind": "convex", "steiner": True, "optimal": False, "time_bound": "n",
     "pieces_bound": "== r+1", "source": "synthetic", "peer": None, "size_ceiling": 100000},
]

SIZES = [100, 200, 400, 800, 1600, 3200]
SEEDS = [1, 2]
INVALID_KEY = "opt/random/n:200/r:50/seed:1"


def polygons():
    """(family, n, r, seed, curves) of the sweep, in sweep order."""
    grid = {}

    def add(family, n, r, curve):
        for seed in SEEDS:
            grid.setdefault((family, n, r, seed), []).append(curve)

    for n in SIZES:
        add("random", n, n // 4, "vs-n r=default")
        add("comb", n, 8, "vs-n r=8")
    for r in (0, 6, 12, 25, 50, 100, 200):
        add("random", 400, r, "vs-r n=400")
    return [key + (curves,) for key, curves in sorted(grid.items())]


def _seconds(name, n, r, seed):
    jitter = 1 + 0.02 * ((n * 7 + r * 3 + seed) % 5 - 2)  # deterministic noise of +-4%
    base = {"quad": n * n, "liar": n * n, "nr2": n * max(r, 1) ** 2}.get(name, n)
    return 1e-9 * base * jitter


def _pieces(name, family, n, r):
    return {"quad": n - 2, "liar": n - 2, "tri": n - 2, "nr2": 2 * r + 1, "approx": 2 * r + 1,
            "opt": (r + 1) // 2 + 1, "greedy": r + 2 if family == "comb" else r + 1}[name]


def run_object(index, algorithm, family, n, r, seed, curves):
    name = "{}/{}/n:{}/r:{}/seed:{}".format(algorithm, family, n, r, seed)
    base = {"name": name, "family_index": index, "per_family_instance_index": 0, "run_name": name,
            "run_type": "iteration", "repetitions": 1, "repetition_index": 0, "threads": 1}
    if algorithm == "opt" and n > 400:
        base.update({"error_occurred": True, "error_message": "skipped (ceiling): n={} is above the size "
                     "ceiling 400".format(n), "iterations": 0, "real_time": 0, "cpu_time": 0, "time_unit": "ns",
                     "key_index": index, "status": "skipped", "curves": curves})
        return base
    t = _seconds(algorithm, n, r, seed)
    valid = 0 if name == INVALID_KEY else 1
    base.update({"iterations": 10, "real_time": t * 1e9, "cpu_time": t * 1e9, "time_unit": "ns", "n": n, "r": r,
                 "pieces": _pieces(algorithm, family, n, r), "steiner": 0, "lower_bound": (r + 1) // 2 + 1,
                 "valid": valid, "op_steps": float(n * n if algorithm in ("quad", "liar") else n)})
    if not valid:
        base["label"] = "piece 3 is not convex at vertex 17"
    base.update({"key_index": index, "status": "ok" if valid else "invalid", "curves": curves})
    return base


def runs():
    out = []
    for family, n, r, seed, curves in polygons():
        for algo in REGISTRY:
            out.append(run_object(len(out), algo["name"], family, n, r, seed, curves))
    return out


CONTEXT = {"sweep": "synthetic", "git_commit": "0123456789abcdef", "git_dirty": "false", "cpu": "test cpu",
           "date": "2024-01-01T00:00:00Z"}


def write(results_path, registry_path):
    """Writes the results file (Google Benchmark format) and the registry file."""
    with open(results_path, "w", encoding="utf-8") as f:
        json.dump({"context": CONTEXT, "benchmarks": runs()}, f)
    with open(registry_path, "w", encoding="utf-8") as f:
        json.dump(REGISTRY, f)


def main(argv):
    """python3 analysis/tests/synthetic.py DIR writes DIR/synthetic.json and DIR/registry.json (ctest's report
    test makes its page from them)."""
    os.makedirs(argv[1], exist_ok=True)
    write(os.path.join(argv[1], "synthetic.json"), os.path.join(argv[1], "registry.json"))


if __name__ == "__main__":
    main(sys.argv)
