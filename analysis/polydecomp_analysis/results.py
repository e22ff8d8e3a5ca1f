"""Sweep results: the journal polydecomp-bench appends to, and the JSON and CSV assembled from it.

The journal (SWEEP[.shard-I-of-K].journal.jsonl) holds one JSON object per line: {"context": {...}}
per invocation, {"refusals": [...]} per invocation of a sweep with corpora (the files they refused),
{"started": key, ...} before each key, and one Google Benchmark run object per finished key with
"status" (ok, invalid, failed, skipped), "key_index" and "curves" added. The
assembled SWEEP.json is Google Benchmark's format, {"context": {...}, "benchmarks": [...]}, one run per
key in sweep order; SWEEP.csv has one row per key. Both are written to a temporary file and renamed,
so a reader never sees half a file.
"""

import csv
import io
import json
import os
import re

_KEY = re.compile(r"^(?P<algorithm>[^/]+)/(?P<family>[^/]+)/n:(?P<n>\d+)/r:(?P<r>\d+)(?:/h:(?P<h>\d+))?"
                  r"/seed:(?P<seed>\d+)$")
_CORPUS_KEY = re.compile(r"^(?P<algorithm>[^/]+)/(?P<family>[^/]+)/(?P<file>[^/]+)/n:(?P<n>\d+)/r:(?P<r>\d+)"
                         r"/h:(?P<h>\d+)$")
_TIME_UNITS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
_CSV_COLUMNS = ["key_index", "name", "algorithm", "family", "file", "n", "r", "h", "seed", "status", "reason",
                "iterations",
                "real_time_s", "cpu_time_s", "pieces", "steiner", "lower_bound", "valid", "curves"]


def parse_key(name):
    """{"algorithm", "family", "file", "n", "r", "h", "seed"} of a key name, or None; h is 0 for a
    family without holes (whose keys have no h:); a corpus's key (algorithm/CORPUS/FILE/n:/r:/h:) has
    the corpus as its family, its file, and seed 0; a generated key has file None."""
    m = _KEY.match(name)
    if m:
        return {"algorithm": m["algorithm"], "family": m["family"], "file": None, "n": int(m["n"]),
                "r": int(m["r"]), "h": int(m["h"] or 0), "seed": int(m["seed"])}
    m = _CORPUS_KEY.match(name)
    if m:
        return {"algorithm": m["algorithm"], "family": m["family"], "file": m["file"], "n": int(m["n"]),
                "r": int(m["r"]), "h": int(m["h"]), "seed": 0}
    return None


def read_journal(path, refused=None):
    """(contexts, runs by name, started keys without a run) of one journal, and into `refused` (a dict,
    when given) the corpus files the latest invocation refused ({"refusals": [...]} lines), by
    "corpus/FILE", with the reason. A torn line (a crash in the middle of a write) is skipped; a later
    run of a key replaces an earlier one."""
    contexts, runs, started = [], {}, {}
    with open(path, encoding="utf-8") as f:
        for line in f:
            try:
                obj = json.loads(line)
            except json.JSONDecodeError:
                continue
            if "context" in obj:
                contexts.append(obj["context"])
            elif "started" in obj:
                started[obj["started"]] = obj
            elif "refusals" in obj:
                if refused is not None:
                    refused.clear()
                    refused.update((item["file"], item["reason"]) for item in obj["refusals"])
            elif "name" in obj:
                runs[obj["name"]] = obj
    unfinished = [s for name, s in started.items() if name not in runs]
    return contexts, runs, unfinished


def append_line(path, obj):
    """Appends one object as one line, in one write, as the harness does."""
    with open(path, "a", encoding="utf-8") as f:
        f.write(json.dumps(obj) + "\n")


def crash_record(started, why):
    """The run object for a key whose process died while running it."""
    return {"name": started["started"], "run_name": started["started"], "run_type": "iteration", "repetitions": 1,
            "repetition_index": 0, "threads": 1, "error_occurred": True, "error_message": "failed: " + why,
            "iterations": 0, "real_time": 0, "cpu_time": 0, "time_unit": "ns",
            "key_index": started.get("key_index", -1), "status": "failed", "curves": started.get("curves", [])}


def merge_contexts(contexts):
    """One context from several (invocations, shards): a field with one value keeps it; string fields
    that differ are joined with " | " in order; other fields keep the last value. A context that is
    itself merged (from a journal written back by rejournal.py) brings its count of invocations and its
    list of versions."""
    merged = {}
    for context in contexts:
        for key, value in context.items():
            if key in merged and isinstance(value, str) and value not in merged[key].split(" | "):
                merged[key] += " | " + value
            elif key not in merged or not isinstance(value, str):
                merged[key] = value
    merged["invocations"] = str(sum(int(context.get("invocations", 1)) for context in contexts))
    merged["git_versions"] = " | ".join(_versions(contexts))
    return merged


def _versions(contexts):
    """Each invocation's commit, abbreviated and marked (dirty) when its tree had changes, in order and
    without repeats: merging git_commit and git_dirty separately loses which commit was dirty."""
    versions = []
    for context in contexts:
        if "git_versions" in context:
            labels = [label for label in context["git_versions"].split(" | ") if label]
        else:
            labels = [context.get("git_commit", "?")[:12] + (" (dirty)" if context.get("git_dirty") == "true" else "")]
        versions += [label for label in labels if label not in versions]
    return versions


def assemble(journal_paths, stem, extra_context=None):
    """Writes STEM.json and STEM.csv from the journals; returns the number of keys. The corpus files the
    sweep refused go into the JSON once each, as "refused": [{"file": "corpus/FILE", "reason": ...}]."""
    contexts, runs, refused = [], {}, {}
    for path in journal_paths:
        c, r, _ = read_journal(path, refused)
        contexts += c
        runs.update(r)
    context = merge_contexts(contexts)
    context.update(extra_context or {})
    ordered = sorted(runs.values(), key=lambda run: (run.get("key_index", -1), run["name"]))
    doc = {"context": context, "benchmarks": ordered}
    if refused:
        doc["refused"] = [{"file": name, "reason": why} for name, why in sorted(refused.items())]
    write_atomic(stem + ".json", json.dumps(doc, indent=1) + "\n")
    write_atomic(stem + ".csv", to_csv(ordered))
    return len(ordered)


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(text)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def seconds(run, field="real_time"):
    return run.get(field, 0) * _TIME_UNITS[run.get("time_unit", "ns")]


def reason(run):
    return run.get("error_message") or run.get("label", "")


def to_csv(runs):
    ops = sorted({k for run in runs for k in run if k.startswith("op_")})
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(_CSV_COLUMNS + ops)
    for run in runs:
        key = parse_key(run["name"]) or {}
        row = {"key_index": run.get("key_index", ""), "name": run["name"], "status": run.get("status", ""),
               "reason": reason(run), "iterations": run.get("iterations", ""),
               "real_time_s": repr(seconds(run)), "cpu_time_s": repr(seconds(run, "cpu_time")),
               "curves": ";".join(run.get("curves", []))}
        for field in ("algorithm", "family", "file", "n", "r", "h", "seed"):
            row[field] = key.get(field) if key.get(field) is not None else ""
        if key.get("file") is not None:
            row["seed"] = ""  # a corpus's key has no seed
        for field in ("n", "r", "pieces", "steiner", "lower_bound", "valid") + tuple(ops):
            if field in run:
                row[field] = _integer_text(run[field])
        writer.writerow([row.get(c, "") for c in _CSV_COLUMNS + ops])
    return out.getvalue()


def _integer_text(v):
    return str(int(v)) if float(v).is_integer() else repr(v)


class Run:
    """One key of a results file, flattened for analysis."""

    def __init__(self, obj):
        key = parse_key(obj["name"])
        self.name = obj["name"]
        self.algorithm, self.family, self.seed, self.file = key["algorithm"], key["family"], key["seed"], key["file"]
        self.n = int(obj.get("n", key["n"]))
        self.r = int(obj.get("r", key["r"]))
        self.h = int(obj.get("h", key["h"]))
        self.status = obj.get("status", "failed" if obj.get("error_occurred") else "ok")
        self.reason = reason(obj)
        # CPU time of one call: the algorithms are single-threaded, and unlike wall time it does not
        # count the time a shared machine gave to other processes.
        self.seconds = seconds(obj, "cpu_time")
        self.pieces = int(obj["pieces"]) if "pieces" in obj else None
        self.valid = obj.get("valid") == 1
        self.ops = {k[3:]: v for k, v in obj.items() if k.startswith("op_")}
        self.curves = obj.get("curves", [])

    @property
    def polygon(self):
        """The polygon's identity, shared by every algorithm run on it."""
        return (self.family, self.n, self.r, self.h, self.seed, self.file)

    @property
    def timed(self):
        return self.status in ("ok", "invalid")


def load(path, refused=None):
    """(context, [Run]) of an assembled results file, and into `refused` (a list, when given) the
    corpus files it lists as refused, [{"file": "corpus/FILE", "reason": ...}]; keys not named
    algorithm/family/n:/r:/seed: or algorithm/corpus/file/n:/r:/h: are ignored (e.g. a hand-added
    Google Benchmark entry)."""
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    if refused is not None:
        refused.extend(doc.get("refused", []))
    runs = [Run(b) for b in doc.get("benchmarks", []) if parse_key(b.get("name", ""))]
    return doc.get("context", {}), runs
