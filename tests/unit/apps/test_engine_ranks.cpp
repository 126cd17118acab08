// The engine pipeline on more than one rank, through the loopback communicator (P threads): until the engine
// splits the model over ranks, every rank refuses with exit 1, rank 0 alone says why, and nothing is written.
#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "apps/engine_pipeline.hpp"
#include "loopback_comm.hpp"
#include "test_util.hpp"

TEST_CASE("run_engine on 2 and 3 ranks: refused by rank 0 alone, nothing written", "[parallel][apps]") {
  for (const int ranks : {2, 3}) {
    radx::test::TempDir dir;
    const auto out_dir = dir.path() / "run";
    std::vector<int> codes(static_cast<std::size_t>(ranks), -1);
    std::vector<std::string> outs(codes.size());
    std::vector<std::string> errs(codes.size());
    radx::test::run_ranks(ranks, [&](radx::solver::parallel::Comm& comm) {
      radx::app::EngineOptions opt;
      opt.engine_deck = std::string(RADX_SOURCE_DIR) + "/decks/bar_rwall/BAR_RWALL_0001.rad";
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
    CHECK(errs[0].find("runs on more than one rank are not available yet") != std::string::npos);
    for (std::size_t r = 0; r < codes.size(); ++r) {
      CHECK(codes[r] == 1);
      CHECK(outs[r].empty());
      if (r > 0) CHECK(errs[r].empty());
    }
    CHECK_FALSE(std::filesystem::exists(out_dir));
  }
}
