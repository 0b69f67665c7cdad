#include "lib/terrain_sketch.hpp"

#include <algorithm>
#include <memory>

#include "lib/band_window.hpp"
#include "lib/errors.hpp"
#include "lib/fill_band.hpp"
#include "lib/pixel_type.hpp"
#include "mcmd/terrain_filters.hpp"

namespace mcmd::gdal {

namespace {

std::string size_text(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

// White of a grey type: 255 for Byte, 65535 for UInt16.
bool white_of(GDALDataType t, double& white) {
  if (t == GDT_Byte) white = 255.0;
  else if (t == GDT_UInt16) white = 65535.0;
  else return false;
  return true;
}

// The value that marks unknown cells, if any.
bool unknown_marker(GDALRasterBand& band, const TerrainOptions& o, bool has_own_mask, double& marker) {
  const GDALDataType t = band.GetRasterDataType();
  if (o.unknown == UnknownRule::none) return false;
  if (o.unknown == UnknownRule::automatic) return !has_own_mask && white_of(t, marker);
  if (!o.unknown_white) {
    marker = o.unknown_value;
    return true;
  }
  if (!white_of(t, marker))
    throw Failure(CPLE_IllegalArg, std::string("white is 255 in a Byte sketch and 65535 in a UInt16 one; this sketch is ") +
                                       GDALGetDataTypeName(t) + ": give the value of unknown cells (-unknown V)");
  return true;
}

// ZRANGE: levels [lo, hi] to [z_min, z_max]; lo, hi the grey type's range,
// else the constraints' own.
void map_levels(SketchCells& s, GDALDataType t, const TerrainOptions& o) {
  double lo = 0.0, hi = 0.0;
  if (!white_of(t, hi)) {
    bool any = false;
    for (std::size_t i = 0; i < s.z.size(); ++i)
      if (s.valid[i]) {
        lo = any ? std::min(lo, s.z[i]) : s.z[i];
        hi = any ? std::max(hi, s.z[i]) : s.z[i];
        any = true;
      }
  }
  const double scale = hi > lo ? (o.z_max - o.z_min) / (hi - lo) : 0.0;
  for (std::size_t i = 0; i < s.z.size(); ++i)
    if (s.valid[i]) s.z[i] = o.z_min + (s.z[i] - lo) * scale;
}

}  // namespace

SketchCells read_sketch(GDALRasterBand& band, const TerrainOptions& o) {
  SketchCells s;
  s.w = band.GetXSize();
  s.h = band.GetYSize();
  check_terrain_size(s.w, s.h);
  std::vector<GDALRasterBand*> masks;
  if (GDALRasterBand* own = own_mask(band)) masks.push_back(own);
  const PixelType type = pixel_type_of(band);
  WindowData d = read_window(band, type, masks, Window{0, 0, s.w, s.h}, true);
  s.z = std::move(d.z);
  s.valid = std::move(d.valid);
  double marker = 0.0;
  if (unknown_marker(band, o, !masks.empty(), marker))
    for (std::size_t i = 0; i < s.z.size(); ++i)
      if (s.z[i] == marker) s.valid[i] = 0;
  if (o.has_zrange) map_levels(s, band.GetRasterDataType(), o);
  return s;
}

Canvas sketch_canvas(const SketchCells& s, int upsample) {
  if (upsample > 1) return upsampled(s.z, s.valid, s.w, s.h, upsample);
  Canvas c(s.w, s.h);
  for (std::size_t i = 0; i < c.cells(); ++i)
    if (s.valid[i]) {
      c.z[i] = s.z[i];
      c.state[i] = CellState::known;
    }
  return c;
}

namespace {

struct DatasetCloser {
  void operator()(GDALDataset* ds) const { GDALClose(GDALDataset::ToHandle(ds)); }
};

std::vector<double> band_values(GDALDataset& ds, int b) {
  std::vector<double> v(static_cast<std::size_t>(ds.GetRasterXSize()) * ds.GetRasterYSize());
  check_io(ds.GetRasterBand(b)->RasterIO(GF_Read, 0, 0, ds.GetRasterXSize(), ds.GetRasterYSize(), v.data(),
                                         ds.GetRasterXSize(), ds.GetRasterYSize(), GDT_Float64, 0, 0, nullptr),
           "cannot read the states raster");
  return v;
}

// Per cell: 0 nothing, 1 ridge, 2 river.
std::vector<std::uint8_t> state_marks(GDALDataset& ds) {
  const std::size_t n = static_cast<std::size_t>(ds.GetRasterXSize()) * ds.GetRasterYSize();
  std::vector<std::uint8_t> marks(n, 0);
  if (ds.GetRasterCount() < 3) {
    const std::vector<double> v = band_values(ds, 1);
    for (std::size_t i = 0; i < n; ++i) marks[i] = v[i] == 1.0 ? 1 : v[i] == 2.0 ? 2 : 0;
    return marks;
  }
  const std::vector<double> r = band_values(ds, 1), g = band_values(ds, 2), b = band_values(ds, 3);
  const double full = ds.GetRasterBand(1)->GetRasterDataType() == GDT_UInt16 ? 65535.0 : 255.0, half = full / 2;
  std::vector<double> alpha;
  if (ds.GetRasterCount() >= 4 && ds.GetRasterBand(4)->GetColorInterpretation() == GCI_AlphaBand)
    alpha = band_values(ds, 4);
  for (std::size_t i = 0; i < n; ++i) {
    if (!alpha.empty() && alpha[i] == 0) continue;
    if (r[i] > half && g[i] < half && b[i] < half) marks[i] = 1;
    else if (b[i] > half && r[i] < half && g[i] < half) marks[i] = 2;
  }
  return marks;
}

}  // namespace

void apply_states(Canvas& c, const std::string& path) {
  CPLErrorReset();
  std::unique_ptr<GDALDataset, DatasetCloser> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) {
    const std::string why = CPLGetLastErrorMsg();
    throw Failure(CPLE_OpenFailed, "cannot open the states raster '" + path + "'" + (why.empty() ? "" : ": " + why));
  }
  if (ds->GetRasterCount() < 1) throw Failure(CPLE_OpenFailed, "the states raster '" + path + "' has no band");
  if (ds->GetRasterXSize() != c.w || ds->GetRasterYSize() != c.h)
    throw Failure(CPLE_IllegalArg, "the states raster '" + path + "' is " +
                                       size_text(ds->GetRasterXSize(), ds->GetRasterYSize()) +
                                       " but the terrain is " + size_text(c.w, c.h));
  const std::vector<std::uint8_t> marks = state_marks(*ds);
  for (std::size_t i = 0; i < c.cells(); ++i)
    if (marks[i] && is_constraint(c.state[i])) c.state[i] = marks[i] == 1 ? CellState::ridge : CellState::river;
}

}  // namespace mcmd::gdal
