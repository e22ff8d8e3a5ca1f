// polydecomp-door-bench: what a user waits for around an algorithm, each part on its own (issue 34).
//
// For every family at n = 10^6 (or its largest n), with Google Benchmark (CPU time of the part alone;
// `make door` takes the median of 3 repetitions; the JSON has their minimum too): the floor (a
// from_chars scan of the text file's bytes into doubles), the text, WKT and GeoJSON readers on the
// same polygon, the checked constructor (simplicity, orientation, layout of the rings), every
// O(n log n) triangulation, its exact validation, and `polydecomp run --algorithm monotone` end to end
// as a process (wall time). Each part reports `peak_bytes`, the most memory it held beyond what it was
// given (counted by this program's operator new). analysis/door.py turns the JSON into
// results/door.md.
#include "core/io.h"
#include "core/polygon.h"
#include "core/registry.h"
#include "core/validate.h"
#include "generators/family.h"
#include "harness/large_stack.h"
#include "harness/provenance.h"

#include <benchmark/benchmark.h>
#include <malloc.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace {

std::atomic<std::size_t> live_bytes{0}, peak_bytes{0};

void* counted(void* p) {
  if (p == nullptr) throw std::bad_alloc();
  const std::size_t now = live_bytes += malloc_usable_size(p);
  for (std::size_t peak = peak_bytes; now > peak && !peak_bytes.compare_exchange_weak(peak, now);) {
  }
  return p;
}

// g++ takes the free() of a pointer that operator new returned for a mismatch; here new is malloc.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void uncounted(void* p) {
  if (p == nullptr) return;
  live_bytes -= malloc_usable_size(p);
  std::free(p);
}

}  // namespace

void* operator new(std::size_t size) { return counted(std::malloc(size)); }
void* operator new[](std::size_t size) { return counted(std::malloc(size)); }
void operator delete(void* p) noexcept { uncounted(p); }
void operator delete[](void* p) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t) noexcept { uncounted(p); }
// The aligned forms too: std::pmr's default resource (behind the sweep's node pool) allocates with them.
void* operator new(std::size_t size, std::align_val_t alignment) {
  const auto a = static_cast<std::size_t>(alignment);
  return counted(std::aligned_alloc(a, (std::max<std::size_t>(size, 1) + a - 1) / a * a));
}
void* operator new[](std::size_t size, std::align_val_t alignment) { return operator new(size, alignment); }
void operator delete(void* p, std::align_val_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::align_val_t) noexcept { uncounted(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { uncounted(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { uncounted(p); }

namespace pd {
namespace {

namespace fs = std::filesystem;

// The memory a part holds beyond what it started with, at its peak.
class PeakMemory {
 public:
  PeakMemory() : start_(live_bytes) { peak_bytes = start_; }
  double extra() const { return static_cast<double>(peak_bytes - start_); }

 private:
  std::size_t start_;
};

const std::vector<std::string> kTriangulations{"monotone", "seidel", "cutting-tri", "cgal-cdt"};

struct Subject {
  std::string family;
  Rings rings;
  std::string txt, wkt, geojson;  // the polygon written in each format (txt only without holes)
  fs::path file;                  // the text file, or the WKT file for a polygon with holes
};

// The floor of reading: every number of the text, whitespace-separated, into doubles.
std::vector<double> scan_numbers(const std::string& text) {
  std::vector<double> numbers;
  const char* at = text.data();
  const char* end = at + text.size();
  while (at < end) {
    if (*at == ' ' || *at == '\n' || *at == '\t' || *at == '\r') {
      ++at;
      continue;
    }
    double d;
    const auto [next, error] = std::from_chars(at, end, d);
    if (error != std::errc()) throw std::runtime_error("the scan met a non-number");
    numbers.push_back(d);
    at = next;
  }
  return numbers;
}

// Registers a part; its repetitions also report their minimum, the figure least disturbed by the
// machine.
template <class Body>
benchmark::internal::Benchmark* add(const std::string& name, Body body) {
  return benchmark::RegisterBenchmark(name.c_str(), body)->ComputeStatistics(
      "min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
}

void report(benchmark::State& state, const PeakMemory& memory, std::size_t n) {
  state.counters["peak_bytes"] = memory.extra();
  state.counters["n"] = static_cast<double>(n);
}

std::size_t vertex_count(const Rings& rings) {
  std::size_t n = 0;
  for (const Ring& ring : rings) n += ring.size();
  return n;
}

void register_reading(const Subject& s) {
  const std::size_t n = vertex_count(s.rings);
  if (!s.txt.empty())
    add("scan/" + s.family, [&s, n](benchmark::State& state) {
      for (auto _ : state) {
        const PeakMemory memory;
        benchmark::DoNotOptimize(scan_numbers(s.txt));
        report(state, memory, n);
      }
    });
  for (const auto& [format, text] : {std::pair{"txt", &s.txt}, {"wkt", &s.wkt}, {"geojson", &s.geojson}}) {
    if (text->empty()) continue;
    add("read-" + std::string(format) + "/" + s.family, [text, n](benchmark::State& state) {
      for (auto _ : state) {
        const PeakMemory memory;
        benchmark::DoNotOptimize(parse_parts(*text));
        report(state, memory, n);
      }
    });
  }
  add("check/" + s.family, [&s, n](benchmark::State& state) {
    for (auto _ : state) {
      state.PauseTiming();
      Rings copy = s.rings;
      state.ResumeTiming();
      const PeakMemory memory;
      benchmark::DoNotOptimize(Polygon::make_with_holes(std::move(copy)));
      report(state, memory, n);
    }
  });
}

void register_triangulations(const Subject& s) {
  const auto polygon = std::make_shared<Polygon>(Polygon::make_with_holes(s.rings));
  for (const std::string& name : kTriangulations) {
    const Algorithm* a = find_algorithm(name);
    if (a == nullptr || refusal(*a, *polygon)) continue;
    add(name + "/" + s.family, [a, polygon](benchmark::State& state) {
      for (auto _ : state) {
        const PeakMemory memory;
        Counters counters;
        benchmark::DoNotOptimize(a->run(*polygon, counters));
        report(state, memory, polygon->size());
      }
    });
    add("validate-" + name + "/" + s.family, [a, polygon](benchmark::State& state) {
      Counters counters;
      const Decomposition d = a->run(*polygon, counters);
      for (auto _ : state) {
        const PeakMemory memory;
        const Validation v = validate(*polygon, d, a->kind, a->steiner);
        if (!v.ok) state.SkipWithError(("not valid: " + v.reason).c_str());
        report(state, memory, polygon->size());
      }
    });
  }
}

// `polydecomp run` as a user runs it: read, check, triangulate, validate, print.
void register_end_to_end(const Subject& s, const fs::path& polydecomp) {
  const std::string command = polydecomp.string() + " run --algorithm monotone --input " + s.file.string() + " >/dev/null";
  add("run-monotone/" + s.family, [command](benchmark::State& state) {
    for (auto _ : state)
      if (std::system(command.c_str()) != 0) state.SkipWithError(("failed: " + command).c_str());
  })->UseRealTime();
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

Subject subject(const std::string& family, std::size_t n, const fs::path& folder) {
  Subject s{family, generate_with_holes(family, n, std::nullopt, std::nullopt, 1), {}, {}, {}, {}};
  if (s.rings.size() == 1) s.txt = format_polygon(s.rings, Format::Txt);
  s.wkt = format_polygon(s.rings, Format::Wkt);
  s.geojson = format_polygon(s.rings, Format::GeoJson);
  s.file = folder / (family + (s.txt.empty() ? ".wkt" : ".txt"));
  write_file(s.file, s.txt.empty() ? s.wkt : s.txt);
  return s;
}

// The families at min(n, their largest n), in registry order.
std::vector<std::pair<std::string, std::size_t>> family_sizes(std::size_t n) {
  std::vector<std::pair<std::string, std::size_t>> sizes;
  for (const Family& f : families()) sizes.push_back({f.name, std::min(n, f.max_n)});
  for (const HoleFamily& f : hole_families()) sizes.push_back({f.name, std::min(n, f.max_n)});
  return sizes;
}

int run(int argc, char** argv) {
  std::size_t n = 1'000'000;
  std::vector<std::string> only;
  std::vector<char*> rest{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--n" && i + 1 < argc) n = std::stoul(argv[++i]);
    else if (arg == "--family" && i + 1 < argc) only.push_back(argv[++i]);
    else rest.push_back(argv[i]);
  }
  int rest_count = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_count, rest.data());
  if (benchmark::ReportUnrecognizedArguments(rest_count, rest.data())) return 2;
  for (const auto& [key, value] : provenance())
    if (key != "date") benchmark::AddCustomContext(key, value);
  const fs::path folder = fs::temp_directory_path() / ("polydecomp-door-" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const fs::path polydecomp = fs::canonical("/proc/self/exe").parent_path() / "polydecomp";
  std::vector<Subject> subjects;
  subjects.reserve(family_sizes(n).size());
  for (const auto& [family, size] : family_sizes(n)) {
    if (!only.empty() && std::find(only.begin(), only.end(), family) == only.end()) continue;
    std::fprintf(stderr, "door: making %s at n=%zu\n", family.c_str(), size);
    subjects.push_back(subject(family, size, folder));
  }
  for (const Subject& s : subjects) {
    register_reading(s);
    register_triangulations(s);
    register_end_to_end(s, polydecomp);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  fs::remove_all(folder);
  return 0;
}

}  // namespace
}  // namespace pd

int main(int argc, char** argv) { return pd::benchmark_main(argc, argv, pd::run); }
