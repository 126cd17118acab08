// A program whose constructor and main announce themselves: built with apps/cpu_check.cpp asking for a CPU
// feature no x86-64 server has (tests/CMakeLists.txt, cpu_check.refuses), it must stop with the check's
// message before either runs.
#include <cstdio>

namespace {

struct Announce {
  Announce() { std::puts("probe: a constructor ran"); }
};
const Announce announce;

}  // namespace

int main() {
  std::puts("probe: main ran");
  return 0;
}
