// Listing, column selection and CSV export of a time-history file (io/hdf5/time_history_export.hpp).
//
// Numbers go through std::to_chars, not iostreams or printf, so the text does not depend on the locale
// (a decimal comma would break the CSV) and 17 significant digits give back the same double.
#include "io/hdf5/time_history_export.hpp"

#include <array>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <utility>

#include "io/signal/cfc_filter.hpp"
#include "io/text_file.hpp"

namespace radx::io {

namespace {

// Six significant digits, for people (listings, messages): 0.3 rather than 0.30000000000000004.
std::string readable(double v) {
  std::array<char, 32> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, 6);
  return {buf.data(), r.ptr};
}

// 17 significant digits (for the CSV values: every double round-trips).
std::string digits17(double v) {
  std::array<char, 40> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, 17);
  return {buf.data(), r.ptr};
}

// Glob match: '*' any run of characters (possibly empty), '?' one character. Iterative with one
// backtrack point, which is enough for '*' (a later '*' supersedes an earlier one).
bool glob(std::string_view pattern, std::string_view text) {
  std::size_t p = 0, t = 0, star = std::string_view::npos, mark = 0;
  while (t < text.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == text[t])) {
      ++p, ++t;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      mark = t;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      t = ++mark;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

// A selector matches a column when it matches its full name or a prefix of it ending before a ':'
// ("node/1" and "node/1:12" for "node/1:12:DX"): group paths and variable names hold no ':'.
bool selects(std::string_view selector, std::string_view column) {
  for (std::size_t end = column.find(':'); end != std::string_view::npos; end = column.find(':', end + 1)) {
    if (glob(selector, column.substr(0, end))) return true;
  }
  return glob(selector, column);
}

std::string with_unit(const std::string& name, const std::string& unit) {
  return unit.empty() ? name : name + " [" + unit + "]";
}

// The object ids, at most `limit` of them, then how many there are in all.
std::string object_list(const std::vector<std::int64_t>& objects, std::size_t limit) {
  std::string s;
  for (std::size_t i = 0; i < objects.size() && i < limit; ++i)
    s += (i ? " " : "") + std::to_string(objects[i]);
  if (objects.size() > limit) s += " ... (" + std::to_string(objects.size()) + " in all)";
  return s;
}

// What a selector can name, for the error of a selector that matches nothing.
std::string what_exists(const std::vector<ThGroupData>& groups) {
  std::string s = "the file holds";
  if (groups.empty()) return s + " no groups";
  s += ':';
  for (const auto& g : groups) {
    s += "\n  " + g.layout.path;
    if (!g.layout.objects.empty()) {
      s += ", objects " + object_list(g.layout.objects, 10);
    } else if (!g.layout.object_kind.empty()) {
      s += ", no objects";
    }
    s += ", variables";
    for (const auto& v : g.layout.variables) s += ' ' + v;
  }
  s += "\nselectors: a group (node/1), a column (global:IE, node/1:12:DX), an object's columns (node/1:12); "
       "'*' and '?' are wildcards";
  return s;
}

// RFC 4180: a field with a comma, a quote or a line break is quoted, its quotes doubled.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
  std::string q = "\"";
  for (const char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + '"';
}

// `head` then the items separated by spaces, on lines of at most about 100 characters; continuation
// lines are indented to the items' column.
void write_wrapped(std::ostream& os, std::string head, const std::vector<std::string>& items) {
  constexpr std::size_t indent = 12;
  std::string line = std::move(head);
  for (const auto& t : items) {
    if (line.size() + 1 + t.size() > 100 && line.size() > indent) {
      os << line << '\n';
      line = std::string(indent, ' ');
    }
    line += ' ' + t;
  }
  os << line << '\n';
}

std::size_t row_count(const ThGroupData& g) {
  return g.columns == 0 ? 0 : g.rows.size() / g.columns;
}

}  // namespace

void list_time_history(const std::string& file, const std::vector<ThGroupData>& groups, std::ostream& os) {
  os << file << ": " << groups.size() << (groups.size() == 1 ? " group" : " groups");
  if (!groups.empty())
    os << ", time in " << (groups[0].time_unit.empty() ? "(no unit)" : groups[0].time_unit);
  os << '\n';
  for (const auto& g : groups) {
    const auto& l = g.layout;
    os << '\n' << l.path << '\n';
    os << "  title:     " << (l.title.empty() ? "(none)" : l.title) << '\n';
    if (l.object_kind.empty() && l.objects.empty()) {
      os << "  objects:   none (one value per variable)\n";
    } else if (l.objects.empty()) {
      os << "  objects:   none (no " << l.object_kind << " listed: no columns)\n";
    } else {
      // All ids: the listing is where one looks them up.
      std::vector<std::string> ids;
      for (std::size_t k = 0; k < l.objects.size(); ++k) {
        const std::int64_t skew = k < l.skews.size() ? l.skews[k] : 0;
        ids.push_back(std::to_string(l.objects[k]) +
                      (skew != 0 ? " (skew " + std::to_string(skew) + ")" : ""));
      }
      write_wrapped(os,
                    "  objects:   " + std::to_string(l.objects.size()) + ' ' +
                        (l.object_kind.empty() ? "object" : l.object_kind) +
                        (l.objects.size() == 1          ? ":"
                         : l.object_kind.ends_with('s') ? "es:"
                                                        : "s:"),
                    ids);
    }
    std::vector<std::string> variables;
    for (std::size_t v = 0; v < l.variables.size(); ++v) {
      variables.push_back(with_unit(l.variables[v], v < l.units.size() ? l.units[v] : "") +
                          (v + 1 < l.variables.size() ? "," : ""));
    }
    write_wrapped(os, "  variables:", variables);
    const std::size_t n = row_count(g);
    os << "  rows:      " << n;
    if (n > 0) {
      os << ", time " << readable(g.rows[0]) << " to " << readable(g.rows[(n - 1) * g.columns]);
      if (!g.time_unit.empty()) os << ' ' << g.time_unit;
    }
    os << '\n';
  }
}

bool select_th_columns(const std::vector<ThGroupData>& groups, const std::vector<std::string>& selectors,
                       std::vector<ThColumnRef>& chosen, std::string& error) {
  chosen.clear();
  std::vector<std::vector<ThColumn>> names;
  for (const auto& g : groups) names.push_back(th_columns(g.layout, g.time_unit));
  std::vector<std::vector<bool>> taken(groups.size());
  for (std::size_t i = 0; i < groups.size(); ++i) taken[i].assign(names[i].size(), false);
  auto take = [&](std::size_t g, std::size_t c) {
    if (taken[g][c]) return;
    taken[g][c] = true;
    chosen.push_back({g, c});
  };
  if (selectors.empty()) {
    for (std::size_t g = 0; g < groups.size(); ++g) {
      for (std::size_t c = 1; c < names[g].size(); ++c) take(g, c);
    }
    if (chosen.empty()) {
      error = "no columns to export: " + what_exists(groups);
      return false;
    }
    return true;
  }
  for (const auto& s : selectors) {
    bool any = false;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      for (std::size_t c = 1; c < names[g].size(); ++c) {
        if (!selects(s, names[g][c].name)) continue;
        any = true;
        take(g, c);
      }
    }
    if (!any) {
      error = "no column matches '" + s + "'; " + what_exists(groups);
      return false;
    }
  }
  return true;
}

bool filter_th_columns(std::vector<ThGroupData>& groups, const std::vector<ThColumnRef>& chosen, double cfc,
                       std::string& error, bool* resampled, bool* coarse) {
  if (resampled != nullptr) *resampled = false;
  if (coarse != nullptr) *coarse = false;
  if (chosen.empty()) return true;
  const std::string& unit = groups[chosen[0].group].time_unit;
  const auto seconds = seconds_per_time_unit(unit);
  if (!seconds) {
    error = "time unit '" + unit +
            "' is not one the CFC filter converts to seconds (s, ms, us, ns, or a factor to seconds)";
    return false;
  }
  // Every column filtered first, then stored: a failure leaves the groups as they were.
  std::vector<std::vector<double>> filtered;
  std::vector<double> times, values;
  for (const auto& ref : chosen) {
    const ThGroupData& g = groups[ref.group];
    const std::size_t n = row_count(g);
    times.resize(n);
    values.resize(n);
    for (std::size_t r = 0; r < n; ++r) {
      times[r] = g.rows[r * g.columns];
      values[r] = g.rows[r * g.columns + ref.column];
    }
    bool moved = false;
    filtered.emplace_back();
    if (!cfc_filter_channel(times, values, cfc, *seconds, filtered.back(), error, &moved)) {
      error = th_columns(g.layout, g.time_unit)[ref.column].name + ": " + error;
      return false;
    }
    if (moved && resampled != nullptr) *resampled = true;
    const double mean_step = n > 1 ? (times[n - 1] - times[0]) / static_cast<double>(n - 1) * *seconds : 0.0;
    if (coarse != nullptr && mean_step > 0 && 1.0 / mean_step < 10.0 * (5.0 / 3.0) * cfc) *coarse = true;
  }
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    ThGroupData& g = groups[chosen[k].group];
    for (std::size_t r = 0; r < filtered[k].size(); ++r)
      g.rows[r * g.columns + chosen[k].column] = filtered[k][r];
  }
  return true;
}

bool write_th_csv(const std::vector<ThGroupData>& groups, const std::vector<ThColumnRef>& chosen,
                  std::ostream& os, std::string& error, const std::string& label) {
  if (chosen.empty()) {
    error = "no columns to export";
    return false;
  }
  // Every chosen group must hold the times of the first one, row for row and bit for bit: the writer
  // appends one time to all groups at once, so anything else is a file we do not understand.
  const ThGroupData& first = groups[chosen[0].group];
  const std::size_t n = row_count(first);
  for (const auto& ref : chosen) {
    const ThGroupData& g = groups[ref.group];
    if (row_count(g) != n) {
      error = "groups " + first.layout.path + " and " + g.layout.path + " do not hold the same times (" +
              std::to_string(n) + " and " + std::to_string(row_count(g)) + " rows)";
      return false;
    }
    for (std::size_t r = 0; r < n; ++r) {
      if (g.rows[r * g.columns] != first.rows[r * first.columns]) {
        error = "groups " + first.layout.path + " and " + g.layout.path +
                " do not hold the same times (row " + std::to_string(r + 1) + ": " +
                digits17(first.rows[r * first.columns]) + " and " + digits17(g.rows[r * g.columns]) + ")";
        return false;
      }
    }
  }

  std::vector<std::vector<ThColumn>> names(groups.size());
  for (const auto& ref : chosen) {
    if (names[ref.group].empty())
      names[ref.group] = th_columns(groups[ref.group].layout, groups[ref.group].time_unit);
  }
  os << csv_field(with_unit("time", first.time_unit));
  for (const auto& ref : chosen) {
    const ThColumn& c = names[ref.group][ref.column];
    os << ',' << csv_field(with_unit(c.name, c.unit) + (label.empty() ? "" : ' ' + label));
  }
  os << '\n';
  std::string line;
  for (std::size_t r = 0; r < n; ++r) {
    line = digits17(first.rows[r * first.columns]);
    for (const auto& ref : chosen) {
      const ThGroupData& g = groups[ref.group];
      line += ',';
      line += digits17(g.rows[r * g.columns + ref.column]);
    }
    line += '\n';
    os << line;
  }
  if (!os) {
    error = "cannot write the CSV output";
    return false;
  }
  return true;
}

bool write_th_csv_file(const std::vector<ThGroupData>& groups, const std::vector<ThColumnRef>& chosen,
                       const std::string& path, std::string& error, const std::string& label) {
  const std::string part = path + ".part";
  bool ok = false;
  {
    CheckedOutputFile f(part);
    if (!f.is_open()) {
      error = f.error();
    } else if (write_th_csv(groups, chosen, f, error, label)) {
      ok = f.error().empty();
      if (!ok) error = f.error();
    }
  }
  std::error_code ec;
  if (ok) {
    std::filesystem::rename(part, path, ec);
    if (ec) {
      ok = false;
      error = "cannot rename " + part + " to " + path + ": " + ec.message();
    }
  }
  if (!ok) std::filesystem::remove(part, ec);
  return ok;
}

}  // namespace radx::io
