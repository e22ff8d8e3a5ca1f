// Where a result came from: git commit and dirty flag, compiler, CGAL and Boost versions, build type,
// CPU, machine and date. Results files carry these fields.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace pd {

std::vector<std::pair<std::string, std::string>> provenance();

}  // namespace pd
