// Polygon families for benchmarks and tests.
//
// Each family makes a simple counter-clockwise polygon with exactly n vertices, integer coordinates
// (|x|, |y| < 2^31), no three consecutive vertices collinear (generate_with_collinear asks for them)
// and, where the family controls it, exactly r reflex vertices. Output depends only on (n, r, seed):
// the project's own PRNG and integer arithmetic, never std::*_distribution, so the same arguments give
// the same bytes on every machine. Each family file registers itself.
//
// The random polygons of Auer and Held's generators (star, space-partition, 2-opt) do not choose r: r
// is what the method gives (r_is_outcome). Their r_infeasible refuses every r that is asked for, so that
// a grid of (n, r) leaves them out; generate() makes them with r left out (or asked for as exactly
// the r the method gives at that n and seed), and reflex_outcome() says that r.
#pragma once

#include "core/geometry.h"
#include "core/named_registry.h"
#include "core/polygon.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pd {

// (n, r) outside a family's feasible range; what() names the range.
class GeneratorError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct Family {
  std::string name;
  std::string shape;    // one sentence: what the polygons look like
  std::size_t min_n;    // the feasible n: min_n <= n <= max_n
  std::size_t max_n;
  std::string r_range;  // the feasible r at a feasible n, in words, e.g. "0 <= r <= 2(n-3)/3"
  bool controls_r;      // whether r can be chosen independently of n
  bool r_is_outcome = false;  // r is what the method gives at (n, seed), never chosen
  // Why r cannot be realised at an n in range, or nothing when it can.
  std::function<std::optional<std::string>(std::size_t n, std::size_t r)> r_infeasible;
  // The r used when none is asked for (e.g. n/4 for random, 0 for convex).
  std::function<std::size_t(std::size_t n)> default_reflex;
  std::function<std::vector<Point>(std::size_t n, std::size_t r, std::uint64_t seed)> make;

  // The feasible (n, r), in words, e.g. "3 <= n <= 2000000, 0 <= r <= 2(n-3)/3".
  std::string range() const;
  // Why (n, r) cannot be realised, or nothing when it can.
  std::optional<std::string> infeasible(std::size_t n, std::size_t r) const;
  // Why n is outside [min_n, max_n], or nothing (for a family whose r is an outcome, all it checks).
  std::optional<std::string> n_infeasible(std::size_t n) const;
};

// A family whose r is an outcome of its method: feasible for min_n <= n <= max_n at whatever r the
// method gives; its r_infeasible refuses every r asked for in a grid.
Family outcome_family(std::string name, std::string shape, std::size_t min_n, std::size_t max_n,
                      std::function<std::vector<Point>(std::size_t n, std::uint64_t seed)> make);

const std::vector<Family>& families();  // sorted by name
const Family* find_family(const std::string& name);
bool register_family(Family f);

// Makes a polygon of `family`; r defaults to the family's default. Throws GeneratorError naming the
// feasible range when (n, r) cannot be realised, std::invalid_argument for an unknown family. For a
// family whose r is an outcome, an r asked for must be the one the method gives, else GeneratorError.
std::vector<Point> generate(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                            std::uint64_t seed);

// The polygon of `family` with k collinear (180-degree) vertices: the family's polygon of n - k vertices
// (at r, or its default r at n - k), coordinates doubled, k of its edges (chosen by the seed) split at
// their midpoints; r unchanged. k = 0 is generate(). Throws GeneratorError when k > n/2 or the doubled
// coordinates would reach 2^31, and as generate does.
std::vector<Point> generate_with_collinear(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                                           std::size_t k, std::uint64_t seed);

// The r that family `family`, whose r is an outcome, gives at (n, seed) (by making the polygon).
std::size_t reflex_outcome(const std::string& family, std::size_t n, std::uint64_t seed);

// The reflex vertices of a simple counter-clockwise ring (exact predicates).
std::size_t reflex_vertices(const std::vector<Point>& ring);

// A family of polygons with holes: n vertices in all (the outer ring's and the holes'), r reflex
// vertices and h holes, exactly, where the family can realise them; the outer ring counter-clockwise,
// the holes clockwise, integer coordinates (|x|, |y| < 2^31), the same bytes on every machine. Its
// sweep keys carry h: "family/n:N/r:R/h:H/seed:S". A family file registers itself with
// REGISTER_HOLE_FAMILY; the names are shared with the families above.
struct HoleFamily {
  std::string name;
  std::string shape;    // one sentence: what the polygons look like
  std::size_t min_n;    // the feasible n: min_n <= n <= max_n
  std::size_t max_n;
  std::string rh_range;  // the feasible (r, h) at a feasible n, in words
  // Why (r, h) cannot be realised at an n in range, or nothing when it can.
  std::function<std::optional<std::string>(std::size_t n, std::size_t r, std::size_t h)> rh_infeasible;
  // The r used when none is asked for, at (n, h).
  std::function<std::size_t(std::size_t n, std::size_t h)> default_reflex;
  std::size_t default_holes;  // the h used when none is asked for
  std::function<Rings(std::size_t n, std::size_t r, std::size_t h, std::uint64_t seed)> make;

  std::string range() const;
  std::optional<std::string> infeasible(std::size_t n, std::size_t r, std::size_t h) const;
};

const std::vector<HoleFamily>& hole_families();  // sorted by name
const HoleFamily* find_hole_family(const std::string& name);
bool register_hole_family(HoleFamily f);

// Makes a polygon with holes of `family`; r and h default to the family's. Throws as generate does.
Rings generate_with_holes(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                          std::optional<std::size_t> h, std::uint64_t seed);

// What `polydecomp generate` asks for (docs/CONTRACT.md, "polydecomp generate").
struct GenerateRequest {
  std::string family;
  std::size_t n = 0;
  std::optional<std::size_t> reflex, holes, collinear;
  std::uint64_t seed = 1;
};

// The polygon `generate` makes, the outer ring then its holes, through generate_with_collinear or
// generate_with_holes; throws as they do, and GeneratorError for options that do not go together (an r
// asked of a family whose r is an outcome, collinear vertices with holes).
Rings generate_polygon(const GenerateRequest& request);

}  // namespace pd

#define REGISTER_FAMILY(...) \
  static const bool PD_CONCAT(pd_family_, __COUNTER__) = ::pd::register_family(__VA_ARGS__)
#define REGISTER_HOLE_FAMILY(...) \
  static const bool PD_CONCAT(pd_hole_family_, __COUNTER__) = ::pd::register_hole_family(__VA_ARGS__)
