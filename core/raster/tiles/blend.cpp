#include "raster/tiles/blend.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace mcmd {

Blender::Blender(const TileLayout& layout, BlockWriter write)
    : Blender(layout, std::move(write), Range{0, layout.x.length()}) {}

Blender::Blender(const TileLayout& layout, BlockWriter write, Range cols)
    : layout_(layout), write_(std::move(write)), cols_{std::max(0, cols.begin), std::min(layout.x.length(), cols.end)} {}

Blender::Strip& Blender::strip_for(int seam) {
  for (Strip* s : {&top_, &bottom_})
    if (s->seam == seam) return *s;
  Strip& s = top_.seam < 0 ? top_ : bottom_;
  if (s.seam >= 0) throw std::logic_error("Blender: results out of tile-row order");
  s.seam = seam;
  s.rows = layout_.y.seam_band(seam);
  const std::size_t cells = static_cast<std::size_t>(s.rows.size()) * cols_.size();
  s.z.assign(cells, 0.0);
  s.mask.assign(cells, 0);
  return s;
}

// Rows of a seam band: every column of the region gets w_x·w_y·F.
void Blender::add_to_strip(const WindowResult& r, int seam) {
  Strip& s = strip_for(seam);
  const Range rows = s.rows;
  const TileAxis& ay = layout_.y;
  const int W = cols_.size();
  const int rw = r.xs.size();
  const int xa = std::max(r.xs.begin, cols_.begin), xb = std::min(r.xs.end, cols_.end);
  for (int y = rows.begin; y < rows.end; ++y) {
    const double wy = ay.weight(r.ty, y);
    const bool own_row = ay.owner(y) == r.ty;
    double* sz = s.z.data() + static_cast<std::size_t>(y - s.rows.begin) * W;
    std::uint8_t* sm = s.mask.data() + static_cast<std::size_t>(y - s.rows.begin) * W;
    const double* fz = r.z.data() + static_cast<std::size_t>(y - r.ys.begin) * rw;
    const std::uint8_t* fm = r.write.data() + static_cast<std::size_t>(y - r.ys.begin) * rw;
    for (int x = xa; x < xb; ++x) {
      const int i = x - r.xs.begin;
      const int k = x - cols_.begin;
      sz[k] += (wx_[i] * wy) * fz[i];
      if (own_row && own_x_[i]) sm[k] = fm[i];
    }
  }
}

// Rows only this tile row covers: solo columns are final, the left seam band
// completes the previous tile's pending part, the right one becomes pending.
void Blender::add_solo_rows(const WindowResult& r) {
  const TileAxis& ax = layout_.x;
  const Range rows = layout_.y.solo(r.ty);
  if (rows.empty()) return;
  const Range right = r.tx + 1 < ax.count() ? ax.seam_band(r.tx + 1) : Range{r.xs.end, r.xs.end};
  const Range left = r.tx > 0 ? ax.seam_band(r.tx) : Range{r.xs.begin, r.xs.begin};
  const int rw = r.xs.size();
  const bool have_pending = pending_.tx == r.tx - 1 && pending_.ty == r.ty && pending_.rows.begin == rows.begin;

  // Final part: [xs.begin, right.begin) × rows.
  const int fw = right.begin - r.xs.begin;
  if (fw > 0) {
    zbuf_.resize(static_cast<std::size_t>(fw) * rows.size());
    mbuf_.resize(zbuf_.size());
    for (int y = rows.begin; y < rows.end; ++y) {
      const double* fz = r.z.data() + static_cast<std::size_t>(y - r.ys.begin) * rw;
      const std::uint8_t* fm = r.write.data() + static_cast<std::size_t>(y - r.ys.begin) * rw;
      double* oz = zbuf_.data() + static_cast<std::size_t>(y - rows.begin) * fw;
      std::uint8_t* om = mbuf_.data() + static_cast<std::size_t>(y - rows.begin) * fw;
      for (int x = r.xs.begin; x < right.begin; ++x) {
        const int i = x - r.xs.begin;
        if (x < left.end) {  // left seam band: previous tile's share + ours
          const int pi = (y - rows.begin) * pending_.cols.size() + (x - left.begin);
          const double mine = wx_[i] * fz[i];
          const bool own = own_x_[i] != 0;
          oz[i] = have_pending ? pending_.z[pi] + mine : mine;
          om[i] = own ? fm[i] : (have_pending ? pending_.mask[pi] : 0);
        } else {
          oz[i] = fz[i];
          om[i] = fm[i];
        }
      }
    }
    emit(r.xs.begin, rows.begin, fw, rows.size(), zbuf_.data(), mbuf_.data(), fw);
  }

  // Pending part: the right seam band, waiting for tile tx + 1.
  pending_.tx = r.tx;
  pending_.ty = r.ty;
  pending_.rows = rows;
  pending_.cols = right;
  pending_.z.assign(static_cast<std::size_t>(right.size()) * rows.size(), 0.0);
  pending_.mask.assign(pending_.z.size(), 0);
  for (int y = rows.begin; y < rows.end; ++y) {
    const double* fz = r.z.data() + static_cast<std::size_t>(y - r.ys.begin) * rw;
    const std::uint8_t* fm = r.write.data() + static_cast<std::size_t>(y - r.ys.begin) * rw;
    for (int x = right.begin; x < right.end; ++x) {
      const std::size_t pi = static_cast<std::size_t>(y - rows.begin) * right.size() + (x - right.begin);
      pending_.z[pi] = wx_[x - r.xs.begin] * fz[x - r.xs.begin];
      pending_.mask[pi] = own_x_[x - r.xs.begin] ? fm[x - r.xs.begin] : 0;
    }
  }
}

void Blender::columns_of(const WindowResult& r) {
  const TileAxis& ax = layout_.x;
  wx_.resize(static_cast<std::size_t>(r.xs.size()));
  own_x_.resize(wx_.size());
  for (int x = r.xs.begin; x < r.xs.end; ++x) {
    wx_[x - r.xs.begin] = ax.weight(r.tx, x);
    own_x_[x - r.xs.begin] = ax.owner(x) == r.tx;
  }
}

void Blender::add(const WindowResult& r) {
  const TileAxis& ay = layout_.y;
  columns_of(r);
  if (r.ty > 0) add_to_strip(r, r.ty);
  add_solo_rows(r);
  if (r.ty + 1 < ay.count()) add_to_strip(r, r.ty + 1);
}

void Blender::emit(int x0, int y0, int w, int h, const double* z, const std::uint8_t* mask, int stride) {
  if (w <= 0 || h <= 0) return;
  bool any = false;
  for (int y = 0; y < h && !any; ++y)
    any = std::any_of(mask + static_cast<std::size_t>(y) * stride, mask + static_cast<std::size_t>(y) * stride + w,
                      [](std::uint8_t m) { return m != 0; });
  if (!any) return;
  if (stride == w) {
    write_(x0, y0, w, h, z, mask);
    return;
  }
  std::vector<double> zc(static_cast<std::size_t>(w) * h);
  std::vector<std::uint8_t> mc(zc.size());
  for (int y = 0; y < h; ++y) {
    std::copy_n(z + static_cast<std::size_t>(y) * stride, w, zc.data() + static_cast<std::size_t>(y) * w);
    std::copy_n(mask + static_cast<std::size_t>(y) * stride, w, mc.data() + static_cast<std::size_t>(y) * w);
  }
  write_(x0, y0, w, h, zc.data(), mc.data());
}

// A finished seam band, written in chunks of one tile's own columns.
void Blender::flush_strip(Strip& s) {
  const TileAxis& ax = layout_.x;
  const int W = ax.length(), stride = cols_.size();
  for (int tx = 0; tx < ax.count(); ++tx) {
    const int x0 = std::max(cols_.begin, tx * ax.step());
    const int x1 = std::min(cols_.end, tx + 1 == ax.count() ? W : std::min(W, (tx + 1) * ax.step()));
    if (x0 >= x1) continue;
    const std::size_t at = static_cast<std::size_t>(x0 - cols_.begin);
    emit(x0, s.rows.begin, x1 - x0, s.rows.size(), s.z.data() + at, s.mask.data() + at, stride);
  }
  s = Strip{};
}

void Blender::end_row(int ty) {
  // The band of seam ty (above this tile row) has all its windows now.
  for (Strip* s : {&top_, &bottom_})
    if (s->seam == ty) flush_strip(*s);
  for (Strip* s : {&top_, &bottom_})
    if (s->seam >= 0 && s->seam <= ty) throw std::logic_error("Blender: tile rows ended out of order");
  pending_ = Pending{};
}

}  // namespace mcmd

