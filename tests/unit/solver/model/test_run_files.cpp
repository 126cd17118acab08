// The names of a run's files (solver/model/run_files.hpp): the later engine decks of a run.
#include <catch2/catch.hpp>

#include <fstream>

#include "solver/model/run_files.hpp"
#include "test_util.hpp"

TEST_CASE("later engine decks: NAME_0002.rad and on beside NAME_0001.rad, by name, no other run's") {
  radx::test::TempDir dir;
  for (const char* name : {"CAR_0000.rad", "CAR_0001.rad", "CAR_0003.rad", "CAR_0002.rad", "CAR_0002.out",
                           "BUS_0002.rad", "CAR_02.rad"})
    std::ofstream(dir.path() / name) << "/END\n";
  const auto later = radx::model::later_engine_decks((dir.path() / "CAR_0001.rad").string());
  REQUIRE(later == std::vector<std::string>{"CAR_0002.rad", "CAR_0003.rad"});
  // Only the first engine deck of a run has later ones.
  CHECK(radx::model::later_engine_decks((dir.path() / "CAR_0002.rad").string()).empty());
  CHECK(radx::model::later_engine_decks((dir.path() / "CAR.rad").string()).empty());
}
