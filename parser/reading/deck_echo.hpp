// Text driven by the keyword declarations: the listing echo of one keyword block (each field with
// its value as used and whether it is a default) and the keyword reference (docs/keywords.md).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "parser/reading/deck.hpp"

namespace radx {

// One line per field: `    Istf       stiffness definition ...  = 4` with `(default)` when the value
// came from the declaration's default.
std::vector<std::string> echo_keyword(const KeywordRecord& r);

// The keyword reference in Markdown: every starter and engine keyword, its cards and fields with
// columns, versions, defaults, dimensions and meanings, and the table of diagnostic codes.
void write_keyword_reference(std::ostream& os);

}  // namespace radx
