#include "chunk_fill.hpp"

#include <climits>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arguments.hpp"
#include "array_fill.hpp"
#include "cli/error_log.hpp"
#include "lib/band_access.hpp"
#include "lib/fill_band.hpp"
#include "lib/errors.hpp"
#include "lib/void_cap.hpp"
#include "mcmd/chunked_fill.hpp"
#include "mcmd/fill_raster.hpp"

namespace py = pybind11;

namespace mcmd::python {

namespace {

TilingParams tiling_for(const gdal::Options& o) {
  TilingParams t = gdal::tiling_of(o);
  t.always_tile = true;  // the chunked fill is the tiled fill
  t.max_void_cells = gdal::void_cap_cells(o, nullptr);  // an array has no cell size: cells only
  return t;
}

CellRect rect_of(const std::tuple<int, int, int, int>& r) {
  return CellRect{std::get<0>(r), std::get<1>(r), std::get<2>(r), std::get<3>(r)};
}

// A block of the raster in memory, at (x0, y0) of a width × height raster,
// seen through the CLI's band access in the raster's coordinates.
class Block {
 public:
  Block(py::array& cells, const std::optional<py::array>& valid, const std::string& gdal_type,
        const py::object& nodata, std::pair<int, int> origin, std::pair<int, int> raster_size)
      : x0_(origin.first), y0_(origin.second) {
    if (cells.ndim() != 2 || !(cells.flags() & py::array::c_style) || !cells.dtype().attr("isnative").cast<bool>())
      throw std::invalid_argument("a block must be a C-contiguous 2-D array in native byte order");
    if (cells.shape(0) > INT_MAX || cells.shape(1) > INT_MAX) throw std::invalid_argument("the block is too large");
    raster_ = memory_raster(gdal_type.c_str(), cells.mutable_data(), static_cast<int>(cells.shape(1)),
                            static_cast<int>(cells.shape(0)));
    if (valid && (valid->ndim() != 2 || valid->shape(0) != cells.shape(0) || valid->shape(1) != cells.shape(1) ||
                  valid->itemsize() != 1 || !(valid->flags() & py::array::c_style)))
      throw std::invalid_argument("a block's mask must be C-contiguous uint8 of the block's shape");
    band_.emplace(raster_, valid ? static_cast<const std::uint8_t*>(valid->data()) : nullptr,
                  nodata_of(nodata, raster_.type));
    access_.emplace(band_->band(), band_->band(), band_->request());
    local_ = access_->access();
    global_.width = raster_size.first;
    global_.height = raster_size.second;
    global_.read = [this](int x, int y, int w, int h, double* z, std::uint8_t* v) {
      check(x, y, w, h);
      local_.read(x - x0_, y - y0_, w, h, z, v);
    };
    global_.write = [this](int x, int y, int w, int h, const double* z, const std::uint8_t* m) {
      check(x, y, w, h);
      local_.write(x - x0_, y - y0_, w, h, z, m);
    };
  }
  const RasterAccess& access() const { return global_; }
  GDALDataType type() const { return raster_.type; }

 private:
  void check(int x, int y, int w, int h) const {
    if (x < x0_ || y < y0_ || x + w > x0_ + raster_.width || y + h > y0_ + raster_.height)
      throw std::logic_error("the chunked fill asked for cells outside its block");
  }
  int x0_, y0_;
  MemoryRaster raster_;
  std::optional<MemoryBand> band_;
  std::optional<gdal::BandAccess> access_;
  RasterAccess local_, global_;
};

template <class T>
py::array_t<T> to_numpy(std::vector<T>&& v) {
  auto* held = new std::vector<T>(std::move(v));
  py::capsule owner(held, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>({static_cast<py::ssize_t>(held->size())}, {sizeof(T)}, held->data(), owner);
}

template <class T>
std::vector<T> from_numpy(const py::handle& h) {
  const auto a = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(h);
  if (!a) throw std::invalid_argument("expected a numeric array");
  return std::vector<T>(a.data(), a.data() + a.size());
}

py::dict summary_dict(ChunkSummary&& s) {
  py::dict d;
  d["own"] = py::make_tuple(s.own.x0, s.own.y0, s.own.w, s.own.h);
  d["lattice"] = py::make_tuple(s.i0, s.i1, s.j0, s.j1);
  d["moments"] = to_numpy(std::move(s.moments));
  d["known"] = s.known;
  d["voids"] = s.voids;
  d["lo"] = s.lo;
  d["hi"] = s.hi;
  d["void_runs"] = to_numpy(std::move(s.void_runs));
  return d;
}

ChunkSummary summary_of(const py::dict& d) {
  ChunkSummary s;
  s.own = rect_of(d["own"].cast<std::tuple<int, int, int, int>>());
  std::tie(s.i0, s.i1, s.j0, s.j1) = d["lattice"].cast<std::tuple<int, int, int, int>>();
  s.moments = from_numpy<double>(d["moments"]);
  s.known = d["known"].cast<std::size_t>();
  s.voids = d["voids"].cast<std::size_t>();
  s.lo = d["lo"].cast<double>();
  s.hi = d["hi"].cast<double>();
  s.void_runs = from_numpy<int>(d["void_runs"]);
  return s;
}

// A chunk's solution as one flat byte array (it crosses processes: one
// buffer pickles without a copy and parses without Python objects):
// counts, then per window tx ty x0 x1 y0 y1 (int32), its runs (int32) and
// z (double), per component its index (uint64), box (int32) and values.
class Writer {
 public:
  template <class T>
  void put(const T& v) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(&v);
    bytes.insert(bytes.end(), p, p + sizeof(T));
  }
  template <class T>
  void put_all(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    const auto* p = reinterpret_cast<const std::uint8_t*>(v.data());
    bytes.insert(bytes.end(), p, p + v.size() * sizeof(T));
  }
  std::vector<std::uint8_t> bytes;
};

class Reader {
 public:
  Reader(const std::uint8_t* p, std::size_t n) : p_(p), end_(p + n) {}
  template <class T>
  T get() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, p_, sizeof(T));
    p_ += sizeof(T);
    return v;
  }
  template <class T>
  std::vector<T> get_all() {
    const auto n = get<std::uint64_t>();
    if (n > static_cast<std::uint64_t>(end_ - p_) / sizeof(T)) throw std::invalid_argument("a truncated solution");
    std::vector<T> v(n);
    std::memcpy(v.data(), p_, n * sizeof(T));
    p_ += n * sizeof(T);
    return v;
  }

 private:
  void need(std::size_t n) const {
    if (static_cast<std::size_t>(end_ - p_) < n) throw std::invalid_argument("a truncated solution");
  }
  const std::uint8_t* p_;
  const std::uint8_t* end_;
};

py::array_t<std::uint8_t> solution_bytes(const ChunkSolution& s) {
  std::size_t size = 2 * sizeof(std::uint64_t);
  for (const WindowSolution& win : s.windows)
    size += 6 * sizeof(std::int32_t) + 2 * sizeof(std::uint64_t) + win.runs.size() * sizeof(std::int32_t) +
            win.z.size() * sizeof(double);
  for (const ComponentSolution& c : s.components)
    size += 2 * sizeof(std::uint64_t) + 4 * sizeof(std::int32_t) + c.values.size() * sizeof(double);
  Writer w;
  w.bytes.reserve(size);  // one allocation: solutions run to megabytes
  w.put<std::uint64_t>(s.windows.size());
  w.put<std::uint64_t>(s.components.size());
  for (const WindowSolution& win : s.windows) {
    for (const int v : {win.tx, win.ty, win.x0, win.x1, win.y0, win.y1}) w.put<std::int32_t>(v);
    w.put_all(win.runs);
    w.put_all(win.z);
  }
  for (const ComponentSolution& c : s.components) {
    w.put<std::uint64_t>(c.index);
    for (const int v : {c.x0, c.y0, c.x1, c.y1}) w.put<std::int32_t>(v);
    w.put_all(c.values);
  }
  return to_numpy(std::move(w.bytes));
}

ChunkSolution solution_of(const py::handle& h) {
  const auto a = py::array_t<std::uint8_t, py::array::c_style>::ensure(h);
  if (!a) throw std::invalid_argument("a solution must be a uint8 array");
  Reader r(a.data(), static_cast<std::size_t>(a.size()));
  ChunkSolution s;
  s.windows.resize(r.get<std::uint64_t>());
  s.components.resize(r.get<std::uint64_t>());
  for (WindowSolution& w : s.windows) {
    for (int* v : {&w.tx, &w.ty, &w.x0, &w.x1, &w.y0, &w.y1}) *v = r.get<std::int32_t>();
    w.runs = r.get_all<std::int32_t>();
    w.z = r.get_all<double>();
  }
  for (ComponentSolution& c : s.components) {
    c.index = r.get<std::uint64_t>();
    for (int* v : {&c.x0, &c.y0, &c.x1, &c.y1}) *v = r.get<std::int32_t>();
    c.values = r.get_all<double>();
  }
  return s;
}

struct Plan {
  int width, height;
  std::unique_ptr<ChunkedPlan> plan;
};

}  // namespace

void register_chunk_fill(py::module_& m) {
  m.def(
      "chunk_grid",
      [](int width, int height, const std::vector<std::string>& options) {
        const gdal::Options o = parse_options(options);
        const ChunkGrid g = chunk_grid(width, height, tiling_for(o), o.fill.method);
        return py::make_tuple(g.step, g.min_side, g.margin, g.whole);
      },
      py::arg("width"), py::arg("height"), py::arg("options"),
      "(step, min_side, margin, whole): chunk sides are multiples of step, at least min_side; blocks are read "
      "with margin cells around a chunk; whole: the raster must be one chunk.");
  m.def(
      "fills_whole",
      [](int width, int height, const std::vector<std::string>& options) {
        const gdal::Options o = parse_options(options);
        return fills_whole(width, height, o.fill, gdal::tiling_of(o));
      },
      py::arg("width"), py::arg("height"), py::arg("options"),
      "Whether the CLI fills such a raster whole rather than through tiles.");
  m.def(
      "max_void_cells",
      [](const std::vector<std::string>& options, const std::string& path) {
        const gdal::Options o = parse_options(options);
        cli::ErrorLog log;
        cli::DatasetPtr ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY));
        if (!ds) throw gdal::Failure(CPLE_OpenFailed, "cannot open '" + path + "'");
        return gdal::void_cap_cells(o, ds.get());
      },
      py::arg("options"), py::arg("path"),
      "MAX_VOID in cells of the raster at `path` (an area converted as the CLI converts it); 0: no cap.");
  m.def(
      "summarize_chunk",
      [](py::array block, std::optional<py::array> valid, const std::string& gdal_type, py::object nodata,
         const std::vector<std::string>& options, std::pair<int, int> origin, std::pair<int, int> raster_size,
         std::tuple<int, int, int, int> own) {
        const gdal::Options o = parse_options(options);
        const TilingParams tiling = tiling_for(o);
        cli::ErrorLog log;
        Block b(block, valid, gdal_type, nodata, origin, raster_size);
        ChunkSummary s;
        {
          const py::gil_scoped_release nogil;
          s = summarize_chunk(b.access(), tiling, o.fill.method, rect_of(own));
        }
        return summary_dict(std::move(s));
      },
      py::arg("block"), py::arg("valid"), py::arg("gdal_type"), py::arg("nodata"), py::arg("options"),
      py::arg("origin"), py::arg("raster_size"), py::arg("own"), "Step 1: a chunk's summary (a dict).");
  py::class_<Plan>(m, "ChunkedPlan", "Step 2: the plan, from every chunk's summary.")
      .def(py::init([](int width, int height, const std::string& gdal_type, const std::vector<std::string>& options,
                       const py::list& summaries) {
             const gdal::Options o = parse_options(options);
             std::vector<ChunkSummary> parts;
             for (const py::handle& h : summaries) parts.push_back(summary_of(h.cast<py::dict>()));
             const MemoryRaster type = memory_raster(gdal_type.c_str(), nullptr, 1, 1);
             const py::gil_scoped_release nogil;
             return Plan{width, height,
                         std::make_unique<ChunkedPlan>(width, height, gdal::fill_params(o, type.type), tiling_for(o),
                                                       parts)};
           }),
           py::arg("width"), py::arg("height"), py::arg("gdal_type"), py::arg("options"), py::arg("summaries"))
      .def_property_readonly("has_voids", [](const Plan& p) { return p.plan->has_voids(); })
      .def_property_readonly("known_cells", [](const Plan& p) { return p.plan->known_cells(); })
      .def_property_readonly("void_cells", [](const Plan& p) { return p.plan->void_cells(); });
  m.def(
      "solve_chunk",
      [](const Plan& plan, py::array block, std::optional<py::array> valid, const std::string& gdal_type,
         py::object nodata, std::pair<int, int> origin, std::tuple<int, int, int, int> own) {
        cli::ErrorLog log;
        Block b(block, valid, gdal_type, nodata, origin, {plan.width, plan.height});
        ChunkSolution s;
        {
          const py::gil_scoped_release nogil;
          s = solve_chunk(b.access(), *plan.plan, rect_of(own));
        }
        return solution_bytes(s);
      },
      py::arg("plan"), py::arg("block"), py::arg("valid"), py::arg("gdal_type"), py::arg("nodata"),
      py::arg("origin"), py::arg("own"), "Step 3: the windows and small voids a chunk owns, solved.");
  m.def(
      "solution_part",
      [](const py::handle& solution, std::tuple<int, int, int, int> other) {
        ChunkSolution s = solution_of(solution);
        ChunkSolution part;
        {
          const py::gil_scoped_release nogil;
          part = solution_part(s, rect_of(other));
        }
        return solution_bytes(part);
      },
      py::arg("solution"), py::arg("other"), "The part of a chunk's solution that chunk `other`'s blend needs.");
  m.def(
      "blend_chunk",
      [](const Plan& plan, py::array out, std::optional<py::array> valid, const std::string& gdal_type,
         py::object nodata, std::tuple<int, int, int, int> own, const py::list& around) {
        std::vector<ChunkSolution> solutions;
        for (const py::handle& h : around) solutions.push_back(solution_of(h));
        std::vector<const ChunkSolution*> pointers;
        for (const ChunkSolution& s : solutions) pointers.push_back(&s);
        const CellRect r = rect_of(own);
        cli::ErrorLog log;
        Block b(out, valid, gdal_type, nodata, {r.x0, r.y0}, {plan.width, plan.height});
        const py::gil_scoped_release nogil;
        blend_chunk(b.access(), *plan.plan, pointers, r);
      },
      py::arg("plan"), py::arg("out"), py::arg("valid"), py::arg("gdal_type"), py::arg("nodata"), py::arg("own"),
      py::arg("around"), "Step 4: fill `out` (the chunk's cells, in place) from the solutions around it.");
}

}  // namespace mcmd::python
