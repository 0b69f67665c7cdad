// The CLIs' OpenMP wait policy: passive (a worker sleeps as soon as it has
// no work) unless the user chose one.
//
// libgomp's default lets each worker spin ~300 000 times at the end of a
// parallel region before it sleeps. The fill runs many short regions (a
// multigrid's sweeps on small levels, one field after another), so on a
// busy machine the spinning took the cores from the work: a 513² 3.3 %-kept
// fill cost 0.36 s of CPU against 0.16 s passive (or with -threads 1); on a
// long fill (the 4801² mosaic) the two are within the noise.
// Measurements: docs/tiling.md, "Order of work, threads, determinism".
//
// libgomp reads OMP_WAIT_POLICY once, with getenv(), in its library
// constructor, before main() and before any constructor of the executable.
// Setting the variable in time is not possible: glibc sets `environ` only
// after the executable's .preinit_array has run (a setenv() there is lost).
// So the executable gives getenv() a default instead: its getenv() is
// glibc's (a scan of `environ`), except that OMP_WAIT_POLICY reads PASSIVE
// when the environment has neither it nor GOMP_SPINCOUNT (a spin count of
// the user's own decides alone). Being the executable's, this getenv()
// is the one every library of the process calls (ELF symbol lookup starts
// at the executable); glibc's own internal reads are unaffected, and so is
// the environment children inherit. Only the executables carry it: the C
// API library leaves its host's environment alone.
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <unistd.h>

namespace {

char* find_variable(const char* name) {
  const std::size_t n = std::strlen(name);
  if (environ == nullptr || n == 0) return nullptr;
  for (char** e = environ; *e != nullptr; ++e) {
    if (std::strncmp(*e, name, n) == 0 && (*e)[n] == '=') return *e + n + 1;
  }
  return nullptr;
}

char kPassive[] = "PASSIVE";

}  // namespace

// Default visibility: the build hides symbols, and a hidden getenv() would
// replace nobody's.
extern "C" [[gnu::visibility("default")]] char* getenv(const char* name) noexcept {
  char* value = find_variable(name);
  if (value == nullptr && std::strcmp(name, "OMP_WAIT_POLICY") == 0 && find_variable("GOMP_SPINCOUNT") == nullptr)
    return kPassive;
  return value;
}
