// Helpers for the plugin tests: temporary folders, real rasters made with the
// GDAL API, and running the real mcmd_fillnodata binary.
#pragma once

#include <cstdint>
#include <optional>
#include <sys/types.h>
#include <string>
#include <vector>

#include "gdal_priv.h"

namespace mcmd::test {

// A fresh folder under the system temp dir, removed with its content.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::string& path() const { return path_; }
  std::string file(const std::string& name) const { return path_ + "/" + name; }
  std::vector<std::string> listing() const;  // sorted file names

 private:
  std::string path_;
};

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// Run mcmd_fillnodata with `args` (and optionally through /bin/sh with
// `shell_prefix`, e.g. "ulimit -f 20;").
RunResult run_cli(const std::vector<std::string>& args, const std::string& shell_prefix = "");
// Run mcmd_fillnodata with `args` through `wrapper`, a program (absolute
// path) and its arguments that runs the rest (e.g. setpriv, as another user).
RunResult run_cli_under(const std::vector<std::string>& wrapper, const std::vector<std::string>& args);

// mcmd_fillnodata started in the background, its stdout and stderr going to
// files of `io` (which must outlive it); finish_cli waits for it.
struct RunningCli {
  pid_t pid = -1;
  std::string out, err;
};
RunningCli start_cli(const std::vector<std::string>& args, const TempDir& io);
RunResult finish_cli(const RunningCli& running);

// Number of lines in s (a trailing newline does not start a line).
int line_count(const std::string& s);

// What a failed run must leave (gtest expectations): a non-zero exit, one
// "mcmd_fillnodata: error: ..." line holding `expect`, no "done", `dir` as
// it was (`listing`), and the bytes of `src` (`src_bytes`, when it exists).
void expect_clean_failure(const RunResult& r, const std::string& expect, const TempDir& dir,
                          const std::vector<std::string>& listing, const std::string& src,
                          const std::string& src_bytes);

struct RasterSpec {
  GDALDataType type = GDT_Int16;
  int width = 67;
  int height = 45;
  int bands = 1;
  std::optional<double> nodata = -32768.0;
  bool voids = true;             // punch the test voids (is_test_void)
  bool nan_voids = false;        // write NaN in voids (float types)
  bool signed_byte = false;      // GDT_Byte with PIXELTYPE=SIGNEDBYTE
  double base = 0.0;             // terrain = base + scale · smooth(x, y), smooth in [0, 1]
  double scale = 100.0;
  std::vector<std::string> creation_options;
};

// The standard spec with this type, nodata value and terrain range.
RasterSpec spec_of(GDALDataType type, std::optional<double> nodata, double base, double scale);

// Is (x, y) a void of the standard test pattern (a blob, a stripe, a border
// notch and single cells)?
bool is_test_void(int x, int y, int w, int h);

// A GeoTIFF at `path` with the test terrain, voids set to nodata (or NaN),
// EPSG:32611, a geotransform, dataset and band metadata, band descriptions.
void make_raster(const std::string& path, const RasterSpec& spec);

// A Byte mask file (0 = void of the test pattern, 255 = valid).
void make_mask(const std::string& path, int width, int height);

// Raw native bytes of one band.
std::vector<unsigned char> raw_band(const std::string& path, int band = 1);
// Values of one band as doubles.
std::vector<double> band_values(const std::string& path, int band = 1);
// Whole file content.
std::string file_bytes(const std::string& path);
bool file_exists(const std::string& path);
void copy_file(const std::string& from, const std::string& to);

}  // namespace mcmd::test
