// Verification decks (decks/verification/, written by scripts/make_verification_decks.py) run through the
// whole library: read_starter_deck + build_model + contact::prepare_type7_interfaces + read_run_controls,
// then solver::ExplicitEngine with a callback that records what each check needs. Every expected value is
// computed HERE from the deck's own parameters read back from the Model (E, rho, lengths from the node
// coordinates, v0 from the initial velocity), with the closed forms of docs/theory/verification.md.
//
// Cases: A.3 elastic bar on a rigid wall, A.4 two bars exchanging velocities through TYPE7 contact, B.10
// cantilever strip of shells, B.9 Taylor bar, B.14 uniaxial Johnson-Cook at one element; and on every deck
// the global checks of section C (energy balance, momentum where no external force acts) plus thread-count
// independence.
//
// Runs use one thread (small models: a parallel region per cycle costs more than it saves, and a loaded
// machine makes OpenMP barriers slow), except the Taylor bar, which also runs with 2 threads to check that
// the result does not depend on the thread count.
//
// Set RADX_VERIFICATION_VERBOSE=1 to print the measured values of every case.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "contact/type7_prepare.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"
#include "solver/conditions/functions.hpp"
#include "solver/engine/explicit_engine.hpp"

namespace {

namespace sv = radx::solver;
namespace md = radx::model;
constexpr std::size_t G = sv::kGroupSize;

bool verbose() {
  static const bool v = std::getenv("RADX_VERIFICATION_VERBOSE") != nullptr;
  return v;
}

struct Case {
  md::Model model;
  md::RunControls controls;
};

std::string diag_text(const radx::Diagnostics& d) {
  std::string s;
  for (const auto& x : d.items()) s += radx::Diagnostics::format(x) + "\n";
  return s;
}

// The deck pair decks/verification/<folder>/<ROOT>_0000.rad and _0001.rad, read as the starter and the
// engine read them.
Case load_case(const std::string& folder, const std::string& root) {
  const std::string dir = std::string(RADX_SOURCE_DIR) + "/decks/verification/" + folder + "/";
  radx::Diagnostics d;
  const radx::Deck deck = radx::read_starter_deck(dir + root + "_0000.rad", d);
  Case c;
  c.model = radx::build_model(deck, d);
  INFO(diag_text(d));
  REQUIRE(!d.has_errors());
  radx::contact::prepare_type7_interfaces(c.model);
  c.controls = radx::read_run_controls(dir + root + "_0001.rad", d);
  INFO(diag_text(d));
  REQUIRE(!d.has_errors());
  REQUIRE(d.warning_count() == 0);
  return c;
}

// Energy balance (docs/theory/verification.md C): |error %| of docs/theory/elements.md 8 at every cycle;
// keeps the worst.
struct EnergyWatch {
  double worst = 0;
  std::int64_t worst_cycle = -1;
  std::int64_t cycles = 0, partial = 0;  // reports seen, and those without energies (must be none)
  void operator()(const sv::CycleReport& r) {
    ++cycles;
    if (!r.full) {
      ++partial;
      return;
    }
    if (std::abs(r.energy.error_percent) > std::abs(worst) || worst_cycle < 0) {
      worst = r.energy.error_percent;
      worst_cycle = r.cycle;
    }
  }
};

// The energy balance must hold within 1 % of the initial total energy at every cycle: the error of
// docs/theory/elements.md 8, E / (E0 + W_ext) - 1, counts kinetic, internal (with bulk-viscosity heat),
// hourglass and contact energies, so 1 % is the whole budget for the time integration and the work
// bookkeeping of the walls and imposed velocities.
void check_energy(const EnergyWatch& e, const char* what) {
  INFO(what << ": worst energy error " << e.worst << " % at cycle " << e.worst_cycle);
  REQUIRE(e.cycles > 0);
  REQUIRE(e.partial == 0);  // EngineOptions::report_every = 1: energies at every cycle
  if (verbose())
    std::printf("%s: worst energy error %.4f %% at cycle %lld\n", what, e.worst, (long long)e.worst_cycle);
  CHECK(std::abs(e.worst) < 1.0);
}

const md::Material& only_material(const md::Model& m) {
  REQUIRE(m.parts.size() == 1);
  return m.materials[static_cast<std::size_t>(m.parts[0].material)];
}

double min_of(const std::vector<double>& v) {
  return *std::min_element(v.begin(), v.end());
}
double max_of(const std::vector<double>& v) {
  return *std::max_element(v.begin(), v.end());
}

// Smallest spacing between the distinct values of v (the element length along that axis of a regular mesh).
double smallest_spacing(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  double h = std::numeric_limits<double>::infinity();
  for (std::size_t k = 1; k < v.size(); ++k) h = std::min(h, v[k] - v[k - 1]);
  return h;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// ---------------------------------------------------------------------------------------------------------
// A.3: elastic bar on a rigid wall (kg, m, s). c = sqrt(E/rho), contact stress rho c v0, contact time 2L/c,
// rebound at v0; momentum constant while no force acts (free flight before the impact and after the rebound).
TEST_CASE("verification: elastic bar on a rigid wall", "[verification]") {
  const auto t0 = std::chrono::steady_clock::now();
  Case c = load_case("bar_rwall", "BAR_RWALL");
  const md::Model& m = c.model;
  const md::Material& mat = only_material(m);
  REQUIRE(mat.law == md::MaterialLaw::Elastic);
  REQUIRE(mat.poisson == 0.0);  // the 1-D closed form needs nu = 0 (then K + 4G/3 = E for the brick)
  REQUIRE(m.rigid_walls.size() == 1);
  const md::RigidWall& wall = m.rigid_walls[0];
  REQUIRE(wall.node == md::kNone);
  const double nn = std::hypot(wall.normal[0], wall.normal[1], wall.normal[2]);
  REQUIRE(wall.normal[2] / nn == 1.0);  // a fixed plane z = const facing +Z
  REQUIRE(m.initial_velocities.size() == 1);
  const auto& iv = m.initial_velocities[0];
  REQUIRE(m.node_groups[static_cast<std::size_t>(iv.group)].nodes.size() == m.nodes.size());
  REQUIRE(iv.v[0] == 0.0);
  REQUIRE(iv.v[1] == 0.0);

  // Closed form from the deck.
  const double E = mat.young, rho = mat.rho, v0 = -iv.v[2];
  REQUIRE(v0 > 0);
  const double zmin = min_of(m.nodes.z), zmax = max_of(m.nodes.z);
  const double L = zmax - zmin;
  const double h = smallest_spacing(m.nodes.z);  // element length along the bar
  const double cw = std::sqrt(E / rho);
  const double sigma_c = rho * cw * v0;
  const double t_contact = 2.0 * L / cw;
  const double t_impact = (zmin - wall.m[2]) / v0;
  const double t_transit = h / cw;  // one element transit time

  std::vector<std::size_t> lower;  // lower end face nodes
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes.z[n] == zmin) lower.push_back(n);
  REQUIRE(!lower.empty());

  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{1});
  // Bricks of the lower layer (a node on the lower face), as (group, slot).
  std::vector<std::pair<std::size_t, std::size_t>> lower_bricks;
  for (std::size_t gi = 0; gi < eng.groups().bricks.size(); ++gi) {
    const auto& g = eng.groups().bricks[gi];
    for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i) {
      const auto e = static_cast<std::size_t>(g.element[i]);
      bool low = false;
      for (std::size_t k = 0; k < 8; ++k)
        low = low || m.nodes.z[static_cast<std::size_t>(m.bricks.conn[8 * e + k])] == zmin;
      if (low) lower_bricks.emplace_back(gi, i);
    }
  }
  REQUIRE(!lower_bricks.empty());

  struct Rec {
    double t, dt, v_lower, szz, lower_z_min;
    std::array<double, 3> p;
  };
  std::vector<Rec> rec;
  EnergyWatch energy;
  double mass = 0;
  double dt1 = 0;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    const auto& s = eng.nodes();
    // Velocity of the lower face at t_n: v^{n-1/2} + dt1/2 a^n after the
    // wall has acted (docs/theory/elements.md 8).
    double vl = 0, zl = std::numeric_limits<double>::infinity();
    for (const auto n : lower) {
      vl += s.vz[n] + 0.5 * dt1 * s.az[n];
      zl = std::min(zl, s.z[n]);
    }
    double szz = 0;
    for (const auto& [gi, i] : lower_bricks) szz += eng.groups().bricks[gi].sig[2 * G + i];
    rec.push_back(Rec{r.time, r.dt, vl / static_cast<double>(lower.size()),
                      szz / static_cast<double>(lower_bricks.size()), zl, r.momentum});
    energy(r);
    mass = r.mass;
    dt1 = r.dt;
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);

  // Contact: from the first cycle where the wall has stopped the lower face (its velocity is no longer
  // -v0) to the first later cycle where the face moves away from the wall.
  std::size_t k_start = rec.size(), k_end = rec.size();
  for (std::size_t k = 0; k < rec.size(); ++k)
    if (rec[k].v_lower > -0.5 * v0) {
      k_start = k;
      break;
    }
  REQUIRE(k_start < rec.size());
  for (std::size_t k = k_start; k < rec.size(); ++k)
    if (rec[k].v_lower > 0) {
      k_end = k;
      break;
    }
  REQUIRE(k_end < rec.size());
  const double duration = rec[k_end].t - rec[k_start].t;

  // Contact stress: the lower bricks' sigma_zz averaged (time-weighted) over the middle 80 % of the contact,
  // so that the ringing of the discrete compression front averages out.
  double s_int = 0, t_int = 0;
  for (std::size_t k = k_start; k < k_end; ++k)
    if (rec[k].t >= rec[k_start].t + 0.1 * t_contact && rec[k].t <= rec[k_start].t + 0.9 * t_contact) {
      s_int += rec[k].szz * rec[k].dt;
      t_int += rec[k].dt;
    }
  REQUIRE(t_int > 0.5 * t_contact);
  const double sigma = -s_int / t_int;

  // Rebound speed: total momentum / total mass at the end of the run (free flight by then, see below).
  const double v_rebound = rec.back().p[2] / mass;

  if (verbose())
    std::printf(
        "bar: c %.6g m/s; impact at %.6e s (closed form %.6e); contact %.6e s (2L/c %.6e, h/c %.3e); "
        "stress %.6e (rho c v0 %.6e); rebound %.6f m/s (v0 %.6g); %zu cycles, %.2f s\n",
        cw, rec[k_start].t, t_impact, duration, t_contact, t_transit, sigma, sigma_c, v_rebound, v0,
        rec.size(), seconds_since(t0));

  // The wall stops the face in the cycle whose predicted position would cross the plane, so the contact
  // starts at most one time step (less than one element transit time) before gap / v0.
  CHECK(std::abs(rec[k_start].t - t_impact) <= t_transit);
  // Contact duration 2L/c within two element transit times h/c: the discrete front is spread over about
  // one element at each end of the contact (arrival of the compression, departure of the unloading wave).
  CHECK(std::abs(duration - t_contact) <= 2.0 * t_transit);
  // Contact stress rho c v0 within 5 %: the plateau behind the front.
  CHECK(std::abs(sigma - sigma_c) <= 0.05 * sigma_c);
  // Rebound speed within 2 % of v0. Budget (measured, see the README): the kinematic wall stops the lower
  // face perfectly plastically (its kinetic energy, 1/(2 N) of the total, is lost: 0.125 % of the speed
  // for N = 200 layers); the default bulk viscosity (qa 1.1, qb 0.05) dissipates about 1.1 % of the speed
  // at the fronts (the bar rebounds at 0.984 v0, and at 0.995 v0 with qa = qb = 1e-6); the rest stays as
  // vibration of the discrete bar.
  CHECK(std::abs(v_rebound - v0) <= 0.02 * v0);

  // Momentum while no external force acts, constant to round-off (1e-12 of m v0):
  // (1) free flight before the impact: P = -m v0 exactly (no stress, no force);
  const double p0 = mass * v0;
  std::size_t before = 0;
  for (std::size_t k = 0; k < k_start; ++k) {
    ++before;
    CHECK(std::abs(rec[k].p[0]) <= 1e-12 * p0);
    CHECK(std::abs(rec[k].p[1]) <= 1e-12 * p0);
    CHECK(std::abs(rec[k].p[2] + p0) <= 1e-12 * p0);
  }
  CHECK(before >= 5);
  // (2) free flight after the rebound, with the bar vibrating (internal forces act, but sum to zero):
  //     from four transit times after the face left the wall, the face stays clear of the plane.
  std::size_t after = 0;
  std::size_t k_free = rec.size();
  for (std::size_t k = k_end; k < rec.size(); ++k) {
    if (rec[k].t < rec[k_end].t + 4.0 * t_transit) continue;
    if (k_free == rec.size()) k_free = k;
    REQUIRE(rec[k].lower_z_min > wall.m[2]);
    ++after;
    for (int d = 0; d < 3; ++d)
      CHECK(std::abs(rec[k].p[static_cast<std::size_t>(d)] - rec[k_free].p[static_cast<std::size_t>(d)]) <=
            1e-12 * p0);
  }
  CHECK(after >= 50);
  check_energy(energy, "bar_rwall");
}

// ---------------------------------------------------------------------------------------------------------
// A.4: two equal elastic bars, one at rest, longitudinal impact through TYPE7 contact (consistent units,
// E = rho = 1). c = sqrt(E/rho); interface stress rho c v0 / 2 (equal impedances share the velocity jump);
// contact lasts 2L/c; then the striker is at rest and the struck bar moves at v0 (exchange of velocities).
// No external force acts (contact forces are internal): momentum is constant to round-off all along.
// Why the deck has Fric 0.1 (Iform 2): see its README (without friction the faces slide sideways off each
// other's boundary edges; the test checks that friction does no work).
TEST_CASE("verification: two bars exchange velocities", "[verification]") {
  const auto t0 = std::chrono::steady_clock::now();
  Case c = load_case("two_bars", "TWO_BARS");
  const md::Model& m = c.model;
  REQUIRE(m.parts.size() == 2);
  REQUIRE(m.parts[0].material == m.parts[1].material);  // equal bars: same material and property
  REQUIRE(m.parts[0].property == m.parts[1].property);
  const md::Material& mat = m.materials[static_cast<std::size_t>(m.parts[0].material)];
  REQUIRE(mat.law == md::MaterialLaw::Elastic);
  REQUIRE(mat.poisson == 0.0);  // the 1-D closed form needs nu = 0 (then K + 4G/3 = E for the brick)
  REQUIRE(m.shells.size() == 0);
  REQUIRE(m.rigid_walls.empty());
  REQUIRE(m.bcs.empty());  // lateral motion free, no support
  REQUIRE(m.interfaces.size() == 1);
  const md::Interface& in = m.interfaces[0];
  REQUIRE(in.istf == 1);
  REQUIRE(in.igap == 0);
  REQUIRE(in.vis_s <= 1e-9);  // the linear dashpot is negligible (a 0 in the deck would mean 0.05)
  const double gap = in.gapmin;
  REQUIRE(gap > 0);

  // Striker = the nodes given the initial velocity (v0 along +Z); struck bar = the nodes of the other part.
  REQUIRE(m.initial_velocities.size() == 1);
  const auto& iv = m.initial_velocities[0];
  REQUIRE(iv.v[0] == 0.0);
  REQUIRE(iv.v[1] == 0.0);
  const double v0 = iv.v[2];
  REQUIRE(v0 > 0);
  const std::size_t nn = m.nodes.size();
  std::vector<int> bar(nn, -1);  // 0 striker, 1 struck bar
  for (std::size_t e = 0; e < m.bricks.size(); ++e)
    for (std::size_t k = 0; k < 8; ++k)
      bar[static_cast<std::size_t>(m.bricks.conn[8 * e + k])] = m.bricks.part[e];
  const auto& moving = m.node_groups[static_cast<std::size_t>(iv.group)].nodes;
  REQUIRE(!moving.empty());
  const int striker_part = bar[static_cast<std::size_t>(moving[0])];
  std::vector<double> zs[2];
  for (std::size_t n = 0; n < nn; ++n) {
    REQUIRE(bar[n] >= 0);
    bar[n] = bar[n] == striker_part ? 0 : 1;
    zs[bar[n]].push_back(m.nodes.z[n]);
  }
  REQUIRE(moving.size() == zs[0].size());  // the initial velocity is on the whole striker and only there
  for (const auto n : moving) REQUIRE(bar[static_cast<std::size_t>(n)] == 0);

  // Closed form from the deck: equal bars of length L, section A, element length h.
  const double L = max_of(zs[0]) - min_of(zs[0]);
  REQUIRE(std::abs(max_of(zs[1]) - min_of(zs[1]) - L) <= 1e-12 * L);
  const double z_face0 = max_of(zs[0]), z_face1 = min_of(zs[1]);  // the striker is below, moving up
  REQUIRE(z_face1 - z_face0 > gap);                               // starts apart, outside the gap
  const double area = (max_of(m.nodes.x) - min_of(m.nodes.x)) * (max_of(m.nodes.y) - min_of(m.nodes.y));
  const double h = smallest_spacing(zs[1]);
  const double E = mat.young, rho = mat.rho;
  const double cw = std::sqrt(E / rho);
  const double sigma_c = rho * cw * v0 / 2.0;
  const double t_contact = 2.0 * L / cw;
  const double t_impact = (z_face1 - z_face0 - gap) / v0;  // the gap closes: the contact force starts
  const double t_transit = h / cw;                         // one element transit time
  // The secondary nodes are the striker's end face.
  REQUIRE(!in.secondary_nodes.empty());
  for (const auto n : in.secondary_nodes) REQUIRE(m.nodes.z[static_cast<std::size_t>(n)] == z_face0);

  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{1});
  REQUIRE(eng.contact() != nullptr);
  // The bricks of each bar at the interface (a node on the bar's end face), as (group, slot).
  std::array<std::vector<std::pair<std::size_t, std::size_t>>, 2> end_bricks;
  for (std::size_t gi = 0; gi < eng.groups().bricks.size(); ++gi) {
    const auto& g = eng.groups().bricks[gi];
    for (std::size_t i = 0; i < static_cast<std::size_t>(g.count); ++i) {
      const auto e = static_cast<std::size_t>(g.element[i]);
      for (std::size_t b = 0; b < 2; ++b) {
        bool touches = false;
        for (std::size_t k = 0; k < 8; ++k) {
          const auto nd = static_cast<std::size_t>(m.bricks.conn[8 * e + k]);
          touches =
              touches || (bar[nd] == static_cast<int>(b) && m.nodes.z[nd] == (b == 0 ? z_face0 : z_face1));
        }
        if (touches) end_bricks[b].emplace_back(gi, i);
      }
    }
  }
  REQUIRE(!end_bricks[0].empty());
  REQUIRE(end_bricks[0].size() == end_bricks[1].size());

  struct Rec {
    double t, dt, force, szz[2];
    std::int64_t pairs;
    std::array<double, 3> p;
  };
  std::vector<Rec> rec;
  EnergyWatch energy;
  sv::EnergyBalance last{};
  double dt1 = 0, lateral = 0;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    const auto ir = eng.contact()->results();
    REQUIRE(ir.size() == 1);
    // force: the normal contact force on the striker's face, positive in compression (it pushes along -Z).
    Rec x{r.time, r.dt, -ir[0].normal_force[2], {0, 0}, ir[0].active_pairs, r.momentum};
    for (std::size_t b = 0; b < 2; ++b) {
      for (const auto& [gi, i] : end_bricks[b]) x.szz[b] += eng.groups().bricks[gi].sig[2 * G + i];
      x.szz[b] /= static_cast<double>(end_bricks[b].size());
    }
    rec.push_back(x);
    const auto& s = eng.nodes();
    for (std::size_t n = 0; n < nn; ++n)
      lateral = std::max({lateral, std::abs(s.x[n] - s.x0[n]), std::abs(s.y[n] - s.y0[n])});
    energy(r);
    last = r.energy;
    dt1 = r.dt;
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);
  CHECK(eng.take_messages().empty());  // no node deactivated (the gap never closes)

  // Contact: from the first to the last cycle with an active pair. Episodes counts the separate intervals
  // (the penalty, stiffer than the elements, lets the end nodes bounce at the first touch).
  std::size_t k_start = rec.size(), k_end = rec.size(), episodes = 0;
  for (std::size_t k = 0; k < rec.size(); ++k)
    if (rec[k].pairs > 0) {
      if (k_start == rec.size()) k_start = k;
      if (k == 0 || rec[k - 1].pairs == 0) ++episodes;
      k_end = k;
    }
  REQUIRE(k_start < rec.size());
  REQUIRE(k_end + 1 < rec.size());  // the run goes on after the separation
  const double duration = rec[k_end].t - rec[k_start].t;

  // Stresses, time-weighted over the middle 80 % of the contact (the ringing of the discrete fronts
  // averages out): the contact pressure (normal force on the secondary nodes over the section) and the mean
  // axial stress of the bricks on each side of the interface.
  double f_int = 0, s_int[2] = {0, 0}, t_int = 0;
  for (std::size_t k = k_start; k <= k_end; ++k)
    if (rec[k].t >= rec[k_start].t + 0.1 * t_contact && rec[k].t <= rec[k_start].t + 0.9 * t_contact) {
      f_int += rec[k].force * rec[k].dt;
      for (std::size_t b = 0; b < 2; ++b) s_int[b] += rec[k].szz[b] * rec[k].dt;
      t_int += rec[k].dt;
    }
  REQUIRE(t_int > 0.5 * t_contact);
  const double pressure = f_int / t_int / area;
  const double sigma0 = -s_int[0] / t_int, sigma1 = -s_int[1] / t_int;

  // Final mean velocity of each bar: its momentum over its mass, sum_i m_i v_i / sum_i m_i over its nodes,
  // with the full-step velocity v^{n-1/2} + dt1/2 a^n (docs/theory/elements.md 8).
  const auto& s = eng.nodes();
  double pb[2] = {0, 0}, mb[2] = {0, 0};
  for (std::size_t n = 0; n < nn; ++n) {
    pb[bar[n]] += s.mass[n] * (s.vz[n] + 0.5 * dt1 * s.az[n]);
    mb[bar[n]] += s.mass[n];
  }
  REQUIRE(std::abs(mb[0] - mb[1]) <= 1e-12 * mb[0]);  // equal bars
  const double v_striker = pb[0] / mb[0], v_struck = pb[1] / mb[1];
  const double e0 = 0.5 * mb[0] * v0 * v0;

  if (verbose())
    std::printf(
        "two bars: c %.6g; contact from %.6f (closed form %.6f) for %.6f (2L/c %.6f, h/c %.3g) in %zu "
        "episode(s); contact pressure %.6e, interface stress striker %.6e struck %.6e (rho c v0/2 %.6e); "
        "final mean velocities striker %+.5f v0, struck %.5f v0; energies / E0: contact damping %.3e, "
        "contact elastic left %.3e, friction %.3e, hourglass %.3e; largest lateral displacement %.3e h; "
        "worst energy error %.4f %%; %zu cycles, %.2f s\n",
        cw, rec[k_start].t, t_impact, duration, t_contact, t_transit, episodes, pressure, sigma0, sigma1,
        sigma_c, v_striker / v0, v_struck / v0, last.contact_damping / e0, last.contact_elastic / e0,
        last.contact_friction / e0, last.hourglass / e0, lateral / h, energy.worst, rec.size(),
        seconds_since(t0));

  // The gap closes at (distance - g) / v0: the first active cycle is within one step of that.
  CHECK(std::abs(rec[k_start].t - t_impact) <= t_transit);
  // Contact duration 2L/c within two element transit times h/c: the discrete fronts are spread over about
  // one element at each end of the contact (arrival of the compression, return of the unloading waves);
  // the penalty spring in series adds its own rise time h / (20 c) (README).
  CHECK(std::abs(duration - t_contact) <= 2.0 * t_transit);
  // Interface stress rho c v0 / 2 within 5 %: the plateau behind the fronts, as the contact pressure and
  // as the axial stress of the bricks on both sides of the interface.
  CHECK(std::abs(pressure - sigma_c) <= 0.05 * sigma_c);
  CHECK(std::abs(sigma0 - sigma_c) <= 0.05 * sigma_c);
  CHECK(std::abs(sigma1 - sigma_c) <= 0.05 * sigma_c);
  // Exchange of velocities: each bar's mean velocity (its momentum over its mass) within 2 % of v0 of its
  // closed-form value, 0 for the striker and v0 for the struck bar. The total momentum is m v0 exactly
  // (below), so both say how much momentum the striker keeps: v_striker = (1 - e) v0 / 2 for an effective
  // coefficient of restitution e, i.e. e >= 0.96. What lowers e is the energy not returned to rigid-body
  // motion, Delta E / E0 ~ 2 v_striker / v0: bulk viscosity at the fronts, hourglass damping, the contact
  // damping, and the vibration left in the discrete bars (README).
  CHECK(std::abs(v_striker) <= 0.02 * v0);
  CHECK(std::abs(v_struck - v0) <= 0.02 * v0);
  CHECK(v_struck > v_striker);  // the bars separate for good

  // The contact's own losses. The quadratic damping term of docs/theory/type7-lagdt.md 4.3 always applies
  // (VISs ~ 0 removes only the linear one); it acts while the faces approach, i.e. at the first touch: its
  // work must stay below 1e-3 of E0, i.e. below 0.05 % of v0 on the final
  // speeds (Delta v ~ Delta E / (2 E0) v0).
  CHECK(last.contact_damping >= 0);
  CHECK(last.contact_damping <= 1e-3 * e0);
  // Friction only holds the faces against sideways sliding: in the 1-D solution they do not slide, so it
  // must do no work (1e-6 of E0); and the bars stay straight: no lateral displacement beyond 1e-3 h at any
  // time (the bulk-viscosity pressure of the compression fronts spreads the bricks by up to ~5e-5 h, most
  // at the first touch; faces sliding off each other reach 5e-2 h, README).
  CHECK(std::abs(last.contact_friction) <= 1e-6 * e0);
  CHECK(lateral <= 1e-3 * h);

  // Momentum, no external force: P = m v0 along Z and 0 across, at every cycle, to round-off (1e-12 of m v0;
  // the contact forces on the secondary node and on the main nodes cancel up to the rounding of the weights).
  const double p0 = mb[0] * v0;
  std::array<double, 3> dp{0, 0, 0};  // worst deviation over the run, per direction
  for (const auto& x : rec) {
    dp[0] = std::max(dp[0], std::abs(x.p[0]));
    dp[1] = std::max(dp[1], std::abs(x.p[1]));
    dp[2] = std::max(dp[2], std::abs(x.p[2] - p0));
  }
  if (verbose())
    std::printf("  momentum: worst deviation / (m v0) %.2e %.2e %.2e\n", dp[0] / p0, dp[1] / p0, dp[2] / p0);
  CHECK(dp[0] <= 1e-12 * p0);
  CHECK(dp[1] <= 1e-12 * p0);
  CHECK(dp[2] <= 1e-12 * p0);
  CHECK(k_start >= 5);  // some free flight before the contact
  check_energy(energy, "two_bars");
}

// ---------------------------------------------------------------------------------------------------------
// B.10: cantilever strip of shells (kg, m, s), f1 = (beta1 L)^2 / (2 pi L^2) sqrt(E I / (rho A)), I/A =
// t^2/12. One run per four-node formulation: Ishell 1 (CANTILEVER_STRIP), 24 (QEPH) and 12 (QBAT).
TEST_CASE("verification: cantilever strip first frequency", "[verification]") {
  struct Variant {
    const char* run;
    int ishell;
  };
  const Variant variant = GENERATE(Variant{"CANTILEVER_STRIP", 1}, Variant{"CANTILEVER_STRIP_QEPH", 24},
                                   Variant{"CANTILEVER_STRIP_QBAT", 12});
  INFO(variant.run);
  const auto t0 = std::chrono::steady_clock::now();
  Case c = load_case("cantilever_strip", variant.run);
  const md::Model& m = c.model;
  const md::Material& mat = only_material(m);
  REQUIRE(mat.poisson == 0.0);  // beam formula = plate strip formula only for nu = 0
  const auto& prop = m.properties[static_cast<std::size_t>(m.parts[0].property)].shell;
  REQUIRE(prop.ishell == variant.ishell);
  for (double t : m.shells.thickness) REQUIRE(t == 0.0);  // the property thickness applies
  const double thick = prop.thickness;
  const double xmin = min_of(m.nodes.x), xmax = max_of(m.nodes.x);
  const double L = xmax - xmin;
  constexpr double beta1 = 1.8751040687119611;  // first root of cos(b) cosh(b) = -1
  const double f1 = beta1 * beta1 / (2.0 * std::numbers::pi * L * L) *
                    std::sqrt(mat.young * thick * thick / (12.0 * mat.rho));

  std::vector<std::size_t> tip;
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes.x[n] == xmax) tip.push_back(n);
  REQUIRE(!tip.empty());

  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{1});
  // Rotational inertia of the tip corner node (one element, docs/theory/elements.md 5): (m_e/4)
  // (A0/d + t^2/12), d = 9 for Ishell 1, 12 for QEPH and QBAT; to round-off of its value.
  {
    const double h = L / 40.0, a0 = h * h;  // the strip's 0.025 m square elements
    const double me = mat.rho * thick * a0;
    const double d = variant.ishell == 1 ? 9.0 : 12.0;
    std::size_t corner = m.nodes.size();
    for (const auto n : tip)
      if (m.nodes.y[n] == min_of(m.nodes.y)) corner = n;
    REQUIRE(corner < m.nodes.size());
    CHECK(std::abs(eng.nodes().inertia[corner] - 0.25 * me * (a0 / d + thick * thick / 12.0)) <=
          1e-12 * eng.nodes().inertia[corner]);
  }
  std::vector<double> t, w;
  EnergyWatch energy;
  double internal_max = 0, hourglass_max = 0;  // over the run
  const auto res = eng.run([&](const sv::CycleReport& r) {
    const auto& s = eng.nodes();
    double z = 0;
    for (const auto n : tip) z += s.z[n] - s.z0[n];
    t.push_back(r.time);
    w.push_back(z / static_cast<double>(tip.size()));
    energy(r);
    if (r.full) {
      internal_max = std::max(internal_max, r.energy.internal);
      hourglass_max = std::max(hourglass_max, std::abs(r.energy.hourglass));
    }
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);

  // Zero crossings of the tip displacement (linear interpolation between cycles); w(0) = 0 is not one.
  std::vector<double> cross;
  for (std::size_t k = 1; k < w.size(); ++k)
    if (w[k - 1] * w[k] < 0) cross.push_back(t[k - 1] + (t[k] - t[k - 1]) * w[k - 1] / (w[k - 1] - w[k]));
  REQUIRE(cross.size() >= 6);  // about three periods
  const double period = 2.0 * (cross.back() - cross.front()) / static_cast<double>(cross.size() - 1);
  const double f = 1.0 / period;
  double amplitude = 0;
  for (double v : w) amplitude = std::max(amplitude, std::abs(v));
  if (verbose())
    std::printf(
        "cantilever %s (Ishell %d): f1 measured %.6f Hz over %zu zero crossings, beam formula %.6f Hz "
        "(%+.3f %%); tip amplitude %.4e m; hourglass / internal energy %.3e; %zu cycles, %.2f s\n",
        variant.run, variant.ishell, f, cross.size(), f1, 100.0 * (f / f1 - 1.0), amplitude,
        internal_max > 0 ? hourglass_max / internal_max : 0.0, t.size(), seconds_since(t0));
  // First frequency within 2 % of the Euler-Bernoulli value: the shells' bilinear bending (one point, or
  // four) and the lumped rotary inertia (docs/theory/elements.md 5) shift it by a fraction of a percent on
  // this mesh; 2 % of f1 is 0.17 Hz, far below the distance to the second mode (52 Hz).
  CHECK(std::abs(f - f1) <= 0.02 * f1);
  // The stabilisation (QEPH) or hourglass control (Ishell 1) must not carry the bending: its energy stays
  // below 1 % of the largest internal energy of the run, i.e. it stiffens the first mode by less than about
  // 0.5 % in frequency (f scales with the square root of the stiffness). QBAT has none.
  CHECK(hourglass_max <= 0.01 * internal_max);
  check_energy(energy, variant.run);
}

// ---------------------------------------------------------------------------------------------------------
// Cantilever beam of one-point bricks (4 through the height) in its first bending mode: Isolid 24 (HEPH,
// physical hourglass) against Euler-Bernoulli; Isolid 1 (viscous hourglass only) measured for comparison.
namespace {

struct BeamRun {
  double f = 0, f1 = 0;      // measured and Euler-Bernoulli first frequencies
  double e_int_max = 0;      // largest internal energy over the run
  double w_hg_max = 0;       // largest physical-hourglass work (Isolid 24; part of e_int)
  double hg_energy_max = 0;  // largest hourglass energy of the balance (Isolid 1)
  std::size_t crossings = 0, cycles = 0;
  EnergyWatch energy;
};

BeamRun run_cantilever_bricks(const char* root) {
  Case c = load_case("cantilever_bricks", root);
  const md::Model& m = c.model;
  const md::Material& mat = only_material(m);
  REQUIRE(mat.poisson == 0.0);  // beam formula without the plate factor only for nu = 0
  const double xmin = min_of(m.nodes.x), xmax = max_of(m.nodes.x);
  const double L = xmax - xmin, H = max_of(m.nodes.z) - min_of(m.nodes.z);
  constexpr double beta1 = 1.8751040687119611;  // first root of cos(b) cosh(b) = -1
  BeamRun out;
  out.f1 = beta1 * beta1 / (2.0 * std::numbers::pi * L * L) * std::sqrt(mat.young * H * H / (12.0 * mat.rho));
  std::vector<std::size_t> tip;
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes.x[n] == xmax) tip.push_back(n);
  REQUIRE(!tip.empty());

  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{1});
  std::vector<double> t, w;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    const auto& s = eng.nodes();
    double z = 0;
    for (const auto n : tip) z += s.z[n] - s.z0[n];
    t.push_back(r.time);
    w.push_back(z / static_cast<double>(tip.size()));
    double e_int = 0, w_hg = 0;
    for (const auto& g : eng.groups().bricks)
      for (int i = 0; i < g.count; ++i) {
        e_int += g.e_int[static_cast<std::size_t>(i)];
        w_hg += g.w_hg[static_cast<std::size_t>(i)];
      }
    out.e_int_max = std::max(out.e_int_max, e_int);
    out.w_hg_max = std::max(out.w_hg_max, w_hg);
    if (r.full) out.hg_energy_max = std::max(out.hg_energy_max, r.energy.hourglass);
    out.energy(r);
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);
  std::vector<double> cross;
  for (std::size_t k = 1; k < w.size(); ++k)
    if (w[k - 1] * w[k] < 0) cross.push_back(t[k - 1] + (t[k] - t[k - 1]) * w[k - 1] / (w[k - 1] - w[k]));
  REQUIRE(cross.size() >= 3);
  out.f = 1.0 / (2.0 * (cross.back() - cross.front()) / static_cast<double>(cross.size() - 1));
  out.crossings = cross.size();
  out.cycles = t.size();
  return out;
}

}  // namespace

TEST_CASE("verification: cantilever of HEPH bricks first frequency", "[verification][heph]") {
  const auto t0 = std::chrono::steady_clock::now();
  const BeamRun r = run_cantilever_bricks("CANTILEVER_BRICKS");
  if (verbose())
    std::printf(
        "cantilever bricks Isolid 24: f1 measured %.4f Hz (%zu crossings), beam %.4f Hz (%+.3f %%); "
        "hourglass work / internal energy %.4f %%; %zu cycles, %.2f s\n",
        r.f, r.crossings, r.f1, 100.0 * (r.f / r.f1 - 1.0), 100.0 * r.w_hg_max / r.e_int_max, r.cycles,
        seconds_since(t0));
  // First frequency within 2 % of Euler-Bernoulli: HEPH's hourglass stresses give each brick the linear
  // bending it cannot represent at its centre, so 4 bricks through the height bend like the beam; the
  // remainder is shear deformation and rotary inertia at L/H = 10 (a few 0.1 %). 2 % of f1 is 7 Hz, far
  // from the Isolid 1 softness this element is meant to remove.
  CHECK(std::abs(r.f - r.f1) <= 0.02 * r.f1);
  // The physical hourglass carries the in-element bending: below 1 % of the internal energy with 4 bricks
  // through the height (with 1 brick it would carry most of it).
  CHECK(r.w_hg_max < 0.01 * r.e_int_max);
  check_energy(r.energy, "cantilever_bricks (Isolid 24)");
}

// The same cantilever cut at mid-length into two meshes that do not match (12 and 8 bricks through the
// height), the tip half's end nodes tied by /INTER/TYPE2 to the root half's end faces, against the single
// mesh: the tie must pass the bending moment and shear across the cut as the continuous mesh does.
namespace {

struct TipRun {
  double peak = 0, t_peak = 0;  // largest mean tip deflection and its time
  EnergyWatch energy;
};

TipRun run_tied_beam(const char* root) {
  Case c = load_case("tied_beam", root);
  const md::Model& m = c.model;
  const double xmax = max_of(m.nodes.x);
  std::vector<std::size_t> tip;
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (m.nodes.x[n] == xmax) tip.push_back(n);
  REQUIRE(!tip.empty());
  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{1});
  TipRun out;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    const auto& s = eng.nodes();
    double z = 0;
    for (const auto n : tip) z += s.z[n] - s.z0[n];
    z /= static_cast<double>(tip.size());
    if (std::abs(z) > std::abs(out.peak)) {
      out.peak = z;
      out.t_peak = r.time;
    }
    out.energy(r);
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);
  return out;
}

}  // namespace

TEST_CASE("verification: two meshes tied by TYPE2 bend as one beam", "[verification][tied]") {
  const TipRun single = run_tied_beam("TIED_BEAM_SINGLE");
  const TipRun tied = run_tied_beam("TIED_BEAM");
  if (verbose())
    std::printf("tied beam: peak tip deflection %.6e m at %.4e s (single mesh %.6e m at %.4e s, %+.3f %%)\n",
                tied.peak, tied.t_peak, single.peak, single.t_peak, 100.0 * (tied.peak / single.peak - 1.0));
  // The peak comes a quarter period after the start (0.72 ms for this beam): a tie that let the halves slip
  // or hinge would make the beam much softer (a larger, later peak); 2 % also covers the tip half's coarser
  // mesh through the height.
  REQUIRE(single.peak > 0);
  CHECK(std::abs(tied.peak - single.peak) <= 0.02 * std::abs(single.peak));
  CHECK(std::abs(tied.t_peak - single.t_peak) <= 0.02 * single.t_peak);
  check_energy(single.energy, "tied_beam (single mesh)");
  check_energy(tied.energy, "tied_beam (two meshes tied)");
}

// The same two meshes tied by the rigid tie (Spotflag 1; the deck's free spring gives the model rotational
// degrees of freedom, without which Spotflag 1 is the standard tie): each tip-mesh node moves with its root
// face's least-squares rotation, and its mass and rotational inertia about the face's centre become point
// masses on the face (1.5 % of the beam's mass added at mid-span).
TEST_CASE("verification: two meshes tied by TYPE2 Spotflag 1 bend as one beam", "[verification][tied]") {
  const TipRun single = run_tied_beam("TIED_BEAM_SINGLE");
  const TipRun rigid = run_tied_beam("TIED_BEAM_RIGID");
  if (verbose())
    std::printf(
        "tied beam Spotflag 1: peak tip deflection %.6e m at %.4e s (single mesh %.6e m at %.4e s, %+.3f "
        "%%)\n",
        rigid.peak, rigid.t_peak, single.peak, single.t_peak, 100.0 * (rigid.peak / single.peak - 1.0));
  // As for Spotflag 0: a tie that let the halves slip or hinge would give a much larger, later peak. The
  // added mass at mid-span lowers the frequency by well under 1 % (a point mass of 1.5 % where the first
  // mode's amplitude is a third of the tip's).
  REQUIRE(single.peak > 0);
  CHECK(std::abs(rigid.peak - single.peak) <= 0.02 * std::abs(single.peak));
  CHECK(std::abs(rigid.t_peak - single.t_peak) <= 0.02 * single.t_peak);
  check_energy(rigid.energy, "tied_beam (two meshes, rigid tie)");
}

TEST_CASE("verification: cantilever of Isolid 1 bricks, measured softness", "[verification]") {
  const BeamRun r = run_cantilever_bricks("CANTILEVER_BRICKS_ISOLID1");
  if (verbose())
    std::printf(
        "cantilever bricks Isolid 1: f1 measured %.4f Hz (%zu crossings), beam %.4f Hz (%+.3f %%); "
        "hourglass energy / internal energy %.4f %%\n",
        r.f, r.crossings, r.f1, 100.0 * (r.f / r.f1 - 1.0), 100.0 * r.hg_energy_max / r.e_int_max);
  // No accuracy claim: the one-point brick with a viscous-only hourglass is soft in bending (its measured
  // error is stated in docs/engine.md). Only that it is softer than the beam, not stiffer.
  CHECK(r.f < r.f1);
}

TEST_CASE("verification: cantilever of Isolid 14 bricks first frequency", "[verification][full]") {
  const auto t0 = std::chrono::steady_clock::now();
  const BeamRun r = run_cantilever_bricks("CANTILEVER_BRICKS_ISOLID14");
  if (verbose())
    std::printf(
        "cantilever bricks Isolid 14: f1 measured %.4f Hz (%zu crossings), beam %.4f Hz (%+.3f %%); "
        "%zu cycles, %.2f s\n",
        r.f, r.crossings, r.f1, 100.0 * (r.f / r.f1 - 1.0), r.cycles, seconds_since(t0));
  // First frequency within 2 % of Euler-Bernoulli: the 2 x 2 x 2 points with ASQBI's assumed strain give
  // the beam its bending stiffness E I and mass; the remainder is shear deformation and rotary inertia at
  // L/H = 10 and the time integration (measured -0.67 %, as Isolid 24; Isolid 18 also -0.67 %). With 12
  // bricks through the height the in-element bending mode carries little of the energy, so even the plain
  // 2 x 2 x 2 brick (Isolid 12) measures +0.29 %: locking is checked by the one-element bending test in
  // test_hex8_full.cpp, not here. 2 % of f1 is 7 Hz.
  CHECK(std::abs(r.f - r.f1) <= 0.02 * r.f1);
  check_energy(r.energy, "cantilever_bricks (Isolid 14)");
}

// ---------------------------------------------------------------------------------------------------------
// B.9: Taylor bar (Mg, mm, s). Final length 21.42 to 21.48 mm for L0 = 32.4 mm (and foot radius 7.11 to 7.23
// mm). The same deck with 1 and 2 threads gives bit-identical node coordinates.
TEST_CASE("verification: Taylor bar final length, thread independence", "[verification]") {
  const auto t0 = std::chrono::steady_clock::now();
  Case c = load_case("taylor_bar", "TAYLOR_BAR");
  const md::Model& m = c.model;
  const md::Material& mat = only_material(m);
  // The reference answer belongs to these parameters (docs/theory/verification.md B.9), so the deck must
  // carry them (compared in SI; relative 1e-12: only the decimal reading and the unit factors round).
  const double f_len = m.units.length, f_mass = m.units.mass, f_time = m.units.time;
  const double f_stress = f_mass / (f_len * f_time * f_time);
  const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::abs(b); };
  REQUIRE(mat.law == md::MaterialLaw::JohnsonCook);
  CHECK(same(mat.rho * f_mass / (f_len * f_len * f_len), 8930.0));
  CHECK(same(mat.young * f_stress, 117e9));
  CHECK(mat.poisson == 0.35);
  CHECK(same(mat.a * f_stress, 400e6));
  CHECK(same(mat.b * f_stress, 100e6));
  CHECK(mat.n == 1.0);
  CHECK(mat.c == 0.0);
  const double zmin0 = min_of(m.nodes.z), zmax0 = max_of(m.nodes.z);
  const double L0 = zmax0 - zmin0;
  double r0 = 0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) r0 = std::max(r0, std::hypot(m.nodes.x[n], m.nodes.y[n]));
  CHECK(same(L0 * f_len, 32.4e-3));
  CHECK(same(r0 * f_len, 3.2e-3));
  REQUIRE(m.initial_velocities.size() == 1);
  CHECK(same(-m.initial_velocities[0].v[2] * f_len / f_time, 227.0));
  CHECK(same(c.controls.t_stop * f_time, 80e-6));

  auto run = [&](int threads, EnergyWatch& energy, std::vector<double>& xyz, double& seconds) {
    const auto ts = std::chrono::steady_clock::now();
    sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{threads});
    const auto res = eng.run([&](const sv::CycleReport& r) {
      energy(r);
      return true;
    });
    INFO(res.message);
    REQUIRE(res.status == sv::RunStatus::Normal);
    const auto& s = eng.nodes();
    xyz.clear();
    xyz.insert(xyz.end(), s.x.begin(), s.x.end());
    xyz.insert(xyz.end(), s.y.begin(), s.y.end());
    xyz.insert(xyz.end(), s.z.begin(), s.z.end());
    seconds = seconds_since(ts);
    return res.cycles;
  };
  EnergyWatch energy2, energy1;
  std::vector<double> xyz2, xyz1;
  double s2 = 0, s1 = 0;
  const auto cycles = run(2, energy2, xyz2, s2);

  const std::size_t nn = m.nodes.size();
  double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin, foot = 0;
  for (std::size_t n = 0; n < nn; ++n) {
    zmin = std::min(zmin, xyz2[2 * nn + n]);
    zmax = std::max(zmax, xyz2[2 * nn + n]);
    foot = std::max(foot, std::hypot(xyz2[n], xyz2[nn + n]));  // the widest section is the foot
  }
  const double length = (zmax - zmin) * f_len, radius = foot * f_len;
  // Distance to the accepted window, relative to the window's centre.
  const auto outside = [](double v, double lo, double hi) {
    return std::max({0.0, lo - v, v - hi}) / (0.5 * (lo + hi));
  };

  // Final length within 3 % of the accepted 21.42-21.48 mm window. Why 3 %: the window comes from converged
  // solutions, while this mesh has 8 one-point bricks across the radius with viscous hourglass control and
  // bulk viscosity, and the foot (plastic strains above 2 near the axis) is resolved by a few strongly
  // flattened bricks; the discretisation error is of the order of one element length along the axis,
  // 0.6 mm, i.e. 3 % of 21.45 mm (measured when this test was written: 21.56, 21.53, 21.51 mm with layers
  // of 0.9, 0.6, 0.45 mm, so the mesh effect is real but well inside). The foot radius is held to the same
  // 3 % of its 7.11-7.23 mm window.
  CHECK(outside(length, 21.42e-3, 21.48e-3) <= 0.03);
  CHECK(outside(radius, 7.11e-3, 7.23e-3) <= 0.03);
  check_energy(energy2, "taylor_bar");

  // Threads: the assembly sums element forces node by node in a fixed order, so 1 and 2 threads must give
  // the same bits.
  run(1, energy1, xyz1, s1);
  REQUIRE(xyz1.size() == xyz2.size());
  std::size_t differ = 0;
  for (std::size_t k = 0; k < xyz1.size(); ++k) differ += xyz1[k] != xyz2[k] ? 1 : 0;
  CHECK(differ == 0);
  if (verbose())
    std::printf(
        "taylor: final length %.5f mm (window 21.42-21.48, L0 %.4g mm), foot radius %.4f mm "
        "(window 7.11-7.23); %lld cycles; 2 threads %.2f s, 1 thread %.2f s; %zu coordinates differ; "
        "total %.2f s\n",
        length * 1e3, L0 * f_len * 1e3, radius * 1e3, (long long)cycles, s2, s1, differ, seconds_since(t0));
}

// ---------------------------------------------------------------------------------------------------------
// B.14: uniaxial Johnson-Cook at one brick (Mg, mm, s): the axial stress follows sigma_y = a + b eps_p^n and
// the plastic work is the area under that curve.
TEST_CASE("verification: Johnson-Cook single brick flow curve", "[verification]") {
  const auto t0 = std::chrono::steady_clock::now();
  Case c = load_case("jc_single_brick", "JC_SINGLE_BRICK");
  const md::Model& m = c.model;
  const md::Material& mat = only_material(m);
  REQUIRE(mat.law == md::MaterialLaw::JohnsonCook);
  REQUIRE(mat.c == 0.0);  // no rate effect: the flow stress depends on eps_p only
  REQUIRE(m.bricks.size() == 1);
  const double a = mat.a, b = mat.b, n = mat.n;
  const auto flow = [&](double e) { return a + b * std::pow(e, n); };

  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{1});
  struct Rec {
    double t, eps_p, w_plastic, vol;
    std::array<double, 6> sig;
  };
  std::vector<Rec> rec;
  EnergyWatch energy;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    const auto& g = eng.groups().bricks.at(0);
    Rec x{r.time, g.eps_p[0], g.w_plastic[0], g.vol[0], {}};
    for (std::size_t k = 0; k < 6; ++k) x.sig[k] = g.sig[k * G];
    rec.push_back(x);
    energy(r);
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);

  // Along the run, on every cycle after the first yield:
  //  * uniaxial stress s_u = szz - (sxx + syy) / 2: for this axisymmetric state (sxx = syy by symmetry, no
  //    shear) it is the von Mises stress, the quantity the return mapping puts on the flow curve;
  //  * axial stress szz = s_u + lateral stress; the lateral faces are free, so the lateral stress is only
  //    the inertia of the lateral contraction, of order rho c (0.5 - nu) eps_dot h ~ 0.1 MPa when the
  //    contraction speeds up at yield (README): it must stay below 1e-3 of the flow stress.
  // Johnson-Cook hardening is explicit (docs/theory/elements.md 6.2-6.3: the slope H is taken at the plastic
  // strain of the start of the step, H = 0 at eps_p = 0 for n < 1), so on a cycle where eps_p grows from e0
  // to e1 the stress lies on the curve up to that cycle's hardening increment |sigma_y(e1) - sigma_y(e0)|
  // (1.7 MPa on the first plastic cycle, below 1e-5 of the flow stress once eps_p > 1e-4), plus round-off
  // (1e-12). On the few cycles right after the first yield where eps_p does not grow, the point reloads
  // elastically inside the yield surface (s_u <= sigma_y), which is only allowed before eps_p reaches 1e-5.
  double worst_u = 0, worst_axial = 0, worst_lateral = 0, worst_late = 0;
  std::size_t plastic = 0, reload = 0;
  for (std::size_t k = 1; k < rec.size(); ++k) {
    const auto& x = rec[k];
    if (x.eps_p <= 0) continue;
    const double e0 = rec[k - 1].eps_p, e1 = x.eps_p;
    const double sy = flow(e1);
    const double lateral = 0.5 * (x.sig[0] + x.sig[1]);
    const double s_u = x.sig[2] - lateral;
    INFO("cycle " << k << " eps_p " << e0 << " -> " << e1 << ": uniaxial " << s_u << ", axial " << x.sig[2]
                  << ", flow " << sy);
    REQUIRE(std::abs(x.sig[0] - x.sig[1]) <= 1e-12 * sy);  // symmetry x <-> y
    CHECK(std::abs(lateral) <= 1e-3 * sy);
    worst_lateral = std::max(worst_lateral, std::abs(lateral) / sy);
    if (e1 > e0) {
      ++plastic;
      const double lag = std::abs(sy - flow(e0));
      CHECK(std::abs(s_u - sy) <= lag + 1e-12 * sy);
      CHECK(std::abs(x.sig[2] - sy) <= lag + 1e-3 * sy);
      worst_u = std::max(worst_u, std::abs(s_u - sy) / sy);
      worst_axial = std::max(worst_axial, std::abs(x.sig[2] - sy) / sy);
      if (e1 > 1e-3) worst_late = std::max(worst_late, std::abs(s_u - sy) / sy);
    } else {
      ++reload;
      CHECK(s_u <= sy * (1 + 1e-12));
      CHECK(e1 < 1e-5);
    }
  }
  CHECK(plastic > rec.size() / 2);  // the run is mostly plastic flow

  // Plastic work = area under the flow curve times the volume. The engine books sigma_vm,new d_eps_p V each
  // cycle (docs/theory/elements.md 6.5) with the current volume V; the reference integrates the closed-form
  // curve exactly over each cycle's plastic increment with the same V:  sum_k V_k [F(e_k) - F(e_k-1)],
  // F(e) = a e + b e^(n+1) / (n + 1). The two differ by where the stress is sampled inside each increment
  // (at most that cycle's hardening increment, below 1e-5 of the stress after the onset of yield):
  // relative 1e-5. Against the initial volume (the README's closed form) the volume differs by the elastic
  // dilatation (1 - 2 nu) sigma / E, below 1e-3 here: relative 2e-3.
  const auto area = [&](double e) { return a * e + b * std::pow(e, n + 1.0) / (n + 1.0); };
  double w_ref = 0;
  for (std::size_t k = 1; k < rec.size(); ++k)
    w_ref += rec[k].vol * (area(rec[k].eps_p) - area(rec[k - 1].eps_p));
  const double eps_end = rec.back().eps_p, w_end = rec.back().w_plastic;
  const double vol0 = eng.groups().bricks.at(0).vol0[0];
  CHECK(std::abs(w_end - w_ref) <= 1e-5 * w_ref);
  CHECK(std::abs(w_end - vol0 * area(eps_end)) <= 2e-3 * vol0 * area(eps_end));
  if (verbose())
    std::printf(
        "jc: %zu plastic cycles (%zu elastic reloads after the first yield), eps_p end %.5f; worst "
        "|s_u - flow|/flow %.3e (%.3e for eps_p > 1e-3), |axial - flow|/flow %.3e, lateral/flow %.3e; "
        "plastic work %.6e, area x V %.6e (%+.2e), area x V0 %.6e (%+.2e); %.2f s\n",
        plastic, reload, eps_end, worst_u, worst_late, worst_axial, worst_lateral, w_end, w_ref,
        w_end / w_ref - 1, vol0 * area(eps_end), w_end / (vol0 * area(eps_end)) - 1, seconds_since(t0));
  check_energy(energy, "jc_single_brick");
}

// ---------------------------------------------------------------------------------------------------------
// Loads under /SENSOR/TIME (kg, m, s; decks/verification/sensor_loads/README.md): a free brick whose 8 nodes
// all get the same load per unit mass, so it translates and each momentum component is its load's closed form
// with the function's time origin at the sensor's activation: /CLOAD Z from sensor 1 (on at T1, off at its
// Tstop), /GRAV X from sensor 2, /IMPVEL Y from sensor 3.
namespace {

// Integral from 0 to a of the piecewise-linear function f (trapezoids between its points, linear beyond).
double integral(const md::Function& f, double a) {
  double sum = 0;
  for (std::size_t k = 0; k + 1 < f.x.size() && f.x[k] < a; ++k) {
    const double x1 = std::min(f.x[k + 1], a);
    const double y1 = f.y[k] + (f.y[k + 1] - f.y[k]) * (x1 - f.x[k]) / (f.x[k + 1] - f.x[k]);
    sum += 0.5 * (f.y[k] + y1) * (x1 - f.x[k]);
  }
  return sum;
}

}  // namespace

TEST_CASE("verification: loads and an imposed velocity started and stopped by /SENSOR/TIME",
          "[verification]") {
  Case c = load_case("sensor_loads", "SENSOR_LOADS");
  const md::Model& m = c.model;
  REQUIRE(m.sensors.size() == 3);
  REQUIRE(m.concentrated_loads.size() == 1);
  REQUIRE(m.gravities.size() == 1);
  REQUIRE(m.imposed_velocities.size() == 1);
  const auto& cl = m.concentrated_loads[0];
  const auto& gr = m.gravities[0];
  const auto& iv = m.imposed_velocities[0];
  const auto sensor = [&](std::int64_t id) {
    return m.sensors[static_cast<std::size_t>(m.sensor_index(id))];
  };
  const double T1 = sensor(cl.sensor).t_delay, T1_stop = sensor(cl.sensor).t_stop;
  const double T2 = sensor(gr.sensor).t_delay, T3 = sensor(iv.sensor).t_delay;
  REQUIRE(T1_stop < c.controls.t_stop);
  const double loaded = static_cast<double>(m.node_groups[static_cast<std::size_t>(cl.group)].nodes.size());
  const md::Function& push = m.functions[static_cast<std::size_t>(cl.function)];
  const md::Function& speed = m.functions[static_cast<std::size_t>(iv.function)];
  double mass = 0;
  for (const double x : m.node_mass) mass += x;
  const double f_total = loaded * cl.fscale_y;  // the largest total force (the function peaks at 1)

  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{1});
  std::vector<std::string> events;
  double dt_max = 0, err_z = 0, err_x = 0, err_y = 0, prev_t = -1, prev_dt = 0, err_energy = 0;
  std::int64_t before = 0;  // momentum components checked to be exactly 0 before their sensor
  const auto res = eng.run([&](const sv::CycleReport& r) {
    REQUIRE(r.full);
    // The energy balance as an absolute error, E - (E0 + W): the run starts at rest (E0 = 0), so right after
    // a sensor the energies are tiny and the relative ERROR % of docs/theory/elements.md 8 says little.
    err_energy =
        std::max(err_energy, std::abs(r.energy.total() - r.energy.initial_total - r.energy.external_work));
    for (auto& e : eng.take_events()) events.push_back(e);
    dt_max = std::max(dt_max, r.dt1);
    const double t = r.time;
    // ZMOM: the impulse of F(t' - T1) from T1 to min(t, Tstop); XMOM: M g (t - T2).
    const double z = loaded * cl.fscale_y * integral(push, std::clamp(t, T1, T1_stop) - T1);
    const double x = mass * gr.fscale_y * std::max(t - T2, 0.0);
    if (t < T1) before += r.momentum[2] == 0.0 ? 1 : -1000;
    if (t < T2) before += r.momentum[0] == 0.0 ? 1 : -1000;
    err_z = std::max(err_z, std::abs(r.momentum[2] - z));
    err_x = std::max(err_x, std::abs(r.momentum[0] - x));
    // VY at the half step t_{n-1} + dt/2: the imposed v(tau) from the cycle where t_{n-1} >= T3, free (0)
    // before: exact up to round-off.
    if (prev_t >= 0) {
      const double vy = eng.nodes().vy[0];
      const double expected = prev_t >= T3 ? sv::scaled_function_value(speed, prev_t + 0.5 * prev_dt - T3,
                                                                       iv.ascale_x, iv.fscale_y)
                                           : 0.0;
      err_y = std::max(err_y, std::abs(vy - expected));
    }
    prev_t = t;
    prev_dt = r.dt;
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);
  // A sensor's load starts at the first cycle at or after its time and stops likewise: one step's impulse.
  INFO("ZMOM error " << err_z << ", XMOM error " << err_x << " (one step's impulse: " << f_total * dt_max
                     << ", " << mass * std::abs(gr.fscale_y) * dt_max << "), VY error " << err_y);
  CHECK(before > 0);
  CHECK(err_z <= f_total * dt_max);
  CHECK(err_x <= mass * std::abs(gr.fscale_y) * dt_max);
  CHECK(err_y <= 1e-12);
  CHECK(events == std::vector<std::string>{"SENSOR (TIME) 1 ACTIVATED AT TIME 1.0000E-03",
                                           "SENSOR (TIME) 3 ACTIVATED AT TIME 1.5000E-03",
                                           "SENSOR (TIME) 2 ACTIVATED AT TIME 2.0000E-03",
                                           "SENSOR (TIME) 1 DEACTIVATED AT TIME 3.0000E-03"});
  // After Tstop the push is over: ZMOM stays at n F0 integral(Tstop - T1).
  CHECK(std::abs(res.last.momentum[2] - f_total * integral(push, T1_stop - T1)) <= f_total * dt_max);
  // The energy balance within 1e-4 of the final energy: the work of a load is booked over the cycle where it
  // stops too (without that the push's last half step, 2e-3 of the final energy here, would be missing);
  // what remains is the trapezoidal work of the ramp.
  const double e_end = res.last.energy.total();
  CHECK(err_energy <= 1e-4 * e_end);
  if (verbose())
    std::printf(
        "sensor_loads: ZMOM error %.3e (bound %.3e), XMOM error %.3e (bound %.3e), VY error %.3e, "
        "worst |E - W| %.3e of final E %.3e\n",
        err_z, f_total * dt_max, err_x, mass * std::abs(gr.fscale_y) * dt_max, err_y, err_energy, e_end);
}

// ---------------------------------------------------------------------------------------------------------
// A block of 4-node tetrahedra dropped on a clamped shell plate; TYPE7 main surface = the block's outer tetra
// faces (triangle segments), secondary = the plate nodes. No closed form for the impact itself: the checks
// are the global ones of docs/theory/verification.md C (energy balance) and that the contact on tetra faces
// works (the block is stopped, no plate node crosses the block's bottom face).
TEST_CASE("verification: tetrahedron block dropped on a plate through TYPE7", "[verification][tetra]") {
  Case c = load_case("tetra_drop", "TETRA_DROP");
  const md::Model& m = c.model;
  REQUIRE(m.tetras.size() == 48);
  REQUIRE(m.interfaces.size() == 1);
  const md::Surface& skin = m.surfaces[static_cast<std::size_t>(m.interfaces[0].main_surface)];
  // 2 x 2 cells on each of 6 sides, 2 triangles per cell face: 48 outer faces, all tetra faces.
  REQUIRE(skin.segments.size() == 48);
  for (const auto t : skin.owner_type) REQUIRE(t == md::SegmentOwner::Tetra4);
  REQUIRE(m.initial_velocities.size() == 1);
  const double v0 = -m.initial_velocities[0].v[2];
  REQUIRE(v0 > 0);
  const double mass_block = m.parts[0].mass;
  REQUIRE(mass_block > 0);
  std::vector<std::uint8_t> in_block(m.nodes.size(), 0);
  for (const auto n : m.tetras.conn) in_block[static_cast<std::size_t>(n)] = 1;
  const double gap = m.interfaces[0].gapmin;

  sv::ExplicitEngine eng(m, c.controls, sv::EngineOptions{1});
  REQUIRE(eng.contact() != nullptr);
  EnergyWatch energy;
  double pz_min = 0, pz_last = 0, e_contact_max = 0;
  double worst_crossing = -std::numeric_limits<double>::infinity();
  // Half the block's width, less a tenth of a cell, for the plate nodes under its bottom face.
  double half = 0;
  for (std::size_t n = 0; n < m.nodes.size(); ++n)
    if (in_block[n]) half = std::max(half, std::abs(m.nodes.x[n]));
  const double inside = 0.95 * half;
  const auto res = eng.run([&](const sv::CycleReport& r) {
    energy(r);
    e_contact_max = std::max(e_contact_max, r.energy.contact_elastic);
    const auto& s = eng.nodes();
    double pz = 0, z_bottom = std::numeric_limits<double>::infinity();
    for (std::size_t n = 0; n < s.n; ++n)
      if (in_block[n]) {
        pz += s.mass[n] * s.vz[n];
        z_bottom = std::min(z_bottom, s.z[n]);
      }
    pz_min = std::min(pz_min, pz);
    // A plate node under the block's bottom face (|x|, |y| inside the block) must stay below it: how far
    // it passes above is the penetration through the face.
    for (std::size_t n = 0; n < s.n; ++n)
      if (!in_block[n] && std::abs(s.x[n]) < inside && std::abs(s.y[n]) < inside)
        worst_crossing = std::max(worst_crossing, s.z[n] - z_bottom);
    pz_last = pz;
    return true;
  });
  REQUIRE(res.status == sv::RunStatus::Normal);
  const double p0 = mass_block * v0;
  if (verbose())
    std::printf(
        "tetra_drop: pz_min / p0 %.4f, final pz / p0 %.4f, worst crossing / gap %.3f, contact energy max "
        "%.4g J of %.4g\n",
        pz_min / p0, pz_last / p0, worst_crossing / gap, e_contact_max, 0.5 * mass_block * v0 * v0);
  // The block starts with p = -m v0 (1e-9 relative: the initial velocity is exact).
  CHECK(pz_min == Approx(-p0).epsilon(1e-9));
  // The contact acts on the tetra faces: it stores energy and removes more than half the downward momentum.
  CHECK(e_contact_max > 0);
  CHECK(pz_last > -0.5 * p0);
  // No plate node goes through the block's bottom face (it stays on the plate side of the face).
  CHECK(worst_crossing < 0);
  check_energy(energy, "tetra_drop");
}
