// The text layer of a deck: files read whole, #include expanded (relative to the including file,
// loops detected), comment lines (# and $) dropped, CRLF and trailing blanks removed. Blank lines are
// kept: in the block format a blank line is a card whose fields are all defaults.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "parser/reading/deck.hpp"

namespace radx {

struct TextLine {
  std::string_view text;  // without line end and trailing blanks
  SourcePos pos;
};

struct DeckText {
  std::vector<std::string> files;                     // display paths
  std::vector<std::unique_ptr<std::string>> buffers;  // file contents; TextLine views point into them
  std::vector<TextLine> lines;
  // Whether an included file ended at an /END: a deck whose main file only includes the model reaches its
  // end there, as Radioss reads it, and needs no /END of its own.
  bool ended_in_include = false;
  [[nodiscard]] Where where(SourcePos p, int column = 0) const {
    return Where{files.at(p.file), static_cast<int>(p.line), column};
  }
};

// Loads `path` and everything it includes. Returns false when the top file cannot be read.
bool load_deck_text(const std::string& path, DeckText& out, Diagnostics& diags);

}  // namespace radx
