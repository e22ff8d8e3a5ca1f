// The programs under test run as a user runs them: one command line, its standard output and error
// captured in files of the test's own scratch folder, no standard input. Shared by the command-line,
// cutting, plug-in and peer tests.
#pragma once

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace pd::command {

namespace fs = std::filesystem;

struct Result {
  int status;  // the exit status, or -1 when the command did not exit
  std::string out, err;
};

inline std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `command_line` through the shell, its output in `scratch`.
inline Result run(const std::string& command_line, const fs::path& scratch) {
  const fs::path out = scratch / "stdout", err = scratch / "stderr";
  const std::string command = command_line + " >" + out.string() + " 2>" + err.string() + " </dev/null";
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
}

// A new scratch folder for the running test, named after `prefix`, the process and the test.
inline fs::path scratch_folder(const std::string& prefix) {
  const fs::path dir = fs::temp_directory_path() / (prefix + "-" + std::to_string(::getpid()) + "-" +
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name());
  fs::create_directories(dir);
  return dir;
}

}  // namespace pd::command
