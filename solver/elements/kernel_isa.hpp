// Instruction-set variants of the hottest element kernels. Internal to the solver; not a public API.
//
// The solver is built for x86-64-v2 (SSE4.2, two doubles per vector; solver/CMakeLists.txt), so that it
// runs on any x86-64 machine of the last fifteen years. A kernel may also be compiled a second time, from
// the same source, for x86-64-v3 (AVX2, four doubles per vector) and pick that copy at run time when the
// processor has it. The two copies give the same results to the bit: the solver is compiled with
// -ffp-contract=off, so that the v3 copy uses no fused multiply-add, and the vectorised loops do the same
// IEEE operations per element in the same order whatever the vector width (GCC reorders no floating-point
// sum without -ffast-math). tests/unit/solver/elements/test_kernel_isa.cpp runs both copies on the same state
// and compares every output bit for bit.
#pragma once

#include "solver/elements/element_groups.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#define RADX_HAVE_ISA_V3 1
// Compiles a function (and, with flatten, everything inlined into it) for x86-64-v3. clang 14 knows the level
// only as -march, not in a target attribute, and is given the level's features instead (the same
// instructions: x86-64-v2's and AVX, AVX2, FMA, BMI1, BMI2, F16C, LZCNT, MOVBE).
#if defined(__clang__)
#define RADX_TARGET_V3 \
  __attribute__((target("sse4.2,popcnt,cx16,sahf,avx,avx2,fma,bmi,bmi2,f16c,lzcnt,movbe,xsave"), flatten))
#else
#define RADX_TARGET_V3 __attribute__((target("arch=x86-64-v3"), flatten))
#endif
#else
#define RADX_HAVE_ISA_V3 0
#endif

namespace radx::solver {

enum class KernelIsa {
  Baseline,  // the build's target (x86-64-v2)
  V3,        // x86-64-v3: AVX2
};

// True when this processor can run the variant.
inline bool kernel_isa_supported(KernelIsa isa) {
  if (isa == KernelIsa::Baseline) return true;
#if RADX_HAVE_ISA_V3 && defined(__clang__)
  // clang 14's __builtin_cpu_supports does not know the level names: the features that tell v3 from v2
  // (every CPU with AVX2, FMA and BMI2 also has F16C, LZCNT and MOVBE), as apps/cpu_check.cpp asks them.
  return __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
         __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
#elif RADX_HAVE_ISA_V3
  return __builtin_cpu_supports("x86-64-v3") != 0;
#else
  return false;
#endif
}

// The best variant this processor runs (the kernels' default).
inline KernelIsa best_kernel_isa() {
  return kernel_isa_supported(KernelIsa::V3) ? KernelIsa::V3 : KernelIsa::Baseline;
}

// shell_bt4_forces with the variant chosen by the caller (an unsupported one is replaced by Baseline).
void shell_bt4_forces(ShellGroup& g, const NodeState& nodes, const MaterialParams& mat, const CycleInfo& cyc,
                      KernelIsa isa);

}  // namespace radx::solver
