// The content hash of a model file (io/hdf5/model_file_hash.hpp).
//
// hash_bytes, with P1..P3 odd 64-bit constants, rotl a left rotation and w the little-endian 64-bit words:
//   four lanes v_j = rotl(v_j + w * P2, 31) * P1 over each 32-byte stripe (the j-th word to lane j);
//   h = rotl(v_0, 1) + rotl(v_1, 7) + rotl(v_2, 12) + rotl(v_3, 18) (seed + P3 below one stripe), h += size;
//   each remaining word: h = rotl(h ^ rotl(w * P2, 31) * P1, 27) * P1 + P3; each remaining byte b:
//   h = rotl(h ^ b * P3, 11) * P1;
//   avalanche: h ^= h >> 33, h *= P2, h ^= h >> 29, h *= P3, h ^= h >> 32.
// The file's hash chains hash_bytes over the pieces listed in the header, each seeded with the hash so far.
#include "io/hdf5/model_file_hash.hpp"

#include <bit>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <vector>

#include "io/hdf5/hdf5_util.hpp"

namespace radx::io {

namespace {

constexpr std::uint64_t kP1 = 0x9E3779B185EBCA87ULL;
constexpr std::uint64_t kP2 = 0xC2B2AE3D27D4EB4FULL;
constexpr std::uint64_t kP3 = 0x165667B19E3779F9ULL;

constexpr std::uint64_t rotl(std::uint64_t x, int r) {
  return (x << r) | (x >> (64 - r));
}

// Little-endian whatever the host: the same bytes give the same hash everywhere (one load on x86).
std::uint64_t load_word(const unsigned char* p) {
  std::uint64_t w = 0;
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(&w, p, sizeof w);
  } else {
    for (int i = 7; i >= 0; --i) w = (w << 8) | p[i];
  }
  return w;
}

std::uint64_t lane(std::uint64_t v, std::uint64_t w) {
  return rotl(v + w * kP2, 31) * kP1;
}

}  // namespace

std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t seed) {
  const auto* p = static_cast<const unsigned char*>(data);
  const unsigned char* const end = p + size;
  std::uint64_t h = seed + kP3;
  if (size >= 32) {
    std::uint64_t v0 = seed + kP1 + kP2, v1 = seed + kP2, v2 = seed, v3 = seed - kP1;
    for (; end - p >= 32; p += 32) {
      v0 = lane(v0, load_word(p));
      v1 = lane(v1, load_word(p + 8));
      v2 = lane(v2, load_word(p + 16));
      v3 = lane(v3, load_word(p + 24));
    }
    h = rotl(v0, 1) + rotl(v1, 7) + rotl(v2, 12) + rotl(v3, 18);
  }
  h += size;
  for (; end - p >= 8; p += 8) h = rotl(h ^ lane(0, load_word(p)), 27) * kP1 + kP3;
  for (; p < end; ++p) h = rotl(h ^ (*p * kP3), 11) * kP1;
  h ^= h >> 33;
  h *= kP2;
  h ^= h >> 29;
  h *= kP3;
  h ^= h >> 32;
  return h;
}

namespace {

using namespace radx::io::h5;  // NOLINT(google-build-using-namespace)

class FileHasher {
 public:
  [[nodiscard]] std::uint64_t value() const { return h_; }

  // depth: a radx model file nests groups four deep at most; a damaged file whose group links back into
  // its own subtree would otherwise recurse until the stack ran out.
  void group(hid_t g, const std::string& path, int depth = 0) {
    if (depth > kMaxDepth)
      fail("group " + path + " is nested deeper than any radx model file (a link loop?)");
    text(path);
    attributes(g, path == "/");
    H5G_info_t info{};
    check(H5Gget_info(g, &info), "cannot read group " + path);
    for (hsize_t i = 0; i < info.nlinks; ++i) {
      const std::string name = link_name(g, i, path);
      const std::string child = (path == "/" ? "/" : path + "/") + name;
      const Handle obj(H5Oopen(g, name.c_str(), H5P_DEFAULT), H5Oclose, "cannot open " + child);
      switch (H5Iget_type(obj)) {
        case H5I_GROUP: group(obj, child, depth + 1); break;
        case H5I_DATASET: dataset(obj, child); break;
        default: text(child); break;  // a named datatype: its name only
      }
    }
  }

 private:
  static constexpr int kMaxDepth = 32;
  std::uint64_t h_ = 0;

  void bytes(const void* data, std::size_t size) { h_ = hash_bytes(data, size, h_); }
  void text(std::string_view s) { bytes(s.data(), s.size()); }
  void number(std::uint64_t v) { bytes(&v, sizeof v); }

  static std::string link_name(hid_t g, hsize_t i, const std::string& path) {
    const ssize_t n = H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr, 0, H5P_DEFAULT);
    if (n < 0) fail("cannot list group " + path);
    std::string name(static_cast<std::size_t>(n), '\0');
    H5Lget_name_by_idx(g, ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size() + 1, H5P_DEFAULT);
    return name;
  }

  // The class and size of a type, and the values of `n` items read by `read` (into a buffer of that type,
  // or into char* for variable-length strings).
  template <class Read>
  void values(hid_t type, hsize_t n, const std::string& what, const Read& read) {
    number(static_cast<std::uint64_t>(H5Tget_class(type)));
    if (H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) > 0) {
      const Handle mem = vlen_string_type();
      std::vector<char*> s(n, nullptr);
      if (n > 0) check(read(mem, s.data()), "cannot read " + what);
      for (char* p : s) text(p != nullptr ? std::string_view(p) : std::string_view());
      if (n > 0) {
        const Handle space = simple_space({n}, what);
        reclaim_strings(mem, space, s.data());
      }
      return;
    }
    const std::size_t item = H5Tget_size(type);
    number(item);
    std::vector<unsigned char> buf(static_cast<std::size_t>(n) * item);
    if (!buf.empty()) check(read(type, buf.data()), "cannot read " + what);
    bytes(buf.data(), buf.size());
  }

  static std::vector<hsize_t> dims_of(hid_t space) {
    const int rank = H5Sget_simple_extent_ndims(space);
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank > 0 ? rank : 0));
    if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    return dims;
  }

  void dataset(hid_t ds, const std::string& path) {
    text(path);
    attributes(ds, false);
    const Handle space(H5Dget_space(ds), H5Sclose, "cannot read dataset " + path);
    const Handle type(H5Dget_type(ds), H5Tclose, "cannot read dataset " + path);
    for (const hsize_t d : dims_of(space)) number(d);
    const auto n = static_cast<hsize_t>(H5Sget_simple_extent_npoints(space));
    values(type, n, "dataset " + path,
           [&](hid_t mem, void* buf) { return H5Dread(ds, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf); });
  }

  void attributes(hid_t obj, bool root) {
    std::vector<std::string> names;
    const auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
      static_cast<std::vector<std::string>*>(data)->emplace_back(name);
      return 0;
    };
    hsize_t at = 0;
    check(H5Aiterate2(obj, H5_INDEX_NAME, H5_ITER_INC, &at, collect, &names),
          "cannot list the attributes of " + path_of(obj, ""));
    for (const auto& name : names) {
      if (root && name == kContentHashAttribute) continue;
      const std::string what = "attribute " + name + " of " + path_of(obj, "");
      const Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open " + what);
      const Handle space(H5Aget_space(a), H5Sclose, "cannot read " + what);
      const Handle type(H5Aget_type(a), H5Tclose, "cannot read " + what);
      text(name);
      for (const hsize_t d : dims_of(space)) number(d);
      const auto n = static_cast<hsize_t>(H5Sget_simple_extent_npoints(space));
      values(type, n, what, [&](hid_t mem, void* buf) { return H5Aread(a, mem, buf); });
    }
  }
};

}  // namespace

std::string model_content_hash(hid_t file) {
  FileHasher hasher;
  const Handle root = open_group(file, "/");
  hasher.group(root, "/");
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hasher.value()));
  return hex;
}

}  // namespace radx::io
