// The starter-deck reader, driven entirely by the keyword declarations of keywords_starter.cpp:
// header line -> declaration (longest path match, aliases included), then the title line, the cards
// of the deck's version (conditional cards by their condition), then the tail (records, id lists,
// text). Values get their declared defaults, are checked against their declared bounds and allowed
// sets, and are converted from input units to work units. Nothing here knows a keyword by name except
// /BEGIN (its version selects every layout), /UNIT, /END, and //SUBMODEL and //ENDSUB, which bracket the
// keywords whose ids get a submodel's offsets (each id by the kind its declaration gives it).
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

#include "parser/reading/closest_names.hpp"
#include "parser/reading/deck.hpp"
#include "parser/reading/deck_text.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx {

using schema::CardDecl;
using schema::FieldDecl;
using schema::FieldType;
using schema::KeywordDecl;

namespace {

constexpr int kNewestVersion = schema::kDeckVersions.back();

// The integer view of a real default, 0 when it has none: defaults such as Pmin = -1e30 lie beyond
// int64, and converting them would be undefined behaviour. Only integer fields read the integer view.
std::int64_t int_if_representable(double d) {
  constexpr double kLimit = 9.2233720368547758e18;  // 2^63, exact in a double
  return (d > -kLimit && d < kLimit) ? static_cast<std::int64_t>(d) : 0;
}

// "90, 100, 110, 120, 130, 140 and 2017 to 2026": the versions radx reads, for messages.
std::string deck_versions_text() {
  std::string s;
  for (int v : schema::kDeckVersions) {
    if (v > 2017) break;
    s += std::to_string(v) + (v == 2017 ? "" : ", ");
  }
  return s + " to " + std::to_string(kNewestVersion);
}

std::string upper(std::string_view s) {
  std::string r(s);
  for (auto& c : r) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return r;
}

std::vector<std::string> split_keyword(std::string_view line) {
  return keyword_fields(line);
}

// `/BEGIN`, and `/BEGIN/0` or `/BEGIN/` as older generators write it: Radioss finds /BEGIN by its prefix.
bool is_begin(const std::vector<std::string>& tokens) {
  return !tokens.empty() && tokens[0] == "BEGIN" &&
         (tokens.size() == 1 ||
          (tokens.size() == 2 && std::all_of(tokens[1].begin(), tokens[1].end(), [](char c) {
             return std::isdigit(static_cast<unsigned char>(c));
           })));
}

std::string join_path(const std::vector<std::string>& tokens, std::size_t n) {
  std::string p;
  for (std::size_t i = 0; i < n; ++i) p += "/" + tokens[i];
  return p;
}

struct Registry {
  std::unordered_map<std::string, const KeywordDecl*> by_path;
  std::size_t max_tokens = 1;
};

const Registry& starter_registry() {
  static const Registry reg = [] {
    Registry r;
    for (const auto& k : schema::starter_keywords()) {
      auto add = [&](std::string_view path) {
        r.by_path[std::string(path)] = &k;
        const auto n = static_cast<std::size_t>(std::count(path.begin(), path.end(), '/'));
        r.max_tokens = std::max(r.max_tokens, n);
      };
      add(k.path);
      for (auto a : k.aliases) add(a);
    }
    return r;
  }();
  return reg;
}

bool is_known_unsupported(const std::string& path) {
  for (auto root : schema::known_unsupported_roots()) {
    if (path.size() >= root.size() && path.compare(0, root.size(), root) == 0 &&
        (path.size() == root.size() || path[root.size()] == '/'))
      return true;
  }
  return false;
}

// The families of Radioss keywords whose members are many (materials, properties, failure models, ...):
// a name radx does not declare there is a Radioss keyword radx lacks far more often than a typing error.
std::string radioss_family(const std::string& path) {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 12> kFamilies = {{
      {"/MAT/", "material law"},
      {"/PROP/", "property type"},
      {"/FAIL/", "failure model"},
      {"/EOS/", "equation of state"},
      {"/INTER/", "contact interface type"},
      {"/TH/", "time-history group"},
      {"/SENSOR/", "sensor type"},
      {"/ALE/", "ALE option"},
      {"/EBCS/", "elementary boundary condition"},
      {"/MONVOL/", "monitored volume"},
      {"/VISC/", "viscosity model"},
      {"/ANIM/", "animation request"},
  }};
  for (const auto& [root, name] : kFamilies)
    if (path.starts_with(root)) return std::string(name);
  return {};
}

// "radx reads /MAT/LAW1, /MAT/LAW2, ..." for the keywords radx declares under the path's first word.
std::string readable_alternatives(const std::string& path) {
  const auto second = path.find('/', 1);
  const std::string root = second == std::string::npos ? path : path.substr(0, second + 1);
  std::vector<std::string> names;
  for (const auto& k : schema::starter_keywords())
    if (k.support != schema::Support::Ignored) {
      if (std::string_view(k.path).starts_with(root)) names.emplace_back(k.path);
      for (auto a : k.aliases)
        if (a.starts_with(root)) names.emplace_back(a);
    }
  if (names.empty() || second == std::string::npos) return "see docs/keywords.md for the keywords radx reads";
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  return "radx reads " + list + " (docs/keywords.md)";
}

// "; did you mean /MAT/PLAS_JOHNS?" when the path is a slip from a keyword radx reads, else "".
std::string suggested_keyword(const std::string& path) {
  static const std::vector<std::string> read = [] {
    std::vector<std::string> names;
    for (const auto& k : schema::starter_keywords())
      if (k.support != schema::Support::Ignored) {
        names.emplace_back(k.path);
        for (auto a : k.aliases) names.emplace_back(a);
      }
    return names;
  }();
  const std::string text = did_you_mean(path, read);
  return text.empty() ? text : "; " + text;
}

// What a unit of `kind` may be called, for messages.
std::string unit_names_accepted(char kind) {
  const std::string prefixes = "an SI prefix (n, u or mu, m, c, d, k, M, G, T, ...) before ";
  if (kind == 'M') return prefixes + "g (kg, g, mg, Mg, Tg), or t, lb";
  if (kind == 'L') return prefixes + "m (m, mm, um, km), or in, ft";
  return prefixes + "s (s, ms, us, ns), or min, h";
}

std::string_view cell(std::string_view line, int first, int last) {
  const auto f = static_cast<std::size_t>(first - 1);
  if (line.size() <= f) return {};
  const auto l = std::min(line.size(), static_cast<std::size_t>(last));
  return line.substr(f, l - f);
}

std::vector<std::string_view> split_free(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    out.push_back(
        trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string fmt_num(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

std::string describe_allowed(const FieldDecl& f) {
  std::string s;
  for (std::size_t i = 0; i < f.allowed.size(); ++i) s += (i ? ", " : "") + std::to_string(f.allowed[i]);
  return s;
}

std::string describe_bounds(const FieldDecl& f) {
  std::string s;
  if (f.min) s += (f.min_exclusive ? "> " : ">= ") + fmt_num(*f.min);
  if (f.max) s += std::string(s.empty() ? "" : " and ") + (f.max_exclusive ? "< " : "<= ") + fmt_num(*f.max);
  return s;
}

class StarterReader {
 public:
  StarterReader(DeckText& text, Diagnostics& diags, Deck& deck) : text_(text), diags_(diags), deck_(deck) {}

  void read(std::size_t first_line) {
    const auto& lines = text_.lines;
    // Find /BEGIN and /END: the starter reads between them.
    std::size_t begin = lines.size();
    for (std::size_t i = first_line; i < lines.size(); ++i) {
      if (is_keyword(lines[i]) && is_begin(split_keyword(lines[i].text))) {
        begin = i;
        break;
      }
    }
    if (begin == lines.size()) {
      const SourcePos p =
          lines.empty() ? SourcePos{0, 1} : lines[first_line < lines.size() ? first_line : 0].pos;
      diags_.error(
          Diag::MissingBegin, text_.where(p, 1), About{"/BEGIN"},
          "no /BEGIN line: a starter deck starts with /BEGIN (run name, version, units) and ends with /END");
      return;
    }
    std::size_t end = lines.size();
    for (std::size_t i = begin + 1; i < lines.size(); ++i) {
      if (is_keyword(lines[i])) {
        const auto t = split_keyword(lines[i].text);
        if (!t.empty() && t[0] == "END" && (t.size() == 1)) {
          end = i;
          break;
        }
      }
    }
    if (end == lines.size() && !text_.ended_in_include) {
      const SourcePos p = lines.back().pos;
      diags_.error(Diag::MissingEnd, text_.where(p, 1), About{"/END"},
                   "the deck has no /END line: the file looks truncated; a starter deck ends with /END");
    }
    // The version selects every layout: read it from /BEGIN card 2 before anything else.
    read_version(begin, end);
    // Blocks.
    std::size_t i = begin;
    while (i < end) {
      std::size_t j = i + 1;
      while (j < end && !is_keyword(lines[j])) ++j;
      read_block(i, j);
      i = j;
    }
    for (auto it = open_.rbegin(); it != open_.rend(); ++it) {
      const Submodel& sm = deck_.submodels[static_cast<std::size_t>(*it)];
      diags_.error(Diag::UnbalancedSubmodel, at(sm.pos, 1), About{"//SUBMODEL", sm.id, sm.title},
                   "//SUBMODEL/" + std::to_string(sm.id) +
                       " is not closed: every //SUBMODEL needs its //ENDSUB before /END (nested ones close "
                       "innermost first)");
    }
    convert_units();
  }

 private:
  static bool is_keyword(const TextLine& l) { return !l.text.empty() && l.text.front() == '/'; }

  Where at(SourcePos p, int col = 0) const { return text_.where(p, col); }

  void read_version(std::size_t begin, std::size_t end) {
    const auto& lines = text_.lines;
    int version = kNewestVersion;
    if (begin + 2 < end && !is_keyword(lines[begin + 2])) {
      std::int64_t v = 0;
      const std::string_view card = lines[begin + 2].text;
      const auto comma = card.find(',');
      const auto st =
          parse_int(comma == std::string_view::npos ? cell(card, 1, 10) : card.substr(0, comma), v);
      if (st == NumberStatus::Ok && v > 0) {
        version = static_cast<int>(v);
        if (v > kNewestVersion) {
          diags_.warning(Diag::UnsupportedVersion, at(lines[begin + 2].pos, 1), About{"/BEGIN"},
                         "deck version " + std::to_string(v) + " is newer than radx knows; the " +
                             std::to_string(kNewestVersion) + " layouts are used");
          version = kNewestVersion;
        } else if (!schema::is_deck_version(version)) {
          // Formats 41 to 51 and numbers Radioss never used: no layout of theirs is established.
          diags_.error(Diag::UnsupportedVersion, at(lines[begin + 2].pos, 1), About{"/BEGIN"},
                       "deck version " + std::to_string(v) +
                           " is not read by radx: it reads the deck formats " + deck_versions_text() +
                           "; convert the deck to one of them");
        }
      }
    }
    deck_.version = version;
  }

  // A fixed-column card field that holds two numbers apart ("0000      .000000000": the card's columns are
  // shifted) is read as its leading value: Radioss's reader scans a field with sscanf, which stops at the
  // blank. A warning, since the value read may not be the one meant. Only on cards, and only when every part
  // is a number: "1.5 E-3" stays an error, and so does a record line (/NODE, /SHELL ...) written without
  // columns, where the leading value of a cell is usually not the one meant.
  std::string_view leading_value(std::string_view raw, const std::string& what, SourcePos pos, int column,
                                 const About& about) {
    const auto blank = raw.find_first_of(" \t");
    if (blank == std::string_view::npos) return raw;
    double probe = 0;
    std::string_view rest = raw;
    while (!rest.empty()) {
      const auto end = rest.find_first_of(" \t");
      if (parse_real(rest.substr(0, end), probe) != NumberStatus::Ok) return raw;
      rest = end == std::string_view::npos ? std::string_view{} : trim(rest.substr(end));
    }
    const std::string_view first = raw.substr(0, blank);
    diags_.warning(Diag::TwoValuesInField, at(pos, column), about,
                   what + " holds '" + std::string(raw) +
                       "', more than one number: the card's columns look " + "shifted; '" +
                       std::string(first) + "' is read and the rest ignored, as Radioss reads " +
                       "it (check the card's alignment against its comment line)");
    return first;
  }

  // Where a field's value was written, and what its messages call it.
  struct FieldPlace {
    std::string what;  // "field E (Young's modulus)"
    SourcePos pos;
    int column;
    const About& about;
  };

  // An integer field's text into v.i (and v.r); false, with the error, when it is not an integer.
  bool read_integer(std::string_view raw, FieldValue& v, const FieldPlace& p) {
    bool ok = true;
    const auto st = parse_int(raw, v.i);
    if (st == NumberStatus::Malformed) {
      // A real with no fractional part written in an integer field is common in decks written by
      // hand; anything else is an error.
      double r = 0;
      if (parse_real(raw, r) == NumberStatus::Ok && r == std::floor(r) && std::abs(r) < 9e15) {
        v.i = static_cast<std::int64_t>(r);
      } else {
        diags_.error(Diag::BadInteger, at(p.pos, p.column), p.about,
                     p.what + ": '" + std::string(raw) + "' is not an integer; write digits only, e.g. 12");
        ok = false;
      }
    } else if (st == NumberStatus::Overflow) {
      diags_.error(Diag::IntegerOverflow, at(p.pos, p.column), p.about,
                   p.what + ": '" + std::string(raw) + "' is out of the integer range");
      ok = false;
    }
    v.r = static_cast<double>(v.i);
    return ok;
  }

  // A real field's text into v.r; false, with the error, when it is not a number.
  bool read_real(std::string_view raw, FieldValue& v, const FieldPlace& p) {
    bool ok = true;
    const auto st = parse_real(raw, v.r);
    if (st == NumberStatus::Malformed) {
      diags_.error(Diag::BadReal, at(p.pos, p.column), p.about,
                   p.what + ": '" + std::string(raw) +
                       "' is not a number; accepted forms: 1.5, .5, 5., 1E-3, 1.D3, 1.5d-3, 210000003000");
      ok = false;
    } else if (st == NumberStatus::Overflow) {
      diags_.error(
          Diag::RealOverflow, at(p.pos, p.column), p.about,
          p.what + ": '" + std::string(raw) + "' is beyond the double-precision range (about 1.8E308)");
      ok = false;
    }
    v.i = 0;
    return ok;
  }

  // A number outside the declared accepted values or bounds is an error, unless it was reported already
  // (`unreadable`, or 0 in a required field) or is a blank optional field with no default.
  void check_accepted(const FieldDecl& f, const FieldValue& v, bool zero, bool unreadable, double value,
                      const FieldPlace& p) {
    if (unreadable || (zero && f.required)) {
      // Already reported as unreadable or missing; a range message on top would repeat it.
    } else if (!f.allowed.empty() && f.type == FieldType::Int &&
               std::find(f.allowed.begin(), f.allowed.end(), v.i) == f.allowed.end()) {
      diags_.error(
          Diag::ValueOutOfRange, at(p.pos, p.column), p.about,
          p.what + " = " + std::to_string(v.i) + " is not accepted; accepted values: " + describe_allowed(f));
    } else if ((f.min && (f.min_exclusive ? value <= *f.min : value < *f.min)) ||
               (f.max && (f.max_exclusive ? value >= *f.max : value > *f.max))) {
      if (!(zero && !f.required && !f.zero_default && v.blank)) {
        diags_.error(Diag::ValueOutOfRange, at(p.pos, p.column), p.about,
                     p.what + " = " + fmt_num(value) + " is out of range; accepted: " + describe_bounds(f));
      }
    }
  }

  // A value given in a field radx reads and does not use: a warning when it changes no result; when it
  // changes the physics, an error, or with --allow-substitutions a warning and a listed substitution.
  void report_unused_value(const FieldDecl& f, double value, const FieldPlace& p) {
    if (!f.changes_physics) {
      diags_.warning(Diag::UnimplementedOption, at(p.pos, p.column), p.about,
                     p.what + " = " + fmt_num(value) + " is read but not used by radx; it changes no result");
    } else if (deck_.allow_substitutions) {
      const std::string text =
          p.what + " = " + fmt_num(value) + " is not implemented by radx: the run goes on without it";
      diags_.warning(Diag::Substitution, at(p.pos, p.column), p.about, text);
      deck_.substitutions.push_back(std::string(p.about.keyword) +
                                    (p.about.id ? " " + std::to_string(p.about.id) : std::string()) + ": " +
                                    text);
    } else {
      diags_.error(Diag::PhysicsNotImplemented, at(p.pos, p.column), p.about,
                   p.what + " = " + fmt_num(value) +
                       " changes the physics and radx does not implement it; leave it blank or 0, or run "
                       "with --allow-substitutions to run without it");
    }
  }

  // The checks of a number once read: a required value, the zero default, the accepted values and bounds,
  // and a value radx does not use.
  void check_number(const FieldDecl& f, FieldValue& v, bool unreadable, const FieldPlace& p) {
    const bool zero = (f.type == FieldType::Int) ? v.i == 0 : v.r == 0.0;
    if (zero && f.required && !unreadable) {
      diags_.error(Diag::RequiredValueMissing, at(p.pos, p.column), p.about,
                   p.what + " is " + (v.blank ? "blank" : "0") + ": a value is required");
    }
    if (zero && f.zero_default) {
      v.r = *f.zero_default;
      v.i = int_if_representable(*f.zero_default);
      v.defaulted = true;
    }
    const double value = f.type == FieldType::Int ? static_cast<double>(v.i) : v.r;
    check_accepted(f, v, zero, unreadable, value, p);
    if (f.ignored && !zero && !v.defaulted) report_unused_value(f, value, p);
  }

  // A field's text -> value, with defaults and checks.
  FieldValue parse_field(const FieldDecl& f, std::string_view raw, SourcePos pos, int column,
                         const About& about, bool card_cell = false) {
    FieldValue v;
    v.decl = &f;
    v.pos = pos;
    v.column = static_cast<std::uint16_t>(column);
    raw = trim(raw);
    v.blank = raw.empty();
    const FieldPlace place{"field " + std::string(f.name) + " (" + std::string(f.meaning) + ")", pos, column,
                           about};
    if (card_cell && f.type != FieldType::String) raw = leading_value(raw, place.what, pos, column, about);
    // A value already reported as unreadable is read as blank; it is not reported again as missing or out
    // of range.
    bool unreadable = false;
    switch (f.type) {
      case FieldType::String: v.s = std::string(raw); break;
      case FieldType::Int: unreadable = !read_integer(raw, v, place); break;
      case FieldType::Real: unreadable = !read_real(raw, v, place); break;
    }
    if (unreadable) v.blank = true;
    if (f.type != FieldType::String) check_number(f, v, unreadable, place);
    return v;
  }

  std::vector<const FieldDecl*> active_fields(const CardDecl& card) const {
    std::vector<const FieldDecl*> out;
    for (const auto& f : card.fields)
      if (f.in_version(deck_.version)) out.push_back(&f);
    std::stable_sort(out.begin(), out.end(),
                     [](const FieldDecl* a, const FieldDecl* b) { return a->first_col < b->first_col; });
    return out;
  }

  // A tab before a value in a fixed-column line is read as Radioss reads it: one blank column (its field
  // reader takes the line as written and scans each cell with blanks and tabs alike), not a jump to the next
  // tab stop. A warning, since an editor showing tab stops shows the values in other columns than the ones
  // they are read from. Free-format (comma) lines have no columns: their tabs are blanks.
  std::string_view check_tabs(const TextLine& line, const About& about) {
    const auto tab = line.text.find('\t');
    if (tab == std::string_view::npos) return line.text;
    if (line.text.find(',') != std::string_view::npos) return line.text;  // free format: tabs are blanks
    // Tabs among the trailing blanks move no value: the line ends before them (as Radioss reads it).
    if (line.text.find_first_not_of(" \t\r", tab) == std::string_view::npos) return line.text.substr(0, tab);
    diags_.warning(Diag::TabInFixedField, at(line.pos, static_cast<int>(tab) + 1), about,
                   "tab character in a fixed-column line: read as one blank column, as Radioss reads it (not "
                   "as a jump to the next tab stop, which an editor may show); check that each value sits in "
                   "its columns counting the tab as one character, or write the values comma-separated");
    return line.text;
  }

  void check_width(const TextLine& line, const About& about) {
    if (line.text.size() > 100 && !trim(line.text.substr(100)).empty()) {
      diags_.warning(Diag::TextBeyondColumn100, at(line.pos, 101), about,
                     "text beyond column 100 is ignored: '" + std::string(trim(line.text.substr(100))) + "'");
    }
  }

  // Reads one card from `line` (nullptr: the card is missing and read as blank).
  void read_card(const CardDecl& card, const TextLine* line, SourcePos keyword_pos, KeywordRecord& rec,
                 const About& about) {
    const auto fields = active_fields(card);
    std::string_view text;
    SourcePos pos = keyword_pos;
    bool free = false;
    std::vector<std::string_view> values;
    if (line) {
      pos = line->pos;
      // A card that is one text field (a title, a run name) keeps its commas and tabs.
      const bool single_text = fields.size() == 1 && fields[0]->type == FieldType::String;
      text = single_text ? line->text : check_tabs(*line, about);
      check_width(*line, about);
      free = !single_text && text.find(',') != std::string_view::npos;
      if (free) values = split_free(text);
    }
    for (std::size_t k = 0; k < fields.size(); ++k) {
      const auto& f = *fields[k];
      std::string_view raw;
      if (free) {
        raw = k < values.size() ? values[k] : std::string_view{};
      } else {
        raw = cell(text, f.first_col, std::min(f.last_col, 100));
        // Radioss pre-reads the line and skips the field when the gate columns are blank: text written
        // there anyway is not read (a free-format line has no columns to test, so it is always read).
        if (f.gate_first > 0 && trim(cell(text, f.gate_first, f.gate_last)).empty()) {
          if (!trim(raw).empty()) {
            diags_.warning(Diag::ExtraData, at(pos, f.first_col), about,
                           "field " + std::string(f.name) + " ('" + std::string(trim(raw)) +
                               "') is not read in a version-" + std::to_string(deck_.version) +
                               " deck because columns " + std::to_string(f.gate_first) + "-" +
                               std::to_string(f.gate_last) +
                               " are blank: that layout reads it only when they hold text");
          }
          raw = {};
        }
      }
      rec.fields.push_back(parse_field(f, raw, pos, line ? f.first_col : 0, about, !free));
    }
    if (free && values.size() > fields.size()) {
      diags_.warning(Diag::ExtraData, at(pos, 1), about,
                     "this free-format line has " + std::to_string(values.size()) + " values; the card has " +
                         std::to_string(fields.size()) + " fields; the extra values are ignored");
    }
  }

  void init_table(RecordTable& t, const CardDecl& card) {
    t.fields = active_fields(card);
    t.ints.resize(t.fields.size());
    t.reals.resize(t.fields.size());
    t.strings.resize(t.fields.size());
  }

  void read_record(RecordTable& t, const TextLine& line, const About& about) {
    const std::size_t errors_before = diags_.error_count();
    const std::string_view text = check_tabs(line, about);
    check_width(line, about);
    const bool free = text.find(',') != std::string_view::npos;
    std::vector<std::string_view> values;
    if (free) values = split_free(text);
    t.pos.push_back(line.pos);
    for (std::size_t k = 0; k < t.fields.size(); ++k) {
      const auto& f = *t.fields[k];
      std::string_view raw = free ? (k < values.size() ? values[k] : std::string_view{})
                                  : cell(text, f.first_col, std::min(f.last_col, 100));
      FieldValue v = parse_field(f, raw, line.pos, f.first_col, about);
      switch (f.type) {
        case FieldType::Int: t.ints[k].push_back(v.i); break;
        case FieldType::Real: t.reals[k].push_back(v.r); break;
        case FieldType::String: t.strings[k].push_back(std::move(v.s)); break;
      }
    }
    t.bad.push_back(diags_.error_count() > errors_before ? 1 : 0);
  }

  // The error for an id-list cell that is not one integer. A cell of several integers apart (ids separated
  // by blanks or tabs rather than placed in their own cells) is read by Radioss as its first id, the others
  // dropped without a word; radx refuses it and says so, since a group that silently loses members changes
  // the model.
  static std::string bad_id_cell(std::string_view cell) {
    std::vector<std::string> parts;
    bool all_ints = true;
    for (std::string_view rest = cell; !rest.empty();) {
      const auto e = rest.find_first_of(" \t");
      const auto part = rest.substr(0, e);
      std::int64_t v = 0;
      if (parse_int(part, v) != NumberStatus::Ok) all_ints = false;
      parts.emplace_back(part);
      rest = e == std::string_view::npos ? std::string_view{} : trim(rest.substr(e));
    }
    std::string shown;
    for (const auto& p : parts) shown += (shown.empty() ? "" : " ") + p;
    if (parts.size() > 1 && all_ints) {
      std::string others;
      for (std::size_t k = 1; k < parts.size(); ++k) others += (k > 1 ? ", " : "") + parts[k];
      return "one 10-column cell holds " + std::to_string(parts.size()) + " ids ('" + shown +
             "', blank- or tab-separated): Radioss reads only the first (" + parts[0] + ") and drops " +
             others + " without a word; give each id its own 10-column cell, or separate the ids with commas";
    }
    return "'" + shown + "' is not an id; ids are integers, 10 per line in 10-column cells";
  }

  void read_ids(KeywordRecord& rec, const TextLine& line, const About& about) {
    const std::string_view text = check_tabs(line, about);
    const bool free = text.find(',') != std::string_view::npos;
    check_width(line, about);
    auto take = [&](std::string_view raw, int col) {
      std::int64_t v = 0;
      const auto st = parse_int(raw, v);
      if (st == NumberStatus::Blank) return;
      if (st != NumberStatus::Ok) {
        diags_.error(Diag::BadInteger, at(line.pos, col), about, bad_id_cell(trim(raw)));
        return;
      }
      if (v == 0) return;
      rec.ids.push_back(v);
      rec.id_pos.push_back(line.pos);
    };
    if (free) {
      for (auto v : split_free(text)) take(v, 1);
    } else {
      for (int c = 0; c < 10; ++c) take(cell(text, 10 * c + 1, 10 * c + 10), 10 * c + 1);
    }
  }

  // A line of a record or id list that starts with a letter cannot be a record: OpenRadioss's reader skips
  // such lines without a word (its QA decks include a qadiags.inc that holds only a licence header of
  // "Copyright>" lines, read after a /GRNOD or /TH list). radx skips them too, with one warning per block
  // naming the lines, because a typo there drops records.
  struct SkippedText {
    std::size_t count = 0;
    SourcePos first{};
    std::string sample;
  };
  static bool starts_with_text(std::string_view text) {
    const auto t = trim(text);
    return !t.empty() && std::isalpha(static_cast<unsigned char>(t.front()));
  }
  bool skip_text_line(const TextLine& line, SkippedText& skipped) {
    if (!starts_with_text(line.text)) return false;
    if (skipped.count++ == 0) {
      skipped.first = line.pos;
      skipped.sample = std::string(trim(line.text).substr(0, 40));
    }
    return true;
  }
  void report_skipped(const SkippedText& skipped, std::string_view path, const About& about) {
    if (skipped.count == 0) return;
    diags_.warning(Diag::ExtraData, at(skipped.first, 1), about,
                   std::to_string(skipped.count) + " line(s) from here start with text ('" + skipped.sample +
                       "') and are not records of " + std::string(path) +
                       ": skipped, as OpenRadioss skips them");
  }

  // The declaration of the longest declared path that matches the leading tokens, with the number of tokens
  // its path takes in `used`; nullptr when none matches.
  static const KeywordDecl* longest_declared_path(const std::vector<std::string>& tokens, std::size_t& used) {
    const auto& reg = starter_registry();
    for (std::size_t n = std::min(tokens.size(), reg.max_tokens); n >= 1; --n) {
      const auto it = reg.by_path.find(join_path(tokens, n));
      if (it != reg.by_path.end()) {
        used = n;
        return it->second;
      }
    }
    return nullptr;
  }

  // How many of the leading tokens are not numeric fields (`/SURF/PART/ALL/5`: 3).
  static std::size_t leading_words(const std::vector<std::string>& tokens) {
    std::size_t words = 0;
    while (words < tokens.size() &&
           !(std::isdigit(static_cast<unsigned char>(tokens[words].empty() ? 'x' : tokens[words][0])) ||
             tokens[words][0] == '-'))
      ++words;
    return words;
  }

  // The error for a keyword line that no declaration takes: a Radioss keyword radx does not support, one of a
  // Radioss family radx reads others of, or an unknown keyword.
  void report_undeclared_keyword(const std::vector<std::string>& tokens, const TextLine& head) {
    // Strip trailing numeric header fields for the message.
    std::size_t n = tokens.size();
    while (n > 1 && !tokens[n - 1].empty() && std::isdigit(static_cast<unsigned char>(tokens[n - 1][0]))) --n;
    const std::string path = join_path(tokens, n);
    // The id written after the path names the object in the message (/MAT/LAW51/9: material 9).
    std::int64_t written_id = 0;
    if (n < tokens.size() && parse_int(tokens[n], written_id) != NumberStatus::Ok) written_id = 0;
    if (written_id != 0) deck_.unread.push_back({path, written_id, head.pos});
    // `/INCLUDE name` on one line reads as /INCLUDENAME (blanks in keyword fields are dropped).
    if (path.starts_with("/INCLUDE") && !path.starts_with("/INCLUDE_")) {
      diags_.error(
          Diag::UnsupportedKeyword, at(head.pos, 1), About{"/INCLUDE"},
          "/INCLUDE does not include a file in Radioss: OpenRadioss skips the line and does not read "
          "the file; write '#include FILE' (FILE relative to this file, no quotes or in single quotes)");
    } else if (is_known_unsupported(path)) {
      diags_.error(
          Diag::UnsupportedKeyword, at(head.pos, 1), About{path, written_id},
          "the Radioss keyword " + path + " is not supported by radx; " + readable_alternatives(path));
    } else if (const auto family = radioss_family(path); !family.empty()) {
      diags_.error(Diag::UnsupportedKeyword, at(head.pos, 1), About{path, written_id},
                   path + " is not a " + family +
                       " radx reads (a Radioss keyword radx does not implement, or "
                       "a misspelling" +
                       suggested_keyword(path) + "); " + readable_alternatives(path));
    } else {
      diags_.error(Diag::UnknownKeyword, at(head.pos, 1), About{path},
                   "unknown keyword " + path + ": not a keyword radx knows (check the spelling" +
                       suggested_keyword(path) + "); see docs/keywords.md for the keywords radx reads");
    }
  }

  // Whether the deck's version has an established layout of `decl`; the error when it has not.
  bool layout_known_in_version(const KeywordDecl& decl, const TextLine& head) {
    if (deck_.version >= decl.since) return true;
    diags_.error(Diag::UnsupportedVersion, at(head.pos, 1), About{decl.path},
                 std::string(decl.path) + " is not read by radx in a deck of version " +
                     std::to_string(deck_.version) +
                     ": its layout in that format is not established; radx "
                     "reads it in decks of version " +
                     std::to_string(decl.since) + " and newer");
    return false;
  }

  // The text field after a Header::Word keyword's path (`/UNIT/LENGTH/mm`), into rec.header_word; `used`
  // then takes every token. False, with the error, when the line has not exactly one such field.
  bool read_header_word(const KeywordDecl& decl, const std::vector<std::string>& tokens, std::size_t& used,
                        const TextLine& head, KeywordRecord& rec) {
    if (tokens.size() != used + 1) {
      diags_.error(Diag::BadHeader, at(head.pos, 1), About{decl.path},
                   std::string(decl.path) + " takes " + header_help(decl));
      return false;
    }
    // The keyword fields are upper-cased; a unit name keeps its case (Mg is not mg).
    std::string word(trim(head.text.substr(head.text.rfind('/') + 1)));
    std::erase_if(word, [](char c) { return c == ' ' || c == '\t'; });
    rec.header_word = word;
    used = tokens.size();
    return true;
  }

  // //SUBMODEL/id/unit/Vnnnn: the optional version of the submodel's text, checked and taken off `tokens`.
  void take_submodel_version(const KeywordDecl& decl, std::vector<std::string>& tokens, std::size_t used,
                             const TextLine& head) {
    if (!(decl.path == "//SUBMODEL" && tokens.size() > used && tokens.back().size() > 1 &&
          tokens.back()[0] == 'V'))
      return;
    std::int64_t v = 0;
    if (parse_int(std::string_view(tokens.back()).substr(1), v) != NumberStatus::Ok || v != deck_.version) {
      diags_.error(Diag::UnsupportedVersion, at(head.pos, 1), About{decl.path},
                   "the submodel's version " + tokens.back() + " differs from the deck's (" +
                       std::to_string(deck_.version) +
                       "): radx reads a submodel only in the format of the deck around it");
    }
    tokens.pop_back();
  }

  // The numeric fields of the keyword line after the path (tokens from `used` on): checked against the
  // declared header, then read as the record's id and unit id.
  void read_header_fields(const KeywordDecl& decl, const std::vector<std::string>& tokens, std::size_t used,
                          const TextLine& head, KeywordRecord& rec) {
    std::vector<std::int64_t> header;
    bool header_ok = true;
    for (std::size_t k = used; k < tokens.size(); ++k) {
      std::int64_t v = 0;
      if (parse_int(tokens[k], v) != NumberStatus::Ok || v < 0) {
        diags_.error(Diag::BadHeader, at(head.pos, 1), About{decl.path},
                     "'" + tokens[k] + "' in the keyword line is not a valid id: " + std::string(decl.path) +
                         " takes " + header_help(decl));
        header_ok = false;
      }
      header.push_back(v);
    }
    using schema::Header;
    const std::size_t allowed = decl.header == Header::None ? 0 : (decl.header == Header::IdUnit ? 2 : 1);
    if (header_ok && header.size() > allowed) {
      diags_.error(
          Diag::BadHeader, at(head.pos, 1), About{decl.path},
          "too many fields in the keyword line: " + std::string(decl.path) + " takes " + header_help(decl));
    }
    const bool needs_id =
        decl.header == Header::IdUnit || decl.header == Header::Id || decl.header == Header::PartId;
    // An interface written without its id (/INTER/TYPE7) is read by OpenRadioss as interface 1; radx does the
    // same and says so (a second interface 1 is then a duplicate id, as in Radioss).
    if (header_ok && needs_id && header.empty() && std::string_view(decl.path).starts_with("/INTER/")) {
      diags_.warning(Diag::DefaultApplied, at(head.pos, 1), About{decl.path, 1},
                     std::string(decl.path) + " has no interface id in the keyword line: it is read as " +
                         std::string(decl.path) + "/1, the id OpenRadioss gives it; write " +
                         header_help(decl));
      header.push_back(1);
    }
    if (header_ok && needs_id && (header.empty() || header[0] <= 0)) {
      diags_.error(Diag::BadHeader, at(head.pos, 1), About{decl.path},
                   std::string(decl.path) + " needs a positive " + std::string(decl.id_name) +
                       " in the keyword line: " + header_help(decl));
    }
    if (decl.header == Header::UnitOnly) {
      rec.unit_id = header.empty() ? 0 : header[0];
    } else if (decl.header != Header::None) {
      rec.id = header.empty() ? 0 : header[0];
      if (header.size() > 1) rec.unit_id = header[1];
    }
  }

  // The title line of a keyword that has one, at line `cur` of the block ending before `last`; returns the
  // line after it.
  std::size_t read_title(const KeywordDecl& decl, std::size_t cur, std::size_t last, const TextLine& head,
                         KeywordRecord& rec) {
    if (!decl.has_title) return cur;
    const auto& lines = text_.lines;
    if (cur < last) {
      rec.title =
          std::string(trim(lines[cur].text.substr(0, std::min<std::size_t>(100, lines[cur].text.size()))));
      for (auto& c : rec.title)
        if (c == '\t') c = ' ';
      ++cur;
    } else {
      diags_.error(
          Diag::MissingTitle, at(head.pos, 1), About{decl.path, rec.id},
          std::string(decl.path) + " is followed by a title line, then its cards; this block has none");
    }
    return cur;
  }

  // The fixed cards of the deck's version whose condition holds, one line each from line `cur` (a card past
  // the block's end is read as blank); returns the line after them.
  std::size_t read_cards(const KeywordDecl& decl, std::size_t cur, std::size_t last, const TextLine& head,
                         KeywordRecord& rec, const About& about) {
    const auto& lines = text_.lines;
    for (const auto& card : decl.cards) {
      if (!card.in_version(deck_.version)) continue;
      if (card.condition.op != schema::CondOp::Always) {
        const FieldValue* f = rec.find(card.condition.field);
        if (!card.condition.holds(f ? f->i : 0)) continue;
      }
      const TextLine* line = cur < last ? &lines[cur] : nullptr;
      read_card(card, line, head.pos, rec, about);
      if (line) ++cur;
    }
    return cur;
  }

  // Tail::None: the first non-blank line after the cards is reported, and none is read.
  void warn_data_after_cards(const KeywordDecl& decl, std::size_t cur, std::size_t last, const About& about) {
    const auto& lines = text_.lines;
    for (; cur < last; ++cur) {
      if (!trim(lines[cur].text).empty()) {
        diags_.warning(Diag::ExtraData, at(lines[cur].pos, 1), about,
                       "data line after the last card of " + std::string(decl.path) + " is ignored: '" +
                           std::string(trim(lines[cur].text)) + "'");
        break;
      }
    }
  }

  // The record lines from `cur` to `last` into rec.records (blank lines and lines of text skipped).
  void read_record_lines(const KeywordDecl& decl, std::size_t cur, std::size_t last, KeywordRecord& rec,
                         const About& about, SkippedText& skipped) {
    const auto& lines = text_.lines;
    init_table(rec.records, decl.record);
    if (decl.record_lines > 1) {
      read_multi_line_records(decl, cur, last, rec, about, skipped);
      return;
    }
    for (; cur < last; ++cur) {
      if (trim(lines[cur].text).empty() || skip_text_line(lines[cur], skipped)) continue;
      read_record(rec.records, lines[cur], about);
    }
  }

  // Records of decl.record_lines lines each (/BRIC20): the lines of one record, blank and comment lines
  // skipped, joined into one text of 100 columns per line, read as one record at its first line. A block
  // that ends inside a record is an error naming the lines it lacks.
  void read_multi_line_records(const KeywordDecl& decl, std::size_t cur, std::size_t last, KeywordRecord& rec,
                               const About& about, SkippedText& skipped) {
    const auto& lines = text_.lines;
    const auto per = static_cast<std::size_t>(decl.record_lines);
    std::vector<std::size_t> taken;
    for (; cur < last; ++cur) {
      if (trim(lines[cur].text).empty() || skip_text_line(lines[cur], skipped)) continue;
      taken.push_back(cur);
      if (taken.size() < per) continue;
      TextLine joined = lines[taken.front()];
      std::string text;
      bool free = false;
      for (const auto l : taken) {
        std::string part(check_tabs(lines[l], about));
        free = free || part.find(',') != std::string::npos;
        if (part.size() > 100) part.resize(100);  // check_width reports longer lines on each one
        part.resize(100, ' ');
        text += part;
        check_width(lines[l], about);
      }
      joined.text = text;
      if (free)
        diags_.error(Diag::BadInteger, at(lines[taken.front()].pos, 1), about,
                     std::string(decl.path) +
                         " is read in fixed 10-column fields only: write its node lines without commas");
      else
        read_joined_record(rec.records, joined, about);
      taken.clear();
    }
    if (!taken.empty())
      diags_.error(Diag::MissingCard, at(lines[taken.front()].pos, 1), about,
                   std::string(decl.path) + " takes " + std::to_string(per) +
                       " lines per element and the block ends after " + std::to_string(taken.size()) +
                       " line(s) of this one; write the element's remaining node lines");
  }

  // One record from lines joined by read_multi_line_records (no width check: each line had its own).
  void read_joined_record(RecordTable& t, const TextLine& joined, const About& about) {
    const std::size_t errors_before = diags_.error_count();
    const std::string_view text = joined.text;
    t.pos.push_back(joined.pos);
    for (std::size_t k = 0; k < t.fields.size(); ++k) {
      const auto& f = *t.fields[k];
      const std::string_view raw = cell(text, f.first_col, f.last_col);
      FieldValue v = parse_field(f, raw, joined.pos, f.first_col, about);
      switch (f.type) {
        case FieldType::Int: t.ints[k].push_back(v.i); break;
        case FieldType::Real: t.reals[k].push_back(v.r); break;
        case FieldType::String: t.strings[k].push_back(std::move(v.s)); break;
      }
    }
    t.bad.push_back(diags_.error_count() > errors_before ? 1 : 0);
  }

  // Tail::Clauses: every non-blank line is a record; a clause word starts its line, so no line is skipped
  // for starting with text.
  void read_clause_lines(const KeywordDecl& decl, std::size_t cur, std::size_t last, KeywordRecord& rec,
                         const About& about) {
    const auto& lines = text_.lines;
    init_table(rec.records, decl.record);
    for (; cur < last; ++cur)
      if (!trim(lines[cur].text).empty()) read_record(rec.records, lines[cur], about);
  }

  // The id lines from `cur` to `last` into rec.ids (lines of text skipped).
  void read_id_lines(std::size_t cur, std::size_t last, KeywordRecord& rec, const About& about,
                     SkippedText& skipped) {
    const auto& lines = text_.lines;
    for (; cur < last; ++cur)
      if (!skip_text_line(lines[cur], skipped)) read_ids(rec, lines[cur], about);
  }

  // Tail::Text: every non-blank character from `cur` to `last`, with where it was written.
  void read_text_lines(std::size_t cur, std::size_t last, KeywordRecord& rec) {
    const auto& lines = text_.lines;
    for (; cur < last; ++cur) {
      const auto& l = lines[cur];
      for (std::size_t c = 0; c < l.text.size(); ++c) {
        if (l.text[c] == ' ' || l.text[c] == '\t') continue;
        rec.text += l.text[c];
        rec.text_pos.push_back(l.pos);
        rec.text_column.push_back(static_cast<std::uint32_t>(c + 1));
      }
    }
  }

  // The lines of time-history variable names from `cur` (the first always, then each line whose first cell
  // does not start with a number), upper-cased into rec.th_variables; returns the line after them.
  std::size_t read_th_variable_lines(std::size_t cur, std::size_t last, KeywordRecord& rec) {
    const auto& lines = text_.lines;
    bool first_line = true;
    for (; cur < last; ++cur) {
      const auto head_cell = trim(cell(lines[cur].text, 1, 10));
      const bool var_line =
          first_line || (!head_cell.empty() && !std::isdigit(static_cast<unsigned char>(head_cell[0])) &&
                         head_cell[0] != '-' && head_cell[0] != '+');
      if (!var_line) break;
      first_line = false;
      for (int c = 0; c < 10; ++c) {
        const auto name = trim(cell(lines[cur].text, 10 * c + 1, 10 * c + 10));
        if (!name.empty()) rec.th_variables.push_back(upper(name));
      }
    }
    return cur;
  }

  // What follows the cards, by the declared tail, from line `cur` to the block's end `last`.
  void read_tail(const KeywordDecl& decl, std::size_t cur, std::size_t last, KeywordRecord& rec,
                 const About& about) {
    using schema::Tail;
    SkippedText skipped;
    switch (decl.tail) {
      case Tail::None: warn_data_after_cards(decl, cur, last, about); return;
      case Tail::Records: read_record_lines(decl, cur, last, rec, about, skipped); break;
      case Tail::IdList: read_id_lines(cur, last, rec, about, skipped); break;
      case Tail::Text: read_text_lines(cur, last, rec); return;
      case Tail::Clauses: read_clause_lines(decl, cur, last, rec, about); return;
      case Tail::ThVarsThenIds:
        read_id_lines(read_th_variable_lines(cur, last, rec), last, rec, about, skipped);
        break;
      case Tail::ThVarsThenRecords:
        read_record_lines(decl, read_th_variable_lines(cur, last, rec), last, rec, about, skipped);
        break;
    }
    report_skipped(skipped, decl.path, about);
  }

  // Whether `decl` is a keyword the deck may hold once and an earlier record of it is kept already; the
  // warning when so.
  bool repeats_singleton(const KeywordDecl& decl, const TextLine& head, const About& about) {
    if (!decl.singleton) return false;
    for (const auto& r : deck_.records) {
      if (r.decl == &decl) {
        diags_.warning(Diag::DuplicateSingleton, at(head.pos, 1), about,
                       std::string(decl.path) + " appears more than once; only the first (line " +
                           std::to_string(r.pos.line) + ") counts");
        return true;
      }
    }
    return false;
  }

  // One keyword block, lines `first` (the keyword line) to `last` (excluded): the declaration, the header,
  // the title, the cards and the tail, into a record of deck_.
  void read_block(std::size_t first, std::size_t last) {
    const TextLine& head = text_.lines[first];
    auto tokens = split_keyword(head.text);
    if (tokens.empty()) {
      diags_.error(Diag::UnknownKeyword, at(head.pos, 1), About{"/"}, "a lone '/' is not a keyword");
      return;
    }
    if (tokens[0] == "END") return;
    std::size_t used = 0;
    const KeywordDecl* decl = longest_declared_path(tokens, used);
    const std::string written(trim(head.text));
    // The declaration must take every leading non-numeric field: `/SURF/PART/ALL/5` is not
    // `/SURF/PART` with id "ALL".
    // A Header::Word keyword takes one text field after its path (`/UNIT/LENGTH/mm`).
    const bool word_header = decl && decl->header == schema::Header::Word;
    if (decl && used + (word_header ? 1 : 0) < leading_words(tokens)) decl = nullptr;
    if (!decl) {
      report_undeclared_keyword(tokens, head);
      return;
    }
    if (!layout_known_in_version(*decl, head)) return;
    KeywordRecord rec;
    rec.decl = decl;
    rec.written = written;
    rec.pos = head.pos;
    if (word_header && !read_header_word(*decl, tokens, used, head, rec)) return;
    if (decl->path == "/BEGIN" && tokens.size() > used) {
      diags_.note(Diag::IgnoredControlCard, at(head.pos, 1), About{decl->path},
                  written + ": the field after /BEGIN is ignored, as Radioss ignores it");
      used = tokens.size();
    }
    take_submodel_version(*decl, tokens, used, head);
    read_header_fields(*decl, tokens, used, head, rec);
    std::size_t cur = read_title(*decl, first + 1, last, head, rec);
    const About about{decl->path, rec.id, rec.title};
    if (decl->support == schema::Support::Ignored) {
      diags_.note(Diag::IgnoredControlCard, at(head.pos, 1), about,
                  written + " is accepted and ignored: it changes no physics in radx");
    }
    cur = read_cards(*decl, cur, last, head, rec, about);
    read_tail(*decl, cur, last, rec, about);
    if (!place_in_submodel(rec, about)) return;
    if (repeats_singleton(*decl, head, about)) return;
    deck_.records.push_back(std::move(rec));
  }

  // //SUBMODEL opens a submodel, //ENDSUB closes the innermost one; every other keyword is tagged with the
  // innermost open submodel and its ids are shifted by that submodel's offsets, by the kind each id names
  // (the keyword declarations say which), as OpenRadioss's reader does. Ids of 0 or less are not shifted.
  // Returns false when the record is not kept.
  bool place_in_submodel(KeywordRecord& rec, const About& about) {
    using schema::IdKind;
    if (rec.decl->path == "//ENDSUB") {
      if (open_.empty()) {
        diags_.error(Diag::UnbalancedSubmodel, at(rec.pos, 1), about,
                     "//ENDSUB with no open //SUBMODEL: each //ENDSUB closes one //SUBMODEL above it");
      } else {
        open_.pop_back();
      }
      return false;
    }
    rec.submodel = open_.empty() ? -1 : open_.back();
    if (rec.submodel >= 0) {
      if (rec.decl->path == "/BEGIN") {
        diags_.error(Diag::UnsupportedKeyword, at(rec.pos, 1), about,
                     "/BEGIN inside a //SUBMODEL (its own version and units) is not read by radx: give the "
                     "submodel's unit system on its keyword line, //SUBMODEL/submodel_ID/unit_ID");
        return false;
      }
      const Submodel& sm = deck_.submodels[static_cast<std::size_t>(rec.submodel)];
      const auto shift = [&](std::int64_t& v, IdKind k) {
        if (v > 0 && k != IdKind::None) v += sm.offset(k);
      };
      using schema::Header;
      if (rec.decl->header != Header::None && rec.decl->header != Header::UnitOnly &&
          rec.decl->header != Header::Word)
        shift(rec.id, rec.decl->id_kind);
      shift(rec.unit_id, IdKind::Other);
      for (auto& f : rec.fields) {
        if (f.decl->type != FieldType::Int || f.decl->ref == IdKind::None) continue;
        shift(f.i, f.decl->ref);
        f.r = static_cast<double>(f.i);
      }
      for (std::size_t k = 0; k < rec.records.fields.size(); ++k) {
        const auto& f = *rec.records.fields[k];
        if (f.type != FieldType::Int) continue;
        for (auto& v : rec.records.ints[k]) shift(v, f.ref);
      }
      for (auto& v : rec.ids) shift(v, rec.decl->list_kind);
    }
    if (rec.decl->path == "//SUBMODEL") {
      Submodel sm;
      sm.id = rec.id;
      sm.title = rec.title;
      sm.pos = rec.pos;
      sm.parent = rec.submodel;
      const Submodel* parent =
          sm.parent >= 0 ? &deck_.submodels[static_cast<std::size_t>(sm.parent)] : nullptr;
      sm.unit_id = rec.unit_id != 0 ? rec.unit_id : (parent ? parent->unit_id : 0);
      // off_def stands for every kind whose own offset is 0; the enclosing offsets add up.
      const std::int64_t def = rec.get_int("off_def");
      const auto own = [&](std::string_view field) {
        const std::int64_t v = rec.get_int(field);
        return v != 0 ? v : def;
      };
      std::array<std::int64_t, 8> o{};
      o[static_cast<std::size_t>(IdKind::Node)] = own("off_nod");
      o[static_cast<std::size_t>(IdKind::Element)] = own("off_ele");
      o[static_cast<std::size_t>(IdKind::Part)] = own("off_part");
      o[static_cast<std::size_t>(IdKind::Material)] = own("off_mat");
      o[static_cast<std::size_t>(IdKind::Property)] = own("off_type");
      o[static_cast<std::size_t>(IdKind::Submodel)] = own("off_sub");
      o[static_cast<std::size_t>(IdKind::Other)] = def;
      for (std::size_t k = 0; k < o.size(); ++k) sm.offsets[k] = o[k] + (parent ? parent->offsets[k] : 0);
      open_.push_back(static_cast<std::int32_t>(deck_.submodels.size()));
      deck_.submodels.push_back(std::move(sm));
    }
    return true;
  }

  static std::string header_help(const KeywordDecl& d) {
    using schema::Header;
    const std::string p(d.path);
    switch (d.header) {
      case Header::None: return "no id (" + p + ")";
      case Header::IdUnit: return p + "/" + std::string(d.id_name) + "[/unit_ID]";
      case Header::Id: return p + "/" + std::string(d.id_name);
      case Header::UnitOnly: return p + "[/unit_ID]";
      case Header::PartId: return p + "/part_ID";
      case Header::OptionalId: return p + "[/" + std::string(d.id_name) + "]";
      case Header::Word: return p + "/" + std::string(d.id_name);
    }
    return p;
  }

  std::optional<UnitSystem> units_from(const KeywordRecord& r, std::string_view mname, std::string_view lname,
                                       std::string_view tname) {
    UnitSystem u;
    bool ok = true;
    auto one = [&](std::string_view field, char kind, double& factor, std::string& name) {
      const FieldValue* f = r.find(field);
      const std::string text = f ? std::string(trim(f->s)) : std::string();
      if (text.empty()) return;  // blank: SI base unit
      const auto v = unit_factor(text, kind);
      if (!v) {
        diags_.error(Diag::BadUnit, at(f->pos, f->column), About{r.decl->path, r.id, r.title},
                     "unknown " +
                         std::string(kind == 'M'   ? "mass"
                                     : kind == 'L' ? "length"
                                                   : "time") +
                         " unit '" + text + "'; accepted: " + unit_names_accepted(kind) +
                         ", or a numeric factor to SI");
        ok = false;
        return;
      }
      factor = *v;
      name = text;
    };
    one(mname, 'M', u.mass, u.mass_name);
    one(lname, 'L', u.length, u.length_name);
    one(tname, 'T', u.time, u.time_name);
    if (!ok) return std::nullopt;
    return u;
  }

  // The declared dimension of a field, or the one an override selects from another field's value.
  static schema::Dim field_dimension(const KeywordRecord& r, const FieldValue& f) {
    for (const auto& o : r.decl->dim_overrides) {
      if (o.field != f.decl->name) continue;
      const FieldValue* w = r.find(o.when_field);
      if (!w) continue;
      const std::string text = w->decl->type == FieldType::String ? upper(trim(w->s)) : std::to_string(w->i);
      if (std::find(o.when_values.begin(), o.when_values.end(), text) != o.when_values.end())
        return o.dimension;
    }
    return f.decl->dimension;
  }

  // Decks of version 90 and older have no unit cards in /BEGIN: `/UNIT/MASS/Mg`, `/UNIT/LENGTH/mm` and
  // `/UNIT/TIME/s` name the work units, and the input units are the work units (nothing is converted).
  // Radioss reads these three keywords only in such decks; in newer decks they are ignored.
  void global_units_of_old_decks() {
    for (const auto& r : deck_.records) {
      const char kind = r.decl->path == "/UNIT/MASS"     ? 'M'
                        : r.decl->path == "/UNIT/LENGTH" ? 'L'
                        : r.decl->path == "/UNIT/TIME"   ? 'T'
                                                         : 0;
      if (kind == 0) continue;
      const About about{r.decl->path};
      if (deck_.version > 90) {
        diags_.warning(Diag::IgnoredControlCard, at(r.pos, 1), about,
                       std::string(r.decl->path) + " is ignored in a deck of version " +
                           std::to_string(deck_.version) +
                           ": it names the units only in decks of version 90 and older; give them in /BEGIN "
                           "cards 3 and 4");
        continue;
      }
      const auto f = unit_factor(r.header_word, kind);
      if (!f) {
        diags_.error(Diag::BadUnit, at(r.pos, 1), about,
                     "unknown unit '" + r.header_word + "'; accepted: " + unit_names_accepted(kind) +
                         ", or a numeric factor to SI");
        continue;
      }
      deck_.units_named = true;
      for (UnitSystem* u : {&deck_.input_units, &deck_.work_units}) {
        double& factor = kind == 'M' ? u->mass : kind == 'L' ? u->length : u->time;
        std::string& name = kind == 'M' ? u->mass_name : kind == 'L' ? u->length_name : u->time_name;
        factor = *f;
        name = r.header_word;
      }
    }
  }

  void convert_units() {
    std::map<std::int64_t, UnitSystem> systems;
    for (const auto& r : deck_.records) {
      if (r.decl->path == "/BEGIN") {
        deck_.run_name = r.get_string("RUNNAME");
        for (const char* name :
             {"input_mass", "input_length", "input_time", "work_mass", "work_length", "work_time"}) {
          const FieldValue* f = r.find(name);
          if (f != nullptr && !trim(f->s).empty()) deck_.units_named = true;
        }
        if (auto u = units_from(r, "input_mass", "input_length", "input_time")) deck_.input_units = *u;
        if (auto u = units_from(r, "work_mass", "work_length", "work_time")) deck_.work_units = *u;
      } else if (r.decl->path == "/UNIT") {
        if (auto u = units_from(r, "MUNIT", "LUNIT", "TUNIT")) systems[r.id] = *u;
      }
    }
    global_units_of_old_decks();
    const UnitSystem& w = deck_.work_units;
    for (auto& r : deck_.records) {
      const UnitSystem* u = &deck_.input_units;
      // A keyword without a unit of its own in a submodel takes the submodel's (reported there if missing).
      const std::int64_t unit_id = r.unit_id != 0 || r.submodel < 0
                                       ? r.unit_id
                                       : deck_.submodels[static_cast<std::size_t>(r.submodel)].unit_id;
      if (unit_id != 0) {
        const auto it = systems.find(unit_id);
        if (it == systems.end()) {
          if (r.unit_id != 0)
            diags_.error(Diag::MissingReference, at(r.pos, 1), About{r.decl->path, r.id, r.title},
                         "unit system " + std::to_string(r.unit_id) +
                             " named in the keyword line has no /UNIT/" + std::to_string(r.unit_id));
          continue;
        }
        u = &it->second;
        deck_.units_named = true;
      }
      const double fm = u->mass / w.mass;
      const double fl = u->length / w.length;
      const double ft = u->time / w.time;
      r.unit_factors = {fm, fl, ft};
      if (fm == 1.0 && fl == 1.0 && ft == 1.0) continue;
      auto factor = [&](schema::Dim d) { return std::pow(fm, d.m) * std::pow(fl, d.l) * std::pow(ft, d.t); };
      for (auto& f : r.fields) {
        if (f.decl->type != FieldType::Real) continue;
        const schema::Dim d = field_dimension(r, f);
        // Values of 1e19 and beyond stand for "never" or "no limit" and stay as they are.
        if (!d.none() && std::abs(f.r) < 1e19) f.r *= factor(d);
      }
      for (std::size_t k = 0; k < r.records.fields.size(); ++k) {
        const auto& f = *r.records.fields[k];
        if (f.type != FieldType::Real || f.dimension.none()) continue;
        const double s = factor(f.dimension);
        for (auto& v : r.records.reals[k])
          if (std::abs(v) < 1e19) v *= s;
      }
    }
  }

  DeckText& text_;
  Diagnostics& diags_;
  Deck& deck_;
  std::vector<std::int32_t> open_;  // the open //SUBMODELs, innermost last (indices into deck_.submodels)
};

std::size_t one_file_start(const DeckText& text) {
  for (std::size_t i = 0; i < text.lines.size(); ++i) {
    const auto& l = text.lines[i].text;
    if (!l.empty() && l.front() == '/' && upper(trim(l)).rfind("/END/ENGINE", 0) == 0) return i + 1;
  }
  return 0;
}

}  // namespace

// A unit name as Radioss reads it: an SI prefix (y z a f p n u or mu or the Greek mu, m c d, da h k K M G T P
// E Z Y, or none) before the base unit of the kind (g for mass, m for length, s for time). radx also reads a
// few names Radioss does not (t, ton, lb, in, ft, min, h as the hour) and a numeric factor to SI.
std::optional<double> unit_factor(std::string_view name, char kind) {
  name = trim(name);
  struct U {
    std::string_view n;
    double f;
  };
  static const U extra_mass[] = {{"t", 1e3}, {"ton", 1e3}, {"lb", 0.45359237}};
  static const U extra_length[] = {{"in", 0.0254}, {"ft", 0.3048}};
  static const U extra_time[] = {{"min", 60.}, {"h", 3600.}};
  auto look = [&](const auto& table) -> std::optional<double> {
    for (const auto& u : table)
      if (u.n == name) return u.f;
    return std::nullopt;
  };
  std::optional<double> f;
  if (kind == 'M') f = look(extra_mass);
  if (kind == 'L') f = look(extra_length);
  if (kind == 'T') f = look(extra_time);
  if (f) return f;
  const char base = kind == 'M' ? 'g' : kind == 'L' ? 'm' : 's';
  if (!name.empty() && name.back() == base) {
    static const U prefixes[] = {
        {"y", 1e-24}, {"z", 1e-21}, {"a", 1e-18}, {"f", 1e-15},       {"p", 1e-12},
        {"n", 1e-9},  {"u", 1e-6},  {"mu", 1e-6}, {"\xc2\xb5", 1e-6}, {"\xce\xbc", 1e-6},
        {"m", 1e-3},  {"c", 1e-2},  {"d", 1e-1},  {"", 1.0},          {"da", 1e1},
        {"h", 1e2},   {"k", 1e3},   {"K", 1e3},   {"M", 1e6},         {"G", 1e9},
        {"T", 1e12},  {"P", 1e15},  {"E", 1e18},  {"Z", 1e21},        {"Y", 1e24}};
    const std::string_view prefix = name.substr(0, name.size() - 1);
    for (const auto& p : prefixes)
      if (p.n == prefix) return kind == 'M' ? p.f * 1e-3 : p.f;  // the SI mass unit is the kg, not the g
  }
  double v = 0;
  if (parse_real(name, v) == NumberStatus::Ok && v > 0) return v;
  return std::nullopt;
}

Deck read_starter_deck(const std::string& path, Diagnostics& diags, const ReadOptions& opt) {
  Deck deck;
  DeckText text;
  if (!load_deck_text(path, text, diags)) {
    deck.files = text.files;
    return deck;
  }
  deck.files = text.files;
  deck.allow_substitutions = opt.allow_substitutions;
  StarterReader reader(text, diags, deck);
  reader.read(opt.allow_one_file ? one_file_start(text) : 0);
  return deck;
}

// ---------------------------------------------------------------------------------------------------
// Accessors.

int RecordTable::column(std::string_view name) const {
  for (std::size_t k = 0; k < fields.size(); ++k)
    if (fields[k]->name == name) return static_cast<int>(k);
  return -1;
}

std::string_view KeywordRecord::keyword() const {
  return decl ? decl->path : std::string_view{};
}

const FieldValue* KeywordRecord::find(std::string_view name) const {
  for (const auto& f : fields)
    if (f.decl->name == name) return &f;
  return nullptr;
}
std::int64_t KeywordRecord::get_int(std::string_view name) const {
  const auto* f = find(name);
  return f ? f->i : 0;
}
double KeywordRecord::get_real(std::string_view name) const {
  const auto* f = find(name);
  return f ? (f->decl->type == FieldType::Int ? static_cast<double>(f->i) : f->r) : 0.0;
}
std::string KeywordRecord::get_string(std::string_view name) const {
  const auto* f = find(name);
  return f ? f->s : std::string();
}
bool KeywordRecord::given(std::string_view name) const {
  const auto* f = find(name);
  return f && !f->blank;
}

std::vector<const KeywordRecord*> Deck::of(std::string_view path) const {
  std::vector<const KeywordRecord*> out;
  for (const auto& r : records)
    if (r.decl->path == path) out.push_back(&r);
  return out;
}

Where Deck::where(SourcePos p, int column) const {
  return Where{p.file < files.size() ? std::string_view(files[p.file]) : std::string_view{},
               static_cast<int>(p.line), column};
}

}  // namespace radx
