// The smooth thin-plate fill on fields of any size (no 2^n+1 padding): the
// same guarantees as on 2^n+1 grids, and the same result on those.
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

#include "thin_plate/lattice.hpp"
#include "test_field.hpp"
#include "thin_plate/thin_plate.hpp"

namespace {

using mcmd::CellState;
using mcmd::test::Field;

// z = f(x, y) everywhere, a random fraction `keep` known, plus an unknown disc.
template <class F>
Field make_field(int w, int h, double keep, unsigned seed, F f, double cx = 0, double cy = 0, double r = -1) {
  Field fd{w, h, std::vector<double>(static_cast<std::size_t>(w) * h), std::vector<CellState>(fd.z.size())};
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      fd.z[i] = f(x, y);
      const bool known = u(rng) < keep && std::hypot(x - cx, y - cy) > r;
      fd.state[i] = known ? CellState::known : CellState::unknown;
    }
  return fd;
}

double max_error(const Field& a, const Field& truth) {
  double e = 0.0;
  for (std::size_t i = 0; i < a.z.size(); ++i) e = std::max(e, std::abs(a.z[i] - truth.z[i]));
  return e;
}

TEST(ThinPlateField, ExactOnPlanesForOddAndEvenSizes) {
  const auto plane = [](int x, int y) { return 812.25 - 0.3 * x + 1.1 * y; };
  for (const auto& [w, h] : {std::pair{37, 23}, {100, 61}, {64, 64}, {1, 50}, {50, 2}, {3, 3}}) {
    Field f = make_field(w, h, 0.08, 5, plane, w / 2.0, h / 2.0, std::min(w, h) / 4.0);
    f.state[0] = CellState::known;  // at least one constraint
    f.state.back() = CellState::known;
    f.state[static_cast<std::size_t>(h / 2) * w] = CellState::known;
    const Field truth = make_field(w, h, 1.0, 5, plane);
    mcmd::thin_plate_smooth(f.view(), {});
    EXPECT_LT(max_error(f, truth), 1e-6) << w << "x" << h;
  }
}

TEST(ThinPlateField, ReproducesAQuadraticBowlOnANonDyadicField) {
  const auto bowl = [](int x, int y) { return 0.01 * ((x - 70.0) * (x - 70.0) + (y - 40.0) * (y - 40.0)); };
  Field f = make_field(150, 90, 1.0, 3, bowl, 70, 40, 25);
  const Field truth = make_field(150, 90, 1.0, 3, bowl);
  mcmd::thin_plate_smooth(f.view(), {});
  EXPECT_LT(max_error(f, truth), 0.02 * 0.01 * 25.0 * 25.0);
}

TEST(ThinPlateField, KeepsConstraintsAndFillsEveryUnknownCell) {
  const auto wave = [](int x, int y) { return 300.0 + 40.0 * std::sin(0.09 * x) * std::cos(0.07 * y); };
  Field f = make_field(203, 117, 0.3, 8, wave, 120, 60, 30);
  const Field before = f;
  mcmd::thin_plate_smooth(f.view(), {});
  for (std::size_t i = 0; i < f.z.size(); ++i) {
    if (before.state[i] != CellState::unknown) {
      EXPECT_EQ(f.z[i], before.z[i]);
    }
    ASSERT_TRUE(std::isfinite(f.z[i]));
    EXPECT_GT(f.z[i], 200.0);
    EXPECT_LT(f.z[i], 400.0);
  }
}

// On a 2^n+1 square the field path is the grid path (same hierarchy).
TEST(ThinPlateField, SquareDyadicFieldMatchesTheGridFill) {
  const auto wave = [](int x, int y) { return 10.0 * std::sin(0.2 * x) + 0.5 * y; };
  Field f = make_field(65, 65, 0.1, 9, wave, 30, 30, 12);
  mcmd::Grid g(6);
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) {
      g.z(x, y) = f.z[static_cast<std::size_t>(y) * 65 + x];
      g.state(x, y) = f.state[static_cast<std::size_t>(y) * 65 + x];
    }
  mcmd::thin_plate_smooth(f.view(), {});
  mcmd::thin_plate_fill_scheduled(g, {}, {});
  for (int y = 0; y < 65; ++y)
    for (int x = 0; x < 65; ++x) ASSERT_EQ(g.z(x, y), f.z[static_cast<std::size_t>(y) * 65 + x]);
}

}  // namespace

namespace {

// A large field (banded: lattice.hpp) is solved on several threads with the
// same bits as on one, and as accurately as the thin plate must be.
TEST(ThinPlateField, LargeFieldIsThreadCountIndependent) {
  const auto wave = [](int x, int y) { return 500.0 + 60.0 * std::sin(0.03 * x) * std::cos(0.02 * y) + 0.2 * x; };
  Field one = make_field(640, 420, 0.033, 21, wave);
  mcmd::Lattice shape;  // the field's size, every cell free
  shape.w = 640;
  shape.h = 420;
  for (int y = 0; y < shape.h; ++y) shape.spans.push_back({y, 0, shape.w});
  ASSERT_TRUE(mcmd::banded(shape));
  Field two = one;
  mcmd::ThinPlateSchedule s1, s2;
  s2.vcycle.threads = 2;
  mcmd::thin_plate_smooth(one.view(), s1);
  mcmd::thin_plate_smooth(two.view(), s2);
  ASSERT_EQ(one.z, two.z);
  const Field truth = make_field(640, 420, 1.0, 21, wave);
  EXPECT_LT(max_error(one, truth), 3.5);  // relief ~250 m, samples every ~5 cells
}

// 3 % samples: no cell is far from data, so the default schedule stops at the
// shallow tolerance. It must do so (cheaper) and stay close to the converged
// fill: on this smooth wave (relief ~250 m) the max error goes 1.2 → 2.5 m.
TEST(ThinPlateField, LargeShallowFieldStopsEarlyButStaysClose) {
  const auto wave = [](int x, int y) { return 500.0 + 60.0 * std::sin(0.03 * x) * std::cos(0.02 * y) + 0.2 * x; };
  Field loose = make_field(640, 420, 0.033, 21, wave);
  Field tight = loose;
  mcmd::ThinPlateSchedule early, converged;
  early.structure_strength = 0;  // the isotropic solve alone (structure_term_test.cpp: with it)
  converged.shallow_pcg_tol = 0;
  converged.structure_strength = 0;
  mcmd::thin_plate_smooth(loose.view(), early);
  mcmd::thin_plate_smooth(tight.view(), converged);
  const Field truth = make_field(640, 420, 1.0, 21, wave);
  EXPECT_NE(loose.z, tight.z);
  EXPECT_LT(max_error(tight, truth), 1.3);
  EXPECT_LT(max_error(loose, truth), 3.0);
  EXPECT_LT(max_error(loose, tight), 2.0);
}

}  // namespace
