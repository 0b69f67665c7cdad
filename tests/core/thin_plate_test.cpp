// The default method (thin-plate MCMD): exactness, invariances, constraints
// untouched, border voids bounded, and its building blocks.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <random>

#include "method/fill_grid.hpp"
#include "thin_plate/biharmonic_relax.hpp"
#include "thin_plate/cubic_prolong.hpp"
#include "thin_plate/multigrid.hpp"
#include "thin_plate/thin_plate.hpp"

namespace {

using mcmd::CellState;
using mcmd::Grid;

// A grid of side 2^n+1 with z = f(x, y) and a random fraction `keep` known.
template <class F>
Grid make_grid(int n, double keep, unsigned seed, F f) {
  Grid g(n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int y = 0; y < g.side(); ++y)
    for (int x = 0; x < g.side(); ++x) {
      g.z(x, y) = f(x, y);
      g.state(x, y) = u(rng) < keep ? CellState::known : CellState::unknown;
    }
  return g;
}

// Unknown disc of radius r around (cx, cy).
void punch_disc(Grid& g, double cx, double cy, double r) {
  for (int y = 0; y < g.side(); ++y)
    for (int x = 0; x < g.side(); ++x)
      if (std::hypot(x - cx, y - cy) <= r) g.state(x, y) = CellState::unknown;
}

double max_error(const Grid& filled, const Grid& truth) {
  double e = 0.0;
  for (std::size_t i = 0; i < filled.cell_count(); ++i)
    e = std::max(e, std::abs(filled.elevations()[i] - truth.elevations()[i]));
  return e;
}

void fill_default(Grid& g, const mcmd::FillParams& p = {}) { mcmd::fill_grid(g, p); }

TEST(ThinPlate, ExactOnTiltedPlaneWithRandomVoids) {
  const auto plane = [](int x, int y) { return 1234.5 + 0.7 * x - 0.4 * y; };
  Grid g = make_grid(7, 0.05, 1, plane);
  punch_disc(g, 40, 70, 20);
  const Grid truth = make_grid(7, 1.0, 1, plane);
  fill_default(g);
  EXPECT_LT(max_error(g, truth), 1e-6);
}

TEST(ThinPlate, ExactOnPlaneWithVoidAtTheBorder) {
  const auto plane = [](int x, int y) { return -50.0 + 2.0 * x + 3.0 * y; };
  Grid g = make_grid(6, 1.0, 2, plane);
  punch_disc(g, 0, 0, 30);
  const Grid truth = make_grid(6, 1.0, 2, plane);
  fill_default(g);
  EXPECT_LT(max_error(g, truth), 1e-6);
}

// A quadratic is biharmonic (Δ²q = 0, and the 13-point stencil is exact on it),
// so an interior void in a bowl is filled by the bowl itself once converged.
// Tolerance: 2% of the bowl's depth inside the void after the default schedule
// (measured 1.35%; 30 V-cycles reach 0.05%).
TEST(ThinPlate, ReproducesAQuadraticBowl) {
  const auto bowl = [](int x, int y) { return 0.01 * ((x - 64.0) * (x - 64.0) + (y - 60.0) * (y - 60.0)); };
  Grid g = make_grid(7, 1.0, 3, bowl);
  punch_disc(g, 64, 60, 25);
  const Grid truth = make_grid(7, 1.0, 3, bowl);
  fill_default(g);
  const double depth = 0.01 * 25.0 * 25.0;
  EXPECT_LT(max_error(g, truth), 0.02 * depth);
}

TEST(ThinPlate, ReproducesABowlFromScatteredSamples) {
  const auto bowl = [](int x, int y) { return 0.02 * ((x - 30.0) * (x - 30.0) + (y - 35.0) * (y - 35.0)); };
  Grid g = make_grid(6, 0.1, 4, bowl);
  const Grid truth = make_grid(6, 1.0, 4, bowl);
  fill_default(g);
  // Cells more than 3 from the border: there the natural boundary bends the plate.
  double e = 0.0;
  for (int y = 3; y < g.side() - 3; ++y)
    for (int x = 3; x < g.side() - 3; ++x) e = std::max(e, std::abs(g.z(x, y) - truth.z(x, y)));
  // 2.5% of the bowl's relief (measured 1.8%: the coarse springs pull towards
  // footprint means, which a bowl's curvature biases; more V-cycles remove it).
  EXPECT_LT(e, 0.025 * 0.02 * 35.0 * 35.0);
}

// Rough synthetic terrain: a few sines plus hashed noise.
double terrain(int x, int y) {
  const double n = std::sin(x * 12.9898 + y * 78.233) * 43758.5453;
  return 500.0 + 80.0 * std::sin(x * 0.07) * std::cos(y * 0.05) + 30.0 * std::sin((x + 2 * y) * 0.13) +
         5.0 * (n - std::floor(n));
}

TEST(ThinPlate, TranslationInvariant) {
  Grid a = make_grid(7, 0.2, 5, terrain);
  punch_disc(a, 90, 30, 18);
  Grid b = a;
  for (std::size_t i = 0; i < b.cell_count(); ++i) b.elevations()[i] += 10000.0;
  fill_default(a);
  fill_default(b);
  double e = 0.0;
  for (std::size_t i = 0; i < a.cell_count(); ++i)
    e = std::max(e, std::abs(b.elevations()[i] - 10000.0 - a.elevations()[i]));
  EXPECT_LT(e, 1e-8 * 10000.0);
}

TEST(ThinPlate, NeverAltersConstraintCellsOrStates) {
  Grid g = make_grid(7, 0.3, 6, terrain);
  for (int x = 10; x < 100; ++x) g.state(x, 64) = CellState::ridge;
  for (int y = 5; y < 50; ++y) g.state(20, y) = CellState::river;
  punch_disc(g, 64, 64, 15);
  const Grid before = g;
  fill_default(g);
  for (std::size_t i = 0; i < g.cell_count(); ++i) {
    ASSERT_EQ(g.states()[i], before.states()[i]);
    if (mcmd::is_constraint(before.states()[i])) {
      ASSERT_EQ(std::memcmp(&g.elevations()[i], &before.elevations()[i], sizeof(double)), 0);
    }
    ASSERT_TRUE(std::isfinite(g.elevations()[i]));
  }
}

TEST(ThinPlate, VoidsTouchingTheBorderStayBounded) {
  for (int corner = 0; corner < 4; ++corner) {
    Grid g = make_grid(7, 1.0, 7, terrain);
    const double cx = (corner & 1) ? 128 : 0, cy = (corner & 2) ? 128 : 0;
    punch_disc(g, cx, cy, 70);                     // a quarter of the grid, two borders
    for (int x = 0; x < g.side(); ++x) g.state(x, 64) = CellState::unknown;  // a border-to-border strip
    const double lo = 500 - 120, hi = 500 + 120;   // terrain's envelope
    fill_default(g);
    for (double z : g.elevations()) {
      ASSERT_TRUE(std::isfinite(z));
      ASSERT_GT(z, lo - 2 * (hi - lo));
      ASSERT_LT(z, hi + 2 * (hi - lo));
    }
  }
}

TEST(ThinPlate, TinyGridsAndSingleConstraint) {
  for (int n = 0; n <= 3; ++n) {
    Grid g(n);
    g.z(0, 0) = 42.0;
    g.state(0, 0) = CellState::known;
    fill_default(g);
    for (double z : g.elevations()) EXPECT_NEAR(z, 42.0, 1e-9);
  }
}

TEST(ThinPlate, Deterministic) {
  Grid a = make_grid(7, 0.05, 8, terrain);
  Grid b = a;
  fill_default(a);
  fill_default(b);
  EXPECT_EQ(std::memcmp(a.elevations().data(), b.elevations().data(), a.cell_count() * sizeof(double)), 0);
}

// The fast interior stencil is the energy gradient the border code computes.
TEST(BiharmonicRelax, InteriorStencilIsTheEnergyGradient) {
  const int side = 9;
  std::vector<double> z(side * side);
  std::mt19937 rng(9);
  std::normal_distribution<double> n01;
  for (double& v : z) v = n01(rng);
  mcmd::Lattice lat;
  lat.w = lat.h = side;
  lat.z = z;
  lat.pinned.assign(z.size(), 0);
  const int x = 4, y = 4;
  const auto at = [&](int dx, int dy) { return z[(y + dy) * side + x + dx]; };
  const double stencil = 20 * at(0, 0) - 8 * (at(-1, 0) + at(1, 0) + at(0, -1) + at(0, 1)) +
                         2 * (at(-1, -1) + at(1, -1) + at(-1, 1) + at(1, 1)) +
                         (at(-2, 0) + at(2, 0) + at(0, -2) + at(0, 2));
  const mcmd::ThinPlateRow row = mcmd::thin_plate_row(z.data(), side, side, x, y);
  EXPECT_NEAR(row.az, stencil, 1e-12);
  EXPECT_DOUBLE_EQ(row.diag, 20.0);
  EXPECT_NEAR(mcmd::residual_at(lat, nullptr, x, y), -stencil, 1e-12);
}

TEST(BiharmonicRelax, PlanesAreInTheNullSpaceEvenAtTheBorder) {
  const int side = 6;
  std::vector<double> z(side * side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) z[y * side + x] = 3.0 + 2.0 * x - 5.0 * y;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) EXPECT_NEAR(mcmd::thin_plate_row(z.data(), side, side, x, y).az, 0.0, 1e-12);
}

TEST(CubicProlong, ExactOnCubicsInsideAndQuadraticsAtTheBorder) {
  const int mc = 9, mf = 2 * mc - 1;
  std::vector<double> cubic(mc * mc), quad(mc * mc);
  const auto fc = [](double x, double y) { return 0.01 * x * x * x - 0.2 * x * y + y * y; };
  const auto fq = [](double x, double y) { return 0.3 * x * x - 0.2 * x * y + y; };
  for (int j = 0; j < mc; ++j)
    for (int i = 0; i < mc; ++i) {
      cubic[j * mc + i] = fc(2.0 * i, 2.0 * j);
      quad[j * mc + i] = fq(2.0 * i, 2.0 * j);
    }
  for (int y = 0; y < mf; ++y)
    for (int x = 0; x < mf; ++x) {
      EXPECT_NEAR(mcmd::prolong_at(quad.data(), mc, mc, x, y), fq(x, y), 1e-9);
      if (x >= 3 && y >= 3 && x <= mf - 4 && y <= mf - 4) {
        EXPECT_NEAR(mcmd::prolong_at(cubic.data(), mc, mc, x, y), fc(x, y), 1e-9);
      }
    }
}

// A 129² lattice with 4 % of its cells pinned at random heights.
mcmd::Lattice scattered_lattice(unsigned seed) {
  const int side = (1 << 7) + 1;
  mcmd::Lattice lat;
  lat.w = lat.h = side;
  lat.z.assign(side * side, 0.0);
  lat.pinned.assign(side * side, 0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < lat.z.size(); ++i)
    if (u(rng) < 0.04) {
      lat.pinned[i] = 1;
      lat.z[i] = 100.0 * u(rng);
    }
  lat.spans = mcmd::free_spans(lat.pinned, side, side);
  return lat;
}

// Euclidean norm of the thin-plate residual on the free cells.
double residual_norm(const mcmd::Lattice& lat) {
  std::vector<double> r(lat.z.size(), 0.0);
  mcmd::residual(lat, nullptr, r);
  double s = 0;
  for (double v : r) s += v * v;
  return std::sqrt(s);
}

// Plain V-cycles need coarse problems at least as stiff as the fine one
// (CoarsePin::neighbourhood); the default's soft coarse pins overshoot alone.
TEST(Multigrid, VCyclesConvergeOnScatteredConstraints) {
  mcmd::Lattice lat = scattered_lattice(10);
  const auto norm = [&] { return residual_norm(lat); };
  const double r0 = norm();
  mcmd::VCycleSchedule stiff;
  stiff.coarse_pin = mcmd::CoarsePin::neighbourhood;
  mcmd::Multigrid mg(lat, stiff);
  for (int c = 0; c < 20; ++c) mg.v_cycle(lat);
  EXPECT_LT(norm(), 1e-3 * r0);
}

// V-cycle-preconditioned CG (flexible form) reaches a tight relative residual
// in far fewer iterations than plain V-cycles need, and stops by its rule.
TEST(Multigrid, PreconditionedCgConvergesOnScatteredConstraints) {
  mcmd::Lattice lat = scattered_lattice(11);
  const auto norm = [&] { return residual_norm(lat); };
  const double r0 = norm();
  mcmd::Multigrid mg(lat, {});
  const int it = mg.solve_pcg(lat, 1e-6, 100);
  EXPECT_LT(it, 100);
  EXPECT_LT(norm(), 1e-6 * r0 * 1.0001);
}

// The soft coarse pins (the default) keep the coarse corrections alive under
// scattered constraints: CG needs fewer iterations than with coarse lattices
// pinned around every fine constraint, to the same residual.
TEST(Multigrid, SoftCoarsePinsPreconditionScatteredConstraintsBetter) {
  const auto iterations = [](mcmd::CoarsePin rule) {
    mcmd::Lattice lat = scattered_lattice(11);
    mcmd::VCycleSchedule s;
    s.coarse_pin = rule;
    mcmd::Multigrid mg(lat, s);
    return mg.solve_pcg(lat, 1e-6, 100);
  };
  EXPECT_LT(iterations(mcmd::CoarsePin::soft), iterations(mcmd::CoarsePin::neighbourhood));
}

// The finest-level springs (the pull towards the cascade's fill) are part of
// the operator CG solves: its solution is a fixed point of the Gauss-Seidel
// smoother, which minimises the same energy springs included.
TEST(Multigrid, PreconditionedCgSolvesTheProblemWithSprings) {
  const int n = 6, side = (1 << n) + 1;
  mcmd::Lattice lat;
  lat.w = lat.h = side;
  lat.z.assign(side * side, 0.0);
  lat.pinned.assign(side * side, 0);
  lat.spring.assign(side * side, 0.0);
  lat.target.assign(side * side, 0.0);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const std::size_t i = lat.index(x, y);
      const bool rim = std::hypot(x - 32.0, y - 30.0) > 24.0;
      if (rim && u(rng) < 0.5) {
        lat.pinned[i] = 1;
        lat.z[i] = 50.0 * std::sin(0.1 * x) + 0.5 * y + u(rng);
      } else {
        lat.spring[i] = std::pow(8.0, -4.0);
        lat.target[i] = 30.0 * std::cos(0.05 * (x + y));
      }
    }
  lat.spans = mcmd::free_spans(lat.pinned, side, side);
  mcmd::Multigrid mg(lat, {});
  const int it = mg.solve_pcg(lat, 1e-10, 200);
  EXPECT_LT(it, 200);
  const std::vector<double> solved = lat.z;
  mcmd::relax(lat, nullptr, 1);
  double change = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < solved.size(); ++i) {
    change = std::max(change, std::abs(lat.z[i] - solved[i]));
    scale = std::max(scale, std::abs(solved[i]));
  }
  EXPECT_LT(change, 1e-7 * scale);
}

// The pull (one spring on every free cell) is part of every coarse
// correction's problem, at 16× per level: without it the corrections are too
// soft for the smooth modes the pull holds deep inside a large void, and CG
// crawls (measured here, to 1e-6: 29 iterations with it, not there in 100
// without).
TEST(Multigrid, CoarseCorrectionsCarryThePull) {
  const int side = 257;
  mcmd::Lattice lat;
  lat.w = lat.h = side;
  lat.z.assign(side * side, 0.0);
  lat.pinned.assign(side * side, 0);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      if (std::hypot(x - 128.0, y - 128.0) > 110.0) {
        lat.pinned[lat.index(x, y)] = 1;
        lat.z[lat.index(x, y)] = 40.0 * std::sin(0.03 * x) + 0.2 * y * std::cos(0.02 * x);
      }
  lat.spans = mcmd::free_spans(lat.pinned, side, side);
  lat.spring_all = std::pow(8.0, -4.0);
  mcmd::Multigrid mg(lat, {});
  const int it = mg.solve_pcg(lat, 1e-6, 100);
  EXPECT_LE(it, 40);
}

// The pull is a far-field term: within a couple of cells of the data the fill
// is the thin plate's, deep inside a large void it moves towards the
// cascade's estimate.
TEST(ThinPlate, PullActsDeepInsideLargeVoidsOnly) {
  Grid g = make_grid(8, 1.0, 13, terrain);
  punch_disc(g, 128, 120, 60);
  Grid plain = g;
  mcmd::ThinPlateSchedule converged;
  converged.pull_length = 0.0;
  converged.pcg_tol = 1e-9;
  converged.pcg_max_iterations = 300;
  mcmd::thin_plate_fill_scheduled(plain, {}, converged);
  mcmd::ThinPlateSchedule pulled = converged;
  pulled.pull_length = mcmd::ThinPlateSchedule{}.pull_length;
  mcmd::thin_plate_fill_scheduled(g, {}, pulled);
  double near = 0.0, deep = 0.0;
  for (int y = 0; y < g.side(); ++y)
    for (int x = 0; x < g.side(); ++x) {
      const double r = std::hypot(x - 128.0, y - 120.0);
      const double d = std::abs(g.z(x, y) - plain.z(x, y));
      if (r <= 60 && r > 58) near = std::max(near, d);
      if (r < 30) deep = std::max(deep, d);
    }
  // Measured: 1.9 within 2 cells of the rim, 44 within 30 cells of the centre.
  EXPECT_GT(deep, 0.0);
  EXPECT_LT(near, 0.1 * deep);
}

}  // namespace
