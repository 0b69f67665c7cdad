#include "raster/whole_raster.hpp"

#include <algorithm>
#include <atomic>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "mcmd/fill_raster.hpp"
#include "morphology/channels.hpp"
#include "morphology/lines.hpp"
#include "raster/coarse_guide.hpp"
#include "raster/frame.hpp"
#include "raster/tiles/tiled_fill.hpp"
#include "raster/void_components.hpp"
#include "raster/void_field.hpp"

namespace mcmd::detail {

namespace {

// The raster in memory, as read.
struct Whole {
  int w = 0, h = 0;
  std::vector<double> z;
  std::vector<std::uint8_t> valid;
  std::vector<double> inflow;          // -morph auto: morphology/channels.hpp's inflow_into_voids
  std::vector<morph::LineCell> lines;  // morphology/lines.hpp
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * w + x; }
};

// How many times the raster's cells the voids' fields may hold together and
// still be drained each on its own. A field's Priority-Flood stays in cache
// where the raster's waits on memory, and fields are drained in parallel:
// at 1.6-2.0 times the raster (blob voids of the hydrology benchmark) the
// whole fill was faster (White Mountains 0.60 -> 0.51 s on two threads,
// 0.84 -> 0.67 s on one), at 2.9-3.2 times slower (Zion 0.19 -> 0.21 s).
// Not a function of the thread count: the two find slightly different
// inflows, and the output must not depend on it.
constexpr std::size_t kFieldDrainageLimit = 2;

// A void component and the part of the raster it is solved in.
struct Domain {
  Box box;                    // the component's bounding box
  Box rect;                   // grown by the margin, inside the raster
  std::vector<VoidRun> runs;  // the component's cells
};

using DomainResult = VoidFieldResult;

// The void components to solve: those with a cell that is not `left`.
std::vector<Domain> find_domains(const Whole& r, const LeftVoids& left) {
  ComponentFinder finder(r.w, std::max(r.w, r.h), std::size_t{1} << 40);
  for (int y = 0; y < r.h; ++y) finder.add_row(y, r.valid.data() + r.index(0, y));
  finder.finish();
  std::vector<Domain> out;
  for (SmallComponent& c : finder.small()) {
    if (!left.empty() && left.count(c.runs) == cell_count(c.runs)) continue;
    out.push_back(Domain{c.box, void_field_rect(c.box, r.w, r.h), std::move(c.runs)});
  }
  return out;
}

// Thrown by DeepGuide::get to a caller that can do other work meanwhile,
// while another thread builds the guide.
struct GuideBusy {};

// The coarse guide, built by the first field that has a cell farther than the
// guide radius from data (none in most rasters: the 3 %-kept benchmark's
// longest void runs exceed twice the radius, its distances never do). Its
// stride is the tiles' one, at least kMinGuideStride. The guide depends on the
// raster only: whichever field builds it, the pins are the same.
class DeepGuide {
 public:
  DeepGuide(const Whole& r, const FillParams& params, int threads)
      : r_(r), params_(params), threads_(threads), stride_(std::max(kMinGuideStride, guide_stride(r.w, r.h))) {}
  double radius() const { return field_pin_radius(stride_); }
  int stride_if_built() const { return guide_.ready() ? stride_ : 0; }
  bool busy() const { return state_.load() == State::building; }
  // With `may_defer`, throws GuideBusy instead of waiting for another
  // thread's build.
  const CoarseGuide* get(bool may_defer) {
    if (may_defer && busy()) throw GuideBusy{};
    std::call_once(built_, [this] {
      state_ = State::building;
      guide_ = CoarseGuide(r_.w, r_.h, stride_);
      guide_.add_rows(0, r_.h, r_.z.data(), r_.valid.data());
      guide_.solve(params_, {}, threads_);
      state_ = State::ready;
    });
    return &guide_;
  }

 private:
  enum class State { none, building, ready };
  const Whole& r_;
  const FillParams& params_;
  int threads_;
  int stride_;
  std::once_flag built_;
  std::atomic<State> state_{State::none};
  CoarseGuide guide_;
};

// Solve one domain as a field (void_field.hpp). Deep inside large voids the
// surface is the coarse guide's, as in tiles (docs/tiling.md): without it, the
// fill of a large void depended on how much terrain its field held (the
// cascade's coarse levels), with it on the void's own surroundings.
DomainResult solve_domain(const Whole& r, const Domain& d, DeepGuide& dg, bool may_defer, const FillParams& params,
                          double max_distance, const ProgressFn& progress, int threads) {
  std::vector<double> z;
  std::vector<std::uint8_t> valid;
  z.reserve(static_cast<std::size_t>(d.rect.width()) * d.rect.height());
  valid.reserve(z.capacity());
  for (int y = d.rect.y0; y <= d.rect.y1; ++y) {
    const std::size_t from = r.index(d.rect.x0, y), to = from + d.rect.width();
    z.insert(z.end(), r.z.begin() + from, r.z.begin() + to);
    valid.insert(valid.end(), r.valid.begin() + from, r.valid.begin() + to);
  }
  const DeepPins pins{[&dg, may_defer] { return dg.get(may_defer); }, dg.radius()};
  const RasterMorphology morphology{r.inflow.empty() ? nullptr : r.inflow.data(), r.w,
                                    r.lines.empty() ? nullptr : &r.lines};
  return solve_void_field(d.rect, d.runs, std::move(z), valid.data(), pins, params, max_distance, progress, threads,
                          morphology);
}

// Hands out the domains, largest first, so that the last ones to finish are
// small. A domain set aside because another thread was building the guide it
// needs (GuideBusy: waiting left a core idle for the guide's ~20 ms on a
// 1201² raster) comes back once the guide is ready, or when nothing else is
// left (its solve then waits). Results do not depend on the order.
class DomainQueue {
 public:
  DomainQueue(const std::vector<Domain>& domains, const DeepGuide& dg) : dg_(dg), order_(domains.size()) {
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
    const auto area = [&](std::size_t k) {
      return static_cast<long long>(domains[k].rect.width()) * domains[k].rect.height();
    };
    std::stable_sort(order_.begin(), order_.end(), [&](std::size_t a, std::size_t b) { return area(a) > area(b); });
  }
  // The next domain, and whether its solve may throw GuideBusy; false when
  // none is left.
  bool next(std::size_t& domain, bool& may_defer) {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (!deferred_.empty() && (!dg_.busy() || next_ == order_.size())) {
      domain = deferred_.front();
      deferred_.pop_front();
      may_defer = false;
      return true;
    }
    if (next_ == order_.size()) return false;
    domain = order_[next_++];
    may_defer = true;
    return true;
  }
  void defer(std::size_t domain) {
    const std::lock_guard<std::mutex> lock(mutex_);
    deferred_.push_back(domain);
  }

 private:
  const DeepGuide& dg_;
  std::vector<std::size_t> order_;
  std::size_t next_ = 0;
  std::deque<std::size_t> deferred_;
  std::mutex mutex_;
};

// Solves every domain, on `threads` threads (the calling one included, which
// alone reports progress). Each result depends on its domain only; one that
// reaches far (reaches_far) has no values: the tiles fill it.
std::vector<DomainResult> solve_domains(const Whole& r, const std::vector<Domain>& domains, DeepGuide& dg,
                                        const FillParams& params, double max_distance, int threads,
                                        const ProgressFn& progress) {
  std::vector<DomainResult> results(domains.size());
  std::vector<std::exception_ptr> errors(domains.size());
  DomainQueue queue(domains, dg);
  std::atomic<std::size_t> done{0};
  std::atomic<bool> cancel{false};
  const ProgressFn worker_progress = [&cancel](double) { return !cancel.load(std::memory_order_relaxed); };
  const auto work = [&](bool main) {
    std::size_t i = 0;
    for (bool may_defer = false; queue.next(i, may_defer);) {
      try {
        // A lone domain is solved on the calling thread with the real progress
        // and every thread inside its solver.
        const bool lone = domains.size() == 1;
        const ProgressFn& p = main && lone ? progress : worker_progress;
        results[i] =
            solve_domain(r, domains[i], dg, may_defer, params, max_distance, p, lone ? threads : 1);
      } catch (const GuideBusy&) {
        queue.defer(i);
        continue;
      } catch (...) {
        errors[i] = std::current_exception();
        cancel = true;
      }
      ++done;
      if (main && !cancel) {
        try {
          report(progress, static_cast<double>(done) / domains.size());
        } catch (...) {
          cancel = true;
          throw;
        }
      }
    }
  };
  std::vector<std::thread> pool;
  const int extra = static_cast<int>(std::min<std::size_t>(domains.size(), threads)) - 1;
  for (int t = 0; t < extra; ++t) pool.emplace_back(work, false);
  std::exception_ptr mine;
  try {
    work(true);
  } catch (...) {
    mine = std::current_exception();
  }
  for (std::thread& t : pool) t.join();
  if (mine) std::rethrow_exception(mine);
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  return results;
}

// The raster as read, for the line cells and the tiles: read from memory,
// written through to the caller's raster.
RasterAccess in_memory(const Whole& r, const RasterAccess& raster) {
  RasterAccess a;
  a.width = r.w;
  a.height = r.h;
  a.read = [&r](int x0, int y0, int w, int h, double* z, std::uint8_t* valid) {
    for (int y = 0; y < h; ++y) {
      const std::size_t from = r.index(x0, y0 + y), to = static_cast<std::size_t>(y) * w;
      std::copy_n(r.z.begin() + from, w, z + to);
      std::copy_n(r.valid.begin() + from, w, valid + to);
    }
  };
  a.write = raster.write;
  a.lines = raster.lines;
  return a;
}

// in_memory, writing only the cells flagged in `only`.
RasterAccess in_memory_far(const Whole& r, const RasterAccess& raster, const std::vector<std::uint8_t>& only) {
  RasterAccess a = in_memory(r, raster);
  a.write = [&r, &raster, &only](int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask) {
    std::vector<std::uint8_t> m(mask, mask + static_cast<std::size_t>(w) * h);
    bool any = false;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        std::uint8_t& c = m[static_cast<std::size_t>(y) * w + x];
        c = c && only[r.index(x0 + x, y0 + y)];
        any = any || c;
      }
    if (any) raster.write(x0, y0, w, h, z, m.data());
  };
  return a;
}

// The filled cells into z, the write mask into mask (the domains that reach
// far have none: they are the tiles'); returns the cells to write.
std::size_t gather(const Whole& r, const std::vector<Domain>& domains, const std::vector<DomainResult>& results,
                   std::vector<double>& z, std::vector<std::uint8_t>& mask) {
  std::size_t written = 0;
  mask.assign(r.valid.size(), 0);
  for (std::size_t k = 0; k < domains.size(); ++k) {
    if (results[k].values.empty()) continue;
    std::size_t n = 0;
    for (const VoidRun& run : domains[k].runs)
      for (int x = run.x0; x < run.x1; ++x, ++n) {
        const std::size_t i = r.index(x, run.y);
        z[i] = results[k].values[n];
        mask[i] = results[k].write[n];
        written += mask[i];
      }
  }
  return written;
}

}  // namespace

void fill_whole_raster(const RasterAccess& raster, const FillParams& params, const TilingParams& tiling,
                       const ProgressFn& progress, const RasterFillHooks& hooks, const LeftVoids& left) {
  Whole r;
  r.w = raster.width;
  r.h = raster.height;
  const std::size_t cells = static_cast<std::size_t>(r.w) * r.h;
  r.z.resize(cells);
  r.valid.resize(cells);
  report(progress, 0.0);
  raster.read(0, 0, r.w, r.h, r.z.data(), r.valid.data());

  // Counts, and the known elevation range: one noise unit for every field,
  // as for every window of a tiled fill.
  RasterFillStats st;
  double lo = 0.0, hi = 0.0;
  for (std::size_t i = 0; i < cells; ++i) {
    if (!r.valid[i]) {
      ++st.void_cells;
      continue;
    }
    lo = st.known_cells ? std::min(lo, r.z[i]) : r.z[i];
    hi = st.known_cells ? std::max(hi, r.z[i]) : r.z[i];
    ++st.known_cells;
  }
  if (hooks.stats) *hooks.stats = st;
  if (st.void_cells == 0) {
    report(progress, 1.0);
    return;
  }
  if (st.known_cells == 0) throw std::invalid_argument("the raster has no known cell to fill from");
  check_range(lo, hi);

  FillParams p = params;
  if (p.noise_unit <= 0) p.noise_unit = hi - lo;
  if (!raster.lines.empty()) r.lines = morph::line_cells(in_memory(r, raster));
  const std::vector<Domain> domains = find_domains(r, left);
  if (p.morph.channels) {
    if (p.morph.min_inflow <= 0) p.morph.min_inflow = default_channel_cells(st.known_cells);
    // The drainage into the voids, in each field, unless the fields together
    // hold more than kFieldDrainageLimit times the raster's cells (many voids,
    // overlapping fields): then once for the whole raster.
    std::size_t field_cells = 0;
    for (const Domain& d : domains) field_cells += static_cast<std::size_t>(d.rect.width()) * d.rect.height();
    if (field_cells > kFieldDrainageLimit * cells)
      r.inflow = morph::inflow_into_voids(r.z.data(), r.valid.data(), r.w, r.h);
  }
  const int threads = effective_threads(tiling.threads);
  DeepGuide dg(r, p, threads);
  report(progress, 0.05);
  const std::vector<DomainResult> results =
      solve_domains(r, domains, dg, p, tiling.max_distance, threads, sub_progress(progress, 0.05, 0.95));
  st.guide_stride = dg.stride_if_built();
  std::vector<double> z = r.z;
  std::vector<std::uint8_t> mask;
  st.cells_written = gather(r, domains, results, z, mask);
  std::vector<std::uint8_t> far(cells, 0);  // the cells of the voids that reach far
  bool any_far = false;
  for (std::size_t k = 0; k < domains.size(); ++k) {
    if (!results[k].values.empty()) continue;
    any_far = true;
    for (const VoidRun& run : domains[k].runs) std::fill_n(far.begin() + r.index(run.x0, run.y), run.x1 - run.x0, 1);
  }
  report(progress, any_far ? 0.5 : 0.95);  // a refusal here leaves the raster untouched
  raster.write(0, 0, r.w, r.h, z.data(), mask.data());
  if (any_far) {
    // A void reaching far from data needs the guide's tension at a coarse
    // scale and its surface deep inside (one field under tension, solved to
    // the usual tolerance, still carried a coast's slope 2 km up): the tiles
    // fill it, from the raster as read; the other voids keep their fields' fill.
    RasterFillStats tiled;
    RasterFillHooks sub = hooks;
    sub.stats = &tiled;
    FillParams plain = params;
    plain.morph.channels = false;  // the tiles fill without channels
    if (hooks.stats) *hooks.stats = st;  // what is written so far, should the tiles stop
    try {
      tiled_fill(in_memory_far(r, raster, far), plain, tiling, sub_progress(progress, 0.5, 1.0), sub, left);
    } catch (...) {
      if (hooks.stats) hooks.stats->cells_written += tiled.cells_written;
      throw;
    }
    st.cells_written += tiled.cells_written;
    st.tile_side = tiled.tile_side, st.tiles_x = tiled.tiles_x, st.tiles_y = tiled.tiles_y;
    st.windows_solved = tiled.windows_solved, st.small_components = tiled.small_components;
    st.guide_stride = tiled.guide_stride;
    st.channels_skipped = params.morph.channels;  // the far voids get none
  }
  if (hooks.stats) *hooks.stats = st;
  report(progress, 1.0);
}

}  // namespace mcmd::detail
