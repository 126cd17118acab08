// The engine pipeline on more than one rank, through the loopback communicator (P threads): a deck that
// uses a feature not yet run on more than one rank (/SECT) is refused with exit 1 on every rank, rank 0 alone
// names the feature, and nothing is written beside the model.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "apps/engine_pipeline.hpp"
#include "apps/starter_pipeline.hpp"
#include "loopback_comm.hpp"
#include "test_util.hpp"

namespace {

std::set<std::string> files_in(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

}  // namespace

TEST_CASE("run_engine on 2 and 3 ranks: a /SECT deck refused by rank 0 alone, nothing written",
          "[parallel][apps]") {
  const std::string decks = std::string(RADX_SOURCE_DIR) + "/decks/old_layout_2019/";
  for (const int ranks : {2, 3}) {
    radx::test::TempDir dir;
    const auto out_dir = dir.path() / "run";
    radx::app::StarterOptions starter;
    starter.deck = decks + "OLD_LAYOUT_2019_0000.rad";
    starter.out_dir = out_dir.string();
    std::ostringstream ignored;
    REQUIRE(radx::app::run_starter(starter, ignored, ignored).exit_code == 0);
    const auto before = files_in(out_dir);
    std::vector<int> codes(static_cast<std::size_t>(ranks), -1);
    std::vector<std::string> outs(codes.size());
    std::vector<std::string> errs(codes.size());
    radx::test::run_ranks(ranks, [&](radx::solver::parallel::Comm& comm) {
      radx::app::EngineOptions opt;
      opt.engine_deck = decks + "OLD_LAYOUT_2019_0001.rad";
      opt.out_dir = out_dir.string();
      opt.threads = 1;
      opt.comm = &comm;
      std::ostringstream out;
      std::ostringstream err;
      const int code = radx::app::run_engine(opt, out, err);
      const auto r = static_cast<std::size_t>(comm.rank());
      codes[r] = code;
      outs[r] = out.str();
      errs[r] = err.str();
    });
    INFO(ranks << " ranks; rank 0 said: " << errs[0]);
    CHECK(errs[0].find("cannot be split over " + std::to_string(ranks) + " ranks yet") != std::string::npos);
    CHECK(errs[0].find("/SECT") != std::string::npos);
    for (std::size_t r = 0; r < codes.size(); ++r) {
      CHECK(codes[r] == 1);
      CHECK(outs[r].empty());
      if (r > 0) CHECK(errs[r].empty());
    }
    CHECK(files_in(out_dir) == before);
  }
}
