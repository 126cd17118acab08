// What the executables say of their build: the version, the git commit and the instruction set, in
// `--version` and in the run summary (NAME_summary.json).
#pragma once

#include <string>
#include <string_view>

namespace radx::app {

// The project version (CMake project(VERSION)) and the instruction set the executables were built for
// (CMake RADX_ARCH, docs/build-arch.md).
inline constexpr std::string_view kVersion = RADX_VERSION;
inline constexpr std::string_view kArch = RADX_ARCH;

// The git commit of the sources built: the short hash, "-dirty" after it when tracked files had changes,
// "unknown" when built from a tree without git (a source tarball). Generated at each build
// (cmake/RadxGitCommit.cmake), so it follows HEAD without a new configure.
std::string_view build_commit();

// "0.1.0 (commit abc1234, x86-64-v2)": what `--version` prints after the program's name.
inline std::string version_text() {
  return std::string(kVersion) + " (commit " + std::string(build_commit()) + ", " + std::string(kArch) + ")";
}

}  // namespace radx::app
