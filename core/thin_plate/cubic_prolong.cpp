#include "thin_plate/cubic_prolong.hpp"

namespace mcmd {

double prolong_at(const double* coarse, int mw, int mh, int x, int y) {
  const Weights1D wx = cubic_weights_1d(x, mw);
  const Weights1D wy = cubic_weights_1d(y, mh);
  double sum = 0.0;
  for (int j = 0; j < wy.count; ++j) {
    const double* row = coarse + static_cast<std::size_t>(wy.first + j) * mw + wx.first;
    double rs = 0.0;
    for (int i = 0; i < wx.count; ++i) rs += wx.w[i] * row[i];
    sum += wy.w[j] * rs;
  }
  return sum;
}

}  // namespace mcmd
