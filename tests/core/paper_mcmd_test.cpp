// The paper-exact methods (-method paper-ds / paper-te): MDBU + MD invariants.
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

#include "method/fill_grid.hpp"
#include "paper/mdbu.hpp"
#include "paper/midpoint_displacement.hpp"
#include "paper/paper_fill.hpp"
#include "test_terrain.hpp"

using namespace mcmd;

namespace {

class PaperMethods : public ::testing::TestWithParam<Method> {
 protected:
  FillParams params() const {
    FillParams p;
    p.method = GetParam();
    return p;
  }
};

Grid voided_hills() {
  Grid g = test::grid_of(6, test::hills);
  test::punch_voids(g, 30, 30, 9, 0.3);
  return g;
}

std::vector<std::uint8_t> fixed_of(const Grid& g) {
  std::vector<std::uint8_t> f(g.cell_count());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = is_constraint(g.states()[i]);
  return f;
}

}  // namespace

TEST_P(PaperMethods, KnownCellsNeverChange) {
  const Grid before = voided_hills();
  Grid g = before;
  fill_grid(g, params());
  for (std::size_t i = 0; i < g.cell_count(); ++i) {
    ASSERT_EQ(g.states()[i], before.states()[i]);
    if (is_constraint(before.states()[i])) {
      ASSERT_EQ(g.elevations()[i], before.elevations()[i]);
    }
    ASSERT_TRUE(std::isfinite(g.elevations()[i]));
  }
}

TEST_P(PaperMethods, AfterMdbuEveryAscendantOfAKnownCellIsKnown) {
  Grid g = voided_hills();
  auto fixed = fixed_of(g);
  const Scheme scheme = scheme_of(GetParam());
  const std::size_t set = mdbu(g, fixed, scheme, params());
  EXPECT_GT(set, 0u);
  for (int y = 0; y < g.side(); ++y)
    for (int x = 0; x < g.side(); ++x) {
      if (!fixed[g.index(x, y)]) continue;
      const Parents p = parents_of(scheme, x, y, g.levels());
      for (int i = 0; i < p.count; ++i) ASSERT_TRUE(fixed[g.index(p.cell[i].x, p.cell[i].y)]);
    }
}

TEST_P(PaperMethods, NoUnknownCellRemainsAfterMd) {
  Grid g = voided_hills();
  auto fixed = fixed_of(g);
  const Scheme scheme = scheme_of(GetParam());
  mdbu(g, fixed, scheme, params());
  midpoint_displacement(g, fixed, scheme, params(), 1.0);
  for (std::size_t i = 0; i < fixed.size(); ++i) ASSERT_TRUE(fixed[i]);
}

TEST_P(PaperMethods, RaisedCentreGivesAMonotoneProfile) {
  // Paper Fig. 2: corners at a medium elevation, centre at the maximum.
  Grid g(6);
  const int last = g.side() - 1, mid = last / 2;
  for (int c : {0, last})
    for (int r : {0, last}) g.z(c, r) = 100.0, g.state(c, r) = CellState::known;
  g.z(mid, mid) = 900.0;
  g.state(mid, mid) = CellState::known;
  fill_grid(g, params());
  for (int x = mid; x < last; ++x) ASSERT_GE(g.z(x, mid), g.z(x + 1, mid)) << x;           // centre → edge
  for (int d = mid; d < last; ++d) ASSERT_GE(g.z(d, d), g.z(d + 1, d + 1)) << d;           // centre → corner
  for (int x = 0; x < mid; ++x) ASSERT_LE(g.z(x, mid), g.z(x + 1, mid)) << x;
}

TEST_P(PaperMethods, NormalizedFormIsTranslationInvariant) {
  FillParams p = params();
  p.known_shape = {0.8, -0.6};  // Δ shapes that matter
  Grid a = voided_hills();
  Grid b = a;
  for (std::size_t i = 0; i < b.cell_count(); ++i)
    if (is_constraint(b.states()[i])) b.elevations()[i] += 1234.5;
  fill_grid(a, p);
  fill_grid(b, p);
  for (std::size_t i = 0; i < a.cell_count(); ++i) ASSERT_NEAR(b.elevations()[i], a.elevations()[i] + 1234.5, 1e-6);
}

TEST_P(PaperMethods, PaperFormWithShapesPullsTowardZero) {
  FillParams p = params();
  p.delta_form = DeltaForm::paper;
  p.known_shape = {0.8, 0.8};
  Grid exact = voided_hills();
  Grid normalized = exact;
  fill_grid(exact, p);
  p.delta_form = DeltaForm::normalized;
  fill_grid(normalized, p);
  double lower = 0;
  for (std::size_t i = 0; i < exact.cell_count(); ++i) lower += normalized.elevations()[i] - exact.elevations()[i];
  EXPECT_GT(lower, 0.0);
}

TEST_P(PaperMethods, SameSeedSameTerrainOtherSeedOther) {
  FillParams p = params();
  p.rs = 0.2;
  p.seed = 11;
  Grid a = voided_hills(), b = voided_hills(), c = voided_hills();
  fill_grid(a, p);
  fill_grid(b, p);
  p.seed = 12;
  fill_grid(c, p);
  EXPECT_EQ(a.elevations(), b.elevations());
  EXPECT_NE(a.elevations(), c.elevations());
}

TEST_P(PaperMethods, RidgeCellsCarryTheirOwnShape) {
  Grid plain = voided_hills();
  Grid ridged = plain;
  for (int x = 0; x < ridged.side(); ++x)
    if (is_constraint(ridged.state(x, 20))) ridged.state(x, 20) = CellState::ridge;
  FillParams p = params();
  p.ridge_shape = {-2.0, 6.0};
  fill_grid(plain, p);
  fill_grid(ridged, p);
  EXPECT_NE(plain.elevations(), ridged.elevations());
}

TEST_P(PaperMethods, ProgressEndsAtOneAndCancelStops) {
  double last = -1;
  Grid g = voided_hills();
  fill_grid(g, params(), [&](double f) {
    EXPECT_GE(f, last);
    last = f;
    return true;
  });
  EXPECT_DOUBLE_EQ(last, 1.0);
  Grid h = voided_hills();
  EXPECT_THROW(fill_grid(h, params(), [](double f) { return f < 0.3; }), Cancelled);
}

INSTANTIATE_TEST_SUITE_P(BothSchemes, PaperMethods, ::testing::Values(Method::paper_ds, Method::paper_te),
                         [](const auto& info) { return info.param == Method::paper_ds ? "ds" : "te"; });

TEST(Fill, RejectsAGridWithoutKnownCells) {
  Grid g(3);
  EXPECT_THROW(fill_grid(g, FillParams{}), std::invalid_argument);
}
