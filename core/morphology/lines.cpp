#include "morphology/lines.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace mcmd::morph {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A traced cell and the height given at it (interpolated along the
// segment), NaN when none.
struct Traced {
  int x, y;
  double z;
};

// Cells of segment a → b (pixel coordinates), sampled finely enough that
// consecutive cells are 8-neighbours (a step of at most half a cell).
void trace_segment(const LinePoint& a, const LinePoint& b, std::vector<Traced>& out) {
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const int steps = std::max(1, static_cast<int>(std::ceil(len * 2.0)));
  for (int s = 0; s <= steps; ++s) {
    const double t = static_cast<double>(s) / steps;
    const int x = static_cast<int>(std::floor(a.x + t * (b.x - a.x)));
    const int y = static_cast<int>(std::floor(a.y + t * (b.y - a.y)));
    const double z = std::isnan(a.z) || std::isnan(b.z) ? kNaN : a.z + t * (b.z - a.z);
    if (!out.empty() && out.back().x == x && out.back().y == y) continue;
    out.push_back({x, y, z});
  }
}

std::vector<Traced> trace_with_z(const Line& line, int w, int h) {
  std::vector<Traced> all;
  if (line.points.size() == 1) {
    const LinePoint& p = line.points.front();
    all.push_back({static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)), p.z});
  }
  for (std::size_t k = 1; k < line.points.size(); ++k) trace_segment(line.points[k - 1], line.points[k], all);
  std::vector<Traced> out;
  std::map<std::pair<int, int>, bool> seen;
  for (const Traced& t : all) {
    if (t.x < 0 || t.y < 0 || t.x >= w || t.y >= h) continue;
    if (!seen.emplace(std::make_pair(t.y, t.x), true).second) continue;
    out.push_back(t);
  }
  return out;
}

struct Known {
  bool valid = false;
  double z = 0.0;
};

Known read_cell(const RasterAccess& raster, int x, int y) {
  double z = 0.0;
  std::uint8_t valid = 0;
  raster.read(x, y, 1, 1, &z, &valid);
  return Known{valid != 0, z};
}

// Heights of the void run cells[b, e) of a traced line: given heights, else
// the straight change between the known cells before and after the run
// (by length along the line), else NaN. A run without given heights between
// two known cells gets each cell's place on it (run number `run`).
void run_heights(const std::vector<Traced>& cells, std::size_t b, std::size_t e, const Known& before,
                 const Known& after, int run, std::vector<double>& z, std::vector<RunPlace>& place) {
  std::vector<double> along(e - b + 2, 0.0);  // from the cell before the run
  const auto pos = [&](std::size_t k) -> std::pair<double, double> {
    const std::size_t i = std::min(std::max(k, std::size_t{1}), cells.size()) - 1;
    return {cells[i].x + 0.5, cells[i].y + 0.5};
  };
  for (std::size_t k = 1; k < along.size(); ++k) {
    const auto [x0, y0] = pos(b + k - 1);
    const auto [x1, y1] = pos(b + k);
    along[k] = along[k - 1] + std::hypot(x1 - x0, y1 - y0);
  }
  const bool given = std::any_of(cells.begin() + b, cells.begin() + e, [](const Traced& t) { return !std::isnan(t.z); });
  for (std::size_t k = b; k < e; ++k) {
    if (!std::isnan(cells[k].z)) {
      z[k] = cells[k].z;
    } else if (before.valid && after.valid) {
      const double t = along[k - b + 1] / along.back();
      z[k] = before.z + t * (after.z - before.z);
      if (!given) place[k] = {run, along[k - b + 1], along.back(), before.z, after.z};
    } else {
      z[k] = kNaN;
    }
  }
}

}  // namespace

std::vector<std::pair<int, int>> trace(const Line& line, int w, int h) {
  std::vector<std::pair<int, int>> out;
  for (const Traced& t : trace_with_z(line, w, h)) out.emplace_back(t.x, t.y);
  return out;
}

std::vector<LineCell> line_cells(const RasterAccess& raster) {
  std::map<std::pair<int, int>, LineCell> by_cell;  // (y, x): sorted, the first line's wins
  int runs = 0;
  for (const Line& line : raster.lines) {
    const std::vector<Traced> cells = trace_with_z(line, raster.width, raster.height);
    std::vector<Known> known(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k) known[k] = read_cell(raster, cells[k].x, cells[k].y);
    std::vector<double> z(cells.size(), kNaN);
    std::vector<RunPlace> place(cells.size());
    for (std::size_t b = 0; b < cells.size();) {
      if (known[b].valid) {
        ++b;
        continue;
      }
      std::size_t e = b;
      while (e < cells.size() && !known[e].valid) ++e;
      run_heights(cells, b, e, b > 0 ? known[b - 1] : Known{}, e < cells.size() ? known[e] : Known{}, runs++, z,
                  place);
      for (std::size_t k = b; k < e; ++k)
        by_cell.emplace(std::make_pair(cells[k].y, cells[k].x),
                        LineCell{cells[k].x, cells[k].y, line.kind, z[k],
                                 line.kind == CellState::river ? place[k] : RunPlace{}});
      b = e;
    }
  }
  std::vector<LineCell> out;
  out.reserve(by_cell.size());
  for (const auto& [key, c] : by_cell) out.push_back(c);
  return out;
}

void place_line_cells(int w, int h, long long ox, long long oy, double* z, CellState* state,
                      const std::vector<LineCell>& cells) {
  const auto [b, e] = cells_in_rows(cells, static_cast<int>(std::max(0LL, oy)), h);
  for (std::size_t k = b; k < e; ++k) {
    const LineCell& c = cells[k];
    const long long u = c.x - ox, v = c.y - oy;
    if (std::isnan(c.z) || u < 0 || v < 0 || u >= w || v >= h) continue;
    const std::size_t i = static_cast<std::size_t>(v) * static_cast<std::size_t>(w) + static_cast<std::size_t>(u);
    if (state[i] != CellState::unknown) continue;
    state[i] = c.kind;
    z[i] = c.z;
  }
}

void place_line_cells(Grid& grid, const std::vector<LineCell>& cells) {
  place_line_cells(grid.side(), grid.side(), grid.origin_x(), grid.origin_y(), grid.elevations().data(),
                   grid.states().data(), cells);
}

std::pair<std::size_t, std::size_t> cells_in_rows(const std::vector<LineCell>& cells, int y0, int h) {
  const auto lo = std::lower_bound(cells.begin(), cells.end(), y0, [](const LineCell& c, int y) { return c.y < y; });
  const auto hi = std::lower_bound(lo, cells.end(), y0 + h, [](const LineCell& c, int y) { return c.y < y; });
  return {static_cast<std::size_t>(lo - cells.begin()), static_cast<std::size_t>(hi - cells.begin())};
}

}  // namespace mcmd::morph
