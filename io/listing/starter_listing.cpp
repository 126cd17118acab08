#include "io/listing/starter_listing.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <utility>

#include "io/listing/unit_labels.hpp"
#include "solver/model/formulations.hpp"
#include "solver/model/hex20_shape.hpp"

namespace radx::io {

namespace {

const char* rule =
    "---------------------------------------------------------------------------------------------------\n";

void heading(std::ostream& os, const char* title) {
  os << '\n' << rule << "  " << title << '\n' << rule;
}

std::string law_name(model::MaterialLaw l) {
  switch (l) {
    case model::MaterialLaw::Elastic: return "LAW1 elastic";
    case model::MaterialLaw::JohnsonCook: return "LAW2 Johnson-Cook";
    case model::MaterialLaw::PlasTab: return "LAW36 tabulated plasticity";
    case model::MaterialLaw::PlasBrit: return "LAW27 brittle elasto-plastic (shells)";
    case model::MaterialLaw::Void: return "LAW0 void";
    case model::MaterialLaw::Rigid: return "LAW13 rigid";
    case model::MaterialLaw::Ogden: return "LAW42 Ogden hyperelastic (one-point bricks)";
    case model::MaterialLaw::FoamTab: return "LAW70 tabulated visco-elastic foam (one-point bricks)";
  }
  return "unknown law";
}

std::string inacti_text(int inacti) {
  switch (inacti) {
    case 0: return "no action (the penalty pushes the node out)";
    case 1: return "stiffness of the node deactivated";
    case 2: return "stiffness of the main segment deactivated";
    case 3: return "node moved out of the gap by the starter";
    case 5: return "gap reduced to g - P0, growing back to g as the pair opens";
    case 6: return "gap reduced to (g - P0) - 5 %, growing back to g as the pair opens";
    default: return "?";
  }
}

// The range "a" or "a to b" of a value that varies over an interface's pairs.
std::string range_text(double lo, double hi) {
  std::ostringstream os;
  os << std::setprecision(6) << lo;
  if (hi != lo) os << " to " << hi;
  return os.str();
}

// The range of the automatic stiffness density K / A_s over the interface's pairs: K from stiff_lo to
// stiff_hi, A_s over the secondary nodes that have an area. {0, 0} when no node has one.
std::pair<double, double> automatic_stiffness_range(const model::Interface& c) {
  const auto [a_lo, a_hi] = c.tributary_area_range();
  if (a_lo == 0) return {0.0, 0.0};
  return {c.stiff_lo / a_hi, c.stiff_hi / a_lo};
}

// A /CTCLAW law as the starter understood it (docs/theory/contact-laws.md sections 2 and 3), in the work
// units.
void write_contact_law(std::ostream& os, const model::Model& m, const model::Interface& c) {
  const auto& law = c.law;
  const auto& u = m.units;
  const std::string pa = unit_label(u, 1, -1, -2);
  const std::string pa_per_l = pa + "/" + u.length_name;
  const std::string per_l = "1/" + u.length_name;
  const std::string len = u.length_name;
  const auto [kc_lo, kc_hi] = automatic_stiffness_range(c);
  const std::string kc_auto = kc_lo > 0
                                  ? range_text(kc_lo, kc_hi) + " " + pa_per_l
                                  : std::string("(no secondary node has an area: that of the segment hit)");
  const char* in = "        ";
  switch (law.normal) {
    case model::NormalLaw::Interface:
      os << in << "normal law     the interface's own penalty (no n part)\n";
      break;
    case model::NormalLaw::Linear:
      os << in << "normal law     n1 bilinear: P = Kc u for u > 0\n";
      if (law.kc == -1)
        os << in << "               Kc automatic, K/A_s from " << kc_auto << '\n';
      else
        os << in << "               Kc " << law.kc << ' ' << pa_per_l << '\n';
      break;
    case model::NormalLaw::Exponential: {
      os << in << "normal law     n2 exponential: P = pz exp(lambda u)\n"
         << in << "               pz " << law.pz << ' ' << pa << '\n';
      double l_lo = law.lambda, l_hi = law.lambda;
      if (law.pe > 0) {
        l_lo = kc_lo / law.pe;
        l_hi = kc_hi / law.pe;
        os << in << "               pe " << law.pe << ' ' << pa << ": lambda = Kc_auto/pe ";
        if (kc_lo > 0)
          os << "from " << range_text(l_lo, l_hi) << ' ' << per_l << " (Kc_auto = K/A_s from " << kc_auto
             << ")\n";
        else
          os << kc_auto << '\n';
      } else {
        os << in << "               lambda " << law.lambda << ' ' << per_l << '\n';
      }
      if (law.kc_max > 0) {
        os << in << "               KcMax " << law.kc_max << ' ' << pa_per_l;
        if (l_lo > 0) {
          // u_max = ln(KcMax / (pz lambda)) / lambda: du/dlambda = -(1 + ln(KcMax / (pz lambda))) / lambda^2
          // < 0 wherever KcMax >= pz lambda (the starter's check), so the ends of the lambda range bound it.
          auto knee = [&](double l) { return std::log(law.kc_max / (law.pz * l)) / l; };
          const double k1 = knee(l_lo), k2 = knee(l_hi);
          os << ": linear beyond the overclosure u_max = ln(KcMax/(pz lambda))/lambda = "
             << range_text(std::min(k1, k2), std::max(k1, k2)) << ' ' << len;
        }
        os << '\n';
      } else {
        os << in << "               KcMax none (the stiffness is not bounded)\n";
      }
      break;
    }
    case model::NormalLaw::Tabulated: {
      os << in << "normal law     n3 tabulated: P(gap) from ";
      if (law.curve >= 0 && static_cast<std::size_t>(law.curve) < m.functions.size()) {
        const auto& f = m.functions[static_cast<std::size_t>(law.curve)];
        os << "/FUNCT/" << f.id << " \"" << f.title << "\" (" << f.x.size() << " points, gap "
           << range_text(f.x.empty() ? 0 : f.x.front(), f.x.empty() ? 0 : f.x.back()) << ' ' << len << ")";
      } else {
        os << "?";
      }
      os << ", " << (law.cubic ? "monotone cubic" : "linear") << " interpolation\n";
      break;
    }
    case model::NormalLaw::Power:
      os << in << "normal law     n4 power: P = sum of kp_m u^m for u > 0\n";
      for (std::size_t j = 0; j < law.power_m.size() && j < law.power_k.size(); ++j) {
        const double mm = law.power_m[j];
        os << in << "               kp" << mm << ' ' << law.power_k[j];
        if (mm == 1)
          os << ' ' << pa << '/' << len;
        else if (mm == std::floor(mm) && mm < 100)
          os << ' ' << pa << '/' << len << '^' << static_cast<int>(mm);
        os << '\n';
      }
      break;
  }
  const char* dirs = law.bidirectional ? "two directions (the tangent plane)"
                                       : "one direction (the segment's first tangent)";
  switch (law.friction) {
    case model::FrictionLaw::Interface:
      os << in << "friction law   the interface's own (no s part)\n";
      return;
    case model::FrictionLaw::None: os << in << "friction law   none: frictionless (no s part)\n"; return;
    case model::FrictionLaw::Coulomb:
      os << in << "friction law   s" << (law.bidirectional ? 11 : 1) << " exact Coulomb, " << dirs << '\n';
      break;
    case model::FrictionLaw::Linear:
      os << in << "friction law   s" << (law.bidirectional ? 12 : 2)
         << " regularised Coulomb, linear: min(ct s, mu p), " << dirs << '\n';
      break;
    case model::FrictionLaw::Arctangent:
      os << in << "friction law   s" << (law.bidirectional ? 13 : 3)
         << " regularised Coulomb, arctangent: mu p (2/pi) atan(ct s), " << dirs << '\n';
      break;
    case model::FrictionLaw::ScaledLinear:
      os << in << "friction law   s" << (law.bidirectional ? 14 : 4)
         << " regularised Coulomb, scaled linear: p min(ct s, mu), " << dirs << '\n';
      break;
  }
  os << in << "               Mu " << law.mu << '\n';
  if (law.friction == model::FrictionLaw::Linear)
    os << in << "               CtLin " << law.ct << ' ' << pa << '.' << u.time_name << '/' << len << '\n';
  else if (law.friction == model::FrictionLaw::Arctangent || law.friction == model::FrictionLaw::ScaledLinear)
    os << in << "               CtLin " << law.ct << ' ' << u.time_name << '/' << len << '\n';
  // Only exact Coulomb has a sticking spring; the regularised laws stick by their slope (a dashpot).
  if (law.friction != model::FrictionLaw::Coulomb)
    os << in << "               kappa not used: the regularised laws have no sticking spring\n";
  else if (law.kappa > 0)
    os << in << "               kappa " << law.kappa << ' ' << pa_per_l << '\n';
  else
    os << in << "               kappa K/A_s (default): " << kc_auto << '\n';
}

// How many of each kind of object the model holds.
void write_counts(std::ostream& os, const model::Model& m) {
  heading(os, "COUNTS");
  auto count = [&](const char* what, std::size_t n) {
    os << "  " << std::left << std::setw(32) << what << n << '\n';
  };
  count("nodes", m.nodes.size());
  count("4-node shells", m.shells.size());
  count("3-node shells", m.shells3.size());
  count("8-node bricks", m.bricks.size());
  if (m.tetras.size() > 0) count("4-node tetrahedra", m.tetras.size());
  if (m.bricks20.size() > 0) count("20-node bricks", m.bricks20.size());
  count("parts", m.parts.size());
  count("properties", m.properties.size());
  count("materials", m.materials.size());
  count("subsets", m.subsets.size());
  count("node groups", m.node_groups.size());
  count("surfaces", m.surfaces.size());
  count("functions", m.functions.size());
  count("boundary conditions", m.bcs.size());
  count("imposed velocities", m.imposed_velocities.size());
  if (!m.imposed_final_geometries.empty())
    count("imposed final geometries", m.imposed_final_geometries.size());
  count("initial velocities", m.initial_velocities.size());
  count("concentrated loads", m.concentrated_loads.size());
  count("pressure loads", m.pressure_loads.size());
  count("gravity loads", m.gravities.size());
  count("rigid walls", m.rigid_walls.size());
  count("rigid bodies", m.rigid_bodies.size());
  count("sensors", m.sensors.size());
  count("time-history groups", m.time_histories.size());
  count("contact interfaces", m.interfaces.size());
  if (!m.tied_interfaces.empty()) count("tied interfaces (TYPE2)", m.tied_interfaces.size());
}

// The constants of the material's law, each law in its own words.
void write_law_constants(std::ostream& os, const model::Model& m, const model::Material& mat) {
  if (mat.law == model::MaterialLaw::JohnsonCook) {
    os << "    yield (a + b eps_p^n)(1 + c ln(rate/rate0)): a " << mat.a << "  b " << mat.b << "  n " << mat.n
       << "  c " << mat.c << "  rate0 " << mat.eps_dot_0 << '\n'
       << "    SIG_max0 " << mat.sig_max0 << "  EPS_p_max " << mat.eps_p_max << "  ICC " << mat.icc
       << "  flagVP " << mat.flag_vp;
    if (mat.iflag == 1)
      os << "  (Iflag 1: from SIG_Y " << mat.sig_y_input << ", UTS " << mat.uts << ", EUTS " << mat.e_uts
         << ")";
    os << '\n';
    if (mat.rho_cp > 0)
      os << "    rhoCp " << mat.rho_cp
         << " given: adiabatic heating is not implemented in radx; the temperature "
         << "term stays 1\n";
  }
  if (mat.law == model::MaterialLaw::PlasTab) {
    const auto& tab = mat.tab;
    os << "    yield curves sigma_y(eps_p) per strain rate: " << tab.function_id.size() << "  EPS_p_max "
       << mat.eps_p_max << "  Fsmooth " << tab.fsmooth << " ("
       << (tab.fsmooth == 2 ? "logarithmic" : "linear") << " in the rate)  Fcut " << mat.f_cut << '\n';
    for (std::size_t i = 0; i < tab.function_id.size(); ++i)
      os << "      curve " << i + 1 << ": function " << tab.function_id[i] << "  scale " << tab.scale[i]
         << "  strain rate " << tab.rate[i] << '\n';
    if (tab.function_id.size() > 1 && tab.rate.front() != 0)
      os << "      (below the first rate the first curve holds: it is repeated at rate 0)\n";
  }
  if (mat.law == model::MaterialLaw::PlasBrit) {
    const auto& b = mat.brit;
    os << "    yield min((a + b eps_p^n) R, SIG_max0 (R if ICC 1)), R = 1 + c ln(rate/rate0): a " << mat.a
       << "  b " << mat.b << "  n " << mat.n << "  SIG_max0 " << mat.sig_max0 << "  c " << mat.c << "  rate0 "
       << mat.eps_dot_0 << "  ICC " << mat.icc << "  Fsmooth " << mat.fsmooth << "  Fcut " << mat.f_cut
       << '\n'
       << "    crack (direction 1): opens at EPS_t1 " << b.eps_t1
       << ", damage (eps_1 - EPS_t1)/(EPS_m1 - EPS_t1)"
       << " with EPS_m1 " << b.eps_m1 << ", at most d_max1 " << b.d_max1 << "; element deleted above EPS_f1 "
       << b.eps_f1 << '\n';
  }
  if (mat.law == model::MaterialLaw::Ogden) {
    const auto& o = mat.ogden;
    os << "    W = sum mu_p/alpha_p (lb1^alpha_p + lb2^alpha_p + lb3^alpha_p - 3) + "
       << (o.iform == 2 ? "K (J - 1 - ln J)" : "K/2 (J - 1)^2") << " (Iform " << o.iform
       << "); G above is the initial shear modulus sum mu_p alpha_p / 2, E = 2 G (1 + nu)\n";
    for (std::size_t k = 0; k < o.mu.size(); ++k)
      os << "      term " << k + 1 << ": mu " << o.mu[k] << "  alpha " << o.alpha[k] << '\n';
    os << "    tension cut-off on the principal Biot stress " << o.sig_cut << '\n';
  }
  if (mat.law == model::MaterialLaw::FoamTab) {
    const auto& f = mat.foam;
    os << "    E0 " << mat.young << "  nu " << mat.poisson << "  Emax " << f.e_max << "  eps_max "
       << f.eps_max << "  Itens " << f.itens << "  Fcut " << mat.f_cut << "  Iflag " << f.iflag << "  Shape "
       << f.shape << "  Hys " << f.hys << '\n';
    for (std::size_t k = 0; k < f.load_function_id.size(); ++k)
      os << "      loading curve " << f.load_function_id[k] << "  rate " << f.load_rate[k] << "  scale "
         << f.load_scale[k] << '\n';
    for (std::size_t k = 0; k < f.unload_function_id.size(); ++k)
      os << "      unloading curve " << f.unload_function_id[k] << "  rate " << f.unload_rate[k] << "  scale "
         << f.unload_scale[k] << '\n';
    if (f.itens == 1)
      os << "      tension factor curve " << f.tens_function_id << "  scale " << f.tens_scale << '\n';
  }
  if (mat.law == model::MaterialLaw::Void)
    os << "    no force; mass rho V, E and nu for the contact stiffness only\n";
  if (mat.law == model::MaterialLaw::Rigid) {
    // The bodies its connected elements form (a body is listed under the first law-13 material it met).
    for (const auto& b : m.rigid_bodies)
      if (b.rigid_material == mat.id)
        os << "    rigid body of " << b.secondary.size() << " nodes on the added main node "
           << m.nodes.id[static_cast<std::size_t>(b.main_node)] << '\n';
  }
}

// The failure models on the material.
void write_failure_models(std::ostream& os, const model::Material& mat) {
  if (mat.fail_jc.on) {
    const auto& f = mat.fail_jc;
    os << "    /FAIL/JOHNSON: eps_f = (D1 + D2 exp(D3 sigma*))(1 + D4 ln(rate/rate0))(1 + D5 T*): D1 " << f.d1
       << "  D2 " << f.d2 << "  D3 " << f.d3 << "  D4 " << f.d4 << "  D5 " << f.d5 << "  rate0 "
       << f.eps_dot_0 << "  EPSF_MIN " << f.eps_f_min << "  Ifail_sh " << f.ifail_sh << "  Ifail_so "
       << f.ifail_so << '\n';
  }
  if (mat.fail_tab.on) {
    const auto& f = mat.fail_tab;
    os << "    /FAIL/TAB: dD = n D^(1-1/n) d_eps_p / eps_f, fails at Dcrit " << f.dcrit << "  n " << f.n
       << "  Ifail_sh " << f.ifail_sh << "  Ifail_so " << f.ifail_so << "  P_thickfail " << f.p_thickfail
       << '\n';
    for (std::size_t i = 0; i < f.function_id.size(); ++i)
      os << "      eps_f(triaxiality): function " << f.function_id[i] << " x " << f.scale[i] << " at rate "
         << f.rate[i] << '\n';
    if (f.size_function_id != 0)
      os << "      element size factor: " << f.size_scale << " x function " << f.size_function_id
         << " of L0 / " << f.el_ref << " (L0 the shell's length at t = 0)\n";
    if (f.temp_function_id != 0)
      os << "      temperature factor (constant function " << f.temp_function_id << "): " << f.temp_factor
         << '\n';
  }
  if (mat.fail_bq.on) {
    const auto& f = mat.fail_bq;
    os << "    /FAIL/BIQUAD: eps_f(triaxiality) through C1 " << f.c1 << " (-1/3)  C2 " << f.c2 << " (0)  C3 "
       << f.c3 << " (1/3)  C4 " << f.c4 << " (1/sqrt 3)  C5 " << f.c5 << " (2/3)  M_Flag " << f.m_flag
       << "  S_Flag " << f.s_flag << "  P_thickfail " << f.p_thickfail << '\n';
    if (f.s_flag == 3) os << "      necking instability (shells): Inst_start " << f.inst_start << '\n';
    if (f.size_function_id != 0)
      os << "      element size factor: function " << f.size_function_id << " of L0 / " << f.el_ref
         << " (L0 the shell's length at t = 0)\n";
  }
}

// Each material with its law and the figures the engine uses.
void write_materials(std::ostream& os, const model::Model& m) {
  os << std::setprecision(6);
  heading(os, "MATERIALS");
  for (const auto& mat : m.materials) {
    os << "  material " << mat.id << " \"" << mat.title << "\"  " << law_name(mat.law) << " (" << mat.keyword
       << ")\n"
       << "    density " << mat.rho << "  E " << mat.young << "  nu " << mat.poisson << "  G " << mat.shear
       << "  K " << mat.bulk << '\n';
    write_law_constants(os, m, mat);
    write_failure_models(os, mat);
  }
}

// A formulation flag's value and name; a value radx does not run says so (a property that elements use with
// it was refused, or substituted under --allow-substitutions, and then holds the value that runs).
std::string formulation_text(int value, const std::string& name, bool runs) {
  return std::to_string(value) + ": " + name +
         (runs ? "" : " (not run by radx: refused where elements use it)");
}

// Each property with its formulation.
void write_properties(std::ostream& os, const model::Model& m) {
  heading(os, "PROPERTIES");
  for (const auto& p : m.properties) {
    os << "  property " << p.id << " \"" << p.title << "\"  ";
    if (p.kind == model::PropertyKind::Shell) {
      const auto& s = p.shell;
      os << "/PROP/SHELL\n    Ishell "
         << formulation_text(s.ishell, model::ishell_name(s.ishell), model::runs_ishell(s.ishell))
         << "\n    Ish3n "
         << formulation_text(s.ish3n, model::ish3n_name(s.ish3n), model::runs_ish3n(s.ish3n))
         << "\n    thickness " << s.thickness << "  N " << s.n_ip << "  Hm " << s.hm << "  Hf " << s.hf
         << "  Hr " << s.hr << "  Ashear " << s.ashear << "  Ismstr " << s.ismstr << "  Ithick " << s.ithick
         << "  Iplas " << s.iplas << '\n';
    } else if (p.kind == model::PropertyKind::Beam) {
      const auto& b = p.beam;
      os << "/PROP/BEAM\n    area " << b.area << "  Iyy " << b.iyy << "  Izz " << b.izz << "  Ixx " << b.ixx
         << "  Dm " << b.dm << "  Df " << b.df << "  Ishear " << b.ishear
         << ": type-3 beam, section resultants (laws 1 and 2)\n";
    } else if (p.kind == model::PropertyKind::Truss) {
      os << "/PROP/TRUSS\n    area " << p.truss.area << ": 2-node truss, axial force only (laws 1 and 2)\n";
    } else if (p.kind == model::PropertyKind::Spring) {
      const int t = p.spring.type;
      os << (t == 4   ? "/PROP/SPRING"
             : t == 8 ? "/PROP/SPR_GENE"
                      : "/PROP/SPR_BEAM")
         << " (TYPE" << t << ")\n    mass " << p.spring.mass << "  inertia " << p.spring.inertia << '\n';
    } else {
      const auto& s = p.solid;
      os << "/PROP/SOLID\n    Isolid "
         << formulation_text(s.isolid, model::isolid_name(s.isolid), model::runs_isolid(s.isolid))
         << "\n    qa " << s.qa << "  qb " << s.qb << "  h " << s.h << "  Ismstr " << s.ismstr << "  Iframe "
         << s.iframe << '\n';
      if (m.tetras.size() > 0)
        os << "    Itetra4 " << s.itetra4
           << ": 4-node tetrahedron, one point, constant strain, no hourglass (for its tetrahedra)\n";
      if (m.bricks20.size() > 0) {
        const auto n =
            s.isolid == 17 ? std::array<int, 3>{2, 2, 2} : model::hex20_rule_of_inpts(s.inpts, s.isolid).n;
        os << "    Inpts " << s.inpts << ": " << n[0] << " x " << n[1] << " x " << n[2]
           << " Gauss points (xi, eta, zeta) for its 20-node bricks, serendipity, no hourglass\n";
      }
    }
  }
}

constexpr const char* kNotComputed = "not computed (the starter stopped on errors)";

// Each part with its property, material, element count and mass, and the total mass.
void write_parts(std::ostream& os, const model::Model& m, bool prepared) {
  const auto& u = m.units;
  heading(os, "PARTS AND MASSES");
  os << "  " << std::left << std::setw(10) << "part" << std::setw(34) << "title" << std::setw(10)
     << "property" << std::setw(10) << "material" << std::setw(12) << "elements"
     << "mass\n";
  for (const auto& p : m.parts) {
    os << "  " << std::left << std::setw(10) << p.id << std::setw(34) << p.title.substr(0, 32)
       << std::setw(10) << (p.property >= 0 ? m.properties[p.property].id : 0) << std::setw(10)
       << (p.material >= 0 ? m.materials[p.material].id : 0) << std::setw(12) << p.element_count;
    if (prepared)
      os << p.mass;
    else
      os << "-";
    os << '\n';
  }
  if (prepared)
    os << "  total mass " << m.total_mass << " " << u.mass_name << '\n';
  else
    os << "  total mass " << kNotComputed << '\n';
}

// The elements with the smallest steps, where a model's step is decided: a small or distorted element shows
// here before it costs hours.
void write_smallest_steps(std::ostream& os, const model::Model& m, const StarterListingInput& in) {
  heading(os, "SMALLEST ELEMENT TIME STEPS");
  if (in.errors > 0) {
    os << "  " << kNotComputed << '\n';
    return;
  }
  if (in.smallest_steps.empty()) {
    os << "  no shell, solid or spring element with a step\n";
    return;
  }
  os << "  L / c of each shell and solid at rest (solids with their bulk viscosity qb), each spring's step "
        "from its property, before the /DT scale factor (time "
     << m.units.time_name << ")\n";
  os << "  " << std::left << std::setw(6) << "rank" << std::setw(16) << "element" << std::setw(12) << "id"
     << std::setw(10) << "part"
     << "dt\n";
  for (std::size_t k = 0; k < in.smallest_steps.size(); ++k) {
    const auto& s = in.smallest_steps[k];
    os << "  " << std::left << std::setw(6) << k + 1 << std::setw(16) << model::element_type_name(s.type)
       << std::setw(12) << s.element_id << std::setw(10)
       << (s.part >= 0 ? m.parts[static_cast<std::size_t>(s.part)].id : 0) << s.dt << '\n';
  }
}

// The sensors and when they switch.
void write_sensors(std::ostream& os, const model::Model& m) {
  if (!m.sensors.empty()) {
    heading(os, "SENSORS");
    for (const auto& sn : m.sensors) {
      os << "  sensor " << sn.id << " \"" << sn.title << "\"  /SENSOR/TIME: on at Tdelay " << sn.t_delay
         << ", off at Tstop ";
      if (sn.t_stop >= model::kNever)
        os << "never\n";
      else
        os << sn.t_stop << '\n';
    }
  }
}

// The contact interfaces: each one's echo, surfaces and law.
void write_interfaces(std::ostream& os, const model::Model& m, const StarterListingInput& in) {
  heading(os, "CONTACT INTERFACES");
  auto range = [&in, &os](double lo, double hi) {
    if (in.errors > 0) return std::string(kNotComputed);
    std::ostringstream r;
    r.copyfmt(os);  // the figures as the rest of the listing prints them
    r << lo << " to " << hi;
    return r.str();
  };
  for (std::size_t k = 0; k < m.interfaces.size(); ++k) {
    const auto& c = m.interfaces[k];
    os << "  interface " << c.id << " \"" << c.title << "\"  "
       << (c.lagdt ? "/INTER/LAGDT/TYPE7" : "/INTER/TYPE7") << '\n';
    if (k < in.interface_echo.size())
      for (const auto& line : in.interface_echo[k]) os << line << '\n';
    os << "    values in use:\n"
       << "      secondary nodes        " << c.secondary_nodes.size() << '\n'
       << "      main segments          "
       << (c.main_surface >= 0 ? m.surfaces[c.main_surface].segments.size() : 0) << '\n'
       << "      Gapmin                 " << c.gapmin
       << (c.gapmin_automatic ? "  (automatic: min(t, l/10, lmin/2))" : "") << '\n'
       << "      gap g                  " << range(c.gap_lo, c.gap_hi) << '\n'
       << "      stiffness K            " << range(c.stiff_lo, c.stiff_hi) << '\n'
       << "      Stfac                  " << c.stfac << '\n'
       << "      VISs                   " << c.vis_s << '\n'
       << "      VISF                   " << c.vis_f << '\n'
       << "      Bumult                 " << c.bumult << '\n'
       << "      Tstart, Tstop          " << c.t_start << ", "
       << (c.t_stop >= model::kNever ? std::string("never") : std::to_string(c.t_stop)) << '\n';
    if (!c.contact_law.empty()) {
      os << "      contact law /CTCLAW/" << c.contact_law_id << "  " << c.contact_law << '\n';
      write_contact_law(os, m, c);
    }
    os << "      initial penetrations   " << c.initial_penetrations;
    if (c.initial_penetrations > 0)
      os << " (largest " << c.max_initial_penetration << " at node " << c.max_penetration_node << "; Inacti "
         << c.inacti << ": " << inacti_text(c.inacti) << ")";
    os << '\n';
  }
}

// The tied interfaces and their secondary nodes.
void write_tied_interfaces(std::ostream& os, const model::Model& m) {
  if (!m.tied_interfaces.empty()) {
    heading(os, "TIED INTERFACES");
    for (const auto& t : m.tied_interfaces) {
      // Spotflag 1 is the rigid tie only with rotational degrees of freedom
      // (solver/conditions/tied_type2.hpp).
      const bool rotations =
          m.shells.size() + m.shells3.size() + m.springs.size() + m.rigid_bodies.size() > 0;
      os << "  interface " << t.id << " \"" << t.title << "\"  /INTER/TYPE2  Spotflag " << t.spotflag
         << (t.spotflag != 1 ? " (kinematic, offset carried along the segment normal)\n"
             : rotations ? " (rigid: the node moves with the segment's least-squares rotation, its mass and "
                           "inertia as added point masses on the segment's nodes)\n"
                         : " (run as Spotflag 0, as OpenRadioss does: the model has no rotational degrees of "
                           "freedom)\n")
         << "      search distance        " << t.search_distance
         << (t.dsearch > 0 ? "  (Dsearch)" : "  (automatic: r.m.s. main segment edge)") << '\n'
         << "      tied secondary nodes   " << t.tie_node.size() << '\n'
         << "      largest normal offset  ";
      double dmax = 0;
      for (const double d : t.tie_offset) dmax = std::max(dmax, std::abs(d));
      os << dmax << '\n' << "      nodes not found        " << t.not_found.size();
      if (!t.not_found.empty()) {
        os << " (" << (t.ignore == 0 ? "error, Ignore = 0" : "left untied, Ignore >= 1") << "):";
        for (const auto id : t.not_found) os << ' ' << id;
      }
      os << '\n';
    }
  }
}

// The control cards accepted and ignored, and the substitutions.
void write_notes(std::ostream& os, const model::Model& m) {
  if (!m.ignored_keywords.empty()) {
    heading(os, "CONTROL CARDS ACCEPTED AND IGNORED");
    for (const auto& k : m.ignored_keywords) os << "  " << k << '\n';
  }

  if (!m.substitutions.empty()) {
    heading(os, "SUBSTITUTIONS (--allow-substitutions: what runs instead of what the deck asks)");
    for (const auto& k : m.substitutions) os << "  " << k << '\n';
  }
}

// The diagnostics, their count, and what was written.
void write_diagnostics(std::ostream& os, const StarterListingInput& in) {
  heading(os, "DIAGNOSTICS");
  for (const auto& d : in.diagnostics) os << "  " << d << '\n';
  os << "  " << in.errors << " error(s), " << in.warnings << " warning(s)\n";
  os << '\n'
     << (in.errors == 0 ? "  model file written: " + in.model_file
                        : std::string("  no model file written: fix the errors above"))
     << '\n'
     << "  starter time " << std::fixed << std::setprecision(3) << in.seconds << " s\n";
}

}  // namespace

void write_starter_listing(std::ostream& os, const StarterListingInput& in) {
  const model::Model& m = *in.model;
  const auto& u = m.units;
  os << "radx starter " << in.program_version << "\n"
     << "deck          " << in.deck_path << "\n"
     << "title         " << m.title << "\n"
     << "run name      " << m.run_name << "\n"
     << "deck version  " << m.deck_version << "\n"
     << "work units    mass " << u.mass_name << ", length " << u.length_name << ", time " << u.time_name
     << "\n";

  write_counts(os, m);
  write_materials(os, m);
  write_properties(os, m);
  write_parts(os, m, in.errors == 0);
  write_smallest_steps(os, m, in);
  write_sensors(os, m);
  write_interfaces(os, m, in);
  write_tied_interfaces(os, m);
  write_notes(os, m);
  write_diagnostics(os, in);
}

}  // namespace radx::io
