#include "thin_plate/multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "thin_plate/biharmonic_relax.hpp"
#include "thin_plate/cubic_prolong.hpp"

namespace mcmd {

namespace {

// fn(i0, n) for the cells [i0, i0 + n) of every span, on `threads` threads
// (each span's cells are independent of the others').
template <class Fn>
void for_spans(const Lattice& lat, int threads, Fn fn) {
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(lat.spans.size());
  threads = team(lat, threads);
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (std::ptrdiff_t k = 0; k < count; ++k) {
    const Span& sp = lat.spans[static_cast<std::size_t>(k)];
    fn(lat.index(sp.x0, sp.y), sp.x1 - sp.x0);
  }
}

// Two sums Σ fn(i0, n) over the spans at once (fn returns a pair), each
// summed per fixed chunk of spans and then in chunk order: the same bits for
// any thread count.
template <class Fn>
std::pair<double, double> sum2_spans(const Lattice& lat, int threads, Fn fn) {
  const std::size_t chunks = (lat.spans.size() + kSumChunkSpans - 1) / kSumChunkSpans;
  std::vector<std::pair<double, double>> part(chunks, {0.0, 0.0});
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(chunks);
  threads = team(lat, threads);
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1)
  for (std::ptrdiff_t c = 0; c < n; ++c) {
    const std::size_t end = std::min(lat.spans.size(), (static_cast<std::size_t>(c) + 1) * kSumChunkSpans);
    double a = 0.0, b = 0.0;
    for (std::size_t k = static_cast<std::size_t>(c) * kSumChunkSpans; k < end; ++k) {
      const Span& sp = lat.spans[k];
      const auto [sa, sb] = fn(lat.index(sp.x0, sp.y), sp.x1 - sp.x0);
      a += sa;
      b += sb;
    }
    part[static_cast<std::size_t>(c)] = {a, b};
  }
  std::pair<double, double> total{0.0, 0.0};
  for (const auto& [a, b] : part) total.first += a, total.second += b;
  return total;
}

// One such sum (the second is 0 throughout: it adds nothing to the time).
template <class Fn>
double sum_spans(const Lattice& lat, int threads, Fn fn) {
  return sum2_spans(lat, threads, [&fn](std::size_t i0, int n) { return std::pair{fn(i0, n), 0.0}; }).first;
}

// Zero `v` over the free cells of `lat`.
void zero_free(const Lattice& lat, std::vector<double>& v) {
  for (const Span& sp : lat.spans)
    std::fill(v.begin() + static_cast<std::ptrdiff_t>(lat.index(sp.x0, sp.y)),
              v.begin() + static_cast<std::ptrdiff_t>(lat.index(sp.x1, sp.y)), 0.0);
}

// Coarse columns [first, last] that fine columns [x0, x1) interpolate from or restrict to.
std::pair<int, int> coarse_columns(int x0, int x1, int mw) {
  return {std::max(0, x0 / 2 - 1), std::min(mw - 1, x1 / 2 + 1)};
}

// row += scale · Pᵀ rr along x for the cells [x0, x1) of one fine row, cell by
// cell in increasing x (that order fixes the bits). Kept scalar: vectorised,
// each odd cell's 2-wide stores were re-read misaligned by the next odd cell
// and stalled store forwarding (60 % of the restriction's time).
__attribute__((optimize("no-tree-vectorize", "no-tree-slp-vectorize")))
void restrict_span(const double* rr, int x0, int x1, double scale, int mw, double* row) {
  for (int x = x0; x < x1; ++x) {
    const double v = scale * rr[x];
    if ((x & 1) == 0) {  // a coarse cell's own position: weight 1
      row[x / 2] += v;
      continue;
    }
    const Weights1D w = cubic_weights_1d(x, mw);
    for (int i = 0; i < w.count; ++i) row[w.first + i] += w.w[i] * v;
  }
}

// b = scale · Pᵀ (rhs - A z) over the free cells of `fine`, separably: the
// residual of one fine row is restricted along x into `row`, which is then
// spread along y into b. Only b's free cells are set (pinned ones are never
// read), and only columns near free cells are touched: the cost follows the
// free cells, not the lattice.
void restrict_residual(const Lattice& fine, const double* rhs, double scale, const Lattice& coarse,
                       std::vector<double>& row, std::vector<double>& b, std::vector<double>& res, int threads) {
  const int mw = coarse.w, mh = coarse.h;
  zero_free(coarse, b);
  int lo = mw, hi = -1;  // columns of `row` in use
  const auto flush = [&](int y) {
    const Weights1D w = cubic_weights_1d(y, mh);
    for (int j = 0; j < w.count; ++j) {
      double* brow = b.data() + static_cast<std::ptrdiff_t>(w.first + j) * mw;
      for (int c = lo; c <= hi; ++c) brow[c] += w.w[j] * row[c];
    }
    if (hi >= lo) std::fill(row.begin() + lo, row.begin() + hi + 1, 0.0);
    lo = mw;
    hi = -1;
  };
  res.resize(fine.z.size());
  residual(fine, rhs, res, threads);
  int current = -1;
  for (const Span& sp : fine.spans) {
    if (sp.y != current && current >= 0) flush(current);
    current = sp.y;
    const auto [c0, c1] = coarse_columns(sp.x0, sp.x1, mw);
    lo = std::min(lo, c0);
    hi = std::max(hi, c1);
    restrict_span(res.data() + fine.index(0, sp.y), sp.x0, sp.x1, scale, mw, row.data());
  }
  if (current >= 0) flush(current);
}

// fine.z += P e at the free cells, separably (along y into one row, then x),
// each run interpolating only the coarse columns it needs (runs are
// independent: any thread count).
void add_correction(Lattice& fine, const Lattice& coarse, int threads) {
  const int mw = coarse.w, mh = coarse.h;
  const std::ptrdiff_t count = static_cast<std::ptrdiff_t>(fine.spans.size());
  threads = team(fine, threads);
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    std::vector<double> row(static_cast<std::size_t>(mw), 0.0);
#pragma omp for schedule(static)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      const Span& sp = fine.spans[static_cast<std::size_t>(k)];
      const Weights1D wy = cubic_weights_1d(sp.y, mh);
      const auto [c0, c1] = coarse_columns(sp.x0, sp.x1, mw);
      std::fill(row.begin() + c0, row.begin() + c1 + 1, 0.0);
      for (int j = 0; j < wy.count; ++j) {
        const double* e = coarse.z.data() + static_cast<std::ptrdiff_t>(wy.first + j) * mw;
        for (int c = c0; c <= c1; ++c) row[c] += wy.w[j] * e[c];
      }
      double* z = fine.z.data() + fine.index(0, sp.y);
      for (int x = sp.x0; x < sp.x1; ++x) {
        if ((x & 1) == 0) {
          z[x] += row[x / 2];
          continue;
        }
        const Weights1D w = cubic_weights_1d(x, mw);
        double v = 0.0;
        for (int i = 0; i < w.count; ++i) v += w.w[i] * row[w.first + i];
        z[x] += v;
      }
    }
  }
}

// 4·Pᵀ v over every fine cell (pinned ones too), separably: along x into one
// coarse row, then spread along y. For v = s on every cell it is 16·s.
std::vector<double> restrict_all(const std::vector<double>& v, int fw, int fh, int cw, int ch) {
  std::vector<double> out(static_cast<std::size_t>(cw) * ch, 0.0), row(static_cast<std::size_t>(cw));
  for (int fy = 0; fy < fh; ++fy) {
    std::fill(row.begin(), row.end(), 0.0);
    restrict_span(v.data() + static_cast<std::size_t>(fy) * fw, 0, fw, 4.0, cw, row.data());
    const Weights1D wy = cubic_weights_1d(fy, ch);
    for (int j = 0; j < wy.count; ++j) {
      double* o = out.data() + static_cast<std::size_t>(wy.first + j) * cw;
      for (int c = 0; c < cw; ++c) o[c] += wy.w[j] * row[c];
    }
  }
  return out;
}

// The next coarse lattice by CoarsePin::soft: pinned where its own position
// is a constraint; every other cell held by springs of the lumped Galerkin
// form 4·Σ_f P_fc·s_f, s_f = `pin` at the fine pinned cells and the fine
// cell's own spring elsewhere (so the pull keeps its 16·s per level over
// free cells, as with the other rules).
Lattice soft_coarser_lattice(const Lattice& fine, double pin) {
  Lattice c = coarser_lattice(fine, CoarsePin::position);
  std::vector<double> s(fine.z.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    s[i] = fine.pinned[i] ? pin : (fine.spring.empty() ? fine.spring_all : fine.spring[i]);
  c.spring = restrict_all(s, fine.w, fine.h, c.w, c.h);
  for (double& v : c.spring) v = std::max(v, 0.0);  // the cubic's negative taps at a border
  return c;
}

}  // namespace

Multigrid::Multigrid(const Lattice& finest, VCycleSchedule schedule) : schedule_(schedule) {
  const Lattice* fine = &finest;
  std::vector<Lattice> chain;
  while ((fine->w > 2 || fine->h > 2) && std::max(fine->w, fine->h) > schedule_.coarsest_side) {
    // The pull (one spring on every free cell) is part of each correction's
    // problem too: 4·Pᵀ(s·I)P ≈ 16·s·I on unit lattices, where the
    // fourth-order term only keeps its form. Without it a coarse correction
    // is too soft for the smooth modes the pull holds deep inside large voids
    // and overshoots: the 4801² blob mosaic took 8.1 CG iterations per
    // unknown cell, 6.9 with it (docs/default-method.md, Multigrid). Read
    // before push_back, which may move the lattice `fine` points to.
    const double spring = fine->spring.empty() ? 16.0 * fine->spring_all : 0.0;
    if (schedule_.coarse_pin == CoarsePin::soft) {
      chain.push_back(soft_coarser_lattice(*fine, schedule_.soft_pin_spring));
    } else {
      chain.push_back(coarser_lattice(*fine, schedule_.coarse_pin));
      chain.back().spring_all = spring;
    }
    fine = &chain.back();
  }
  // chain was built fine to coarse; index it coarse to fine.
  coarse_.assign(std::make_move_iterator(chain.rbegin()), std::make_move_iterator(chain.rend()));
  // Corrections are 0 at pinned cells; cycles then only ever clear free ones.
  for (Lattice& c : coarse_) std::fill(c.z.begin(), c.z.end(), 0.0);
  rhs_.resize(coarse_.size());
  for (std::size_t k = 0; k < coarse_.size(); ++k) rhs_[k].assign(coarse_[k].z.size(), 0.0);
  res_.resize(coarse_.size());
}

void Multigrid::v_cycle(Lattice& finest) { cycle(finest, nullptr, static_cast<int>(coarse_.size()) - 1); }

// `k` indexes the coarse lattice below `fine` (-1: none, solve by sweeping).
void Multigrid::cycle(Lattice& fine, const double* rhs, int k) {
  const int threads = schedule_.threads;
  if (k < 0) {
    relax(fine, rhs, schedule_.coarsest_sweeps, 1.0, threads);
    return;
  }
  relax(fine, rhs, schedule_.pre_sweeps, 1.0, threads);
  Lattice& coarse = coarse_[k];
  if (coarse.spans.empty()) {  // nothing free below: smoothing is all we can do
    relax(fine, rhs, schedule_.post_sweeps, 1.0, threads);
    return;
  }
  // Coarse right-hand side 4·Pᵀr: on unit lattices Pᵀ A_h P ≈ A_2h / 4 for the
  // 4th-order thin-plate operator (column sums of P are 4, h⁴ scaling 1/16).
  std::vector<double> row(coarse.w);
  restrict_residual(fine, rhs, 4.0, coarse, row, rhs_[k], res_[k], threads);

  zero_free(coarse, coarse.z);
  cycle(coarse, rhs_[k].data(), k - 1);

  add_correction(fine, coarse, threads);
  relax(fine, rhs, schedule_.post_sweeps, 1.0, threads);
}

namespace {

double dot_free(const Lattice& lat, const std::vector<double>& a, const std::vector<double>& b, int threads) {
  return sum_spans(lat, threads, [&](std::size_t i0, int n) {
    double s = 0.0;
    for (int t = 0; t < n; ++t) s += a[i0 + t] * b[i0 + t];
    return s;
  });
}

}  // namespace

int Multigrid::solve_pcg(Lattice& finest, double rel_tol, int max_iterations, const ProgressFn& progress,
                         const StructureTerm* extra) {
  if (finest.spans.empty()) return 0;
  const int threads = schedule_.threads;
  const int top = static_cast<int>(coarse_.size()) - 1;
  const std::size_t cells = finest.z.size();
  // r = -A z at the free cells (the problem is A z = 0 with pinned cells fixed).
  std::vector<double> r(cells, 0.0);
  residual(finest, nullptr, r, threads);
  if (extra) extra->subtract(finest, finest.z, r, threads);
  const double r0 = std::sqrt(dot_free(finest, r, r, threads));
  if (!(r0 > 0)) return 0;
  // Work lattice: the same free cells and springs (the error equation has
  // a target of 0). It owns no values: the vector a step works on is swapped
  // in and out, so no copy is made. Every vector below is 0 at pinned cells
  // and only ever written at free ones, as the V-cycle and A need.
  Lattice work;
  work.w = finest.w;
  work.h = finest.h;
  work.tension = finest.tension;
  work.pinned = finest.pinned;
  work.spans = finest.spans;
  if (!finest.spring.empty()) work.spring = finest.spring;
  work.spring_all = finest.spring_all;
  std::vector<double> zv(cells, 0.0), p(cells, 0.0), nq(cells, 0.0);
  const auto precondition = [&](const std::vector<double>& rhs, std::vector<double>& out) {  // out = M r
    for_spans(work, threads, [&](std::size_t i0, int n) { std::fill_n(out.begin() + i0, n, 0.0); });
    std::swap(work.z, out);
    cycle(work, rhs.data(), top);
    std::swap(work.z, out);
  };
  // out = -A v: the residual of v with no right-hand side. The iteration
  // below is written with q = -out (α, β and r as usual, the same bits):
  // no pass to negate it.
  const auto apply_negated = [&](std::vector<double>& v, std::vector<double>& out) {
    std::swap(work.z, v);
    residual(work, nullptr, out, threads);
    std::swap(work.z, v);
    if (extra) extra->subtract(work, v, out, threads);
  };
  precondition(r, zv);
  for_spans(work, threads, [&](std::size_t i0, int n) { std::copy_n(zv.begin() + i0, n, p.begin() + i0); });
  double rz = dot_free(finest, r, zv, threads);
  int it = 0;
  while (it < max_iterations) {
    apply_negated(p, nq);
    const double pq = -dot_free(finest, p, nq, threads);
    if (!(pq > 0)) break;
    const double alpha = rz / pq;
    // z += α p, r -= α q, and |r|² in the same pass (summed as dot_free sums).
    const double rr = sum_spans(finest, threads, [&](std::size_t i0, int n) {
      double s = 0.0;
      for (int t = 0; t < n; ++t) {
        finest.z[i0 + t] += alpha * p[i0 + t];
        r[i0 + t] += alpha * nq[i0 + t];
        s += r[i0 + t] * r[i0 + t];
      }
      return s;
    });
    ++it;
    report(progress, static_cast<double>(it) / max_iterations);
    if (std::sqrt(rr) <= rel_tol * r0 || it == max_iterations) break;  // no V-cycle for a step not taken
    precondition(r, zv);
    // Polak-Ribière β = zᵀ(r - r_old) / rz (the V-cycle is not symmetric),
    // with r - r_old = -α q: no copy of the old residual. zᵀq and the new
    // rz in one pass.
    const auto [zq, rz_next] = sum2_spans(finest, threads, [&](std::size_t i0, int n) {
      double a = 0.0, b = 0.0;
      for (int t = 0; t < n; ++t) {
        a += zv[i0 + t] * nq[i0 + t];
        b += r[i0 + t] * zv[i0 + t];
      }
      return std::pair{a, b};
    });
    const double num = alpha * zq;
    const double beta = rz > 0 ? num / rz : 0.0;
    rz = rz_next;
    for_spans(finest, threads, [&](std::size_t i0, int n) {
      for (int t = 0; t < n; ++t) p[i0 + t] = zv[i0 + t] + beta * p[i0 + t];
    });
  }
  return it;
}

}  // namespace mcmd
