#include "io/regress/regression_extract.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

namespace radx::io {

namespace {

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (i < line.size()) {
    while (i < line.size() && blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !blank(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

template <class T>
std::optional<T> parse_whole(std::string_view s) {
  T v{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(v)) return std::nullopt;  // from_chars reads "inf" and "nan"
  }
  return v;
}

constexpr std::size_t kCycleSlot = 4, kTimeSlot = 5, kSlots = 6;  // after the four energies

}  // namespace

std::string_view extract_key(ExtractEnergy e) {
  switch (e) {
    case ExtractEnergy::Internal: return "IENERGY";
    case ExtractEnergy::KineticTranslational: return "KENERGYT";
    case ExtractEnergy::KineticRotational: return "KENERGYR";
    case ExtractEnergy::ExternalWork: return "EXTWORK";
  }
  return "?";
}

std::string_view extract_label(ExtractEnergy e) {
  switch (e) {
    case ExtractEnergy::Internal: return "IE";
    case ExtractEnergy::KineticTranslational: return "KE";
    case ExtractEnergy::KineticRotational: return "KER";
    case ExtractEnergy::ExternalWork: return "EXT";
  }
  return "?";
}

bool parse_regression_extract(std::string_view text, const std::string& name, RegressionExtract& out,
                              std::string& error) {
  RegressionExtract r;
  std::array<int, kSlots> seen_at{};  // line of each key, 0 when not seen yet
  int line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    const auto fields = split_fields(line);
    if (fields.empty()) continue;
    const std::string where = name + ":" + std::to_string(line_no) + ": ";
    if (fields.size() < 2 || !parse_whole<long long>(fields[0])) {
      error = where + "expected a line number and a key, found \"" + std::string(line) + "\"";
      return false;
    }
    const std::string_view key = fields[1];
    std::size_t slot = kSlots;
    if (key == "CYCLE") slot = kCycleSlot;
    if (key == "TIME") slot = kTimeSlot;
    for (const auto e : kExtractEnergies)
      if (key == extract_key(e)) slot = static_cast<std::size_t>(e);
    if (slot == kSlots) continue;  // a key radx does not compare
    if (seen_at[slot] != 0) {
      error = where + "a second " + std::string(key) + " line (the first is line " +
              std::to_string(seen_at[slot]) + ")";
      return false;
    }
    seen_at[slot] = line_no;
    const std::size_t wanted = slot < 4 ? 2 : 1;
    const char* what = slot == kCycleSlot  ? "CYCLE needs one integer (the cycle count)"
                       : slot == kTimeSlot ? "TIME needs one number (the final time)"
                                           : nullptr;
    const std::string energy_what =
        std::string(key) + " needs a value and a reference magnitude (two numbers)";
    const auto fail = [&](const std::string& detail) {
      error = where + (what ? std::string(what) : energy_what) + detail;
      return false;
    };
    if (fields.size() != 2 + wanted) {
      std::string found;
      for (std::size_t k = 2; k < fields.size(); ++k) found += (k > 2 ? " " : "") + std::string(fields[k]);
      return fail(found.empty() ? ", found nothing" : ", found \"" + found + "\"");
    }
    if (slot == kCycleSlot) {
      const auto c = parse_whole<std::int64_t>(fields[2]);
      if (!c || *c < 0) return fail(", found \"" + std::string(fields[2]) + "\"");
      r.cycles = *c;
      continue;
    }
    const auto v = parse_whole<double>(fields[2]);
    if (!v) return fail(", found \"" + std::string(fields[2]) + "\"");
    if (slot == kTimeSlot) {
      r.time = *v;
      continue;
    }
    const auto m = parse_whole<double>(fields[3]);
    if (!m || *m < 0)
      return fail(", found magnitude \"" + std::string(fields[3]) + "\" (a number >= 0 expected)");
    r.energy[slot] = ReferenceEnergy{*v, *m};
  }
  std::string missing;
  for (std::size_t slot = 0; slot < kSlots; ++slot) {
    if (seen_at[slot] != 0) continue;
    const std::string_view key = slot == kCycleSlot  ? std::string_view("CYCLE")
                                 : slot == kTimeSlot ? std::string_view("TIME")
                                                     : extract_key(static_cast<ExtractEnergy>(slot));
    missing += (missing.empty() ? "" : ", ") + std::string(key);
  }
  if (!missing.empty()) {
    error = name + ": no " + missing +
            " line (radx compares CYCLE, TIME, IENERGY, KENERGYT, KENERGYR and EXTWORK)";
    return false;
  }
  out = r;
  return true;
}

bool read_regression_extract(const std::string& path, RegressionExtract& out, std::string& error) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    error = path + ": cannot open the file";
    return false;
  }
  std::ostringstream text;
  text << f.rdbuf();
  return parse_regression_extract(text.str(), path, out, error);
}

double energy_deviation(double radx, double ref, double magnitude) {
  if (std::isnan(radx) || std::isnan(ref) || std::isnan(magnitude))
    return std::numeric_limits<double>::quiet_NaN();
  const double diff = std::abs(radx - ref);
  if (magnitude > 0) return diff / magnitude;
  return diff == 0 ? 0.0 : std::numeric_limits<double>::infinity();
}

double relative_deviation(double radx, double ref) {
  return energy_deviation(radx, ref, std::abs(ref));
}

bool ExtractComparison::within(double tolerance) const {
  for (const double d : energy)
    if (!(d <= tolerance)) return false;
  return true;
}

ExtractComparison compare_to_extract(const RunFigures& radx, const RegressionExtract& ref) {
  ExtractComparison c;
  for (const auto e : kExtractEnergies) {
    const auto k = static_cast<std::size_t>(e);
    c.energy[k] = energy_deviation(radx.energy[k], ref.energy[k].value, ref.energy[k].magnitude);
  }
  c.time = relative_deviation(radx.time, ref.time);
  c.cycle_ratio = ref.cycles > 0 ? static_cast<double>(radx.cycles) / static_cast<double>(ref.cycles)
                                 : std::numeric_limits<double>::quiet_NaN();
  return c;
}

}  // namespace radx::io
