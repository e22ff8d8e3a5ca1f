// polydecomp-bench: runs a named sweep (harness/sweeps.json, or --sweep-file) as Google Benchmark
// benchmarks, one per key "algorithm/family/n:N/r:R[/h:H]/seed:S" or, for a corpus's file,
// "algorithm/CORPUS/FILE/n:N/r:R/h:H", and journals every finished key to
// DIR/SWEEP[.shard-I-of-K].journal.jsonl. Keys already in the journal are not run again, so an
// interrupted sweep resumes where it stopped. analysis/sweep.py drives it and assembles the JSON and
// CSV results.
//
// Exit status: 0 the sweep (or shard) is complete; 2 bad usage; kTimeoutExit (75) a key hit the
// timeout, was journaled as skipped, and the sweep should be run again to go on.
#include "harness/bench_runner.h"
#include "core/json.h"
#include "harness/large_stack.h"
#include "harness/plugins.h"
#include "harness/provenance.h"

#include <benchmark/benchmark.h>
#include <boost/program_options.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <regex>
#include <string>
#include <vector>

namespace po = boost::program_options;

namespace pd {
namespace {

struct Options {
  std::string sweep = "quick";
  std::string sweeps_file = default_sweeps_file();
  std::string out = "results";
  Shard shard;
  std::vector<std::string> plugins;         // folders of external algorithms' manifests
  std::vector<std::string> benchmark_args;  // everything else, for Google Benchmark
};

const char* kUsage = "usage: polydecomp-bench [options] [--benchmark_*=...]\n";

po::options_description option_descriptions(Options& o, std::string& shard) {
  po::options_description opts("Options (other --benchmark_* flags go to Google Benchmark; a filter selects keys by name)");
  opts.add_options()("help,h", "this help")(
      "sweep", po::value(&o.sweep)->default_value(o.sweep), "a sweep defined in the sweeps file")(
      "sweep-file", po::value(&o.sweeps_file), "the sweeps file, a user's own (default: harness/sweeps.json)")(
      "sweeps", po::value(&o.sweeps_file), "the same as --sweep-file")(
      "out", po::value(&o.out)->default_value(o.out), "where the journal goes")(
      "shard", po::value(&shard), "I/K: run shard I of K, every K-th polygon of the sweep from the I-th")(
      "plugins", po::value(&o.plugins)->composing(), "a folder of external algorithms' manifests (any number)");
  return opts;
}

Options parse_options(int argc, char** argv) {
  Options o;
  std::string shard;
  const po::options_description opts = option_descriptions(o, shard);
  po::variables_map vm;
  try {
    const po::parsed_options parsed = po::command_line_parser(argc, argv).options(opts).allow_unregistered().run();
    po::store(parsed, vm);
    po::notify(vm);
    o.benchmark_args = po::collect_unrecognized(parsed.options, po::include_positional);
  } catch (const po::error& e) {
    throw SweepError(std::string(e.what()) + "\n" + kUsage);
  }
  if (vm.count("help")) {
    std::cout << kUsage << opts;
    std::exit(0);
  }
  if (vm.count("shard")) o.shard = parse_shard(shard);
  return o;
}

// Google Benchmark's --benchmark_filter semantics: a regular expression searched in the name; a
// leading '-' selects the names that do not match.
class KeyFilter {
 public:
  explicit KeyFilter(std::string spec) {
    if (spec.empty() || spec == "all") spec = ".";
    negated_ = spec[0] == '-';
    re_ = std::regex(negated_ ? spec.substr(1) : spec, std::regex::extended);
  }
  bool selects(const std::string& name) const { return std::regex_search(name, re_) != negated_; }

 private:
  std::regex re_;
  bool negated_;
};

// Hands the remaining arguments to Google Benchmark, with the sweep's minimum time first so that an
// explicit --benchmark_min_time still wins.
// Google Benchmark keeps a pointer to argv[0] (the executable's name), so that one is the program's own.
void initialize_benchmark(const Options& o, const Sweep& sweep, char* program) {
  std::vector<std::string> args{"--benchmark_min_time=" + double_text(sweep.min_time)};
  args.insert(args.end(), o.benchmark_args.begin(), o.benchmark_args.end());
  std::vector<char*> argv{program};
  for (std::string& a : args) argv.push_back(a.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) throw SweepError("unknown arguments\n" + std::string(kUsage));
}

std::string stem(const Options& o) {
  std::string s = o.out + "/" + o.sweep;
  if (o.shard.count > 1) s += ".shard-" + std::to_string(o.shard.index) + "-of-" + std::to_string(o.shard.count);
  return s;
}

// "name=seconds, ..." (empty when every algorithm has the sweep's budget).
std::string budgets_text(const std::map<std::string, double>& budgets) {
  std::string text;
  for (const auto& [name, seconds] : budgets) text += (text.empty() ? "" : ", ") + name + "=" + double_text(seconds);
  return text;
}

SweepRunner::Context run_context(const Options& o, const Sweep& sweep) {
  SweepRunner::Context c = provenance();
  c.insert(c.end(), {{"sweep", sweep.name},
                     {"sweep_description", sweep.description},
                     {"sweeps_file", o.sweeps_file},
                     {"shard", std::to_string(o.shard.index) + "/" + std::to_string(o.shard.count)},
                     {"min_time", double_text(sweep.min_time)},
                     {"budget_seconds", double_text(sweep.budget_seconds)},
                     {"budget_seconds_for", budgets_text(sweep.budget_seconds_for)},
                     {"timeout_seconds", double_text(sweep.timeout_seconds)}});
  // Google Benchmark writes its own "date"; the journal's context carries provenance's.
  for (const auto& [key, value] : c)
    if (key != "date") benchmark::AddCustomContext(key, value);
  return c;
}

// Every key of the sweep in run order; key.index is the position in this whole list.
std::vector<SweepKey> sweep_keys(const Sweep& sweep, const std::vector<SweepPolygon>& polygons) {
  std::vector<SweepKey> keys;
  for (const SweepPolygon& p : polygons)
    for (const std::string& name : sweep.algorithms)
      keys.push_back({keys.size(), find_algorithm(name), &p, key_name(name, p)});
  return keys;
}

// The progress line while a corpus folder is read (a large one takes a while).
CorpusProgress corpus_progress(const std::string& sweep) {
  auto line = std::make_shared<std::unique_ptr<Progress>>();
  return [sweep, line](std::size_t done, std::size_t total) {
    if (!*line) *line = std::make_unique<Progress>(sweep + ": reading corpora", total, "files");
    (*line)->finished("");
    if (done == total) (*line)->end(), line->reset();
  };
}

// The files the corpora refuse, as this invocation read them, in one line (the latest line is the one
// that counts): {"refusals": [{"file": "corpus/FILE", "reason": "..."}, ...]}.
void journal_refusals(Journal& journal, const Sweep& sweep) {
  if (sweep.corpora.empty()) return;
  std::string items;
  for (const auto& [file, reason] : refused_files(sweep))
    items += (items.empty() ? "" : ", ") + std::string("{\"file\": ") + json_quote(file) + ", \"reason\": " +
             json_quote(reason) + "}";
  journal.append("{\"refusals\": [" + items + "]}");
}

int run(int argc, char** argv) {
  const Options o = parse_options(argc, argv);
  register_plugins(plugin_folders(o.plugins));
  const Sweep sweep = load_sweep(o.sweeps_file, o.sweep, corpus_progress(o.sweep));
  initialize_benchmark(o, sweep, argv[0]);
  const KeyFilter filter(benchmark::GetBenchmarkFilter());

  std::filesystem::create_directories(o.out);
  const std::string journal_path = stem(o) + ".journal.jsonl";
  const auto finished = Journal::finished(journal_path);
  Journal journal(journal_path);
  journal_refusals(journal, sweep);

  const std::vector<SweepPolygon> polygons = sweep_polygons(sweep);
  const std::vector<SweepKey> keys = sweep_keys(sweep, polygons);
  std::vector<const SweepKey*> mine, to_run;
  for (const SweepKey& key : keys) {
    const std::size_t position = key.index / sweep.algorithms.size();
    if (in_shard(position, o.shard) && filter.selects(key.name)) mine.push_back(&key);
  }
  for (const SweepKey* key : mine)
    if (!finished.count(key->name)) to_run.push_back(key);

  std::string title = sweep.name;
  if (o.shard.count > 1) title += " " + std::to_string(o.shard.index) + "/" + std::to_string(o.shard.count);
  std::fprintf(stderr, "%s: %zu keys, %zu already in %s, %zu to run\n", title.c_str(), mine.size(),
               mine.size() - to_run.size(), journal_path.c_str(), to_run.size());
  if (to_run.empty()) return 0;

  Progress progress(title, to_run.size());
  SweepRunner runner(sweep, journal, progress, run_context(o, sweep));
  for (const SweepKey* key : mine) {
    const auto done = finished.find(key->name);
    if (done != finished.end())
      runner.remember(*key, done->second);
    else
      runner.register_key(*key);
  }
  JournalReporter reporter(runner);
  benchmark::RunSpecifiedBenchmarks(&reporter);
  progress.end();
  benchmark::Shutdown();
  return 0;
}

}  // namespace
}  // namespace pd

int main(int argc, char** argv) { return pd::benchmark_main(argc, argv, pd::run); }
