#include "harness/bench_runner.h"

#include "core/json.h"
#include "core/validate.h"
#include "generators/family.h"

#include <cstdio>
#include <cstdlib>

namespace pd {
namespace {

// A JSON object written field by field, in order, on one line.
class JsonLine {
 public:
  JsonLine& raw(const std::string& key, const std::string& json) {
    text_ += (text_.empty() ? "{" : ", ") + json_quote(key) + ": " + json;
    return *this;
  }
  JsonLine& str(const std::string& key, const std::string& value) { return raw(key, json_quote(value)); }
  JsonLine& num(const std::string& key, double value) { return raw(key, double_text(value)); }
  std::string done() const { return text_ + "}"; }

 private:
  std::string text_;
};

std::string json_strings(const std::vector<std::string>& items) {
  std::string out = "[";
  for (const std::string& s : items) out += (out.size() > 1 ? ", " : "") + json_quote(s);
  return out + "]";
}

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

std::string status_of(const benchmark::BenchmarkReporter::Run& run) {
  if (run.error_occurred) return starts_with(run.error_message, "skipped") ? "skipped" : "failed";
  const auto valid = run.counters.find("valid");
  return valid != run.counters.end() && valid->second.value == 1 ? "ok" : "invalid";
}

// Google Benchmark's own context fields, as its JSON reporter writes them.
JsonLine benchmark_context(const benchmark::BenchmarkReporter::Context& c) {
  std::string caches = "[";
  for (const auto& cache : c.cpu_info.caches) {
    caches += (caches.size() > 1 ? ", " : "") + JsonLine()
                                                    .str("type", cache.type)
                                                    .num("level", cache.level)
                                                    .num("size", cache.size)
                                                    .num("num_sharing", cache.num_sharing)
                                                    .done();
  }
  std::string load = "[";
  for (double l : c.cpu_info.load_avg) load += (load.size() > 1 ? ", " : "") + double_text(l);
  JsonLine line;
  line.str("host_name", c.sys_info.name)
      .str("executable", benchmark::BenchmarkReporter::Context::executable_name)
      .num("num_cpus", c.cpu_info.num_cpus)
      .num("mhz_per_cpu", static_cast<long>(c.cpu_info.cycles_per_second / 1e6))
      .raw("cpu_scaling_enabled", c.cpu_info.scaling == benchmark::CPUInfo::ENABLED ? "true" : "false")
      .raw("caches", caches + "]")
      .raw("load_avg", load + "]");
  return line;
}

// The budget predicts a key from the keys of its family it dominates in n and r; with holes, from
// those with as many holes; in a corpus, from any of its files.
std::string budget_family(const SweepPolygon& p) {
  return p.h && !p.file ? p.family + "/h:" + std::to_string(*p.h) : p.family;
}

// The polygon of a sweep: generated, or read from its corpus file (which the corpus accepted).
Polygon polygon_of(const SweepPolygon& p) {
  if (p.file) return read_corpus_polygon(p.file->path);
  return Polygon::make_with_holes(generate_with_holes(p.family, p.n, p.r, p.h, p.seed));
}

}  // namespace

SweepRunner::SweepRunner(const Sweep& sweep, Journal& journal, Progress& progress, Context context)
    : sweep_(sweep),
      journal_(journal),
      progress_(progress),
      context_(std::move(context)),
      budget_(sweep.budget_seconds, sweep.budget_seconds_for),
      watchdog_([this] { watch(); }) {}

SweepRunner::~SweepRunner() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  watchdog_.join();
}

void SweepRunner::remember(const SweepKey& key, const JournalRecord& record) {
  learn(key, record.status, record.error_message, record.seconds);
}

void SweepRunner::register_key(const SweepKey& key) {
  registered_[key.name] = &key;
  benchmark::internal::Benchmark* b =
      benchmark::RegisterBenchmark(key.name.c_str(), [this, &key](benchmark::State& state) { run_key(state, key); });
  // An external algorithm's time is its own report of the call, without the exchange around it.
  if (key.algorithm->times_itself) b->UseManualTime();
}

void SweepRunner::learn(const SweepKey& key, const std::string& status, const std::string& error_message,
                        double seconds) {
  const SweepPolygon& p = *key.polygon;
  if (status == "ok" || status == "invalid") budget_.record_time(*key.algorithm, budget_family(p), p.n, p.r, seconds);
  if (starts_with(error_message, "skipped (budget)") || starts_with(error_message, "skipped (timeout)"))
    budget_.record_over_budget(*key.algorithm, budget_family(p), p.n, p.r);
}

const SweepRunner::CachedPolygon& SweepRunner::polygon_for(const SweepPolygon& p) {
  if (cache_.id == p.id()) return cache_;
  cache_ = CachedPolygon{p.id(), std::nullopt, 0, ""};
  try {
    cache_.polygon = polygon_of(p);
    cache_.reflex = cache_.polygon->reflex_count();
  } catch (const std::exception& e) {
    cache_.error = std::string(p.file ? "failed: reading: " : "failed: generator: ") + e.what();
  }
  return cache_;
}

void SweepRunner::run_key(benchmark::State& state, const SweepKey& key) {
  const SweepPolygon& sp = *key.polygon;
  if (const auto why = budget_.skip_reason(*key.algorithm, budget_family(sp), sp.n, sp.r)) {
    state.SkipWithError(why->c_str());
    return;
  }
  const CachedPolygon& cached = polygon_for(sp);
  if (!cached.polygon) {
    state.SkipWithError(cached.error.c_str());
    return;
  }
  if (const auto why = refusal(*key.algorithm, *cached.polygon)) {
    state.SkipWithError(("skipped (input): " + *why).c_str());
    return;
  }
  begin(key);
  // Google Benchmark's first call of a key runs one iteration: its result is the one validated and its
  // operation counts are the ones reported, so `ops` is not cleared inside the timed loop.
  Counters ops;
  Decomposition d;
  for (auto _ : state) {
    try {
      if (key.algorithm->times_itself) {
        const auto start = std::chrono::steady_clock::now();
        d = key.algorithm->run(*cached.polygon, ops);
        const double call = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        state.SetIterationTime(d.own_seconds.value_or(call));
      } else {
        d = key.algorithm->run(*cached.polygon, ops);
      }
    } catch (const std::exception& e) {
      state.SkipWithError((std::string("failed: ") + e.what()).c_str());
      break;
    } catch (...) {
      state.SkipWithError("failed: a non-standard exception");
      break;
    }
  }
  if (state.error_occurred()) return;
  if (!current_.checked) {
    current_.ops = ops;
    check(*cached.polygon, d, *key.algorithm);
  }
  set_counters(state, cached);
  if (!current_.valid) state.SetLabel(current_.reason);
}

void SweepRunner::begin(const SweepKey& key) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (current_.key == &key) return;
  current_ = Current{};
  current_.key = &key;
  current_.since = std::chrono::steady_clock::now();
  journal_.append(JsonLine()
                      .str("started", key.name)
                      .num("key_index", static_cast<double>(key.index))
                      .raw("curves", json_strings(key.polygon->curves))
                      .done());
  progress_.started(key.name);
}

// The one exact validation of the key, on the result of its first call.
void SweepRunner::check(const Polygon& p, const Decomposition& d, const Algorithm& a) {
  current_.checked = true;
  current_.steiner = d.steiner.size();
  std::vector<Piece> pieces;
  try {
    pieces = pieces_of(p, d);
  } catch (const std::invalid_argument& e) {
    current_.valid = false;
    current_.reason = e.what();
    return;
  }
  current_.pieces = pieces.size();
  const Validation v = validate_pieces(p, d, pieces, a.kind, a.steiner);
  current_.valid = v.ok;
  current_.reason = v.reason;
}

void SweepRunner::set_counters(benchmark::State& state, const CachedPolygon& p) const {
  const double r = static_cast<double>(p.reflex);
  state.counters["n"] = static_cast<double>(p.polygon->size());
  state.counters["r"] = r;
  state.counters["pieces"] = static_cast<double>(current_.pieces);
  state.counters["steiner"] = static_cast<double>(current_.steiner);
  // ceil(r/2) + 1 - h, at least 1: every convex decomposition's (docs/holes.md).
  const std::size_t holes = p.polygon->hole_count(), bound = (p.reflex + 1) / 2 + 1;
  state.counters["lower_bound"] = static_cast<double>(bound > holes ? bound - holes : 1);
  if (holes > 0) state.counters["h"] = static_cast<double>(holes);
  state.counters["valid"] = current_.valid ? 1 : 0;
  for (const auto& [name, count] : current_.ops) state.counters["op_" + name] = static_cast<double>(count);
}

void SweepRunner::write_context(const benchmark::BenchmarkReporter::Context& c) {
  JsonLine context = benchmark_context(c);
  for (const auto& [key, value] : context_) context.str(key, value);
  std::lock_guard<std::mutex> lock(mutex_);
  journal_.append(JsonLine().raw("context", context.done()).done());
}

void SweepRunner::finish(const benchmark::BenchmarkReporter::Run& run) {
  const SweepKey& key = *registered_.at(run.run_name.function_name);
  const std::string status = status_of(run);
  const double seconds = run.iterations > 0 ? run.real_accumulated_time / static_cast<double>(run.iterations) : 0;
  learn(key, status, run.error_message, seconds);

  JsonLine line;
  line.str("name", key.name)
      .num("family_index", static_cast<double>(run.family_index))
      .num("per_family_instance_index", static_cast<double>(run.per_family_instance_index))
      .str("run_name", run.run_name.str())
      .str("run_type", "iteration")
      .num("repetitions", static_cast<double>(run.repetitions))
      .num("repetition_index", static_cast<double>(run.repetition_index))
      .num("threads", static_cast<double>(run.threads));
  if (run.error_occurred) line.raw("error_occurred", "true").str("error_message", run.error_message);
  line.num("iterations", static_cast<double>(run.iterations))
      .num("real_time", run.GetAdjustedRealTime())
      .num("cpu_time", key.algorithm->times_itself ? run.GetAdjustedRealTime() : run.GetAdjustedCPUTime())
      .str("time_unit", benchmark::GetTimeUnitString(run.time_unit));
  for (const auto& [name, counter] : run.counters) line.num(name, counter.value);
  if (!run.report_label.empty()) line.str("label", run.report_label);
  line.num("key_index", static_cast<double>(key.index)).str("status", status).raw("curves", json_strings(key.polygon->curves));

  std::lock_guard<std::mutex> lock(mutex_);
  journal_.append(line.done());
  current_ = Current{};
  progress_.finished(key.name);
}

void SweepRunner::watch() {
  const auto timeout = std::chrono::duration<double>(sweep_.timeout_seconds);
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    wake_.wait_for(lock, std::chrono::milliseconds(200));
    if (!current_.key || std::chrono::steady_clock::now() - current_.since < timeout) continue;
    const SweepKey& key = *current_.key;
    const std::string why = "skipped (timeout): still running after " + double_text(sweep_.timeout_seconds) + " s";
    journal_.append(JsonLine()
                        .str("name", key.name)
                        .str("run_name", key.name)
                        .str("run_type", "iteration")
                        .num("repetitions", 1)
                        .num("repetition_index", 0)
                        .num("threads", 1)
                        .raw("error_occurred", "true")
                        .str("error_message", why)
                        .num("iterations", 0)
                        .num("real_time", 0)
                        .num("cpu_time", 0)
                        .str("time_unit", "ns")
                        .num("key_index", static_cast<double>(key.index))
                        .str("status", "skipped")
                        .raw("curves", json_strings(key.polygon->curves))
                        .done());
    progress_.end();
    std::fprintf(stderr, "%s: %s; journaled. Run the sweep again to resume after it.\n", key.name.c_str(), why.c_str());
    std::_Exit(kTimeoutExit);
  }
}

bool JournalReporter::ReportContext(const Context& context) {
  runner_.write_context(context);
  return true;
}

void JournalReporter::ReportRuns(const std::vector<Run>& runs) {
  for (const Run& run : runs)
    if (run.run_type == Run::RT_Iteration) runner_.finish(run);
}

}  // namespace pd
