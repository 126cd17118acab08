// /INTER/TYPE7 and /INTER/LAGDT/TYPE7 (docs/theory/type7-lagdt.md sections 2-3, docs/theory/deck-format.md
// section 2): every field read through build_model into model::Interface, the conditional cards, every
// default, and the checks with the line of the field at fault.
//
// The interface sits on a tiny model: a one-element shell plate (part 1) as the main surface
// (/SURF/PART/31) and one brick (part 2) above it whose nodes are the secondary group (/GRNOD/PART/21).
// Cards are written from an independent statement of the layouts: every field right-justified at its
// columns by a helper, so nothing is counted by hand.
//
// Tolerances: values read from text are compared with Approx(...).epsilon(1e-12) (parsing exactness);
// defaults that are constants of the code are compared exactly.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"
#include "solver/model/model.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using radx::Diag;
using radx::Diagnostics;

constexpr double kEps = 1e-12;

using radx::test::TempDir;

// One card line: values right-justified in columns [first, last] (1-based, inclusive).
class Card {
 public:
  Card& at(int first, int last, const std::string& v) {
    const auto width = static_cast<std::size_t>(last - first + 1);
    if (v.size() > width) throw std::invalid_argument("test bug: '" + v + "' does not fit its columns");
    if (s_.size() < static_cast<std::size_t>(last)) s_.resize(static_cast<std::size_t>(last), ' ');
    s_.replace(static_cast<std::size_t>(last) - v.size(), v.size(), v);
    return *this;
  }
  [[nodiscard]] const std::string& str() const { return s_; }

 private:
  std::string s_;
};

std::string all_diags(const Diagnostics& diags) {
  std::string s;
  for (const auto& d : diags.items()) s += Diagnostics::format(d) + "\n";
  return s;
}

// --- the layouts, as docs/theory/type7-lagdt.md section 2 and docs/keywords.md /INTER/TYPE7 give them

using Vals = std::map<std::string, std::string>;  // field name -> text as written (absent: blank)

std::int64_t ival(const Vals& v, const std::string& name) {
  const auto it = v.find(name);
  return it == v.end() || it->second.empty() ? 0 : std::stoll(it->second);
}

enum class Cond { Always, IcurvIs1Or2, IfricGt0, IfricGt1, IadmIs2, ItheIs1 };

struct Col {
  std::string name;
  int a;
  int b;
  int since = 0;
};
struct CardLayout {
  std::string card;
  Cond cond;
  std::vector<Col> cols;
};

bool holds(Cond c, const Vals& v) {
  switch (c) {
    case Cond::Always: return true;
    case Cond::IcurvIs1Or2: return ival(v, "Icurv") == 1 || ival(v, "Icurv") == 2;
    case Cond::IfricGt0: return ival(v, "Ifric") > 0;
    case Cond::IfricGt1: return ival(v, "Ifric") > 1;
    case Cond::IadmIs2: return ival(v, "Iadm") == 2;
    case Cond::ItheIs1: return ival(v, "Ithe") == 1;
  }
  return false;
}

std::vector<CardLayout> friction_cards() {
  return {{"C1-C5",
           Cond::IfricGt0,
           {{"C1", 1, 20}, {"C2", 21, 40}, {"C3", 41, 60}, {"C4", 61, 80}, {"C5", 81, 100}}},
          {"C6", Cond::IfricGt1, {{"C6", 1, 20}}}};
}

std::vector<CardLayout> type7_layout() {
  std::vector<CardLayout> l = {
      {"card 1",
       Cond::Always,
       {{"grnd_IDs", 1, 10},
        {"surf_IDm", 11, 20},
        {"Istf", 21, 30},
        {"Ithe", 31, 40},
        {"Igap", 41, 50},
        {"Ibag", 61, 70},
        {"Idel", 71, 80},
        {"Icurv", 81, 90},
        {"Iadm", 91, 100}}},
      {"card 2",
       Cond::Always,
       {{"Fscalegap", 1, 20},
        {"Gapmax", 21, 40},
        {"Fpenmax", 41, 60},
        {"Itied", 81, 90, 2020},
        {"Ists", 91, 100, 2026}}},
      {"card 3",
       Cond::Always,
       {{"Stmin", 1, 20},
        {"Stmax", 21, 40},
        {"mesh_size", 41, 60},
        {"dtmin", 61, 80},
        {"Irem_gap", 81, 90},
        {"Irem_i2", 91, 100}}},
      {"card 4", Cond::IcurvIs1Or2, {{"node_ID1", 1, 10}, {"node_ID2", 11, 20}}},
      {"card 5",
       Cond::Always,
       {{"Stfac", 1, 20}, {"Fric", 21, 40}, {"Gapmin", 41, 60}, {"Tstart", 61, 80}, {"Tstop", 81, 100}}},
      {"card 6",
       Cond::Always,
       {{"IBCX", 8, 8},
        {"IBCY", 9, 9},
        {"IBCZ", 10, 10},
        {"Inacti", 31, 40},
        {"VISs", 41, 60},
        {"VISF", 61, 80},
        {"Bumult", 81, 100}}},
      {"card 7",
       Cond::Always,
       {{"Ifric", 1, 10},
        {"Ifiltr", 11, 20},
        {"Xfreq", 21, 40},
        {"Iform", 41, 50},
        {"sens_ID", 51, 60},
        {"fct_IDF", 61, 70},
        {"AscaleF", 71, 90},
        {"fric_ID", 91, 100, 2018}}},
  };
  for (auto& c : friction_cards()) l.push_back(c);
  l.push_back({"adaptive", Cond::IadmIs2, {{"NRadm", 1, 10}, {"Padm", 11, 30}, {"Angladm", 31, 50}}});
  l.push_back(
      {"thermal 1",
       Cond::ItheIs1,
       {{"Kthe", 1, 20}, {"fct_IDK", 21, 30}, {"Tint", 41, 60}, {"Ithe_form", 61, 70}, {"AscaleK", 71, 90}}});
  l.push_back({"thermal 2",
               Cond::ItheIs1,
               {{"Frad", 1, 20}, {"Drad", 21, 40}, {"Fheats", 41, 60}, {"Fheatm", 61, 80}}});
  return l;
}

std::vector<CardLayout> lagdt_layout() {
  std::vector<CardLayout> l = {
      {"card 1",
       Cond::Always,
       {{"grnd_IDs", 1, 10},
        {"surf_IDm", 11, 20},
        {"Istf", 21, 30},
        {"Igap", 41, 50},
        {"Ibag", 61, 70},
        {"Idel", 71, 80}}},
      {"card 2", Cond::Always, {{"Fscalegap", 1, 20}, {"Gapmax", 21, 40}}},
      {"card 3", Cond::Always, {{"Stmin", 1, 20}, {"Stmax", 21, 40}}},
      {"card 4",
       Cond::Always,
       {{"Stfac", 1, 20}, {"Fric", 21, 40}, {"Gapmin", 41, 60}, {"Tstart", 61, 80}, {"Tstop", 81, 100}}},
      {"card 5",
       Cond::Always,
       {{"IBCX", 8, 8},
        {"IBCY", 9, 9},
        {"IBCZ", 10, 10},
        {"Inacti", 31, 40},
        {"VISs", 41, 60},
        {"VISF", 61, 80},
        {"Bumult", 81, 100}}},
      {"card 6", Cond::Always, {{"Ifric", 1, 10}, {"Ifiltr", 11, 20}, {"Xfreq", 21, 40}, {"Iform", 41, 50}}},
  };
  for (auto& c : friction_cards()) l.push_back(c);
  return l;
}

// Which interface deck to write.
struct Kind {
  bool lagdt = false;
  int version = 2026;
  [[nodiscard]] std::string name() const {
    return std::string(lagdt ? "/INTER/LAGDT/TYPE7" : "/INTER/TYPE7") + " in a " + std::to_string(version) +
           " deck";
  }
};

const Kind kAllKinds[] = {{false, 2026}, {false, 2019}, {true, 2026}, {true, 2019}};

struct DeckOut {
  std::string text;
  std::uint32_t keyword_line = 0;
  std::map<std::string, std::uint32_t> line_of;  // field -> line of its card
  std::vector<std::string> cards_written;
};

// The tiny model, the interface, then `after` (the next keyword, right after the last card).
DeckOut make_deck(const Kind& kind, const Vals& v, const std::string& after = "", bool only_card1 = false) {
  std::vector<std::string> lines;
  auto add = [&lines](const std::string& s) {
    lines.push_back(s);
    return static_cast<std::uint32_t>(lines.size());
  };
  const std::string units = Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str();
  add("#RADIOSS STARTER");
  add("/BEGIN");
  add("TYPE7 FIELDS");
  add(Card().at(1, 10, std::to_string(kind.version)).str());
  add(units);
  add(units);
  add("/NODE");
  struct N {
    int id;
    const char* x;
    const char* y;
    const char* z;
  };
  const N nodes[] = {{1, "0.", "0.", "0."},       {2, "1.", "0.", "0."},       {3, "1.", "1.", "0."},
                     {4, "0.", "1.", "0."},       {5, "0.25", "0.25", "0.1"},  {6, "0.75", "0.25", "0.1"},
                     {7, "0.75", "0.75", "0.1"},  {8, "0.25", "0.75", "0.1"},  {9, "0.25", "0.25", "0.6"},
                     {10, "0.75", "0.25", "0.6"}, {11, "0.75", "0.75", "0.6"}, {12, "0.25", "0.75", "0.6"}};
  for (const auto& n : nodes)
    add(Card().at(1, 10, std::to_string(n.id)).at(11, 30, n.x).at(31, 50, n.y).at(51, 70, n.z).str());
  const std::string part1 = Card().at(1, 10, "1").at(11, 20, "1").str();
  const std::string part2 = Card().at(1, 10, "2").at(11, 20, "1").str();
  for (const std::string& l :
       {std::string("/PART/1"), std::string("plate"), part1, std::string("/PART/2"), std::string("block"),
        part2, std::string("/PROP/SHELL/1"), std::string("plate property"), std::string(), std::string()})
    add(l);
  add(Card().at(21, 40, "0.01").str());
  for (const char* l : {"/PROP/SOLID/2", "block property", "/MAT/LAW1/1", "steel"}) add(l);
  add(Card().at(1, 20, "7800.").str());
  add(Card().at(1, 20, "2.1E11").at(21, 40, "0.3").str());
  add("/SHELL/1");
  add(Card().at(1, 10, "1").at(11, 20, "1").at(21, 30, "2").at(31, 40, "3").at(41, 50, "4").str());
  add("/BRICK/2");
  {
    Card c;
    c.at(1, 10, "1");
    for (int k = 0; k < 8; ++k) c.at(11 + 10 * k, 20 + 10 * k, std::to_string(5 + k));
    add(c.str());
  }
  add("/GRNOD/PART/21");
  add("block nodes");
  add(Card().at(1, 10, "2").str());
  add("/SURF/PART/31");
  add("plate surface");
  add(Card().at(1, 10, "1").str());
  add("/SENSOR/TIME/17");  // the interface's sens_ID
  add("sensor");
  add(Card().at(1, 20, "0.001").str());
  add("#---1----|----2----|----3----|----4----|----5----|----6----|----7----|----8----|----9----|---10----|");

  DeckOut out;
  out.keyword_line = add(std::string(kind.lagdt ? "/INTER/LAGDT/TYPE7/7" : "/INTER/TYPE7/7"));
  add("interface under test");
  for (const auto& card : kind.lagdt ? lagdt_layout() : type7_layout()) {
    if (!holds(card.cond, v)) continue;
    if (only_card1 && card.card != "card 1") break;
    Card c;
    for (const auto& col : card.cols) {
      if (col.since > kind.version) continue;
      const auto it = v.find(col.name);
      if (it != v.end() && !it->second.empty()) c.at(col.a, col.b, it->second);
    }
    add("# " + card.card);
    const auto line = add(c.str());
    for (const auto& col : card.cols) out.line_of[col.name] = line;
    out.cards_written.push_back(card.card);
  }
  if (!after.empty()) {
    std::size_t start = 0;
    while (start < after.size()) {
      const auto end = after.find('\n', start);
      add(after.substr(start, end == std::string::npos ? std::string::npos : end - start));
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }
  add("/END");
  for (const auto& l : lines) out.text += l + "\n";
  return out;
}

struct Built {
  DeckOut deck;
  radx::Deck parsed;
  radx::model::Model model;
};

Built build(TempDir& dir, const Kind& kind, const Vals& v, Diagnostics& diags, const std::string& after = "",
            bool only_card1 = false) {
  Built b;
  b.deck = make_deck(kind, v, after, only_card1);
  static int n = 0;
  const auto path = dir.write("TYPE7_" + std::to_string(n++) + "_0000.rad", b.deck.text);
  // Every field may hold a distinct value, also those radx reads but does not implement (Itied, Ists, ...):
  // what is tested is the reading, so their substitution is allowed (test_formulations.cpp tests the
  // refusal).
  radx::ReadOptions opt;
  opt.allow_substitutions = true;
  b.parsed = radx::read_starter_deck(path, diags, opt);
  b.model = radx::build_model(b.parsed, diags);
  return b;
}

const radx::KeywordRecord* interface_record(const radx::Deck& d) {
  for (const auto& r : d.records)
    if (r.keyword() == "/INTER/TYPE7" || r.keyword() == "/INTER/LAGDT/TYPE7") return &r;
  return nullptr;
}

const radx::Diagnostic* first(const Diagnostics& d, Diag code) {
  for (const auto& i : d.items())
    if (i.code == code) return &i;
  return nullptr;
}

// Checks that `code` was reported as an error on the line of `field`.
void expect_error_at(const Diagnostics& diags, const DeckOut& deck, Diag code, const std::string& field) {
  INFO(all_diags(diags));
  INFO("expected " << radx::diag_code(code) << " on the line of " << field);
  REQUIRE(diags.contains(code));
  const auto* d = first(diags, code);
  REQUIRE(d != nullptr);
  CHECK(d->severity == radx::Severity::Error);
  REQUIRE(deck.line_of.count(field) == 1u);
  CHECK(d->line == static_cast<int>(deck.line_of.at(field)));
  CHECK(d->id == 7);
}

// The values of every field, distinct and valid (Renard friction with consistent coefficients).
Vals full_type7(int version) {
  Vals v = {{"grnd_IDs", "21"},  {"surf_IDm", "31"},    {"Istf", "4"},         {"Ithe", "1"},
            {"Igap", "2"},       {"Ibag", "1"},         {"Idel", "-1"},        {"Icurv", "1"},
            {"Iadm", "2"},       {"Fscalegap", "0.75"}, {"Gapmax", "2.5"},     {"Fpenmax", "0.35"},
            {"Stmin", "150.5"},  {"Stmax", "2.5E6"},    {"mesh_size", "0.45"}, {"dtmin", "1.25E-7"},
            {"Irem_gap", "2"},   {"Irem_i2", "1"},      {"node_ID1", "3"},     {"node_ID2", "4"},
            {"Stfac", "0.65"},   {"Fric", "0.15"},      {"Gapmin", "0.0055"},  {"Tstart", "0.0125"},
            {"Tstop", "3.5"},    {"IBCX", "1"},         {"IBCY", "0"},         {"IBCZ", "1"},
            {"Inacti", "5"},     {"VISs", "0.35"},      {"VISF", "0.85"},      {"Bumult", "0.27"},
            {"Ifric", "3"},      {"Ifiltr", "1"},       {"Xfreq", "0.4"},      {"Iform", "2"},
            {"sens_ID", "17"},   {"fct_IDF", "18"},     {"AscaleF", "1.75"},   {"fric_ID", "19"},
            {"C1", "0.3"},       {"C2", "0.2"},         {"C3", "0.5"},         {"C4", "0.1"},
            {"C5", "1.5"},       {"C6", "2.5"},         {"NRadm", "4"},        {"Padm", "0.6"},
            {"Angladm", "30.5"}, {"Kthe", "11.5"},      {"fct_IDK", "12"},     {"Tint", "293.5"},
            {"Ithe_form", "1"},  {"AscaleK", "1.25"},   {"Frad", "0.5"},       {"Drad", "0.25"},
            {"Fheats", "0.3"},   {"Fheatm", "0.7"}};
  if (version >= 2020) v["Itied"] = "1";
  if (version >= 2026) v["Ists"] = "2";
  return v;
}

Vals full_lagdt() {
  return {{"grnd_IDs", "21"},   {"surf_IDm", "31"},   {"Istf", "2"},         {"Igap", "1"},
          {"Ibag", "1"},        {"Idel", "2"},        {"Fscalegap", "0.85"}, {"Gapmax", "3.5"},
          {"Stmin", "250.5"},   {"Stmax", "3.5E6"},   {"Stfac", "0.45"},     {"Fric", "0.25"},
          {"Gapmin", "0.0065"}, {"Tstart", "0.0225"}, {"Tstop", "4.5"},      {"IBCX", "0"},
          {"IBCY", "1"},        {"IBCZ", "1"},        {"Inacti", "6"},       {"VISs", "0.45"},
          {"VISF", "0.95"},     {"Bumult", "0.33"},   {"Ifric", "2"},        {"Ifiltr", "3"},
          {"Xfreq", "12.5"},    {"Iform", "2"},       {"C1", "0.11"},        {"C2", "0.12"},
          {"C3", "0.13"},       {"C4", "0.14"},       {"C5", "0.15"},        {"C6", "0.16"}};
}

// Minimal valid interface: the two required ids.
Vals minimal() {
  return {{"grnd_IDs", "21"}, {"surf_IDm", "31"}};
}

void check_no_errors(const Diagnostics& diags) {
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
}

void check_tiny_model_links(const radx::model::Model& m, const radx::model::Interface& in) {
  REQUIRE(in.secondary_group >= 0);
  REQUIRE(in.main_surface >= 0);
  CHECK(m.node_groups.at(static_cast<std::size_t>(in.secondary_group)).id == 21);
  CHECK(m.surfaces.at(static_cast<std::size_t>(in.main_surface)).id == 31);
  std::vector<std::int64_t> secondary;
  for (auto n : in.secondary_nodes) secondary.push_back(m.nodes.id.at(static_cast<std::size_t>(n)));
  CHECK(secondary == std::vector<std::int64_t>{5, 6, 7, 8, 9, 10, 11, 12});
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// Every field.

TEST_CASE("/INTER/TYPE7 2026 and 2019: every field with a distinct value reaches model::Interface",
          "[type7]") {
  for (int version : {2026, 2019}) {
    INFO("deck version " << version);
    TempDir dir;
    Diagnostics diags;
    const Vals v = full_type7(version);
    const auto b = build(dir, {false, version}, v, diags);
    check_no_errors(diags);
    CHECK(b.parsed.version == version);
    REQUIRE(b.model.interfaces.size() == 1u);
    const auto& in = b.model.interfaces[0];
    CHECK(in.id == 7);
    CHECK(in.title == "interface under test");
    CHECK_FALSE(in.lagdt);
    check_tiny_model_links(b.model, in);
    CHECK(in.istf == 4);
    CHECK(in.ithe == 1);
    CHECK(in.igap == 2);
    CHECK(in.ibag == 1);
    CHECK(in.idel == -1);
    CHECK(in.icurv == 1);
    CHECK(in.iadm == 2);
    CHECK(in.fscale_gap == Approx(0.75).epsilon(kEps));
    CHECK(in.gap_max == Approx(2.5).epsilon(kEps));
    CHECK(in.fpenmax == Approx(0.35).epsilon(kEps));
    CHECK(in.itied == (version >= 2020 ? 1 : 0));
    CHECK(in.ists == (version >= 2026 ? 2 : 0));
    CHECK(in.stmin == Approx(150.5).epsilon(kEps));
    CHECK(in.stmax == Approx(2.5e6).epsilon(kEps));
    CHECK(in.mesh_size_pct == Approx(0.45).epsilon(kEps));
    CHECK(in.dt_min == Approx(1.25e-7).epsilon(kEps));
    CHECK(in.irem_gap == 2);
    CHECK(in.irem_i2 == 1);
    CHECK(in.stfac == Approx(0.65).epsilon(kEps));
    CHECK(in.fric == Approx(0.15).epsilon(kEps));
    CHECK(in.gapmin_input == Approx(0.0055).epsilon(kEps));
    CHECK(in.t_start == Approx(0.0125).epsilon(kEps));
    CHECK(in.t_stop == Approx(3.5).epsilon(kEps));
    CHECK(in.ibc == std::array<std::uint8_t, 3>{1, 0, 1});
    CHECK(in.inacti == 5);
    CHECK(in.vis_s == Approx(0.35).epsilon(kEps));
    CHECK(in.vis_f == Approx(0.85).epsilon(kEps));
    CHECK(in.bumult == Approx(0.27).epsilon(kEps));
    CHECK(in.ifric == 3);
    CHECK(in.ifiltr == 1);
    CHECK(in.xfreq == Approx(0.4).epsilon(kEps));
    CHECK(in.iform == 2);
    CHECK(in.sens_id == 17);
    CHECK(in.fct_id_f == 18);
    CHECK(in.ascale_f == Approx(1.75).epsilon(kEps));
    CHECK(in.fric_id == 19);
    const double c[6] = {0.3, 0.2, 0.5, 0.1, 1.5, 2.5};
    for (int k = 0; k < 6; ++k) {
      INFO("C" << k + 1);
      CHECK(in.c[static_cast<std::size_t>(k)] == Approx(c[k]).epsilon(kEps));
    }
    CHECK(in.contact_law_id == 0);
    // Fields the model does not carry: read into the record at their columns.
    const auto* r = interface_record(b.parsed);
    REQUIRE(r != nullptr);
    CHECK(r->get_int("node_ID1") == 3);
    CHECK(r->get_int("node_ID2") == 4);
    CHECK(r->get_int("NRadm") == 4);
    CHECK(r->get_real("Padm") == Approx(0.6).epsilon(kEps));
    CHECK(r->get_real("Angladm") == Approx(30.5).epsilon(kEps));
    CHECK(r->get_real("Kthe") == Approx(11.5).epsilon(kEps));
    CHECK(r->get_int("fct_IDK") == 12);
    CHECK(r->get_real("Tint") == Approx(293.5).epsilon(kEps));
    CHECK(r->get_int("Ithe_form") == 1);
    CHECK(r->get_real("AscaleK") == Approx(1.25).epsilon(kEps));
    CHECK(r->get_real("Frad") == Approx(0.5).epsilon(kEps));
    CHECK(r->get_real("Drad") == Approx(0.25).epsilon(kEps));
    CHECK(r->get_real("Fheats") == Approx(0.3).epsilon(kEps));
    CHECK(r->get_real("Fheatm") == Approx(0.7).epsilon(kEps));
    if (version < 2020) {
      CHECK(r->find("Itied") == nullptr);
      CHECK(r->find("Ists") == nullptr);
    } else {
      CHECK(r->find("Itied") != nullptr);
    }
    // Every field's line is the line of its card.
    for (const auto& [name, line] : b.deck.line_of) {
      const auto* f = r->find(name);
      if (f == nullptr) continue;  // not in this layout
      INFO("field " << name);
      CHECK(f->pos.line == line);
    }
  }
}

TEST_CASE("/INTER/LAGDT/TYPE7: every field with a distinct value reaches model::Interface", "[type7]") {
  for (int version : {2026, 2019, 2017}) {
    INFO("deck version " << version);
    TempDir dir;
    Diagnostics diags;
    const auto b = build(dir, {true, version}, full_lagdt(), diags);
    check_no_errors(diags);
    REQUIRE(b.model.interfaces.size() == 1u);
    const auto& in = b.model.interfaces[0];
    CHECK(in.id == 7);
    CHECK(in.title == "interface under test");
    CHECK(in.lagdt);
    check_tiny_model_links(b.model, in);
    CHECK(in.istf == 2);
    CHECK(in.igap == 1);
    CHECK(in.ibag == 1);
    CHECK(in.idel == 2);
    CHECK(in.fscale_gap == Approx(0.85).epsilon(kEps));
    CHECK(in.gap_max == Approx(3.5).epsilon(kEps));
    CHECK(in.stmin == Approx(250.5).epsilon(kEps));
    CHECK(in.stmax == Approx(3.5e6).epsilon(kEps));
    CHECK(in.stfac == Approx(0.45).epsilon(kEps));
    CHECK(in.fric == Approx(0.25).epsilon(kEps));
    CHECK(in.gapmin_input == Approx(0.0065).epsilon(kEps));
    CHECK(in.t_start == Approx(0.0225).epsilon(kEps));
    CHECK(in.t_stop == Approx(4.5).epsilon(kEps));
    CHECK(in.ibc == std::array<std::uint8_t, 3>{0, 1, 1});
    CHECK(in.inacti == 6);
    CHECK(in.vis_s == Approx(0.45).epsilon(kEps));
    CHECK(in.vis_f == Approx(0.95).epsilon(kEps));
    CHECK(in.bumult == Approx(0.33).epsilon(kEps));
    CHECK(in.ifric == 2);
    CHECK(in.ifiltr == 3);
    CHECK(in.xfreq == Approx(12.5).epsilon(kEps));
    CHECK(in.iform == 2);
    const double c[6] = {0.11, 0.12, 0.13, 0.14, 0.15, 0.16};
    for (int k = 0; k < 6; ++k) {
      INFO("C" << k + 1);
      CHECK(in.c[static_cast<std::size_t>(k)] == Approx(c[k]).epsilon(kEps));
    }
    // TYPE7-only fields keep their defaults.
    CHECK(in.ithe == 0);
    CHECK(in.icurv == 0);
    CHECK(in.iadm == 0);
    CHECK(in.itied == 0);
    CHECK(in.ists == 0);
    CHECK(in.fpenmax == 0.0);
    CHECK(in.mesh_size_pct == 0.0);
    CHECK(in.dt_min == 0.0);
    CHECK(in.irem_gap == 0);
    CHECK(in.irem_i2 == 0);
    CHECK(in.sens_id == 0);
    CHECK(in.fct_id_f == 0);
    CHECK(in.fric_id == 0);
    CHECK(in.ascale_f == 0.0);
    const auto* r = interface_record(b.parsed);
    REQUIRE(r != nullptr);
    for (const char* absent :
         {"Ithe", "Icurv", "Iadm", "Fpenmax", "Itied", "Ists", "mesh_size", "dtmin", "Irem_gap", "Irem_i2",
          "node_ID1", "sens_ID", "fct_IDF", "AscaleF", "fric_ID"}) {
      INFO("field " << absent);
      CHECK(r->find(absent) == nullptr);
    }
    for (const auto& [name, line] : b.deck.line_of) {
      const auto* f = r->find(name);
      INFO("field " << name);
      REQUIRE(f != nullptr);
      CHECK(f->pos.line == line);
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// Conditional cards.

TEST_CASE("TYPE7 and LAGDT conditional cards: Ifric 0/1/2/3, Icurv, Iadm 2, Ithe 1, next keyword right after",
          "[type7]") {
  struct Case {
    int ifric;
    int icurv;
    int iadm;
    int ithe;
  };
  // Each conditional card is followed by one that would be misread if a card were taken or skipped wrongly.
  const Case cases[] = {
      {0, 0, 0, 0},  // card 7 then the next keyword
      {0, 0, 0, 1},  // no C cards: the thermal cards follow card 7
      {1, 2, 2, 0},  // C1..C5 only, then the adaptive card
      {2, 0, 0, 1},  // C1..C5 and C6, then the thermal cards
      {3, 1, 2, 1},  // everything
      {1, 0, 0, 0},  // C1..C5, then the next keyword
      {2, 0, 0, 0},  // C6, then the next keyword
  };
  const std::string after = "/FUNCT/9\nafter the interface\n" +
                            Card().at(1, 20, "0.").at(21, 40, "1.5").str() + "\n" +
                            Card().at(1, 20, "2.").at(21, 40, "3.5").str();
  for (const auto& kind : kAllKinds) {
    for (const auto& cs : cases) {
      if (kind.lagdt && (cs.icurv || cs.iadm || cs.ithe)) continue;  // LAGDT has none of these
      INFO(kind.name() << ": Ifric " << cs.ifric << ", Icurv " << cs.icurv << ", Iadm " << cs.iadm
                       << ", Ithe " << cs.ithe);
      Vals v = kind.lagdt ? full_lagdt() : full_type7(kind.version);
      v["Ifric"] = std::to_string(cs.ifric);
      if (!kind.lagdt) {
        v["Icurv"] = std::to_string(cs.icurv);
        v["Iadm"] = std::to_string(cs.iadm);
        v["Ithe"] = std::to_string(cs.ithe);
        v["Ifiltr"] = "3";  // Xfreq free
      }
      // Renard-consistent coefficients for every law.
      const double c[6] = {0.3, 0.2, 0.5, 0.1, 1.5, 2.5};
      const char* ctext[6] = {"0.3", "0.2", "0.5", "0.1", "1.5", "2.5"};
      for (int k = 0; k < 6; ++k) v["C" + std::to_string(k + 1)] = ctext[k];
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags, after);
      check_no_errors(diags);
      CHECK_FALSE(diags.contains(Diag::ExtraData));
      CHECK_FALSE(diags.contains(Diag::MissingCard));
      REQUIRE(b.model.interfaces.size() == 1u);
      const auto& in = b.model.interfaces[0];
      CHECK(in.ifric == cs.ifric);
      for (int k = 0; k < 6; ++k) {
        INFO("C" << k + 1);
        const bool read = cs.ifric > 1 || (cs.ifric == 1 && k < 5);
        CHECK(in.c[static_cast<std::size_t>(k)] == Approx(read ? c[k] : 0.0).epsilon(kEps));
      }
      const auto* r = interface_record(b.parsed);
      REQUIRE(r != nullptr);
      CHECK((r->find("C1") != nullptr) == (cs.ifric > 0));
      CHECK((r->find("C6") != nullptr) == (cs.ifric > 1));
      // The cards before and after a conditional card keep their values.
      CHECK(in.stfac == Approx(kind.lagdt ? 0.45 : 0.65).epsilon(kEps));
      CHECK(in.vis_s == Approx(kind.lagdt ? 0.45 : 0.35).epsilon(kEps));
      CHECK(in.iform == 2);
      if (!kind.lagdt) {
        CHECK(in.icurv == cs.icurv);
        CHECK(in.iadm == cs.iadm);
        CHECK(in.ithe == cs.ithe);
        CHECK((r->find("node_ID1") != nullptr) == (cs.icurv != 0));
        if (cs.icurv != 0) {
          CHECK(r->get_int("node_ID1") == 3);
          CHECK(r->get_int("node_ID2") == 4);
        }
        CHECK((r->find("NRadm") != nullptr) == (cs.iadm == 2));
        if (cs.iadm == 2) {
          CHECK(r->get_int("NRadm") == 4);
          CHECK(r->get_real("Padm") == Approx(0.6).epsilon(kEps));
          CHECK(r->get_real("Angladm") == Approx(30.5).epsilon(kEps));
        }
        CHECK((r->find("Kthe") != nullptr) == (cs.ithe == 1));
        if (cs.ithe == 1) {
          CHECK(r->get_real("Kthe") == Approx(11.5).epsilon(kEps));
          CHECK(r->get_int("fct_IDK") == 12);
          CHECK(r->get_real("AscaleK") == Approx(1.25).epsilon(kEps));
          CHECK(r->get_real("Frad") == Approx(0.5).epsilon(kEps));
          CHECK(r->get_real("Fheatm") == Approx(0.7).epsilon(kEps));
        }
      }
      // The next keyword is intact.
      REQUIRE(b.model.functions.size() == 1u);
      const auto& f = b.model.functions[0];
      CHECK(f.id == 9);
      CHECK(f.title == "after the interface");
      CHECK(f.x == std::vector<double>{0.0, 2.0});
      CHECK(f.y == std::vector<double>{1.5, 3.5});
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// Defaults.

namespace {

void check_defaults(const radx::model::Interface& in) {
  CHECK(in.istf == 0);
  CHECK(in.igap == 0);
  CHECK(in.ibag == 0);
  CHECK(in.idel == 0);
  CHECK(in.fscale_gap == 1.0);
  CHECK(in.gap_max == 0.0);
  CHECK(in.stmin == 0.0);
  CHECK(in.stmax == 1e30);
  CHECK(in.stfac == 1.0);
  CHECK(in.fric == 0.0);
  CHECK(in.gapmin_input == 0.0);
  CHECK(in.t_start == 0.0);
  CHECK(in.t_stop == 1e30);
  CHECK(in.t_stop == radx::model::kNever);
  CHECK(in.ibc == std::array<std::uint8_t, 3>{0, 0, 0});
  CHECK(in.inacti == 0);
  CHECK(in.vis_s == 0.05);
  CHECK(in.vis_f == 1.0);
  CHECK(in.bumult == 0.2);  // 12 nodes: the small-model value
  CHECK(in.ifric == 0);
  CHECK(in.ifiltr == 0);
  CHECK(in.xfreq == 0.0);
  CHECK(in.iform == 1);
  CHECK(in.c == std::array<double, 6>{});
  CHECK(in.ithe == 0);
  CHECK(in.icurv == 0);
  CHECK(in.iadm == 0);
  CHECK(in.itied == 0);
  CHECK(in.ists == 0);
  CHECK(in.fpenmax == 0.0);
  CHECK(in.dt_min == 0.0);
}

}  // namespace

TEST_CASE("TYPE7 and LAGDT defaults: every optional field blank, missing or written 0", "[type7]") {
  for (const auto& kind : kAllKinds) {
    INFO(kind.name());
    {
      INFO("blank cards");
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, minimal(), diags);
      check_no_errors(diags);
      REQUIRE(b.model.interfaces.size() == 1u);
      check_defaults(b.model.interfaces[0]);
      CHECK(b.deck.cards_written.size() == 6u);  // no conditional card
    }
    {
      INFO("the block ends after card 1");
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, minimal(), diags, "", true);
      check_no_errors(diags);
      REQUIRE(b.model.interfaces.size() == 1u);
      check_defaults(b.model.interfaces[0]);
      CHECK(b.deck.cards_written.size() == 1u);
    }
    {
      INFO("every optional field written as 0");
      Vals v = minimal();
      const auto layout = kind.lagdt ? lagdt_layout() : type7_layout();
      for (const auto& card : layout)
        for (const auto& col : card.cols)
          if (!v.count(col.name)) v[col.name] = "0";
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      check_no_errors(diags);
      REQUIRE(b.model.interfaces.size() == 1u);
      check_defaults(b.model.interfaces[0]);
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// Checks, each reported on the line of the field at fault.

TEST_CASE("TYPE7 and LAGDT: Istf = 1 with Stfac blank or 0 is RX502 on the Stfac line", "[type7]") {
  for (const auto& kind : kAllKinds) {
    for (const char* stfac : {"", "0", "0."}) {
      INFO(kind.name() << ", Stfac '" << stfac << "'");
      Vals v = minimal();
      v["Istf"] = "1";
      v["Stfac"] = stfac;
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      expect_error_at(diags, b.deck, Diag::RequiredValueMissing, "Stfac");
    }
  }
}

TEST_CASE("TYPE7 and LAGDT: Istf = 1 with Stfac > 0 takes Stfac as the stiffness, no error", "[type7]") {
  for (const auto& kind : kAllKinds) {
    INFO(kind.name());
    Vals v = minimal();
    v["Istf"] = "1";
    v["Stfac"] = "2.5E5";
    TempDir dir;
    Diagnostics diags;
    const auto b = build(dir, kind, v, diags);
    check_no_errors(diags);
    REQUIRE(b.model.interfaces.size() == 1u);
    CHECK(b.model.interfaces[0].istf == 1);
    CHECK(b.model.interfaces[0].stfac == Approx(2.5e5).epsilon(kEps));
  }
}

TEST_CASE("TYPE7 and LAGDT: Stmax < Stmin with Istf 2 is RX507 on the Stmax line", "[type7]") {
  for (const auto& kind : kAllKinds) {
    INFO(kind.name());
    Vals v = minimal();
    v["Istf"] = "2";
    v["Stmin"] = "2000.";
    v["Stmax"] = "1000.";
    TempDir dir;
    Diagnostics diags;
    const auto b = build(dir, kind, v, diags);
    expect_error_at(diags, b.deck, Diag::InconsistentValues, "Stmax");
  }
}

TEST_CASE("TYPE7 and LAGDT: Tstop <= Tstart is RX507 on the Tstop line", "[type7]") {
  for (const auto& kind : kAllKinds) {
    for (const char* tstop : {"0.5", "0.25"}) {
      INFO(kind.name() << ", Tstart 0.5, Tstop " << tstop);
      Vals v = minimal();
      v["Tstart"] = "0.5";
      v["Tstop"] = tstop;
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      expect_error_at(diags, b.deck, Diag::InconsistentValues, "Tstop");
    }
  }
}

TEST_CASE("TYPE7 and LAGDT: Renard friction (Ifric 3) with C5 = 0 or C5 >= C6 is RX703 on the C5 line",
          "[type7]") {
  struct Case {
    const char* what;
    const char* c5;
    const char* c6;
  };
  const Case cases[] = {{"C5 = 0", "", "2.5"}, {"C5 > C6", "2.5", "1.5"}, {"C5 = C6", "1.5", "1.5"}};
  for (const auto& kind : kAllKinds) {
    for (const auto& cs : cases) {
      INFO(kind.name() << ": " << cs.what);
      Vals v = minimal();
      v["Ifric"] = "3";
      v["C1"] = "0.3";
      v["C2"] = "0.2";
      v["C3"] = "0.5";
      v["C4"] = "0.1";
      v["C5"] = cs.c5;
      v["C6"] = cs.c6;
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      expect_error_at(diags, b.deck, Diag::BadFrictionLaw, "C5");
    }
  }
}

TEST_CASE("TYPE7 and LAGDT: Istf 7 and Inacti 4 are RX501 on their card's line", "[type7]") {
  for (const auto& kind : kAllKinds) {
    INFO(kind.name());
    {
      Vals v = minimal();
      v["Istf"] = "7";
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      expect_error_at(diags, b.deck, Diag::ValueOutOfRange, "Istf");
      CHECK(first(diags, Diag::ValueOutOfRange)->column == 21);
    }
    {
      Vals v = minimal();
      v["Inacti"] = "4";
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      expect_error_at(diags, b.deck, Diag::ValueOutOfRange, "Inacti");
      CHECK(first(diags, Diag::ValueOutOfRange)->column == 31);
    }
  }
}

TEST_CASE("TYPE7 and LAGDT: Ibag 1 is accepted with a warning RX509 on card 1, no error", "[type7]") {
  for (const auto& kind : kAllKinds) {
    INFO(kind.name());
    Vals v = minimal();
    v["Ibag"] = "1";
    TempDir dir;
    Diagnostics diags;
    const auto b = build(dir, kind, v, diags);
    check_no_errors(diags);
    REQUIRE(diags.contains(Diag::UnimplementedOption));
    const auto* d = first(diags, Diag::UnimplementedOption);
    CHECK(d->severity == radx::Severity::Warning);
    CHECK(d->line == static_cast<int>(b.deck.line_of.at("Ibag")));
    REQUIRE(b.model.interfaces.size() == 1u);
    CHECK(b.model.interfaces[0].ibag == 1);
  }
}

TEST_CASE("TYPE7 and LAGDT: a missing node group or surface is RX402 on card 1", "[type7]") {
  for (const auto& kind : kAllKinds) {
    INFO(kind.name());
    {
      Vals v = minimal();
      v["grnd_IDs"] = "99";
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      expect_error_at(diags, b.deck, Diag::MissingReference, "grnd_IDs");
      CHECK(first(diags, Diag::MissingReference)->column == 1);
      REQUIRE(b.model.interfaces.size() == 1u);
      CHECK(b.model.interfaces[0].secondary_group == radx::model::kNone);
    }
    {
      Vals v = minimal();
      v["surf_IDm"] = "98";
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      expect_error_at(diags, b.deck, Diag::MissingReference, "surf_IDm");
      CHECK(first(diags, Diag::MissingReference)->column == 11);
    }
  }
}

TEST_CASE(
    "TYPE7 and LAGDT: grnd_IDs 0 takes the main surface's nodes as secondary nodes, with a note, as "
    "Radioss does",
    "[type7]") {
  for (const auto& kind : kAllKinds) {
    INFO(kind.name());
    for (const char* zero : {"0", ""}) {
      Vals v = minimal();
      v["grnd_IDs"] = zero;
      TempDir dir;
      Diagnostics diags;
      const auto b = build(dir, kind, v, diags);
      check_no_errors(diags);
      REQUIRE(b.model.interfaces.size() == 1u);
      const auto& in = b.model.interfaces[0];
      CHECK(in.secondary_group == radx::model::kNone);
      std::set<std::int32_t> expected;
      for (const auto& seg : b.model.surfaces.at(static_cast<std::size_t>(in.main_surface)).segments)
        expected.insert(seg.begin(), seg.end());
      CHECK(std::set<std::int32_t>(in.secondary_nodes.begin(), in.secondary_nodes.end()) == expected);
      CHECK(in.secondary_nodes.size() == expected.size());
      const auto* d = first(diags, Diag::DefaultApplied);
      REQUIRE(d);
      CHECK(d->severity == radx::Severity::Note);
      CHECK(d->message.find("self-contact") != std::string::npos);
    }
  }
}

TEST_CASE("TYPE7 and LAGDT: Igap 1000 is the constant gap of Igap 0, with a note, as Radioss reads it",
          "[type7]") {
  for (const auto& kind : kAllKinds) {
    INFO(kind.name());
    Vals v = minimal();
    v["Igap"] = "1000";
    TempDir dir;
    Diagnostics diags;
    const auto b = build(dir, kind, v, diags);
    check_no_errors(diags);
    REQUIRE(b.model.interfaces.size() == 1u);
    CHECK(b.model.interfaces[0].igap == 0);
    const auto* d = first(diags, Diag::DefaultApplied);
    REQUIRE(d);
    CHECK(d->line == static_cast<int>(b.deck.line_of.at("Igap")));
    CHECK(d->message.find("Igap = 1000") != std::string::npos);
  }
}
