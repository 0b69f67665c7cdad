#include "cli/run.hpp"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <memory>
#include <string>
#include <unistd.h>
#include <vector>

#include "cli/background_copy.hpp"
#include "cli/dataset.hpp"
#include "cli/destination.hpp"
#include "cli/disk_space.hpp"
#include "cli/output_driver.hpp"
#include "cli/output_file.hpp"
#include "cli/verify_copy.hpp"
#include "cpl_string.h"
#include "cpl_vsi.h"
#include "lib/errors.hpp"
#include "lib/fill_band.hpp"
#include "mcmd/fill_raster.hpp"

namespace mcmd::cli {

using gdal::Failure;

namespace {

// Set from a signal handler, read by other threads: a lock-free atomic.
std::atomic<int> g_interrupted{0};
static_assert(std::atomic<int>::is_always_lock_free);

// A slice [lo, hi] of the user's progress bar that also honours SIGINT.
struct ProgressSlice {
  GDALProgressFunc fn;
  double lo;
  double hi;
  static int CPL_STDCALL call(double f, const char* msg, void* self) {
    const auto* s = static_cast<const ProgressSlice*>(self);
    if (g_interrupted) return FALSE;
    return s->fn ? s->fn(s->lo + (s->hi - s->lo) * f, msg, nullptr) : TRUE;
  }
  ProgressFn as_fn() const {
    return [this](double f) { return call(f, "", const_cast<ProgressSlice*>(this)) != FALSE; };
  }
};

// In place needs a file we may write: GDAL's open for update of a
// read-only file failed as "not a raster format GDAL can read".
void check_writable(const std::string& path) {
  if (STARTS_WITH(path.c_str(), "/vsi") || ::access(path.c_str(), W_OK) == 0) return;
  throw Failure(CPLE_OpenFailed, "cannot open '" + path + "' for update: " + std::strerror(errno) +
                                     " (give a dst_file to write a filled copy)");
}

// A raster GDAL reads but cannot update (its driver, or the file's form).
[[noreturn]] void refuse_update(const std::string& path, const char* role) {
  const std::string why = CPLGetLastErrorMsg();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  DatasetPtr ro(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  CPLPopErrorHandler();
  if (ro)
    throw Failure(CPLE_OpenFailed, std::string("cannot open ") + role + " '" + path + "' for update: GDAL's " +
                                       ro->GetDriver()->GetDescription() +
                                       " driver cannot change it in place (give a dst_file to write a filled copy)");
  throw Failure(CPLE_OpenFailed, std::string("cannot open ") + role + " '" + path +
                                     "' for update: " + (why.empty() ? "not a raster format GDAL can read" : why));
}

DatasetPtr open_raster(const std::string& path, bool update, const char* role) {
  VSIStatBufL st;
  if (VSIStatL(path.c_str(), &st) != 0)
    throw Failure(CPLE_OpenFailed, std::string("cannot open ") + role + " '" + path + "': no such file");
  if (update) check_writable(path);
  const unsigned flags = GDAL_OF_RASTER | (update ? GDAL_OF_UPDATE : GDAL_OF_READONLY);
  CPLErrorReset();
  DatasetPtr ds(GDALDataset::Open(path.c_str(), flags));
  if (!ds && update) refuse_update(path, role);
  if (!ds) {
    const std::string why = CPLGetLastErrorMsg();
    throw Failure(CPLE_OpenFailed, std::string("cannot open ") + role + " '" + path + "'" +
                                       (update ? " for update" : "") + ": " +
                                       (why.empty() ? "not a raster format GDAL can read" : why));
  }
  if (ds->GetRasterCount() == 0)
    throw Failure(CPLE_OpenFailed, std::string(role) + " '" + path + "' has no raster band");
  return ds;
}

std::vector<int> select_bands(GDALDataset& ds, const std::vector<int>& wanted) {
  const int count = ds.GetRasterCount();
  std::vector<int> bands;
  for (int b : wanted) {
    if (b > count)
      throw Failure(CPLE_IllegalArg, "band " + std::to_string(b) + " is out of range: the raster has " +
                                         std::to_string(count) + " band(s)");
    if (ds.GetRasterBand(b)->GetColorInterpretation() == GCI_AlphaBand)
      throw Failure(CPLE_IllegalArg, "band " + std::to_string(b) +
                                         " is an alpha band: it marks where the other bands are valid and is "
                                         "not filled (leave out -b " + std::to_string(b) + ")");
    bands.push_back(b);
  }
  if (!wanted.empty()) return bands;
  for (int b = 1; b <= count; ++b)
    if (ds.GetRasterBand(b)->GetColorInterpretation() != GCI_AlphaBand) bands.push_back(b);
  if (bands.empty()) throw Failure(CPLE_IllegalArg, "the raster has only alpha bands: nothing to fill");
  return bands;
}

GDALRasterBand* open_mask(const Args& args, GDALDataset& src, DatasetPtr& holder) {
  if (args.mask_file.empty()) return nullptr;
  holder = open_raster(args.mask_file, false, "mask");
  if (holder->GetRasterXSize() != src.GetRasterXSize() || holder->GetRasterYSize() != src.GetRasterYSize())
    throw Failure(CPLE_IllegalArg, "mask '" + args.mask_file + "' is " + std::to_string(holder->GetRasterXSize()) +
                                       "x" + std::to_string(holder->GetRasterYSize()) + " but the raster is " +
                                       std::to_string(src.GetRasterXSize()) + "x" +
                                       std::to_string(src.GetRasterYSize()));
  return holder->GetRasterBand(1);
}

gdal::FillRequest request_for(GDALDataset& source, int band, GDALRasterBand* file_mask, const Args& args) {
  gdal::FillRequest req;
  if (file_mask) req.masks.push_back(file_mask);
  GDALRasterBand* own = gdal::own_mask(*source.GetRasterBand(band));
  if (own && !args.nomask) req.masks.push_back(own);
  req.require_void_marker = true;
  req.use_nodata = !args.nomask;
  req.band_number = band;
  return req;
}

// Statistics stored with the band (min, max, mean...) no longer hold once voids are filled.
void clear_statistics(GDALRasterBand& band) {
  CPLStringList kept;
  bool dropped = false;
  for (CSLConstList p = band.GetMetadata(); p && *p; ++p) {
    if (STARTS_WITH_CI(*p, "STATISTICS_"))
      dropped = true;
    else
      kept.AddString(*p);
  }
  if (dropped) band.SetMetadata(kept.List());
}

// Fill the selected bands of `source`: in place (`copy` null) or into a copy
// still being made, which each band asks for at its first write.
void fill_bands(GDALDataset& source, BackgroundCopy* copy, const std::vector<int>& bands, GDALRasterBand* file_mask,
                const Args& args, const ProgressSlice& slice) {
  const gdal::Options& options = args.fill;
  if (!copy && bands.size() > 1)  // in place: refuse before writing anything
    for (int b : bands) gdal::check_band(*source.GetRasterBand(b), request_for(source, b, file_mask, args));
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const int b = bands[i];
    gdal::FillRequest req = request_for(source, b, file_mask, args);
    req.blank_target = copy && copy->blank();
    const double w = (slice.hi - slice.lo) / static_cast<double>(bands.size());
    const ProgressSlice part{slice.fn, slice.lo + w * i, slice.lo + w * (i + 1)};
    GDALRasterBand& band = *source.GetRasterBand(b);
    if (!copy) {
      gdal::fill_band(band, req, options, part.as_fn());
      clear_statistics(band);
      continue;
    }
    const gdal::TargetBand target = [copy, b]() -> GDALRasterBand& { return *copy->dataset().GetRasterBand(b); };
    gdal::fill_band(target, band, req, options, part.as_fn());
    clear_statistics(target());
  }
}

CPLStringList creation_options(const Args& args, GDALDriver* driver, ErrorLog& log) {
  CPLStringList co;
  for (const std::string& o : args.creation_options) co.AddString(o.c_str());
  log.reset();
  CPLErrorReset();
  if (!GDALValidateCreationOptions(driver, co.List()))
    throw Failure(CPLE_IllegalArg, std::string("invalid creation option for ") + driver->GetDescription() + ": " +
                                       CPLGetLastErrorMsg());
  return co;
}

DatasetPtr create_copy(GDALDriver* driver, const std::string& path, GDALDataset& from, CSLConstList co,
                       ErrorLog& log, const ProgressSlice& slice, const std::string& shown) {
  return cli::create_copy(driver, path, from, co, log, &ProgressSlice::call, const_cast<ProgressSlice*>(&slice),
                          shown);
}

// An uncompressed GeoTIFF output can be filled where it lies; other formats
// (COG, compressed GeoTIFF, PNG...) are written in one go from a filled work file.
bool fill_output_directly(GDALDriver* driver, const CPLStringList& co) {
  if (!EQUAL(driver->GetDescription(), "GTiff")) return false;
  const char* compress = co.FetchNameValue("COMPRESS");
  return !compress || EQUAL(compress, "NONE");
}

// The bytes a copy takes on disk at its peak: the uncompressed raster,
// filled where it lies, or the uncompressed work file and, unless the output
// is known to be compressed, as much again for the output.
bool compressed_output(GDALDriver* driver, const CPLStringList& co) {
  const char* compress = co.FetchNameValue("COMPRESS");
  return (compress && !EQUAL(compress, "NONE")) || EQUAL(driver->GetDescription(), "COG");
}

std::uint64_t space_needed(GDALDataset& src, GDALDriver* driver, const CPLStringList& co) {
  const std::uint64_t raster = uncompressed_bytes(src);
  if (fill_output_directly(driver, co) || compressed_output(driver, co)) return raster;
  return 2 * raster;
}

std::string space_reason(GDALDriver* driver, const CPLStringList& co) {
  if (fill_output_directly(driver, co)) return "the uncompressed raster";
  if (compressed_output(driver, co)) return "the uncompressed work file";
  return "the uncompressed work file and the output";
}

// A raster the fill reads whole once and writes at the end (the core's
// small-raster path): its copy is made while the fill works.
bool copy_in_background(GDALDataset& src, const Args& args) {
  return fills_whole(src.GetRasterXSize(), src.GetRasterYSize(), args.fill.fill, gdal::tiling_of(args.fill));
}

// The copy that the tiled fill then reads and fills, from a second handle on
// the source opened with GDAL_NUM_THREADS at the fill's thread count: GTiff
// decodes the blocks of one request in parallel while nothing else runs yet
// (10801×4801 LZW blobs: 2.18 -> 2.08 s). The decode threads' errors
// reach the tool's log through its process-wide handler (ErrorLog::Reach).
// The fill's own handle stays as it was: set for the whole run, the threads
// slowed the windows' reads.
DatasetPtr copy_decoded_in_parallel(GDALDriver* driver, const std::string& path, GDALDataset& src, const Args& args,
                                    const CPLStringList& co, ErrorLog& log, const ProgressSlice& slice) {
  const int threads = args.fill.num_threads;
  CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", threads > 0 ? std::to_string(threads).c_str() : "ALL_CPUS");
  DatasetPtr parallel(GDALDataset::Open(args.src.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
  CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", nullptr);
  return create_copy(driver, path, parallel ? *parallel : src, co.List(), log, slice, args.dst);
}

void run_in_place(const Args& args, ErrorLog& log, GDALProgressFunc progress) {
  DatasetPtr src = open_raster(args.src, true, "raster");
  const std::vector<int> bands = select_bands(*src, args.bands);
  DatasetPtr mask_ds;
  GDALRasterBand* mask = open_mask(args, *src, mask_ds);
  log.reset();
  fill_bands(*src, nullptr, bands, mask, args, ProgressSlice{progress, 0.0, 1.0});
  src.reset();  // flush
  if (log.failures() != 0)
    throw Failure(CPLE_FileIO, "writing '" + args.src + "' failed (it may be partly filled): " + log.first_failure());
}

// The source is read block by block and never held in memory: the output is
// a streamed copy of it (or a work GeoTIFF copy) whose void cells are filled
// in place. An uncompressed GeoTIFF copy is read back by the fill (cheaper
// than decoding a compressed source twice), and so is the work copy. A small
// raster (read whole once, written at the end) is the exception: the fill
// reads the source while the copy is made on a second thread (BackgroundCopy).
// A single-band source's copy is blank (its structure, no pixel: the source
// is decoded once), and the fill writes every cell of it.
void run_to_copy(const Args& args, ErrorLog& log, GDALProgressFunc progress) {
  DatasetPtr src = open_raster(args.src, false, "raster");
  const std::vector<int> bands = select_bands(*src, args.bands);
  DatasetPtr mask_ds;
  GDALRasterBand* mask = open_mask(args, *src, mask_ds);
  GDALDriver* driver = output_driver(args.format, args.dst);
  const CPLStringList co = creation_options(args, driver, log);
  check_output_driver(driver, co, *src);
  check_destination(args.dst);
  remove_stale_temporaries(args.dst);
  check_space(args.dst, space_needed(*src, driver, co), space_reason(driver, co));
  TempOutput out(args.dst);
  if (fill_output_directly(driver, co) && copy_in_background(*src, args)) {
    BackgroundCopy dst(driver, args.src, out.path(), co, args.dst, [] { return g_interrupted == 0; },
                       src->GetRasterCount() == 1);
    log.reset();
    fill_bands(*src, &dst, bands, mask, args, ProgressSlice{progress, 0.0, 1.0});
    dst.close();  // waits for a copy that had nothing to fill, flushes
  } else if (fill_output_directly(driver, co)) {
    DatasetPtr dst =
        copy_decoded_in_parallel(driver, out.path(), *src, args, co, log, ProgressSlice{progress, 0.0, 0.1});
    dst = reopen_for_update(std::move(dst), out.path(), args.dst);
    // The fill reads the copy (uncompressed, unlike most sources): it must be whole.
    if (log.failures() != 0) throw Failure(CPLE_FileIO, "cannot write '" + args.dst + "': " + log.first_failure());
    copy_band_info(*src, *dst);
    log.reset();
    fill_bands(*dst, nullptr, bands, mask, args, ProgressSlice{progress, 0.1, 1.0});
    dst.reset();  // close: flushes the last blocks
  } else {
    GDALDriver* gtiff = GetGDALDriverManager()->GetDriverByName("GTiff");
    const std::string work = out.work_path();  // removed with the temporary folder
    CPLStringList work_co;
    work_co.AddNameValue("TILED", "YES");
    work_co.AddNameValue("BIGTIFF", "IF_SAFER");
    DatasetPtr tmp =
        create_copy(gtiff, work, *src, work_co.List(), log, ProgressSlice{progress, 0.0, 0.1}, args.dst);
    tmp = reopen_for_update(std::move(tmp), work, args.dst);
    // The fill reads the work copy: it must be whole.
    if (log.failures() != 0) throw Failure(CPLE_FileIO, "cannot write '" + args.dst + "': " + log.first_failure());
    copy_band_info(*src, *tmp);
    log.reset();
    fill_bands(*tmp, nullptr, bands, mask, args, ProgressSlice{progress, 0.1, 0.85});
    tmp->FlushCache();
    if (log.failures() != 0) throw Failure(CPLE_FileIO, "cannot write '" + args.dst + "': " + log.first_failure());
    DatasetPtr dst = create_copy(driver, out.path(), *tmp, co.List(), log, ProgressSlice{progress, 0.85, 0.98}, args.dst);
    dst.reset();
    if (log.failures() != 0) throw Failure(CPLE_FileIO, "cannot write '" + args.dst + "': " + log.first_failure());
    verify_copy(*tmp, out.path(), driver);  // "done" only once the copy is known to be exact
    ProgressSlice done{progress, 0.98, 1.0};
    ProgressSlice::call(1.0, "", &done);
  }
  if (log.failures() != 0) throw Failure(CPLE_FileIO, "cannot write '" + args.dst + "': " + log.first_failure());
  out.commit();
}

}  // namespace

void request_interrupt() { g_interrupted = 1; }

bool interrupted() { return g_interrupted != 0; }

void run(const Args& args, ErrorLog& log, GDALProgressFunc progress) {
  if (args.dst.empty())
    run_in_place(args, log, progress);
  else
    run_to_copy(args, log, progress);
}

}  // namespace mcmd::cli
