"""A sweep's journal written back from its assembled results, leaving out the keys to measure again
(analysis/rejournal.py is its command line).

The journal (RESULTS/SWEEP.journal.jsonl) is not committed; the assembled RESULTS/SWEEP.json is. On a
fresh clone, to measure some keys of the committed reference run again and keep the rest, this writes
the journal from SWEEP.json: its context (already merged from every earlier invocation) and every run
whose name the pattern `remeasure` does not match. Running the sweep again then measures just the keys
left out, and assembling merges the old context with the new invocations' contexts
(results.merge_contexts counts the invocations of both and lists their versions in order).

The journal written is the unsharded one (a sharded sweep journals per shard and is merged by
merge.py). Keys the sweep has gained since (a changed sweeps file or a new algorithm) are measured
too.
"""

import json
import os
import re

from . import results


def rejournal(results_dir, sweep, remeasure):
    """Writes the journal; returns (runs kept, runs left out). Raises ValueError when the journal
    already exists (it may hold measurements the results file lacks) or the results file is missing."""
    stem = os.path.join(results_dir, sweep)
    journal = stem + ".journal.jsonl"
    if os.path.exists(journal):
        raise ValueError("{} exists; it would be replaced (delete it first)".format(journal))
    try:
        with open(stem + ".json", encoding="utf-8") as f:
            doc = json.load(f)
    except FileNotFoundError:
        raise ValueError("no results file {}.json".format(stem)) from None
    pattern = re.compile(remeasure) if remeasure else None
    runs = doc.get("benchmarks", [])
    kept = [run for run in runs if not (pattern and pattern.search(run.get("name", "")))]
    refusals = [{"refusals": doc["refused"]}] if "refused" in doc else []
    lines = [{"context": doc.get("context", {})}] + refusals + kept
    results.write_atomic(journal, "".join(json.dumps(line) + "\n" for line in lines))
    return len(kept), len(runs) - len(kept)
