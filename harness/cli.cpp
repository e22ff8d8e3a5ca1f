// The polydecomp command line: list | generate | run | cut | check | corpus (see docs/CONTRACT.md).
//
// Exit status: 0 success, 2 bad usage, 3 bad polygon, 4 the run failed (the algorithm failed, ran out
// of memory or stack, or `--max-seconds` / `--max-memory` stopped it), 5 `run`'s result is not valid
// (the report is still printed), 6 the output could not be written. Every failure prints one line on
// stderr beginning "error:" and nothing on stdout; output is assembled completely before any of it is
// written, and every write is checked, so a failure never leaves partial output unreported.
#include "core/coordinate.h"
#include "core/io.h"
#include "core/json.h"
#include "core/registry.h"
#include "core/validate.h"
#include "engines/cutting/polygon_cutting.h"
#include "generators/family.h"
#include "harness/corpus.h"
#include "harness/large_stack.h"
#include "harness/last_resort.h"
#include "harness/plugins.h"
#include "harness/progress.h"
#include "harness/run.h"
#include "harness/write_all.h"

#include <boost/program_options.hpp>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace po = boost::program_options;

namespace pd {
namespace {

[[noreturn]] void usage(const std::string& why) { throw Exit{kUsage, why}; }

// `--help` of a command: its usage lines and options, on stdout with status 0.
struct Help {
  std::string text;
};

// A non-negative integer option. Program_options would read "-5" as 2^64 - 5.
struct Count {
  std::uint64_t value;
};

void validate(boost::any& v, const std::vector<std::string>& values, Count*, int) {
  po::validators::check_first_occurrence(v);
  const std::string& s = po::validators::get_single_string(values);
  errno = 0;
  char* end = nullptr;
  const unsigned long long x = s.empty() || s[0] < '0' || s[0] > '9' ? 0 : std::strtoull(s.c_str(), &end, 10);
  if (!end || *end != '\0' || errno == ERANGE) throw po::invalid_option_value(s);
  v = Count{x};
}

const char* kUsageText =
    "usage: polydecomp list [--json | --markdown] [--plugins DIR]...\n"
    "       polydecomp generate --family F --n N [--reflex R] [--holes H] [--collinear K] [--seed S] [--format txt|wkt|geojson] [-o FILE]\n"
    "       polydecomp run --algorithm A --input FILE|- [--json] [--svg FILE] [--no-validate] [--max-seconds S]\n"
    "                      [--max-memory SIZE] [--plugins DIR]...\n"
    "       polydecomp cut --input FILE [--weights reflex|all|FILE] [--vertical] [--json]\n"
    "       polydecomp check --input FILE|- [--json]\n"
    "       polydecomp corpus --dir DIR [--json] | --dir DIR --n N [--rank K] [-o FILE]\n";

// The usage lines of `command` in kUsageText.
std::string usage_of(const std::string& command) {
  std::string out;
  bool in_command = false;
  std::istringstream lines(kUsageText);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t at = line.find("polydecomp ");
    if (at != std::string::npos) in_command = line.compare(at + 11, command.size() + 1, command + " ") == 0;
    if (in_command) out += line + "\n";
  }
  return out;
}

po::variables_map parse(const std::string& command, const std::vector<std::string>& args,
                        const po::options_description& opts) {
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") {
      std::ostringstream text;
      text << usage_of(command) << opts;
      throw Help{text.str()};
    }
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(args).options(opts).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    usage(e.what());
  }
  return vm;
}

[[noreturn]] void cannot_write(const std::string& what) {
  throw Exit{kCannotWrite, "cannot write " + what + ": " + std::strerror(errno)};
}

void write_stdout(const std::string& text) {
  if (!write_all(STDOUT_FILENO, text)) cannot_write("to the standard output");
}

// A new or regular file is replaced atomically: a temporary file beside it (same mode), then a rename,
// so that a failure leaves the old file whole.
void replace_regular_file(const std::string& path, const std::string& text, const struct stat* old) {
  std::string tmp = path + ".XXXXXX";
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0) cannot_write(path);
  const mode_t umask_now = ::umask(0);
  ::umask(umask_now);
  bool ok = ::fchmod(fd, old ? old->st_mode & 07777 : 0666 & ~umask_now) == 0 && write_all(fd, text);
  int error = errno;
  if (::close(fd) != 0 && ok) ok = false, error = errno;
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) ok = false, error = errno;
  if (!ok) {
    ::unlink(tmp.c_str());
    errno = error;
    cannot_write(path);
  }
}

// Anything else (a device such as /dev/null, a FIFO) is written through, never replaced.
void write_through(const std::string& path, const std::string& text) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_TRUNC | O_CREAT, 0666);
  if (fd < 0) cannot_write(path);
  bool ok = write_all(fd, text);
  const int error = errno;
  if (::close(fd) != 0 && ok) ok = false;
  else errno = error;
  if (!ok) cannot_write(path);
}

// Writes text to a file, or to stdout for "" and "-". A symbolic link is followed: its target is what
// gets replaced or written.
void emit(const std::string& text, const std::string& path) {
  if (path.empty() || path == "-") return write_stdout(text);
  char resolved[PATH_MAX];
  struct stat info;
  const bool is_link = ::lstat(path.c_str(), &info) == 0 && S_ISLNK(info.st_mode);
  const std::string target = is_link && ::realpath(path.c_str(), resolved) ? std::string(resolved) : path;
  if (::stat(target.c_str(), &info) != 0) {
    if (is_link) return write_through(target, text);
    return replace_regular_file(target, text, nullptr);
  }
  if (S_ISDIR(info.st_mode)) {
    errno = EISDIR;
    cannot_write(path);
  }
  if (S_ISREG(info.st_mode)) return replace_regular_file(target, text, &info);
  write_through(target, text);
}

// The README's algorithm table.
std::string list_markdown() {
  std::string out =
      "| name | kind | Steiner | optimal | holes | time | pieces | source | peer |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const Algorithm& a : algorithms()) {
    out += "| `" + a.name + "` | " + kind_name(a.kind) + " | " + (a.steiner ? "yes" : "no") + " | " +
           (a.optimal ? "yes" : "no") + " | " + (a.accepts.holes ? "yes" : "no") + " | O(" + a.time_bound + ") | " +
           a.pieces_bound + " | " + a.source + " | " + (is_peer(a) ? a.peer : "") + " |\n";
  }
  return out;
}

std::string list_text() {
  int width = 0;  // of the name column: the longest name
  for (const Algorithm& a : algorithms()) width = std::max(width, static_cast<int>(a.name.size()));
  std::string out;
  char line[1024];
  for (const Algorithm& a : algorithms()) {
    std::snprintf(line, sizeof line, "%-*s %-13s %-10s %-8s %-18s %-12s %s\n", width, a.name.c_str(), kind_name(a.kind),
                  a.steiner ? "steiner" : "diagonals", a.optimal ? "optimal" : "-", ("O(" + a.time_bound + ")").c_str(),
                  a.pieces_bound.c_str(), a.source.c_str());
    out += line;
  }
  return out;
}

// --plugins DIR (any number of times): folders of external algorithms' manifests, besides the project's
// peers/ and POLYDECOMP_PLUGINS.
void add_plugins_option(po::options_description& opts) {
  opts.add_options()("plugins", po::value<std::vector<std::string>>()->composing(), "folder of plug-in manifests");
}

void register_plugins_of(const po::variables_map& vm) {
  const std::vector<std::string> given =
      vm.count("plugins") ? vm["plugins"].as<std::vector<std::string>>() : std::vector<std::string>{};
  try {
    register_plugins(plugin_folders(given));
  } catch (const PluginError& e) {
    usage(e.what());
  }
}

int cmd_list(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("json", "JSON output")("markdown", "a Markdown table")("help,h", "this help");
  add_plugins_option(opts);
  const auto vm = parse("list", args, opts);
  register_plugins_of(vm);
  write_stdout(vm.count("json") ? algorithms_json() : vm.count("markdown") ? list_markdown() : list_text());
  return 0;
}

int cmd_generate(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("family", po::value<std::string>()->required(), "family")(
      "n", po::value<Count>()->required(), "vertices")("reflex", po::value<Count>(), "reflex vertices")(
      "holes", po::value<Count>(), "holes (families with holes)")(
      "collinear", po::value<Count>(), "K 180-degree vertices, edge midpoints (families without holes)")("seed", po::value<Count>()->default_value(Count{1}, "1"), "seed")(
      "format", po::value<std::string>()->default_value("txt"), "txt|wkt|geojson")(
      "output,o", po::value<std::string>()->default_value(""), "file")("help,h", "this help");
  const auto vm = parse("generate", args, opts);
  Format format;
  try {
    format = parse_format(vm["format"].as<std::string>());
  } catch (const std::invalid_argument& e) {
    usage(e.what());
  }
  GenerateRequest request;
  request.family = vm["family"].as<std::string>();
  request.n = vm["n"].as<Count>().value;
  if (vm.count("reflex")) request.reflex = vm["reflex"].as<Count>().value;
  if (vm.count("holes")) request.holes = vm["holes"].as<Count>().value;
  if (vm.count("collinear")) request.collinear = vm["collinear"].as<Count>().value;
  request.seed = vm["seed"].as<Count>().value;
  Rings rings;
  try {
    rings = generate_polygon(request);
  } catch (const std::invalid_argument& e) {
    usage(e.what());
  }
  if (rings.size() > 1 && format == Format::Txt)
    usage("family " + request.family + " makes polygons with holes, which plain text cannot hold: add --format wkt or --format geojson");
  emit(format_polygon(rings, format), vm["output"].as<std::string>());
  return 0;
}

// "" or " (--max-memory SIZE)": what an out-of-memory message adds.
std::string memory_note;

// A size in bytes: digits with an optional K, M, G or T (powers of 1024).
std::uint64_t byte_size(const std::string& text) {
  std::size_t digits = 0;
  while (digits < text.size() && std::isdigit(static_cast<unsigned char>(text[digits]))) ++digits;
  const std::string unit = text.substr(digits);
  const std::string units = "KMGT";
  const std::size_t power = unit.empty() ? 0 : unit.size() == 1 ? units.find(unit[0]) + 1 : 0;
  if (digits == 0 || digits > 12 || (!unit.empty() && power == 0))
    usage("--max-memory takes a size such as 2G, 512M or 1000000 (bytes)");
  return std::stoull(text.substr(0, digits)) << (10 * power);
}

// --max-memory: the process may grow its address space by `bytes` beyond what it holds now (its code,
// libraries and stack reservation), through RLIMIT_AS; beyond that allocations fail, and the run ends
// with one "ran out of memory" line.
void limit_memory_growth(std::uint64_t bytes, const std::string& text) {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  if (!(statm >> pages)) throw Exit{kAlgorithmFailed, "cannot read /proc/self/statm for --max-memory"};
  const std::uint64_t now = pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
  struct rlimit limit;
  ::getrlimit(RLIMIT_AS, &limit);
  limit.rlim_cur = std::min<std::uint64_t>(now + bytes, limit.rlim_max);
  if (::setrlimit(RLIMIT_AS, &limit) != 0) throw Exit{kAlgorithmFailed, std::string("cannot set --max-memory: ") + std::strerror(errno)};
  memory_note = " (--max-memory " + text + ")";
}

// The polygon of --input (a multipolygon's parts), through the one checked door: a bad polygon is exit
// 3, running out of memory while reading it exit 4.
std::vector<Polygon> read_input(const std::string& input) {
  try {
    return make_parts(read_parts_file(input));
  } catch (const PolygonError& e) {
    throw Exit{kBadPolygon, e.what()};
  } catch (const std::bad_alloc&) {
    throw Exit{kAlgorithmFailed, "out of memory reading " + (input == "-" ? "the standard input" : input) + memory_note};
  }
}

std::string svg_path(const po::variables_map& vm) {
  if (!vm.count("svg")) return "";
  const std::string path = vm["svg"].as<std::string>();
  if (path.empty() || path == "-") usage("--svg takes a file name (the figure cannot share the standard output)");
  return path;
}

int cmd_run(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("algorithm", po::value<std::string>()->required(), "algorithm")(
      "input", po::value<std::string>()->required(), "polygon file, or - for the standard input")(
      "json", "JSON output")("svg", po::value<std::string>(), "SVG figure")("no-validate", "skip validation")(
      "max-seconds", po::value<double>(), "stop the algorithm (and validation) after this many seconds")(
      "max-memory", po::value<std::string>(), "stop the run when it grows by more than this (2G, 512M, bytes)")(
      "help,h", "this help");
  add_plugins_option(opts);
  const auto vm = parse("run", args, opts);
  register_plugins_of(vm);
  const std::string name = vm["algorithm"].as<std::string>();
  const Algorithm* algo = find_algorithm(name);
  if (!algo) usage("unknown algorithm " + quoted_input(name) + "; 'polydecomp list' names them");
  std::optional<double> max_seconds;
  if (vm.count("max-seconds")) {
    max_seconds = vm["max-seconds"].as<double>();
    if (!(*max_seconds > 0) || *max_seconds > 1e9) usage("--max-seconds takes a number of seconds above 0");
  }
  const std::string svg = svg_path(vm);
  if (vm.count("max-memory")) limit_memory_growth(byte_size(vm["max-memory"].as<std::string>()), vm["max-memory"].as<std::string>());
  const std::vector<Polygon> parts = read_input(vm["input"].as<std::string>());
  check_accepted(*algo, parts);
  PolygonTotals totals;
  for (const Polygon& part : parts) totals.add(part);
  RunOptions options{vm.count("json") > 0, vm.count("no-validate") == 0, !svg.empty(), max_seconds, memory_note};
  std::optional<RunOutput> result;
  {
    const Heartbeat heartbeat(name + " on n = " + std::to_string(totals.n) + ", r = " + std::to_string(totals.reflex) +
                              (max_seconds ? " (stops at " + double_text(*max_seconds) + " s)" : ""));
    result = run_algorithm(*algo, parts, options);
  }
  if (!svg.empty()) emit(result->svg, svg);
  write_stdout(result->out);
  if (!result->invalid.empty()) throw Exit{kInvalidResult, "the result of " + name + " is not valid: " + result->invalid};
  return 0;
}

// `cut`'s weights in counter-clockwise order: reflex vertices, all vertices, or a file of 0/1 values,
// one per vertex in the input's order (without a repeated closing vertex; '#' starts a comment).
std::vector<int> cut_weights(const std::string& spec, const Polygon& p) {
  if (spec == "reflex") return vertex_weights(p, WeightRule::Reflex);
  if (spec == "all") return vertex_weights(p, WeightRule::All);
  std::ifstream in(spec, std::ios::binary);
  if (!in) usage("cannot read weights file " + spec + " (--weights takes reflex, all or a file)");
  std::vector<int> in_file_order;
  for (std::string token; in >> token;) {
    if (token[0] == '#') {
      std::getline(in, token);
      continue;
    }
    if (token != "0" && token != "1") usage("weights file " + spec + ": " + quoted_input(token) + " is not 0 or 1");
    in_file_order.push_back(token == "1");
  }
  if (in_file_order.size() != p.size())
    usage("weights file " + spec + ": " + std::to_string(in_file_order.size()) + " weights for " +
          std::to_string(p.size()) + " vertices");
  std::vector<int> w(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) w[i] = in_file_order[p.input_index(i)];
  return w;
}

std::string json_counters(const Counters& counters) {
  std::string out = "{";
  for (const auto& [name, value] : counters) out += (out.size() > 1 ? ", " : "") + json_quote(name) + ": " + std::to_string(value);
  return out + "}";
}

// The fair cut in the input's indices, a < b; C1 weighs the vertices strictly between a and b in the
// input's order, C2 the others but a and b.
std::string fair_cut_report(const Polygon& p, const std::vector<int>& weights, bool json) {
  Counters counters;
  const FairCut cut = fair_cut(p, weights, counters);
  const std::size_t a = std::min(p.input_index(cut.a), p.input_index(cut.b));
  const std::size_t b = std::max(p.input_index(cut.a), p.input_index(cut.b));
  std::vector<int> in_file_order(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) in_file_order[p.input_index(i)] = weights[i];
  std::int64_t c1 = 0;
  for (std::size_t k = a + 1; k < b; ++k) c1 += in_file_order[k];
  const std::int64_t c2 = cut.C - c1 - in_file_order[a] - in_file_order[b];
  auto number = [](auto v) { return std::to_string(v); };
  if (json)
    return "{\"a\": " + number(a) + ", \"b\": " + number(b) + ", \"C\": " + number(cut.C) + ", \"C1\": " + number(c1) +
           ", \"C2\": " + number(c2) + ", \"counters\": " + json_counters(counters) + "}\n";
  return "cut: a=" + number(a) + " b=" + number(b) + " C=" + number(cut.C) + " C1=" + number(c1) + " C2=" + number(c2) + "\n";
}

// Theorem 3's chord AB in the input's indices: A inside edge_a, B inside edge_b or B a vertex; C1
// weighs the vertices from edge_a's second vertex on to B in the input's order, C2 the others (B
// excluded).
std::string vertical_report(const Polygon& p, const std::vector<int>& weights, bool json) {
  Counters counters;
  const VerticalCut cut = vertical_cut(p, weights, counters);
  const std::size_t n = p.size();
  auto file_edge = [&](std::size_t e) {
    const std::size_t i = p.input_index(e), j = p.input_index(p.next(e));
    return (i + 1) % n == j ? std::make_pair(i, j) : std::make_pair(j, i);
  };
  std::vector<int> in_file_order(n);
  for (std::size_t i = 0; i < n; ++i) in_file_order[p.input_index(i)] = weights[i];
  const auto edge_a = file_edge(cut.edge_a);
  const std::size_t b = cut.b_is_vertex ? p.input_index(cut.edge_b) : file_edge(cut.edge_b).first;
  const std::size_t stop = cut.b_is_vertex ? b : (b + 1) % n;
  std::int64_t c1 = 0;
  for (std::size_t k = edge_a.second; k != stop; k = (k + 1) % n) c1 += in_file_order[k];
  const std::int64_t c2 = cut.C - c1 - (cut.b_is_vertex ? in_file_order[b] : 0);
  auto coord = [&](const Rational& v) {
    const std::string t = rational_text(v);
    return json && t.find('/') != std::string::npos ? json_quote(t) : t;
  };
  auto point = [&](const QPoint& q) { return "[" + coord(q.x()) + ", " + coord(q.y()) + "]"; };
  auto number = [](auto v) { return std::to_string(v); };
  if (json)
    return "{\"A\": " + point(cut.A) + ", \"B\": " + point(cut.B) + ", \"edge_a\": [" + number(edge_a.first) + ", " +
           number(edge_a.second) + "], " +
           (cut.b_is_vertex ? "\"vertex_b\": " + number(b) : "\"edge_b\": [" + number(b) + ", " + number((b + 1) % n) + "]") +
           ", \"C\": " + number(cut.C) + ", \"C1\": " + number(c1) + ", \"C2\": " + number(c2) +
           ", \"counters\": " + json_counters(counters) + "}\n";
  return "vertical: A=" + point(cut.A) + " on edge " + number(edge_a.first) + "-" + number(edge_a.second) + " B=" +
         point(cut.B) + (cut.b_is_vertex ? " at vertex " + number(b) : " on edge " + number(b) + "-" + number((b + 1) % n)) +
         " C=" + number(cut.C) + " C1=" + number(c1) + " C2=" + number(c2) + "\n";
}

// The polygon-cutting theorem (engines/cutting/polygon_cutting.h). A polygon with no fair cut promised (a
// triangle, weights totalling 1) is refused with exit status 3, like a bad polygon.
int cmd_cut(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("input", po::value<std::string>()->required(), "polygon file")(
      "weights", po::value<std::string>()->default_value("reflex"), "reflex|all|FILE")(
      "vertical", "Theorem 3's vertical chord instead of the diagonal")("json", "JSON output")("help,h", "this help");
  const auto vm = parse("cut", args, opts);
  const std::vector<Polygon> parts = read_input(vm["input"].as<std::string>());
  if (parts.size() > 1) throw Exit{kBadPolygon, "cut takes one polygon, not a multipolygon"};
  if (parts[0].hole_count() > 0)
    throw Exit{kBadPolygon, "cut takes a polygon without holes: the polygon-cutting theorem is for simple polygons"};
  if (!parts[0].merged().empty())
    throw Exit{kBadPolygon, "cut takes a polygon without repeated vertices (its weights are one per vertex)"};
  const Polygon& polygon = parts[0];
  const std::vector<int> weights = cut_weights(vm["weights"].as<std::string>(), polygon);
  std::string out;
  try {
    out = vm.count("vertical") ? vertical_report(polygon, weights, vm.count("json") > 0)
                               : fair_cut_report(polygon, weights, vm.count("json") > 0);
  } catch (const NoFairCut& e) {
    throw Exit{kBadPolygon, std::string("no fair cut: ") + e.what()};
  } catch (const std::bad_alloc&) {
    throw Exit{kAlgorithmFailed, "cut ran out of memory"};
  } catch (const std::exception& e) {
    throw Exit{kAlgorithmFailed, std::string("cut failed: ") + e.what()};
  }
  write_stdout(out);
  return 0;
}

// Reads and checks a polygon, as `run` does before any algorithm: its size, notches and orientation.
int cmd_check(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("input", po::value<std::string>()->required(), "polygon file, or - for the standard input")(
      "json", "JSON output")("help,h", "this help");
  const auto vm = parse("check", args, opts);
  const std::vector<Polygon> parts = read_input(vm["input"].as<std::string>());
  PolygonTotals t;
  for (const Polygon& p : parts) t.add(p);
  const bool clockwise = parts[0].input_was_clockwise();
  auto number = [](std::size_t v) { return std::to_string(v); };
  write_stdout(vm.count("json") ? "{\"n\": " + number(t.n) + ", \"reflex\": " + number(t.reflex) + ", \"clockwise\": " +
                                      json_bool(clockwise) + ", \"holes\": " + number(t.holes) + ", \"parts\": " +
                                      number(parts.size()) + ", \"merged\": " + number(t.merged) + "}\n"
                                : "polygon: n=" + number(t.n) + " reflex=" + number(t.reflex) + " orientation=" +
                                      (clockwise ? "clockwise" : "counter-clockwise") + count_text("holes", t.holes, t.holes > 0) +
                                      count_text("parts", parts.size(), parts.size() > 1) +
                                      count_text("merged", t.merged, t.merged > 0) + "\n");
  return 0;
}

// A corpus's files, each with its n, r and h or why it is refused (docs/CONTRACT.md, "polydecomp corpus").
std::string corpus_listing(const Corpus& c, bool json) {
  std::string out;
  const std::size_t accepted = c.accepted().size(), refused = c.files.size() - accepted;
  auto number = [](std::size_t v) { return std::to_string(v); };
  for (const CorpusFile& f : c.files) {
    if (json) {
      out += std::string(out.empty() ? "" : ",\n  ") + "{\"file\": " + json_quote(f.name) +
             (f.refused ? ", \"refused\": " + json_quote(*f.refused)
                        : ", \"n\": " + number(f.n) + ", \"reflex\": " + number(f.r) + ", \"holes\": " + number(f.h)) +
             "}";
    } else {
      out += quoted_input(f.name) + ": " +
             (f.refused ? "refused: " + *f.refused : "n=" + number(f.n) + " reflex=" + number(f.r) + " holes=" + number(f.h)) + "\n";
    }
  }
  if (json)
    return "{\"corpus\": " + json_quote(c.name) + ", \"accepted\": " + number(accepted) + ", \"refused\": " +
           number(refused) + ", \"files\": [\n  " + out + "]}\n";
  return out + "corpus " + quoted_input(c.name) + ": " + number(c.files.size()) + " files, " + number(accepted) + " accepted, " +
         number(refused) + " refused\n";
}

// Lists a folder of polygon files as a sweep reads it, or writes the file nearest to --n vertices.
int cmd_corpus(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("dir", po::value<std::string>()->required(), "a folder of polygon files")(
      "json", "JSON listing")("n", po::value<Count>(), "write the accepted file nearest to N vertices")(
      "rank", po::value<Count>()->default_value(Count{1}, "1"), "with --n: the K-th nearest")(
      "output,o", po::value<std::string>()->default_value(""), "with --n: file")("help,h", "this help");
  const auto vm = parse("corpus", args, opts);
  if (vm.count("n") && vm.count("json")) usage("--json lists the folder; with --n the command writes one file");
  if (!vm.count("n") && (!vm["rank"].defaulted() || !vm["output"].defaulted()))
    usage("--rank and -o go with --n");
  Corpus c;
  try {
    c = read_corpus(vm["dir"].as<std::string>());
  } catch (const std::runtime_error& e) {
    throw Exit{kBadPolygon, e.what()};
  }
  if (!vm.count("n")) {
    write_stdout(corpus_listing(c, vm.count("json") > 0));
    return 0;
  }
  const std::size_t n = vm["n"].as<Count>().value, rank = vm["rank"].as<Count>().value;
  const CorpusFile* f = c.nearest(n, rank);
  if (!f)
    throw Exit{kBadPolygon, "corpus " + quoted_input(c.name) + " accepts " + std::to_string(c.accepted().size()) +
                                " files; none is at rank " + std::to_string(rank) + " from n=" + std::to_string(n)};
  const std::optional<std::string> text = read_file_bytes(f->path);
  if (!text) throw Exit{kBadPolygon, "cannot read " + f->path};
  emit(*text, vm["output"].as<std::string>());
  return 0;
}

int dispatch(const std::vector<std::string>& argv) {
  if (argv.empty()) usage("no command; commands: list, generate, run, cut, check, corpus ('polydecomp --help' shows their options)");
  if (argv[0] == "--help" || argv[0] == "-h" || argv[0] == "help") {
    write_stdout(kUsageText);
    return 0;
  }
  const std::vector<std::string> rest(argv.begin() + 1, argv.end());
  if (argv[0] == "list") return cmd_list(rest);
  if (argv[0] == "generate") return cmd_generate(rest);
  if (argv[0] == "run") return cmd_run(rest);
  if (argv[0] == "cut") return cmd_cut(rest);
  if (argv[0] == "check") return cmd_check(rest);
  if (argv[0] == "corpus") return cmd_corpus(rest);
  usage("unknown command " + quoted_input(argv[0]) + "; commands: list, generate, run, cut, check, corpus");
}

// The one place a failure becomes its error line and exit status.
int run_command_line(const std::vector<std::string>& argv) {
  try {
    try {
      return dispatch(argv);
    } catch (const Help& help) {
      write_stdout(help.text);
      return 0;
    }
  } catch (const Exit& e) {
    std::cerr << "error: " << e.message << "\n";
    return e.status;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory" << memory_note << "\n";
    return kAlgorithmFailed;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace
}  // namespace pd

int main(int argc, char** argv) {
  return pd::run_on_large_stack([&] {
    pd::install_last_resort_handlers();
    return pd::run_command_line(std::vector<std::string>(argv + 1, argv + argc));
  });
}
