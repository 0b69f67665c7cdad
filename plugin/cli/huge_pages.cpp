// The CLI's global operator new: malloc, as the default one, but a large
// block is marked for transparent huge pages (madvise MADV_HUGEPAGE) before
// anything touches it. The solver's buffers (~120 bytes per field cell) are
// then faulted in 2 MiB at a time instead of 4 KiB: on the benchmark machine
// a 4 KiB fault costs ~2.5 µs, and a 1201² fill took ~47 000 of them (120 ms
// of system time). Where the kernel's THP mode is "never", or the block is
// already touched (malloc reusing freed memory), the advice changes nothing.
// Only the executable replaces operator new: the C API library leaves its
// host's allocator alone. Measurements: docs/default-method.md, session 10.
#include <cstdint>
#include <cstdlib>
#include <new>
#include <sys/mman.h>

namespace {

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// Below this a block holds no whole aligned huge page often enough to matter.
constexpr std::size_t kAdviseFrom = 2 * kHugePage;

void advise_huge_pages(void* p, std::size_t n) {
  const auto begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + n) & ~(kHugePage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);  // advice: errors ignored
}

}  // namespace

void* operator new(std::size_t n) {
  if (n == 0) n = 1;
  for (;;) {
    if (void* p = std::malloc(n)) {
      if (n >= kAdviseFrom) advise_huge_pages(p, n);
      return p;
    }
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

// The matching deletes, so that allocation checkers (valgrind) see malloc
// paired with free.
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
