// External algorithms (harness/plugins.h) end to end: plug-ins written into a temporary folder outside
// the tree, named by --plugins, are listed, run, validated and benchmarked without rebuilding anything;
// one that crashes, hangs, prints garbage, refuses or returns a wrong decomposition is reported as
// exactly that.
#include "core/json.h"
#include "tests/command.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace pd {
namespace {

namespace fs = std::filesystem;

using command::Result;
using command::slurp;

// A plug-in's body: Python that answers every polygon line with what `answer` computes from `points`.
std::string python_plugin(const std::string& answer) {
  return "import json, sys\n"
         "for line in sys.stdin:\n"
         "    points = json.loads(line)['points']\n"
         "    n = len(points)\n" +
         answer + "\n";
}

class Plugins : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = command::scratch_folder("polydecomp-plugins");
    fs::create_directories(dir_ / "plugins");
    fs::copy(PD_SOURCE_DIR "/examples/plugin/fan.py", dir_ / "plugins");
    fs::copy(PD_SOURCE_DIR "/examples/plugin/fan.json", dir_ / "plugins");
    std::ofstream(dir_ / "square.txt") << "0 0\n4 0\n4 4\n0 4\n";
    std::ofstream(dir_ / "ell.txt") << "0 0\n2 0\n2 1\n1 1\n1 2\n0 2\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A triangulation plug-in called `name` whose answer to each polygon is `answer` (Python).
  void add_plugin(const std::string& name, const std::string& answer) {
    std::ofstream(dir_ / "plugins" / (name + ".py")) << python_plugin(answer);
    std::ofstream(dir_ / "plugins" / (name + ".json"))
        << "{\"name\": \"" << name << "\", \"kind\": \"triangulation\", \"time_bound\": \"n\", "
        << "\"pieces_bound\": \"== n-2\", \"command\": [\"/usr/bin/python3\", \"" << name << ".py\"]}\n";
  }

  Result run(const std::string& program, const std::string& args) { return command::run(program + " " + args, dir_); }
  Result cli(const std::string& args) { return run(PD_CLI, args + " --plugins " + (dir_ / "plugins").string()); }
  Result run_on(const std::string& algorithm, const std::string& polygon) {
    return cli("run --json --algorithm " + algorithm + " --input " + (dir_ / polygon).string());
  }

  fs::path dir_;
};

TEST_F(Plugins, AreListedWithTheirManifestsFields) {
  const Result r = cli("list --json");
  ASSERT_EQ(r.status, 0) << r.err;
  bool found = false;
  for (const Json& a : parse_json(r.out).items) {
    if (a.get("name")->text != "example-fan") continue;
    found = true;
    EXPECT_EQ(a.get("kind")->text, "triangulation");
    EXPECT_EQ(a.get("time_bound")->text, "n");
    EXPECT_TRUE(a.get("accepts")->get("convex_only")->boolean);
    EXPECT_EQ(a.get("peer")->text, "external (fan.json)");
  }
  EXPECT_TRUE(found) << r.out;
}

TEST_F(Plugins, RunsAndIsValidatedLikeARegisteredAlgorithm) {
  const Result r = run_on("example-fan", "square.txt");
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = parse_json(r.out);
  EXPECT_EQ(j.get("piece_count")->number(), 2);
  EXPECT_TRUE(j.get("valid")->boolean);
  EXPECT_GE(j.get("seconds")->number(), 0);
}

TEST_F(Plugins, InputItDoesNotTakeIsRefusedBeforeRunning) {
  const Result r = run_on("example-fan", "ell.txt");
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "error: example-fan takes only convex polygons; this one has 1 reflex vertex\n");
}

TEST_F(Plugins, AWrongDecompositionIsReportedInvalid) {
  add_plugin("one-triangle", "    print(json.dumps({'pieces': [[0, 1, 2]], 'steiner': [], 'seconds': 0}), flush=True)");
  const Result r = run_on("one-triangle", "square.txt");
  ASSERT_EQ(r.status, 5) << r.err;
  EXPECT_FALSE(parse_json(r.out).get("valid")->boolean);
  EXPECT_EQ(r.err.rfind("error: the result of one-triangle is not valid: ", 0), 0u) << r.err;
}

TEST_F(Plugins, ExactSteinerPointsAreRead) {
  // The square cut into four triangles at its centre, given as the rational "4/2".
  add_plugin("centre", "    print(json.dumps({'pieces': [[0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]], "
                       "'steiner': [['4/2', 2]], 'seconds': 0}), flush=True)");
  const Result r = cli("run --json --algorithm centre --no-validate --input " + (dir_ / "square.txt").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const Json j = parse_json(r.out);
  EXPECT_EQ(j.get("steiner_count")->number(), 1);
  EXPECT_EQ(j.get("points")->items[4].items[0].number(), 2);
}

TEST_F(Plugins, ACrashIsThatRunsFailure) {
  add_plugin("crash", "    import os, signal; os.kill(os.getpid(), signal.SIGSEGV)");
  const Result r = run_on("crash", "square.txt");
  EXPECT_EQ(r.status, 4);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "error: crash failed: crash: crashed (signal 11) before answering\n");
}

TEST_F(Plugins, AnExitIsThatRunsFailure) {
  add_plugin("quits", "    sys.exit(7)");
  const Result r = run_on("quits", "square.txt");
  EXPECT_EQ(r.status, 4);
  EXPECT_EQ(r.err, "error: quits failed: quits: exited with status 7 before answering\n");
}

TEST_F(Plugins, GarbageIsThatRunsFailure) {
  add_plugin("garbage", "    print('hello', flush=True)");
  const Result r = run_on("garbage", "square.txt");
  EXPECT_EQ(r.status, 4);
  EXPECT_EQ(r.err.rfind("error: garbage failed: garbage: printed a line that is not JSON", 0), 0u) << r.err;
  add_plugin("no-pieces", "    print(json.dumps({'pieces': [[0, 1, 99]]}), flush=True)");
  const Result bad_index = run_on("no-pieces", "square.txt");
  EXPECT_EQ(bad_index.status, 4);
  EXPECT_NE(bad_index.err.find("does not keep the protocol (a piece index is a whole number below 4)"), std::string::npos)
      << bad_index.err;
}

TEST_F(Plugins, ARefusalIsThatRunsFailure) {
  add_plugin("refuses", "    print(json.dumps({'error': 'too many vertices'}), flush=True)");
  const Result r = run_on("refuses", "square.txt");
  EXPECT_EQ(r.status, 4);
  EXPECT_EQ(r.err, "error: refuses failed: refused: 'too many vertices'\n");
}

TEST_F(Plugins, AHangIsStoppedByMaxSeconds) {
  add_plugin("hangs", "    import time; time.sleep(3600)");
  const Result r = cli("run --json --algorithm hangs --max-seconds 1 --input " + (dir_ / "square.txt").string());
  EXPECT_EQ(r.status, 4);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "error: hangs stopped after 1 s (--max-seconds)\n");
}

TEST_F(Plugins, ABrokenManifestIsNamed) {
  std::ofstream(dir_ / "plugins" / "broken.json") << "{\"name\": \"broken\", \"kind\": \"triangulation\"}\n";
  const Result r = cli("list");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "error: " + (dir_ / "plugins" / "broken.json").string() + ": \"command\" must name the program to run\n");
  const Result missing = run(PD_CLI, "list --plugins " + (dir_ / "no-such-folder").string());
  EXPECT_EQ(missing.status, 2);
  EXPECT_EQ(missing.err, "error: " + (dir_ / "no-such-folder").string() + ": not a folder of plug-in manifests\n");
}

// A sweep of the example plug-in on convex polygons (taken) and combs (refused before running).
void write_tiny_sweep(const fs::path& file) {
  std::ofstream(file)
      << "{\"tiny\": {\"description\": \"the example plug-in\", \"algorithms\": [\"example-fan\"], "
         "\"seeds\": [1], \"min_time\": 0.001, \"budget_seconds\": 1, \"timeout_seconds\": 20, "
         "\"curves\": [{\"vs\": \"n\", \"families\": [\"convex\", \"comb\"], \"r\": [\"default\"], \"n\": [20, 40]}]}}\n";
}

// The records of a journal or of an assembled results file's "benchmarks": 2 ok, 2 refused.
void expect_tiny_sweep_results(const std::vector<Json>& records) {
  int ok = 0, refused = 0;
  for (const Json& j : records) {
    const Json* status = j.get("status");
    if (status == nullptr) continue;
    const std::string line = j.get("name")->text;
    if (status->text == "ok") {
      ++ok;
      EXPECT_EQ(j.get("valid")->number(), 1) << line;
      EXPECT_EQ(j.get("pieces")->number(), j.get("n")->number() - 2) << line;
    } else {
      ++refused;
      EXPECT_NE(j.get("error_message")->text.find("takes only convex polygons"), std::string::npos) << line;
    }
  }
  EXPECT_EQ(ok, 2);       // convex n = 20, 40
  EXPECT_EQ(refused, 2);  // comb n = 20, 40: skipped before running
}

TEST_F(Plugins, AreBenchmarkedByTheHarness) {
  write_tiny_sweep(dir_ / "sweeps.json");
  const Result r = run(PD_BENCH, "--sweep tiny --sweeps " + (dir_ / "sweeps.json").string() + " --out " +
                                     dir_.string() + " --plugins " + (dir_ / "plugins").string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream journal(dir_ / "tiny.journal.jsonl");
  std::vector<Json> records;
  for (std::string line; std::getline(journal, line);) records.push_back(parse_json(line));
  expect_tiny_sweep_results(records);
}

TEST_F(Plugins, AreSweptBySweepPy) {
  write_tiny_sweep(dir_ / "sweeps.json");
  const std::string build = fs::path(PD_CLI).parent_path().string();
  const Result r = run("/usr/bin/python3 " PD_SOURCE_DIR "/analysis/sweep.py",
                       "--sweep tiny --sweeps " + (dir_ / "sweeps.json").string() + " --build " + build +
                           " --results " + dir_.string() + " --no-analysis --plugins " + (dir_ / "plugins").string());
  ASSERT_EQ(r.status, 0) << r.err;
  expect_tiny_sweep_results(parse_json(slurp(dir_ / "tiny.json")).get("benchmarks")->items);
}

}  // namespace
}  // namespace pd
