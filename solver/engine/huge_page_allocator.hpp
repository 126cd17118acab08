// Memory on transparent huge pages (2 MB) for the engine's large structure-of-arrays vectors.
//
// Why: a cycle sweeps every node array and every group array; on 4 KB pages a 2.66 M-element model (4 GB)
// spans a million pages, far beyond the TLB's reach, and its first touch costs a million page faults. Linux
// gives huge pages to anonymous memory when asked (transparent_hugepage `madvise` mode, the common default)
// or always (`always` mode); this allocator asks: it maps a large request 2 MB-aligned and advises
// MADV_HUGEPAGE before anything touches it, so the first touch faults in whole 2 MB pages. A request below
// kHugePageMinBytes goes to operator new: a small vector would not fill a huge page. Where the advice fails
// (a kernel without THP, `never` mode) the memory is ordinary 4 KB pages, nothing else changes; the values
// stored never depend on the pages, so results are bit-identical either way.
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory_resource>
#include <new>
#include <vector>

namespace radx::solver {

inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;
// At least two huge pages: the mapping's tail beyond the last full 2 MB stays on 4 KB pages (it is not
// rounded up, so no memory is wasted), so a smaller request would gain little.
inline constexpr std::size_t kHugePageMinBytes = 2 * kHugePageBytes;

// Maps `bytes` (a multiple of nothing in particular) at a 2 MB boundary, advised MADV_HUGEPAGE; nullptr when
// the mapping fails. The over-mapped head and tail needed for the alignment are unmapped at once.
inline void* map_huge_pages(std::size_t bytes) noexcept {
  const std::size_t page = 4096;
  const std::size_t len = (bytes + page - 1) / page * page;
  void* raw =
      ::mmap(nullptr, len + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) return nullptr;
  const auto start = reinterpret_cast<std::uintptr_t>(raw);
  const auto aligned = (start + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  if (aligned > start) ::munmap(raw, aligned - start);
  const std::size_t tail = start + len + kHugePageBytes - (aligned + len);
  if (tail > 0) ::munmap(reinterpret_cast<void*>(aligned + len), tail);
  // A hint only: its failure leaves 4 KB pages, which work the same.
  (void)::madvise(reinterpret_cast<void*>(aligned), len, MADV_HUGEPAGE);
  return reinterpret_cast<void*>(aligned);
}

inline void unmap_huge_pages(void* p, std::size_t bytes) noexcept {
  const std::size_t page = 4096;
  ::munmap(p, (bytes + page - 1) / page * page);
}

// Stateless: any two instances are interchangeable, so vectors copy, move and swap as with std::allocator.
template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() noexcept = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}  // NOLINT(google-explicit-constructor): rebind

  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageMinBytes) return static_cast<T*>(::operator new(bytes));
    void* p = map_huge_pages(bytes);
    if (p == nullptr) throw std::bad_alloc();
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageMinBytes)
      ::operator delete(p);
    else
      unmap_huge_pages(p, bytes);
  }

  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) noexcept { return true; }
};

// The same memory as a std::pmr resource: the upstream of the engine's group arena (a monotonic buffer whose
// buffers grow geometrically, so all but the first few are large enough for huge pages).
class HugePageResource final : public std::pmr::memory_resource {
 private:
  void* do_allocate(std::size_t bytes, std::size_t align) override {
    if (bytes < kHugePageMinBytes || align > kHugePageBytes)
      return ::operator new (bytes, std::align_val_t{align});
    void* p = map_huge_pages(bytes);
    if (p == nullptr) throw std::bad_alloc();
    return p;
  }
  void do_deallocate(void* p, std::size_t bytes, std::size_t align) override {
    if (bytes < kHugePageMinBytes || align > kHugePageBytes)
      ::operator delete (p, std::align_val_t{align});
    else
      unmap_huge_pages(p, bytes);
  }
  [[nodiscard]] bool do_is_equal(const std::pmr::memory_resource& other) const noexcept override {
    return this == &other;
  }
};

// The engine's large arrays: a std::vector in every respect but where its memory comes from.
template <class T>
using HugeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace radx::solver
