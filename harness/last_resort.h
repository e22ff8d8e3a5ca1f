// How a program that cannot go on still ends with one error line (docs/CONTRACT.md, "Errors").
//
// Three failures end a process without an exception to catch: GNU MP cannot allocate (it prints its
// own message and aborts), a recursion runs off the end of the stack, and any other segmentation
// fault. The handlers installed here turn each into one line, "error: REASON", and exit status 4 (a
// failure of the run); out of memory in C++ is std::bad_alloc, which the programs catch themselves.
// In `run --max-seconds`'s child the line goes to the parent through its pipe instead, so that the
// parent still prints exactly one line. The handlers use only async-signal-safe calls.
#pragma once

namespace pd {

// GNU MP's allocation functions that report a failure as above, and a SIGSEGV handler on an
// alternate signal stack. Call once, first thing, on the thread that runs the program's body: a fault
// just below that thread's stack reads "out of stack", any other "crashed (segmentation fault)".
void install_last_resort_handlers();

// From now on (a --max-seconds child), a last-resort report is written to `fd` as a child's failure
// message ("4\nREASON") and the process exits with status 0; the parent reports it.
void send_last_resort_reports_to(int fd);

// Writes the report and ends the process (status 4), with async-signal-safe calls only.
[[noreturn]] void die_of(const char* reason);

}  // namespace pd
