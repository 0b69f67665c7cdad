// A Python progress callback as the fill sees it (mcmd::ProgressFn), called
// with the GIL released: each call that reaches Python takes the GIL back,
// runs the callback, then Python's signal handlers (Ctrl-C). A False return,
// an exception or a KeyboardInterrupt stops the fill.
#pragma once

#include <chrono>
#include <optional>

#include <pybind11/pybind11.h>

#include "mcmd/progress.hpp"

namespace mcmd::python {

class PythonProgress {
 public:
  // `callback`: None, or callable(fraction) -> bool | None (False cancels).
  explicit PythonProgress(pybind11::object callback);
  PythonProgress(const PythonProgress&) = delete;
  PythonProgress& operator=(const PythonProgress&) = delete;

  // false = stop. Calls into Python at most every kMinInterval (and at the
  // first and last report): taking the GIL from a busy thread costs up to
  // its switch interval (5 ms).
  bool operator()(double fraction);

  // The ProgressFn calling this object; valid while it lives.
  ProgressFn as_fn() { return [this](double f) { return (*this)(f); }; }

  // With the GIL held, after a fill that threw: raises (as
  // pybind11::error_already_set) the Python exception that stopped it, if any.
  void raise_pending();

 private:
  static constexpr std::chrono::milliseconds kMinInterval{100};
  bool call_python(double fraction);

  pybind11::object callback_;
  std::optional<pybind11::error_already_set> pending_;
  std::optional<std::chrono::steady_clock::time_point> last_;
};

}  // namespace mcmd::python
