// The starter executables as a user runs them: exit codes, outputs, listing content, and the model
// masses against the closed form rho * t * A (shells) and rho * V (bricks).
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/hdf5/model_file.hpp"
#include "solver/model/stable_step.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

int run(const std::string& cmd) {
  const int rc = std::system((cmd + " >/dev/null 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const std::string kDefaultDeck =
    std::string(RADX_SOURCE_DIR) + "/decks/block_on_plate/BLOCK_ON_PLATE_0000.rad";

}  // namespace

TEST_CASE("radx-starter exit codes: 0 success, 1 input error, 2 usage error", "[app]") {
  radx::test::TempDir dir;
  const std::string exe = RADX_STARTER_EXE;
  CHECK(run(exe + " --help") == 0);
  CHECK(run(exe + " --version") == 0);
  CHECK(run(exe + " --bogus") == 2);
  CHECK(run(exe + " -i") == 2);
  CHECK(run(exe + " " + kDefaultDeck + " --out " + dir.path().string()) == 0);
  CHECK(run(exe + " -i " + kDefaultDeck + " --out " + dir.path().string()) == 0);
  // Radioss's own command line (starter_linux64 -i DECK -np 1 -nt 1) runs unchanged.
  CHECK(run(exe + " -i " + kDefaultDeck + " -np 1 -nt 1 --out " + dir.path().string()) == 0);
  CHECK(run(exe + " -version") == 0);
  CHECK(run(exe + " -i " + kDefaultDeck + " -nt") == 2);
  CHECK(run(exe + " " + dir.file("no_such_0000.rad") + " --out " + dir.path().string()) == 1);
  const std::string driver = RADX_DRIVER_EXE;
  CHECK(run(driver + " --help") == 0);
  CHECK(run(driver + " check " + kDefaultDeck) == 0);
  CHECK(run(driver + " check " + std::string(RADX_SOURCE_DIR) + "/decks/invalid/istf_7.rad") == 1);
  CHECK(run(driver + " frobnicate") == 2);
}

TEST_CASE("every radx command answers --help with its own usage and runs nothing", "[app]") {
  radx::test::TempDir dir;
  const std::string driver = RADX_DRIVER_EXE;
  for (const std::string cmd : {"check", "keywords", "run", "th", "regress"}) {
    INFO(cmd);
    const std::string out = dir.file(cmd + ".txt");
    // --help after other arguments too: nothing is read, checked or run.
    CHECK(std::system((driver + " " + cmd + " no_such_deck.rad --help > " + out + " 2>&1").c_str()) == 0);
    CHECK(slurp(out).rfind("usage: radx " + cmd, 0) == 0);
    CHECK(run(driver + " help " + cmd) == 0);
    CHECK(run(driver + " " + cmd + " -h") == 0);
  }
  CHECK(run(driver + " help frobnicate") == 2);
}

TEST_CASE("radx-engine takes Radioss's -nt N and states the threads in its listing header", "[app]") {
  radx::test::TempDir dir;
  const std::string out = " --out " + dir.path().string();
  REQUIRE(run(std::string(RADX_STARTER_EXE) + " -i " + kDefaultDeck + out) == 0);
  const std::string engine_deck =
      std::string(RADX_SOURCE_DIR) + "/decks/block_on_plate/BLOCK_ON_PLATE_0001.rad";
  REQUIRE(run(std::string(RADX_ENGINE_EXE) + " -i " + engine_deck + " -nt 2 --no-plot" + out) == 0);
  const auto listing = slurp(dir.path() / "BLOCK_ON_PLATE_0001.out");
  CHECK(listing.find("threads       2\n") != std::string::npos);
  CHECK(slurp(dir.path() / "BLOCK_ON_PLATE_summary.json").find("\"threads\": 2") != std::string::npos);
  CHECK(run(std::string(RADX_ENGINE_EXE) + " -version") == 0);
  CHECK(run(std::string(RADX_ENGINE_EXE) + " -i " + engine_deck + " -nt 0" + out) == 2);
}

TEST_CASE("the default deck gives a listing and a model file whose masses match rho t A and rho V", "[app]") {
  radx::test::TempDir dir;
  REQUIRE(run(std::string(RADX_STARTER_EXE) + " " + kDefaultDeck + " --out " + dir.path().string()) == 0);
  const auto listing = slurp(dir.path() / "BLOCK_ON_PLATE_0000.out");
  for (const char* section : {"COUNTS", "MATERIALS", "PROPERTIES", "PARTS AND MASSES", "CONTACT INTERFACES",
                              "DIAGNOSTICS", "model file written"})
    CHECK(listing.find(section) != std::string::npos);
  CHECK(listing.find("(default)") != std::string::npos);  // defaults are marked in the interface echo

  radx::model::Model m;
  std::string error;
  REQUIRE(radx::io::read_model_file((dir.path() / "BLOCK_ON_PLATE_0000.hdf").string(), m, error));
  // Independent mass from the deck's own data: every shell part rho * t * area, every brick part
  // rho * volume, with the areas and volumes of the (axis-aligned) elements from their node boxes.
  double expected = 0;
  // Extent of an element's node box along each axis.
  auto extent = [&](const std::vector<std::int32_t>& conn, std::size_t e, int npe) {
    std::array<double, 3> lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
    for (int k = 0; k < npe; ++k) {
      const auto n = conn[e * static_cast<std::size_t>(npe) + static_cast<std::size_t>(k)];
      const double x[3] = {m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]};
      for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
    }
    return std::array<double, 3>{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  };
  for (std::size_t e = 0; e < m.shells.size(); ++e) {
    const auto d = extent(m.shells.conn, e, 4);
    const auto& part = m.parts[m.shells.part[e]];
    const double t =
        m.shells.thickness[e] > 0 ? m.shells.thickness[e] : m.properties[part.property].shell.thickness;
    expected += m.materials[part.material].rho * t * d[0] * d[1];
  }
  for (std::size_t e = 0; e < m.bricks.size(); ++e) {
    const auto d = extent(m.bricks.conn, e, 8);
    expected += m.materials[m.parts[m.bricks.part[e]].material].rho * d[0] * d[1] * d[2];
  }
  // Same arithmetic up to summation order: 1e-12 relative.
  CHECK(m.total_mass == Approx(expected).epsilon(1e-12));
  double nodal = 0;
  for (double v : m.node_mass) nodal += v;
  CHECK(nodal == Approx(expected).epsilon(1e-12));  // lumping conserves the mass
  CHECK(m.interfaces.size() == 2);
}

TEST_CASE("the starter listing names the ten smallest element steps, L / c of the elements at rest",
          "[app]") {
  // decks/block_on_plate: 5 mm aluminium cubes (E 70000 MPa, nu 0.33, rho 2.7e-9 Mg/mm^3) and 10 mm steel
  // shells (E 210000 MPa, rho 7.85e-9). Brick: L = V / largest face = 5 mm, c = sqrt((K + 4G/3) / rho),
  // lowered by the default bulk viscosity qb = 0.05 at rest (times sqrt(1 + qb^2) - qb); shell: L = 10 mm,
  // c = sqrt(E / rho). The bricks' 7.67e-7 s is below the shells' 1.93e-6 s, so the ten smallest are ten of
  // the 64 equal bricks: the first ten in element order.
  const double E = 70000, nu = 0.33, rho = 2.7e-9, qb = 0.05;
  const double K = E / (3 * (1 - 2 * nu)), G = E / (2 * (1 + nu));
  const double dt_brick = 5.0 / std::sqrt((K + 4 * G / 3) / rho) * (std::sqrt(1 + qb * qb) - qb);
  const double dt_shell = 10.0 / std::sqrt(210000 / 7.85e-9);
  REQUIRE(dt_brick < dt_shell);
  radx::test::TempDir dir;
  REQUIRE(run(std::string(RADX_STARTER_EXE) + " " + kDefaultDeck + " --out " + dir.path().string()) == 0);
  radx::model::Model m;
  std::string error;
  REQUIRE(radx::io::read_model_file((dir.path() / "BLOCK_ON_PLATE_0000.hdf").string(), m, error));
  const auto step = radx::model::estimate_stable_step(m, 10);
  REQUIRE(step.smallest.size() == 10);
  for (std::size_t k = 0; k < 10; ++k) {
    CHECK(step.smallest[k].type == radx::model::ElementType::Brick8);
    CHECK(step.smallest[k].dt == Approx(dt_brick).epsilon(1e-9));  // the same formula, another order of sums
    CHECK(step.smallest[k].element_id == m.bricks.id[k]);
    CHECK(m.parts[static_cast<std::size_t>(step.smallest[k].part)].id == 2);
  }
  CHECK(step.dt == step.smallest[0].dt);
  const auto listing = slurp(dir.path() / "BLOCK_ON_PLATE_0000.out");
  const auto at = listing.find("SMALLEST ELEMENT TIME STEPS");
  REQUIRE(at != std::string::npos);
  std::ostringstream first;
  first << "  1     brick           " << m.bricks.id[0];
  CHECK(listing.find(first.str(), at) != std::string::npos);
  CHECK(listing.find("  10    brick", at) != std::string::npos);
  CHECK(listing.find("  11 ", at) > listing.find("CONTACT INTERFACES", at));  // ten rows, no more
}

TEST_CASE("after errors the starter prints no mass, gap or stiffness of a model that is not whole", "[app]") {
  radx::test::TempDir dir;
  std::string deck = slurp(kDefaultDeck);
  const auto p = deck.find("/MAT/PLAS_JOHNS");
  REQUIRE(p != std::string::npos);
  deck.replace(p, 15, "/MAT/PLAS_JHONS");  // the plate loses its material: its mass cannot be computed
  const auto path = dir.write("ERR_0000.rad", deck);
  const std::string log = dir.file("starter.log");
  const int rc = std::system(
      (std::string(RADX_STARTER_EXE) + " " + path + " --out " + dir.path().string() + " > " + log + " 2>&1")
          .c_str());
  CHECK((WIFEXITED(rc) ? WEXITSTATUS(rc) : -1) == 1);
  const auto out = slurp(log);
  CHECK(out.find("total mass") == std::string::npos);
  CHECK(out.find("gap ") == std::string::npos);
  CHECK(out.find("not computed") != std::string::npos);
  const auto listing = slurp(dir.path() / "ERR_0000.out");
  CHECK(listing.find("total mass not computed (the starter stopped on errors)") != std::string::npos);
  CHECK(listing.find("gap g                  not computed") != std::string::npos);
  CHECK(listing.find("stiffness K            not computed") != std::string::npos);
}

TEST_CASE("a deck that now has errors removes the stale model file of an earlier run", "[app]") {
  radx::test::TempDir dir;
  const std::string deck_text = slurp(kDefaultDeck);
  const auto deck = dir.write("CASE_0000.rad", deck_text);
  REQUIRE(run(std::string(RADX_STARTER_EXE) + " " + deck + " --out " + dir.path().string()) == 0);
  REQUIRE(fs::exists(dir.path() / "CASE_0000.hdf"));
  // Break one reference: the first /PART's material id.
  std::string broken = deck_text;
  const auto p = broken.find("/PART/");
  REQUIRE(p != std::string::npos);
  dir.write("CASE_0000.rad", broken.substr(0, p) + "/MAT/LAW36/99\n" + broken.substr(p));
  CHECK(run(std::string(RADX_STARTER_EXE) + " " + deck + " --out " + dir.path().string()) == 1);
  CHECK_FALSE(fs::exists(dir.path() / "CASE_0000.hdf"));
  CHECK(fs::exists(dir.path() / "CASE_0000.out"));
}
