// /PROP/SPRING (TYPE4), /PROP/SPR_GENE (TYPE8), /PROP/SPR_BEAM (TYPE13) and /SPRING: the properties'
// defaults as OpenRadioss's starter resolves them (hm_read_prop04.F, hm_read_prop08.F, hm_read_prop13.F:
// each of the six laws of TYPE8 and TYPE13 as TYPE4's one), the elements, and the checks that refuse what
// would not run.
//   A, D, F, Ascale, Hscale: 0 -> 1. Without fct_ID1 the force is linear, K dx: A = 1, B = E = 0 whatever
//   the card says (a non-default A then warns, as Radioss's message 663 does). delta_min, delta_max:
//   0 -> no failure. Ileng 1: dx, M, K, C per unit initial length (handled by the engine).
// The spring's mass is M (M L0 with Ileng 1), half on each node; the inertia of TYPE8 and TYPE13 too
// (OpenRadioss starter rmass.F). TYPE13's Ileng 1 is refused by its declaration (RX510).
#include <algorithm>
#include <cmath>
#include <string>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx::detail {

using model::kNone;

// One law: the fields of /PROP/SPRING (suffix "") or of one degree of freedom of /PROP/SPR_GENE (suffix
// "1".."6": K1, fct_ID11, delta_min1, ...), which /PROP/SPR_BEAM shares. `type8` (TYPE8 and TYPE13): a
// stiffness of 0 is a free direction, not an error.
void ModelBuilder::read_spring_law(const KeywordRecord& r, model::SpringLaw& s, const std::string& sfx,
                                   bool type8) {
  auto f = [&](const char* base) { return std::string(base) + sfx; };
  s.stiffness = r.get_real(f("K"));
  s.damping = r.get_real(f("C"));
  s.hardening = static_cast<int>(r.get_int(f("H")));
  const bool curve = r.get_int(f("fct_ID1")) != 0;
  const double a = r.get_real(f("A"));
  s.a = curve ? (a == 0 ? 1.0 : a) : 1.0;
  s.b = curve ? r.get_real(f("B")) : 0.0;
  s.e = curve ? r.get_real(f("E")) : 0.0;
  if (!curve && a != 0 && a != 1)
    warning_at(
        r, f("A"), Diag::InconsistentValues,
        f("A") + " = " + number_text(a) + " amplifies the force of " + f("fct_ID1") +
            ", which the property does not give: the linear force K dx is not amplified (A is taken as "
            "1, as Radioss does)");
  auto one_if_zero = [&](const std::string& field) {
    const double v = r.find(field) ? r.get_real(field) : 0.0;
    return v == 0 ? 1.0 : v;
  };
  s.d = one_if_zero(f("D"));
  s.fscale = one_if_zero(f("F"));
  s.ascale = one_if_zero(f("Ascale"));
  s.hscale = one_if_zero(f("Hscale"));
  const double dmin = r.get_real(f("delta_min")), dmax = r.get_real(f("delta_max"));
  s.delta_min = dmin == 0 ? -1e30 : dmin;
  s.delta_max = dmax == 0 ? 1e30 : dmax;

  // H 4, 5 and 6 bound or shape the force by fct_ID1 and fct_ID3, H 8 by fct_ID1: Radioss's starter refuses
  // them without their curves (errors 231 and 1057).
  const bool needs_unload = s.hardening == 4 || s.hardening == 5 || s.hardening == 6;
  if ((needs_unload || s.hardening == 8) && !curve)
    error_at(r, f("fct_ID1"), Diag::RequiredValueMissing,
             f("H") + " = " + std::to_string(s.hardening) + " needs the force curve " + f("fct_ID1") +
                 ", which is 0; give a /FUNCT (H = 0 without a curve is the linear spring K dx)");
  if (needs_unload && r.get_int(f("fct_ID3")) == 0)
    error_at(r, f("fct_ID3"), Diag::RequiredValueMissing,
             f("H") + " = " + std::to_string(s.hardening) + " needs the curve " + f("fct_ID3") +
                 (s.hardening == 4   ? " (the lower yield force of the elongation)"
                  : s.hardening == 5 ? " (the residual elongation of the largest elongation)"
                                     : " (the unloading curve, whose slope at the current force unloads)") +
                 ", which is 0; give a /FUNCT");
  // Without fct_ID1 Radioss runs the linear force K dx whatever H says (redef3.F90 tests the curve first).
  if (!curve && s.hardening != 0 && !needs_unload && s.hardening != 8) {
    warning_at(r, f("H"), Diag::InconsistentValues,
               f("H") + " = " + std::to_string(s.hardening) + " acts on the curve " + f("fct_ID1") +
                   ", which the property does not give: the spring is linear, K dx (as Radioss runs it)");
    s.hardening = 0;
  }
  // H 7 needs both curves (Radioss: error 1058 without fct_ID1; without fct_ID3 it warns and runs H 2).
  if (s.hardening == 7 && curve && r.get_int(f("fct_ID3")) == 0) {
    warning_at(r, f("fct_ID3"), Diag::DefaultApplied,
               f("H") + " = 7 without the unloading curve " + f("fct_ID3") +
                   " is H = 2 (uncoupled hardening), as Radioss reads it");
    s.hardening = 2;
  }
  if (s.stiffness < 0)
    error_at(
        r, f("K"), Diag::ValueOutOfRange,
        "stiffness " + f("K") + " = " + number_text(s.stiffness) +
            " is negative; K must be > 0 (the linear stiffness, or with fct_ID1 the stiffness of the time "
            "step)");
  else if (!type8 && s.stiffness == 0 && !curve && s.damping <= 0 && r.get_int(f("fct_ID4")) == 0)
    // OpenRadioss runs such a spring (its QA deck IMPOSED/IMPDISP_FGEO uses one to carry a node's mass): it
    // only adds its mass to its nodes.
    warning_at(
        r, f("K"), Diag::ValueOutOfRange,
        "stiffness K is 0 and the spring has no damping nor force curve: it carries no force, only its "
        "mass, as in Radioss; give K > 0 or a force curve fct_ID1 if it should resist");
  else if (s.stiffness == 0 && curve && s.hardening != 0)
    // H 1 to 8 unload or bound the force with the slope K: with K = 0 there is no such slope. (H = 0 takes
    // the step stiffness from the curve: resolve_spring_functions.)
    error_at(r, f("K"), Diag::ValueOutOfRange,
             "stiffness " + f("K") + " is 0 with " + f("H") + " = " + std::to_string(s.hardening) +
                 ": that law unloads or yields with the slope K; give K > 0 (K = 0 with a force curve is "
                 "accepted for H = 0, the nonlinear elastic spring)");
  if (s.damping < 0)
    error_at(r, f("C"), Diag::ValueOutOfRange,
             "damping " + f("C") + " = " + number_text(s.damping) + " is negative; C must be >= 0");
  if (s.delta_min > 0)
    error_at(r, f("delta_min"), Diag::ValueOutOfRange,
             f("delta_min") + " = " + number_text(dmin) +
                 " is positive; the failure elongation in compression must be < 0 (0 = none)");
  if (s.delta_max < 0)
    error_at(r, f("delta_max"), Diag::ValueOutOfRange,
             f("delta_max") + " = " + number_text(dmax) +
                 " is negative; the failure elongation in tension must be > 0 (0 = none)");
}

void ModelBuilder::read_spring_property(const KeywordRecord& r, model::Property& p) {
  p.kind = model::PropertyKind::Spring;
  auto& s = p.spring;
  const bool type13 = r.decl->path == "/PROP/SPR_BEAM";
  const bool type8 = r.decl->path == "/PROP/SPR_GENE" || type13;  // six laws
  s.type = type13 ? 13 : type8 ? 8 : 4;
  s.mass = r.get_real("M");
  s.sensor = r.get_int("sens_ID");
  if (!type8) {
    s.ileng = static_cast<int>(r.get_int("Ileng"));
    read_spring_law(r, s.x, "", false);
  } else {
    s.inertia = r.get_real("Inertia");
    s.ifail = static_cast<int>(r.get_int("Ifail"));
    for (int d = 0; d < 6; ++d) read_spring_law(r, s.law(d), std::to_string(d + 1), true);
    // TYPE13's shear laws Y and Z turn the nodes too (their end moments L/2 F): they need the inertia.
    bool rotation_moves = false;
    for (int d = type13 ? 1 : 3; d < 6; ++d)
      rotation_moves = rotation_moves || s.law(d).stiffness > 0 || s.law(d).damping > 0;
    if (s.inertia < 0 || (rotation_moves && !(s.inertia > 1e-15)))
      error_at(r, "Inertia", Diag::ValueOutOfRange,
               "spring inertia = " + number_text(s.inertia) + " is not positive and " +
                   (type13 ? "a shear or rotation (K2..K6, C2..C6)" : "a rotation (K4..K6, C4..C6)") +
                   " has stiffness or damping; give Inertia > 0 (half goes to each node; it sets the "
                   "rotational time step sqrt(I/K))");
  }
  // A spring without mass has no step and moves its nodes without inertia (Radioss error 229 below 1e-15).
  if (!(s.mass > 1e-15))
    error_at(r, "M", Diag::ValueOutOfRange,
             "spring mass M = " + number_text(s.mass) +
                 " is not positive; a spring needs a mass M > 0 (half goes to "
                 "each node; it sets the spring's time step sqrt(M/K))");
}

// K = 0 with a force curve and H = 0: the curve is the law, and K, which only sets the time step there, is
// taken as the stiffness of the curve's steepest segment, A max |df/dx| / Ascale (the force is A f(x /
// Ascale)), so that the step sqrt(M / K) resolves the stiffest part of the curve. OpenRadioss runs such a
// spring with the step of that stiffness (a deck with a straight curve of slope k steps as one with K = k).
void ModelBuilder::step_stiffness_from_curve(const KeywordRecord& r, model::SpringLaw& s,
                                             const std::string& sfx) {
  const auto& fn = m_.functions[static_cast<std::size_t>(s.f_load)];
  double slope = 0;
  for (std::size_t k = 1; k < fn.x.size(); ++k)
    if (fn.x[k] > fn.x[k - 1])
      slope = std::max(slope, std::abs((fn.y[k] - fn.y[k - 1]) / (fn.x[k] - fn.x[k - 1])));
  const double k = s.a * slope / s.ascale;
  if (!(k > 0)) {
    error_at(r, "K" + sfx, Diag::ValueOutOfRange,
             "stiffness K" + sfx + " is 0 and the force curve fct_ID1" + sfx + " = " + std::to_string(fn.id) +
                 " is flat: the spring would carry no force and has no time step; give K > 0 or a curve "
                 "with a slope");
    return;
  }
  s.stiffness = k;
  note_at(r, "K" + sfx, Diag::DefaultApplied,
          "K" + sfx + " = 0 with the force curve fct_ID1" + sfx + " = " + std::to_string(fn.id) +
              ": the curve is the law; the time step takes the curve's largest slope A df/dx = " +
              number_text(k) + " as the stiffness, as Radioss steps it");
}

void ModelBuilder::resolve_spring_functions() {
  for (const auto& r : deck_.records) {
    const bool type8 = r.decl->path == "/PROP/SPR_GENE" || r.decl->path == "/PROP/SPR_BEAM";  // six laws
    if (r.decl->path != "/PROP/SPRING" && !type8) continue;
    const auto it = prop_ids_.find(r.id);
    if (it == prop_ids_.end()) continue;
    auto& p = m_.properties[static_cast<std::size_t>(it->second)];
    if (p.kind != model::PropertyKind::Spring || p.title != r.title) continue;  // a duplicate id
    for (int d = 0; d < (type8 ? 6 : 1); ++d) {
      auto& s = p.spring.law(d);
      const std::string sfx = type8 ? std::to_string(d + 1) : "";
      s.f_load = ref(funct_ids_, r, "fct_ID1" + sfx, "force curve", "/FUNCT", true);
      s.f_damp = ref(funct_ids_, r, "fct_ID2" + sfx, "amplification curve", "/FUNCT", true);
      s.f_unload = ref(funct_ids_, r, "fct_ID3" + sfx, "unloading curve", "/FUNCT", true);
      if (r.find("fct_ID4" + sfx))
        s.f_damp4 = ref(funct_ids_, r, "fct_ID4" + sfx, "velocity force curve", "/FUNCT", true);
      if (s.stiffness == 0 && s.hardening == 0 && s.f_load != kNone) step_stiffness_from_curve(r, s, sfx);
    }
  }
}

// TYPE8's frame: a /SKEW/FIX, or a /SKEW/MOV whose axes the engine follows every cycle (OpenRadioss r2def3.F
// reads the skew's current axes). TYPE13's skew only orients the spring's own frame at the start
// (OpenRadioss r4buf3.F, with the skew's initial axes).
void ModelBuilder::resolve_spring_skews() {
  for (const auto& rec : deck_.records) {
    if (rec.decl->path != "/PROP/SPR_GENE" && rec.decl->path != "/PROP/SPR_BEAM") continue;
    const auto* r = &rec;
    const auto it = prop_ids_.find(r->id);
    if (it == prop_ids_.end()) continue;
    auto& p = m_.properties[static_cast<std::size_t>(it->second)];
    if (p.kind != model::PropertyKind::Spring || p.title != r->title) continue;
    p.spring.skew = ref(skew_ids_, *r, "skew_ID", "skew", "/SKEW", true);
    // A skew whose frame was refused (degenerate nodes) is registered but not built: reported already.
    if (p.spring.skew != kNone && static_cast<std::size_t>(p.spring.skew) >= m_.skews.size()) {
      p.spring.skew = kNone;
      continue;
    }
  }
}

void ModelBuilder::build_springs() {
  auto& b = m_.springs;
  std::vector<SourcePos> pos;
  const char* names[3] = {"n1", "n2", "n3"};
  for (const auto* r : deck_.of("/SPRING")) {
    const auto& t = r->records;
    std::int32_t part = kNone;
    const auto pit = part_ids_.find(r->id);
    if (pit == part_ids_.end()) {
      diags_.error(Diag::MissingReference, at(r->pos, 1), about(*r),
                   "/SPRING/" + std::to_string(r->id) + ": part " + std::to_string(r->id) +
                       " does not exist (no /PART/" + std::to_string(r->id) +
                       "); the keyword line names the part");
    } else {
      part = pit->second;
      const auto& pp = m_.parts[static_cast<std::size_t>(part)];
      if (pp.property != kNone &&
          m_.properties[static_cast<std::size_t>(pp.property)].kind != model::PropertyKind::Spring) {
        diags_.error(Diag::PartWrongKind, at(r->pos, 1), about(*r),
                     "part " + std::to_string(r->id) + " has /PROP/" +
                         std::to_string(m_.properties[static_cast<std::size_t>(pp.property)].id) +
                         ", not a spring property; /SPRING elements need a /PROP/SPRING (TYPE4) or "
                         "/PROP/SPR_GENE (TYPE8) or /PROP/SPR_BEAM (TYPE13) part");
      }
    }
    const int cid = t.column("spring_ID");
    if (cid < 0) continue;
    int cn[3];
    for (int k = 0; k < 3; ++k) cn[k] = t.column(names[k]);
    for (std::size_t e = 0; e < t.size(); ++e) {
      const std::int64_t eid = t.ints[static_cast<std::size_t>(cid)][e];
      const About ab{"/SPRING", eid};
      b.id.push_back(eid);
      b.part.push_back(part);
      b.thickness.push_back(0.0);
      b.phi.push_back(0.0);
      pos.push_back(t.pos[e]);
      for (int k = 0; k < 3; ++k) {
        const std::int64_t user = cn[k] >= 0 ? t.ints[static_cast<std::size_t>(cn[k])][e] : 0;
        std::int32_t n = kNone;
        if (user == 0) {
          if (k < 2)
            diags_.error(Diag::ElementNodeMissing, at(t.pos[e], 11 + 10 * k), ab,
                         std::string(names[k]) + " is blank or 0: spring " + std::to_string(eid) +
                             " needs 2 nodes (n3, the orientation node, is optional)");
        } else {
          n = m_.nodes.index.find(user);
          if (n < 0) {
            diags_.error(Diag::ElementNodeMissing, at(t.pos[e], 11 + 10 * k), ab,
                         "spring " + std::to_string(eid) + " uses node " + std::to_string(user) + " (" +
                             names[k] + "), which does not exist");
            n = kNone;
          } else {
            node_used_[static_cast<std::size_t>(n)] = 1;
          }
        }
        b.conn.push_back(n);
      }
      if (part != kNone) ++m_.parts[static_cast<std::size_t>(part)].element_count;
      const auto n1 = b.conn[b.conn.size() - 3], n2 = b.conn[b.conn.size() - 2];
      if (n1 != kNone && n1 == n2)
        diags_.error(Diag::RepeatedNodeInElement, at(t.pos[e], 21), ab,
                     "spring " + std::to_string(eid) + " joins node " +
                         std::to_string(m_.nodes.id[static_cast<std::size_t>(n1)]) +
                         " to itself; a TYPE4 spring needs two distinct nodes n1 and n2");
    }
  }
  std::int64_t dup = 0;
  if (!b.index.build(b.id, dup)) {
    std::unordered_map<std::int64_t, std::size_t> first;
    for (std::size_t i = 0; i < b.id.size(); ++i) {
      const auto [it, ok] = first.emplace(b.id[i], i);
      if (!ok) {
        const SourcePos p = pos[it->second];
        diags_.error(Diag::DuplicateId, at(pos[i], 1), About{"/SPRING", b.id[i]},
                     "spring id " + std::to_string(b.id[i]) + " is already used at " + deck_.files[p.file] +
                         ":" + std::to_string(p.line) + "; spring ids must be unique");
      }
    }
  }
}

}  // namespace radx::detail
