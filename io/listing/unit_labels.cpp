#include "io/listing/unit_labels.hpp"

namespace radx::io {

namespace {

std::string power(const std::string& name, int e) {
  return e == 1 ? name : name + std::to_string(e);
}

}  // namespace

std::string unit_label(const model::Units& u, int mass, int length, int time) {
  if (mass == 0 && length == 0 && time == 0) return "1";
  // The consistent unit systems crash decks use, with the names engineers read: energy, force, force per
  // length, stress.
  struct System {
    const char *mass, *length, *time;
    const char* names[4];
  };
  static constexpr System kSystems[] = {
      {"kg", "m", "s", {"J", "N", "N/m", "Pa"}},
      {"Mg", "mm", "s", {"mJ", "N", "N/mm", "MPa"}},
      {"kg", "mm", "ms", {"J", "kN", "kN/mm", "GPa"}},
      {"g", "mm", "ms", {"mJ", "N", "N/mm", "MPa"}},
  };
  static constexpr int kDims[4][3] = {{1, 2, -2}, {1, 1, -2}, {1, 0, -2}, {1, -1, -2}};
  for (const auto& sys : kSystems) {
    if (u.mass_name != sys.mass || u.length_name != sys.length || u.time_name != sys.time) continue;
    for (int k = 0; k < 4; ++k)
      if (kDims[k][0] == mass && kDims[k][1] == length && kDims[k][2] == time) return sys.names[k];
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
