#include "mcmd/cubic_prolong.hpp"

namespace mcmd {

Weights1D cubic_weights_1d(int x, int mc) {
  Weights1D r;
  if ((x & 1) == 0) {
    r.first = x / 2;
    r.count = 1;
    r.w[0] = 1.0;
    return r;
  }
  const int a = (x - 1) / 2;  // left coarse neighbour
  const bool left = a - 1 >= 0;
  const bool right = a + 2 <= mc - 1;
  if (left && right) {
    r = {a - 1, 4, {-1.0 / 16, 9.0 / 16, 9.0 / 16, -1.0 / 16}};
  } else if (left) {
    r = {a - 1, 3, {-1.0 / 8, 3.0 / 4, 3.0 / 8, 0.0}};
  } else if (right) {
    r = {a, 3, {3.0 / 8, 3.0 / 4, -1.0 / 8, 0.0}};
  } else {
    r = {a, 2, {0.5, 0.5, 0.0, 0.0}};
  }
  return r;
}

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
