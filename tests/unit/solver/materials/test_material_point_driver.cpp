// Every material law at one point through the one entry point, material_point_update
// (solver/materials/material_point.hpp): one driver takes a law through a uniaxial strain and a simple shear,
// and each law is checked against closed forms written here from its equations (docs/theory/elements.md 1.4,
// 3.3 and 6 for laws 1 and 2; docs/elements-openradioss.md 6.6 law 36, 6.7 /FAIL/JOHNSON, 6.8 law 70; the
// opening comments of law27_plas_brit.cpp and law42_ogden.cpp). Units: MPa, mm, s. "Round-off" is 1e-12
// relative: a few thousand ulps of the quantities summed over the increments, far below any modelling
// effect tested here.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "solver/materials/material_point.hpp"
#include "test_util.hpp"

using radx::model::Function;
using radx::model::Material;
using radx::model::MaterialLaw;
using namespace radx::solver;

namespace {

constexpr double kRound = 1e-12;

using radx::test::close;

// ---- The driver ----

enum class Path { UniaxialStrain, SimpleShear };

// One step of a driven point: the imposed strain at its end (eps_xx or gamma_xy), the plastic strain at its
// start and what the point gave.
struct Step {
  double strain = 0;
  double eps_p_start = 0;
  PointState st;
  PointResult r;
};

// Drives one point from rest to `total` (uniaxial strain eps_xx, or simple shear gamma_xy) in `n` equal
// increments at the constant strain rate |total| / (n dt), through material_point_update. Each step gives
// the law the increment, the total deformation gradient (F = diag(1 + e, 1, 1), or F = I + gamma e_x (x)
// e_y) and the density ratio rho / rho0 = 1 / det F. plane_stress: a shell point (sigma_zz = 0), with the
// transverse shear modulus 5/6 G.
std::vector<Step> drive(const MaterialParams& p, Path path, double total, int n, bool plane_stress = false) {
  const double dt = 1e-6;
  PointInput in;
  in.plane_stress = plane_stress;
  in.transverse_shear = 5.0 / 6.0 * p.shear;
  in.dt = dt;
  in.rate = std::abs(total) / (n * dt);
  const int k = path == Path::UniaxialStrain ? 0 : 3;  // the driven component (engineering shear for xy)
  in.de[k] = total / n;
  PointState st = initial_point_state(p);
  std::vector<Step> steps;
  for (int i = 1; i <= n; ++i) {
    const double e = total * i / n;
    if (path == Path::UniaxialStrain) {
      in.F[0][0] = 1.0 + e;
      in.rho_ratio = 1.0 / (1.0 + e);
    } else {
      in.F[0][1] = e;
    }
    Step s;
    s.strain = e;
    s.eps_p_start = st.eps_p;
    s.r = material_point_update(p, in, st);
    s.st = st;
    steps.push_back(s);
  }
  return steps;
}

// ---- The materials ----

Material elastic_steel(MaterialLaw law) {
  Material m;
  m.law = law;
  m.rho = 7.85e-9;
  m.young = 210000.0;
  m.poisson = 0.3;
  return m;
}

// Johnson-Cook with linear hardening (n = 1), so that the radial return is exact and eps_p has a closed
// form, and a rate term that the driver's constant rate turns into the factor R.
Material johnson_cook() {
  Material m = elastic_steel(MaterialLaw::JohnsonCook);
  m.a = 200.0;
  m.b = 500.0;
  m.n = 1.0;
  m.c = 0.02;
  m.eps_dot_0 = 1.0;
  return m;
}

// A piecewise-linear hardening curve of law 36 (slopes 1200, 800, 250, 71.4) at every rate.
Function hardening_curve() {
  Function f;
  f.x = {0.0, 0.05, 0.1, 0.3, 1.0};
  f.y = {200.0, 260.0, 300.0, 350.0, 400.0};
  return f;
}

// The curve written out again: linear between its points.
double hardening_at(double eps_p) {
  const Function f = hardening_curve();
  std::size_t i = 0;
  while (i + 2 < f.x.size() && eps_p >= f.x[i + 1]) ++i;
  return f.y[i] + (f.y[i + 1] - f.y[i]) / (f.x[i + 1] - f.x[i]) * (eps_p - f.x[i]);
}

// von Mises stress of a 3D stress (xx yy zz xy yz zx) and of a plane stress (xx yy xy).
double vm_solid(const double* s) {
  const double m = (s[0] + s[1] + s[2]) / 3.0;
  const double d0 = s[0] - m, d1 = s[1] - m, d2 = s[2] - m;
  return std::sqrt(1.5 * (d0 * d0 + d1 * d1 + d2 * d2) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}
double vm_plane(double sxx, double syy, double sxy) {
  return std::sqrt(sxx * sxx + syy * syy - sxx * syy + 3.0 * sxy * sxy);
}

}  // namespace

TEST_CASE("driver, law 1: uniaxial strain and simple shear give the elastic moduli", "[material][driver]") {
  const MaterialParams p = make_material_params(elastic_steel(MaterialLaw::Elastic));
  const double g = p.shear, k = p.bulk;
  SECTION("solid, uniaxial strain: sigma_xx = K eps_v + 4G/3 eps, sigma_yy = sigma_zz = K eps_v - 2G/3 eps") {
    // The pressure is total, from the density: eps_v = 1 - rho/rho0 = eps / (1 + eps), the small-strain eps
    // to first order; the deviator is the sum of the increments.
    for (const Step& s : drive(p, Path::UniaxialStrain, 1e-3, 10)) {
      const double eps = s.strain, eps_v = eps / (1.0 + eps);
      CHECK(s.r.supported);
      CHECK(close(s.st.sig[0], k * eps_v + 4.0 / 3.0 * g * eps, kRound));
      CHECK(close(s.st.sig[1], k * eps_v - 2.0 / 3.0 * g * eps, kRound));
      CHECK(close(s.st.sig[2], k * eps_v - 2.0 / 3.0 * g * eps, kRound));
      CHECK(std::abs(s.st.sig[3]) + std::abs(s.st.sig[4]) + std::abs(s.st.sig[5]) == 0.0);
      CHECK(s.st.eps_p == 0.0);
    }
  }
  SECTION("solid, simple shear: tau = G gamma, no normal stress") {
    for (const Step& s : drive(p, Path::SimpleShear, 1e-3, 10)) {
      CHECK(close(s.st.sig[3], g * s.strain, kRound));
      CHECK(std::abs(s.st.sig[0]) + std::abs(s.st.sig[1]) + std::abs(s.st.sig[2]) <= kRound * g * s.strain);
    }
  }
  SECTION(
      "shell, uniaxial strain: sigma_xx = E/(1 - nu^2) eps, sigma_yy = nu sigma_xx, dezz = -nu/(1-nu) deps") {
    const double e = p.young, nu = p.nu;
    for (const Step& s : drive(p, Path::UniaxialStrain, 1e-3, 10, true)) {
      CHECK(close(s.st.sig[0], e / (1.0 - nu * nu) * s.strain, kRound));
      CHECK(close(s.st.sig[1], nu * e / (1.0 - nu * nu) * s.strain, kRound));
      CHECK(s.st.sig[2] == 0.0);
      CHECK(close(s.r.dezz, -nu / (1.0 - nu) * 1e-4, kRound));
    }
  }
  SECTION("shell, simple shear: tau = G gamma") {
    for (const Step& s : drive(p, Path::SimpleShear, 1e-3, 10, true))
      CHECK(close(s.st.sig[3], g * s.strain, kRound));
  }
}

TEST_CASE("driver, law 2: the deviator saturates at the Johnson-Cook flow stress", "[material][driver]") {
  const MaterialParams p = make_material_params(johnson_cook());
  const double g = p.shear, k = p.bulk;
  // The driver's constant rate (0.02 over 200 steps of 1e-6: 100 per second) gives R = 1 + c ln(rate /
  // rate0); with n = 1 the flow stress is (A + B eps_p) R and the radial return is exact: once plastic the
  // equivalent strain splits into its elastic part sigma_y / 3G and eps_p.
  const double total = 0.02;
  const int n = 200;
  const double r = 1.0 + 0.02 * std::log(total / (n * 1e-6) / 1.0);
  const double a = 200.0 * r, b = 500.0 * r;
  SECTION("uniaxial strain: sigma_xx - sigma_yy = sigma_y(eps_p), eps_p = (2G eps - A R) / (3G + B R)") {
    int plastic = 0;
    for (const Step& s : drive(p, Path::UniaxialStrain, total, n)) {
      const double eps = s.strain, eps_v = eps / (1.0 + eps);
      const double eps_p = std::max(0.0, (2.0 * g * eps - a) / (3.0 * g + b));
      const double dev = eps_p > 0 ? a + b * eps_p : 2.0 * g * eps;  // sigma_xx - sigma_yy
      CHECK(close(s.st.eps_p, eps_p, 1e-9, kRound * eps));
      CHECK(close(s.st.sig[0] - s.st.sig[1], dev, 1e-9));
      CHECK(close(s.st.sig[1], s.st.sig[2], kRound));
      CHECK(close((s.st.sig[0] + s.st.sig[1] + s.st.sig[2]) / 3.0, k * eps_v, kRound));  // the pressure
      plastic += eps_p > 0;
    }
    CHECK(plastic > n / 2);  // the path goes well past the yield strain A R / 2G
  }
  SECTION("simple shear: sqrt(3) tau = sigma_y(eps_p), eps_p = (sqrt(3) G gamma - A R) / (3G + B R)") {
    for (const Step& s : drive(p, Path::SimpleShear, total, n)) {
      const double eps_p = std::max(0.0, (std::sqrt(3.0) * g * s.strain - a) / (3.0 * g + b));
      const double tau = eps_p > 0 ? (a + b * eps_p) / std::sqrt(3.0) : g * s.strain;
      CHECK(close(s.st.eps_p, eps_p, 1e-9, kRound * s.strain));
      CHECK(close(s.st.sig[3], tau, 1e-9));
      CHECK(close(vm_solid(s.st.sig), std::sqrt(3.0) * tau, 1e-9));
    }
  }
}

TEST_CASE("driver, law 27: plane-stress Johnson-Cook return, deleted past EPS_f1", "[material][driver]") {
  // Perfectly plastic (b = 0, c = 0) with the crack never opening (EPS_t1 default): the shell point's
  // plane-stress von Mises stress stays at A once it yields; the element is deleted once the largest
  // principal strain (here eps_xx, or gamma / 2 in simple shear) passes EPS_f1.
  Material m = elastic_steel(MaterialLaw::PlasBrit);
  m.a = 290.0;
  m.brit.eps_f1 = 0.0105;
  const MaterialParams p = make_material_params(m);
  const double e = p.young, nu = p.nu, g = p.shear;
  SECTION("uniaxial strain") {
    for (const Step& s : drive(p, Path::UniaxialStrain, 0.02, 20, true)) {
      const double sxx = e / (1.0 - nu * nu) * s.strain, syy = nu * sxx;
      if (vm_plane(sxx, syy, 0.0) <= 290.0) {
        CHECK(close(s.st.sig[0], sxx, kRound));
        CHECK(close(s.st.sig[1], syy, kRound));
      } else {
        CHECK(close(vm_plane(s.st.sig[0], s.st.sig[1], s.st.sig[3]), 290.0, kRound));
        CHECK(s.st.eps_p > 0);
      }
      CHECK(s.r.element_fails == (s.strain > 0.0105));
    }
  }
  SECTION("simple shear") {
    for (const Step& s : drive(p, Path::SimpleShear, 0.01, 20, true)) {
      const double tau = std::min(g * s.strain, 290.0 / std::sqrt(3.0));
      CHECK(close(s.st.sig[3], tau, kRound));
      CHECK(!s.r.element_fails);  // gamma / 2 <= 0.005
    }
  }
}

TEST_CASE("driver, law 36: the deviator follows the tabulated curve", "[material][driver]") {
  Material m = elastic_steel(MaterialLaw::PlasTab);
  m.tab.function_id = {1};
  m.tab.function = {0};
  m.tab.scale = {1.0};
  m.tab.rate = {0.0};
  const std::vector<Function> functions = {hardening_curve()};
  std::vector<TabCurve> curves;
  const MaterialParams p = make_material_params(m, functions, curves);
  const double g = p.shear;
  SECTION("uniaxial strain: sigma_xx - sigma_yy = sigma_y(eps_p at the start of the step)") {
    // Law 36 hardens explicitly: the returned deviator sits on the curve at the plastic strain of the start
    // of the step, so eps_p lags the consistent return's (2G eps - Y0) / (3G + H) (here on the first segment,
    // Y0 = 200, H = 1200): each step solves (3G + H) eps_p = 2G eps - Y0 - H eps_p(start of the step), which
    // keeps it above (2G eps - Y0) / (3G + 2H), the slope counted twice.
    const double h = 1200.0;
    int plastic = 0;
    for (const Step& s : drive(p, Path::UniaxialStrain, 0.04, 400)) {
      const double dev = s.st.sig[0] - s.st.sig[1];
      if (s.st.eps_p == 0) {
        CHECK(close(dev, 2.0 * g * s.strain, kRound));
        CHECK(2.0 * g * s.strain <= 200.0 * (1.0 + kRound));
        continue;
      }
      ++plastic;
      CHECK(close(dev, hardening_at(s.eps_p_start), kRound));
      const double driven = 2.0 * g * s.strain - 200.0;  // 3G times the plastic part of the driven strain
      CHECK(s.st.eps_p <= driven / (3.0 * g + h) * (1.0 + kRound));
      CHECK(s.st.eps_p >= driven / (3.0 * g + 2.0 * h) * (1.0 - kRound));
      REQUIRE(s.st.eps_p < 0.05);  // still on the first segment, where H = 1200
    }
    CHECK(plastic > 300);
  }
  SECTION("simple shear: tau = G gamma, then sqrt(3) tau = sigma_y(eps_p at the start of the step)") {
    for (const Step& s : drive(p, Path::SimpleShear, 0.04, 400)) {
      if (s.st.eps_p == 0)
        CHECK(close(s.st.sig[3], g * s.strain, kRound));
      else
        CHECK(close(std::sqrt(3.0) * s.st.sig[3], hardening_at(s.eps_p_start), kRound));
    }
  }
}

TEST_CASE("driver, law 42: Ogden's small-strain limit has the moduli G and K", "[material][driver]") {
  // The QA rubber of OpenRadioss's law42 deck (mu 827.6, 55; alpha 2, -2), nu 0.45, with the starter's
  // moduli G0 = sum mu alpha / 2 and K = 2 G0 (1 + nu) / 3 (1 - 2 nu). At eps = 1e-6 the second-order terms
  // are of relative size |alpha| eps, and the isochoric powers of the stretches lose 1e-16 / eps to
  // cancellation: 1e-4 is far above both and far below any error in a modulus.
  Material m;
  m.law = MaterialLaw::Ogden;
  m.rho = 940.0;
  m.poisson = 0.45;
  m.ogden.mu = {827.6, 55.0};
  m.ogden.alpha = {2.0, -2.0};
  const double g2 = 827.6 * 2.0 - 55.0 * 2.0;
  m.shear = 0.5 * g2;
  m.bulk = g2 * 1.45 / (3.0 * (1.0 - 0.9));
  m.young = g2 * 1.45;
  const MaterialParams p = make_material_params(m);
  const double g = 0.5 * g2, k = m.bulk, tol = 1e-4;
  SECTION("uniaxial strain") {
    for (const Step& s : drive(p, Path::UniaxialStrain, 1e-6, 2)) {
      CHECK(close(s.st.sig[0], (k + 4.0 / 3.0 * g) * s.strain, tol));
      CHECK(close(s.st.sig[1], (k - 2.0 / 3.0 * g) * s.strain, tol));
      CHECK(close(s.st.sig[2], (k - 2.0 / 3.0 * g) * s.strain, tol));
      CHECK(close(s.r.wave_speed, std::sqrt((k + 4.0 / 3.0 * g) / (940.0 / (1.0 + s.strain))), tol));
    }
  }
  SECTION("simple shear") {
    for (const Step& s : drive(p, Path::SimpleShear, 1e-6, 2)) {
      CHECK(close(s.st.sig[3], g * s.strain, tol));
      CHECK(std::abs(s.st.sig[0]) <= tol * g * s.strain);
    }
  }
}

TEST_CASE("driver, law 70: the foam's stress follows its loading curve", "[material][driver]") {
  // nu = 0, so the law's Hooke matrix is diagonal and the stress is the curve's value in the direction of the
  // strain: uniaxial strain eps_xx = -e gives sigma_xx = -L(e); simple shear gamma has the strain norm
  // e = gamma / sqrt(2) and the stress norm L(e) in xy, sqrt(2) |tau| = L(e). The curve's slopes (10, 0.5, 6)
  // stay below E0 = 20, so on loading the elastic trial is above the curve and the stress is the curve.
  Function l;
  l.x = {0.0, 0.1, 0.5, 0.8};
  l.y = {0.0, 1.0, 1.2, 3.0};
  const auto curve = [](double e) {
    if (e <= 0.1) return 10.0 * e;
    if (e <= 0.5) return 1.0 + 0.5 * (e - 0.1);
    return 1.2 + 6.0 * (e - 0.5);
  };
  Material m;
  m.law = MaterialLaw::FoamTab;
  m.rho = 1e-8;
  m.young = 20.0;
  m.poisson = 0.0;
  m.foam.e_max = 100.0;
  m.foam.eps_max = 0.8;
  m.foam.load_function_id = {1};
  m.foam.load_function = {0};
  m.foam.load_scale = {1.0};
  m.foam.load_rate = {0.0};
  const std::vector<Function> functions = {l};
  std::vector<TabCurve> curves;
  const MaterialParams p = make_material_params(m, functions, curves);
  SECTION("uniaxial compression along the curve's three segments") {
    for (const Step& s : drive(p, Path::UniaxialStrain, -0.7, 70)) {
      CHECK(close(s.st.sig[0], -curve(-s.strain), kRound, kRound));
      CHECK(std::abs(s.st.sig[1]) + std::abs(s.st.sig[2]) <= kRound);
    }
  }
  SECTION("simple shear on the first segment") {
    // V - I of a simple shear has normal components and a shear of order gamma^2 beside gamma: at gamma =
    // 1e-3 they change the stress by a relative 1e-3 at most.
    for (const Step& s : drive(p, Path::SimpleShear, 1e-3, 10))
      CHECK(close(std::sqrt(2.0) * s.st.sig[3], curve(s.strain / std::sqrt(2.0)), 1e-3));
  }
}

TEST_CASE("driver, law 2 with /FAIL/JOHNSON: the brick is deleted at the failure strain",
          "[material][driver]") {
  // A constant failure strain eps_f = D1 (D2 = D3 = D4 = 0): the damage is eps_p / eps_f and the brick
  // starts its deletion in the step eps_p reaches eps_f; eps_p follows the closed form of the law-2 case.
  Material m = johnson_cook();
  m.c = 0.0;
  m.fail_jc.on = true;
  m.fail_jc.d1 = 0.01;
  const MaterialParams p = make_material_params(m);
  const double g = p.shear;
  bool failed = false;
  for (const Step& s : drive(p, Path::UniaxialStrain, 0.03, 300)) {
    const double eps_p = std::max(0.0, (2.0 * g * s.strain - 200.0) / (3.0 * g + 500.0));
    REQUIRE(close(s.st.eps_p, eps_p, 1e-9, kRound * s.strain));
    if (eps_p < 0.01 * (1.0 - 1e-9)) {
      CHECK(!s.r.element_fails);
      CHECK(close(s.st.dmg, eps_p / 0.01, 1e-9, kRound));
    } else if (!failed) {
      CHECK(s.r.element_fails);  // the first step past eps_f
      CHECK(s.st.dmg == 1.0);
      failed = true;
    }
  }
  CHECK(failed);
}

TEST_CASE("driver: a law gives no update where it does not run", "[material][driver]") {
  // Law 27 is a shell law; laws 42 and 70 are brick laws.
  const MaterialParams brit = make_material_params(elastic_steel(MaterialLaw::PlasBrit));
  PointState st = initial_point_state(brit);
  PointInput in;
  in.de[0] = 1e-3;
  CHECK(!material_point_update(brit, in, st).supported);
  CHECK(st.sig[0] == 0.0);
}
