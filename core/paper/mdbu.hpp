// MDBU — the paper's bottom-up pass (Belhadj 2007, §3.3, Algorithm 1).
//
// Why: top-down midpoint displacement computes a cell from its parents only,
// so a known cell whose parents are unknown makes a jump (paper Fig. 4). MDBU
// first gives every ascendant of a known cell a value computed from below.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "common/grid.hpp"
#include "mcmd/params.hpp"
#include "mcmd/progress.hpp"
#include "paper/delta.hpp"
#include "paper/subdivision.hpp"

namespace mcmd {

// Algorithm 1 on any hierarchy. `Topology` provides
//   template <class F> void for_each_parent(std::uint32_t cell, F visit) const;
//   double distance(std::uint32_t a, std::uint32_t b) const;   // in cells
// Waves: every cell of the FIFO offers itself to each of its still-unset
// ascendants (a hash map from ascendant to its list of known children); then
// each collected ascendant is set to the Δ_BU combination of its children
// (I_bu of each child's state), marked fixed, and queued for the next wave.
// Pre: z, states, fixed have one entry per cell; fixed marks the set cells.
// Post: every ascendant of every fixed cell is fixed; returns how many MDBU set.
template <class Topology>
std::size_t mdbu_waves(std::vector<double>& z, const std::vector<CellState>& states,
                       std::vector<std::uint8_t>& fixed, const Topology& topology,
                       const FillParams& params, double dmax, int expected_waves,
                       const ProgressFn& progress = {}) {
  std::vector<std::uint32_t> wave;
  for (std::uint32_t i = 0; i < fixed.size(); ++i)
    if (fixed[i]) wave.push_back(i);

  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> known_children;
  std::vector<std::uint32_t> collected;  // insertion order: keeps the pass reproducible
  std::vector<Contribution> contributions;
  std::size_t set = 0;
  for (int w = 1; !wave.empty(); ++w) {
    for (std::uint32_t child : wave) {
      topology.for_each_parent(child, [&](std::uint32_t parent) {
        if (fixed[parent]) return;
        auto [it, fresh] = known_children.try_emplace(parent);
        if (fresh) collected.push_back(parent);
        it->second.push_back(child);
      });
    }
    for (std::uint32_t parent : collected) {
      contributions.clear();
      for (std::uint32_t child : known_children[parent])
        contributions.push_back({z[child], topology.distance(parent, child),
                                 shape_for(params, states[child]).I_bu});
      z[parent] = combine(params.delta_form, contributions, dmax);
      fixed[parent] = 1;
    }
    set += collected.size();
    wave.swap(collected);  // the FIFO's next wave: the cells just set
    collected.clear();
    known_children.clear();
    report(progress, static_cast<double>(w) / (expected_waves > w ? expected_waves : w + 1));
  }
  return set;
}

// MDBU on a 2^n+1 grid with `scheme`'s ascendants (see subdivision.hpp).
// Pre: fixed.size() == grid.cell_count(). Post: as mdbu_waves; grid states unchanged.
std::size_t mdbu(Grid& grid, std::vector<std::uint8_t>& fixed, Scheme scheme,
                 const FillParams& params, const ProgressFn& progress = {});

// Δ's d_max for a grid: params.dmax, or the grid's diagonal.
double dmax_for(const Grid& grid, const FillParams& params);

}  // namespace mcmd
