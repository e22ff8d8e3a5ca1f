// The polydecomp command line: list | generate | run (see CONTRACT.md).
//
// Exit status: 0 success, 2 bad usage, 3 bad polygon, 4 an algorithm failed. Every failure prints one
// line on stderr beginning "error:" and nothing on stdout; output is assembled completely before any of
// it is written, so a failure never leaves partial output.
#include "core/io.h"
#include "core/json.h"
#include "core/registry.h"
#include "core/validate.h"
#include "generators/family.h"

#include <boost/program_options.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace po = boost::program_options;

namespace pd {
namespace {

constexpr int kUsage = 2, kBadPolygon = 3, kAlgorithmFailed = 4;

struct Exit {
  int status;
  std::string message;
};

[[noreturn]] void usage(const std::string& why) { throw Exit{kUsage, why}; }

const char* kUsageText =
    "usage: polydecomp list [--json]\n"
    "       polydecomp generate --family F --n N [--reflex R] [--seed S] [--format txt|wkt|geojson] [-o FILE]\n"
    "       polydecomp run --algorithm A --input FILE [--json] [--svg FILE] [--no-validate]\n";

po::variables_map parse(const std::vector<std::string>& args, const po::options_description& opts) {
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(args).options(opts).run(), vm);
    po::notify(vm);
  } catch (const po::error& e) {
    usage(e.what());
  }
  return vm;
}

// Writes text to a file atomically (a temporary beside it, then a rename), or to stdout.
void emit(const std::string& text, const std::string& path) {
  if (path.empty() || path == "-") {
    std::cout << text << std::flush;
    return;
  }
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out.flush()) usage("cannot write " + path);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) usage("cannot write " + path);
}

std::string json_bool(bool b) { return b ? "true" : "false"; }

int cmd_list(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("json", "JSON output")("help,h", "help");
  const auto vm = parse(args, opts);
  std::string out;
  if (vm.count("json")) {
    out = "[";
    for (const Algorithm& a : algorithms()) {
      out += std::string(out.size() > 1 ? ",\n " : "") + "{\"name\": " + json_quote(a.name) +
             ", \"kind\": " + json_quote(kind_name(a.kind)) + ", \"steiner\": " + json_bool(a.steiner) +
             ", \"optimal\": " + json_bool(a.optimal) + ", \"time_bound\": " + json_quote(a.time_bound) +
             ", \"pieces_bound\": " + json_quote(a.pieces_bound) + ", \"source\": " + json_quote(a.source) +
             ", \"size_ceiling\": " + std::to_string(a.size_ceiling) + "}";
    }
    out += "]\n";
  } else {
    char line[512];
    for (const Algorithm& a : algorithms()) {
      std::snprintf(line, sizeof line, "%-22s %-13s %-10s %-8s %-18s %-12s %s\n", a.name.c_str(), kind_name(a.kind),
                    a.steiner ? "steiner" : "diagonals", a.optimal ? "optimal" : "-", ("O(" + a.time_bound + ")").c_str(),
                    a.pieces_bound.c_str(), a.source.c_str());
      out += line;
    }
  }
  emit(out, "");
  return 0;
}

int cmd_generate(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("family", po::value<std::string>()->required(), "family")(
      "n", po::value<std::size_t>()->required(), "vertices")("reflex", po::value<std::size_t>(), "reflex vertices")(
      "seed", po::value<std::uint64_t>()->default_value(1), "seed")(
      "format", po::value<std::string>()->default_value("txt"), "txt|wkt|geojson")(
      "output,o", po::value<std::string>()->default_value(""), "file");
  const auto vm = parse(args, opts);
  Format format;
  try {
    format = parse_format(vm["format"].as<std::string>());
  } catch (const std::invalid_argument& e) {
    usage(e.what());
  }
  std::optional<std::size_t> reflex;
  if (vm.count("reflex")) reflex = vm["reflex"].as<std::size_t>();
  std::vector<Point> ring;
  try {
    ring = generate(vm["family"].as<std::string>(), vm["n"].as<std::size_t>(), reflex, vm["seed"].as<std::uint64_t>());
  } catch (const std::invalid_argument& e) {
    usage(e.what());
  }
  emit(format_polygon(ring, format), vm["output"].as<std::string>());
  return 0;
}

int cmd_run(const std::vector<std::string>& args) {
  po::options_description opts;
  opts.add_options()("algorithm", po::value<std::string>()->required(), "algorithm")(
      "input", po::value<std::string>()->required(), "polygon file")("json", "JSON output")(
      "svg", po::value<std::string>(), "SVG figure")("no-validate", "skip validation");
  const auto vm = parse(args, opts);
  const std::string name = vm["algorithm"].as<std::string>();
  const Algorithm* algo = find_algorithm(name);
  if (!algo) usage("unknown algorithm '" + name + "'; 'polydecomp list' names them");
  std::optional<Polygon> polygon;
  try {
    polygon = Polygon::make(read_polygon_file(vm["input"].as<std::string>()));
  } catch (const PolygonError& e) {
    throw Exit{kBadPolygon, e.what()};
  }
  Counters counters;
  Decomposition d;
  const auto start = std::chrono::steady_clock::now();
  try {
    d = algo->run(*polygon, counters);
  } catch (const std::exception& e) {
    throw Exit{kAlgorithmFailed, name + " failed: " + e.what()};
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::vector<Piece> pieces;
  std::optional<bool> valid;
  std::string reason;
  try {
    pieces = pieces_of(*polygon, d);
  } catch (const std::invalid_argument& e) {
    valid = false;
    reason = e.what();
  }
  if (!vm.count("no-validate") && !valid) {
    const Validation v = validate_pieces(*polygon, exact_points(*polygon, d), pieces, algo->kind, algo->steiner);
    valid = v.ok;
    reason = v.reason;
  }
  std::string out;
  if (vm.count("json")) {
    out = run_json({name, &*polygon, &d, &pieces, valid, seconds, &counters});
  } else {
    out = name + ": n=" + std::to_string(polygon->size()) + " reflex=" + std::to_string(polygon->reflex_count()) +
          " pieces=" + std::to_string(pieces.size()) + " steiner=" + std::to_string(d.steiner.size()) +
          (valid ? std::string(" valid=") + (*valid ? "yes" : "NO (" + reason + ")") : "") +
          " seconds=" + double_text(seconds) + "\n";
  }
  if (vm.count("svg")) emit(run_svg(*polygon, d, pieces, name), vm["svg"].as<std::string>());
  emit(out, "");
  return 0;
}

int dispatch(const std::vector<std::string>& argv) {
  if (argv.empty()) usage("no command; commands: list, generate, run ('polydecomp --help' shows their options)");
  if (argv[0] == "--help" || argv[0] == "-h" || argv[0] == "help") {
    std::cout << kUsageText;
    return 0;
  }
  const std::vector<std::string> rest(argv.begin() + 1, argv.end());
  if (argv[0] == "list") return cmd_list(rest);
  if (argv[0] == "generate") return cmd_generate(rest);
  if (argv[0] == "run") return cmd_run(rest);
  usage("unknown command '" + argv[0] + "'; commands: list, generate, run");
}

}  // namespace
}  // namespace pd

int main(int argc, char** argv) {
  try {
    return pd::dispatch(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const pd::Exit& e) {
    std::cerr << "error: " << e.message << "\n";
    return e.status;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
