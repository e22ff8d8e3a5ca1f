#include "harness/run.h"

#include "core/io.h"
#include "core/validate.h"
#include "harness/last_resort.h"
#include "harness/write_all.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <functional>
#include <new>
#include <sstream>
#include <stdexcept>

namespace pd {
namespace {

// One part's pieces and validation; `reason` is empty when they are valid or were not validated.
struct PartCheck {
  std::vector<Piece> pieces;
  std::optional<bool> valid;
  std::string reason;
};

PartCheck check_part(const Algorithm& algo, const Polygon& polygon, const Decomposition& d, bool validate_result) {
  PartCheck c;
  try {
    c.pieces = pieces_of(polygon, d);
  } catch (const std::invalid_argument& e) {
    c.valid = false;
    c.reason = e.what();
  }
  if (validate_result && !c.valid) {
    const Validation v = validate_pieces(polygon, d, c.pieces, algo.kind, algo.steiner);
    c.valid = v.ok;
    c.reason = v.reason;
  }
  return c;
}

// The result's pieces, validation and report, over every part.
RunOutput report(const Algorithm& algo, const std::vector<Polygon>& parts, const std::vector<Decomposition>& ds,
                 const Counters& counters, double seconds, const RunOptions& options) {
  std::vector<PartCheck> checks;
  std::vector<PartResult> results;
  std::optional<bool> valid;
  std::string reason;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    checks.push_back(check_part(algo, parts[k], ds[k], options.validate));
    if (checks[k].valid) valid = valid.value_or(true) && *checks[k].valid;
    if (reason.empty() && !checks[k].reason.empty())
      reason = (parts.size() > 1 ? "part " + std::to_string(k) + ": " : "") + checks[k].reason;
  }
  for (std::size_t k = 0; k < parts.size(); ++k) results.push_back({&parts[k], &ds[k], &checks[k].pieces});
  RunOutput result;
  if (options.json) {
    result.out = run_json({algo.name, results, valid, seconds, &counters});
  } else {
    const RunTotals t = totals_of(results);
    result.out = algo.name + ": n=" + std::to_string(t.n) + " reflex=" + std::to_string(t.reflex) +
                 count_text("holes", t.holes, t.holes > 0) + count_text("parts", parts.size(), parts.size() > 1) +
                 " pieces=" + std::to_string(t.pieces) + " steiner=" + std::to_string(t.steiner) +
                 (valid ? std::string(" valid=") + (*valid ? "yes" : "NO (" + reason + ")") : "") +
                 " seconds=" + double_text(seconds) + "\n";
  }
  if (valid == false) result.invalid = reason.empty() ? "no reason given" : reason;
  if (options.svg) result.svg = run_svg(results, algo.name);
  return result;
}

// The run in this process: the algorithm on each part in turn, then the report.
RunOutput run_here(const Algorithm& algo, const std::vector<Polygon>& parts, const RunOptions& options) {
  Counters counters;
  std::vector<Decomposition> ds(parts.size());
  double seconds = 0;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    Counters part_counters;
    const auto start = std::chrono::steady_clock::now();
    try {
      ds[k] = algo.run(parts[k], part_counters);
    } catch (const std::bad_alloc&) {
      throw Exit{kAlgorithmFailed, algo.name + " ran out of memory" + options.memory_note};
    } catch (const std::exception& e) {
      throw Exit{kAlgorithmFailed, algo.name + " failed" + (parts.size() > 1 ? " on part " + std::to_string(k) : "") +
                                       ": " + e.what()};
    }
    seconds += ds[k].own_seconds ? *ds[k].own_seconds
                                 : std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const auto& [name, value] : part_counters) counters[name] += value;
  }
  try {
    return report(algo, parts, ds, counters, seconds, options);
  } catch (const std::bad_alloc&) {
    throw Exit{kAlgorithmFailed, "out of memory validating and reporting " + algo.name + "'s result" + options.memory_note};
  }
}

// --max-seconds: `compute` runs in a forked child, which sends back its output (or its Exit) through a
// pipe; at the deadline the parent kills the child and fails with one error line. A separate process is
// the one safe way to stop an algorithm anywhere (inside GMP, inside CGAL) without its cooperation, and
// nothing is written until the child has finished, so a stopped run leaves no partial output. The
// child dies with its parent (a killed `run` leaves nothing running).
// The message format: "STATUS\n" then, for status 0, "OUT_LENGTH SVG_LENGTH\n" + out + svg + invalid;
// otherwise the Exit message.
std::string encode(const RunOutput& r) {
  return "0\n" + std::to_string(r.out.size()) + " " + std::to_string(r.svg.size()) + "\n" + r.out + r.svg + r.invalid;
}
std::string encode(const Exit& e) { return std::to_string(e.status) + "\n" + e.message; }

RunOutput decode(const std::string& message) {
  std::size_t at = message.find('\n');
  const int status = std::stoi(message.substr(0, at));
  std::string rest = message.substr(at + 1);
  if (status != 0) throw Exit{status, rest};
  at = rest.find('\n');
  std::istringstream lengths(rest.substr(0, at));
  std::size_t out_length = 0, svg_length = 0;
  lengths >> out_length >> svg_length;
  const std::string body = rest.substr(at + 1);
  return {body.substr(0, out_length), body.substr(out_length, svg_length), body.substr(out_length + svg_length)};
}

// Reads the pipe to its end, or returns false at the deadline.
bool read_until(int fd, std::chrono::steady_clock::time_point deadline, std::string& message) {
  char buffer[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd wait_for{fd, POLLIN, 0};
    const int ready = ::poll(&wait_for, 1, static_cast<int>(std::min<std::int64_t>(left.count(), 1 << 30)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) return false;
    const ssize_t k = ::read(fd, buffer, sizeof buffer);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return true;
    message.append(buffer, static_cast<std::size_t>(k));
  }
}

[[noreturn]] void run_child(int parent, int fd, const std::string& name, const RunOptions& options,
                            const std::function<RunOutput()>& compute) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(0);  // the parent died before the line above
  // Another thread's pipes (another call's deadline, a plug-in's) must not stay open here: their
  // readers wait for the end of file that only their own writer's exit gives.
  if (options.close_inherited) {
    if (fd > 3) ::close_range(3, static_cast<unsigned>(fd) - 1, 0);
    ::close_range(static_cast<unsigned>(fd) + 1, ~0U, 0);
  }
  send_last_resort_reports_to(fd);
  std::string message;
  try {
    message = encode(compute());
  } catch (const Exit& e) {
    message = encode(e);
  } catch (const std::bad_alloc&) {
    message = encode(Exit{kAlgorithmFailed, name + " ran out of memory" + options.memory_note});
  } catch (const std::exception& e) {
    message = encode(Exit{kAlgorithmFailed, name + " failed: " + e.what()});
  }
  write_all(fd, message);
  ::_exit(0);
}

RunOutput with_deadline(const std::string& name, double max_seconds, const RunOptions& options,
                        const std::function<RunOutput()>& compute) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw Exit{kAlgorithmFailed, "cannot create a pipe for --max-seconds"};
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                               std::chrono::duration<double>(max_seconds));
  const pid_t parent = ::getpid();
  const pid_t child = ::fork();
  if (child < 0) throw Exit{kAlgorithmFailed, "cannot fork for --max-seconds"};
  if (child == 0) {
    ::close(fds[0]);
    run_child(parent, fds[1], name, options, compute);
  }
  ::close(fds[1]);
  std::string message;
  const bool finished = read_until(fds[0], deadline, message);
  ::close(fds[0]);
  if (!finished) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (!finished) throw Exit{kAlgorithmFailed, name + " stopped after " + double_text(max_seconds) + " s (--max-seconds)"};
  if (WIFSIGNALED(status)) throw Exit{kAlgorithmFailed, name + " crashed (signal " + std::to_string(WTERMSIG(status)) + ")"};
  if (message.empty()) throw Exit{kAlgorithmFailed, name + " ended without a result"};
  return decode(message);
}

}  // namespace

void check_accepted(const Algorithm& algo, const std::vector<Polygon>& parts) {
  for (std::size_t k = 0; k < parts.size(); ++k)
    if (const auto why = refusal(algo, parts[k]))
      throw Exit{kBadPolygon, (parts.size() > 1 ? "part " + std::to_string(k) + ": " : "") + *why};
}

RunOutput run_algorithm(const Algorithm& algo, const std::vector<Polygon>& parts, const RunOptions& options) {
  const auto compute = [&] { return run_here(algo, parts, options); };
  return options.max_seconds ? with_deadline(algo.name, *options.max_seconds, options, compute) : compute();
}

std::string count_text(const char* name, std::size_t value, bool shown) {
  return shown ? std::string(" ") + name + "=" + std::to_string(value) : "";
}

}  // namespace pd
