// Result fields (solver/outputs/result_fields.hpp) against independent quantities:
// * every /ANIM name the engine deck accepts has a field the engine can fill (the two tables agree);
// * Johnson-Cook brick (decks/verification/jc_single_brick): the von Mises output lies on the flow curve
//   a + b eps_p^n of the plastic-strain output; the axial stress equals it and the pressure is -1/3 of it
//   (uniaxial stress); the density is rho0 V0 / V with V the hexahedron volume of the current nodes; the
//   displacement of the pulled face is V t;
// * shells (decks/block_on_plate after 300 cycles): the global stress tensor of each shell is plane stress
//   in the element: n.sigma.n = 0 with n the normal of the current diagonals (computed here), and the von
//   Mises value of the tensor equals the one of the through-thickness mean stress in the element frame
//   (rotation invariance); the stress at each through-thickness point, weighted by the rule, sums to that
//   mean, and the bottom and top layers are the first and last points (test_shell_layers.cpp checks the
//   layers against closed forms).
// Tolerances: outputs are float32 (relative 6e-8 rounding, so 1e-6 of the value); the flow-curve lag of an
// explicit hardening step is bounded by 1e-5 of the flow stress once eps_p > 1e-3 (test_verification.cpp);
// the lateral inertia stress of the brick is below 1e-3 of the flow stress (jc_single_brick README).
#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "contact/type7_prepare.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"
#include "solver/elements/shell/shell_section.hpp"
#include "solver/model/geometry.hpp"
#include "solver/outputs/result_fields.hpp"

namespace {

namespace sv = radx::solver;
namespace md = radx::model;

struct Case {
  md::Model model;
  md::RunControls controls;
};

Case load(const std::string& rel_dir, const std::string& root) {
  const std::string dir = std::string(RADX_SOURCE_DIR) + "/decks/" + rel_dir + "/";
  radx::Diagnostics d;
  const radx::Deck deck = radx::read_starter_deck(dir + root + "_0000.rad", d);
  Case c;
  c.model = radx::build_model(deck, d);
  REQUIRE(!d.has_errors());
  radx::contact::prepare_type7_interfaces(c.model);
  c.controls = radx::read_run_controls(dir + root + "_0001.rad", d);
  REQUIRE(!d.has_errors());
  return c;
}

}  // namespace

TEST_CASE("every /ANIM name maps to a field the engine fills", "[results-fields]") {
  for (const auto& a : radx::anim_field_names()) {
    const std::string array(a.array);
    INFO(std::string(a.family) + "/" + std::string(a.name) + " -> " + array);
    const bool always = array == "displacement" || array == "velocity";
    const auto cell = sv::cell_field_named(array);
    const auto node = sv::node_field_named(array);
    CHECK((always || cell.has_value() || node.has_value()));
    CHECK(!(cell.has_value() && node.has_value()));
    if (cell) CHECK((a.family == "/ANIM/ELEM" || a.family == "/ANIM/TENS"));
    if (node) CHECK((a.family == "/ANIM/VECT" || a.family == "/ANIM/NODA"));
    if (cell) CHECK(sv::field_name(*cell) == array);
    if (node) CHECK(sv::field_name(*node) == array);
  }
}

TEST_CASE("Johnson-Cook brick: von Mises on the flow curve, uniaxial stress, density, displacement",
          "[results-fields]") {
  Case c = load("verification/jc_single_brick", "JC_SINGLE_BRICK");
  const md::Model& m = c.model;
  const auto& mat = m.materials.at(0);
  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions(1));
  double dt1 = 0;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    dt1 = r.dt1;
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);
  std::vector<float> vm(1), ep(1), p(1), rho(1), sig(6), disp(3 * m.nodes.size());
  sv::gather_cell_field(eng, sv::CellField::VonMises, vm);
  sv::gather_cell_field(eng, sv::CellField::PlasticStrain, ep);
  sv::gather_cell_field(eng, sv::CellField::Pressure, p);
  sv::gather_cell_field(eng, sv::CellField::Density, rho);
  sv::gather_cell_field(eng, sv::CellField::Stress, sig);
  sv::gather_node_field(eng, sv::NodeField::Displacement, dt1, disp);
  REQUIRE(ep[0] > 1e-3);
  const double flow = mat.a + mat.b * std::pow(static_cast<double>(ep[0]), mat.n);
  CHECK(std::abs(vm[0] - flow) <= 1e-5 * flow + 1e-6 * flow);
  CHECK(std::abs(sig[2] - flow) <= 1e-3 * flow);      // axial = von Mises (uniaxial)
  CHECK(std::abs(p[0] + flow / 3.0) <= 1e-3 * flow);  // pressure = -axial / 3
  CHECK(std::abs(sig[3]) + std::abs(sig[4]) + std::abs(sig[5]) <= 1e-6 * flow);  // no shear
  std::array<md::Vec3, 8> x{}, x0{};
  const auto& s = eng.nodes();
  for (int k = 0; k < 8; ++k) {
    const auto n = static_cast<std::size_t>(m.bricks.conn[static_cast<std::size_t>(k)]);
    x[static_cast<std::size_t>(k)] = {s.x[n], s.y[n], s.z[n]};
    x0[static_cast<std::size_t>(k)] = {m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]};
  }
  const double rho_expected = mat.rho * md::brick_volume(x0) / md::brick_volume(x);
  CHECK(std::abs(rho[0] - rho_expected) <= 1e-6 * rho_expected);
  // The pulled face moves at the imposed speed V from t = 0: dz = V t (deck README: V = Fscale_y).
  const double v = m.imposed_velocities.at(0).fscale_y;
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes.z[n] > 0) CHECK(std::abs(disp[3 * n + 2] - v * res.time) <= 1e-6 * v * res.time);
}

TEST_CASE("shell stress output: plane stress in the element, von Mises invariant under the rotation",
          "[results-fields]") {
  Case c = load("block_on_plate", "BLOCK_ON_PLATE");
  c.controls.t_stop = 1e30;
  const md::Model& m = c.model;
  REQUIRE(m.shells.size() > 0);
  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions(1));
  const auto res = eng.run([&](const sv::CycleReport& r) { return r.cycle < 300; });
  REQUIRE(res.cycles >= 300);
  std::vector<float> sig(6 * m.element_count()), vm(m.element_count());
  sv::gather_cell_field(eng, sv::CellField::Stress, sig);
  sv::gather_cell_field(eng, sv::CellField::VonMises, vm);
  const auto& s = eng.nodes();
  double largest = 0;
  int checked = 0;
  for (const auto& g : eng.groups().shells) {
    if (g.triangle) continue;
    const int np = g.props.n_points;
    const auto rule = sv::shell_detail::thickness_rule(np > 0 ? np : 0);
    for (int i = 0; i < g.count; ++i) {
      const auto e = static_cast<std::size_t>(g.element[static_cast<std::size_t>(i)]);
      const float* t = &sig[6 * e];
      // Normal from the current diagonals, independently of the kernel's frame.
      auto X = [&](int k) {
        const auto n = static_cast<std::size_t>(m.shells.conn[4 * e + static_cast<std::size_t>(k)]);
        return md::Vec3{s.x[n], s.y[n], s.z[n]};
      };
      md::Vec3 nrm = md::cross(md::sub(X(2), X(0)), md::sub(X(3), X(1)));
      nrm = md::scale(nrm, 1.0 / md::norm(nrm));
      const double S[3][3] = {{t[0], t[3], t[5]}, {t[3], t[1], t[4]}, {t[5], t[4], t[2]}};
      double nsn = 0, scale = 0;
      for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t b = 0; b < 3; ++b) {
          nsn += nrm[a] * S[a][b] * nrm[b];
          scale = std::max(scale, std::abs(S[a][b]));
        }
      // Local mean stress and its plane-stress von Mises (szz = 0).
      double l[5] = {0, 0, 0, 0, 0};
      for (int q = 0; q < 5; ++q)
        for (int p = 0; p < std::max(np, 1); ++p)
          l[q] +=
              (np > 0 ? rule.w[p] * g.sig[sv::shell_detail::sig_index(p, q, i)]
                      : g.sig[static_cast<std::size_t>(q) * sv::kGroupSize + static_cast<std::size_t>(i)]);
      const double vm_local = std::sqrt(l[0] * l[0] - l[0] * l[1] + l[1] * l[1] +
                                        3.0 * (l[2] * l[2] + l[3] * l[3] + l[4] * l[4]));
      // Transverse shears (syz, szx) make n.sigma.n non-zero only at second order; they are not part of
      // the membrane state compared here when they are small.
      if (scale <= 0) continue;
      INFO("shell " << m.shells.id[e] << ": n.s.n " << nsn << ", max |s| " << scale);
      CHECK(std::abs(vm[e] - vm_local) <= 1e-6 * vm_local + 1e-30);
      CHECK(std::abs(nsn) <= 1e-5 * scale);
      largest = std::max(largest, scale);
      ++checked;
    }
  }
  CHECK(checked > 0);
  CHECK(largest > 0);
}

// The shells' per-point and layer outputs against the mean stress output of the same state: the mean is the
// rule's weighted sum of the points (sum w_i sigma_i, docs/theory/elements.md 1.4), the bottom and top layers
// are the first and last points, whatever the frame they are rotated from (the same for all).
TEST_CASE("shell point and layer stress outputs agree with the mean stress output", "[results-fields]") {
  Case c = load("block_on_plate", "BLOCK_ON_PLATE");
  c.controls.t_stop = 1e30;
  const md::Model& m = c.model;
  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions(1));
  const auto res = eng.run([&](const sv::CycleReport& r) { return r.cycle < 300; });
  REQUIRE(res.cycles >= 300);
  const int np = sv::shell_points_max(eng);
  REQUIRE(np >= 2);
  const std::size_t nc = m.element_count();
  std::vector<float> mean(6 * nc), bottom(6 * nc), top(6 * nc), vm_top(nc);
  std::vector<std::vector<float>> point(static_cast<std::size_t>(np), std::vector<float>(6 * nc));
  sv::gather_cell_field(eng, sv::CellField::Stress, mean);
  sv::gather_cell_field(eng, sv::CellField::StressBottom, bottom);
  sv::gather_cell_field(eng, sv::CellField::StressTop, top);
  sv::gather_cell_field(eng, sv::CellField::VonMisesTop, vm_top);
  for (int p = 0; p < np; ++p) sv::gather_shell_point_stress(eng, p, point[static_cast<std::size_t>(p)]);
  double largest = 0;  // the largest stress value of any point
  for (const auto& values : point)
    for (const float v : values) largest = std::max(largest, std::abs(static_cast<double>(v)));
  REQUIRE(largest > 0);
  int checked = 0;
  for (const auto& g : eng.groups().shells) {
    REQUIRE(g.props.n_points == np);  // one shell property in this deck
    const auto rule = sv::shell_detail::thickness_rule(np);
    for (int i = 0; i < g.count; ++i) {
      const std::size_t cell =
          sv::first_cell(m, g) + static_cast<std::size_t>(g.element[static_cast<std::size_t>(i)]);
      for (std::size_t q = 0; q < 6; ++q) {
        double sum = 0;
        for (int p = 0; p < np; ++p) sum += rule.w[p] * point[static_cast<std::size_t>(p)][6 * cell + q];
        // float32 outputs: 1e-6 of the largest stress per value, times the sum of the weights (1).
        CHECK(std::abs(sum - mean[6 * cell + q]) <= 2e-6 * largest);
        CHECK(bottom[6 * cell + q] == point[0][6 * cell + q]);
        CHECK(top[6 * cell + q] == point[static_cast<std::size_t>(np - 1)][6 * cell + q]);
      }
      const float* t = &top[6 * cell];
      const double a = t[0] - t[1], b = t[1] - t[2], d = t[2] - t[0];
      const double vm =
          std::sqrt(0.5 * (a * a + b * b + d * d) + 3.0 * (t[3] * t[3] + t[4] * t[4] + t[5] * t[5]));
      CHECK(std::abs(vm - vm_top[cell]) <= 2e-6 * std::max(vm, 1e-30) + 1e-6 * largest);
      ++checked;
    }
  }
  CHECK(checked == static_cast<int>(m.shells.size() + m.shells3.size()));
}
