#include "parser/reading/closest_names.hpp"

#include <algorithm>
#include <cctype>

namespace radx {

namespace {

char folded(char c) {
  return static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
}

std::size_t slip_bound(std::size_t length) {
  if (length < 3) return 0;  // one edit from "-x" is every short option: no suggestion is better
  return std::max<std::size_t>(1, std::min<std::size_t>(3, length / 4));
}

// Whether a and b differ in their digits only: LAW51 and LAW1, TYPE7 and TYPE77 are other members of a
// numbered family, not slips.
bool differ_in_digits_only(std::string_view a, std::string_view b) {
  auto letters = [](std::string_view s) {
    std::string out;
    for (char c : s)
      if (!std::isdigit(static_cast<unsigned char>(c))) out.push_back(folded(c));
    return out;
  };
  return letters(a) == letters(b);
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic-programming table: the transposition looks two rows back.
  const std::size_t n = b.size();
  std::vector<std::size_t> before(n + 1), previous(n + 1), current(n + 1);
  for (std::size_t j = 0; j <= n; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const bool same = folded(a[i - 1]) == folded(b[j - 1]);
      std::size_t d = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && folded(a[i - 1]) == folded(b[j - 2]) && folded(a[i - 2]) == folded(b[j - 1]))
        d = std::min(d, before[j - 2] + 1);
      current[j] = d;
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[n];
}

std::vector<std::string> closest_names(std::string_view written, const std::vector<std::string>& known,
                                       std::size_t most) {
  const std::size_t bound = slip_bound(written.size());
  std::size_t best = bound;
  std::vector<std::string> out;
  for (const auto& k : known) {
    const std::size_t d = edit_distance(written, k);
    if (d == 0) return {};
    if (d > bound || differ_in_digits_only(written, k)) continue;
    if (d < best || out.empty()) {
      best = d;
      out.clear();
    }
    if (d == best && out.size() < most && std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  }
  return out;
}

std::string did_you_mean(std::string_view written, const std::vector<std::string>& known) {
  const auto names = closest_names(written, known);
  if (names.empty()) return {};
  std::string text = "did you mean " + names[0];
  for (std::size_t k = 1; k < names.size(); ++k) text += (k + 1 == names.size() ? " or " : ", ") + names[k];
  return text + "?";
}

}  // namespace radx
