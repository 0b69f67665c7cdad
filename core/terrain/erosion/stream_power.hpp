// Fluvial erosion by the stream-power law with uplift,
//   ∂z/∂t = U − K·A^m·S^n,
// solved implicitly along the receivers from the outlets up (Braun &
// Willett 2013): each cell's new height depends only on its receiver's new
// height, so one pass in Drainage::order is a whole step, stable for any
// time step. Heights and lengths are in finest-grid cells, areas in
// finest-grid cells²; a grid cell is `spacing` finest cells across.
#pragma once

#include <cstdint>
#include <vector>

#include "terrain/erosion/drainage.hpp"

namespace mcmd::terrain {

struct StreamPower {
  double K = 1.0, m = 0.5, n = 1.0;
  double spacing = 1.0;
};

// One step of dt on the free cells (fixed cells keep their heights; water
// passes over them). uplift × rate: per cell, per unit time. A cell whose
// receiver rose above it (uplifted faster) only rises: a pit the next
// step's flood fills.
void stream_power_step(std::vector<double>& z, const std::vector<double>& uplift, double rate,
                       const std::vector<std::uint8_t>& fixed, const Drainage& d, const StreamPower& sp, double dt);

// The erodibility at which the steady state of this network (uplift equal
// to erosion everywhere: each free cell (U / (K·A^m))^(1/n) per unit length
// above its receiver) has the relief of `target` above the cells the water
// reaches first that are fixed (the 99th percentiles of both). 0 when
// target has none.
double steady_state_erodibility(const std::vector<double>& target, const std::vector<double>& uplift,
                                const std::vector<std::uint8_t>& fixed, const Drainage& d, const StreamPower& sp);

}  // namespace mcmd::terrain
