// "Did you mean": the known names nearest to a name the user wrote, for keywords, animation requests and
// command-line options that are not known.
//
// The distance is the optimal-string-alignment edit distance (Levenshtein's insertions, deletions and
// substitutions, plus the swap of two adjacent characters, each counting 1), compared without regard to
// case: "PLAS_JHONS" is one edit from "PLAS_JOHNS", "VNOM" one from "VONM". A name is suggested only when it
// is close enough to be a slip of the hand rather than another word: at most max(1, min(3, n / 4)) edits for
// a written name of n >= 3 characters; none for shorter names, where one edit reaches every short option.
// A name that differs in its digits only is another member of a numbered family (/MAT/LAW51 is a Radioss law,
// not a slip from /MAT/LAW1), never a suggestion.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace radx {

std::size_t edit_distance(std::string_view a, std::string_view b);

// The known names at the smallest distance from `written` (at most `most` of them, in the order given),
// when that distance is within the slip bound above; none when `written` is itself known.
std::vector<std::string> closest_names(std::string_view written, const std::vector<std::string>& known,
                                       std::size_t most = 3);

// "did you mean X?" or "did you mean X or Y?" for the closest names, or "" when there is none.
std::string did_you_mean(std::string_view written, const std::vector<std::string>& known);

}  // namespace radx
