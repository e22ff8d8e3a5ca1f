// The sweep's progress line on stderr: keys done of total, the current key, time elapsed and an
// estimate of the time left. On a terminal the line is redrawn in place; otherwise (a log file, a
// batch job) a new line is written at most every ten seconds, so logs stay short.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace pd {

class Progress {
 public:
  Progress(std::string title, std::size_t total);

  void started(const std::string& key);   // a key begins to run
  void finished(const std::string& key);  // a key is done (run, failed or skipped)
  void end();                             // the sweep is over (or stopping): finish the line

 private:
  void show(const std::string& key, bool force);
  double elapsed() const;

  std::string title_;
  std::size_t total_, done_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double last_shown_ = -1e9;
  bool terminal_;
  bool line_open_ = false;
};

}  // namespace pd
