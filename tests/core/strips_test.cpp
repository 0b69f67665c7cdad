// The streaming pass over a raster: strips in order, whole, and, when
// overlapped, read on the caller's thread while the work runs on a helper.
#include "raster/strips.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>
#include <vector>

namespace mcmd::detail {
namespace {

// A raster whose cell (x, y) holds y * width + x; every read's thread is noted.
struct CountingRaster {
  int width, height;
  std::vector<std::thread::id> readers;
  RasterAccess access() {
    RasterAccess a;
    a.width = width;
    a.height = height;
    a.read = [this](int x0, int y0, int w, int h, double* z, std::uint8_t* valid) {
      readers.push_back(std::this_thread::get_id());
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
          z[static_cast<std::size_t>(y) * w + x] = static_cast<double>(y0 + y) * width + x0 + x;
          valid[static_cast<std::size_t>(y) * w + x] = 1;
        }
    };
    a.write = [](int, int, int, int, const double*, const std::uint8_t*) {};
    return a;
  }
};

TEST(Strips, OverlappedPassSeesEveryRowInOrderAndReadsOnTheCaller) {
  CountingRaster r{3000, 1000, {}};  // 349 rows a strip: 3 strips
  const RasterAccess a = r.access();
  std::vector<double> seen;
  std::vector<int> ends;
  std::vector<std::thread::id> workers;
  for_each_strip_overlapped(
      a,
      [&](int y0, int rows, const double* z, const std::uint8_t*) {
        workers.push_back(std::this_thread::get_id());
        EXPECT_EQ(static_cast<double>(y0) * r.width, z[0]);
        seen.insert(seen.end(), z, z + static_cast<std::size_t>(rows) * r.width);
      },
      [&](int y_end) { ends.push_back(y_end); });
  ASSERT_EQ(seen.size(), static_cast<std::size_t>(r.width) * r.height);
  for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], static_cast<double>(i));
  EXPECT_EQ(ends, (std::vector<int>{349, 698, 1000}));
  ASSERT_EQ(r.readers.size(), 3u);
  for (const std::thread::id& id : r.readers) EXPECT_EQ(id, std::this_thread::get_id());
  for (const std::thread::id& id : workers) EXPECT_NE(id, std::this_thread::get_id());
}

TEST(Strips, OverlappedPassRethrowsAndStops) {
  CountingRaster r{3000, 1000, {}};
  const RasterAccess a = r.access();
  int calls = 0;
  EXPECT_THROW(for_each_strip_overlapped(
                   a,
                   [&](int, int, const double*, const std::uint8_t*) {
                     if (++calls == 1) throw std::runtime_error("stop");
                   },
                   [](int) { ADD_FAILURE() << "no strip finished"; }),
               std::runtime_error);
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace mcmd::detail
