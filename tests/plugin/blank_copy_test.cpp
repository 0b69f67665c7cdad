// The CLI makes a small single-band raster's output as a copy of the source
// without its pixels (blank_source) and has the fill write every cell of it
// (FillRequest::blank_target). These tests hold both halves to what the
// ordinary copy-then-fill gives: the same structure, and the same cells
// whichever path the fill takes (whole raster, tiles, paper method, cells
// left void by MAX_DISTANCE, no void at all, a type read as Float64).
#include <gtest/gtest.h>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "cpl_string.h"
#include "gdal_priv.h"
#include "lib/blank_source.hpp"
#include "lib/fill_band.hpp"
#include "lib/options.hpp"
#include "test_support.hpp"

namespace {

using mcmd::test::RasterSpec;
using mcmd::test::TempDir;

struct Closer {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};
using Dataset = std::unique_ptr<GDALDataset, Closer>;

Dataset open(const std::string& path, bool update = false) {
  return Dataset(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | (update ? GDAL_OF_UPDATE : GDAL_OF_READONLY)));
}

Dataset gtiff_copy(GDALDataset& from, const std::string& path) {
  GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
  return Dataset(gtiff->CreateCopy(path.c_str(), &from, FALSE, nullptr, nullptr, nullptr));
}

std::vector<unsigned char> mask_bytes(GDALRasterBand& band) {
  const int w = band.GetXSize(), h = band.GetYSize();
  std::vector<unsigned char> m(static_cast<std::size_t>(w) * h);
  EXPECT_EQ(band.GetMaskBand()->RasterIO(GF_Read, 0, 0, w, h, m.data(), w, h, GDT_Byte, 0, 0, nullptr), CE_None);
  return m;
}

TEST(BlankSource, CopyHasTheSourcesStructureAndNoPixel) {
  GDALAllRegister();
  TempDir dir;
  const std::string src_path = dir.file("src.tif");
  RasterSpec spec;
  spec.type = GDT_Float32;
  spec.nodata = -9999.0;
  mcmd::test::make_raster(src_path, spec);
  {  // a mask of its own (per dataset), which the copy must carry over
    Dataset ds = open(src_path, true);
    GDALRasterBand* band = ds->GetRasterBand(1);
    ASSERT_EQ(band->CreateMaskBand(GMF_PER_DATASET), CE_None);
    std::vector<unsigned char> m(static_cast<std::size_t>(spec.width) * spec.height, 255);
    for (std::size_t i = 0; i < m.size(); i += 7) m[i] = 0;
    ASSERT_EQ(band->GetMaskBand()->RasterIO(GF_Write, 0, 0, spec.width, spec.height, m.data(), spec.width,
                                            spec.height, GDT_Byte, 0, 0, nullptr),
              CE_None);
  }
  Dataset src = open(src_path);
  ASSERT_TRUE(src);
  const std::unique_ptr<GDALDataset> view = mcmd::gdal::blank_source(*src);
  Dataset out = gtiff_copy(*view, dir.file("out.tif"));
  ASSERT_TRUE(out);

  ASSERT_EQ(out->GetRasterXSize(), spec.width);
  ASSERT_EQ(out->GetRasterYSize(), spec.height);
  ASSERT_EQ(out->GetRasterCount(), 1);
  ASSERT_NE(out->GetSpatialRef(), nullptr);
  EXPECT_TRUE(out->GetSpatialRef()->IsSame(src->GetSpatialRef()));
  double a[6], b[6];
  ASSERT_EQ(src->GetGeoTransform(a), CE_None);
  ASSERT_EQ(out->GetGeoTransform(b), CE_None);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(a[i], b[i]);
  EXPECT_STREQ(out->GetMetadataItem("MCMD_TEST"), "dataset item");
  GDALRasterBand& sb = *src->GetRasterBand(1);
  GDALRasterBand& ob = *out->GetRasterBand(1);
  EXPECT_EQ(ob.GetRasterDataType(), GDT_Float32);
  int has = 0;
  EXPECT_EQ(ob.GetNoDataValue(&has), -9999.0);
  EXPECT_TRUE(has);
  EXPECT_STREQ(ob.GetMetadataItem("BAND_NOTE"), "band 1");
  EXPECT_EQ(ob.GetMaskFlags(), GMF_PER_DATASET);
  EXPECT_EQ(mask_bytes(ob), mask_bytes(sb));

  // Not one cell of the source was read: the copy's band is all zeros.
  std::vector<float> z(static_cast<std::size_t>(spec.width) * spec.height, 1.0f);
  ASSERT_EQ(ob.RasterIO(GF_Read, 0, 0, spec.width, spec.height, z.data(), spec.width, spec.height, GDT_Float32, 0, 0,
                        nullptr),
            CE_None);
  for (float v : z) ASSERT_EQ(v, 0.0f);
  // A resampled read of the view is zeros too.
  std::vector<double> small(16, 5.0);
  ASSERT_EQ(view->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, spec.width, spec.height, small.data(), 4, 4,
                                             GDT_Float64, 0, 0, nullptr),
            CE_None);
  for (double v : small) EXPECT_EQ(v, 0.0);
}

struct BlankCase {
  const char* name;
  GDALDataType type;
  std::vector<std::string> options;
  bool voids = true;
};

void PrintTo(const BlankCase& c, std::ostream* os) { *os << c.name; }

class BlankTarget : public ::testing::TestWithParam<BlankCase> {};

// The band filled into a copy of the source (the ordinary way) and into a
// blank copy whose every cell starts as a value no fill would write: the
// two must hold the same bytes.
TEST_P(BlankTarget, HoldsExactlyWhatTheOrdinaryCopyHolds) {
  GDALAllRegister();
  const BlankCase& c = GetParam();
  TempDir dir;
  const std::string src_path = dir.file("src.tif");
  RasterSpec spec;
  spec.type = c.type;
  spec.nodata = -9999.0;
  spec.voids = c.voids;
  spec.base = 500.0;
  mcmd::test::make_raster(src_path, spec);
  CPLStringList list;
  for (const std::string& o : c.options) list.AddString(o.c_str());
  const mcmd::gdal::Options options = mcmd::gdal::parse_options(list.List());

  Dataset src = open(src_path);
  GDALRasterBand& source = *src->GetRasterBand(1);
  mcmd::gdal::FillRequest req;
  req.masks.push_back(source.GetMaskBand());
  const auto fill_into = [&](GDALRasterBand& target, bool blank) {
    mcmd::gdal::FillRequest r = req;
    r.blank_target = blank;
    const mcmd::gdal::TargetBand get = [&target]() -> GDALRasterBand& { return target; };
    mcmd::gdal::fill_band(get, source, r, options, [](double) { return true; });
  };

  Dataset ordinary = gtiff_copy(*src, dir.file("ordinary.tif"));
  fill_into(*ordinary->GetRasterBand(1), false);
  Dataset blank = gtiff_copy(*mcmd::gdal::blank_source(*src), dir.file("blank.tif"));
  ASSERT_EQ(blank->GetRasterBand(1)->Fill(77.0), CE_None);  // no fill writes 77 here: the terrain is >= 500
  fill_into(*blank->GetRasterBand(1), true);
  ordinary.reset();
  blank.reset();

  const std::vector<unsigned char> want = mcmd::test::raw_band(dir.file("ordinary.tif"));
  EXPECT_EQ(mcmd::test::raw_band(dir.file("blank.tif")), want);
  if (c.voids) {
    EXPECT_NE(mcmd::test::raw_band(src_path), want) << "nothing was filled: the case tests nothing";
  }
}

INSTANTIATE_TEST_SUITE_P(
    Paths, BlankTarget,
    ::testing::Values(BlankCase{"WholeRaster", GDT_Float32, {}},
                      BlankCase{"WholeRasterInt16", GDT_Int16, {}},
                      BlankCase{"Tiles", GDT_Float32, {"TILING=ALWAYS", "TILE_SIZE=17"}},
                      BlankCase{"PaperMethod", GDT_Int16, {"METHOD=PAPER-DS"}},
                      BlankCase{"MaxDistanceLeavesVoids", GDT_Float32, {"MAX_DISTANCE=2"}},
                      BlankCase{"NoVoid", GDT_Int16, {}, false},
                      BlankCase{"Int64ReadAsFloat64", GDT_Int64, {}}),
    [](const ::testing::TestParamInfo<BlankCase>& info) { return std::string(info.param.name); });

}  // namespace
