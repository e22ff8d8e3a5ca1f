#include "harness/provenance.h"

#include <CGAL/version.h>
#include <boost/version.hpp>

#include <array>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <memory>
#include <thread>

namespace pd {
namespace {

std::string command_output(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  if (!pipe) return {};
  std::string out;
  std::array<char, 256> buf;
  while (std::fgets(buf.data(), buf.size(), pipe.get())) out += buf.data();
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> provenance() {
  const std::string git = "git -C '" PD_SOURCE_DIR "' ";
  std::string commit = command_output(git + "rev-parse HEAD 2>/dev/null");
  if (commit.empty()) commit = PD_GIT_COMMIT;
  // Dirty means changed sources: results/ is where sweeps write, so a resumed sweep is not "dirty".
  const std::string dirty =
      command_output(git + "status --porcelain --untracked-files=no -- . ':(exclude)results' 2>/dev/null");
  return {
      {"git_commit", commit},
      {"git_dirty", dirty.empty() ? "false" : "true"},
      {"compiler", "g++ " __VERSION__},
      {"cgal_version", CGAL_VERSION_STR},
      {"boost_version", BOOST_LIB_VERSION},
      {"build_type", PD_BUILD_TYPE},
      {"cpu", cpu_model()},
      {"cores", std::to_string(std::thread::hardware_concurrency())},
      {"host", command_output("uname -srm")},
      {"date", utc_now()},
  };
}

}  // namespace pd
