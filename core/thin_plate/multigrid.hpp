// Multigrid V-cycles for the constrained thin-plate problem: free cells solve
// A z = rhs, pinned cells are Dirichlet.
#pragma once

#include <vector>

#include "mcmd/progress.hpp"
#include "thin_plate/lattice.hpp"
#include "thin_plate/structure_term.hpp"

namespace mcmd {

struct VCycleSchedule {
  int pre_sweeps = 2;      // Gauss-Seidel sweeps before the coarse correction
  int post_sweeps = 2;     // and after it
  int coarsest_side = 5;   // solve here by sweeping only
  int coarsest_sweeps = 60;
  CoarsePin coarse_pin = CoarsePin::soft;
  double soft_pin_spring = 5.0;  // CoarsePin::soft: the spring that stands for a fine pin
  int threads = 1;         // for banded lattices and span loops: any count gives the same bits
};

// Corrections live on coarser lattices whose pinned cells follow
// schedule.coarse_pin. With `position` a coarse problem misses the fine
// constraints between its lattice points, is softer than the fine one and its
// corrections overshoot (V-cycles diverged on scattered constraints);
// `neighbourhood` keeps it at least as stiff, but under scattered constraints
// pins most of every coarse lattice (3.3 % of cells kept: 26 % of the next
// level, 93 % of the one after), which then corrects nothing. `soft` (the
// default) pins positions only and stands for the other fine constraints with
// springs of the Galerkin form: every level corrects what it can. Its
// V-cycle overshoots as a plain iteration (use `neighbourhood` for v_cycle
// alone) but preconditions CG well: 3.3 %-kept Mt Washington reaches 1e-2 in
// 6 iterations instead of 9, blob voids in a third fewer
// (docs/default-method.md, Multigrid).
class Multigrid {
 public:
  Multigrid(const Lattice& finest, VCycleSchedule schedule);

  // One V-cycle on `finest` (the lattice given to the constructor, or one with
  // the same pinned cells): smooth, restrict the residual with the transpose of
  // the cubic prolongation, correct from the next coarser lattice (recursively,
  // zero at its pinned cells), add its cubic prolongation, smooth.
  void v_cycle(Lattice& finest);

  // Conjugate gradients on the free cells of `finest`, preconditioned by one
  // V-cycle per iteration (flexible form: β of Polak-Ribière, so the slightly
  // non-symmetric Gauss-Seidel V-cycle is harmless), until the residual's
  // 2-norm is below rel_tol times the starting one, or max_iterations.
  // Springs of `finest` (Lattice::spring, target) are part of the operator;
  // the coarse corrections ignore them (the preconditioner stays close
  // enough for weak springs). Dot products run over the spans in a fixed
  // order: deterministic.
  // `progress` is told each iteration (it / max_iterations): a cancel stops
  // the solve there (Cancelled).
  // `extra` (null: none) adds its term to the operator; the V-cycle still
  // preconditions the thin plate alone.
  // Returns the iterations done.
  int solve_pcg(Lattice& finest, double rel_tol, int max_iterations, const ProgressFn& progress = {},
                const StructureTerm* extra = nullptr);

 private:
  void cycle(Lattice& fine, const double* rhs, int k);

  VCycleSchedule schedule_;
  std::vector<Lattice> coarse_;                // coarse to fine, z = correction
  std::vector<std::vector<double>> rhs_;       // right-hand side of coarse_[k]
  std::vector<std::vector<double>> res_;       // residual of the lattice above coarse_[k]
};

}  // namespace mcmd
