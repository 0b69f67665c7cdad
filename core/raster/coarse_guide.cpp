#include "raster/coarse_guide.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <stdexcept>
#include <thread>

#include "common/distance.hpp"
#include "common/padding.hpp"
#include "method/fill_grid.hpp"
#include "thin_plate/lattice.hpp"
#include "thin_plate/thin_plate.hpp"

namespace mcmd {

int guide_stride(int width, int height, int max_side) {
  const long long longest = std::max(width, height);
  int s = 1;
  while ((longest - 1 + s - 1) / s + 1 > max_side) s *= 2;
  return s;
}

CoarseGuide::CoarseGuide(int width, int height, int stride)
    : width_(width), height_(height), stride_(stride) {
  if (width < 1 || height < 1) throw std::invalid_argument("raster size must be >= 1");
  if (stride < 1 || (stride & (stride - 1)) != 0) throw std::invalid_argument("guide stride must be a power of two");
  // The last lattice point lies on or past the last raster cell, so that
  // interpolation inside the raster never needs the mirrored lattice.
  cw_ = (width - 1 + stride - 1) / stride + 1;
  ch_ = (height - 1 + stride - 1) / stride + 1;
  open_.resize(static_cast<std::size_t>(ch_));
  rows_left_.resize(static_cast<std::size_t>(ch_));
  for (int j = 0; j < ch_; ++j)  // the raster rows of lattice row j's blocks
    rows_left_[j] = std::min(height, j * stride - stride / 2 + stride) - std::max(0, j * stride - stride / 2);
  mean_.assign(static_cast<std::size_t>(cw_) * ch_, 0.0);
  known_.assign(mean_.size(), 0);
}

namespace {

// Adds raster row y's known cells to the blocks of lattice points [i0, i1) of
// lattice row j: `mrow` holds those points' moments, zr/vr the row's cells
// from raster column xoff on. Block by block, the block's sums held in
// locals: the same additions in the same order as cell by cell into memory,
// without a store and reload between the cells of a block (a 1201² raster:
// 9 → 4 ms). Offsets are integers, so the count and the coordinate moments
// are summed exactly as integers (in any order: the same doubles); only the
// elevation sums are floating point, in raster order.
void add_row_to_blocks(CoarseGuide::Moments* mrow, int i0, int i1, int stride, int width, int y, int j,
                       const double* zr, const std::uint8_t* vr, int xoff) {
  const int half = stride / 2;
  const double dy = static_cast<double>(y) - static_cast<double>(j) * stride;
  const long long iy = y - static_cast<long long>(j) * stride;
  for (int i = i0; i < i1; ++i) {
    const int xa = std::max(0, i * stride - half), xb = std::min(width, i * stride - half + stride);
    if (xa >= xb) break;
    CoarseGuide::Moments m = mrow[i - i0];
    long long n = 0, sx = 0, sxx = 0;
    for (int x = xa; x < xb; ++x) {
      if (!vr[x - xoff]) continue;
      const long long ix = x - static_cast<long long>(i) * stride;
      const double dx = static_cast<double>(ix), zv = zr[x - xoff];
      n += 1;
      sx += ix;
      sxx += ix * ix;
      m.z += zv;
      m.zx += zv * dx;
      m.zy += zv * dy;
    }
    m.n += static_cast<double>(n);
    m.x += static_cast<double>(sx);
    m.y += static_cast<double>(n * iy);
    m.xx += static_cast<double>(sxx);
    m.yy += static_cast<double>(n * iy * iy);
    m.xy += static_cast<double>(sx * iy);
    mrow[i - i0] = m;
  }
}

// Lattice index of the block holding raster coordinate v: floor((v + S/2) / S).
int lattice_of(int v, int stride) { return (v + stride / 2) / stride; }

}  // namespace

void CoarseGuide::add_rows(int y0, int rows, const double* z, const std::uint8_t* valid) {
  for (int r = 0; r < rows; ++r) {
    const int j = lattice_of(y0 + r, stride_);
    if (j >= ch_) continue;  // past the last lattice row's block
    std::vector<Moments>& sums = open_[j];
    if (sums.empty()) sums.assign(static_cast<std::size_t>(cw_), Moments{});
    add_row_to_blocks(sums.data(), 0, cw_, stride_, width_, y0 + r, j, z + static_cast<std::size_t>(r) * width_,
                      valid + static_cast<std::size_t>(r) * width_, 0);
    if (--rows_left_[j] == 0) close_row(j);
  }
}

Range CoarseGuide::lattice_points(int length, int stride, int begin, int end) {
  const int count = (length - 1 + stride - 1) / stride + 1;
  // The last point may lie past the raster's last cell: the part that ends the axis holds it.
  const int last = end >= length ? count : std::min(count, (end + stride - 1) / stride);
  return Range{std::min(count, (begin + stride - 1) / stride), last};
}

std::vector<CoarseGuide::Moments> CoarseGuide::part_moments(int width, int height, int stride, Range is, Range js,
                                                            const CellBlock& cells) {
  std::vector<Moments> part(static_cast<std::size_t>(is.size()) * js.size());
  if (part.empty()) return part;
  const int half = stride / 2;
  const int ya = std::max(0, js.begin * stride - half), yb = std::min(height, (js.end - 1) * stride - half + stride);
  const int xa = std::max(0, is.begin * stride - half), xb = std::min(width, (is.end - 1) * stride - half + stride);
  if (xa < cells.x0 || ya < cells.y0 || xb > cells.x0 + cells.w || yb > cells.y0 + cells.h)
    throw std::invalid_argument("part_moments: the cells do not hold the lattice points' blocks");
  for (int y = ya; y < yb; ++y) {
    const int j = lattice_of(y, stride);
    const std::size_t row = static_cast<std::size_t>(y - cells.y0) * cells.w;
    add_row_to_blocks(part.data() + static_cast<std::size_t>(j - js.begin) * is.size(), is.begin, is.end, stride,
                      width, y, j, cells.z + row, cells.valid + row, cells.x0);
  }
  return part;
}

void CoarseGuide::set_moments(Range is, Range js, const std::vector<Moments>& part) {
  if (is.begin < 0 || js.begin < 0 || is.end > cw_ || js.end > ch_ ||
      part.size() != static_cast<std::size_t>(is.size()) * js.size())
    throw std::invalid_argument("set_moments: the part does not fit the lattice");
  for (int j = js.begin; j < js.end; ++j)
    for (int i = is.begin; i < is.end; ++i)
      set_point(static_cast<std::size_t>(j) * cw_ + i,
                part[static_cast<std::size_t>(j - js.begin) * is.size() + (i - is.begin)]);
}

namespace {
// The block's plane fit evaluated at the lattice point (offset 0, 0).
double plane_at_lattice(double n, double z, double x, double y, double xx, double yy, double xy, double zx,
                        double zy, int stride) {
  const double mz = z / n, mx = x / n, my = y / n;
  // Centred second moments, regularised so that few or collinear cells give
  // a mean-like value instead of a wild extrapolation.
  const double reg = 0.02 * (static_cast<double>(stride) * stride) / 12.0 + 1e-9;
  const double cxx = xx / n - mx * mx + reg, cyy = yy / n - my * my + reg, cxy = xy / n - mx * my;
  const double czx = zx / n - mz * mx, czy = zy / n - mz * my;
  const double det = cxx * cyy - cxy * cxy;
  const double gx = (cyy * czx - cxy * czy) / det;
  const double gy = (cxx * czy - cxy * czx) / det;
  return mz - gx * mx - gy * my;
}
}  // namespace

void CoarseGuide::set_point(std::size_t i, const Moments& m) {
  if (m.n == 0) return;
  mean_[i] = m.n == 1 ? m.z : plane_at_lattice(m.n, m.z, m.x, m.y, m.xx, m.yy, m.xy, m.zx, m.zy, stride_);
  known_[i] = 1;
}

void CoarseGuide::close_row(int j) {
  std::vector<Moments>& sums = open_[static_cast<std::size_t>(j)];
  if (sums.empty()) return;  // closed already, or no raster row came
  for (int i = 0; i < cw_; ++i) set_point(static_cast<std::size_t>(j) * cw_ + i, sums[i]);
  std::vector<Moments>().swap(sums);
}

// A pure thin plate extends the slopes at a void's edge linearly: fine across
// a blob, but across a void hundreds or thousands of cells wide it builds
// mountains and trenches out of the slopes at its rim. Far from data the
// guide becomes a thin plate under tension, whose membrane term lets slopes
// level off over kSlopeReach cells instead, weighted in per void with how
// far that void reaches: ordinary voids keep the plain thin plate, and a
// huge void does not put its neighbours under tension.
constexpr double kSlopeReach = 8.0;         // raster cells
constexpr double kFarVoidCells = 128.0;     // beyond: the guide's surface deep inside, tiles
constexpr double kTensionFrom = 32.0;       // farthest void cell from data: no tension below
constexpr double kTensionFull = 96.0;       // full tension above (docs/tiling.md: the ramp)
// The tensioned surface costs more than the plain one (a padded lattice) and,
// on a small raster, the time its largest field waits for the guide: a void
// that would take less than 1 % of it (farthest cell within ~4 cells of
// kTensionFrom) keeps the plain surface.
constexpr double kMinTensionWeight = 0.01;

double far_void_weight(double farthest) {
  const double ramp = std::clamp((farthest - kTensionFrom) / (kTensionFull - kTensionFrom), 0.0, 1.0);
  const double weight = ramp * ramp * (3.0 - 2.0 * ramp);
  return weight < kMinTensionWeight ? 0.0 : weight;
}

bool reaches_far(double farthest) { return farthest > kFarVoidCells; }

namespace {
// The full tension (ThinPlateSchedule::tension) on a lattice of `stride` cells.
double full_tension(int stride) {
  const double reach = kSlopeReach / stride;  // in lattice cells
  return 1.0 / (reach * reach);
}
}  // namespace

CoarseGuide::FarVoids CoarseGuide::far_voids() const {
  const std::vector<double> dist = distance_to_valid(known_.data(), cw_, ch_);
  FarVoids far;
  far.weight.assign(known_.size(), 0.0);
  far.label.assign(known_.size(), -1);
  std::vector<std::uint8_t> seen(known_);
  std::vector<std::size_t> component, stack;
  for (std::size_t start = 0; start < seen.size(); ++start) {
    if (seen[start]) continue;
    // The unknown points 8-connected to `start`, the farthest of them from
    // data, and their box.
    component.clear();
    stack.assign(1, start);
    seen[start] = 1;
    double farthest = 0.0;
    LatticeBox box{cw_, ch_, 0, 0};
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      component.push_back(i);
      farthest = std::max(farthest, dist[i] * stride_);
      const int x = static_cast<int>(i % cw_), y = static_cast<int>(i / cw_);
      box = LatticeBox{std::min(box.x0, x), std::min(box.y0, y), std::max(box.x1, x + 1), std::max(box.y1, y + 1)};
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= cw_ || ny >= ch_) continue;
          const std::size_t n = static_cast<std::size_t>(ny) * cw_ + nx;
          if (!seen[n]) {
            seen[n] = 1;
            stack.push_back(n);
          }
        }
    }
    const double w = far_void_weight(farthest);
    if (w == 0) continue;
    for (std::size_t i : component) {
      far.weight[i] = w;
      far.label[i] = static_cast<int>(far.boxes.size());
    }
    far.boxes.push_back(box);
  }
  return far;
}

std::vector<double> CoarseGuide::filled(const std::vector<double>& start, const FillParams& params,
                                        const ProgressFn& progress, int threads) const {
  std::vector<double> out = start;
  if (params.method == Method::mcmd) {
    // The lattice as it is, no 2^m+1 padding (a 676×301 lattice padded to
    // 1025² was 5× the work; a 301² one to 513², with -rs auto, half the
    // guide's time).
    std::vector<CellState> state(out.size());
    for (std::size_t i = 0; i < state.size(); ++i) state[i] = known_[i] ? CellState::known : CellState::unknown;
    ThinPlateSchedule schedule;
    schedule.vcycle.threads = threads;
    thin_plate_with_roughness(FieldView{cw_, ch_, out.data(), state.data()}, 0, 0, params, schedule, progress);
    return out;
  }
  Grid g = mirror_padded_grid(start.data(), known_.data(), cw_, ch_, levels_to_cover(cw_, ch_));
  fill_grid(g, params, progress);
  for (int j = 0; j < ch_; ++j)
    for (int i = 0; i < cw_; ++i) out[static_cast<std::size_t>(j) * cw_ + i] = g.z(i, j);
  return out;
}

namespace {
// How far around a far void its tensioned solve reaches: the tensioned
// operator's response decays over kSlopeReach raster cells, so what lies 8
// reaches away moves the void's values by less than e^-8 of itself (at
// least 16 points).
int tense_margin(int stride) { return std::max(16, static_cast<int>(std::ceil(8.0 * kSlopeReach / stride))); }
}  // namespace

std::vector<double> CoarseGuide::tense_filled(const std::vector<double>& mean, const FarVoids& far, double tension,
                                              const FillParams& params, const ProgressFn& progress,
                                              int threads) const {
  // The tensioned surface is that of the lattice mirror-padded to a 2^m+1
  // square (free at the left and top edges, mirrored at the right and
  // bottom: across a void reaching the raster's edge the mirror, a level
  // surface there, is what stops a coast's slope; a free edge under tension
  // left it 2.2 km too high in HugeVoidDoesNotExtrapolateCoastSlopesIntoMountains).
  // Tension levels a surface off towards the plane it is solved around:
  // that square's least-squares plane, whose mirrored half tilts it back
  // towards level. Each far void is then solved in a square of that padded
  // lattice around its box and margin, around that plane: the same surface
  // near the void, without solving the whole square (the 4801² blob
  // mosaic's 601² lattice padded to 1025² faulted 120 MB in for a few blobs).
  const Plane plane = [&] {  // the padded lattice freed before the solves (the half-void tile: 10 MB of peak)
    const Grid whole = mirror_padded_grid(mean.data(), known_.data(), cw_, ch_, levels_to_cover(cw_, ch_));
    return constraint_plane(
        FieldView{whole.side(), whole.side(), const_cast<double*>(whole.elevations().data()), whole.states().data()});
  }();
  ThinPlateSchedule schedule;
  schedule.tension = tension;
  schedule.vcycle.threads = threads;
  std::vector<double> out = mean;
  const int margin = tense_margin(stride_);
  for (std::size_t k = 0; k < far.boxes.size(); ++k) {
    const LatticeBox& v = far.boxes[k];
    const int x0 = std::max(0, v.x0 - margin), y0 = std::max(0, v.y0 - margin);
    Grid g = mirror_padded_grid(mean.data(), known_.data(), cw_, ch_,
                                levels_to_cover(std::min(cw_, v.x1 + margin) - x0, std::min(ch_, v.y1 + margin) - y0),
                                x0, y0);
    for (int j = 0; j < g.side(); ++j)
      for (int i = 0; i < g.side(); ++i)
        if (g.state(i, j) == CellState::known) g.z(i, j) -= plane.at(x0 + i, y0 + j);
    FieldView field{g.side(), g.side(), g.elevations().data(), g.states().data()};
    field.own_plane = false;
    const double n = static_cast<double>(far.boxes.size());
    thin_plate_with_roughness(field, x0, y0, params, schedule, sub_progress(progress, k / n, (k + 1) / n));
    for (int j = v.y0; j < v.y1; ++j)
      for (int i = v.x0; i < v.x1; ++i) {
        const std::size_t at = static_cast<std::size_t>(j) * cw_ + i;
        if (far.label[at] == static_cast<int>(k)) out[at] = g.z(i - x0, j - y0) + plane.at(i, j);
      }
  }
  return out;
}

std::vector<double> CoarseGuide::plain_and_tense(const std::vector<double>& mean, const FarVoids& far,
                                                 std::size_t unknown, const FillParams& params,
                                                 const ProgressFn& progress, int threads) {
  const double tension = full_tension(stride_);
  // A large lattice (banded: its solver uses every thread) is solved once
  // then again: solved side by side, the two large solves' buffers set the
  // peak memory of a raster that is half void (3601²: 335 MB against
  // 260 MB, for 0.07 s more). Small ones side by side, each on one thread.
  if (threads <= 1 || unknown >= kBandedMinFree) {
    value_ = filled(mean, params, sub_progress(progress, 0.0, 0.3), threads);
    return tense_filled(mean, far, tension, params, sub_progress(progress, 0.3, 1.0), threads);
  }
  // The tensioned solves (padded lattices) on a helper thread,
  // which stops when this one is cancelled; progress is this thread's.
  std::atomic<bool> stop{false};
  std::vector<double> tense;
  std::exception_ptr failed;
  std::thread helper([&] {
    try {
      tense = tense_filled(mean, far, tension, params,
                           [&stop](double) { return !stop.load(std::memory_order_relaxed); }, 1);
    } catch (...) {
      failed = std::current_exception();
    }
  });
  try {
    value_ = filled(mean, params, sub_progress(progress, 0.0, 0.9), 1);
  } catch (...) {
    stop = true;
    helper.join();
    throw;
  }
  helper.join();
  if (failed) std::rethrow_exception(failed);
  report(progress, 1.0);
  return tense;
}

bool CoarseGuide::solve(const FillParams& params, const ProgressFn& progress, int threads) {
  for (int j = 0; j < ch_; ++j) close_row(j);  // rows of blocks that did not get all their raster rows
  const std::vector<double> mean = std::move(mean_);
  mean_ = {};
  const std::size_t known_count = static_cast<std::size_t>(std::count(known_.begin(), known_.end(), 1));
  if (known_count == 0) return false;
  value_ = mean;
  if (known_count < value_.size()) {
    const FarVoids far = params.method == Method::mcmd ? far_voids() : FarVoids{};
    if (far.boxes.empty()) {
      value_ = filled(mean, params, progress, threads);
    } else {
      // Each void's blend of the two surfaces: one weight per void, so the
      // fill stays as smooth as either inside it, and both agree with the
      // known points around it.
      const std::vector<double> tense =
          plain_and_tense(mean, far, value_.size() - known_count, params, progress, threads);
      for (std::size_t i = 0; i < value_.size(); ++i) value_[i] += far.weight[i] * (tense[i] - value_[i]);
    }
  }
  ready_ = true;
  return true;
}

namespace {
// Catmull-Rom weights for the 4 lattice points around fraction f in [0, 1).
void catmull_rom(double f, double w[4]) {
  const double f2 = f * f, f3 = f2 * f;
  w[0] = 0.5 * (-f3 + 2.0 * f2 - f);
  w[1] = 0.5 * (3.0 * f3 - 5.0 * f2 + 2.0);
  w[2] = 0.5 * (-3.0 * f3 + 4.0 * f2 + f);
  w[3] = 0.5 * (f3 - f2);
}
}  // namespace

double CoarseGuide::at(long long x, long long y) const {
  const long long rx = reflect_index(x, width_);
  const long long ry = reflect_index(y, height_);
  const long long ix = rx / stride_, iy = ry / stride_;
  const double fx = static_cast<double>(rx - ix * stride_) / stride_;
  const double fy = static_cast<double>(ry - iy * stride_) / stride_;
  if (fx == 0.0 && fy == 0.0) return value_[static_cast<std::size_t>(iy) * cw_ + ix];
  double wx[4], wy[4];
  catmull_rom(fx, wx);
  catmull_rom(fy, wy);
  double total = 0.0;
  for (int b = 0; b < 4; ++b) {
    const std::size_t row = static_cast<std::size_t>(reflect_index(iy - 1 + b, ch_)) * cw_;
    double acc = 0.0;
    for (int a = 0; a < 4; ++a) acc += wx[a] * value_[row + reflect_index(ix - 1 + a, cw_)];
    total += wy[b] * acc;
  }
  return total;
}

void CoarseGuide::prepare_distance() {
  if (distance_.empty()) distance_ = distance_to_valid(known_.data(), cw_, ch_);
}

double CoarseGuide::coarse_distance(long long x, long long y) const {
  const long long rx = reflect_index(x, width_), ry = reflect_index(y, height_);
  const long long i = std::min<long long>((rx + stride_ / 2) / stride_, cw_ - 1);
  const long long j = std::min<long long>((ry + stride_ / 2) / stride_, ch_ - 1);
  return stride_ * distance_[static_cast<std::size_t>(j) * cw_ + i];
}

}  // namespace mcmd
