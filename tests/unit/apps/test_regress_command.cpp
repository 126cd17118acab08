// `radx regress` end to end (apps/regress_command.hpp), on decks built here from the repository's free-fall
// deck, with reference values from the closed form KE = W_ext = M g^2 t^2 / 2 (M = 2.7 kg, g = 9.81 m/s2;
// decks/verification/free_fall/README.md): statuses, table, exit code, JSON summary and usage errors.
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_util.hpp"

namespace fs = std::filesystem;

namespace {

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
