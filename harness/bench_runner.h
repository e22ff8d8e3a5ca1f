// Runs a sweep's keys as Google Benchmark benchmarks and journals each one as it finishes.
//
// One key is one algorithm on one polygon. Its benchmark function builds the polygon (once: keys come
// polygon by polygon, and the last polygon is cached), asks the budget whether to run, times only
// Algorithm::run in the benchmark loop, then validates the result exactly once, outside the timing,
// and attaches the counters: n, r, pieces, steiner, lower_bound (ceil(r/2)+1), valid, and the
// algorithm's own operation counts as "op_<name>". An exception is SkipWithError("failed: ..."); a
// key the budget refuses is SkipWithError("skipped (ceiling|budget): ..."); an invalid result is a
// normal run with valid = 0 and the validator's reason as its label.
//
// A watchdog thread stops a key that runs longer than the sweep's timeout: it journals the key as
// "skipped (timeout)" and ends the process with kTimeoutExit, so that the sweep can be run again and
// resume after it (analysis/sweep.py does so).
#pragma once

#include "core/registry.h"
#include "harness/budget.h"
#include "harness/journal.h"
#include "harness/progress.h"
#include "harness/sweep.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace pd {

constexpr int kTimeoutExit = 75;  // EX_TEMPFAIL: a key timed out and was journaled; run again

struct SweepKey {
  std::size_t index;  // position in the whole sweep's key list (unsharded), for ordering merged shards
  const Algorithm* algorithm;
  const SweepPolygon* polygon;
  std::string name;
};

class SweepRunner {
 public:
  using Context = std::vector<std::pair<std::string, std::string>>;

  SweepRunner(const Sweep& sweep, Journal& journal, Progress& progress, Context context);
  ~SweepRunner();

  // A key finished by an earlier invocation: teaches the budget what it cost.
  void remember(const SweepKey& key, const JournalRecord& record);
  // Registers the key with Google Benchmark; `key` must outlive the run.
  void register_key(const SweepKey& key);

  // Called by the reporter.
  void write_context(const benchmark::BenchmarkReporter::Context& context);
  void finish(const benchmark::BenchmarkReporter::Run& run);

 private:
  struct Current {
    const SweepKey* key = nullptr;  // the running key, or nullptr
    std::chrono::steady_clock::time_point since;
    bool checked = false;  // validated already (Google Benchmark calls a key's function repeatedly)
    bool valid = false;
    std::string reason;
    std::size_t pieces = 0, steiner = 0;
    Counters ops;  // of the checked call
  };
  struct CachedPolygon {
    std::string id;
    std::optional<Polygon> polygon;
    std::size_t reflex = 0;
    std::string error;
  };

  void run_key(benchmark::State& state, const SweepKey& key);
  const CachedPolygon& polygon_for(const SweepPolygon& p);
  void begin(const SweepKey& key);
  void check(const Polygon& p, const Decomposition& d, const Algorithm& a);
  void set_counters(benchmark::State& state, const CachedPolygon& p) const;
  void learn(const SweepKey& key, const std::string& status, const std::string& error_message, double seconds);
  void watch();

  const Sweep& sweep_;
  Journal& journal_;
  Progress& progress_;
  Context context_;
  Budget budget_;
  std::map<std::string, const SweepKey*> registered_;  // by name
  CachedPolygon cache_;

  std::mutex mutex_;  // guards current_, the journal and the progress line (the watchdog uses them)
  Current current_;
  bool stopping_ = false;
  std::condition_variable wake_;
  std::thread watchdog_;
};

// Passes Google Benchmark's reports to the runner; prints nothing (the progress line does).
class JournalReporter : public benchmark::BenchmarkReporter {
 public:
  explicit JournalReporter(SweepRunner& runner) : runner_(runner) {}
  bool ReportContext(const Context& context) override;
  void ReportRuns(const std::vector<Run>& runs) override;

 private:
  SweepRunner& runner_;
};

}  // namespace pd
