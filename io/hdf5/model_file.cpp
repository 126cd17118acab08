// Model file writer and reader (layout: docs/model-file.md; VTKHDF part:
// docs/theory/results-format.md section 2).
//
// How the code is organised:
// - HDF5 calls go through the helpers of io/hdf5/hdf5_util.hpp (Handle, check, typed datasets and
//   attributes), which throw h5::Failure with the path of the HDF5 object and the innermost message of
//   the HDF5 error stack. write_model_file / read_model_file catch it and return false: nothing else
//   escapes.
// - The /VTKHDF mesh is written by io/hdf5/vtkhdf_mesh.cpp, shared with the result mesh file P.mesh.hdf.
// - Schema<S>: one table per Model struct of (member name, member pointer). It drives both directions:
//   a collection (vector of records) is written as a "table" group: attribute count, one dataset per
//   member (a column), variable-length members as CSR (values + <name>_offsets), nested structs
//   flattened as <outer>_<inner>. Interfaces and Units are written one group per record: scalars as
//   attributes, vectors as datasets.
// - Big arrays (points, connectivity, element blocks) are written with one H5Dwrite each, in checksummed
//   chunks, no fill, no conversion (memory and file types are both little-endian).
#include "io/hdf5/model_file.hpp"

#include <hdf5.h>

#include <array>
#include <filesystem>
#include <limits>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "io/hdf5/hdf5_util.hpp"
#include "io/hdf5/vtkhdf_mesh.hpp"

#ifndef RADX_VERSION
#define RADX_VERSION "unknown"
#endif

namespace radx::io {

namespace {

namespace fs = std::filesystem;
using model::Model;
// The generic HDF5 helpers are this file's vocabulary: used unqualified.
using namespace radx::io::h5;  // NOLINT(google-build-using-namespace)

// ---------------------------------------------------------------------------------------------------
// Types

// How a member type is stored: bool as uint8 (0/1), enums as their underlying integer.
template <class M>
struct StoredT {
  using type = M;
};
template <>
struct StoredT<bool> {
  using type = std::uint8_t;
};
template <class M>
requires std::is_enum_v<M>
struct StoredT<M> {
  using type = std::underlying_type_t<M>;
};
template <class M>
using Stored = typename StoredT<M>::type;

// An item of a dataset row: a scalar (one value) or a std::array (K values, dataset [n, K]).
template <class E>
struct Item {
  using value = E;
  static constexpr hsize_t k = 0;  // 0: scalar, 1-D dataset
};
template <class E, std::size_t K>
struct Item<std::array<E, K>> {
  using value = E;
  static constexpr hsize_t k = K;
};

template <class M>
inline constexpr bool kIsVector = false;
template <class E>
inline constexpr bool kIsVector<std::vector<E>> = true;
template <class M>
inline constexpr bool kIsArray = false;
template <class E, std::size_t K>
inline constexpr bool kIsArray<std::array<E, K>> = true;

// ---------------------------------------------------------------------------------------------------
// Items: a vector of scalars or std::arrays of scalars, stored as [n] or [n, K] with the stored type.

template <class E>
void write_items(hid_t loc, const std::string& name, const std::vector<E>& items) {
  using V = typename Item<E>::value;
  using S = Stored<V>;
  constexpr hsize_t k = Item<E>::k;
  if constexpr (k == 0 && std::is_same_v<S, E>) {
    write_dataset(loc, name, items);
  } else {
    std::vector<S> flat;
    flat.reserve(items.size() * (k > 0 ? k : 1));
    for (const E& e : items) {
      if constexpr (k == 0) {
        flat.push_back(static_cast<S>(e));
      } else {
        for (const V& x : e) flat.push_back(static_cast<S>(x));
      }
    }
    write_dataset(loc, name, flat, k);
  }
}

template <class E>
std::vector<E> read_items(hid_t loc, const std::string& name) {
  using V = typename Item<E>::value;
  using S = Stored<V>;
  constexpr hsize_t k = Item<E>::k;
  if constexpr (k == 0 && std::is_same_v<S, E>) {
    return read_dataset<S>(loc, name);
  } else {
    const std::vector<S> flat = read_dataset<S>(loc, name, k);
    std::vector<E> items(flat.size() / (k > 0 ? k : 1));
    for (std::size_t i = 0; i < items.size(); ++i) {
      if constexpr (k == 0) {
        items[i] = static_cast<E>(flat[i]);
      } else {
        for (std::size_t j = 0; j < k; ++j) items[i][j] = static_cast<V>(flat[i * k + j]);
      }
    }
    return items;
  }
}

std::string join_lines(const std::vector<std::string>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i > 0 ? "\n" : "") + v[i];
  return s;
}

std::vector<std::string> split_lines(const std::string& s) {
  std::vector<std::string> v;
  if (s.empty()) return v;
  std::size_t start = 0;
  for (std::size_t nl = s.find('\n'); nl != std::string::npos; nl = s.find('\n', start)) {
    v.push_back(s.substr(start, nl - start));
    start = nl + 1;
  }
  v.push_back(s.substr(start));
  return v;
}

// CSR offsets of n rows over `total` values: offsets[0] = 0, non-decreasing, offsets[n] = total.
void check_offsets(const std::vector<std::int64_t>& off, std::size_t n, std::size_t total,
                   const std::string& where) {
  bool ok = off.size() == n + 1 && off.front() == 0 && off.back() == static_cast<std::int64_t>(total);
  for (std::size_t i = 1; ok && i < off.size(); ++i) ok = off[i] >= off[i - 1];
  if (!ok) {
    throw Failure(where + " is not a valid CSR offsets array for " + std::to_string(n) + " rows and " +
                  std::to_string(total) + " values");
  }
}

// ---------------------------------------------------------------------------------------------------
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
static_assert(member_count<Model>() == 42, "model::Model changed: update write_radx and read_file");
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

// ---------------------------------------------------------------------------------------------------
// Tables: one group per collection, attribute count, one column per member.

// Accessors of a member (and of a member of a member), usable on const and non-const records.
template <class P>
struct MemberOf {
  P member;
  template <class R>
  auto& operator()(R& r) const {
    return r.*member;
  }
};
template <class Outer, class P>
struct NestedMemberOf {
  const Outer& outer;
  P member;
  template <class R>
  auto& operator()(R& r) const {
    return outer(r).*member;
  }
};
template <class P>
MemberOf<P> member_of(P member) {
  return {member};
}
template <class Outer, class P>
NestedMemberOf<Outer, P> member_of(const Outer& outer, P member) {
  return {outer, member};
}

template <class T, class Get>
void write_column(hid_t g, const std::string& name, const std::vector<T>& recs, const Get& get) {
  using M = std::remove_cvref_t<decltype(get(std::declval<const T&>()))>;
  if constexpr (Record<M>) {
    for_each_field<M>([&](const char* sub, auto member) {
      write_column(g, name + "_" + sub, recs, member_of(get, member));
    });
  } else if constexpr (std::is_same_v<M, std::string> || std::is_same_v<M, std::vector<std::string>>) {
    std::vector<std::string> col;
    col.reserve(recs.size());
    for (const T& r : recs) {
      if constexpr (std::is_same_v<M, std::string>) {
        col.push_back(get(r));
      } else {
        col.push_back(join_lines(get(r)));
      }
    }
    write_strings(g, name, col);
  } else if constexpr (kIsVector<M>) {  // CSR
    M values;
    std::vector<std::int64_t> offsets{0};
    for (const T& r : recs) {
      values.insert(values.end(), get(r).begin(), get(r).end());
      offsets.push_back(static_cast<std::int64_t>(values.size()));
    }
    write_items(g, name, values);
    write_dataset(g, name + "_offsets", offsets);
  } else {
    std::vector<M> col;
    col.reserve(recs.size());
    for (const T& r : recs) col.push_back(get(r));
    write_items(g, name, col);
  }
}

template <class T, class Get>
void read_column(hid_t g, const std::string& name, std::vector<T>& recs, const Get& get) {
  using M = std::remove_cvref_t<decltype(get(std::declval<T&>()))>;
  const std::size_t n = recs.size();
  const auto check_rows = [&](std::size_t have) {
    if (have != n) {
      throw Failure("dataset " + path_of(g, name) + " has " + std::to_string(have) + " rows, expected " +
                    std::to_string(n) + " (attribute count of " + path_of(g, "") + ")");
    }
  };
  if constexpr (Record<M>) {
    for_each_field<M>([&](const char* sub, auto member) {
      read_column(g, name + "_" + sub, recs, member_of(get, member));
    });
  } else if constexpr (std::is_same_v<M, std::string> || std::is_same_v<M, std::vector<std::string>>) {
    const std::vector<std::string> col = read_strings(g, name);
    check_rows(col.size());
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (std::is_same_v<M, std::string>) {
        get(recs[i]) = col[i];
      } else {
        get(recs[i]) = split_lines(col[i]);
      }
    }
  } else if constexpr (kIsVector<M>) {
    const M values = read_items<typename M::value_type>(g, name);
    const std::vector<std::int64_t> offsets = read_dataset<std::int64_t>(g, name + "_offsets");
    check_offsets(offsets, n, values.size(), "dataset " + path_of(g, name + "_offsets"));
    for (std::size_t i = 0; i < n; ++i) {
      get(recs[i]).assign(values.begin() + offsets[i], values.begin() + offsets[i + 1]);
    }
  } else {
    const std::vector<M> col = read_items<M>(g, name);
    check_rows(col.size());
    for (std::size_t i = 0; i < n; ++i) get(recs[i]) = col[i];
  }
}

template <class T>
void write_table(hid_t parent, const std::string& name, const std::vector<T>& recs) {
  const Handle g = create_group(parent, name);
  const auto count = static_cast<std::int64_t>(recs.size());
  write_attr(g, "count", &count);
  for_each_field<T>([&](const char* col, auto member) { write_column(g, col, recs, member_of(member)); });
}

std::size_t read_count(hid_t g) {
  const auto count = read_attr<std::int64_t>(g, "count");
  if (count < 0 || count > std::numeric_limits<std::int32_t>::max()) {
    throw Failure("attribute count of " + path_of(g, "") + " is out of range: " + std::to_string(count));
  }
  return static_cast<std::size_t>(count);
}

template <class T>
void read_table(hid_t parent, const std::string& name, std::vector<T>& recs) {
  const Handle g = open_group(parent, name);
  recs.assign(read_count(g), T{});
  for_each_field<T>([&](const char* col, auto member) { read_column(g, col, recs, member_of(member)); });
}

// ---------------------------------------------------------------------------------------------------
// Records: one group per record, scalars and fixed arrays as attributes, vectors as datasets.

template <class R>
void write_record(hid_t g, const R& r, const std::string& prefix = "") {
  for_each_field<R>([&](const char* field_name, auto member) {
    using M = std::remove_cvref_t<decltype(r.*member)>;
    const std::string name = prefix + field_name;
    const M& v = r.*member;
    if constexpr (Record<M>) {
      write_record(g, v, name + "_");
    } else if constexpr (std::is_same_v<M, std::string>) {
      write_string_attr(g, name, v);
    } else if constexpr (std::is_same_v<M, std::vector<std::string>>) {
      write_string_attr(g, name, join_lines(v));
    } else if constexpr (kIsVector<M>) {
      write_items(g, name, v);
    } else if constexpr (kIsArray<M>) {
      using S = Stored<typename M::value_type>;
      std::array<S, std::tuple_size_v<M>> s{};
      for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<S>(v[i]);
      write_attr(g, name, s.data(), s.size());
    } else {
      const auto s = static_cast<Stored<M>>(v);
      write_attr(g, name, &s);
    }
  });
}

template <class R>
void read_record(hid_t g, R& r, const std::string& prefix = "") {
  for_each_field<R>([&](const char* field_name, auto member) {
    using M = std::remove_cvref_t<decltype(r.*member)>;
    const std::string name = prefix + field_name;
    M& v = r.*member;
    if constexpr (Record<M>) {
      read_record(g, v, name + "_");
    } else if constexpr (std::is_same_v<M, std::string>) {
      v = read_string_attr(g, name);
    } else if constexpr (std::is_same_v<M, std::vector<std::string>>) {
      v = split_lines(read_string_attr(g, name));
    } else if constexpr (kIsVector<M>) {
      v = read_items<typename M::value_type>(g, name);
    } else if constexpr (kIsArray<M>) {
      using S = Stored<typename M::value_type>;
      std::array<S, std::tuple_size_v<M>> s{};
      read_attr(g, name, s.data(), s.size());
      for (std::size_t i = 0; i < s.size(); ++i) v[i] = static_cast<typename M::value_type>(s[i]);
    } else {
      v = static_cast<M>(read_attr<Stored<M>>(g, name));
    }
  });
}

// Group `name` with attribute count and sub-groups "0", "1", ... one per record.
template <class T>
void write_record_list(hid_t parent, const std::string& name, const std::vector<T>& recs) {
  const Handle g = create_group(parent, name);
  const auto count = static_cast<std::int64_t>(recs.size());
  write_attr(g, "count", &count);
  for (std::size_t i = 0; i < recs.size(); ++i) write_record(create_group(g, std::to_string(i)), recs[i]);
}

template <class T>
void read_record_list(hid_t parent, const std::string& name, std::vector<T>& recs) {
  const Handle g = open_group(parent, name);
  recs.assign(read_count(g), T{});
  for (std::size_t i = 0; i < recs.size(); ++i) read_record(open_group(g, std::to_string(i)), recs[i]);
}

// ---------------------------------------------------------------------------------------------------
// Writing

void write_block(hid_t elements, const std::string& name, const model::ElementBlock& b) {
  const Handle g = create_group(elements, name);
  const auto type = static_cast<std::uint8_t>(b.type);
  const auto count = static_cast<std::int64_t>(b.size());
  write_attr(g, "type", &type);
  write_attr(g, "count", &count);
  write_dataset(g, "id", b.id);
  write_dataset(g, "part", b.part);
  write_dataset(g, "conn", b.conn, static_cast<hsize_t>(b.npe()));
  write_dataset(g, "thickness", b.thickness);
  write_dataset(g, "phi", b.phi);
}

void write_radx(hid_t file, const Model& m) {
  const Handle radx = create_group(file, "radx");
  write_string_attr(radx, "title", m.title);
  write_string_attr(radx, "run_name", m.run_name);
  const auto deck_version = static_cast<std::int32_t>(m.deck_version);
  write_attr(radx, "deck_version", &deck_version);
  write_attr(radx, "total_mass", &m.total_mass);
  write_record(create_group(radx, "units"), m.units);
  {  // The node arrays are already in /VTKHDF: hard links, not copies.
    const Handle nodes = create_group(radx, "nodes");
    const auto count = static_cast<std::int64_t>(m.nodes.size());
    write_attr(nodes, "count", &count);
    link_hard(file, "/VTKHDF/PointData/node_id", nodes, "id");
    link_hard(file, "/VTKHDF/Points", nodes, "xyz");
  }
  write_dataset(radx, "node_mass", m.node_mass);
  const Handle elements = create_group(radx, "elements");
  for_each_block(m, [&](const char* name, const model::ElementBlock& b) { write_block(elements, name, b); });
  for_each_table(m, [&](const char* name, const auto& recs) { write_table(radx, name, recs); });
  write_record_list(radx, "interfaces", m.interfaces);
  write_strings(radx, "ignored_keywords", m.ignored_keywords);
  write_strings(radx, "substitutions", m.substitutions);
}

// Writes the whole file at `part`; closes it (and flushes it to disk) before returning.
void write_file(const Model& m, const std::string& part) {
  check_vtkhdf_mesh(m);
  WriteFile file = create_file(part);
  {
    const std::string version = RADX_VERSION;
    write_attr(file, "radx_model_format_version", &kModelFormatVersion);
    write_string_attr(file, "radx_version", version);
    write_vtkhdf_mesh(file, m);
    write_radx(file, m);
  }
  file.close();
  sync_file(part);
}

// ---------------------------------------------------------------------------------------------------
// Reading

void read_block(hid_t elements, const std::string& name, model::ElementBlock& b, std::size_t node_count) {
  const Handle g = open_group(elements, name);
  const auto type = read_attr<std::uint8_t>(g, "type");
  if (type != static_cast<std::uint8_t>(b.type)) {
    throw Failure("attribute type of " + path_of(g, "") + " is " + std::to_string(type) + ", expected " +
                  std::to_string(static_cast<int>(b.type)));
  }
  b.id = read_dataset<std::int64_t>(g, "id");
  b.part = read_dataset<std::int32_t>(g, "part");
  b.conn = read_dataset<std::int32_t>(g, "conn", static_cast<hsize_t>(b.npe()));
  b.thickness = read_dataset<double>(g, "thickness");
  b.phi = read_dataset<double>(g, "phi");
  if (b.part.size() != b.size() || b.conn.size() != b.size() * static_cast<std::size_t>(b.npe())) {
    throw Failure("datasets part and conn of " + path_of(g, "") + " do not match its id count");
  }
  for (std::size_t k = 0; k < b.conn.size(); ++k) {
    const std::int32_t node = b.conn[k];
    // A spring's third node (orientation) is optional.
    if ((b.type == model::ElementType::Spring2 || b.type == model::ElementType::Beam2) && k % 3 == 2 &&
        node == model::kNone)
      continue;
    if (node < 0 || static_cast<std::size_t>(node) >= node_count) {
      throw Failure("dataset " + path_of(g, "conn") + " has node index " + std::to_string(node) +
                    " out of range");
    }
  }
  std::int64_t duplicate = 0;
  if (!b.index.build(b.id, duplicate)) {
    throw Failure("dataset " + path_of(g, "id") + " repeats element id " + std::to_string(duplicate));
  }
}

void read_file(const std::string& path, Model& m) {
  Handle file = open_file_read_only(path);
  const auto format = read_attr<std::int64_t>(file, "radx_model_format_version");
  if (format != kModelFormatVersion) {
    throw Failure("model format version " + std::to_string(format) + " (written by radx " +
                  read_string_attr(file, "radx_version") + "), this radx reads version " +
                  std::to_string(kModelFormatVersion) + ": run the starter of this radx again");
  }
  m = Model{};
  const Handle radx = open_group(file, "radx");
  m.title = read_string_attr(radx, "title");
  m.run_name = read_string_attr(radx, "run_name");
  m.deck_version = read_attr<std::int32_t>(radx, "deck_version");
  m.total_mass = read_attr<double>(radx, "total_mass");
  read_record(open_group(radx, "units"), m.units);
  {
    const Handle nodes = open_group(radx, "nodes");
    m.nodes.id = read_dataset<std::int64_t>(nodes, "id");
    const std::vector<double> xyz = read_dataset<double>(nodes, "xyz", 3);
    const std::size_t nn = m.nodes.size();
    if (xyz.size() != 3 * nn)
      throw Failure("dataset " + path_of(nodes, "xyz") + " does not match the node ids");
    m.nodes.x.resize(nn);
    m.nodes.y.resize(nn);
    m.nodes.z.resize(nn);
    for (std::size_t i = 0; i < nn; ++i) {
      m.nodes.x[i] = xyz[3 * i];
      m.nodes.y[i] = xyz[3 * i + 1];
      m.nodes.z[i] = xyz[3 * i + 2];
    }
    std::int64_t duplicate = 0;
    if (!m.nodes.index.build(m.nodes.id, duplicate)) {
      throw Failure("dataset " + path_of(nodes, "id") + " repeats node id " + std::to_string(duplicate));
    }
  }
  m.node_mass = read_dataset<double>(radx, "node_mass");
  const Handle elements = open_group(radx, "elements");
  for_each_block(
      m, [&](const char* name, model::ElementBlock& b) { read_block(elements, name, b, m.nodes.size()); });
  for_each_table(m, [&](const char* name, auto& recs) { read_table(radx, name, recs); });
  read_record_list(radx, "interfaces", m.interfaces);
  m.ignored_keywords = read_strings(radx, "ignored_keywords");
  m.substitutions = read_strings(radx, "substitutions");
  file.close("cannot close file " + path);
}

}  // namespace

bool write_model_file(const Model& m, const std::string& path, std::string& error) {
  const std::string part = path + ".part";
  try {
    const QuietHdf5 quiet;
    write_file(m, part);
    replace_file(part, path);
    return true;
  } catch (const std::exception& e) {
    error = "cannot write model file " + path + ": " + e.what();
  }
  std::error_code ignored;
  fs::remove(part, ignored);
  return false;
}

bool read_model_file(const std::string& path, Model& m, std::string& error) {
  try {
    const QuietHdf5 quiet;
    read_file(path, m);
    return true;
  } catch (const std::exception& e) {
    error = "cannot read model file " + path + ": " + e.what();
  }
  return false;
}

}  // namespace radx::io
