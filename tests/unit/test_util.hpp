// Helpers for tests: a temporary folder removed at the end, file writing, and a small deck writer that
// places values at exact columns so tests never hand-count spaces.
#pragma once

#include <catch2/catch.hpp>

#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"

#include <signal.h>
#include <sys/resource.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace radx::test {

// x within a relative tolerance `rel` of `expected`, plus an absolute floor for expected values near zero.
inline bool close(double x, double expected, double rel, double abs_floor = 0.0) {
  return std::abs(x - expected) <= rel * std::abs(expected) + abs_floor;
}

class TempDir {
 public:
  TempDir() {
    std::random_device rd;
    path_ =
        std::filesystem::temp_directory_path() / ("radx_test_" + std::to_string(rd()) + std::to_string(rd()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    const auto p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }

 private:
  std::filesystem::path path_;
};

// For its lifetime, writes past `bytes` in any file fail with EFBIG ("File too large"): the soft
// RLIMIT_FSIZE of the process, SIGXFSZ ignored (whose default would end the process). How tests make a
// write fail without a full disk.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    ::sigaction(SIGXFSZ, &ignore, &saved_action_);
    struct rlimit limit = saved_;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    ::sigaction(SIGXFSZ, &saved_action_, nullptr);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  struct rlimit saved_ {};
  struct sigaction saved_action_ {};
};

// A card line built field by field: put(value, first_col, last_col) right-justifies the value.
class Line {
 public:
  Line& put(const std::string& v, int first, int last) {
    if (static_cast<int>(s_.size()) < last) s_.resize(static_cast<std::size_t>(last), ' ');
    const int width = last - first + 1;
    // A test deck with a value cut to its columns would test something else than it says.
    if (v.size() > static_cast<std::size_t>(width))
      throw std::logic_error("test deck: '" + v + "' does not fit columns " + std::to_string(first) + "-" +
                             std::to_string(last));
    const std::string& t = v;
    s_.replace(static_cast<std::size_t>(last) - t.size(), t.size(), t);
    return *this;
  }
  Line& put(long long v, int first, int last) { return put(std::to_string(v), first, last); }
  Line& put(int v, int first, int last) { return put(std::to_string(v), first, last); }
  // The most digits (up to 15) that fit the field: a value written wider than its columns would be cut.
  Line& put(double v, int first, int last) {
    const auto width = static_cast<std::size_t>(last - first + 1);
    std::string t;
    for (int digits = 15; digits >= 1; --digits) {
      std::ostringstream os;
      os.precision(digits);
      os << v;
      t = os.str();
      if (t.find_first_of(".eE") == std::string::npos) t += ".";
      if (t.size() <= width) break;
    }
    return put(t, first, last);
  }
  Line& left(const std::string& v, int first) {
    if (s_.size() < static_cast<std::size_t>(first - 1 + static_cast<int>(v.size())))
      s_.resize(static_cast<std::size_t>(first - 1) + v.size(), ' ');
    s_.replace(static_cast<std::size_t>(first - 1), v.size(), v);
    return *this;
  }
  [[nodiscard]] std::string str() const { return s_; }

 private:
  std::string s_;
};

inline std::string begin_block(int version, const char* units = "Mg mm s") {
  std::istringstream is(units);
  std::string m, l, t;
  is >> m >> l >> t;
  std::ostringstream os;
  os << "/BEGIN\nTEST\n"
     << Line().put(version, 1, 10).str() << '\n'
     << Line().put(m, 1, 20).put(l, 21, 40).put(t, 41, 60).str() << '\n'
     << Line().put(m, 1, 20).put(l, 21, 40).put(t, 41, 60).str() << '\n';
  return os.str();
}

// The model of a starter deck given as text, read and built as the starter does (errors fail the test).
inline radx::model::Model model_of_deck(const std::string& text) {
  TempDir dir;
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir.write("m_0000.rad", text), diags);
  auto m = radx::build_model(deck, diags);
  for (const auto& d : diags.items()) INFO(radx::Diagnostics::format(d));
  REQUIRE_FALSE(diags.has_errors());
  return m;
}

#ifdef RADX_SOURCE_DIR
// The impact benchmark's decks (bench/gen_shell_plate.py --n N --impact, --block B unless 0) written into
// `dir` as PLATE<N>I_0000.rad and _0001.rad, and the starter deck's model read and built as the starter does
// (its TYPE7 gaps and search boxes not yet prepared).
inline radx::model::Model impact_benchmark_model(const TempDir& dir, int n, int block = 0) {
  const std::string gen = "/usr/bin/python3 " + std::string(RADX_SOURCE_DIR) +
                          "/bench/gen_shell_plate.py --n " + std::to_string(n) + " --impact" +
                          (block > 0 ? " --block " + std::to_string(block) : std::string()) + " --out " +
                          dir.path().string() + " > " + dir.file("gen.txt");
  REQUIRE(std::system(gen.c_str()) == 0);
  std::ifstream in(dir.file("PLATE" + std::to_string(n) + "I_0000.rad"));
  std::stringstream text;
  text << in.rdbuf();
  return model_of_deck(text.str());
}
#endif

}  // namespace radx::test
