// Deck -> Model, core steps: nodes, materials, properties (with /DEF_SHELL and /DEF_SOLID two-stage
// defaults, docs/theory/deck-format.md section 5.1), subsets, parts, elements and their geometry checks,
// lumped masses (docs/theory/elements.md section 5: shells m = rho t0 A0 split equally over the 4 slots,
// bricks m = rho V0 split 1/8 per node, 3-node shells split by interior angle alpha_k / pi).
#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "solver/model/geometry.hpp"
#include "solver/model/hex20_shape.hpp"
#include "solver/model/masses.hpp"

namespace radx {
namespace detail {

using model::kNone;

Where ModelBuilder::at_field(const KeywordRecord& r, std::string_view field) const {
  const FieldValue* f = r.find(field);
  if (f && f->column > 0) return at(f->pos, f->column);
  if (f) return at(f->pos, 1);
  return at(r.pos, 1);
}

void ModelBuilder::error_at(const KeywordRecord& r, std::string_view field, Diag code, std::string msg) {
  diags_.error(code, at_field(r, field), about(r), std::move(msg));
}
void ModelBuilder::warning_at(const KeywordRecord& r, std::string_view field, Diag code, std::string msg) {
  diags_.warning(code, at_field(r, field), about(r), std::move(msg));
}

void ModelBuilder::note_at(const KeywordRecord& r, std::string_view field, Diag code, std::string msg) {
  diags_.note(code, at_field(r, field), about(r), std::move(msg));
}

namespace {
// "box" -> "boxes", "part" -> "parts": the kinds named in duplicate-id messages.
std::string plural(std::string_view noun) {
  const bool sibilant =
      noun.ends_with('x') || noun.ends_with('s') || noun.ends_with("sh") || noun.ends_with("ch");
  return std::string(noun) + (sibilant ? "es" : "s");
}
}  // namespace

bool ModelBuilder::register_id(IdIndex& index, std::int64_t id, std::int32_t dense, const KeywordRecord& r,
                               std::string_view what,
                               std::unordered_map<std::int64_t, SourcePos>& first_pos) {
  const auto [it, inserted] = index.emplace(id, dense);
  if (!inserted) {
    const SourcePos p = first_pos[id];
    diags_.error(Diag::DuplicateId, at(r.pos, 1), about(r),
                 std::string(what) + " id " + std::to_string(id) + " is already used at " +
                     deck_.files[p.file] + ":" + std::to_string(p.line) + "; ids must be unique among " +
                     plural(what));
    return false;
  }
  first_pos[id] = r.pos;
  return true;
}

std::int32_t ModelBuilder::ref(const IdIndex& index, const KeywordRecord& r, std::string_view field,
                               std::string_view what, std::string_view target_keyword, bool optional) {
  const std::int64_t id = r.get_int(field);
  if (id == 0) {
    if (!optional)
      error_at(r, field, Diag::RequiredIdMissing,
               std::string(field) + " is blank or 0: a " + std::string(what) + " id (" +
                   std::string(target_keyword) + ") is required");
    return kNone;
  }
  const auto it = index.find(id);
  // A set of the id stands in for a node group or a surface no /GRNOD or /SURF defines (Radioss builds the
  // group from the set where it is named); a group of the same id wins, as in Radioss.
  if (it == index.end() && (target_keyword == "/GRNOD" || target_keyword == "/SURF")) {
    const auto s = target_keyword == "/GRNOD" ? node_group_from_set(id) : surface_from_set(id);
    if (s != kNone) return s;
  }
  if (it == index.end()) {
    const std::string prefix = std::string(target_keyword) + "/";
    // Radioss lets a group reference (/GRNOD, /SURF, /GRSHEL ...) name a /SET as well, in the same ids.
    const bool set_ok = target_keyword.rfind("/GR", 0) == 0 || target_keyword == "/SURF";
    const auto unread = std::find_if(deck_.unread.begin(), deck_.unread.end(), [&](const Deck::Unread& u) {
      return u.id == id && (u.path.rfind(prefix, 0) == 0 || (set_ok && u.path.rfind("/SET/", 0) == 0));
    });
    if (unread != deck_.unread.end() && unread->path.rfind("/SET/", 0) == 0) {
      const Where w = deck_.where(unread->pos);
      error_at(r, field, Diag::MissingReference,
               std::string(field) + " = " + std::to_string(id) + " names " + unread->path + " " +
                   std::to_string(id) + " (" + std::string(w.file) + ":" + std::to_string(w.line) +
                   "), a /SET of a type radx does not read (reported there; radx reads /SET/GENERAL and "
                   "/SET/COLLECT), not a " +
                   std::string(target_keyword) + ": give the " + std::string(what) + " as a " +
                   std::string(target_keyword) + " or a /SET/GENERAL instead");
    } else if (unread != deck_.unread.end()) {
      const Where w = deck_.where(unread->pos);
      error_at(r, field, Diag::MissingReference,
               std::string(field) + " = " + std::to_string(id) + " names " + unread->path + " " +
                   std::to_string(id) + " (" + std::string(w.file) + ":" + std::to_string(w.line) +
                   "), a keyword radx does not read (reported there): what uses it cannot be built");
    } else {
      error_at(r, field, Diag::MissingReference,
               std::string(field) + " = " + std::to_string(id) + ": there is no " +
                   std::string(target_keyword) + "/" + std::to_string(id) + " in the deck");
    }
    return kNone;
  }
  return it->second;
}

std::int32_t ModelBuilder::node_ref(std::int64_t user_id, const KeywordRecord& r, SourcePos pos,
                                    std::string_view what) {
  const auto k = m_.nodes.index.find(user_id);
  if (k < 0) {
    diags_.error(Diag::MissingReference, at(pos, 1), about(r),
                 std::string(what) + ": node " + std::to_string(user_id) +
                     " does not exist (no /NODE line defines it)");
  }
  return k;
}

// ---------------------------------------------------------------------------------------------------

void ModelBuilder::build_nodes() {
  auto& n = m_.nodes;
  for (const auto* r : deck_.of("/NODE")) {
    const auto& t = r->records;
    const int cid = t.column("node_ID"), cx = t.column("X"), cy = t.column("Y"), cz = t.column("Z");
    if (cid < 0 || cx < 0 || cy < 0 || cz < 0) continue;
    n.id.insert(n.id.end(), t.ints[cid].begin(), t.ints[cid].end());
    n.x.insert(n.x.end(), t.reals[cx].begin(), t.reals[cx].end());
    n.y.insert(n.y.end(), t.reals[cy].begin(), t.reals[cy].end());
    n.z.insert(n.z.end(), t.reals[cz].begin(), t.reals[cz].end());
    node_pos_.insert(node_pos_.end(), t.pos.begin(), t.pos.end());
    node_submodel_.insert(node_submodel_.end(), t.size(), r->submodel);
    node_bad_.insert(node_bad_.end(), t.bad.begin(), t.bad.end());
  }
  std::int64_t dup = 0;
  if (!n.index.build(n.id, dup)) {
    // Report every duplicate with both lines.
    std::unordered_map<std::int64_t, std::size_t> first;
    first.reserve(n.id.size());
    for (std::size_t i = 0; i < n.id.size(); ++i) {
      const auto [it, ok] = first.emplace(n.id[i], i);
      if (!ok) {
        const SourcePos p = node_pos_[it->second];
        diags_.error(Diag::DuplicateId, at(node_pos_[i], 1), About{"/NODE", n.id[i]},
                     "node id " + std::to_string(n.id[i]) + " is already defined at " + deck_.files[p.file] +
                         ":" + std::to_string(p.line) + "; node ids must be unique");
      }
    }
    // Keep going with the first definition of each id so references can still be checked.
    std::vector<std::int64_t> ids = n.id;
    std::unordered_map<std::int64_t, int> seen;
    for (auto& id : ids)
      if (seen[id]++ > 0) id = -id - 1;  // an id no reference can name
    n.index.build(ids, dup);
  }
  for (std::size_t i = 0; i < n.id.size(); ++i) {
    if (n.id[i] <= 0)
      diags_.error(Diag::ValueOutOfRange, at(node_pos_[i], 1), About{"/NODE", n.id[i]},
                   "node id " + std::to_string(n.id[i]) + " is not a positive integer");
  }
  node_used_.assign(n.size(), 0);
}

namespace {

// The law of a material keyword the builder reads (LAW13 is /MAT/RIGID), or none.
std::optional<model::MaterialLaw> material_law(std::string_view path) {
  if (path == "/MAT/LAW1") return model::MaterialLaw::Elastic;
  if (path == "/MAT/LAW2") return model::MaterialLaw::JohnsonCook;
  if (path == "/MAT/LAW27") return model::MaterialLaw::PlasBrit;
  if (path == "/MAT/LAW36") return model::MaterialLaw::PlasTab;
  if (path == "/MAT/LAW0") return model::MaterialLaw::Void;
  if (path == "/MAT/LAW42") return model::MaterialLaw::Ogden;
  if (path == "/MAT/LAW70") return model::MaterialLaw::FoamTab;
  if (path == "/MAT/LAW13") return model::MaterialLaw::Rigid;
  return std::nullopt;
}

// A warning when the wave speed sqrt(E/rho) is one no material has in any plausible reading of the units.
void warn_implausible_wave_speed(ModelBuilder& b, const KeywordRecord& r, const model::Material& mat) {
  // Values typed in other units than the deck's (a modulus in Pa in an mm-Mg-s deck) give wave
  // speeds no material has, and with them steps or run times that are absurd; warn, as the run can
  // still be meant (a scaled model). c = sqrt(E/rho) is in the work units' length over time; with
  // units the deck names that is a speed in m/s. A deck that names none reads as SI but may be in any
  // consistent system, whose velocity unit is 1e-3 (mm/s) to 1e4 (cm/us) m/s: warn only when every
  // such reading is implausible.
  const double c = std::sqrt(mat.young / mat.rho);
  const auto& w = b.deck_.work_units;
  constexpr double kLight = 299792458.0;
  const double fastest = b.deck_.units_named ? w.length / w.time : 1e4;
  const double slowest = b.deck_.units_named ? w.length / w.time : 1e-3;
  const bool slow = c * fastest<1.0, fast = c * slowest> kLight;
  if (!slow && !fast) return;
  const std::string speed =
      b.deck_.units_named
          ? number_text(c * fastest) + " m/s (E = " + number_text(mat.young) +
                ", RHO_I = " + number_text(mat.rho) + " in the deck's work units " + w.mass_name + " " +
                w.length_name + " " + w.time_name + ")"
          : number_text(c) + " length per time unit (E = " + number_text(mat.young) +
                ", RHO_I = " + number_text(mat.rho) +
                "; the deck names no units, so radx takes the most plausible of the usual systems: " +
                (slow ? number_text(c * fastest) + " m/s if in cm/us"
                      : number_text(c * slowest) + " m/s if in mm/s") +
                ")";
  b.warning_at(r, "E", Diag::ImplausibleMaterial,
               "the wave speed sqrt(E/RHO_I) = " + speed + " is " +
                   (fast ? "above the speed of light (3.0e8 m/s)" : "below 1 m/s") +
                   "; solids have 20 (soft foams, rubbers) to 18000 m/s (diamond), metals about 5000 "
                   "m/s: check the units of E and RHO_I");
}

// The densities, E and nu of the laws whose card starts with them, checked, with G and K.
void read_elastic_constants(ModelBuilder& b, const KeywordRecord& r, model::Material& mat) {
  ModelBuilder::read_densities(r, mat);
  mat.young = r.get_real("E");
  mat.poisson = r.get_real("nu");
  if (mat.rho < 0 && r.given("RHO_I"))  // 0 is reported by the field's rule (a value is required)
    b.error_at(r, "RHO_I", Diag::ValueOutOfRange, "density RHO_I = " + number_text(mat.rho) + " must be > 0");
  if (mat.young < 0)
    b.error_at(r, "E", Diag::ValueOutOfRange,
               "Young's modulus E = " + number_text(mat.young) + " must be > 0");
  if (mat.poisson < 0 || mat.poisson >= 0.5) {
    b.error_at(r, "nu", Diag::BadPoisson,
               "Poisson's ratio nu = " + number_text(mat.poisson) +
                   " is outside [0, 0.5): the bulk modulus E/3(1-2nu) would be infinite or negative (Radioss "
                   "turns "
                   "exactly 0.5 into 0.499 silently; radx asks for the value you mean, e.g. 0.499)");
  }
  if (mat.rho > 0 && mat.young > 0) warn_implausible_wave_speed(b, r, mat);
  mat.shear = mat.young / (2.0 * (1.0 + mat.poisson));
  mat.bulk = mat.poisson < 0.5 ? mat.young / (3.0 * (1.0 - 2.0 * mat.poisson)) : 0.0;
}

// /MAT/PLAS_JOHNS with Iflag = 1: a, b and n from the yield stress, the ultimate stress and its strain.
void johnson_cook_from_uts(ModelBuilder& b, const KeywordRecord& r, model::Material& mat) {
  mat.sig_y_input = r.get_real("SIG_Y");
  mat.uts = r.get_real("UTS");
  mat.e_uts = r.get_real("EUTS");
  // Iflag = 1: rm = UTS (1 + e_uts), ag = ln(1 + e_uts), n = rm ag / (rm - sy), b = rm / (n ag^(n-1)).
  const double sy = mat.sig_y_input;
  const double rm = mat.uts * (1.0 + mat.e_uts);
  const double ag = std::log1p(mat.e_uts);
  if (sy <= 0 || mat.uts <= 0 || mat.e_uts <= 0 || rm <= sy) {
    b.error_at(r, "SIG_Y", Diag::InconsistentValues,
               "Iflag = 1 needs SIG_Y > 0, UTS > 0, EUTS > 0 and UTS(1+EUTS) > SIG_Y; got SIG_Y = " +
                   number_text(sy) + ", UTS = " + number_text(mat.uts) +
                   ", EUTS = " + number_text(mat.e_uts));
    return;
  }
  mat.a = sy;
  mat.n = rm * ag / (rm - sy);
  mat.b = rm / (mat.n * std::pow(ag, mat.n - 1.0));
  if (mat.n > 1.0) {
    mat.n = 1.0;
    mat.b = (rm - sy) / (ag - rm / mat.young - sy / mat.young);
    b.warning_at(
        r, "SIG_Y", Diag::DefaultApplied,
        "Iflag = 1 gives a hardening exponent above 1; n = 1 is used with b = " + number_text(mat.b));
  }
}

// /MAT/PLAS_JOHNS (law 2) past its elastic constants: the flags, the yield curve (Iflag 0: a, b, n; 1: from
// the ultimate stress), the strain-rate and the thermal terms, with their zero defaults.
void read_johnson_cook(ModelBuilder& b, const KeywordRecord& r, model::Material& mat) {
  mat.iflag = static_cast<int>(r.get_int("Iflag"));
  mat.flag_vp = static_cast<int>(r.get_int("flagVP"));
  if (mat.flag_vp == 0) mat.flag_vp = 2;
  mat.p_min = r.given("Pmin") && r.get_real("Pmin") != 0 ? r.get_real("Pmin") : -1e20;
  mat.eps_p_max = r.get_real("EPS_p_max");
  mat.sig_max0 = r.get_real("SIG_max0");
  if (mat.eps_p_max == 0) mat.eps_p_max = 1e20;
  if (mat.sig_max0 == 0) mat.sig_max0 = 1e20;
  if (mat.iflag == 1) {
    johnson_cook_from_uts(b, r, mat);
  } else {
    mat.a = r.get_real("a");
    mat.b = r.get_real("b");
    mat.n = r.get_real("n");  // <= 1: the field's rule (keywords_starter.cpp)
    if (mat.n == 0) mat.n = 1.0;
    if (mat.a <= 0)
      b.error_at(r, "a", Diag::ValueOutOfRange, "yield stress a = " + number_text(mat.a) + " must be > 0");
  }
  mat.c = r.get_real("c");
  mat.eps_dot_0 = r.get_real("EPS_DOT_0");
  if (mat.c != 0 && mat.eps_dot_0 <= 0) {
    b.error_at(r, "EPS_DOT_0", Diag::RequiredValueMissing,
               "strain-rate coefficient c = " + number_text(mat.c) +
                   " needs a reference strain rate EPS_DOT_0 > 0 (it is blank or 0)");
  }
  if (mat.c == 0) mat.eps_dot_0 = 1.0;
  mat.icc = static_cast<int>(r.get_int("ICC"));
  if (mat.icc == 0) mat.icc = 1;
  mat.fsmooth = static_cast<int>(r.get_int("Fsmooth"));
  mat.f_cut = r.get_real("F_cut");
  mat.chard = r.get_real("Chard");
  mat.m_temp = r.get_real("m");
  if (mat.m_temp == 0) mat.m_temp = 1.0;
  mat.t_melt = r.get_real("T_melt");
  if (mat.t_melt == 0) mat.t_melt = 1e20;
  mat.rho_cp = r.get_real("rhoC_p");
  mat.t_ref = r.get_real("T_r");
  if (mat.t_ref <= 0) mat.t_ref = 300.0;
  mat.t_max = r.get_real("T_max");
  if (mat.t_max == 0) mat.t_max = 1e20;
}

}  // namespace

void ModelBuilder::build_materials() {
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto& r : deck_.records) {
    const auto law = material_law(r.decl->path);
    if (!law) continue;
    model::Material mat;
    mat.id = r.id;
    mat.title = r.title;
    mat.keyword = r.written.substr(0, r.written.find_last_of('/'));
    mat.law = *law;
    switch (mat.law) {
      case model::MaterialLaw::Void: read_void(r, mat); break;
      case model::MaterialLaw::Ogden: read_ogden(r, mat); break;
      case model::MaterialLaw::FoamTab: read_foam_tab(r, mat); break;
      default:
        read_elastic_constants(*this, r, mat);
        if (mat.law == model::MaterialLaw::JohnsonCook) read_johnson_cook(*this, r, mat);
        if (mat.law == model::MaterialLaw::PlasTab) read_plas_tab(r, mat);
        if (mat.law == model::MaterialLaw::PlasBrit) read_plas_brit(r, mat);
        break;
    }
    if (register_id(mat_ids_, mat.id, static_cast<std::int32_t>(m_.materials.size()), r, "material", first))
      m_.materials.push_back(std::move(mat));
  }
  build_failure_models();
  build_fail_tab();
  build_fail_biquad();
}

// /MAT/VOID (law 0), read as OpenRadioss hm_read_mat00.F does: every value may be blank. The density gives
// the element mass (rho_I V, none when 0); E and nu give only the contact stiffness (bulk E/3(1-2nu)).
void ModelBuilder::read_void(const KeywordRecord& r, model::Material& mat) {
  mat.rho = mat.rho_ref = r.get_real("RHO_I");
  read_isotropic_elastic(
      r, mat, "E",
      "the contact stiffness takes the bulk modulus E/3(1-2nu), which would be infinite or "
      "negative; leave it blank (0) or give a value such as 0.3");
}

void ModelBuilder::read_densities(const KeywordRecord& r, model::Material& mat) {
  mat.rho = r.get_real("RHO_I");
  mat.rho_ref = r.get_real("RHO_ref");
  if (mat.rho_ref == 0) mat.rho_ref = mat.rho;
}

void ModelBuilder::read_isotropic_elastic(const KeywordRecord& r, model::Material& mat,
                                          std::string_view young_field, std::string_view nu_consequence) {
  mat.young = r.get_real(young_field);
  mat.poisson = r.get_real("nu");
  if (mat.poisson < 0 || mat.poisson >= 0.5)
    error_at(r, "nu", Diag::BadPoisson,
             "Poisson's ratio nu = " + number_text(mat.poisson) +
                 " is outside [0, 0.5): " + std::string(nu_consequence));
  mat.shear = mat.young / (2.0 * (1.0 + mat.poisson));
  mat.bulk = mat.poisson < 0.5 ? mat.young / (3.0 * (1.0 - 2.0 * mat.poisson)) : 0.0;
}

// /MAT/PLAS_TAB (law 36), read as OpenRadioss hm_read_mat36.F does: one curve keeps no rate effect (Fsmooth,
// Fcut and VP are set to 0); several curves need strictly increasing rates, and Fcut 0 means 10 kHz. The
// function ids are resolved once the functions are built (resolve_plas_tab_functions).
void ModelBuilder::read_plas_tab(const KeywordRecord& r, model::Material& mat) {
  mat.eps_p_max = r.get_real("Eps_p_max");  // 0 -> 1e20 by the field's rule
  mat.f_cut = r.get_real("Fcut");
  auto& tab = mat.tab;
  tab.fsmooth = static_cast<int>(r.get_int("Fsmooth"));
  tab.vp = static_cast<int>(r.get_int("VP"));
  const auto n = static_cast<int>(std::clamp<std::int64_t>(r.get_int("N_funct"), 0, 100));
  for (int i = 0; i < n; ++i) {
    const std::string k = std::to_string(i + 1);
    const std::string fid = "fct_ID" + k, fs = "Fscale" + k, rate = "Eps_dot" + k;
    tab.function_id.push_back(r.get_int(fid));
    tab.function.push_back(model::kNone);
    tab.scale.push_back(r.get_real(fs));  // 0 -> 1 by the field's rule
    tab.rate.push_back(r.get_real(rate));
    if (tab.function_id.back() <= 0)
      error_at(r, fid, Diag::RequiredIdMissing,
               "yield curve " + k + " of " + std::to_string(n) + " (N_funct): " + fid + " = " +
                   std::to_string(tab.function_id.back()) + "; each curve needs the id of a /FUNCT");
    if (tab.scale.back() < 0)
      error_at(r, fs, Diag::ValueOutOfRange,
               fs + " = " + number_text(tab.scale.back()) +
                   " is negative: a yield curve's scale factor must be > 0");
    if (i > 0 && !(tab.rate[static_cast<std::size_t>(i)] > tab.rate[static_cast<std::size_t>(i - 1)]))
      error_at(r, rate, Diag::InconsistentValues,
               "strain rates must be strictly increasing: Eps_dot" + std::to_string(i) + " = " +
                   number_text(tab.rate[static_cast<std::size_t>(i - 1)]) + ", " + rate + " = " +
                   number_text(tab.rate[static_cast<std::size_t>(i)]));
  }
  if (n == 1) {
    // A single (static) curve: no rate effect, no filter (OpenRadioss sets them so).
    tab.fsmooth = 0;
    tab.vp = 0;
    mat.f_cut = 0;
  } else if (mat.f_cut == 0) {
    mat.f_cut = 1e4 * deck_.work_units.time;  // 10 kHz in work units (one work time unit is `time` s)
  }
}

// /PROP/BEAM's fields (hm_read_prop03.F): Df 0 is 0.01; the released rotations from the Wdof digits.
void ModelBuilder::read_beam_property(const KeywordRecord& r, model::BeamProperty& b) {
  b.area = r.get_real("Area");
  b.iyy = r.get_real("Iyy");
  b.izz = r.get_real("Izz");
  b.ixx = r.get_real("Ixx");
  b.dm = r.get_real("Dm");
  b.df = r.get_real("Df");
  if (b.df == 0) b.df = 0.01;
  b.ishear = static_cast<int>(r.get_int("Ishear"));
  b.ismstr = static_cast<int>(r.get_int("Ismstr"));
  b.release_x = r.get_int("Wx1") != 0 || r.get_int("Wx2") != 0 ? 1 : 0;
  b.release_y1 = static_cast<int>(r.get_int("Wy1"));
  b.release_z1 = static_cast<int>(r.get_int("Wz1"));
  b.release_y2 = static_cast<int>(r.get_int("Wy2"));
  b.release_z2 = static_cast<int>(r.get_int("Wz2"));
}

// /MAT/PLAS_BRIT (law 27), read as OpenRadioss hm_read_mat27.F does: a 0 = 1e20 (no yield), n 0 = 1, SIG_max0
// 0 = 1e20, c 0 sets EPS_DOT_0 to 1, ICC 0 = 1, Fcut not 0 turns Fsmooth 0 into 1; the crack fields' zero
// defaults are the fields' rules (keywords_starter.cpp). Direction 2 is read and kept, never used (m27crak.F
// opens only direction 1).
void ModelBuilder::read_plas_brit(const KeywordRecord& r, model::Material& mat) {
  mat.a = r.get_real("a");
  mat.b = r.get_real("b");
  mat.n = r.get_real("n");
  mat.sig_max0 = r.get_real("SIG_max0");
  mat.c = r.get_real("c");
  mat.eps_dot_0 = r.get_real("EPS_DOT_0");
  if (mat.c != 0 && mat.eps_dot_0 <= 0)
    error_at(r, "EPS_DOT_0", Diag::RequiredValueMissing,
             "strain-rate coefficient c = " + number_text(mat.c) +
                 " needs a reference strain rate EPS_DOT_0 > 0 (it is " + number_text(mat.eps_dot_0) + ")");
  if (mat.c == 0) mat.eps_dot_0 = 1.0;
  mat.icc = static_cast<int>(r.get_int("ICC"));
  mat.fsmooth = static_cast<int>(r.get_int("Fsmooth"));
  mat.f_cut = r.get_real("Fcut");
  if (mat.fsmooth == 0 && mat.f_cut != 0) mat.fsmooth = 1;
  auto& b = mat.brit;
  b.eps_t1 = r.get_real("EPS_t1");
  b.eps_m1 = r.get_real("EPS_m1");
  b.d_max1 = r.get_real("d_max1");
  b.eps_f1 = r.get_real("EPS_f1");
  b.eps_t2 = r.get_real("EPS_t2");
  b.eps_m2 = r.get_real("EPS_m2");
  b.d_max2 = r.get_real("d_max2");
  b.eps_f2 = r.get_real("EPS_f2");
  // The damage is (eps_1 - EPS_t1) / (EPS_m1 - EPS_t1): it needs EPS_m1 above EPS_t1 (hm_read_mat27.F, 208).
  if (!(b.eps_m1 > b.eps_t1))
    error_at(r, "EPS_m1", Diag::InconsistentValues,
             "EPS_m1 = " + number_text(b.eps_m1) + " must be above EPS_t1 = " + number_text(b.eps_t1) +
                 ": the damage grows from 0 at EPS_t1 to 1 at EPS_m1 (0 in both leaves the crack off)");
}

void ModelBuilder::resolve_plas_tab_functions() {
  for (const auto& r : deck_.records) {
    if (r.decl->path != "/MAT/LAW36") continue;
    const auto it = mat_ids_.find(r.id);
    if (it == mat_ids_.end()) continue;
    auto& mat = m_.materials[static_cast<std::size_t>(it->second)];
    if (mat.law != model::MaterialLaw::PlasTab || mat.title != r.title) continue;  // a duplicate id
    for (std::size_t i = 0; i < mat.tab.function_id.size(); ++i) {
      if (mat.tab.function_id[i] <= 0) continue;  // reported by read_plas_tab
      mat.tab.function[i] =
          ref(funct_ids_, r, "fct_ID" + std::to_string(i + 1), "yield curve", "/FUNCT", false);
    }
  }
}

// The material a failure model's keyword line names, when radx can attach it there: it exists, is of law 2
// or 36, and has no failure model yet; otherwise the error and nullptr.
model::Material* ModelBuilder::failure_material(const KeywordRecord& r, std::string_view keyword) {
  const auto it = mat_ids_.find(r.id);
  if (it == mat_ids_.end()) {
    diags_.error(Diag::MissingReference, at(r.pos), about(r),
                 std::string(keyword) + " names material " + std::to_string(r.id) +
                     ", which does not exist; the id on the keyword line is the material's");
    return nullptr;
  }
  auto& mat = m_.materials[static_cast<std::size_t>(it->second)];
  if (mat.law != model::MaterialLaw::JohnsonCook && mat.law != model::MaterialLaw::PlasTab) {
    diags_.error(Diag::PhysicsNotImplemented, at(r.pos), about(r),
                 std::string(keyword) + " on material " + std::to_string(r.id) + " (" + mat.keyword +
                     "): radx implements it on /MAT/PLAS_JOHNS (law 2) and /MAT/PLAS_TAB (law 36) only");
    return nullptr;
  }
  if (mat.fail_jc.on || mat.fail_tab.on || mat.fail_bq.on) {
    diags_.error(Diag::DuplicateId, at(r.pos), about(r),
                 "material " + std::to_string(r.id) + " already has a " +
                     (mat.fail_jc.on    ? "/FAIL/JOHNSON"
                      : mat.fail_tab.on ? "/FAIL/TAB"
                                        : "/FAIL/BIQUAD") +
                     "; radx takes one failure model per material");
    return nullptr;
  }
  return &mat;
}

// /FAIL/JOHNSON/mat_ID: attached to its material (law 2 or 36), at most one per material. Defaults of
// OpenRadioss hm_read_fail_johnson.F: Epsilon_Dot_0 0 -> 1e-20, Ifail_sh and Ifail_so 0 -> 1.
void ModelBuilder::build_failure_models() {
  for (const auto* rp : deck_.of("/FAIL/JOHNSON")) {
    const auto& r = *rp;
    model::Material* target = failure_material(r, "/FAIL/JOHNSON");
    if (!target) continue;
    auto& mat = *target;
    if (r.get_int("FAILIP") > 1)
      error_at(r, "FAILIP", Diag::PhysicsNotImplemented,
               "FAILIP = " + std::to_string(r.get_int("FAILIP")) +
                   " is not implemented: radx deletes a shell by Ifail_sh (FAILIP 0 or 1)");
    auto& f = mat.fail_jc;
    f.on = true;
    f.fail_id = r.get_int("fail_ID");
    f.d1 = r.get_real("D1");
    f.d2 = r.get_real("D2");
    f.d3 = r.get_real("D3");
    f.d4 = r.get_real("D4");
    f.d5 = r.get_real("D5");
    f.eps_dot_0 = r.get_real("Epsilon_Dot_0");
    if (f.eps_dot_0 == 0) f.eps_dot_0 = 1e-20;
    f.eps_f_min = r.get_real("EPSF_MIN");
    f.dadv = r.get_real("Dadv");
    if (f.dadv == 0 || f.dadv > 1) f.dadv = 1;
    f.ifail_sh = static_cast<int>(r.get_int("Ifail_sh"));
    f.ifail_so = static_cast<int>(r.get_int("Ifail_so"));
    if (f.d5 != 0)
      warning_at(r, "D5", Diag::DefaultApplied,
                 "D5 = " + number_text(f.d5) +
                     " multiplies the temperature term T*, which is 0 in radx (no heating)");
    // eps_f at triaxiality 1 (OpenRadioss checks this too): a criterion that is never positive fails at once.
    if (f.d1 + f.d2 * std::exp(f.d3) <= 0 && f.eps_f_min <= 0)
      warning_at(r, "D1", Diag::ImplausibleMaterial,
                 "the failure strain D1 + D2 exp(D3 sigma*) is <= 0 at triaxiality 1: points in tension do "
                 "not accumulate damage there (radx adds d_eps_p / eps_f only for eps_f > 0)");
  }
}

// /FAIL/TAB/mat_ID: attached to its material (law 2 or 36), at most one failure model per material.
// Defaults of OpenRadioss hm_read_fail_tab_old.F / hm_read_fail_tab1.F: Dcrit 0 -> 1, n 0 -> 1, Ifail_sh and
// Ifail_so 0 -> 1, the scale factors 0 -> 1, EI_ref 0 -> 1 (in the deck's length unit). The functions are
// resolved once they are built (resolve_fail_tab_functions).
void ModelBuilder::build_fail_tab() {
  for (const auto* rp : deck_.of("/FAIL/TAB")) {
    const auto& r = *rp;
    model::Material* target = failure_material(r, "/FAIL/TAB");
    if (!target) continue;
    auto& mat = *target;
    auto& f = mat.fail_tab;
    f.on = true;
    f.fail_id = r.get_int("fail_ID");
    f.ifail_sh = static_cast<int>(r.get_int("Ifail_sh"));
    f.ifail_so = static_cast<int>(r.get_int("Ifail_so"));
    f.p_thickfail = r.get_real("P_thickfail");
    if (f.p_thickfail < 0)
      error_at(
          r, "P_thickfail", Diag::PhysicsNotImplemented,
          "P_thickfail = " + number_text(f.p_thickfail) +
              " < 0 (a fraction of failed points) is not implemented by radx: give the failed fraction of "
              "the thickness, 0 to 1");
    f.dcrit = r.get_real("Dcrit");
    f.d = r.get_real("D");
    if (f.d == 1.0) f.d = 0.999;
    f.n = r.get_real("n");
    const auto n_rate = static_cast<int>(std::clamp<std::int64_t>(r.get_int("N_rate"), 0, 100));
    for (int i = 1; i <= n_rate; ++i) {
      const std::string k = std::to_string(i);
      f.function_id.push_back(r.get_int("fct_ID" + k));
      f.function.push_back(-1);
      f.scale.push_back(r.get_real("Fscale" + k));
      f.rate.push_back(r.get_real("Epsdot" + k));
      if (i > 1 && !(f.rate[static_cast<std::size_t>(i - 1)] > f.rate[static_cast<std::size_t>(i - 2)]))
        error_at(r, "Epsdot" + k, Diag::InconsistentValues,
                 "Epsdot" + k + " = " + number_text(f.rate.back()) + " is not above Epsdot" +
                     std::to_string(i - 1) +
                     ": the strain rates of the failure-strain functions must increase");
    }
    f.size_function_id = r.get_int("fct_IDel");
    f.size_scale = r.get_real("Fscale_el");
    f.el_ref = r.get_real("EI_ref");
    f.temp_function_id = r.get_int("fct_IDt");
    f.temp_factor = r.get_real("FscaleT");
  }
}

// /FAIL/TAB's function ids, once the functions exist. A temperature function is accepted only when it is
// constant (radx has no temperature: any other would change eps_f with a temperature radx does not compute).
void ModelBuilder::resolve_fail_tab_functions() {
  for (const auto* rp : deck_.of("/FAIL/TAB")) {
    const auto& r = *rp;
    const auto it = mat_ids_.find(r.id);
    if (it == mat_ids_.end()) continue;
    auto& f = m_.materials[static_cast<std::size_t>(it->second)].fail_tab;
    if (!f.on) continue;
    for (std::size_t i = 0; i < f.function.size(); ++i)
      f.function[i] =
          ref(funct_ids_, r, "fct_ID" + std::to_string(i + 1), "failure strain function", "/FUNCT", false);
    f.size_function = ref(funct_ids_, r, "fct_IDel", "element size factor function", "/FUNCT", true);
    const auto ti = ref(funct_ids_, r, "fct_IDt", "temperature factor function", "/FUNCT", true);
    if (ti >= 0) {
      const auto& fn = m_.functions[static_cast<std::size_t>(ti)];
      const bool constant =
          !fn.y.empty() && std::all_of(fn.y.begin(), fn.y.end(), [&](double y) { return y == fn.y.front(); });
      if (!constant)
        error_at(r, "fct_IDt", Diag::PhysicsNotImplemented,
                 "the temperature factor function " + std::to_string(f.temp_function_id) +
                     " is not constant: radx has no temperature, so it takes a constant temperature function "
                     "only (its value times FscaleT)");
      else
        f.temp_factor *= fn.y.front();
    }
  }
}

void ModelBuilder::shell_hourglass_defaults(const KeywordRecord& r, model::ShellProperty& s) {
  const bool h3 = s.ishell == 3;
  s.hm = r.find("Hm") && !r.find("Hm")->defaulted ? r.get_real("Hm") : (h3 ? 0.1 : 0.01);
  s.hf = r.find("Hf") && !r.find("Hf")->defaulted ? r.get_real("Hf") : (h3 ? 0.1 : 0.01);
  s.hr = r.find("Hr") && !r.find("Hr")->defaulted ? r.get_real("Hr") : 0.01;
}

void ModelBuilder::build_properties() {
  // Two-stage defaults: the /PROP value if non-zero, else the first /DEF_SHELL or /DEF_SOLID value if
  // non-zero, else the hard default (explicit analysis).
  const auto def_shell = deck_.of("/DEF_SHELL");
  const auto def_solid = deck_.of("/DEF_SOLID");
  auto dshell = [&](std::string_view name) -> std::int64_t {
    return def_shell.empty() ? 0 : def_shell.front()->get_int(name);
  };
  auto dsolid = [&](std::string_view name) -> std::int64_t {
    return def_solid.empty() ? 0 : def_solid.front()->get_int(name);
  };
  auto pick = [](std::int64_t prop, std::int64_t def, int hard) {
    if (def == -2) return -1;  // /DEF_* -2: "automatic" forced on every property
    if (prop != 0) return static_cast<int>(prop);
    if (def != 0) return static_cast<int>(def);
    return hard;
  };
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto& r : deck_.records) {
    const auto path = r.decl->path;
    if (path != "/PROP/SHELL" && path != "/PROP/SOLID" && path != "/PROP/SPRING" &&
        path != "/PROP/SPR_GENE" && path != "/PROP/SPR_BEAM" && path != "/PROP/TRUSS" && path != "/PROP/BEAM")
      continue;
    model::Property p;
    p.id = r.id;
    p.title = r.title;
    if (path == "/PROP/SPRING" || path == "/PROP/SPR_GENE" || path == "/PROP/SPR_BEAM") {
      read_spring_property(r, p);
    } else if (path == "/PROP/BEAM") {
      p.kind = model::PropertyKind::Beam;
      read_beam_property(r, p.beam);
    } else if (path == "/PROP/TRUSS") {
      p.kind = model::PropertyKind::Truss;
      p.truss.area = r.get_real("Area");  // > 0: the field's rule
    } else if (path == "/PROP/SHELL") {
      p.kind = model::PropertyKind::Shell;
      auto& s = p.shell;
      s.ishell = pick(r.get_int("Ishell"), dshell("Ishell"), 1);
      if (s.ishell == 22 || s.ishell == 23) s.ishell = 24;
      s.ismstr = pick(r.get_int("Ismstr"), dshell("Ismstr"), 2);
      s.ish3n = pick(r.get_int("Ish3n"), dshell("Ish3n"), 2);
      s.idrill = pick(r.get_int("Idrill"), dshell("Idrill"), 0);
      if (s.idrill == 2) s.idrill = 0;
      s.ithick = pick(r.get_int("Ithick"), dshell("Ithick"), 2);
      s.iplas = pick(r.get_int("Iplas"), dshell("Iplas"), 2);
      s.ipinch = static_cast<int>(r.get_int("Ipinch"));
      s.ipos = static_cast<int>(r.get_int("Ipos"));
      s.p_thick_fail = r.get_real("P_Thick_Fail");
      if (s.p_thick_fail == 0) s.p_thick_fail = 0.999999;
      shell_hourglass_defaults(r, s);
      s.dm = r.get_real("Dm");
      s.dn = r.get_real("Dn");
      if (s.dn == 0 && s.ishell == 24) s.dn = 0.015;
      // QEPH's membrane damping default (docs/theory/elements.md 1.10)
      if (s.dm == 0 && s.ishell == 24) s.dm = 0.015;
      s.n_ip = static_cast<int>(r.get_int("N"));  // 0 to 10: the field's rule (keywords_starter.cpp)
      s.thickness = r.get_real("Thick");
      if (s.thickness < 0)
        error_at(r, "Thick", Diag::NonPositiveThickness,
                 "shell thickness Thick = " + number_text(s.thickness) + " is negative; it must be > 0");
      s.ashear = r.get_real("Ashear");
      if (s.ashear == 0) s.ashear = 5.0 / 6.0;
    } else {
      p.kind = model::PropertyKind::Solid;
      auto& s = p.solid;
      s.isolid = pick(r.get_int("Isolid"), dsolid("Isolid"), 1);
      // Isolid 18 defaults to Ismstr 2 (OpenRadioss sgrtails.F), the others to 4.
      s.ismstr = pick(r.get_int("Ismstr"), dsolid("Ismstr"), s.isolid == 18 ? 2 : 4);
      s.icpre = pick(r.get_int("Icpre"), dsolid("Icpre"), 0);
      s.iframe = pick(r.get_int("Iframe"), dsolid("Iframe"), 1);
      if (s.isolid == 14 || s.isolid == 15 || s.isolid == 18 || s.isolid == 24) s.iframe = 2;
      s.itetra4 = pick(r.get_int("Itetra4"), dsolid("Itetra4"), 1000);
      s.itetra10 = pick(r.get_int("Itetra10"), dsolid("Itetra10"), 1000);
      s.iale = static_cast<int>(r.get_int("Iale"));
      s.inpts = static_cast<int>(r.get_int("Inpts"));
      s.qa = r.get_real("qa");
      s.qb = r.get_real("qb");
      // Both 0 or blank in the deck (the fields' rules have put the defaults in): law 70 then runs without
      // bulk viscosity (hm_read_prop14.F).
      auto zero_in_deck = [&](std::string_view name) {
        const auto* v = r.find(name);
        return v == nullptr || v->defaulted || (v->decl != nullptr && v->r == 0.0);
      };
      s.q_default = zero_in_deck("qa") && zero_in_deck("qb");
      if (s.qa == 0) s.qa = 1.1;
      if (s.qb == 0) s.qb = 0.05;
      s.h = r.get_real("h");
      if (s.h == 0) s.h = 0.1;
      s.lambda_v = r.get_real("Lambda");
      s.mu_v = r.get_real("Mu");
      s.dn = r.get_real("dn");
      s.dt_min = r.get_real("deltaT_min");
    }
    if (register_id(prop_ids_, p.id, static_cast<std::int32_t>(m_.properties.size()), r, "property", first))
      m_.properties.push_back(std::move(p));
  }
}

void ModelBuilder::build_subsets_and_parts() {
  std::unordered_map<std::int64_t, SourcePos> first_subset;
  const auto subsets = deck_.of("/SUBSET");
  for (const auto* r : subsets) {
    model::Subset s;
    s.id = r->id;
    s.title = r->title;
    if (register_id(subset_ids_, s.id, static_cast<std::int32_t>(m_.subsets.size()), *r, "subset",
                    first_subset))
      m_.subsets.push_back(std::move(s));
  }
  for (const auto* r : subsets) {
    const auto it = subset_ids_.find(r->id);
    if (it == subset_ids_.end()) continue;
    for (std::size_t k = 0; k < r->ids.size(); ++k) {
      const auto c = subset_ids_.find(r->ids[k]);
      if (c == subset_ids_.end()) {
        // Radioss ignores it with its warning 182.
        diags_.warning(Diag::MissingReference, at(r->id_pos[k], 1), about(*r),
                       "child subset " + std::to_string(r->ids[k]) + " does not exist (no /SUBSET/" +
                           std::to_string(r->ids[k]) + "): it is left out, as Radioss does");
      } else {
        m_.subsets[it->second].children.push_back(c->second);
      }
    }
  }
  std::unordered_map<std::int64_t, SourcePos> first;
  for (const auto* r : deck_.of("/PART")) {
    model::Part p;
    p.id = r->id;
    p.title = r->title;
    p.property = ref(prop_ids_, *r, "prop_ID", "property", "/PROP", false);
    // Springs take their mechanics from the property alone: a spring part needs no material.
    // A property that is missing (or of a keyword radx refuses, e.g. /PROP/SPR_GENE) is reported already; its
    // part's mat_ID 0 would only repeat it.
    const bool spring = p.property == kNone || m_.properties[static_cast<std::size_t>(p.property)].kind ==
                                                   model::PropertyKind::Spring;
    p.material = ref(mat_ids_, *r, "mat_ID", "material", "/MAT", spring);
    // A subset that does not exist is Radioss's warning 183: the part's subset is reset to none.
    if (const auto sid = r->get_int("subset_ID"); sid != 0 && subset_ids_.find(sid) == subset_ids_.end())
      warning_at(*r, "subset_ID", Diag::MissingReference,
                 "subset_ID = " + std::to_string(sid) + ": there is no /SUBSET/" + std::to_string(sid) +
                     " in the deck; the part belongs to no subset, as Radioss resets it");
    else
      p.subset = ref(subset_ids_, *r, "subset_ID", "subset", "/SUBSET", true);
    p.contact_thickness = r->get_real("Thick");
    if (p.contact_thickness < 0)
      error_at(*r, "Thick", Diag::NonPositiveThickness,
               "/PART contact thickness " + number_text(p.contact_thickness) +
                   " is negative; it must be >= 0 (0 = none)");
    const auto dense = static_cast<std::int32_t>(m_.parts.size());
    if (register_id(part_ids_, p.id, dense, *r, "part", first)) {
      if (p.subset != kNone) m_.subsets[p.subset].parts.push_back(dense);
      m_.parts.push_back(std::move(p));
    }
  }
}

namespace {

// An element keyword: its id field, the block it fills, the property kind its parts need.
struct ElementKind {
  std::string_view keyword;
  std::string_view id_field;
  model::ElementBlock* block;
  model::PropertyKind prop_kind;
};

constexpr const char* kNodeNames[20] = {"n1",  "n2",  "n3",  "n4",  "n5",  "n6",  "n7",  "n8",  "n9",  "n10",
                                        "n11", "n12", "n13", "n14", "n15", "n16", "n17", "n18", "n19", "n20"};

// The column a node field starts at on its line: the element cards put n1 at 11, n2 at 21, ...; the 20-node
// brick's n9-n16 and n17-n20 start their own lines at column 1.
int node_column(model::ElementType type, int k) {
  if (type == model::ElementType::Brick20 && k >= 8) return 1 + 10 * ((k - 8) % 8);
  return 11 + 10 * k;
}

std::string_view property_kind_name(model::PropertyKind k) {
  switch (k) {
    case model::PropertyKind::Shell: return "shell";
    case model::PropertyKind::Solid: return "solid";
    case model::PropertyKind::Spring: return "spring";
    case model::PropertyKind::Truss: return "truss";
    case model::PropertyKind::Beam: return "beam";
  }
  return "other";
}
std::string_view property_keyword(model::PropertyKind k) {
  switch (k) {
    case model::PropertyKind::Shell: return "/PROP/SHELL";
    case model::PropertyKind::Solid: return "/PROP/SOLID";
    case model::PropertyKind::Spring: return "/PROP/SPRING";
    case model::PropertyKind::Truss: return "/PROP/TRUSS";
    case model::PropertyKind::Beam: return "/PROP/BEAM";
  }
  return "/PROP";
}

// The part the keyword line names (kNone, with the error, when it does not exist); a part whose property is
// of another shape than the elements' is an error.
std::int32_t element_part(ModelBuilder& b, const KeywordRecord& r, const ElementKind& kind) {
  const auto pit = b.part_ids_.find(r.id);
  if (pit == b.part_ids_.end()) {
    b.diags_.error(Diag::MissingReference, b.at(r.pos, 1), ModelBuilder::about(r),
                   std::string(kind.keyword) + "/" + std::to_string(r.id) + ": part " + std::to_string(r.id) +
                       " does not exist (no /PART/" + std::to_string(r.id) +
                       "); the keyword line names the part");
    return kNone;
  }
  const std::int32_t part = pit->second;
  const auto& m = b.m_;
  const auto& p = m.parts[part];
  if (p.property != kNone && m.properties[p.property].kind != kind.prop_kind) {
    b.diags_.error(Diag::PartWrongKind, b.at(r.pos, 1), ModelBuilder::about(r),
                   "part " + std::to_string(r.id) + " has a " +
                       std::string(property_kind_name(m.properties[p.property].kind)) + " property (/PROP/" +
                       std::to_string(m.properties[p.property].id) + "); " + std::string(kind.keyword) +
                       " elements need a " + std::string(property_keyword(kind.prop_kind)));
  }
  return part;
}

// The nodes of element `eid` (user ids `user`, read at `pos`) into blk.conn, each marked used; returns
// whether one is blank or does not exist (kNone in its slot, with the error).
bool append_element_nodes(ModelBuilder& b, model::ElementBlock& blk, std::string_view keyword,
                          std::int64_t eid, const std::int64_t* user, SourcePos pos) {
  const int npe = blk.npe();
  // A beam's third node only orients its section: blank takes a global axis (beam_type3.cpp).
  const int optional_from = blk.type == model::ElementType::Beam2 ? 2 : npe;
  bool missing = false;
  for (int k = 0; k < npe; ++k) {
    std::int32_t n = kNone;
    if (user[k] == 0 && k >= optional_from) {
      blk.conn.push_back(kNone);
      continue;
    }
    if (user[k] == 0) {
      b.diags_.error(Diag::ElementNodeMissing, b.at(pos, node_column(blk.type, k)), About{keyword, eid},
                     std::string(kNodeNames[k]) + " is blank or 0: element " + std::to_string(eid) +
                         " needs " + std::to_string(npe) + " nodes");
      missing = true;
    } else {
      n = b.m_.nodes.index.find(user[k]);
      if (n < 0) {
        b.diags_.error(Diag::ElementNodeMissing, b.at(pos, node_column(blk.type, k)), About{keyword, eid},
                       "element " + std::to_string(eid) + " uses node " + std::to_string(user[k]) + " (" +
                           kNodeNames[k] + "), which does not exist");
        missing = true;
      } else {
        b.node_used_[n] = 1;
      }
    }
    blk.conn.push_back(n);
  }
  return missing;
}

model::Vec3 element_node_position(const model::Model& m, const model::ElementBlock& blk, std::size_t base,
                                  int k) {
  const auto n = blk.conn[base + static_cast<std::size_t>(k)];
  return model::Vec3{m.nodes.x[n], m.nodes.y[n], m.nodes.z[n]};
}

// A brick whose nodes start at blk.conn[base]: a volume that is not positive is an error, a corner turned
// inside out a warning.
void check_brick_shape(ModelBuilder& b, const model::ElementBlock& blk, std::size_t base, SourcePos pos,
                       const About& ab) {
  const auto& m = b.m_;
  const std::int64_t eid = ab.id;
  std::array<model::Vec3, 8> x{};
  for (int k = 0; k < 8; ++k) x[k] = element_node_position(m, blk, base, k);
  const double v = model::brick_volume(x);
  if (!(v > 0)) {
    b.diags_.error(Diag::NonPositiveVolume, b.at(pos, 1), ab,
                   "brick " + std::to_string(eid) + " has " + (v == 0 ? "zero" : "negative") + " volume (" +
                       number_text(v) + "): " +
                       (v < 0 ? "its nodes n1-n4 and n5-n8 are numbered so that the element is inverted; "
                                "n1-n4 must turn counter-clockwise seen from the n5-n8 face"
                              : "its nodes are flat or collapsed"));
  } else if (const auto corner = model::most_negative_brick_corner(x); corner.ratio < -1e-6) {
    // The one-point volume averages the corners, so a tangled brick passes it and then runs
    // with a stiffness and a step that belong to no real shape.
    b.diags_.warning(
        Diag::TangledBrick, b.at(pos, 1), ab,
        "brick " + std::to_string(eid) + " is tangled: its corner at node " +
            std::to_string(m.nodes.id[blk.conn[base + static_cast<std::size_t>(corner.node)]]) + " (n" +
            std::to_string(corner.node + 1) +
            ") is turned inside out (its edges there span a negative volume: the faces meeting there "
            "fold through each other or the brick is re-entrant), though its volume (" +
            number_text(v) +
            ") is positive; in a valid brick every corner's three edges turn the same "
            "way as n1-n2, n1-n4, n1-n5");
  }
}

// A truss or beam whose nodes start at blk.conn[base]: its two nodes must be distinct and apart (its length
// is the denominator of its strains and its step); a beam's orientation node must lie off its axis.
void check_line_shape(ModelBuilder& b, const model::ElementBlock& blk, std::size_t base, SourcePos pos,
                      const About& ab) {
  const std::string what = blk.type == model::ElementType::Beam2 ? "beam" : "truss";
  const auto x1 = element_node_position(b.m_, blk, base, 0), x2 = element_node_position(b.m_, blk, base, 1);
  const double length = model::norm(model::sub(x2, x1));
  if (blk.conn[base] == blk.conn[base + 1]) {
    b.diags_.error(
        Diag::RepeatedNodeInElement, b.at(pos, 1), ab,
        what + " " + std::to_string(ab.id) + " has n1 = n2; a " + what + " joins two distinct nodes");
    return;
  }
  if (!(length > 0)) {
    b.diags_.error(
        Diag::RepeatedNodeInElement, b.at(pos, 1), ab,
        what + " " + std::to_string(ab.id) + " has zero length: its two nodes are at the same place");
    return;
  }
  if (blk.type != model::ElementType::Beam2 || blk.conn[base + 2] == kNone) return;
  const auto y = model::sub(element_node_position(b.m_, blk, base, 2), x1);
  const double off_axis = model::norm(model::cross(model::sub(x2, x1), y));
  if (!(off_axis > 1e-12 * length * model::norm(y)))
    b.diags_.error(Diag::DegenerateElement, b.at(pos, 31), ab,
                   "beam " + std::to_string(ab.id) +
                       ": its orientation node n3 lies on the beam's axis, so it gives no y axis; choose a "
                       "node off the line n1 n2, or leave n3 blank for the global axis");
}

// A shell whose nodes start at blk.conn[base], read at `pos` (its thickness in column `thick_column`): fewer
// than 3 distinct nodes, no area, a negative thickness, or no thickness on the element nor on its property,
// are errors.
void check_shell_shape(ModelBuilder& b, const model::ElementBlock& blk, std::size_t base, SourcePos pos,
                       int thick_column, std::int32_t part, const About& ab) {
  const auto& m = b.m_;
  const std::int64_t eid = ab.id;
  const int npe = blk.npe();
  auto X = [&](int k) { return element_node_position(m, blk, base, k); };
  double area = 0;
  if (blk.type == model::ElementType::Shell3) {
    area = model::triangle_area(X(0), X(1), X(2));
  } else {
    area = model::quad_area(X(0), X(1), X(2), X(3));
    if (blk.conn[base + 2] == blk.conn[base + 3]) {
      // n4 = n3: a degenerate triangle, accepted as Radioss does.
    }
  }
  int distinct = 0;
  for (int k = 0; k < npe; ++k) {
    bool seen = false;
    for (int l = 0; l < k; ++l) seen = seen || blk.conn[base + k] == blk.conn[base + l];
    distinct += seen ? 0 : 1;
  }
  if (distinct < 3) {
    b.diags_.error(Diag::RepeatedNodeInElement, b.at(pos, 1), ab,
                   "shell " + std::to_string(eid) + " has only " + std::to_string(distinct) +
                       " distinct nodes; a shell needs 3 (triangle) or 4");
  } else if (!(area > 0)) {
    b.diags_.error(Diag::NonPositiveArea, b.at(pos, 1), ab,
                   "shell " + std::to_string(eid) + " has zero area: its nodes are aligned or collapsed");
  }
  const double th = blk.thickness.back();
  if (th < 0) {
    b.diags_.error(Diag::NonPositiveThickness, b.at(pos, thick_column), ab,
                   "element thickness " + number_text(th) +
                       " is negative; it must be > 0 (or blank to use the "
                       "property thickness)");
  } else if (th == 0 && part != kNone && m.parts[part].property != kNone &&
             m.properties[m.parts[part].property].kind == model::PropertyKind::Shell &&
             m.properties[m.parts[part].property].shell.thickness == 0) {
    b.diags_.error(Diag::NonPositiveThickness, b.at(pos, 1), ab,
                   "shell " + std::to_string(eid) +
                       " has no thickness: the element card gives none and /PROP/" +
                       std::to_string(m.properties[m.parts[part].property].id) +
                       " Thick is 0; give a thickness > 0 on either");
  }
}

// A 20-node brick whose nodes start at blk.conn[base]: 20 distinct nodes, and det J > 0 at the 3 x 3 x 3
// Gauss points (OpenRadioss's engine stops at the first point with a volume <= 0, s20deri3.F; the starter
// catches it before the run). A mid-side node far off its edge, or corners numbered the other way round,
// give such a point.
void check_brick20_shape(ModelBuilder& b, const model::ElementBlock& blk, std::size_t base, SourcePos pos,
                         const About& ab) {
  const auto& m = b.m_;
  const std::int64_t eid = ab.id;
  for (std::size_t k = 1; k < 20; ++k)
    for (std::size_t l = 0; l < k; ++l)
      if (blk.conn[base + k] == blk.conn[base + l]) {
        b.diags_.error(Diag::RepeatedNodeInElement, b.at(pos, 1), ab,
                       "20-node brick " + std::to_string(eid) + " lists node " +
                           std::to_string(m.nodes.id[static_cast<std::size_t>(blk.conn[base + k])]) +
                           " twice (n" + std::to_string(l + 1) + " and n" + std::to_string(k + 1) +
                           "); a /BRIC20 needs 20 distinct nodes (radx does not run degenerate 20-node "
                           "bricks)");
        return;
      }
  double x[20][3];
  for (int k = 0; k < 20; ++k) {
    const auto p = element_node_position(m, blk, base, k);
    for (int d = 0; d < 3; ++d) x[k][d] = p[static_cast<std::size_t>(d)];
  }
  double det_min = 0;
  const double v = model::hex20_volume(x, model::hex20_starter_rule(), &det_min);
  if (!(det_min > 0)) {
    b.diags_.error(Diag::NonPositiveVolume, b.at(pos, 1), ab,
                   "20-node brick " + std::to_string(eid) + " has a non-positive Jacobian at a Gauss point " +
                       "(smallest det J " + number_text(det_min) + ", volume " + number_text(v) +
                       "): its corners n1-n4 must turn counter-clockwise seen from the n5-n8 face and each "
                       "mid-side node n9-n20 must lie near the middle of its edge");
  }
}

// The elements of one keyword's records into the kind's block, with their nodes and shapes checked; the
// line of each element to `pos`.
void read_element_records(ModelBuilder& b, const ElementKind& kind, const KeywordRecord& r,
                          std::vector<SourcePos>& pos) {
  auto& blk = *kind.block;
  const int npe = blk.npe();
  const auto& t = r.records;
  const std::int32_t part = element_part(b, r, kind);
  const int cid = t.column(kind.id_field);
  int cn[20];
  for (int k = 0; k < npe; ++k) cn[k] = t.column(kNodeNames[k]);
  const int cthick = t.column("Thick");
  const int cphi = t.column("PHI");
  if (cid < 0) return;
  for (std::size_t e = 0; e < t.size(); ++e) {
    const std::int64_t eid = t.ints[cid][e];
    blk.id.push_back(eid);
    blk.part.push_back(part);
    blk.thickness.push_back(cthick >= 0 ? t.reals[cthick][e] : 0.0);
    blk.phi.push_back(cphi >= 0 ? t.reals[cphi][e] : 0.0);
    pos.push_back(t.pos[e]);
    std::int64_t user[20] = {};
    for (int k = 0; k < npe; ++k) user[k] = cn[k] >= 0 ? t.ints[cn[k]][e] : 0;
    // A quad with n4 = 0 is a triangle written as a quad: n4 := n3.
    if (blk.type == model::ElementType::Shell4 && user[3] == 0) user[3] = user[2];
    const bool missing = append_element_nodes(b, blk, kind.keyword, eid, user, t.pos[e]);
    if (part != kNone) ++b.m_.parts[part].element_count;
    if (missing) continue;
    // Coordinates that could not be read are already reported; their geometry would only echo it.
    bool unreadable = false;
    for (int k = 0; k < npe; ++k) {
      const auto n = blk.conn[blk.conn.size() - static_cast<std::size_t>(npe) + static_cast<std::size_t>(k)];
      unreadable = unreadable || (n != kNone && b.node_bad_[n]);
    }
    if (unreadable) continue;
    // Geometry.
    const std::size_t base = blk.conn.size() - static_cast<std::size_t>(npe);
    const About ab{kind.keyword, eid};
    if (blk.type == model::ElementType::Tetra4)
      b.check_tetra(blk, base, t.pos[e], eid);
    else if (blk.type == model::ElementType::Brick20)
      check_brick20_shape(b, blk, base, t.pos[e], ab);
    else if (blk.type == model::ElementType::Brick8)
      check_brick_shape(b, blk, base, t.pos[e], ab);
    else if (blk.type == model::ElementType::Truss2 || blk.type == model::ElementType::Beam2)
      check_line_shape(b, blk, base, t.pos[e], ab);
    else
      check_shell_shape(b, blk, base, t.pos[e], cthick >= 0 ? t.fields[cthick]->first_col : 1, part, ab);
  }
}

// Tetrahedra share the bricks' id space (Radioss keeps both in one solid element table): a tetrahedron id
// that a brick has is an error.
void check_tetra_ids_against_bricks(ModelBuilder& b, const ElementKind& kind,
                                    const std::vector<SourcePos>& pos) {
  const auto& blk = *kind.block;
  for (std::size_t i = 0; i < blk.id.size(); ++i) {
    const auto other = b.m_.bricks.index.find(blk.id[i]);
    if (other < 0) continue;
    const SourcePos p = b.brick_pos_[static_cast<std::size_t>(other)];
    b.diags_.error(Diag::DuplicateId, b.at(pos[i], 1), About{kind.keyword, blk.id[i]},
                   "element id " + std::to_string(blk.id[i]) + " is already used by /BRICK at " +
                       b.deck_.files[p.file] + ":" + std::to_string(p.line) +
                       "; tetrahedra and bricks share one id space (solid elements), element ids must "
                       "be unique");
  }
}

// 20-node bricks share the solid id space with bricks and tetrahedra (one solid element table in Radioss).
void check_brick20_ids_against_solids(ModelBuilder& b, const ElementKind& kind,
                                      const std::vector<SourcePos>& pos) {
  const auto& blk = *kind.block;
  for (std::size_t i = 0; i < blk.id.size(); ++i) {
    for (const auto* other_blk : {&b.m_.bricks, &b.m_.tetras}) {
      const auto other = other_blk->index.find(blk.id[i]);
      if (other < 0) continue;
      const bool brick = other_blk == &b.m_.bricks;
      const SourcePos p = (brick ? b.brick_pos_ : b.tetra_pos_)[static_cast<std::size_t>(other)];
      b.diags_.error(Diag::DuplicateId, b.at(pos[i], 1), About{kind.keyword, blk.id[i]},
                     "element id " + std::to_string(blk.id[i]) + " is already used by " +
                         (brick ? "/BRICK" : "/TETRA4") + " at " + b.deck_.files[p.file] + ":" +
                         std::to_string(p.line) +
                         "; 20-node bricks, bricks and tetrahedra share one id space (solid elements), "
                         "element ids must be unique");
    }
  }
}

// The block's id index; every id used twice within it is an error, with both lines.
void index_element_ids(ModelBuilder& b, const ElementKind& kind, const std::vector<SourcePos>& pos) {
  auto& blk = *kind.block;
  std::int64_t dup = 0;
  if (blk.index.build(blk.id, dup)) return;
  std::unordered_map<std::int64_t, std::size_t> first;
  for (std::size_t i = 0; i < blk.id.size(); ++i) {
    const auto [it, ok] = first.emplace(blk.id[i], i);
    if (!ok) {
      const SourcePos p = pos[it->second];
      b.diags_.error(Diag::DuplicateId, b.at(pos[i], 1), About{kind.keyword, blk.id[i]},
                     "element id " + std::to_string(blk.id[i]) + " is already used at " +
                         b.deck_.files[p.file] + ":" + std::to_string(p.line) +
                         "; element ids must be unique");
    }
  }
}

}  // namespace

void ModelBuilder::build_elements() {
  const ElementKind kinds[] = {{"/SHELL", "shell_ID", &m_.shells, model::PropertyKind::Shell},
                               {"/SH3N", "tria_ID", &m_.shells3, model::PropertyKind::Shell},
                               {"/BRICK", "brick_ID", &m_.bricks, model::PropertyKind::Solid},
                               {"/TETRA4", "tetra_ID", &m_.tetras, model::PropertyKind::Solid},
                               {"/BRIC20", "brick20_ID", &m_.bricks20, model::PropertyKind::Solid},
                               {"/TRUSS", "truss_ID", &m_.trusses, model::PropertyKind::Truss},
                               {"/BEAM", "beam_ID", &m_.beams, model::PropertyKind::Beam}};
  for (const auto& kind : kinds) {
    std::vector<SourcePos> pos;
    for (const auto* r : deck_.of(kind.keyword)) read_element_records(*this, kind, *r, pos);
    if (kind.block->type == model::ElementType::Brick8) brick_pos_ = pos;
    // Element ids unique within the type; tetrahedra also share the bricks' id space.
    if (kind.block->type == model::ElementType::Tetra4) check_tetra_ids_against_bricks(*this, kind, pos);
    if (kind.block->type == model::ElementType::Tetra4) tetra_pos_ = pos;
    if (kind.block->type == model::ElementType::Brick20) check_brick20_ids_against_solids(*this, kind, pos);
    index_element_ids(*this, kind, pos);
  }
}

// A tetrahedron's nodes and volume, at the record of element `eid` whose nodes start at b.conn[base]:
// repeated nodes and a zero volume are errors; a negative volume (n1 n2 n3 turning the other way round)
// is renumbered by swapping n2 and n4, as OpenRadioss's reader does (hm_read_solid.F), with a warning so
// that the deck's author knows the model file's order is not the deck's.
void ModelBuilder::check_tetra(model::ElementBlock& b, std::size_t base, const SourcePos& pos,
                               std::int64_t eid) {
  const About ab{"/TETRA4", eid};
  auto X = [&](std::size_t k) {
    const auto n = static_cast<std::size_t>(b.conn[base + k]);
    return model::Vec3{m_.nodes.x[n], m_.nodes.y[n], m_.nodes.z[n]};
  };
  for (std::size_t k = 1; k < 4; ++k)
    for (std::size_t l = 0; l < k; ++l)
      if (b.conn[base + k] == b.conn[base + l]) {
        diags_.error(Diag::RepeatedNodeInElement, at(pos, 11 + 10 * static_cast<int>(k)), ab,
                     "tetrahedron " + std::to_string(eid) + " lists node " +
                         std::to_string(m_.nodes.id[static_cast<std::size_t>(b.conn[base + k])]) +
                         " twice (n" + std::to_string(l + 1) + " and n" + std::to_string(k + 1) +
                         "); a /TETRA4 needs 4 distinct nodes");
        return;
      }
  const double v = model::tetra_volume(X(0), X(1), X(2), X(3));
  // Flat relative to its size: the volume against the cube of the longest edge (a regular tetrahedron has
  // 0.118); below 1e-10 the gradients are rounding noise.
  double l_max = 0;
  for (std::size_t k = 1; k < 4; ++k)
    for (std::size_t l = 0; l < k; ++l) l_max = std::max(l_max, model::norm(model::sub(X(k), X(l))));
  if (!(std::abs(v) > 1e-10 * l_max * l_max * l_max)) {
    diags_.error(Diag::NonPositiveVolume, at(pos, 1), ab,
                 "tetrahedron " + std::to_string(eid) + " has zero volume (" + number_text(v) +
                     "): its 4 nodes lie in one plane; a /TETRA4 needs a positive volume");
    return;
  }
  if (v < 0) {
    std::swap(b.conn[base + 1], b.conn[base + 3]);
    diags_.warning(Diag::RenumberedTetra, at(pos, 1), ab,
                   "tetrahedron " + std::to_string(eid) + " has negative volume (" + number_text(v) +
                       ") in the order n1 n2 n3 n4: the right-hand normal of n1 n2 n3 points towards n4; "
                       "its nodes n2 and n4 are swapped, as Radioss does");
  }
}

void ModelBuilder::compute_masses() {
  model::compute_lumped_masses(m_);
  warn_massless_accelerometers();
}

// An accelerometer on a node that no element, added mass or rigid body gives mass to reads 0 for the
// whole run (the engine leaves a massless node's acceleration at 0): say so rather than write zeros.
void ModelBuilder::warn_massless_accelerometers() {
  std::vector<std::uint8_t> in_body(m_.nodes.id.size(), 0);
  for (const auto& rb : m_.rigid_bodies) {
    if (rb.main_node != kNone) in_body[static_cast<std::size_t>(rb.main_node)] = 1;
    for (const auto n : rb.secondary) in_body[static_cast<std::size_t>(n)] = 1;
  }
  for (const auto* r : deck_.of("/ACCEL")) {
    const auto it = accel_ids_.find(r->id);
    if (it == accel_ids_.end()) continue;
    const auto n = m_.accelerometers[static_cast<std::size_t>(it->second)].node;
    if (n == kNone || in_body[static_cast<std::size_t>(n)] || m_.node_mass[static_cast<std::size_t>(n)] > 0)
      continue;
    warning_at(*r, "node_ID", Diag::UnusedNode,
               "node " + std::to_string(m_.nodes.id[static_cast<std::size_t>(n)]) +
                   " carries no mass (no element, /ADMAS or rigid body): the accelerometer will read 0 for "
                   "the whole run");
  }
}

void ModelBuilder::check_unused_nodes() {
  std::size_t unused = 0;
  std::string first_ids;
  for (std::size_t n = 0; n < node_used_.size(); ++n) {
    if (node_used_[n]) continue;
    // A repeated node id is already an error; its second definition is unused by construction.
    if (m_.nodes.index.find(m_.nodes.id[n]) != static_cast<std::int32_t>(n)) continue;
    ++unused;
    if (unused <= 10) first_ids += (unused > 1 ? ", " : "") + std::to_string(m_.nodes.id[n]);
  }
  if (unused > 0) {
    const SourcePos p = node_pos_.empty() ? SourcePos{} : node_pos_[0];
    // One warning for all of them: a generated mesh can leave thousands and each would drown the rest.
    for (std::size_t n = 0; n < node_used_.size(); ++n) {
      if (!node_used_[n] && m_.nodes.index.find(m_.nodes.id[n]) == static_cast<std::int32_t>(n)) {
        diags_.warning(Diag::UnusedNode, at(node_pos_[n], 1), About{"/NODE", m_.nodes.id[n]},
                       std::to_string(unused) +
                           " node(s) are used by no element, rigid body or rigid wall (" + first_ids +
                           (unused > 10 ? ", ..." : "") +
                           "); they carry no mass and take no part in the run");
        break;
      }
    }
    (void)p;
  }
}

model::Model ModelBuilder::build() {
  m_.deck_version = deck_.version;
  m_.run_name = deck_.run_name;
  m_.units.mass = deck_.work_units.mass;
  m_.units.length = deck_.work_units.length;
  m_.units.time = deck_.work_units.time;
  m_.units.mass_name = deck_.work_units.mass_name;
  m_.units.length_name = deck_.work_units.length_name;
  m_.units.time_name = deck_.work_units.time_name;
  for (const auto* r : deck_.of("/TITLE")) m_.title = r->get_string("TITLE");
  for (const auto& r : deck_.records)
    if (r.decl->support == schema::Support::Ignored) m_.ignored_keywords.push_back(r.written);
  m_.substitutions = deck_.substitutions;
  build_nodes();
  build_materials();
  build_properties();
  build_subsets_and_parts();
  build_elements();  // element geometry is checked as written, before any transform
  build_springs();
  check_formulations();
  transform_submodels();  // /TRANSFORM with sub_ID: before anything that reads coordinates
  build_boxes();
  build_functions();
  move_functions();
  resolve_plas_tab_functions();
  resolve_foam_tab_functions();
  resolve_fail_tab_functions();
  resolve_fail_biquad_functions();
  resolve_spring_functions();
  build_element_groups();  // before surfaces and node groups, which are built from element groups
  build_sets();            // after the element groups: a set is one where no group has its id
  build_surfaces();        // before the groups: /GRNOD/SURF takes the nodes of surfaces
  build_groups();
  transform_node_groups();      // /TRANSFORM with grnod_ID: on the groups just built, in deck order
  apply_random_perturbation();  // on the placed nodes, before anything reads positions
  build_skews();                // after every move: a /SKEW/MOV takes its frame from its nodes
  resolve_spring_skews();
  build_sensors();
  build_loads();
  build_rigid_walls();
  build_rigid_bodies();
  build_rigid_material_bodies();  // after the /RBODY: its added main nodes come last
  build_interfaces();
  build_tied_interfaces();
  build_contact_laws();
  build_sections();
  build_time_histories();
  compute_masses();
  check_unused_nodes();
  return std::move(m_);
}

}  // namespace detail

model::Model build_model(const Deck& deck, Diagnostics& diags) {
  detail::ModelBuilder b(deck, diags);
  return b.build();
}

}  // namespace radx
