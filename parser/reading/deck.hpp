// What a deck said and where, with nothing interpreted beyond the keyword declarations: each keyword
// block becomes a KeywordRecord holding typed field values (defaults applied, units converted to work
// units) and the file:line of every card, so later checks can point at the right place.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/keywords/keyword_schema.hpp"
#include "parser/reading/diagnostics.hpp"

namespace radx {

struct SourcePos {
  std::uint32_t file = 0;  // index into Deck::files
  std::uint32_t line = 0;  // 1-based
};

// One field value of a card. `blank` says the columns were empty; `defaulted` that the value came from
// the declaration's zero default.
struct FieldValue {
  const schema::FieldDecl* decl = nullptr;
  std::int64_t i = 0;
  double r = 0.0;
  std::string s;
  bool blank = true;
  bool defaulted = false;
  SourcePos pos;
  std::uint16_t column = 0;
};

// Columnar storage for record tails (/NODE, /SHELL, ...): one column per field of the record card.
struct RecordTable {
  std::vector<const schema::FieldDecl*> fields;
  std::vector<std::vector<std::int64_t>> ints;    // per field; empty for non-integer fields
  std::vector<std::vector<double>> reals;         // per field; empty for non-real fields
  std::vector<std::vector<std::string>> strings;  // per field; empty for non-string fields
  std::vector<SourcePos> pos;                     // per record
  std::vector<std::uint8_t> bad;                  // per record: 1 when a field could not be read
  [[nodiscard]] std::size_t size() const { return pos.size(); }
  // Index of a field by name; -1 when the record has no such field.
  [[nodiscard]] int column(std::string_view name) const;
};

struct KeywordRecord {
  const schema::KeywordDecl* decl = nullptr;
  std::string written;  // the keyword line as written (trimmed)
  std::int64_t id = 0;  // header object id (or part id for element blocks)
  std::int64_t unit_id = 0;
  std::string title;
  std::string header_word;         // Header::Word: the text field as written (case kept), e.g. "mm"
  SourcePos pos;                   // the keyword line
  std::vector<FieldValue> fields;  // all fixed-card fields, in card order
  RecordTable records;             // Tail::Records and ThVarsThenRecords
  std::vector<std::int64_t> ids;   // Tail::IdList and ThVarsThenIds
  std::vector<SourcePos> id_pos;   // where each id was written
  std::vector<std::string> th_variables;
  std::string text;  // Tail::Text
  // Where each character of `text` was written (Tail::Text): its line and 1-based column.
  std::vector<SourcePos> text_pos;
  std::vector<std::uint32_t> text_column;
  // The factors from the record's input units to the work units (mass, length, time) that its real fields
  // were converted with; what the record's own text (a /CTCLAW law) needs converting with.
  std::array<double, 3> unit_factors{1.0, 1.0, 1.0};
  // The innermost //SUBMODEL the keyword sits in (index into Deck::submodels), -1 at the top level. Its ids
  // are already shifted by that submodel's offsets.
  std::int32_t submodel = -1;

  [[nodiscard]] std::string_view keyword() const;
  [[nodiscard]] const FieldValue* find(std::string_view name) const;
  [[nodiscard]] std::int64_t get_int(std::string_view name) const;  // 0 when absent
  [[nodiscard]] double get_real(std::string_view name) const;       // 0 when absent
  [[nodiscard]] std::string get_string(std::string_view name) const;
  [[nodiscard]] bool given(std::string_view name) const;  // present and not blank
};

// Unit system: factors of one unit of mass, length and time in SI.
struct UnitSystem {
  double mass = 1.0;
  double length = 1.0;
  double time = 1.0;
  std::string mass_name = "kg";
  std::string length_name = "m";
  std::string time_name = "s";
};

// Parses a unit name (kg, g, mg, Mg, t, lb, m, mm, cm, km, um/mum, in, ft, s, ms, mus/us, ns, min, h)
// or a numeric factor; returns the SI factor or nullopt.
std::optional<double> unit_factor(std::string_view name, char kind /* 'M', 'L', 'T' */);

// A //SUBMODEL ... //ENDSUB block. Offsets are cumulative: a nested submodel's ids are shifted by its own
// offsets plus those of every enclosing submodel (the specific offset, or off_def when it is 0), as
// OpenRadioss's reader sums them up the chain.
struct Submodel {
  std::int64_t id = 0;  // after the enclosing submodels' offsets
  std::string title;
  std::int32_t parent = -1;  // index into Deck::submodels; -1 at the top level
  std::int64_t unit_id = 0;  // its own unit system, else the enclosing one's; 0 = the deck's input units
  std::array<std::int64_t, 8> offsets{};  // by schema::IdKind
  SourcePos pos;                          // the //SUBMODEL line
  [[nodiscard]] std::int64_t offset(schema::IdKind k) const { return offsets[static_cast<std::size_t>(k)]; }
};

struct Deck {
  std::vector<std::string> files;  // display paths, index = SourcePos::file
  int version = 0;                 // INVERS from /BEGIN
  std::string run_name;            // RUNNAME from /BEGIN
  UnitSystem input_units;
  UnitSystem work_units;
  // The deck says which units it is in: /BEGIN names input or work units, an old deck has /UNIT/LENGTH and
  // the like, or an object is given in a /UNIT system of its own (converted to the work units). When none
  // does, blank units read as SI but the deck may be written in any consistent system (mm Mg s, mm kg ms).
  bool units_named = false;
  std::vector<KeywordRecord> records;  // starter keywords in deck order
  std::vector<Submodel> submodels;     // in deck order; a parent comes before its children
  bool allow_substitutions = false;    // ReadOptions::allow_substitutions
  // What runs instead of what the deck asks (only with allow_substitutions), one sentence each.
  std::vector<std::string> substitutions;
  // Keywords refused as not read (RX302), with the id written after their path: a reference to one of them
  // says what it names instead of "there is no ..." (a /PART naming a /PROP/SPR_PRE).
  struct Unread {
    std::string path;  // /PROP/SPR_PRE
    std::int64_t id = 0;
    SourcePos pos;
  };
  std::vector<Unread> unread;
  std::vector<const KeywordRecord*> of(std::string_view path) const;
  [[nodiscard]] Where where(SourcePos p, int column = 0) const;
};

struct EngineRecord {
  const schema::EngineKeywordDecl* decl = nullptr;
  std::string written;
  SourcePos pos;
  std::vector<std::string> header;         // header field values as written
  std::vector<std::vector<double>> lines;  // numbers per data line (0 where a value is not a number)
  bool has_unreadable = false;             // a value was not a number: reported by the reader
  std::vector<std::int64_t> ids;           // id_lines keywords
  std::vector<SourcePos> id_pos;           // the line of each id
  [[nodiscard]] double value(std::size_t line, std::size_t k, double dflt = 0.0) const;
};

struct EngineDeck {
  std::vector<std::string> files;
  std::vector<EngineRecord> records;
  [[nodiscard]] std::vector<const EngineRecord*> of(std::string_view path) const;
  [[nodiscard]] Where where(SourcePos p, int column = 0) const;
};

struct ReadOptions {
  // Treat a file with an /END/ENGINE line as a one-file deck: the starter part starts after it.
  bool allow_one_file = true;
  // Run the nearest implemented formulation where the deck asks for one radx lacks (listed as
  // substitutions) instead of refusing the deck.
  bool allow_substitutions = false;
};

// Reads a starter deck (or the starter part of a one-file deck). Never throws on bad input: every
// problem goes to `diags`.
Deck read_starter_deck(const std::string& path, Diagnostics& diags, const ReadOptions& opt = {});
// Reads an engine deck (or the engine part of a one-file deck).
EngineDeck read_engine_deck(const std::string& path, Diagnostics& diags);

}  // namespace radx
