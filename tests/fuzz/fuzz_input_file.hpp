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

// The input as a file for the time of one call; removed after it, so a fuzzing run leaves nothing behind.
class InputFile {
 public:
  InputFile(const std::uint8_t* data, std::size_t size, const char* name) {
    std::error_code ec;
    const std::filesystem::path dir =
        std::filesystem::is_directory("/dev/shm", ec) ? "/dev/shm" : std::filesystem::temp_directory_path();
    // One file per process: parallel fuzzing jobs must not read each other's inputs.
    path_ = (dir / ("radx_fuzz_" + std::to_string(getpid()) + "_" + name)).string();
    std::ofstream(path_, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  ~InputFile() {
    std::error_code ec;
    std::filesystem::remove(path_, ec);
  }
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace radx::fuzz
