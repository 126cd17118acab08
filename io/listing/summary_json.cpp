#include "io/listing/summary_json.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace radx::io {

namespace {

// Length of the valid UTF-8 sequence starting at s[i], or 0 when the bytes there are not valid UTF-8.
std::size_t utf8_length(std::string_view s, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  std::size_t n = 0;
  unsigned lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) {
    n = 2;
  } else if (c >= 0xE0 && c <= 0xEF) {
    n = 3;
    if (c == 0xE0) lo = 0xA0;
    if (c == 0xED) hi = 0x9F;  // no surrogates
  } else if (c >= 0xF0 && c <= 0xF4) {
    n = 4;
    if (c == 0xF0) lo = 0x90;
    if (c == 0xF4) hi = 0x8F;
  } else {
    return 0;
  }
  if (i + n > s.size()) return 0;
  if (b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k)
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  return n;
}

class Writer {
 public:
  void open(char c) {
    out_ += c;
    ++depth_;
    first_ = true;
  }
  void close(char c) {
    --depth_;
    if (!first_) newline();
    out_ += c;
    first_ = false;
  }
  void key(std::string_view k) {
    if (!first_) out_ += ',';
    newline();
    out_ += json_string(k);
    out_ += ": ";
    first_ = true;  // the value follows the key directly
  }
  void item() {
    if (!first_) out_ += ',';
    newline();
  }
  void raw(const std::string& v) {
    out_ += v;
    first_ = false;
  }
  void field(std::string_view k, const std::string& json_value) {
    key(k);
    raw(json_value);
  }
  void field(std::string_view k, double v) { field(k, json_number(v)); }
  void field_int(std::string_view k, long long v) { field(k, std::to_string(v)); }
  std::string take() { return std::move(out_) + "\n"; }

 private:
  void newline() {
    out_ += '\n';
    out_.append(static_cast<std::size_t>(2 * depth_), ' ');
  }
  std::string out_;
  int depth_ = 0;
  bool first_ = true;
};

}  // namespace

std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 0x80) {
      switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\b': out += "\\b"; break;
        case '\f': out += "\\f"; break;
        case '\n': out += "\\n"; break;
        case '\r': out += "\\r"; break;
        case '\t': out += "\\t"; break;
        default:
          if (c < 0x20 || c == 0x7F) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", c);
            out += buf;
          } else {
            out += static_cast<char>(c);
          }
      }
      ++i;
      continue;
    }
    const std::size_t n = utf8_length(s, i);
    if (n == 0) {
      out += "\\ufffd";  // not UTF-8: the replacement character keeps the document valid
      ++i;
    } else {
      out.append(s.substr(i, n));
      i += n;
    }
  }
  out += '"';
  return out;
}

std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 17);
  return std::string(buf, r.ptr);
}

std::string_view status_name(RunStatus s) {
  switch (s) {
    case RunStatus::Normal: return "normal";
    case RunStatus::Error: return "error";
    case RunStatus::Interrupted: return "interrupted";
    case RunStatus::Running: return "running";
  }
  return "";
}

std::string summary_json(const RunSummary& s) {
  const EnergyBalance& e = s.energy;
  Writer w;
  w.open('{');
  w.field("status", json_string(status_name(s.status)));
  w.field("message", json_string(s.message));
  w.field("run_name", json_string(s.run_name));
  w.field_int("run_number", s.run_number);
  if (!s.version.empty()) w.field("version", json_string(s.version));
  if (!s.commit.empty()) w.field("commit", json_string(s.commit));
  if (!s.arch.empty()) w.field("arch", json_string(s.arch));
  if (!s.mass_unit.empty()) {
    w.key("units");
    w.open('{');
    w.field("mass", json_string(s.mass_unit));
    w.field("length", json_string(s.length_unit));
    w.field("time", json_string(s.time_unit));
    w.close('}');
  }
  w.field_int("cycles", static_cast<long long>(s.cycles));
  w.field("time", s.time);
  w.field("dt", s.dt);
  w.field_int("nodes", static_cast<long long>(s.nodes));
  w.field_int("elements", static_cast<long long>(s.elements));
  w.field_int("threads", s.threads);
  w.field("wall_seconds", s.wall_seconds);
  w.field("us_per_element_cycle", us_per_element_cycle(s));
  w.field("element_loop_seconds", s.element_loop_seconds);
  w.field("element_loop_us_per_element_cycle", us_per_element_cycle(s, s.element_loop_seconds));
  w.field("initial_mass", s.initial_mass);
  w.field("mass", s.mass);
  w.field("added_mass", s.added_mass);
  w.field("momentum", "[" + json_number(s.momentum[0]) + ", " + json_number(s.momentum[1]) + ", " +
                          json_number(s.momentum[2]) + "]");
  w.key("energy");
  w.open('{');
  w.field("kinetic", e.kinetic_t + e.kinetic_r);
  w.field("kinetic_translational", e.kinetic_t);
  w.field("kinetic_rotational", e.kinetic_r);
  w.field("internal", e.internal);
  w.field("hourglass", e.hourglass);
  w.field("external_work", e.external_work);
  w.field("contact_elastic", e.contact_elastic);
  w.field("contact_damping", e.contact_damping);
  w.field("contact_friction", e.contact_friction);
  w.field("contact_lagrange", e.contact_lagrange);
  w.field("initial_total", e.initial_total);
  w.field("total", e.total());
  w.field("error_percent", e.error_percent());
  w.close('}');
  w.key("interfaces");
  w.open('[');
  for (const auto& in : s.interfaces) {
    w.item();
    w.raw("{\"id\": " + std::to_string(in.id) + ", \"active_pairs\": " + std::to_string(in.active_pairs) +
          ", \"max_penetration\": " + json_number(in.max_penetration) +
          ", \"switched_pairs_max\": " + std::to_string(in.switched_pairs_max) +
          ", \"switched_pairs_total\": " + std::to_string(in.switched_pairs_total) + ", \"added_mass\": " +
          json_number(in.added_mass) + ", \"removed_nodes\": " + std::to_string(in.removed_nodes) +
          ", \"candidates_mean\": " + json_number(in.candidates_mean) +
          ", \"search_sorts\": " + std::to_string(in.search_sorts) + "}");
  }
  w.close(']');
  w.key("deleted_elements");
  w.open('{');
  w.field_int("total", static_cast<long long>(s.deleted_total()));
  w.key("by_part");
  w.open('[');
  for (const auto& p : s.deleted_by_part) {
    w.item();
    w.raw("{\"part\": " + std::to_string(p.part_id) + ", \"title\": " + json_string(p.title) +
          ", \"count\": " + std::to_string(p.count) + "}");
  }
  w.close(']');
  w.key("first");
  w.open('[');
  for (const auto& d : s.first_deleted) {
    w.item();
    w.raw("{\"element\": " + json_string(d.kind) + ", \"id\": " + std::to_string(d.element_id) +
          ", \"part\": " + std::to_string(d.part_id) + ", \"cycle\": " + std::to_string(d.cycle) +
          ", \"time\": " + json_number(d.time) + "}");
  }
  w.close(']');
  w.close('}');
  w.key("substitutions");
  w.open('[');
  for (const auto& text : s.substitutions) {
    w.item();
    w.raw(json_string(text));
  }
  w.close(']');
  w.key("warnings");
  w.open('[');
  for (const auto& text : s.warnings) {
    w.item();
    w.raw(json_string(text));
  }
  if (s.warnings_left_out > 0) {
    w.item();
    w.raw(json_string("... and " + std::to_string(s.warnings_left_out) + " more (see the listing)"));
  }
  w.close(']');
  if (s.lagrange.present) {
    const auto& L = s.lagrange;
    w.key("lagrange_solver");
    w.open('{');
    w.field_int("cycles", L.cycles);
    w.field_int("rows_max", L.rows_max);
    w.field_int("rows_total", L.rows_total);
    w.field_int("nonzeros_max", L.nonzeros_max);
    w.field_int("dropped_rows", L.dropped_rows);
    w.field_int("merged_rows", L.merged_rows);
    w.field_int("factorizations", L.factorizations);
    w.field_int("symbolic_analyses", L.analyses);
    w.field_int("symbolic_reuses", L.symbolic_reuses);
    w.field_int("active_set_passes", L.active_set_passes);
    w.field_int("active_set_passes_max", L.passes_max);
    w.field_int("unconverged_cycles", L.unconverged);
    w.field_int("regularisations", L.regularisations);
    w.field("beta_max", L.beta_max);
    w.field("seconds_assembly", L.seconds_assembly);
    w.field("seconds_factorization", L.seconds_factorization);
    w.field("seconds_solve", L.seconds_solve);
    w.close('}');
  }
  w.close('}');
  return w.take();
}

std::string summary_json_path(const std::string& dir, const std::string& output_root) {
  return (std::filesystem::path(dir) / (output_root + "_summary.json")).string();
}

namespace {

// One attempt at the summary: through `path.part`, flushed to disk, and a rename. False with `error`
// naming the file and the system's reason.
bool write_summary_once(const std::string& path, const std::string& text, std::string& error) {
  const std::string part = path + ".part";
  std::FILE* f = std::fopen(part.c_str(), "wb");
  if (!f) {
    error = "cannot create " + part + ": " + std::strerror(errno);
    return false;
  }
  int failure = std::fwrite(text.data(), 1, text.size(), f) == text.size() ? 0 : errno;
  if (std::fflush(f) != 0 && failure == 0) failure = errno;
  if (::fsync(::fileno(f)) != 0 && failure == 0) failure = errno;
  if (std::fclose(f) != 0 && failure == 0) failure = errno;
  std::error_code ec;
  if (failure != 0) {
    error = "cannot write " + part + ": " + std::strerror(failure);
    std::filesystem::remove(part, ec);
    return false;
  }
  std::filesystem::rename(part, path, ec);
  if (ec) {
    error = "cannot rename " + part + " to " + path + ": " + ec.message();
    std::filesystem::remove(part, ec);
    return false;
  }
  return true;
}

}  // namespace

bool write_summary_json(const std::string& path, const RunSummary& s, std::string& error) {
  const std::string text = summary_json(s);
  if (write_summary_once(path, text, error)) return true;
  // The summary there is the one written as the run started ("running"), which must not outlive the run:
  // removed, which on a full disk also frees its space for a second try.
  std::error_code ec;
  if (!std::filesystem::remove(path, ec) || ec) return false;
  std::string again;
  return write_summary_once(path, text, again);
}

namespace {

// A JSON value as the reader needs it: numbers as doubles (the counts written are far below 2^53), objects as
// ordered maps (duplicate keys: the last wins, as in most readers).
struct JsonValue {
  enum class Kind : std::uint8_t { Null, Boolean, Number, String, Array, Object } kind = Kind::Null;
  bool boolean = false;
  double number = 0;
  std::string string;
  std::vector<JsonValue> array;
  std::map<std::string, JsonValue, std::less<>> object;
};

// Recursive descent over RFC 8259; throws std::runtime_error naming the byte offset of the problem.
class JsonReader {
 public:
  explicit JsonReader(std::string_view text) : t_(text) {}
  JsonValue document() {
    JsonValue v = value(0);
    skip_space();
    if (i_ != t_.size()) fail("text after the document");
    return v;
  }

 private:
  static constexpr int kMaxDepth = 64;  // a summary nests three deep; this only stops runaway input

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error(what + " at byte " + std::to_string(i_));
  }
  void skip_space() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\t' || t_[i_] == '\n' || t_[i_] == '\r')) ++i_;
  }
  bool take(std::string_view word) {
    if (t_.substr(i_, word.size()) != word) return false;
    i_ += word.size();
    return true;
  }
  JsonValue value(int depth) {
    if (depth > kMaxDepth) fail("nesting too deep");
    skip_space();
    if (i_ >= t_.size()) fail("unexpected end of the document");
    JsonValue v;
    const char c = t_[i_];
    if (c == '{') {
      v.kind = JsonValue::Kind::Object;
      ++i_;
      skip_space();
      if (take("}")) return v;
      for (;;) {
        skip_space();
        if (i_ >= t_.size() || t_[i_] != '"') fail("expected a key");
        std::string k = string_literal();
        skip_space();
        if (!take(":")) fail("expected ':'");
        v.object[std::move(k)] = value(depth + 1);
        skip_space();
        if (take("}")) return v;
        if (!take(",")) fail("expected ',' or '}'");
      }
    }
    if (c == '[') {
      v.kind = JsonValue::Kind::Array;
      ++i_;
      skip_space();
      if (take("]")) return v;
      for (;;) {
        v.array.push_back(value(depth + 1));
        skip_space();
        if (take("]")) return v;
        if (!take(",")) fail("expected ',' or ']'");
      }
    }
    if (c == '"') {
      v.kind = JsonValue::Kind::String;
      v.string = string_literal();
      return v;
    }
    if (take("null")) return v;
    if (take("true") || take("false")) {
      v.kind = JsonValue::Kind::Boolean;
      v.boolean = t_[i_ - 2] == 'u';  // tr(u)e, fal(s)e
      return v;
    }
    v.kind = JsonValue::Kind::Number;
    v.number = number();
    return v;
  }
  double number() {
    const std::size_t start = i_;
    // The JSON grammar: -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)?
    auto digits = [&] {
      const std::size_t from = i_;
      while (i_ < t_.size() && t_[i_] >= '0' && t_[i_] <= '9') ++i_;
      return i_ > from;
    };
    if (i_ < t_.size() && t_[i_] == '-') ++i_;
    if (i_ < t_.size() && t_[i_] == '0') {
      ++i_;
    } else if (!digits()) {
      i_ = start;
      fail("expected a value");
    }
    if (i_ < t_.size() && t_[i_] == '.') {
      ++i_;
      if (!digits()) fail("expected digits after '.'");
    }
    if (i_ < t_.size() && (t_[i_] == 'e' || t_[i_] == 'E')) {
      ++i_;
      if (i_ < t_.size() && (t_[i_] == '+' || t_[i_] == '-')) ++i_;
      if (!digits()) fail("expected digits in the exponent");
    }
    double v = 0;
    const auto r = std::from_chars(t_.data() + start, t_.data() + i_, v);
    // Out of range: from_chars leaves v unset; a summary never holds such a number, but say so rather than 0.
    if (r.ec == std::errc::result_out_of_range) {
      i_ = start;
      fail("number out of range");
    }
    return v;
  }
  unsigned hex4() {
    if (i_ + 4 > t_.size()) fail("short \\u escape");
    unsigned u = 0;
    const auto r = std::from_chars(t_.data() + i_, t_.data() + i_ + 4, u, 16);
    if (r.ptr != t_.data() + i_ + 4) fail("bad \\u escape");
    i_ += 4;
    return u;
  }
  static void append_utf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }
  std::string string_literal() {
    ++i_;  // the opening quote
    std::string out;
    for (;;) {
      if (i_ >= t_.size()) fail("unterminated string");
      const char c = t_[i_++];
      if (c == '"') return out;
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string");
      if (c != '\\') {
        out += c;
        continue;
      }
      if (i_ >= t_.size()) fail("unterminated string");
      switch (t_[i_++]) {
        case '"': out += '"'; break;
        case '\\': out += '\\'; break;
        case '/': out += '/'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'n': out += '\n'; break;
        case 'r': out += '\r'; break;
        case 't': out += '\t'; break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xD800 && cp <= 0xDBFF && take("\\u")) {
            const unsigned lo = hex4();
            cp = lo >= 0xDC00 && lo <= 0xDFFF ? 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00) : 0xFFFD;
          } else if (cp >= 0xD800 && cp <= 0xDFFF) {
            cp = 0xFFFD;  // a lone surrogate is no character
          }
          append_utf8(out, cp);
          break;
        }
        default: fail("unknown escape");
      }
    }
  }

  std::string_view t_;
  std::size_t i_ = 0;
};

const JsonValue* member(const JsonValue& v, std::string_view key) {
  if (v.kind != JsonValue::Kind::Object) return nullptr;
  const auto it = v.object.find(key);
  return it == v.object.end() ? nullptr : &it->second;
}

// A number member: NaN when it is null (non-finite values are written as null); `fallback` when absent.
double number_member(const JsonValue& v, std::string_view key, double fallback = 0) {
  const JsonValue* m = member(v, key);
  if (!m) return fallback;
  if (m->kind == JsonValue::Kind::Number) return m->number;
  if (m->kind == JsonValue::Kind::Null) return std::numeric_limits<double>::quiet_NaN();
  throw std::runtime_error("\"" + std::string(key) + "\" is not a number");
}

std::string string_member(const JsonValue& v, std::string_view key) {
  const JsonValue* m = member(v, key);
  if (!m) return {};
  if (m->kind != JsonValue::Kind::String)
    throw std::runtime_error("\"" + std::string(key) + "\" is not a string");
  return m->string;
}

}  // namespace

bool read_summary_json(const std::string& path, RunSummary& s, std::string& error) {
  std::ifstream f(path, std::ios::binary);
  if (!f) {
    error = path + ": cannot open the file";
    return false;
  }
  std::ostringstream text;
  text << f.rdbuf();
  try {
    const JsonValue d = JsonReader(text.str()).document();
    if (d.kind != JsonValue::Kind::Object) throw std::runtime_error("the document is not an object");
    for (const char* key : {"status", "cycles", "time", "energy"})
      if (!member(d, key)) throw std::runtime_error(std::string("no \"") + key + "\" key");
    const std::string status = string_member(d, "status");
    RunSummary r;
    bool known = false;
    for (const auto k : {RunStatus::Normal, RunStatus::Error, RunStatus::Interrupted, RunStatus::Running})
      if (status == status_name(k)) {
        r.status = k;
        known = true;
      }
    if (!known)
      throw std::runtime_error("status \"" + status +
                               "\" is none of \"normal\", \"error\", \"interrupted\", \"running\"");
    r.message = string_member(d, "message");
    r.run_name = string_member(d, "run_name");
    r.run_number = static_cast<int>(number_member(d, "run_number", 1));
    r.version = string_member(d, "version");
    r.commit = string_member(d, "commit");
    r.arch = string_member(d, "arch");
    if (const JsonValue* u = member(d, "units"); u && u->kind == JsonValue::Kind::Object) {
      r.mass_unit = string_member(*u, "mass");
      r.length_unit = string_member(*u, "length");
      r.time_unit = string_member(*u, "time");
    }
    r.cycles = static_cast<std::int64_t>(number_member(d, "cycles"));
    r.time = number_member(d, "time");
    r.dt = number_member(d, "dt");
    r.nodes = static_cast<std::size_t>(number_member(d, "nodes"));
    r.elements = static_cast<std::size_t>(number_member(d, "elements"));
    r.threads = static_cast<int>(number_member(d, "threads", 1));
    r.wall_seconds = number_member(d, "wall_seconds");
    r.element_loop_seconds = number_member(d, "element_loop_seconds");
    r.initial_mass = number_member(d, "initial_mass");
    r.mass = number_member(d, "mass");
    r.added_mass = number_member(d, "added_mass");
    if (const JsonValue* m = member(d, "momentum");
        m && m->kind == JsonValue::Kind::Array && m->array.size() == 3) {
      for (std::size_t k = 0; k < 3; ++k)
        r.momentum[k] = m->array[k].kind == JsonValue::Kind::Number
                            ? m->array[k].number
                            : std::numeric_limits<double>::quiet_NaN();
    }
    const JsonValue& e = *member(d, "energy");
    if (e.kind != JsonValue::Kind::Object) throw std::runtime_error("\"energy\" is not an object");
    r.energy.kinetic_t = number_member(e, "kinetic_translational");
    r.energy.kinetic_r = number_member(e, "kinetic_rotational");
    r.energy.internal = number_member(e, "internal");
    r.energy.hourglass = number_member(e, "hourglass");
    r.energy.external_work = number_member(e, "external_work");
    r.energy.contact_elastic = number_member(e, "contact_elastic");
    r.energy.contact_damping = number_member(e, "contact_damping");
    r.energy.contact_friction = number_member(e, "contact_friction");
    r.energy.contact_lagrange = number_member(e, "contact_lagrange");
    r.energy.initial_total = number_member(e, "initial_total");
    if (const JsonValue* list = member(d, "interfaces"); list && list->kind == JsonValue::Kind::Array) {
      for (const JsonValue& i : list->array) {
        if (i.kind != JsonValue::Kind::Object)
          throw std::runtime_error("an \"interfaces\" entry is not an object");
        InterfaceSummary is;
        is.id = static_cast<std::int64_t>(number_member(i, "id"));
        is.active_pairs = static_cast<std::int64_t>(number_member(i, "active_pairs"));
        is.max_penetration = number_member(i, "max_penetration");
        is.switched_pairs_max = static_cast<std::int64_t>(number_member(i, "switched_pairs_max"));
        is.switched_pairs_total = static_cast<std::int64_t>(number_member(i, "switched_pairs_total"));
        is.added_mass = number_member(i, "added_mass");
        is.removed_nodes = static_cast<std::int64_t>(number_member(i, "removed_nodes"));
        is.candidates_mean = number_member(i, "candidates_mean");
        is.search_sorts = static_cast<std::int64_t>(number_member(i, "search_sorts"));
        r.interfaces.push_back(is);
      }
    }
    s = std::move(r);
    return true;
  } catch (const std::exception& ex) {
    error = path + ": " + ex.what();
    return false;
  }
}

}  // namespace radx::io
