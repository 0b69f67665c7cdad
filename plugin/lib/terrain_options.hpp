// Every MCMDTerrain option (mcmd_terrain's flags are shorthands for them),
// parsed and validated in one place. The fill parameters it shares with
// MCMDFillNodata (RS, H, RT, SEED, the shapes, DELTA, NUM_THREADS) go
// through that parser (options.hpp), so they mean the same in both.
#pragma once

#include <string>
#include <vector>

#include "cpl_port.h"
#include "mcmd/erosion.hpp"
#include "mcmd/skeleton.hpp"
#include "mcmd/terrain.hpp"

namespace mcmd::gdal {

// Which sketch cells are unknown, besides its nodata, mask, alpha and NaN cells.
enum class UnknownRule {
  automatic,  // white (the paper's convention) for a Byte or UInt16 band with no nodata or mask
  none,       // nothing else
  value,      // cells equal to TerrainOptions::unknown_value (white, black or a number)
};

struct TerrainPoint {
  int col = 0, row = 0;
  double z = 0.0;
};

struct TerrainOptions {
  TerrainParams terrain{};
  UnknownRule unknown = UnknownRule::automatic;
  double unknown_value = 0.0;
  bool unknown_white = false;  // unknown_value is the band type's white (resolved when the sketch is read)
  bool has_zrange = false;
  double z_min = 0.0, z_max = 1000.0;
  bool skeleton = false;
  int ridge_couples = 0, river_particles = 0;  // 0: automatic
  std::string peaks;                           // "", "iizuka" or a count
  double peaks_noise = 0.0;
  bool has_peaks_threshold = false;
  double peaks_threshold = 0.0;
  std::vector<TerrainPoint> points;
  std::string states_file;
  std::string ridges, rivers;             // line files (OGR vectors or raster masks)
  std::vector<double> ridge_z, river_z;   // heights for line cells without one: Z, or Z1,Z2 along the line
  int upsample = 1;
  int median = 0, median_passes = 1;
  bool median_all = false;
  // EROSION and its law, UPLIFT, DIFFUSION, TALUS. Without EROSION the
  // skeleton, from-scratch and line terrains are eroded (auto), a sketch,
  // peaks or points are not.
  ErosionParams erosion{};
  bool has_erosion = false;
  std::string uplift_file;  // UPLIFT=FILE: a raster of relative rates, the terrain's size
};

// The erosion steps o asks for, or its default: auto for the skeleton,
// from-scratch and line terrains, 0 for a sketch, peaks, points or
// METHOD=none.
int erosion_steps(const TerrainOptions& o, bool has_sketch);

// Parse NAME=VALUE strings (names case-insensitive). Throws OptionError.
TerrainOptions parse_terrain_options(CSLConstList options);

// The accepted names, comma separated.
const char* terrain_option_names();

}  // namespace mcmd::gdal
