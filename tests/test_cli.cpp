// The command line end to end, as docs/CONTRACT.md promises it: list, generate, run, and the error
// behaviour (one "error:" line, exit 2 for usage and 3 for a bad polygon, nothing on stdout).
#include "core/io.h"
#include "core/json.h"
#include "core/registry.h"
#include "generators/family.h"
#include "tests/command.h"
#include "tests/fixtures.h"
#include "tests/independent_check.h"
#include "tests/reliability.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace pd {
namespace {

namespace fs = std::filesystem;

using command::Result;
using command::slurp;

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = command::scratch_folder("polydecomp-cli");
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path file(const std::string& name, const std::string& content) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }

  Result cli(const std::string& args) { return command::run(std::string(PD_CLI) + " " + args, dir_); }

  void expect_error(const std::string& args, int status, const std::string& message) {
    const Result r = cli(args);
    EXPECT_EQ(r.status, status) << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_EQ(r.err, "error: " + message + "\n") << args;
  }

  fs::path dir_;
};

TEST_F(Cli, ListJsonHasEveryAlgorithmWithTheContractKeys) {
  const Result r = cli("list --json");
  ASSERT_EQ(r.status, 0);
  const Json list = parse_json(r.out);
  // Besides the algorithms built in, the CLI lists the external ones of the project's peers/ (one
  // manifest each), which are peers, and their variants (hertel-mehlhorn[earcut]), each naming its
  // base, which is listed.
  std::size_t manifests = 0;
  if (fs::is_directory(PD_SOURCE_DIR "/peers"))
    for (const auto& entry : fs::directory_iterator(PD_SOURCE_DIR "/peers"))
      manifests += entry.path().extension() == ".json";
  std::set<std::string> listed;
  std::size_t variants_of_manifests = 0;
  for (const Json& a : list.items) listed.insert(a.get("name")->text);
  for (const Json& a : list.items) {
    for (const char* key : {"name", "kind", "steiner", "optimal", "time_bound", "pieces_bound", "source", "peer",
                            "holes", "accepts", "size_ceiling", "variant_of"})
      ASSERT_NE(a.get(key), nullptr) << key;
    const bool variant = a.get("variant_of")->type == Json::Type::String;
    if (variant) {
      EXPECT_EQ(listed.count(a.get("variant_of")->text), 1u) << a.get("name")->text;
    }
    const Algorithm* registered = find_algorithm(a.get("name")->text);
    if (registered == nullptr) {
      EXPECT_EQ(a.get("peer")->type, Json::Type::String) << a.get("name")->text << " (from peers/) is a peer";
      variants_of_manifests += variant;
      continue;
    }
    EXPECT_EQ(a.get("peer")->type == Json::Type::Null, !is_peer(*registered)) << registered->name;
    EXPECT_EQ(a.get("accepts")->get("convex_only")->boolean, registered->accepts.convex_only) << registered->name;
  }
  EXPECT_EQ(list.items.size(), algorithms().size() + manifests + variants_of_manifests);
  EXPECT_EQ(cli("list").status, 0);
}

// The lines of `text` between the line `begin` and the line `end`.
std::vector<std::string> lines_between(const std::string& text, const std::string& begin, const std::string& end) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  bool inside = false;
  for (std::string line; std::getline(in, line);) {
    if (line == end) break;
    if (inside) lines.push_back(line);
    inside = inside || line == begin;
  }
  return lines;
}

// The algorithm column of the committed reference results.
std::set<std::string> algorithms_in_reference_results() {
  std::istringstream csv(slurp(PD_SOURCE_DIR "/results/paper.csv"));
  std::set<std::string> names;
  std::string line;
  std::getline(csv, line);  // the header: key_index,name,algorithm,...
  while (std::getline(csv, line)) {
    const std::size_t first = line.find(','), second = line.find(',', first + 1);
    names.insert(line.substr(second + 1, line.find(',', second + 1) - second - 1));
  }
  return names;
}

// The README's algorithm table is rows of `polydecomp list --markdown`, unchanged and in its order: every
// algorithm of the committed reference run, and any other registered one. A new algorithm file needs
// no README edit until it joins the reference run.
TEST_F(Cli, ReadmeAlgorithmTableIsCurrent) {
  const Result r = cli("list --markdown");
  ASSERT_EQ(r.status, 0);
  std::istringstream listed(r.out);
  std::vector<std::string> current;
  for (std::string line; std::getline(listed, line);) current.push_back(line);
  const std::vector<std::string> readme =
      lines_between(slurp(PD_SOURCE_DIR "/README.md"), "<!-- polydecomp list --markdown -->", "<!-- end of list -->");
  ASSERT_GE(readme.size(), 2u);
  std::size_t at = 0;
  std::set<std::string> in_readme;
  for (const std::string& row : readme) {
    while (at < current.size() && current[at] != row) ++at;
    ASSERT_LT(at, current.size()) << "not in `polydecomp list --markdown`, or out of its order: " << row;
    const std::size_t tick = row.find('`');
    if (tick != std::string::npos) in_readme.insert(row.substr(tick + 1, row.find('`', tick + 1) - tick - 1));
  }
  for (const std::string& name : algorithms_in_reference_results())
    EXPECT_TRUE(in_readme.count(name)) << name << " is in the reference results but not in the README's table";
}

TEST_F(Cli, GenerateIsDeterministicAndNamesTheFeasibleRange) {
  const Result a = cli("generate --family random --n 50 --reflex 10 --seed 7");
  const Result b = cli("generate --family random --n 50 --reflex 10 --seed 7 --format txt");
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(cli("generate --family convex --n 12 --format wkt").out.rfind("POLYGON ((", 0), 0u);
  EXPECT_EQ(cli("generate --family convex --n 12 --format geojson").out.rfind("{\"type\": \"Polygon\"", 0), 0u);
  const fs::path out = dir_ / "p.txt";
  EXPECT_EQ(cli("generate --family spiral --n 40 -o " + out.string()).status, 0);
  EXPECT_TRUE(fs::exists(out));
  const Result bad = cli("generate --family convex --n 12 --reflex 3");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.out, "");
  EXPECT_EQ(bad.err.rfind("error: ", 0), 0u);
  EXPECT_NE(bad.err.find("feasible"), std::string::npos) << bad.err;
  EXPECT_EQ(cli("generate --family nosuch --n 12").status, 2);
  EXPECT_EQ(cli("generate --family convex --n -4").status, 2);
}

TEST_F(Cli, GenerateMakesCollinearVerticesOnRequest) {
  const fs::path out = dir_ / "flat.txt";
  ASSERT_EQ(cli("generate --family star --n 40 --collinear 10 --seed 3 -o " + out.string()).status, 0);
  const Result plain = cli("generate --family star --n 30 --seed 3 -o " + (dir_ / "plain.txt").string());
  ASSERT_EQ(plain.status, 0) << plain.err;
  const Result flat = cli("check --input " + out.string()), base = cli("check --input " + (dir_ / "plain.txt").string());
  EXPECT_EQ(flat.out, "polygon: n=40" + base.out.substr(base.out.find(" reflex=")));
  expect_error("generate --family star --n 10 --collinear 6", 2, "at n=10 at most n/2 = 5 vertices can be collinear (one on an edge of the polygon of n - k vertices), not 6");
  expect_error("generate --family convex-holes --n 30 --holes 2 --collinear 2", 2, "--collinear and --holes do not go together: collinear vertices are made for families without holes");
  expect_error("generate --family star --n 12 --reflex 4", 2, "family star does not choose r: it is an outcome of the method (leave out --reflex; polydecomp check counts it)");
}

TEST_F(Cli, BadPolygonsGetOneErrorLineAndExit3) {
  expect_error("run --algorithm ear-n2 --input " + file("bow.txt", "0 0\n2 2\n2 0\n0 2\n").string(), 3,
               "not simple: edge 0-1 crosses edge 2-3");
  expect_error("run --algorithm ear-n2 --input " + file("two.txt", "0 0\n1 1\n").string(), 3,
               "2 vertices; a polygon needs at least 3");
  expect_error("run --algorithm ear-n2 --input " + file("empty.txt", "").string(), 3, "the input is empty");
  expect_error("run --algorithm ear-n2 --input " + file("nan.txt", "0 0\n1 NaN\n0 1\n").string(), 3,
               "vertex 1 has a coordinate that is not finite");
  expect_error("run --algorithm ear-n2 --input " + file("junk.txt", "hello world\n").string(), 3,
               "line 1: 'hello' is not a number");
  expect_error("run --algorithm keil --input " +
                   file("hole.wkt", "POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 2 1, 1 2, 1 1))").string(),
               3, "keil does not take polygons with holes; this one has 1 hole");
  expect_error("run --algorithm keil --input " +
                   file("hole.json", R"({"type":"Polygon","coordinates":[[[0,0],[9,0],[0,9]],[[1,1],[2,1],[1,2]]]})").string(),
               3, "keil does not take polygons with holes; this one has 1 hole");
  expect_error("run --algorithm monotone --input " +
                   file("out.wkt", "POLYGON ((0 0, 9 0, 9 9, 0 9, 0 0), (10 1, 12 1, 10 2, 10 1))").string(),
               3, "hole 1 is not inside the outer ring");
  expect_error("run --algorithm ear-n2 --input " + (dir_ / "missing.txt").string(), 3,
               "cannot read " + (dir_ / "missing.txt").string() + ": No such file or directory");
  expect_error("run --algorithm ear-n2 --input " + dir_.string(), 3,
               dir_.string() + " is a directory; --input takes one polygon file");
  expect_error("run --algorithm ear-n2 --input /dev/zero", 3,
               "/dev/zero holds a NUL byte at offset 0; polygon files are text");
}

TEST_F(Cli, CheckNamesAPolygonOrItsDefect) {
  const fs::path cw = file("cw.txt", "0 0\n0 4\n4 4\n4 0\n2 2\n");
  Result r = cli("check --input " + cw.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "polygon: n=5 reflex=1 orientation=clockwise\n");
  r = cli("check --json --input " + cw.string());
  EXPECT_EQ(r.out, "{\"n\": 5, \"reflex\": 1, \"clockwise\": true, \"holes\": 0, \"parts\": 1, \"merged\": 0}\n");
  const fs::path two = file("two.wkt", "MULTIPOLYGON (((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 1 2, 2 2, 2 1, 2 1)), ((20 0, 21 0, 20 1)))");
  EXPECT_EQ(cli("check --input " + two.string()).out,
            "polygon: n=12 reflex=4 orientation=counter-clockwise holes=1 parts=2 merged=1\n");
  expect_error("check --input " + file("bow.txt", "0 0\n2 2\n2 0\n0 2\n").string(), 3, "not simple: edge 0-1 crosses edge 2-3");
}

TEST_F(Cli, BadUsageExits2) {
  expect_error("run --algorithm nosuch --input x", 2, "unknown algorithm 'nosuch'; 'polydecomp list' names them");
  EXPECT_EQ(cli("run --input x").status, 2);
  EXPECT_EQ(cli("frobnicate").status, 2);
  EXPECT_EQ(cli("").status, 2);
  EXPECT_EQ(cli("--help").status, 0);
}

TEST_F(Cli, AcceptsClockwiseClosedAndCollinearInput) {
  const fs::path p = file("cw.txt", "# clockwise, closed, with a flat vertex at (2,0)\n0 0\n0 4\n4 4\n4 0\n2 0\n0 0\n");
  const Result r = cli("run --algorithm ear-n2 --json --input " + p.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = parse_json(r.out);
  EXPECT_EQ(j.get("n")->text, "5");
  EXPECT_TRUE(j.get("valid")->boolean);
  EXPECT_EQ(j.get("points")->items[1].items[1].text, "4");  // file order kept
  EXPECT_EQ(j.get("piece_count")->text, "3");
}

// `valid` from run --json agrees with the independent exact check, for every algorithm, computed from
// the JSON alone.
TEST_F(Cli, RunJsonValidAgreesWithTheIndependentCheck) {
  for (const std::string family : {"random", "spiral", "comb", "notch-heavy", "few-notches"}) {
    const fs::path poly = dir_ / (family + ".txt");
    ASSERT_EQ(cli("generate --family " + family + " --n 30 --seed 3 -o " + poly.string()).status, 0);
    const Polygon p = Polygon::make(generate(family, 30, std::nullopt, 3));
    for (const Algorithm& a : algorithms()) {
      if (!reliability::takes(a, p)) continue;
      const Result r = cli("run --json --algorithm " + a.name + " --input " + poly.string());
      ASSERT_EQ(r.status, 0) << a.name << ": " << r.err;
      const Json j = parse_json(r.out);
      for (const char* key : {"algorithm", "n", "reflex", "points", "pieces", "piece_count", "steiner_count", "valid",
                              "seconds", "counters"})
        ASSERT_NE(j.get(key), nullptr) << key;
      independent::Cycle points;
      for (const Json& q : j.get("points")->items) {
        auto coord = [](const Json& c) {
          return c.type == Json::Type::String ? Rational(c.text) : Rational(std::strtod(c.text.c_str(), nullptr));
        };
        points.emplace_back(coord(q.items[0]), coord(q.items[1]));
      }
      const std::size_t n = std::stoul(j.get("n")->text);
      independent::Cycle outline(points.begin(), points.begin() + n);
      if (independent::area2(outline) < 0) std::reverse(outline.begin(), outline.end());
      std::vector<independent::Cycle> pieces;
      for (const Json& piece : j.get("pieces")->items) {
        independent::Cycle c;
        for (const Json& v : piece.items) c.push_back(points.at(std::stoul(v.text)));
        pieces.push_back(c);
      }
      EXPECT_EQ(j.get("valid")->boolean, independent::tiles_once({outline}, pieces, a.kind != Kind::Partition))
          << a.name << " on " << family;
    }
  }
}

TEST_F(Cli, MaxSecondsStopsASlowRunWithOneErrorLine) {
  const fs::path poly = dir_ / "big.txt", svg = dir_ / "big.svg";
  ASSERT_EQ(cli("generate --family random --n 3000 -o " + poly.string()).status, 0);
  const auto start = std::chrono::steady_clock::now();
  expect_error("run --algorithm diagonal-n4 --max-seconds 0.5 --json --svg " + svg.string() + " --input " + poly.string(),
               4, "diagonal-n4 stopped after 0.5 s (--max-seconds)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
  EXPECT_FALSE(fs::exists(svg));
}

// A run that lasts shows on a terminal what runs and for how long, and erases that line when it ends;
// off a terminal, stderr holds only the contract's error line. util-linux's `script` gives the run a
// terminal.
TEST_F(Cli, ShowsHowLongARunTakesOnATerminalOnly) {
  if (std::system("script --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no `script` (util-linux) for a terminal";
  const fs::path poly = dir_ / "big.txt", log = dir_ / "terminal.log";
  ASSERT_EQ(cli("generate --family random --n 3000 --reflex 10 -o " + poly.string()).status, 0);
  const std::string run = std::string(PD_CLI) + " run --algorithm diagonal-n4 --max-seconds 3.5 --input " + poly.string();
  ASSERT_NE(std::system(("script -qec '" + run + "' /dev/null >" + log.string() + " 2>&1 </dev/null").c_str()), -1);
  const std::string terminal = slurp(log);
  EXPECT_NE(terminal.find("\r\033[Kdiagonal-n4 on n = 3000, r = 10 (stops at 3.5 s): 0:02 elapsed"), std::string::npos)
      << terminal;
  EXPECT_NE(terminal.find("\r\033[Kerror: diagonal-n4 stopped after 3.5 s (--max-seconds)"), std::string::npos) << terminal;
  expect_error("run --algorithm diagonal-n4 --max-seconds 2.5 --input " + poly.string(), 4,
               "diagonal-n4 stopped after 2.5 s (--max-seconds)");
}

TEST_F(Cli, MaxSecondsKeepsAFinishedRunsOutput) {
  const fs::path poly = file("l.txt", "0 0\n4 0\n4 2\n2 2\n2 4\n0 4\n"), svg = dir_ / "l.svg";
  const Result plain = cli("run --algorithm hertel-mehlhorn --input " + poly.string());
  const Result timed = cli("run --algorithm hertel-mehlhorn --max-seconds 60 --svg " + svg.string() + " --input " + poly.string());
  ASSERT_EQ(timed.status, 0) << timed.err;
  EXPECT_EQ(timed.err, "");
  auto without_seconds = [](const std::string& out) { return out.substr(0, out.find(" seconds=")); };
  EXPECT_EQ(without_seconds(timed.out), without_seconds(plain.out));
  EXPECT_NE(timed.out.find("valid=yes"), std::string::npos) << timed.out;
  EXPECT_NE(slurp(svg).find("</svg>"), std::string::npos);
  const Result json = cli("run --algorithm ear-n2 --json --max-seconds 60 --input " + poly.string());
  ASSERT_EQ(json.status, 0) << json.err;
  EXPECT_EQ(parse_json(json.out).get("piece_count")->text, "4");
  for (const std::string bad : {"0", "-1", "nan", "x"})
    EXPECT_EQ(cli("run --algorithm ear-n2 --max-seconds " + bad + " --input " + poly.string()).status, 2) << bad;
}

// Every earcut fixture, whole (holes and all), through every registered algorithm within its budget:
// a valid result, or one clean error line (exit 3 for a polygon with a defect, refused before any
// algorithm runs, or for holes given to an algorithm that takes none; exit 4 for a peer that fails;
// exit 5 and its report for a peer's invalid result), never a crash, a hang or an invalid result from
// one of ours. test_holes.cpp says which fixtures are refused and why; the outer rings alone go through
// every algorithm in test_algorithms.cpp.
TEST_F(Cli, EveryEarcutFixtureThroughEveryAlgorithm) {
  std::size_t refused = 0, runs = 0;
  for (const auto& path : fixtures::earcut_files()) {
    std::optional<Polygon> p;
    try {
      std::vector<Polygon> parts = make_parts(read_parts_file(path.string()));
      p = std::move(parts.at(0));
    } catch (const PolygonError& e) {
      // Refused before the algorithm runs, whichever it is: each refused fixture names the next one.
      const Algorithm& a = algorithms()[refused++ % algorithms().size()];
      expect_error("run --algorithm " + a.name + " --input " + path.string(), 3, e.what());
      continue;
    }
    for (const Algorithm& a : algorithms()) {
      if (!reliability::within_work(a, *p, reliability::kTestWork)) continue;
      ++runs;
      const Result r = cli("run --algorithm " + a.name + " --json --max-seconds 300 --input " + path.string());
      const std::string label = a.name + " on " + path.filename().string();
      if (r.status == 0) {
        EXPECT_EQ(r.err, "") << label;
        EXPECT_TRUE(parse_json(r.out).get("valid")->boolean) << label;
      } else if (r.status == 5) {
        EXPECT_TRUE(is_peer(a)) << label << ": " << r.err;
        EXPECT_FALSE(parse_json(r.out).get("valid")->boolean) << label;
        EXPECT_EQ(r.err.rfind("error: the result of " + a.name + " is not valid: ", 0), 0u) << label;
      } else {
        EXPECT_TRUE(is_peer(a)) << label << ": " << r.err;
        EXPECT_EQ(r.status, 4) << label;
        EXPECT_EQ(r.out, "") << label;
        EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << label;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << label << ": " << r.err;
      }
    }
  }
  EXPECT_EQ(refused, 47u);
  EXPECT_GT(runs, 50u);
}

// A multipolygon with a hole and a repeated vertex: points in file order (the repeat included, the
// closing vertices not), pieces in those indices (never the merged one), "parts" naming each part's
// pieces, and the triangles of each part adding up to its area.
TEST_F(Cli, RunReportsHolesPartsAndMergedVertices) {
  const fs::path two = file("two.wkt", "MULTIPOLYGON (((0 0, 9 0, 9 9, 0 9, 0 0), (1 1, 1 2, 2 2, 2 1, 2 1)), ((20 0, 21 0, 20 1)))");
  const Result r = cli("run --algorithm monotone --json --svg " + (dir_ / "two.svg").string() + " --input " + two.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = parse_json(r.out);
  EXPECT_EQ(j.get("n")->text, "12");
  EXPECT_EQ(j.get("holes")->text, "1");
  ASSERT_EQ(j.get("points")->items.size(), 12u);
  EXPECT_EQ(j.get("points")->items[8].items[0].text, "2");
  ASSERT_EQ(j.get("merged")->items.size(), 1u);
  EXPECT_EQ(j.get("merged")->items[0].items[0].text, "8");
  EXPECT_EQ(j.get("merged")->items[0].items[1].text, "7");
  EXPECT_EQ(j.get("piece_count")->text, "9");  // 8 + 2*1 - 2 triangles, and one
  const auto& parts = j.get("parts")->items;
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].items.size(), 8u);
  ASSERT_EQ(parts[1].items.size(), 1u);
  EXPECT_EQ(parts[1].items[0].text, "8");
  for (const Json& piece : j.get("pieces")->items)
    for (const Json& v : piece.items) EXPECT_NE(v.text, "8") << "a piece names the merged vertex";
  EXPECT_TRUE(j.get("valid")->boolean);
  EXPECT_NE(slurp(dir_ / "two.svg").find("<svg"), std::string::npos);
  const Result text = cli("run --algorithm monotone --input " + two.string());
  EXPECT_EQ(text.out.rfind("monotone: n=12 reflex=4 holes=1 parts=2 pieces=9 steiner=0 valid=yes", 0), 0u) << text.out;
  expect_error("run --algorithm keil --input " + two.string(), 3, "part 0: keil does not take polygons with holes; this one has 1 hole");
  expect_error("cut --input " + two.string(), 3, "cut takes one polygon, not a multipolygon");
}

TEST_F(Cli, SvgIsWritten) {
  const fs::path poly = file("l.txt", "0 0\n4 0\n4 2\n2 2\n2 4\n0 4\n"), svg = dir_ / "l.svg";
  ASSERT_EQ(cli("run --algorithm ear-n2 --input " + poly.string() + " --svg " + svg.string()).status, 0);
  EXPECT_NE(slurp(svg).find("</svg>"), std::string::npos);
}

// CGAL's y-monotone partition recurses about once per vertex on a spiral and overflowed the default
// 8 MiB stack at n = 300,000 (a segmentation fault); the command line runs on a 1 GiB stack.
TEST_F(Cli, DeepRecursionInAPeerIsNotACrash) {
  const fs::path poly = dir_ / "spiral.txt";
  ASSERT_EQ(cli("generate --family spiral --n 300000 -o " + poly.string()).status, 0);
  const Result r = cli("run --algorithm cgal-y-monotone --no-validate --input " + poly.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("cgal-y-monotone: n=300000"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace pd
