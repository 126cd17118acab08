// The schema of the model file's /radx part (docs/model-file.md section 5), internal to io/hdf5: for every
// Model struct the list of its members as (name, member pointer), in declaration order, and the collections
// and element blocks of the Model with their group names. It drives the writer and the reader of
// model_file.cpp in both directions, and the checks of model_file_checks.cpp, which name a bad value by its
// dataset. Not part of the public io interface.
#pragma once

#include <array>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "solver/model/model.hpp"

namespace radx::io::schema {

template <class M>
inline constexpr bool kIsVector = false;
template <class E>
inline constexpr bool kIsVector<std::vector<E>> = true;
template <class M>
inline constexpr bool kIsArray = false;
template <class E, std::size_t K>
inline constexpr bool kIsArray<std::array<E, K>> = true;

// Schemas: (name, member pointer) for every member of every Model struct, in declaration order.

template <class S, class M>
struct Field {
  const char* name;
  M S::*member;
};
template <class S, class M>
constexpr Field<S, M> field(const char* name, M S::*member) {
  return {name, member};
}

template <class S>
struct Schema {};

template <class M>
concept Record = requires {
  Schema<M>::fields;
};

template <class S, class Fn>
void for_each_field(Fn&& fn) {
  std::apply([&](const auto&... f) { (fn(f.name, f.member), ...); }, Schema<S>::fields);
}

// Number of members of an aggregate: the largest N for which S{x1, ..., xN} compiles, each x converting
// to anything. Lets the compiler check that a Schema lists every member: a member added to model.hpp
// and not here is a compile error, not a field silently missing from the file.
struct AnyValue {
  template <class T>
  operator T() const;  // NOLINT: declared only, used in unevaluated context
};
template <class S, std::size_t... I>
constexpr bool brace_initializable(std::index_sequence<I...>) {
  return requires {
    S{(void(I), AnyValue{})...};
  };
}
template <class S, std::size_t N = 0>
constexpr std::size_t member_count() {
  if constexpr (brace_initializable<S>(std::make_index_sequence<N + 1>())) {
    return member_count<S, N + 1>();
  } else {
    return N;
  }
}

#define RADX_FIELD(m) field(#m, &S::m)
#define RADX_SCHEMA(Type, ...)                                                                           \
  template <>                                                                                            \
  struct Schema<model::Type> {                                                                           \
    using S = model::Type;                                                                               \
    static constexpr auto fields = std::make_tuple(__VA_ARGS__);                                         \
  };                                                                                                     \
  static_assert(std::tuple_size_v<decltype(Schema<model::Type>::fields)> == member_count<model::Type>(), \
                "the Schema of " #Type " must list every member of model::" #Type                        \
                " (then update docs/model-file.md and kModelFormatVersion)")

RADX_SCHEMA(Units, RADX_FIELD(mass), RADX_FIELD(length), RADX_FIELD(time), RADX_FIELD(mass_name),
            RADX_FIELD(length_name), RADX_FIELD(time_name));
RADX_SCHEMA(PlasTab, RADX_FIELD(function_id), RADX_FIELD(function), RADX_FIELD(scale), RADX_FIELD(rate),
            RADX_FIELD(fsmooth), RADX_FIELD(vp));
RADX_SCHEMA(PlasBrit, RADX_FIELD(eps_t1), RADX_FIELD(eps_m1), RADX_FIELD(d_max1), RADX_FIELD(eps_f1),
            RADX_FIELD(eps_t2), RADX_FIELD(eps_m2), RADX_FIELD(d_max2), RADX_FIELD(eps_f2));
RADX_SCHEMA(Ogden, RADX_FIELD(mu), RADX_FIELD(alpha), RADX_FIELD(sig_cut), RADX_FIELD(iform));
RADX_SCHEMA(FoamTab, RADX_FIELD(load_function_id), RADX_FIELD(load_function), RADX_FIELD(load_scale),
            RADX_FIELD(load_rate), RADX_FIELD(unload_function_id), RADX_FIELD(unload_function),
            RADX_FIELD(unload_scale), RADX_FIELD(unload_rate), RADX_FIELD(e_max), RADX_FIELD(eps_max),
            RADX_FIELD(itens), RADX_FIELD(tens_function_id), RADX_FIELD(tens_function),
            RADX_FIELD(tens_scale), RADX_FIELD(israte), RADX_FIELD(iflag), RADX_FIELD(shape),
            RADX_FIELD(hys));
RADX_SCHEMA(FailJohnson, RADX_FIELD(on), RADX_FIELD(fail_id), RADX_FIELD(d1), RADX_FIELD(d2), RADX_FIELD(d3),
            RADX_FIELD(d4), RADX_FIELD(d5), RADX_FIELD(eps_dot_0), RADX_FIELD(eps_f_min), RADX_FIELD(dadv),
            RADX_FIELD(ifail_sh), RADX_FIELD(ifail_so));
RADX_SCHEMA(FailTab, RADX_FIELD(on), RADX_FIELD(fail_id), RADX_FIELD(ifail_sh), RADX_FIELD(ifail_so),
            RADX_FIELD(p_thickfail), RADX_FIELD(dcrit), RADX_FIELD(d), RADX_FIELD(n), RADX_FIELD(function_id),
            RADX_FIELD(function), RADX_FIELD(scale), RADX_FIELD(rate), RADX_FIELD(size_function_id),
            RADX_FIELD(size_function), RADX_FIELD(size_scale), RADX_FIELD(el_ref),
            RADX_FIELD(temp_function_id), RADX_FIELD(temp_factor));
RADX_SCHEMA(FailBiquad, RADX_FIELD(on), RADX_FIELD(fail_id), RADX_FIELD(c1), RADX_FIELD(c2), RADX_FIELD(c3),
            RADX_FIELD(c4), RADX_FIELD(c5), RADX_FIELD(m_flag), RADX_FIELD(s_flag), RADX_FIELD(inst_start),
            RADX_FIELD(p_thickfail), RADX_FIELD(size_function_id), RADX_FIELD(size_function),
            RADX_FIELD(el_ref));
RADX_SCHEMA(Material, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(law), RADX_FIELD(keyword),
            RADX_FIELD(rho), RADX_FIELD(rho_ref), RADX_FIELD(young), RADX_FIELD(poisson), RADX_FIELD(shear),
            RADX_FIELD(bulk), RADX_FIELD(iflag), RADX_FIELD(flag_vp), RADX_FIELD(icc), RADX_FIELD(fsmooth),
            RADX_FIELD(a), RADX_FIELD(b), RADX_FIELD(n), RADX_FIELD(eps_p_max), RADX_FIELD(sig_max0),
            RADX_FIELD(sig_y_input), RADX_FIELD(uts), RADX_FIELD(e_uts), RADX_FIELD(c), RADX_FIELD(eps_dot_0),
            RADX_FIELD(f_cut), RADX_FIELD(chard), RADX_FIELD(p_min), RADX_FIELD(m_temp), RADX_FIELD(t_melt),
            RADX_FIELD(rho_cp), RADX_FIELD(t_ref), RADX_FIELD(t_max), RADX_FIELD(tab), RADX_FIELD(fail_jc),
            RADX_FIELD(fail_tab), RADX_FIELD(fail_bq), RADX_FIELD(brit), RADX_FIELD(ogden), RADX_FIELD(foam));
RADX_SCHEMA(ShellProperty, RADX_FIELD(ishell), RADX_FIELD(ismstr), RADX_FIELD(ish3n), RADX_FIELD(idrill),
            RADX_FIELD(ipinch), RADX_FIELD(n_ip), RADX_FIELD(ithick), RADX_FIELD(iplas), RADX_FIELD(ipos),
            RADX_FIELD(p_thick_fail), RADX_FIELD(hm), RADX_FIELD(hf), RADX_FIELD(hr), RADX_FIELD(dm),
            RADX_FIELD(dn), RADX_FIELD(thickness), RADX_FIELD(ashear));
RADX_SCHEMA(SolidProperty, RADX_FIELD(isolid), RADX_FIELD(ismstr), RADX_FIELD(icpre), RADX_FIELD(iframe),
            RADX_FIELD(inpts), RADX_FIELD(itetra4), RADX_FIELD(itetra10), RADX_FIELD(iale), RADX_FIELD(qa),
            RADX_FIELD(qb), RADX_FIELD(h), RADX_FIELD(lambda_v), RADX_FIELD(mu_v), RADX_FIELD(dn),
            RADX_FIELD(dt_min), RADX_FIELD(q_default));
RADX_SCHEMA(SpringLaw, RADX_FIELD(stiffness), RADX_FIELD(damping), RADX_FIELD(a), RADX_FIELD(b),
            RADX_FIELD(d), RADX_FIELD(e), RADX_FIELD(hardening), RADX_FIELD(f_load), RADX_FIELD(f_damp),
            RADX_FIELD(f_unload), RADX_FIELD(f_damp4), RADX_FIELD(fscale), RADX_FIELD(ascale),
            RADX_FIELD(hscale), RADX_FIELD(delta_min), RADX_FIELD(delta_max));
RADX_SCHEMA(SpringProperty, RADX_FIELD(type), RADX_FIELD(mass), RADX_FIELD(inertia), RADX_FIELD(ileng),
            RADX_FIELD(sensor), RADX_FIELD(skew), RADX_FIELD(ifail), RADX_FIELD(x), RADX_FIELD(y),
            RADX_FIELD(z), RADX_FIELD(rx), RADX_FIELD(ry), RADX_FIELD(rz));
RADX_SCHEMA(TrussProperty, RADX_FIELD(area));
RADX_SCHEMA(BeamProperty, RADX_FIELD(area), RADX_FIELD(iyy), RADX_FIELD(izz), RADX_FIELD(ixx), RADX_FIELD(dm),
            RADX_FIELD(df), RADX_FIELD(ishear), RADX_FIELD(ismstr), RADX_FIELD(release_x),
            RADX_FIELD(release_y1), RADX_FIELD(release_z1), RADX_FIELD(release_y2), RADX_FIELD(release_z2));
RADX_SCHEMA(Property, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(kind), RADX_FIELD(shell),
            RADX_FIELD(solid), RADX_FIELD(spring), RADX_FIELD(truss), RADX_FIELD(beam));
RADX_SCHEMA(Part, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(property), RADX_FIELD(material),
            RADX_FIELD(subset), RADX_FIELD(contact_thickness), RADX_FIELD(mass), RADX_FIELD(element_count));
RADX_SCHEMA(Subset, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(children), RADX_FIELD(parts));
RADX_SCHEMA(NodeGroup, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(kind), RADX_FIELD(nodes));
RADX_SCHEMA(Box, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(shape), RADX_FIELD(p1), RADX_FIELD(p2),
            RADX_FIELD(diameter));
RADX_SCHEMA(Surface, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(kind), RADX_FIELD(segments),
            RADX_FIELD(owner_type), RADX_FIELD(owner));
RADX_SCHEMA(Function, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(x), RADX_FIELD(y));
RADX_SCHEMA(BoundaryCondition, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(fixed), RADX_FIELD(skew),
            RADX_FIELD(group));
RADX_SCHEMA(ImposedVelocity, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(function), RADX_FIELD(dir),
            RADX_FIELD(skew), RADX_FIELD(sensor), RADX_FIELD(frame), RADX_FIELD(icoor), RADX_FIELD(group),
            RADX_FIELD(ascale_x), RADX_FIELD(fscale_y), RADX_FIELD(t_start), RADX_FIELD(t_stop),
            RADX_FIELD(displacement));
RADX_SCHEMA(ImposedFinalGeometry, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(function), RADX_FIELD(sensor),
            RADX_FIELD(ascale_x), RADX_FIELD(t_start), RADX_FIELD(t_stop), RADX_FIELD(nodes),
            RADX_FIELD(targets));
RADX_SCHEMA(Skew, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(origin), RADX_FIELD(axes), RADX_FIELD(n1),
            RADX_FIELD(n2), RADX_FIELD(n3), RADX_FIELD(dir), RADX_FIELD(frame));
RADX_SCHEMA(AddedMass, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(type), RADX_FIELD(mass),
            RADX_FIELD(group));
RADX_SCHEMA(InitialVelocity, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(v), RADX_FIELD(group),
            RADX_FIELD(skew), RADX_FIELD(sensor), RADX_FIELD(t_start), RADX_FIELD(rotational));
RADX_SCHEMA(ConcentratedLoad, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(function), RADX_FIELD(dir),
            RADX_FIELD(skew), RADX_FIELD(sensor), RADX_FIELD(group), RADX_FIELD(itypfun),
            RADX_FIELD(ascale_x), RADX_FIELD(fscale_y));
RADX_SCHEMA(PressureLoad, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(surface), RADX_FIELD(function),
            RADX_FIELD(sensor), RADX_FIELD(ipinch), RADX_FIELD(idel), RADX_FIELD(itypfun),
            RADX_FIELD(ascale_x), RADX_FIELD(fscale_y));
RADX_SCHEMA(Gravity, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(function), RADX_FIELD(dir),
            RADX_FIELD(skew), RADX_FIELD(sensor), RADX_FIELD(group), RADX_FIELD(ascale_x),
            RADX_FIELD(fscale_y));
RADX_SCHEMA(RigidWall, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(node), RADX_FIELD(slide),
            RADX_FIELD(iform), RADX_FIELD(ifq), RADX_FIELD(group1), RADX_FIELD(group2), RADX_FIELD(distance),
            RADX_FIELD(friction), RADX_FIELD(diameter), RADX_FIELD(ffac), RADX_FIELD(mass), RADX_FIELD(m),
            RADX_FIELD(m1), RADX_FIELD(v0), RADX_FIELD(normal), RADX_FIELD(secondary), RADX_FIELD(shape),
            RADX_FIELD(m2));
RADX_SCHEMA(RigidBody, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(main_node), RADX_FIELD(sensor),
            RADX_FIELD(skew), RADX_FIELD(ispher), RADX_FIELD(ikrem), RADX_FIELD(icog), RADX_FIELD(ioptoff),
            RADX_FIELD(iexpams), RADX_FIELD(ifail), RADX_FIELD(mass), RADX_FIELD(inertia), RADX_FIELD(fn),
            RADX_FIELD(ft), RADX_FIELD(exp_n), RADX_FIELD(exp_t), RADX_FIELD(group), RADX_FIELD(surface),
            RADX_FIELD(secondary), RADX_FIELD(rigid_material));
RADX_SCHEMA(Accelerometer, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(node), RADX_FIELD(skew),
            RADX_FIELD(fcut));
RADX_SCHEMA(Sensor, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(type), RADX_FIELD(t_delay),
            RADX_FIELD(t_stop));
RADX_SCHEMA(Section, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(n1), RADX_FIELD(n2), RADX_FIELD(n3),
            RADX_FIELD(node_group), RADX_FIELD(iframe), RADX_FIELD(nodes), RADX_FIELD(shells),
            RADX_FIELD(shells3), RADX_FIELD(bricks), RADX_FIELD(trusses), RADX_FIELD(beams));
RADX_SCHEMA(TimeHistoryGroup, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(kind), RADX_FIELD(variables),
            RADX_FIELD(objects), RADX_FIELD(skews));
RADX_SCHEMA(ContactLaw, RADX_FIELD(normal), RADX_FIELD(friction), RADX_FIELD(bidirectional), RADX_FIELD(kc),
            RADX_FIELD(pz), RADX_FIELD(lambda), RADX_FIELD(pe), RADX_FIELD(kc_max), RADX_FIELD(curve),
            RADX_FIELD(cubic), RADX_FIELD(power_m), RADX_FIELD(power_k), RADX_FIELD(mu), RADX_FIELD(ct),
            RADX_FIELD(kappa));
RADX_SCHEMA(TiedInterface, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(secondary_group),
            RADX_FIELD(main_surface), RADX_FIELD(ignore), RADX_FIELD(spotflag), RADX_FIELD(level),
            RADX_FIELD(isearch), RADX_FIELD(idel2), RADX_FIELD(dsearch), RADX_FIELD(search_distance),
            RADX_FIELD(tie_node), RADX_FIELD(tie_segment), RADX_FIELD(tie_r), RADX_FIELD(tie_s),
            RADX_FIELD(tie_offset), RADX_FIELD(not_found));
RADX_SCHEMA(Interface, RADX_FIELD(id), RADX_FIELD(title), RADX_FIELD(lagdt), RADX_FIELD(secondary_group),
            RADX_FIELD(main_surface), RADX_FIELD(istf), RADX_FIELD(igap), RADX_FIELD(ibag), RADX_FIELD(idel),
            RADX_FIELD(ithe), RADX_FIELD(icurv), RADX_FIELD(iadm), RADX_FIELD(itied), RADX_FIELD(ists),
            RADX_FIELD(fscale_gap), RADX_FIELD(gap_max), RADX_FIELD(fpenmax), RADX_FIELD(stmin),
            RADX_FIELD(stmax), RADX_FIELD(mesh_size_pct), RADX_FIELD(dt_min), RADX_FIELD(irem_gap),
            RADX_FIELD(irem_i2), RADX_FIELD(stfac), RADX_FIELD(fric), RADX_FIELD(gapmin_input),
            RADX_FIELD(t_start), RADX_FIELD(t_stop), RADX_FIELD(ibc), RADX_FIELD(inacti), RADX_FIELD(vis_s),
            RADX_FIELD(vis_f), RADX_FIELD(bumult), RADX_FIELD(ifric), RADX_FIELD(ifiltr), RADX_FIELD(iform),
            RADX_FIELD(xfreq), RADX_FIELD(c), RADX_FIELD(sens_id), RADX_FIELD(fct_id_f), RADX_FIELD(fric_id),
            RADX_FIELD(ascale_f), RADX_FIELD(contact_law_id), RADX_FIELD(contact_law), RADX_FIELD(law),
            RADX_FIELD(secondary_nodes), RADX_FIELD(gapmin), RADX_FIELD(gapmin_automatic),
            RADX_FIELD(gap_node), RADX_FIELD(gap_segment), RADX_FIELD(stiff_node), RADX_FIELD(stiff_segment),
            RADX_FIELD(gap_lo), RADX_FIELD(gap_hi), RADX_FIELD(stiff_lo), RADX_FIELD(stiff_hi),
            RADX_FIELD(initial_penetrations), RADX_FIELD(max_initial_penetration),
            RADX_FIELD(max_penetration_node), RADX_FIELD(inactive_nodes), RADX_FIELD(inactive_segments),
            RADX_FIELD(penetrating_nodes), RADX_FIELD(initial_gap_reduction), RADX_FIELD(tributary_area));

#undef RADX_SCHEMA
#undef RADX_FIELD

// Written member by member below (write_radx, read_file, write_block, read_block): a new member of these
// structs must be added there.
static_assert(member_count<model::Model>() == 42, "model::Model changed: update write_radx and read_file");
static_assert(member_count<model::Nodes>() == 5, "model::Nodes changed: update write_radx and read_file");
static_assert(member_count<model::ElementBlock>() == 7, "model::ElementBlock changed: update write_block");

// The collections of the Model: table groups under /radx (one column per member) ...
template <class ModelT, class Fn>
void for_each_table(ModelT& m, Fn&& fn) {
  fn("materials", m.materials);
  fn("properties", m.properties);
  fn("parts", m.parts);
  fn("subsets", m.subsets);
  fn("node_groups", m.node_groups);
  fn("boxes", m.boxes);
  fn("surfaces", m.surfaces);
  fn("functions", m.functions);
  fn("bcs", m.bcs);
  fn("imposed_velocities", m.imposed_velocities);
  fn("imposed_final_geometries", m.imposed_final_geometries);
  fn("initial_velocities", m.initial_velocities);
  fn("concentrated_loads", m.concentrated_loads);
  fn("pressure_loads", m.pressure_loads);
  fn("gravities", m.gravities);
  fn("rigid_walls", m.rigid_walls);
  fn("rigid_bodies", m.rigid_bodies);
  fn("added_masses", m.added_masses);
  fn("skews", m.skews);
  fn("sections", m.sections);
  fn("accelerometers", m.accelerometers);
  fn("sensors", m.sensors);
  fn("time_histories", m.time_histories);
  fn("tied_interfaces", m.tied_interfaces);
}

// ... and the element blocks under /radx/elements.
template <class ModelT, class Fn>
void for_each_block(ModelT& m, Fn&& fn) {
  fn("shell4", m.shells);
  fn("shell3", m.shells3);
  fn("brick8", m.bricks);
  fn("tetra4", m.tetras);
  fn("brick20", m.bricks20);
  fn("spring2", m.springs);
  fn("truss2", m.trusses);
  fn("beam2", m.beams);
}

}  // namespace radx::io::schema
