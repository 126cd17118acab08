// The decks of `radx regress` (docs/regress.md): every deck under the folders given, with its references,
// the diagnostics it declares ("# expect:" lines) and where its outputs go; and the --filter patterns that
// pick among them.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace radx::io {

// A diagnostic a deck must get: a "# expect: RXnnn [line L] [file F] [warning]" line at the top of its
// starter deck (decks/invalid/README.md). Without "warning" it is an error, and the deck must be refused.
struct ExpectedError {
  std::string code;                        // "RX402"
  std::int64_t line = 0;                   // 0: any line
  std::filesystem::path file;              // absolute; the deck itself when the line names no file
  bool warning = false;                    // "... warning": a warning, not an error that refuses the deck
  [[nodiscard]] std::string text() const;  // "RX402 line 97 in x.rad", "RX512 line 84 in x.rad (warning)"
};

// The "# expect:" lines of the comment block that opens `deck` (paths relative to its folder). Lines that
// do not parse are returned in `problems` ("FILE:LINE: ...").
std::vector<ExpectedError> read_expected_errors(const std::filesystem::path& deck,
                                                std::vector<std::string>& problems);

// One deck found under a DIR.
struct RegressDeck {
  std::string label;                   // the folder relative to DIR (see find_regress_decks)
  std::filesystem::path starter_deck;  // NAME_0000.rad, or a one-file deck
  std::filesystem::path reference;     // ref.extract beside it; empty when none (or not this deck's)
  // NAME.ref beside the starter deck (io/regress/regress_reference.hpp): where the deck's own reference is,
  // or where --update writes it. It takes precedence over ref.extract when it exists.
  std::filesystem::path own_reference;
  bool has_own_reference = false;
  bool starter_only = false;  // no engine deck beside it (NAME_0001.rad) and not a one-file deck: only the
                              // starter runs
  std::vector<ExpectedError> expected;  // not empty: the deck must get these diagnostics and no other error
  std::vector<std::string> expect_problems;  // "# expect:" lines that do not parse
  std::filesystem::path work_subdir;         // where its outputs go, relative to the work folder
  std::string note;  // what the run leaves out (a restart deck), or why ref.extract is not used
};

// Every deck under `dirs`, recursively (hidden folders, symbolic links to folders and `skip` excepted),
// sorted by path within each DIR. A deck is a starter deck NAME_0000.rad, or, in a folder without one, a
// one-file deck NAME.rad. Its label is its folder relative to DIR ("LOIS/LOI14/data"; DIR's own name for
// a deck directly in DIR), prefixed by DIR as given when there are several DIRs, and followed by
// "/NAME_0000.rad" when the folder holds several decks; a folder's ref.extract belongs to its deck only
// when the folder holds one deck. Engine decks NAME_0002.rad and later are noted: radx runs NAME_0001.rad
// only (they are OpenRadioss restarts).
std::vector<RegressDeck> find_regress_decks(const std::vector<std::filesystem::path>& dirs,
                                            const std::filesystem::path& skip = {});

// Whether a deck's label matches a --filter pattern: a glob ('*', '?', '[...]') against the whole label, or
// a substring when the pattern has no wildcard.
bool label_matches(const std::string& label, const std::string& pattern);

}  // namespace radx::io
