#include "lib/terrain_band.hpp"

#include <cmath>
#include <cstring>
#include <memory>
#include <limits>
#include <stdexcept>
#include <string>

#include "lib/errors.hpp"
#include "lib/line_input.hpp"
#include "lib/options.hpp"
#include "lib/pixel_type.hpp"
#include "lib/terrain_sketch.hpp"
#include "lib/void_cap.hpp"
#include "mcmd/erosion.hpp"
#include "mcmd/fill_raster.hpp"
#include "mcmd/peaks.hpp"
#include "mcmd/skeleton.hpp"
#include "mcmd/terrain_filters.hpp"
#include "mcmd/terrain_lines.hpp"

namespace mcmd::gdal {

namespace {

std::string size_text(long long w, long long h) { return std::to_string(w) + "x" + std::to_string(h); }

[[noreturn]] void refuse(const std::string& why) { throw Failure(CPLE_IllegalArg, why); }

void check_combination(GDALRasterBand* sketch, const TerrainOptions& o) {
  const int generators = (sketch != nullptr) + !o.peaks.empty() + o.skeleton;
  if (generators > 1) refuse("a terrain has one source of constraints: a sketch, PEAKS or SKELETON, not several");
  if (o.upsample > 1 && !sketch && o.peaks.empty()) refuse("UPSAMPLE supersamples a sketch or the peaks: there is none");
  if (o.has_zrange && !sketch && o.peaks.empty() && !o.skeleton)
    refuse("ZRANGE maps a sketch's grey levels or a generator's elevations: there is no sketch, PEAKS or SKELETON");
  if (o.terrain.method == TerrainMethod::none && o.median > 0) refuse("METHOD=none makes nothing to filter");
}

// The coarse size of a w×h terrain supersampled by k.
void coarse_size(int w, int h, int k, int& cw, int& ch) {
  if ((w - 1) % k || (h - 1) % k)
    refuse("with UPSAMPLE=" + std::to_string(k) + " the terrain's size minus 1 must be a multiple of " +
           std::to_string(k) + ": " + size_text(w, h) + " is not");
  cw = (w - 1) / k + 1;
  ch = (h - 1) / k + 1;
}

Canvas from_sketch(int w, int h, GDALRasterBand& sketch, const TerrainOptions& o) {
  const SketchCells cells = read_sketch(sketch, o);
  const long long fw = (static_cast<long long>(cells.w) - 1) * o.upsample + 1;
  const long long fh = (static_cast<long long>(cells.h) - 1) * o.upsample + 1;
  if (fw != w || fh != h)
    refuse("the sketch is " + size_text(cells.w, cells.h) +
           (o.upsample > 1 ? " (" + size_text(fw, fh) + " upsampled by " + std::to_string(o.upsample) + ")" : "") +
           " but the terrain is " + size_text(w, h));
  return sketch_canvas(cells, o.upsample);
}

Canvas from_peaks(int w, int h, const TerrainOptions& o) {
  int cw = w, ch = h;
  if (o.upsample > 1) coarse_size(w, h, o.upsample, cw, ch);
  PeaksParams p;
  p.peaks = o.peaks == "iizuka" ? iizuka_table1() : random_peaks(std::stoi(o.peaks), o.terrain.fill.seed);
  p.E = o.peaks_noise;
  if (o.has_peaks_threshold) p.threshold = o.peaks_threshold;
  if (o.has_zrange) p.z_low = o.z_min, p.z_high = o.z_max;
  p.seed = o.terrain.fill.seed;
  const std::vector<double> z = peaks_surface(cw, ch, p);
  return upsampled(z, std::vector<std::uint8_t>(z.size(), 1), cw, ch, o.upsample);
}

Canvas from_skeleton(int w, int h, const TerrainOptions& o) {
  SkeletonParams p;
  p.ridge_couples = o.ridge_couples;
  p.river_particles = o.river_particles;
  p.z_low = o.z_min;
  p.z_high = o.z_max;
  p.seed = o.terrain.fill.seed;  // its H stays its own: -H shapes the relief, not the skeleton
  return make_skeleton(w, h, p).canvas;
}

void add_points(Canvas& c, const TerrainOptions& o) {
  for (const TerrainPoint& p : o.points) {
    if (!c.contains(p.col, p.row))
      refuse("the point at column " + std::to_string(p.col) + ", row " + std::to_string(p.row) +
             " is outside the " + size_text(c.w, c.h) + " raster");
    c.set(p.col, p.row, p.z);
  }
}

// RIDGES and RIVERS, in the target's georeferencing: none may miss the raster whole.
void add_lines(Canvas& c, GDALRasterBand& target, const TerrainOptions& o) {
  std::vector<Line> lines;
  for (const auto& [path, kind] : {std::pair{o.ridges, CellState::ridge}, std::pair{o.rivers, CellState::river}}) {
    if (path.empty()) continue;
    GDALDataset* ds = target.GetDataset();
    if (!ds) refuse("RIDGES and RIVERS need the target band's dataset (its georeferencing)");
    const std::vector<Line> read = read_lines(path, kind, *ds);
    if (lines_inside(read, c.w, c.h) == 0)
      refuse(std::string("no ") + (kind == CellState::ridge ? "ridge" : "river") + " line of '" + path +
             "' crosses the " + size_text(c.w, c.h) + " raster (check its CRS and extent)");
    lines.insert(lines.end(), read.begin(), read.end());
  }
  if (!lines.empty()) draw_lines(c, lines, o.ridge_z, o.river_z);
}

// METHOD=none: what an unknown cell is written as.
double unknown_value(const PixelType& t) {
  if (t.has_nodata) return t.nodata;
  if (t.gdt == GDT_Float32 || t.gdt == GDT_Float64) return std::numeric_limits<double>::quiet_NaN();
  refuse("METHOD=none leaves unknown cells: the target band needs a nodata value (or a float type)");
}

void write_canvas(GDALRasterBand& target, const Canvas& c, bool unknown_as_nodata) {
  const PixelType type = pixel_type_of(target);
  PixelType encoding = type;
  double marker = 0.0;
  if (unknown_as_nodata) {
    marker = unknown_value(type);
    encoding.has_nodata = false;  // the nodata value is written on purpose
  }
  const int bytes = GDALGetDataTypeSizeBytes(type.gdt);
  std::vector<double> row(static_cast<std::size_t>(c.w));
  std::vector<unsigned char> out(static_cast<std::size_t>(c.w) * bytes);
  // The marker's bytes, written as they are: encode() refuses a NaN.
  std::vector<unsigned char> marker_bytes(bytes);
  if (unknown_as_nodata) {
    if (type.gdt == GDT_Float32) {
      const float f = static_cast<float>(marker);
      std::memcpy(marker_bytes.data(), &f, sizeof f);
    } else if (type.gdt == GDT_Float64) {
      std::memcpy(marker_bytes.data(), &marker, sizeof marker);
    } else {
      encode(encoding, &marker, 1, marker_bytes.data());
    }
  }
  for (int y = 0; y < c.h; ++y) {
    for (int x = 0; x < c.w; ++x) {
      const std::size_t i = c.index(x, y);
      row[x] = unknown_as_nodata && !is_constraint(c.state[i]) ? 0.0 : c.z[i];
    }
    encode(encoding, row.data(), row.size(), out.data());
    for (int x = 0; x < c.w && unknown_as_nodata; ++x)
      if (!is_constraint(c.state[c.index(x, y)])) std::memcpy(out.data() + static_cast<std::size_t>(x) * bytes, marker_bytes.data(), bytes);
    check_io(target.RasterIO(GF_Write, 0, y, c.w, 1, out.data(), c.w, 1, type.gdt, 0, 0, nullptr),
             "cannot write the terrain");
  }
}

// A cell's side in metres: from the CRS and geotransform, the geotransform
// alone (its unit), or 30 m (SRTM 1″'s spacing) without one.
double cell_side(GDALRasterBand& target) {
  GDALDataset* ds = target.GetDataset();
  double gt[6];
  if (!ds || ds->GetGeoTransform(gt) != CE_None) return 30.0;
  const OGRSpatialReference* srs = ds->GetSpatialRef();
  if (srs && !srs->IsEmpty()) return std::sqrt(cell_area_m2(*ds));
  return std::sqrt(std::fabs(gt[1] * gt[5] - gt[2] * gt[4]));
}

// UPLIFT=FILE: band 1 of a raster of the terrain's size, relative rates >= 0.
std::vector<double> uplift_map(const std::string& path, int w, int h) {
  CPLErrorReset();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) refuse("cannot open the uplift map '" + path + "': " + (CPLGetLastErrorMsg()[0] ? CPLGetLastErrorMsg() : "not a raster"));
  if (ds->GetRasterXSize() != w || ds->GetRasterYSize() != h)
    refuse("the uplift map '" + path + "' is " + size_text(ds->GetRasterXSize(), ds->GetRasterYSize()) +
           " but the terrain is " + size_text(w, h));
  std::vector<double> u(static_cast<std::size_t>(w) * h);
  check_io(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, w, h, u.data(), w, h, GDT_Float64, 0, 0, nullptr),
           ("cannot read the uplift map '" + path + "'").c_str());
  for (double v : u)
    if (!std::isfinite(v) || v < 0) refuse("the uplift map '" + path + "' holds a rate that is not a number >= 0");
  return u;
}

// The erosion asked for (steps 0: none), its uplift map read and its
// parameters checked before anything is made.
ErosionParams erosion_of(GDALRasterBand& target, bool has_sketch, const TerrainOptions& o, int threads) {
  ErosionParams e = o.erosion;
  e.steps = erosion_steps(o, has_sketch);
  if (e.steps == 0) return e;
  e.threads = threads;
  e.cell_size = cell_side(target);
  e.texture = o.terrain.method == TerrainMethod::mcmd;
  const int w = target.GetXSize(), h = target.GetYSize();
  if (e.uplift == UpliftPattern::map) e.uplift_map = uplift_map(o.uplift_file, w, h);
  try {
    check_erosion(e, w, h);
  } catch (const std::invalid_argument& err) {
    refuse(err.what());
  }
  return e;
}

}  // namespace

Canvas terrain_constraints(GDALRasterBand& target, GDALRasterBand* sketch, const TerrainOptions& o) {
  const int w = target.GetXSize(), h = target.GetYSize();
  check_terrain_size(w, h);
  check_combination(sketch, o);
  Canvas c = sketch ? from_sketch(w, h, *sketch, o)
             : !o.peaks.empty() ? from_peaks(w, h, o)
             : o.skeleton ? from_skeleton(w, h, o)
                          : Canvas(w, h);
  add_points(c, o);
  if (!o.states_file.empty()) apply_states(c, o.states_file);
  add_lines(c, target, o);
  return c;
}

void make_terrain(GDALRasterBand& target, GDALRasterBand* sketch, const TerrainOptions& o, const ProgressFn& progress) {
  report(progress, 0.0);
  Canvas c = terrain_constraints(target, sketch, o);
  report(progress, 0.1);
  TerrainParams params = o.terrain;
  params.threads = effective_threads(params.threads);
  const ErosionParams erosion = erosion_of(target, sketch != nullptr, o, params.threads);
  const double made = erosion.steps == 0 ? 0.9 : 0.5;  // the erosion takes the rest
  synthesize(c, params, sub_progress(progress, 0.1, made));
  if (erosion.steps != 0) {
    const ErosionReport r = erode(c, erosion, sub_progress(progress, made, 0.9));
    CPLDebug("MCMD", "erosion: %d grids, %d steps on the coarsest (network %s), %d on the finest (%.1f %% of its "
             "channels moved in its last step), K %.4g", r.grids, r.coarse_steps, r.converged ? "converged" : "not converged",
             r.steps, 100.0 * r.moved, r.K);
  }
  if (o.median > 0) median_filter(c, o.median, o.median_passes, o.median_all, params.threads);
  report(progress, 0.95);
  write_canvas(target, c, params.method == TerrainMethod::none);
  report(progress, 1.0);
}

}  // namespace mcmd::gdal
