// MCMDFillNodata() on in-memory datasets, plus the pieces behind it: option
// parsing, type conversion and the distance transform behind -md.
#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <string>
#include <vector>

#include "common/distance.hpp"
#include "cpl_string.h"
#include "lib/options.hpp"
#include "lib/pixel_type.hpp"
#include "mcmd_gdal.h"

namespace {

constexpr int kW = 40, kH = 30;

GDALDatasetH mem_dataset(GDALDataType type = GDT_Float32) {
  GDALDriverH mem = GDALGetDriverByName("MEM");
  GDALDatasetH ds = GDALCreate(mem, "", kW, kH, 1, type, nullptr);
  GDALRasterBandH b = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(b, -9999);
  std::vector<double> z(kW * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const bool hole = (x - 20) * (x - 20) + (y - 15) * (y - 15) < 36;
      z[y * kW + x] = hole ? -9999 : 100 + x * 2.0 + y;
    }
  EXPECT_EQ(GDALRasterIO(b, GF_Write, 0, 0, kW, kH, z.data(), kW, kH, GDT_Float64, 0, 0), CE_None);
  return ds;
}

std::vector<double> values(GDALDatasetH ds) {
  std::vector<double> z(kW * kH);
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, 0, kW, kH, z.data(), kW, kH, GDT_Float64, 0, 0),
            CE_None);
  return z;
}

int CPL_STDCALL cancel_at_half(double f, const char*, void* calls) {
  ++*static_cast<int*>(calls);
  return f < 0.5 ? TRUE : FALSE;
}

int CPL_STDCALL count_calls(double f, const char*, void* last) {
  *static_cast<double*>(last) = f;
  return TRUE;
}

TEST(Api, FillsEveryVoidAndReportsProgressToOne) {
  GDALAllRegister();
  GDALDatasetH ds = mem_dataset();
  const auto before = values(ds);
  double last = -1;
  ASSERT_EQ(MCMDFillNodata(GDALGetRasterBand(ds, 1), nullptr, nullptr, count_calls, &last), CE_None);
  EXPECT_EQ(last, 1.0);
  const auto after = values(ds);
  for (std::size_t i = 0; i < after.size(); ++i) {
    if (before[i] != -9999) {
      ASSERT_EQ(after[i], before[i]);
    } else {
      ASSERT_NE(after[i], -9999);
    }
  }
  GDALClose(ds);
}

TEST(Api, PaperMethodsFillEveryVoid) {
  GDALAllRegister();
  for (const char* method : {"METHOD=paper-ds", "METHOD=paper-te"}) {
    GDALDatasetH ds = mem_dataset(GDT_Float64);
    const char* opts[] = {method, "RS=0", nullptr};
    ASSERT_EQ(MCMDFillNodata(GDALGetRasterBand(ds, 1), nullptr, opts, nullptr, nullptr), CE_None);
    for (double v : values(ds)) ASSERT_TRUE(std::isfinite(v) && v != -9999);
    GDALClose(ds);
  }
}

TEST(Api, CancelledProgressFailsWithUserInterruptAndWritesNothing) {
  GDALAllRegister();
  GDALDatasetH ds = mem_dataset();
  const auto before = values(ds);
  int calls = 0;
  CPLPushErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
  const CPLErr err = MCMDFillNodata(GDALGetRasterBand(ds, 1), nullptr, nullptr, cancel_at_half, &calls);
  CPLPopErrorHandler();
  EXPECT_EQ(err, CE_Failure);
  EXPECT_EQ(CPLGetLastErrorNo(), CPLE_UserInterrupt);
  EXPECT_GT(calls, 0);
  EXPECT_EQ(values(ds), before);
  GDALClose(ds);
}

int CPL_STDCALL refuse_past_60_percent(double f, const char*, void*) { return f <= 0.6; }

// The tiled path writes as it goes: a cancel after the first writes leaves
// the band partly filled, and the message says so (known cells unchanged).
TEST(Api, CancelAfterTilesWroteSaysPartlyFilled) {
  GDALAllRegister();
  constexpr int n = 200;
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("MEM"), "", n, n, 1, GDT_Float32, nullptr);
  GDALRasterBandH b = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(b, -9999);
  std::vector<float> z(n * n);
  for (int i = 0; i < n * n; ++i) z[i] = (i % 7 == 0 && (i / n) % 5 == 0) ? -9999.0f : 100.0f + (i % n) + (i / n);
  ASSERT_EQ(GDALRasterIO(b, GF_Write, 0, 0, n, n, z.data(), n, n, GDT_Float32, 0, 0), CE_None);
  const char* opts[] = {"TILING=ALWAYS", "TILE_SIZE=33", "NUM_THREADS=1", "MAX_DISTANCE=50", nullptr};
  CPLPushErrorHandler(CPLQuietErrorHandler);
  CPLErrorReset();
  const CPLErr err = MCMDFillNodata(b, nullptr, opts, refuse_past_60_percent, nullptr);
  CPLPopErrorHandler();
  EXPECT_EQ(err, CE_Failure);
  EXPECT_EQ(CPLGetLastErrorNo(), CPLE_UserInterrupt);
  EXPECT_NE(std::string(CPLGetLastErrorMsg()).find("partly filled in place"), std::string::npos)
      << CPLGetLastErrorMsg();
  std::vector<float> after(n * n);
  ASSERT_EQ(GDALRasterIO(b, GF_Read, 0, 0, n, n, after.data(), n, n, GDT_Float32, 0, 0), CE_None);
  std::size_t filled = 0, left = 0;
  for (int i = 0; i < n * n; ++i) {
    if (z[i] != -9999.0f) {
      ASSERT_EQ(after[i], z[i]);
      continue;
    }
    (after[i] == -9999.0f ? left : filled) += 1;
  }
  EXPECT_GT(filled, 0u);
  EXPECT_GT(left, 0u);
  GDALClose(ds);
}

TEST(Api, ExplicitMaskBandSelectsTheVoids) {
  GDALAllRegister();
  GDALDatasetH ds = mem_dataset();
  GDALDatasetH mask = GDALCreate(GDALGetDriverByName("MEM"), "", kW, kH, 1, GDT_Byte, nullptr);
  std::vector<unsigned char> m(kW * kH, 255);
  m[3 * kW + 3] = 0;  // only this cell is a void; the nodata disc is not
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(mask, 1), GF_Write, 0, 0, kW, kH, m.data(), kW, kH, GDT_Byte, 0, 0),
            CE_None);
  const auto before = values(ds);
  ASSERT_EQ(MCMDFillNodata(GDALGetRasterBand(ds, 1), GDALGetRasterBand(mask, 1), nullptr, nullptr, nullptr),
            CE_None);
  const auto after = values(ds);
  for (std::size_t i = 0; i < after.size(); ++i)
    if (i != 3 * kW + 3) {
      ASSERT_EQ(after[i], before[i]);
    }
  GDALClose(mask);
  GDALClose(ds);
}

TEST(Api, BadOptionFailsWithIllegalArg) {
  GDALAllRegister();
  GDALDatasetH ds = mem_dataset();
  const char* opts[] = {"H=2", nullptr};
  CPLPushErrorHandler(CPLQuietErrorHandler);
  EXPECT_EQ(MCMDFillNodata(GDALGetRasterBand(ds, 1), nullptr, opts, nullptr, nullptr), CE_Failure);
  CPLPopErrorHandler();
  EXPECT_EQ(CPLGetLastErrorNo(), CPLE_IllegalArg);
  EXPECT_NE(std::string(CPLGetLastErrorMsg()).find("H=2"), std::string::npos);
  GDALClose(ds);
  CPLPushErrorHandler(CPLQuietErrorHandler);
  EXPECT_EQ(MCMDFillNodata(nullptr, nullptr, nullptr, nullptr, nullptr), CE_Failure);
  CPLPopErrorHandler();
}

TEST(Options, DefaultsAndEveryName) {
  using namespace mcmd::gdal;
  const Options d = parse_options(nullptr);
  EXPECT_EQ(d.fill.method, mcmd::Method::mcmd);
  EXPECT_EQ(d.fill.rs, 0.0);
  EXPECT_EQ(d.max_distance, 0.0);
  const char* all[] = {"method=paper-te", "DELTA=paper", "I=2", "I_BU=-1", "RIDGE_I=3", "RIDGE_I_BU=4", "RIVER_I=-3",
                       "RIVER_I_BU=-4", "H=0.7", "RT=-0.2", "RS=auto", "SEED=18446744073709551615",
                       "MAX_DISTANCE=12.5", "TILE_SIZE=513", "NUM_THREADS=ALL_CPUS", nullptr};
  const Options o = parse_options(all);
  EXPECT_EQ(o.fill.method, mcmd::Method::paper_te);
  EXPECT_EQ(o.fill.delta_form, mcmd::DeltaForm::paper);
  EXPECT_EQ(o.fill.known_shape.I, 2);
  EXPECT_EQ(o.fill.known_shape.I_bu, -1);
  EXPECT_EQ(o.fill.ridge_shape.I, 3);
  EXPECT_EQ(o.fill.ridge_shape.I_bu, 4);
  EXPECT_EQ(o.fill.river_shape.I, -3);
  EXPECT_EQ(o.fill.river_shape.I_bu, -4);
  EXPECT_EQ(o.fill.H, 0.7);
  EXPECT_EQ(o.fill.rt, -0.2);
  EXPECT_TRUE(o.fill.rs_auto);
  EXPECT_EQ(o.fill.seed, 18446744073709551615ull);
  EXPECT_EQ(o.max_distance, 12.5);
  EXPECT_EQ(o.tile_size, 513);
  EXPECT_EQ(o.num_threads, 0);
}

TEST(Options, AbsurdValuesAreRejected) {
  using namespace mcmd::gdal;
  for (const char* bad : {"H=-0.1", "H=1.01", "RS=-1", "RS=nan", "RS=11", "RT=2", "I=1e9", "I=abc", "I=",
                          "SEED=-1", "SEED=1.5", "SEED=99999999999999999999", "TILE_SIZE=512", "TILE_SIZE=2",
                          "TILE_SIZE=65537", "NUM_THREADS=0", "NUM_THREADS=many", "MAX_DISTANCE=-1",
                          "MAX_DISTANCE=inf", "METHOD=rbf", "DELTA=other", "NOPE=1", "JUSTANAME"}) {
    const char* list[] = {bad, nullptr};
    EXPECT_THROW(parse_options(list), OptionError) << bad;
  }
}

TEST(PixelType, IntegersAreRoundedClampedAndNeverNodata) {
  using namespace mcmd::gdal;
  PixelType t;
  t.gdt = GDT_Byte;
  t.has_nodata = true;
  t.nodata = 0;
  const double in[] = {-5.0, 0.2, 0.6, 254.5, 300.0, 17.5};
  unsigned char out[6];
  encode(t, in, 6, out);
  EXPECT_EQ(out[0], 1);  // clamped to 0 = nodata, nudged up
  EXPECT_EQ(out[1], 1);  // rounds to nodata, nudged towards the fill
  EXPECT_EQ(out[2], 1);
  EXPECT_EQ(out[3], 255);
  EXPECT_EQ(out[4], 255);
  EXPECT_EQ(out[5], 18);
  t.gdt = GDT_Int16;
  t.nodata = 32767;
  const double hi[] = {1e9, 32766.6};
  std::int16_t o16[2];
  encode(t, hi, 2, o16);
  EXPECT_EQ(o16[0], 32766);
  EXPECT_EQ(o16[1], 32766);
}

TEST(PixelType, FloatsAvoidNodataAndStayFinite) {
  using namespace mcmd::gdal;
  PixelType t;
  t.gdt = GDT_Float32;
  t.has_nodata = true;
  t.nodata = -9999;
  const double in[] = {-9999.0, 1e300, 12.25};
  float out[3];
  encode(t, in, 3, out);
  EXPECT_NE(out[0], -9999.0f);
  EXPECT_NEAR(out[0], -9999.0f, 0.01);
  EXPECT_EQ(out[1], std::numeric_limits<float>::max());
  EXPECT_EQ(out[2], 12.25f);
}

TEST(Distance, EuclideanDistanceToNearestValidCell) {
  const int w = 7, h = 5;
  std::vector<std::uint8_t> valid(w * h, 0);
  valid[2 * w + 1] = 1;  // (1, 2)
  const auto d = mcmd::distance_to_valid(valid.data(), w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) EXPECT_DOUBLE_EQ(d[y * w + x], std::hypot(x - 1.0, y - 2.0));
  std::vector<std::uint8_t> none(w * h, 0);
  for (double v : mcmd::distance_to_valid(none.data(), w, h)) EXPECT_TRUE(std::isinf(v));
}

}  // namespace
