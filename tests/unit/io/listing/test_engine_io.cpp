// The engine's input and output edges: run controls from small engine decks written here (every keyword,
// the defaults of docs/theory/deck-format.md section 3, errors at their lines, unknown /ANIM names, one-file
// decks), the listing line and its blocks, the energy error of docs/theory/elements.md section 8 and
// NAME_summary.json.
//
// Tolerances:
// * Values read from deck text are compared with Approx(...).epsilon(1e-12): the decimal text is converted
//   once, so anything beyond the rounding of the last bit is a reading error. Defaults are compared exactly.
// * Listing lines print reals with 6 significant digits (%.5E), so a value parsed back from a line may differ
//   from the printed one by half a unit of the 6th digit: relative 5e-6 (+1e-300 absolute for zeros). The
//   error % has one decimal: 0.05 absolute.
// * energy_error_percent is compared with Approx epsilon 1e-12 against the formula evaluated by hand; the
//   clipped and zero cases exactly.
// * JSON doubles carry 17 significant digits, so they must read back bit for bit (exact comparison, in C++
//   with strtod and in Python with ==).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "io/listing/engine_listing.hpp"
#include "io/listing/summary_json.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/reading/deck.hpp"
#include "solver/model/run_files.hpp"
#include "test_util.hpp"

namespace {

using radx::Diag;
using radx::Diagnostics;
using radx::model::DtAction;
namespace fs = std::filesystem;

constexpr double kEps = 1e-12;

std::string all_diags(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.items()) s += Diagnostics::format(x) + "\n";
  return s;
}

// 1-based number of the first line of `text` that starts with `start`; 0 when none.
int line_of(const std::string& text, const std::string& start) {
  std::istringstream is(text);
  std::string l;
  int n = 0;
  while (std::getline(is, l)) {
    ++n;
    if (l.rfind(start, 0) == 0) return n;
  }
  return 0;
}

const radx::Diagnostic* find(const Diagnostics& d, Diag code) {
  for (const auto& x : d.items())
    if (x.code == code) return &x;
  return nullptr;
}

struct Built {
  radx::model::RunControls rc;
  Diagnostics diags;
};

Built build(const radx::test::TempDir& dir, const std::string& name, const std::string& text) {
  Built b;
  const std::string path = dir.write(name, text);
  b.rc = radx::read_run_controls(path, b.diags);
  return b;
}

std::vector<std::string> split(const std::string& s) {
  std::istringstream is(s);
  std::vector<std::string> out;
  std::string t;
  while (is >> t) out.push_back(t);
  return out;
}

bool close_rel(double got, double want, double rel) {
  return std::abs(got - want) <= rel * std::abs(want) + 1e-300;
}

}  // namespace

TEST_CASE("every engine keyword resolves into the run controls", "[engine-io]") {
  radx::test::TempDir dir;
  const std::string deck =
      "#RADIOSS ENGINE\n"
      "/RUN/MyCase/1\n"
      "# Tstop\n"
      "0.0125\n"
      "/VERS/2019\n"
      "/TFILE/4\n"
      "2.5e-5\n"
      "/ANIM/DT\n"
      "0.001, 0.0002, 0.008\n"
      "/ANIM/ELEM/VONM\n/ANIM/ELEM/EPSP\n/ANIM/ELEM/THIC\n/ANIM/ELEM/ENER\n/ANIM/ELEM/P\n"
      "/ANIM/ELEM/DENS\n/ANIM/ELEM/HOUR\n/ANIM/ELEM/VONM\n"
      "/ANIM/VECT/VEL\n/ANIM/VECT/DIS\n/ANIM/VECT/ACC\n/ANIM/VECT/CONT\n/ANIM/VECT/FINT\n"
      "/ANIM/VECT/FEXT\n/ANIM/VECT/FREAC\n/ANIM/VECT/DISP\n"
      "/ANIM/TENS/STRESS\n"
      "/ANIM/NODA/DMAS\n/ANIM/NODA/DT\n"
      "/ANIM/GZIP\n"
      "/ANIM/VERS/44\n"
      "/DT\n"
      "0.8 1e-9\n"
      "/DT/NODA/CST\n"
      "0.7 2e-8 5.5\n"
      "/DT/INTER/LAG\n"
      "0.6 3e-8\n"
      "/DT/BRICK/CST\n"
      "0 4e-8\n"
      "/DT/SHELL/CST\n"
      "0.5 0\n"
      "/DT/SH3N/CST\n"
      "0.4 5e-8\n"
      "/PRINT/-50/20\n"
      "/STOP\n"
      "5.0 0.1 0 1 0 1\n"
      "/RFILE/5\n"
      "1000\n"
      "/PARITH/ON\n"
      "/MON/ON\n"
      "/RBODY/ON\n"
      "1 2\n"
      "3\n"
      "/RBODY/OFF\n"
      "7\n"
      "/END\n";
  const Built b = build(dir, "MYCASE_0001.rad", deck);
  INFO(all_diags(b.diags));
  REQUIRE_FALSE(b.diags.has_errors());
  CHECK(b.diags.warning_count() == 0);
  const auto& rc = b.rc;
  CHECK(rc.run_name == "MyCase");  // as written, though the reader stores keyword fields in upper case
  CHECK(rc.run_number == 1);
  CHECK(rc.t_stop == Approx(0.0125).epsilon(kEps));
  CHECK(rc.th_dt == Approx(2.5e-5).epsilon(kEps));
  CHECK(rc.anim_start == Approx(0.001).epsilon(kEps));
  CHECK(rc.anim_dt == Approx(0.0002).epsilon(kEps));
  CHECK(rc.anim_stop == Approx(0.008).epsilon(kEps));
  // Canonical names, each once, in deck order (DIS is DISP; the repeated VONM and DISP are dropped).
  CHECK(rc.anim_elem == std::vector<std::string>{"VONM", "EPSP", "THIC", "ENER", "P", "DENS", "HOUR"});
  CHECK(rc.anim_vect == std::vector<std::string>{"VEL", "DISP", "ACC", "CONT", "FINT", "FEXT", "FREAC"});
  CHECK(rc.anim_tens == std::vector<std::string>{"STRESS"});
  CHECK(rc.anim_noda == std::vector<std::string>{"DMAS", "DT"});
  CHECK(rc.global.scale == Approx(0.8).epsilon(kEps));
  CHECK(rc.global.t_min == Approx(1e-9).epsilon(kEps));
  CHECK(rc.global.action == DtAction::Stop);
  CHECK(rc.global.given);
  CHECK(rc.nodal.scale == Approx(0.7).epsilon(kEps));
  CHECK(rc.nodal.t_min == Approx(2e-8).epsilon(kEps));
  CHECK(rc.nodal.action == DtAction::AddMass);
  CHECK(rc.nodal_max_added_mass_pct == Approx(5.5).epsilon(kEps));
  CHECK(rc.inter.scale == Approx(0.6).epsilon(kEps));
  CHECK(rc.inter.t_min == Approx(3e-8).epsilon(kEps));
  CHECK(rc.inter.action == DtAction::Lagrange);
  // Family Tscale 0 and Tmin 0 take the /DT values.
  CHECK(rc.brick.scale == Approx(0.8).epsilon(kEps));
  CHECK(rc.brick.t_min == Approx(4e-8).epsilon(kEps));
  CHECK(rc.brick.action == DtAction::Constant);
  CHECK(rc.shell.scale == Approx(0.5).epsilon(kEps));
  CHECK(rc.shell.t_min == Approx(1e-9).epsilon(kEps));
  CHECK(rc.shell.action == DtAction::Constant);
  CHECK(rc.shell3.scale == Approx(0.4).epsilon(kEps));  // written with the /DT/SH3N/CST alias
  CHECK(rc.shell3.t_min == Approx(5e-8).epsilon(kEps));
  CHECK(rc.shell3.action == DtAction::Constant);
  CHECK(rc.print_every == 50);
  CHECK(rc.print_stdout);
  CHECK(rc.print_header_every == 20);
  CHECK(rc.stop_energy_error_pct == Approx(5.0).epsilon(kEps));
  CHECK(rc.stop_mass_error == Approx(0.1).epsilon(kEps));
  CHECK(rc.stop_nodal_mass_error == 1e30);  // 0 -> off
  CHECK(rc.stop_writes_th);
  CHECK_FALSE(rc.stop_writes_anim);
  CHECK(rc.stop_positive_error_only);
  CHECK(rc.rbody_on == std::vector<std::int64_t>{1, 2, 3});
  CHECK(rc.rbody_off == std::vector<std::int64_t>{7});
}

TEST_CASE("engine defaults: /PRINT -100, no /TFILE, Tscale 0, Tstop 0, /STOP 0", "[engine-io]") {
  radx::test::TempDir dir;
  SECTION("only /RUN") {
    const Built b = build(dir, "A_0001.rad", "/RUN/A/1\n1.5\n/END\n");
    INFO(all_diags(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    const auto& rc = b.rc;
    CHECK(rc.t_stop == 1.5);
    CHECK(rc.print_every == 100);
    CHECK(rc.print_stdout);
    CHECK(rc.print_header_every == 0);
    CHECK(rc.th_dt == 1e30);
    CHECK(rc.anim_dt == 0);
    CHECK(rc.anim_stop == 1e20);
    CHECK(rc.global.scale == 0.9);
    CHECK(rc.global.t_min == 0);
    CHECK(rc.global.action == DtAction::Stop);
    CHECK_FALSE(rc.global.given);
    for (const auto* f : {&rc.brick, &rc.shell, &rc.shell3}) {  // copies of /DT, not given
      CHECK(f->scale == 0.9);
      CHECK(f->t_min == 0);
      CHECK(f->action == DtAction::Stop);
      CHECK_FALSE(f->given);
    }
    CHECK(rc.nodal.action == DtAction::None);
    CHECK(rc.inter.action == DtAction::None);
    CHECK(rc.stop_energy_error_pct == 1e30);
    CHECK(rc.stop_mass_error == 1e30);
    CHECK(rc.stop_nodal_mass_error == 1e30);
    CHECK(rc.anim_elem.empty());
  }
  SECTION("zeros mean defaults") {
    const Built b = build(dir, "A_0001.rad",
                          "/RUN/A/1\n1.5\n/PRINT/10\n/ANIM/DT\n0 0.1 0\n/DT\n0 0\n/DT/NODA/CST\n0 1e-6\n"
                          "/DT/INTER/CST\n0 2e-6\n/STOP\n0 0 0\n/TFILE\n0.01\n/END\n");
    INFO(all_diags(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    const auto& rc = b.rc;
    CHECK(rc.print_every == 10);
    CHECK_FALSE(rc.print_stdout);  // positive n: the .out file only
    CHECK(rc.anim_stop == 1e20);
    CHECK(rc.anim_dt == Approx(0.1).epsilon(kEps));
    CHECK(rc.global.scale == 0.9);
    CHECK(rc.global.given);
    CHECK(rc.nodal.scale == 0.9);
    CHECK(rc.nodal.action == DtAction::AddMass);
    CHECK(rc.nodal_max_added_mass_pct == 0);
    CHECK(rc.inter.scale == 0.9);
    CHECK(rc.inter.action == DtAction::AddMass);
    CHECK(rc.stop_energy_error_pct == 1e30);
    CHECK(rc.stop_mass_error == 1e30);
    CHECK(rc.stop_nodal_mass_error == 1e30);
    CHECK(rc.th_dt == Approx(0.01).epsilon(kEps));
  }
  SECTION("/ANIM/DT with dT 0 and a frame count") {
    const Built b = build(dir, "A_0001.rad", "/RUN/A/1\n2.0\n/ANIM/DT\n0.5 0 0 6\n/END\n");
    INFO(all_diags(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    CHECK(b.rc.anim_dt == Approx((2.0 - 0.5) / 6).epsilon(kEps));  // frames span Tstart to the run end
  }
  SECTION("/DT/INTER/DEL has precedence over /DT/INTER/CST") {
    const std::string text = "/RUN/A/1\n1\n/DT/INTER/CST\n0.5 1e-7\n/DT/INTER/DEL\n0.7 2e-7\n/END\n";
    const Built b = build(dir, "A_0001.rad", text);
    INFO(all_diags(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    CHECK(b.rc.inter.action == DtAction::Delete);
    CHECK(b.rc.inter.scale == Approx(0.7).epsilon(kEps));
    const auto* w = find(b.diags, Diag::InconsistentValues);
    REQUIRE(w);
    CHECK(w->severity == radx::Severity::Warning);
    CHECK(w->line == line_of(text, "/DT/INTER/CST"));
  }
}

TEST_CASE("output intervals no schedule can follow, or that ask for absurd counts, are said at the deck",
          "[engine-io]") {
  radx::test::TempDir dir;
  SECTION("a time-history interval below the time resolution is every cycle, with the rows it asked for") {
    const Built b = build(dir, "A_0001.rad", "/RUN/A/1\n0.02\n/TFILE\n1e-30\n/END\n");
    INFO(all_diags(b.diags));
    CHECK_FALSE(b.diags.has_errors());
    const auto* w = find(b.diags, Diag::ValueOutOfRange);
    REQUIRE(w);
    CHECK(w->severity == radx::Severity::Warning);
    CHECK(w->line == 3);
    CHECK(w->message.find("2e+28 rows") != std::string::npos);  // 0.02 / 1e-30
    CHECK(b.rc.th_dt == 0.0);
  }
  SECTION("an interval just above the resolution is kept as given") {
    const Built b = build(dir, "A_0001.rad", "/RUN/A/1\n1\n/TFILE\n1e-15\n/END\n");
    CHECK(b.diags.items().empty());
    CHECK(b.rc.th_dt == 1e-15);
  }
  SECTION("an animation interval below the time resolution is every cycle, with the states it asked for") {
    // Tstop 1: the spacing of doubles at the last state time is 2^-52 = 2.2e-16.
    const Built b = build(dir, "A_0001.rad", "/RUN/A/1\n1\n/ANIM/DT\n0 1e-300\n/END\n");
    INFO(all_diags(b.diags));
    CHECK_FALSE(b.diags.has_errors());
    const auto* w = find(b.diags, Diag::ValueOutOfRange);
    REQUIRE(w);
    CHECK(w->severity == radx::Severity::Warning);
    CHECK(w->message.find("1e+300 states") != std::string::npos);
    CHECK(b.rc.anim_dt == std::ldexp(1.0, -52));
  }
}

TEST_CASE("engine deck errors are located at their keyword line", "[engine-io]") {
  struct Case {
    const char* what;
    std::string body;     // between /RUN and /END
    const char* keyword;  // the line the diagnostic must point at
    Diag code;
    const char* message;  // part of the message
  };
  const std::vector<Case> cases = {
      {"Tstop 0", "", "/RUN", Diag::ValueOutOfRange, "Tstop = 0"},
      {"dT 0", "/ANIM/DT\n0 0\n", "/ANIM/DT", Diag::ValueOutOfRange, "dT = 0"},
      {"dT negative", "/ANIM/DT\n0 -1e-3\n", "/ANIM/DT", Diag::ValueOutOfRange, "dT = -0.001"},
      {"anim Tstop negative", "/ANIM/DT\n0 1e-3 -1\n", "/ANIM/DT", Diag::ValueOutOfRange, "Tstop = -1"},
      {"anim function", "/ANIM/DT\n0 1e-3 0 0 12\n", "/ANIM/DT", Diag::UnimplementedOption, "fct_ID = 12"},
      {"Tscale negative", "/DT\n-0.5 0\n", "/DT", Diag::ValueOutOfRange, "Tscale = -0.5"},
      {"Tmin negative", "/DT/SHELL/CST\n0.9 -1e-6\n", "/DT/SHELL/CST", Diag::ValueOutOfRange,
       "Tmin = -1e-06"},
      {"print 0", "/PRINT/0\n", "/PRINT", Diag::ValueOutOfRange, "n = 0"},
      {"print not a number", "/PRINT/X1\n", "/PRINT", Diag::BadInteger, "'X1'"},
      {"print nh negative", "/PRINT/-10/-2\n", "/PRINT", Diag::ValueOutOfRange, "nh = -2"},
      {"stop negative", "/STOP\n-1 0 0\n", "/STOP", Diag::ValueOutOfRange, "Emax = -1"},
      {"stop flag 2", "/STOP\n0 0 0 2\n", "/STOP", Diag::ValueOutOfRange, "NTH = 2"},
      {"tfile negative", "/TFILE\n-1e-3\n", "/TFILE", Diag::ValueOutOfRange, "dt_his = -0.001"},
      {"cst and lag", "/DT/INTER/CST\n0.9 1e-7\n/DT/INTER/LAG\n0.9 1e-7\n", "/DT/INTER/LAG",
       Diag::InconsistentValues, "both given"},
      {"duplicate /DT", "/DT\n0.9 0\n/DT\n0.8 0\n", "/DT\n0.8", Diag::DuplicateSingleton, "given again"},
      {"nodal group", "/DT/NODA/CST/1\n0.9 1e-7\n12\n", "/DT/NODA/CST", Diag::UnimplementedOption,
       "grnod_ID = 12"},
      {"nodal stop", "/DT/NODA/STOP\n0.9 1e-7\n", "/DT/NODA/STOP", Diag::UnsupportedKeyword,
       "radx runs /DT/NODA (no action at Tmin)"},
      {"nodal twice", "/DT/NODA/0\n0.9 1e-7\n/DT/NODA/CST\n0.9 1e-7\n", "/DT/NODA/CST",
       Diag::DuplicateSingleton, "both given"},
      {"restart letter", "", "/RUN", Diag::UnimplementedOption, "restart letter"},
  };
  for (const auto& c : cases) {
    DYNAMIC_SECTION(c.what) {
      radx::test::TempDir dir;
      const std::string run = std::string(c.what) == "Tstop 0"          ? "/RUN/A/1\n0\n"
                              : std::string(c.what) == "restart letter" ? "/RUN/A/1/R\n1\n"
                                                                        : "/RUN/A/1\n1\n";
      // A comment line first, so the line numbers are those of the file, comments included.
      const std::string text = "# engine deck\n" + run + c.body + "/END\n";
      const Built b = build(dir, "A_0001.rad", text);
      INFO(all_diags(b.diags));
      CHECK(b.diags.error_count() + b.diags.warning_count() == 1);
      const auto* d = find(b.diags, c.code);
      REQUIRE(d);
      CHECK(d->severity == radx::Severity::Error);
      // The duplicate case points at the second /DT: find the line of "/DT" followed by "0.8".
      int want = line_of(text, c.keyword);
      if (std::string(c.keyword) == "/DT\n0.8") want = line_of(text, "0.8") - 1;
      CHECK(d->line == want);
      CHECK(d->file.find("A_0001.rad") != std::string::npos);
      CHECK(d->message.find(c.message) != std::string::npos);
    }
  }
}

TEST_CASE("an /ANIM name radx does not write is a warning that lists the names it writes", "[engine-io]") {
  struct Case {
    const char* keyword;
    const char* accepted;
  };
  const std::vector<Case> cases = {
      {"/ANIM/ELEM/TEMP", "VONM EPSP THIC ENER P DENS HOUR"},  // a Radioss field radx does not write
      {"/ANIM/VECT/VROT", "VEL DISP (DIS) ACC CONT FINT FEXT FREAC"},
      {"/ANIM/TENS/STRAIN", "STRESS"},
      {"/ANIM/NODA/TEMP", "DMAS DT"},
      {"/ANIM/ELEM/DENS3", "VONM EPSP THIC ENER P DENS HOUR"},  // Radioss's DENS3 is not DENS
      {"/ANIM/VECT/CONT2", "VEL DISP (DIS) ACC CONT FINT FEXT FREAC"},
  };
  for (const auto& c : cases) {
    DYNAMIC_SECTION(c.keyword) {
      radx::test::TempDir dir;
      const std::string text = "/RUN/A/1\n1\n/ANIM/ELEM/VONM\n" + std::string(c.keyword) + "\n/END\n";
      const Built b = build(dir, "A_0001.rad", text);
      INFO(all_diags(b.diags));
      CHECK_FALSE(b.diags.has_errors());
      REQUIRE(b.diags.warning_count() == 1);
      const auto* d = find(b.diags, Diag::OutputNotWritten);
      REQUIRE(d);
      CHECK(d->severity == radx::Severity::Warning);
      CHECK(d->line == 4);
      const std::string name = std::string(c.keyword).substr(std::string(c.keyword).rfind('/') + 1);
      CHECK(d->message.find("'" + name + "'") != std::string::npos);
      CHECK(d->message.find(std::string("radx writes: ") + c.accepted) != std::string::npos);
      CHECK(d->message.find("docs/results.md") != std::string::npos);
      CHECK(b.rc.anim_elem == std::vector<std::string>{"VONM"});  // the known name is still read
    }
  }
  SECTION("a qualifier after a known name is a warning; the qualified field is not written") {
    radx::test::TempDir dir;
    const Built b = build(dir, "A_0001.rad", "/RUN/A/1\n1\n/ANIM/TENS/STRESS/MEMB\n/END\n");
    INFO(all_diags(b.diags));
    CHECK_FALSE(b.diags.has_errors());
    REQUIRE(find(b.diags, Diag::OutputNotWritten));
    CHECK(find(b.diags, Diag::OutputNotWritten)->line == 3);
    CHECK(find(b.diags, Diag::OutputNotWritten)->message.find("'MEMB'") != std::string::npos);
    CHECK(b.rc.anim_tens.empty());
  }
  SECTION("names are read on the letters Radioss reads") {
    radx::test::TempDir dir;
    const Built b =
        build(dir, "A_0001.rad",
              "/RUN/A/1\n1\n/ANIM/ELEM/HOURG\n/ANIM/ELEM/PRES\n/ANIM/ELEM/DENSITY\n"
              "/ANIM/VECT/ACCEL\n/ANIM/VECT/VELOCITY\n/ANIM/VECT/DISPL\n/ANIM/NODA/DMASS\n/END\n");
    INFO(all_diags(b.diags));
    CHECK(b.diags.items().empty());
    CHECK(b.rc.anim_elem == std::vector<std::string>{"HOUR", "P", "DENS"});
    CHECK(b.rc.anim_vect == std::vector<std::string>{"ACC", "VEL", "DISP"});
    CHECK(b.rc.anim_noda == std::vector<std::string>{"DMAS"});
  }
  SECTION("the table maps each name to a results array") {
    for (const auto& a : radx::anim_field_names()) {
      INFO(a.name);
      CHECK_FALSE(a.array.empty());
      CHECK(a.array.find_first_of("/.") == std::string_view::npos);  // docs/theory/results-format.md 3
      CHECK(radx::find_anim_field(a.family, a.name) == &a);
    }
    const auto* dis = radx::find_anim_field("/ANIM/VECT", "dis");
    REQUIRE(dis);
    CHECK(dis->name == "DISP");
    CHECK(radx::find_anim_field("/ANIM/ELEM", "DISP") == nullptr);  // a name belongs to one family
  }
}

TEST_CASE(
    "/RUN without a run number takes it from the file name, /TFILE 0 asks for every cycle, as in Radioss",
    "[engine-io]") {
  radx::test::TempDir dir;
  for (const char* name : {"CASE_0003.rad", "CASE.rad"}) {
    DYNAMIC_SECTION(name) {
      const Built b = build(dir, name, "/RUN/CASE\n1.5\n/TFILE/4\n0.0\n/END\n");
      INFO(all_diags(b.diags));
      const bool restart = std::string(name) != "CASE.rad";
      // Run 3 would be a restart, which radx refuses (the restart test below); nothing else is said.
      CHECK(b.diags.items().size() == (restart ? 1u : 0u));
      CHECK(b.diags.has_errors() == restart);
      CHECK(b.rc.run_name == "CASE");
      CHECK(b.rc.run_number == (restart ? 3 : 1));
      CHECK(b.rc.th_dt == 0.0);
    }
  }
}

TEST_CASE("/RUN with run number 0 takes the file name's number with a note, as the Radioss engine does",
          "[engine-io]") {
  radx::test::TempDir dir;
  for (const char* name : {"CASE_0002.rad", "CASE.rad"}) {
    DYNAMIC_SECTION(name) {
      const Built b = build(dir, name, "/RUN/CASE/0\n1.5\n/END\n");
      INFO(all_diags(b.diags));
      CHECK(b.diags.has_errors() == (std::string(name) != "CASE.rad"));  // run 2: a restart, refused
      CHECK(b.diags.warning_count() == 0);
      const auto* d = find(b.diags, Diag::DefaultApplied);
      REQUIRE(d);
      CHECK(d->severity == radx::Severity::Note);
      CHECK(d->message.find("run number 0") != std::string::npos);
      CHECK(b.rc.run_number == (std::string(name) == "CASE.rad" ? 1 : 2));
    }
  }
  const Built negative = build(dir, "CASE_0001.rad", "/RUN/CASE/-1\n1.5\n/END\n");
  CHECK(find(negative.diags, Diag::ValueOutOfRange));
}

TEST_CASE("a restart run (/RUN/name/2 and on) is refused by name until radx can resume one", "[engine-io]") {
  radx::test::TempDir dir;
  for (const char* text :
       {"/RUN/CASE/2\n1.5\n/END\n", "/RUN/CASE/0\n1.5\n/END\n", "/RUN/CASE\n1.5\n/END\n"}) {
    DYNAMIC_SECTION(text) {
      const Built b = build(dir, "CASE_0002.rad", text);
      INFO(all_diags(b.diags));
      REQUIRE(b.diags.error_count() == 1);
      const auto* d = find(b.diags, Diag::UnimplementedOption);
      REQUIRE(d);
      CHECK(d->line == 1);
      CHECK(d->message.find("run number 2 is a restart run") != std::string::npos);
      CHECK(d->message.find("CASE_0001.rad") != std::string::npos);
    }
  }
  // /RUN's number decides, as in Radioss: run 1 in a file named for run 2 is run 1 (with RX803's warning).
  const Built one = build(dir, "CASE_0002.rad", "/RUN/CASE/1\n1.5\n/END\n");
  CHECK_FALSE(one.diags.has_errors());
}

TEST_CASE("/RBODY/ON and /RBODY/OFF pass over ids that name no rigid body, as Radioss does", "[engine-io]") {
  radx::test::TempDir dir;
  const std::string text = "/RUN/A/1\n1\n/RBODY/ON\n0\n/RBODY/OFF\n4 -2\n/END\n";
  radx::EngineDeck deck;
  Diagnostics diags;
  auto rc = radx::read_run_controls(dir.write("A_0001.rad", text), diags, &deck);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  REQUIRE(diags.items().size() == 2);
  // Id 0 (real decks write it to switch nothing): a note at its line.
  CHECK(diags.items()[0].severity == radx::Severity::Note);
  CHECK(diags.items()[0].line == 4);
  CHECK(diags.items()[0].message.find("id 0") != std::string::npos);
  // A negative id names no rigid body: a warning at its line.
  CHECK(diags.items()[1].severity == radx::Severity::Warning);
  CHECK(diags.items()[1].line == 6);
  CHECK(diags.items()[1].message.find("id -2") != std::string::npos);
  CHECK(rc.rbody_on.empty());
  CHECK(rc.rbody_off == std::vector<std::int64_t>{4});
  SECTION("against the model: an id it lacks is a warning at its line and is dropped") {
    Diagnostics model_diags;
    const std::vector<std::int64_t> bodies = {3, 5};
    radx::check_rigid_body_switches(deck, bodies, rc, model_diags);
    REQUIRE(model_diags.items().size() == 1);
    const auto& d = model_diags.items()[0];
    CHECK(d.severity == radx::Severity::Warning);
    CHECK(d.code == Diag::MissingReference);
    CHECK(d.line == 6);
    CHECK(d.message.find("rigid body 4") != std::string::npos);
    CHECK(rc.rbody_off.empty());
  }
  SECTION("an id the model has stays") {
    Diagnostics model_diags;
    const std::vector<std::int64_t> bodies = {4};
    radx::check_rigid_body_switches(deck, bodies, rc, model_diags);
    CHECK(model_diags.items().empty());
    CHECK(rc.rbody_off == std::vector<std::int64_t>{4});
  }
}

TEST_CASE("output root names and the /RUN name check", "[engine-io]") {
  CHECK(radx::model::run_output_root("dir/NAME_0001.rad") == "NAME");
  CHECK(radx::model::run_output_root("NAME_0000.rad") == "NAME");  // one-file deck named like a starter deck
  CHECK(radx::model::run_output_root("/a/b/Name.rad") == "Name");  // one-file deck
  CHECK(radx::model::run_output_root("CASE_A_0012.rad") == "CASE_A");
  CHECK(radx::model::run_output_root("CASE_12.rad") == "CASE_12");  // not four digits: part of the name

  radx::test::TempDir dir;
  SECTION("name differs") {
    const Built b = build(dir, "BLOCK_0001.rad", "#c\n/RUN/PLATE/1\n1\n/END\n");
    REQUIRE(b.diags.warning_count() == 1);
    CHECK_FALSE(b.diags.has_errors());
    const auto* d = find(b.diags, Diag::EngineRunNameMismatch);
    REQUIRE(d);
    CHECK(d->severity == radx::Severity::Warning);
    CHECK(d->line == 2);
    CHECK(d->message.find("PLATE") != std::string::npos);
    CHECK(d->message.find("BLOCK") != std::string::npos);
  }
  SECTION("number differs") {
    const Built b = build(dir, "BLOCK_0002.rad", "/RUN/BLOCK/1\n1\n/END\n");
    REQUIRE(find(b.diags, Diag::EngineRunNameMismatch));
    CHECK(b.diags.warning_count() == 1);
  }
  SECTION("same name in another case") {
    const Built b = build(dir, "block_0001.rad", "/RUN/Block/1\n1\n/END\n");
    INFO(all_diags(b.diags));
    CHECK(b.diags.items().empty());
  }
}

TEST_CASE("a one-file deck gives the engine part's run controls", "[engine-io]") {
  radx::test::TempDir dir;
  const std::string text = radx::test::begin_block(2019);  // only for its layout; placed after the engine
  const std::string deck =
      "#RADIOSS ONE-FILE\n/RUN/ONE/1\n0.5\n/ANIM/DT\n0 0.05\n/ANIM/VECT/CONT\n"
      "/PRINT/-20\n/END/ENGINE\n" +
      text + "/END\n";
  for (const char* name : {"ONE.rad", "ONE_0000.rad"}) {
    DYNAMIC_SECTION(name) {
      const std::string path = dir.write(name, deck);
      REQUIRE(radx::model::is_one_file_deck(path));
      CHECK(radx::model::run_output_root(path) == "ONE");
      Diagnostics diags;
      const auto rc = radx::read_run_controls(path, diags);
      INFO(all_diags(diags));
      CHECK(diags.items().empty());
      CHECK(rc.run_name == "ONE");
      CHECK(rc.t_stop == Approx(0.5).epsilon(kEps));
      CHECK(rc.anim_dt == Approx(0.05).epsilon(kEps));
      CHECK(rc.anim_vect == std::vector<std::string>{"CONT"});
      CHECK(rc.print_every == 20);
    }
  }
}

TEST_CASE("the energy error of docs/theory/elements.md 8", "[engine-io]") {
  using radx::io::energy_error_percent;
  CHECK(energy_error_percent(110, 100, 0) == Approx(10).epsilon(kEps));
  CHECK(energy_error_percent(90, 100, 10) == Approx(100 * (90.0 / 110.0 - 1)).epsilon(kEps));
  CHECK(energy_error_percent(50, 20, 30) == Approx(0).margin(1e-12));          // W_ext counts like E0
  CHECK(energy_error_percent(1000, 1, 0) == 99.9);                             // clipped
  CHECK(energy_error_percent(0, 1, 0) == -99.9);                               // -100 clipped
  CHECK(energy_error_percent(5, 1e-21, 0) == 0);                               // |E0 + W| <= 1e-20
  CHECK(energy_error_percent(5, 1, -1) == 0);                                  // E0 + W = 0
  CHECK(energy_error_percent(5, 1e-20, 0) == 0);                               // the limit is inclusive
  CHECK(energy_error_percent(2.02e-20, 2e-20, 0) == Approx(1).epsilon(1e-9));  // just above the limit
  CHECK(std::isnan(energy_error_percent(std::nan(""), 1, 0)));                 // NaN shows
  radx::io::EnergyBalance e;
  e.kinetic_t = 60;
  e.kinetic_r = 10;
  e.internal = 25;
  e.hourglass = 3;  // radx books hourglass (and contact) energy in E_tot: its balance closes
  e.initial_total = 80;
  e.external_work = 20;
  CHECK(e.total() == 98);
  CHECK(e.error_percent() == Approx(-2).epsilon(kEps));
}

TEST_CASE("a listing line reads back to its values", "[engine-io]") {
  radx::io::ListingLine l;
  l.cycle = 123456;
  l.time = 1.234567e-3;
  l.dt = 2.2151234e-7;
  l.source = radx::io::StepSource::Shell3;
  l.source_id = 9876543;
  l.error_percent = -12.34;
  l.internal_energy = 15.59876;
  l.kinetic_t = 1.0e-120;  // three-digit exponent
  l.kinetic_r = -3.5e+150;
  l.external_work = 0;
  l.mass_error = -1.25e-9;
  l.total_mass = 4.928e-3;
  l.added_mass = 7.777777e-6;
  const std::string line = radx::io::format_listing_line(l);
  INFO(line);
  const auto t = split(line);
  REQUIRE(t.size() == 13);
  CHECK(std::stoll(t[0]) == l.cycle);
  const double rel = 5e-6;
  CHECK(close_rel(std::stod(t[1]), l.time, rel));
  CHECK(close_rel(std::stod(t[2]), l.dt, rel));
  CHECK(t[3] == "SH3N");
  CHECK(std::stoll(t[4]) == l.source_id);
  REQUIRE(t[5].back() == '%');
  CHECK(std::abs(std::stod(t[5]) - l.error_percent) <= 0.05);
  const double want[] = {l.internal_energy, l.kinetic_t,  l.kinetic_r, l.external_work,
                         l.mass_error,      l.total_mass, l.added_mass};
  for (int k = 0; k < 7; ++k) {
    INFO("column " << 6 + k << ": " << t[static_cast<std::size_t>(6 + k)]);
    CHECK(close_rel(std::stod(t[static_cast<std::size_t>(6 + k)]), want[k], rel));
  }
  // The titles line up with the columns: same length, and each title ends where its column ends.
  const std::string titles = radx::io::listing_column_titles();
  CHECK(titles.size() == line.size());
  for (const char* title : {"CYCLE", "TIME-STEP", "I-ENERGY", "MASS ADDED"}) {
    const auto end = titles.find(title) + std::string(title).size();
    INFO(title);
    REQUIRE(end <= line.size());
    CHECK(line[end - 1] != ' ');
    CHECK((end == line.size() || line[end] == ' '));
  }
  // No controlling element.
  l.source = radx::io::StepSource::None;
  const auto t2 = split(radx::io::format_listing_line(l));
  REQUIRE(t2.size() == 13);
  CHECK(t2[3] == "-");
  CHECK(t2[4] == "-");
  // A negative zero prints as zero.
  l.error_percent = -0.0;
  l.external_work = -0.0;
  const auto t3 = split(radx::io::format_listing_line(l));
  CHECK(t3[5] == "0.0%");
  CHECK(t3[9] == "0.00000E+00");
}

TEST_CASE("listing sinks: titles every nh lines, stdout lines, progress on terminals only", "[engine-io]") {
  radx::io::ListingLine l;
  l.source = radx::io::StepSource::Brick;
  l.source_id = 5;
  auto count = [](const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
    return n;
  };
  SECTION("titles every 3 lines") {
    std::ostringstream file, term;
    radx::io::EngineListing out({&file, &term, true, false, 3});
    for (int k = 0; k < 7; ++k) out.line(l);
    CHECK(count(file.str(), "TIME-STEP") == 3);  // before lines 1, 4 and 7
    std::string order;                           // T: titles, L: a listing line
    std::istringstream is(file.str());
    for (std::string row; std::getline(is, row);)
      order += row.find("TIME-STEP") != std::string::npos ? 'T' : 'L';
    CHECK(order == "TLLLTLLLTL");
    CHECK(count(file.str(), "BRICK") == 7);
    CHECK(term.str() == file.str());
    CHECK(out.lines_written() == 7);
  }
  SECTION("titles once, lines not on stdout") {
    std::ostringstream file, term;
    radx::io::EngineListing out({&file, &term, false, false, 0});
    for (int k = 0; k < 7; ++k) out.line(l);
    CHECK(count(file.str(), "TIME-STEP") == 1);
    CHECK(term.str().empty());
  }
  SECTION("progress") {
    std::ostringstream file, term;
    radx::io::EngineListing piped({&file, &term, true, false, 0});
    piped.progress(10, 0.25, 1.0, 1.0);
    CHECK(term.str().empty());  // not a terminal: nothing
    radx::io::EngineListing tty({&file, &term, true, true, 0});
    tty.progress(10, 0.25, 1.0, 1.0);
    const std::string p = term.str();
    CHECK(p.front() == '\r');
    CHECK(p.find("25.0 %") != std::string::npos);
    CHECK(p.find("left about 3.0 s") != std::string::npos);  // 1 s for a quarter: 3 s more
    tty.progress(11, 0.26, 1.0, 1.1);                        // within 0.5 s: not written
    CHECK(term.str() == p);
    tty.line(l);  // the progress line is blanked first
    CHECK(term.str().find("\r" + std::string(p.size() - 1, ' ') + "\r") == p.size());
    CHECK(file.str().find('\r') == std::string::npos);
  }
  CHECK(radx::io::format_duration(12.34) == "12.3 s");
  CHECK(radx::io::format_duration(187) == "3 min 07 s");
  CHECK(radx::io::format_duration(7500) == "2 h 05 min");
}

namespace {

radx::io::RunSummary sample_summary() {
  radx::io::RunSummary s;
  s.status = radx::io::RunStatus::Error;
  s.message = "stop: \"energy\" \\ error\n\tabove 5 %\x01 caf\xc3\xa9 \xff";
  s.run_name = "BLOCK";
  s.run_number = 2;
  s.version = "0.1.0";
  s.commit = "abc1234-dirty";
  s.arch = "x86-64-v3";
  s.mass_unit = "Mg";
  s.length_unit = "mm";
  s.time_unit = "s";
  s.cycles = 500;
  s.time = 0.1;
  s.dt = 1.0 / 3.0;
  s.nodes = 1234;
  s.elements = 1000;
  s.threads = 4;
  s.wall_seconds = 2.0;
  s.element_loop_seconds = 1.5;  // 3 us per element-cycle over 1000 elements x 500 cycles
  s.initial_mass = 7.5;
  s.mass = 7.625;
  s.added_mass = 0.125;
  s.momentum = {1e-300, -2.5, std::numeric_limits<double>::infinity()};
  s.energy.kinetic_t = 10.5;
  s.energy.kinetic_r = 0.25;
  s.energy.internal = 3.0;
  s.energy.hourglass = 0.5;
  s.energy.contact_elastic = 0.1;
  s.energy.contact_damping = 0.2;
  s.energy.contact_friction = 0.3;
  s.energy.contact_lagrange = 0.4;
  s.energy.external_work = 1.0;
  s.energy.initial_total = 12.0;
  s.interfaces = {{7, 12, 1.5e-3, 4, 40, 2.5e-6, 3, 2468.3, 17}, {9, 0, 0, 0, 0, 0, 0, 0, 0}};
  return s;
}

}  // namespace

TEST_CASE("the end-of-run block", "[engine-io]") {
  const auto s = sample_summary();
  CHECK(radx::io::us_per_element_cycle(s) == Approx(4.0).epsilon(kEps));  // 2 s / (1000 x 500)
  std::ostringstream os;
  radx::io::write_run_summary(os, s);
  const std::string text = os.str();
  INFO(text);
  for (const char* label : {"ERROR TERMINATION", "kinetic, translational", "kinetic, rotational", "internal",
                            "hourglass", "contact, elastic", "contact, damping", "contact, friction",
                            "contact, Lagrange", "external work", "cycles", "wall time", "added mass"})
    CHECK(text.find(label) != std::string::npos);
  CHECK(text.find("1.05000E+01") != std::string::npos);                 // kinetic translational
  CHECK(text.find("4 us per element per cycle") != std::string::npos);  // cost
  // The element loop: 1.5 s / (1000 x 500) = 3 us, 1.5 / 2 = 75 % of the wall time.
  CHECK(text.find("element loop") != std::string::npos);
  CHECK(text.find("3 us per element per cycle, 75.0 % of the wall time") != std::string::npos);
  CHECK(text.find(" 500\n") != std::string::npos);                        // cycles
  CHECK(text.find("(1.67 % of the initial mass)") != std::string::npos);  // 0.125 / 7.5
  CHECK(text.find("17.3 %") != std::string::npos);  // error 100 (15.25 / (12 + 1) - 1) = 17.31
  // One line per interface, with the search's workload: mean candidate pairs per cycle (one decimal), sorts.
  CHECK(
      text.find("  interface 7: active pairs 12, max penetration 1.50000E-03, switched pairs max 4 total 40, "
                "added mass 2.50000E-06, nodes removed 3, candidate pairs per cycle 2468.3 (mean), search "
                "sorts 17\n") != std::string::npos);
  CHECK(text.find("  interface 9: active pairs 0, max penetration 0.00000E+00, switched pairs max 0 total 0, "
                  "added mass 0.00000E+00, nodes removed 0, candidate pairs per cycle 0.0 (mean), search "
                  "sorts 0\n") != std::string::npos);
}

TEST_CASE("NAME_summary.json reads back with its values", "[engine-io]") {
  using radx::io::json_number;
  // Doubles read back bit for bit; non-finite values are null.
  for (double v : {0.1, 1.0 / 3.0, -2.5e-300, 1e30, 6.02214076e23, 5e-324, -0.0, 123456789012345.0}) {
    INFO(json_number(v));
    CHECK(std::strtod(json_number(v).c_str(), nullptr) == v);
  }
  CHECK(json_number(std::numeric_limits<double>::infinity()) == "null");
  CHECK(json_number(std::nan("")) == "null");
  CHECK(radx::io::json_string("a\"b\\c\n\x1f") == "\"a\\\"b\\\\c\\n\\u001f\"");

  radx::test::TempDir dir;
  const auto s = sample_summary();
  const std::string path = radx::io::summary_json_path(dir.path().string(), "BLOCK");
  CHECK(fs::path(path).filename() == "BLOCK_summary.json");
  std::string error;
  REQUIRE(radx::io::write_summary_json(path, s, error));
  CHECK(error.empty());
  CHECK(fs::exists(path));
  CHECK_FALSE(fs::exists(path + ".part"));

  // An independent reader: Python's json module, with the expected values written here.
  const std::string script = dir.write("check.py", R"PY(
import json, sys
d = json.load(open(sys.argv[1], encoding="utf-8"))
def need(cond, what):
    if not cond:
        print("FAILED:", what, file=sys.stderr)
        sys.exit(1)
for k in ["status", "message", "cycles", "time", "dt", "nodes", "elements", "threads", "wall_seconds",
          "us_per_element_cycle", "mass", "added_mass", "momentum", "energy", "interfaces"]:
    need(k in d, "key " + k)
need(d["status"] == "error", "status")
need(d["message"] == 'stop: "energy" \\ error\n\tabove 5 %\x01 caf\u00e9 \ufffd', "message " + repr(d["message"]))
need(d["run_name"] == "BLOCK" and d["run_number"] == 2, "run")
need(d["version"] == "0.1.0" and d["commit"] == "abc1234-dirty" and d["arch"] == "x86-64-v3", "build")
need(d["units"] == {"mass": "Mg", "length": "mm", "time": "s"}, "units " + repr(d.get("units")))
need(d["cycles"] == 500 and isinstance(d["cycles"], int), "cycles")
need(d["time"] == 0.1, "time")
need(d["dt"] == 1.0 / 3.0, "dt")
need(d["nodes"] == 1234 and d["elements"] == 1000 and d["threads"] == 4, "counts")
need(d["wall_seconds"] == 2.0, "wall")
need(abs(d["us_per_element_cycle"] - 4.0) <= 1e-12, "cost")
need(d["element_loop_seconds"] == 1.5, "element loop wall time")
need(abs(d["element_loop_us_per_element_cycle"] - 3.0) <= 1e-12, "element loop cost")
need(d["mass"] == 7.625 and d["added_mass"] == 0.125, "mass")
need(d["momentum"] == [1e-300, -2.5, None], "momentum " + repr(d["momentum"]))
e = d["energy"]
for k in ["kinetic", "internal", "hourglass", "external_work", "contact_elastic", "contact_damping",
          "contact_friction", "contact_lagrange", "error_percent"]:
    need(k in e, "energy key " + k)
need(e["kinetic"] == 10.75 and e["internal"] == 3.0 and e["hourglass"] == 0.5, "energies")
need(e["external_work"] == 1.0 and e["contact_elastic"] == 0.1 and e["contact_damping"] == 0.2, "contact")
need(e["contact_friction"] == 0.3 and e["contact_lagrange"] == 0.4, "contact 2")
need(abs(e["error_percent"] - 100 * (15.25 / 13.0 - 1)) <= 1e-12, "error_percent")
i = d["interfaces"]
need(len(i) == 2, "interfaces")
need(i[0] == {"id": 7, "active_pairs": 12, "max_penetration": 1.5e-3, "switched_pairs_max": 4,
              "switched_pairs_total": 40, "added_mass": 2.5e-6, "removed_nodes": 3, "candidates_mean": 2468.3,
              "search_sorts": 17}, "interface 7 " + repr(i[0]))
need(isinstance(i[0]["search_sorts"], int), "search_sorts is an integer")
need(i[1]["id"] == 9 and i[1]["max_penetration"] == 0, "interface 9")
)PY");
  const std::string cmd = "/usr/bin/python3 " + script + " " + path;
  CHECK(std::system(cmd.c_str()) == 0);

  // With no interface the list is empty, and the document is still valid JSON. Build and units unknown (a
  // run stopped before its model was read): their keys are left out rather than written empty.
  auto s2 = s;
  s2.interfaces.clear();
  s2.status = radx::io::RunStatus::Normal;
  s2.version = s2.commit = s2.arch = s2.mass_unit = s2.length_unit = s2.time_unit = "";
  const std::string text = radx::io::summary_json(s2);
  CHECK(text.find("\"interfaces\": []") != std::string::npos);
  CHECK(text.find("\"status\": \"normal\"") != std::string::npos);
  for (const char* key : {"\"version\"", "\"commit\"", "\"arch\"", "\"units\""}) {
    INFO(key);
    CHECK(text.find(key) == std::string::npos);
  }
  const std::string p2 = dir.write("empty.json", text);
  const std::string cmd2 =
      "/usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(d[\"interfaces\"] != "
      "[])' " +
      p2;
  CHECK(std::system(cmd2.c_str()) == 0);

  // A folder that does not exist: an error, no file.
  CHECK_FALSE(radx::io::write_summary_json((dir.path() / "no" / "x.json").string(), s, error));
  CHECK_FALSE(error.empty());
}

TEST_CASE("NAME_summary.json reads back through read_summary_json", "[engine-io]") {
  radx::test::TempDir dir;
  const auto s = sample_summary();
  const std::string path = radx::io::summary_json_path(dir.path().string(), "BLOCK");
  std::string error;
  REQUIRE(radx::io::write_summary_json(path, s, error));
  radx::io::RunSummary r;
  REQUIRE(radx::io::read_summary_json(path, r, error));
  CHECK(r.status == radx::io::RunStatus::Error);
  // The invalid byte 0xff was written as U+FFFD; the rest of the message comes back byte for byte.
  CHECK(r.message == "stop: \"energy\" \\ error\n\tabove 5 %\x01 caf\xc3\xa9 \xef\xbf\xbd");
  CHECK(r.run_name == "BLOCK");
  CHECK(r.run_number == 2);
  CHECK(r.version == "0.1.0");
  CHECK(r.commit == "abc1234-dirty");
  CHECK(r.arch == "x86-64-v3");
  CHECK(r.mass_unit == "Mg");
  CHECK(r.length_unit == "mm");
  CHECK(r.time_unit == "s");
  CHECK(r.cycles == 500);
  CHECK(r.time == 0.1);
  CHECK(r.dt == 1.0 / 3.0);  // 17 digits: the same double
  CHECK(r.nodes == 1234);
  CHECK(r.elements == 1000);
  CHECK(r.threads == 4);
  CHECK(r.element_loop_seconds == 1.5);
  CHECK(r.mass == 7.625);
  CHECK(r.momentum[0] == 1e-300);
  CHECK(std::isnan(r.momentum[2]));  // infinity was written as null
  CHECK(r.energy.kinetic_t == 10.5);
  CHECK(r.energy.kinetic_r == 0.25);
  CHECK(r.energy.internal == 3.0);
  CHECK(r.energy.hourglass == 0.5);
  CHECK(r.energy.contact_lagrange == 0.4);
  CHECK(r.energy.external_work == 1.0);
  CHECK(r.energy.initial_total == 12.0);
  REQUIRE(r.interfaces.size() == 2);
  CHECK(r.interfaces[0].id == 7);
  CHECK(r.interfaces[0].removed_nodes == 3);
  CHECK(r.interfaces[0].candidates_mean == 2468.3);
  CHECK(r.interfaces[0].search_sorts == 17);
  CHECK(r.interfaces[1].candidates_mean == 0);
  CHECK(r.interfaces[1].search_sorts == 0);

  // Not JSON, or not a summary: an error naming the file.
  for (const char* bad :
       {"{\"status\": \"normal\", \"cycles\": 1, \"time\": 0.1}",                 // no energy
        "{\"status\": \"normal\", \"cycles\": 1, \"time\": 0.1, \"energy\": {}",  // unclosed
        "{\"status\": \"fine\", \"cycles\": 1, \"time\": 0.1, \"energy\": {}}",
        "{\"status\": \"normal\", \"cycles\": \"1\", \"time\": 0.1, \"energy\": {}}",
        "{\"status\": \"normal\", \"cycles\": 01, \"time\": 0.1, \"energy\": {}}", "[]", ""}) {
    INFO(bad);
    const std::string p = dir.write("bad.json", bad);
    error.clear();
    CHECK_FALSE(radx::io::read_summary_json(p, r, error));
    CHECK(error.rfind(p + ": ", 0) == 0);
  }
  const std::string ok = dir.write("ok.json",
                                   " {\"status\":\"normal\",\"cycles\":7,\"time\":2.5E-1,\"energy\":{"
                                   "\"internal\":-1e-3},\"x\":[true,false,null]}\n");
  REQUIRE(radx::io::read_summary_json(ok, r, error));
  CHECK(r.status == radx::io::RunStatus::Normal);
  CHECK(r.cycles == 7);
  CHECK(r.time == 0.25);
  CHECK(r.energy.internal == -1e-3);
  CHECK_FALSE(radx::io::read_summary_json((dir.path() / "none.json").string(), r, error));
}

TEST_CASE("A summary of a run stopped by a signal or still running reads back as neither normal nor error",
          "[engine-io]") {
  radx::test::TempDir dir;
  std::string error;
  using radx::io::RunStatus;
  // SIGTERM stopped the run after a cycle (interrupted); the summary a run writes when it starts (running),
  // which a run killed outright leaves behind.
  for (const auto& [status, name, label] :
       {std::tuple{RunStatus::Interrupted, "interrupted", "INTERRUPTED TERMINATION"},
        std::tuple{RunStatus::Running, "running", "RUNNING"}}) {
    INFO(name);
    auto s = sample_summary();
    s.status = status;
    const std::string text = radx::io::summary_json(s);
    CHECK(text.find(std::string("\"status\": \"") + name + "\"") != std::string::npos);
    const std::string path = radx::io::summary_json_path(dir.path().string(), name);
    REQUIRE(radx::io::write_summary_json(path, s, error));
    radx::io::RunSummary r;
    REQUIRE(radx::io::read_summary_json(path, r, error));
    CHECK(r.status == status);
    CHECK(radx::io::termination_label(status) == label);
  }
  std::ostringstream listing;
  auto s = sample_summary();
  s.status = RunStatus::Interrupted;
  s.message = "interrupted by SIGTERM at cycle 12, time 1.00000E-03";
  radx::io::write_run_summary(listing, s);
  // The heading with its reason, and the last line a script checks.
  const auto heading = listing.str().find("  INTERRUPTED TERMINATION\n");
  REQUIRE(heading != std::string::npos);
  CHECK(listing.str().find("  interrupted by SIGTERM at cycle 12") > heading);
  CHECK(listing.str().ends_with("  INTERRUPTED TERMINATION\n"));
}

TEST_CASE("/DTIX: DT_ini and DT_max reach the run controls, bad values are located errors", "[engine-io]") {
  radx::test::TempDir dir;
  {
    const Built b = build(dir, "A_0001.rad", "/RUN/A/1\n1.5\n/DTIX\n1e-7 4e-7\n/END\n");
    INFO(all_diags(b.diags));
    CHECK_FALSE(b.diags.has_errors());
    CHECK(b.rc.dt_initial == 1e-7);
    CHECK(b.rc.dt_max == 4e-7);
  }
  {
    const Built b = build(dir, "A_0001.rad", "/RUN/A/1\n1.5\n/DTIX\n2e-7 0\n/END\n");  // 0: no bound
    CHECK_FALSE(b.diags.has_errors());
    CHECK(b.rc.dt_max >= 1e30);
  }
  {
    const std::string text = "/RUN/A/1\n1.5\n/DTIX\n5e-7 4e-7\n/END\n";
    const Built b = build(dir, "A_0001.rad", text);
    const auto* d = find(b.diags, Diag::InconsistentValues);
    REQUIRE(d != nullptr);
    CHECK(d->line == line_of(text, "/DTIX"));
    CHECK(d->message.find("DT_ini") != std::string::npos);
  }
}

TEST_CASE("/DT/<family>/STOP and /DT/INTER/STOP: the family's scale and a minimum that stops the run",
          "[engine-io]") {
  radx::test::TempDir dir;
  {
    const Built b =
        build(dir, "A_0001.rad",
              "/RUN/A/1\n1.5\n/DT/INTER/STOP\n0.5 1e-8\n/DT/SPRING/STOP\n0.7 2e-8\n/DT/BRICK/STOP\n"
              "0 3e-8\n/DT/SHELL/STOP\n0.6 4e-8\n/DT/SH3N/STOP\n0.4 5e-8\n/END\n");
    INFO(all_diags(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    CHECK(b.diags.warning_count() == 0);
    struct Want {
      const radx::model::DtControl* c;
      double scale, t_min;
    };
    for (const auto& w :
         {Want{&b.rc.inter, 0.5, 1e-8}, Want{&b.rc.spring, 0.7, 2e-8}, Want{&b.rc.brick, 0.9, 3e-8},
          Want{&b.rc.shell, 0.6, 4e-8}, Want{&b.rc.shell3, 0.4, 5e-8}}) {
      CHECK(w.c->given);
      CHECK(w.c->action == DtAction::Stop);
      CHECK(w.c->scale == Approx(w.scale).epsilon(kEps));  // Tscale 0: the /DT scale, 0.9
      CHECK(w.c->t_min == Approx(w.t_min).epsilon(kEps));
    }
  }
  {
    // One action per minimum: /STOP with /CST is a located error; Tmin 0 never stops (a warning).
    const std::string text =
        "/RUN/A/1\n1.5\n/DT/BRICK/CST\n0.9 1e-8\n/DT/BRICK/STOP\n0.9 1e-8\n/DT/INTER/LAG\n"
        "0.9 1e-8\n/DT/INTER/STOP\n0.9 1e-8\n/DT/SPRING/STOP\n0.9 0\n/END\n";
    const Built b = build(dir, "A_0001.rad", text);
    std::size_t both = 0;
    for (const auto& d : b.diags.items())
      if (d.code == Diag::InconsistentValues && d.message.find("are both given") != std::string::npos) ++both;
    CHECK(both == 2);
    const auto* zero = find(b.diags, Diag::ValueOutOfRange);
    REQUIRE(zero != nullptr);
    CHECK(zero->line == line_of(text, "/DT/SPRING/STOP"));
    CHECK(zero->message.find("never stops the run") != std::string::npos);
  }
}
