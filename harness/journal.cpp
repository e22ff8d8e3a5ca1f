#include "harness/journal.h"

#include "core/json.h"
#include "harness/write_all.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace pd {
namespace {

double seconds_per_unit(const std::string& unit) {
  if (unit == "ns") return 1e-9;
  if (unit == "us") return 1e-6;
  if (unit == "ms") return 1e-3;
  return 1;
}

bool ends_in_torn_line(int fd) {
  const off_t size = lseek(fd, 0, SEEK_END);
  char last = '\n';
  return size > 0 && pread(fd, &last, 1, size - 1) == 1 && last != '\n';
}

std::string text_of(const Json& object, const std::string& key) {
  const Json* v = object.get(key);
  return v ? v->text : std::string();
}

}  // namespace

Journal::Journal(const std::string& path) {
  fd_ = open(path.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw std::runtime_error("cannot open journal " + path + ": " + std::strerror(errno));
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    close(fd_);
    throw std::runtime_error(path + " is in use: another polydecomp-bench is running this sweep");
  }
  needs_newline_ = ends_in_torn_line(fd_);
}

Journal::~Journal() { close(fd_); }

void Journal::append(const std::string& object) {
  const std::string line = (needs_newline_ ? "\n" : "") + object + "\n";
  needs_newline_ = false;
  if (!write_all(fd_, line)) throw std::runtime_error(std::string("cannot write the journal: ") + std::strerror(errno));
}

std::map<std::string, JournalRecord> Journal::finished(const std::string& path) {
  std::map<std::string, JournalRecord> records;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    Json object;
    try {
      object = parse_json(line);
    } catch (const JsonError&) {
      continue;  // a torn line: that key did not finish
    }
    const Json* name = object.is_object() ? object.get("name") : nullptr;
    if (!name) continue;
    JournalRecord r;
    r.status = text_of(object, "status");
    r.error_message = text_of(object, "error_message");
    const Json* real_time = object.get("real_time");
    if (real_time && real_time->is_number()) r.seconds = real_time->number() * seconds_per_unit(text_of(object, "time_unit"));
    records[name->text] = r;
  }
  return records;
}

}  // namespace pd
