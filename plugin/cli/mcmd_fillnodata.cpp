// mcmd_fillnodata: fill nodata voids of a raster with MCMD (gdal_fillnodata conventions).
#include <atomic>
#include <csignal>
#include <cstdio>
#include <optional>
#include <string>
#include <unistd.h>

#include "cli/args.hpp"
#include "cli/cancel_watchdog.hpp"
#include "cli/error_log.hpp"
#include "cli/general_options.hpp"
#include "cli/help.hpp"
#include "cli/run.hpp"
#include "cpl_conv.h"
#include "gdal.h"

namespace {

// Errors are one line: fold any newline GDAL put in a message.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

extern "C" void on_interrupt(int) { mcmd::cli::request_interrupt(); }

std::atomic<bool> g_progress_shown{false};  // read by the watchdog's thread too

// GDAL's terminal progress; remembers that a line was started.
int CPL_STDCALL term_progress(double f, const char* msg, void* arg) {
  g_progress_shown = true;
  return GDALTermProgress(f, msg, arg);
}

void print_error(const std::string& msg) {
  if (g_progress_shown) std::fputs("\n", stdout);  // end the dots before the error line
  std::fflush(stdout);
  std::fprintf(stderr, "mcmd_fillnodata: error: %s\n", one_line(msg).c_str());
}

mcmd::cli::CancelWatchdog* g_watchdog = nullptr;

// Before the run's last line: when the watchdog has ended the run meanwhile
// (it prints the line and exits), nothing more.
void end_run() {
  if (g_watchdog && !g_watchdog->claim_exit())
    for (;;) ::pause();
}

int fail(const std::string& msg) {
  end_run();
  print_error(msg);
  return 1;
}

}  // namespace

constexpr GIntBig kDefaultCacheBytes = GIntBig{64} << 20;

int main(int argc, char** argv) {
  std::signal(SIGXFSZ, SIG_IGN);  // a file size limit becomes a write error, not a kill
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  GDALAllRegister();
  mcmd::cli::CancelWatchdog watchdog([] { print_error("cancelled by the user"); });
  g_watchdog = &watchdog;
  mcmd::cli::ErrorLog log(mcmd::cli::ErrorLog::Reach::every_thread);
  try {
    const std::optional<CPLStringList> argl = mcmd::cli::apply_gdal_general_options(argc, argv);
    if (!argl) return 0;  // e.g. --formats: printed
    // GDAL's default block cache is 5% of RAM: with a raster streamed through
    // tiles that makes peak memory grow with the raster. A fixed cache keeps it
    // bounded; GDAL_CACHEMAX (environment or --config) still wins.
    if (!CPLGetConfigOption("GDAL_CACHEMAX", nullptr)) GDALSetCacheMax64(kDefaultCacheBytes);
    const mcmd::cli::Args args = mcmd::cli::parse_args(argl->size(), argl->List());
    if (args.help) return std::fputs(mcmd::cli::help_text().c_str(), stdout) < 0;
    if (args.version) return std::fputs(mcmd::cli::version_text().c_str(), stdout) < 0;
    mcmd::cli::run(args, log, args.quiet ? nullptr : term_progress);
    end_run();
    return 0;
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}
