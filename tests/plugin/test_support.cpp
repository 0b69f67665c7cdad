#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <limits>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include "ogr_spatialref.h"

extern char** environ;

namespace mcmd::test {

namespace fs = std::filesystem;

TempDir::TempDir() {
  std::string tmpl = (fs::temp_directory_path() / "mcmd-plugin-test-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
  path_ = tmpl;
}

TempDir::~TempDir() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::vector<std::string> TempDir::listing() const {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool file_exists(const std::string& path) { return fs::exists(path); }

void copy_file(const std::string& from, const std::string& to) {
  fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

namespace {

RunningCli start(std::vector<std::string> argv, const TempDir& io) {
  RunningCli c;
  c.out = io.file("stdout");
  c.err = io.file("stderr");
  std::vector<char*> cargv;
  for (auto& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, c.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, c.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int rc = posix_spawn(&c.pid, cargv[0], &actions, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + argv[0]);
  return c;
}

RunResult spawn(std::vector<std::string> argv) {
  TempDir io;
  return finish_cli(start(std::move(argv), io));
}

}  // namespace

RunResult run_cli(const std::vector<std::string>& args, const std::string& shell_prefix) {
  std::vector<std::string> argv;
  if (!shell_prefix.empty()) {
    argv = {"/bin/sh", "-c", shell_prefix + " exec \"$0\" \"$@\"", MCMD_FILLNODATA_EXE};
  } else {
    argv = {MCMD_FILLNODATA_EXE};
  }
  argv.insert(argv.end(), args.begin(), args.end());
  return spawn(std::move(argv));
}

RunningCli start_cli(const std::vector<std::string>& args, const TempDir& io) {
  std::vector<std::string> argv = {MCMD_FILLNODATA_EXE};
  argv.insert(argv.end(), args.begin(), args.end());
  return start(std::move(argv), io);
}

RunResult finish_cli(const RunningCli& c) {
  int status = 0;
  ::waitpid(c.pid, &status, 0);
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = file_bytes(c.out);
  r.err = file_bytes(c.err);
  return r;
}

RunResult run_cli_under(const std::vector<std::string>& wrapper, const std::vector<std::string>& args) {
  std::vector<std::string> argv = wrapper;
  argv.push_back(MCMD_FILLNODATA_EXE);
  argv.insert(argv.end(), args.begin(), args.end());
  return spawn(std::move(argv));
}

void expect_clean_failure(const RunResult& r, const std::string& expect, const TempDir& dir,
                          const std::vector<std::string>& listing, const std::string& src,
                          const std::string& src_bytes) {
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("mcmd_fillnodata: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(expect), std::string::npos) << "expected '" << expect << "' in: " << r.err;
  EXPECT_EQ(r.out.find("100 - done"), std::string::npos);
  EXPECT_EQ(dir.listing(), listing) << "a file was left behind (or removed)";
  if (file_exists(src)) {
    EXPECT_EQ(file_bytes(src), src_bytes) << "source modified";
  }
}

int line_count(const std::string& s) {
  int n = 0;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i] == '\n' || i + 1 == s.size()) ++n;
  return n;
}

RasterSpec spec_of(GDALDataType type, std::optional<double> nodata, double base, double scale) {
  RasterSpec spec;
  spec.type = type;
  spec.nodata = nodata;
  spec.base = base;
  spec.scale = scale;
  return spec;
}

bool is_test_void(int x, int y, int w, int h) {
  const double cx = w * 0.35, cy = h * 0.4, r = std::min(w, h) * 0.18;
  if ((x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r) return true;  // blob
  if (std::abs(x - (y + w / 2)) <= 1 && y > h / 2) return true;           // slanted stripe
  if (x >= w - 3 && y >= 2 && y < 8) return true;                         // notch on the border
  return (x == 5 && y == h - 5) || (x == w - 10 && y == h - 4);           // single cells
}

namespace {

double terrain(int x, int y, int w, int h) {
  return 0.5 + 0.25 * std::sin(x * 0.13) * std::cos(y * 0.11) + 0.25 * double(x + y) / double(w + h);
}

void set_nodata(GDALRasterBand& band, GDALDataType type, double nd) {
  if (type == GDT_Int64)
    band.SetNoDataValueAsInt64(static_cast<std::int64_t>(nd));
  else if (type == GDT_UInt64)
    band.SetNoDataValueAsUInt64(static_cast<std::uint64_t>(nd));
  else
    band.SetNoDataValue(nd);
}

std::vector<double> band_data(const RasterSpec& s, int b) {
  std::vector<double> v(static_cast<std::size_t>(s.width) * s.height);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      double z = s.base + s.scale * terrain(x + 3 * b, y, s.width, s.height);
      if (!GDALDataTypeIsFloating(s.type)) z = std::round(z);
      if (s.voids && is_test_void(x + (b - 1) * 4, y, s.width, s.height)) z = s.nan_voids ? nan : s.nodata.value_or(nan);
      v[static_cast<std::size_t>(y) * s.width + x] = z;
    }
  return v;
}

void write_band(GDALRasterBand& band, const RasterSpec& s, const std::vector<double>& v) {
  CPLErr err;
  if (s.signed_byte) {
    std::vector<signed char> raw(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) raw[i] = static_cast<signed char>(v[i]);
    err = band.RasterIO(GF_Write, 0, 0, s.width, s.height, raw.data(), s.width, s.height, GDT_Byte, 0, 0, nullptr);
  } else {
    err = band.RasterIO(GF_Write, 0, 0, s.width, s.height, const_cast<double*>(v.data()), s.width, s.height,
                        GDT_Float64, 0, 0, nullptr);
  }
  if (err != CE_None) throw std::runtime_error("cannot write test band");
}

}  // namespace

void make_raster(const std::string& path, const RasterSpec& s) {
  GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
  CPLStringList co;
  for (const auto& o : s.creation_options) co.AddString(o.c_str());
  if (s.signed_byte) co.SetNameValue("PIXELTYPE", "SIGNEDBYTE");
  GDALDataset* ds = gtiff->Create(path.c_str(), s.width, s.height, s.bands, s.type, co.List());
  if (!ds) throw std::runtime_error("cannot create " + path);
  OGRSpatialReference srs;
  srs.importFromEPSG(32611);
  ds->SetSpatialRef(&srs);
  double gt[6] = {350000.0, 30.0, 0.0, 4110000.0, 0.0, -30.0};
  ds->SetGeoTransform(gt);
  ds->SetMetadataItem("MCMD_TEST", "dataset item");
  for (int b = 1; b <= s.bands; ++b) {
    GDALRasterBand* band = ds->GetRasterBand(b);
    if (s.nodata) set_nodata(*band, s.type, *s.nodata);
    band->SetDescription(("elevation " + std::to_string(b)).c_str());
    band->SetMetadataItem("BAND_NOTE", ("band " + std::to_string(b)).c_str());
    band->SetUnitType("m");
    write_band(*band, s, band_data(s, b));
  }
  GDALClose(ds);
}

void make_mask(const std::string& path, int w, int h) {
  GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
  GDALDataset* ds = gtiff->Create(path.c_str(), w, h, 1, GDT_Byte, nullptr);
  std::vector<unsigned char> m(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m[static_cast<std::size_t>(y) * w + x] = is_test_void(x, y, w, h) ? 0 : 255;
  if (ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, w, h, m.data(), w, h, GDT_Byte, 0, 0, nullptr) != CE_None)
    throw std::runtime_error("cannot write mask");
  GDALClose(ds);
}

std::vector<unsigned char> raw_band(const std::string& path, int b) {
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER);
  if (!ds) throw std::runtime_error("cannot open " + path);
  GDALRasterBand* band = ds->GetRasterBand(b);
  const GDALDataType t = band->GetRasterDataType();
  const int w = band->GetXSize(), h = band->GetYSize();
  std::vector<unsigned char> raw(static_cast<std::size_t>(w) * h * GDALGetDataTypeSizeBytes(t));
  const CPLErr err = band->RasterIO(GF_Read, 0, 0, w, h, raw.data(), w, h, t, 0, 0, nullptr);
  GDALClose(ds);
  if (err != CE_None) throw std::runtime_error("cannot read " + path);
  return raw;
}

std::vector<double> band_values(const std::string& path, int b) {
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER);
  if (!ds) throw std::runtime_error("cannot open " + path);
  GDALRasterBand* band = ds->GetRasterBand(b);
  const int w = band->GetXSize(), h = band->GetYSize();
  std::vector<double> v(static_cast<std::size_t>(w) * h);
  const CPLErr err = band->RasterIO(GF_Read, 0, 0, w, h, v.data(), w, h, GDT_Float64, 0, 0, nullptr);
  GDALClose(ds);
  if (err != CE_None) throw std::runtime_error("cannot read " + path);
  return v;
}

}  // namespace mcmd::test

namespace {
// Every test in this binary opens rasters through GDAL.
const struct GdalInit {
  GdalInit() { GDALAllRegister(); }
} gdal_init;
}  // namespace
