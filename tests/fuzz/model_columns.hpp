// Every column of a Model as the model file stores it (docs/model-file.md section 5), for the model-file fuzz
// target: the node ids and coordinates, the nodal masses, each element block's arrays, each table's columns
// (nested structs flattened, CSR columns over all records) and each interface's members, in a fixed order.
// A column is seen as a flat array of scalars (an entry of a [n, K] column is one of its n K values), which
// the fuzz target changes entry by entry as a damaged file would hold them.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "io/hdf5/model_schema.hpp"
#include "solver/model/model.hpp"

namespace radx::fuzz {

// fn(name, size, at, resize) for each column of `m`: `at(i)` is a reference to entry i (a scalar: an
// integer, a real, a bool or an enum) for i < size; `resize(i, grow)` removes the last value of the record
// that holds entry i or repeats it (grow), for the columns of variable length (CSR, element arrays),
// and does nothing for the others.
template <class Fn>
void for_each_column(model::Model& m, Fn&& fn);

namespace detail {

inline constexpr auto kNoResize = [](std::size_t, bool) {};

template <class M>
inline constexpr bool kIsText = std::is_same_v<M, std::string> || std::is_same_v<M, std::vector<std::string>>;

template <class E>
struct Width {
  static constexpr std::size_t k = 1;
  static auto& at(E& e, std::size_t) { return e; }
};
template <class E, std::size_t K>
struct Width<std::array<E, K>> {
  static constexpr std::size_t k = K;
  static auto& at(std::array<E, K>& e, std::size_t j) { return e[j]; }
};

// A flat vector (node arrays, element arrays, nodal masses).
template <class E, class Fn>
void vector_column(std::string_view name, std::vector<E>& v, Fn& fn) {
  using W = Width<E>;
  fn(
      name, v.size() * W::k, [&](std::size_t i) -> auto& { return W::at(v[i / W::k], i % W::k); },
      [&](std::size_t, bool grow) {
        if (grow && !v.empty()) v.push_back(v.back());
        if (!grow && !v.empty()) v.pop_back();
      });
}

// One member of every record of `recs`, reached by `get`.
template <class T, class Get, class Fn>
void table_column(const std::string& name, std::vector<T>& recs, const Get& get, Fn& fn) {
  using M = std::remove_cvref_t<decltype(get(std::declval<T&>()))>;
  if constexpr (io::schema::Record<M>) {
    io::schema::for_each_field<M>([&](const char* sub, auto member) {
      table_column(
          name + "_" + sub, recs, [&](T & r) -> auto& { return get(r).*member; }, fn);
    });
  } else if constexpr (kIsText<M>) {
    return;  // names and titles: the engine only prints them
  } else if constexpr (io::schema::kIsVector<M>) {
    using W = Width<typename M::value_type>;
    std::size_t total = 0;
    for (auto& r : recs) total += get(r).size();
    // Entry i of the CSR values: the record holding it and its position there.
    const auto locate = [&](std::size_t i, std::size_t& k) -> M& {
      std::size_t flat = i / W::k;
      for (auto& r : recs) {
        if (flat < get(r).size()) {
          k = flat;
          return get(r);
        }
        flat -= get(r).size();
      }
      k = 0;
      return get(recs.front());  // not reached: i < total
    };
    fn(
        name, total * W::k,
        [&](std::size_t i) -> auto& {
          std::size_t k = 0;
          M& v = locate(i, k);
          return W::at(v[k], i % W::k);
        },
        [&](std::size_t i, bool grow) {
          std::size_t k = 0;
          M& v = locate(i, k);
          if (grow) v.insert(v.begin() + static_cast<std::ptrdiff_t>(k), v[k]);
          if (!grow) v.erase(v.begin() + static_cast<std::ptrdiff_t>(k));
        });
  } else {
    using W = Width<M>;
    fn(
        name,
        recs.size() * W::k, [&](std::size_t i) -> auto& { return W::at(get(recs[i / W::k]), i % W::k); },
        kNoResize);
  }
}

template <class T, class Fn>
void table(const std::string& name, std::vector<T>& recs, Fn& fn) {
  io::schema::for_each_field<T>([&](const char* col, auto member) {
    table_column(
        name + "/" + col, recs, [member](T & r) -> auto& { return r.*member; }, fn);
  });
}

}  // namespace detail

template <class Fn>
void for_each_column(model::Model& m, Fn&& fn) {
  detail::vector_column("nodes/id", m.nodes.id, fn);
  detail::vector_column("nodes/x", m.nodes.x, fn);
  detail::vector_column("nodes/y", m.nodes.y, fn);
  detail::vector_column("nodes/z", m.nodes.z, fn);
  detail::vector_column("node_mass", m.node_mass, fn);
  fn(
      "total_mass", 1, [&](std::size_t) -> auto& { return m.total_mass; }, detail::kNoResize);
  io::schema::for_each_block(m, [&](const char* name, model::ElementBlock& b) {
    const std::string block = std::string("elements/") + name;
    detail::vector_column(block + "/id", b.id, fn);
    detail::vector_column(block + "/part", b.part, fn);
    detail::vector_column(block + "/conn", b.conn, fn);
    detail::vector_column(block + "/thickness", b.thickness, fn);
    detail::vector_column(block + "/phi", b.phi, fn);
  });
  io::schema::for_each_table(m, [&](const char* name, auto& recs) { detail::table(name, recs, fn); });
  detail::table("interfaces", m.interfaces, fn);
}

}  // namespace radx::fuzz
