// The checks that the fuzz targets (fuzz/) and the reliability tests share: what counts as a finding on
// an arbitrary input, so that every input a fuzzer saved (data/fuzz-regressions) is replayed by the test
// suite with exactly the check that found it.
//
// Readers: any text either parses, or is refused with a PolygonError; an accepted ring either makes a
// Polygon or is refused with a PolygonError; an accepted Polygon written in every format reads back as
// the same polygon. Algorithms: on an accepted polygon, every registered algorithm within the work
// budget returns, and ours return a valid decomposition; a peer's exception or invalid result is its own
// known behaviour, recorded and not a finding.
#pragma once

#include "core/bound_expr.h"
#include "core/io.h"
#include "core/registry.h"
#include "core/validate.h"

#include <optional>
#include <string>
#include <vector>

namespace pd::reliability {

// Whether `a` takes p (Algorithm::accepts) and p is under its size ceiling.
inline bool takes(const Algorithm& a, const Polygon& p) { return !refusal(a, p) && p.size() <= a.size_ceiling; }

// Whether `a` is given p within `work`: it takes p (Algorithm::accepts), p is under its size ceiling,
// and its claimed bound in n and r is at most `work` there (the ceiling alone ignores r: an n*r^2
// program on a real-world ring with r = n/2 is cubic).
inline bool within_work(const Algorithm& a, const Polygon& p, double work) {
  const auto bound = BoundExpr::parse(a.time_bound);
  const auto n = static_cast<double>(p.size()), r = static_cast<double>(p.reflex_count());
  return takes(a, p) && (!bound || (*bound)(n, r) <= work);
}

// The polygon in `text` (a multipolygon's parts), or nothing when it is refused with a PolygonError.
// Any other exception escapes: a reader that fails otherwise is a finding. Throws std::logic_error when
// an accepted part does not read back from one of the writers' formats (plain text: without holes).
inline std::optional<std::vector<Polygon>> read_checked(const std::string& text) {
  std::optional<std::vector<Polygon>> parts;
  try {
    parts = make_parts(parse_parts(text));
  } catch (const PolygonError&) {
    return std::nullopt;
  }
  for (const Polygon& p : *parts)
    for (const Format f : {Format::Txt, Format::Wkt, Format::GeoJson}) {
      if (f == Format::Txt && p.hole_count() > 0) continue;
      const std::vector<Polygon> back = make_parts(parse_parts(format_polygon(p.rings(), f)));
      if (back.size() != 1 || back[0].vertices() != p.vertices() || back[0].ring_count() != p.ring_count())
        throw std::logic_error("the polygon does not read back from format " + std::to_string(static_cast<int>(f)));
    }
  return parts;
}

struct Verdict {
  const Algorithm* algorithm;
  bool ok;
  std::string reason;  // the validator's, or the exception's
};

// Every registered algorithm within `work` on p, validated.
inline std::vector<Verdict> run_every_algorithm(const Polygon& p, double work) {
  std::vector<Verdict> verdicts;
  for (const Algorithm& a : algorithms()) {
    if (!within_work(a, p, work)) continue;
    Counters counters;
    try {
      const Validation v = validate(p, a.run(p, counters), a.kind, a.steiner);
      verdicts.push_back({&a, v.ok, v.reason});
    } catch (const std::exception& e) {
      verdicts.push_back({&a, false, std::string("threw: ") + e.what()});
    }
  }
  return verdicts;
}

// The first verdict against one of our algorithms, as "algorithm: reason".
inline std::optional<std::string> first_finding(const std::vector<Verdict>& verdicts) {
  for (const Verdict& v : verdicts)
    if (!v.ok && !is_peer(*v.algorithm)) return v.algorithm->name + ": " + v.reason;
  return std::nullopt;
}

// The test suite's work budget: an algorithm is tested on a polygon when its claimed bound there is at
// most this.
constexpr double kTestWork = 2e8;

// The fuzz targets' input ceilings: run_every_algorithm is given polygons of at most kFuzzMaxVertices
// vertices, and each algorithm whose claimed bound there is at most kFuzzWork, so that one input
// takes milliseconds.
constexpr std::size_t kFuzzMaxVertices = 32;
constexpr double kFuzzWork = 2e6;

}  // namespace pd::reliability
