#include "paper/line.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "paper/mdbu.hpp"
#include "paper/midpoint_displacement.hpp"
#include "roughness/noise.hpp"

namespace mcmd {

namespace {

struct LineTopology {
  int n;

  template <class F>
  void for_each_parent(std::uint32_t i, F visit) const {
    const std::uint32_t v = i | (1u << n);
    const std::uint32_t h = v & (~v + 1u);
    if (h == (1u << n)) return;  // an end of the line: a root
    visit(i - h);
    visit(i + h);
  }
  double distance(std::uint32_t a, std::uint32_t b) const { return std::fabs(double(a) - double(b)); }
};

int line_levels(std::size_t size) {
  if (size < 2 || !std::has_single_bit(size - 1)) throw std::invalid_argument("a line must have 2^n + 1 cells");
  return std::countr_zero(size - 1);
}

std::vector<std::uint8_t> fixed_from(const std::vector<CellState>& s) {
  std::vector<std::uint8_t> fixed(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) fixed[i] = is_constraint(s[i]) ? 1 : 0;
  return fixed;
}

// Top-down pass on a line, as midpoint_displacement does on a grid.
void top_down(std::vector<double>& z, const std::vector<CellState>& s, std::vector<std::uint8_t>& fixed,
              const FillParams& params, int n) {
  const std::uint32_t last = static_cast<std::uint32_t>(z.size() - 1);
  const std::array<std::uint32_t, 2> ends{0, last};
  seed_roots(z, fixed, ends);
  const double dmax = params.dmax > 0 ? params.dmax : static_cast<double>(last);
  const double unit = params.noise_unit > 0 ? params.noise_unit : known_range(z, s);
  for (int level = 0; level < n; ++level) {
    const std::uint32_t h = 1u << (n - 1 - level);
    for (std::uint32_t i = h; i < last; i += 2 * h) {
      if (fixed[i]) continue;
      const std::array<Contribution, 2> parts{{{z[i - h], double(h), shape_for(params, s[i - h]).I},
                                               {z[i + h], double(h), shape_for(params, s[i + h]).I}}};
      z[i] = combine(params.delta_form, parts, dmax);
      if (params.rs > 0)
        z[i] += double(h) / double(1u << (n - 1)) *
                paper_delta(params.seed, i, 0, level, 1, params.H, params.rt, params.rs) * unit;
      fixed[i] = 1;
    }
  }
}

}  // namespace

std::vector<double> line_md(const std::vector<double>& z, const std::vector<CellState>& s,
                            const FillParams& params) {
  const int n = line_levels(z.size());
  std::vector<double> out = z;
  auto fixed = fixed_from(s);
  top_down(out, s, fixed, params, n);
  return out;
}

std::vector<double> line_mcmd(const std::vector<double>& z, const std::vector<CellState>& s,
                              const FillParams& params) {
  const int n = line_levels(z.size());
  std::vector<double> out = z;
  auto fixed = fixed_from(s);
  const double dmax = params.dmax > 0 ? params.dmax : static_cast<double>(z.size() - 1);
  mdbu_waves(out, s, fixed, LineTopology{n}, params, dmax, n + 1);
  top_down(out, s, fixed, params, n);
  return out;
}

}  // namespace mcmd
