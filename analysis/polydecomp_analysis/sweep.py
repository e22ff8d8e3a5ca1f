"""The sweep driver behind analysis/sweep.py: polydecomp-bench until the sweep (or shard) is complete,
then the bounds table, the plots and the HTML report (analyse, which analysis/merge.py also runs on a merged
sweep).

polydecomp-bench journals every key it finishes and resumes after the keys already journaled. This
driver keeps it going when a key ends the process:
  - exit status 75: a key hit the sweep's timeout and was journaled as skipped; run again;
  - killed by a signal other than an interrupt (a crash, the OOM killer): the key it was running is
    journaled as failed, with the signal, and the sweep runs again.
An interrupt (Ctrl-C, SIGTERM) stops the driver; running the same command again resumes.

The functions take the options of analysis/sweep.py's command line (sweep, sweeps, shard, build,
results, bench_args).
"""

import os
import signal
import subprocess
import sys

from . import bounds, plots, report, results

TIMEOUT_EXIT = 75
USAGE_EXIT = 2
INTERRUPTS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


def stem(args):
    """RESULTS/SWEEP, or RESULTS/SWEEP.shard-I-of-K for a shard: the path of its files without suffix."""
    s = os.path.join(args.results, args.sweep)
    if args.shard:
        i, k = args.shard.split("/")
        s += ".shard-{}-of-{}".format(i, k)
    return s


def bench_command(args):
    command = [os.path.join(args.build, "polydecomp-bench"), "--sweep", args.sweep, "--out", args.results]
    if args.sweeps:
        command += ["--sweep-file", args.sweeps]
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
    """Writes RESULTS_DIR/bounds.md, the figures in RESULTS_DIR/plots and the report RESULTS_DIR/index.html
    (which links the gallery figure, so it comes last) from one results file."""
    polydecomp = os.path.join(build, "polydecomp")
    registry = bounds.load_registry(polydecomp)
    bounds_file = os.path.join(results_dir, "bounds.md")
    bounds.write_bounds(results_file, registry, bounds_file)
    plots_dir = os.path.join(results_dir, "plots")
    made = plots.make_plots(results_file, registry, plots_dir, polydecomp, gallery)
    print("sweep: wrote {} and {} figures in {}".format(bounds_file, len(made), plots_dir), file=sys.stderr)
    page = os.path.join(results_dir, "index.html")
    size = report.write_report(results_file, registry, page, bounds_file, os.path.join(plots_dir, "gallery.png"),
                               polydecomp)
    print("sweep: wrote {} ({:.1f} MB)".format(page, size / 1e6), file=sys.stderr)
