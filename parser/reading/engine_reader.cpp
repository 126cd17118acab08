// The engine-deck reader. Engine decks are free format (Fortran list-directed): numbers separated by
// blanks or commas, one data line per declared line. Keyword fields are compared on their first five
// non-blank characters, as the Radioss engine does (`/PARITH/ON` is `/PARIT/ON`), except `/ANIM`
// keywords, whose second field is compared on its first four characters as the Radioss animation reader
// does (`/ANIM/ELEMENT/VONM` is `/ANIM/ELEM/VONM`; `/ANIM/DT` is DT alone). Reading stops at the first
// `/END` line (so the engine part of a one-file deck ends at `/END/ENGINE`), or at the end of the file when
// there is none, as in Radioss.
//
// What follows a keyword depends on its class (keywords_engine.cpp): a keyword radx reads has its data
// lines read and checked; one it ignores gets a note, an output it does not write a warning, and one that
// changes the results and that radx cannot run an error; their data lines are passed over unchecked. A
// keyword whose first field Radioss does not know is an unknown keyword (RX301), as in Radioss; a known
// first field with a form radx does not declare is not supported (RX302).
#include <algorithm>

#include "parser/reading/closest_names.hpp"
#include "parser/reading/deck.hpp"
#include "parser/reading/deck_text.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx {

using schema::EngineKeywordDecl;

namespace {

std::vector<std::string> engine_tokens(std::string_view line, bool& is_anim) {
  auto tokens = keyword_fields(line);
  is_anim = !tokens.empty() && tokens[0] == "ANIM";
  return tokens;
}

std::string five(const std::string& s) {
  return s.substr(0, std::min<std::size_t>(5, s.size()));
}

std::vector<std::string> path_tokens(std::string_view path) {
  bool dummy = false;
  return engine_tokens(path, dummy);
}

// Whether the /ANIM field `written` is the declared `want`: the Radioss animation reader compares its
// first four characters (MAT three), except DT, which must be DT alone.
bool anim_field_matches(const std::string& want, const std::string& written) {
  if (want == "DT") return written == "DT";
  const std::size_t n = std::min<std::size_t>(4, want.size());
  return written.size() >= n && written.compare(0, n, want, 0, n) == 0;
}

// Number of leading tokens of `tokens` that match `decl` (0: no match).
std::size_t match(const EngineKeywordDecl& decl, std::string_view path,
                  const std::vector<std::string>& tokens, bool is_anim) {
  const auto want = path_tokens(path);
  if (want.size() > tokens.size()) return 0;
  for (std::size_t k = 0; k < want.size(); ++k) {
    const bool ok = !is_anim ? five(want[k]) == five(tokens[k])
                    : k == 0 ? want[k] == tokens[k]
                             : anim_field_matches(want[k], tokens[k]);
    if (!ok) return 0;
  }
  if (!decl.prefix_match && tokens.size() - want.size() > decl.header_fields.size()) return 0;
  return want.size();
}

// The declared paths whose first field is that of `tokens` (empty: Radioss does not know the keyword).
std::string paths_of_root(const std::vector<std::string>& tokens, bool is_anim) {
  std::string out;
  for (const auto& d : schema::engine_keywords()) {
    const auto want = path_tokens(d.path);
    const bool same = !want.empty() && !tokens.empty() &&
                      (is_anim ? want[0] == tokens[0] : five(want[0]) == five(tokens[0]));
    if (!same) continue;
    out += (out.empty() ? "" : ", ") + std::string(d.path);
    if (d.prefix_match) out += "/...";
  }
  return out;
}

// The one diagnostic of a keyword radx does not read, by its class.
void report_not_read(const EngineKeywordDecl& decl, const std::string& written, Where where, About about,
                     Diagnostics& diags) {
  const std::string what = written + ": " + std::string(decl.meaning) + ". ";
  switch (decl.support) {
    case schema::Support::Read: break;
    case schema::Support::Ignored:
      diags.note(Diag::IgnoredControlCard, where, about,
                 what + "Accepted and ignored: " + std::string(decl.reason) + ".");
      break;
    case schema::Support::NotWritten:
      diags.warning(Diag::OutputNotWritten, where, about,
                    what + "Not written by radx; the run goes on without it: " + std::string(decl.reason) +
                        " (docs/results.md).");
      break;
    case schema::Support::Unsupported:
      diags.error(Diag::UnsupportedKeyword, where, about,
                  what + "It changes the results and radx cannot run it: " + std::string(decl.reason) +
                      "; without it the run would not be the one Radioss makes.");
      break;
  }
}

std::vector<std::string_view> split_values(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == ',')) ++i;
    if (i >= line.size()) break;
    std::size_t j = i;
    while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != ',') ++j;
    out.push_back(line.substr(i, j - i));
    i = j;
  }
  return out;
}

// The declaration whose path or alias matches the most leading tokens, with that count in `used`; nullptr
// when none matches.
const EngineKeywordDecl* matching_declaration(const std::vector<std::string>& tokens, bool is_anim,
                                              std::size_t& used) {
  const EngineKeywordDecl* decl = nullptr;
  for (const auto& d : schema::engine_keywords()) {
    std::size_t n = match(d, d.path, tokens, is_anim);
    for (auto a : d.aliases) n = std::max(n, match(d, a, tokens, is_anim));
    if (n > used) {
      used = n;
      decl = &d;
    }
  }
  return decl;
}

// The error for a keyword line no declaration takes: unknown to Radioss, or a form radx does not read.
void report_undeclared_engine_keyword(const std::vector<std::string>& tokens, bool is_anim,
                                      const std::string& written, Where where, Diagnostics& diags) {
  const std::string forms = paths_of_root(tokens, is_anim);
  if (forms.empty()) {
    static const std::vector<std::string> declared = [] {
      std::vector<std::string> names;
      for (const auto& d : schema::engine_keywords()) {
        names.emplace_back(d.path);
        for (auto a : d.aliases) names.emplace_back(a);
      }
      return names;
    }();
    const std::string suggestion = did_you_mean(written, declared);
    diags.error(Diag::UnknownKeyword, where, About{written},
                "engine keyword " + written +
                    " is not a keyword of the Radioss engine deck (Radioss stops on it too)" +
                    (suggestion.empty() ? "" : " (" + suggestion + ")") +
                    "; see docs/keywords.md for the engine keywords");
  } else
    diags.error(Diag::UnsupportedKeyword, where, About{written},
                "engine keyword " + written + " is not a form radx reads; radx reads " + forms +
                    " (docs/keywords.md)");
}

// The lines of one keyword block while they are read: `cur` is the next one, `end` the first after the
// block. `checked`: the keyword is one radx reads, so its lines are checked.
struct EngineBlock {
  const DeckText& text;
  Diagnostics& diags;
  const TextLine& head;
  std::size_t cur;
  std::size_t end;
  About about;
  bool checked;
};

// The next non-blank line of the block, or nullptr at its end: list-directed reads pass over blank lines.
const TextLine* next_data_line(EngineBlock& b) {
  while (b.cur < b.end && trim(b.text.lines[b.cur].text).empty()) ++b.cur;
  return b.cur < b.end ? &b.text.lines[b.cur] : nullptr;
}

// The numbers of a data line (0 where a value is not a number: the error when the block is checked).
std::vector<double> read_line_values(EngineBlock& b, const TextLine& line, const schema::EngineLineDecl& ld,
                                     EngineRecord& rec) {
  std::vector<double> values;
  const auto parts = split_values(line.text);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    double v = 0;
    const auto st = parse_real(parts[k], v);
    if (st != NumberStatus::Ok) rec.has_unreadable = true;
    if (st != NumberStatus::Ok && b.checked) {
      const std::string name =
          k < ld.names.size() ? std::string(ld.names[k]) : "value " + std::to_string(k + 1);
      b.diags.error(st == NumberStatus::Overflow ? Diag::RealOverflow : Diag::BadReal,
                    b.text.where(line.pos, 1), b.about,
                    name + ": '" + std::string(parts[k]) + "' is not a number");
    }
    values.push_back(v);
  }
  return values;
}

// One data line per declared line into rec.lines; in a checked block, a line with fewer values than its
// declaration requires is an error.
void read_declared_lines(EngineBlock& b, const EngineKeywordDecl& decl, EngineRecord& rec) {
  for (const auto& ld : decl.lines) {
    const TextLine* line = next_data_line(b);
    std::vector<double> values;
    if (line) {
      values = read_line_values(b, *line, ld, rec);
      ++b.cur;
    }
    if (b.checked && values.size() < ld.required) {
      std::string names;
      for (std::size_t k = 0; k < ld.names.size(); ++k) names += (k ? " " : "") + std::string(ld.names[k]);
      b.diags.error(Diag::EngineBadLine, b.text.where(line ? line->pos : b.head.pos, 1), b.about,
                    std::string(decl.path) + " needs " + std::to_string(ld.required) +
                        " value(s) on this line (" + names + "); found " + std::to_string(values.size()));
    }
    rec.lines.push_back(std::move(values));
  }
}

// Every remaining line of the block as integer ids into rec.ids.
void read_engine_id_lines(EngineBlock& b, EngineRecord& rec) {
  const auto& lines = b.text.lines;
  for (; b.cur < b.end; ++b.cur) {
    for (auto part : split_values(lines[b.cur].text)) {
      std::int64_t v = 0;
      if (parse_int(part, v) != NumberStatus::Ok) {
        b.diags.error(Diag::BadInteger, b.text.where(lines[b.cur].pos, 1), b.about,
                      "'" + std::string(part) + "' is not an id");
        continue;
      }
      rec.ids.push_back(v);
      rec.id_pos.push_back(lines[b.cur].pos);
    }
  }
}

// The keyword block of lines `first` (the keyword line, split into `tokens`) to `end` (excluded) into a
// record of `deck`.
void read_engine_block(const DeckText& text, std::size_t first, std::size_t end,
                       const std::vector<std::string>& tokens, bool is_anim, EngineDeck& deck,
                       Diagnostics& diags) {
  const TextLine& head = text.lines[first];
  std::size_t used = 0;
  const EngineKeywordDecl* decl = matching_declaration(tokens, is_anim, used);
  std::string written(trim(head.text));
  if (!decl) {
    report_undeclared_engine_keyword(tokens, is_anim, written, text.where(head.pos, 1), diags);
    return;
  }
  EngineRecord rec;
  rec.decl = decl;
  rec.written = written;
  rec.pos = head.pos;
  for (std::size_t k = used; k < tokens.size(); ++k) rec.header.push_back(tokens[k]);
  // Keywords radx does not read are reported once; their data lines are read but never checked.
  EngineBlock b{text, diags, head, first + 1, end, About{decl->path}, decl->support == schema::Support::Read};
  report_not_read(*decl, written, text.where(head.pos, 1), b.about, diags);
  if (b.checked && rec.header.size() < decl->header_required) {
    diags.error(Diag::BadHeader, text.where(head.pos, 1), b.about,
                std::string(decl->path) + " needs " + std::to_string(decl->header_required) +
                    " field(s) after the keyword in the keyword line");
  }
  read_declared_lines(b, *decl, rec);
  if (b.checked && decl->id_lines) read_engine_id_lines(b, rec);
  if (b.checked && next_data_line(b)) {
    diags.warning(Diag::ExtraData, text.where(text.lines[b.cur].pos, 1), b.about,
                  "data line after the last line of " + std::string(decl->path) + " is ignored: '" +
                      std::string(trim(text.lines[b.cur].text)) + "'");
  }
  deck.records.push_back(std::move(rec));
}

}  // namespace

double EngineRecord::value(std::size_t line, std::size_t k, double dflt) const {
  if (line >= lines.size() || k >= lines[line].size()) return dflt;
  return lines[line][k];
}

std::vector<const EngineRecord*> EngineDeck::of(std::string_view path) const {
  std::vector<const EngineRecord*> out;
  for (const auto& r : records)
    if (r.decl->path == path) out.push_back(&r);
  return out;
}

Where EngineDeck::where(SourcePos p, int column) const {
  return Where{p.file < files.size() ? std::string_view(files[p.file]) : std::string_view{},
               static_cast<int>(p.line), column};
}

EngineDeck read_engine_deck(const std::string& path, Diagnostics& diags) {
  EngineDeck deck;
  DeckText text;
  if (!load_deck_text(path, text, diags)) {
    deck.files = text.files;
    return deck;
  }
  deck.files = text.files;
  const auto& lines = text.lines;
  bool ended = false;
  std::size_t i = 0;
  while (i < lines.size()) {
    const TextLine& head = lines[i];
    if (head.text.empty() || head.text.front() != '/') {
      if (!trim(head.text).empty()) {
        diags.error(Diag::EngineBadLine, text.where(head.pos, 1), About{},
                    "data line outside any keyword: '" + std::string(trim(head.text)) +
                        "'; engine decks start every block with a /KEYWORD line");
      }
      ++i;
      continue;
    }
    bool is_anim = false;
    const auto tokens = engine_tokens(head.text, is_anim);
    if (!tokens.empty() && five(tokens[0]) == "END") {
      ended = true;
      break;
    }
    std::size_t j = i + 1;
    while (j < lines.size() && (lines[j].text.empty() || lines[j].text.front() != '/')) ++j;
    read_engine_block(text, i, j, tokens, is_anim, deck, diags);
    i = j;
  }
  if (!ended) {
    // Radioss reads an engine deck to /END or to the end of the file, whichever comes first, and real
    // engine decks often stop without /END: say so, as a note, at the last line read.
    const SourcePos p = lines.empty() ? SourcePos{0, 1} : lines.back().pos;
    diags.note(Diag::EngineNoEnd, text.where(p, 1), About{"/END"},
               "the engine deck has no /END line: it was read to the end of the file, as Radioss reads it");
  }
  if (deck.of("/RUN").empty()) {
    diags.error(
        Diag::EngineMissingRun, text.where(SourcePos{0, 1}, 1), About{"/RUN"},
        "the engine deck has no /RUN: it sets the run name, number and end time (/RUN/name/1, then Tstop)");
  }
  return deck;
}

}  // namespace radx
