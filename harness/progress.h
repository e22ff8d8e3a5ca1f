// Progress lines on stderr: the sweep's (Progress) and a single run's (Heartbeat).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

namespace pd {

// The sweep's progress line: keys (or other units) done of total, the current key, time elapsed and an
// estimate of the time left. On a terminal the line is redrawn in place; otherwise (a log file, a batch job) a new line
// is written at most every ten seconds, so logs stay short.
class Progress {
 public:
  Progress(std::string title, std::size_t total, std::string unit = "keys");

  void started(const std::string& key);   // a key begins to run
  void finished(const std::string& key);  // a key is done (run, failed or skipped)
  void end();                             // the sweep is over (or stopping): finish the line

 private:
  void show(const std::string& key, bool force);
  double elapsed() const;

  std::string title_;
  std::size_t total_, done_ = 0;
  std::string unit_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  double last_shown_ = -1e9;
  bool terminal_;
  bool line_open_ = false;
};

// While `polydecomp run` works on one polygon, a line saying what runs and for how long, drawn once
// the run has taken two seconds and redrawn every second until the object is destroyed, which erases
// it. Only when stderr is a terminal: scripts and logs see the contract's output alone.
class Heartbeat {
 public:
  explicit Heartbeat(std::string what);
  ~Heartbeat();
  Heartbeat(const Heartbeat&) = delete;
  Heartbeat& operator=(const Heartbeat&) = delete;

 private:
  void beat();

  std::string what_;
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace pd
