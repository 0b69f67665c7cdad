// The in-memory grid every mcmd algorithm works on: a square of side 2^n + 1
// holding an elevation and a state per cell.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "mcmd/cell_state.hpp"

namespace mcmd {

// Square grid of side 2^n + 1, row-major, y growing downwards like raster rows.
// A grid may be a window of a larger raster: origin_x/origin_y give the global
// raster coordinates of cell (0, 0), so noise keyed on global coordinates is the
// same whichever window computes a cell.
class Grid {
 public:
  Grid() = default;
  // Pre: 0 <= n <= 30. Post: every cell unknown with elevation 0.
  explicit Grid(int n, std::int64_t origin_x = 0, std::int64_t origin_y = 0);

  int levels() const { return n_; }  // n
  int side() const { return side_; }  // 2^n + 1
  std::size_t cell_count() const { return z_.size(); }
  std::int64_t origin_x() const { return origin_x_; }
  std::int64_t origin_y() const { return origin_y_; }

  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(side_) + static_cast<std::size_t>(x);
  }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < side_ && y < side_; }

  double& z(int x, int y) { return z_[index(x, y)]; }
  double z(int x, int y) const { return z_[index(x, y)]; }
  CellState& state(int x, int y) { return s_[index(x, y)]; }
  CellState state(int x, int y) const { return s_[index(x, y)]; }

  std::vector<double>& elevations() { return z_; }
  const std::vector<double>& elevations() const { return z_; }
  std::vector<CellState>& states() { return s_; }
  const std::vector<CellState>& states() const { return s_; }

  std::size_t count(CellState s) const;

 private:
  int n_ = 0;
  int side_ = 1;
  std::int64_t origin_x_ = 0;
  std::int64_t origin_y_ = 0;
  std::vector<double> z_{0.0};
  std::vector<CellState> s_{CellState::unknown};
};

// Elevation range (max - min) over the constraint cells; 0 when there are none.
// Pre: z and states have one entry per cell.
double known_range(std::span<const double> z, std::span<const CellState> states);
double known_range(const Grid& grid);

}  // namespace mcmd
