#include "lib/errors.hpp"

#include <new>

#include "lib/options.hpp"
#include "mcmd/progress.hpp"

namespace mcmd::gdal {

void check_io(CPLErr err, const char* what) {
  if (err != CE_None) {
    const std::string detail = CPLGetLastErrorMsg();
    throw Failure(CPLE_FileIO, std::string(what) + (detail.empty() ? "" : ": " + detail));
  }
}

void warn(const std::string& msg) { CPLError(CE_Warning, CPLE_AppDefined, "%s%s", kWarningPrefix, msg.c_str()); }

void report_current_exception() {
  try {
    throw;
  } catch (const Failure& e) {
    CPLError(CE_Failure, e.num(), "%s", e.what());
  } catch (const Cancelled&) {
    CPLError(CE_Failure, CPLE_UserInterrupt, "cancelled by the user");
  } catch (const OptionError& e) {
    CPLError(CE_Failure, CPLE_IllegalArg, "%s", e.what());
  } catch (const std::bad_alloc&) {
    CPLError(CE_Failure, CPLE_OutOfMemory, "out of memory: the raster is too large to fill in memory");
  } catch (const std::exception& e) {
    CPLError(CE_Failure, CPLE_AppDefined, "%s", e.what());
  } catch (...) {
    CPLError(CE_Failure, CPLE_AppDefined, "unexpected internal error");
  }
}

}  // namespace mcmd::gdal
