// The /CTCLAW law string (docs/theory/contact-laws.md section 4): every rule with the values read, and every
// error naming its parameter; then the same laws in a deck, located at their line, with the curve of a
// tabulated law and unit conversion checked by the model builder.
#include <algorithm>
#include <catch2/catch.hpp>
#include <fstream>
#include <sstream>

#include "apps/starter_pipeline.hpp"
#include "parser/building/ctclaw_urn.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"
#include "parser/reading/field_parse.hpp"
#include "test_util.hpp"

using radx::parse_ctclaw_urn;
using radx::UrnResult;
namespace m = radx::model;

namespace {

UrnResult ok(const std::string& text) {
  UrnResult r = parse_ctclaw_urn(text);
  INFO(text);
  for (const auto& p : r.problems) INFO(p.parameter << ": " << p.message);
  CHECK(r.problems.empty());
  return r;
}

// The problems of a law that must be refused; at least one of them names `parameter`.
std::vector<radx::UrnProblem> refused(const std::string& text, const std::string& parameter) {
  UrnResult r = parse_ctclaw_urn(text);
  std::ostringstream all;
  for (const auto& p : r.problems)
    all << "  " << p.parameter << " @" << p.offset << ": " << p.message << '\n';
  INFO(text << "\n" << all.str());
  CHECK_FALSE(r.problems.empty());
  CHECK(std::any_of(r.problems.begin(), r.problems.end(),
                    [&](const radx::UrnProblem& p) { return p.parameter == parameter; }));
  return r.problems;
}

bool mentions(const std::vector<radx::UrnProblem>& ps, const std::string& what) {
  return std::any_of(ps.begin(), ps.end(),
                     [&](const radx::UrnProblem& p) { return p.message.find(what) != std::string::npos; });
}

}  // namespace

TEST_CASE("n1: Kc > 0 or -1 (automatic), with friction s13, Mu and CtLin", "[ctclaw]") {
  auto r = ok("n1s13{Kc1e12,Mu0.1,CtLin1e3}");
  CHECK(r.law.normal == m::NormalLaw::Linear);
  CHECK(r.law.kc == 1e12);
  CHECK(r.law.friction == m::FrictionLaw::Arctangent);
  CHECK(r.law.bidirectional);
  CHECK(r.law.mu == Approx(0.1));
  CHECK(r.law.ct == 1e3);
  CHECK(r.law.kappa == 0);
  CHECK(ok("n1{Kc-1}").law.kc == -1);
  CHECK(ok("n1{Kc=-1}").law.kc == -1);
  refused("n1{Kc-2}", "Kc");
  refused("n1{Kc0}", "Kc");
  refused("n1{}", "Kc");
  refused("n1", "Kc");
}

TEST_CASE("n2: pz with lambda or pe, optional KcMax at least lambda pz", "[ctclaw]") {
  auto r = ok("n2s13{pz1e5,lambda2e3,KcMax1e15,Mu0.3,CtLin10}");
  CHECK(r.law.normal == m::NormalLaw::Exponential);
  CHECK(r.law.pz == 1e5);
  CHECK(r.law.lambda == 2e3);
  CHECK(r.law.pe == 0);
  CHECK(r.law.kc_max == 1e15);
  CHECK(r.law.mu == Approx(0.3));
  CHECK(r.law.ct == 10);
  auto p = ok("n2{pz1e5,pe2e6}");
  CHECK(p.law.pe == 2e6);
  CHECK(p.law.lambda == 0);
  CHECK(p.law.kc_max == 0);
  CHECK(p.law.friction == m::FrictionLaw::None);
  // KcMax exactly lambda pz is accepted; below it is not, and the message gives both values.
  CHECK(ok("n2{pz1e5,lambda2e3,KcMax2e8}").law.kc_max == 2e8);
  const auto below = refused("n2{pz1e5,lambda2e3,KcMax1e8}", "KcMax");
  CHECK(mentions(below, "1e+08"));
  CHECK(mentions(below, "2e+08"));
  // With pe, KcMax is checked by the starter once the pair stiffnesses are known.
  CHECK(ok("n2{pz1e5,pe1e6,KcMax1}").law.kc_max == 1);
  // lambda and pe are exclusive; one of them is required.
  CHECK(mentions(refused("n2{pz1e5,lambda2e3,pe1e6}", "pe"), "exclusive"));
  CHECK(mentions(refused("n2{pz1e5,pe1e6,lambda2e3}", "lambda"), "exclusive"));
  refused("n2{pz1e5}", "lambda");
  refused("n2{lambda2e3}", "pz");
  refused("n2{pz-1e5,lambda2e3}", "pz");
  refused("n2{pz1e5,lambda0}", "lambda");
  refused("n2{pz1e5,pe-3}", "pe");
  refused("n2{pz1e5,lambda2e3,KcMax0}", "KcMax");
}

TEST_CASE("n3: CurveID a positive integer, Cubic 0 or 1", "[ctclaw]") {
  auto r = ok("n3s12{CurveID12,Cubic1,Mu0.3,CtLin10}");
  CHECK(r.law.normal == m::NormalLaw::Tabulated);
  CHECK(r.curve_id == 12);
  CHECK(r.law.curve == m::kNone);  // resolved by the model builder
  CHECK(r.law.cubic);
  CHECK(r.law.friction == m::FrictionLaw::Linear);
  CHECK(r.law.bidirectional);
  CHECK_FALSE(ok("n3{CurveID7}").law.cubic);
  CHECK(ok("n3{CurveID7,Cubic0}").curve_id == 7);
  refused("n3{}", "CurveID");
  refused("n3{CurveID0}", "CurveID");
  refused("n3{CurveID2.5}", "CurveID");
  refused("n3{CurveID-4}", "CurveID");
  refused("n3{CurveID4,Cubic2}", "Cubic");
}

TEST_CASE("n4: power terms kp<m>=<value> in the order given", "[ctclaw]") {
  auto r = ok("n4{kp1=1e9,kp2=1e15}");
  CHECK(r.law.normal == m::NormalLaw::Power);
  CHECK(r.law.power_m == std::vector<double>{1, 2});
  CHECK(r.law.power_k == std::vector<double>{1e9, 1e15});
  auto q = ok("n4{KP2.5=3,kp1=0}");
  CHECK(q.law.power_m == std::vector<double>{2.5, 1});
  CHECK(q.law.power_k == std::vector<double>{3, 0});
  refused("n4{}", "kp");
  CHECK(mentions(refused("n4{kp2=1,kp2.0=3}", "kp2.0"), "twice"));
  refused("n4{kp0.5=1}", "kp0.5");
  refused("n4{kp2=-1}", "kp2");
  CHECK(mentions(refused("n4{kp21e15}", "kp21e15"), "kp<m>=<value>"));
  refused("n4{kp1=0}", "kp1");  // a law that never pushes
  refused("n4{kp1=x}", "kp1");
}

TEST_CASE("the friction laws: s1..s4 one direction, s11..s14 two, with Mu, CtLin, kappa", "[ctclaw]") {
  struct Case {
    const char* text;
    m::FrictionLaw law;
    bool both;
  };
  for (const auto& c :
       {Case{"s1{Mu.2}", m::FrictionLaw::Coulomb, false}, Case{"s11{Mu.2}", m::FrictionLaw::Coulomb, true},
        Case{"s2{Mu.2,CtLin5}", m::FrictionLaw::Linear, false},
        Case{"s12{Mu.2,CtLin5}", m::FrictionLaw::Linear, true},
        Case{"s3{Mu.2,CtLin5}", m::FrictionLaw::Arctangent, false},
        Case{"s13{Mu.2,CtLin5}", m::FrictionLaw::Arctangent, true},
        Case{"s4{Mu.2,CtLin5}", m::FrictionLaw::ScaledLinear, false},
        Case{"s14{Mu.2,CtLin5}", m::FrictionLaw::ScaledLinear, true}}) {
    INFO(c.text);
    auto r = ok(c.text);
    // No n part: the interface's own penalty stays the normal law.
    CHECK(r.law.normal == m::NormalLaw::Interface);
    CHECK(r.law.friction == c.law);
    CHECK(r.law.bidirectional == c.both);
    CHECK(r.law.mu == Approx(0.2));
    CHECK(r.law.ct == (c.law == m::FrictionLaw::Coulomb ? 0.0 : 5.0));
  }
  CHECK(ok("n2s11{pz1e5,lambda2e3,KcMax1e15,Mu0.2,kappa1e6}").law.kappa == 1e6);
  CHECK(ok("s1{Mu0}").law.mu == 0);
  refused("s1{}", "Mu");
  refused("s2{Mu.2}", "CtLin");
  refused("s1{Mu.2,CtLin5}", "CtLin");  // exact Coulomb has no slope
  refused("s11{Mu.2,CtLin5}", "CtLin");
  refused("s3{Mu-0.1,CtLin5}", "Mu");
  refused("s3{Mu0.1,CtLin0}", "CtLin");
  refused("s3{Mu0.1,CtLin5,kappa0}", "kappa");
  refused("s3{Mu0.1,CtLin5,kappa-1}", "kappa");
}

TEST_CASE("the law string's syntax: spaces, case, '=', Fortran numbers", "[ctclaw]") {
  auto r = ok(" N2 S13 { PZ 1.D5 , Lambda = 2E3 , kcmax1.5d15, mu.3, ctlin10 } ");
  CHECK(r.law.pz == 1e5);
  CHECK(r.law.lambda == 2e3);
  CHECK(r.law.kc_max == 1.5e15);
  CHECK(r.law.mu == Approx(0.3));
  CHECK(r.law.ct == 10);
  CHECK(ok("n1s1{Kc1.5-3,Mu=.5}").law.kc == Approx(1.5e-3));
  // Neither part: an error; so are unknown law numbers.
  refused("{Mu0.3}", "law string");
  refused("", "law string");
  CHECK(mentions(refused("n5{Kc1}", "law string"), "unknown normal law n5"));
  CHECK(mentions(refused("n1s5{Kc1,Mu1}", "law string"), "unknown friction law s5"));
  refused("n0{Kc1}", "law string");
  refused("s15{Mu1}", "law string");
  refused("n{Kc1}", "law string");
  refused("n1s{Kc1}", "law string");
}

TEST_CASE("every problem of a law is reported, each naming its parameter", "[ctclaw]") {
  // Unknown name: the message lists what the law takes.
  auto u = refused("n1s13{Kc1e12,Mu0.1,CtLin1e3,Foo3}", "Foo");
  CHECK(mentions(u, "unknown parameter 'Foo'"));
  CHECK(mentions(u, "Kc, Mu, CtLin, kappa"));
  // A parameter of another law.
  auto other = refused("n1{Kc1,pz3}", "pz");
  CHECK(mentions(other, "not a parameter of n1"));
  refused("n1{Kc1,Mu0.3}", "Mu");  // no s part: frictionless
  refused("s1{Mu0.3,Kc1}", "Kc");  // no n part: the interface's penalty
  // Duplicates, names without value, values that are not numbers.
  CHECK(mentions(refused("n1{Kc1,kc2}", "Kc"), "twice"));
  CHECK(mentions(refused("n1{Kc}", "Kc"), "no value"));
  CHECK(mentions(refused("n1{Kc1e}", "Kc"), "not a number"));
  CHECK(mentions(refused("n1{Kcabc}", "Kcabc"), "unknown parameter"));
  refused("n1{Kc1e999}", "Kc");
  // Braces and trailing text.
  refused("n1{Kc1", "law string");
  refused("n1{Kc1}x", "law string");
  refused("n1x{Kc1}", "law string");
  refused("n1{Kc1,,}", "law string");
  refused("n1{Kc1{}", "law string");
  refused("n1{3}", "law string");
  // All of them at once, none lost.
  auto all = parse_ctclaw_urn("n2s2{pz-1,lambda2,pe3,Mu-1,Bar2,Kc1,Mu2}");
  std::vector<std::string> named;
  for (const auto& p : all.problems) named.push_back(p.parameter);
  for (const char* want : {"pz", "pe", "Mu", "Bar", "Kc", "CtLin"}) {
    INFO(want);
    CHECK(std::find(named.begin(), named.end(), want) != named.end());
  }
  // Offsets point into the text as given (spaces kept).
  auto at = parse_ctclaw_urn("n1 { Kc1, Foo2 }");
  REQUIRE(at.problems.size() == 1);
  CHECK(at.problems[0].offset == 10);
}

// ---------------------------------------------------------------------------------------------------
// In a deck: located errors, the curve, the units.

namespace {

// The sample deck block_on_plate (interfaces 1 and 2) with a /CTCLAW/5 on interface 1 before its /END: the
// law's lines start at line kLawLine; `extra` follows them. `input_units` replaces the input-units line.
constexpr int kLawLine = 596;
std::string law_deck(const std::vector<std::string>& law_lines, const std::string& extra = "",
                     const std::string& input_units = "") {
  std::ifstream in(std::string(RADX_SOURCE_DIR) + "/decks/block_on_plate/BLOCK_ON_PLATE_0000.rad");
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  REQUIRE(lines.size() == 593);
  REQUIRE(lines.back() == "/END");
  REQUIRE(lines[12].find("Mg") != std::string::npos);
  if (!input_units.empty()) lines[12] = input_units;
  lines.pop_back();
  std::ostringstream d;
  for (const auto& l : lines) d << l << '\n';
  d << "/CTCLAW/5\na law\n         1\n";
  for (const auto& l : law_lines) d << l << '\n';
  d << extra << "/END\n";
  return d.str();
}

struct Built {
  radx::Diagnostics diags;
  m::Model model;
};

Built build(const std::string& text) {
  radx::test::TempDir dir;
  const auto path = dir.write("LAW_0000.rad", text);
  Built b;
  const radx::Deck deck = radx::read_starter_deck(path, b.diags);
  b.model = radx::build_model(deck, b.diags);
  return b;
}

// The first RX704 error whose message holds `what` (nullptr when none).
const radx::Diagnostic* law_error(const radx::Diagnostics& d, const std::string& what) {
  for (const auto& x : d.items())
    if (x.code == radx::Diag::BadContactLaw && x.message.find(what) != std::string::npos) return &x;
  return nullptr;
}

std::string all_of(const radx::Diagnostics& d) {
  std::ostringstream os;
  d.print(os);
  return os.str();
}

}  // namespace

TEST_CASE("a /CTCLAW in a deck: the law is attached, problems are RX704 at their line", "[ctclaw]") {
  {
    auto b = build(law_deck({"n2s13{pz1e5,lambda2e3,", "  KcMax1e15, Mu0.3, CtLin10}"}));
    INFO(all_of(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    REQUIRE(b.model.interfaces.size() == 2);
    const auto& in = b.model.interfaces[0];
    CHECK(in.contact_law_id == 5);
    CHECK(in.contact_law == "n2s13{pz1e5,lambda2e3,KcMax1e15,Mu0.3,CtLin10}");
    CHECK(in.law.normal == m::NormalLaw::Exponential);
    CHECK(in.law.kc_max == 1e15);
    CHECK(in.law.ct == 10);
  }
  {
    // Two problems on two lines, each at its own line and column, naming the law and the parameter.
    auto b = build(law_deck({"n2s13{pz1e5,lambda2e3,Foo1,", "  KcMax1e3, Mu0.3, CtLin10}"}));
    INFO(all_of(b.diags));
    const auto* foo = law_error(b.diags, "unknown parameter 'Foo'");
    REQUIRE(foo != nullptr);
    CHECK(foo->line == kLawLine);
    CHECK(foo->column == 23);
    CHECK(foo->message.find("/CTCLAW/5") != std::string::npos);
    const auto* kcmax = law_error(b.diags, "below the initial stiffness");
    REQUIRE(kcmax != nullptr);
    CHECK(kcmax->line == kLawLine + 1);
    CHECK(kcmax->column == 3);
    CHECK(kcmax->message.rfind("/CTCLAW/5 KcMax:", 0) == 0);
  }
}

TEST_CASE("a tabulated law's curve: found, at least 2 points, pressures >= 0 not rising with the gap",
          "[ctclaw]") {
  auto funct = [](const std::vector<std::pair<double, double>>& pts) {
    std::ostringstream f;
    f << "/FUNCT/12\npressure\n";
    for (const auto& [x, y] : pts) {
      radx::test::Line l;
      l.put(radx::number_text(x), 1, 20).put(radx::number_text(y), 21, 40);
      f << l.str() << '\n';
    }
    return f.str();
  };
  {
    auto b = build(law_deck({"n3{CurveID12,Cubic1}"}, funct({{-0.1, 100.0}, {0.0, 10.0}, {0.2, 0.0}})));
    INFO(all_of(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    REQUIRE(b.model.functions.size() == 2);
    CHECK(b.model.functions[1].id == 12);
    CHECK(b.model.interfaces[0].law.curve == 1);
    CHECK(b.model.interfaces[0].law.cubic);
  }
  {
    auto b = build(law_deck({"n3{CurveID13}"}, funct({{-0.1, 100.0}, {0.0, 10.0}})));
    const auto* e = law_error(b.diags, "names no /FUNCT");
    REQUIRE(e != nullptr);
    CHECK(e->line == kLawLine);
    CHECK(e->message.find("13") != std::string::npos);
  }
  CHECK(law_error(build(law_deck({"n3{CurveID12}"}, funct({{0.0, 10.0}}))).diags, "at least 2") != nullptr);
  CHECK(law_error(build(law_deck({"n3{CurveID12}"}, funct({{-0.1, 100.0}, {0.0, 10.0}, {0.2, -1.0}}))).diags,
                  "< 0") != nullptr);
  CHECK(law_error(build(law_deck({"n3{CurveID12}"}, funct({{-0.1, 1.0}, {0.0, 10.0}, {0.2, 0.0}}))).diags,
                  "rises") != nullptr);
  // A pressure that never ends (flat and positive at the largest gap), or never starts.
  CHECK(law_error(build(law_deck({"n3{CurveID12}"}, funct({{-0.1, 100.0}, {0.0, 10.0}, {0.2, 10.0}}))).diags,
                  "must reach 0") != nullptr);
  CHECK(law_error(build(law_deck({"n3{CurveID12}"}, funct({{-0.1, 0.0}, {0.0, 0.0}}))).diags,
                  "no positive pressure") != nullptr);
  // Falling at its last point, the table ends where its last segment reaches 0: accepted.
  CHECK_FALSE(build(law_deck({"n3{CurveID12}"}, funct({{-0.1, 100.0}, {0.0, 10.0}}))).diags.has_errors());
}

// The first warning of `code` whose message holds `what` (nullptr when none).
const radx::Diagnostic* warning_of(const radx::Diagnostics& d, radx::Diag code, const std::string& what) {
  for (const auto& x : d.items())
    if (x.code == code && x.message.find(what) != std::string::npos) return &x;
  return nullptr;
}

TEST_CASE("what a law replaces without using is said: the interface's friction, kappa of a regularised law",
          "[ctclaw]") {
  // Interface 1 of the sample deck has Fric 0.1: a law without an s part makes it frictionless.
  auto b = build(law_deck({"n1{Kc1e3}"}));
  INFO(all_of(b.diags));
  REQUIRE_FALSE(b.diags.has_errors());
  CHECK(warning_of(b.diags, radx::Diag::InterfaceFieldIgnored, "Fric = 0.1") != nullptr);
  CHECK(warning_of(build(law_deck({"n1s11{Kc1e3,Mu0.1}"})).diags, radx::Diag::InterfaceFieldIgnored,
                   "Fric") == nullptr);
  // kappa is the exact Coulomb law's sticking spring only.
  CHECK(warning_of(build(law_deck({"n1s12{Kc1e3,Mu0.1,CtLin1,kappa1e3}"})).diags,
                   radx::Diag::InterfaceFieldIgnored, "kappa") != nullptr);
  CHECK(warning_of(build(law_deck({"n1s11{Kc1e3,Mu0.1,kappa1e3}"})).diags, radx::Diag::InterfaceFieldIgnored,
                   "kappa") == nullptr);
}

TEST_CASE("law values in input units other than the work units are converted", "[ctclaw]") {
  // Input kg m s, work Mg mm s: a pressure of 1 Pa is 1e-6 MPa, 1 Pa/m is 1e-9 MPa/mm, 1/m is 1e-3 /mm.
  auto b = build(law_deck({"n2s2{pz1e5,lambda2e3,KcMax1e15,Mu0.3,CtLin10,kappa1e12}"}, "",
                          "                  kg                   m                   s"));
  INFO(all_of(b.diags));
  REQUIRE_FALSE(b.diags.has_errors());
  const auto& law = b.model.interfaces[0].law;
  CHECK(law.pz == Approx(1e5 * 1e-6));
  CHECK(law.lambda == Approx(2e3 * 1e-3));
  CHECK(law.kc_max == Approx(1e15 * 1e-9));
  CHECK(law.mu == Approx(0.3));
  CHECK(law.ct == Approx(10 * 1e-9));  // Pa s/m
  CHECK(law.kappa == Approx(1e12 * 1e-9));
  auto p =
      build(law_deck({"n4{kp2=1e15}"}, "", "                  kg                   m                   s"));
  REQUIRE_FALSE(p.diags.has_errors());
  CHECK(p.model.interfaces[0].law.power_k[0] == Approx(1e15 * 1e-6 * 1e-6));  // Pa/m^2 -> MPa/mm^2
  // The arctangent and scaled-linear slopes multiply a slip speed into a pure number (atan(ct s), ct s < mu):
  // s/m -> s/mm.
  for (const char* urn : {"n1s13{Kc1e9,Mu0.3,CtLin10}", "n1s14{Kc1e9,Mu0.3,CtLin10}"}) {
    INFO(urn);
    auto a = build(law_deck({urn}, "", "                  kg                   m                   s"));
    REQUIRE_FALSE(a.diags.has_errors());
    CHECK(a.model.interfaces[0].law.ct == Approx(10 * 1e-3));
  }
}

TEST_CASE("law values in input units with another time unit too are converted", "[ctclaw]") {
  // Input g, cm, ms; work Mg, mm, s (the helper's deck): mass fm = 1e-6 (1 g = 1e-6 Mg), length fl = 10 (1 cm
  // = 10 mm), time ft = 1e-3 (1 ms = 1e-3 s): three different factors, so a wrong exponent on any of them
  // shows.
  //   pressure  g/(cm ms^2)          = 1e-6 Mg / (10 mm * 1e-6 s^2)      = 0.1 MPa           : x 0.1
  //   Kc, KcMax, kappa  g/(cm^2 ms^2) = 0.1 MPa / 10 mm                    = 0.01 MPa/mm       : x 1e-2
  //   lambda    1/cm                 = 1 / (10 mm)                          = 0.1 /mm           : x 0.1
  //   kp_m      g/(cm ms^2) / cm^m   = 0.1 MPa / (10 mm)^m:  m = 2: 1e-3 MPa/mm^2, m = 3: 1e-4 MPa/mm^3
  //   CtLin s2  g/(cm ms^2) ms/cm    = 0.1 MPa * 1e-3 s / 10 mm              = 1e-5 MPa s/mm     : x 1e-5
  //   CtLin s13, s14  ms/cm          = 1e-3 s / 10 mm                         = 1e-4 s/mm         : x 1e-4
  // (Approx's default relative margin, ~1e-5 of the value, is round-off here: every wrong factor is off by
  // at least a factor 10.)
  const std::string units = "                   g                  cm                  ms";
  {
    auto b = build(law_deck({"n1s2{Kc3e4,Mu0.3,CtLin7}"}, "", units));
    INFO(all_of(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    const auto& law = b.model.interfaces[0].law;
    CHECK(law.kc == Approx(3e4 * 1e-2));
    CHECK(law.mu == Approx(0.3));
    CHECK(law.ct == Approx(7 * 1e-5));  // Pa s/m
  }
  {
    auto b = build(law_deck({"n2s11{pz2e3,lambda40,KcMax9e7,Mu0.2,kappa6e5}"}, "", units));
    INFO(all_of(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    const auto& law = b.model.interfaces[0].law;
    CHECK(law.pz == Approx(2e3 * 0.1));
    CHECK(law.lambda == Approx(40 * 0.1));
    CHECK(law.kc_max == Approx(9e7 * 1e-2));
    CHECK(law.kappa == Approx(6e5 * 1e-2));
  }
  {
    // pe instead of lambda: a pressure.
    auto b = build(law_deck({"n2{pz2e3,pe8e3}"}, "", units));
    INFO(all_of(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    CHECK(b.model.interfaces[0].law.pz == Approx(2e3 * 0.1));
    CHECK(b.model.interfaces[0].law.pe == Approx(8e3 * 0.1));
  }
  {
    auto b = build(law_deck({"n4{kp2=4e9,kp3=5e11}"}, "", units));
    INFO(all_of(b.diags));
    REQUIRE_FALSE(b.diags.has_errors());
    const auto& law = b.model.interfaces[0].law;
    REQUIRE(law.power_k.size() == 2);
    CHECK(law.power_k[0] == Approx(4e9 * 1e-3));   // Pa/m^2
    CHECK(law.power_k[1] == Approx(5e11 * 1e-4));  // Pa/m^3
  }
  for (const char* urn : {"n1s13{Kc1e4,Mu0.3,CtLin20}", "n1s14{Kc1e4,Mu0.3,CtLin20}"}) {
    INFO(urn);
    auto a = build(law_deck({urn}, "", units));
    INFO(all_of(a.diags));
    REQUIRE_FALSE(a.diags.has_errors());
    CHECK(a.model.interfaces[0].law.ct == Approx(20 * 1e-4));  // s/m
  }
}

TEST_CASE("an exponential law by pe: KcMax below the largest initial stiffness is refused by the starter",
          "[ctclaw]") {
  radx::test::TempDir dir;
  auto run = [&](const std::string& law) {
    const auto path = dir.write("PE_0000.rad", law_deck({law}));
    radx::app::StarterOptions opt;
    opt.deck = path;
    opt.out_dir = dir.path().string();
    std::ostringstream so, se;
    const auto res = radx::app::run_starter(opt, so, se);
    return std::pair{res.exit_code, se.str()};
  };
  // K / A_s here is of order 1e4 to 1e5 N/mm^3 (MPa/mm): with pz = 1 and pe = 1 the initial stiffness is
  // that.
  const auto [code_ok, err_ok] = run("n2{pz1,pe1,KcMax1e12}");
  INFO(err_ok);
  CHECK(code_ok == 0);
  const auto [code, err] = run("n2{pz1,pe1,KcMax1}");
  INFO(err);
  CHECK(code == 1);
  CHECK(err.find("RX704") != std::string::npos);
  CHECK(err.find("/CTCLAW/5 KcMax") != std::string::npos);
  CHECK(err.find(":" + std::to_string(kLawLine) + ":") != std::string::npos);
  // The listing prints the law as understood, lambda as a range over the secondary nodes.
  run("n2s11{pz1,pe1,KcMax1e12,Mu0.2}");
  std::ifstream listing(dir.file("PE_0000.out"));
  std::stringstream text;
  text << listing.rdbuf();
  INFO(text.str());
  CHECK(text.str().find("n2 exponential") != std::string::npos);
  CHECK(text.str().find("lambda = Kc_auto/pe from") != std::string::npos);
  CHECK(text.str().find("u_max") != std::string::npos);
  CHECK(text.str().find("s11 exact Coulomb, two directions") != std::string::npos);
  CHECK(text.str().find("kappa K/A_s (default)") != std::string::npos);
}
