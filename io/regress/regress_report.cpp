// radx regress: the report of a batch (io/regress/regress_report.hpp).
#include "io/regress/regress_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>

#include "io/listing/summary_json.hpp"
#include "io/regress/regress_text.hpp"
#include "io/xml_text.hpp"

namespace radx::io {

namespace {

// Widths of the refusal text: on the line printed per deck, and in the table.
constexpr std::size_t kLineRefusalChars = 160;
constexpr std::size_t kTableRefusalChars = 72;
constexpr std::size_t kMostFrequentShown = 10;

// A percentage for the report: two decimals, or three significant digits when large.
std::string percent(double fraction) {
  if (std::isnan(fraction)) return "nan";
  if (std::isinf(fraction)) return "inf";
  char buf[32];
  const double p = 100.0 * fraction;
  std::snprintf(buf, sizeof buf, p < 1000 ? "%.2f" : "%.3g", p);
  return buf;
}

}  // namespace

namespace {

std::string refusal_text(const RegressResult& r, std::size_t max_chars, bool with_location) {
  if (r.refusal.message.empty()) return shorten(r.detail, max_chars);
  std::string t = with_location && !r.refusal.location.empty() ? r.refusal.location + ": " : "";
  return shorten(t + r.refusal.message, max_chars);
}

std::string cycles_text(const RegressResult& r) {
  if (!r.radx) return "-";
  return std::to_string(r.radx->cycles) + "/" + (r.reference ? std::to_string(r.reference->cycles) : "-");
}

std::string energy_text(const RegressResult& r, ExtractEnergy e) {
  return r.comparison ? percent(r.comparison->energy[static_cast<std::size_t>(e)]) : "-";
}

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// One quantity's check: "energy.internal x1.53 (radx 510, ref 494.9, +3.1 %, allowed 9.9)", the score being
// the deviation over its allowance ("missing" when there is no value to compare).
std::string check_text(const QuantityCheck& c, bool with_values) {
  char score[32];
  if (!c.reference || !c.radx)
    std::snprintf(score, sizeof score, "missing");
  else if (std::isinf(c.score))
    std::snprintf(score, sizeof score, "xinf");  // a difference where the tolerance is zero
  else
    std::snprintf(score, sizeof score, "x%.2f", c.score);
  std::string t = c.name + " " + score;
  if (!with_values) return t;
  if (!c.reference || !c.radx) return t + " (" + c.why + ")";
  t += " (radx " + number_text(*c.radx) + ", ref " + number_text(*c.reference);
  if (*c.reference != 0) {
    char rel[32];
    std::snprintf(rel, sizeof rel, ", %+.3g %%", 100 * (*c.radx - *c.reference) / std::abs(*c.reference));
    t += rel;
  }
  return t + ", allowed " + number_text(c.allowed) + ")";
}

std::string worst_text(const RegressResult& r, bool with_values) {
  const QuantityCheck* w = worst_check(r);
  return w ? check_text(*w, with_values) : std::string();
}

}  // namespace

std::string format_regress_line(const RegressResult& r) {
  std::string s = r.deck.label + "  " + std::string(status_name(r.status));
  if (r.comparison) {
    const auto& c = *r.comparison;
    char ratio[32];
    std::snprintf(ratio, sizeof ratio, "%.2f", c.cycle_ratio);
    s += "  cycles " + cycles_text(r) + " (x" + ratio + ")  TIME " + percent(c.time) + " %" +
         (r.at_reference_time ? " (at the reference's last line)" : "");
    for (const auto e : kExtractEnergies)
      s += "  " + std::string(extract_label(e)) + " " + energy_text(r, e) + " %";
  } else if (r.radx) {
    char t[32];
    std::snprintf(t, sizeof t, "%.5g", r.radx->time);
    s += "  cycles " + std::to_string(r.radx->cycles) + "  time " + t;
  }
  if (!r.checks.empty()) {
    const std::size_t failed = failed_checks(r);
    s += "  worst " + worst_text(r, true);
    s += failed
             ? "  " + std::to_string(failed) + " of " + std::to_string(r.checks.size()) + " beyond tolerance"
             : "  " + std::to_string(r.checks.size()) + " quantities within tolerance";
  }
  if (r.status == RegressStatus::ReadError || r.status == RegressStatus::RunError ||
      r.status == RegressStatus::RefError) {
    s += "  " + refusal_text(r, kLineRefusalChars, true);
    if (!r.refusal.message.empty() && !r.detail.empty()) s += " (" + r.detail + ")";
  }
  if (r.status == RegressStatus::Diagnosed || r.status == RegressStatus::Unexpected) s += "  " + r.detail;
  if (!r.deck.note.empty()) s += "  [" + r.deck.note + "]";
  s += "  (" + seconds_text(r.seconds) + ")";
  // Every quantity beyond its tolerance, and what --update changed, on the lines below.
  for (const auto& c : r.checks)
    if (!c.passed()) s += "\n      " + check_text(c, true);
  if (!r.update_report.empty()) {
    s += "\n" + r.update_report;
    while (!s.empty() && s.back() == '\n') s.pop_back();
  }
  return s;
}

namespace {

// Counts of a batch for the totals line and the JSON summary.
struct RegressTotals {
  std::map<RegressStatus, std::size_t> count;
  std::size_t found = 0, must_fail = 0, read = 0, ran = 0, with_reference = 0, compared = 0;
};

RegressTotals regress_totals(const std::vector<RegressResult>& results) {
  RegressTotals t;
  t.found = results.size();
  for (const auto& r : results) {
    ++t.count[r.status];
    if (!r.deck.expected.empty()) {
      ++t.must_fail;
      continue;
    }
    if (r.status != RegressStatus::ReadError) ++t.read;
    if (r.radx) ++t.ran;
    if (!r.deck.reference.empty() || r.deck.has_own_reference) ++t.with_reference;
    if (r.status == RegressStatus::Compared) ++t.compared;
  }
  return t;
}

}  // namespace

void write_regress_table(std::ostream& os, const std::vector<RegressResult>& results, double tolerance) {
  const std::vector<std::string> titles{
      "deck",     "status",    "cycles radx/ref", "IE dev %",
      "KE dev %", "KER dev %", "EXT dev %",       "worst quantity, or first refusal"};
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : results) {
    std::vector<std::string> row{r.deck.label, std::string(status_name(r.status)), cycles_text(r)};
    for (const auto e : kExtractEnergies) row.push_back(energy_text(r, e));
    const bool refused = r.status == RegressStatus::ReadError || r.status == RegressStatus::RunError ||
                         r.status == RegressStatus::RefError;
    if (refused)
      row.push_back(refusal_text(r, kTableRefusalChars, false));
    else if (!r.checks.empty())
      row.push_back(worst_text(r, false));
    else if (r.status == RegressStatus::Unexpected)
      row.push_back(shorten(r.detail, kTableRefusalChars));
    else
      row.push_back("");
    rows.push_back(std::move(row));
  }
  std::vector<std::size_t> width(titles.size());
  for (std::size_t c = 0; c < titles.size(); ++c) {
    width[c] = titles[c].size();
    for (const auto& row : rows) width[c] = std::max(width[c], row[c].size());
  }
  const auto put_row = [&](const std::vector<std::string>& row) {
    std::string line;
    for (std::size_t c = 0; c < row.size(); ++c) {
      const bool number = c >= 2 && c <= 6;  // right-aligned
      const std::string pad(width[c] - std::min(width[c], row[c].size()), ' ');
      if (c > 0) line += "  ";
      line += number ? pad + row[c] : (c + 1 == row.size() ? row[c] : row[c] + pad);
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    os << line << '\n';
  };
  put_row(titles);
  std::size_t total = 0;
  for (const auto w : width) total += w + 2;
  os << std::string(std::min<std::size_t>(total, 160), '-') << '\n';
  for (const auto& row : rows) put_row(row);

  std::map<std::string, std::size_t> groups;
  for (const auto& r : results)
    if (!r.refusal.message.empty() && r.deck.expected.empty() &&
        (r.status == RegressStatus::ReadError || r.status == RegressStatus::RunError))
      ++groups[std::string(status_name(r.status)) + "  " + refusal_group(r.refusal.message)];
  RegressTotals t = regress_totals(results);
  os << "\ndecks found " << t.found << ", read " << t.read << ", ran " << t.ran << ", compared " << t.compared
     << " of " << t.with_reference << " with a reference (NAME.ref; ref.extract within "
     << tolerance_text(tolerance) << " %)";
  if (t.must_fail)
    os << ", diagnosed as expected " << t.count[RegressStatus::Diagnosed] << " of " << t.must_fail;
  os << "\n";
  os << "  read-error " << t.count[RegressStatus::ReadError] << ", run-error "
     << t.count[RegressStatus::RunError] << ", ref-error " << t.count[RegressStatus::RefError]
     << ", deviates " << t.count[RegressStatus::Deviates] << ", unexpected "
     << t.count[RegressStatus::Unexpected] << "; ran (no reference) " << t.count[RegressStatus::Ran]
     << ", compared " << t.count[RegressStatus::Compared] << ", read (starter only) "
     << t.count[RegressStatus::Read] << ", diagnosed " << t.count[RegressStatus::Diagnosed] << ", updated "
     << t.count[RegressStatus::Updated] << '\n';
  if (!groups.empty()) {
    std::vector<std::pair<std::string, std::size_t>> sorted(groups.begin(), groups.end());
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    os << "\nmost frequent first refusals:\n";
    for (std::size_t k = 0; k < std::min(sorted.size(), kMostFrequentShown); ++k) {
      char n[16];
      std::snprintf(n, sizeof n, "%5zu", sorted[k].second);
      os << n << "  " << sorted[k].first << '\n';
    }
  }
}

std::string regress_summary_json(const std::vector<RegressResult>& results, const RegressSettings& settings,
                                 bool work_dir_kept) {
  RegressTotals t = regress_totals(results);
  std::string j = "{\n";
  j += "  \"tolerance_percent\": " + json_number(100 * settings.tolerance) + ",\n";
  j += "  \"timeout_seconds\": " + json_number(settings.timeout_seconds) + ",\n";
  j += "  \"threads\": " + std::to_string(settings.threads) + ",\n";
  j += "  \"work_dir\": " + json_string(settings.work_dir.string()) + ",\n";
  j += "  \"work_dir_kept\": " + std::string(work_dir_kept ? "true" : "false") + ",\n";
  j += "  \"totals\": {\"found\": " + std::to_string(t.found) + ", \"read\": " + std::to_string(t.read) +
       ", \"ran\": " + std::to_string(t.ran) + ", \"with_reference\": " + std::to_string(t.with_reference) +
       ", \"compared\": " + std::to_string(t.compared) +
       ", \"with_expected_diagnostics\": " + std::to_string(t.must_fail);
  for (const auto s : {RegressStatus::ReadError, RegressStatus::RunError, RegressStatus::RefError,
                       RegressStatus::Ran, RegressStatus::Deviates, RegressStatus::Read,
                       RegressStatus::Diagnosed, RegressStatus::Unexpected, RegressStatus::Updated}) {
    std::string key(status_name(s));
    std::replace(key.begin(), key.end(), '-', '_');
    if (s == RegressStatus::Ran) key = "ran_without_reference";
    if (s == RegressStatus::Read) key = "read_starter_only";
    j += ", \"" + key + "\": " + std::to_string(t.count[s]);
  }
  j += "},\n  \"decks\": [";
  for (std::size_t k = 0; k < results.size(); ++k) {
    const RegressResult& r = results[k];
    j += k ? ",\n    {" : "\n    {";
    j += "\"deck\": " + json_string(r.deck.label);
    j += ", \"status\": " + json_string(status_name(r.status));
    j += ", \"starter_deck\": " + json_string(r.deck.starter_deck.string());
    j += ", \"reference\": " + (r.deck.reference.empty() ? "null" : json_string(r.deck.reference.string()));
    j += ", \"work_dir\": " + json_string((settings.work_dir / r.deck.work_subdir).string());
    j += ", \"seconds\": " + json_number(r.seconds);
    j += ", \"first_refusal\": " + (r.refusal.message.empty()
                                        ? "null"
                                        : "{\"location\": " + json_string(r.refusal.location) +
                                              ", \"message\": " + json_string(r.refusal.message) + "}");
    j += ", \"detail\": " + json_string(r.detail);
    j += ", \"note\": " + json_string(r.deck.note);
    if (r.radx) {
      j += ",\n     \"radx\": {\"cycles\": " + std::to_string(r.radx->cycles) +
           ", \"TIME\": " + json_number(r.radx->time);
      for (const auto e : kExtractEnergies)
        j += ", \"" + std::string(extract_key(e)) +
             "\": " + json_number(r.radx->energy[static_cast<std::size_t>(e)]);
      j += "}";
    } else {
      j += ", \"radx\": null";
    }
    if (r.reference) {
      j += ",\n     \"ref\": {\"cycles\": " + std::to_string(r.reference->cycles) +
           ", \"TIME\": " + json_number(r.reference->time);
      for (const auto e : kExtractEnergies) {
        const auto& v = (*r.reference)[e];
        j += ", \"" + std::string(extract_key(e)) + "\": {\"value\": " + json_number(v.value) +
             ", \"magnitude\": " + json_number(v.magnitude) + "}";
      }
      j += "}";
    } else {
      j += ", \"ref\": null";
    }
    if (r.comparison) {
      const auto& c = *r.comparison;
      j += ",\n     \"cycle_ratio\": " + json_number(c.cycle_ratio) +
           ", \"deviation_percent\": {\"TIME\": " + json_number(100 * c.time);
      for (const auto e : kExtractEnergies)
        j += ", \"" + std::string(extract_key(e)) +
             "\": " + json_number(100 * c.energy[static_cast<std::size_t>(e)]);
      j += "}";
    } else {
      j += ", \"cycle_ratio\": null, \"deviation_percent\": null";
    }
    j += ",\n     \"own_reference\": " +
         (r.deck.has_own_reference ? json_string(r.deck.own_reference.string()) : std::string("null"));
    j += ", \"checks\": [";
    for (std::size_t c = 0; c < r.checks.size(); ++c) {
      const auto& q = r.checks[c];
      const auto opt = [](const std::optional<double>& v) {
        return v ? json_number(*v) : std::string("null");
      };
      j += (c ? ", " : "") + std::string("{\"quantity\": ") + json_string(q.name) +
           ", \"radx\": " + opt(q.radx) + ", \"ref\": " + opt(q.reference) +
           ", \"allowed\": " + json_number(q.allowed) + ", \"score\": " + json_number(q.score) +
           ", \"passed\": " + (q.passed() ? "true" : "false") + "}";
    }
    j += "]}";
  }
  j += results.empty() ? "]\n}\n" : "\n  ]\n}\n";
  return j;
}

std::string regress_junit_xml(const std::vector<RegressResult>& results, double total_seconds) {
  std::size_t failures = 0, errors = 0;
  for (const auto& r : results) {
    if (r.status == RegressStatus::Deviates || r.status == RegressStatus::Unexpected) ++failures;
    if (r.status == RegressStatus::ReadError || r.status == RegressStatus::RunError ||
        r.status == RegressStatus::RefError)
      ++errors;
  }
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.3f", total_seconds);
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  const std::string counts = " tests=\"" + std::to_string(results.size()) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"" + std::to_string(errors) +
                             "\" skipped=\"0\" time=\"" + seconds + "\"";
  x += "<testsuites name=\"radx regress\"" + counts + ">\n";
  x += "  <testsuite name=\"radx regress\"" + counts + ">\n";
  for (const auto& r : results) {
    std::snprintf(seconds, sizeof seconds, "%.3f", r.seconds);
    x += "    <testcase classname=\"radx.regress\" name=\"" + xml_escape(r.deck.label) + "\" time=\"" +
         seconds + "\">\n";
    const std::string line = format_regress_line(r);
    const std::string first_line = line.substr(0, line.find('\n'));
    if (is_failure(r.status)) {
      const bool failure = r.status == RegressStatus::Deviates || r.status == RegressStatus::Unexpected;
      const std::string tag = failure ? "failure" : "error";
      x += "      <" + tag + " type=\"" + std::string(status_name(r.status)) + "\" message=\"" +
           xml_escape(shorten(first_line, 300)) + "\">" + xml_escape(line) + "</" + tag + ">\n";
    }
    x += "      <system-out>" + xml_escape(line) + "</system-out>\n";
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

}  // namespace radx::io
