#include "terrain/terrain_run.hpp"

#include <algorithm>
#include <csignal>
#include <limits>
#include <memory>
#include <string>

#include "cli/args.hpp"
#include "cli/dataset.hpp"
#include "cli/destination.hpp"
#include "cli/output_driver.hpp"
#include "cli/output_file.hpp"
#include "cpl_string.h"
#include "cpl_vsi.h"
#include "lib/errors.hpp"
#include "lib/terrain_band.hpp"
#include "terrain/hillshade_png.hpp"
#include "terrain/terrain_geo.hpp"

namespace mcmd::cli {

using gdal::Failure;

namespace {

volatile std::sig_atomic_t g_interrupted = 0;

// The user's progress bar over [lo, hi], which SIGINT stops.
ProgressFn progress_part(GDALProgressFunc fn, double lo, double hi) {
  return [=](double f) { return !g_interrupted && (!fn || fn(lo + (hi - lo) * f, "", nullptr) != FALSE); };
}

// A ProgressFn behind GDAL's callback (arg: the ProgressFn).
int CPL_STDCALL through(double f, const char*, void* arg) {
  return (*static_cast<const ProgressFn*>(arg))(f) ? TRUE : FALSE;
}

std::string size_text(long long w, long long h) { return std::to_string(w) + "x" + std::to_string(h); }

DatasetPtr open_input(const std::string& path, const char* role) {
  VSIStatBufL st;
  if (VSIStatL(path.c_str(), &st) != 0)
    throw Failure(CPLE_OpenFailed, std::string("cannot open ") + role + " '" + path + "': no such file");
  CPLErrorReset();
  DatasetPtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  if (!ds) {
    const std::string why = CPLGetLastErrorMsg();
    throw Failure(CPLE_OpenFailed, std::string("cannot open ") + role + " '" + path + "': " +
                                       (why.empty() ? "not a raster format GDAL can read" : why));
  }
  if (ds->GetRasterCount() == 0) throw Failure(CPLE_OpenFailed, std::string(role) + " '" + path + "' has no raster band");
  return ds;
}

// The output's size and georeferencing, and the sketch band (null: none).
struct Layout {
  int w = 0, h = 0;
  Georef georef;
  GDALRasterBand* sketch = nullptr;
};

void check_size(const TerrainArgs& a, long long w, long long h, const std::string& from) {
  if (a.width && (a.width != w || a.height != h))
    throw Failure(CPLE_IllegalArg, from + " is " + size_text(w, h) + " but -size asks " + size_text(a.width, a.height));
}

Layout layout_of(const TerrainArgs& a, DatasetPtr& sketch, DatasetPtr& like) {
  Layout l;
  const int k = a.terrain.upsample;
  if (!a.sketch.empty()) {
    sketch = open_input(a.sketch, "sketch");
    if (a.band > sketch->GetRasterCount())
      throw Failure(CPLE_IllegalArg, "band " + std::to_string(a.band) + " is out of range: the sketch has " +
                                         std::to_string(sketch->GetRasterCount()) + " band(s)");
    l.sketch = sketch->GetRasterBand(a.band);
    const long long w = (static_cast<long long>(sketch->GetRasterXSize()) - 1) * k + 1;
    const long long h = (static_cast<long long>(sketch->GetRasterYSize()) - 1) * k + 1;
    check_size(a, w, h, k > 1 ? "the sketch upsampled by " + std::to_string(k) : std::string("the sketch"));
    check_terrain_size(w, h);
    l.w = static_cast<int>(w), l.h = static_cast<int>(h);
    l.georef = supersampled(georef_of(*sketch), k);
  }
  if (!a.like.empty()) {
    like = open_input(a.like, "template");
    if (!sketch) {
      check_size(a, like->GetRasterXSize(), like->GetRasterYSize(), "the template '" + a.like + "'");
      l.w = like->GetRasterXSize(), l.h = like->GetRasterYSize();
    } else if (like->GetRasterXSize() != l.w || like->GetRasterYSize() != l.h) {
      throw Failure(CPLE_IllegalArg, "the template '" + a.like + "' is " +
                                         size_text(like->GetRasterXSize(), like->GetRasterYSize()) +
                                         " but the terrain is " + size_text(l.w, l.h));
    }
    l.georef = georef_of(*like);
  }
  if (!l.w) {
    if (!a.width) throw UsageError("give the terrain's size (-size W H), a sketch or a template (-like)");
    check_terrain_size(a.width, a.height);
    l.w = a.width, l.h = a.height;
  }
  l.georef = with_overrides(l.georef, a, l.w, l.h);
  return l;
}


DatasetPtr memory_raster(const TerrainArgs& a, const Layout& l) {
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  DatasetPtr ds(mem->Create("", l.w, l.h, 1, GDALGetDataTypeByName(a.type.c_str()), nullptr));
  if (!ds) throw Failure(CPLE_OutOfMemory, "cannot hold a " + size_text(l.w, l.h) + " " + a.type + " raster in memory");
  apply(*ds, l.georef);
  GDALRasterBand& band = *ds->GetRasterBand(1);
  if (a.nodata) band.SetNoDataValue(*a.nodata);
  else if (a.terrain.terrain.method == TerrainMethod::none) {
    const GDALDataType t = band.GetRasterDataType();
    if (t == GDT_Float32 || t == GDT_Float64) band.SetNoDataValue(std::numeric_limits<double>::quiet_NaN());
    else band.SetNoDataValue(t == GDT_Byte || t == GDT_UInt16 || t == GDT_UInt32 ? 0 : GDALAdjustValueToDataType(t, -1e300, nullptr, nullptr));
  }
  return ds;
}

void write_copy(GDALDriver* driver, const std::string& path, GDALDataset& from, const CPLStringList& co,
                ErrorLog& log, const ProgressFn& progress, const std::string& shown) {
  DatasetPtr out = create_copy(driver, path, from, co.List(), log, through, const_cast<ProgressFn*>(&progress), shown);
  out.reset();  // closes: flushes
  if (log.failures() != 0) throw Failure(CPLE_FileIO, "cannot write '" + shown + "': " + log.first_failure());
}

}  // namespace

void interrupt_terrain() { g_interrupted = 1; }

void run_terrain(const TerrainArgs& a, ErrorLog& log, GDALProgressFunc progress) {
  DatasetPtr sketch, like;
  const Layout l = layout_of(a, sketch, like);
  GDALDriver* driver = output_driver(a.format, a.dst);
  CPLStringList co;
  for (const std::string& c : a.creation_options) co.AddString(c.c_str());
  check_destination(a.dst);
  if (!a.hillshade.empty()) check_destination(a.hillshade);
  DatasetPtr terrain = memory_raster(a, l);
  check_output_driver(driver, co, *terrain);  // the sketch's cells are kept exactly
  remove_stale_temporaries(a.dst);
  TempOutput out(a.dst);
  std::unique_ptr<TempOutput> shade;
  if (!a.hillshade.empty()) remove_stale_temporaries(a.hillshade), shade = std::make_unique<TempOutput>(a.hillshade);

  gdal::make_terrain(*terrain->GetRasterBand(1), l.sketch, a.terrain, progress_part(progress, 0.0, 0.85));
  log.reset();
  write_copy(driver, out.path(), *terrain, co, log, progress_part(progress, 0.85, shade ? 0.95 : 1.0), a.dst);
  if (shade) {
    DatasetPtr png = hillshade_of(*terrain->GetRasterBand(1), l.georef);
    write_copy(png_driver(), shade->path(), *png, CPLStringList(), log, progress_part(progress, 0.95, 1.0),
               a.hillshade);
  }
  out.commit();
  if (shade) shade->commit();
}

}  // namespace mcmd::cli
