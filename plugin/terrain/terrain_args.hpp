// Command line of mcmd_terrain, parsed into plain values; the terrain's own
// flags become MCMDTerrain options (terrain_options.hpp) and are checked
// before any file is opened.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lib/terrain_options.hpp"

namespace mcmd::cli {

struct GeoBox {
  double ulx = 0, uly = 0, lrx = 0, lry = 0;
};

struct TerrainArgs {
  bool help = false;
  bool version = false;
  bool quiet = false;
  int width = 0, height = 0;  // -size; 0: from the sketch or -like
  std::string type = "Float32";
  std::string format;                         // "" = from dst's extension, else GTiff
  std::vector<std::string> creation_options;  // -co NAME=VALUE
  std::string srs;                            // -a_srs
  std::optional<GeoBox> ullr;                 // -a_ullr
  std::optional<double> nodata;               // -a_nodata (written with -method none)
  std::string like;                           // -like template raster
  int band = 1;                               // -b: the sketch's band
  std::string hillshade;                      // -hillshade FILE.png
  std::vector<std::string> options;           // NAME=VALUE for MCMDTerrain, as given
  gdal::TerrainOptions terrain;               // options, parsed
  std::string sketch;                         // "" = none
  std::string dst;
};

// Parse argv (argv[0] skipped). Throws UsageError (cli/args.hpp).
TerrainArgs parse_terrain_args(int argc, const char* const* argv);

}  // namespace mcmd::cli
