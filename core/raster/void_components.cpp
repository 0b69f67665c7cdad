#include "raster/void_components.hpp"

#include <algorithm>
#include <climits>
#include <utility>

namespace mcmd::detail {

std::vector<std::uint8_t> run_mask(const std::vector<VoidRun>& runs, int x0, int y0, int w, int h) {
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  for (const VoidRun& r : runs) {
    const std::size_t first = static_cast<std::size_t>(r.y - y0) * static_cast<std::size_t>(w) + (r.x0 - x0);
    std::fill_n(mask.begin() + static_cast<std::ptrdiff_t>(first), r.x1 - r.x0, std::uint8_t{1});
  }
  return mask;
}

std::size_t cell_count(const std::vector<VoidRun>& runs) {
  std::size_t n = 0;
  for (const VoidRun& r : runs) n += static_cast<std::size_t>(r.x1 - r.x0);
  return n;
}

RunsByRow::RunsByRow(std::vector<VoidRun> runs, int height) : runs_(std::move(runs)) {
  std::sort(runs_.begin(), runs_.end(),
            [](const VoidRun& a, const VoidRun& b) { return a.y != b.y ? a.y < b.y : a.x0 < b.x0; });
  row_start_.assign(static_cast<std::size_t>(height) + 1, 0);
  for (const VoidRun& r : runs_) {
    ++row_start_[static_cast<std::size_t>(r.y) + 1];
    cells_ += static_cast<std::size_t>(r.x1 - r.x0);
  }
  for (std::size_t y = 0; y + 1 < row_start_.size(); ++y) row_start_[y + 1] += row_start_[y];
}

void RunsByRow::clear(int x0, int y0, int w, int h, std::uint8_t* mask) const {
  if (runs_.empty()) return;
  for (int y = y0; y < y0 + h; ++y)
    for (std::size_t k = row_start_[y]; k < row_start_[y + 1]; ++k) {
      const int b = std::max(runs_[k].x0, x0), e = std::min(runs_[k].x1, x0 + w);
      std::uint8_t* row = mask + static_cast<std::size_t>(y - y0) * w;
      if (b < e) std::fill(row + (b - x0), row + (e - x0), 0);
    }
}

std::size_t RunsByRow::count(const std::vector<VoidRun>& runs) const {
  std::size_t n = 0;
  for (const VoidRun& r : runs)
    for (std::size_t k = row_start_[r.y]; k < row_start_[r.y + 1]; ++k) {
      const int b = std::max(runs_[k].x0, r.x0), e = std::min(runs_[k].x1, r.x1);
      if (b < e) n += static_cast<std::size_t>(e - b);
    }
  return n;
}

void RunsByRow::mark_row(int y, std::uint8_t* row) const {
  if (runs_.empty()) return;
  for (std::size_t k = row_start_[y]; k < row_start_[y + 1]; ++k) std::fill(row + runs_[k].x0, row + runs_[k].x1, 1);
}

ComponentFinder::ComponentFinder(int width, int max_extent, std::size_t max_runs)
    : width_(width), max_extent_(max_extent), max_runs_(max_runs) {}

int ComponentFinder::make(const VoidRun& run) {
  int id;
  if (!free_.empty()) {
    id = free_.back();
    free_.pop_back();
  } else {
    id = static_cast<int>(recs_.size());
    recs_.emplace_back();
  }
  Rec& r = recs_[id];
  r.parent = id;
  r.box = Box{run.x0, run.y, run.x1 - 1, run.y};
  r.stamp = -1;
  r.large = overflow_;
  r.runs.clear();
  if (!r.large) {
    r.runs.push_back(run);
    if (++stored_runs_ > max_runs_) overflow_ = true;
    check_extent(r);
  }
  return id;
}

int ComponentFinder::find(int i) {
  int root = i;
  while (recs_[root].parent != root) root = recs_[root].parent;
  while (recs_[i].parent != root) {
    const int next = recs_[i].parent;
    recs_[i].parent = root;
    i = next;
  }
  return root;
}

void ComponentFinder::check_extent(Rec& r) {
  if (r.large || (r.box.width() <= max_extent_ && r.box.height() <= max_extent_)) return;
  r.large = true;
  stored_runs_ -= r.runs.size();
  std::vector<VoidRun>().swap(r.runs);
}

void ComponentFinder::unite(int a, int b) {
  a = find(a);
  b = find(b);
  if (a == b) return;
  if (recs_[a].runs.size() < recs_[b].runs.size()) std::swap(a, b);
  Rec& keep = recs_[a];
  Rec& gone = recs_[b];
  keep.box = Box{std::min(keep.box.x0, gone.box.x0), std::min(keep.box.y0, gone.box.y0),
                 std::max(keep.box.x1, gone.box.x1), std::max(keep.box.y1, gone.box.y1)};
  if (gone.large && !keep.large) {
    keep.large = true;
    stored_runs_ -= keep.runs.size();
    std::vector<VoidRun>().swap(keep.runs);
  }
  if (keep.large) {
    stored_runs_ -= gone.runs.size();
  } else {
    keep.runs.insert(keep.runs.end(), gone.runs.begin(), gone.runs.end());
  }
  std::vector<VoidRun>().swap(gone.runs);
  gone.parent = a;
  absorbed_.push_back(b);
  check_extent(keep);
}

void ComponentFinder::close(int root) {
  Rec& r = recs_[root];
  if (r.large) {
    large_.push_back(r.box);
  } else {
    small_.push_back(SmallComponent{r.box, std::move(r.runs)});
  }
  r.runs = {};
  free_.push_back(root);
}

void ComponentFinder::add_row(int y, const std::uint8_t* valid) {
  row_ = y;
  cur_.clear();
  for_each_void_run(valid, width_, [&](int x, int e) {
    const int label = make(VoidRun{y, x, e});
    if (!cur_.empty() && cur_.back().x1 + 2 == x) unite(cur_.back().label, label);  // one known cell between
    cur_.push_back(Labeled{x, e - 1, label});
  });
  // Rows above: Manhattan distance <= 2 means |dx| <= 1 one row up, dx = 0 two rows up.
  auto connect = [&](const std::vector<Labeled>& prev, int reach) {
    std::size_t j = 0;
    for (const Labeled& c : cur_) {
      while (j < prev.size() && prev[j].x1 + reach < c.x0) ++j;
      for (std::size_t k = j; k < prev.size() && prev[k].x0 <= c.x1 + reach; ++k) unite(c.label, prev[k].label);
    }
  };
  connect(prev1_, 1);
  connect(prev2_, 0);

  for (Labeled& l : cur_) l.label = find(l.label);
  for (Labeled& l : prev1_) l.label = find(l.label);
  // Roots with cells in rows y-1 or y stay open; the other previously open ones are complete.
  std::vector<int> open;
  for (const auto* rows : {&prev1_, &cur_})
    for (const Labeled& l : *rows)
      if (recs_[l.label].stamp != y) {
        recs_[l.label].stamp = y;
        open.push_back(l.label);
      }
  for (int r : open_) {
    const int root = find(r);
    if (recs_[root].stamp == y) continue;
    recs_[root].stamp = y;
    close(root);
  }
  for (int a : absorbed_) {
    recs_[a].parent = a;
    free_.push_back(a);
  }
  absorbed_.clear();
  open_ = std::move(open);
  prev2_ = std::move(prev1_);
  prev1_ = std::move(cur_);
  cur_ = {};
}

void ComponentFinder::finish() {
  for (int r : open_) {
    const int root = find(r);
    if (recs_[root].stamp == INT_MAX) continue;
    recs_[root].stamp = INT_MAX;
    close(root);
  }
  open_.clear();
  auto run_less = [](const VoidRun& a, const VoidRun& b) { return a.y != b.y ? a.y < b.y : a.x0 < b.x0; };
  for (SmallComponent& c : small_) std::sort(c.runs.begin(), c.runs.end(), run_less);
  std::sort(small_.begin(), small_.end(),
            [&](const SmallComponent& a, const SmallComponent& b) { return run_less(a.runs[0], b.runs[0]); });
  recs_ = {};
  free_ = {};
}

}  // namespace mcmd::detail
