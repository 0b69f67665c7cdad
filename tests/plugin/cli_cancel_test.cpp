// Cancelling (SIGINT, SIGTERM) stops every phase within a second, GDAL's own
// silent steps included (closing a huge uncompressed GeoTIFF copy writes
// every block nobody wrote, without progress): one error line, nothing left,
// the source untouched. A raster that cannot fit is refused before writing.
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <gtest/gtest.h>
#include <optional>
#include <sys/statvfs.h>
#include <thread>
#include <unistd.h>

#include "test_support.hpp"

namespace mcmd::test {
namespace {

using Clock = std::chrono::steady_clock;

// A VRT of size×size Int16 cells whose only data is the small raster at `src`.
void make_sparse_vrt(const std::string& path, const std::string& src, long size) {
  std::ofstream(path) << "<VRTDataset rasterXSize=\"" << size << "\" rasterYSize=\"" << size << "\">\n"
                      << "  <GeoTransform>350000, 30, 0, 4110000, 0, -30</GeoTransform>\n"
                      << "  <VRTRasterBand dataType=\"Int16\" band=\"1\">\n"
                      << "    <NoDataValue>-32768</NoDataValue>\n"
                      << "    <SimpleSource>\n"
                      << "      <SourceFilename relativeToVRT=\"0\">" << src << "</SourceFilename>\n"
                      << "      <SourceBand>1</SourceBand>\n"
                      << "    </SimpleSource>\n"
                      << "  </VRTRasterBand>\n"
                      << "</VRTDataset>\n";
}

double free_gb(const std::string& dir) {
  struct statvfs st {};
  if (::statvfs(dir.c_str(), &st) != 0) return 0;
  return static_cast<double>(st.f_bavail) * static_cast<double>(st.f_frsize) / 1e9;
}

// Whether process `pid` has `path` open (Linux: /proc/<pid>/fd).
bool has_open(pid_t pid, const std::string& path) {
  std::error_code ec;
  for (const auto& fd : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec))
    if (std::filesystem::read_symlink(fd.path(), ec) == path) return true;
  return false;
}

struct Stopped {
  double seconds;  // from the signal to the end
  RunResult result;
};

// Sends `sig` to `run` once `ready` holds (polled, up to 10 s).
Stopped signal_when(const RunningCli& run, int sig, const std::function<bool()>& ready) {
  for (int i = 0; i < 2000 && !ready(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const auto t0 = Clock::now();
  ::kill(run.pid, sig);
  RunResult r = finish_cli(run);
  return {std::chrono::duration<double>(Clock::now() - t0).count(), std::move(r)};
}

class CliCancel : public ::testing::TestWithParam<int> {};

// 48000² Int16 (4.6 GB uncompressed) over a 67×45 raster: the copy's own
// progress ends at once (empty blocks are left for the close), the close
// then writes gigabytes without a progress call.
TEST_P(CliCancel, StopsTheCopyWithinASecondLeavingNothing) {
  TempDir dir, io;
  if (free_gb(dir.path()) < 10) GTEST_SKIP() << "needs 10 GB free in " << dir.path();
  make_raster(dir.file("data.tif"), RasterSpec{});
  const std::string vrt = dir.file("src.vrt"), dst = dir.file("dst.tif");
  make_sparse_vrt(vrt, dir.file("data.tif"), 48000);
  const auto listing = dir.listing();
  const RunningCli run = start_cli({"-q", vrt, dst}, io);
  const std::string copy = dir.file("dst.mcmd-tmp-" + std::to_string(run.pid) + "/dst.tif");
  const Stopped s = signal_when(run, GetParam(), [&] { return file_exists(copy); });
  EXPECT_LT(s.seconds, 1.0);
  EXPECT_EQ(s.result.exit_code, 1);
  EXPECT_EQ(s.result.err, "mcmd_fillnodata: error: cancelled by the user\n");
  EXPECT_EQ(dir.listing(), listing) << "left behind";
}

// In place, the fill stops at its next progress report: before it writes
// (the source untouched), or, when the tiles had begun writing, saying so.
TEST_P(CliCancel, StopsAFillInPlaceWithinASecondSayingWhatIsLeft) {
  TempDir dir, io;
  RasterSpec spec;
  spec.type = GDT_Float32;
  spec.width = spec.height = 1400;  // a second or more of -rs auto fill
  spec.nodata = -9999.0;
  const std::string src = dir.file("src.tif");
  make_raster(src, spec);
  const std::string before = file_bytes(src);
  const RunningCli run = start_cli({"-q", "-rs", "auto", "-threads", "1", src}, io);
  // Signalled once it has opened the source (its handlers are set: a
  // sanitizer build takes a while to reach main), and a little later.
  std::optional<Clock::time_point> opened;
  const Stopped s = signal_when(run, GetParam(), [&] {
    if (!opened && has_open(run.pid, src)) opened = Clock::now();
    return opened && Clock::now() - *opened > std::chrono::milliseconds(150);
  });
  EXPECT_LT(s.seconds, 1.0);
  EXPECT_EQ(s.result.exit_code, 1) << "the fill ended first?";
  EXPECT_EQ(line_count(s.result.err), 1);
  EXPECT_EQ(s.result.err.rfind("mcmd_fillnodata: error: cancelled by the user", 0), 0u) << s.result.err;
  if (s.result.err.find("partly filled in place") == std::string::npos) {
    EXPECT_TRUE(file_bytes(src) == before) << "source modified, and not said: " << s.result.err;
  }
  EXPECT_EQ(dir.listing(), std::vector<std::string>{"src.tif"});
}

INSTANTIATE_TEST_SUITE_P(Signals, CliCancel, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& info) { return info.param == SIGINT ? "Interrupt" : "Terminate"; });

TEST(CliSpace, RasterThatCannotFitIsRefusedBeforeWriting) {
  TempDir dir;
  make_raster(dir.file("data.tif"), RasterSpec{});
  const std::string vrt = dir.file("src.vrt"), dst = dir.file("dst.tif");
  make_sparse_vrt(vrt, dir.file("data.tif"), 3000000);  // 18 TB uncompressed
  const auto listing = dir.listing();
  const RunResult r = run_cli({"-q", vrt, dst});
  expect_clean_failure(r, "it needs 18000.0 GB (the uncompressed raster)", dir, listing, vrt, file_bytes(vrt));
  EXPECT_NE(r.err.find("free"), std::string::npos) << r.err;
  const RunResult cog = run_cli({"-q", "-of", "COG", vrt, dst});
  expect_clean_failure(cog, "(the uncompressed work file)", dir, listing, vrt, file_bytes(vrt));
}

}  // namespace
}  // namespace mcmd::test
