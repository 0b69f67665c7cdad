#include <gtest/gtest.h>
#include <vector>

#include "paper/delta.hpp"

using namespace mcmd;

TEST(Delta, WeightFollowsThePapersShapes) {
  EXPECT_DOUBLE_EQ(delta_weight(0.0, 5.0, 10.0), 1.0);
  EXPECT_DOUBLE_EQ(delta_weight(1.0, 5.0, 10.0), 0.5);   // linear fall-off
  EXPECT_DOUBLE_EQ(delta_weight(-1.0, 5.0, 10.0), 1.5);  // ridged: grows with distance
  EXPECT_LT(delta_weight(2.0, 5.0, 10.0), delta_weight(0.5, 5.0, 10.0));
}

TEST(Delta, NormalizedFormIsTranslationInvariantPaperFormIsNot) {
  const std::vector<Contribution> a{{100.0, 1.0, 0.8}, {200.0, 3.0, 0.8}};
  const std::vector<Contribution> b{{1100.0, 1.0, 0.8}, {1200.0, 3.0, 0.8}};
  EXPECT_NEAR(combine(DeltaForm::normalized, b, 10.0), combine(DeltaForm::normalized, a, 10.0) + 1000.0, 1e-9);
  EXPECT_GT(std::abs(combine(DeltaForm::paper, b, 10.0) - combine(DeltaForm::paper, a, 10.0) - 1000.0), 1.0);
}

TEST(Delta, EqualDistancesGiveThePlainMeanWhenNormalized) {
  const std::vector<Contribution> c{{1.0, 2.0, 3.0}, {3.0, 2.0, 3.0}};
  EXPECT_DOUBLE_EQ(combine(DeltaForm::normalized, c, 10.0), 2.0);
}
