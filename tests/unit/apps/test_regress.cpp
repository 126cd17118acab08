// `radx regress`: the ref.extract reader and its errors, the deviation arithmetic, how a deck's status
// follows from its run, deck discovery, and the command end to end on decks built here from the repository's
// free-fall deck, with reference values from the closed form KE = W_ext = M g^2 t^2 / 2 (M = 2.7 kg,
// g = 9.81 m/s2; decks/verification/free_fall/README.md).
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "apps/regress.hpp"
#include "io/regress/regression_extract.hpp"
#include "test_util.hpp"

namespace fs = std::filesystem;
using radx::io::ExtractEnergy;

namespace {

// The example of the brief, as OpenRadioss writes it: blanks then tabs.
const std::string kExtract =
    "    1 Start                    0\n"
    "    2 CYCLE\t        29\n"
    "    3 TIME\t 2.5380e-02\n"
    "    4 TSTEP\t 8.7470e-04\n"
    "    5 ELEMENT\t0\n"
    "    6 ELTID\t        70\n"
    "    7 ERROR\t  0.2\n"
    "    8 IENERGY\t 8.8150e-02 2.3330e-01\n"
    "    9 KENERGYT\t 1.4560e-01 2.3330e-01\n"
    "   10 KENERGYR\t 7.0160e-18 2.3330e-01\n"
    "   11 EXTWORK\t 2.3330e-01 2.3330e-01\n"
    "   12 MASERR\t0.000\n"
    "   13 Stop                    0\n";

std::string parse_error(const std::string& text) {
  radx::io::RegressionExtract r;
  std::string error;
  CHECK_FALSE(radx::io::parse_regression_extract(text, "dir/ref.extract", r, error));
  return error;
}

// kExtract with line `n` (1-based) replaced by `line`, or removed when `line` is empty.
std::string with_line(int n, const std::string& line) {
  std::istringstream in(kExtract);
  std::string out, l;
  for (int k = 1; std::getline(in, l); ++k) {
    if (k != n)
      out += l + "\n";
    else if (!line.empty())
      out += line + "\n";
  }
  return out;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int exit_code(const std::string& cmd) {
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

// The free-fall closed form (decks/verification/free_fall/README.md).
constexpr double kMass = 2700.0 * 0.1 * 0.1 * 0.1;  // rho L^3, kg
constexpr double kG = 9.81;
double free_fall_energy(double t) {
  return 0.5 * kMass * kG * kG * t * t;
}

// A ref.extract whose four energies are those of a free fall at time t (internal and rotational zero), the
// magnitude the kinetic energy.
std::string free_fall_extract(double t, long cycles) {
  const double ke = free_fall_energy(t);
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "    1 Start                    0\n"
                "    2 CYCLE\t%10ld\n"
                "    3 TIME\t %.4e\n"
                "    8 IENERGY\t 0.0000e+00 %.4e\n"
                "    9 KENERGYT\t %.4e %.4e\n"
                "   10 KENERGYR\t 0.0000e+00 %.4e\n"
                "   11 EXTWORK\t %.4e %.4e\n"
                "   13 Stop                    0\n",
                cycles, t, ke, ke, ke, ke, ke, ke);
  return buf;
}

}  // namespace

TEST_CASE("ref.extract: values, magnitudes, the keys radx skips", "[regress]") {
  radx::io::RegressionExtract r;
  std::string error;
  REQUIRE(radx::io::parse_regression_extract(kExtract, "ref.extract", r, error));
  CHECK(r.cycles == 29);
  CHECK(r.time == 2.5380e-02);
  CHECK(r[ExtractEnergy::Internal].value == 8.8150e-02);
  CHECK(r[ExtractEnergy::Internal].magnitude == 2.3330e-01);
  CHECK(r[ExtractEnergy::KineticTranslational].value == 1.4560e-01);
  CHECK(r[ExtractEnergy::KineticRotational].value == 7.0160e-18);
  CHECK(r[ExtractEnergy::KineticRotational].magnitude == 2.3330e-01);
  CHECK(r[ExtractEnergy::ExternalWork].value == 2.3330e-01);

  // Windows line ends, blank lines and a key radx does not know change nothing.
  std::string crlf;
  for (char c : "\n" + kExtract + "\n   14 NEWKEY 1 2 3\n")
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  radx::io::RegressionExtract r2;
  REQUIRE(radx::io::parse_regression_extract(crlf, "ref.extract", r2, error));
  CHECK(r2.cycles == 29);
  CHECK(r2[ExtractEnergy::ExternalWork].magnitude == 2.3330e-01);

  CHECK(radx::io::extract_key(ExtractEnergy::KineticRotational) == "KENERGYR");
  CHECK(radx::io::extract_label(ExtractEnergy::ExternalWork) == "EXT");
}

TEST_CASE("ref.extract: a malformed line is an error naming the file and the line", "[regress]") {
  using Catch::Matchers::Contains;
  using Catch::Matchers::StartsWith;
  CHECK_THAT(parse_error(with_line(8, "    8 IENERGY\t 8.8150e-02")),
             StartsWith("dir/ref.extract:8: IENERGY needs a value and a reference magnitude") &&
                 Contains("found \"8.8150e-02\""));
  CHECK_THAT(parse_error(with_line(9, "    9 KENERGYT\t 1.4x60e-01 2.3330e-01")),
             StartsWith("dir/ref.extract:9: KENERGYT needs") && Contains("1.4x60e-01"));
  CHECK_THAT(parse_error(with_line(11, "   11 EXTWORK\t 2.3330e-01 -1.0")),
             StartsWith("dir/ref.extract:11: EXTWORK") && Contains("magnitude \"-1.0\""));
  CHECK_THAT(parse_error(with_line(11, "   11 EXTWORK\t 2.3330e-01 2.3330e-01 7")),
             StartsWith("dir/ref.extract:11: EXTWORK"));
  CHECK_THAT(parse_error(with_line(10, "   10 KENERGYR\t inf 2.3330e-01")),
             StartsWith("dir/ref.extract:10: "));
  CHECK_THAT(parse_error(with_line(2, "    2 CYCLE\t 29.5")),
             StartsWith("dir/ref.extract:2: CYCLE needs one integer"));
  CHECK_THAT(parse_error(with_line(3, "    3 TIME")),
             StartsWith("dir/ref.extract:3: TIME needs one number") && Contains("found nothing"));
  CHECK_THAT(parse_error(with_line(3, "TIME 2.5e-2")),
             StartsWith("dir/ref.extract:3: expected a line number and a key"));
  CHECK_THAT(parse_error(with_line(5, "    5 CYCLE 30")),
             StartsWith("dir/ref.extract:5: a second CYCLE line (the first is line 2)"));
  CHECK_THAT(parse_error(with_line(10, "")), StartsWith("dir/ref.extract: no KENERGYR line"));
  CHECK_THAT(parse_error(""), Contains("no IENERGY, KENERGYT, KENERGYR, EXTWORK, CYCLE, TIME line"));

  radx::io::RegressionExtract r;
  std::string error;
  CHECK_FALSE(radx::io::read_regression_extract("/nonexistent/ref.extract", r, error));
  CHECK_THAT(error, StartsWith("/nonexistent/ref.extract: cannot open"));
}

TEST_CASE("regress: deviations are |radx - ref| / magnitude, the cycle count a ratio", "[regress]") {
  using radx::io::energy_deviation;
  CHECK(energy_deviation(0.1, 0.08815, 0.2333) == Approx((0.1 - 0.08815) / 0.2333).epsilon(1e-15));
  CHECK(energy_deviation(0.08, 0.08815, 0.2333) == Approx((0.08815 - 0.08) / 0.2333).epsilon(1e-15));
  // A tiny energy against a tiny reference is measured on the run's scale, not its own.
  CHECK(energy_deviation(2e-18, 7.016e-18, 0.2333) < 1e-16);
  CHECK(energy_deviation(0.0, 0.0, 0.0) == 0.0);
  CHECK(std::isinf(energy_deviation(1e-30, 0.0, 0.0)));
  CHECK(std::isnan(energy_deviation(std::nan(""), 1.0, 1.0)));
  CHECK(radx::io::relative_deviation(0.0254, 0.02538) == Approx(0.02 / 25.38).epsilon(1e-12));

  radx::io::RegressionExtract ref;
  std::string error;
  REQUIRE(radx::io::parse_regression_extract(kExtract, "ref.extract", ref, error));
  radx::io::RunFigures radx;
  radx.cycles = 58;
  radx.time = 2.5380e-02;
  radx.energy = {8.8150e-02 + 0.05 * 2.3330e-01, 1.4560e-01 - 0.01 * 2.3330e-01, 0.0, 2.3330e-01};
  const auto c = radx::io::compare_to_extract(radx, ref);
  CHECK(c.cycle_ratio == 2.0);
  CHECK(c.time == 0.0);
  CHECK(c.energy[0] == Approx(0.05).epsilon(1e-12));
  CHECK(c.energy[1] == Approx(0.01).epsilon(1e-12));
  CHECK(c.energy[2] == Approx(7.016e-18 / 0.2333).epsilon(1e-12));
  CHECK(c.energy[3] == 0.0);
  CHECK(c.within(0.0501));
  CHECK_FALSE(c.within(0.0499));
  auto nan = c;
  nan.energy[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(nan.within(1e9));  // a NaN energy never passes
}

TEST_CASE("regress: the first error line, shortened, and its group", "[regress]") {
  const auto e = radx::app::first_error(
      "radx starter 0.1.0\n  0 error(s), 3 warning(s)\n"
      "/a/b/LOI14_0000.rad:12:1: warning: RX900: something\n"
      "/a/b/LOI14_0000.rad:40:11: error: RX402: [/PART id 1 \"x\"] mat_ID = 1: there is no /MAT/1\n"
      "/a/b/LOI14_0000.rad:59:1: error: RX301: [/MAT/LAW14] unknown keyword /MAT/LAW14: not a keyword\n"
      "/a/b/LOI14_0000.rad:60:1: error: RX402: second\n");
  CHECK(e.location == "LOI14_0000.rad:59");
  CHECK(e.message == "RX301: [/MAT/LAW14] unknown keyword /MAT/LAW14: not a keyword");
  CHECK(radx::app::refusal_group(e.message) == "RX301 /MAT/LAW14");
  CHECK(radx::app::refusal_group("RX402: [/PART id 1 \"x\"] prop_ID = 2: no /PROP/2") == "RX402 /PART");
  CHECK(radx::app::refusal_group("cannot write the results: disk full") == "cannot write the results");

  // Only dangling references: the first of them.
  CHECK(
      radx::app::first_error("F.rad:7:1: error: RX402: [/PART id 2] no /PROP/3\nF.rad:9:1: error: RX402: b\n")
          .location == "F.rad:7");

  const auto p = radx::app::first_error("radx-engine: error: cannot write the results\r\n");
  CHECK(p.location == "radx-engine");
  CHECK(p.message == "cannot write the results");
  const auto none = radx::app::first_error("radx-engine: 1 error(s) in X; nothing was run\nterror: no\n");
  CHECK(none.message.empty());
  CHECK(radx::app::first_error("error: bare\n").message == "bare");

  CHECK(radx::app::shorten("short", 10) == "short");
  CHECK(radx::app::shorten("the Radioss keyword /MAT/LAW36 is not supported", 30) ==
        "the Radioss keyword...");
  CHECK(radx::app::shorten("the Radioss keyword /MAT/LAW36 is not supported", 30).size() <= 30);
}

TEST_CASE("regress: deck folders, labels, references and restart notes", "[regress]") {
  radx::test::TempDir dir;
  const fs::path root = dir.path() / "qa";
  dir.write("qa/A/data/CASE_0000.rad", "/BEGIN\n");
  dir.write("qa/A/data/CASE_0001.rad", "/RUN\n");
  dir.write("qa/A/data/ref.extract", kExtract);
  dir.write("qa/B/ONE_0000.rad", "");
  dir.write("qa/B/TWO_0000.rad", "");
  dir.write("qa/B/TWO_0001.rad", "");
  dir.write("qa/B/ref.extract", kExtract);
  dir.write("qa/C/Single.rad", "#RADIOSS STARTER\n/BEGIN\n/END\n/END/ENGINE\n");
  dir.write("qa/C/include.rad", "/NODE\n");  // neither a starter deck nor a one-file deck
  dir.write("qa/D/R_0000.rad", "");
  dir.write("qa/D/R_0001.rad", "");
  dir.write("qa/D/R_0002.rad", "");
  dir.write("qa/D/R_0003.rad", "");
  dir.write("qa/.hidden/H_0000.rad", "");
  dir.write("qa/E/only_include.rad", "/NODE\n");
  dir.write("qa/TOP_0000.rad", "");

  const auto decks = radx::app::find_regress_decks({root});
  REQUIRE(decks.size() == 6);
  CHECK(decks[0].label == "qa");  // a deck directly in DIR: DIR's name
  CHECK(decks[0].starter_deck.filename() == "TOP_0000.rad");
  CHECK(decks[1].label == "A/data");
  CHECK(decks[1].reference == root / "A/data/ref.extract");
  CHECK(decks[1].work_subdir == fs::path("A~data"));
  CHECK(decks[1].note.empty());
  CHECK(decks[2].label == "B/ONE_0000.rad");
  CHECK(decks[2].reference.empty());
  CHECK(decks[2].note == "ref.extract not used: the folder holds 2 decks");
  CHECK(decks[3].label == "B/TWO_0000.rad");
  CHECK(decks[3].work_subdir == fs::path("B~TWO_0000"));
  CHECK(decks[4].label == "C");
  CHECK(decks[4].starter_deck.filename() == "Single.rad");
  CHECK(decks[5].label == "D");
  CHECK(decks[5].note == "R_0002.rad, R_0003.rad not run (radx runs R_0001.rad only: it has no restart)");

  // Several DIRs: labels start with each DIR as given; a deck reached twice runs once; the work folder
  // is skipped.
  const auto two = radx::app::find_regress_decks({root / "A", root / "D", root}, root / "B");
  REQUIRE(two.size() == 4);
  CHECK(two[0].label == (root / "A/data").generic_string());
  CHECK(two[0].work_subdir == fs::path("1_A~data"));
  CHECK(two[1].label == (root / "D").generic_string());
  CHECK(two[2].starter_deck.filename() == "TOP_0000.rad");
  CHECK(two[3].starter_deck.filename() == "Single.rad");
}

TEST_CASE("regress: a deck's status follows from its run", "[regress]") {
  radx::test::TempDir dir;
  radx::app::RegressDeck deck;
  deck.label = "X";
  radx::app::ChildOutcome exited;
  exited.exit_code = 0;
  radx::app::RegressRunFiles files;
  using radx::app::RegressStatus;

  // No model file: the starter refused it.
  auto failed = exited;
  failed.exit_code = 1;
  files.output = "X_0000.rad:3:1: error: RX302: [/MAT/LAW36] not supported\n";
  auto r = radx::app::evaluate_deck(deck, failed, files, 0.05);
  CHECK(r.status == RegressStatus::ReadError);
  CHECK(r.refusal.message == "RX302: [/MAT/LAW36] not supported");
  CHECK(r.detail.empty());
  CHECK(radx::app::is_failure(r.status));

  // A model file, then the time limit: the engine ran out of time.
  files.model_written = true;
  files.output.clear();
  auto late = failed;
  late.exit_code = -1;
  late.timed_out = true;
  late.signal = 9;
  late.seconds = 3.0;
  r = radx::app::evaluate_deck(deck, late, files, 0.05);
  CHECK(r.status == RegressStatus::RunError);
  CHECK(r.detail == "the engine ran out of time (3.0 s)");

  // An error termination.
  radx::io::RunSummary s;
  s.status = radx::io::RunStatus::Error;
  s.message = "/STOP: energy error above 10 %";
  files.summary = s;
  r = radx::app::evaluate_deck(deck, failed, files, 0.05);
  CHECK(r.status == RegressStatus::RunError);
  CHECK(r.detail == "error termination: /STOP: energy error above 10 %");

  // Stopped by SIGTERM (the engine exits 143), or killed outright so the summary written at the start is
  // left: a run error even with exit code 0, since the figures are not those of the finished run.
  s.status = radx::io::RunStatus::Interrupted;
  s.message = "interrupted by SIGTERM at cycle 12, time 1.00000E-03";
  files.summary = s;
  r = radx::app::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::RunError);
  CHECK(r.detail == "the engine was interrupted by SIGTERM at cycle 12, time 1.00000E-03");
  s.status = radx::io::RunStatus::Running;
  files.summary = s;
  r = radx::app::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::RunError);
  CHECK(r.detail == "the engine did not finish (its summary still says \"running\")");

  // A normal run: ran without a reference, compared or deviates with one, ref-error with a broken one.
  s.status = radx::io::RunStatus::Normal;
  s.cycles = 40;
  s.time = 2.5380e-02;
  s.energy.internal = 8.8150e-02;
  s.energy.kinetic_t = 1.4560e-01 + 0.04 * 2.3330e-01;  // 4 % of the magnitude
  s.energy.kinetic_r = 0;
  s.energy.external_work = 2.3330e-01;
  s.energy.hourglass = 1.0;  // not compared: IENERGY is the listing's I-ENERGY
  files.summary = s;
  r = radx::app::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::Ran);
  REQUIRE(r.radx);
  CHECK(r.radx->cycles == 40);
  CHECK_FALSE(radx::app::is_failure(r.status));

  deck.reference = dir.write("ref.extract", kExtract);
  r = radx::app::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::Compared);
  REQUIRE(r.comparison);
  CHECK(r.comparison->energy[1] == Approx(0.04).epsilon(1e-9));
  CHECK(r.comparison->energy[0] == 0.0);
  CHECK(r.comparison->cycle_ratio == Approx(40.0 / 29.0));
  CHECK(radx::app::format_regress_line(r).find("compared  cycles 40/29 (x1.38)") != std::string::npos);
  r = radx::app::evaluate_deck(deck, exited, files, 0.03);
  CHECK(r.status == RegressStatus::Deviates);
  CHECK(radx::app::is_failure(r.status));

  deck.reference = dir.write("bad.extract", with_line(9, "    9 KENERGYT\t 1.4560e-01"));
  r = radx::app::evaluate_deck(deck, exited, files, 0.05);
  CHECK(r.status == RegressStatus::RefError);
  CHECK(r.detail.find("bad.extract:9: KENERGYT") != std::string::npos);
}

TEST_CASE("radx regress end to end: statuses, table, exit code and JSON summary", "[regress][app]") {
  radx::test::TempDir dir;
  const fs::path decks = dir.path() / "decks";
  const fs::path source = fs::path(RADX_SOURCE_DIR) / "decks/verification/free_fall";
  const std::string starter = slurp(source / "FREE_FALL_0000.rad");
  const std::string engine = slurp(source / "FREE_FALL_0001.rad");
  REQUIRE(starter.find("/MAT/LAW1/1") != std::string::npos);
  REQUIRE(engine.find("                0.01\n") != std::string::npos);  // Tstop
  const auto add = [&](const std::string& folder, const std::string& s, const std::string& e) {
    dir.write("decks/" + folder + "/FREE_FALL_0000.rad", s);
    dir.write("decks/" + folder + "/FREE_FALL_0001.rad", e);
  };
  // Falls 0.01 s; its reference is the closed form at 0.01 s.
  add("ok", starter, engine);
  dir.write("decks/ok/ref.extract", free_fall_extract(0.01, 1000));
  // The same run against the closed form at 0.012 s: KE deviates by 1 - (0.01 / 0.012)^2 = 30.6 %.
  add("off", starter, engine);
  dir.write("decks/off/ref.extract", free_fall_extract(0.012, 1000));
  // No reference.
  add("noref", starter, engine);
  // A material law radx does not read: the starter refuses it.
  std::string broken = starter;
  broken.replace(broken.find("/MAT/LAW1/1"), 11, "/MAT/LAW14/1");
  add("broken", broken, engine);
  // Falls for 1000 s (about 10^8 cycles): stopped by the time limit.
  std::string endless = engine;
  endless.replace(endless.find("                0.01\n"), 21, "              1000.0\n");
  add("endless", starter, endless);
  dir.write("decks/endless/ref.extract", free_fall_extract(0.01, 1000));

  const std::string exe = RADX_DRIVER_EXE;
  const fs::path work = dir.path() / "work";
  const fs::path summary = dir.path() / "summary.json";
  const fs::path log = dir.path() / "out.txt";
  const std::string cmd = exe + " regress " + decks.string() + " --timeout 4 --work " + work.string() +
                          " --summary " + summary.string() + " > " + log.string() + " 2>&1";
  CHECK(exit_code(cmd) == 1);  // a deck fails
  const std::string out = slurp(log);
  INFO(out);
  CHECK(out.find("broken  read-error  FREE_FALL_0000.rad:") != std::string::npos);
  CHECK(out.find("[/MAT/LAW14 id 1]") != std::string::npos);
  CHECK(out.find("endless  run-error") != std::string::npos);
  CHECK(out.find("the engine ran out of time") != std::string::npos);
  CHECK(out.find("noref  ran  cycles") != std::string::npos);
  CHECK(out.find("ok  compared  cycles") != std::string::npos);
  CHECK(out.find("off  deviates  cycles") != std::string::npos);
  CHECK(out.find("deck     status      cycles radx/ref  IE dev %  KE dev %  KER dev %  EXT dev %  worst "
                 "quantity, or first refusal") != std::string::npos);
  CHECK(out.find("decks found 5, read 4, ran 3, compared 1 of 3 with a reference (NAME.ref; ref.extract "
                 "within 5 %)") != std::string::npos);
  CHECK(fs::exists(work / "ok" / "run.log"));  // --work is kept
  CHECK(fs::exists(work / "ok" / "FREE_FALL_summary.json"));

  // The JSON summary, read by an independent reader (Python's json), the expected values computed here.
  const double off = 100 * (1 - (0.01 / 0.012) * (0.01 / 0.012));
  const std::string script = dir.write("check.py", R"PY(
import json, sys
d = json.load(open(sys.argv[1], encoding="utf-8"))
off = float(sys.argv[2])
def need(cond, what):
    if not cond:
        print("FAILED:", what, file=sys.stderr)
        sys.exit(1)
t = d["totals"]
need(t["found"] == 5 and t["read"] == 4 and t["ran"] == 3 and t["compared"] == 1, "totals " + repr(t))
need(t["deviates"] == 1 and t["read_error"] == 1 and t["run_error"] == 1 and t["ran_without_reference"] == 1,
     "totals by status " + repr(t))
need(d["tolerance_percent"] == 5 and d["timeout_seconds"] == 4 and d["threads"] == 1, "settings")
decks = {x["deck"]: x for x in d["decks"]}
need(sorted(decks) == ["broken", "endless", "noref", "off", "ok"], "decks " + repr(sorted(decks)))
need({k: v["status"] for k, v in decks.items()} == {"broken": "read-error", "endless": "run-error",
     "noref": "ran", "off": "deviates", "ok": "compared"}, "statuses")
need("/MAT/LAW14" in decks["broken"]["first_refusal"]["message"], "refusal")
need(decks["broken"]["radx"] is None and decks["broken"]["deviation_percent"] is None, "no figures when refused")
ok = decks["ok"]
need(ok["ref"]["cycles"] == 1000 and ok["ref"]["TIME"] == 0.01, "ok ref")
need(ok["radx"]["TIME"] >= 0.01 and ok["radx"]["cycles"] > 100, "ok radx")
need(abs(ok["cycle_ratio"] - ok["radx"]["cycles"] / 1000) < 1e-12, "ok cycle ratio")
for k in ["IENERGY", "KENERGYT", "KENERGYR", "EXTWORK"]:
    need(ok["deviation_percent"][k] < 0.5, "ok " + k + " " + repr(ok["deviation_percent"]))
dev = decks["off"]["deviation_percent"]
need(abs(dev["KENERGYT"] - off) < 0.1 and abs(dev["EXTWORK"] - off) < 0.1, "off " + repr(dev))
need(abs(dev["TIME"] - 100 * (1 - 0.01 / 0.012)) < 0.1, "off TIME " + repr(dev))
need(decks["noref"]["ref"] is None and decks["noref"]["radx"]["cycles"] > 100, "noref")
need("ran out of time" in decks["endless"]["detail"] and 3.5 < decks["endless"]["seconds"] < 30, "endless")
)PY");
  CHECK(exit_code("/usr/bin/python3 " + script + " " + summary.string() + " " + std::to_string(off)) == 0);

  // Only passing decks: exit code 0 (two DIRs; the same --work again, which carries the marker).
  CHECK(exit_code(exe + " regress " + (decks / "ok").string() + " " + (decks / "noref").string() +
                  " --work " + work.string() + " > " + log.string() + " 2>&1") == 0);
  CHECK(slurp(log).find("decks found 2, read 2, ran 2, compared 1 of 1 with a reference") !=
        std::string::npos);
  // --tol widens the tolerance: the 30.6 % deck compares at 31 %.
  CHECK(exit_code(exe + " regress " + (decks / "off").string() + " --tol 31 > /dev/null 2>&1") == 0);
  CHECK(exit_code(exe + " regress " + (decks / "off").string() + " --tol 30 > /dev/null 2>&1") == 1);

  // Usage errors: 2. With no folder, radx regress looks for ./decks; run it from an empty folder so that the
  // answer does not depend on where the test binary is started (the repository root has a decks folder).
  radx::test::TempDir empty;
  CHECK(exit_code("cd '" + empty.path().string() + "' && " + exe + " regress > /dev/null 2>&1") == 2);
  CHECK(exit_code(exe + " regress " + (dir.path() / "missing").string() + " > /dev/null 2>&1") == 2);
  CHECK(exit_code(exe + " regress " + decks.string() + " --tol x > /dev/null 2>&1") == 2);
  CHECK(exit_code(exe + " regress " + decks.string() + " --bogus > /dev/null 2>&1") == 2);
  // A --work folder that holds something else is refused (its deck folders would be cleared).
  CHECK(exit_code(exe + " regress " + (decks / "ok").string() + " --work " + decks.string() +
                  " > /dev/null 2>&1") == 2);
  CHECK(fs::exists(decks / "ok" / "FREE_FALL_0000.rad"));
}

TEST_CASE("regress: a reference that stops before the run's end is compared at its time, from the listing",
          "[regress]") {
  // The listing lines as the engine writes them (io::format_listing_line), read back by listing_points.
  std::string listing = "  some header line\n";
  for (int k = 0; k <= 4; ++k) {
    radx::io::ListingLine l;
    l.cycle = 10 * k;
    l.time = 0.01 * k;
    l.dt = 1e-3;
    l.source = radx::io::StepSource::Brick;
    l.source_id = 7;
    l.internal_energy = 1.0 + k;  // linear in time: the interpolation is exact
    l.kinetic_t = 10.0 - k;
    l.kinetic_r = 0.5 * k;
    l.external_work = 2.0 * k;
    listing += radx::io::format_listing_line(l) + "\n";
  }
  const auto points = radx::app::listing_points(listing);
  REQUIRE(points.size() == 5);
  CHECK(points[3].cycle == 30);
  CHECK(points[3].time == Approx(0.03));
  CHECK(points[3].energy[0] == Approx(4.0));
  CHECK(points[3].energy[2] == Approx(1.5));

  // The run ended at 0.04; the reference's last line is at t = 0.025 with the values the line above gives
  // there: IE 3.5, KE 7.5, KER 1.25, EXT 5 (magnitude 10).
  radx::test::TempDir dir;
  radx::app::RegressDeck deck;
  deck.reference =
      dir.write("ref.extract",
                "    1 Start                    0\n    2 CYCLE\t        25\n    3 TIME\t 2.5000e-02\n"
                "    4 TSTEP\t 1.0000e-03\n    5 ELEMENT\t0\n    6 ELTID\t        7\n"
                "    7 ERROR\t  0.0\n    8 IENERGY\t 3.5000e+00 1.0000e+01\n"
                "    9 KENERGYT\t 7.5000e+00 1.0000e+01\n   10 KENERGYR\t 1.2500e+00 1.0000e+01\n"
                "   11 EXTWORK\t 5.0000e+00 1.0000e+01\n   12 MASERR\t0.000\n"
                "   13 Stop                    0\n");
  radx::app::ChildOutcome exited;
  exited.exit_code = 0;
  radx::app::RegressRunFiles files;
  files.model_written = true;
  radx::io::RunSummary s;
  s.cycles = 40;
  s.time = 0.04;
  s.energy.internal = 5.0;
  s.energy.kinetic_t = 6.0;
  s.energy.kinetic_r = 2.0;
  s.energy.external_work = 8.0;
  files.summary = s;
  files.listing = points;
  const auto r = radx::app::evaluate_deck(deck, exited, files, 0.01);
  INFO(r.detail);
  REQUIRE(r.comparison);
  CHECK(r.at_reference_time);
  CHECK(r.status == radx::app::RegressStatus::Compared);
  for (const double d : r.comparison->energy) CHECK(d <= 1e-12);
  CHECK(r.radx->time == Approx(0.025));
  // Without the listing the run's end is compared: the deviation shows.
  files.listing.clear();
  const auto end = radx::app::evaluate_deck(deck, exited, files, 0.01);
  CHECK_FALSE(end.at_reference_time);
  CHECK(end.status == radx::app::RegressStatus::Deviates);
}

TEST_CASE("regress: a deck's run folder never holds another deck's", "[regress]") {
  // Deck A and deck A/B: each run folder is cleared before its run and removed when it passes, so A's must
  // not contain A/B's.
  radx::test::TempDir dir;
  dir.write("qa/A/X_0000.rad", "");
  dir.write("qa/A/B/Y_0000.rad", "");
  dir.write("qa/A~B/Z_0000.rad", "");  // a folder whose flat name is A/B's
  const auto decks = radx::app::find_regress_decks({dir.path() / "qa"});
  REQUIRE(decks.size() == 3);
  for (const auto& a : decks) {
    CHECK(a.work_subdir.has_filename());
    CHECK(a.work_subdir.parent_path().empty());  // one level: no deck's folder inside another's
    for (const auto& b : decks)
      if (&a != &b) CHECK(a.work_subdir != b.work_subdir);
  }
}

TEST_CASE("regress: # expect: lines, their severity and their problems", "[regress]") {
  radx::test::TempDir dir;
  const fs::path deck =
      dir.write("d/x.rad",
                "# expect: RX402 line 37\n"
                "# expect: RX102 line 5 file inc/b.rad\n"
                "# expect: RX512 line 84 warning\n"
                "# expect: RX301\n"
                "# expect: RX9 line 99999999999999999999\n"  // a line number too long: a problem
                "# expect: line 3\n"                         // no code
                "# fault: text\n"
                "/BEGIN\n"
                "# expect: RX1 line 1\n");  // after the opening comment block: not read
  std::vector<std::string> problems;
  const auto e = radx::app::read_expected_errors(deck, problems);
  REQUIRE(e.size() == 4);
  CHECK(e[0].code == "RX402");
  CHECK(e[0].line == 37);
  CHECK_FALSE(e[0].warning);
  CHECK(e[0].file == deck.lexically_normal());
  CHECK(e[1].file == (dir.path() / "d/inc/b.rad").lexically_normal());
  CHECK(e[2].warning);
  CHECK(e[2].text() == "RX512 line 84 in x.rad (warning)");
  CHECK(e[3].line == 0);  // any line
  REQUIRE(problems.size() == 2);
  CHECK(problems[0].find("x.rad:5: an expectation is \"# expect: RXnnn [line L] [file PATH] [warning]\"") !=
        std::string::npos);
  CHECK(problems[1].find("x.rad:6:") != std::string::npos);
}

TEST_CASE("regress: --filter is a glob on the whole name, or a part of it", "[regress]") {
  using radx::app::label_matches;
  CHECK(label_matches("verification/ctclaw_drop/CTCLAW_DROP_N1_0000.rad", "ctclaw"));
  CHECK_FALSE(label_matches("taylor_bar", "ctclaw"));
  CHECK(label_matches("ctclaw_laws", "ctclaw*"));
  CHECK_FALSE(label_matches("verification/ctclaw_drop", "ctclaw*"));  // a glob matches the whole name
  CHECK(label_matches("verification/ctclaw_drop", "*/ctclaw_[dl]*"));
}
