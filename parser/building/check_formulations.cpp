// Formulation honesty: every element formulation flag a used property asks for must be one radx implements.
// Otherwise the deck is refused by name (RX510), or, with --allow-substitutions, runs the nearest formulation
// radx implements and lists the substitution (RX511, the listing and NAME_summary.json). A property used by
// no element changes nothing and is not checked; a flag that only matters for another element shape (Ish3n
// on quadrangles, Icpre on Isolid 1 and 2) is not checked either.
//
// What radx implements (docs/theory/elements.md):
//   4-node shells:  Ishell 1 (Belytschko-Tsay, viscous + elastic hourglass), 12 (QBAT: four Gauss points,
//                   assumed transverse shear) and 24 (QEPH: one point with physical hourglass stabilisation),
//                   Ismstr 2 (large strain, small strain only after /DT/SHELL/CST), 4 and -1 (large strain,
//                   never switched) and 1 (small strain from the start, Ishell 1 only), Ithick 1/2, Iplas
//                   1/2; every other Ishell is refused by name
//   3-node shells:  Ish3n 2 (C0) and 1 (C0 without the in-plane large-rotation terms), Ismstr 2 and 1
//   8-node bricks:  Isolid 1 (one point, Flanagan-Belytschko viscous hourglass) and 2 (plain h vectors),
//                   each with Iframe 1 (Jaumann rate) or 2 (co-rotational element frame); Isolid 24 (HEPH:
//                   one point, physical elasto-plastic hourglass, always co-rotational) with Icpre 0 or 1
//                   (3 = off, as 0; Icpre 2 and Ihkt 2+ refused); Ismstr 4 (large strain) and 2 (large
//                   strain, small strain after a /DT/BRICK/CST switch: without /DT/BRICK/CST the same as 4);
//                   no distortion control (Icontrol 1)
//                   fully integrated (2 x 2 x 2 points, hex8_full.cpp): Isolid 14 (HA8, co-rotational, Icpre
//                   0 to 3, Inpts 222 only), 17 (H8C, Icpre default 1), 18 (H8D, run as 17 with Icpre chosen
//                   by the law) and 12 (S8), each with Iframe 1 or 2 (14 and 18 impose 2)
//   springs:        /PROP/SPRING (TYPE4) with H 0 (elastic: linear K, or the curve fct_ID1), 1, 2, 4, 5, 6
//                   (elasto-plastic), 7 (elastic hysteresis) and 8 (elastic of the total length), with the
//                   damping C, the amplification A, B, D, E fct_ID2 and the force fct_ID4 (spring_law.hpp);
//                   /PROP/SPR_GENE (TYPE8) and /PROP/SPR_BEAM (TYPE13) the same for each of their six
//                   H1..H6 but H 8, refused by name
//   trusses:        /PROP/TRUSS (TYPE2) with laws 1 and 2 (Gap 0), as OpenRadioss's truss runs them: law 2
//                   without its strain-rate term, no /FAIL model; other laws are refused by name
//   beams:          /PROP/BEAM (TYPE3) with laws 1 and 2 (OpenRadioss's type-3 beam runs 1, 2 and 44), Ismstr
//                   0, 2, 4, the released rotations and Ishear; law 2 with flagVP 2 or 3
//   4-node tetras:  Itetra4 1000 (constant strain, one point; OpenRadioss hm_read_prop14.F also reads 0 as
//                   /DEF_SOLID's value, 2 and unexpected values as 1000), Ismstr 2 or 4, Iframe 1; Itetra4 1
//                   and 3 (nodal pressure) and 10 (converted to a 10-node tetra) are refused
#include <algorithm>
#include <array>
#include <string>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"
#include "solver/model/formulations.hpp"

namespace radx::detail {

namespace {

std::string ismstr_name(int v) {
  switch (v) {
    case 1: return "small strain from the start";
    case 2: return "large strain, small strain below the minimum step";
    case 3: return "small strain on the element";
    case 4: return "large strain, never switching";
    case 10:
    case 11:
    case 12: return "total Lagrangian";
    default: return v < 0 ? "automatic choice" : "strain formulation " + std::to_string(v);
  }
}

std::string itetra4_name(int v) {
  switch (v) {
    case 1: return "nodal pressure averaging";
    case 3: return "nodal pressure, smoothed";
    case 10: return "converted to a 10-node tetrahedron";
    default: return "constant strain, one point";
  }
}

// /PROP/SPRING's hardening flag H (OpenRadioss hm_read_prop04.F's listing).
std::string spring_h_name(int v) {
  switch (v) {
    case 0: return "elastic, linear or nonlinear by fct_ID1";
    case 1: return "elasto-plastic, isotropic hardening";
    case 2: return "elasto-plastic, uncoupled hardening";
    case 3: return "elasto-plastic, tension and compression coupled over the six degrees of freedom";
    case 4: return "elasto-plastic, kinematic hardening";
    case 5: return "nonlinear elastic-plastic with uncoupled loading and unloading";
    case 6: return "elasto-plastic with hardening of the yield curve";
    case 7: return "elastic hysteresis";
    case 8: return "elastic, force of the total length";
    default: return "hardening flag " + std::to_string(v);
  }
}

// The hardening flags spring_law.hpp runs: all of redef3.F90's but H 3 (tension and compression coupled over
// the six degrees of freedom); H 8 on TYPE4 only: Radioss evaluates a TYPE8 law's curve at the spring's
// initial offset along the axis (r2def3.F passes it), a constant force radx does not reproduce.
bool spring_h_runs(int h, bool type8) {
  return h == 0 || h == 1 || h == 2 || h == 4 || h == 5 || h == 6 || h == 7 || (h == 8 && !type8);
}

// The element shapes that use a property, as bits.
constexpr std::uint8_t kQuad = 1, kTri = 2, kBrick = 4, kTetra = 8, kSpring = 16, kBrick20 = 32;

// Which element shapes use each property.
std::vector<std::uint8_t> property_uses(const model::Model& m) {
  std::vector<std::uint8_t> use(m.properties.size(), 0);
  auto mark = [&](const model::ElementBlock& b, std::uint8_t bit) {
    std::vector<std::uint8_t> part_seen(m.parts.size(), 0);
    for (const auto p : b.part)
      if (p >= 0 && static_cast<std::size_t>(p) < part_seen.size())
        part_seen[static_cast<std::size_t>(p)] = 1;
    for (std::size_t p = 0; p < m.parts.size(); ++p)
      if (part_seen[p] && m.parts[p].property >= 0) use[static_cast<std::size_t>(m.parts[p].property)] |= bit;
  };
  mark(m.shells, kQuad);
  mark(m.shells3, kTri);
  mark(m.bricks, kBrick);
  mark(m.tetras, kTetra);
  mark(m.springs, kSpring);
  mark(m.bricks20, kBrick20);
  return use;
}

// The formulation flags of one used property's record.
struct PropertyFlags {
  ModelBuilder& b;
  const KeywordRecord& rec;
  std::string_view path;    // /PROP/SHELL ...
  std::string def_keyword;  // /DEF_SHELL or /DEF_SOLID: where a flag the property leaves 0 may come from
  std::uint8_t used;        // the shapes that use the property (kQuad ...)
};

// One flag: accepted when `ok`; otherwise refused, or substituted by `nearest`.
void check_flag(const PropertyFlags& p, std::string_view field, int& value, bool ok, int nearest,
                const std::string& what_value, const std::string& what_nearest, std::string_view shape) {
  if (ok) return;
  const auto& rec = p.rec;
  // Where the value comes from when the property leaves the field 0.
  std::string source;
  if (rec.get_int(field) == 0) {
    const auto defs = p.b.deck_.of(p.def_keyword);
    const bool from_def = !defs.empty() && defs.front()->find(field) && defs.front()->get_int(field) != 0;
    source = from_def ? " (the property leaves it 0: from " + p.def_keyword + ")"
                      : " (the property leaves it 0: the formulation's default)";
  }
  const std::string asked =
      std::string(field) + " = " + std::to_string(value) + " (" + what_value + ")" + source;
  if (p.b.deck_.allow_substitutions) {
    const std::string text = asked + " runs as " + std::string(field) + " = " + std::to_string(nearest) +
                             " (" + what_nearest + ") for its " + std::string(shape);
    p.b.warning_at(rec, field, Diag::Substitution, text);
    p.b.m_.substitutions.push_back(std::string(p.path) + " " + std::to_string(rec.id) + " \"" + rec.title +
                                   "\": " + text);
    value = nearest;
  } else {
    p.b.error_at(rec, field, Diag::PhysicsNotImplemented,
                 asked + " is used by " + std::string(shape) +
                     " and radx does not implement it; radx implements " + std::string(field) + " = " +
                     std::to_string(nearest) + " (" + what_nearest +
                     "); set it, or run with --allow-substitutions to run that instead");
  }
}

// /PROP/SPRING's H, /PROP/SPR_GENE's and /PROP/SPR_BEAM's H1 ... H6.
void check_spring_flags(const PropertyFlags& p, model::Property& prop) {
  if (p.path == "/PROP/SPRING") {
    auto& s = prop.spring.x;
    check_flag(p, "H", s.hardening, spring_h_runs(s.hardening, false), 0, spring_h_name(s.hardening),
               spring_h_name(0), "springs (TYPE4)");
    return;
  }
  static constexpr std::array<std::string_view, 6> h = {"H1", "H2", "H3", "H4", "H5", "H6"};
  for (int d = 0; d < 6; ++d) {
    auto& s = prop.spring.law(d);
    check_flag(p, h[static_cast<std::size_t>(d)], s.hardening, spring_h_runs(s.hardening, true), 0,
               spring_h_name(s.hardening), spring_h_name(0),
               prop.spring.type == 8 ? "springs (TYPE8)" : "springs (TYPE13)");
  }
}

// /PROP/SHELL: Ishell where quadrangles use it, Ish3n where triangles do, and Ismstr.
void check_shell_flags(const PropertyFlags& p, model::ShellProperty& s) {
  if (p.used & kQuad) {
    check_flag(p, "Ishell", s.ishell, model::runs_ishell(s.ishell), 1, model::ishell_name(s.ishell),
               model::ishell_name(1), "4-node shells");
    // A substituted formulation runs with its own defaults: Ishell 3's hourglass coefficients are not
    // 1's.
    ModelBuilder::shell_hourglass_defaults(p.rec, s);
  }
  if (p.used & kTri)
    check_flag(p, "Ish3n", s.ish3n, model::runs_ish3n(s.ish3n), 2, model::ish3n_name(s.ish3n),
               model::ish3n_name(2), "3-node shells");
  // 4 (and -1, which OpenRadioss's shells run as 4: hm_read_prop01.F keeps it, no shell path tests it) is
  // large strain never switched: radx's 2 without the /DT/SHELL/CST switch (the step rule switches 2 only).
  check_flag(p, "Ismstr", s.ismstr, s.ismstr == 1 || s.ismstr == 2 || s.ismstr == 4 || s.ismstr == -1, 2,
             ismstr_name(s.ismstr), ismstr_name(2), "shells");
}

// The Iframe the deck asks for: the property's, else /DEF_SOLID's, else 1.
int deck_iframe(const PropertyFlags& p) {
  auto asked = p.rec.get_int("Iframe");
  const auto defs = p.b.deck_.of("/DEF_SOLID");
  if (asked == 0 && !defs.empty() && defs.front()->find("Iframe")) asked = defs.front()->get_int("Iframe");
  return asked > 0 ? static_cast<int>(asked) : 1;
}

// /PROP/SOLID where tetrahedra use it: Itetra4, Ismstr (when no brick uses it too) and the frame.
void check_tetra_flags(const PropertyFlags& p, model::SolidProperty& s) {
  check_flag(p, "Itetra4", s.itetra4, s.itetra4 != 1 && s.itetra4 != 3 && s.itetra4 != 10, 1000,
             itetra4_name(s.itetra4), itetra4_name(1000), "4-node tetrahedra");
  if (!(p.used & kBrick))
    check_flag(p, "Ismstr", s.ismstr, s.ismstr == 2 || s.ismstr == 4, 4, ismstr_name(s.ismstr),
               ismstr_name(4), "4-node tetrahedra");
  // The deck's frame (the property's Iframe, else /DEF_SOLID's, else 1), also when bricks share the
  // property: OpenRadioss's tetrahedron runs co-rotational with 2 (s4forc3.F, JCVT), radx's only with
  // the Jaumann rate. Checked on a copy, so that under --allow-substitutions a brick sharing the
  // property keeps its frame while the tetrahedra run the Jaumann rate.
  auto tet_frame = static_cast<int>(p.rec.get_int("Iframe"));
  const auto def_solid = p.b.deck_.of("/DEF_SOLID");
  if (tet_frame == 0 && !def_solid.empty() && def_solid.front()->find("Iframe"))
    tet_frame = static_cast<int>(def_solid.front()->get_int("Iframe"));
  if (tet_frame <= 0) tet_frame = 1;
  check_flag(p, "Iframe", tet_frame, tet_frame == 1, 1, tet_frame == 2 ? "co-rotational" : "frame option",
             "Jaumann rate, not co-rotational", "4-node tetrahedra");
}

// What a 20-node brick does with an Isolid, as OpenRadioss runs it: every 20-node brick runs s20forc3.F
// (forint.F dispatches on the node count); the Isolid only sets the Gauss points (starter hm_read_prop14.F,
// sgrtails.F, elbuf_ini.F): 16 (and 222) the Inpts rule (default 222), 14 the Inpts rule with other digit
// axes, 17 2 x 2 x 2, 1, 2 and 24 one point, 12, 13 and 18 eight points along one axis.
std::string brick20_isolid_name(int v) {
  switch (v) {
    case 16: return "quadratic brick, Inpts Gauss points";
    case 14: return "Inpts Gauss points (HA8's digit order)";
    case 17: return "2 x 2 x 2 Gauss points";
    case 1:
    case 2:
    case 24:
      return "one Gauss point: OpenRadioss runs it without hourglass control, so the element has zero-energy "
             "modes";
    case 12:
    case 13:
    case 18: return "eight Gauss points along one axis (one across the other two): zero-energy modes";
    default: return "formulation " + std::to_string(v);
  }
}

// What an Inpts code asks of a 20-node brick, for the message that refuses it.
std::string brick20_inpts_name(int inpts) {
  const int d[3] = {inpts / 100, (inpts / 10) % 10, inpts % 10};
  if (inpts < 100 || inpts > 999 || d[0] == 0 || d[1] == 0 || d[2] == 0) return "not three point counts";
  if (d[0] == 1 || d[1] == 1 || d[2] == 1)
    return "one Gauss point along a direction: zero-energy modes, and the element has no hourglass control";
  return "more than 3 Gauss points along a direction (OpenRadioss's 4 to 9 along s serve 16-node thick "
         "shells)";
}

// Whether each digit of an Inpts code asks for 2 or 3 points (the rules radx builds for 20-node bricks).
bool brick20_inpts_runs(int inpts) {
  if (inpts == 0) return true;
  if (inpts < 100 || inpts > 999) return false;
  for (const int d : {inpts / 100, (inpts / 10) % 10, inpts % 10})
    if (d != 2 && d != 3) return false;
  return true;
}

// /PROP/SOLID where 20-node bricks use it: Isolid (16, 14, 17 run; the one-point and one-axis rules that
// OpenRadioss also runs on them are refused), Inpts (2 or 3 points per direction) and Ismstr.
void check_brick20_flags(const PropertyFlags& p, model::SolidProperty& s) {
  int isolid = s.isolid;
  check_flag(p, "Isolid", isolid, isolid == 16 || isolid == 14 || isolid == 17 || isolid == 222, 16,
             brick20_isolid_name(isolid), brick20_isolid_name(16), "20-node bricks");
  if (isolid != 17) {
    int inpts = s.inpts;
    check_flag(p, "Inpts", inpts, brick20_inpts_runs(inpts), 222, brick20_inpts_name(inpts),
               "2 x 2 x 2 Gauss points; 2 or 3 along each direction run", "20-node bricks");
    if (!(p.used & kBrick)) s.inpts = inpts;
  }
  if (!(p.used & kBrick)) s.isolid = isolid;
  if (!(p.used & (kBrick | kTetra)))
    check_flag(p, "Ismstr", s.ismstr, s.ismstr == 2 || s.ismstr == 4, 4, ismstr_name(s.ismstr),
               ismstr_name(4), "20-node bricks");
}

// /PROP/SOLID where bricks use it: Isolid, HA8's Inpts, HEPH's Icpre and Ihkt, Ismstr, Iframe and Icontrol.
void check_brick_flags(const PropertyFlags& p, model::SolidProperty& s) {
  check_flag(p, "Isolid", s.isolid, model::runs_isolid(s.isolid), 1, model::isolid_name(s.isolid),
             model::isolid_name(1), "bricks");
  if (s.isolid == 14)  // HA8 reads Inpts; radx implements its default 2 x 2 x 2 (222)
    check_flag(p, "Inpts", s.inpts, s.inpts == 0 || s.inpts == 222, 222,
               "integration points " + std::to_string(s.inpts), "2 x 2 x 2 Gauss points", "bricks");
  if (s.isolid == 24) {
    check_flag(p, "Icpre", s.icpre, s.icpre == 0 || s.icpre == 1 || s.icpre == 3, 0,  // 3: off, as 0
               s.icpre == 2 ? "pressure from the plastic state" : "pressure option",
               "compressible hourglass modes", "HEPH bricks (Isolid 24)");
    // Ihkt (old layouts) 2 and above change HEPH's hourglass (szhour3.F, szsvm.F).
    int ihkt = p.rec.find("Ihkt") ? static_cast<int>(p.rec.get_int("Ihkt")) : 0;
    check_flag(p, "Ihkt", ihkt, ihkt <= 1, 1, "hourglass option", "hourglass from the shear modulus",
               "HEPH bricks (Isolid 24)");
  }
  check_flag(p, "Ismstr", s.ismstr, s.ismstr == 2 || s.ismstr == 4, 4, ismstr_name(s.ismstr), ismstr_name(4),
             "bricks");
  check_flag(p, "Iframe", s.iframe, s.iframe == 1 || s.iframe == 2, 1, "frame option",
             "Jaumann rate, not co-rotational", "bricks");
  int icontrol = static_cast<int>(p.rec.get_int("Icontrol"));
  check_flag(p, "Icontrol", icontrol, icontrol != 1, 2, "distortion control on", "distortion control off",
             "bricks");
}

// /PROP/SOLID: the frame the deck asks for where the formulation imposes its own, then the tetrahedra's and
// the bricks' flags.
void check_solid_flags(const PropertyFlags& p, model::SolidProperty& s) {
  // Isolid 14, 15, 18 and 24 impose the co-rotational frame (model_builder.cpp): that is not the deck's
  // choice, which is the property's Iframe, else /DEF_SOLID's, else 1.
  // Isolid 24 is implemented with its forced frame, so it keeps iframe 2.
  if (s.isolid == 14 || s.isolid == 15 || s.isolid == 18) s.iframe = deck_iframe(p);
  if (p.used & kTetra) check_tetra_flags(p, s);
  if (p.used & kBrick) check_brick_flags(p, s);
  if (p.used & kBrick20) check_brick20_flags(p, s);
}

}  // namespace

void ModelBuilder::check_formulations() {
  const auto use = property_uses(m_);
  for (const auto& rec : deck_.records) {
    const auto path = rec.decl->path;
    if (path != "/PROP/SHELL" && path != "/PROP/SOLID" && path != "/PROP/SPRING" &&
        path != "/PROP/SPR_GENE" && path != "/PROP/SPR_BEAM")
      continue;
    const auto it = prop_ids_.find(rec.id);
    if (it == prop_ids_.end()) continue;
    auto& prop = m_.properties[static_cast<std::size_t>(it->second)];
    const std::uint8_t used = use[static_cast<std::size_t>(it->second)];
    if (used == 0) continue;
    const PropertyFlags flags{*this, rec, path, path == "/PROP/SHELL" ? "/DEF_SHELL" : "/DEF_SOLID", used};
    if (path == "/PROP/SPRING" || path == "/PROP/SPR_GENE" || path == "/PROP/SPR_BEAM")
      check_spring_flags(flags, prop);
    else if (path == "/PROP/SHELL")
      check_shell_flags(flags, prop.shell);
    else
      check_solid_flags(flags, prop.solid);
  }
  check_shell_only_laws();
  check_ogden_parts();
  check_truss_and_beam_laws();
}

// Trusses run laws 1 and 2 (truss_axial.cpp). OpenRadioss's truss runs laws 1, 2, 34 and 44: 34 and 44 radx
// does not have, so they are refused by name (RX510). Its law 2 takes neither the strain-rate term nor a
// /FAIL model (m2lawt.F): radx runs it the same and says so with a warning where the deck gives them.
void ModelBuilder::check_truss_and_beam_laws() {
  check_line_element_laws(m_.trusses, "trusses");
  check_line_element_laws(m_.beams, "beams");
  // Small strain (Ismstr 1, 3) takes the initial length in place of the current one: not implemented.
  for (const auto* r : deck_.of("/PROP/BEAM")) {
    const auto& rec = *r;
    const auto ismstr = rec.get_int("Ismstr");
    if (ismstr == 1 || ismstr == 3)
      error_at(
          rec, "Ismstr", Diag::PhysicsNotImplemented,
          "Ismstr = " + std::to_string(ismstr) +
              " (small strain: the initial length in the strains) is not implemented for beams; radx runs "
              "Ismstr 0, 2 and 4 (large strain)");
  }
}

// The laws a truss or beam part runs: 1 and 2; law 2 without its strain-rate term on trusses, with
// /FAIL/JOHNSON or /FAIL/BIQUAD on beams only (OpenRadioss's m2lawt.F, m2lawp.F and fail_beam3.F).
void ModelBuilder::check_line_element_laws(const model::ElementBlock& block, std::string_view what) {
  std::vector<std::uint8_t> used(m_.parts.size(), 0);
  for (const auto p : block.part)
    if (p >= 0 && static_cast<std::size_t>(p) < used.size()) used[static_cast<std::size_t>(p)] = 1;
  const bool truss = block.type == model::ElementType::Truss2;
  // One pass over the /PART records (a part's record is where the message points).
  for (const auto* r : deck_.of("/PART")) {
    const auto& rec = *r;
    const auto it = part_ids_.find(rec.id);
    if (it == part_ids_.end() || !used[static_cast<std::size_t>(it->second)]) continue;
    const auto& part = m_.parts[static_cast<std::size_t>(it->second)];
    if (part.material < 0) continue;
    const auto& mat = m_.materials[static_cast<std::size_t>(part.material)];
    const std::string used_by = mat.keyword + " " + std::to_string(mat.id) + " on the " + std::string(what) +
                                " of part " + std::to_string(part.id);
    if (mat.law != model::MaterialLaw::Elastic && mat.law != model::MaterialLaw::JohnsonCook) {
      error_at(rec, "mat_ID", Diag::PhysicsNotImplemented,
               used_by + ": radx's " + std::string(what) +
                   " run law 1 (/MAT/LAW1, /MAT/ELAST) and law 2 (/MAT/LAW2, /MAT/PLAS_JOHNS) only");
      continue;
    }
    if (truss && mat.law == model::MaterialLaw::JohnsonCook && mat.c != 0)
      warning_at(rec, "mat_ID", Diag::UnimplementedOption,
                 used_by + ": the strain-rate term (c = " + number_text(mat.c) +
                     ") does not act on trusses, as in Radioss (its truss takes the static yield curve)");
    if (!truss && mat.law == model::MaterialLaw::JohnsonCook && mat.c != 0 && mat.flag_vp == 1)
      error_at(rec, "mat_ID", Diag::PhysicsNotImplemented,
               used_by +
                   ": flagVP = 1 (the plastic strain rate) is not implemented for beams; radx's beams "
                   "take the rate of the section's work (flagVP 2 or 3)");
    // Radioss's trusses take no failure model, and its type-3 beams /FAIL/JOHNSON and /FAIL/BIQUAD among
    // radx's (main_beam3.F: not /FAIL/TAB): a model they ignore is only a warning, as Radioss says nothing.
    const bool beam_fails = !truss && (mat.fail_jc.on || mat.fail_bq.on);
    if (!beam_fails && (mat.fail_jc.on || mat.fail_tab.on || mat.fail_bq.on))
      warning_at(rec, "mat_ID", Diag::UnimplementedOption,
                 used_by + ": its /FAIL model does not act on " + std::string(what) +
                     ", as in Radioss; they fail at the material's EPS_max only");
  }
}

// /MAT/PLAS_BRIT (law 27) is a shell law with integration points (OpenRadioss: SHELL_ISOTROPIC only, and
// cm27in3.F refuses N = 0): refused on bricks and tetrahedra, and with a shell property of N = 0 (radx would
// run LAW2's three points; nothing to substitute, so there is no --allow-substitutions way out).
void ModelBuilder::check_shell_only_laws() {
  std::vector<std::uint8_t> solid_part(m_.parts.size(), 0), shell_part(m_.parts.size(), 0);
  for (const auto* b : {&m_.bricks, &m_.tetras, &m_.bricks20})
    for (const auto p : b->part)
      if (p >= 0 && static_cast<std::size_t>(p) < solid_part.size())
        solid_part[static_cast<std::size_t>(p)] = 1;
  for (const auto* b : {&m_.shells, &m_.shells3})
    for (const auto p : b->part)
      if (p >= 0 && static_cast<std::size_t>(p) < shell_part.size())
        shell_part[static_cast<std::size_t>(p)] = 1;
  for (std::size_t p = 0; p < m_.parts.size(); ++p) {
    const auto& part = m_.parts[p];
    if (part.material < 0 || part.property < 0) continue;
    const auto& mat = m_.materials[static_cast<std::size_t>(part.material)];
    // /FAIL/TAB on bricks and tetrahedra: OpenRadioss's solid update (fail_tab_s.F) takes the damage factor
    // n D^(1 - 1/n) with the card's D instead of the damage, and the element length of the cycle; radx runs
    // the shell rule (the damage, the initial length), so it refuses what would differ: n != 1 and a size
    // function.
    if (mat.fail_tab.on && solid_part[p]) {
      for (const auto& rec : deck_.records) {
        if (rec.decl->path != "/FAIL/TAB" || rec.id != mat.id) continue;
        if (mat.fail_tab.n != 1.0)
          error_at(
              rec, "n", Diag::PhysicsNotImplemented,
              "n = " + number_text(mat.fail_tab.n) + " on part " + std::to_string(part.id) +
                  " (bricks or tetrahedra): OpenRadioss's solids take n D^(1 - 1/n) with the card's D; radx "
                  "implements /FAIL/TAB on solids with n = 1 only");
        if (mat.fail_tab.size_function_id != 0)
          error_at(rec, "fct_IDel", Diag::PhysicsNotImplemented,
                   "an element size function on part " + std::to_string(part.id) +
                       " (bricks or tetrahedra): OpenRadioss scales the solids' eps_f with the length of the "
                       "cycle; radx implements the size function on shells only");
      }
    }
    // /FAIL/BIQUAD on bricks and tetrahedra: OpenRadioss takes the size factor from the length of the first
    // cycle the solid is updated in; radx keeps the size factor on shells only.
    if (mat.fail_bq.on && solid_part[p] && mat.fail_bq.size_function_id != 0) {
      for (const auto& rec : deck_.records)
        if (rec.decl->path == "/FAIL/BIQUAD" && rec.id == mat.id)
          error_at(rec, "fct_IDel", Diag::PhysicsNotImplemented,
                   "an element size function on part " + std::to_string(part.id) +
                       " (bricks or tetrahedra): radx implements /FAIL/BIQUAD's size factor on shells only; "
                       "accepted on solids: fct_IDel 0");
    }
    if (mat.law != model::MaterialLaw::PlasBrit) continue;
    const auto& prop = m_.properties[static_cast<std::size_t>(part.property)];
    for (const auto& rec : deck_.records) {
      const auto path = rec.decl->path;
      if (solid_part[p] && path == "/MAT/LAW27" && rec.id == mat.id)
        diags_.error(
            Diag::PhysicsNotImplemented, at(rec.pos), about(rec),
            mat.keyword + " " + std::to_string(mat.id) + " is used by part " + std::to_string(part.id) +
                ", whose elements are bricks or tetrahedra: law 27 is a shell law (its crack lives in "
                "the shell plane); use it on 3- and 4-node shells only");
      if (shell_part[p] && path == "/PROP/SHELL" && rec.id == prop.id && prop.shell.n_ip == 0)
        error_at(rec, "N", Diag::PhysicsNotImplemented,
                 "N = 0 (global plasticity) with " + mat.keyword + " " + std::to_string(mat.id) +
                     " in part " + std::to_string(part.id) +
                     ": law 27 cracks each integration point through the thickness and needs N = 1 to 10");
    }
  }
}

}  // namespace radx::detail
