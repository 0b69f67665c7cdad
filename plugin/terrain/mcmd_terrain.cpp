// mcmd_terrain: make a terrain with MCMD (gdal tool conventions).
#include <csignal>
#include <cstdio>
#include <optional>
#include <string>

#include "cli/error_log.hpp"
#include "cli/general_options.hpp"
#include "cpl_conv.h"
#include "gdal.h"
#include "terrain/terrain_args.hpp"
#include "terrain/terrain_help.hpp"
#include "terrain/terrain_run.hpp"

namespace {

bool g_dots = false;  // a progress line was started

int CPL_STDCALL progress(double f, const char* msg, void* arg) {
  g_dots = true;
  return GDALTermProgress(f, msg, arg);
}

extern "C" void on_signal(int) { mcmd::cli::interrupt_terrain(); }

// One line on stderr, after ending the progress dots.
int report_error(std::string what) {
  for (char& c : what)
    if (c == '\n' || c == '\r') c = ' ';
  if (g_dots) std::fputs("\n", stdout);
  std::fflush(stdout);
  std::fprintf(stderr, "mcmd_terrain: error: %s\n", what.c_str());
  return 1;
}

int print(const std::string& text) { return std::fputs(text.c_str(), stdout) < 0 ? 1 : 0; }

}  // namespace

int main(int argc, char** argv) {
  std::signal(SIGXFSZ, SIG_IGN);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  GDALAllRegister();
  mcmd::cli::ErrorLog log(mcmd::cli::ErrorLog::Reach::every_thread);
  try {
    // GDAL's general options (--config, --debug on, --formats, ...) first.
    const std::optional<CPLStringList> argl = mcmd::cli::apply_gdal_general_options(argc, argv);
    if (!argl) return 0;
    if (!CPLGetConfigOption("GDAL_CACHEMAX", nullptr)) GDALSetCacheMax64(GIntBig{64} << 20);
    const mcmd::cli::TerrainArgs args = mcmd::cli::parse_terrain_args(argl->size(), argl->List());
    if (args.help) return print(mcmd::cli::terrain_help_text());
    if (args.version) return print(mcmd::cli::terrain_version_text());
    mcmd::cli::run_terrain(args, log, args.quiet ? nullptr : progress);
    return 0;
  } catch (const std::exception& e) {
    return report_error(e.what());
  }
}
