// Comparison of two runs (io/compare/run_compare.hpp: what is compared, the tolerance and its floor).
#include "io/compare/run_compare.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "io/hdf5/time_history.hpp"
#include "io/listing/summary_json.hpp"
#include "io/regress/regress_reference.hpp"

namespace radx::io {

namespace {

namespace fs = std::filesystem;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr std::string_view kSummarySuffix = "_summary.json";

std::string number(double v, int digits = 6) {
  std::array<char, 40> buf{};
  const auto r = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, digits);
  return {buf.data(), r.ptr};
}

// The family of a summary figure, for its floor: "energy" for energy.*, "momentum" for momentum.*, the name
// itself otherwise.
std::string family(const std::string& name) {
  if (name == "energy.error_percent") return name;  // a percentage, not an energy
  const auto dot = name.find('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

double score_of(double a, double b, double allowed) {
  const double d = std::abs(b - a);
  if (std::isnan(d)) return kInf;
  return allowed > 0 ? d / allowed : (d == 0 ? 0.0 : kInf);
}

// Linear interpolation of a channel (rows of `g`, column `col`) at `t`, inside the rows' span.
double at_time(const std::vector<double>& times, const ThGroupData& g, std::size_t col, double t) {
  const auto it = std::lower_bound(times.begin(), times.end(), t);
  auto j = static_cast<std::size_t>(it - times.begin());
  const auto value = [&](std::size_t r) { return g.rows[r * g.columns + col]; };
  if (j < times.size() && times[j] == t) return value(j);
  if (j == 0) return value(0);
  if (j >= times.size()) return value(times.size() - 1);
  const double w = (t - times[j - 1]) / (times[j] - times[j - 1]);
  return value(j - 1) + w * (value(j) - value(j - 1));
}

std::vector<double> times_of(const std::vector<ThGroupData>& groups) {
  std::vector<double> t;
  if (groups.empty() || groups.front().columns == 0) return t;
  const auto& g = groups.front();
  for (std::size_t r = 0; r * g.columns < g.rows.size(); ++r) t.push_back(g.rows[r * g.columns]);
  return t;
}

struct ChannelRef {
  std::size_t group = 0, column = 0;
};

std::map<std::string, ChannelRef> channels_of(const std::vector<ThGroupData>& groups) {
  std::map<std::string, ChannelRef> m;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto cols = th_columns(groups[g].layout, groups[g].time_unit);
    for (std::size_t c = 1; c < cols.size(); ++c) m.emplace(cols[c].name, ChannelRef{g, c});
  }
  return m;
}

void compare_summaries(const RunSummary& a, const RunSummary& b, const CompareOptions& o,
                       RunComparison& out) {
  struct Figure {
    std::string name;
    std::optional<double> a, b;
    std::string why;
  };
  std::vector<Figure> figures;
  std::map<std::string, double> scale;  // per family, the largest magnitude in either run
  for (const auto name : kReferenceScalars) {
    Figure f{std::string(name), {}, {}, {}};
    std::string why_a, why_b;
    f.a = run_quantity(name, a, nullptr, why_a);
    f.b = run_quantity(name, b, nullptr, why_b);
    if (!f.a && !f.b) continue;  // neither run has it (no interface: no penetration)
    if (!f.a || !f.b) f.why = (!f.a ? "run A: " + why_a : "run B: " + why_b);
    double& s = scale[family(f.name)];
    if (f.a) s = std::max(s, std::abs(*f.a));
    if (f.b) s = std::max(s, std::abs(*f.b));
    figures.push_back(std::move(f));
  }
  for (const auto& f : figures) {
    Deviation d;
    d.quantity = f.name;
    ++out.figures;
    if (!f.why.empty()) {
      d.a = f.a.value_or(std::nan("")), d.b = f.b.value_or(std::nan(""));
      d.score = kInf;
      d.why = f.why;
    } else {
      d.a = *f.a, d.b = *f.b;
      const double floor = o.abs ? *o.abs : o.rel * scale[family(f.name)];
      d.allowed = std::max(o.rel * std::abs(d.a), floor);
      d.score = score_of(d.a, d.b, d.allowed);
    }
    out.deviations.push_back(std::move(d));
  }
}

bool compare_histories(const RunFiles& fa, const RunFiles& fb, const std::vector<ThGroupData>& a,
                       const std::vector<ThGroupData>& b, const CompareOptions& o, RunComparison& out,
                       std::string& error) {
  const std::string unit_a = a.empty() ? "" : a.front().time_unit,
                    unit_b = b.empty() ? "" : b.front().time_unit;
  if (unit_a != unit_b) {
    error = fa.th + " and " + fb.th + " have their times in different units ('" + unit_a + "' and '" +
            unit_b + "'): run them with the same units to compare them";
    return false;
  }
  out.time_unit = unit_a;
  const auto ta = times_of(a), tb = times_of(b);
  if (ta.empty() || tb.empty()) {
    error = (ta.empty() ? fa.th : fb.th) + ": the time history has no rows";
    return false;
  }
  const double t0 = std::max(ta.front(), tb.front()), t1 = std::min(ta.back(), tb.back());
  if (t0 > t1) {
    error = "the time histories do not overlap in time (" + fa.th + ": " + number(ta.front()) + " to " +
            number(ta.back()) + ", " + fb.th + ": " + number(tb.front()) + " to " + number(tb.back()) + ")";
    return false;
  }
  std::vector<double> common;
  for (const auto* t : {&ta, &tb})
    for (const double x : *t)
      if (x >= t0 && x <= t1) common.push_back(x);
  std::sort(common.begin(), common.end());
  common.erase(std::unique(common.begin(), common.end()), common.end());
  out.common_times = common.size();
  out.first_time = t0, out.last_time = t1;
  if (ta.front() != tb.front() || ta.back() != tb.back()) {
    out.notes.push_back("the runs' time histories span " + number(ta.front()) + " to " + number(ta.back()) +
                        " and " + number(tb.front()) + " to " + number(tb.back()) + " " + unit_a +
                        ": the channels are compared from " + number(t0) + " to " + number(t1));
  }
  const auto ca = channels_of(a), cb = channels_of(b);
  // Both runs' values of every channel A and B share, read at the common times; the floor's scale per group
  // and unit (the largest magnitude of those channels in either run).
  struct Pair {
    std::string name, scale_key;
    std::vector<double> va, vb;
  };
  std::vector<Pair> pairs;
  std::map<std::string, double> scale;
  // A channel one run has and the other lacks: a deviation past every tolerance.
  auto only_in_one_run = [&out](const std::string& name, const char* run) {
    Deviation d;
    d.quantity = "th:" + name;
    ++out.channels;
    d.score = kInf;
    d.why = std::string("only run ") + run + " has this channel";
    out.deviations.push_back(std::move(d));
  };
  for (const auto& [name, ra] : ca) {
    const auto it = cb.find(name);
    if (it == cb.end()) {
      only_in_one_run(name, "A");
      continue;
    }
    const ChannelRef rb = it->second;
    Pair p;
    p.name = name;
    p.scale_key = a[ra.group].layout.path + '|' + th_columns(a[ra.group].layout, unit_a)[ra.column].unit;
    p.va.resize(common.size());
    p.vb.resize(common.size());
    double& peak = scale[p.scale_key];
    for (std::size_t i = 0; i < common.size(); ++i) {
      p.va[i] = at_time(ta, a[ra.group], ra.column, common[i]);
      p.vb[i] = at_time(tb, b[rb.group], rb.column, common[i]);
      peak = std::max({peak, std::abs(p.va[i]), std::abs(p.vb[i])});
    }
    pairs.push_back(std::move(p));
  }
  for (const auto& p : pairs) {
    Deviation d;
    d.quantity = "th:" + p.name;
    ++out.channels;
    const double floor = o.abs ? *o.abs : o.rel * scale[p.scale_key];
    d.score = -1;
    for (std::size_t i = 0; i < common.size(); ++i) {
      const double allowed = std::max(o.rel * std::abs(p.va[i]), floor);
      const double sc = score_of(p.va[i], p.vb[i], allowed);
      if (sc > d.score) d.score = sc, d.time = common[i], d.a = p.va[i], d.b = p.vb[i], d.allowed = allowed;
    }
    out.deviations.push_back(std::move(d));
  }
  for (const auto& [name, rb] : cb) {
    if (ca.count(name) == 0) only_in_one_run(name, "B");
  }
  return true;
}

}  // namespace

std::size_t RunComparison::past() const {
  return static_cast<std::size_t>(
      std::count_if(deviations.begin(), deviations.end(), [](const Deviation& d) { return d.past(); }));
}

bool find_run_files(const std::string& run, RunFiles& out, std::string& error) {
  out = RunFiles{};
  out.name = run;
  std::error_code ec;
  const fs::path p(run);
  if (fs::is_directory(p, ec)) {
    std::vector<fs::path> found;
    for (const auto& e : fs::directory_iterator(p, ec)) {
      const std::string f = e.path().filename().string();
      if (f.size() > kSummarySuffix.size() && f.ends_with(kSummarySuffix)) found.push_back(e.path());
    }
    if (found.size() != 1) {
      error = run + ": a run folder must hold exactly one NAME_summary.json (it holds " +
              std::to_string(found.size()) + "); give RUN as DIR/NAME_summary.json or DIR/NAME";
      return false;
    }
    out.summary = found.front().string();
  } else if (p.filename().string().ends_with(kSummarySuffix)) {
    out.summary = run;
  } else {
    out.summary = run + std::string(kSummarySuffix);  // the prefix DIR/NAME
  }
  if (!fs::is_regular_file(out.summary, ec)) {
    error = run + ": no run summary " + out.summary +
            " (RUN is a NAME_summary.json, a folder holding one, or the prefix DIR/NAME of a run)";
    return false;
  }
  const std::string s = out.summary;
  const std::string th = s.substr(0, s.size() - kSummarySuffix.size()) + "_th.h5";
  if (fs::is_regular_file(th, ec)) out.th = th;
  return true;
}

bool compare_runs(const RunFiles& a, const RunFiles& b, const CompareOptions& options, RunComparison& out,
                  std::string& error) {
  out = RunComparison{};
  if (!(options.rel >= 0) || (options.abs && !(*options.abs >= 0))) {
    error = "the tolerances must be numbers >= 0";
    return false;
  }
  RunSummary sa, sb;
  if (!read_summary_json(a.summary, sa, error) || !read_summary_json(b.summary, sb, error)) return false;
  compare_summaries(sa, sb, options, out);
  if (a.th.empty() != b.th.empty()) {
    error = (a.th.empty() ? b.th : a.th) + " has no counterpart beside " +
            (a.th.empty() ? a.summary : b.summary) + ": both runs need a time history, or neither";
    return false;
  }
  if (a.th.empty()) {
    out.notes.push_back("neither run has a time history: only their summaries are compared");
  } else {
    std::vector<ThGroupData> ga, gb;
    if (!read_time_history(a.th, ga, error) || !read_time_history(b.th, gb, error)) return false;
    if (!compare_histories(a, b, ga, gb, options, out, error)) return false;
  }
  std::stable_sort(out.deviations.begin(), out.deviations.end(),
                   [](const Deviation& x, const Deviation& y) { return x.score > y.score; });
  return true;
}

void write_comparison(const RunFiles& a, const RunFiles& b, const CompareOptions& o, const RunComparison& c,
                      std::ostream& os) {
  os << "A: " << a.summary << (a.th.empty() ? "" : ", " + a.th) << '\n';
  os << "B: " << b.summary << (b.th.empty() ? "" : ", " + b.th) << '\n';
  os << "compared: " << c.figures << " summary figures";
  if (c.channels > 0 || c.common_times > 0) {
    os << ", " << c.channels << " time-history channels at " << c.common_times << " times from "
       << number(c.first_time) << " to " << number(c.last_time)
       << (c.time_unit.empty() ? "" : " " + c.time_unit);
  }
  os << '\n';
  os << "tolerance: |B - A| <= max(" << number(o.rel) << " |A|, "
     << (o.abs ? number(*o.abs)
               : number(o.rel) + " x the largest magnitude of the channel's group and unit (figure's family)")
     << ")\n";
  for (const auto& n : c.notes) os << "note: " << n << '\n';
  const std::size_t past = c.past();
  os << (past == 0 ? "within the tolerance: " : "past the tolerance: ") << past << " of "
     << c.deviations.size() << '\n';
  const std::size_t shown = std::min(o.top, c.deviations.size());
  if (shown == 0) return;
  os << "largest deviations (score = |B - A| / allowed; past when above 1):\n";
  os << "  score        quantity                                  time          A                  B"
        "                  allowed\n";
  for (std::size_t i = 0; i < shown; ++i) {
    const auto& d = c.deviations[i];
    auto pad = [](std::string s, std::size_t w) {
      if (s.size() < w) s += std::string(w - s.size(), ' ');
      return s;
    };
    os << "  " << pad(std::isinf(d.score) ? "inf" : number(d.score, 4), 12) << ' ' << pad(d.quantity, 41)
       << ' ';
    if (!d.why.empty()) {
      os << d.why << '\n';
      continue;
    }
    os << pad(d.time ? number(*d.time) : "-", 13) << ' ' << pad(number(d.a, 10), 18) << ' '
       << pad(number(d.b, 10), 18) << ' ' << number(d.allowed, 4) << '\n';
  }
}

}  // namespace radx::io
