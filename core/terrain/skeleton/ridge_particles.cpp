#include "terrain/skeleton/ridge_particles.hpp"

#include <cmath>
#include <numbers>

#include "roughness/noise.hpp"
#include "terrain/skeleton/fbm_path.hpp"

namespace mcmd::terrain {

namespace {

constexpr double kHeadingSigma = 0.8;  // radians of side impacts over a whole route
constexpr double kSpent = 0.05;        // a particle stops below this fraction of its start height
constexpr std::uint64_t kStartStream = 11, kHeadingStream = 12;

struct Particle {
  int couple;
  double x, y, start_height, heading;
  std::vector<double> turns;  // fBm of the heading, per step
};

class RidgeRun {
 public:
  RidgeRun(int w, int h, double sigma) : w_(w), h_(h), sigma_(sigma) {
    out_.height.assign(static_cast<std::size_t>(w) * h, -1.0);
    out_.owner.assign(out_.height.size(), -1);
  }

  // Move `p` until its altitude is spent, it leaves the raster or meets another couple.
  void run(const Particle& p) {
    std::vector<RoutePoint> route;
    double x = p.x, y = p.y;
    const int steps = static_cast<int>(p.turns.size()) - 1;
    for (int i = 0;; ++i) {
      const double g = std::exp(-0.5 * (i / sigma_) * (i / sigma_));
      const int cx = static_cast<int>(std::lround(x)), cy = static_cast<int>(std::lround(y));
      if (g < kSpent || i > steps || !inside(cx, cy)) break;
      const bool met = meets_other(cx, cy, p.couple);
      mark(cx, cy, p.couple, p.start_height * g);
      route.push_back({x, y, p.start_height * g});
      if (met) break;
      const double heading = p.heading + p.turns[i];
      x += std::cos(heading);
      y += std::sin(heading);
    }
    out_.routes.push_back(std::move(route));
  }

  bool free_at(int x, int y) const { return out_.owner[index(x, y)] < 0; }
  RidgeRoutes take() { return std::move(out_); }

 private:
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * w_ + x; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < w_ && y < h_; }
  // The cell or one of its 4 neighbours is on another couple's route: two
  // 8-connected routes cannot cross without one of these.
  bool meets_other(int x, int y, int couple) const {
    const int dx[] = {0, 1, -1, 0, 0}, dy[] = {0, 0, 0, 1, -1};
    for (int k = 0; k < 5; ++k) {
      const int nx = x + dx[k], ny = y + dy[k];
      if (inside(nx, ny) && out_.owner[index(nx, ny)] >= 0 && out_.owner[index(nx, ny)] != couple) return true;
    }
    return false;
  }
  void mark(int x, int y, int couple, double height) {
    const std::size_t i = index(x, y);
    if (out_.owner[i] < 0) out_.owner[i] = couple;
    if (height > out_.height[i]) out_.height[i] = height;
  }

  int w_, h_;
  double sigma_;
  RidgeRoutes out_;
};

}  // namespace

double ridge_sigma(int w, int h) { return (w > h ? w : h) / 4.0; }

RidgeRoutes run_ridge_particles(int w, int h, int couples, double H, double top, std::uint64_t seed) {
  const double sigma = ridge_sigma(w, h);
  const int steps = static_cast<int>(std::ceil(sigma * std::sqrt(-2.0 * std::log(kSpent)))) + 1;
  RidgeRun run(w, h, sigma);
  const UniformHash draw(seed, kStartStream);
  int started = 0;
  for (int k = 0; k < couples; ++k) {
    const auto u = [&](int j) { return 0.5 * (draw(k, j) + 1.0); };  // [0, 1)
    const double x = (0.15 + 0.7 * u(0)) * (w - 1), y = (0.15 + 0.7 * u(1)) * (h - 1);
    if (!run.free_at(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)))) continue;
    const double height = top * (0.75 + 0.25 * u(2));
    const double heading = 2.0 * std::numbers::pi * u(3);
    for (int side = 0; side < 2; ++side)  // back to back: opposite headings
      run.run(Particle{k, x, y, height, heading + side * std::numbers::pi,
                       fbm_path(steps, H, kHeadingSigma, seed, kHeadingStream + 2 * k + side)});
    ++started;
  }
  RidgeRoutes out = run.take();
  out.couples = started;
  return out;
}

}  // namespace mcmd::terrain
