// The noise's amplitude (internal to roughness/): a constant (-rs > 0), or
// per-block scales interpolated bilinearly between block centres (-rs auto,
// calibration.hpp), applied as the noise is written.
#pragma once

#include <climits>
#include <vector>

#include "roughness/blocks.hpp"

namespace mcmd::rough {

struct Amplitude {
  double constant = 1.0;           // the amplitude everywhere, without block scales
  const Blocks* blocks = nullptr;  // with block scales: their lattice
  std::vector<double> scales;      // per block of *blocks
};

// The amplitude along field cells x0 .. x1 - 1 of successive rows: with
// block scales, interpolated along the row of block centres above and the one
// below (computed when a row passes a centre); a row is a blend of the two,
// done by the caller as it writes the row.
class AmplitudeRows {
 public:
  AmplitudeRows(const Amplitude& a, int x0, int x1);
  // Field row y's amplitude at cell x0 + i: above[i] + t · (below[i] - above[i]).
  struct Row {
    const double* above;
    const double* below;
    double t;
    double at(int i) const { return above[i] + t * (below[i] - above[i]); }
  };
  Row row(int y);

 private:
  void centre_row(int cj, double* to) const;  // along the centres of block row cj
  const Amplitude& a_;
  int x0_, x1_;
  int cj_ = INT_MIN;                   // the centre row above the last row (or at it)
  std::vector<double> above_, below_;  // along centre rows cj_ and cj_ + 1 (without scales: the constant)
};

}  // namespace mcmd::rough
