// The CLI's allocator: glibc's malloc, told to keep what is freed, and a
// global operator new on it.
//
// Kept memory: a tiled fill allocates and frees the same few-MB buffers for
// every window. By default glibc returns blocks above its mmap threshold
// (dynamic, at most 32 MiB) to the kernel on free and trims its arenas, so
// each window's buffers were faulted in and zeroed by the kernel again: 15 %
// of the 4801² blob fill's CPU samples were page faults. With blocks up to
// 32 MiB taken from the arenas and arenas trimmed only above 256 MiB free,
// the next window reuses them: 4801² and 10801×4801 blob mosaics ~0.1 s
// faster (system time 0.30 -> 0.20 s).
//
// One arena: by default each thread that allocates (the fill's workers,
// OpenMP's, GDAL's decode threads) gets its own arena, and each kept its own
// high-water mark: 45-75 MB more peak RSS on the mosaics and the half-void
// tile than one arena shared by all, for no measurable time (the solver's
// allocations are few and large).
//
// operator new: malloc, as the default one, but a large block is marked for
// transparent huge pages (madvise MADV_HUGEPAGE) before anything touches it.
// The solver's buffers (~120 bytes per field cell) are then faulted in 2 MiB
// at a time instead of 4 KiB: on the benchmark machine a 4 KiB fault costs
// ~2.5 µs, and a 1201² fill took ~47 000 of them (120 ms of system time). Where the kernel's THP mode is "never", or the block is
// already touched (malloc reusing freed memory), the advice changes nothing.
// Only the executable replaces operator new: the C API library leaves its
// host's allocator alone (and so do these malloc settings). Measurements:
// docs/tiling.md, "The plugin's I/O".
//
// The whole family is replaced (plain, array, nothrow, aligned, and every
// delete), all on malloc/aligned_alloc and free: a block taken by one form
// and given back by another (std::stable_sort's buffer: nothrow new, plain
// delete) then meets the same allocator, as address sanitizers check.
#include <cstdint>
#include <cstdlib>
#include <malloc.h>
#include <new>
#include <sys/mman.h>

namespace {

// Before main, as the allocator's own setting (mallopt errors leave the
// defaults: nothing to report).
const bool kKeepsFreedMemory = [] {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  mallopt(M_ARENA_MAX, 1);
  return true;
}();

constexpr std::size_t kHugePage = std::size_t{2} << 20;
// Below this a block holds no whole aligned huge page often enough to matter.
constexpr std::size_t kAdviseFrom = 2 * kHugePage;

void advise_huge_pages(void* p, std::size_t n) {
  const auto begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (begin + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (begin + n) & ~(kHugePage - 1);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);  // advice: errors ignored
}

// malloc (align 0) or aligned_alloc, advised; nullptr when memory is out.
void* take(std::size_t n, std::size_t align) {
  if (n == 0) n = 1;
  void* p = nullptr;
  if (align == 0) {
    p = std::malloc(n);
  } else {
    const std::size_t rounded = (n + align - 1) / align * align;  // aligned_alloc wants a multiple
    p = rounded >= n ? std::aligned_alloc(align, rounded) : nullptr;
  }
  if (p && n >= kAdviseFrom) advise_huge_pages(p, n);
  return p;
}

// take(), calling the new handler until it succeeds (or throws bad_alloc).
void* take_or_throw(std::size_t n, std::size_t align) {
  for (;;) {
    if (void* p = take(n, align)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

void* take_or_null(std::size_t n, std::size_t align) noexcept {
  try {
    return take_or_throw(n, align);
  } catch (...) {
    return nullptr;
  }
}

std::size_t alignment(std::align_val_t a) { return static_cast<std::size_t>(a); }

}  // namespace

void* operator new(std::size_t n) { return take_or_throw(n, 0); }
void* operator new[](std::size_t n) { return take_or_throw(n, 0); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return take_or_null(n, 0); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return take_or_null(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) { return take_or_throw(n, alignment(a)); }
void* operator new[](std::size_t n, std::align_val_t a) { return take_or_throw(n, alignment(a)); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return take_or_null(n, alignment(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return take_or_null(n, alignment(a));
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
