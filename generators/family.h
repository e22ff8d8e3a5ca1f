// Polygon families for benchmarks and tests.
//
// Each family makes a simple counter-clockwise polygon with exactly n vertices, integer coordinates
// (|x|, |y| < 2^31) and, where the family controls it, exactly r reflex vertices. Output depends only
// on (n, r, seed): the project's own PRNG and integer arithmetic, never std::*_distribution, so the same
// arguments give the same bytes on every machine. Each family file registers itself.
#pragma once

#include "core/geometry.h"

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
  std::string shape;     // one sentence: what the polygons look like
  std::string range;     // the feasible (n, r), in words, e.g. "n >= 4, 0 <= r <= n-3"
  bool controls_r;       // whether r can be chosen independently of n
  // Why (n, r) cannot be realised, or nothing when it can.
  std::function<std::optional<std::string>(std::size_t n, std::size_t r)> infeasible;
  // The r used when none is asked for (e.g. n/4 for random, 0 for convex).
  std::function<std::size_t(std::size_t n)> default_reflex;
  std::function<std::vector<Point>(std::size_t n, std::size_t r, std::uint64_t seed)> make;
};

const std::vector<Family>& families();  // sorted by name
const Family* find_family(const std::string& name);
bool register_family(Family f);

// Makes a polygon of `family`; r defaults to the family's default. Throws GeneratorError naming the
// feasible range when (n, r) cannot be realised, std::invalid_argument for an unknown family.
std::vector<Point> generate(const std::string& family, std::size_t n, std::optional<std::size_t> r,
                            std::uint64_t seed);

}  // namespace pd

#define REGISTER_FAMILY(...) \
  static const bool PD_CONCAT(pd_family_, __COUNTER__) = ::pd::register_family(__VA_ARGS__)
#ifndef PD_CONCAT
#define PD_CONCAT_INNER(a, b) a##b
#define PD_CONCAT(a, b) PD_CONCAT_INNER(a, b)
#endif
