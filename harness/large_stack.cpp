#include "harness/large_stack.h"

#include <pthread.h>
#include <sys/resource.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>

namespace pd {
namespace {

// From 1 GiB down. The reservation counts against a limit on address space (ulimit -v), so under one
// the stack takes at most a quarter of it, leaving the rest to the heap.
constexpr std::size_t kStackBytes[] = {std::size_t(1) << 30, std::size_t(1) << 28, std::size_t(1) << 26,
                                       std::size_t(1) << 24};

std::size_t largest_stack_allowed() {
  struct rlimit limit;
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return SIZE_MAX;
  return static_cast<std::size_t>(limit.rlim_cur / 4);
}

struct Call {
  const std::function<int()>* body;
  int result;
};

void* call_body(void* arg) {
  Call* call = static_cast<Call*>(arg);
  call->result = (*call->body)();
  return nullptr;
}

bool start_with_stack(std::size_t bytes, Call& call, pthread_t& thread) {
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) return false;
  const bool started = pthread_attr_setstacksize(&attr, bytes) == 0 && pthread_create(&thread, &attr, call_body, &call) == 0;
  pthread_attr_destroy(&attr);
  return started;
}

}  // namespace

int run_on_large_stack(const std::function<int()>& body) {
  Call call{&body, 0};
  pthread_t thread;
  const std::size_t allowed = largest_stack_allowed();
  for (const std::size_t bytes : kStackBytes) {
    if (bytes <= allowed && start_with_stack(bytes, call, thread)) {
      pthread_join(thread, nullptr);
      return call.result;
    }
  }
  return body();
}

int benchmark_main(int argc, char** argv, int (*run)(int, char**)) {
  return run_on_large_stack([&] {
    try {
      return run(argc, argv);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 2;
    }
  });
}

}  // namespace pd
