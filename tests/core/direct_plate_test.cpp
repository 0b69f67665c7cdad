// The exact thin plate of tiny voids (thin_plate/direct_plate.hpp): the same
// surface the multigrid solver converges to, exact on planes, and only for
// fields with few unknown cells.
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

#include "thin_plate/direct_plate.hpp"
#include "test_field.hpp"
#include "thin_plate/thin_plate.hpp"

namespace {

using mcmd::CellState;
using mcmd::test::Field;

// z = f(x, y), unknown where hole(x, y).
template <class F, class H>
Field make(int w, int h, F f, H hole) {
  Field fd{w, h, {}, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      fd.z.push_back(hole(x, y) ? 0.0 : f(x, y));
      fd.state.push_back(hole(x, y) ? CellState::unknown : CellState::known);
    }
  return fd;
}

double terrain(int x, int y) { return 700.0 + 40.0 * std::sin(0.3 * x) * std::cos(0.25 * y) + 0.5 * x * y; }

// A 5×6 void inside the field and a 3×4 one against its left edge (natural
// boundary): the multigrid solver converged without its pull gives the same.
TEST(DirectPlate, MatchesTheConvergedMultigridPlate) {
  const auto holes = [](int x, int y) { return (x >= 9 && x < 14 && y >= 7 && y < 13) || (x < 3 && y >= 2 && y < 6); };
  Field direct = make(24, 20, terrain, holes);
  Field iterative = direct;
  ASSERT_TRUE(mcmd::direct_thin_plate(direct.w, direct.h, direct.z.data(), direct.state.data(), 64));
  mcmd::ThinPlateSchedule converged;
  converged.direct_max_unknown = 0;
  converged.pull_length = 0;
  converged.pcg_tol = 1e-12;
  converged.pcg_max_iterations = 200;
  mcmd::thin_plate_smooth(iterative.view(), converged);
  for (std::size_t i = 0; i < direct.z.size(); ++i) EXPECT_NEAR(direct.z[i], iterative.z[i], 1e-6) << i;
}

TEST(DirectPlate, ExactOnPlanesAndKeepsConstraints) {
  const auto plane = [](int x, int y) { return 1234.5 - 2.25 * x + 0.75 * y; };
  const auto holes = [](int x, int y) { return (x - 6) * (x - 6) + (y - 5) * (y - 5) <= 8; };
  Field f = make(13, 11, plane, holes);
  const Field before = f;
  ASSERT_TRUE(mcmd::direct_thin_plate(f.w, f.h, f.z.data(), f.state.data(), 64));
  for (int y = 0; y < f.h; ++y)
    for (int x = 0; x < f.w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * f.w + x;
      if (f.state[i] == CellState::known) EXPECT_EQ(f.z[i], before.z[i]);
      else EXPECT_NEAR(f.z[i], plane(x, y), 1e-8);
    }
}

// More unknown cells than allowed, or none: not solved here, untouched.
TEST(DirectPlate, DeclinesLargeOrEmptyFields) {
  Field big = make(30, 30, terrain, [](int x, int y) { return x >= 5 && x < 15 && y >= 5 && y < 15; });
  const Field before = big;
  EXPECT_FALSE(mcmd::direct_thin_plate(big.w, big.h, big.z.data(), big.state.data(), 64));
  EXPECT_EQ(big.z, before.z);
  Field none = make(8, 8, terrain, [](int, int) { return false; });
  EXPECT_FALSE(mcmd::direct_thin_plate(none.w, none.h, none.z.data(), none.state.data(), 64));
  // One known cell cannot hold a plate: not unique, declined.
  Field loose = make(4, 4, terrain, [](int x, int y) { return x + y > 0; });
  EXPECT_FALSE(mcmd::direct_thin_plate(loose.w, loose.h, loose.z.data(), loose.state.data(), 64));
}

}  // namespace
