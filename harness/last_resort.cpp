#include "harness/last_resort.h"

#include "harness/write_all.h"

#include <gmp.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace pd {
namespace {

constexpr int kRunFailed = 4;
int report_fd = -1;  // -1: stderr, as "error: REASON"
const char* stack_lowest = nullptr;  // of the thread that installed the handlers

void* allocate_or_die(std::size_t bytes) {
  void* p = std::malloc(bytes);
  if (!p) die_of("out of memory (GNU MP could not allocate)");
  return p;
}

void* reallocate_or_die(void* old, std::size_t, std::size_t bytes) {
  void* p = std::realloc(old, bytes);
  if (!p) die_of("out of memory (GNU MP could not allocate)");
  return p;
}

void release(void* p, std::size_t) { std::free(p); }

// A fault within 1 MiB below the body's stack (its guard page and what a large frame skips) is a
// stack overflow.
bool below_the_stack(const void* address) {
  if (!stack_lowest) return false;
  const auto a = reinterpret_cast<std::uintptr_t>(address), low = reinterpret_cast<std::uintptr_t>(stack_lowest);
  return a < low + 4096 && a + (std::uintptr_t(1) << 20) >= low;
}

void on_segmentation_fault(int, siginfo_t* info, void*) {
  die_of(below_the_stack(info->si_addr) ? "out of stack (a recursion deeper than the stack allows)"
                                        : "crashed (segmentation fault)");
}

void note_this_threads_stack() {
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return;
  void* lowest = nullptr;
  std::size_t bytes = 0;
  if (pthread_attr_getstack(&attr, &lowest, &bytes) == 0) stack_lowest = static_cast<const char*>(lowest);
  pthread_attr_destroy(&attr);
}

}  // namespace

void die_of(const char* reason) {
  if (report_fd >= 0) {
    write_all(report_fd, "4\n");
    write_all(report_fd, reason);
    ::_exit(0);
  }
  write_all(STDERR_FILENO, "error: ");
  write_all(STDERR_FILENO, reason);
  write_all(STDERR_FILENO, "\n");
  ::_exit(kRunFailed);
}

void install_last_resort_handlers() {
  note_this_threads_stack();
  mp_set_memory_functions(allocate_or_die, reallocate_or_die, release);
  // A thread may have its alternate stack already (AddressSanitizer gives each thread one, and unmaps
  // it when the thread ends): keep that one.
  stack_t current{};
  if (::sigaltstack(nullptr, &current) == 0 && (current.ss_flags & SS_DISABLE)) {
    static char alternate_stack[1 << 16];
    stack_t alternate{};
    alternate.ss_sp = alternate_stack;
    alternate.ss_size = sizeof alternate_stack;
    ::sigaltstack(&alternate, nullptr);
  }
  struct sigaction action {};
  action.sa_sigaction = on_segmentation_fault;
  action.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGSEGV, &action, nullptr);
}

void send_last_resort_reports_to(int fd) { report_fd = fd; }

}  // namespace pd
