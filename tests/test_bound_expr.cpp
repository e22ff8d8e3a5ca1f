// The time-bound grammar (core/bound_expr.h) on the vectors it shares with the analysis's parser
// (analysis/polydecomp_analysis/bound_expr.py): tests/data/bound_expr_vectors.json, read here and by
// analysis/tests/test_bound_expr.py, so that the harness's budget and the analysis read claims alike.
#include "core/bound_expr.h"
#include "core/json.h"
#include "core/registry.h"
#include "harness/budget.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace pd {
namespace {

// The Python test's tolerance: assertAlmostEqual to 6 places.
constexpr double kTolerance = 5e-7;

Json shared_vectors() {
  std::ifstream in(PD_SOURCE_DIR "/tests/data/bound_expr_vectors.json", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return parse_json(text.str());
}

TEST(BoundExpr, SharedVectorsEvaluate) {
  const Json vectors = shared_vectors();
  const Json* cases = vectors.get("time_bounds");
  ASSERT_NE(cases, nullptr);
  ASSERT_FALSE(cases->items.empty());
  for (const Json& c : cases->items) {
    const std::string& text = c.get("text")->text;
    const auto bound = BoundExpr::parse(text);
    if (!bound) {
      ADD_FAILURE() << "'" << text << "' does not parse";
      continue;
    }
    EXPECT_NEAR((*bound)(c.get("n")->number(), c.get("r")->number()), c.get("value")->number(), kTolerance) << text;
  }
}

TEST(BoundExpr, SharedVectorsWithoutClaimParseToNothing) {
  const Json vectors = shared_vectors();
  const Json* texts = vectors.get("no_claim");
  ASSERT_NE(texts, nullptr);
  ASSERT_FALSE(texts->items.empty());
  for (const Json& text : texts->items) EXPECT_FALSE(BoundExpr::parse(text.text)) << "'" << text.text << "'";
}

// The sweep's budget predicts a key's time from the claim; an algorithm's own budget replaces the
// common one, and a variant without its own takes its base's.
TEST(Budget, AVariantTakesItsBasesBudget) {
  const Algorithm base{.name = "base", .time_bound = "n"};
  const Algorithm variant{.name = "family[base]", .time_bound = "n", .variant_of = "base"};
  const Algorithm other{.name = "other", .time_bound = "n"};
  Budget budget(1.0, {{"base", 100.0}});
  for (const Algorithm* a : {&base, &variant, &other}) budget.record_time(*a, "random", 1000, 0, 2.0);
  EXPECT_FALSE(budget.skip_reason(base, "random", 2000, 0));
  EXPECT_FALSE(budget.skip_reason(variant, "random", 2000, 0));
  EXPECT_EQ(budget.skip_reason(other, "random", 2000, 0).value_or("").rfind("skipped (budget): predicted", 0), 0u);
}

}  // namespace
}  // namespace pd
