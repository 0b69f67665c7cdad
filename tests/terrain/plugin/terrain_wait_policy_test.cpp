// mcmd_terrain's OpenMP wait policy: passive unless the user set one, as
// libgomp reports it at start-up (tests/plugin/cli_wait_policy_test.cpp has
// the cases).
#include <gtest/gtest.h>

#include "terrain_support.hpp"
#include "wait_policy_env.hpp"

namespace mcmd::test {
namespace {

#ifdef _OPENMP

TEST(TerrainWaitPolicy, PassiveByDefaultUsersKept) {
  {
    const WaitPolicyEnv env(nullptr, nullptr);
    const RunResult r = run_terrain({"--version"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("GOMP_SPINCOUNT = '0'"), std::string::npos) << r.err;
  }
  const WaitPolicyEnv env("active", nullptr);
  const RunResult r = run_terrain({"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("OMP_WAIT_POLICY = 'ACTIVE'"), std::string::npos) << r.err;
}

#else

TEST(TerrainWaitPolicy, PassiveByDefaultUsersKept) { GTEST_SKIP() << "built without OpenMP"; }

#endif

}  // namespace
}  // namespace mcmd::test
