#include "terrain/skeleton/ridge_relief.hpp"

#include <algorithm>
#include <cmath>

namespace mcmd::terrain {

namespace {

constexpr double kDome = 0.1;  // of top: the lean of flats towards the border

}  // namespace

RidgeRelief::RidgeRelief(int w, int h, const RidgeRoutes& routes, double top)
    : w_(w), h_(h), cross_sigma_(ridge_sigma(w, h) / 4.0) {
  stride_ = std::max(1, static_cast<int>(cross_sigma_ / 4.0));
  nx_ = (w - 1) / stride_ + 2;
  ny_ = (h - 1) / stride_ + 2;
  lattice_.assign(static_cast<std::size_t>(nx_) * ny_, 0.0);
  trough_.assign(lattice_.size(), 0.0);
  const double reach = 3.0 * cross_sigma_, k = 0.5 / (cross_sigma_ * cross_sigma_);
  // Every route point's profile, at points about half a lattice step apart.
  const int every = std::max(1, stride_ / 2);
  for (const auto& route : routes.routes)
    for (std::size_t p = 0; p < route.size(); p += every) {
      const RoutePoint& q = route[p];
      const int i0 = std::max(0, static_cast<int>(std::floor((q.x - reach) / stride_)));
      const int i1 = std::min(nx_ - 1, static_cast<int>(std::ceil((q.x + reach) / stride_)));
      const int j0 = std::max(0, static_cast<int>(std::floor((q.y - reach) / stride_)));
      const int j1 = std::min(ny_ - 1, static_cast<int>(std::ceil((q.y + reach) / stride_)));
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
          const double dx = i * stride_ - q.x, dy = j * stride_ - q.y;
          double& v = lattice_[static_cast<std::size_t>(j) * nx_ + i];
          v = std::max(v, q.height * std::exp(-k * (dx * dx + dy * dy)));
        }
    }
  for (int j = 0; j < ny_; ++j)
    for (int i = 0; i < nx_; ++i) {
      const double u = 2.0 * i * stride_ / std::max(1, w - 1) - 1.0, v = 2.0 * j * stride_ / std::max(1, h - 1) - 1.0;
      lattice_[static_cast<std::size_t>(j) * nx_ + i] += kDome * top * std::max(0.0, 1 - u * u) * std::max(0.0, 1 - v * v);
    }
}

double RidgeRelief::node(int i, int j) const {
  const std::size_t k = static_cast<std::size_t>(std::clamp(j, 0, ny_ - 1)) * nx_ + std::clamp(i, 0, nx_ - 1);
  return lattice_[k] - trough_[k];
}

void RidgeRelief::dig(double x, double y, double depth, double width) {
  const double reach = 3.0 * width, k = 0.5 / (width * width);
  const int i0 = std::max(0, static_cast<int>(std::floor((x - reach) / stride_)));
  const int i1 = std::min(nx_ - 1, static_cast<int>(std::ceil((x + reach) / stride_)));
  const int j0 = std::max(0, static_cast<int>(std::floor((y - reach) / stride_)));
  const int j1 = std::min(ny_ - 1, static_cast<int>(std::ceil((y + reach) / stride_)));
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const double dx = i * stride_ - x, dy = j * stride_ - y;
      double& t = trough_[static_cast<std::size_t>(j) * nx_ + i];
      t = std::max(t, depth * std::exp(-k * (dx * dx + dy * dy)));
    }
}

// Catmull-Rom in both directions: C1, so river paths bend smoothly
// instead of kinking along the lattice's lines.
double RidgeRelief::at(double x, double y) const {
  const double u = x / stride_, v = y / stride_;
  const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
  const auto weights = [](double t, double w[4]) {
    const double t2 = t * t, t3 = t2 * t;
    w[0] = 0.5 * (-t + 2 * t2 - t3);
    w[1] = 0.5 * (2 - 5 * t2 + 3 * t3);
    w[2] = 0.5 * (t + 4 * t2 - 3 * t3);
    w[3] = 0.5 * (t3 - t2);
  };
  double wu[4], wv[4];
  weights(u - i, wu);
  weights(v - j, wv);
  double sum = 0.0;
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) sum += wv[b] * wu[a] * node(i - 1 + a, j - 1 + b);
  return sum;
}

void RidgeRelief::gradient(double x, double y, double& gx, double& gy) const {
  gx = at(x + 0.5, y) - at(x - 0.5, y);
  gy = at(x, y + 0.5) - at(x, y - 0.5);
}

std::vector<double> RidgeRelief::cells() const {
  std::vector<double> out(static_cast<std::size_t>(w_) * h_);
  for (int y = 0; y < h_; ++y)
    for (int x = 0; x < w_; ++x) out[static_cast<std::size_t>(y) * w_ + x] = at(x, y);
  return out;
}

}  // namespace mcmd::terrain
