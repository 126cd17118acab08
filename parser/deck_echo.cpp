#include "parser/deck_echo.hpp"

#include <iomanip>
#include <ostream>
#include <sstream>

namespace radx {

using schema::FieldDecl;
using schema::FieldType;

namespace {

std::string value_text(const FieldValue& v) {
  std::ostringstream os;
  switch (v.decl->type) {
    case FieldType::Int: os << v.i; break;
    case FieldType::Real: os << std::setprecision(8) << v.r; break;
    case FieldType::String: os << '\'' << v.s << '\''; break;
  }
  return os.str();
}

std::string dim_text(schema::Dim d) {
  if (d.none()) return "-";
  std::string s;
  auto part = [&](const char* sym, int e) {
    if (e == 0) return;
    if (!s.empty()) s += " ";
    s += sym;
    if (e != 1) s += "^" + std::to_string(e);
  };
  part("M", d.m);
  part("L", d.l);
  part("T", d.t);
  return s;
}

std::string versions_text(int since, int until) {
  if (since <= schema::kAnyVersion && until >= schema::kLastVersion) return "all";
  if (since <= schema::kAnyVersion) return "<= " + std::to_string(until);
  if (until >= schema::kLastVersion) return ">= " + std::to_string(since);
  return std::to_string(since) + "-" + std::to_string(until);
}

std::string condition_text(const schema::Condition& c) {
  const std::string f(c.field);
  switch (c.op) {
    case schema::CondOp::Always: return "";
    case schema::CondOp::Eq: return "only if " + f + " = " + std::to_string(c.a);
    case schema::CondOp::Ne: return "only if " + f + " != " + std::to_string(c.a);
    case schema::CondOp::Gt: return "only if " + f + " > " + std::to_string(c.a);
    case schema::CondOp::InRange:
      return "only if " + f + " in [" + std::to_string(c.a) + ", " + std::to_string(c.b) + "]";
  }
  return "";
}

std::string rule_text(const FieldDecl& f) {
  std::ostringstream os;
  if (f.required) os << "required; ";
  if (f.zero_default) os << "0 -> " << *f.zero_default << "; ";
  if (!f.allowed.empty()) {
    os << "one of {";
    for (std::size_t i = 0; i < f.allowed.size(); ++i) os << (i ? ", " : "") << f.allowed[i];
    os << "}; ";
  }
  if (f.min) os << (f.min_exclusive ? "> " : ">= ") << *f.min << "; ";
  if (f.max) os << (f.max_exclusive ? "< " : "<= ") << *f.max << "; ";
  if (f.ignored) os << "read, not used; ";
  std::string s = os.str();
  if (s.size() >= 2) s.resize(s.size() - 2);
  return s.empty() ? "-" : s;
}

void field_rows(std::ostream& os, const std::vector<FieldDecl>& fields) {
  os << "| field | columns | type | versions | unit | rule | meaning |\n|---|---|---|---|---|---|---|\n";
  for (const auto& f : fields) {
    const char* type = f.type == FieldType::Int ? "I" : (f.type == FieldType::Real ? "R" : "S");
    os << "| " << f.name << " | " << f.first_col << "-" << f.last_col << " | " << type << " | "
       << versions_text(f.since, f.until) << " | " << dim_text(f.dimension) << " | " << rule_text(f) << " | "
       << f.meaning << " |\n";
  }
}

}  // namespace

std::vector<std::string> echo_keyword(const KeywordRecord& r) {
  std::vector<std::string> lines;
  for (const auto& v : r.fields) {
    std::ostringstream os;
    std::string value = value_text(v);
    if (v.defaulted)
      value += " (default)";
    else if (v.blank)
      value += " (blank)";
    os << "    " << std::left << std::setw(14) << v.decl->name << std::setw(24) << value << v.decl->meaning;
    lines.push_back(os.str());
  }
  return lines;
}

void write_keyword_reference(std::ostream& os) {
  os << "# radx keyword reference\n\n"
     << "Generated from the keyword declarations (`parser/keywords_starter.cpp`, "
        "`parser/keywords_engine.cpp`) by "
        "`radx keywords --markdown`; do not edit by hand (`cmake --build build --target keyword-docs`).\n\n"
     << "Columns are 1-based and inclusive. Units: M mass, L length, T time (the field is converted from the "
        "deck's input units to its work units). Versions are the `/BEGIN` deck version (INVERS).\n\n"
     << "## Starter keywords\n\n";
  for (const auto& k : schema::starter_keywords()) {
    os << "### " << k.path << "\n\n";
    if (!k.aliases.empty()) {
      os << "Also written:";
      for (auto a : k.aliases) os << " `" << a << "`";
      os << ".\n\n";
    }
    os << k.meaning << (k.support == schema::Support::Ignored ? " **Accepted and ignored by radx.**" : "")
       << "\n\n";
    os << "Title line: " << (k.has_title ? "yes" : "no") << ".\n\n";
    for (const auto& c : k.cards) {
      os << "**" << c.name << "**";
      const auto cond = condition_text(c.condition);
      if (!cond.empty()) os << " (" << cond << ")";
      if (c.since > schema::kAnyVersion || c.until < schema::kLastVersion)
        os << " (versions " << versions_text(c.since, c.until) << ")";
      os << "\n\n";
      field_rows(os, c.fields);
      os << "\n";
    }
    for (const auto& o : k.dim_overrides) {
      os << "Unit of " << o.field << ": " << dim_text(o.dimension) << " when " << o.when_field << " is";
      for (auto v : o.when_values) os << ' ' << v;
      os << ".\n\n";
    }
    using schema::Tail;
    switch (k.tail) {
      case Tail::None: break;
      case Tail::Records:
        os << "Then one record per line:\n\n";
        field_rows(os, k.record.fields);
        os << "\n";
        break;
      case Tail::IdList: os << "Then ids, 10 per line in 10-column cells.\n\n"; break;
      case Tail::Text: os << "Then text lines, joined with blanks removed.\n\n"; break;
      case Tail::ThVarsThenIds:
        os << "Then variable-name lines (10-column cells), then object ids.\n\n";
        break;
      case Tail::ThVarsThenRecords:
        os << "Then variable-name lines (10-column cells), then one object per line:\n\n";
        field_rows(os, k.record.fields);
        os << "\n";
        break;
    }
  }
  os << "## Engine keywords\n\nFree format: values separated by blanks or commas, one declared line each. "
        "Every keyword of the Radioss engine deck is listed; the radx column says what radx does with it: "
        "**read**; **ignored** (it changes no result: a note, RX303); **not written** (an output radx does "
        "not "
        "write: a warning, RX311, and the run goes on); **refused** (it changes the results and radx cannot "
        "run "
        "it: an error, RX302). A keyword radx does not read also takes any further fields after its path, "
        "and "
        "its data lines are passed over. A keyword whose first field is none of these is unknown (RX301).\n\n"
     << "| keyword | header fields | data lines | radx | meaning |\n|---|---|---|---|---|\n";
  for (const auto& k : schema::engine_keywords()) {
    os << "| " << k.path;
    for (auto a : k.aliases) os << " (" << a << ")";
    os << " | ";
    for (auto h : k.header_fields) os << h << " ";
    os << "| ";
    for (const auto& l : k.lines) {
      os << "[";
      for (std::size_t i = 0; i < l.names.size(); ++i) os << (i ? " " : "") << l.names[i];
      os << "] (" << l.required << " required) ";
    }
    if (k.id_lines) os << "ids, any number of lines";
    os << " | ";
    switch (k.support) {
      case schema::Support::Read: os << "read"; break;
      case schema::Support::Ignored: os << "ignored: " << k.reason; break;
      case schema::Support::NotWritten: os << "not written: " << k.reason; break;
      case schema::Support::Unsupported: os << "refused: " << k.reason; break;
    }
    os << " | " << k.meaning << " |\n";
  }
  os << "\n## Diagnostic codes\n\n| code | meaning |\n|---|---|\n";
  for (auto d : all_diag_codes()) os << "| " << diag_code(d) << " | " << diag_summary(d) << " |\n";
}

}  // namespace radx
