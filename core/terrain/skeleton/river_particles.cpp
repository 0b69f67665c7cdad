#include "terrain/skeleton/river_particles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include "mcmd/skeleton.hpp"
#include "roughness/noise.hpp"

namespace mcmd::terrain {

namespace {

constexpr double kGravity = 1.0;
constexpr double kFriction = 0.2;    // per step, of the velocity
constexpr double kMaxMove = 0.5;     // cells per sub-step: consecutive path cells are neighbours
constexpr double kRestSpeed = 0.01;  // cells per step
constexpr int kRestSteps = 40;       // that slow for this long: at rest
constexpr double kTopPart = 0.3;     // sources lie in the first 30 % of a route (its high part)
constexpr int kJoinReach = 6;
constexpr double kTroughDepth = 0.05;  // of the relief's scale: the valley a kept river digs        // a river this close (Chebyshev) is joined: no parallel rivers
constexpr std::uint64_t kSourceStream = 21;

class RiverRun {
 public:
  RiverRun(int w, int h, RidgeRelief& relief, double top)
      : w_(w), h_(h), relief_(relief), top_(top), to_slope_(relief.cross_sigma() / top) {
    net_.downstream.assign(static_cast<std::size_t>(w) * h, kNoRiver);
    net_.mass.assign(net_.downstream.size(), 0);
    near_.assign(net_.downstream.size(), -1);
  }

  // Roll one particle from (x, y) with velocity (vx, vy); keep its path if it drains.
  void roll(double x, double y, double vx, double vy) {
    path_.clear();
    where_.clear();
    const long long start = cell_at(x, y);
    if (start < 0 || net_.downstream[start] != kNoRiver) return;
    append(start);
    const int max_steps = 8 * (w_ + h_);
    for (int step = 0, slow = 0; step < max_steps && slow < kRestSteps; ++step) {
      double gx, gy;
      relief_.gradient(x, y, gx, gy);
      vx += -kGravity * gx * to_slope_ - kFriction * vx;
      vy += -kGravity * gy * to_slope_ - kFriction * vy;
      const double speed = std::hypot(vx, vy);
      slow = speed < kRestSpeed ? slow + 1 : 0;
      const int sub = std::max(1, static_cast<int>(std::ceil(speed / kMaxMove)));
      for (int s = 0; s < sub; ++s) {
        x += vx / sub;
        y += vy / sub;
        if (const auto end = enter(cell_at(x, y)); end != kContinue) return commit(end);
      }
    }
    ++net_.dropped;  // at rest in a hollow, or wandering
  }

  RiverNetwork take() { return std::move(net_); }

 private:
  static constexpr std::int64_t kContinue = -3;

  long long cell_at(double x, double y) const {
    const long long cx = std::llround(x), cy = std::llround(y);
    return cx < 0 || cy < 0 || cx >= w_ || cy >= h_ ? -1 : cy * w_ + cx;
  }

  void append(long long c) {
    where_[c] = path_.size();
    path_.push_back(c);
  }

  // The particle enters cell c: returns kExits (left the raster), the river
  // cell it joins, or kContinue.
  std::int64_t enter(long long c) {
    if (c < 0) return kExits;
    if (c == path_.back()) return kContinue;
    if (net_.downstream[c] != kNoRiver) return c;
    if (where_.count(c)) {  // a loop: cut it off
      cut_back_to(c);
      return kContinue;
    }
    append(c);
    return near_[c] >= 0 ? reach(c, near_[c]) : kContinue;
  }

  // Drop the path after its cell c.
  void cut_back_to(long long c) {
    const std::size_t at = where_.at(c);
    for (std::size_t k = at + 1; k < path_.size(); ++k) where_.erase(path_[k]);
    path_.resize(at + 1);
  }

  // From path cell c to river cell r a few cells away: the cells of the
  // straight 8-connected step line between them join the path; returns the
  // first river cell met.
  std::int64_t reach(long long c, long long r) {
    long long x = c % w_, y = c / w_;
    const long long rx = r % w_, ry = r / w_;
    while (x != rx || y != ry) {
      x += (rx > x) - (rx < x);
      y += (ry > y) - (ry < y);
      const long long next = y * w_ + x;
      if (net_.downstream[next] != kNoRiver) return next;
      if (where_.count(next)) cut_back_to(next);  // back on its own path
      else append(next);
    }
    return r;
  }

  void commit(std::int64_t end) {
    for (std::size_t k = 0; k + 1 < path_.size(); ++k) net_.downstream[path_[k]] = path_[k + 1];
    net_.downstream[path_.back()] = end;
    for (long long c : path_) claim_around(c);
    const int every = std::max(1, static_cast<int>(relief_.cross_sigma() / 8));
    for (std::size_t k = 0; k < path_.size(); k += every)
      relief_.dig(static_cast<double>(path_[k] % w_), static_cast<double>(path_[k] / w_), kTroughDepth * top_,
                  relief_.cross_sigma() / 2);
    for (std::int64_t c = path_.front(); c >= 0; c = net_.downstream[c]) ++net_.mass[c];
    ++net_.kept;
  }

  // Cells near a kept river lead to it.
  void claim_around(long long c) {
    const int x = static_cast<int>(c % w_), y = static_cast<int>(c / w_);
    for (int ny = std::max(0, y - kJoinReach); ny <= std::min(h_ - 1, y + kJoinReach); ++ny)
      for (int nx = std::max(0, x - kJoinReach); nx <= std::min(w_ - 1, x + kJoinReach); ++nx) {
        const long long n = static_cast<long long>(ny) * w_ + nx;
        if (near_[n] < 0 && net_.downstream[n] == kNoRiver) near_[n] = c;
      }
  }

  int w_, h_;
  RidgeRelief& relief_;
  double top_;
  double to_slope_;  // relief units to a dimensionless slope at the profiles' scale
  RiverNetwork net_;
  std::vector<long long> path_;
  std::unordered_map<long long, std::size_t> where_;
  std::vector<long long> near_;  // per cell: the kept river cell it leads to, -1: none near
};

}  // namespace

RiverNetwork run_river_particles(int w, int h, const RidgeRoutes& routes, RidgeRelief& relief, double top,
                                 int particles, std::uint64_t seed) {
  RiverRun run(w, h, relief, top);
  const UniformHash draw(seed, kSourceStream);
  std::vector<const std::vector<RoutePoint>*> usable;
  for (const auto& r : routes.routes)
    if (r.size() > 1) usable.push_back(&r);
  for (int k = 0; k < particles && !usable.empty(); ++k) {
    const auto u = [&](int j) { return 0.5 * (draw(k, j) + 1.0); };
    const auto& route = *usable[static_cast<std::size_t>(u(0) * usable.size()) % usable.size()];
    const std::size_t p = static_cast<std::size_t>(u(1) * kTopPart * route.size()) % route.size();
    const double angle = 2.0 * std::numbers::pi * u(2);
    // Off the crest by a cell, with a nudge: on the crest itself the slope is 0 across.
    run.roll(route[p].x + std::cos(angle), route[p].y + std::sin(angle), 0.3 * std::cos(angle),
             0.3 * std::sin(angle));
  }
  return run.take();
}

}  // namespace mcmd::terrain
