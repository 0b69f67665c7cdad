#include "terrain/erosion/drainage.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

#include "common/d8.hpp"
#include "morphology/flow.hpp"

namespace mcmd::terrain {

namespace {

using d8::kDx, d8::kDy;
// The width of flow through each side of a cell (Quinn et al. 1991's
// contour lengths: ½ across a side, √2/4 across a corner).
constexpr double kContour[8] = {0.5, 0.3535533905932738, 0.5, 0.3535533905932738,
                                0.5, 0.3535533905932738, 0.5, 0.3535533905932738};

// The set bits of an 8-bit mask (std::popcount is a library call without
// the POPCNT instruction, which the portable build does not assume).
unsigned bits_set(unsigned m) {
  m = m - ((m >> 1) & 0x55u);
  m = (m & 0x33u) + ((m >> 2) & 0x33u);
  return (m + (m >> 4)) & 0x0Fu;
}

// The directions that stay off the border from an interior cell at x, y
// (the border sends no water).
unsigned inside_directions(int x, int y, int w, int h) {
  unsigned m = 0xFFu;
  if (x == 1) m &= ~0b0011'1000u;      // west: 3, 4, 5
  if (x == w - 2) m &= ~0b1000'0011u;  // east: 7, 0, 1
  if (y == 1) m &= ~0b1110'0000u;      // north: 5, 6, 7
  if (y == h - 2) m &= ~0b0000'1110u;  // south: 1, 2, 3
  return m;
}

// Where each interior cell sends its water (d.lower, d.to), and how many
// cells send water to each (`higher`, for the order). Without divides a
// cell's senders are its higher interior neighbours, counted with its own
// slopes; with them, the counts are scattered from each sender.
void receivers(Drainage& d, const std::vector<std::uint8_t>& divide, std::vector<std::uint8_t>& higher) {
  const int w = d.w, h = d.h;
  const auto& off = d.offset;
  const std::size_t n = d.level.size();
  d.to.assign(n, kOutlet);
  d.lower.assign(n, 0);
  higher.assign(n, 0);
  const bool divides = !divide.empty();
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x) {
      const std::int32_t i = y * w + x;
      const double zi = d.level[i];
      double s[8];
      unsigned mask = 0, above = 0;  // lower and higher neighbours
      for (int k = 0; k < 8; ++k) {
        s[k] = (zi - d.level[i + off[k]]) * d8::kPerStep[k];
        mask |= static_cast<unsigned>(s[k] > 0) << k;
        above |= static_cast<unsigned>(s[k] < 0) << k;
      }
      double steepest = 0.0;
      std::uint8_t to = kOutlet;
      if (!divides) {
        for (int k = 0; k < 8; ++k)
          if (s[k] > steepest) steepest = s[k], to = static_cast<std::uint8_t>(k);
        d.lower[i] = static_cast<std::uint8_t>(mask);
        d.to[i] = to;
        higher[i] = static_cast<std::uint8_t>(bits_set(above & inside_directions(x, y, w, h)));
        continue;
      }
      // The steepest of the lower neighbours that are not divides, if any.
      unsigned open = 0;
      for (unsigned b = mask; b; b &= b - 1) {
        const int k = std::countr_zero(b);
        if (!divide[i + off[k]]) {
          if (!open || s[k] > steepest) steepest = s[k], to = static_cast<std::uint8_t>(k);
          open |= 1u << k;
        } else if (!open && s[k] > steepest) {
          steepest = s[k], to = static_cast<std::uint8_t>(k);
        }
      }
      const unsigned lower = open ? open : mask;
      d.lower[i] = static_cast<std::uint8_t>(lower);
      d.to[i] = to;
      for (unsigned b = lower; b; b &= b - 1) ++higher[i + off[std::countr_zero(b)]];
    }
  if (divides) return;
  // The border: its interior neighbours that send to it (neighbour k of
  // cell i sends to i when its bit (k + 4) % 8 is set).
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; x += (y == 0 || y == h - 1) ? 1 : w - 1) {
      const std::int32_t i = y * w + x;
      int count = 0;
      for (int k = 0; k < 8; ++k) {
        const int nx = x + kDx[k], ny = y + kDy[k];
        if (nx > 0 && ny > 0 && nx < w - 1 && ny < h - 1) count += d.lower[i + off[k]] >> ((k + 4) & 7) & 1u;
      }
      higher[i] = static_cast<std::uint8_t>(count);
    }
}

// A topological sort from the highest cells down (a cell once every higher
// neighbour has passed its water on: Kahn's, depth first so that the
// cells taken one after the other are mostly neighbours), spreading the
// area on the way: each interior cell passes its area to its lower
// neighbours in proportion to slope² × contour length (Quinn et al. 1991's
// weights, Freeman's sharper exponent: flow spreads on hillslopes and
// gathers in the valleys).
// d.order is the reverse: outlets first. `higher` ends at kTaken everywhere.
void spread_area(Drainage& d, const std::vector<double>& source, std::vector<std::uint8_t>& higher,
                 std::vector<std::int32_t>& stack) {
  constexpr std::uint8_t kTaken = 255;
  const auto& off = d.offset;
  const std::size_t n = d.level.size();
  d.area.assign(n, 1.0f);
  for (std::size_t i = 0; i < source.size(); ++i) d.area[i] += static_cast<float>(source[i]);
  d.order.resize(n);
  std::size_t taken = n;  // the order is filled from its end: outlets first
  stack.clear();
  double share[8];
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (higher[seed] != 0) continue;
    stack.push_back(static_cast<std::int32_t>(seed));
    while (!stack.empty()) {
      const std::int32_t i = stack.back();
      stack.pop_back();
      higher[i] = kTaken;
      d.order[--taken] = i;
      const unsigned mask = d.lower[i];
      if (!mask) continue;  // the border (every interior cell has a lower neighbour)
      const double zi = d.level[i];
      double total = 0.0;
      for (unsigned b = mask; b; b &= b - 1) {
        const int j = std::countr_zero(b);
        const double slope = (zi - d.level[i + off[j]]) * d8::kPerStep[j];
        share[j] = slope * slope * kContour[j];
        total += share[j];
      }
      const double a = d.area[i] / total;  // total > 0: an interior cell has a lower neighbour
      for (unsigned b = mask; b; b &= b - 1) {
        const int j = std::countr_zero(b);
        const std::int32_t t = i + off[j];
        d.area[t] += static_cast<float>(a * share[j]);
        if (--higher[t] == 0) stack.push_back(t);
      }
    }
  }
}

void route(Drainage& d, const WaterGuides& guides, DrainageScratch& s) {
  receivers(d, guides.divide, s.count);
  spread_area(d, guides.source, s.count, s.stack);
}

}  // namespace

void flood(std::vector<double>& z, const std::vector<std::uint8_t>& fixed, const WaterGuides& guides, int w, int h,
           Drainage& d, DrainageScratch& s) {
  d.w = w, d.h = h;
  d.offset = d8::offsets(w);
  const std::vector<morph::FlowCell> land(z.size(), morph::FlowCell::land);
  d.level = morph::flood_levels(z.data(), w, h, land.data());
  for (std::size_t i = 0; i < z.size(); ++i)
    if (!fixed[i]) z[i] = d.level[i];
  route(d, guides, s);
}

void keep_draining(std::vector<double>& z, const std::vector<std::uint8_t>& fixed, const WaterGuides& guides,
                   Drainage& d, DrainageScratch& s) {
  for (const std::int32_t i : d.order) {
    const std::int32_t r = d.receiver(i);
    double v = z[i];
    if (r >= 0) v = std::max(v, morph::next_above(d.level[r]));
    d.level[i] = v;
    if (!fixed[i]) z[i] = v;
  }
  route(d, guides, s);
}

}  // namespace mcmd::terrain
