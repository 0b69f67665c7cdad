#include "mcmd/multigrid.hpp"

#include <algorithm>

#include "mcmd/biharmonic_relax.hpp"
#include "mcmd/cubic_prolong.hpp"

namespace mcmd {

namespace {

// b = scale · Pᵀ (rhs - A z) over the free cells of `fine`, separably: the
// residual of one fine row is restricted along x into `row`, which is then
// spread along y into b. Zero at pinned coarse cells.
void restrict_residual(const Lattice& fine, const double* rhs, double scale, const Lattice& coarse,
                       std::vector<double>& row, std::vector<double>& b) {
  const int mc = coarse.side;
  std::fill(b.begin(), b.end(), 0.0);
  const auto flush = [&](int y) {
    const Weights1D w = cubic_weights_1d(y, mc);
    for (int j = 0; j < w.count; ++j) {
      double* brow = b.data() + static_cast<std::ptrdiff_t>(w.first + j) * mc;
      for (int c = 0; c < mc; ++c) brow[c] += w.w[j] * row[c];
    }
    std::fill(row.begin(), row.end(), 0.0);
  };
  std::fill(row.begin(), row.end(), 0.0);
  int current = -1;
  for (const Span& sp : fine.spans) {
    if (sp.y != current && current >= 0) flush(current);
    current = sp.y;
    for (int x = sp.x0; x < sp.x1; ++x) {
      const double v = scale * residual_at(fine, rhs, x, sp.y);
      const Weights1D w = cubic_weights_1d(x, mc);
      for (int i = 0; i < w.count; ++i) row[w.first + i] += w.w[i] * v;
    }
  }
  if (current >= 0) flush(current);
  for (std::size_t i = 0; i < b.size(); ++i)
    if (coarse.pinned[i]) b[i] = 0.0;
}

// fine.z += P e at the free cells, separably (along y into one row, then x).
void add_correction(Lattice& fine, const Lattice& coarse, std::vector<double>& row) {
  const int mc = coarse.side;
  int current = -1;
  for (const Span& sp : fine.spans) {
    if (sp.y != current) {
      current = sp.y;
      const Weights1D w = cubic_weights_1d(sp.y, mc);
      std::fill(row.begin(), row.end(), 0.0);
      for (int j = 0; j < w.count; ++j) {
        const double* e = coarse.z.data() + static_cast<std::ptrdiff_t>(w.first + j) * mc;
        for (int c = 0; c < mc; ++c) row[c] += w.w[j] * e[c];
      }
    }
    for (int x = sp.x0; x < sp.x1; ++x) {
      const Weights1D w = cubic_weights_1d(x, mc);
      double v = 0.0;
      for (int i = 0; i < w.count; ++i) v += w.w[i] * row[w.first + i];
      fine.z[fine.index(x, sp.y)] += v;
    }
  }
}

}  // namespace

Multigrid::Multigrid(const Lattice& finest, VCycleSchedule schedule) : schedule_(schedule) {
  const Lattice* fine = &finest;
  std::vector<Lattice> chain;
  while (fine->side > 2 && fine->side > schedule_.coarsest_side) {
    chain.push_back(coarser_lattice(*fine, schedule_.coarse_pin));
    fine = &chain.back();
  }
  // chain was built fine to coarse; index it coarse to fine.
  coarse_.assign(std::make_move_iterator(chain.rbegin()), std::make_move_iterator(chain.rend()));
  rhs_.resize(coarse_.size());
  for (std::size_t k = 0; k < coarse_.size(); ++k) rhs_[k].assign(coarse_[k].z.size(), 0.0);
}

void Multigrid::v_cycle(Lattice& finest) { cycle(finest, nullptr, static_cast<int>(coarse_.size()) - 1); }

// `k` indexes the coarse lattice below `fine` (-1: none, solve by sweeping).
void Multigrid::cycle(Lattice& fine, const double* rhs, int k) {
  if (k < 0) {
    relax(fine, rhs, schedule_.coarsest_sweeps);
    return;
  }
  relax(fine, rhs, schedule_.pre_sweeps);
  Lattice& coarse = coarse_[k];
  if (coarse.spans.empty()) {  // nothing free below: smoothing is all we can do
    relax(fine, rhs, schedule_.post_sweeps);
    return;
  }
  // Coarse right-hand side 4·Pᵀr: on unit lattices Pᵀ A_h P ≈ A_2h / 4 for the
  // 4th-order thin-plate operator (column sums of P are 4, h⁴ scaling 1/16).
  std::vector<double> row(coarse.side);
  restrict_residual(fine, rhs, 4.0, coarse, row, rhs_[k]);

  std::fill(coarse.z.begin(), coarse.z.end(), 0.0);
  cycle(coarse, rhs_[k].data(), k - 1);

  add_correction(fine, coarse, row);
  relax(fine, rhs, schedule_.post_sweeps);
}

}  // namespace mcmd
