// Corpora (harness/corpus.h, docs/CONTRACT.md, "polydecomp corpus" and "Corpora in sweeps"): a folder of polygon files read through the
// checked door, each file accepted with its own n, r and h or refused with the reason; `polydecomp
// corpus` lists it and picks the file nearest to n vertices; a sweep names it as "dir:PATH" (relative
// to the sweeps file), its keys "algorithm/CORPUS/FILE/n:N/r:R/h:H", and refuses malformed curves of
// corpora. The end-to-end sweep of a user's folder through sweep.py is analysis/integration_sweep.py's.
#include "harness/corpus.h"
#include "harness/sweep.h"
#include "tests/command.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace pd {
namespace {

namespace fs = std::filesystem;

void write(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A folder of three good files (n 4, 6 and 8, one with a hole), four bad ones and two that are not
// polygon files.
fs::path sample_folder(const std::string& prefix) {
  const fs::path dir = command::scratch_folder(prefix) / "shapes";
  fs::create_directories(dir);
  write(dir / "square.txt", "0 0\n4 0\n4 4\n0 4\n");
  write(dir / "hexagon.wkt", "POLYGON ((0 0, 4 0, 6 2, 4 4, 0 4, -2 2, 0 0))");
  write(dir / "framed.geojson",
        "{\"type\": \"Polygon\", \"coordinates\": [[[0,0],[9,0],[9,9],[0,9],[0,0]], [[3,3],[3,6],[6,6],[6,3],[3,3]]]}");
  write(dir / "bowtie.txt", "0 0\n1 1\n0 1\n1 0\n");
  write(dir / "garbage.json", "garbage\n");
  write(dir / "two.wkt", "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), ((5 5, 6 5, 6 6, 5 5)))");
  write(dir / "line.TXT", "0 0\n1 1\n");
  write(dir / "README.md", "0 0\n1 0\n0 1\n");
  write(dir / ".hidden.txt", "0 0\n1 0\n0 1\n");
  return dir;
}

TEST(Corpus, AcceptsAndRefusesEachFileOnceInNameOrder) {
  const Corpus c = read_corpus(sample_folder("pd-corpus-read").string());
  EXPECT_EQ(c.name, "shapes");
  std::vector<std::string> names;
  for (const CorpusFile& f : c.files) names.push_back(f.name + (f.refused ? ": " + *f.refused : ""));
  EXPECT_EQ(names, (std::vector<std::string>{
                       "bowtie.txt: not simple: edge 0-1 crosses edge 2-3", "framed.geojson", "garbage.json: line 1: 'garbage' is not a number",
                       "hexagon.wkt", "line.TXT: 2 vertices; a polygon needs at least 3",
                       "square.txt", "two.wkt: a multipolygon of 2 parts; a corpus file holds one polygon"}));
  ASSERT_EQ(c.accepted().size(), 3u);
  const CorpusFile& framed = *c.accepted()[0];
  EXPECT_EQ(framed.n, 8u);
  EXPECT_EQ(framed.r, 4u);
  EXPECT_EQ(framed.h, 1u);
  // Nearest to 5: the square (4) and the hexagon (6) are as near; the smaller n first.
  EXPECT_EQ(c.nearest(5, 1)->name, "square.txt");
  EXPECT_EQ(c.nearest(5, 2)->name, "hexagon.wkt");
  EXPECT_EQ(c.nearest(5, 3)->name, "framed.geojson");
  EXPECT_EQ(c.nearest(5, 4), nullptr);
  EXPECT_EQ(c.nearest(1000, 1)->name, "framed.geojson");
  EXPECT_THROW(read_corpus((c.path + "/square.txt")), std::runtime_error);
}

TEST(Corpus, CommandListsTheFolderAndWritesTheNearestFile) {
  const fs::path dir = sample_folder("pd-corpus-cli"), scratch = dir.parent_path();
  const command::Result list = command::run(std::string(PD_CLI) + " corpus --dir " + dir.string(), scratch);
  EXPECT_EQ(list.status, 0) << list.err;
  EXPECT_NE(list.out.find("'framed.geojson': n=8 reflex=4 holes=1\n"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("'bowtie.txt': refused: not simple: edge 0-1 crosses edge 2-3\n"), std::string::npos);
  EXPECT_NE(list.out.find("corpus 'shapes': 7 files, 3 accepted, 4 refused\n"), std::string::npos);
  const command::Result json = command::run(std::string(PD_CLI) + " corpus --json --dir " + dir.string(), scratch);
  EXPECT_EQ(json.out.rfind("{\"corpus\": \"shapes\", \"accepted\": 3, \"refused\": 4, \"files\": [", 0), 0u) << json.out;
  const command::Result nearest = command::run(std::string(PD_CLI) + " corpus --dir " + dir.string() + " --n 7 --rank 2", scratch);
  EXPECT_EQ(nearest.status, 0) << nearest.err;
  EXPECT_EQ(nearest.out, command::slurp(dir / "framed.geojson"));  // 6 and 8 as near: 6 first
  const command::Result past = command::run(std::string(PD_CLI) + " corpus --dir " + dir.string() + " --n 7 --rank 4", scratch);
  EXPECT_EQ(past.status, 3);
  EXPECT_EQ(past.err, "error: corpus 'shapes' accepts 3 files; none is at rank 4 from n=7\n");
  const command::Result misused = command::run(std::string(PD_CLI) + " corpus --dir " + dir.string() + " --rank 2", scratch);
  EXPECT_EQ(misused.status, 2);
  EXPECT_EQ(misused.err, "error: --rank and -o go with --n\n");
  const command::Result missing = command::run(std::string(PD_CLI) + " corpus --dir " + (dir / "nowhere").string(), scratch);
  EXPECT_EQ(missing.status, 3);
  EXPECT_EQ(missing.err, "error: corpus " + (dir / "nowhere").string() + " is not a folder\n");
}

TEST(Corpus, SweepsNameItRelativeToTheSweepsFile) {
  const fs::path dir = sample_folder("pd-corpus-sweep"), scratch = dir.parent_path();
  write(scratch / "sweeps.json",
        "{\"all\": {\"algorithms\": [\"monotone\"], \"seeds\": [1, 2], \"min_time\": 0.001, \"budget_seconds\": 1, "
        "\"timeout_seconds\": 10, \"curves\": [{\"vs\": \"n\", \"families\": [\"dir:shapes\"]}]},"
        " \"near\": {\"algorithms\": [\"monotone\"], \"seeds\": [1, 2], \"min_time\": 0.001, \"budget_seconds\": 1, "
        "\"timeout_seconds\": 10, \"curves\": [{\"vs\": \"n\", \"families\": [\"dir:shapes\"], \"n\": [4, 100]}]},"
        " \"mixed\": {\"algorithms\": [\"monotone\"], \"seeds\": [1], \"min_time\": 0.001, \"budget_seconds\": 1, "
        "\"timeout_seconds\": 10, \"curves\": [{\"vs\": \"n\", \"families\": [\"dir:shapes\", \"comb\"], \"n\": [4]}]},"
        " \"with_r\": {\"algorithms\": [\"monotone\"], \"seeds\": [1], \"min_time\": 0.001, \"budget_seconds\": 1, "
        "\"timeout_seconds\": 10, \"curves\": [{\"vs\": \"n\", \"families\": [\"dir:shapes\"], \"r\": [\"default\"]}]},"
        " \"gone\": {\"algorithms\": [\"monotone\"], \"seeds\": [1], \"min_time\": 0.001, \"budget_seconds\": 1, "
        "\"timeout_seconds\": 10, \"curves\": [{\"vs\": \"n\", \"families\": [\"dir:nowhere\"]}]}}");
  const std::string file = (scratch / "sweeps.json").string();
  const Sweep all = load_sweep(file, "all");
  std::vector<std::string> ids;
  for (const SweepPolygon& p : sweep_polygons(all)) ids.push_back(p.id() + " " + p.curves[0]);
  EXPECT_EQ(ids, (std::vector<std::string>{"shapes/square.txt/n:4/r:0/h:0 vs-n corpus",
                                           "shapes/hexagon.wkt/n:6/r:0/h:0 vs-n corpus",
                                           "shapes/framed.geojson/n:8/r:4/h:1 vs-n corpus"}));
  EXPECT_EQ(refused_files(all).size(), 4u);
  EXPECT_EQ(refused_files(all)[0], (std::pair<std::string, std::string>{"shapes/bowtie.txt", "not simple: edge 0-1 crosses edge 2-3"}));
  // Seeds 1 and 2: the nearest two to 4 (the square, the hexagon) and to 100 (framed, hexagon).
  ids.clear();
  const Sweep near = load_sweep(file, "near");  // its polygons point into it
  for (const SweepPolygon& p : sweep_polygons(near)) ids.push_back(p.id());
  EXPECT_EQ(ids, (std::vector<std::string>{"shapes/square.txt/n:4/r:0/h:0", "shapes/hexagon.wkt/n:6/r:0/h:0",
                                           "shapes/framed.geojson/n:8/r:4/h:1"}));
  const auto error_of = [&](const std::string& sweep) {
    try {
      load_sweep(file, sweep);
    } catch (const SweepError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("mixed"), file + ": sweep mixed curve 1: a curve holds corpora (\"dir:PATH\") or families, not both");
  EXPECT_EQ(error_of("with_r"), file + ": sweep with_r curve 1: a corpus's files have their own r and h; a curve of corpora takes neither \"r\" nor \"h\"");
  EXPECT_EQ(error_of("gone"), file + ": sweep gone: corpus " + (scratch / "nowhere").string() + " is not a folder");
}

}  // namespace
}  // namespace pd
