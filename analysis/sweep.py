#!/usr/bin/python3
"""Runs a sweep end to end: polydecomp-bench until the sweep (or shard) is complete, then the results
files, then (for a whole sweep) the bounds table and the plots.

polydecomp-bench journals every key it finishes and resumes after the keys already journaled. This
driver keeps it going when a key ends the process:
  - exit status 75: a key hit the sweep's timeout and was journaled as skipped; run again;
  - killed by a signal other than an interrupt (a crash, the OOM killer): the key it was running is
    journaled as failed, with the signal, and the sweep runs again.
An interrupt (Ctrl-C, SIGTERM) stops the driver; run the same command again to resume.

usage: sweep.py --sweep NAME [--shard I/K] [--build DIR] [--results DIR] [--no-analysis]
                [-- extra polydecomp-bench arguments]
"""

import argparse
import os
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bounds  # noqa: E402
import plots  # noqa: E402
import results  # noqa: E402

TIMEOUT_EXIT = 75
USAGE_EXIT = 2
INTERRUPTS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


def stem(args):
    s = os.path.join(args.results, args.sweep)
    if args.shard:
        i, k = args.shard.split("/")
        s += ".shard-{}-of-{}".format(i, k)
    return s


def bench_command(args):
    command = [os.path.join(args.build, "polydecomp-bench"), "--sweep", args.sweep, "--out", args.results]
    if args.sweeps:
        command += ["--sweeps", args.sweeps]
    if args.shard:
        command += ["--shard", args.shard]
    return command + args.bench_args


def journal_crash(journal, status):
    """Journals the key a dead process was running as failed; False when there was none."""
    _, _, unfinished = results.read_journal(journal)
    if not unfinished:
        return False
    why = "polydecomp-bench died ({}) while running this key".format(
        signal.Signals(-status).name if status < 0 else "exit status {}".format(status))
    for started in unfinished:
        results.append_line(journal, results.crash_record(started, why))
        print("sweep: {}: {}".format(started["started"], why), file=sys.stderr)
    return True


def run_until_complete(args):
    """Runs the benchmark until it reports the sweep complete; returns a process exit status."""
    journal = stem(args) + ".journal.jsonl"
    while True:
        status = subprocess.call(bench_command(args))
        if status == 0:
            return 0
        if status == TIMEOUT_EXIT:
            continue
        if status == USAGE_EXIT or (status < 0 and -status in INTERRUPTS):
            return status if status > 0 else 128 - status
        if not journal_crash(journal, status):
            print("sweep: polydecomp-bench failed (status {}) outside any key".format(status), file=sys.stderr)
            return 1


def analyse(results_file, results_dir, build, gallery):
    """Writes RESULTS_DIR/bounds.md and the figures in RESULTS_DIR/plots from one results file."""
    polydecomp = os.path.join(build, "polydecomp")
    registry = bounds.load_registry(polydecomp)
    bounds_file = os.path.join(results_dir, "bounds.md")
    bounds.write_bounds(results_file, registry, bounds_file)
    plots_dir = os.path.join(results_dir, "plots")
    made = plots.make_plots(results_file, registry, plots_dir, polydecomp, gallery)
    print("sweep: wrote {} and {} figures in {}".format(bounds_file, len(made), plots_dir), file=sys.stderr)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sweep", required=True, help="a sweep of harness/sweeps.json, e.g. quick or paper")
    parser.add_argument("--sweeps", help="another sweeps file")
    parser.add_argument("--shard", help="I/K: run shard I of K (merge the shards with analysis/merge.py)")
    parser.add_argument("--build", default="build")
    parser.add_argument("--results", default="results")
    parser.add_argument("--gallery", default="random:40:12:1", help="FAMILY:N:R:SEED of the gallery polygon")
    parser.add_argument("--no-analysis", action="store_true", help="only run the sweep and write JSON and CSV")
    parser.add_argument("bench_args", nargs="*", help="after --: more polydecomp-bench arguments")
    args = parser.parse_args(argv)

    start = time.monotonic()
    try:
        status = run_until_complete(args)
    except KeyboardInterrupt:
        status = 130
    journal = stem(args) + ".journal.jsonl"
    if os.path.exists(journal):
        count = results.assemble([journal], stem(args))
        print("sweep: {} keys in {}.json and {}.csv".format(count, stem(args), stem(args)), file=sys.stderr)
    if status != 0:
        print("sweep: stopped; run the same command again to resume", file=sys.stderr)
        return status
    if not args.shard and not args.no_analysis:
        analyse(stem(args) + ".json", args.results, args.build, args.gallery)
    print("sweep: {} done in {:.0f} s".format(args.sweep, time.monotonic() - start), file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
