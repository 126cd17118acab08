// The CPU check of an executable built for a newer x86-64 level than the baseline (CMake RADX_ARCH,
// docs/build-arch.md): a binary built with -march=x86-64-v3 uses AVX2 and FMA instructions anywhere, and on a
// CPU without them it would die of SIGILL somewhere in a constructor or in main. This file is compiled with
// -march=x86-64 whatever RADX_ARCH is (radx_add_cpu_check in the top CMakeLists.txt), and its function runs
// from .preinit_array: after the shared libraries (Debian's, built for the baseline) are initialised and
// before any constructor or main of the executable, the first code of this project to run. It asks libgcc's
// CPU model (cpuid, and xgetbv for the operating system's support of the AVX registers) whether every
// feature of the level is there, and otherwise says what is missing and exits with status 1.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#ifndef RADX_ARCH
#error "RADX_ARCH (the -march level, e.g. \"x86-64-v2\") must be defined"
#endif

namespace {

// Whether the CPU, and the operating system for the AVX registers, has every feature of RADX_ARCH. g++ knows
// the level names; clang 14 does not, and is asked for the features that tell the levels apart (every CPU
// with AVX2, FMA and BMI2 also has F16C, LZCNT and MOVBE). Tests name a feature this CPU lacks
// (RADX_CPU_CHECK_FEATURE, tests/CMakeLists.txt) to see the refusal.
#if defined(RADX_CPU_CHECK_FEATURE)
constexpr const char* kWanted = RADX_CPU_CHECK_FEATURE;
#else
constexpr const char* kWanted = RADX_ARCH;
#endif

bool cpu_has_level() {
#if defined(RADX_CPU_CHECK_FEATURE)
  return __builtin_cpu_supports(RADX_CPU_CHECK_FEATURE);
#elif !defined(__clang__)
  return __builtin_cpu_supports(RADX_ARCH);
#else
  constexpr std::string_view arch = RADX_ARCH;
  const bool v2 = __builtin_cpu_supports("ssse3") && __builtin_cpu_supports("sse4.1") &&
                  __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt");
  const bool v3 = v2 && __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") &&
                  __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
                  __builtin_cpu_supports("bmi2");
  if constexpr (arch == "x86-64-v3") return v3;
  if constexpr (arch == "x86-64-v2") return v2;
  return true;
#endif
}

void radx_check_cpu(int /*argc*/, char** argv, char** /*envp*/) {
  __builtin_cpu_init();  // needed before constructors have run (libgcc's own constructor may not have yet)
  if (cpu_has_level()) return;
  const char* name = argv != nullptr && argv[0] != nullptr ? argv[0] : "radx";
  std::fprintf(
      stderr,
      "%s: this executable was built for %s (-march=%s) and this CPU, or its operating system, lacks "
      "some of its instructions (x86-64-v3: AVX, AVX2, FMA, BMI1, BMI2, F16C, LZCNT, MOVBE; x86-64-v2: "
      "SSE4.2, SSSE3, POPCNT, CMPXCHG16B). Build the portable default instead: cmake "
      "-DRADX_ARCH=x86-64-v2 (docs/build-arch.md).\n",
      name, kWanted, RADX_ARCH);
  std::_Exit(1);
}

// glibc calls the .preinit_array entries of the executable with (argc, argv, envp) before its .init_array.
[[gnu::section(".preinit_array"), gnu::used]] void (*const radx_check_cpu_entry)(int, char**,
                                                                                 char**) = radx_check_cpu;

}  // namespace
