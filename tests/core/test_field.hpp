// A w×h field of elevations and cell states owned by a test, viewed as the
// default method's FieldView (thin_plate/thin_plate.hpp).
#pragma once

#include <vector>

#include "thin_plate/thin_plate.hpp"

namespace mcmd::test {

struct Field {
  int w, h;
  std::vector<double> z;
  std::vector<CellState> state;
  FieldView view() { return {w, h, z.data(), state.data()}; }
};

}  // namespace mcmd::test
