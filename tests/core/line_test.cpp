// The 1D case: paper Fig. 4 (MD alone jumps at interior constraints) against
// Fig. 6 (MDBU first: no jump).
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

#include "paper/line.hpp"

using namespace mcmd;

namespace {

struct Profile {
  std::vector<double> z = std::vector<double>(65, 0.0);
  std::vector<CellState> s = std::vector<CellState>(65, CellState::unknown);
  void set(int i, double v) { z[i] = v, s[i] = CellState::known; }
};

Profile interior_constraints() {
  Profile p;  // constraints inside intervals whose ends are unknown
  p.set(5, 10.0);
  p.set(37, 80.0);
  p.set(41, 90.0);
  return p;
}

double largest_step(const std::vector<double>& z) {
  double m = 0;
  for (std::size_t i = 1; i < z.size(); ++i) m = std::max(m, std::fabs(z[i] - z[i - 1]));
  return m;
}

}  // namespace

TEST(Line, MdAloneJumpsMcmdDoesNot) {
  const Profile p = interior_constraints();
  const FillParams params;
  const auto md = line_md(p.z, p.s, params);
  const auto mcmd = line_mcmd(p.z, p.s, params);
  EXPECT_GT(largest_step(md), 30.0);   // Fig. 4: a jump of ~50 next to cell 5
  EXPECT_LT(largest_step(mcmd), 10.0);  // Fig. 6: no jump
  for (int i : {5, 37, 41}) {
    EXPECT_EQ(md[i], p.z[i]);
    EXPECT_EQ(mcmd[i], p.z[i]);
  }
}

TEST(Line, NoiseIsDeterministicPerSeed) {
  const Profile p = interior_constraints();
  FillParams params;
  params.rs = 0.3;
  params.seed = 5;
  const auto a = line_mcmd(p.z, p.s, params);
  EXPECT_EQ(a, line_mcmd(p.z, p.s, params));
  params.seed = 6;
  EXPECT_NE(a, line_mcmd(p.z, p.s, params));
}

TEST(Line, RejectsLengthsThatAreNotTwoToTheNPlusOne) {
  const std::vector<double> z(10, 0.0);
  const std::vector<CellState> s(10, CellState::known);
  EXPECT_THROW(line_md(z, s, FillParams{}), std::invalid_argument);
}
