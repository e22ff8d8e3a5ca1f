// libFuzzer target for the readers (core/io.h parse_parts, every format, and make_parts: holes,
// multipolygons, merged vertices): any bytes are either read or refused with a PolygonError, and an
// accepted part reads back from every writer's format. A crash, a sanitizer report, any other
// exception or a failed read-back is a finding.
// Built by the sanitizer build (CMake PD_FUZZ); `make fuzz` runs it, ctest runs it briefly.
#include "tests/reliability.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  pd::reliability::read_checked(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
