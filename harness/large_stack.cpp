#include "harness/large_stack.h"

#include <pthread.h>

#include <cstddef>

namespace pd {
namespace {

constexpr std::size_t kStackBytes = std::size_t(1) << 30;

struct Call {
  const std::function<int()>* body;
  int result;
};

void* call_body(void* arg) {
  Call* call = static_cast<Call*>(arg);
  call->result = (*call->body)();
  return nullptr;
}

}  // namespace

int run_on_large_stack(const std::function<int()>& body) {
  pthread_attr_t attr;
  if (pthread_attr_init(&attr) != 0) return body();
  Call call{&body, 0};
  pthread_t thread;
  const bool started =
      pthread_attr_setstacksize(&attr, kStackBytes) == 0 && pthread_create(&thread, &attr, call_body, &call) == 0;
  pthread_attr_destroy(&attr);
  if (!started) return body();
  pthread_join(thread, nullptr);
  return call.result;
}

}  // namespace pd
