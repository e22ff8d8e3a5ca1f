// Corpora: see corpus.h.
#include "harness/corpus.h"

#include "core/io.h"
#include "core/polygon.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

namespace fs = std::filesystem;

namespace pd {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Reads one file through the checked door; a refusal is recorded, not thrown.
CorpusFile read_one(const fs::path& path) {
  CorpusFile f{path.filename().string(), path.string(), 0, 0, 0, std::nullopt};
  try {
    const Polygon p = read_corpus_polygon(f.path);
    f.n = p.size(), f.r = p.reflex_count(), f.h = p.hole_count();
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception& e) {
    f.refused = e.what();
  }
  return f;
}

}  // namespace

Polygon read_corpus_polygon(const std::string& path) {
  const std::vector<Rings> parts = read_parts_file(path);
  if (parts.size() != 1)
    throw std::invalid_argument(parts.empty() ? std::string("no polygon in the file")
                                              : "a multipolygon of " + std::to_string(parts.size()) +
                                                    " parts; a corpus file holds one polygon");
  return Polygon::make_with_holes(parts[0]);
}

bool is_corpus_file_name(const std::string& name) {
  const std::string ext = lower(fs::path(name).extension().string());
  return !name.empty() && name[0] != '.' && (ext == ".txt" || ext == ".wkt" || ext == ".json" || ext == ".geojson");
}

std::vector<const CorpusFile*> Corpus::accepted() const {
  std::vector<const CorpusFile*> out;
  for (const CorpusFile& f : files)
    if (!f.refused) out.push_back(&f);
  return out;
}

const CorpusFile* Corpus::nearest(std::size_t n, std::size_t rank) const {
  std::vector<const CorpusFile*> order = accepted();
  if (rank == 0 || rank > order.size()) return nullptr;
  const auto distance = [n](const CorpusFile* f) { return f->n > n ? f->n - n : n - f->n; };
  std::stable_sort(order.begin(), order.end(), [&](const CorpusFile* a, const CorpusFile* b) {
    if (distance(a) != distance(b)) return distance(a) < distance(b);
    return a->n < b->n;  // then the name: the files are in name order and the sort is stable
  });
  return order[rank - 1];
}

Corpus read_corpus(const std::string& path, const CorpusProgress& progress) {
  std::error_code error;
  if (!fs::is_directory(path, error)) throw std::runtime_error("corpus " + path + " is not a folder");
  std::vector<fs::path> paths;
  for (const fs::directory_entry& e : fs::directory_iterator(path, error))
    if (e.is_regular_file() && is_corpus_file_name(e.path().filename().string())) paths.push_back(e.path());
  if (error) throw std::runtime_error("cannot read corpus folder " + path + ": " + error.message());
  std::sort(paths.begin(), paths.end(), [](const fs::path& a, const fs::path& b) {
    return a.filename().string() < b.filename().string();
  });
  fs::path folder = fs::weakly_canonical(path);
  if (!folder.has_filename()) folder = folder.parent_path();  // "x/" is "x"
  Corpus c{folder.filename().string(), path, {}};
  for (const fs::path& p : paths) {
    c.files.push_back(read_one(p));
    if (progress) progress(c.files.size(), paths.size());
  }
  return c;
}

}  // namespace pd
