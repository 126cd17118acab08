// Trusses (/TRUSS with /PROP/TRUSS): the kernel against its force law, a bar's elastic wave against the
// one-dimensional wave solution, a plastic bar against its yield force, and the starter's checks. Expected
// values come from formulas with the deck's own parameters.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "kernel_test_util.hpp"
#include "solver/elements/element_groups.hpp"
#include "solver/engine/explicit_engine.hpp"
#include "solver/materials/material_params.hpp"
#include "test_util.hpp"

namespace {

using radx::test::Line;
using radx::test::rel;

constexpr std::size_t G = radx::solver::kGroupSize;

// Steel in Mg mm s: E (MPa), rho (Mg/mm^3), nu; c = sqrt(E / rho) = 5172 mm/ms.
constexpr double kE = 210000.0, kRho = 7.85e-9, kNu = 0.3, kArea = 100.0;

radx::solver::MaterialParams steel(double a = 0, double b = 0, double n = 1) {
  radx::model::Material m;
  m.law = a > 0 ? radx::model::MaterialLaw::JohnsonCook : radx::model::MaterialLaw::Elastic;
  m.rho = kRho;
  m.young = kE;
  m.poisson = kNu;
  m.a = a;
  m.b = b;
  m.n = n;
  return radx::solver::make_material_params(m);
}

// One truss between nodes 0 and 1 of `ns`.
radx::solver::TrussGroup one_truss(const radx::solver::NodeState& ns) {
  radx::solver::TrussGroup g;
  g.allocate(1);
  g.conn[0] = 0;
  g.conn[G] = 1;
  g.element[0] = 0;
  g.l0[0] = std::hypot(ns.x0[1] - ns.x0[0], ns.y0[1] - ns.y0[0], ns.z0[1] - ns.z0[0]);
  g.area0[0] = g.area[0] = kArea;
  return g;
}

// The bar of the engine tests: n trusses of length h along X from node 1 (clamped) to node n + 1, every
// other node moving at v0 along X at the start; `mat` is the material card.
std::string bar_deck(int n, double h, double v0, const std::string& mat) {
  std::string s = radx::test::begin_block(2024);
  s += "/NODE\n";
  for (int k = 0; k <= n; ++k)
    s += Line().put(k + 1, 1, 10).put(k * h, 11, 30).put(0.0, 31, 50).put(0.0, 51, 70).str() + "\n";
  s += "/TRUSS/1\n";
  for (int k = 0; k < n; ++k)
    s += Line().put(k + 1, 1, 10).put(k + 1, 11, 20).put(k + 2, 21, 30).str() + "\n";
  s += "/PART/1\nbar\n" + Line().put(1, 1, 10).put(1, 11, 20).str() + "\n";
  s += "/PROP/TRUSS/1\nbar section\n" + Line().put(kArea, 1, 20).str() + "\n";
  s += mat;
  s += "/GRNOD/NODE/1\nclamped\n" + Line().put(1, 1, 10).str() + "\n";
  s += "/BCS/1\nclamped\n" + Line().put("111 000", 4, 10).put(0, 11, 20).put(1, 21, 30).str() + "\n";
  s += "/GRNOD/GENE/2\nmoving\n" + Line().put(2, 1, 10).put(n + 1, 11, 20).str() + "\n";
  s += "/INIVEL/TRA/1\nstart\n" +
       Line().put(v0, 1, 20).put(0.0, 21, 40).put(0.0, 41, 60).put(2, 61, 70).str() + "\n";
  s += "/END\n";
  return s;
}
std::string elastic_card() {
  return "/MAT/LAW1/1\nsteel\n" + Line().put(kRho, 1, 20).str() + "\n" +
         Line().put(kE, 1, 20).put(kNu, 21, 40).str() + "\n";
}
std::string johnson_cook_card(double a, double c = 0) {
  return "/MAT/PLAS_JOHNS/1\nsteel\n" + Line().put(kRho, 1, 20).str() + "\n" +
         Line().put(kE, 1, 20).put(kNu, 21, 40).str() + "\n" + Line().put(a, 1, 20).put(0.0, 21, 40).str() +
         "\n" + Line().put(c, 1, 20).put(1.0, 21, 40).str() + "\n";
}

// Axial forces of trusses `watch` (element indices) at every cycle.
struct BarTrace {
  std::vector<double> t;
  std::vector<std::vector<double>> force;  // [watch][cycle]
  std::vector<double> plas_first;          // plastic strain of the clamped end's truss
  double dt = 0;
  double worst_error = 0;
};

BarTrace run_bar(const radx::model::Model& m, double t_stop, const std::vector<int>& watch) {
  radx::model::RunControls rc;
  rc.t_stop = t_stop;
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  BarTrace tr;
  tr.force.resize(watch.size());
  engine.run([&](const radx::solver::CycleReport& r) {
    const auto& g = engine.groups().trusses.at(0);
    tr.t.push_back(r.time);
    for (std::size_t w = 0; w < watch.size(); ++w)
      tr.force[w].push_back(g.force[static_cast<std::size_t>(watch[w])]);
    tr.plas_first.push_back(g.eps_p[0]);
    if (tr.dt == 0) tr.dt = r.dt;
    if (r.full) tr.worst_error = std::max(tr.worst_error, std::abs(r.energy.error_percent));
    return true;
  });
  return tr;
}

// The mean of f over the cycles with t in [t0, t1].
double mean_over(const BarTrace& tr, std::size_t w, double t0, double t1) {
  double s = 0;
  int n = 0;
  for (std::size_t k = 0; k < tr.t.size(); ++k)
    if (tr.t[k] >= t0 && tr.t[k] <= t1) s += tr.force[w][k], ++n;
  REQUIRE(n > 0);
  return s / n;
}

std::string errors_of(const std::string& text, radx::Severity severity = radx::Severity::Error) {
  radx::test::TempDir dir;
  radx::Diagnostics diags;
  const auto deck = radx::read_starter_deck(dir.write("m_0000.rad", text), diags);
  (void)radx::build_model(deck, diags);
  std::string all;
  for (const auto& d : diags.items())
    if (d.severity == severity) all += radx::Diagnostics::format(d) + "\n";
  return all;
}

}  // namespace

TEST_CASE("truss kernel: the force grows by E A eps_dot dt along the line, equal and opposite, step l / c",
          "[truss]") {
  auto ns = radx::test::make_nodes({{0, 0, 0}, {30, 40, 0}});  // l = 50, e = (0.6, 0.8, 0)
  auto g = one_truss(ns);
  const auto mat = steel();
  // Node 2 moves along the line at u = 2 mm/s: eps_dot = u / l exactly (the mid-step correction
  // eps_dot^2 - |dv|^2 / l^2 vanishes for a motion along the line).
  const double u = 2.0, dt = 1e-3;
  ns.vx[1] = 0.6 * u;
  ns.vy[1] = 0.8 * u;
  radx::solver::truss_axial_forces(g, ns, mat, radx::solver::CycleInfo{dt, dt, 0});
  const double eps_dot = u / 50.0;
  const double area = kArea * (1 - 2 * kNu * eps_dot * dt);
  const double n = kE * area * eps_dot * dt;
  CHECK(rel(g.force[0], n) < 1e-12);
  CHECK(rel(g.area[0], area) < 1e-14);
  CHECK(rel(g.sig[0], n / area) < 1e-12);
  CHECK(rel(g.nodal_force[0 * G], 0.6 * n) < 1e-12);  // tension pulls node 1 towards node 2
  CHECK(rel(g.nodal_force[1 * G], 0.8 * n) < 1e-12);
  CHECK(rel(g.nodal_force[3 * G], -0.6 * n) < 1e-12);
  CHECK(rel(g.nodal_force[4 * G], -0.8 * n) < 1e-12);
  CHECK(g.nodal_force[2 * G] == 0.0);
  // Work by the trapezoid (0 + N)/2 eps_dot l dt: the elastic energy N^2 l / (2 E A) of the stretch.
  CHECK(rel(g.e_int[0], 0.5 * n * eps_dot * 50.0 * dt) < 1e-12);
  CHECK(rel(g.dt[0], 50.0 / std::sqrt(kE / kRho)) < 1e-12);
  CHECK(rel(g.k_nodal[0], kE * area / 50.0) < 1e-12);
}

TEST_CASE("truss kernel: law 2 caps the force at the yield force and books the plastic strain", "[truss]") {
  auto ns = radx::test::make_nodes({{0, 0, 0}, {100, 0, 0}});
  auto g = one_truss(ns);
  const double a = 200.0, b = 1000.0;  // linear hardening (n = 1): H = b
  const auto mat = steel(a, b, 1.0);
  // One step of strain increment 0.01: the elastic trial E A 0.01 = 21000 A is far above the yield a A.
  ns.vx[1] = 1.0;
  const double dt = 1.0;
  radx::solver::truss_axial_forces(g, ns, mat, radx::solver::CycleInfo{dt, dt, 0});
  const double eps_dot = 0.01 + 0.5 * dt * (0.01 * 0.01 - 0.01 * 0.01);  // along the line: 0.01
  const double area = kArea * (1 - 2 * kNu * eps_dot * dt);
  const double trial = kE * area * eps_dot * dt;
  const double d_eps_p = (trial - a * area) / ((kE + b) * area);
  CHECK(rel(g.eps_p[0], d_eps_p) < 1e-12);
  CHECK(rel(g.force[0], a * area) < 1e-12);  // the yield force of the start of the step (radial return)
  CHECK(rel(g.w_plastic[0], a * area * d_eps_p * 100.0) < 1e-12);
  CHECK(g.off[0] == 1.0);
}

TEST_CASE("truss kernel: law 2 breaks the truss at EPS_max, which then fades over cycles", "[truss]") {
  auto ns = radx::test::make_nodes({{0, 0, 0}, {100, 0, 0}});
  auto g = one_truss(ns);
  auto mat = steel(200.0, 0.0, 1.0);
  mat.jc.eps_p_max = 0.005;
  ns.vx[1] = 1.0;  // a strain increment of 0.01 per step: eps_p passes 0.005 in the first
  radx::solver::truss_axial_forces(g, ns, mat, radx::solver::CycleInfo{1.0, 1.0, 0});
  CHECK(g.off[0] == Approx(0.8).epsilon(1e-15));
  const double f1 = g.force[0];
  CHECK(rel(f1, 0.8 * 200.0 * g.area[0]) < 1e-12);
  for (int k = 0; k < 12; ++k)
    radx::solver::truss_axial_forces(g, ns, mat, radx::solver::CycleInfo{1.0, 1.0, 0});
  CHECK(g.off[0] == 0.0);  // 0.8^11 < 0.1: off is 0 and the force with it
  CHECK(g.force[0] == 0.0);
  CHECK(std::isinf(g.dt[0]));
}

TEST_CASE("truss bar: the elastic wave carries rho c v0 A at the bar's wave speed, with its mass and step",
          "[truss][engine]") {
  const int n = 50;
  const double h = 20.0, v0 = 1000.0;  // a 1 m bar of 20 mm trusses, 1 m/s
  const auto m = radx::test::model_of_deck(bar_deck(n, h, v0, elastic_card()));
  REQUIRE(m.trusses.size() == static_cast<std::size_t>(n));
  // Lumped mass rho A h per inner node (half of each neighbour's rho A h).
  CHECK(rel(m.node_mass[10], kRho * kArea * h) < 1e-12);
  CHECK(rel(m.total_mass, kRho * kArea * h * n) < 1e-12);
  const double c = std::sqrt(kE / kRho), L = n * h;
  const double f_wave = kRho * c * v0 * kArea;  // the stress rho c v0 behind the front, times A
  const int mid = n / 2;                        // truss 26, centred at x = 0.51 L
  const auto tr = run_bar(m, 1.8 * L / c, {0, mid});
  // The default /DT scale 0.9 times the truss step h / c.
  CHECK(rel(tr.dt, 0.9 * h / c) < 1e-9);
  // Clamped end: the front leaves at t = 0 and comes back from the free end at 2 L / c. Its mean over the
  // plateau is rho c v0 A within 1 % (the mesh's dispersion ringing averages out; the strain is 2e-4, so the
  // area changes by less than 1e-4).
  CHECK(rel(mean_over(tr, 0, 0.2 * L / c, 1.8 * L / c), f_wave) < 0.01);
  // Middle truss: unloaded until the front arrives at 0.51 L / c, then rho c v0 A.
  CHECK(std::abs(mean_over(tr, 1, 0.0, 0.4 * L / c)) < 0.01 * f_wave);
  CHECK(rel(mean_over(tr, 1, 0.7 * L / c, 1.3 * L / c), f_wave) < 0.02);
  // Elastic, no contact: the energy balance within 0.5 % of the initial kinetic energy.
  CHECK(tr.worst_error < 0.5);
}

TEST_CASE("truss bar of law 2: the elastic precursor carries the yield force a A and the clamped end yields",
          "[truss][engine]") {
  const int n = 50;
  const double h = 20.0, v0 = 1000.0, a = 20.0;  // rho c v0 = 40.6 MPa > a: the bar yields at the clamp
  const auto m = radx::test::model_of_deck(bar_deck(n, h, v0, johnson_cook_card(a)));
  const double c = std::sqrt(kE / kRho), L = n * h;
  const auto tr = run_bar(m, 1.5 * L / c, {n / 2});
  // Behind the elastic front the stress is the yield stress: the force a A within 1 %.
  CHECK(rel(mean_over(tr, 0, 0.8 * L / c, 1.2 * L / c), a * kArea) < 0.01);
  // The first truss flows: (rho c v0 - a) / (rho c) of the velocity jump goes into plastic strain.
  CHECK(tr.plas_first.back() > 0.0);
  CHECK(tr.worst_error < 1.0);
}

TEST_CASE("truss starter: what radx refuses or warns about by name", "[truss][starter]") {
  const std::string base = bar_deck(4, 20.0, 0.0, elastic_card());
  // Gap > 0 (a gap element) is not implemented.
  std::string gap = base;
  const std::string area_line = Line().put(kArea, 1, 20).str();
  gap.replace(gap.find(area_line), area_line.size(), Line().put(kArea, 1, 20).put(1.0, 21, 40).str());
  CHECK(errors_of(gap).find("Gap") != std::string::npos);
  // A law trusses do not run: law 36 is refused by name on the part.
  std::string tab =
      bar_deck(4, 20.0, 0.0,
               "/MAT/PLAS_TAB/1\nsteel\n" + Line().put(kRho, 1, 20).str() + "\n" +
                   Line().put(kE, 1, 20).put(kNu, 21, 40).str() + "\n" + Line().put(1, 1, 10).str() + "\n" +
                   Line().put(1, 1, 10).str() + "\n" + Line().put(1.0, 1, 20).str() + "\n" +
                   "/FUNCT/1\nyield\n" + Line().put(0.0, 1, 20).put(200.0, 21, 40).str() + "\n" +
                   Line().put(1.0, 1, 20).put(300.0, 21, 40).str() + "\n");
  const auto e = errors_of(tab);
  CHECK(e.find("RX510") != std::string::npos);
  CHECK(e.find("trusses run law 1") != std::string::npos);
  // Two trusses on one node, and a truss part with a shell property.
  std::string same = base;
  const std::string first = Line().put(1, 1, 10).put(1, 11, 20).put(2, 21, 30).str();
  same.replace(same.find(first), first.size(), Line().put(1, 1, 10).put(2, 11, 20).put(2, 21, 30).str());
  CHECK(errors_of(same).find("n1 = n2") != std::string::npos);
  std::string shell = base + "";
  shell.replace(shell.find("/PROP/TRUSS/1"), 13, "/PROP/SHELL/1");
  CHECK(errors_of(shell).find("elements need a /PROP/TRUSS") != std::string::npos);
  // Law 2's strain-rate term does not act on trusses: a warning, as Radioss runs it without.
  const auto w = errors_of(bar_deck(4, 20.0, 0.0, johnson_cook_card(200.0, 0.1)), radx::Severity::Warning);
  CHECK(w.find("strain-rate term") != std::string::npos);
  // Nor does any failure model (Radioss's trusses call none): /FAIL/BIQUAD on the truss material warns.
  const std::string biquad = "/FAIL/BIQUAD/1\n" + Line().put(0.08, 41, 60).str() + "\n" +
                             Line().put(0.0, 1, 20).put(2, 21, 30).str() + "\n\n";
  const auto wb =
      errors_of(bar_deck(4, 20.0, 0.0, johnson_cook_card(200.0, 0.0) + biquad), radx::Severity::Warning);
  CHECK(wb.find("its /FAIL model does not act on trusses") != std::string::npos);
}

TEST_CASE("truss bar: a truss that breaks at EPS_max is named once among the engine's events",
          "[truss][engine]") {
  const int n = 10;
  const double h = 20.0, v0 = 1000.0, a = 20.0;
  // EPS_p_max 0.001: the clamped truss flows at (rho c v0 - a) / (rho c) of v0 over h and breaks early.
  const std::string mat = "/MAT/PLAS_JOHNS/1\nsteel\n" + Line().put(kRho, 1, 20).str() + "\n" +
                          Line().put(kE, 1, 20).put(kNu, 21, 40).str() + "\n" +
                          Line().put(a, 1, 20).put(0.0, 21, 40).put(1.0, 41, 60).put(0.001, 61, 80).str() +
                          "\n" + Line().put(0.0, 1, 20).put(1.0, 21, 40).str() + "\n";
  const auto m = radx::test::model_of_deck(bar_deck(n, h, v0, mat));
  radx::model::RunControls rc;
  rc.t_stop = 4.0 * n * h / std::sqrt(kE / kRho);
  radx::solver::ExplicitEngine engine(m, rc, radx::solver::EngineOptions{1, 1});
  std::vector<std::string> events;
  engine.run([&](const radx::solver::CycleReport&) {
    for (auto& e : engine.take_events()) events.push_back(e);
    return true;
  });
  std::size_t first = 0;
  for (const auto& e : events) first += e.rfind("truss 1 of part 1 deleted", 0) == 0 ? 1 : 0;
  INFO(events.size() << " events");
  CHECK(first == 1);
  CHECK(engine.groups().trusses.at(0).off[0] == 0.0);
}
