// The CLI's OpenMP wait policy (cli/wait_policy.cpp): passive unless the user
// set OMP_WAIT_POLICY or GOMP_SPINCOUNT, as libgomp itself reports it at
// start-up (OMP_DISPLAY_ENV=verbose). Passive is a spin count of 0; libgomp's
// own default (300000) also prints OMP_WAIT_POLICY = 'PASSIVE'.
#include <gtest/gtest.h>

#include "test_support.hpp"
#include "wait_policy_env.hpp"

namespace mcmd::test {
namespace {

#ifdef _OPENMP

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

TEST(CliWaitPolicy, PassiveByDefault) {
  TempDir dir;
  make_raster(dir.file("src.tif"), RasterSpec{});
  const WaitPolicyEnv env(nullptr, nullptr);
  const RunResult r = run_cli({"-q", dir.file("src.tif"), dir.file("dst.tif")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "OMP_WAIT_POLICY = 'PASSIVE'")) << r.err;
  EXPECT_TRUE(contains(r.err, "GOMP_SPINCOUNT = '0'")) << r.err;
  EXPECT_TRUE(file_exists(dir.file("dst.tif")));
}

TEST(CliWaitPolicy, UsersPolicyIsKept) {
  const WaitPolicyEnv env("active", nullptr);
  const RunResult r = run_cli({"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "OMP_WAIT_POLICY = 'ACTIVE'")) << r.err;
  EXPECT_FALSE(contains(r.err, "GOMP_SPINCOUNT = '0'")) << r.err;
}

TEST(CliWaitPolicy, UsersSpinCountIsKept) {
  const WaitPolicyEnv env(nullptr, "1000");
  const RunResult r = run_cli({"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "GOMP_SPINCOUNT = '1000'")) << r.err;
}

#else

TEST(CliWaitPolicy, PassiveByDefault) { GTEST_SKIP() << "built without OpenMP"; }

#endif

}  // namespace
}  // namespace mcmd::test
