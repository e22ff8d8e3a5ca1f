// A corpus: a folder of polygon files, one polygon a file, as a sweep family ("dir:PATH" in a sweeps
// file) and as `polydecomp corpus`'s input (docs/CONTRACT.md, "polydecomp corpus" and "Corpora in sweeps").
//
// Every regular file whose name ends in .txt, .wkt, .json or .geojson (any case) is read through the
// one checked door (read_parts_file, then Polygon::make_with_holes); its n, r and h are its own. A file
// that the door refuses, or that holds a multipolygon of several parts, is refused with the reason,
// once, and never reaches an algorithm. The corpus's name is the folder's name; a file is known by
// its name in the folder. Files are listed in name order (bytewise), so a corpus reads the same on
// every machine.
#pragma once

#include "core/polygon.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace pd {

struct CorpusFile {
  std::string name;  // in the folder
  std::string path;
  std::size_t n = 0, r = 0, h = 0;
  std::optional<std::string> refused;  // why the file is not a polygon of the corpus
};

struct Corpus {
  std::string name;
  std::string path;
  std::vector<CorpusFile> files;  // every candidate file, in name order, accepted or refused

  std::vector<const CorpusFile*> accepted() const;
  // The accepted file `rank` places from n vertices (rank 1: the nearest), nearer ones first, among
  // equally near ones the smaller n, then the name; nothing when fewer files are accepted.
  const CorpusFile* nearest(std::size_t n, std::size_t rank) const;
};

// The polygon of a corpus file through the checked door; throws PolygonError (or std::invalid_argument
// for a multipolygon of several parts) naming what is wrong.
Polygon read_corpus_polygon(const std::string& path);

// Whether a file name is a polygon file of a corpus (by its extension).
bool is_corpus_file_name(const std::string& name);

// Reads the folder. Throws std::runtime_error when it is not a readable folder. `progress` (may be
// empty) is called after each file with the count read so far and the total.
using CorpusProgress = std::function<void(std::size_t done, std::size_t total)>;
Corpus read_corpus(const std::string& path, const CorpusProgress& progress = {});

}  // namespace pd
