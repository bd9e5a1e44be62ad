// Large allocations on huge pages. A garment's arrays (a million and more chain points,
// samples, vertices) are allocated fresh stage after stage; glibc maps each one anew and
// the kernel zero-fills it 4 KiB at a time, and on a virtual machine each of those page
// faults is dear: on the sweater front they took about a third of the run. So blocks of
// 2 MiB and more, and malloc's heap as it grows, ask for transparent huge pages (madvise,
// which the kernel's default "madvise" mode honours), faulted in 2 MiB at a time, and
// freed blocks are kept for the next. Nothing else changes: the memory is malloc's, freed
// by free, and the contents are the same (docs/performance.md).
//
// The program's operator new is replaced in the command line only, the one executable a
// user runs; sanitizer builds keep their own.
#if !defined(__SANITIZE_ADDRESS__) && !defined(__has_feature)
#define KNITC_HUGE_PAGES 1
#elif defined(__has_feature)
#if !__has_feature(address_sanitizer)
#define KNITC_HUGE_PAGES 1
#endif
#endif

#if defined(KNITC_HUGE_PAGES) && defined(__linux__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t huge_page = std::size_t{2} << 20;
constexpr std::size_t worth_it = huge_page;  // a block holding at least one whole huge page, about

// Freed memory kept for the next stage's arrays rather than given back and faulted in
// again: blocks up to 32 MiB (the most malloc allows) come from its heap, whose free top
// is given back only past 1 GiB. Set outright, malloc's threshold no longer rises only as
// blocks are freed, which left the first block of each size a fresh mapping of its own.
// The heap grows 64 MiB at a time, and every thread takes its blocks from it (not from
// arenas of its own), so that its growth, seen below, can be advised as it comes.
std::atomic<std::uintptr_t> heap_advised{0};  // the heap's end, as far as advised

const bool heap_kept = [] {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 64 << 20);
  mallopt(M_ARENA_MAX, 1);
  heap_advised = reinterpret_cast<std::uintptr_t>(sbrk(0));
#endif
  return true;
}();

std::uintptr_t up(std::uintptr_t a) { return (a + huge_page - 1) & ~(huge_page - 1); }
std::uintptr_t down(std::uintptr_t a) { return a & ~(huge_page - 1); }

// Huge pages for the heap's new top, before its blocks are touched (what glibc's
// glibc.malloc.hugetlb=1 does, which it reads only from the environment as the program
// starts). The few pages malloc touched as it grew stay small.
void advise_heap_growth() {
  if (heap_advised.load(std::memory_order_relaxed) == 0) return;  // not glibc's heap, as set above
  const auto top = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::uintptr_t seen = heap_advised.load(std::memory_order_relaxed);
  if (top <= seen || !heap_advised.compare_exchange_strong(seen, top)) return;  // none, or another thread's to advise
  if (down(top) > up(seen)) madvise(reinterpret_cast<void*>(up(seen)), down(top) - up(seen), MADV_HUGEPAGE);
}

void* allocate(std::size_t size) noexcept {
  void* p = std::malloc(size == 0 ? 1 : size);
  advise_heap_growth();
  if (p && size >= worth_it) {
    // The whole huge pages inside the block: of its own mapping past 32 MiB, else of the
    // heap's, where the advice holds for those pages as they are reused.
    const auto from = up(reinterpret_cast<std::uintptr_t>(p));
    const auto to = down(reinterpret_cast<std::uintptr_t>(p) + size);
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);  // advice: a refusal costs nothing
  }
  return p;
}

}  // namespace

void* operator new(std::size_t size) {
  if (void* p = allocate(size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  if (void* p = allocate(size)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
#endif
