// Keywords as data. Every card of every keyword radx reads is declared once here-by-type and in
// keywords_starter.cpp / keywords_engine.cpp by content: field name, columns, type, default, physical
// dimension, allowed values, meaning and the deck versions it belongs to. The reader, the listing echo
// and the generated keyword reference (docs/keywords.md) are all driven by these declarations.
#pragma once

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <vector>

namespace radx::schema {

enum class FieldType : std::uint8_t {
  Int,     // integer, right-justified in its cells
  Real,    // Fortran real forms accepted (1.D3, 1E-3, .5, 1.5d-3, 210000003000)
  String,  // free text, trimmed
};

// Physical dimension as exponents of mass, length and time: the unit conversion of a real field is
// (M_in/M_work)^m (L_in/L_work)^l (T_in/T_work)^t.
struct Dim {
  std::int8_t m = 0;
  std::int8_t l = 0;
  std::int8_t t = 0;
  [[nodiscard]] constexpr bool none() const { return m == 0 && l == 0 && t == 0; }
};

namespace dim {
inline constexpr Dim none{0, 0, 0};
inline constexpr Dim mass{1, 0, 0};
inline constexpr Dim length{0, 1, 0};
inline constexpr Dim time{0, 0, 1};
inline constexpr Dim area{0, 2, 0};
inline constexpr Dim velocity{0, 1, -1};
inline constexpr Dim acceleration{0, 1, -2};
inline constexpr Dim force{1, 1, -2};
inline constexpr Dim moment{1, 2, -2};
inline constexpr Dim pressure{1, -1, -2};  // also stress and Young's modulus
inline constexpr Dim density{1, -3, 0};
inline constexpr Dim stiffness{1, 0, -2};  // force per length
inline constexpr Dim inertia{1, 2, 0};
inline constexpr Dim rate{0, 0, -1};  // strain rate, frequency
inline constexpr Dim energy{1, 2, -2};
inline constexpr Dim heat_capacity_per_volume{1, -1, -2};  // rho*cp per kelvin
}  // namespace dim

// What an integer field refers to, for the id offsets of //SUBMODEL: inside a submodel every id (an
// object's own id and every reference) is shifted by the submodel's offset of that kind (off_nod,
// off_ele, off_part, off_mat, off_type, off_sub; every other kind takes off_def), as Radioss does.
enum class IdKind : std::uint8_t {
  None,      // not an id (a flag, a count)
  Node,      // off_nod
  Element,   // off_ele
  Part,      // off_part
  Material,  // off_mat
  Property,  // off_type
  Submodel,  // off_sub
  Other,     // off_def: groups, surfaces, functions, skews, boxes, units, interfaces, sensors, ...
};

inline constexpr int kAnyVersion = 0;
inline constexpr int kLastVersion = 9999;

// The deck format versions (/BEGIN INVERS) radx reads, oldest first. Radioss numbered its formats 90, 100,
// ..., 140, then 2017, 2018, ...; a keyword's layout is the one of the highest band at or below the deck's
// version, so the bands below are plain integer ranges. Formats older than 90 (41 to 51) are not read.
inline constexpr std::array<int, 16> kDeckVersions = {90,   100,  110,  120,  130,  140,  2017, 2018,
                                                      2019, 2020, 2021, 2022, 2023, 2024, 2025, 2026};
[[nodiscard]] constexpr bool is_deck_version(int v) {
  for (int k : kDeckVersions)
    if (k == v) return true;
  return false;
}

// One field of a card. Built with the small fluent helpers below, e.g.
//   I("Istf", 21, 30, "stiffness definition").allow({0, 1, 2, 3, 4, 5})
//   R("Fscalegap", 1, 20, "gap scale factor (Igap = 2)").zero_is(1.0).gt(0.0)
struct FieldDecl {
  std::string_view name;
  FieldType type = FieldType::Int;
  int first_col = 1;  // 1-based, inclusive
  int last_col = 10;  // 1-based, inclusive
  std::string_view meaning;
  int since = kAnyVersion;             // first deck version (INVERS) that has this field at these columns
  int until = kLastVersion;            // last deck version that has it
  std::optional<double> zero_default;  // value used when the field is blank or 0
  bool required = false;               // blank or 0 is an error
  Dim dimension = dim::none;           // for unit conversion (reals only)
  std::vector<std::int64_t> allowed;   // integer flags: the accepted values (empty: any)
  std::optional<double> min;           // reals and ints: lower bound
  bool min_exclusive = false;
  std::optional<double> max;  // upper bound
  bool max_exclusive = false;
  bool ignored = false;  // read and echoed, but radx does not use it (a non-default value warns)
  // With `ignored`: a non-default value changes the physics, so it is an error unless substitutions are
  // allowed (then the run goes on without it, listed as a substitution).
  bool changes_physics = false;
  // Radioss pre-reads some cards and reads a field only when given columns of the line hold text (the
  // 100-130 /MAT/LAW2 reads RHO_ref at 21-40 only when 11-20 are not blank). 0: always read.
  int gate_first = 0;
  int gate_last = 0;
  IdKind ref = IdKind::None;  // integers: the kind of object the id names (submodel offsets)

  FieldDecl& versions(int from, int to = kLastVersion) {
    since = from;
    until = to;
    return *this;
  }
  FieldDecl& zero_is(double v) {
    zero_default = v;
    return *this;
  }
  FieldDecl& must() {
    required = true;
    return *this;
  }
  FieldDecl& dims(Dim d) {
    dimension = d;
    return *this;
  }
  FieldDecl& allow(std::initializer_list<std::int64_t> values) {
    allowed.assign(values);
    return *this;
  }
  FieldDecl& ge(double v) {
    min = v;
    min_exclusive = false;
    return *this;
  }
  FieldDecl& gt(double v) {
    min = v;
    min_exclusive = true;
    return *this;
  }
  FieldDecl& le(double v) {
    max = v;
    max_exclusive = false;
    return *this;
  }
  FieldDecl& lt(double v) {
    max = v;
    max_exclusive = true;
    return *this;
  }
  FieldDecl& unused() {
    ignored = true;
    return *this;
  }
  // Read, not implemented, and a non-default value would change the results.
  FieldDecl& not_implemented() {
    ignored = true;
    changes_physics = true;
    return *this;
  }
  // Read only when columns [first, last] of the card line hold text; otherwise the field is blank.
  FieldDecl& read_if_text(int first, int last) {
    gate_first = first;
    gate_last = last;
    return *this;
  }
  // The field holds the id of an object of kind `k` (shifted by a submodel's offset of that kind).
  FieldDecl& refs(IdKind k) {
    ref = k;
    return *this;
  }
  [[nodiscard]] bool in_version(int v) const { return v >= since && v <= until; }
};

inline FieldDecl I(std::string_view name, int first, int last, std::string_view meaning) {
  FieldDecl f;
  f.name = name;
  f.type = FieldType::Int;
  f.first_col = first;
  f.last_col = last;
  f.meaning = meaning;
  return f;
}
inline FieldDecl R(std::string_view name, int first, int last, std::string_view meaning) {
  FieldDecl f = I(name, first, last, meaning);
  f.type = FieldType::Real;
  return f;
}
inline FieldDecl S(std::string_view name, int first, int last, std::string_view meaning) {
  FieldDecl f = I(name, first, last, meaning);
  f.type = FieldType::String;
  return f;
}

// A card is read only when its condition holds on a field read earlier in the same keyword.
enum class CondOp : std::uint8_t { Always, Eq, Ne, Gt, InRange };
struct Condition {
  CondOp op = CondOp::Always;
  std::string_view field;
  std::int64_t a = 0;  // Eq/Ne/Gt value, InRange lower bound
  std::int64_t b = 0;  // InRange upper bound
  [[nodiscard]] bool holds(std::int64_t v) const {
    switch (op) {
      case CondOp::Always: return true;
      case CondOp::Eq: return v == a;
      case CondOp::Ne: return v != a;
      case CondOp::Gt: return v > a;
      case CondOp::InRange: return v >= a && v <= b;
    }
    return false;
  }
};
inline Condition when_eq(std::string_view f, std::int64_t v) {
  return {CondOp::Eq, f, v, 0};
}
inline Condition when_ne(std::string_view f, std::int64_t v) {
  return {CondOp::Ne, f, v, 0};
}
inline Condition when_gt(std::string_view f, std::int64_t v) {
  return {CondOp::Gt, f, v, 0};
}
inline Condition when_in(std::string_view f, std::int64_t lo, std::int64_t hi) {
  return {CondOp::InRange, f, lo, hi};
}

struct CardDecl {
  std::string_view name;  // "card 1", or a descriptive name for conditional cards
  std::vector<FieldDecl> fields;
  Condition condition;
  int since = kAnyVersion;
  int until = kLastVersion;
  [[nodiscard]] bool in_version(int v) const { return v >= since && v <= until; }
};

// What follows the fixed cards of a keyword, up to the next keyword line.
enum class Tail : std::uint8_t {
  None,
  Records,            // one `record` card per line (/NODE, /SHELL, /FUNCT, /SURF/SEG, ...)
  IdList,             // integers in 10-column cells, 10 per line (/GRNOD/NODE, /SURF/PART, ...)
  Text,               // lines joined, blanks removed (/CTCLAW law string)
  ThVarsThenIds,      // /TH/PART, /TH/INTER, ...: variable-name lines, then ids 10 per line
  ThVarsThenRecords,  // /TH/NODE, /TH/SHEL: variable-name lines, then `record` lines
  // /SET: one `record` card per line, text lines included (a clause word in columns 1-10, blank on the
  // lines that carry on the clause above, then its ids in 10-column cells).
  Clauses,
};

// Header fields after the keyword path: `/INTER/TYPE7/inter_ID/unit_ID`.
enum class Header : std::uint8_t {
  None,        // `/BEGIN`, `/END`, `/DEF_SHELL`
  IdUnit,      // object id (required) then an optional unit id
  Id,          // object id only
  UnitOnly,    // `/NODE/unit_ID`
  PartId,      // `/SHELL/part_ID`: the elements' part
  OptionalId,  // `/RANDOM[/GRNOD/id]`-style or `/SUBSET`: id if present
  Word,        // `/UNIT/LENGTH/mm`: one text field (a unit name or a factor), kept as written
};

enum class Support : std::uint8_t {
  Read,     // read and used
  Ignored,  // accepted control card that changes no result: echoed as ignored (a note)
  // Engine deck only:
  NotWritten,   // an output request for a file or field radx does not write: accepted with a warning
  Unsupported,  // a Radioss keyword that changes the results in a way radx cannot run: an error
};

// A real field whose dimension depends on another field of the same keyword: Stfac is a stiffness
// when Istf = 1, Fscale_y a moment when a /CLOAD acts on a rotation. `when_values` are compared with
// the other field as written (integers as decimal text, strings trimmed and upper-cased).
struct DimOverride {
  std::string_view field;
  std::string_view when_field;
  std::vector<std::string_view> when_values;
  Dim dimension;
};

struct KeywordDecl {
  std::string_view path;                  // canonical, e.g. "/INTER/TYPE7"
  std::vector<std::string_view> aliases;  // e.g. "/MAT/PLAS_JOHNS", "/MAT/LAW02"
  std::string_view meaning;               // one line for the reference
  Header header = Header::IdUnit;
  bool has_title = true;
  std::vector<CardDecl> cards;
  Tail tail = Tail::None;
  CardDecl record;  // for Records and ThVarsThenRecords
  // Tail::Records: the lines one record spans (/BRIC20: 3). Line k's columns 1-100 are the record's columns
  // 100 k + 1 .. 100 k + 100, so a field on the second line at columns 1-10 is declared at 101-110.
  int record_lines = 1;
  // For Tail::Text: what the text says (the reference prints it after the generic sentence).
  std::string_view text_meaning;
  Support support = Support::Read;
  bool singleton = false;           // may appear once (/BEGIN, /TITLE, /DEF_SHELL counts only its first)
  std::string_view id_name = "id";  // name of the header id in messages and listings
  std::vector<DimOverride> dim_overrides;
  // First deck version radx reads this keyword in: in an older deck it is refused (RX307) because its
  // layout there is not established.
  int since = kAnyVersion;
  // Submodel offsets: the kind of the keyword line's id (an element block's id names its part) and of the
  // ids of an IdList or time-history tail.
  IdKind id_kind = IdKind::Other;
  IdKind list_kind = IdKind::None;
};

// The starter deck's keywords, in the order docs/keywords.md lists them (it is generated from this table).
const std::vector<KeywordDecl>& starter_keywords();

// Radioss keyword roots that radx recognises as real Radioss keywords but does not support: used to
// tell "not supported by radx" from "unknown keyword".
const std::vector<std::string_view>& known_unsupported_roots();

// Engine deck keywords: free-format data lines (Fortran list-directed).
struct EngineLineDecl {
  std::vector<std::string_view> names;  // values on this line, in order
  std::size_t required = 0;             // how many must be present
  std::vector<Dim> dims;                // per value (empty: all dimensionless)
};

struct EngineKeywordDecl {
  std::string_view path;  // e.g. "/DT/INTER/CST", "/ANIM/ELEM"
  std::vector<std::string_view> aliases;
  std::string_view meaning;
  // Names of the header fields after the path, e.g. /RUN/name/irun/letter or /PRINT/n/nh or the
  // variable name of /ANIM/ELEM/VONM.
  std::vector<std::string_view> header_fields;
  std::size_t header_required = 0;
  std::vector<EngineLineDecl> lines;
  bool id_lines = false;  // any number of lines of integer ids (/RBODY/ON)
  Support support = Support::Read;
  bool prefix_match = false;  // path matches the start of the keyword (/ANIM/ELEM/xxx, /DEL/...)
  // Why radx does not read it, by `support`: Ignored, why it changes no result; NotWritten, what radx writes
  // instead; Unsupported, what radx would need to run it. Empty for Read.
  std::string_view reason;
};

const std::vector<EngineKeywordDecl>& engine_keywords();

}  // namespace radx::schema
