#include "harness/plugins.h"

#include "core/coordinate.h"
#include "core/io.h"
#include "core/json.h"
#include "core/registry.h"
#include "harness/write_all.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>

namespace pd {
namespace {

namespace fs = std::filesystem;

// ---- the manifest ----

std::string read_file(const fs::path& path) {
  std::optional<std::string> text = read_file_bytes(path.string());
  if (!text) throw PluginError(path.string() + ": cannot read it");
  return std::move(*text);
}

class ManifestReader {
 public:
  ManifestReader(const fs::path& path, const Json& json) : path_(path), json_(json) {
    if (!json_.is_object()) fail("a manifest is one JSON object");
  }

  [[noreturn]] void fail(const std::string& why) const { throw PluginError(path_.string() + ": " + why); }

  const Json* field(const Json& in, const std::string& key, Json::Type type, const char* what) const {
    const Json* v = in.get(key);
    if (v != nullptr && v->type != type) fail("\"" + key + "\" must be " + what);
    return v;
  }
  std::string text(const std::string& key, bool required) const {
    const Json* v = field(json_, key, Json::Type::String, "a string");
    if (v == nullptr && required) fail("\"" + key + "\" is missing");
    return v ? v->text : "";
  }
  bool flag(const Json& in, const std::string& key) const {
    const Json* v = field(in, key, Json::Type::Bool, "true or false");
    return v != nullptr && v->boolean;
  }
  std::size_t count(const Json& in, const std::string& key, std::size_t otherwise) const {
    const Json* v = field(in, key, Json::Type::Number, "a whole number");
    if (v == nullptr) return otherwise;
    const double d = v->number();
    if (!(d >= 1 && d <= 1e12 && d == static_cast<double>(static_cast<std::size_t>(d))))
      fail("\"" + key + "\" must be a whole number from 1 to 10^12");
    return static_cast<std::size_t>(d);
  }
  Kind kind() const {
    const std::string k = text("kind", true);
    for (Kind candidate : {Kind::Triangulation, Kind::Partition, Kind::Convex, Kind::Cut})
      if (k == kind_name(candidate)) return candidate;
    fail("\"kind\" must be triangulation, partition, convex or cut, not \"" + k + "\"");
  }
  Accepts accepts() const {
    Accepts a;
    const Json* v = field(json_, "accepts", Json::Type::Object, "an object");
    if (v == nullptr) return a;
    a.holes = flag(*v, "holes");
    a.convex_only = flag(*v, "convex_only");
    a.max_vertices = count(*v, "max_vertices", 0);
    return a;
  }
  std::vector<std::string> command() const {
    const Json* v = field(json_, "command", Json::Type::Array, "an array of strings");
    if (v == nullptr || v->items.empty()) fail("\"command\" must name the program to run");
    std::vector<std::string> argv;
    for (const Json& word : v->items) {
      if (word.type != Json::Type::String || word.text.empty()) fail("\"command\" must be an array of strings");
      argv.push_back(word.text);
    }
    return argv;
  }
  std::size_t size_ceiling() const { return count(json_, "size_ceiling", 1000000); }

 private:
  const fs::path& path_;
  const Json& json_;
};

// ---- the process ----

[[noreturn]] void start_child(const std::vector<std::string>& argv, const fs::path& folder, int input, int output,
                              int status) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);  // dies with polydecomp, whatever ends it
  if (::dup2(input, STDIN_FILENO) < 0 || ::dup2(output, STDOUT_FILENO) < 0 || ::chdir(folder.c_str()) != 0) {
    const int e = errno;
    (void)!::write(status, &e, sizeof e);
    ::_exit(127);
  }
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  ::execvp(args[0], args.data());
  const int e = errno;
  (void)!::write(status, &e, sizeof e);
  ::_exit(127);
}

// The thread that forks the commands. A child's parent-death signal fires when the thread that forked
// it ends, not the process; the commands are forked from this one thread, which lives as long as its
// process, so that a command outlives the call that started it (the Python module runs each call on a
// thread of its own) and still dies with polydecomp. Only a host whose calls come from threads that
// end uses it (use_plugin_launcher: the Python module, which makes it at import, before other threads
// run); a forked copy of the host (max_seconds's child, one thread) makes its own, unlocked. The
// command line forks from its run thread, which lives as long as it does.
class Launcher {
 public:
  static Launcher& of_this_process() {
    static Launcher* launcher = nullptr;  // never destroyed: its thread waits until the process ends
    if (launcher == nullptr || launcher->owner_ != ::getpid()) launcher = new Launcher;
    return *launcher;
  }

  // Runs `task` on the launcher's thread and returns when it is done.
  void run(const std::function<void()>& task) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return task_ == nullptr; });
    task_ = &task;
    bool finished = false;
    finished_ = &finished;
    ready_.notify_one();
    done_.wait(lock, [&] { return finished; });
  }

 private:
  // Returns once the thread waits for tasks, so that no fork meets it starting up (holding an allocator's
  // lock that the child would then wait for).
  Launcher() : owner_(::getpid()) {
    std::unique_lock<std::mutex> lock(mutex_);
    std::thread([this] { serve(); }).detach();
    done_.wait(lock, [&] { return serving_; });
  }

  void serve() {
    std::unique_lock<std::mutex> lock(mutex_);
    serving_ = true;
    done_.notify_all();
    for (;;) {
      ready_.wait(lock, [&] { return task_ != nullptr; });
      (*task_)();
      *finished_ = true;
      task_ = nullptr;
      done_.notify_all();
    }
  }

  pid_t owner_;
  std::mutex mutex_;
  std::condition_variable ready_, done_;
  const std::function<void()>* task_ = nullptr;
  bool* finished_ = nullptr;
  bool serving_ = false;
};

bool launcher_in_use = false;

// One running command: a line written, a line read.
class PluginProcess {
 public:
  PluginProcess(std::string name, std::vector<std::string> argv, fs::path folder)
      : name_(std::move(name)), argv_(std::move(argv)), folder_(std::move(folder)) {}
  ~PluginProcess() { stop(); }

  // The line the command answers `request` with. Throws std::runtime_error (and stops the command) when
  // it cannot be started, exits or crashes before answering.
  // Calls from several threads (the Python module's) take turns: the command answers one line at a time.
  std::string exchange(const std::string& request) {
    const std::lock_guard<std::recursive_mutex> turn(turn_of_this_process());
    if (pid_ <= 0) start();
    if (!write_all(to_, request + "\n")) fail_ended();
    std::string line;
    if (!read_line(line)) fail_ended();
    return line;
  }

  // Stops the command and throws; in turn with exchange, so that no other call is using it.
  [[noreturn]] void fail(const std::string& why) {
    const std::lock_guard<std::recursive_mutex> turn(turn_of_this_process());
    stop();
    throw std::runtime_error(name_ + ": " + why);
  }

 private:
  // The lock calls take turns on. A forked copy of polydecomp (one thread) may have inherited it held
  // by another thread of the parent, and the parent's command with it: the copy takes a lock of its
  // own and forgets that command (its pipes are closed there: harness/run.cpp), then starts its own,
  // so that a copy stopped in mid-answer leaves no half line to the parent.
  std::recursive_mutex& turn_of_this_process() {
    if (turn_pid_ != ::getpid()) {
      (void)turn_.release();  // the parent's lock, held or not, is left as it was
      turn_ = std::make_unique<std::recursive_mutex>();
      turn_pid_ = ::getpid();
      pid_ = -1;
    }
    return *turn_;
  }

  void start() {
    // A command that has closed its input must not kill polydecomp with SIGPIPE on the next write.
    ::signal(SIGPIPE, SIG_IGN);
    // Close-on-exec: a command started meanwhile by another thread must not hold these pipes open.
    int in[2], out[2], status[2];
    if (::pipe2(in, O_CLOEXEC) != 0 || ::pipe2(out, O_CLOEXEC) != 0 || ::pipe2(status, O_CLOEXEC) != 0)
      throw std::runtime_error(name_ + ": cannot create pipes");
    pid_t pid = -1;
    const std::function<void()> fork_command = [&] {
      pid = ::fork();
      if (pid == 0) {
        ::close(in[1]);
        ::close(out[0]);
        ::close(status[0]);
        start_child(argv_, folder_, in[0], out[1], status[1]);
      }
    };
    if (launcher_in_use) Launcher::of_this_process().run(fork_command);
    else fork_command();
    if (pid < 0) throw std::runtime_error(name_ + ": cannot fork");
    ::close(in[0]);
    ::close(out[1]);
    ::close(status[1]);
    pid_ = pid, to_ = in[1], from_ = out[0];
    buffer_.clear();
    int exec_errno = 0;
    const ssize_t k = ::read(status[0], &exec_errno, sizeof exec_errno);
    ::close(status[0]);
    if (k == static_cast<ssize_t>(sizeof exec_errno))
      fail("cannot start '" + argv_[0] + "' in " + folder_.string() + ": " + std::strerror(exec_errno));
  }

  void stop() {
    if (pid_ <= 0) return;
    ::close(to_);
    ::close(from_);
    ::kill(pid_, SIGKILL);
    reap();
  }

  int reap() {
    int status = 0;
    while (pid_ > 0 && ::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
  }

  [[noreturn]] void fail_ended() {
    ::close(to_);
    ::close(from_);
    const int status = reap();
    if (WIFSIGNALED(status))
      throw std::runtime_error(name_ + ": crashed (signal " + std::to_string(WTERMSIG(status)) + ") before answering");
    throw std::runtime_error(name_ + ": exited with status " + std::to_string(WEXITSTATUS(status)) +
                             " before answering");
  }

  bool read_line(std::string& line) {
    for (;;) {
      const std::size_t end = buffer_.find('\n');
      if (end != std::string::npos) {
        line = buffer_.substr(0, end);
        buffer_.erase(0, end + 1);
        return true;
      }
      char chunk[1 << 16];
      const ssize_t k = ::read(from_, chunk, sizeof chunk);
      if (k < 0 && errno == EINTR) continue;
      if (k <= 0) return false;
      buffer_.append(chunk, static_cast<std::size_t>(k));
    }
  }

  std::string name_;
  std::vector<std::string> argv_;
  fs::path folder_;
  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
  std::unique_ptr<std::recursive_mutex> turn_ = std::make_unique<std::recursive_mutex>();
  pid_t turn_pid_ = ::getpid();  // the process turn_ belongs to
  std::string buffer_;
};

// ---- the protocol ----

// The outer ring counter-clockwise as "points", each hole clockwise in "holes": vertex ids in order.
std::string request_line(const Polygon& p) {
  auto ring = [&](std::size_t k) {
    std::string text = "[";
    for (std::size_t i = p.ring_begin(k); i < p.ring_end(k); ++i)
      text += std::string(i > p.ring_begin(k) ? ", [" : "[") + double_text(p[i].x()) + ", " + double_text(p[i].y()) + "]";
    return text + "]";
  };
  std::string line = "{\"points\": " + ring(0) + ", \"holes\": [";
  for (std::size_t k = 1; k < p.ring_count(); ++k) line += (k > 1 ? ", " : "") + ring(k);
  return line + "]}";
}

// A coordinate of the protocol: a JSON number, or an exact rational as the string "p/q".
Rational coordinate(const Json& v) {
  if (v.is_number()) return Rational(v.number());
  const auto digits = [](const std::string& s, std::size_t from) {
    return s.size() > from && s.find_first_not_of("0123456789", from) == std::string::npos;
  };
  if (v.type == Json::Type::String) {
    const std::size_t slash = v.text.find('/');
    const std::string num = v.text.substr(0, slash), den = slash == std::string::npos ? "1" : v.text.substr(slash + 1);
    if (digits(num, num[0] == '-' ? 1 : 0) && digits(den, 0) && den.find_first_not_of('0') != std::string::npos)
      return Rational(num) / Rational(den);  // the quotient is canonical, whatever the digits
  }
  throw std::invalid_argument("a coordinate is a number or a string \"p/q\"");
}

Decomposition decomposition_of(const Json& result, std::size_t n) {
  const Json* pieces = result.get("pieces");
  if (pieces == nullptr || !pieces->is_array()) throw std::invalid_argument("no \"pieces\" array");
  Decomposition d;
  if (const Json* steiner = result.get("steiner")) {
    if (!steiner->is_array()) throw std::invalid_argument("\"steiner\" is not an array");
    for (const Json& point : steiner->items) {
      if (!point.is_array() || point.items.size() != 2) throw std::invalid_argument("a Steiner point is [x, y]");
      d.add_steiner(QPoint(coordinate(point.items[0]), coordinate(point.items[1])));
    }
  }
  const double ids = static_cast<double>(n + d.steiner.size());
  d.pieces.emplace();
  for (const Json& piece : pieces->items) {
    if (!piece.is_array()) throw std::invalid_argument("a piece is an array of indices");
    Piece cycle;
    for (const Json& id : piece.items) {
      const double v = id.is_number() ? id.number() : -1;
      if (!(v >= 0 && v < ids && v == static_cast<double>(static_cast<VertexId>(v))))
        throw std::invalid_argument("a piece index is a whole number below " + double_text(ids));
      cycle.push_back(static_cast<VertexId>(v));
    }
    d.pieces->push_back(std::move(cycle));
  }
  if (const Json* seconds = result.get("seconds")) {
    if (!seconds->is_number() || !(seconds->number() >= 0)) throw std::invalid_argument("\"seconds\" is not a time");
    d.own_seconds = seconds->number();
  }
  return d;
}

// The registered algorithm's run: one exchange with the command.
Decomposition run_plugin(PluginProcess& process, const Polygon& p) {
  const std::string line = process.exchange(request_line(p));
  Json result;
  try {
    result = parse_json(line);
  } catch (const JsonError& e) {
    process.fail("printed a line that is not JSON (" + std::string(e.what()) + "): " + quoted_input(line, 200));
  }
  if (!result.is_object()) process.fail("printed a line that is not a JSON object: " + quoted_input(line, 200));
  if (const Json* error = result.get("error")) {
    throw std::runtime_error("refused: " + quoted_input(error->type == Json::Type::String ? error->text : line, 200));
  }
  try {
    return decomposition_of(result, p.size());
  } catch (const std::invalid_argument& e) {
    process.fail("printed a result that does not keep the protocol (" + std::string(e.what()) + ")");
  }
}

Algorithm algorithm_of(const fs::path& path) {
  const Json json = [&] {
    try {
      return parse_json(read_file(path));
    } catch (const JsonError& e) {
      throw PluginError(path.string() + ": " + e.what());
    }
  }();
  const ManifestReader m(path, json);
  Algorithm a;
  a.name = m.text("name", true);
  a.kind = m.kind();
  a.steiner = m.flag(json, "steiner");
  a.optimal = m.flag(json, "optimal");
  a.time_bound = m.text("time_bound", false);
  a.pieces_bound = m.text("pieces_bound", false);
  a.source = m.text("source", false);
  a.peer = m.text("peer", false);
  if (a.peer.empty()) a.peer = "external (" + path.filename().string() + ")";
  a.accepts = m.accepts();
  a.size_ceiling = m.size_ceiling();
  a.times_itself = true;
  auto process = std::make_shared<PluginProcess>(a.name, m.command(), fs::absolute(path).parent_path());
  a.run = [process](const Polygon& p, Counters&) { return run_plugin(*process, p); };
  return a;
}

}  // namespace

std::vector<std::string> plugin_folders(const std::vector<std::string>& given) {
  std::vector<std::string> folders{PD_SOURCE_DIR "/peers"};
  folders.insert(folders.end(), given.begin(), given.end());
  if (const char* env = std::getenv("POLYDECOMP_PLUGINS")) {
    std::stringstream list(env);
    for (std::string folder; std::getline(list, folder, ':');)
      if (!folder.empty()) folders.push_back(folder);
  }
  return folders;
}

void use_plugin_launcher() {
  launcher_in_use = true;
  Launcher::of_this_process();
}

void register_plugins(const std::vector<std::string>& folders) {
  for (const std::string& folder : folders) {
    std::error_code error;
    if (!fs::is_directory(folder, error)) {
      if (folder == PD_SOURCE_DIR "/peers") continue;
      throw PluginError(folder + ": not a folder of plug-in manifests");
    }
    std::vector<fs::path> manifests;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.path().extension() == ".json") manifests.push_back(entry.path());
    std::sort(manifests.begin(), manifests.end());
    for (const fs::path& path : manifests) {
      Algorithm a = algorithm_of(path);
      if (const auto taken = taken_name(a))
        throw PluginError(path.string() + ": an algorithm named " + *taken + " exists already");
      register_algorithm(std::move(a));
    }
  }
}

}  // namespace pd
