// The output's temporary folder (<stem>.mcmd-tmp-<pid>/, output_file.hpp):
// what a killed run leaves is removed by the next run writing the same
// dst_file, and only what belongs to processes that no longer exist.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

namespace fs = std::filesystem;

bool has_temporary(const TempDir& dir) {
  for (const std::string& name : dir.listing())
    if (name.find(".mcmd-tmp-") != std::string::npos) return true;
  return false;
}

// The id of a process that has just ended.
pid_t gone_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

TEST(CliTemporaries, ThoseOfGoneProcessesAreRemoved) {
  TempDir dir;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, RasterSpec{});
  const std::string gone = std::to_string(gone_pid()), alive = std::to_string(::getppid());
  fs::create_directory(dir.file("dst.mcmd-tmp-" + gone));
  std::ofstream(dir.file("dst.mcmd-tmp-" + gone + "/dst.tif")) << "left by a killed run";
  std::ofstream(dir.file("dst.mcmd-tmp-" + gone + ".tif")) << "an earlier version's name";
  std::ofstream(dir.file("dst.tif.work.mcmd-tmp-" + gone + ".tif")) << "an earlier version's work file";
  std::ofstream(dir.file("dst.mcmd-tmp-" + alive + ".tif")) << "a run still going";
  std::ofstream(dir.file("dst.mcmd-tmp-x.tif")) << "not ours";
  std::ofstream(dir.file("other.mcmd-tmp-" + gone + ".tif")) << "another destination's";

  const RunResult r = run_cli({"-q", src, dst});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"dst.mcmd-tmp-" + alive + ".tif", "dst.mcmd-tmp-x.tif", "dst.tif",
                                                     "other.mcmd-tmp-" + gone + ".tif", "src.tif"}));
}

TEST(CliTemporaries, KilledRunLeavesItsFolderUntilTheNextRun) {
  TempDir dir, io;
  RasterSpec big;
  big.type = GDT_Float32;
  big.width = big.height = 1600;  // several seconds of tiled fill with -rs
  big.nodata = -9999.0;
  const std::string src = dir.file("src.tif"), dst = dir.file("dst.tif");
  make_raster(src, big);
  const RunningCli run = start_cli({"-q", "-rs", "auto", "-of", "COG", src, dst}, io);
  for (int i = 0; i < 1000 && !has_temporary(dir); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(run.pid, SIGKILL);
  const RunResult killed = finish_cli(run);
  ASSERT_EQ(killed.exit_code, 128 + SIGKILL);
  ASSERT_TRUE(has_temporary(dir)) << "the run ended before it could be killed";

  make_raster(src, RasterSpec{});
  const RunResult again = run_cli({"-q", src, dst});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(dir.listing(), (std::vector<std::string>{"dst.tif", "src.tif"}));
}

}  // namespace
}  // namespace mcmd::test
