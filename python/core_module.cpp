// polydecomp._core, the compiled half of the Python module (python/polydecomp/__init__.py is its API,
// docs/python.md its documentation). It speaks in plain values: a ring is the bytes of its float64
// (x, y) pairs, a result is the `run --json` text, a Steiner coordinate the decimal numerator and
// denominator of an exact rational. The Python side does the conversions (numpy, shapely, Fraction);
// this side is the command line's own code: the checked door (make_parts), run_algorithm, the
// generators' generate_polygon and the exact validator, so that a result is the CLI's byte for byte.
//
// The GIL is released while a call computes, which runs on a thread with a large stack (as the command
// line's body does: some peers recurse once per vertex). Bad input raises ValueError with the CLI's
// one-line message; a failed run (exit status 4 in the CLI) raises RuntimeError.
#include "core/coordinate.h"
#include "core/decomposition.h"
#include "core/io.h"
#include "core/polygon.h"
#include "core/registry.h"
#include "core/validate.h"
#include "generators/family.h"
#include "harness/large_stack.h"
#include "harness/plugins.h"
#include "harness/run.h"

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace py = pybind11;

namespace pd::bindings {
namespace {

Ring ring_of(const py::bytes& bytes) {
  const std::string text = bytes;
  if (text.size() % (2 * sizeof(double)) != 0) throw py::value_error("a ring's bytes are not (x, y) float64 pairs");
  Ring ring;
  ring.reserve(text.size() / (2 * sizeof(double)));
  for (std::size_t at = 0; at < text.size(); at += 2 * sizeof(double)) {
    double xy[2];
    std::memcpy(xy, text.data() + at, sizeof xy);
    ring.emplace_back(xy[0], xy[1]);
  }
  return ring;
}

py::bytes bytes_of(const Ring& ring) {
  std::string text(ring.size() * 2 * sizeof(double), '\0');
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const double xy[2] = {ring[i].x(), ring[i].y()};
    std::memcpy(text.data() + i * sizeof xy, xy, sizeof xy);
  }
  return py::bytes(text);
}

std::vector<Rings> parts_of(const std::vector<std::vector<py::bytes>>& parts) {
  std::vector<Rings> out;
  for (const auto& rings : parts) {
    out.emplace_back();
    for (const py::bytes& ring : rings) out.back().push_back(ring_of(ring));
  }
  return out;
}

// Calls `body` without the GIL on a large stack; its exception is raised on this thread.
template <class Body>
auto computed(Body body) -> decltype(body()) {
  std::optional<decltype(body())> result;
  std::exception_ptr failure;
  {
    const py::gil_scoped_release unlocked;
    run_on_large_stack([&] {
      try {
        result.emplace(body());
      } catch (...) {
        failure = std::current_exception();
      }
      return 0;
    });
  }
  if (failure) std::rethrow_exception(failure);
  return std::move(*result);
}

// The failures of the command line as Python exceptions: bad input ValueError, a failed run RuntimeError.
template <class Body>
auto raising(Body body) -> decltype(body()) {
  try {
    return body();
  } catch (const PolygonError& e) {
    throw py::value_error(e.what());
  } catch (const Exit& e) {
    if (e.status == kUsage || e.status == kBadPolygon) throw py::value_error(e.message);
    throw std::runtime_error(e.message);
  } catch (const std::bad_alloc&) {
    throw std::runtime_error("out of memory");
  }
}

std::vector<Polygon> checked_parts(const std::vector<std::vector<py::bytes>>& parts) {
  std::vector<Rings> rings = parts_of(parts);
  return raising([&] { return computed([&] { return make_parts(std::move(rings)); }); });
}

const Algorithm& algorithm_named(const std::string& name) {
  const Algorithm* algo = find_algorithm(name);
  if (!algo) throw py::value_error("unknown algorithm " + quoted_input(name) + "; 'polydecomp list' names them");
  return *algo;
}

std::vector<py::bytes> generate(const std::string& family, std::size_t n, std::optional<std::size_t> reflex,
                                std::optional<std::size_t> holes, std::optional<std::size_t> collinear,
                                std::uint64_t seed) {
  const GenerateRequest request{family, n, reflex, holes, collinear, seed};
  const Rings rings = computed([&] { return generate_polygon(request); });
  std::vector<py::bytes> out;
  for (const Ring& ring : rings) out.push_back(bytes_of(ring));
  return out;
}

// The `run --json` text and, when the result is not valid, why.
std::pair<std::string, std::string> decompose(const std::vector<std::vector<py::bytes>>& parts,
                                              const std::string& algorithm, bool validate,
                                              std::optional<double> max_seconds) {
  const Algorithm& algo = algorithm_named(algorithm);
  if (max_seconds && !(*max_seconds > 0 && *max_seconds <= 1e9))
    throw py::value_error("max_seconds takes a number of seconds above 0");
  const std::vector<Polygon> polygons = checked_parts(parts);
  RunOptions options;
  options.json = true;
  options.validate = validate;
  options.max_seconds = max_seconds;
  options.close_inherited = true;
  const RunOutput output = raising([&] {
    check_accepted(algo, polygons);
    return computed([&] { return run_algorithm(algo, polygons, options); });
  });
  return {output.out, output.invalid};
}

Kind kind_named(const std::string& name) {
  for (const Kind k : {Kind::Triangulation, Kind::Partition, Kind::Convex, Kind::Cut})
    if (name == kind_name(k)) return k;
  throw py::value_error("unknown kind '" + name + "'; kinds: triangulation, partition, convex, cut");
}

// Polygon ids of the points as decompose numbers them: input vertices in file order (a merged vertex
// is the vertex it repeats), then Steiner points.
std::vector<VertexId> ids_of_file_order(const Polygon& p) {
  std::vector<VertexId> id(p.input_size());
  for (std::size_t i = 0; i < p.size(); ++i) id[p.input_index(i)] = static_cast<VertexId>(i);
  for (const auto& [merged, repeats] : p.merged()) id[merged] = id[repeats];
  return id;
}

using RationalText = std::pair<std::string, std::string>;  // numerator, denominator

std::pair<bool, std::string> validate(const std::vector<py::bytes>& rings, const std::vector<std::vector<std::int64_t>>& pieces,
                                      const std::string& kind, const std::vector<std::pair<RationalText, RationalText>>& steiner) {
  const Kind k = kind_named(kind);
  const std::vector<Polygon> parts = checked_parts({rings});
  const Polygon& p = parts[0];
  const std::vector<VertexId> id = ids_of_file_order(p);
  const std::int64_t points = static_cast<std::int64_t>(id.size() + steiner.size());
  std::vector<Piece> in_ids;
  for (const auto& piece : pieces) {
    in_ids.emplace_back();
    for (const std::int64_t v : piece) {
      if (v < 0 || v >= points)
        return {false, "piece " + std::to_string(in_ids.size() - 1) + " names point " + std::to_string(v) + " of " +
                           std::to_string(points)};
      const std::size_t u = static_cast<std::size_t>(v);
      in_ids.back().push_back(u < id.size() ? id[u] : static_cast<VertexId>(p.size() + (u - id.size())));
    }
  }
  std::vector<QPoint> exact;
  for (const Point& v : p.vertices()) exact.emplace_back(v.x(), v.y());
  const auto rational = [](const RationalText& t) -> Rational { return Rational(t.first) / Rational(t.second); };
  for (const auto& [x, y] : steiner) exact.emplace_back(rational(x), rational(y));
  const Validation v = computed([&] { return validate_pieces(p, exact, in_ids, k, !steiner.empty()); });
  return {v.ok, v.reason};
}

py::dict family_entry(const std::string& name, const std::string& shape, const std::string& range, std::size_t min_n,
                      bool holes, bool r_is_outcome) {
  return py::dict(py::arg("name") = name, py::arg("shape") = shape, py::arg("range") = range, py::arg("min_n") = min_n,
                  py::arg("holes") = holes, py::arg("r_is_outcome") = r_is_outcome);
}

py::list families() {
  py::list out;
  for (const Family& f : pd::families()) out.append(family_entry(f.name, f.shape, f.range(), f.min_n, false, f.r_is_outcome));
  for (const HoleFamily& f : hole_families()) out.append(family_entry(f.name, f.shape, f.range(), f.min_n, true, false));
  return out;
}

}  // namespace
}  // namespace pd::bindings

PYBIND11_MODULE(_core, m) {
  m.doc() = "polydecomp's compiled core; use the polydecomp package, not this module";
  pd::register_plugins(pd::plugin_folders({}));
  pd::use_plugin_launcher();
  m.def("algorithms_json", &pd::algorithms_json);
  m.def("families", &pd::bindings::families);
  m.def("generate", &pd::bindings::generate);
  m.def("decompose", &pd::bindings::decompose);
  m.def("validate", &pd::bindings::validate);
}
