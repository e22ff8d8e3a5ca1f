// Writing the whole of a text to a file descriptor: short writes continued, interrupted calls retried.
// Only write(2), so that a signal handler and a forked child may use it too.
#pragma once

#include <unistd.h>

#include <cerrno>
#include <string_view>

namespace pd {

// False, with errno set, when a write fails (or writes nothing).
inline bool write_all(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t k = ::write(fd, text.data(), text.size());
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    text.remove_prefix(static_cast<std::size_t>(k));
  }
  return true;
}

}  // namespace pd
