// Formulation honesty (parser/building/check_formulations.cpp): a formulation radx does not implement is
// refused by name, or with --allow-substitutions runs the nearest implemented one, listed in the starter
// listing, the engine listing and NAME_summary.json. The substituted run must be the implemented
// formulation's run, bit for bit: the same deck written with that formulation gives the same energies.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_util.hpp"

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The default deck (decks/block_on_plate) copied into dir, its /PROP/SHELL/1 Ishell set to `ishell`.
std::filesystem::path block_on_plate_with_ishell(const std::filesystem::path& dir, int ishell) {
  const std::filesystem::path src = std::filesystem::path(RADX_SOURCE_DIR) / "decks" / "block_on_plate";
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(src / "BLOCK_ON_PLATE_0001.rad", dir / "BLOCK_ON_PLATE_0001.rad");
  std::istringstream in(slurp(src / "BLOCK_ON_PLATE_0000.rad"));
  std::ostringstream out;
  std::string line;
  int after = -1;  // data lines seen after /PROP/SHELL/1 (its title is the first)
  while (std::getline(in, line)) {
    if (line.rfind("/PROP/SHELL/1", 0) == 0)
      after = 0;
    else if (after >= 0 && !line.empty() && line[0] != '#' && ++after == 2) {
      std::string field = std::to_string(ishell);
      line.replace(0, 10, std::string(10 - field.size(), ' ') + field);  // Ishell, columns 1-10
      after = -1;
    }
    out << line << '\n';
  }
  std::ofstream(dir / "BLOCK_ON_PLATE_0000.rad") << out.str();
  return dir / "BLOCK_ON_PLATE_0000.rad";
}

int run(const std::filesystem::path& deck, const std::filesystem::path& out, const std::string& extra,
        const std::filesystem::path& log) {
  const std::string cmd = std::string(RADX_DRIVER_EXE) + " run " + deck.string() + " --out " + out.string() +
                          " --threads 1 --no-plot " + extra + " > " + log.string() + " 2>&1";
  return std::system(cmd.c_str());
}

// The "energy" object of a summary, as text (compared exactly between runs).
std::string energy_block(const std::string& summary) {
  const auto a = summary.find("\"energy\"");
  const auto b = summary.find('}', a);
  return a == std::string::npos ? std::string() : summary.substr(a, b - a);
}

}  // namespace

TEST_CASE("a shell formulation radx lacks is refused by name, or substituted and listed when allowed",
          "[starter][engine]") {
  radx::test::TempDir dir;
  const auto deck4 = block_on_plate_with_ishell(dir.path() / "plain_h", 2);
  const auto deck1 = block_on_plate_with_ishell(dir.path() / "bt", 1);
  REQUIRE(slurp(deck4).find("         2") != std::string::npos);

  // Refused: exit code 1, the code, property, field, value and what radx implements; nothing written.
  const auto refused = dir.path() / "refused";
  CHECK(run(deck4, refused, "", dir.path() / "refused.log") != 0);
  const std::string log = slurp(dir.path() / "refused.log");
  CHECK(log.find("RX510") != std::string::npos);
  CHECK(log.find("/PROP/SHELL id 1") != std::string::npos);
  CHECK(log.find("Ishell = 2 (Belytschko-Tsay with the plain hourglass vector") != std::string::npos);
  CHECK(log.find("radx implements Ishell = 1") != std::string::npos);
  CHECK(log.find("--allow-substitutions") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(refused / "BLOCK_ON_PLATE_0000.hdf"));
  CHECK_FALSE(std::filesystem::exists(refused / "BLOCK_ON_PLATE_summary.json"));

  // Allowed: runs, and says so in the starter listing, the engine listing and the summary.
  const auto allowed = dir.path() / "allowed";
  REQUIRE(run(deck4, allowed, "--allow-substitutions", dir.path() / "allowed.log") == 0);
  const std::string starter = slurp(allowed / "BLOCK_ON_PLATE_0000.out");
  const std::string engine = slurp(allowed / "BLOCK_ON_PLATE_0001.out");
  const std::string summary = slurp(allowed / "BLOCK_ON_PLATE_summary.json");
  CHECK(starter.find("SUBSTITUTIONS") != std::string::npos);
  CHECK(starter.find("RX511") != std::string::npos);
  CHECK(engine.find("SUBSTITUTIONS") != std::string::npos);
  CHECK(engine.find("Ishell = 2 (Belytschko-Tsay with the plain hourglass vector) runs as Ishell = 1") !=
        std::string::npos);
  const auto key = summary.find("\"substitutions\"");
  REQUIRE(key != std::string::npos);
  const std::string list = summary.substr(key, summary.find(']', key) - key);
  CHECK(list.find("/PROP/SHELL 1") != std::string::npos);
  CHECK(list.find("runs as Ishell = 1") != std::string::npos);

  // What ran is Ishell 1: the deck written with Ishell 1 gives the same energies, bit for bit, and no
  // substitution.
  const auto plain = dir.path() / "plain";
  REQUIRE(run(deck1, plain, "", dir.path() / "plain.log") == 0);
  const std::string summary1 = slurp(plain / "BLOCK_ON_PLATE_summary.json");
  CHECK_FALSE(energy_block(summary).empty());
  CHECK(energy_block(summary) == energy_block(summary1));
  CHECK(summary1.find("\"substitutions\": []") != std::string::npos);
}

TEST_CASE(
    "a field read but not implemented that changes the physics is an error, a substitution when allowed",
    "[starter]") {
  // decks/invalid/solid_numerical_viscosity.rad: /PROP/SOLID Lambda = 0.01.
  const std::string deck = std::string(RADX_SOURCE_DIR) + "/decks/invalid/solid_numerical_viscosity.rad";
  radx::test::TempDir dir;
  const auto log = dir.file("log.txt");
  const std::string starter = std::string(RADX_STARTER_EXE) + " " + deck + " --out " + dir.path().string();
  CHECK(std::system((starter + " > " + log + " 2>&1").c_str()) != 0);
  std::string text = slurp(log);
  CHECK(text.find("RX510") != std::string::npos);
  CHECK(text.find("field Lambda") != std::string::npos);
  CHECK(std::system((starter + " --allow-substitutions > " + log + " 2>&1").c_str()) == 0);
  text = slurp(log);
  CHECK(text.find("RX511") != std::string::npos);
  CHECK(text.find("RX510") == std::string::npos);
  CHECK(slurp(dir.path() / "solid_numerical_viscosity_0000.out").find("SUBSTITUTIONS") != std::string::npos);
}

TEST_CASE("a substituted shell formulation runs with the defaults of the one that runs",
          "[starter][engine]") {
  // Ishell 3 defaults its hourglass coefficients Hm and Hf to 0.1, Ishell 1 to 0.01
  // (docs/theory/elements.md 1.7); the default deck leaves them blank. Ishell 3 substituted by Ishell 1 must
  // run Ishell 1 with Ishell 1's defaults: the same energies, bit for bit, as the deck written with Ishell 1.
  radx::test::TempDir dir;
  const auto deck3 = block_on_plate_with_ishell(dir.path() / "ishell3", 3);
  const auto deck1 = block_on_plate_with_ishell(dir.path() / "bt", 1);
  const auto substituted = dir.path() / "substituted", plain = dir.path() / "plain";
  REQUIRE(run(deck3, substituted, "--allow-substitutions", dir.path() / "substituted.log") == 0);
  REQUIRE(run(deck1, plain, "", dir.path() / "plain.log") == 0);
  const std::string summary3 = slurp(substituted / "BLOCK_ON_PLATE_summary.json");
  const std::string summary1 = slurp(plain / "BLOCK_ON_PLATE_summary.json");
  CHECK(summary3.find("Ishell = 3") != std::string::npos);
  CHECK_FALSE(energy_block(summary3).empty());
  CHECK(energy_block(summary3) == energy_block(summary1));
}

TEST_CASE(
    "shell Ismstr 4 and -1 run as large strain without a switch: the default deck's energies to the bit",
    "[starter]") {
  // The default deck's engine deck has no /DT/SHELL/CST, so Ismstr 2's switch never acts: 4 and -1 (which
  // OpenRadioss's shells run as 4) give the same run, bit for bit.
  radx::test::TempDir dir;
  const auto plain_deck = block_on_plate_with_ishell(dir.path() / "deck2", 1);
  REQUIRE(run(plain_deck, dir.path() / "plain", "", dir.path() / "plain.log") == 0);
  const std::string plain = energy_block(slurp(dir.path() / "plain" / "BLOCK_ON_PLATE_summary.json"));
  REQUIRE_FALSE(plain.empty());
  for (const int ismstr : {4, -1}) {
    const auto sub = dir.path() / ("deck" + std::to_string(ismstr + 10));
    std::filesystem::create_directories(sub);
    std::filesystem::copy_file(plain_deck.parent_path() / "BLOCK_ON_PLATE_0001.rad",
                               sub / "BLOCK_ON_PLATE_0001.rad");
    std::string text = slurp(plain_deck);
    const auto at = text.find("/PROP/SHELL/1");
    REQUIRE(at != std::string::npos);
    // The first data line after the title: Ishell in 1-10, Ismstr in 11-20.
    auto line = text.find('\n', text.find('\n', at) + 1) + 1;
    while (text[line] == '#') line = text.find('\n', line) + 1;
    const std::string field = std::to_string(ismstr);
    text.replace(line + 10, 10, std::string(10 - field.size(), ' ') + field);
    std::ofstream(sub / "BLOCK_ON_PLATE_0000.rad") << text;
    const auto out = dir.path() / ("out" + std::to_string(ismstr + 10));
    INFO("Ismstr " << ismstr << ": " << slurp(dir.path() / "log.txt"));
    REQUIRE(run(sub / "BLOCK_ON_PLATE_0000.rad", out, "", dir.path() / "log.txt") == 0);
    CHECK(energy_block(slurp(out / "BLOCK_ON_PLATE_summary.json")) == plain);
  }
}
