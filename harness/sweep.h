// Sweeps: named grids of (algorithm, family, n, r, seed) keys, and (algorithm, family, n, r, h, seed)
// for the families with holes, and the files of corpora (folders of polygon files, harness/corpus.h),
// read from one JSON file (harness/sweeps.json, or a user's own), and the deterministic list of keys a
// sweep (or one shard of it) runs.
//
// A sweep is a set of curves. A curve is an axis and a grid: time versus n (a list of n, one curve per
// reflex rule, and per number of holes), time versus r (a list of reflex rules, one curve per n and
// number of holes) or, for the families with holes, time versus h (a list of numbers of holes, one
// curve per n and reflex rule). A reflex rule is a number, "default" (the family's own choice for that
// n, and h) or a fraction of n written "n/8", "3*n/8"; a family whose r is an outcome of its method
// (Family::r_is_outcome) takes only "default", its r at each seed the method's. "families" is a list, "all" (every family
// without holes), "controls_r" (those that control r) or "holes" (every family with holes, whose
// curves need "h"). Points a family cannot realise (Family::infeasible) are left out of the grid, not
// reported as errors.
//
// A curve of corpora, {"vs": "n", "families": ["dir:PATH", ...]}, takes every file each folder accepts
// (curve "vs-n corpus"); with "n": [...] it takes, for each n and seed s, the file s-th nearest to n
// vertices (curve "vs-n nearest"), so that a corpus serves the n-curves. A relative PATH is read from
// the sweeps file's folder. Its keys are "algorithm/CORPUS/FILE/n:N/r:R/h:H", n, r and h the file's own;
// the files a folder refuses are listed once (refused_files), never run. A corpus may not be named
// like a generated family (their keys and budgets would mix).
//
// Keys run polygon by polygon: by family, then n, then r, then h, then seed (a corpus's: its file
// name), then algorithm. So every polygon
// is built once, and a grid point runs after every point it dominates (smaller n and smaller r), which
// is what the budget's prediction needs.
#pragma once

#include "harness/corpus.h"

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pd {

class SweepError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Sweep {
  std::string name;
  std::string description;
  std::vector<std::string> algorithms;  // in registry order
  std::vector<std::uint64_t> seeds;
  double min_time = 0;         // seconds Google Benchmark repeats each key for, at least
  double budget_seconds = 0;   // a key predicted to take longer than this (one call) is skipped
  // Budgets of single algorithms in place of budget_seconds ("budget_seconds_for": {"name": seconds}),
  // for the few whose curves need sizes past the common budget; a variant without one of its own takes
  // its base's (hertel-mehlhorn[diagonal-n4] diagonal-n4's).
  std::map<std::string, double> budget_seconds_for;
  double timeout_seconds = 0;  // a key still running after this long is stopped and recorded skipped

  struct GridPoint {
    std::size_t n;
    std::string rule;               // the reflex rule
    std::optional<std::size_t> h;   // the number of holes, for the families with holes
  };
  struct Curve {
    std::string label;  // e.g. "vs-n r=default", "vs-r n=1000", "vs-h n=1000 r=n/2", "vs-n corpus"
    std::vector<std::string> families;  // or, for a curve of corpora, their paths
    std::vector<GridPoint> points;      // for a curve of corpora, the n of "vs-n nearest" (no rule)
    bool corpora = false;
  };
  std::vector<Curve> curves;
  std::map<std::string, Corpus> corpora;  // by path, as the curves name them
};

// One polygon of a sweep: a family at (n, r), and h for a family with holes, with a seed, or a file of
// a corpus (family: the corpus's name; seed 0), and the curves it lies on.
struct SweepPolygon {
  std::string family;
  std::size_t n, r;
  std::optional<std::size_t> h;
  std::uint64_t seed;
  std::vector<std::string> curves;
  const CorpusFile* file = nullptr;

  // "family/n:N/r:R/seed:S", "family/n:N/r:R/h:H/seed:S", or "corpus/FILE/n:N/r:R/h:H".
  std::string id() const;
};

struct Shard {
  std::size_t index = 1, count = 1;  // shard `index` of `count`, 1-based
};

// harness/sweeps.json of the source tree this program was built from.
std::string default_sweeps_file();

// Reads sweep `name` from the JSON file at `path`, and the folders of its corpora (`progress` as
// read_corpus's). Throws SweepError naming the problem (unknown sweep, family or algorithm; a malformed
// rule; a corpus folder that cannot be read), listing the sweeps the file defines.
Sweep load_sweep(const std::string& path, const std::string& name, const CorpusProgress& progress = {});

// The files the sweep's corpora refuse: "corpus/FILE" and the reason, in corpus then name order.
std::vector<std::pair<std::string, std::string>> refused_files(const Sweep& sweep);

// The sweep's polygons in run order, without duplicates and without infeasible points. A corpus's
// polygons point into the sweep's corpora: they must not outlive `sweep`.
std::vector<SweepPolygon> sweep_polygons(const Sweep& sweep);

// Parses "i/k" with 1 <= i <= k; throws SweepError.
Shard parse_shard(const std::string& text);

// Whether polygon number `position` (in run order) belongs to the shard. Shards take polygons
// round-robin, so each gets a similar mix of small and large ones.
inline bool in_shard(std::size_t position, const Shard& shard) {
  return position % shard.count == shard.index - 1;
}

// The benchmark name of a key: "algorithm/" followed by the polygon's id.
std::string key_name(const std::string& algorithm, const SweepPolygon& polygon);

}  // namespace pd
