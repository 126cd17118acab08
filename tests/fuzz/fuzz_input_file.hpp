// The readers take a path (a deck is files: #include, the engine deck beside the starter deck), so each
// fuzz input is written to a file first. The file lives in /dev/shm when there is one: a fuzzer runs
// thousands of inputs a second and a disk would be the bottleneck.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace radx::fuzz {

inline std::string input_file(const std::uint8_t* data, std::size_t size, const char* name) {
  std::error_code ec;
  const std::filesystem::path dir =
      std::filesystem::is_directory("/dev/shm", ec) ? "/dev/shm" : std::filesystem::temp_directory_path();
  // One file per process: parallel fuzzing jobs must not read each other's inputs.
  const std::string path = (dir / ("radx_fuzz_" + std::to_string(getpid()) + "_" + name)).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace radx::fuzz
