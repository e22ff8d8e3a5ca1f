// A sweep's journal: the record of everything the sweep finished, one JSON object per line, appended
// as each key finishes. It is what makes a sweep resumable and an interruption harmless: a line is
// written with one write(2) to a file opened O_APPEND, so a finished key is in the file (the page
// cache) even if the process is killed a moment later; a line torn by a machine crash does not parse
// and is ignored when the journal is read. analysis/polydecomp_analysis/results.py assembles the JSON and
// CSV from it.
//
// Lines: {"context": {...}} once per invocation (provenance); {"started": "key"} before a key runs, so
// that a driver can tell which key a crashed process was running; and one Google Benchmark run object
// per finished key ({"name": "key", ..., "status": "ok|invalid|failed|skipped"}).
#pragma once

#include <map>
#include <string>

namespace pd {

struct JournalRecord {
  std::string status;         // ok | invalid | failed | skipped
  std::string error_message;  // for failed and skipped keys
  double seconds = 0;         // real time per call of the algorithm, for ok and invalid keys
};

class Journal {
 public:
  // Opens (creating) the journal at `path` and locks it, so that two processes never run the same
  // sweep into one journal; throws std::runtime_error when it cannot.
  explicit Journal(const std::string& path);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  // Appends one JSON object (without newline) as one line.
  void append(const std::string& object);

  // The finished keys recorded in the journal at `path` (none when it does not exist), by name; a later
  // record of the same key replaces an earlier one.
  static std::map<std::string, JournalRecord> finished(const std::string& path);

 private:
  int fd_;
  bool needs_newline_;  // the file ended in a torn line
};

}  // namespace pd
