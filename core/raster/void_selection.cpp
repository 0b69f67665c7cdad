#include "raster/void_selection.hpp"

#include <algorithm>
#include <utility>

#include "raster/strips.hpp"

namespace mcmd::detail {

VoidSelector::VoidSelector(int width, int height, const TilingParams& tiling)
    : width_(width), height_(height), inner_only_(tiling.inner_only), max_cells_(tiling.max_void_cells) {}

int VoidSelector::find(int i) {
  int root = i;
  while (parent_[root] != root) root = parent_[root];
  while (parent_[i] != root) i = std::exchange(parent_[i], root);
  return root;
}

void VoidSelector::unite(int a, int b) {
  a = find(a), b = find(b);
  if (a == b) return;
  if (a > b) std::swap(a, b);  // the older run stays the root: labels do not depend on the union order
  parent_[b] = a;
  cells_[a] += cells_[b];
  border_[a] = border_[a] || border_[b];
}

void VoidSelector::add_row(int y, const std::uint8_t* valid) {
  const std::size_t begin = runs_.size();
  std::size_t p = prev_begin_;
  for_each_void_run(valid, width_, [&](int x0, int x) {
    const int id = static_cast<int>(runs_.size());
    runs_.push_back(VoidRun{y, x0, x});
    parent_.push_back(id);
    cells_.push_back(static_cast<std::size_t>(x - x0));
    border_.push_back(y == 0 || y == height_ - 1 || x0 == 0 || x == width_);
    // 8-neighbours: a run of the row above touching [x0 - 1, x] (inclusive).
    while (p < prev_end_ && runs_[p].x1 < x0) ++p;
    for (std::size_t q = p; q < prev_end_ && runs_[q].x0 <= x; ++q) unite(static_cast<int>(q), id);
  });
  prev_begin_ = begin;
  prev_end_ = runs_.size();
}

LeftVoids VoidSelector::finish() {
  std::vector<VoidRun> left;
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    const int root = find(static_cast<int>(i));
    const bool leave = (inner_only_ && border_[root]) || (max_cells_ > 0 && cells_[root] > max_cells_);
    if (leave) left.push_back(runs_[i]);
  }
  return LeftVoids(std::move(left), height_);
}

LeftVoids find_left_voids(const RasterAccess& raster, const TilingParams& tiling) {
  VoidSelector selector(raster.width, raster.height, tiling);
  for_each_strip(raster, [&](int y0, int rows, const double*, const std::uint8_t* valid) {
    for (int r = 0; r < rows; ++r) selector.add_row(y0 + r, valid + static_cast<std::size_t>(r) * raster.width);
  });
  return selector.finish();
}

RasterAccess without_left_voids(const RasterAccess& raster, const LeftVoids& left) {
  RasterAccess a = raster;
  a.write = [&raster, &left](int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
    std::vector<std::uint8_t> m(mask, mask + static_cast<std::size_t>(w) * h);
    left.clear(x0, y0, w, h, m.data());
    raster.write(x0, y0, w, h, z, m.data());
  };
  return a;
}

}  // namespace mcmd::detail
