#include "thin_plate/cubic_prolong.hpp"

namespace mcmd {

namespace {

inline double prolong_with(const double* coarse, int mw, const Weights1D& wx, const Weights1D& wy) {
  double sum = 0.0;
  for (int j = 0; j < wy.count; ++j) {
    const double* row = coarse + static_cast<std::size_t>(wy.first + j) * mw + wx.first;
    double rs = 0.0;
    for (int i = 0; i < wx.count; ++i) rs += wx.w[i] * row[i];
    sum += wy.w[j] * rs;
  }
  return sum;
}

}  // namespace

double prolong_at(const double* coarse, int mw, int mh, int x, int y) {
  return prolong_with(coarse, mw, cubic_weights_1d(x, mw), cubic_weights_1d(y, mh));
}

void prolong_run(const double* coarse, int mw, int mh, int y, int x0, int x1, double* out) {
  const Weights1D wy = cubic_weights_1d(y, mh);
  for (int x = x0; x < x1; ++x) out[x - x0] = prolong_with(coarse, mw, cubic_weights_1d(x, mw), wy);
}

}  // namespace mcmd
