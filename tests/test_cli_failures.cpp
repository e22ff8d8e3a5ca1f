// The command line when the world fails it (docs/CONTRACT.md, "Errors"): output that cannot be
// written, output targets that are not regular files, limits on memory and stack, a killed parent, and
// the arguments a careless script passes. Each ends as one `error:` line and a documented exit status,
// never a silent exit 0, a replaced device, a bare signal or an orphan.
#include "tests/command.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)
#define PD_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PD_UNDER_ASAN 1
#endif
#endif

namespace pd {
namespace {

namespace fs = std::filesystem;

using command::Result;
using command::slurp;

class CliFailures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = command::scratch_folder("polydecomp-failures");
    square_ = (dir_ / "square.txt").string();
    std::ofstream(square_) << "0 0\n4 0\n4 4\n0 4\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  Result cli(const std::string& args) { return command::run(std::string(PD_CLI) + " " + args, dir_); }
  // The command with its standard output sent where `redirection` says (">/dev/full", ">&-").
  Result with_stdout(const std::string& args, const std::string& redirection) {
    const fs::path err = dir_ / "stderr";
    const std::string line = std::string(PD_CLI) + " " + args + " " + redirection + " 2>" + err.string() + " </dev/null";
    const int raw = std::system(line.c_str());
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, "", slurp(err)};
  }
  // The command under `ulimit -v KIB` (a limit on address space, as a shared machine sets).
  Result under_ulimit(std::size_t kib, const std::string& args) {
    return command::run("bash -c 'ulimit -v " + std::to_string(kib) + " && exec " + PD_CLI + " " + args + "'", dir_);
  }
  static void expect_one_error_line(const Result& r, int status, const std::string& start, const std::string& label) {
    EXPECT_EQ(r.status, status) << label << ": " << r.err;
    EXPECT_EQ(r.out, "") << label;
    EXPECT_EQ(r.err.rfind("error: " + start, 0), 0u) << label << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << label << ": " << r.err;
  }

  fs::path dir_;
  std::string square_;
};

const std::vector<std::string> kEveryOutput = {
    "list", "list --json", "list --markdown", "generate --family convex --n 5", "--help", "run --help", "corpus --help",
};

TEST_F(CliFailures, EveryWriteToAFullDeviceOrAClosedStdoutFails) {
  std::vector<std::string> commands = kEveryOutput;
  for (const std::string run : {"run --algorithm ear-n2 --input ", "run --json --algorithm ear-n2 --input ",
                                "cut --json --input ", "cut --input "})
    commands.push_back(run + square_);
  for (const std::string& args : commands) {
    Result r = with_stdout(args, ">/dev/full");
    EXPECT_EQ(r.status, 6) << args;
    EXPECT_EQ(r.err, "error: cannot write to the standard output: No space left on device\n") << args;
    r = with_stdout(args, ">&-");
    EXPECT_EQ(r.status, 6) << args;
    EXPECT_EQ(r.err, "error: cannot write to the standard output: Bad file descriptor\n") << args;
  }
}

// -o and --svg replace a regular file atomically (a failure leaves the old one) and write through
// anything else: a device stays a device, a FIFO a FIFO, a symbolic link a link to the file written.
TEST_F(CliFailures, OutputTargetsThatAreNotRegularFilesAreWrittenThrough) {
  const std::string generate = "generate --family convex --n 5 -o ";
  const std::string expected = cli("generate --family convex --n 5").out;
  ASSERT_EQ(cli(generate + "/dev/null").status, 0);
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  expect_one_error_line(cli(generate + "/dev/full"), 6, "cannot write /dev/full: No space left on device", "/dev/full");
  EXPECT_TRUE(fs::is_character_file("/dev/full"));

  const fs::path fifo = dir_ / "fifo", got = dir_ / "from-fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread reader([&] { std::ofstream(got) << slurp(fifo); });
  EXPECT_EQ(cli(generate + fifo.string()).status, 0);
  reader.join();
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(slurp(got), expected);

  const fs::path target = dir_ / "target.txt", link = dir_ / "link.txt", dangling = dir_ / "dangling.txt";
  std::ofstream(target) << "old";
  fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  fs::create_symlink(target, link);
  fs::create_symlink(dir_ / "new.txt", dangling);
  EXPECT_EQ(cli(generate + link.string()).status, 0);
  EXPECT_EQ(cli(generate + dangling.string()).status, 0);
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(slurp(target), expected);
  EXPECT_EQ(fs::status(target).permissions(), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  EXPECT_EQ(slurp(dir_ / "new.txt"), expected);
}

TEST_F(CliFailures, SvgTargetsThatCannotBeAFile) {
  const fs::path folder = dir_ / "figures";
  fs::create_directory(folder);
  const std::string run = "run --algorithm ear-n2 --input " + square_ + " --svg ";
  expect_one_error_line(cli(run + folder.string()), 6, "cannot write " + folder.string() + ": Is a directory", "DIR");
  for (const std::string stdout_name : {"-", "''"})
    expect_one_error_line(cli(run + stdout_name), 2, "--svg takes a file name", stdout_name);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir_)) left.push_back(entry.path().filename().string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"figures", "square.txt", "stderr", "stdout"}));  // no temporary left
}

// Out of memory and out of stack are failures of the run (exit 4), each one error line, with and
// without --max-seconds (whose child reports through the parent): reading a large file, a peer deep in
// CGAL's recursion, an exact program deep in GNU MP; and --max-memory's own guard. The limits are
// `ulimit -v` (address space), as a shared machine sets them.
TEST_F(CliFailures, OutOfMemoryAndStackAreOneErrorLine) {
#ifdef PD_UNDER_ASAN
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no ulimit -v under it";
#endif
  const fs::path big = dir_ / "convex.txt", spiral = dir_ / "spiral.txt", random = dir_ / "random.txt";
  ASSERT_EQ(cli("generate --family convex --n 2000000 -o " + big.string()).status, 0);
  ASSERT_EQ(cli("generate --family spiral --n 50000 -o " + spiral.string()).status, 0);
  ASSERT_EQ(cli("generate --family random --n 3000 -o " + random.string()).status, 0);
  for (const std::string deadline : {"", "--max-seconds 300 "}) {
    const std::string run = "run " + deadline + "--no-validate --algorithm ";
    expect_one_error_line(under_ulimit(100000, run + "ear-n2 --input " + big.string()), 4,
                          "out of memory reading " + big.string(), "large file " + deadline);
    expect_one_error_line(under_ulimit(250000, run + "chazelle-dobkin --input " + random.string()), 4,
                          "out of memory (GNU MP could not allocate)", "GNU MP " + deadline);
    // 60 MB leave no room for a stack thread: the recursion runs on the main thread's 256 KiB.
    const Result deep = command::run("bash -c 'ulimit -s 256 && ulimit -v 60000 && exec " + std::string(PD_CLI) + " " +
                                     run + "cgal-y-monotone --input " + spiral.string() + "'", dir_);
    expect_one_error_line(deep, 4, "out of stack (a recursion deeper than the stack allows)", "stack " + deadline);
  }
  expect_one_error_line(cli("run --max-memory 20M --algorithm ear-n2 --input " + big.string()), 4,
                        "out of memory", "--max-memory");
  EXPECT_NE(cli("run --max-memory 20M --algorithm ear-n2 --input " + big.string()).err.find("(--max-memory 20M)"),
            std::string::npos);
  expect_one_error_line(cli("run --max-memory 12Q --algorithm ear-n2 --input " + square_), 2,
                        "--max-memory takes a size", "12Q");
}

// Under a limit that leaves no room for the 1 GiB stack, CGAL's y-monotone partition still gets a stack
// deep enough for the spiral at n = 300,000 (it took the 8 MiB one and crashed).
TEST_F(CliFailures, ALimitedAddressSpaceStillGetsADeepStack) {
#ifdef PD_UNDER_ASAN
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: no ulimit -v under it";
#endif
  const fs::path spiral = dir_ / "spiral.txt";
  ASSERT_EQ(cli("generate --family spiral --n 300000 -o " + spiral.string()).status, 0);
  const Result r = under_ulimit(600000, "run --no-validate --algorithm cgal-y-monotone --input " + spiral.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("cgal-y-monotone: n=300000 ", 0), 0u) << r.out;
}

// `kill -TERM` of a `run --max-seconds` takes its child (the computation) with it.
TEST_F(CliFailures, AKilledRunLeavesNoChildRunning) {
  const fs::path big = dir_ / "random.txt", pid = dir_ / "pid", child = dir_ / "child";
  ASSERT_EQ(cli("generate --family random --n 3000 -o " + big.string()).status, 0);
  const std::string start = std::string(PD_CLI) + " run --algorithm diagonal-n4 --max-seconds 600 --input " +
                            big.string() + " >/dev/null 2>&1 & echo $! >" + pid.string();
  ASSERT_EQ(std::system(start.c_str()), 0);
  std::string children;
  for (int tries = 0; tries < 100 && children.empty(); ++tries) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::system(("pgrep -P $(cat " + pid.string() + ") >" + child.string()).c_str());
    children = slurp(child);
    children.erase(std::remove(children.begin(), children.end(), '\n'), children.end());
  }
  ASSERT_FALSE(children.empty()) << "the run started no child";
  ASSERT_EQ(std::system(("kill -TERM $(cat " + pid.string() + ")").c_str()), 0);
  bool gone = false;
  for (int tries = 0; tries < 100 && !gone; ++tries) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    gone = std::system(("kill -0 " + children + " 2>/dev/null").c_str()) != 0;
  }
  EXPECT_TRUE(gone) << "child " << children << " still runs";
}

TEST_F(CliFailures, EveryCommandHasItsHelp) {
  for (const std::string command : {"list", "generate", "run", "cut"}) {
    const Result r = cli(command + " --help");
    EXPECT_EQ(r.status, 0) << command << ": " << r.err;
    EXPECT_NE(r.out.find("polydecomp " + command + " "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--help"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "");
  }
}

TEST_F(CliFailures, NegativeCountsAreRefused) {
  expect_one_error_line(cli("generate --family convex --n -5"), 2, "the argument ('-5') for option '--n' is invalid", "n");
  expect_one_error_line(cli("generate --family convex --n 5 --seed -1"), 2, "the argument ('-1') for option '--seed' is invalid", "seed");
  expect_one_error_line(cli("generate --family comb --n 8 --reflex -1"), 2, "the argument ('-1') for option '--reflex' is invalid", "reflex");
  expect_one_error_line(cli("generate --family convex --n 5x"), 2, "the argument ('5x') for option '--n' is invalid", "5x");
}

TEST_F(CliFailures, FigureOfAPolygonAtTheEdgeOfTheDoubles) {
  const fs::path wide = dir_ / "wide.txt", svg = dir_ / "wide.svg";
  std::ofstream(wide) << "-1.7e308 -1.7e308\n1.7e308 -1.7e308\n0 1.7e308\n";
  ASSERT_EQ(cli("run --algorithm ear-n2 --input " + wide.string() + " --svg " + svg.string()).status, 0);
  const std::string figure = slurp(svg);
  EXPECT_NE(figure.find("<path"), std::string::npos);
  EXPECT_EQ(figure.find("nan"), std::string::npos) << figure;
  EXPECT_EQ(figure.find("inf"), std::string::npos) << figure;
}

TEST_F(CliFailures, StandardInputIsAnInput) {
  const Result r = command::run("(cat " + square_ + " | " + PD_CLI + " run --algorithm ear-n2 --input -)", dir_);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.rfind("ear-n2: n=4 ", 0), 0u) << r.out;
}

}  // namespace
}  // namespace pd
