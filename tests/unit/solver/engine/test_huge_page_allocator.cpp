// The huge-page memory of the engine's large arrays (solver/engine/huge_page_allocator.hpp): a large vector
// starts on a 2 MB boundary in a mapping advised MADV_HUGEPAGE, a small one comes from the heap, values
// survive growth across that threshold, copies and moves; the group arena (HugePageResource under a monotonic
// buffer) hands out the same memory to the groups' arrays, which keep it when the group moves.
#include <catch2/catch.hpp>
#include <cstdint>
#include <fstream>
#include <memory_resource>
#include <sstream>
#include <string>
#include <utility>

#include "solver/elements/element_groups.hpp"
#include "solver/engine/huge_page_allocator.hpp"

using radx::solver::HugePageResource;
using radx::solver::HugeVector;
using radx::solver::kHugePageBytes;
using radx::solver::kHugePageMinBytes;

namespace {

bool aligned_2mb(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % (std::uintptr_t{2} << 20) == 0;
}

// The VmFlags line of the mapping holding p in /proc/self/smaps ("" when not found).
std::string vm_flags_of(const void* p) {
  std::ifstream smaps("/proc/self/smaps");
  const auto addr = reinterpret_cast<std::uintptr_t>(p);
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(':') > line.find(' ')) {
      inside = addr >= lo && addr < hi;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line;
  }
  return "";
}

bool kernel_has_thp() {
  return std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled").good();
}

}  // namespace

TEST_CASE(
    "a large HugeVector starts on a 2 MB boundary advised for huge pages and a small one works as usual",
    "[hugepages]") {
  const std::size_t n = 3 * kHugePageBytes / sizeof(double) + 5;  // 6 MB and a bit: not a multiple of 2 MB
  HugeVector<double> big(n, 0.0);
  REQUIRE(big.size() == n);
  CHECK(aligned_2mb(big.data()));
  for (std::size_t i = 0; i < n; ++i) big[i] = 0.5 * static_cast<double>(i);
  bool same = true;
  for (std::size_t i = 0; i < n; ++i) same = same && big[i] == 0.5 * static_cast<double>(i);
  CHECK(same);
  // The tail past the last full 2 MB is usable (the mapping is not cut at a huge page).
  CHECK(big.back() == 0.5 * static_cast<double>(n - 1));
  if (kernel_has_thp()) {
    const auto flags = vm_flags_of(big.data());
    INFO(flags);
    CHECK(flags.find(" hg") != std::string::npos);  // MADV_HUGEPAGE's flag on the mapping
  }

  HugeVector<double> small(1000, 2.0);
  CHECK(small.size() == 1000);
  CHECK(small[999] == 2.0);
  CHECK(1000 * sizeof(double) < kHugePageMinBytes);
}

TEST_CASE("a HugeVector grows across the huge-page threshold and copies and moves with its values",
          "[hugepages]") {
  HugeVector<std::int32_t> v;
  const std::size_t n = 3 * kHugePageMinBytes / sizeof(std::int32_t);  // three times the threshold
  for (std::size_t i = 0; i < n; ++i) v.push_back(static_cast<std::int32_t>(i * 7 % 1000003));
  REQUIRE(v.size() == n);
  CHECK(aligned_2mb(v.data()));
  bool same = true;
  for (std::size_t i = 0; i < n; ++i) same = same && v[i] == static_cast<std::int32_t>(i * 7 % 1000003);
  CHECK(same);

  const HugeVector<std::int32_t> copy = v;
  CHECK(copy == v);
  CHECK(copy.data() != v.data());
  CHECK(aligned_2mb(copy.data()));

  const auto* data = v.data();
  HugeVector<std::int32_t> moved = std::move(v);
  CHECK(moved.data() == data);  // a move takes the memory over (the allocator is stateless)
  CHECK(moved == copy);

  moved.resize(10);  // shrinking keeps the values; shrink_to_fit goes back to the heap
  moved.shrink_to_fit();
  CHECK(moved.size() == 10);
  CHECK(moved[9] == 63);
}

TEST_CASE("the group arena gives the group arrays huge-page memory that they keep when a group moves",
          "[hugepages]") {
  HugePageResource huge;
  // A large request of the resource itself: a 2 MB-aligned mapping.
  void* p = huge.allocate(kHugePageMinBytes, alignof(double));
  CHECK(aligned_2mb(p));
  huge.deallocate(p, kHugePageMinBytes, alignof(double));

  std::pmr::monotonic_buffer_resource arena(kHugePageMinBytes, &huge);
  radx::solver::ShellGroup g(&arena);
  g.allocate(radx::solver::kGroupSize, 5, 1, 3);
  CHECK(g.sig.get_allocator().resource() == &arena);
  CHECK(g.nodal_force.get_allocator().resource() == &arena);
  CHECK(g.conn.get_allocator().resource() == &arena);
  // The first buffer is one mapping on a 2 MB boundary: the first array allocate() makes (conn) starts there.
  CHECK(aligned_2mb(g.conn.data()));
  for (std::size_t i = 0; i < g.sig.size(); ++i) g.sig[i] = static_cast<double>(i);
  const auto* sig = g.sig.data();
  radx::solver::ShellGroup moved(std::move(g));
  CHECK(moved.sig.data() == sig);
  CHECK(moved.sig.get_allocator().resource() == &arena);
  CHECK(moved.sig[moved.sig.size() - 1] == static_cast<double>(moved.sig.size() - 1));

  // Without an arena a group lives on the heap.
  radx::solver::ShellGroup plain;
  plain.allocate(4, 1, 1, 3);
  CHECK(plain.sig.get_allocator().resource() == std::pmr::get_default_resource());
}
