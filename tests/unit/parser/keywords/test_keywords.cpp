// Every keyword of the subset (docs/theory/deck-format.md section 2 and 3) read from small decks written in
// each layout band, values checked field by field through the Deck API.
//
// The decks are written by the test from an independent statement of the layouts (for 2017 and newer the
// layouts docs/keywords.md lists, for the formats 90 to 140 the FORMAT blocks of the reference's reader
// files; written out here, not taken from the reader's declarations): each field is placed right-justified
// at the columns of its band by a helper, so no column is counted by hand. Every field gets a distinct
// non-default value (11, 12, 13, ... for integers, 14.5, 15.5, ... for reals), so a field read from the
// wrong columns, or a card read in the wrong order, gives a wrong value. Fields that a band does not have
// must be absent from the record.
//
// Tolerances: reals read from text are compared with Approx(...).epsilon(1e-12) (parsing exactness: the
// decimal text is converted once; anything beyond rounding of the last bit is a parsing error). Unit
// conversions are compared with the same relative tolerance against factors computed by hand.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "parser/reading/deck.hpp"
#include "solver/model/run_files.hpp"
#include "test_util.hpp"

namespace {

namespace fs = std::filesystem;
using radx::Diag;
using radx::Diagnostics;

constexpr double kEps = 1e-12;

using radx::test::TempDir;

// One card line: values placed right-justified in columns [first, last] (1-based, inclusive), or
// left-justified from a column.
class Card {
 public:
  Card& at(int first, int last, const std::string& v) {
    const auto width = static_cast<std::size_t>(last - first + 1);
    if (v.size() > width) throw std::invalid_argument("test bug: '" + v + "' does not fit its columns");
    grow(static_cast<std::size_t>(last));
    s_.replace(static_cast<std::size_t>(last) - v.size(), v.size(), v);
    return *this;
  }
  Card& at(int first, int last, long long v) { return at(first, last, std::to_string(v)); }
  Card& left(int first, const std::string& v) {
    grow(static_cast<std::size_t>(first - 1) + v.size());
    s_.replace(static_cast<std::size_t>(first - 1), v.size(), v);
    return *this;
  }
  [[nodiscard]] const std::string& str() const { return s_; }

 private:
  void grow(std::size_t n) {
    if (s_.size() < n) s_.resize(n, ' ');
  }
  std::string s_;
};

// The diagnostics as text, for INFO on failure (errors only where warnings are expected by design).
std::string all_diags(const Diagnostics& diags, bool errors_only = false) {
  std::string s;
  for (const auto& d : diags.items())
    if (!errors_only || d.severity == radx::Severity::Error) s += Diagnostics::format(d) + "\n";
  return s;
}

// ---------------------------------------------------------------------------------------------------
// Keyword layouts as the test states them.

enum class Ty { Int, Real, Str };

struct Fld {
  std::string name;
  int a = 1;
  int b = 10;
  Ty ty = Ty::Int;
  int since = 0;
  int until = 9999;
  std::string text;  // as written; empty: left blank
  bool left = false;
  std::int64_t i = 0;  // expected values
  double r = 0;
  std::string s;
  Fld& ver(int from, int to = 9999) {
    since = from;
    until = to;
    return *this;
  }
  [[nodiscard]] bool in(int v) const { return v >= since && v <= until; }
};
using CardSpec = std::vector<Fld>;

Fld field(const std::string& name, int a, int b, Ty ty) {
  Fld f;
  f.name = name;
  f.a = a;
  f.b = b;
  f.ty = ty;
  return f;
}
Fld Ix(const std::string& name, int a, int b, std::int64_t v) {
  Fld f = field(name, a, b, Ty::Int);
  f.text = std::to_string(v);
  f.i = v;
  return f;
}
Fld Rx(const std::string& name, int a, int b, const std::string& text, double v) {
  Fld f = field(name, a, b, Ty::Real);
  f.text = text;
  f.r = v;
  return f;
}
Fld Sx(const std::string& name, int a, int b, const std::string& text) {
  Fld f = field(name, a, b, Ty::Str);
  f.text = text;
  f.s = text;
  return f;
}
Fld Sl(const std::string& name, int a, int b, const std::string& text) {
  Fld f = Sx(name, a, b, text);
  f.left = true;
  return f;
}
Fld Blank(const std::string& name, int a, int b, Ty ty) {
  return field(name, a, b, ty);
}

// Distinct values: every call gives a value no other field of the deck has.
class Values {
 public:
  Fld I(const std::string& name, int a, int b) { return Ix(name, a, b, n_++); }
  Fld R(const std::string& name, int a, int b) {
    const auto v = n_++;
    return Rx(name, a, b, std::to_string(v) + ".5", static_cast<double>(v) + 0.5);
  }
  std::int64_t next() { return n_++; }

 private:
  std::int64_t n_ = 11;
};

struct Kw {
  std::string header;  // keyword line as written
  std::string path;    // canonical path the reader must give
  std::int64_t id = 0;
  std::int64_t unit = 0;
  bool has_title = false;
  std::string title;
  std::vector<CardSpec> cards;                      // fixed cards the reader must read, in order
  std::vector<CardSpec> records;                    // record tail, one line each
  std::vector<std::vector<std::string>> var_lines;  // /TH variable lines
  std::vector<std::string> th_vars;                 // expected th_variables
  std::vector<std::vector<std::int64_t>> id_lines;  // id-list tail, one line each
  std::vector<std::string> text_lines;              // text tail as written
  std::string text;                                 // expected text
  std::vector<std::string> absent;                  // field names the record must not have
  std::string word;                                 // Header::Word keywords: the text field
  // Filled by the writer: physical line numbers.
  std::uint32_t line = 0;
  std::vector<std::uint32_t> card_lines, record_lines, id_line_numbers;
};

class DeckSpec {
 public:
  explicit DeckSpec(int version) : v(version) {}
  Kw& add(const std::string& header, const std::string& path, std::int64_t id = 0, std::int64_t unit = 0) {
    Kw k;
    k.header = header;
    k.path = path;
    k.id = id;
    k.unit = unit;
    kws.push_back(std::move(k));
    return kws.back();
  }
  Kw& titled(const std::string& header, const std::string& path, std::int64_t id, const std::string& title,
             std::int64_t unit = 0) {
    Kw& k = add(header, path, id, unit);
    k.has_title = true;
    k.title = title;
    return k;
  }
  int v;
  Values x;
  std::vector<Kw> kws;
};

std::string render(const CardSpec& c, int v) {
  Card line;
  for (const auto& f : c) {
    if (!f.in(v) || f.text.empty()) continue;
    if (f.left)
      line.left(f.a, f.text);
    else
      line.at(f.a, f.b, f.text);
  }
  return line.str();
}

// Writes the deck with a comment line before every keyword and every card (comments may appear
// anywhere); fills the line numbers of the spec.
std::string write_deck(DeckSpec& d, const std::string& eol = "\n") {
  std::vector<std::string> lines;
  auto add = [&lines](std::string s) {
    lines.push_back(std::move(s));
    return static_cast<std::uint32_t>(lines.size());
  };
  add("#RADIOSS STARTER");
  for (auto& k : d.kws) {
    add("#---1----|----2----|----3----|----4----|----5----|----6----|----7----|----8----|----9----|---10----"
        "|");
    k.line = add(k.header);
    if (k.has_title) add(k.title);
    for (const auto& c : k.cards) {
      add("# card");
      k.card_lines.push_back(add(render(c, d.v)));
    }
    for (const auto& vl : k.var_lines) {
      Card c;
      for (std::size_t n = 0; n < vl.size(); ++n) c.left(static_cast<int>(10 * n + 1), vl[n]);
      add(c.str());
    }
    for (const auto& il : k.id_lines) {
      Card c;
      for (std::size_t n = 0; n < il.size(); ++n)
        c.at(static_cast<int>(10 * n + 1), static_cast<int>(10 * n + 10), il[n]);
      k.id_line_numbers.push_back(add(c.str()));
    }
    for (const auto& r : k.records) k.record_lines.push_back(add(render(r, d.v)));
    for (const auto& t : k.text_lines) add(t);
  }
  add("/END");
  add("anything after /END is ignored");
  std::string out;
  for (const auto& l : lines) out += l + eol;
  return out;
}

// --- the keywords

CardSpec prop_shell_card1(Values& x) {
  return {Ix("Ishell", 1, 10, 12),           Ix("Ismstr", 11, 20, 10),
          Ix("Ish3n", 21, 30, 31),           Ix("Idrill", 31, 40, 2).ver(110),
          Ix("Ipinch", 41, 50, 1).ver(2020), x.R("P_Thick_Fail", 61, 80).ver(2018)};
}

void add_prop_shell(DeckSpec& d, const std::string& header, std::int64_t id) {
  auto& x = d.x;
  Kw& k = d.titled(header, "/PROP/SHELL", id, "shell property " + std::to_string(id));
  k.cards = {
      prop_shell_card1(x),
      {x.R("Hm", 1, 20), x.R("Hf", 21, 40), x.R("Hr", 41, 60), x.R("Dm", 61, 80), x.R("Dn", 81, 100)},
      {Ix("N", 1, 10, 5), x.I("Istrain", 11, 20).ver(0, 2023), x.R("Thick", 21, 40), x.R("Ashear", 41, 60),
       Ix("Ithick", 71, 80, 1), Ix("Iplas", 81, 90, 2), x.I("Ipos", 91, 100).ver(2024)}};
}

void add_prop_solid(DeckSpec& d, const std::string& header, std::int64_t id) {
  auto& x = d.x;
  Kw& k = d.titled(header, "/PROP/SOLID", id, "solid property " + std::to_string(id));
  // 90: no Itetra4, card 3 only deltaT_min; 100-110: no Lambda, Mu, Ihkt; up to 130: no card 4.
  k.cards = {
      {Ix("Isolid", 1, 10, 14), Ix("Ismstr", 11, 20, 12), Ix("Iale", 21, 30, 1).ver(2022),
       Ix("Icpre", 31, 40, 3), Ix("Itetra10", 41, 50, 2).ver(2019), x.I("Inpts", 51, 60),
       Ix("Itetra4", 61, 70, 1000).ver(100), Ix("Iframe", 71, 80, 2), x.R("dn", 81, 100)},
      {x.R("qa", 1, 20), x.R("qb", 21, 40), x.R("h", 41, 60), x.R("Lambda", 61, 80).ver(120),
       x.R("Mu", 81, 100).ver(120)},
      {x.R("deltaT_min", 1, 20), x.I("Istrain", 21, 30).ver(100, 2022), x.I("Ihkt", 31, 40).ver(120, 2022),
       x.R("vdef_min", 21, 40).ver(2023), x.R("vdef_max", 41, 60).ver(2023), x.R("ASP_max", 61, 80).ver(2023),
       x.R("COL_min", 81, 100).ver(2023)}};
  if (d.v >= 140)
    k.cards.push_back({x.I("Ndir", 1, 10), x.I("sphpart_ID", 11, 20), Ix("Icontrol", 21, 30, 1).ver(2025)});
  else
    k.absent = {"Ndir", "sphpart_ID", "Icontrol"};
}

void add_law1(DeckSpec& d, const std::string& header, std::int64_t id, std::int64_t unit) {
  auto& x = d.x;
  Kw& k = d.titled(header, "/MAT/LAW1", id, "elastic " + std::to_string(id), unit);
  k.cards = {{x.R("RHO_I", 1, 20), x.R("RHO_ref", 21, 40)}, {x.R("E", 1, 20), Rx("nu", 21, 40, "0.3", 0.3)}};
  k.absent = {"Iflag", "a"};
}

void add_law2(DeckSpec& d, const std::string& header, std::int64_t id, int iflag) {
  auto& x = d.x;
  Kw& k = d.titled(header, "/MAT/LAW2", id, "Johnson-Cook " + std::to_string(id));
  // RHO_I is right-justified, so columns 11-20 hold text and the 90-130 layouts read RHO_ref too.
  k.cards.push_back({x.R("RHO_I", 1, 20), x.R("RHO_ref", 21, 40)});
  k.cards.push_back({x.R("E", 1, 20), Rx("nu", 21, 40, "0.3", 0.3), Ix("Iflag", 41, 50, iflag).ver(140),
                     Ix("flagVP", 51, 60, 3).ver(2023), x.R("Pmin", 61, 80).ver(2025)});
  // Before 140 card 2 has no Iflag: card 3 is always a, b, n.
  if (d.v < 140) iflag = 0;
  if (iflag == 0) {
    k.cards.push_back({x.R("a", 1, 20), x.R("b", 21, 40), Rx("n", 41, 60, "0.45", 0.45),
                       x.R("EPS_p_max", 61, 80), x.R("SIG_max0", 81, 100)});
    k.absent = {"SIG_Y", "UTS", "EUTS"};
  } else {
    k.cards.push_back({x.R("SIG_Y", 1, 20), x.R("UTS", 21, 40), x.R("EUTS", 41, 60), x.R("EPS_p_max", 61, 80),
                       x.R("SIG_max0", 81, 100)});
    k.absent = {"a", "b", "n"};
  }
  k.cards.push_back({x.R("c", 1, 20), x.R("EPS_DOT_0", 21, 40), Ix("ICC", 41, 50, 2),
                     Ix("Fsmooth", 51, 60, 1), x.R("F_cut", 61, 80),
                     Rx("Chard", 81, 100, "0.25", 0.25).ver(100)});
  k.cards.push_back({x.R("m", 1, 20), x.R("T_melt", 21, 40), x.R("rhoC_p", 41, 60), x.R("T_r", 61, 80),
                     x.R("T_max", 81, 100).ver(2025)});
}

void add_type7(DeckSpec& d, std::int64_t id) {
  auto& x = d.x;
  const int v = d.v;
  Kw& k = d.titled("/INTER/TYPE7/" + std::to_string(id), "/INTER/TYPE7", id, "type7 every card");
  k.cards = {
      {x.I("grnd_IDs", 1, 10), x.I("surf_IDm", 11, 20), Ix("Istf", 21, 30, 4), Ix("Ithe", 31, 40, 1),
       Ix("Igap", 41, 50, 2), x.I("Multimp", 51, 60).ver(0, 110), Ix("Ibag", 61, 70, 1),
       Ix("Idel", 71, 80, -1), Ix("Icurv", 81, 90, 1), Ix("Iadm", 91, 100, 2)},
      {x.R("Fscalegap", 1, 20), x.R("Gapmax", 21, 40), x.R("Fpenmax", 41, 60).ver(120),
       x.I("Itied", 81, 90).ver(2020), x.I("Ists", 91, 100).ver(2026)},
      {x.R("Stmin", 1, 20), x.R("Stmax", 21, 40), x.R("mesh_size", 41, 60).ver(110),
       x.R("dtmin", 61, 80).ver(120), x.I("Irem_gap", 81, 90).ver(120), x.I("Irem_i2", 91, 100).ver(130)},
      {x.I("node_ID1", 1, 10), x.I("node_ID2", 11, 20)},  // Icurv = 1
      {x.R("Stfac", 1, 20), x.R("Fric", 21, 40), x.R("Gapmin", 41, 60), x.R("Tstart", 61, 80),
       x.R("Tstop", 81, 100)},
      {Ix("IBCX", 8, 8, 1), Ix("IBCY", 9, 9, 0), Ix("IBCZ", 10, 10, 1), Ix("Inacti", 31, 40, 6),
       x.R("VISs", 41, 60), x.R("VISF", 61, 80), x.R("Bumult", 81, 100)},
      {Ix("Ifric", 1, 10, 2), Ix("Ifiltr", 11, 20, 3), x.R("Xfreq", 21, 40), Ix("Iform", 41, 50, 2),
       x.I("sens_ID", 51, 60).ver(120), x.I("fct_IDF", 61, 70).ver(140), x.R("AscaleF", 71, 90).ver(140),
       x.I("fric_ID", 91, 100).ver(2018)},
      {x.R("C1", 1, 20), x.R("C2", 21, 40), x.R("C3", 41, 60), x.R("C4", 61, 80), x.R("C5", 81, 100)},
      {x.R("C6", 1, 20)},
  };
  const CardSpec adaptive = {x.I("NRadm", 1, 10), x.R("Padm", 11, 30), x.R("Angladm", 31, 50)};  // Iadm = 2
  // Ithe = 1: from 140 two thermal cards; 100 to 130 one shorter card; the 90 layout reads its thermal card
  // only for Ithe > 1, so none here.
  std::vector<CardSpec> thermal;
  if (v >= 140) {
    thermal = {{x.R("Kthe", 1, 20), x.I("fct_IDK", 21, 30), x.R("Tint", 41, 60), x.I("Ithe_form", 61, 70),
                x.R("AscaleK", 71, 90)},
               {x.R("Frad", 1, 20), x.R("Drad", 21, 40), x.R("Fheats", 41, 60), x.R("Fheatm", 61, 80)}};
  } else if (v >= 100) {
    thermal = {{x.R("Kthe", 1, 20), x.R("Tint", 41, 60), x.I("Ithe_form", 61, 70)}};
    k.absent = {"fct_IDK", "AscaleK", "Frad", "Fheatm"};
  } else {
    k.absent = {"Kthe", "Tint", "Ithe_form", "Frad"};
  }
  // From 110 the adaptive-meshing card comes before the thermal cards; up to 100 after them.
  if (v >= 110) k.cards.push_back(adaptive);
  for (auto& c : thermal) k.cards.push_back(c);
  if (v < 110) k.cards.push_back(adaptive);
}

void add_lagdt(DeckSpec& d, std::int64_t id) {
  auto& x = d.x;
  Kw& k = d.titled("/INTER/LAGDT/TYPE7/" + std::to_string(id), "/INTER/LAGDT/TYPE7", id, "lagdt every card");
  k.cards = {
      {x.I("grnd_IDs", 1, 10), x.I("surf_IDm", 11, 20), Ix("Istf", 21, 30, 5), Ix("Igap", 41, 50, 1),
       x.I("Multimp", 51, 60).ver(0, 130), Ix("Ibag", 61, 70, 1), Ix("Idel", 71, 80, 2)},
      {x.R("Fscalegap", 1, 20), x.R("Gapmax", 21, 40)},
      {x.R("Stmin", 1, 20), x.R("Stmax", 21, 40)},
      {x.R("Stfac", 1, 20), x.R("Fric", 21, 40), x.R("Gapmin", 41, 60), x.R("Tstart", 61, 80),
       x.R("Tstop", 81, 100)},
      {Ix("IBCX", 8, 8, 0), Ix("IBCY", 9, 9, 1), Ix("IBCZ", 10, 10, 1), Ix("Inacti", 31, 40, 3),
       x.R("VISs", 41, 60), x.R("VISF", 61, 80), x.R("Bumult", 81, 100)},
      {Ix("Ifric", 1, 10, 3), Ix("Ifiltr", 11, 20, 2), x.R("Xfreq", 21, 40), Ix("Iform", 41, 50, 1)},
      {x.R("C1", 1, 20), x.R("C2", 21, 40), x.R("C3", 41, 60), x.R("C4", 61, 80), x.R("C5", 81, 100)},
      {x.R("C6", 1, 20)},
  };
  k.absent = {"Ithe",      "Icurv",   "Iadm",     "Fpenmax", "Itied",    "Ists",
              "mesh_size", "dtmin",   "Irem_gap", "Irem_i2", "node_ID1", "sens_ID",
              "fct_IDF",   "AscaleF", "fric_ID",  "NRadm",   "Kthe"};
}

// The whole starter subset in the layout of deck version v.
DeckSpec full_deck(int v) {
  DeckSpec d(v);
  auto& x = d.x;
  {
    Kw& k = d.add("/BEGIN", "/BEGIN");
    // Input units written as SI factors, work units as names: the same systems, so nothing is converted.
    k.cards = {{Sx("RUNNAME", 1, 100, "KEYWORDS_" + std::to_string(v))},
               {Ix("INVERS", 1, 10, v), x.I("IRUN", 11, 20).ver(0, 2020)}};
    if (v >= 100) {
      k.cards.push_back({Sx("input_mass", 1, 20, "1000"), Sx("input_length", 21, 40, "0.001"),
                         Sx("input_time", 41, 60, "1")});
      k.cards.push_back(
          {Sx("work_mass", 1, 20, "Mg"), Sx("work_length", 21, 40, "mm"), Sx("work_time", 41, 60, "s")});
    } else {
      // Version 90: no unit cards; the global units are keywords of their own, input = work.
      k.absent = {"input_mass", "work_mass"};
      d.add("/UNIT/MASS/Mg", "/UNIT/MASS").word = "Mg";
      d.add("/UNIT/LENGTH/ mm", "/UNIT/LENGTH").word = "mm";
      d.add("/UNIT/TIME/s", "/UNIT/TIME").word = "s";
    }
  }
  d.add("/TITLE", "/TITLE").cards = {
      {Sx("TITLE", 1, 100, "Every keyword of the subset in layout " + std::to_string(v))}};
  d.titled("/UNIT/7", "/UNIT", 7, "the work units again").cards = {
      {Sx("MUNIT", 1, 20, "Mg"), Sx("LUNIT", 21, 40, "mm"), Sx("TUNIT", 41, 60, "s")}};
  {
    Kw& k = d.add("/NODE", "/NODE");
    for (int n = 0; n < 3; ++n)
      k.records.push_back({x.I("node_ID", 1, 10), x.R("X", 11, 30), x.R("Y", 31, 50), x.R("Z", 51, 70)});
  }
  d.add("/NODE/7", "/NODE", 0, 7).records = {
      {x.I("node_ID", 1, 10), x.R("X", 11, 30), x.R("Y", 31, 50), x.R("Z", 51, 70)}};
  d.add("/SHELL/101", "/SHELL", 101).records = {
      {x.I("shell_ID", 1, 10), x.I("n1", 11, 20), x.I("n2", 21, 30), x.I("n3", 31, 40), x.I("n4", 41, 50),
       x.R("PHI", 61, 80), x.R("Thick", 81, 100)},
      {x.I("shell_ID", 1, 10), x.I("n1", 11, 20), x.I("n2", 21, 30), x.I("n3", 31, 40), x.I("n4", 41, 50),
       x.R("PHI", 61, 80), x.R("Thick", 81, 100)}};
  // /SH3N: the reader's windows are 71-90 and 91-100; the second line follows the comment ruler
  // (61-80, 81-100), which reads the same for right-justified numbers of up to 10 characters.
  d.add("/SH3N/102", "/SH3N", 102).records = {{x.I("tria_ID", 1, 10), x.I("n1", 11, 20), x.I("n2", 21, 30),
                                               x.I("n3", 31, 40), x.R("PHI", 71, 90), x.R("Thick", 91, 100)},
                                              {x.I("tria_ID", 1, 10), x.I("n1", 11, 20), x.I("n2", 21, 30),
                                               x.I("n3", 31, 40), x.R("PHI", 61, 80), x.R("Thick", 81, 100)}};
  d.add("/BRICK/103", "/BRICK", 103).records = {{x.I("brick_ID", 1, 10), x.I("n1", 11, 20), x.I("n2", 21, 30),
                                                 x.I("n3", 31, 40), x.I("n4", 41, 50), x.I("n5", 51, 60),
                                                 x.I("n6", 61, 70), x.I("n7", 71, 80), x.I("n8", 81, 90)}};
  d.titled("/PART/101", "/PART", 101, "the shell part").cards = {
      {x.I("prop_ID", 1, 10), x.I("mat_ID", 11, 20), x.I("subset_ID", 21, 30), x.R("Thick", 31, 50)}};
  add_prop_shell(d, "/PROP/SHELL/201", 201);
  add_prop_shell(d, "/PROP/TYPE1/202", 202);
  add_prop_solid(d, "/PROP/SOLID/203", 203);
  add_prop_solid(d, "/PROP/TYPE14/204", 204);
  add_law1(d, "/MAT/LAW1/301/7", 301, 7);
  add_law1(d, "/MAT/ELAST/302", 302, 0);
  add_law1(d, "/MAT/LAW01/303", 303, 0);
  add_law2(d, "/MAT/LAW2/304", 304, 0);
  add_law2(d, "/MAT/PLAS_JOHNS/305", 305, 1);
  add_law2(d, "/MAT/LAW02/306", 306, 0);
  {
    Kw& k = d.titled("/GRNOD/NODE/401", "/GRNOD/NODE", 401, "twelve nodes on two lines");
    k.id_lines.resize(2);
    for (int n = 0; n < 10; ++n) k.id_lines[0].push_back(x.next());
    k.id_lines[1] = {x.next(), x.next()};
  }
  d.titled("/GRNOD/PART/402", "/GRNOD/PART", 402, "a part, minus another").id_lines = {{101, -103}};
  d.titled("/GRNOD/GRNOD/403", "/GRNOD/GRNOD", 403, "union minus").id_lines = {{401, -402}};
  d.titled("/BOX/RECTA/501", "/BOX/RECTA", 501, "a box").cards = {
      {x.I("N1", 1, 10), x.I("N2", 11, 20), x.I("Iskew", 21, 30)},
      {x.R("Xp1", 1, 20), x.R("Yp1", 21, 40), x.R("Zp1", 41, 60)},
      {x.R("Xp2", 1, 20), x.R("Yp2", 21, 40), x.R("Zp2", 41, 60)}};
  d.titled("/GRNOD/BOX/404", "/GRNOD/BOX", 404, "nodes in the box").id_lines = {{501}};
  d.titled("/GRNOD/GENE/405", "/GRNOD/GENE", 405, "two ranges").id_lines = {{1, 4, 9, 12}};
  d.titled("/SUBSET/601", "/SUBSET", 601, "parent subset").id_lines = {{602}};
  d.titled("/SUBSET/602", "/SUBSET", 602, "child subset, empty list");
  d.titled("/SURF/PART/701", "/SURF/PART", 701, "shell surface").id_lines = {{101}};
  d.titled("/SURF/PART/EXT/702", "/SURF/PART/EXT", 702, "outer faces").id_lines = {{103, 101}};
  d.titled("/SURF/SEG/703", "/SURF/SEG", 703, "two segments").records = {
      {x.I("seg_ID", 1, 10), x.I("n1", 11, 20), x.I("n2", 21, 30), x.I("n3", 31, 40), x.I("n4", 41, 50)},
      {x.I("seg_ID", 1, 10), x.I("n1", 11, 20), x.I("n2", 21, 30), x.I("n3", 31, 40), x.I("n4", 41, 50)}};
  // Element groups and what is built from them: id lists; an element group may name a unit system.
  d.titled("/GRSHEL/PART/421", "/GRSHEL/PART", 421, "shells of a part, minus another").id_lines = {
      {101, -103}};
  d.titled("/GRBRIC/BOX2/422/7", "/GRBRIC/BOX2", 422, "bricks touching the box", 7).id_lines = {{501}};
  d.titled("/GRNOD/GRSHEL/406", "/GRNOD/GRSHEL", 406, "nodes of a shell group").id_lines = {{421}};
  d.titled("/SURF/PART/ALL/704", "/SURF/PART/ALL", 704, "every brick face").id_lines = {{103}};
  d.titled("/SURF/GRBRIC/EXT/705", "/SURF/GRBRIC/EXT", 705, "outer faces of a brick group").id_lines = {
      {422}};
  d.titled("/SURF/GRSH3N/706", "/SURF/GRSH3N", 706, "3-node shells, flipped").id_lines = {{-423}};
  add_type7(d, 801);
  add_lagdt(d, 802);
  {
    Kw& k = d.titled("/CTCLAW/811", "/CTCLAW", 811, "a contact law");
    k.cards = {{x.I("inter_ID", 1, 10)}};
    k.text_lines = {"n2s13{pz1e5,", "   lambda2e3, Mu0.3}"};
    k.text = "n2s13{pz1e5,lambda2e3,Mu0.3}";
  }
  d.titled("/BCS/901", "/BCS", 901, "fixed").cards = {
      {Ix("Tx", 4, 4, 1), Ix("Ty", 5, 5, 0), Ix("Tz", 6, 6, 1), Ix("Rx", 8, 8, 1), Ix("Ry", 9, 9, 1),
       Ix("Rz", 10, 10, 0), x.I("skew_ID", 11, 20), x.I("grnod_ID", 21, 30)}};
  d.titled("/IMPVEL/902", "/IMPVEL", 902, "imposed velocity").cards = {
      {x.I("funct_IDT", 1, 10), Sx("Dir", 11, 20, "Y"), x.I("skew_ID", 21, 30), x.I("sensor_ID", 31, 40),
       x.I("grnod_ID", 41, 50), x.I("frame_ID", 51, 60), Ix("Icoor", 61, 70, 1).ver(120)},
      {x.R("Ascale_x", 1, 20), x.R("Fscale_y", 21, 40), x.R("Tstart", 41, 60), x.R("Tstop", 61, 80)}};
  d.titled("/IMPDISP/912", "/IMPDISP", 912, "imposed displacement").cards = {
      {x.I("funct_IDT", 1, 10), Sx("Dir", 11, 20, "Z"), x.I("skew_ID", 21, 30), x.I("sensor_ID", 31, 40),
       x.I("grnod_ID", 41, 50), x.I("frame_ID", 51, 60).ver(110), Ix("Icoor", 61, 70, 1).ver(120)},
      {x.R("Ascale_x", 1, 20), x.R("Fscale_y", 21, 40), x.R("Tstart", 41, 60), x.R("Tstop", 61, 80)}};
  {
    Kw& k = d.titled("/INIVEL/TRA/903", "/INIVEL/TRA", 903, "initial velocity");
    k.cards = {{x.R("Vx", 1, 20), x.R("Vy", 21, 40), x.R("Vz", 41, 60), x.I("grnod_ID", 61, 70),
                x.I("skew_ID", 71, 80)}};
    if (v >= 2025)
      k.cards.push_back({x.R("Tstart", 1, 20), x.I("sensor_ID", 21, 30)});
    else
      k.absent = {"Tstart", "sensor_ID"};
  }
  d.titled("/CLOAD/904", "/CLOAD", 904, "concentrated load").cards = {
      {x.I("funct_IDT", 1, 10), Sx("Dir", 11, 20, "ZZ"), x.I("skew_ID", 21, 30), x.I("sensor_ID", 31, 40),
       x.I("grnod_ID", 41, 50), Ix("Itypfun", 51, 60, 3).ver(2023), x.R("Ascale_x", 61, 80),
       x.R("Fscale_y", 81, 100)}};
  d.titled("/PLOAD/905", "/PLOAD", 905, "pressure").cards = {
      {x.I("surf_ID", 1, 10), x.I("funct_IDT", 11, 20), x.I("sensor_ID", 21, 30),
       x.I("Ipinch", 31, 40).ver(2020), Ix("Idel", 41, 50, 2).ver(2021), Ix("Itypfun", 51, 60, 3).ver(2023),
       x.R("Ascale_x", 61, 80), x.R("Fscale_y", 81, 100)}};
  d.titled("/GRAV/906", "/GRAV", 906, "gravity").cards = {
      {x.I("funct_IDT", 1, 10), Sx("Dir", 11, 20, "X"), x.I("skew_ID", 21, 30), x.I("sensor_ID", 31, 40),
       x.I("grnod_ID", 41, 50), x.R("Ascale_x", 61, 80), x.R("Fscale_y", 81, 100)}};
  d.titled("/FUNCT/907", "/FUNCT", 907, "three points").records = {{x.R("X", 1, 20), x.R("Y", 21, 40)},
                                                                   {x.R("X", 1, 20), x.R("Y", 21, 40)},
                                                                   {x.R("X", 1, 20), x.R("Y", 21, 40)}};
  // /MOVE_FUNCT (one layout) and the node transformations: sub_ID at 91-100 of TRA and ROT from the 100
  // layout, of SCA and SYM from 2026; the 2026 TRA has a second card with skew_ID.
  d.titled("/MOVE_FUNCT/907", "/MOVE_FUNCT", 907, "moved").cards = {
      {x.R("Ascalex", 1, 20), x.R("Fscaley", 21, 40), x.R("Ashiftx", 41, 60), x.R("Fshifty", 61, 80)}};
  {
    Kw& k = d.titled("/TRANSFORM/TRA/921/7", "/TRANSFORM/TRA", 921, "translation", 7);
    k.cards = {{x.I("grnod_ID", 1, 10), x.R("X_translation", 11, 30), x.R("Y_translation", 31, 50),
                x.R("Z_translation", 51, 70), x.I("node_ID1", 71, 80), x.I("node_ID2", 81, 90),
                x.I("sub_ID", 91, 100).ver(100)}};
    if (v >= 2026)
      k.cards.push_back({x.I("skew_ID", 1, 10)});
    else
      k.absent = {"skew_ID"};
  }
  d.titled("/TRANSFORM/ROT/922", "/TRANSFORM/ROT", 922, "rotation").cards = {
      {x.I("grnod_ID", 1, 10), x.R("X_point_1", 11, 30), x.R("Y_point_1", 31, 50), x.R("Z_point_1", 51, 70),
       x.I("node_ID1", 71, 80), x.I("node_ID2", 81, 90), x.I("sub_ID", 91, 100).ver(100)},
      {x.R("X_point_2", 11, 30), x.R("Y_point_2", 31, 50), x.R("Z_point_2", 51, 70), x.R("Angle", 71, 90)}};
  d.titled("/TRANSFORM/SCA/923", "/TRANSFORM/SCA", 923, "scaling").cards = {
      {x.I("grnod_ID", 1, 10), x.R("Fscale_X", 11, 30), x.R("Fscale_Y", 31, 50), x.R("Fscale_Z", 51, 70),
       x.I("node_IDc", 71, 80), x.I("sub_ID", 91, 100).ver(2026)}};
  d.titled("/TRANSFORM/SYM/924", "/TRANSFORM/SYM", 924, "mirror").cards = {
      {x.I("grnod_ID", 1, 10), x.R("X_point_1", 11, 30), x.R("Y_point_1", 31, 50), x.R("Z_point_1", 51, 70),
       x.I("node_ID1", 71, 80), x.I("node_ID2", 81, 90), x.I("sub_ID", 91, 100).ver(2026)},
      {x.R("X_point_2", 11, 30), x.R("Y_point_2", 31, 50), x.R("Z_point_2", 51, 70)}};
  {
    Kw& k = d.titled("/RWALL/PLANE/908", "/RWALL/PLANE", 908, "moving wall with friction");
    k.cards = {{x.I("node_ID", 1, 10), Ix("Slide", 11, 20, 2), x.I("grnd_ID1", 21, 30),
                x.I("grnd_ID2", 31, 40), Ix("Iform", 41, 50, 1).ver(2026)},
               {x.R("d", 1, 20), x.R("fric", 21, 40), x.R("Diameter", 41, 60), x.R("ffac", 61, 80),
                Ix("ifq", 81, 90, 3)},
               {x.R("Mass", 1, 20), x.R("VX0", 21, 40), x.R("VY0", 41, 60), x.R("VZ0", 61, 80)},
               {x.R("XM1", 1, 20), x.R("YM1", 21, 40), x.R("ZM1", 41, 60)}};
    k.absent = {"XM", "YM", "ZM"};
  }
  {
    Kw& k = d.titled("/RWALL/PLANE/909", "/RWALL/PLANE", 909, "fixed wall, tied");
    k.cards = {{Blank("node_ID", 1, 10, Ty::Int), Ix("Slide", 11, 20, 1), x.I("grnd_ID1", 21, 30),
                x.I("grnd_ID2", 31, 40), Ix("Iform", 41, 50, 1).ver(2026)},
               {x.R("d", 1, 20)},
               {x.R("XM", 1, 20), x.R("YM", 21, 40), x.R("ZM", 41, 60)},
               {x.R("XM1", 1, 20), x.R("YM1", 21, 40), x.R("ZM1", 41, 60)}};
    k.absent = {"fric", "ifq", "Mass", "VX0"};
  }
  {
    Kw& k = d.titled("/RBODY/910", "/RBODY", 910, "rigid body");
    k.cards = {{x.I("node_ID", 1, 10), x.I("sens_ID", 11, 20), x.I("skew_ID", 21, 30),
                Ix("Ispher", 31, 40, 1), x.R("Mass", 41, 60), x.I("grnd_ID", 61, 70), x.I("Ikrem", 71, 80),
                Ix("ICoG", 81, 90, 3), x.I("surf_ID", 91, 100)},
               {x.R("Jxx", 1, 20), x.R("Jyy", 21, 40), x.R("Jzz", 41, 60)},
               {x.R("Jxy", 1, 20), x.R("Jyz", 21, 40), x.R("Jxz", 41, 60)}};
    // Card 4 from 110 (Iexpams from 2017, Ifail from 2021).
    if (v >= 110)
      k.cards.push_back(
          {Ix("Ioptoff", 1, 10, 1), x.I("Iexpams", 11, 20).ver(2017), x.I("Ifail", 21, 30).ver(2021)});
    if (v >= 2021)
      k.cards.push_back({x.R("FN", 1, 20), x.R("FT", 21, 40), x.R("expN", 41, 60), x.R("expT", 61, 80)});
    else
      k.absent = {"FN", "expT", "Ifail"};
    if (v < 110) k.absent.push_back("Ioptoff");
  }
  auto th_record = [&x](const std::string& name) {
    return CardSpec{x.I("id", 1, 10), x.I("skew_ID", 11, 20), Sl("name", 21, 100, name)};
  };
  // /TH/SHEL element lines: no skew_ID before 140.
  auto th_shel_record = [&x, v, &th_record](const std::string& name) {
    return v >= 140 ? th_record(name) : CardSpec{x.I("id", 1, 10), Sl("name", 21, 100, name)};
  };
  {
    Kw& k = d.titled("/TH/NODE/1001", "/TH/NODE", 1001, "nodes");
    k.var_lines = {{"DX", "DY", "DZ"}, {"VX", "DEF"}};
    k.th_vars = {"DX", "DY", "DZ", "VX", "DEF"};
    k.records = {th_record("first node"), th_record("second node")};
  }
  {
    Kw& k = d.titled("/TH/PART/1002", "/TH/PART", 1002, "parts");
    k.var_lines = {{"DEF"}};
    k.th_vars = {"DEF"};
    k.id_lines = {{101, 102}};
  }
  {
    Kw& k = d.titled("/TH/INTER/1003", "/TH/INTER", 1003, "interfaces");
    k.var_lines = {{"FNX", "FNY", "FNZ"}};
    k.th_vars = {"FNX", "FNY", "FNZ"};
    k.id_lines = {{801, 802}};
  }
  {
    Kw& k = d.titled("/TH/RWALL/1004", "/TH/RWALL", 1004, "walls");
    k.var_lines = {{"FNX", "FTX"}};
    k.th_vars = {"FNX", "FTX"};
    k.id_lines = {{908, 909}};
  }
  {
    Kw& k = d.titled("/TH/SHEL/1005", "/TH/SHEL", 1005, "shells");
    k.var_lines = {{"F1", "F2", "M12"}};
    k.th_vars = {"F1", "F2", "M12"};
    k.records = {th_shel_record("shell a")};
  }
  {
    Kw& k = d.titled("/TH/SHELL/1006", "/TH/SHEL", 1006, "shells, long spelling");
    k.var_lines = {{"DEF"}};
    k.th_vars = {"DEF"};
    k.records = {th_shel_record("shell b")};
  }
  {
    Kw& k = d.titled("/TH/SUBS/1007", "/TH/SUBS", 1007, "subsets");
    k.var_lines = {{"IE", "KE"}};
    k.th_vars = {"IE", "KE"};
    k.id_lines = {{601}};
  }
  {
    Kw& k = d.titled("/TH/BRIC/1008", "/TH/BRIC", 1008, "bricks");
    k.var_lines = {{"DEF", "VOL"}};
    k.th_vars = {"DEF", "VOL"};
    k.records = {CardSpec{x.I("id", 1, 10), Sl("name", 21, 100, "brick a")}};
  }
  {
    Kw& k = d.titled("/TH/BRICK/1009", "/TH/BRIC", 1009, "bricks, long spelling");
    k.var_lines = {{"STRESS"}};
    k.th_vars = {"STRESS"};
    k.records = {CardSpec{x.I("id", 1, 10), Sl("name", 21, 100, "brick b")}};
  }
  {
    Kw& k = d.titled("/TH/SH3N/1010", "/TH/SH3N", 1010, "triangles");
    k.var_lines = {{"F1", "IEM"}};
    k.th_vars = {"F1", "IEM"};
    k.records = {th_record("triangle a"), th_record("triangle b")};
  }
  {
    Kw& k = d.titled("/TH/RBODY/1011", "/TH/RBODY", 1011, "rigid bodies");
    k.var_lines = {{"DEF", "MASS"}};
    k.th_vars = {"DEF", "MASS"};
    k.id_lines = {{701, 702}};
  }
  d.add("/DEF_SHELL", "/DEF_SHELL").cards = {
      {x.I("Ishell", 1, 10), x.I("Ismstr", 11, 20), x.I("Ithick", 21, 30), x.I("Iplas", 31, 40),
       x.I("Istrain", 41, 50), x.I("Ioffset", 51, 60).ver(2024), x.I("Ish3n", 71, 80),
       x.I("Idrill", 81, 90).ver(110), x.I("Ithin_drape", 91, 100).ver(2026)}};
  d.add("/DEF_SOLID", "/DEF_SOLID").cards = {
      {x.I("Isolid", 1, 10), x.I("Ismstr", 11, 20), x.I("Icpre", 21, 30).ver(2021),
       x.I("Istrain", 31, 40).ver(100, 2020), x.I("Itetra4", 41, 50).ver(2019),
       x.I("Itetra10", 51, 60).ver(2019), x.I("Imas", 61, 70).ver(120), x.I("Iframe", 71, 80),
       x.I("Icontrol", 81, 90).ver(2025)}};
  d.add("/ANALY", "/ANALY").cards = {{Ix("N2D3D", 1, 10, 1), x.I("ITEMP", 11, 20).ver(2026),
                                      Ix("IPARITH", 21, 30, 2), x.I("ISUBCYC", 31, 40).ver(0, 2022)}};
  d.add("/IOFLAG", "/IOFLAG").cards = {{x.I("IPRI", 1, 10), x.I("IGTYP", 21, 30).ver(0, 140),
                                        x.I("IOUTP", 31, 40), x.I("IOUTYY", 41, 50).ver(100),
                                        x.I("IROOTYY", 51, 60).ver(100), x.I("Irot", 61, 70).ver(100)}};
  d.add("/RANDOM", "/RANDOM").cards = {{x.R("XALEA", 1, 20), x.R("SEED", 21, 40)}};
  d.add("/RANDOM/0", "/RANDOM").cards = {{x.R("XALEA", 1, 20), x.R("SEED", 21, 40)}};
  d.add("/MEMORY", "/MEMORY").cards = {{x.I("MEMORY", 1, 10), Rx("REAL", 21, 40, ".66", 0.66)}};
  d.add("/RANDOM/GRNOD/401", "/RANDOM/GRNOD", 401).cards = {{x.R("XALEA", 1, 20), x.R("SEED", 21, 40)}};
  d.add("/SPMD", "/SPMD").cards = {
      {x.I("Domdec", 1, 10), x.I("Nspmd", 11, 20), x.I("Dkword", 31, 40), x.I("Nthread", 51, 60).ver(110)}};
  d.add("/SHFRA/V4", "/SHFRA/V4");
  return d;
}

// --- checks

bool in_version_elsewhere(const Kw& k, const std::string& name, int v) {
  for (const auto& c : k.cards)
    for (const auto& f : c)
      if (f.name == name && f.in(v)) return true;
  return false;
}

void check_value(const radx::KeywordRecord& rec, const Fld& f) {
  switch (f.ty) {
    case Ty::Int: CHECK(rec.get_int(f.name) == f.i); break;
    case Ty::Real: CHECK(rec.get_real(f.name) == Approx(f.r).epsilon(kEps)); break;
    case Ty::Str: CHECK(rec.get_string(f.name) == f.s); break;
  }
}

void check_keyword(const radx::KeywordRecord& rec, const Kw& k, int v) {
  INFO("keyword " << k.header << " (deck line " << k.line << ")");
  REQUIRE(rec.decl != nullptr);
  CHECK(rec.keyword() == k.path);
  CHECK(rec.written == k.header);
  CHECK(rec.pos.line == k.line);
  CHECK(rec.id == k.id);
  CHECK(rec.unit_id == k.unit);
  CHECK(rec.title == (k.has_title ? k.title : std::string()));
  CHECK(rec.header_word == k.word);
  // Fixed cards, field by field.
  std::size_t expected_fields = 0;
  for (std::size_t c = 0; c < k.cards.size(); ++c) {
    for (const auto& f : k.cards[c]) {
      INFO("field " << f.name << " (columns " << f.a << "-" << f.b << ")");
      if (!f.in(v)) {
        if (!in_version_elsewhere(k, f.name, v)) CHECK(rec.find(f.name) == nullptr);
        continue;
      }
      ++expected_fields;
      const radx::FieldValue* fv = rec.find(f.name);
      REQUIRE(fv != nullptr);
      CHECK(fv->pos.file == 0u);
      CHECK(fv->pos.line == k.card_lines[c]);
      CHECK(fv->column == f.a);
      CHECK(fv->blank == f.text.empty());
      CHECK_FALSE(fv->defaulted);
      CHECK(rec.given(f.name) == !f.text.empty());
      check_value(rec, f);
    }
  }
  CHECK(rec.fields.size() == expected_fields);
  for (const auto& name : k.absent) {
    INFO("field " << name << " must be absent");
    CHECK(rec.find(name) == nullptr);
  }
  // Record tail.
  const auto& t = rec.records;
  REQUIRE(t.size() == k.records.size());
  for (std::size_t row = 0; row < k.records.size(); ++row) {
    INFO("record " << row << " (deck line " << k.record_lines[row] << ")");
    CHECK(t.pos[row].line == k.record_lines[row]);
    CHECK(t.fields.size() == k.records[row].size());
    for (const auto& f : k.records[row]) {
      INFO("record field " << f.name);
      const int col = t.column(f.name);
      REQUIRE(col >= 0);
      const auto c = static_cast<std::size_t>(col);
      switch (f.ty) {
        case Ty::Int:
          REQUIRE(t.ints[c].size() == t.size());
          CHECK(t.ints[c][row] == f.i);
          break;
        case Ty::Real:
          REQUIRE(t.reals[c].size() == t.size());
          CHECK(t.reals[c][row] == Approx(f.r).epsilon(kEps));
          break;
        case Ty::Str:
          REQUIRE(t.strings[c].size() == t.size());
          CHECK(t.strings[c][row] == f.s);
          break;
      }
    }
  }
  if (k.records.empty()) CHECK(t.size() == 0u);
  // Id-list tail.
  std::vector<std::int64_t> ids;
  std::vector<std::uint32_t> id_lines;
  for (std::size_t l = 0; l < k.id_lines.size(); ++l)
    for (auto id : k.id_lines[l]) {
      ids.push_back(id);
      id_lines.push_back(k.id_line_numbers[l]);
    }
  CHECK(rec.ids == ids);
  REQUIRE(rec.id_pos.size() == rec.ids.size());
  if (rec.ids == ids)
    for (std::size_t n = 0; n < ids.size(); ++n) CHECK(rec.id_pos[n].line == id_lines[n]);
  CHECK(rec.th_variables == k.th_vars);
  CHECK(rec.text == k.text);
}

// The full decks give every field a distinct non-zero value, also the fields radx reads but does not
// implement; those that change the physics are errors unless substitutions are allowed, and what these tests
// check is the reading, so they allow them.
radx::ReadOptions every_field_options() {
  radx::ReadOptions opt;
  opt.allow_substitutions = true;
  return opt;
}

void check_full_deck(int version) {
  INFO("deck version " << version);
  TempDir dir;
  DeckSpec spec = full_deck(version);
  const std::string path = dir.write("KEYWORDS_" + std::to_string(version) + "_0000.rad", write_deck(spec));
  Diagnostics diags;
  const radx::Deck deck = radx::read_starter_deck(path, diags, every_field_options());
  INFO(all_diags(diags, true));
  CHECK_FALSE(diags.has_errors());
  CHECK(deck.version == version);
  CHECK(deck.run_name == "KEYWORDS_" + std::to_string(version));
  CHECK(deck.input_units.mass == 1000.0);
  CHECK(deck.input_units.length == 0.001);
  CHECK(deck.input_units.time == 1.0);
  CHECK(deck.work_units.mass_name == "Mg");
  CHECK(deck.work_units.length_name == "mm");
  CHECK(deck.work_units.time_name == "s");
  REQUIRE(deck.records.size() == spec.kws.size());
  for (std::size_t n = 0; n < spec.kws.size(); ++n) check_keyword(deck.records[n], spec.kws[n], version);
  CHECK(deck.of("/PROP/SHELL").size() == 2u);
  CHECK(deck.of("/PROP/SOLID").size() == 2u);
  CHECK(deck.of("/MAT/LAW1").size() == 3u);
  CHECK(deck.of("/MAT/LAW2").size() == 3u);
  CHECK(deck.of("/TH/SHEL").size() == 2u);
  CHECK(deck.of("/TH/BRIC").size() == 2u);
}

}  // namespace

// ---------------------------------------------------------------------------------------------------

TEST_CASE("every starter keyword read field by field in the 90 layout (units as /UNIT/MASS ...)",
          "[keywords]") {
  check_full_deck(90);
}

TEST_CASE("every starter keyword read field by field in the 100 and 110 layouts", "[keywords]") {
  check_full_deck(100);
  check_full_deck(110);
}

TEST_CASE("every starter keyword read field by field in the 120, 130 and 140 layouts", "[keywords]") {
  check_full_deck(120);
  check_full_deck(130);
  check_full_deck(140);
}

TEST_CASE("every starter keyword read field by field in the 2017 layout", "[keywords]") {
  check_full_deck(2017);
}

TEST_CASE("every starter keyword read field by field in the 2018 and 2019 layouts", "[keywords]") {
  check_full_deck(2018);
  check_full_deck(2019);
}

TEST_CASE("every starter keyword read field by field in the 2020 to 2025 layouts", "[keywords]") {
  for (int v : {2020, 2021, 2022, 2023, 2024, 2025}) check_full_deck(v);
}

TEST_CASE("every starter keyword read field by field in the 2026 layout", "[keywords]") {
  check_full_deck(2026);
}

TEST_CASE("the full keyword deck reads the same with CRLF line ends", "[keywords]") {
  TempDir dir;
  DeckSpec spec = full_deck(2026);
  const std::string path = dir.write("KEYWORDS_CRLF_0000.rad", write_deck(spec, "\r\n"));
  Diagnostics diags;
  const radx::Deck deck = radx::read_starter_deck(path, diags, every_field_options());
  INFO(all_diags(diags, true));
  CHECK_FALSE(diags.has_errors());
  REQUIRE(deck.records.size() == spec.kws.size());
  for (std::size_t n = 0; n < spec.kws.size(); ++n) check_keyword(deck.records[n], spec.kws[n], 2026);
}

TEST_CASE("a 2026 /BEGIN accepts the trailing IRUN 0 of old decks and has no IRUN field", "[keywords]") {
  TempDir dir;
  const std::string deck_text = "/BEGIN\nRUN\n" + Card().at(1, 10, 2026).at(11, 20, 0).str() + "\n" +
                                Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n" +
                                Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n/END\n";
  const auto path = dir.write("IRUN_0000.rad", deck_text);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK(diags.warning_count() == 0u);
  CHECK(deck.version == 2026);
  REQUIRE(deck.records.size() == 1u);
  CHECK(deck.records[0].find("IRUN") == nullptr);
  CHECK(deck.records[0].get_int("INVERS") == 2026);
}

// ---------------------------------------------------------------------------------------------------
// Old deck formats.

namespace {

std::string begin_lines(int version, bool unit_cards = true) {
  std::string s = "/BEGIN\nOLD\n" + Card().at(1, 10, version).at(11, 20, 0).str() + "\n";
  if (unit_cards)
    s += Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n" +
         Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n";
  return s;
}

bool has_diag(const Diagnostics& diags, Diag code, radx::Severity sev, const std::string& text) {
  for (const auto& d : diags.items())
    if (d.code == code && d.severity == sev && Diagnostics::format(d).find(text) != std::string::npos)
      return true;
  return false;
}

}  // namespace

TEST_CASE("the deck formats 90 to 140 are read, 51, 95 and 2016 are refused by version", "[keywords]") {
  for (int v : {90, 100, 110, 120, 130, 140}) {
    INFO("version " << v);
    TempDir dir;
    const auto path = dir.write("V_0000.rad", begin_lines(v, v >= 100) + "/END\n");
    Diagnostics diags;
    const auto deck = radx::read_starter_deck(path, diags);
    INFO(all_diags(diags));
    CHECK_FALSE(diags.has_errors());
    CHECK(deck.version == v);
  }
  for (int v : {41, 51, 95, 2016}) {
    INFO("version " << v);
    TempDir dir;
    const auto path = dir.write("V_0000.rad", begin_lines(v) + "/END\n");
    Diagnostics diags;
    (void)radx::read_starter_deck(path, diags);
    INFO(all_diags(diags));
    CHECK(has_diag(diags, Diag::UnsupportedVersion, radx::Severity::Error,
                   "deck version " + std::to_string(v) +
                       " is not read by radx: it reads the deck formats 90, "
                       "100, 110, 120, 130, 140, 2017 to 2026"));
  }
}

TEST_CASE("a keyword whose old layout is not established is refused by name in old decks", "[keywords]") {
  const std::string body =
      "/GRNOD/GEN_INCR/3\nranges\n" + Card().at(1, 10, 1).at(11, 20, 9).at(21, 30, 2).str() + "\n/END\n";
  {
    TempDir dir;
    const auto path = dir.write("GEN_0000.rad", begin_lines(130) + body);
    Diagnostics diags;
    const auto deck = radx::read_starter_deck(path, diags);
    INFO(all_diags(diags));
    CHECK(diags.error_count() == 1u);
    CHECK(has_diag(
        diags, Diag::UnsupportedVersion, radx::Severity::Error,
        "[/GRNOD/GEN_INCR] /GRNOD/GEN_INCR is not read by radx in a deck of version 130: its layout in "
        "that format is not established; radx reads it in decks of version 2017 and newer"));
    CHECK(deck.of("/GRNOD/GEN_INCR").empty());
  }
  {
    TempDir dir;
    const auto path = dir.write("GEN_0000.rad", begin_lines(2017) + body);
    Diagnostics diags;
    const auto deck = radx::read_starter_deck(path, diags);
    INFO(all_diags(diags));
    CHECK_FALSE(diags.has_errors());
    REQUIRE(deck.of("/GRNOD/GEN_INCR").size() == 1u);
  }
}

TEST_CASE("/MAT/LAW2 up to 130 reads RHO_ref only when columns 11-20 hold text, from 140 always",
          "[keywords]") {
  // RHO_I left-justified (columns 1-6): 11-20 blank.
  const std::string mat = "/MAT/LAW2/1\nsteel\n" + Card().left(1, "7.8E-9").at(21, 40, "7.5E-9").str() +
                          "\n" + Card().at(1, 20, "210000.").at(21, 40, "0.3").str() + "\n" +
                          Card().at(1, 20, "250.").str() + "\n\n\n";
  // RHO_I right-justified in 1-20: 11-20 hold text.
  const std::string mat2 = "/MAT/LAW2/2\nsteel 2\n" + Card().at(1, 20, "7.8E-9").at(21, 40, "7.5E-9").str() +
                           "\n" + Card().at(1, 20, "210000.").at(21, 40, "0.3").str() + "\n" +
                           Card().at(1, 20, "250.").str() + "\n\n\n";
  for (int v : {100, 130, 140}) {
    INFO("version " << v);
    TempDir dir;
    const auto path = dir.write("RHO_0000.rad", begin_lines(v) + mat + mat2 + "/END\n");
    Diagnostics diags;
    const auto deck = radx::read_starter_deck(path, diags);
    INFO(all_diags(diags));
    CHECK_FALSE(diags.has_errors());
    const auto mats = deck.of("/MAT/LAW2");
    REQUIRE(mats.size() == 2u);
    CHECK(mats[0]->get_real("RHO_I") == Approx(7.8e-9).epsilon(kEps));
    CHECK(mats[1]->get_real("RHO_ref") == Approx(7.5e-9).epsilon(kEps));
    if (v < 140) {
      CHECK(mats[0]->get_real("RHO_ref") == 0.0);
      CHECK(mats[0]->find("RHO_ref")->blank);
      CHECK(has_diag(diags, Diag::ExtraData, radx::Severity::Warning,
                     "field RHO_ref ('7.5E-9') is not read in a version-" + std::to_string(v) +
                         " deck because columns 11-20 are blank"));
      CHECK(mats[0]->find("Iflag") == nullptr);  // no Iflag before 140: card 3 is a, b, n
    } else {
      CHECK(mats[0]->get_real("RHO_ref") == Approx(7.5e-9).epsilon(kEps));
      CHECK(diags.warning_count() == 0u);
    }
    CHECK(mats[0]->get_real("a") == Approx(250.0).epsilon(kEps));
  }
}

TEST_CASE("version 90: /UNIT/MASS, /LENGTH, /TIME name the work units, which are also the input units",
          "[keywords]") {
  std::string s = begin_lines(90, false) + "/UNIT/MASS/Mg\n/UNIT/LENGTH/mm\n/UNIT/TIME/ms\n";
  // A local unit system in kg m s: converted into the work units Mg mm ms.
  s += "/UNIT/2\nSI\n" + Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n";
  s += "/NODE\n" + Card().at(1, 10, 1).at(11, 30, "1.5").str() + "\n";
  s += "/MAT/LAW1/5/2\nSI steel\n" + Card().at(1, 20, "7800.").str() + "\n" +
       Card().at(1, 20, "2.1E11").at(21, 40, "0.3").str() + "\n/END\n";
  TempDir dir;
  const auto path = dir.write("U90_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK(deck.version == 90);
  CHECK(deck.work_units.mass == 1e3);
  CHECK(deck.work_units.length == 1e-3);
  CHECK(deck.work_units.time == 1e-3);
  CHECK(deck.work_units.time_name == "ms");
  CHECK(deck.input_units.mass == 1e3);
  CHECK(deck.input_units.length == 1e-3);
  CHECK(deck.input_units.time == 1e-3);
  const auto& n = deck.of("/NODE").at(0)->records;
  CHECK(n.reals[static_cast<std::size_t>(n.column("X"))][0] == 1.5);  // input = work: not converted
  const auto& m = *deck.of("/MAT/LAW1").at(0);
  CHECK(m.get_real("RHO_I") == Approx(7800.0 * 1e-3 / 1e9).epsilon(kEps));    // kg/m3 -> Mg/mm3
  CHECK(m.get_real("E") == Approx(2.1e11 * 1e-3 / 1e3 / 1e6).epsilon(kEps));  // Pa -> Mg/(mm ms^2)
}

TEST_CASE("/UNIT/LENGTH and the like are ignored with a warning in decks newer than 90", "[keywords]") {
  TempDir dir;
  const auto path = dir.write("U100_0000.rad", begin_lines(100) + "/UNIT/LENGTH/mm\n/END\n");
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK(has_diag(diags, Diag::IgnoredControlCard, radx::Severity::Warning,
                 "/UNIT/LENGTH is ignored in a deck of version 100"));
  CHECK(deck.work_units.length == 1.0);
  CHECK(deck.input_units.length == 1.0);
}

// ---------------------------------------------------------------------------------------------------
// Units.

TEST_CASE("input units g mm ms and a /UNIT on a /MAT are converted to work units kg m s", "[keywords]") {
  // Factors computed by hand, SI value of one input unit over one work unit.
  const double m = 1e-3;  // g -> kg
  const double l = 1e-3;  // mm -> m
  const double t = 1e-3;  // ms -> s
  const double density = m / (l * l * l);
  const double pressure = m / (l * t * t);
  const double stiffness = m / (t * t);
  // /UNIT/2 = Mg mm s.
  const double density2 = 1e3 / (1e-3 * 1e-3 * 1e-3);
  const double pressure2 = 1e3 / 1e-3;

  std::string s = "/BEGIN\nUNITS\n" + Card().at(1, 10, 2026).str() + "\n" +
                  Card().at(1, 20, "g").at(21, 40, "mm").at(41, 60, "ms").str() + "\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n";
  s += "/UNIT/2\nMg mm s\n" + Card().at(1, 20, "Mg").at(21, 40, "mm").at(41, 60, "s").str() + "\n";
  s += "/NODE\n" + Card().at(1, 10, 1).at(11, 30, "1.5").at(31, 50, "-2.5").at(51, 70, "3.25").str() + "\n";
  s += "/NODE/2\n" + Card().at(1, 10, 2).at(11, 30, "4.5").str() + "\n";
  s += "/MAT/LAW1/5\ninput units\n" + Card().at(1, 20, "7.8E-3").str() + "\n" +
       Card().at(1, 20, "210.").at(21, 40, "0.3").str() + "\n";
  s += "/MAT/LAW1/6/2\nunit 2\n" + Card().at(1, 20, "7.8E-9").str() + "\n" +
       Card().at(1, 20, "210000.").at(21, 40, "0.3").str() + "\n";
  s += "/INTER/TYPE7/7\ncontact\n" + Card().at(1, 10, 1).at(11, 20, 2).at(21, 30, 2).str() + "\n\n" +
       Card().at(1, 20, "150.").str() + "\n" +
       Card().at(41, 60, "0.25").at(61, 80, "0.5").at(81, 100, "12.5").str() + "\n\n\n";
  s += "/INIVEL/TRA/8\nvelocity\n" + Card().at(1, 20, "2.5").at(61, 70, 1).str() + "\n/END\n";
  TempDir dir;
  const auto path = dir.write("UNITS_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK(deck.input_units.mass == Approx(1e-3).epsilon(kEps));
  CHECK(deck.input_units.length == Approx(1e-3).epsilon(kEps));
  CHECK(deck.input_units.time == Approx(1e-3).epsilon(kEps));
  CHECK(deck.work_units.mass == 1.0);
  CHECK(deck.work_units.length == 1.0);
  CHECK(deck.work_units.time == 1.0);

  const auto nodes = deck.of("/NODE");
  REQUIRE(nodes.size() == 2u);
  const auto& n1 = nodes[0]->records;
  CHECK(n1.reals[static_cast<std::size_t>(n1.column("X"))][0] == Approx(1.5 * l).epsilon(kEps));
  CHECK(n1.reals[static_cast<std::size_t>(n1.column("Y"))][0] == Approx(-2.5 * l).epsilon(kEps));
  CHECK(n1.reals[static_cast<std::size_t>(n1.column("Z"))][0] == Approx(3.25 * l).epsilon(kEps));
  CHECK(n1.ints[static_cast<std::size_t>(n1.column("node_ID"))][0] == 1);
  const auto& n2 = nodes[1]->records;
  CHECK(nodes[1]->unit_id == 2);
  CHECK(n2.reals[static_cast<std::size_t>(n2.column("X"))][0] == Approx(4.5 * 1e-3).epsilon(kEps));

  const auto mats = deck.of("/MAT/LAW1");
  REQUIRE(mats.size() == 2u);
  CHECK(mats[0]->get_real("RHO_I") == Approx(7.8e-3 * density).epsilon(kEps));
  CHECK(mats[0]->get_real("RHO_I") == Approx(7800.0).epsilon(kEps));
  CHECK(mats[0]->get_real("E") == Approx(210.0 * pressure).epsilon(kEps));
  CHECK(mats[0]->get_real("nu") == Approx(0.3).epsilon(kEps));  // dimensionless: unchanged
  CHECK(mats[1]->unit_id == 2);
  CHECK(mats[1]->get_real("RHO_I") == Approx(7.8e-9 * density2).epsilon(kEps));
  CHECK(mats[1]->get_real("RHO_I") == Approx(7800.0).epsilon(kEps));
  CHECK(mats[1]->get_real("E") == Approx(210000.0 * pressure2).epsilon(kEps));
  CHECK(mats[1]->get_real("E") == Approx(2.1e11).epsilon(kEps));

  const auto inter = deck.of("/INTER/TYPE7");
  REQUIRE(inter.size() == 1u);
  CHECK(inter[0]->get_real("Stmin") == Approx(150.0 * stiffness).epsilon(kEps));
  CHECK(inter[0]->get_real("Stmax") == 1e30);  // "no limit" is not converted
  CHECK(inter[0]->get_real("Gapmin") == Approx(0.25 * l).epsilon(kEps));
  CHECK(inter[0]->get_real("Tstart") == Approx(0.5 * t).epsilon(kEps));
  CHECK(inter[0]->get_real("Tstop") == Approx(12.5 * t).epsilon(kEps));
  CHECK(inter[0]->get_real("Stfac") == 1.0);  // dimensionless default

  const auto vel = deck.of("/INIVEL/TRA");
  REQUIRE(vel.size() == 1u);
  CHECK(vel[0]->get_real("Vx") == Approx(2.5 * l / t).epsilon(kEps));  // mm/ms = m/s
}

// ---------------------------------------------------------------------------------------------------
// Lexical forms.

TEST_CASE("free-format comma lines are split on commas for cards, records and id lists", "[keywords]") {
  TempDir dir;
  std::string s = "/BEGIN\nFREE\n" + Card().at(1, 10, 2019).at(11, 20, 0).str() + "\nkg,m,s\nkg, m , s\n";
  s += "/NODE\n7, 1.5, -2.5, 3.25\n" + Card().at(1, 10, 8).at(11, 30, "4.5").str() + "\n";
  s += "/PART/5\nfree part\n  3, 4 ,5, 1.25\n";
  s += "/PART/6\nempty values between commas\n3,4,,2.5\n";
  s += "/GRNOD/NODE/9\nfree ids\n7, 8,  9\n";
  s += "/INTER/TYPE7/3\nfree contact\n9,10,2,0,1\n1.5,2.5\n\n0.75,0,0.25,1.0,9.5\n/END\n";
  const auto path = dir.write("FREE_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK(deck.version == 2019);
  CHECK(deck.work_units.length_name == "m");
  REQUIRE_FALSE(deck.records.empty());
  CHECK(deck.records[0].get_int("INVERS") == 2019);
  CHECK(deck.work_units.mass_name == "kg");

  const auto node = deck.of("/NODE");
  REQUIRE(node.size() == 1u);
  const auto& t = node[0]->records;
  REQUIRE(t.size() == 2u);
  CHECK(t.ints[static_cast<std::size_t>(t.column("node_ID"))][0] == 7);
  CHECK(t.reals[static_cast<std::size_t>(t.column("X"))][0] == Approx(1.5).epsilon(kEps));
  CHECK(t.reals[static_cast<std::size_t>(t.column("Y"))][0] == Approx(-2.5).epsilon(kEps));
  CHECK(t.reals[static_cast<std::size_t>(t.column("Z"))][0] == Approx(3.25).epsilon(kEps));
  CHECK(t.ints[static_cast<std::size_t>(t.column("node_ID"))][1] == 8);
  CHECK(t.reals[static_cast<std::size_t>(t.column("X"))][1] == Approx(4.5).epsilon(kEps));

  const auto parts = deck.of("/PART");
  REQUIRE(parts.size() == 2u);
  CHECK(parts[0]->get_int("prop_ID") == 3);
  CHECK(parts[0]->get_int("mat_ID") == 4);
  CHECK(parts[0]->get_int("subset_ID") == 5);
  CHECK(parts[0]->get_real("Thick") == Approx(1.25).epsilon(kEps));
  CHECK(parts[1]->get_int("prop_ID") == 3);
  CHECK(parts[1]->get_int("mat_ID") == 4);
  CHECK(parts[1]->find("subset_ID")->blank);
  CHECK(parts[1]->get_int("subset_ID") == 0);
  CHECK(parts[1]->get_real("Thick") == Approx(2.5).epsilon(kEps));

  const auto g = deck.of("/GRNOD/NODE");
  REQUIRE(g.size() == 1u);
  CHECK(g[0]->ids == std::vector<std::int64_t>{7, 8, 9});

  // Free format takes the fields of the card in column order.
  const auto in = deck.of("/INTER/TYPE7");
  REQUIRE(in.size() == 1u);
  const auto& r = *in[0];
  CHECK(r.get_int("grnd_IDs") == 9);
  CHECK(r.get_int("surf_IDm") == 10);
  CHECK(r.get_int("Istf") == 2);
  CHECK(r.get_int("Ithe") == 0);
  CHECK(r.get_int("Igap") == 1);
  CHECK(r.get_real("Fscalegap") == Approx(1.5).epsilon(kEps));
  CHECK(r.get_real("Gapmax") == Approx(2.5).epsilon(kEps));
  CHECK(r.get_real("Stfac") == Approx(0.75).epsilon(kEps));
  CHECK(r.get_real("Fric") == 0.0);
  CHECK(r.get_real("Gapmin") == Approx(0.25).epsilon(kEps));
  CHECK(r.get_real("Tstart") == Approx(1.0).epsilon(kEps));
  CHECK(r.get_real("Tstop") == Approx(9.5).epsilon(kEps));
}

TEST_CASE("a free-format /BEGIN version line (2019,0) selects the 2019 layouts", "[keywords]") {
  TempDir dir;
  const std::string s = "/BEGIN\nFREE VERSION\n2019,0\nkg,m,s\nkg,m,s\n/PROP/SHELL/1\nshell\n" +
                        Card().at(1, 10, 1).at(61, 80, "0.5").str() + "\n\n" +
                        Card().at(1, 10, 5).at(11, 20, 1).at(21, 40, "1.5").str() + "\n/END\n";
  const auto path = dir.write("FREEVERSION_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK_FALSE(diags.contains(Diag::ExtraData));  // "0" is the 2019 IRUN, not an extra value
  CHECK(deck.version == 2019);
  REQUIRE(deck.records.size() == 2u);
  CHECK(deck.records[0].get_int("INVERS") == 2019);
  REQUIRE(deck.records[0].find("IRUN") != nullptr);  // the 2019 /BEGIN has IRUN
  CHECK(deck.records[0].get_int("IRUN") == 0);
  const auto& shell = deck.records[1];
  CHECK(shell.find("Ipinch") == nullptr);  // 2020+
  CHECK(shell.get_real("P_Thick_Fail") == Approx(0.5).epsilon(kEps));
  REQUIRE(shell.find("Istrain") != nullptr);  // 2017-2023
  CHECK(shell.get_int("Istrain") == 1);
  CHECK(shell.find("Ipos") == nullptr);  // 2024+
}

TEST_CASE("a /TITLE and a RUNNAME holding commas are kept whole (one 100-column string, not free format)",
          "[keywords]") {
  TempDir dir;
  const std::string s = "/BEGIN\nRun, with a comma\n" + Card().at(1, 10, 2026).str() + "\n" +
                        Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n" +
                        Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() +
                        "\n/TITLE\nPlate, block and wall: a title with commas\n/END\n";
  const auto path = dir.write("COMMA_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK(diags.warning_count() == 0u);
  CHECK(deck.run_name == "Run, with a comma");
  REQUIRE(deck.of("/TITLE").size() == 1u);
  CHECK(deck.of("/TITLE")[0]->get_string("TITLE") == "Plate, block and wall: a title with commas");
}

TEST_CASE("blank fields and missing cards take the declared defaults, flagged defaulted", "[keywords]") {
  TempDir dir;
  std::string s = "/BEGIN\nDEFAULTS\n" + Card().at(1, 10, 2026).str() + "\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n";
  // Blank cards written as empty lines.
  s += "/PROP/SHELL/1\nblank cards\n\n\n" + Card().at(21, 40, "0.5").str() + "\n";
  // Only card 1 given: the block ends early.
  s += "/PROP/SOLID/2\ntruncated\n" + Card().at(1, 10, 14).str() + "\n";
  s += "/MAT/LAW2/3\nJC defaults\n" + Card().at(1, 20, "7800.").str() + "\n" +
       Card().at(1, 20, "2.1E11").at(21, 40, "0.3").str() + "\n" + Card().at(1, 20, "2.5E8").str() + "\n\n\n";
  // Stfac written as 0: not blank, but 0 takes the default.
  s += "/INTER/TYPE7/4\ncontact defaults\n" + Card().at(1, 10, 1).at(11, 20, 2).str() + "\n\n\n" +
       Card().at(1, 20, "0").str() + "\n\n\n";
  s += "/INTER/LAGDT/TYPE7/5\nlagdt defaults\n" + Card().at(1, 10, 1).at(11, 20, 2).str() + "\n";
  s += "/CLOAD/6\nload\n" + Card().at(1, 10, 1).at(11, 20, "X").at(41, 50, 1).str() + "\n";
  s += "/PLOAD/7\npressure\n" + Card().at(1, 10, 2).at(11, 20, 1).str() + "\n";
  s += "/IMPVEL/8\nvelocity\n" + Card().at(1, 10, 1).at(11, 20, "Z").at(41, 50, 1).str() + "\n\n";
  s += "/GRAV/9\ngravity\n" + Card().at(11, 20, "Z").str() + "\n";
  s += "/RBODY/10\nbody\n" + Card().at(1, 10, 1).at(61, 70, 1).str() + "\n";
  s += "/ANALY\n\n/DEF_SHELL\n\n/END\n";
  const auto path = dir.write("DEFAULTS_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());

  auto expect_default = [](const radx::KeywordRecord& r, const std::string& name, double value, bool blank) {
    INFO(r.written << " field " << name);
    const auto* f = r.find(name);
    REQUIRE(f != nullptr);
    CHECK(f->defaulted);
    CHECK(f->blank == blank);
    CHECK(r.get_real(name) == Approx(value).epsilon(kEps));
  };
  auto expect_plain_zero = [](const radx::KeywordRecord& r, const std::string& name) {
    INFO(r.written << " field " << name);
    const auto* f = r.find(name);
    REQUIRE(f != nullptr);
    CHECK(f->blank);
    CHECK_FALSE(f->defaulted);
    CHECK(r.get_real(name) == 0.0);
    CHECK(r.get_int(name) == 0);
    CHECK_FALSE(r.given(name));
  };

  const auto& shell = *deck.of("/PROP/SHELL").at(0);
  for (const char* f : {"Hm", "Hf", "Hr"}) expect_default(shell, f, 0.01, true);
  expect_default(shell, "Ashear", 5.0 / 6.0, true);
  expect_default(shell, "P_Thick_Fail", 0.999999, true);
  for (const char* f : {"Ishell", "Ismstr", "Ish3n", "Idrill", "Dm", "Dn", "N", "Ithick", "Iplas"})
    expect_plain_zero(shell, f);
  CHECK(shell.get_real("Thick") == Approx(0.5).epsilon(kEps));

  const auto& solid = *deck.of("/PROP/SOLID").at(0);
  CHECK(solid.get_int("Isolid") == 14);
  expect_default(solid, "qa", 1.1, true);
  expect_default(solid, "qb", 0.05, true);
  expect_default(solid, "h", 0.1, true);
  for (const char* f : {"Lambda", "Mu", "deltaT_min", "COL_min", "Ndir", "Icontrol", "Iframe", "dn"})
    expect_plain_zero(solid, f);
  // A missing card's fields point at the keyword line.
  CHECK(solid.find("qa")->pos.line == solid.pos.line);

  const auto& jc = *deck.of("/MAT/LAW2").at(0);
  expect_default(jc, "flagVP", 2, true);
  expect_default(jc, "Pmin", -1e20, true);
  expect_default(jc, "n", 1.0, true);
  expect_default(jc, "EPS_p_max", 1e20, true);
  expect_default(jc, "SIG_max0", 1e20, true);
  expect_default(jc, "ICC", 1, true);
  expect_default(jc, "m", 1.0, true);
  expect_default(jc, "T_melt", 1e20, true);
  expect_default(jc, "T_r", 300.0, true);
  expect_default(jc, "T_max", 1e20, true);
  for (const char* f : {"RHO_ref", "Iflag", "b", "c", "EPS_DOT_0", "Fsmooth", "F_cut", "Chard", "rhoC_p"})
    expect_plain_zero(jc, f);

  for (const auto* path : {"/INTER/TYPE7", "/INTER/LAGDT/TYPE7"}) {
    const auto& in = *deck.of(path).at(0);
    expect_default(in, "Fscalegap", 1.0, true);
    expect_default(in, "Stmax", 1e30, true);
    expect_default(in, "Stfac", 1.0, std::string(path) == "/INTER/LAGDT/TYPE7");
    expect_default(in, "VISs", 0.05, true);
    expect_default(in, "VISF", 1.0, true);
    expect_default(in, "Iform", 1, true);
    for (const char* f : {"Istf", "Igap", "Ibag", "Idel", "Gapmax", "Stmin", "Fric", "Gapmin", "Tstart",
                          "Tstop", "IBCX", "IBCY", "IBCZ", "Inacti", "Bumult", "Ifric", "Ifiltr", "Xfreq"})
      expect_plain_zero(in, f);
    CHECK(in.find("C1") == nullptr);  // Ifric = 0: no friction cards
  }
  CHECK_FALSE(deck.of("/INTER/TYPE7").at(0)->find("Stfac")->blank);

  const auto& cload = *deck.of("/CLOAD").at(0);
  expect_default(cload, "Itypfun", 1, true);
  expect_default(cload, "Ascale_x", 1.0, true);
  expect_default(cload, "Fscale_y", 1.0, true);
  const auto& pload = *deck.of("/PLOAD").at(0);
  expect_default(pload, "Idel", 1, true);
  expect_default(pload, "Itypfun", 1, true);
  expect_default(pload, "Ascale_x", 1.0, true);
  expect_default(pload, "Fscale_y", 1.0, true);
  const auto& impvel = *deck.of("/IMPVEL").at(0);
  expect_default(impvel, "Ascale_x", 1.0, true);
  expect_default(impvel, "Fscale_y", 1.0, true);
  expect_plain_zero(impvel, "Tstop");
  const auto& grav = *deck.of("/GRAV").at(0);
  expect_default(grav, "Ascale_x", 1.0, true);
  expect_default(grav, "Fscale_y", 1.0, true);
  expect_plain_zero(grav, "funct_IDT");
  const auto& rbody = *deck.of("/RBODY").at(0);
  expect_default(rbody, "Ispher", 2, true);
  expect_default(rbody, "ICoG", 1, true);
  expect_plain_zero(rbody, "Mass");
  CHECK(rbody.find("FN") == nullptr);  // Ifail = 0: no card 5
  expect_default(*deck.of("/ANALY").at(0), "IPARITH", 1, true);
  expect_plain_zero(*deck.of("/ANALY").at(0), "N2D3D");
  expect_default(*deck.of("/DEF_SHELL").at(0), "Ithin_drape", 1, true);
}

TEST_CASE("comment lines between the cards of a keyword are skipped and positions stay physical",
          "[keywords]") {
  TempDir dir;
  std::string s = "/BEGIN\nCOMMENTS\n# version next\n" + Card().at(1, 10, 2019).str() + "\n$ units\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n";
  s += "/MAT/PLAS_JOHNS/3\n# a comment where the title would be is not the title\nsteel\n";  // line 8-10
  s += "#              RHO_I\n" + Card().at(1, 20, "7800.").str() + "\n";                    // 11-12
  s += "$                  E                  nu     Iflag\n" +
       Card().at(1, 20, "2.1E11").at(21, 40, "0.3").at(41, 50, 0).str() + "\n";  // 13-14
  s += "#---1----|----2----|\n#\n" + Card().at(1, 20, "2.5E8").at(21, 40, "4.5E8").at(41, 60, "0.3").str() +
       "\n";  // 15-17
  s += Card().at(1, 20, "0.014").at(21, 40, "1.").str() + "\n# between cards 4 and 5\n" +
       Card().at(1, 20, "1.5").at(21, 40, "1800.").str() + "\n/END\n";  // 18-20
  const auto path = dir.write("COMMENTS_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK(deck.version == 2019);
  const auto mats = deck.of("/MAT/LAW2");
  REQUIRE(mats.size() == 1u);
  const auto& r = *mats[0];
  CHECK(r.title == "steel");
  CHECK(r.pos.line == 8u);
  CHECK(r.get_real("RHO_I") == Approx(7800.0).epsilon(kEps));
  CHECK(r.find("RHO_I")->pos.line == 12u);
  CHECK(r.get_real("E") == Approx(2.1e11).epsilon(kEps));
  CHECK(r.find("E")->pos.line == 14u);
  CHECK(r.get_real("a") == Approx(2.5e8).epsilon(kEps));
  CHECK(r.get_real("b") == Approx(4.5e8).epsilon(kEps));
  CHECK(r.get_real("n") == Approx(0.3).epsilon(kEps));
  CHECK(r.find("a")->pos.line == 17u);
  CHECK(r.get_real("c") == Approx(0.014).epsilon(kEps));
  CHECK(r.get_real("EPS_DOT_0") == Approx(1.0).epsilon(kEps));
  CHECK(r.find("c")->pos.line == 18u);
  CHECK(r.get_real("m") == Approx(1.5).epsilon(kEps));
  CHECK(r.get_real("T_melt") == Approx(1800.0).epsilon(kEps));
  CHECK(r.find("m")->pos.line == 20u);
  CHECK(r.find("flagVP") == nullptr);  // 2019 layout
  CHECK(r.find("T_max") == nullptr);
}

TEST_CASE("#include inserts a file holding /NODE lines, relative to the including file", "[keywords]") {
  TempDir dir;
  dir.write("inc/nodes.inc",
            "# included node block\n/NODE\n" +
                Card().at(1, 10, 1).at(11, 30, "1.25").at(31, 50, "2.5").at(51, 70, "3.75").str() + "\n" +
                Card().at(1, 10, 2).at(11, 30, "-1.").str() + "\n#include more.inc\n");
  dir.write("inc/more.inc", Card().at(1, 10, 3).at(51, 70, "9.5").str() + "\n");
  const std::string main = "/BEGIN\nINCLUDE\n" + Card().at(1, 10, 2026).str() + "\n" +
                           Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n" +
                           Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() +
                           "\n#include inc/nodes.inc\n/NODE\n" + Card().at(1, 10, 4).at(31, 50, "7.5").str() +
                           "\n/END\n";
  const auto path = dir.write("INCLUDE_0000.rad", main);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  REQUIRE(deck.files.size() == 3u);
  const auto nodes = deck.of("/NODE");
  REQUIRE(nodes.size() == 2u);
  const auto& t = nodes[0]->records;
  REQUIRE(t.size() == 3u);
  const auto id = static_cast<std::size_t>(t.column("node_ID"));
  const auto cx = static_cast<std::size_t>(t.column("X"));
  const auto cy = static_cast<std::size_t>(t.column("Y"));
  const auto cz = static_cast<std::size_t>(t.column("Z"));
  CHECK(t.ints[id] == std::vector<std::int64_t>{1, 2, 3});
  CHECK(t.reals[cx][0] == Approx(1.25).epsilon(kEps));
  CHECK(t.reals[cy][0] == Approx(2.5).epsilon(kEps));
  CHECK(t.reals[cz][0] == Approx(3.75).epsilon(kEps));
  CHECK(t.reals[cx][1] == Approx(-1.0).epsilon(kEps));
  CHECK(t.reals[cz][2] == Approx(9.5).epsilon(kEps));
  // Positions name the included files and their own line numbers.
  CHECK(nodes[0]->pos.file == 1u);
  CHECK(nodes[0]->pos.line == 2u);
  CHECK(t.pos[0].file == 1u);
  CHECK(t.pos[0].line == 3u);
  CHECK(t.pos[2].file == 2u);
  CHECK(t.pos[2].line == 1u);
  CHECK(deck.files[1].find("nodes.inc") != std::string::npos);
  CHECK(deck.files[2].find("more.inc") != std::string::npos);
  const auto& t2 = nodes[1]->records;
  REQUIRE(t2.size() == 1u);
  CHECK(t2.ints[id][0] == 4);
  CHECK(t2.reals[cy][0] == Approx(7.5).epsilon(kEps));
  CHECK(t2.pos[0].file == 0u);
  CHECK(t2.pos[0].line == 8u);
}

TEST_CASE("CRLF line ends and trailing spaces do not reach titles, strings or values", "[keywords]") {
  TempDir dir;
  std::string s = "/BEGIN   \r\nCRLF RUN   \r\n" + Card().at(1, 10, 2026).str() + "    \r\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\r\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "  \r\n";
  s += "/TITLE\r\nA title with trailing blanks   \r\n";
  s += "/PART/12   \r\npart title  \r\n" + Card().at(1, 10, 3).at(11, 20, 4).at(31, 50, "1.5").str() +
       "   \r\n";
  s += "/IMPVEL/13\r\nv\r\n" + Card().at(1, 10, 5).at(11, 20, "X").at(41, 50, 6).str() + "\r\n" +
       Card().at(1, 20, "2.").at(21, 40, "3.").str() + "\r\n";
  s += "/END\r\n";
  const auto path = dir.write("CRLF_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  CHECK(deck.version == 2026);
  CHECK(deck.run_name == "CRLF RUN");
  CHECK(deck.work_units.time_name == "s");
  const auto title = deck.of("/TITLE");
  REQUIRE(title.size() == 1u);
  CHECK(title[0]->get_string("TITLE") == "A title with trailing blanks");
  const auto part = deck.of("/PART");
  REQUIRE(part.size() == 1u);
  CHECK(part[0]->id == 12);
  CHECK(part[0]->title == "part title");
  CHECK(part[0]->get_int("prop_ID") == 3);
  CHECK(part[0]->get_int("mat_ID") == 4);
  CHECK(part[0]->get_real("Thick") == Approx(1.5).epsilon(kEps));
  const auto v = deck.of("/IMPVEL");
  REQUIRE(v.size() == 1u);
  CHECK(v[0]->get_string("Dir") == "X");
  CHECK(v[0]->get_int("grnod_ID") == 6);
  CHECK(v[0]->get_real("Fscale_y") == Approx(3.0).epsilon(kEps));
}

TEST_CASE("Fortran real forms in node coordinates: 1.D3 1E-3 .5 1.5d-3 210000003000", "[keywords]") {
  TempDir dir;
  struct Row {
    const char* x;
    const char* y;
    const char* z;
    double vx, vy, vz;
  };
  const Row rows[] = {{"1.D3", "1E-3", ".5", 1000.0, 1e-3, 0.5},
                      {"1.5d-3", "210000003000", "-2.5D+2", 1.5e-3, 210000003000.0, -250.0},
                      {"5.", "-.25e1", "+1.25E+02", 5.0, -2.5, 125.0},
                      {"1d0", "0.1", "3", 1.0, 0.1, 3.0}};
  std::string s = "/BEGIN\nFORTRAN\n" + Card().at(1, 10, 2026).str() + "\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n" +
                  Card().at(1, 20, "kg").at(21, 40, "m").at(41, 60, "s").str() + "\n/NODE\n";
  int id = 1;
  for (const auto& r : rows)
    s += Card().at(1, 10, id++).at(11, 30, r.x).at(31, 50, r.y).at(51, 70, r.z).str() + "\n";
  s += "/END\n";
  const auto path = dir.write("FORTRAN_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  const auto nodes = deck.of("/NODE");
  REQUIRE(nodes.size() == 1u);
  const auto& t = nodes[0]->records;
  REQUIRE(t.size() == std::size(rows));
  for (std::size_t k = 0; k < std::size(rows); ++k) {
    INFO("node line " << k + 1 << ": " << rows[k].x << " " << rows[k].y << " " << rows[k].z);
    CHECK(t.reals[static_cast<std::size_t>(t.column("X"))][k] == Approx(rows[k].vx).epsilon(kEps));
    CHECK(t.reals[static_cast<std::size_t>(t.column("Y"))][k] == Approx(rows[k].vy).epsilon(kEps));
    CHECK(t.reals[static_cast<std::size_t>(t.column("Z"))][k] == Approx(rows[k].vz).epsilon(kEps));
  }
}

// ---------------------------------------------------------------------------------------------------
// Engine deck.

namespace {

struct EngineExpect {
  std::string path;
  std::vector<std::string> header;
  std::vector<std::vector<double>> lines;
  std::vector<std::int64_t> ids;
};

void check_engine(const radx::EngineDeck& deck, const std::vector<EngineExpect>& want) {
  REQUIRE(deck.records.size() == want.size());
  for (std::size_t k = 0; k < want.size(); ++k) {
    const auto& r = deck.records[k];
    const auto& w = want[k];
    INFO("engine record " << k << ": " << r.written << " (expected " << w.path << ")");
    REQUIRE(r.decl != nullptr);
    CHECK(r.decl->path == w.path);
    CHECK(r.header == w.header);
    REQUIRE(r.lines.size() == w.lines.size());
    for (std::size_t l = 0; l < w.lines.size(); ++l) {
      REQUIRE(r.lines[l].size() == w.lines[l].size());
      for (std::size_t n = 0; n < w.lines[l].size(); ++n) {
        CHECK(r.lines[l][n] == Approx(w.lines[l][n]).epsilon(kEps));
        CHECK(r.value(l, n) == Approx(w.lines[l][n]).epsilon(kEps));
      }
    }
    CHECK(r.ids == w.ids);
  }
}

}  // namespace

TEST_CASE("every engine keyword read with its values, including the 5-character truncation", "[keywords]") {
  TempDir dir;
  const std::string text = R"(#RADIOSS ENGINE
/RUN/ENGRUN/3
# end time
12.5
/VERS/2026
/TFILE/4
0.0025
/ANIM/DT
0.125 0.375 9.5 40 7
/ANIM/ELEM/VONM
/ANIM/ELEM/EPSP
/ANIM/VECT/VEL
/ANIM/TENS/STRESS
/ANIM/NODA/DMAS
/ANIM/GZIP
/ANIM/VERS/41
/DT
0.85 1.5E-7
/DT/NODA/CST/1
0.65, 2.5E-7, 3.5
17
/DT/INTERFACE/CST
0.55 3.5D-7
/DT/INTER/DEL
   0.45      4.5e-7
/DT/INTER/LAG

0.35 5.5E-7
/DT/BRICK/CST/1
0.25 6.5E-7
0.125 0.0625
/DT/SHELL/CST
0.15 7.5E-7
/DT/SH_3N/CST
0.05 8.5E-7
/DT/SH3N/CST
0.06 9.5E-7
/PRINT/-100/55
/STOP
1.5 2.5 3.5 1 1 1
/RFILE/5
5000
/RFILE/OFF
/MON/ON
/PARIT/ON
/PARITH/OFF
/RBODY/ON
3 4 5
6
/RBODY/OFF
7
/END
/RUN/AFTER/END/IS/IGNORED
)";
  const auto path = dir.write("ENGRUN_0001.rad", text);
  Diagnostics diags;
  const auto deck = radx::read_engine_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  check_engine(deck, {
                         {"/RUN", {"ENGRUN", "3"}, {{12.5}}, {}},
                         {"/VERS", {"2026"}, {}, {}},
                         {"/TFILE", {"4"}, {{0.0025}}, {}},
                         {"/ANIM/DT", {}, {{0.125, 0.375, 9.5, 40, 7}}, {}},
                         {"/ANIM/ELEM", {"VONM"}, {}, {}},
                         {"/ANIM/ELEM", {"EPSP"}, {}, {}},
                         {"/ANIM/VECT", {"VEL"}, {}, {}},
                         {"/ANIM/TENS", {"STRESS"}, {}, {}},
                         {"/ANIM/NODA", {"DMAS"}, {}, {}},
                         {"/ANIM/GZIP", {}, {}, {}},
                         {"/ANIM/VERS", {"41"}, {}, {}},
                         {"/DT", {}, {{0.85, 1.5e-7}}, {}},
                         {"/DT/NODA/CST", {"1"}, {{0.65, 2.5e-7, 3.5}, {17}}, {}},
                         {"/DT/INTER/CST", {}, {{0.55, 3.5e-7}}, {}},
                         {"/DT/INTER/DEL", {}, {{0.45, 4.5e-7}}, {}},
                         {"/DT/INTER/LAG", {}, {{0.35, 5.5e-7}}, {}},
                         {"/DT/BRICK/CST", {"1"}, {{0.25, 6.5e-7}, {0.125, 0.0625}}, {}},
                         {"/DT/SHELL/CST", {}, {{0.15, 7.5e-7}}, {}},
                         {"/DT/SH_3N/CST", {}, {{0.05, 8.5e-7}}, {}},
                         {"/DT/SH_3N/CST", {}, {{0.06, 9.5e-7}}, {}},
                         {"/PRINT", {"-100", "55"}, {}, {}},
                         {"/STOP", {}, {{1.5, 2.5, 3.5, 1, 1, 1}}, {}},
                         {"/RFILE", {"5"}, {{5000}}, {}},
                         {"/RFILE/OFF", {}, {}, {}},
                         {"/MON/ON", {}, {}, {}},
                         {"/PARITH/ON", {}, {}, {}},
                         {"/PARITH/OFF", {}, {}, {}},
                         {"/RBODY/ON", {}, {}, {3, 4, 5, 6}},
                         {"/RBODY/OFF", {}, {}, {7}},
                     });
  // Positions: physical lines of the file.
  REQUIRE_FALSE(deck.records.empty());
  CHECK(deck.records[0].pos.line == 2u);
  CHECK(deck.records[0].written == "/RUN/ENGRUN/3");
  CHECK(deck.of("/PARITH/ON").at(0)->written == "/PARIT/ON");
  CHECK(deck.of("/DT/INTER/CST").at(0)->written == "/DT/INTERFACE/CST");
  // Optional values not written take the caller's default.
  CHECK(deck.of("/DT").at(0)->value(0, 2, -1.0) == -1.0);
}

TEST_CASE("engine keyword fields are cut to 5 characters, /ANIM fields are compared as Radioss does",
          "[keywords]") {
  TempDir dir;
  const std::string text =
      "/RUN/TRUNC/1\n1.0\n/PARITHMETIC/ON\n/DT/INTERFACES/CST\n0.5 1E-6\n/DT/SHELLS/CST\n0.5 2E-6\n"
      "/ANIM/ELEMENT/VONM\n/END\n";
  const auto path = dir.write("TRUNC_0001.rad", text);
  Diagnostics diags;
  const auto deck = radx::read_engine_deck(path, diags);
  INFO(all_diags(diags));
  // /ANIM fields are kept whole, and the Radioss animation reader compares the second one on its first four
  // characters: /ANIM/ELEMENT/VONM is /ANIM/ELEM/VONM.
  CHECK_FALSE(diags.has_errors());
  REQUIRE(deck.records.size() == 5u);
  CHECK(deck.records[1].decl->path == "/PARITH/ON");
  CHECK(deck.records[2].decl->path == "/DT/INTER/CST");
  CHECK(deck.records[2].value(0, 1) == Approx(1e-6).epsilon(kEps));
  CHECK(deck.records[3].decl->path == "/DT/SHELL/CST");
  CHECK(deck.records[3].value(0, 1) == Approx(2e-6).epsilon(kEps));
  CHECK(deck.records[4].decl->path == "/ANIM/ELEM");
  CHECK(deck.records[4].header == std::vector<std::string>{"VONM"});
}

TEST_CASE("a one-file deck is read by both readers: engine part, /END/ENGINE, then /BEGIN ... /END",
          "[keywords]") {
  TempDir dir;
  const std::string text =
      "#RADIOSS ONE FILE\n/RUN/ONEFILE/1\n0.01\n/ANIM/DT\n0. 1E-3\n/DT/NODA/CST\n0.9 1E-7\n"
      "/PRINT/-10\n/END/ENGINE\n/BEGIN\nONEFILE\n" +
      Card().at(1, 10, 2026).str() + "\n" + Card().at(1, 20, "Mg").at(21, 40, "mm").at(41, 60, "s").str() +
      "\n" + Card().at(1, 20, "Mg").at(21, 40, "mm").at(41, 60, "s").str() + "\n/NODE\n" +
      Card().at(1, 10, 1).at(11, 30, "1.5").at(31, 50, "2.5").at(51, 70, "3.5").str() +
      "\n/FUNCT/2\ncurve\n" + Card().at(1, 20, "0.").at(21, 40, "1.").str() + "\n" +
      Card().at(1, 20, "1.").at(21, 40, "2.").str() + "\n/END\n";
  const auto path = dir.write("ONEFILE_0000.rad", text);
  CHECK(radx::model::is_one_file_deck(path));

  Diagnostics ediags;
  const auto engine = radx::read_engine_deck(path, ediags);
  {
    INFO(all_diags(ediags));
    CHECK_FALSE(ediags.has_errors());
  }
  check_engine(engine, {{"/RUN", {"ONEFILE", "1"}, {{0.01}}, {}},
                        {"/ANIM/DT", {}, {{0.0, 1e-3}}, {}},
                        {"/DT/NODA/CST", {}, {{0.9, 1e-7}, {}}, {}},
                        {"/PRINT", {"-10"}, {}, {}}});

  Diagnostics sdiags;
  const auto starter = radx::read_starter_deck(path, sdiags);
  INFO(all_diags(sdiags));
  CHECK_FALSE(sdiags.has_errors());
  CHECK(starter.version == 2026);
  CHECK(starter.run_name == "ONEFILE");
  REQUIRE(starter.records.size() == 3u);
  CHECK(starter.records[0].keyword() == "/BEGIN");
  CHECK(starter.records[0].pos.line == 10u);
  CHECK(starter.records[1].keyword() == "/NODE");
  const auto& t = starter.records[1].records;
  REQUIRE(t.size() == 1u);
  CHECK(t.reals[static_cast<std::size_t>(t.column("Z"))][0] == Approx(3.5).epsilon(kEps));
  CHECK(starter.records[2].keyword() == "/FUNCT");
  CHECK(starter.records[2].records.size() == 2u);
}

TEST_CASE(
    "lines of a record or id list that start with text are skipped with one warning, as OpenRadioss does",
    "[keywords]") {
  // OpenRadioss's QA decks end with `#include qadiags.inc`, a file holding only "Copyright>" licence lines,
  // read as data of the block before it.
  TempDir dir;
  dir.write("licence.inc", "Copyright>        OpenRadioss\nCopyright>\nCopyright>  see <https://x>.\n");
  const std::string s = begin_lines(2022) + "/NODE\n" + Card().at(1, 10, 7).at(11, 30, "1.5").str() + "\n" +
                        "Copyright> text inside a record list\n" +
                        Card().at(1, 10, 8).at(11, 30, "4.5").str() + "\n" + "/GRNOD/NODE/3\nthe group\n" +
                        Card().at(1, 10, 7).at(11, 20, 8).str() + "\n#include licence.inc\n/END\n";
  const auto path = dir.write("SKIP_0000.rad", s);
  Diagnostics diags;
  const auto deck = radx::read_starter_deck(path, diags);
  INFO(all_diags(diags));
  CHECK_FALSE(diags.has_errors());
  // One warning per block, however many lines it skipped.
  CHECK(has_diag(diags, Diag::ExtraData, radx::Severity::Warning,
                 "1 line(s) from here start with text ('Copyright> text inside a record list')"));
  CHECK(has_diag(diags, Diag::ExtraData, radx::Severity::Warning,
                 "3 line(s) from here start with text ('Copyright>        OpenRadioss')"));
  const auto node = deck.of("/NODE");
  REQUIRE(node.size() == 1u);
  CHECK(node[0]->records.size() == 2u);
  const auto g = deck.of("/GRNOD/NODE");
  REQUIRE(g.size() == 1u);
  CHECK(g[0]->ids == std::vector<std::int64_t>{7, 8});
}
