#include "harness/progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace pd {
namespace {

constexpr double kLogInterval = 10;  // seconds between lines when stderr is not a terminal
constexpr auto kHeartbeatDelay = std::chrono::seconds(2), kHeartbeatInterval = std::chrono::seconds(1);

std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

std::size_t terminal_width() {
  winsize w{};
  return ioctl(STDERR_FILENO, TIOCGWINSZ, &w) == 0 && w.ws_col > 20 ? w.ws_col : 120;
}

}  // namespace

Progress::Progress(std::string title, std::size_t total, std::string unit)
    : title_(std::move(title)), total_(total), unit_(std::move(unit)), terminal_(isatty(STDERR_FILENO) != 0) {}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::started(const std::string& key) { show(key, false); }

void Progress::finished(const std::string& key) {
  ++done_;
  show(key, done_ == total_);
}

void Progress::end() {
  if (line_open_) std::fputc('\n', stderr);
  line_open_ = false;
}

void Progress::show(const std::string& key, bool force) {
  const double t = elapsed();
  if (!terminal_ && !force && t - last_shown_ < kLogInterval) return;
  last_shown_ = t;
  const std::string left = done_ > 0 ? ", ~" + clock_text(t / done_ * (total_ - done_)) + " left" : "";
  const int percent = total_ > 0 ? static_cast<int>(100 * done_ / total_) : 100;
  std::string line = title_ + ": " + std::to_string(done_) + "/" + std::to_string(total_) + " " + unit_ + " (" +
                     std::to_string(percent) + "%), " + clock_text(t) + " elapsed" + left + "  " + key;
  if (terminal_) {
    line.resize(std::min(line.size(), terminal_width() - 1));
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
    line_open_ = true;
  } else {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
  std::fflush(stderr);
}

Heartbeat::Heartbeat(std::string what) : what_(std::move(what)) {
  if (isatty(STDERR_FILENO)) thread_ = std::thread([this] { beat(); });
}

Heartbeat::~Heartbeat() {
  if (!thread_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  stop_.notify_one();
  thread_.join();
}

void Heartbeat::beat() {
  const auto start = std::chrono::steady_clock::now();
  std::unique_lock<std::mutex> lock(mutex_);
  bool drawn = false;
  for (auto next = start + kHeartbeatDelay; !stop_.wait_until(lock, next, [this] { return stopping_; });
       next += kHeartbeatInterval) {
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string line = what_ + ": " + clock_text(seconds) + " elapsed";
    line.resize(std::min(line.size(), terminal_width() - 1));
    std::fprintf(stderr, "\r\033[K%s", line.c_str());
    std::fflush(stderr);
    drawn = true;
  }
  if (drawn) {
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
  }
}

}  // namespace pd
