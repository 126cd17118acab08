#include "parser/reading/deck_echo.hpp"

#include <algorithm>
#include <iomanip>
#include <map>
#include <ostream>
#include <set>
#include <sstream>

namespace radx {

using schema::FieldDecl;
using schema::FieldType;

namespace {

std::string value_text(const FieldValue& v) {
  std::ostringstream os;
  switch (v.decl->type) {
    case FieldType::Int: os << v.i; break;
    case FieldType::Real: os << std::setprecision(8) << v.r; break;
    case FieldType::String: os << '\'' << v.s << '\''; break;
  }
  return os.str();
}

std::string dim_text(schema::Dim d) {
  if (d.none()) return "-";
  std::string s;
  auto part = [&](const char* sym, int e) {
    if (e == 0) return;
    if (!s.empty()) s += " ";
    s += sym;
    if (e != 1) s += "^" + std::to_string(e);
  };
  part("M", d.m);
  part("L", d.l);
  part("T", d.t);
  return s;
}

std::string versions_text(int since, int until) {
  if (since <= schema::kAnyVersion && until >= schema::kLastVersion) return "all";
  if (since <= schema::kAnyVersion) return "<= " + std::to_string(until);
  if (until >= schema::kLastVersion) return ">= " + std::to_string(since);
  return std::to_string(since) + "-" + std::to_string(until);
}

std::string condition_text(const schema::Condition& c) {
  const std::string f(c.field);
  switch (c.op) {
    case schema::CondOp::Always: return "";
    case schema::CondOp::Eq: return "only if " + f + " = " + std::to_string(c.a);
    case schema::CondOp::Ne: return "only if " + f + " != " + std::to_string(c.a);
    case schema::CondOp::Gt: return "only if " + f + " > " + std::to_string(c.a);
    case schema::CondOp::InRange:
      return "only if " + f + " in [" + std::to_string(c.a) + ", " + std::to_string(c.b) + "]";
  }
  return "";
}

std::string rule_text(const FieldDecl& f) {
  std::ostringstream os;
  if (f.required) os << "required; ";
  if (f.zero_default) os << "0 -> " << *f.zero_default << "; ";
  if (!f.allowed.empty()) {
    os << "one of {";
    for (std::size_t i = 0; i < f.allowed.size(); ++i) os << (i ? ", " : "") << f.allowed[i];
    os << "}; ";
  }
  if (f.min) os << (f.min_exclusive ? "> " : ">= ") << *f.min << "; ";
  if (f.max) os << (f.max_exclusive ? "< " : "<= ") << *f.max << "; ";
  if (f.gate_first > 0) os << "read only if columns " << f.gate_first << "-" << f.gate_last << " hold text; ";
  if (f.ignored) os << "read, not used; ";
  std::string s = os.str();
  if (s.size() >= 2) s.resize(s.size() - 2);
  return s.empty() ? "-" : s;
}

void field_rows(std::ostream& os, const std::vector<FieldDecl>& fields) {
  os << "| field | columns | type | versions | unit | rule | meaning |\n|---|---|---|---|---|---|---|\n";
  for (const auto& f : fields) {
    const char* type = f.type == FieldType::Int ? "I" : (f.type == FieldType::Real ? "R" : "S");
    os << "| " << f.name << " | " << f.first_col << "-" << f.last_col << " | " << type << " | "
       << versions_text(f.since, f.until) << " | " << dim_text(f.dimension) << " | " << rule_text(f) << " | "
       << f.meaning << " |\n";
  }
}

// The deck versions at which a keyword's layout changes: where a band of one of its fields or cards starts
// or ends, mapped to the first version radx reads at or after that point.
std::vector<int> layout_changes(const schema::KeywordDecl& k) {
  std::set<int> at;
  auto add = [&at](int since, int until) {
    for (int v : {since, until + 1}) {
      if (v <= schema::kAnyVersion || v > schema::kDeckVersions.back()) continue;
      const auto first = std::find_if(schema::kDeckVersions.begin(), schema::kDeckVersions.end(),
                                      [v](int d) { return d >= v; });
      if (first != schema::kDeckVersions.end() && *first > schema::kDeckVersions.front()) at.insert(*first);
    }
  };
  auto fields = [&add](const std::vector<FieldDecl>& fs) {
    for (const auto& f : fs) add(f.since, f.until);
  };
  for (const auto& c : k.cards) {
    add(c.since, c.until);
    fields(c.fields);
  }
  fields(k.record.fields);
  return {at.begin(), at.end()};
}

void deck_versions_section(std::ostream& os) {
  os << "## Deck versions\n\n"
     << "radx reads the starter decks of the Radioss formats (`/BEGIN` INVERS)";
  for (std::size_t i = 0; i < schema::kDeckVersions.size(); ++i)
    os << (i == 0 ? " " : (i + 1 == schema::kDeckVersions.size() ? " and " : ", "))
       << schema::kDeckVersions[i];
  os << "; older formats (41 to 51) and other numbers are refused (RX307), a newer one is read in the "
     << schema::kDeckVersions.back() << " layouts with a warning.\n\n"
     << "Each keyword is read in the layout OpenRadioss reads it in: its reader file is the newest of the "
        "reference's versioned CFG directories that has the keyword, and in that file the "
        "`FORMAT(radiossNNN)` "
        "block with the highest NNN at or below the deck's version (or, when there is none, the lowest one "
        "above it: the element lines, `/BOX/RECTA` and `/RANDOM` have only a 110 block, which Radioss also "
        "applies to 90 and 100 decks). The field and card tables above give each band in their `versions` "
        "column. Semantics that change with the version:\n\n"
     << "- Version 90 decks have no unit cards in `/BEGIN`: `/UNIT/MASS/u`, `/UNIT/LENGTH/u` and "
        "`/UNIT/TIME/u` name the work units, and the input units are the work units. In newer decks these "
        "three keywords are ignored (warning), as Radioss ignores them.\n"
     << "- `/MAT/LAW2` up to 130 reads RHO_ref (columns 21-40) only when columns 11-20 hold text: a "
        "left-justified RHO_I leaves them blank and RHO_ref is then not read (warning when text is there). "
        "Its "
        "card 2 has no Iflag, so card 3 is always a, b, n.\n"
     << "- `/INTER/TYPE7` up to 100 reads the adaptive-meshing card (Iadm = 2) after the thermal card, from "
        "110 "
        "before; the 90 layout reads its thermal card for Ithe > 1.\n"
     << "- A keyword refused in old decks (its layout there is not established) is refused by name with "
        "RX307.\n\n"
     << "Versions at which each starter keyword's layout changes (a keyword not listed reads the same in "
        "every version):\n\n"
     << "| keyword | layout changes at | read from |\n|---|---|---|\n";
  for (const auto& k : schema::starter_keywords()) {
    const auto changes = layout_changes(k);
    if (changes.empty() && k.since <= schema::kAnyVersion) continue;
    os << "| " << k.path << " | ";
    for (std::size_t i = 0; i < changes.size(); ++i) os << (i ? ", " : "") << changes[i];
    if (changes.empty()) os << "-";
    os << " | " << (k.since > schema::kAnyVersion ? std::to_string(k.since) : std::string("all")) << " |\n";
  }
  os << "\n";
}

// How //SUBMODEL, /TRANSFORM and /MOVE_FUNCT act (parser/reading/deck_reader.cpp,
// parser/building/build_transforms.cpp).
void assembly_section(std::ostream& os) {
  os << "## Submodels and transforms\n\n"
     << "- `//SUBMODEL/submodel_ID[/unit_ID]` opens a submodel and `//ENDSUB` closes the innermost open one "
        "(an unbalanced pair is RX312). Submodels nest; an `#include` inside one belongs to it, so one file "
        "included in two submodels with different offsets is built twice.\n"
     << "- Inside a submodel every id is shifted by the submodel's offset for the kind of object it names: "
        "nodes off_nod, elements off_ele, parts off_part (an element block's part too), materials off_mat, "
        "properties off_type, submodels off_sub, everything else (groups, surfaces, functions, skews, boxes, "
        "units, interfaces, ...) off_def; a specific offset of 0 takes off_def. The object's own id and "
        "every "
        "id it refers to are shifted, also references to objects outside the submodel; ids of 0 or less are "
        "not. Offsets add up through nested submodels. Diagnostics give the ids as shifted and the file and "
        "line as written.\n"
     << "- A keyword with no unit id of its own inside a submodel is read in the submodel's unit system (or "
        "the one of the submodel around it).\n"
     << "- `/TRANSFORM/TRA`, `/ROT`, `/SCA` and `/SYM` move a node group (grnod_ID) or every node written "
        "inside a submodel and the submodels nested in it (sub_ID), never both. Submodel transforms are "
        "applied first, right after the nodes are read, each submodel's own in deck order and then those of "
        "the submodels around it; points and directions written inside a moved submodel (box corners, skew "
        "frames, rigid-wall points and velocities, initial velocities without a skew) move with it. "
        "Node-group transforms follow once the groups are built (a `/GRNOD/BOX` selects with the coordinates "
        "before them), in deck order, each on the coordinates the previous ones left. Two nodes "
        "(node_ID1, node_ID2) replace the two points or the vector, taken where the transform sees them.\n"
     << "- TRA: x + t. ROT: right-handed rotation by Angle degrees about the axis from point 1 to point 2. "
        "SCA: c + s (x - c) per axis about node_IDc (else the origin); a scale factor of 0 means 1. SYM: "
        "mirror in the plane through point 1 normal to point 1 -> 2. A rotation axis or a mirror normal of "
        "zero length is RX605.\n"
     << "- A mirror (SYM, or a negative scale factor) turns bricks inside out: their faces n1-n4 and n5-n8 "
        "are swapped so that their volume stays positive, as Radioss does (a note says how many); shells "
        "keep their connectivity and their normal flips. Element geometry is checked as written, before "
        "any transform.\n"
     << "- `/MOVE_FUNCT/fct_ID` scales then shifts the points of `/FUNCT/fct_ID`: X Ascalex + Ashiftx, "
        "Y Fscaley + Fshifty (0 scales mean 1); a negative Ascalex also reverses the points so that the "
        "abscissas stay increasing. Several apply in deck order; one naming no function is RX402.\n\n";
}

}  // namespace

std::vector<std::string> echo_keyword(const KeywordRecord& r) {
  std::vector<std::string> lines;
  for (const auto& v : r.fields) {
    std::ostringstream os;
    std::string value = value_text(v);
    if (v.defaulted)
      value += " (default)";
    else if (v.blank)
      value += " (blank)";
    os << "    " << std::left << std::setw(14) << v.decl->name << std::setw(24) << value << v.decl->meaning;
    lines.push_back(os.str());
  }
  return lines;
}

namespace {

// The families of the support table: a keyword belongs to the first family one of whose prefixes starts its
// path (a prefix ending in '/' takes every keyword under it, one without takes that keyword and its forms).
struct SupportFamily {
  std::string_view name;
  std::vector<std::string_view> prefixes;
};

const std::vector<SupportFamily>& support_families() {
  static const std::vector<SupportFamily> families = {
      {"Elements",
       {"/SHELL", "/SH3N", "/BRICK", "/BRIC20", "/TETRA4", "/TETRA10", "/SPRING", "/TRUSS", "/BEAM", "/QUAD",
        "/PENTA6", "/SPHCEL", "/XELEM"}},
      {"Element properties", {"/PROP/"}},
      {"Materials", {"/MAT/"}},
      {"Failure models", {"/FAIL/"}},
      {"Contact", {"/INTER/", "/CTCLAW"}},
      {"Rigid bodies, walls, ties", {"/RBODY", "/RWALL", "/RBE", "/RLINK", "/CYL_JOINT"}},
      {"Loads and initial conditions",
       {"/BCS", "/IMPVEL", "/IMPDISP", "/IMPACC", "/CLOAD", "/PLOAD", "/GRAV", "/INIVEL", "/LOAD", "/PBLAST",
        "/ADMAS", "/INISTA", "/INISHE", "/INIBRI"}},
      {"Outputs", {"/TH/", "/ANIM", "/SECT", "/ACCEL", "/TFILE", "/H3D", "/OUTP", "/PRINT"}},
      {"Run controls (engine deck)", {"/RUN", "/DT", "/STOP", "/PARITH", "/VERS"}},
  };
  return families;
}

// The family of `path`, or "Model set-up" (nodes, groups, surfaces, sets, functions, skews, units, ...).
std::string_view support_family(std::string_view path) {
  for (const auto& f : support_families())
    for (auto p : f.prefixes)
      if (path.starts_with(p) && (p.ends_with('/') || path.size() == p.size() || path[p.size()] == '/'))
        return f.name;
  return "Model set-up";
}

// "What radx supports": per family, the keywords radx runs, and the Radioss keywords it knows and refuses by
// name (it never runs another formulation in their place).
void write_support_table(std::ostream& os) {
  std::vector<std::string_view> order;
  for (const auto& f : support_families()) order.push_back(f.name);
  order.insert(order.begin(), "Model set-up");
  std::map<std::string_view, std::vector<std::string>> runs, refused, ignored;
  // Each keyword as the table shows it, with its other spellings: "`/MAT/LAW2` (`/MAT/PLAS_JOHNS`,
  // `/MAT/LAW02`)".
  auto shown = [](std::string_view path, const std::vector<std::string_view>& aliases,
                  std::string_view note) {
    std::string text = "`" + std::string(path) + "`" + std::string(note);
    for (std::size_t k = 0; k < aliases.size(); ++k)
      text += (k == 0 ? " (`" : ", `") + std::string(aliases[k]) + "`" + (k + 1 == aliases.size() ? ")" : "");
    return text;
  };
  for (const auto& k : schema::starter_keywords())
    (k.support == schema::Support::Ignored ? ignored : runs)[support_family(k.path)].push_back(
        shown(k.path, k.aliases, ""));
  for (const auto& k : schema::engine_keywords()) {
    auto& bucket = k.support == schema::Support::Read          ? runs
                   : k.support == schema::Support::Unsupported ? refused
                                                               : ignored;
    bucket[support_family(k.path)].push_back(shown(k.path, k.aliases, " (engine)"));
  }
  for (auto root : schema::known_unsupported_roots())
    refused[support_family(root)].push_back(shown(root, {}, ""));
  auto list = [](const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out.empty() ? std::string("-") : out;
  };
  os << "## What radx supports\n\n"
     << "Every keyword radx declares, by family: those it runs, those it accepts and ignores (they change no "
        "result, or are outputs it does not write: a note or a warning), and the Radioss keywords it knows "
        "and refuses by name (it never runs another formulation in their place; `--allow-substitutions` runs "
        "the nearest one it has where a formulation flag, not a keyword, is missing). The cards of each are "
        "below.\n\n"
     << "| family | runs | accepted, ignored or not written | refused by name |\n|---|---|---|---|\n";
  for (auto f : order)
    os << "| " << f << " | " << list(runs[f]) << " | " << list(ignored[f]) << " | " << list(refused[f])
       << " |\n";
  os << "\n";
}

}  // namespace

void write_keyword_reference(std::ostream& os) {
  os << "# radx keyword reference\n\n"
     << "Generated from the keyword declarations (`parser/keywords/keywords_starter.cpp`, "
        "`parser/keywords/keywords_engine.cpp`) by "
        "`radx keywords --markdown`; do not edit by hand (`cmake --build build --target keyword-docs`).\n\n"
     << "Columns are 1-based and inclusive. Units: M mass, L length, T time (the field is converted from the "
        "deck's input units to its work units). Versions are the `/BEGIN` deck version (INVERS).\n\n";
  write_support_table(os);
  os << "## Starter keywords\n\n";
  for (const auto& k : schema::starter_keywords()) {
    os << "### " << k.path << "\n\n";
    if (!k.aliases.empty()) {
      os << "Also written:";
      for (auto a : k.aliases) os << " `" << a << "`";
      os << ".\n\n";
    }
    os << k.meaning << (k.support == schema::Support::Ignored ? " **Accepted and ignored by radx.**" : "")
       << "\n\n";
    os << "Title line: " << (k.has_title ? "yes" : "no") << ".\n\n";
    if (k.header == schema::Header::Word)
      os << "Keyword line: `" << k.path << "/" << k.id_name << "` (one text field, case kept).\n\n";
    if (k.since > schema::kAnyVersion)
      os << "Read in decks of version " << k.since << " and newer; refused in older decks (RX307).\n\n";
    for (const auto& c : k.cards) {
      os << "**" << c.name << "**";
      const auto cond = condition_text(c.condition);
      if (!cond.empty()) os << " (" << cond << ")";
      if (c.since > schema::kAnyVersion || c.until < schema::kLastVersion)
        os << " (versions " << versions_text(c.since, c.until) << ")";
      os << "\n\n";
      field_rows(os, c.fields);
      os << "\n";
    }
    for (const auto& o : k.dim_overrides) {
      os << "Unit of " << o.field << ": " << dim_text(o.dimension) << " when " << o.when_field << " is";
      for (auto v : o.when_values) os << ' ' << v;
      os << ".\n\n";
    }
    using schema::Tail;
    switch (k.tail) {
      case Tail::None: break;
      case Tail::Records:
        if (k.record_lines > 1)
          os << "Then one record per " << k.record_lines
             << " lines, fixed 10-column fields only (columns 101-200 below are columns 1-100 of a record's "
                "second line, 201-300 of its third):\n\n";
        else
          os << "Then one record per line:\n\n";
        field_rows(os, k.record.fields);
        os << "\n";
        break;
      case Tail::IdList: os << "Then ids, 10 per line in 10-column cells.\n\n"; break;
      case Tail::Text:
        os << "Then text lines, joined with blanks removed.\n\n";
        if (!k.text_meaning.empty()) os << k.text_meaning << "\n\n";
        break;
      case Tail::Clauses:
        os << "Then clause lines: a clause word in columns 1-10 (a blank word carries on the clause above), "
              "then its ids in 10-column cells:\n\n";
        field_rows(os, k.record.fields);
        os << "\n";
        if (!k.text_meaning.empty()) os << k.text_meaning << "\n\n";
        break;
      case Tail::ThVarsThenIds:
        os << "Then variable-name lines (10-column cells), then object ids.\n\n";
        break;
      case Tail::ThVarsThenRecords:
        os << "Then variable-name lines (10-column cells), then one object per line:\n\n";
        field_rows(os, k.record.fields);
        os << "\n";
        break;
    }
  }
  deck_versions_section(os);
  assembly_section(os);
  os << "## Engine keywords\n\nFree format: values separated by blanks or commas, one declared line each. "
        "Every keyword of the Radioss engine deck is listed; the radx column says what radx does with it: "
        "**read**; **ignored** (it changes no result: a note, RX303); **not written** (an output radx does "
        "not "
        "write: a warning, RX311, and the run goes on); **refused** (it changes the results and radx cannot "
        "run "
        "it: an error, RX302). A keyword radx does not read also takes any further fields after its path, "
        "and "
        "its data lines are passed over. A keyword whose first field is none of these is unknown (RX301).\n\n"
     << "| keyword | header fields | data lines | radx | meaning |\n|---|---|---|---|---|\n";
  for (const auto& k : schema::engine_keywords()) {
    os << "| " << k.path;
    for (auto a : k.aliases) os << " (" << a << ")";
    os << " | ";
    for (auto h : k.header_fields) os << h << " ";
    os << "| ";
    for (const auto& l : k.lines) {
      os << "[";
      for (std::size_t i = 0; i < l.names.size(); ++i) os << (i ? " " : "") << l.names[i];
      os << "] (" << l.required << " required) ";
    }
    if (k.id_lines) os << "ids, any number of lines";
    os << " | ";
    switch (k.support) {
      case schema::Support::Read: os << "read"; break;
      case schema::Support::Ignored: os << "ignored: " << k.reason; break;
      case schema::Support::NotWritten: os << "not written: " << k.reason; break;
      case schema::Support::Unsupported: os << "refused: " << k.reason; break;
    }
    os << " | " << k.meaning << " |\n";
  }
  os << "\n## Diagnostic codes\n\n| code | meaning |\n|---|---|\n";
  for (auto d : all_diag_codes()) os << "| " << diag_code(d) << " | " << diag_summary(d) << " |\n";
}

}  // namespace radx
