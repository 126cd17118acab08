// NAME.ref reading, checking and rewriting (io/regress/regress_reference.hpp).
#include "io/regress/regress_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace radx::io {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Token {
  std::size_t begin = 0, end = 0;  // [begin, end) in the line
};

// The blank-separated fields of a line before its '#' comment.
std::vector<Token> fields_of(std::string_view line) {
  const std::size_t hash = std::min(line.find('#'), line.size());
  std::vector<Token> out;
  std::size_t k = 0;
  while (k < hash) {
    while (k < hash && (line[k] == ' ' || line[k] == '\t' || line[k] == '\r')) ++k;
    if (k >= hash) break;
    Token t{k, k};
    while (t.end < hash && line[t.end] != ' ' && line[t.end] != '\t' && line[t.end] != '\r') ++t.end;
    out.push_back(t);
    k = t.end;
  }
  return out;
}

bool parse_number(std::string_view text, double& v) {
  const std::string s(text);
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return !s.empty() && end == s.c_str() + s.size() && std::isfinite(v);
}

// "th:COLUMN@TIME" -> COLUMN, TIME.
bool split_th(std::string_view name, std::string_view& column, double& time) {
  if (name.substr(0, 3) != "th:") return false;
  const std::size_t at = name.rfind('@');
  if (at == std::string_view::npos || at <= 3) return false;
  column = name.substr(3, at - 3);
  return parse_number(name.substr(at + 1), time);
}

std::optional<double> th_value(std::string_view column, double time, const std::vector<ThGroupData>& groups,
                               std::string& why) {
  for (const auto& g : groups) {
    const std::vector<ThColumn> cols = th_columns(g.layout, g.time_unit);
    for (std::size_t c = 1; c < cols.size(); ++c) {
      if (cols[c].name != column) continue;
      const std::size_t rows = g.columns ? g.rows.size() / g.columns : 0;
      if (rows == 0) {
        why = "the time history has no rows";
        return std::nullopt;
      }
      const auto t = [&](std::size_t r) { return g.rows[r * g.columns]; };
      const auto v = [&](std::size_t r) { return g.rows[r * g.columns + c]; };
      // A time within a millionth of the span of the first or last row is that row: a reference written at
      // the end time must not fail on the round-off of the last row's time.
      const double span = std::max(t(rows - 1) - t(0), std::abs(t(rows - 1)));
      const double slack = 1e-6 * span;
      if (time < t(0) - slack || time > t(rows - 1) + slack) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "time %g is outside the time history's rows (%g to %g)", time, t(0),
                      t(rows - 1));
        why = buf;
        return std::nullopt;
      }
      if (time <= t(0)) return v(0);
      if (time >= t(rows - 1)) return v(rows - 1);
      std::size_t r = 1;
      while (r + 1 < rows && t(r) < time) ++r;
      const double t0 = t(r - 1), t1 = t(r);
      const double w = t1 > t0 ? (time - t0) / (t1 - t0) : 1.0;
      return (1 - w) * v(r - 1) + w * v(r);
    }
  }
  why = "the time history has no column " + std::string(column) + " (`radx th NAME_th.h5` lists them)";
  return std::nullopt;
}

std::string read_file(const std::string& path, bool& ok) {
  std::ifstream f(path, std::ios::binary);
  ok = static_cast<bool>(f);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

}  // namespace

std::string reference_number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

bool valid_reference_quantity(std::string_view name, std::string& why) {
  if (std::find(kReferenceScalars.begin(), kReferenceScalars.end(), name) != kReferenceScalars.end())
    return true;
  std::string_view column;
  double time = 0;
  if (name.substr(0, 3) == "th:") {
    if (split_th(name, column, time) && !column.empty()) return true;
    why =
        "a time-history quantity is th:COLUMN@TIME, COLUMN as `radx th` names it (node/1:61:DZ, "
        "global:KE) and TIME a number";
    return false;
  }
  why = "unknown quantity; accepted: th:COLUMN@TIME or one of";
  for (const auto q : kReferenceScalars) why += " " + std::string(q);
  return false;
}

bool parse_regress_reference(std::string_view text, const std::string& file, RegressReference& out,
                             std::vector<std::string>& errors) {
  RegressReference ref;
  std::set<std::string, std::less<>> seen;
  const std::size_t errors_before = errors.size();
  std::size_t pos = 0, line_no = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_no;
    ref.lines.emplace_back(line);
    const std::vector<Token> f = fields_of(line);
    if (f.empty()) continue;
    const auto field = [&](std::size_t k) { return line.substr(f[k].begin, f[k].end - f[k].begin); };
    const std::string where = file + ":" + std::to_string(line_no) + ": ";
    const std::string name(field(0));
    if (f.size() != 4) {
      errors.push_back(where + name + ": " + std::to_string(f.size()) +
                       " field(s); a quantity line is QUANTITY VALUE REL_TOL ABS_FLOOR (VALUE '-' when not "
                       "recorded yet), then an optional # comment");
      continue;
    }
    ReferenceQuantity q;
    q.name = name;
    q.line = line_no;
    std::string why;
    if (!valid_reference_quantity(name, why)) errors.push_back(where + name + ": " + why);
    if (!seen.insert(name).second) errors.push_back(where + name + ": given twice; give each quantity once");
    double v = 0;
    if (field(1) != "-") {
      if (parse_number(field(1), v))
        q.value = v;
      else
        errors.push_back(where + name + ": value '" + std::string(field(1)) +
                         "' is not a number; give a finite number, or '-' for a value not recorded yet");
    }
    const char* tol_names[2] = {"REL_TOL", "ABS_FLOOR"};
    double* tols[2] = {&q.rel_tol, &q.abs_floor};
    for (int k = 0; k < 2; ++k) {
      if (!parse_number(field(2 + k), *tols[k]) || *tols[k] < 0)
        errors.push_back(where + name + ": " + tol_names[k] + " '" + std::string(field(2 + k)) +
                         "' is not a number >= 0 (REL_TOL a fraction, 0.01 for 1 %; ABS_FLOOR in the "
                         "quantity's unit)");
    }
    ref.quantities.push_back(std::move(q));
  }
  if (errors.size() == errors_before && ref.quantities.empty())
    errors.push_back(file +
                     ": holds no quantity, so it would pass whatever the run gives; a quantity line is "
                     "QUANTITY VALUE REL_TOL ABS_FLOOR (`radx regress --update` writes a default set when "
                     "the file is absent)");
  if (errors.size() != errors_before) return false;
  out = std::move(ref);
  return true;
}

bool read_regress_reference(const std::string& path, RegressReference& out,
                            std::vector<std::string>& errors) {
  bool ok = false;
  const std::string text = read_file(path, ok);
  if (!ok) {
    errors.push_back(path + ": cannot open the file");
    return false;
  }
  return parse_regress_reference(text, path, out, errors);
}

namespace {

// The run's figure for a quantity, as it is (NaN included).
std::optional<double> run_figure(std::string_view name, const RunSummary& s,
                                 const std::vector<ThGroupData>* th, std::string& why) {
  const EnergyBalance& e = s.energy;
  const auto over_interfaces = [&](auto pick, bool sum) -> std::optional<double> {
    if (s.interfaces.empty()) {
      why = "the run has no contact interface";
      return std::nullopt;
    }
    double r = sum ? 0.0 : -kInf;
    for (const auto& i : s.interfaces) r = sum ? r + pick(i) : std::max(r, pick(i));
    return r;
  };
  if (name == "cycles") return static_cast<double>(s.cycles);
  if (name == "time") return s.time;
  if (name == "dt") return s.dt;
  if (name == "initial_mass") return s.initial_mass;
  if (name == "mass") return s.mass;
  if (name == "added_mass") return s.added_mass;
  if (name == "energy.kinetic_translational") return e.kinetic_t;
  if (name == "energy.kinetic_rotational") return e.kinetic_r;
  if (name == "energy.internal") return e.internal;
  if (name == "energy.hourglass") return e.hourglass;
  if (name == "energy.external_work") return e.external_work;
  if (name == "energy.contact_elastic") return e.contact_elastic;
  if (name == "energy.contact_damping") return e.contact_damping;
  if (name == "energy.contact_friction") return e.contact_friction;
  if (name == "energy.contact_lagrange") return e.contact_lagrange;
  if (name == "energy.total") return e.total();
  if (name == "energy.error_percent") return e.error_percent();
  if (name == "max_penetration")
    return over_interfaces([](const InterfaceSummary& i) { return i.max_penetration; }, false);
  if (name == "switched_pairs_max")
    return over_interfaces([](const InterfaceSummary& i) { return double(i.switched_pairs_max); }, false);
  if (name == "switched_pairs_total")
    return over_interfaces([](const InterfaceSummary& i) { return double(i.switched_pairs_total); }, true);
  if (name == "removed_nodes")
    return over_interfaces([](const InterfaceSummary& i) { return double(i.removed_nodes); }, true);
  if (name == "momentum.x") return s.momentum[0];
  if (name == "momentum.y") return s.momentum[1];
  if (name == "momentum.z") return s.momentum[2];
  std::string_view column;
  double time = 0;
  if (split_th(name, column, time)) {
    if (!th) {
      why = "the run wrote no time history (NAME_th.h5)";
      return std::nullopt;
    }
    return th_value(column, time, *th, why);
  }
  why = "unknown quantity";
  return std::nullopt;
}

}  // namespace

std::optional<double> run_quantity(std::string_view name, const RunSummary& s,
                                   const std::vector<ThGroupData>* th, std::string& why) {
  std::optional<double> v = run_figure(name, s, th, why);
  if (v && !std::isfinite(*v)) {
    why = "the run's value is not a finite number";
    return std::nullopt;
  }
  return v;
}

std::vector<QuantityCheck> check_reference(const RegressReference& ref, const RunSummary& s,
                                           const std::vector<ThGroupData>* th) {
  std::vector<QuantityCheck> out;
  for (const auto& q : ref.quantities) {
    QuantityCheck c;
    c.name = q.name;
    c.reference = q.value;
    c.radx = run_quantity(q.name, s, th, c.why);
    if (!q.value) {
      c.why = "not recorded yet ('-'): `radx regress --update` records it";
      c.score = kInf;
    } else if (!c.radx) {
      c.score = kInf;
    } else {
      c.allowed = std::max(q.rel_tol * std::abs(*q.value), q.abs_floor);
      const double d = std::abs(*c.radx - *q.value);
      if (std::isnan(d))
        c.score = kInf;
      else
        c.score = c.allowed > 0 ? d / c.allowed : (d == 0 ? 0.0 : kInf);
    }
    out.push_back(std::move(c));
  }
  return out;
}

std::string updated_reference_text(const RegressReference& ref, const std::vector<double>& values) {
  std::vector<std::string> lines = ref.lines;
  for (std::size_t k = 0; k < ref.quantities.size() && k < values.size(); ++k) {
    if (std::isnan(values[k])) continue;
    std::string& line = lines[ref.quantities[k].line - 1];
    const std::vector<Token> f = fields_of(line);
    if (f.size() < 3) continue;
    const std::string text = reference_number(values[k]);
    // Keep the next field where it was when the new value fits before it (one blank at least); else one
    // blank separates them.
    const std::size_t room = f[2].begin - f[1].begin;
    const std::size_t pad = text.size() + 1 <= room ? room - text.size() : 1;
    line.replace(f[1].begin, room, text + std::string(pad, ' '));
  }
  std::string out;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    out += lines[k];
    if (k + 1 < lines.size()) out += '\n';
  }
  // The text split on '\n' gives a last empty line when it ended with one: keep exactly one line end.
  if (out.empty() || out.back() != '\n') out += '\n';
  return out;
}

std::string new_reference_text(const std::string& deck_name, const RunSummary& s) {
  const EnergyBalance& e = s.energy;
  // The run's energy scale: what a deviation of an energy is measured against when its own value is small.
  const double scale = std::max({std::abs(e.initial_total), std::abs(e.external_work), std::abs(e.total()),
                                 std::abs(e.internal), e.kinetic_t + e.kinetic_r});
  std::ostringstream o;
  o << "# radx regression reference of " << deck_name << "\n"
    << "# Written by `radx regress --update` from a run; --update rewrites the values and keeps the lines,\n"
    << "# their order, the tolerances and the comments. A quantity passes when\n"
    << "#   |radx - VALUE| <= max(REL_TOL |VALUE|, ABS_FLOOR)   (docs/regress.md)\n"
    << "# quantity                      value             rel_tol   abs_floor\n";
  const auto put = [&](std::string_view name, double v, double rel, double floor, const std::string& why) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%-30s %-17s %-9s %-11s # %s\n", std::string(name).c_str(),
                  reference_number(v).c_str(), reference_number(rel).c_str(), reference_number(floor).c_str(),
                  why.c_str());
    o << buf;
  };
  put("cycles", double(s.cycles), 0.01, 2, "1 % of the cycles: the step rule and the element sizes");
  put("time", s.time, 1e-9, 0, "the end time the engine deck sets");
  put("mass", s.mass, 1e-9, 0, "the model's mass (with any added mass)");
  if (s.added_mass > 0)
    put("added_mass", s.added_mass, 0.02, 1e-6 * s.initial_mass,
        "2 % of the mass the time-step control adds");
  const std::string energy_why =
      "2 % of the value, or 0.5 % of the run's energy scale (" + reference_number(scale) + ")";
  const std::pair<std::string_view, double> energies[] = {{"energy.kinetic_translational", e.kinetic_t},
                                                          {"energy.kinetic_rotational", e.kinetic_r},
                                                          {"energy.internal", e.internal},
                                                          {"energy.hourglass", e.hourglass},
                                                          {"energy.external_work", e.external_work},
                                                          {"energy.contact_elastic", e.contact_elastic},
                                                          {"energy.contact_damping", e.contact_damping},
                                                          {"energy.contact_friction", e.contact_friction},
                                                          {"energy.contact_lagrange", e.contact_lagrange}};
  // An energy at round-off level (1e-21 mJ of hourglass in a free fall) is left out: its value is noise.
  for (const auto& [name, v] : energies)
    if (std::abs(v) > 1e-9 * scale || name == "energy.internal" || name == "energy.kinetic_translational")
      put(name, v, 0.02, 0.005 * scale, energy_why);
  put("energy.error_percent", e.error_percent(), 0, 0.5, "half a percentage point of the energy balance");
  if (!s.interfaces.empty()) {
    std::string why;
    const double pen = *run_quantity("max_penetration", s, nullptr, why);
    put("max_penetration", pen, 0.05, 0, "5 % of the largest penetration");
    const double switched = *run_quantity("switched_pairs_max", s, nullptr, why);
    if (switched > 0)
      put("switched_pairs_max", switched, 0.1, 2, "10 % of the pairs solved with multipliers, or 2 pairs");
  }
  return o.str();
}

}  // namespace radx::io
