// One run of an algorithm as `polydecomp run` makes it (docs/CONTRACT.md, "polydecomp run"): the
// algorithm on each part of the polygon, its pieces, the exact validation and the report, optionally
// in a child process stopped at a deadline. The command line and the Python module (python/) both call
// it, so that a result is the same bytes whichever door it came through.
#pragma once

#include "core/polygon.h"
#include "core/registry.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pd {

// The exit statuses of docs/CONTRACT.md ("Exit status").
constexpr int kUsage = 2, kBadPolygon = 3, kAlgorithmFailed = 4, kInvalidResult = 5, kCannotWrite = 6;

// A failure: its exit status and its one-line message (without "error: ").
struct Exit {
  int status;
  std::string message;
};

struct RunOptions {
  bool json = false;                  // the `run --json` object, else the one-line report
  bool validate = true;               // the exact validation (`--no-validate` turns it off)
  bool svg = false;                   // draw the figure
  std::optional<double> max_seconds;  // run in a child process, stopped after this many seconds
  std::string memory_note;            // what an out-of-memory message adds, e.g. " (--max-memory 2G)"
  // The deadline's child closes every descriptor but its own: in a host with threads (the Python
  // module), another call's pipes must not stay open in it.
  bool close_inherited = false;
};

// The report on stdout, the SVG figure (empty without RunOptions::svg), and why the result is not valid
// (empty when it is, or when it was not validated).
struct RunOutput {
  std::string out, svg, invalid;
};

// Refuses (kBadPolygon, naming the part) a polygon the algorithm does not take.
void check_accepted(const Algorithm& algo, const std::vector<Polygon>& parts);

// Runs `algo` on each part in turn (seconds and counters are totals over the parts) and reports.
// Throws Exit (kAlgorithmFailed) when the algorithm fails, runs out of memory or misses the deadline.
RunOutput run_algorithm(const Algorithm& algo, const std::vector<Polygon>& parts, const RunOptions& options);

// " NAME=VALUE" when shown, else "": the optional fields of the one-line reports.
std::string count_text(const char* name, std::size_t value, bool shown);

}  // namespace pd
