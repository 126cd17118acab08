// Shell stresses at the bottom, middle and top layers and at the through-thickness points
// (solver/outputs/result_fields.hpp) against the closed forms of a plate section:
// * pure bending by a moment M per unit length: sigma(z) = 12 M z / t^3, so the top (z = +t/2) is
//   +6 M/t^2, the bottom -6 M/t^2 and the middle 0, for a resultant section (N = 0, FOR = N/t and
//   MOM = M/t^2) and for integrated sections of 2 to 5 points holding that distribution at their points;
// * membrane force N per unit length: the three layers all N/t;
// * QBAT's four in-plane Gauss points: their mean.
// Tolerance: the values are sums of a few doubles of order 1e8 Pa; 1e-12 relative is rounding.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "solver/elements/shell/shell_section.hpp"
#include "solver/outputs/result_fields.hpp"

namespace {

namespace sv = radx::solver;
using sv::ShellLayer;

constexpr double kT = 0.002;                    // thickness, m
constexpr double kM = 40.0;                     // bending moment per unit length, N m / m
constexpr double kN = 3.0e5;                    // membrane force per unit length, N / m
constexpr double kBend = 6.0 * kM / (kT * kT);  // 6 M / t^2 = 6e7 Pa
constexpr double kMembrane = kN / kT;           // N / t = 1.5e8 Pa

void check_close(double got, double want) {
  CHECK(std::abs(got - want) <= 1e-12 * std::max(std::abs(want), kBend));
}

// Element 1 of a group of `points` points (0: resultants) and `gauss` in-plane points, with sxx from
// N and M, syy = sxx / 2 and sxy = sxx / 4 so that the three in-plane rows are checked, and the
// transverse shear szx = 1e6 Pa constant; Gauss point gp scaled by (1 + gp) / mean so their mean is the
// section's.
sv::ShellGroup make_section(int points, int gauss, double n, double m) {
  sv::ShellGroup g;
  g.allocate(2, points, gauss);
  const double mean_scale = (gauss + 1) / 2.0;  // mean of 1 .. gauss
  const auto G = static_cast<std::size_t>(sv::kGroupSize);
  const std::size_t rows = static_cast<std::size_t>(points <= 0 ? 8 : 5 * points) * G;
  for (int gp = 0; gp < gauss; ++gp) {
    const double f = (1.0 + gp) / mean_scale;
    double* sig = g.sig.data() + static_cast<std::size_t>(gp) * rows;
    const std::array<double, 3> ratio{1.0, 0.5, 0.25};
    if (points <= 0) {
      for (std::size_t q = 0; q < 3; ++q) {
        sig[q * G + 1] = f * ratio[q] * n / kT;               // FOR = N / t
        sig[(5 + q) * G + 1] = f * ratio[q] * m / (kT * kT);  // MOM = M / t^2
      }
      sig[4 * G + 1] = f * 1e6;
      continue;
    }
    const auto rule = sv::shell_detail::thickness_rule(points);
    for (int p = 0; p < points; ++p) {
      const double z = rule.zeta[p] * kT;
      const double s = n / kT + 12.0 * m * z / (kT * kT * kT);
      for (int q = 0; q < 3; ++q)
        sig[sv::shell_detail::sig_index(p, q, 1)] = f * ratio[static_cast<std::size_t>(q)] * s;
      sig[sv::shell_detail::sig_index(p, 4, 1)] = f * 1e6;
    }
  }
  return g;
}

void check_layers(const sv::ShellGroup& g, double bottom, double middle, double top) {
  const std::array<double, 3> ratio{1.0, 0.5, 0.25};
  const std::array<std::pair<ShellLayer, double>, 3> want{
      {{ShellLayer::Bottom, bottom}, {ShellLayer::Middle, middle}, {ShellLayer::Top, top}}};
  for (const auto& [layer, value] : want) {
    INFO("layer " << static_cast<int>(layer));
    const auto s = sv::shell_layer_stress(g, 1, layer);
    for (std::size_t q = 0; q < 3; ++q) check_close(s[q], ratio[q] * value);
    check_close(s[3], 0.0);
    check_close(s[4], 1e6);
  }
}

}  // namespace

TEST_CASE("shell layers under pure bending: top +6M/t^2, bottom -6M/t^2, middle 0", "[results-fields]") {
  for (const int points : {0, 2, 3, 4, 5}) {
    for (const int gauss : {1, 4}) {
      INFO(points << " points, " << gauss << " in-plane Gauss points");
      check_layers(make_section(points, gauss, 0.0, kM), -kBend, 0.0, kBend);
    }
  }
}

TEST_CASE("shell layers under a membrane force: all three N/t", "[results-fields]") {
  for (const int points : {0, 1, 2, 3, 5}) {
    INFO(points << " points");
    check_layers(make_section(points, 1, kN, 0.0), kMembrane, kMembrane, kMembrane);
  }
}

TEST_CASE("shell layers under bending and membrane: N/t -+ 6M/t^2", "[results-fields]") {
  for (const int points : {0, 3, 4}) {
    INFO(points << " points");
    check_layers(make_section(points, 4, kN, kM), kMembrane - kBend, kMembrane, kMembrane + kBend);
  }
}

TEST_CASE("shell point stresses: point k at zeta_k, bottom to top", "[results-fields]") {
  const int points = 5;
  const auto g = make_section(points, 4, 0.0, kM);
  const auto rule = sv::shell_detail::thickness_rule(points);
  for (int p = 0; p < points; ++p) {
    INFO("point " << p);
    // sigma(z) = 12 M z / t^3 at z = zeta t: -6M/t^2, -3M/t^2, 0, 3M/t^2, 6M/t^2.
    check_close(sv::shell_point_stress(g, 1, p)[0], 12.0 * kM * rule.zeta[p] / (kT * kT));
  }
  check_close(sv::shell_point_stress(g, 1, 0)[0], -kBend);
  check_close(sv::shell_point_stress(g, 1, points - 1)[0], kBend);
}
