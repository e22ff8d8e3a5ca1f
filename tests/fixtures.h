// earcut's real-world polygons (data/earcut-fixtures, ISC licence) for the tests: each fixture's outer
// ring, holes dropped, so that the polygons with holes still give their (often large) outer boundary.
#pragma once

#include "core/geometry.h"
#include "core/json.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pd::fixtures {

inline std::vector<std::filesystem::path> earcut_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(PD_SOURCE_DIR "/data/earcut-fixtures"))
    if (entry.path().extension() == ".json" && entry.path().filename() != "expected.json")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// (name, outer ring as written) of every fixture.
inline std::vector<std::pair<std::string, std::vector<Point>>> earcut_outer_rings() {
  std::vector<std::pair<std::string, std::vector<Point>>> rings;
  for (const auto& path : earcut_files()) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    const Json doc = parse_json(text.str());
    std::vector<Point> ring;
    for (const Json& pos : doc.items.at(0).items) ring.emplace_back(pos.items.at(0).number(), pos.items.at(1).number());
    rings.emplace_back(path.stem().string(), std::move(ring));
  }
  return rings;
}

}  // namespace pd::fixtures
