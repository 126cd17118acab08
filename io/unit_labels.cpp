#include "io/unit_labels.hpp"

namespace radx::io {

namespace {

std::string power(const std::string& name, int e) {
  return e == 1 ? name : name + std::to_string(e);
}

}  // namespace

std::string unit_label(const model::Units& u, int mass, int length, int time) {
  if (mass == 0 && length == 0 && time == 0) return "1";
  const bool si = u.mass_name == "kg" && u.length_name == "m" && u.time_name == "s";
  if (si) {
    struct Named {
      int m, l, t;
      const char* name;
    };
    static constexpr Named kNamed[] = {
        {1, 2, -2, "J"}, {1, 1, -2, "N"}, {1, 0, -2, "N/m"}, {1, -1, -2, "Pa"}};
    for (const auto& n : kNamed)
      if (n.m == mass && n.l == length && n.t == time) return n.name;
  }
  std::string num, den;
  auto add = [&](const std::string& name, int e) {
    if (e > 0) num += (num.empty() ? "" : ".") + power(name, e);
    if (e < 0) den += (den.empty() ? "" : ".") + power(name, -e);
  };
  add(u.mass_name, mass);
  add(u.length_name, length);
  add(u.time_name, time);
  if (num.empty()) num = "1";
  return den.empty() ? num : num + "/" + den;
}

}  // namespace radx::io
