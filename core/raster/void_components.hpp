// Void components of a raster, found in one streaming pass (internal to the
// tiled fill; docs/tiling.md, "Small voids").
//
// Two void cells interact through the thin-plate stencil when their Manhattan
// distance is at most 2; a component is a connected set under that relation.
// Rows are fed top to bottom; a component is closed once two rows without any
// of its cells have passed. Components whose bounding box has a side of at
// most `max_extent` cells are "small": their runs are kept, so they can be
// solved alone in a grid placed by their bounding box. Of the other ("large")
// components only the bounding box is kept. Memory: the open components of the
// last rows, plus the small components' runs (capped: past `max_runs` stored
// runs, the finder gives up and reports overflow()).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/zero_runs.hpp"

namespace mcmd::detail {

struct VoidRun {
  int y = 0;
  int x0 = 0;  // [x0, x1)
  int x1 = 0;
};

struct Box {  // inclusive bounds
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  int width() const { return x1 - x0 + 1; }
  int height() const { return y1 - y0 + 1; }
};

// Calls f(x0, x1) for each run [x0, x1) of void cells (valid[x] == 0) among
// the w cells of a row, left to right.
// (memchr skips the known cells a vector at a time: rows are mostly known.)
template <class F>
void for_each_void_run(const std::uint8_t* valid, int w, F&& f) {
  for_each_zero_run(valid, w, std::forward<F>(f));
}

// One byte per cell of the w×h rectangle whose first cell is (x0, y0): 1
// where one of `runs` covers it. Pre: the runs lie inside the rectangle.
std::vector<std::uint8_t> run_mask(const std::vector<VoidRun>& runs, int x0, int y0, int w, int h);

// The number of cells of `runs`.
std::size_t cell_count(const std::vector<VoidRun>& runs);

// Void runs indexed by row: which cells of a rectangle or a row they cover.
class RunsByRow {
 public:
  RunsByRow() = default;
  RunsByRow(std::vector<VoidRun> runs, int height);  // runs in any order, rows < height
  bool empty() const { return runs_.empty(); }
  std::size_t cells() const { return cells_; }
  // Clears mask[] (a w×h rectangle at (x0, y0), row-major) on the runs' cells.
  void clear(int x0, int y0, int w, int h, std::uint8_t* mask) const;
  // The number of cells of `runs` that these runs cover.
  std::size_t count(const std::vector<VoidRun>& runs) const;
  // Sets row[x] = 1 on the runs' cells of row y (row: the raster's width).
  void mark_row(int y, std::uint8_t* row) const;

 private:
  std::vector<VoidRun> runs_;           // sorted by (y, x0)
  std::vector<std::size_t> row_start_;  // runs_ of row y: [row_start_[y], row_start_[y+1])
  std::size_t cells_ = 0;
};

struct SmallComponent {
  Box box;
  std::vector<VoidRun> runs;  // row-major order
};

class ComponentFinder {
 public:
  ComponentFinder(int width, int max_extent, std::size_t max_runs = std::size_t{4} << 20);

  // Row y (rows in order 0, 1, 2, ...): valid[x] != 0 for known cells.
  void add_row(int y, const std::uint8_t* valid);
  // After the last row. Sorts the small components by their first run.
  void finish();

  bool overflow() const { return overflow_; }
  std::vector<SmallComponent>& small() { return small_; }
  const std::vector<Box>& large() const { return large_; }

 private:
  struct Rec {
    int parent = -1;
    Box box;
    bool large = false;
    int stamp = -1;
    std::vector<VoidRun> runs;
  };
  struct Labeled {
    int x0, x1;  // inclusive
    int label;
  };
  int make(const VoidRun& r);
  int find(int i);
  void unite(int a, int b);
  void check_extent(Rec& r);
  void close(int root);

  int width_;
  int max_extent_;
  std::size_t max_runs_;
  std::size_t stored_runs_ = 0;
  bool overflow_ = false;
  std::vector<Rec> recs_;
  std::vector<int> free_;
  std::vector<int> absorbed_;
  std::vector<Labeled> prev2_, prev1_, cur_;
  std::vector<int> open_;  // roots with cells in the last two rows
  int row_ = -1;
  std::vector<SmallComponent> small_;
  std::vector<Box> large_;
};

}  // namespace mcmd::detail
