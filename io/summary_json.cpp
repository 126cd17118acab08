#include "io/summary_json.hpp"

#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

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

std::string summary_json(const RunSummary& s) {
  const EnergyBalance& e = s.energy;
  Writer w;
  w.open('{');
  w.field("status", json_string(s.status == RunStatus::Normal ? "normal" : "error"));
  w.field("message", json_string(s.message));
  w.field("run_name", json_string(s.run_name));
  w.field_int("run_number", s.run_number);
  w.field_int("cycles", static_cast<long long>(s.cycles));
  w.field("time", s.time);
  w.field("dt", s.dt);
  w.field_int("nodes", static_cast<long long>(s.nodes));
  w.field_int("elements", static_cast<long long>(s.elements));
  w.field_int("threads", s.threads);
  w.field("wall_seconds", s.wall_seconds);
  w.field("us_per_element_cycle", us_per_element_cycle(s));
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
          json_number(in.added_mass) + ", \"removed_nodes\": " + std::to_string(in.removed_nodes) + "}");
  }
  w.close(']');
  w.key("substitutions");
  w.open('[');
  for (const auto& text : s.substitutions) {
    w.item();
    w.raw(json_string(text));
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

bool write_summary_json(const std::string& path, const RunSummary& s, std::string& error) {
  const std::string text = summary_json(s);
  const std::string part = path + ".part";
  std::FILE* f = std::fopen(part.c_str(), "wb");
  if (!f) {
    error = "cannot create " + part;
    return false;
  }
  bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  ok = std::fflush(f) == 0 && ok;
  ok = ::fsync(::fileno(f)) == 0 && ok;
  ok = std::fclose(f) == 0 && ok;
  std::error_code ec;
  if (!ok) {
    error = "cannot write " + part;
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

}  // namespace radx::io
