"""The shards of a sweep joined into one results file (analysis/merge.py is its command line).

Shard I of K of sweep S journals to RESULTS/S.shard-I-of-K.journal.jsonl. Once every shard's journal
is in RESULTS (copied back from the machines that ran them), merge_shards writes RESULTS/S.json and
S.csv as if the sweep had run on one machine: keys in sweep order, contexts merged (fields that differ
between shards, such as host and date, list every value). It refuses to merge while a shard is missing.
"""

import glob
import os
import re

from . import results


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


def merge_shards(results_dir, name):
    """Writes RESULTS_DIR/NAME.json and .csv from every shard's journal; returns (keys, shards). Raises
    ValueError as shard_journals does."""
    journals = shard_journals(results_dir, name)
    count = results.assemble(journals, os.path.join(results_dir, name),
                             {"shard": "merged from {} shards".format(len(journals))})
    return count, len(journals)
