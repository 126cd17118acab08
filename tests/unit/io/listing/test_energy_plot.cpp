// NAME_energy.csv and NAME_energy.png (io/listing/energy_plot.hpp): the table read back, the chart checked
// from its bytes (PNG signature and the size in its IHDR chunk), the temporary files gone, the previous chart
// kept when a new one fails, and every failure a warning rather than an exception. The chart is drawn by the
// Debian /usr/bin/python3 with python3-matplotlib (scripts/deps.sh installs it).
//
// Tolerances:
// * CSV values carry 17 significant digits, so they must read back bit for bit (exact comparison).
// * The chart is 9 x 5.5 inches at 100 dpi, 900 x 550 pixels; the size is checked within +-100 pixels so a
//   matplotlib version that rounds the figure differently still passes, while a wrong dpi (x2) does not.
#include <catch2/catch.hpp>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "io/listing/energy_plot.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using radx::io::EnergyPlotRequest;
using radx::io::EnergySample;

// A body of mass m sliding to rest under a constant deceleration a: kinetic energy 0.5 m v(t)^2 with
// v(t) = v0 - a t; the lost energy split 80 / 5 / 15 % into internal, hourglass and contact energy, so the
// total stays 0.5 m v0^2 (no external work). Values like 4/3 need all 17 digits to read back.
std::vector<EnergySample> decelerating_body() {
  const double m = 2.0, v0 = 10.0, a = 4.0 / 3.0;  // stops at t = 7.5 s
  const double e0 = 0.5 * m * v0 * v0;
  std::vector<EnergySample> s;
  for (int k = 0; k <= 200; ++k) {
    const double t = 0.0371 * k;
    const double v = v0 - a * t;
    const double kinetic = 0.5 * m * v * v;
    const double lost = e0 - kinetic;
    const double internal = 0.80 * lost, hourglass = 0.05 * lost, contact = 0.15 * lost;
    s.push_back({t, kinetic, internal, hourglass, contact, 0.0, kinetic + internal + hourglass + contact});
  }
  return s;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<unsigned char> read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t big_endian32(const std::vector<unsigned char>& b, std::size_t at) {
  return (std::uint32_t{b[at]} << 24) | (std::uint32_t{b[at + 1]} << 16) | (std::uint32_t{b[at + 2]} << 8) |
         std::uint32_t{b[at + 3]};
}

// Files in `dir` whose names end with a temporary suffix of energy_plot.cpp.
std::vector<std::string> leftovers(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (n.ends_with(".part") || n.ends_with(".part.png")) out.push_back(n);
  }
  return out;
}

EnergyPlotRequest request_in(const fs::path& dir) {
  EnergyPlotRequest r;
  r.csv_path = (dir / "MY RUN_energy.csv").string();
  r.png_path = (dir / "MY RUN_energy.png").string();
  r.title = "MY RUN: body sliding to rest, \"quoted\" & spaced";
  r.time_unit = "s";
  r.energy_unit = "J";
  r.samples = decelerating_body();
  return r;
}

}  // namespace

TEST_CASE("energy CSV: header with units, values read back exactly", "[plot]") {
  radx::test::TempDir tmp;
  const EnergyPlotRequest r = request_in(tmp.path());
  std::string error;
  REQUIRE(radx::io::write_energy_csv(r, error));
  CHECK(error.empty());
  CHECK(leftovers(tmp.path()).empty());

  std::istringstream in(read_text(r.csv_path));
  std::string line;
  REQUIRE(std::getline(in, line));
  CHECK(line == "time [s],kinetic [J],internal [J],hourglass [J],contact [J],external_work [J],total [J]");
  std::size_t row = 0;
  while (std::getline(in, line)) {
    REQUIRE(row < r.samples.size());
    const EnergySample& s = r.samples[row];
    const double expected[] = {s.time,    s.kinetic,       s.internal, s.hourglass,
                               s.contact, s.external_work, s.total};
    const char* p = line.data();
    const char* end = line.data() + line.size();
    for (std::size_t k = 0; k < 7; ++k) {
      double v = 0.0;
      const auto res = std::from_chars(p, end, v);
      REQUIRE(res.ec == std::errc());
      CHECK(v == expected[k]);
      p = res.ptr;
      if (k < 6) {
        REQUIRE(p < end);
        REQUIRE(*p == ',');
        ++p;
      }
    }
    CHECK(p == end);
    ++row;
  }
  CHECK(row == r.samples.size());
}

TEST_CASE("energy CSV: units with commas cannot break the header, empty units are left out", "[plot]") {
  radx::test::TempDir tmp;
  EnergyPlotRequest r = request_in(tmp.path());
  r.time_unit = "";
  r.energy_unit = "kg,m2/s2";
  r.samples.resize(1);
  std::string error;
  REQUIRE(radx::io::write_energy_csv(r, error));
  std::istringstream in(read_text(r.csv_path));
  std::string line;
  REQUIRE(std::getline(in, line));
  CHECK(line.starts_with("time,kinetic [kg m2/s2],"));
}

TEST_CASE("energy chart: a PNG of the expected size replaces the previous one, no temporary file left",
          "[plot]") {
  radx::test::TempDir tmp;
  const fs::path dir = tmp.path() / "folder with spaces";
  fs::create_directories(dir);
  const EnergyPlotRequest r = request_in(dir);
  tmp.write("folder with spaces/MY RUN_energy.png", "previous chart");
  tmp.write("folder with spaces/MY RUN_energy.png.part.png", "left by a killed run");

  std::string warning;
  const auto start = std::chrono::steady_clock::now();
  const bool ok = radx::io::write_energy_plot(r, warning);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  INFO("warning: " << warning);
  INFO("one plot took " << seconds << " s");
  REQUIRE(ok);
  CHECK(warning.empty());
  CHECK(leftovers(dir).empty());
  CHECK(fs::is_regular_file(r.csv_path));

  const std::vector<unsigned char> png = read_bytes(r.png_path);
  REQUIRE(png.size() > 33);  // signature (8) + IHDR chunk (4 + 4 + 13 + 4)
  const std::vector<unsigned char> signature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  CHECK(std::vector<unsigned char>(png.begin(), png.begin() + 8) == signature);
  CHECK(big_endian32(png, 8) == 13u);  // IHDR length
  CHECK(std::string(png.begin() + 12, png.begin() + 16) == "IHDR");
  const std::uint32_t width = big_endian32(png, 16), height = big_endian32(png, 20);
  CHECK(width >= 800u);
  CHECK(width <= 1000u);
  CHECK(height >= 450u);
  CHECK(height <= 650u);
}

TEST_CASE("energy chart: a folder that does not exist is a warning, not an exception", "[plot]") {
  radx::test::TempDir tmp;
  EnergyPlotRequest r = request_in(tmp.path());
  r.png_path = (tmp.path() / "no such folder" / "MY RUN_energy.png").string();
  std::string warning;
  bool ok = true;
  REQUIRE_NOTHROW(ok = radx::io::write_energy_plot(r, warning));
  CHECK_FALSE(ok);
  CHECK(warning.find("does not exist") != std::string::npos);
  CHECK(warning.find(r.csv_path) != std::string::npos);  // the table is still there for the user
  CHECK(fs::is_regular_file(r.csv_path));
  CHECK_FALSE(fs::exists(tmp.path() / "no such folder"));
}

TEST_CASE("energy chart: a missing interpreter says how to install it and keeps the previous chart",
          "[plot]") {
  radx::test::TempDir tmp;
  const EnergyPlotRequest r = request_in(tmp.path());
  std::string error;
  REQUIRE(radx::io::write_energy_csv(r, error));
  tmp.write("MY RUN_energy.png", "previous chart");
  std::string warning;
  bool ok = true;
  REQUIRE_NOTHROW(ok = radx::io::draw_energy_png(r, (tmp.path() / "bin" / "python3").string(), warning));
  CHECK_FALSE(ok);
  CHECK(warning.find("not found") != std::string::npos);
  CHECK(warning.find("apt-get install python3-matplotlib") != std::string::npos);
  CHECK(read_text(r.png_path) == "previous chart");
  CHECK(leftovers(tmp.path()).empty());
}

TEST_CASE("energy chart: a script failure is reported with the script's own words", "[plot]") {
  radx::test::TempDir tmp;
  const EnergyPlotRequest r = request_in(tmp.path());
  tmp.write("MY RUN_energy.csv", "time [s],kinetic [J]\n0.0,not-a-number\n");
  tmp.write("MY RUN_energy.png", "previous chart");
  std::string warning;
  bool ok = true;
  REQUIRE_NOTHROW(ok = radx::io::draw_energy_png(r, radx::io::kDebianPython, warning));
  INFO("warning: " << warning);
  CHECK_FALSE(ok);
  CHECK(warning.find("cannot read") != std::string::npos);
  CHECK(warning.find("not-a-number") != std::string::npos);
  CHECK(read_text(r.png_path) == "previous chart");
  CHECK(leftovers(tmp.path()).empty());
}

TEST_CASE("energy chart: the embedded script is io/listing/plot_energy.py", "[plot]") {
  const std::string source = read_text(fs::path(RADX_SOURCE_DIR) / "io" / "listing" / "plot_energy.py");
  REQUIRE_FALSE(source.empty());
  CHECK(radx::io::energy_plot_script() == source);
}
