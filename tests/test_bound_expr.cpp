// The time-bound grammar (core/bound_expr.h) on the vectors it shares with the analysis's parser
// (analysis/polydecomp_analysis/bound_expr.py): tests/data/bound_expr_vectors.json, read here and by
// analysis/tests/test_bound_expr.py, so that the harness's budget and the analysis read claims alike.
#include "core/bound_expr.h"
#include "core/json.h"

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

}  // namespace
}  // namespace pd
