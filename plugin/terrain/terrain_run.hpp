// What mcmd_terrain does once its command line is parsed: the output's size
// and georeferencing (from the sketch, -like, -size, -a_ullr, -a_srs), the
// terrain made in memory (MCMDTerrain's body), then written under a
// temporary name and renamed (cli/output_file.hpp), the hillshade likewise.
#pragma once

#include "cli/error_log.hpp"
#include "gdal.h"
#include "terrain/terrain_args.hpp"

namespace mcmd::cli {

// Throws gdal::Failure / std::exception with a one-line message; no output
// file is left behind on failure.
void run_terrain(const TerrainArgs& args, ErrorLog& log, GDALProgressFunc progress);

// Set by SIGINT: the next progress report cancels the run cleanly.
void interrupt_terrain();

}  // namespace mcmd::cli
