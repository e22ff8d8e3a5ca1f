// libFuzzer target for `run` on every registered algorithm: the input is read as a polygon file; each
// accepted part (holes and all) of at most kFuzzMaxVertices vertices is given to every algorithm that
// takes it and whose claimed bound
// there is small (tests/reliability.h), and each result is validated exactly. A crash, a sanitizer
// report, or an exception or invalid result from one of our algorithms is a finding (the CGAL peers'
// invalid results and exceptions are their known behaviour, not findings). Built by the sanitizer build
// (CMake PD_FUZZ); `make fuzz` runs it, ctest runs it briefly.
#include "tests/reliability.h"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace pd::reliability;
  const auto parts = read_checked(std::string(reinterpret_cast<const char*>(data), size));
  if (!parts) return 0;
  for (const pd::Polygon& polygon : *parts) {
    if (polygon.size() > kFuzzMaxVertices) continue;
    if (const auto finding = first_finding(run_every_algorithm(polygon, kFuzzWork))) {
      std::fprintf(stderr, "finding: %s\n", finding->c_str());
      std::abort();
    }
  }
  return 0;
}
