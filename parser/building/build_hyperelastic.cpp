// /MAT/OGDEN (law 42): reading its cards and checking the elements and formulations it is used with.
//
// Read as OpenRadioss hm_read_mat42.F does: nu 0 means 0.495; the terms with mu_p = 0 are dropped and the
// others kept in the deck's order; G = sum mu_p alpha_p (twice the initial shear modulus) must be > 0;
// K = G (1 + nu) / (3 (1 - 2 nu)); sigma_cut <= 0 means 1e20; Iform 0 means 1. radx refuses nu = 0.5
// (OpenRadioss divides by max(1e-20, 1 - 2 nu): an infinite bulk modulus), the Prony series (M > 0) and the
// tabulated bulk (fct_IDbulk), both by the fields' rules (keywords_starter.cpp).
//
// Elements: law 42 needs the total deformation gradient, which radx carries only in the one-point brick
// (Isolid 1 and 2, either frame; solver/elements/solid/hex8_fb.cpp). Shells, tetrahedra and the other brick
// formulations with law 42 are refused by name (RX510), and so is Ismstr 2 (the small-strain switch would
// freeze the geometry the total stretch is measured on).
#include <string>

#include "parser/building/model_builder.hpp"
#include "parser/reading/field_parse.hpp"

namespace radx::detail {

void ModelBuilder::read_ogden(const KeywordRecord& r, model::Material& mat) {
  read_densities(r, mat);
  mat.poisson = r.get_real("nu");  // 0 -> 0.495 by the field's rule
  if (mat.poisson < 0 || mat.poisson >= 0.5)
    error_at(
        r, "nu", Diag::BadPoisson,
        "Poisson's ratio nu = " + number_text(mat.poisson) +
            " is outside [0, 0.5): the bulk modulus G (1 + nu) / 3 (1 - 2 nu) would be infinite or negative "
            "(OpenRadioss takes 1e-20 for 1 - 2 nu; radx asks for the value you mean, e.g. 0.4999)");
  auto& o = mat.ogden;
  o.sig_cut = r.get_real("sigma_cut");
  if (o.sig_cut <= 0) o.sig_cut = 1e20;
  o.iform = static_cast<int>(r.get_int("Iform"));
  if (o.iform == 0) o.iform = 1;
  static constexpr const char* kMu[] = {"mu_1", "mu_2", "mu_3", "mu_4", "mu_5",
                                        "mu_6", "mu_7", "mu_8", "mu_9", "mu_10"};
  static constexpr const char* kAlpha[] = {"alpha_1", "alpha_2", "alpha_3", "alpha_4", "alpha_5",
                                           "alpha_6", "alpha_7", "alpha_8", "alpha_9", "alpha_10"};
  double g = 0;  // sum mu_p alpha_p
  for (int p = 0; p < 10; ++p) {
    const double mu = r.get_real(kMu[p]);
    const double alpha = r.get_real(kAlpha[p]);
    if (mu == 0) continue;
    if (alpha == 0)
      error_at(
          r, kAlpha[p], Diag::InconsistentValues,
          std::string(kMu[p]) + " = " + number_text(mu) + " with " + kAlpha[p] +
              " = 0: a term with a zero exponent has no stiffness and an undefined energy mu_p / alpha_p; "
              "give its exponent or set its mu to 0");
    o.mu.push_back(mu);
    o.alpha.push_back(alpha);
    g += mu * alpha;
  }
  if (!(g > 0))
    error_at(r, "mu_1", Diag::InconsistentValues,
             "sum mu_p alpha_p = " + number_text(g) +
                 " must be > 0: it is twice the initial shear modulus, the sum of each term's contribution "
                 "mu_p alpha_p");
  mat.shear = 0.5 * g;
  const double nu = mat.poisson;
  mat.bulk = nu < 0.5 ? g * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu)) : 0.0;
  mat.young = g * (1.0 + nu);  // 2 G0 (1 + nu): the contact stiffness and the listing
}

void ModelBuilder::check_ogden_parts() {
  std::vector<std::uint8_t> other_part(m_.parts.size(), 0), brick_part(m_.parts.size(), 0);
  for (const auto* b : {&m_.shells, &m_.shells3, &m_.tetras, &m_.bricks20})
    for (const auto p : b->part)
      if (p >= 0 && static_cast<std::size_t>(p) < other_part.size())
        other_part[static_cast<std::size_t>(p)] = 1;
  for (const auto p : m_.bricks.part)
    if (p >= 0 && static_cast<std::size_t>(p) < brick_part.size())
      brick_part[static_cast<std::size_t>(p)] = 1;
  for (std::size_t p = 0; p < m_.parts.size(); ++p) {
    const auto& part = m_.parts[p];
    if (part.material < 0 || part.property < 0) continue;
    const auto& mat = m_.materials[static_cast<std::size_t>(part.material)];
    const bool ogden = mat.law == model::MaterialLaw::Ogden;
    const bool foam = mat.law == model::MaterialLaw::FoamTab;
    if (!ogden && !foam) continue;
    const std::string law = ogden ? "law 42" : "law 70";
    const std::string_view mat_path = ogden ? "/MAT/LAW42" : "/MAT/LAW70";
    const auto& prop = m_.properties[static_cast<std::size_t>(part.property)];
    const std::string who =
        mat.keyword + " " + std::to_string(mat.id) + " in part " + std::to_string(part.id);
    for (const auto& rec : deck_.records) {
      const auto path = rec.decl->path;
      if (other_part[p] && path == mat_path && rec.id == mat.id)
        diags_.error(
            Diag::PhysicsNotImplemented, at(rec.pos), about(rec),
            who + " has shells, tetrahedra or 20-node bricks: radx implements " + law +
                " on 8-node bricks of Isolid 1 or 2 only (the one-point brick carries the total deformation "
                "gradient)");
      if (!brick_part[p] || path != "/PROP/SOLID" || rec.id != prop.id) continue;
      const auto& s = prop.solid;
      if (s.isolid != 1 && s.isolid != 2)
        error_at(rec, "Isolid", Diag::PhysicsNotImplemented,
                 "Isolid " + std::to_string(s.isolid) + " with " + who + ": radx implements " + law +
                     " on the one-point brick only (Isolid 1 or 2, with Iframe 1 or 2)");
      if (ogden && s.ismstr != 4)
        error_at(rec, "Ismstr", Diag::PhysicsNotImplemented,
                 "Ismstr " + std::to_string(s.ismstr) + " with " + who +
                     ": law 42's stretch is measured from the initial geometry (Ismstr 4, the default); the "
                     "small-strain switch of Ismstr 2 is not implemented for it");
      // Law 70: OpenRadioss keeps Ismstr 1 (small strain on the initial geometry) and runs every other
      // value as the total strain of Ismstr 11, which radx measures from the stretches (law70_foam_tab.cpp).
      // Ismstr 1 is refused for every brick by check_formulations.cpp (or run as 4 under
      // --allow-substitutions, which for law 70 is OpenRadioss's total strain).
    }
  }
}

}  // namespace radx::detail
