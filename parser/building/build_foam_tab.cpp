// /MAT/FOAM_TAB (law 70): reading its cards and checking its curves.
//
// Read as OpenRadioss hm_read_mat70.F does: RHO_ref 0 takes RHO_I; Eps_max 0 means 1; Emax below E0 is
// dropped (then the largest slope of the loading curves, a warning); Fcut > 0 turns the rate filter on;
// the loading curves are sorted by rate and the first takes rate 0 (a warning when it was not); with no
// unloading curve and Iflag <= 2 the first loading curve unloads and Iflag becomes 0 (a warning); Shape and
// Hys 0 mean 1 (the fields' rules). radx refuses, where OpenRadioss goes on: two loading (or two unloading)
// curves at the same rate (OpenRadioss refuses it for unloading curves only, and drops exact repeats). Curves
// and tables of more than 100 points are thinned by the engine as OpenRadioss thins them
// (solver/model/foam_table.hpp).
// The elements law 70 runs on are checked with law 42's (build_hyperelastic.cpp).
#include <string>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx::detail {

void ModelBuilder::read_foam_tab(const KeywordRecord& r, model::Material& mat) {
  read_densities(r, mat);
  read_isotropic_elastic(
      r, mat, "E0", "law 70's Hooke matrix E (1 - nu) / ((1 + nu)(1 - 2 nu)) would be infinite or negative");
  auto& f = mat.foam;
  f.e_max = r.get_real("E_max");
  if (f.e_max > 0 && f.e_max < mat.young) {
    warning_at(
        r, "E_max", Diag::DefaultApplied,
        "E_max = " + number_text(f.e_max) + " is below E0 = " + number_text(mat.young) +
            ": it is dropped and the largest slope of the loading curves taken instead, as OpenRadioss "
            "does");
    f.e_max = 0;
  }
  f.eps_max = r.get_real("Eps_max");  // 0 -> 1 by the field's rule
  f.itens = static_cast<int>(r.get_int("Itens"));
  mat.f_cut = r.get_real("Fcut");
  f.israte = static_cast<int>(r.get_int("Ismooth"));
  if (mat.f_cut > 0) f.israte = 1;
  f.iflag = static_cast<int>(r.get_int("Iflag"));
  f.shape = r.get_real("Shape");
  f.hys = r.get_real("Hys");
  const auto nl = static_cast<int>(std::clamp<std::int64_t>(r.get_int("Nload"), 0, 10));
  const auto nu = static_cast<int>(std::clamp<std::int64_t>(r.get_int("Nunload"), 0, 10));
  auto read_list = [&](bool load, int n, std::vector<std::int64_t>& ids, std::vector<std::int32_t>& dense,
                       std::vector<double>& scale, std::vector<double>& rate) {
    const std::string what = load ? "load" : "unload";
    const std::string tag = load ? "L" : "U";
    for (int i = 0; i < n; ++i) {
      const std::string k = std::to_string(i + 1);
      const std::string fid = "fct_" + tag + k, fs = "scale_" + tag + k, fr = "rate_" + tag + k;
      ids.push_back(r.get_int(fid));
      dense.push_back(model::kNone);
      scale.push_back(r.get_real(fs));
      rate.push_back(r.get_real(fr));
      if (ids.back() <= 0)
        error_at(r, fid, Diag::RequiredIdMissing,
                 what + "ing curve " + k + " of " + std::to_string(n) + ": " + fid + " = " +
                     std::to_string(ids.back()) + "; each curve needs the id of a /FUNCT");
      for (int j = 0; j < i; ++j)
        if (rate[static_cast<std::size_t>(j)] == rate.back())
          error_at(r, fr, Diag::InconsistentValues,
                   what + "ing curves " + std::to_string(j + 1) + " and " + k +
                       " have the same strain rate " + number_text(rate.back()) +
                       ": the curves of a table need distinct rates (give each its own rate or drop one)");
    }
  };
  read_list(true, nl, f.load_function_id, f.load_function, f.load_scale, f.load_rate);
  read_list(false, nu, f.unload_function_id, f.unload_function, f.unload_scale, f.unload_rate);
  if (nl > 1) {
    double lowest = f.load_rate[0];
    for (double v : f.load_rate) lowest = std::min(lowest, v);
    if (lowest != 0)
      warning_at(r, "rate_L1", Diag::DefaultApplied,
                 "the lowest loading rate is " + number_text(lowest) +
                     ": its curve is the static one and is taken at rate 0, as OpenRadioss does");
  }
  if (nu == 0 && f.iflag <= 2) {
    if (f.iflag != 0)
      warning_at(r, "Iflag", Diag::DefaultApplied,
                 "Iflag = " + std::to_string(f.iflag) +
                     " without an unloading curve: the first loading curve unloads and Iflag is 0, as "
                     "OpenRadioss does");
    f.iflag = 0;
  }
  if (f.itens == 1) {
    f.tens_function_id = r.get_int("fctIDTens");
    f.tens_scale = r.get_real("FscaleTens");
    if (f.tens_function_id <= 0)
      error_at(r, "fctIDTens", Diag::RequiredIdMissing,
               "Itens = 1 needs the id of the /FUNCT of the tension factor (fctIDTens = " +
                   std::to_string(f.tens_function_id) + ")");
  }
}

void ModelBuilder::resolve_foam_tab_functions() {
  for (const auto& r : deck_.records) {
    if (r.decl->path != "/MAT/LAW70") continue;
    const auto it = mat_ids_.find(r.id);
    if (it == mat_ids_.end()) continue;
    auto& mat = m_.materials[static_cast<std::size_t>(it->second)];
    if (mat.law != model::MaterialLaw::FoamTab || mat.title != r.title) continue;  // a duplicate id
    auto& f = mat.foam;
    auto resolve = [&](const std::vector<std::int64_t>& ids, std::vector<std::int32_t>& dense,
                       const char* base, const char* what) {
      for (std::size_t i = 0; i < ids.size(); ++i) {
        if (ids[i] <= 0) continue;  // reported by read_foam_tab
        dense[i] = ref(funct_ids_, r, base + std::to_string(i + 1), what, "/FUNCT", false);
      }
    };
    resolve(f.load_function_id, f.load_function, "fct_L", "loading curve");
    resolve(f.unload_function_id, f.unload_function, "fct_U", "unloading curve");
    if (f.itens == 1 && f.tens_function_id > 0)
      f.tens_function = ref(funct_ids_, r, "fctIDTens", "tension factor curve", "/FUNCT", false);
  }
}

}  // namespace radx::detail
