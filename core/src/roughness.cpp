#include "mcmd/roughness.hpp"

namespace mcmd {

void add_roughness(Lattice&, const Grid&, const FillParams&) {}

}  // namespace mcmd
