#!/usr/bin/python3
"""Joins the shards of a sweep into one results file.

Shard I of K of sweep S journals to RESULTS/S.shard-I-of-K.journal.jsonl. Once every shard's journal
is in RESULTS (copied back from the machines that ran them), this writes RESULTS/S.json and S.csv as if
the sweep had run on one machine: keys in sweep order, contexts merged (fields that differ between
shards, such as host and date, list every value). It refuses to merge while a shard is missing.

usage: merge.py --sweep S [--results DIR] [--analyse [--build DIR]]
"""

import argparse
import glob
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import results  # noqa: E402
import sweep  # noqa: E402


def shard_journals(results_dir, name):
    """The shard journals of sweep `name`, in shard order; raises ValueError when shards are missing or
    the journals disagree on the number of shards."""
    pattern = re.compile(re.escape(name) + r"\.shard-(\d+)-of-(\d+)\.journal\.jsonl$")
    found = {}
    for path in glob.glob(os.path.join(results_dir, name + ".shard-*-of-*.journal.jsonl")):
        m = pattern.search(os.path.basename(path))
        if m:
            found[(int(m.group(1)), int(m.group(2)))] = path
    counts = {k for _, k in found}
    if not found:
        raise ValueError("no shard journals of sweep '{}' in {}".format(name, results_dir))
    if len(counts) != 1:
        raise ValueError("shard journals of different splits: {}".format(", ".join(sorted(
            "{}/{}".format(i, k) for i, k in found))))
    k = counts.pop()
    missing = [str(i) for i in range(1, k + 1) if (i, k) not in found]
    if missing:
        raise ValueError("missing shard(s) {} of {}".format(", ".join(missing), k))
    return [found[(i, k)] for i in range(1, k + 1)]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sweep", required=True)
    parser.add_argument("--results", default="results")
    parser.add_argument("--analyse", action="store_true", help="then write bounds.md and the plots")
    parser.add_argument("--build", default="build")
    parser.add_argument("--gallery", default="random:40:12:1")
    args = parser.parse_args(argv)
    try:
        journals = shard_journals(args.results, args.sweep)
    except ValueError as e:
        print("error: " + str(e), file=sys.stderr)
        return 1
    out = os.path.join(args.results, args.sweep)
    count = results.assemble(journals, out, {"shard": "merged from {} shards".format(len(journals))})
    print("merge: {} keys from {} shards in {}.json and {}.csv".format(count, len(journals), out, out),
          file=sys.stderr)
    if args.analyse:
        sweep.analyse(out + ".json", args.results, args.build, args.gallery)
    return 0


if __name__ == "__main__":
    sys.exit(main())
