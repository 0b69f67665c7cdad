#include "roughness/roughness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "common/distance.hpp"
#include "roughness/noise.hpp"

namespace mcmd {

namespace {

constexpr int kOctaves = 6;         // spacings 1 .. 32 cells
constexpr double kStrength = 0.85;  // global calibration: of the terrain's curvature amplitude
                                    // (measured Laplacian spread in voids ≈ 1, the smooth fill adds some)
constexpr double kGolden = 2.399963229728653;  // golden angle, radians
// Second-difference variance of the benchmark DEMs (dense data) ÷ the fBm form
// γ(1)(8 - 2·4^H) with their own γ(1), H: 0.30-0.60, median 0.34.
constexpr double kFbmToTerrain = 0.34;
// Laplacian variance ÷ twice the second-difference variance on the benchmark
// DEMs (dense data): 1.37-1.47, median 1.39 (dxx and dyy correlate).
constexpr double kLapPerCurvature = 1.39;
// Lag-1 pairs from which 8γ(1) - 2γ(2) is trusted fully (from a tenth of it, partly).
constexpr double kDensePairs = 40000;

double smoothstep(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Blocks of kBlock² cells aligned to global raster coordinates, so every
// window of a tiled fill cuts the same blocks: the unit of local statistics
// and of where noise is generated at all.
constexpr int kBlock = 32;

// Cells [x0, x1) × [y0, y1) of a field (empty: x1 <= x0 or y1 <= y0).
struct Rect {
  int x0, x1, y0, y1;
  bool empty() const { return x1 <= x0 || y1 <= y0; }
};

struct Blocks {
  int nx = 0, ny = 0;    // blocks per row, per column
  int ox = 0, oy = 0;    // local x + ox = position in the block lattice (cells); likewise y
  std::vector<Rect> noise_box;  // per block, the box of its noise cells: noise is generated where not empty
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
  bool active(int i, int j) const { return !noise_box[index(i, j)].empty(); }
  bool inside(int i, int j) const { return i >= 0 && j >= 0 && i < nx && j < ny; }
  // Local cells [x0, x1) of block column i (rows likewise), clipped to the field.
  int x0(int i) const { return std::max(0, i * kBlock - ox); }
  int x1(int i, int w) const { return std::min(w, (i + 1) * kBlock - ox); }
  int y0(int j) const { return std::max(0, j * kBlock - oy); }
  int y1(int j, int h) const { return std::min(h, (j + 1) * kBlock - oy); }
};

int positive_mod(long long v, int m) { return static_cast<int>(((v % m) + m) % m); }

// The part of a field whose cells may carry noise: every per-cell array of
// the noise (targets, noise cells, values) covers it, not the whole field (a
// void's field is its void grown by a margin of up to 32 + its extent on each
// side). Field coordinates; row-major, w wide.
struct Area {
  int x0 = 0, y0 = 0, w = 0, h = 0;
  std::size_t cells() const { return static_cast<std::size_t>(w) * static_cast<std::size_t>(h); }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x - x0);
  }
};

// The cells whose noise a fill uses: its wanted unknown cells (targets) and the
// cells within kNoiseReach cells (Chebyshev) of one. The discrete thin plate at an
// unknown cell involves no constraint farther than 2 cells; the finest
// level's pull towards the cascade (length 8) sees farther, through the coarse
// levels, and a reach of 2 let the noise's coarse octaves through deep inside
// large voids (blob RMSE median 0.941 at 8, 0.955 at 2, 0.938 at 16 and with
// whole 32² blocks around the voids: docs/default-method.md).
constexpr int kNoiseReach = 8;
std::vector<std::uint8_t> noise_cells(const std::vector<std::uint8_t>& target, const Area& a) {
  return within_chebyshev(target.data(), a.w, a.h, kNoiseReach);
}

// Whether the cell is one the noise is made for: unknown and wanted.
bool is_target(const RoughField& g, std::size_t i) { return !is_constraint(g.state[i]) && (!g.wanted || g.wanted[i]); }

// The bounding box of the target cells (empty: x1 <= x0). With a wanted mask
// (a void's own cells: a small part of its field), the mask's rows are
// scanned 8 bytes at a time.
Rect target_bounds(const RoughField& g) {
  Rect b{g.w, 0, g.h, 0};
  for (int y = 0; y < g.h; ++y) {
    const std::size_t row = g.index(0, y);
    int x = 0;
    if (g.wanted)
      for (std::uint64_t word; x + 8 <= g.w; x += 8) {
        std::memcpy(&word, g.wanted + row + x, sizeof word);
        if (word) break;
      }
    while (x < g.w && !is_target(g, row + x)) ++x;
    if (x == g.w) continue;
    int last = g.w - 1;
    if (g.wanted)
      for (std::uint64_t word; last - 7 > x; last -= 8) {
        std::memcpy(&word, g.wanted + row + last - 7, sizeof word);
        if (word) break;
      }
    while (!is_target(g, row + last)) --last;
    b = Rect{std::min(b.x0, x), std::max(b.x1, last + 1), std::min(b.y0, y), y + 1};
  }
  return b;
}

// The target cells of an area, all inside rectangle `t` of it.
std::vector<std::uint8_t> target_mask(const RoughField& g, const Area& a, const Rect& t) {
  std::vector<std::uint8_t> mask(a.cells());
  for (int y = t.y0; y < t.y1; ++y)
    for (int x = t.x0; x < t.x1; ++x) mask[a.index(x, y)] = is_target(g, g.index(x, y));
  return mask;
}

// The block lattice of a field, no block active.
Blocks block_lattice(const RoughField& g) {
  Blocks b;
  b.ox = positive_mod(g.x0, kBlock);
  b.oy = positive_mod(g.y0, kBlock);
  b.nx = (g.w + kBlock - 1) / kBlock + 1;
  b.ny = (g.h + kBlock - 1) / kBlock + 1;
  b.noise_box.assign(static_cast<std::size_t>(b.nx) * b.ny, Rect{0, 0, 0, 0});
  return b;
}

// Four doubles as one value (a GCC vector extension: one AVX2 register in
// add_octave's AVX2 clone, two SSE2 ones in its baseline x86-64 clone, lowered
// to scalars elsewhere). The noise's splines are evaluated at four cells at
// once by the very operations of the one-cell form (templates below, T =
// double or Quad; no fused multiply-add in either clone): the same bits
// either way, on any x86-64 machine.
using Quad = double __attribute__((vector_size(32)));
using QuadBits = long long __attribute__((vector_size(32)));
using QuadIndex = int __attribute__((vector_size(16)));  // node offsets: small

// The hot loops' AVX2 clones, chosen at load time (GNU ifunc); elsewhere
// (other architectures, other compilers) the one portable version.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define MCMD_AVX2_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define MCMD_AVX2_CLONES
#endif

// std::floor for the node coordinates (|v| far below 2^51), without the call
// to libm that std::floor is on baseline x86-64: 2 per cell and octave.
[[gnu::always_inline]] inline double floor_of(double v) {
  const auto t = static_cast<double>(static_cast<long long>(v));  // towards zero
  return t > v ? t - 1.0 : t;
}
// The same floor in double arithmetic only (x86 converts four doubles to
// 64-bit integers one at a time before AVX-512): adding and taking away
// 2^52 rounds to the nearest integer, then 1 off where that is above v.
[[gnu::always_inline]] inline Quad floor_of(Quad v) {
  constexpr double k = 0x1p52;
  const Quad magic = v < 0.0 ? Quad{-k, -k, -k, -k} : Quad{k, k, k, k};
  const Quad t = (v + magic) - magic;
  const QuadBits one = (QuadBits)Quad{1.0, 1.0, 1.0, 1.0};
  return t - (Quad)((t > v) & one);
}

// Catmull-Rom weights of the 4 nodes around a point at fraction t.
template <class T>
[[gnu::always_inline]] inline void catmull_rom_weights(T t, T w[4]) {
  const T t2 = t * t, t3 = t2 * t;
  w[0] = 0.5 * (-t + 2.0 * t2 - t3);
  w[1] = 0.5 * (2.0 - 5.0 * t2 + 3.0 * t3);
  w[2] = 0.5 * (t + 4.0 * t2 - 3.0 * t3);
  w[3] = 0.5 * (t3 - t2);
}

// Σ_r wv[r] Σ_a wu[a] node(r, a): the spline from its 4×4 nodes.
template <class T, class Node>
[[gnu::always_inline]] inline T bicubic(const T wu[4], const T wv[4], const Node& node) {
  T sum{};
  for (int r = 0; r < 4; ++r)
    sum += wv[r] * (wu[0] * node(r, 0) + wu[1] * node(r, 1) + wu[2] * node(r, 2) + wu[3] * node(r, 3));
  return sum;
}

// Octaves of spacing 2^j >= 2^kSampledFrom are smooth at the scale of a
// cell: their splines are evaluated at the cells of even raster coordinates
// only, and the others interpolated between those with the 4-point cubic
// (-1, 9, 9, -1)/16, once along rows, then along columns (a quarter of the
// evaluations; the spline's detail at 8 cells is 4 samples wide).
constexpr int kSampledFrom = 3;

long long floor_half(long long v) { return v >= 0 ? v / 2 : -((1 - v) / 2); }  // floor(v / 2)

// The 4-point cubic midway between b and c (a, d: their outer neighbours).
double cubic_mid(double a, double b, double c, double d) { return (9.0 * (b + c) - (a + d)) / 16.0; }

// The cells an octave is added to: raster rectangle [gx0, gx1) × [gy0, gy1),
// row-major in `out` (`stride` apart), where `mask` is set.
struct OctaveCells {
  long long gx0, gx1, gy0, gy1;
  const std::uint8_t* mask;
  double* out;
  int stride;
  int width() const { return static_cast<int>(gx1 - gx0); }
  const std::uint8_t* mask_row(long long gy) const { return mask + (gy - gy0) * stride; }
  double* out_row(long long gy) const { return out + (gy - gy0) * stride; }
};

// Samples k0 .. k1 - 1 (at raster coordinates 2k) that the cubic needs for
// cells v0 .. v1 - 1: 3 cells beyond each end.
struct SampleRange {
  long long k0, k1;
};
SampleRange samples_for(long long v0, long long v1) { return {floor_half(v0 - 3), floor_half(v1 + 2) + 1}; }

// weight × the spline added at each masked cell, evaluated there;
// spline_row(x0, y, n, wanted, to) evaluates n points of row y from x0.
template <class SplineRow>
[[gnu::always_inline]] inline void add_evaluated(const OctaveCells& c, double weight, const SplineRow& spline_row,
                                                 std::vector<double>& scratch) {
  const int w = c.width();
  scratch.resize(static_cast<std::size_t>(w));
  for (long long gy = c.gy0; gy < c.gy1; ++gy) {
    const std::uint8_t* m = c.mask_row(gy);
    double* o = c.out_row(gy);
    spline_row(static_cast<double>(c.gx0), static_cast<double>(gy), w, m, scratch.data());
    for (int i = 0; i < w; ++i)
      if (m[i]) o[i] += weight * scratch[i];
  }
}

// weight × the spline added at each masked cell, interpolated from its
// samples at even raster coordinates: each row of samples (spline_row with
// a step of 2) at every cell of the rectangle's width, then the cells of
// each row from those rows.
template <class SplineRow>
[[gnu::always_inline]] inline void add_interpolated(const OctaveCells& c, double weight, const SplineRow& spline_row,
                                                    std::vector<double>& scratch) {
  const int w = c.width();
  const SampleRange sx = samples_for(c.gx0, c.gx1), sy = samples_for(c.gy0, c.gy1);
  const int nsx = static_cast<int>(sx.k1 - sx.k0), nsy = static_cast<int>(sy.k1 - sy.k0);
  scratch.resize(static_cast<std::size_t>(nsy) * (nsx + w));
  double* sample = scratch.data();
  double* across = sample + static_cast<std::size_t>(nsy) * nsx;  // nsy rows of w
  for (int r = 0; r < nsy; ++r) {
    double* srow = sample + static_cast<std::size_t>(r) * nsx;
    spline_row(2.0 * sx.k0, 2.0 * (sy.k0 + r), nsx, nullptr, srow);
    double* arow = across + static_cast<std::size_t>(r) * w;
    for (int i = 0; i < w; ++i) {
      const long long gx = c.gx0 + i;
      const long long k = floor_half(gx) - sx.k0;  // the sample at or left of gx
      arow[i] = (gx & 1) == 0 ? srow[k] : cubic_mid(srow[k - 1], srow[k], srow[k + 1], srow[k + 2]);
    }
  }
  for (long long gy = c.gy0; gy < c.gy1; ++gy) {
    const std::uint8_t* m = c.mask_row(gy);
    double* o = c.out_row(gy);
    const double* a1 = across + static_cast<std::size_t>(floor_half(gy) - sy.k0) * w;
    for (int i = 0; i < w; ++i) {
      if (!m[i]) continue;
      const double v = (gy & 1) == 0 ? a1[i] : cubic_mid(a1[i - w], a1[i], a1[i + w], a1[i + 2 * w]);
      o[i] += weight * v;
    }
  }
}

// One octave's noise, times `weight`, added to `cells`: white noise on a
// lattice of spacing 2^j rotated by j golden angles, interpolated with
// Catmull-Rom splines. The nodes are a function of global coordinates, so any
// window, field or block sees the same value at a cell (the sampled octaves'
// samples too: even raster coordinates). The AVX2 clone takes 4 cells per
// instruction where the baseline takes 2: the noise's time on White Mountains
// blobs fell by 16 % (the nodes' loads stay one by one). `node` and `scratch`
// are buffers reused by the caller.
MCMD_AVX2_CLONES
void add_octave(std::uint64_t seed, int j, double weight, const OctaveCells& cells, std::vector<double>& node,
                std::vector<double>& scratch) {
  const double s = std::ldexp(1.0, j);
  const double c = std::cos(j * kGolden) / s, sn = std::sin(j * kGolden) / s;
  const double ox = 0.618 * j, oy = 0.382 * j;
  // (u, v) of cells at x (one or a Quad), y.
  const auto uv = [&](auto x, double y, auto& u, auto& v) {
    u = c * x + sn * y + ox;
    v = -sn * x + c * y + oy;
  };
  const UniformHash hash(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(j + 1));
  if (j == 0) {  // unrotated, unit spacing: every cell is a node, the spline its value
    for (long long gy = cells.gy0; gy < cells.gy1; ++gy)
      for (long long gx = cells.gx0; gx < cells.gx1; ++gx)
        if (cells.mask_row(gy)[gx - cells.gx0])
          cells.out_row(gy)[gx - cells.gx0] += weight * (std::sqrt(3.0) * hash(gx, gy));
    return;
  }
  // The points where the spline is evaluated: the cells, or their samples.
  const bool sampled = j >= kSampledFrom;
  const int step = sampled ? 2 : 1;
  const SampleRange sx = sampled ? samples_for(cells.gx0, cells.gx1) : SampleRange{cells.gx0, cells.gx1};
  const SampleRange sy = sampled ? samples_for(cells.gy0, cells.gy1) : SampleRange{cells.gy0, cells.gy1};
  // Node box covering the corners in (u, v).
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300;
  for (long long cx : {sx.k0 * step, (sx.k1 - 1) * step})
    for (long long cy : {sy.k0 * step, (sy.k1 - 1) * step}) {
      double u, v;
      uv(static_cast<double>(cx), static_cast<double>(cy), u, v);
      umin = std::min(umin, u); umax = std::max(umax, u);
      vmin = std::min(vmin, v); vmax = std::max(vmax, v);
    }
  const long long i0 = static_cast<long long>(std::floor(umin)) - 1;
  const long long j0 = static_cast<long long>(std::floor(vmin)) - 1;
  const int nu = static_cast<int>(std::floor(umax) - i0) + 3, nv = static_cast<int>(std::floor(vmax) - j0) + 3;
  node.resize(static_cast<std::size_t>(nu) * nv);
  for (int b = 0; b < nv; ++b)
    for (int a = 0; a < nu; ++a) node[static_cast<std::size_t>(b) * nu + a] = std::sqrt(3.0) * hash(i0 + a, j0 + b);
  // A point's (u, v), the origin of its 4×4 nodes in `node`, and its weights.
  const auto locate = [&](auto x, double y, auto& first_node, auto wu, auto wv) {
    decltype(x) u, v;
    uv(x, y, u, v);
    const auto fu = floor_of(u), fv = floor_of(v);
    catmull_rom_weights(u - fu, wu);
    catmull_rom_weights(v - fv, wv);
    first_node = (fv - static_cast<double>(j0 + 1)) * nu + (fu - static_cast<double>(i0 + 1));  // exact: small integers
  };
  // The spline at points x0 + step·k, k < n, of row y, where `wanted` (null:
  // all), into `to` (k-th entry; others untouched).
  const auto spline_row = [&](double x0, double y, int n, const std::uint8_t* wanted, double* to)
                              __attribute__((always_inline)) {
    int k = 0;
    for (; k + 3 < n; k += 4) {  // four points at a time
      if (wanted) {
        std::uint32_t any;
        std::memcpy(&any, wanted + k, sizeof any);
        if (!any) continue;
      }
      Quad first, wu[4], wv[4];
      const double x = x0 + step * k;
      locate(Quad{x, x + step, x + 2 * step, x + 3 * step}, y, first, wu, wv);
      const QuadIndex at = __builtin_convertvector(first, QuadIndex);
      const double* p0 = node.data() + at[0];
      const double* p1 = node.data() + at[1];
      const double* p2 = node.data() + at[2];
      const double* p3 = node.data() + at[3];
      const Quad sum = bicubic(wu, wv, [&](int r, int a) {
        const int i = r * nu + a;
        return Quad{p0[i], p1[i], p2[i], p3[i]};
      });
      for (int lane = 0; lane < 4; ++lane) to[k + lane] = sum[lane];
    }
    for (; k < n; ++k) {  // the last few
      if (wanted && !wanted[k]) continue;
      double first, wu[4], wv[4];
      locate(x0 + step * k, y, first, wu, wv);
      const double* p = node.data() + static_cast<long long>(first);
      to[k] = bicubic(wu, wv, [&](int r, int a) { return p[r * nu + a]; });
    }
  };
  if (sampled)
    add_interpolated(cells, weight, spline_row, scratch);
  else
    add_evaluated(cells, weight, spline_row, scratch);
}

// The bounding box of the `mask` cells (over area `a`) in a rectangle of it
// (empty: x1 <= x0).
Rect mask_bounds(const Area& a, const std::vector<std::uint8_t>& mask, Rect r) {
  Rect b{r.x1, r.x0, r.y1, r.y0};
  for (int y = r.y0; y < r.y1; ++y) {
    const std::uint8_t* m = mask.data() + a.index(a.x0, y);
    const auto at = [&](int x) { return m[x - a.x0]; };
    int first = r.x0;
    while (first < r.x1 && !at(first)) ++first;
    if (first == r.x1) continue;
    int last = r.x1 - 1;
    while (!at(last)) --last;
    b = Rect{std::min(b.x0, first), std::max(b.x1, last + 1), std::min(b.y0, y), y + 1};
  }
  return b;
}

// Each block's box of `mask` cells (over area `a`): the blocks holding one
// become active, and their noise is made and scaled over that box only.
void set_noise_boxes(const RoughField& g, const Area& a, const std::vector<std::uint8_t>& mask, Blocks& b) {
  for (int bj = 0; bj < b.ny; ++bj)
    for (int bi = 0; bi < b.nx; ++bi) {
      const Rect block{std::max(b.x0(bi), a.x0), std::min(b.x1(bi, g.w), a.x0 + a.w), std::max(b.y0(bj), a.y0),
                       std::min(b.y1(bj, g.h), a.y0 + a.h)};
      b.noise_box[b.index(bi, bj)] = block.empty() ? Rect{0, 0, 0, 0} : mask_bounds(a, mask, block);
    }
}

// The noise, octave j weighted 2^(jH), added to `out` (over area `a`) at the
// cells of `mask`, block by block (active blocks only, over their noise box:
// the coarse octaves' nodes cover the box), block rows on
// `threads` threads (a lone field's noise, e.g. 3 % kept cells: each cell is
// written by one block, the same bits for any count).
void add_noise(const RoughField& g, const Area& a, const Blocks& blocks, const std::vector<std::uint8_t>& mask,
               std::uint64_t seed, double H, int octaves, std::vector<double>& out, int threads) {
#pragma omp parallel for num_threads(threads) schedule(dynamic) if (threads > 1)
  for (int bj = 0; bj < blocks.ny; ++bj) {
    std::vector<double> node, scratch;
    for (int bi = 0; bi < blocks.nx; ++bi) {
      if (!blocks.active(bi, bj)) continue;
      const Rect& r = blocks.noise_box[blocks.index(bi, bj)];
      for (int j = 0; j < octaves; ++j)
        add_octave(seed, j, std::exp2(j * H),
                   OctaveCells{g.x0 + r.x0, g.x0 + r.x1, g.y0 + r.y0, g.y0 + r.y1, mask.data() + a.index(r.x0, r.y0),
                               out.data() + a.index(r.x0, r.y0), a.w},
                   node, scratch);
    }
  }
}

// The octaves -rs auto makes for a field whose target cells all lie within
// `depth` cells of a constraint (< 0: not known): those of spacing up to the
// depth. A coarser octave is smooth across every void of the field, and the
// conditioning on the constraints around it takes it out again (scattered
// samples: 3 % kept cells lie within ~16 cells, spacings 16 and 32 go). On the
// 42 benchmark cases RMSE median 0.9069 -> 0.9054 (kept3 0.8430 -> 0.8410),
// Laplacian spread 0.967 unchanged; White Mountains kept3 s2 684 -> 594 ms CPU.
int auto_octaves(double depth) {
  if (depth < 0) return kOctaves;
  int n = 1;
  while (n < kOctaves && std::ldexp(1.0, n) <= depth) ++n;
  return n;
}

// ---- pair statistics ------------------------------------------------------

// Lags (dx, dy) of the pairs of constraint cells summed per block (the
// pair's first cell in the block). The first kLaplacianLags give the variance
// of the 5-point Laplacian of a field with stationary increments,
// 16(γx1+γy1) - 2(γx2+γy2) - 4(γ(1,1)+γ(1,-1)); the x and y pairs at 1, 2, 4,
// 8, 16 give the semivariogram from which H is fitted.
constexpr int kLags = 12;
constexpr int kLaplacianLags = 6;
constexpr int kLagDx[kLags] = {1, 0, 2, 0, 1, 1, 4, 0, 8, 0, 16, 0};
constexpr int kLagDy[kLags] = {0, 1, 0, 2, 1, -1, 0, 4, 0, 8, 0, 16};
// The long lags (4, 8, 16) only feed the field-wide semivariogram (H): their
// pairs are taken on every kLongLagRowStep-th raster row (a quarter of them;
// model_of uses a lag from 30 pairs).
constexpr int kLongLagRowStep = 4;
constexpr int kVariogramLags = 5;  // distances 1, 2, 4, 8, 16: lags kVariogramPair[k]
constexpr int kVariogramPair[kVariogramLags][2] = {{0, 1}, {2, 3}, {6, 7}, {8, 9}, {10, 11}};
// Pairs per lag before a neighbourhood's estimate is trusted: the Laplacian
// variance is a small difference of large γ terms (about 10× cancellation).
constexpr double kMinPairs = 2000;
// Neighbourhoods grow to at most this many blocks around a void block; short
// of kMinPairs there, the estimate blends into the global calibration.
constexpr int kMaxRadius = 4;

struct LagSums {
  double sum[kLags] = {};
  double count[kLags] = {};
  void add(const LagSums& o, double sign = 1.0) {
    for (int l = 0; l < kLags; ++l) {
      sum[l] += sign * o.sum[l];
      count[l] += sign * o.count[l];
    }
  }
  double gamma(int l) const { return count[l] > 0 ? 0.5 * sum[l] / count[l] : 0.0; }
  double min_laplacian_count() const { return *std::min_element(count, count + kLaplacianLags); }
  double laplacian_variance() const {
    return 16.0 * (gamma(0) + gamma(1)) - 2.0 * (gamma(2) + gamma(3)) - 4.0 * (gamma(4) + gamma(5));
  }
};

// One lag's pairs along a row segment of n cells: z is 0 and m 0 at the
// non-constraint cells, m 1 at the constraints. Arithmetic only, four cells at
// a time in Quad accumulators, their lanes added in a fixed order (an omp
// simd reduction kept its partial sums in memory, a store per step).
struct PairRun {
  double sum = 0.0, count = 0.0;
};
[[gnu::always_inline]] inline PairRun pair_run(const double* __restrict z0, const double* __restrict m0,
                                               const double* __restrict z1, const double* __restrict m1, int n) {
  const auto load = [](const double* p) {
    Quad v;
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  Quad sum{}, count{};
  int x = 0;
  for (; x + 3 < n; x += 4) {
    const Quad d = load(z1 + x) - load(z0 + x), m = load(m0 + x) * load(m1 + x);
    sum += m * (d * d);
    count += m;
  }
  PairRun r{(sum[0] + sum[1]) + (sum[2] + sum[3]), (count[0] + count[1]) + (count[2] + count[3])};
  for (; x < n; ++x) {
    const double d = z1[x] - z0[x], m = m0[x] * m1[x];
    r.sum += m * (d * d);
    r.count += m;
  }
  return r;
}

// z = the value at a constraint, +0.0 elsewhere; m = 1.0 or +0.0. As bit masks:
// GCC vectorises the and of a widened byte with the value's bits, not the
// select (scalar: ~12 instructions a cell, a fifth of block_row_pairs' time).
[[gnu::always_inline]] inline void constraint_values(const CellState* __restrict c, const double* __restrict v,
                                                     std::size_t n, double* __restrict z, double* __restrict m) {
  constexpr std::uint64_t kOne = 0x3ff0000000000000;  // the bits of 1.0
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t keep = is_constraint(c[i]) ? ~std::uint64_t{0} : 0;
    std::uint64_t bits;
    std::memcpy(&bits, v + i, sizeof bits);
    bits &= keep;
    std::memcpy(z + i, &bits, sizeof bits);
    const std::uint64_t one = kOne & keep;
    std::memcpy(m + i, &one, sizeof one);
  }
}

// The pair sums of the blocks of block row bj into `out`, on a copy of its
// rows and the 16 below as pair_run's z and m (buffers reused by the caller).
// Cloned for AVX2 as add_octave is (the same bits).
MCMD_AVX2_CLONES
void block_row_pairs(const RoughField& g, const Blocks& b, int bj,
                     std::vector<double>& z, std::vector<double>& m, std::vector<LagSums>& out) {
  constexpr int kReach = 16;  // the longest lag
  const int y0 = b.y0(bj), y1 = b.y1(bj, g.h);
  if (y1 <= y0) return;
  // Rows ry0 .. ry1 - 1 (from one above, for the (1, -1) lag).
  const int ry0 = std::max(0, y0 - 1), ry1 = std::min(g.h, y1 + kReach);
  const std::size_t first = g.index(0, ry0), cells = static_cast<std::size_t>(ry1 - ry0) * g.w;
  z.resize(cells);
  m.resize(cells);
  constraint_values(g.state + first, g.z + first, cells, z.data(), m.data());
  const auto at = [&](int x, int y) { return static_cast<std::size_t>(y - ry0) * g.w + x; };
  for (int y = y0; y < y1; ++y)
    for (int l = 0; l < kLags; ++l) {
      const int dx = kLagDx[l], py = y + kLagDy[l];
      if (py < 0 || py >= g.h || dx >= g.w) continue;
      if (l >= kLaplacianLags && positive_mod(g.y0 + y, kLongLagRowStep) != 0) continue;
      for (int bi = 0; bi < b.nx; ++bi) {
        const int x0 = b.x0(bi), x1 = std::min(b.x1(bi, g.w), g.w - dx);
        if (x1 <= x0) continue;
        const PairRun r = pair_run(&z[at(x0, y)], &m[at(x0, y)], &z[at(x0 + dx, py)], &m[at(x0 + dx, py)], x1 - x0);
        LagSums& s = out[b.index(bi, bj)];
        s.sum[l] += r.sum;
        s.count[l] += r.count;
      }
    }
}

// Per block, the pair sums of every lag; block rows on `threads` threads, each
// block summed by one thread in a fixed order (the same bits for any count).
std::vector<LagSums> pair_sums(const RoughField& g, const Blocks& b,
                               int threads) {
  std::vector<LagSums> out(static_cast<std::size_t>(b.nx) * b.ny);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    std::vector<double> z, m;
#pragma omp for schedule(dynamic)
    for (int bj = 0; bj < b.ny; ++bj) block_row_pairs(g, b, bj, z, m, out);
  }
  return out;
}

// The semivariogram γ(d) over the whole field, d = 1, 2, 4, 8, 16.
struct Variogram {
  double gamma[kVariogramLags] = {};
  double pairs[kVariogramLags] = {};
};
Variogram variogram_of(const std::vector<LagSums>& blocks) {
  LagSums total;
  for (const LagSums& s : blocks) total.add(s);
  Variogram v;
  for (int k = 0; k < kVariogramLags; ++k) {
    const int a = kVariogramPair[k][0], b = kVariogramPair[k][1];
    v.pairs[k] = total.count[a] + total.count[b];
    v.gamma[k] = v.pairs[k] > 0 ? 0.5 * (total.sum[a] + total.sum[b]) / v.pairs[k] : 0.0;
  }
  return v;
}

// Summed-area table of the per-block lag sums: any square neighbourhood in O(1).
class LagTable {
 public:
  LagTable(const std::vector<LagSums>& block, const Blocks& b)
      : nx_(b.nx), ny_(b.ny), sat_(static_cast<std::size_t>(b.nx + 1) * (b.ny + 1)) {
    for (int j = 0; j < ny_; ++j)
      for (int i = 0; i < nx_; ++i) {
        LagSums& s = sat_[at(i + 1, j + 1)];
        s = block[b.index(i, j)];
        s.add(sat_[at(i, j + 1)]);
        s.add(sat_[at(i + 1, j)]);
        s.add(sat_[at(i, j)], -1.0);
      }
  }
  // Sums over blocks [i0, i1] × [j0, j1], clipped to the lattice.
  LagSums box(int i0, int j0, int i1, int j1) const {
    i0 = std::max(i0, 0); j0 = std::max(j0, 0);
    i1 = std::min(i1, nx_ - 1); j1 = std::min(j1, ny_ - 1);
    LagSums s = sat_[at(i1 + 1, j1 + 1)];
    s.add(sat_[at(i0, j1 + 1)], -1.0);
    s.add(sat_[at(i1 + 1, j0)], -1.0);
    s.add(sat_[at(i0, j0)]);
    return s;
  }

 private:
  std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * (nx_ + 1) + i; }
  int nx_, ny_;
  std::vector<LagSums> sat_;
};

// The noise's second differences over the target cells of one block: the
// moments of its 5-point Laplacian, and Σ(dxx² + dyy²).
struct NoiseMoments {
  double n = 0, q = 0, qq = 0, curvature = 0;
  void add(const NoiseMoments& o) { n += o.n; q += o.q; qq += o.qq; curvature += o.curvature; }
  double laplacian_var() const { return n > 1 ? std::max(0.0, qq / n - (q / n) * (q / n)) : 0.0; }
};

// Per active block (target cells lie in active blocks only, inside area `a`
// with a cell to spare around them), block rows on `threads` threads; each
// row segment a pass that vectorises.
std::vector<NoiseMoments> noise_moments(const RoughField& g, const Area& a, const std::vector<std::uint8_t>& target,
                                        const Blocks& b, const std::vector<double>& noise, int threads) {
  std::vector<NoiseMoments> out(static_cast<std::size_t>(b.nx) * b.ny);
  const int w = a.w;
#pragma omp parallel for num_threads(threads) schedule(dynamic) if (threads > 1)
  for (int bj = 0; bj < b.ny; ++bj)
    for (int bi = 0; bi < b.nx; ++bi) {
      if (!b.active(bi, bj)) continue;
      const int x0 = std::max(1, b.x0(bi)), n_x = std::min(b.x1(bi, g.w), g.w - 1) - x0;
      NoiseMoments m;
      for (int y = std::max(1, b.y0(bj)); y < std::min(b.y1(bj, g.h), g.h - 1); ++y) {
        const double* v = noise.data() + a.index(x0, y);
        const std::uint8_t* t = target.data() + a.index(x0, y);
        if (!std::memchr(t, 1, static_cast<std::size_t>(std::max(0, n_x)))) continue;  // adds 0: a small void's rows
        double n = 0, q = 0, qq = 0, cv = 0;
#pragma omp simd reduction(+ : n, q, qq, cv)
        for (int k = 0; k < n_x; ++k) {
          const double weight = t[k];  // 0 or 1: arithmetic, not a select, so that it vectorises
          const double dxx = v[k - 1] - 2.0 * v[k] + v[k + 1], dyy = v[k - w] - 2.0 * v[k] + v[k + w];
          const double lq = dxx + dyy;
          n += weight;
          q += weight * lq;
          qq += weight * (lq * lq);
          cv += weight * (dxx * dxx + dyy * dyy);
        }
        m.add(NoiseMoments{n, q, qq, cv});
      }
      out[b.index(bi, bj)] = m;
    }
  return out;
}

// H and the field's curvature from its semivariogram.
RoughnessModel model_of(const Variogram& vg) {
  RoughnessModel m;
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0, g1 = 0, g2 = 0, pairs1 = 0;
  for (int k = 0, d = 1; k < kVariogramLags; ++k, d *= 2) {
    const double pairs = vg.pairs[k];
    const double gamma = vg.gamma[k];
    if (pairs < 30 || gamma <= 0) continue;
    if (d == 1) { g1 = gamma; pairs1 = pairs; }
    if (d == 2) g2 = gamma;
    const double lx = std::log(static_cast<double>(d)), ly = std::log(gamma);
    sx += lx; sy += ly; sxx += lx * lx; sxy += lx * ly; n += 1;
  }
  if (n < 2 || g1 <= 0) return m;
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);  // 2H
  m.H = std::clamp(0.5 * slope, 0.05, 0.95);
  // Var(z(x-1) - 2z(x) + z(x+1)) = 8γ(1) - 2γ(2): a small difference of large
  // terms, unreliable from scattered samples (pair1 pairs at lag 1). Then the
  // fBm form γ(1)(8 - 2·4^H), from γ(1) and the H of all lags (both stable),
  // scaled by kFbmToTerrain: real DEMs are smoother at the cell scale than
  // that extrapolation (also where 8γ(1) - 2γ(2) is not positive).
  const double empirical = 8.0 * g1 - 2.0 * g2;
  const double fbm_form = kFbmToTerrain * g1 * (8.0 - 2.0 * std::pow(4.0, m.H));
  const double trust = empirical > 0 ? smoothstep((pairs1 - kDensePairs / 10) / (0.9 * kDensePairs)) : 0.0;
  m.curvature = trust * empirical + (1.0 - trust) * fbm_form;
  m.valid = m.curvature > 0;
  return m;
}

}  // namespace

RoughnessModel estimate_roughness(const RoughField& grid) {
  return model_of(variogram_of(pair_sums(grid, block_lattice(grid), 1)));
}

RoughnessModel estimate_roughness(const Grid& grid) { return estimate_roughness(RoughField::of(grid)); }

namespace {

// -rs auto: the noise's scale per block. Each block with target cells gets the
// Laplacian variance of the terrain around it (directional semivariogram of
// the constraint pairs in the smallest square of blocks with kMinPairs pairs
// per lag) and the scale that gives the noise that variance over the target
// cells of the block and its 8 neighbours. Where the pairs are too few within
// kMaxRadius blocks (scattered samples, the middle of huge voids), the target
// blends into the global one. Blocks without target cells take the mean of
// their neighbours with one (they only support the interpolation).
std::vector<double> block_scales(const Blocks& blocks, const LagTable& lags, const std::vector<NoiseMoments>& lap,
                                 const RoughnessModel& global, double global_scale) {
  const int nbx = blocks.nx, nby = blocks.ny;
  const double global_target = kLapPerCurvature * 2.0 * global.curvature;
  std::vector<double> scale(static_cast<std::size_t>(nbx) * nby, -1.0);
  for (int bj = 0; bj < nby; ++bj)
    for (int bi = 0; bi < nbx; ++bi) {
      if (lap[blocks.index(bi, bj)].n == 0) continue;
      LagSums around;
      for (int r = 1; r <= kMaxRadius; ++r) {
        around = lags.box(bi - r, bj - r, bi + r, bj + r);
        if (around.min_laplacian_count() >= kMinPairs) break;
      }
      const double local = around.laplacian_variance();
      const double trust =
          local > 0 ? smoothstep((around.min_laplacian_count() - 0.25 * kMinPairs) / (0.75 * kMinPairs)) : 0.0;
      const double target = trust * local + (1.0 - trust) * global_target;
      NoiseMoments m;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          if (blocks.inside(bi + di, bj + dj)) m.add(lap[blocks.index(bi + di, bj + dj)]);
      const double vq = m.laplacian_var();
      scale[blocks.index(bi, bj)] = vq > 0 ? std::sqrt(target / vq) : global_scale;
    }
  std::vector<double> filled = scale;
  for (int bj = 0; bj < nby; ++bj)
    for (int bi = 0; bi < nbx; ++bi) {
      if (scale[blocks.index(bi, bj)] >= 0) continue;
      double s = 0, n = 0;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          if (!blocks.inside(bi + di, bj + dj)) continue;
          const double v = scale[blocks.index(bi + di, bj + dj)];
          if (v >= 0) { s += v; n += 1; }
        }
      filled[blocks.index(bi, bj)] = n > 0 ? s / n : global_scale;
    }
  return filled;
}

// noise (over area `a`) × the block scales interpolated bilinearly between
// block centres (a smooth amplitude field), in place; the noise lies in the
// active blocks' noise boxes only.
void scale_noise(const Area& a, const Blocks& blocks, const std::vector<double>& scales, std::vector<double>& noise,
                 int threads) {
  const auto at = [&](int bi, int bj) {
    return scales[blocks.index(std::clamp(bi, 0, blocks.nx - 1), std::clamp(bj, 0, blocks.ny - 1))];
  };
#pragma omp parallel for num_threads(threads) schedule(dynamic) if (threads > 1)
  for (int bj = 0; bj < blocks.ny; ++bj)
    for (int bi = 0; bi < blocks.nx; ++bi) {
      if (!blocks.active(bi, bj)) continue;
      const Rect& r = blocks.noise_box[blocks.index(bi, bj)];
      for (int y = r.y0; y < r.y1; ++y) {
        const double fy = (y + blocks.oy + 0.5) / kBlock - 0.5;
        const int cj = static_cast<int>(floor_of(fy));
        const double ty = fy - cj;
        for (int x = r.x0; x < r.x1; ++x) {
          double& v = noise[a.index(x, y)];
          if (v == 0.0) continue;
          const double fx = (x + blocks.ox + 0.5) / kBlock - 0.5;
          const int ci = static_cast<int>(floor_of(fx));
          const double tx = fx - ci;
          v *= (1 - ty) * ((1 - tx) * at(ci, cj) + tx * at(ci + 1, cj)) +
               ty * ((1 - tx) * at(ci, cj + 1) + tx * at(ci + 1, cj + 1));
        }
      }
    }
}

// The area the noise of a field covers: its target cells (bounds `t`) grown
// by kNoiseReach, widened to whole blocks and one cell more (the Laplacian at
// a block's edge), inside the field. Empty without target cells.
Area noise_area(const RoughField& g, const Blocks& b, const Rect& t) {
  if (t.x1 <= t.x0) return Area{};
  const auto block_of = [](int v, int offset) { return (v + offset) / kBlock; };
  const int x0 = b.x0(block_of(std::max(0, t.x0 - kNoiseReach), b.ox));
  const int x1 = b.x1(block_of(std::min(g.w, t.x1 + kNoiseReach) - 1, b.ox), g.w);
  const int y0 = b.y0(block_of(std::max(0, t.y0 - kNoiseReach), b.oy));
  const int y1 = b.y1(block_of(std::min(g.h, t.y1 + kNoiseReach) - 1, b.oy), g.h);
  Area a;
  a.x0 = std::max(0, x0 - 1);
  a.y0 = std::max(0, y0 - 1);
  a.w = std::min(g.w, x1 + 1) - a.x0;
  a.h = std::min(g.h, y1 + 1) - a.y0;
  return a;
}

// d (over area `a`) cut down to the union of the blocks' noise boxes,
// outside which it is 0: a small void's area is whole 32² blocks, its noise
// a few cells.
Displacement crop_to_noise(const Area& a, const Blocks& b, Displacement d) {
  Rect r{a.x0 + a.w, a.x0, a.y0 + a.h, a.y0};
  for (const Rect& box : b.noise_box)
    if (!box.empty())
      r = Rect{std::min(r.x0, box.x0), std::max(r.x1, box.x1), std::min(r.y0, box.y0), std::max(r.y1, box.y1)};
  if (r.empty()) return {};
  if (r.x1 - r.x0 == a.w && r.y1 - r.y0 == a.h) return d;
  Displacement out{r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0, {}};
  out.values.reserve(static_cast<std::size_t>(out.w) * out.h);
  for (int y = r.y0; y < r.y1; ++y) {
    const auto from = d.values.begin() + static_cast<std::ptrdiff_t>(a.index(r.x0, y));
    out.values.insert(out.values.end(), from, from + out.w);
  }
  return out;
}

}  // namespace

double Displacement::at(int x, int y) const {
  if (x < x0 || y < y0 || x >= x0 + w || y >= y0 + h || values.empty()) return 0.0;
  return values[static_cast<std::size_t>(y - y0) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x - x0)];
}

std::vector<double> Displacement::whole(int field_w, int field_h) const {
  std::vector<double> out(static_cast<std::size_t>(field_w) * static_cast<std::size_t>(field_h), 0.0);
  for (int y = y0; y < y0 + h && !values.empty(); ++y)
    for (int x = x0; x < x0 + w; ++x) out[static_cast<std::size_t>(y) * field_w + x] = at(x, y);
  return out;
}

Displacement roughness_displacement(const RoughField& grid, const FillParams& params, int threads) {
  if (!adds_roughness(params)) return {};
  Blocks blocks = block_lattice(grid);
  std::vector<LagSums> pairs;
  double H = params.H;
  RoughnessModel global;
  if (params.rs_auto) {
    pairs = pair_sums(grid, blocks, threads);
    global = model_of(variogram_of(pairs));
    if (!global.valid) return {};
    H = global.H;
  }
  const Rect targets = target_bounds(grid);
  const Area area = noise_area(grid, blocks, targets);
  if (area.cells() == 0) return {};
  // Unconditioned noise at the noise cells only (0 elsewhere).
  const std::vector<std::uint8_t> target = target_mask(grid, area, targets);
  const std::vector<std::uint8_t> mask = noise_cells(target, area);
  set_noise_boxes(grid, area, mask, blocks);
  Displacement d{area.x0, area.y0, area.w, area.h, std::vector<double>(area.cells(), 0.0)};
  std::vector<double>& noise = d.values;
  add_noise(grid, area, blocks, mask, params.seed, H, params.rs_auto ? auto_octaves(grid.depth) : kOctaves, noise,
            threads);
  if (!params.rs_auto) {  // the coarsest octave's amplitude is rs · unit
    const double unit = params.noise_unit > 0 ? params.noise_unit
                                              : known_range({grid.z, grid.cells()}, {grid.state, grid.cells()});
    const double scale = params.rs * unit * std::exp2(-(kOctaves - 1) * H);
    for (double& v : noise) v *= scale;
    return crop_to_noise(area, blocks, std::move(d));
  }
  // Global calibration: the noise's second-difference variance is kStrength²
  // of the terrain's; local targets per block where there are pairs enough.
  const std::vector<NoiseMoments> moments = noise_moments(grid, area, target, blocks, noise, threads);
  NoiseMoments all;
  for (const NoiseMoments& m : moments) all.add(m);
  const double c = all.n > 0 ? all.curvature / (2.0 * all.n) : 0.0;
  const double global_scale = c > 0 ? kStrength * std::sqrt(global.curvature / c) : 0.0;
  scale_noise(area, blocks, block_scales(blocks, LagTable(pairs, blocks), moments, global, global_scale), noise,
              threads);
  return crop_to_noise(area, blocks, std::move(d));
}

}  // namespace mcmd
