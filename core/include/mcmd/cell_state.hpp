// What a fill knows about a cell. A leaf header.
#pragma once

#include <cstdint>

namespace mcmd {

// Only `unknown` cells are ever written by a fill; ridge and river cells are
// constraints that carry their own shape parameters (paper §4.3: terrain from
// sketches, FillParams::ridge_shape and river_shape).
enum class CellState : std::uint8_t { unknown = 0, known = 1, ridge = 2, river = 3 };

constexpr bool is_constraint(CellState s) { return s != CellState::unknown; }

}  // namespace mcmd
