// Deck -> Model: /INTER/TYPE7 and /INTER/LAGDT/TYPE7 into one interface definition, with the
// defaults and checks of docs/theory/type7-lagdt.md section 3, and /CTCLAW law strings attached to their
// interface (docs/theory/contact-laws.md section 5). The gap, stiffness and initial-penetration computations
// of sections 4.1, 4.2 and 4.6 are physics and live in contact/type7_prepare.cpp.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "parser/building/ctclaw_urn.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx {
namespace detail {

using model::kNone;

namespace {

// The fields of an /INTER/TYPE7 or /INTER/LAGDT/TYPE7 record, with their zero defaults.
model::Interface read_type7(ModelBuilder& b, const KeywordRecord& r, bool lagdt) {
  model::Interface in;
  in.id = r.id;
  in.title = r.title;
  in.lagdt = lagdt;
  // 0: no group; build_interfaces takes the main surface's nodes, as Radioss does.
  in.secondary_group = b.ref(b.grnod_ids_, r, "grnd_IDs", "node group", "/GRNOD", true);
  in.main_surface = b.ref(b.surf_ids_, r, "surf_IDm", "surface", "/SURF", false);
  auto geti = [&](std::string_view f) { return static_cast<int>(r.get_int(f)); };
  in.istf = geti("Istf");
  in.igap = geti("Igap");
  if (in.igap == 1000) {
    // 1000 asks for Radioss's built-in default over a /DEFAULT/INTER value: the constant gap of Igap 0.
    in.igap = 0;
    b.note_at(r, "Igap", Diag::DefaultApplied,
              "Igap = 1000 is the constant gap Gapmin of Igap = 0 (Radioss's own default, whatever "
              "/DEFAULT/INTER says), as Radioss reads it");
  }
  in.ibag = geti("Ibag");
  in.idel = geti("Idel");
  in.ithe = geti("Ithe");
  in.icurv = geti("Icurv");
  in.iadm = geti("Iadm");
  in.itied = geti("Itied");
  in.ists = geti("Ists");
  in.fscale_gap = r.get_real("Fscalegap");
  if (in.fscale_gap == 0) in.fscale_gap = 1.0;
  in.gap_max = r.get_real("Gapmax");
  in.fpenmax = r.get_real("Fpenmax");
  in.stmin = r.get_real("Stmin");
  in.stmax = r.get_real("Stmax");
  if (in.stmax == 0) in.stmax = 1e30;
  in.mesh_size_pct = r.get_real("mesh_size");
  in.dt_min = r.get_real("dtmin");
  in.irem_gap = geti("Irem_gap");
  in.irem_i2 = geti("Irem_i2");
  in.stfac = r.get_real("Stfac");
  in.fric = r.get_real("Fric");
  in.gapmin_input = r.get_real("Gapmin");
  in.t_start = r.get_real("Tstart");
  in.t_stop = r.get_real("Tstop");
  if (in.t_stop == 0) in.t_stop = model::kNever;
  in.ibc = {static_cast<std::uint8_t>(r.get_int("IBCX")), static_cast<std::uint8_t>(r.get_int("IBCY")),
            static_cast<std::uint8_t>(r.get_int("IBCZ"))};
  in.inacti = geti("Inacti");
  in.vis_s = r.get_real("VISs");
  if (in.vis_s == 0) in.vis_s = 0.05;
  in.vis_f = r.get_real("VISF");
  if (in.vis_f == 0) in.vis_f = 1.0;
  in.bumult = r.get_real("Bumult");
  if (in.bumult == 0) {
    const auto n = b.m_.nodes.size();
    in.bumult = n > 2500000 ? 0.4 : (n > 1500000 ? 0.3 : 0.2);
  }
  in.ifric = geti("Ifric");
  in.ifiltr = geti("Ifiltr");
  in.xfreq = r.get_real("Xfreq");
  in.iform = geti("Iform");
  if (in.iform == 0) in.iform = 1;
  for (int k = 0; k < 6; ++k) in.c[k] = r.get_real("C" + std::to_string(k + 1));
  in.sens_id = b.sensor_ref(r, "sens_ID");
  in.fct_id_f = r.get_int("fct_IDF");
  in.ascale_f = r.get_real("AscaleF");
  in.fric_id = r.get_int("fric_ID");
  return in;
}

// The stiffness options: Stfac by Istf (with its 0-means-1 default where it is a factor), Stmin <= Stmax.
void check_type7_stiffness(ModelBuilder& b, const KeywordRecord& r, model::Interface& in) {
  if (in.istf == 1) {
    // Stfac is the stiffness itself here: its "0 means 1" default does not apply.
    const FieldValue* f = r.find("Stfac");
    if (!f || f->blank || f->defaulted || in.stfac <= 0)
      b.error_at(r, "Stfac", Diag::RequiredValueMissing,
                 "Istf = 1 takes the stiffness value from Stfac, which is " +
                     std::string(f && !f->defaulted && !f->blank ? number_text(in.stfac) : "0 or blank") +
                     "; give the interface stiffness (force per length) > 0");
  } else {
    if (in.stfac == 0) in.stfac = 1.0;
    if (in.stfac < 0)
      b.error_at(r, "Stfac", Diag::ValueOutOfRange,
                 "Stfac = " + number_text(in.stfac) + " must be > 0 (0 means 1)");
  }
  if (in.istf >= 2 && in.stmax < in.stmin)
    b.error_at(r, "Stmax", Diag::InconsistentValues,
               "Stmax = " + number_text(in.stmax) + " is below Stmin = " + number_text(in.stmin) +
                   "; need Stmin <= Stmax");
}

// Renard friction (Ifric = 3): C1 = mu_s, C2 = mu_d, C3 = mu_max, C4 = mu_min, C5 = V_cr1, C6 = V_cr2, in
// the order the law needs them.
void check_renard_friction(ModelBuilder& b, const KeywordRecord& r, const model::Interface& in) {
  const auto& c = in.c;
  std::string why;
  if (c[4] == 0)
    why = "C5 (critical speed V_cr1) is 0";
  else if (!(c[4] < c[5]))
    why = "C5 = " + number_text(c[4]) + " is not below C6 = " + number_text(c[5]);
  else if (!(c[3] <= c[0] && c[0] <= c[2]))
    why = "C1 (mu_s) must lie in [C4, C3] = [mu_min, mu_max]";
  else if (!(c[3] <= c[1] && c[1] <= c[2]))
    why = "C2 (mu_d) must lie in [C4, C3] = [mu_min, mu_max]";
  if (!why.empty())
    b.error_at(r, "C1", Diag::BadFrictionLaw,
               "Renard friction (Ifric = 3): " + why +
                   "; the law needs C5 != 0, C5 < C6, C4 <= C1 <= C3 and "
                   "C4 <= C2 <= C3");
}

// The checks the declarations cannot make alone.
void check_type7(ModelBuilder& b, const KeywordRecord& r, model::Interface& in) {
  check_type7_stiffness(b, r, in);
  if (in.t_stop <= in.t_start)
    b.error_at(r, "Tstop", Diag::InconsistentValues,
               "Tstop = " + number_text(in.t_stop) + " is not after Tstart = " + number_text(in.t_start) +
                   ": the interface would never act; need Tstop > Tstart (0 = never stop)");
  if (in.ibag != 0)
    b.warning_at(r, "Ibag", Diag::UnimplementedOption,
                 "Ibag = " + std::to_string(in.ibag) +
                     ": airbag vent-hole closure is accepted but monitored volumes are not modelled by radx");
  if ((in.ifiltr == 1 || in.ifiltr == 2) && (in.xfreq < 0 || in.xfreq > 1))
    b.error_at(r, "Xfreq", Diag::ValueOutOfRange,
               "Xfreq = " + number_text(in.xfreq) + " with Ifiltr = " + std::to_string(in.ifiltr) +
                   " must be in [0, 1]");
  if (in.ifric == 3) check_renard_friction(b, r, in);
}

// One /CTCLAW record while its law string is read.
struct ContactLawRecord {
  ModelBuilder& b;
  const KeywordRecord& r;
  std::string law_id;  // "/CTCLAW/5"

  // Where character `offset` of the law string was written.
  Where where(std::size_t offset) const {
    if (r.text_pos.empty()) return b.at(r.pos, 1);
    const auto i = std::min(offset, r.text_pos.size() - 1);
    return b.at(r.text_pos[i], static_cast<int>(r.text_column[i]));
  }
  void bad(std::size_t offset, const std::string& parameter, const std::string& message) const {
    b.diags_.error(Diag::BadContactLaw, where(offset), ModelBuilder::about(r),
                   law_id + (parameter == "law string" ? " law string '" + r.text + "'" : " " + parameter) +
                       ": " + message);
  }
};

// The law's values from the record's input units to work units; whether they differ.
bool law_to_work_units(const KeywordRecord& r, model::ContactLaw& law) {
  const auto [fm, fl, ft] = r.unit_factors;
  const bool converted = fm != 1.0 || fl != 1.0 || ft != 1.0;
  if (!converted) return false;
  const double fp = fm / (fl * ft * ft);  // pressure
  if (law.kc > 0) law.kc *= fp / fl;
  law.pz *= fp;
  law.pe *= fp;
  law.lambda /= fl;
  law.kc_max *= fp / fl;
  for (std::size_t j = 0; j < law.power_k.size(); ++j) law.power_k[j] *= fp / std::pow(fl, law.power_m[j]);
  law.ct *= law.friction == model::FrictionLaw::Linear ? fp * ft / fl : ft / fl;  // s2: Pa s/m; s3, s4: s/m
  law.kappa *= fp / fl;
  return true;
}

// Whether /FUNCT `f` (CurveID `id`) is a pressure curve a tabulated law can use: at least 2 points, no
// negative pressure, none rising with the gap, one that ends at 0 and pushes somewhere; the error for the
// first rule it breaks of each kind.
bool pressure_curve_ok(const ContactLawRecord& c, const UrnResult& urn, std::int64_t id,
                       const model::Function& f) {
  const std::string fn = "/FUNCT/" + std::to_string(f.id);
  bool curve_ok = true;
  auto curve_error = [&](const std::string& msg) {
    c.bad(urn.curve_offset, "CurveID", "CurveID = " + std::to_string(id) + ": " + msg);
    curve_ok = false;
  };
  if (f.x.size() < 2)
    curve_error(fn + " has " + std::to_string(f.x.size()) +
                " point(s); a tabulated law needs at least 2 points (gap, pressure)");
  for (std::size_t j = 0; j < f.y.size(); ++j)
    if (f.y[j] < 0) {
      curve_error(fn + " point " + std::to_string(j + 1) + " (gap " + number_text(f.x[j]) +
                  ") has the pressure " + number_text(f.y[j]) + " < 0: contact pressures are >= 0");
      break;
    }
  for (std::size_t j = 1; j < f.y.size(); ++j)
    if (f.y[j] > f.y[j - 1]) {
      curve_error(fn + ": the pressure rises from " + number_text(f.y[j - 1]) + " at gap " +
                  number_text(f.x[j - 1]) + " to " + number_text(f.y[j]) + " at gap " + number_text(f.x[j]) +
                  "; the pressure must not increase as the gap grows (the stiffness would be negative)");
      break;
    }
  // The pressure must end somewhere: a table still pushing at its largest gap, and not falling there,
  // would press every node the search finds at any distance.
  const std::size_t n = f.y.size();
  if (curve_ok && n >= 2 && f.y[n - 1] > 0 && !(f.y[n - 1] < f.y[n - 2]))
    curve_error(fn + " ends at gap " + number_text(f.x[n - 1]) + " with the pressure " +
                number_text(f.y[n - 1]) +
                " > 0 and a last segment that does not fall: the pressure must reach 0 at some gap (end the "
                "table with a 0, or let its last segment fall)");
  if (curve_ok && n >= 2 && std::all_of(f.y.begin(), f.y.end(), [](double y) { return !(y > 0); }))
    curve_error(fn + " has no positive pressure: the law would never push");
  return curve_ok;
}

// The /FUNCT of a tabulated law (its id shifted by the record's submodel) into law.curve, when it exists,
// is a valid pressure curve, and the record is in work units.
void resolve_law_curve(const ContactLawRecord& c, const UrnResult& urn, bool converted,
                       model::ContactLaw& law) {
  const auto& b = c.b;
  const auto& r = c.r;
  const std::int64_t id =
      urn.curve_id +
      (r.submodel >= 0 ? b.deck_.submodels[static_cast<std::size_t>(r.submodel)].offset(schema::IdKind::Other)
                       : 0);
  const auto it = b.funct_ids_.find(id);
  if (it == b.funct_ids_.end()) {
    c.bad(
        urn.curve_offset, "CurveID",
        "CurveID = " + std::to_string(id) + " names no /FUNCT: give the id of the /FUNCT of gap to pressure");
    return;
  }
  const auto& f = b.m_.functions[static_cast<std::size_t>(it->second)];
  if (!pressure_curve_ok(c, urn, id, f)) return;
  if (converted) {
    b.diags_.error(Diag::PhysicsNotImplemented, c.where(urn.curve_offset), ModelBuilder::about(r),
                   c.law_id + " CurveID: the tabulated law takes the gaps and pressures of /FUNCT/" +
                       std::to_string(f.id) +
                       " as written, in the work units, but this /CTCLAW is in other input units; write "
                       "the deck in its work units to use a tabulated law");
    return;
  }
  law.curve = it->second;
}

// The law, as understood (also with errors: the listing shows it), onto interface `in`, unless it has one.
void attach_law(const ContactLawRecord& c, model::Interface& in, model::ContactLaw& law) {
  const auto& r = c.r;
  if (in.contact_law_id != 0) {
    c.b.diags_.error(
        Diag::InconsistentValues, c.b.at(r.pos, 1), ModelBuilder::about(r),
        "interface " + std::to_string(in.id) + " already has /CTCLAW/" + std::to_string(in.contact_law_id));
    return;
  }
  in.contact_law_id = r.id;
  in.contact_law = r.text;
  in.law = std::move(law);  // as understood, also with errors: the listing shows it
  // docs/theory/contact-laws.md 4: a law with no s part is frictionless; the
  // interface's own friction is replaced too.
  if (in.law.friction == model::FrictionLaw::None && (in.fric > 0 || in.ifric > 0))
    c.b.diags_.warning(Diag::InterfaceFieldIgnored, c.where(0), ModelBuilder::about(r),
                       c.law_id + " has no friction part (s...): the interface " + std::to_string(in.id) +
                           "'s Fric = " + number_text(in.fric) + ", Ifric = " + std::to_string(in.ifric) +
                           " is replaced and the contact is frictionless; add an s part to keep friction");
}

}  // namespace

void ModelBuilder::build_interfaces() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto& r : deck_.records) {
    const auto path = r.decl->path;
    const bool lagdt = path == "/INTER/LAGDT/TYPE7";
    if (path != "/INTER/TYPE7" && !lagdt) continue;
    model::Interface in = read_type7(*this, r, lagdt);
    check_type7(*this, r, in);
    if (in.secondary_group != kNone) {
      if (const auto* nodes = group_nodes(in.secondary_group)) in.secondary_nodes = *nodes;
    } else if (r.get_int("grnd_IDs") == 0 && in.main_surface != kNone) {
      // No secondary group: the Radioss starter takes the main surface as the secondary side too (its nodes
      // against its segments, a self-contact).
      for (const auto& seg : m_.surfaces[static_cast<std::size_t>(in.main_surface)].segments)
        in.secondary_nodes.insert(in.secondary_nodes.end(), seg.begin(), seg.end());
      std::sort(in.secondary_nodes.begin(), in.secondary_nodes.end());
      in.secondary_nodes.erase(std::unique(in.secondary_nodes.begin(), in.secondary_nodes.end()),
                               in.secondary_nodes.end());
      note_at(r, "grnd_IDs", Diag::DefaultApplied,
              "grnd_IDs = 0: the secondary nodes are the " + std::to_string(in.secondary_nodes.size()) +
                  " nodes of the main surface " + std::to_string(r.get_int("surf_IDm")) +
                  " (a self-contact), as Radioss takes them");
    }
    // Radioss stops on an interface whose main surface holds no segment (its error 3160): the contact would
    // find nothing, and the deck almost always names the wrong surface or parts.
    if (in.main_surface != kNone && m_.surfaces[static_cast<std::size_t>(in.main_surface)].segments.empty())
      error_at(r, "surf_IDm", Diag::EmptyGroup,
               "the main surface " + std::to_string(r.get_int("surf_IDm")) +
                   " holds no segment, so the interface would find no contact (Radioss stops on it too); "
                   "check the surface's parts or segments");
    else if (in.main_surface != kNone && in.secondary_nodes.empty())
      warning_at(r, "grnd_IDs", Diag::EmptyGroup,
                 "the interface has no secondary node, so it finds no contact (Radioss warns too); check the "
                 "secondary node group");
    if (register_id(inter_ids_, in.id, static_cast<std::int32_t>(m_.interfaces.size()), r, "interface",
                    first))
      m_.interfaces.push_back(std::move(in));
  }
}

void ModelBuilder::build_contact_laws() {
  for (const auto* r : deck_.of("/CTCLAW")) {
    const auto k = ref(inter_ids_, *r, "inter_ID", "interface", "/INTER/TYPE7 or /INTER/LAGDT/TYPE7", false);
    if (r->text.empty()) {
      diags_.error(Diag::MissingCard, at(r->pos, 1), about(*r),
                   "/CTCLAW needs a law string after the interface card, e.g. n1s13{Kc1e12,Mu0.1,CtLin1e3}");
      continue;
    }
    const ContactLawRecord c{*this, *r, "/CTCLAW/" + std::to_string(r->id)};
    UrnResult urn = parse_ctclaw_urn(r->text);
    for (const auto& p : urn.problems) c.bad(p.offset, p.parameter, p.message);
    model::ContactLaw& law = urn.law;
    // The values are in the record's input units: to work units.
    const bool converted = law_to_work_units(*r, law);
    if (law.kappa > 0 && law.friction != model::FrictionLaw::Coulomb)
      diags_.warning(Diag::InterfaceFieldIgnored, c.where(0), about(*r),
                     c.law_id +
                         " kappa: the sticking stiffness belongs to exact Coulomb (s1, s11); the regularised "
                         "laws (s2..s4, s12..s14) stick through their slope CtLin, so kappa has no effect");
    // The curve of a tabulated law.
    if (urn.curve_id != 0) resolve_law_curve(c, urn, converted, law);
    if (k == kNone) continue;
    attach_law(c, m_.interfaces[k], law);
  }
}

}  // namespace detail
}  // namespace radx
