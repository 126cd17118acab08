// Internal HDF5 helpers of the io library (model file, result states, time history): RAII handles,
// error reporting with the HDF5 object path, typed datasets and attributes, and the file-level steps of
// a crash-safe write (flush to disk, make a rename durable). Not part of the public io interface.
//
// Conventions:
// - Every HDF5 call that can fail goes through Handle or check(). A failure throws h5::Failure whose
//   message names the HDF5 object ("cannot write dataset /VTKHDF/Points") and ends with the innermost
//   message of the HDF5 error stack, which is the specific one ("unable to open file: ... errno = 2").
// - Run the HDF5 calls of a public entry point under a QuietHdf5, so HDF5 does not print its own error
//   stack to stderr: the error is reported once, through the exception.
// - Datasets are written contiguous, without fill, with one H5Dwrite each; memory and file types are both
//   little-endian, so HDF5 copies without conversion. That keeps large arrays fast to write.
#pragma once

#include <fcntl.h>
#include <hdf5.h>
#include <unistd.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace radx::io::h5 {

// ---------------------------------------------------------------------------------------------------
// Errors and handles

struct Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Innermost (most specific) message of the HDF5 error stack, e.g. "unable to open file: name = ...,
// errno = 2, error message = 'No such file or directory'". Clears the stack.
inline std::string hdf5_detail() {
  std::string detail;
  H5Ewalk2(
      H5E_DEFAULT, H5E_WALK_UPWARD,
      [](unsigned n, const H5E_error2_t* e, void* data) -> herr_t {
        if (n == 0 && e->desc != nullptr) *static_cast<std::string*>(data) = e->desc;
        return 0;
      },
      &detail);
  H5Eclear2(H5E_DEFAULT);
  return detail;
}

// Throws Failure(what), completed by the HDF5 error stack's message when there is one.
[[noreturn]] inline void fail(const std::string& what) {
  const std::string detail = hdf5_detail();
  throw Failure(detail.empty() ? what : what + " (HDF5: " + detail + ")");
}

inline void check(herr_t status, const std::string& what) {
  if (status < 0) fail(what);
}

// Silences HDF5's automatic error printing while it lives; failures are reported through Failure.
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// Owner of an hid_t: throws Failure(what) when the id is invalid, closes it at the end of its scope.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer close, const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) fail(what);
  }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, -1)), close_(o.close_) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  operator hid_t() const { return id_; }  // NOLINT: used as an hid_t in HDF5 calls
  // Closes now and reports a failure (for a file: the data may not be complete on disk).
  void close(const std::string& what) { check(close_(std::exchange(id_, -1)), what); }

 private:
  hid_t id_;
  Closer close_;
};

// Path of the object `loc` ("/radx/materials"), or of its member `name` ("/radx/materials/rho").
inline std::string path_of(hid_t loc, const std::string& name) {
  std::string base;
  const ssize_t n = H5Iget_name(loc, nullptr, 0);
  if (n > 0) {
    base.resize(static_cast<std::size_t>(n));
    H5Iget_name(loc, base.data(), static_cast<std::size_t>(n) + 1);
  }
  if (name.empty()) return base.empty() ? "/" : base;
  if (base.empty() || base.back() != '/') base += '/';
  return base + name;
}

// ---------------------------------------------------------------------------------------------------
// Types: the memory type and the (little-endian) file type of each stored C++ type.

template <class T>
struct Hdf5Type;
template <>
struct Hdf5Type<double> {
  static hid_t mem() { return H5T_NATIVE_DOUBLE; }
  static hid_t file() { return H5T_IEEE_F64LE; }
};
template <>
struct Hdf5Type<float> {
  static hid_t mem() { return H5T_NATIVE_FLOAT; }
  static hid_t file() { return H5T_IEEE_F32LE; }
};
template <>
struct Hdf5Type<std::int64_t> {
  static hid_t mem() { return H5T_NATIVE_INT64; }
  static hid_t file() { return H5T_STD_I64LE; }
};
template <>
struct Hdf5Type<std::int32_t> {
  static hid_t mem() { return H5T_NATIVE_INT32; }
  static hid_t file() { return H5T_STD_I32LE; }
};
template <>
struct Hdf5Type<std::uint8_t> {
  static hid_t mem() { return H5T_NATIVE_UINT8; }
  static hid_t file() { return H5T_STD_U8LE; }
};

// Variable-length UTF-8 string type (free-form text: titles, names).
inline Handle vlen_string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose, "cannot create the string type");
  check(H5Tset_size(t, H5T_VARIABLE), "cannot create the string type");
  check(H5Tset_cset(t, H5T_CSET_UTF8), "cannot create the string type");
  return t;
}

// Frees the strings HDF5 allocated in a variable-length string read. (H5Treclaim is declared by the
// 1.10.8 headers but not exported by Debian 12's libhdf5: use the 1.10 name there.)
inline void reclaim_strings(hid_t type, hid_t space, void* buf) {
#if H5_VERSION_GE(1, 12, 0)
  H5Treclaim(type, space, H5P_DEFAULT, buf);
#else
  H5Dvlen_reclaim(type, space, H5P_DEFAULT, buf);
#endif
}

inline Handle simple_space(const std::vector<hsize_t>& dims, const std::string& what) {
  return Handle(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose, what);
}

// ---------------------------------------------------------------------------------------------------
// Files

// Creates (truncates) `path` for writing. The close degree SEMI makes closing the file fail, instead of
// being silently deferred, if an object of it were still open: a successful close() means all written.
// `marked` writes the 1.10 file format (superblock version 3, checksummed metadata), whose superblock
// holds a "file open for writing" flag: set as the file is opened for writing, cleared as it is closed,
// so a reader refuses a file whose writer was killed before closing it.
inline Handle create_file(const std::string& path, bool marked = false) {
  const Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create a file access list");
  check(H5Pset_fclose_degree(fapl, H5F_CLOSE_SEMI), "cannot set the file close degree");
  if (marked)
    check(H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_V110), "cannot set the file format");
  return Handle(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose,
                "cannot create file " + path);
}

inline Handle open_file_read_only(const std::string& path) {
  return Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "cannot open file " + path);
}

// HDF5's message when a file's "open for writing" flag is set (a writer has it open, or was killed).
inline bool open_for_write_refusal(const std::string& message) {
  return message.find("already open for") != std::string::npos;
}

// As a single-writer/multi-reader (SWMR) reader: opens a 1.10-format file whose SWMR writer has it open or
// was killed with it open, as HDF5 ordered its writes so that such a reader sees consistent metadata.
inline Handle open_file_swmr_read(const std::string& path) {
  const Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create a file access list");
  check(H5Pset_file_locking(fapl, false, true), "cannot set the file locking");
  return Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, fapl), H5Fclose,
                "cannot open file " + path);
}

// Without HDF5's file lock: a reader holding the file open (h5py, `radx th` during a run) would make the
// writer's open fail, and with it the run. What keeps readers from a file being written is the 1.10
// format's "open for writing" flag in the superblock, which HDF5 sets at this open and clears at the close
// (files of the earliest format have none: a reader can then open the file while it is written).
// `swmr`: as the single writer of SWMR (a 1.10-format file only): HDF5 then orders its metadata writes so
// that a SWMR reader sees a consistent file at every moment, also after the writer is killed.
inline Handle open_file_read_write(const std::string& path, bool swmr = false) {
  const Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "cannot create a file access list");
  check(H5Pset_fclose_degree(fapl, H5F_CLOSE_SEMI), "cannot set the file close degree");
  check(H5Pset_file_locking(fapl, false, true), "cannot set the file locking");
  if (swmr) check(H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_V110), "cannot set the file format");
  return Handle(H5Fopen(path.c_str(), H5F_ACC_RDWR | (swmr ? H5F_ACC_SWMR_WRITE : 0u), fapl), H5Fclose,
                "cannot open file " + path);
}

// Flushes a closed file's data to disk. Called before renaming `name.part` to `name`, so a system crash
// cannot leave a renamed but empty file.
inline void sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  const bool synced = fd >= 0 && ::fsync(fd) == 0;
  if (fd >= 0) ::close(fd);
  if (!synced) throw Failure("cannot flush file " + path + " to disk");
}

// Best effort: makes a rename in the folder of `path` durable. Some file systems cannot fsync a folder;
// the renamed file is complete either way.
inline void sync_folder_of(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  const int fd = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// Renames `from` over `to` (atomic on POSIX) and makes the rename durable.
inline void replace_file(const std::string& from, const std::string& to) {
  std::error_code ec;
  std::filesystem::rename(from, to, ec);
  if (ec) throw Failure("cannot rename " + from + " to " + to + ": " + ec.message());
  sync_folder_of(to);
}

// ---------------------------------------------------------------------------------------------------
// Groups, links

inline Handle create_group(hid_t loc, const std::string& name) {
  return Handle(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                "cannot create group " + path_of(loc, name));
}

inline Handle open_group(hid_t loc, const std::string& name) {
  return Handle(H5Gopen2(loc, name.c_str(), H5P_DEFAULT), H5Gclose,
                "cannot open group " + path_of(loc, name));
}

// Hard link `loc/name` to the object at absolute path `target` of the same file.
inline void link_hard(hid_t file, const std::string& target, hid_t loc, const std::string& name) {
  check(H5Lcreate_hard(file, target.c_str(), loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
        "cannot link " + path_of(loc, name) + " to " + target);
}

// External link `loc/name` to `object` (absolute path) in file `file_name`. The file name is stored as
// given: a bare name is found relative to the linking file's folder when the link is followed, so a
// result folder can be moved as a whole.
inline void link_external(const std::string& file_name, const std::string& object, hid_t loc,
                          const std::string& name) {
  check(H5Lcreate_external(file_name.c_str(), object.c_str(), loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT),
        "cannot link " + path_of(loc, name) + " to " + file_name + ":" + object);
}

// ---------------------------------------------------------------------------------------------------
// Datasets

// Creates a contiguous dataset and writes it with a single H5Dwrite. `data` holds product(dims) values.
inline void write_raw(hid_t loc, const std::string& name, hid_t file_type, hid_t mem_type, const void* data,
                      const std::vector<hsize_t>& dims) {
  const std::string what = "cannot write dataset " + path_of(loc, name);
  const Handle space = simple_space(dims, what);
  const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, what);
  check(H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER), what);
  const Handle ds(H5Dcreate2(loc, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose,
                  what);
  hsize_t count = 1;
  for (const hsize_t d : dims) count *= d;
  if (count > 0) check(H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), what);
}

// 1-D dataset [size] when cols == 0, else [size / cols, cols].
template <class T>
void write_dataset(hid_t loc, const std::string& name, std::span<const T> v, hsize_t cols = 0) {
  std::vector<hsize_t> dims{v.size()};
  if (cols > 0) dims = {v.size() / cols, cols};
  write_raw(loc, name, Hdf5Type<T>::file(), Hdf5Type<T>::mem(), v.data(), dims);
}

template <class T>
void write_dataset(hid_t loc, const std::string& name, const std::vector<T>& v, hsize_t cols = 0) {
  write_dataset(loc, name, std::span<const T>(v), cols);
}

// Reads a 1-D dataset (cols == 0) or a [n, cols] dataset, flattened row-major.
template <class T>
std::vector<T> read_dataset(hid_t loc, const std::string& name, hsize_t cols = 0) {
  const std::string where = "dataset " + path_of(loc, name);
  const Handle ds(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, "cannot open " + where);
  const Handle space(H5Dget_space(ds), H5Sclose, "cannot read " + where);
  const int rank = H5Sget_simple_extent_ndims(space);
  const int want = cols > 0 ? 2 : 1;
  if (rank != want) {
    throw Failure(where + " has rank " + std::to_string(rank) + ", expected " + std::to_string(want));
  }
  std::array<hsize_t, 2> dims{0, 0};
  check(H5Sget_simple_extent_dims(space, dims.data(), nullptr), "cannot read " + where);
  if (cols > 0 && dims[1] != cols) {
    throw Failure(where + " has " + std::to_string(dims[1]) + " columns, expected " + std::to_string(cols));
  }
  std::vector<T> out(static_cast<std::size_t>(dims[0] * (cols > 0 ? cols : 1)));
  if (!out.empty()) {
    check(H5Dread(ds, Hdf5Type<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "cannot read " + where);
  }
  return out;
}

// 1-D dataset of variable-length strings.
inline void write_strings(hid_t loc, const std::string& name, const std::vector<std::string>& v) {
  const std::string what = "cannot write dataset " + path_of(loc, name);
  std::vector<const char*> ptr(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) ptr[i] = v[i].c_str();
  const Handle type = vlen_string_type();
  const Handle space = simple_space({v.size()}, what);
  const Handle ds(H5Dcreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
                  what);
  if (!v.empty()) check(H5Dwrite(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptr.data()), what);
}

inline std::vector<std::string> read_strings(hid_t loc, const std::string& name) {
  const std::string where = "dataset " + path_of(loc, name);
  const Handle ds(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, "cannot open " + where);
  const Handle space(H5Dget_space(ds), H5Sclose, "cannot read " + where);
  const Handle file_type(H5Dget_type(ds), H5Tclose, "cannot read " + where);
  if (H5Sget_simple_extent_ndims(space) != 1 || H5Tget_class(file_type) != H5T_STRING ||
      H5Tis_variable_str(file_type) <= 0) {
    throw Failure(where + " is not a 1-D dataset of variable-length strings");
  }
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<std::string> out(n);
  if (n == 0) return out;
  const Handle type = vlen_string_type();
  std::vector<char*> ptr(n, nullptr);
  check(H5Dread(ds, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, ptr.data()), "cannot read " + where);
  for (std::size_t i = 0; i < n; ++i) out[i] = ptr[i] != nullptr ? ptr[i] : "";
  reclaim_strings(type, space, ptr.data());
  return out;
}

// ---------------------------------------------------------------------------------------------------
// Attributes

// Scalar attribute (n == 0) or 1-D attribute [n].
template <class T>
void write_attr(hid_t obj, const std::string& name, const T* data, hsize_t n = 0) {
  const std::string what = "cannot write attribute " + name + " of " + path_of(obj, "");
  const Handle space = n == 0 ? Handle(H5Screate(H5S_SCALAR), H5Sclose, what) : simple_space({n}, what);
  const Handle a(H5Acreate2(obj, name.c_str(), Hdf5Type<T>::file(), space, H5P_DEFAULT, H5P_DEFAULT),
                 H5Aclose, what);
  check(H5Awrite(a, Hdf5Type<T>::mem(), data), what);
}

// Scalar variable-length UTF-8 string attribute.
inline void write_string_attr(hid_t obj, const std::string& name, const std::string& value) {
  const std::string what = "cannot write attribute " + name + " of " + path_of(obj, "");
  const Handle type = vlen_string_type();
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, what);
  const Handle a(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, what);
  const char* p = value.c_str();
  check(H5Awrite(a, type, &p), what);
}

// Scalar fixed-length ASCII string attribute of exactly value.size() bytes, NULLPAD, no terminating NUL.
// For readers that compare the stored bytes, such as VTK's VTKHDF reader with @Type (a 17-byte value
// with its NUL, or a variable-length string, makes it fail with "Unknown data set type").
inline void write_fixed_string_attr(hid_t obj, const std::string& name, const std::string& value) {
  const std::string what = "cannot write attribute " + name + " of " + path_of(obj, "");
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose, what);
  check(H5Tset_size(type, value.size()), what);
  check(H5Tset_strpad(type, H5T_STR_NULLPAD), what);
  check(H5Tset_cset(type, H5T_CSET_ASCII), what);
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose, what);
  const Handle a(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, what);
  check(H5Awrite(a, type, value.data()), what);
}

// Reads an attribute of exactly n values (n == 1 for a scalar).
template <class T>
void read_attr(hid_t obj, const std::string& name, T* data, hsize_t n = 1) {
  const std::string where = "attribute " + name + " of " + path_of(obj, "");
  const Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open " + where);
  const Handle space(H5Aget_space(a), H5Sclose, "cannot read " + where);
  const hssize_t have = H5Sget_simple_extent_npoints(space);
  if (have != static_cast<hssize_t>(n)) {
    throw Failure(where + " has " + std::to_string(have) + " values, expected " + std::to_string(n));
  }
  check(H5Aread(a, Hdf5Type<T>::mem(), data), "cannot read " + where);
}

template <class T>
T read_attr(hid_t obj, const std::string& name) {
  T value{};
  read_attr(obj, name, &value);
  return value;
}

// Reads a scalar string attribute, variable-length or fixed-length (NUL padded or terminated).
inline std::string read_string_attr(hid_t obj, const std::string& name) {
  const std::string where = "attribute " + name + " of " + path_of(obj, "");
  const Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open " + where);
  const Handle file_type(H5Aget_type(a), H5Tclose, "cannot read " + where);
  const Handle space(H5Aget_space(a), H5Sclose, "cannot read " + where);
  if (H5Tget_class(file_type) != H5T_STRING || H5Sget_simple_extent_npoints(space) != 1) {
    throw Failure(where + " is not a scalar string");
  }
  if (H5Tis_variable_str(file_type) > 0) {
    const Handle type = vlen_string_type();
    char* p = nullptr;
    check(H5Aread(a, type, &p), "cannot read " + where);
    std::string out = p != nullptr ? p : "";
    reclaim_strings(type, space, &p);
    return out;
  }
  std::string out(H5Tget_size(file_type), '\0');
  check(H5Aread(a, file_type, out.data()), "cannot read " + where);
  out.resize(out.find('\0') == std::string::npos ? out.size() : out.find('\0'));
  return out;
}

}  // namespace radx::io::h5

// ---------------------------------------------------------------------------------------------------
// Added for the time history (io/hdf5/time_history.cpp): string-array and variable-length attributes,
// chunked extendible datasets.

namespace radx::io::h5 {

inline bool has_attr(hid_t obj, const std::string& name) {
  const htri_t e = H5Aexists(obj, name.c_str());
  if (e < 0) fail("cannot look for attribute " + name + " of " + path_of(obj, ""));
  return e > 0;
}

// 1-D attribute [v.size()] of variable-length UTF-8 strings (zero-length when v is empty).
inline void write_string_array_attr(hid_t obj, const std::string& name, const std::vector<std::string>& v) {
  const std::string what = "cannot write attribute " + name + " of " + path_of(obj, "");
  std::vector<const char*> ptr(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) ptr[i] = v[i].c_str();
  const Handle type = vlen_string_type();
  const Handle space = simple_space({v.size()}, what);
  const Handle a(H5Acreate2(obj, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, what);
  if (!v.empty()) check(H5Awrite(a, type, ptr.data()), what);
}

// Reads a 1-D (or scalar, as one string) attribute of variable-length strings.
inline std::vector<std::string> read_string_array_attr(hid_t obj, const std::string& name) {
  const std::string where = "attribute " + name + " of " + path_of(obj, "");
  const Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open " + where);
  const Handle file_type(H5Aget_type(a), H5Tclose, "cannot read " + where);
  const Handle space(H5Aget_space(a), H5Sclose, "cannot read " + where);
  if (H5Tget_class(file_type) != H5T_STRING || H5Tis_variable_str(file_type) <= 0 ||
      H5Sget_simple_extent_ndims(space) > 1) {
    throw Failure(where + " is not a 1-D array of variable-length strings");
  }
  const auto n = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
  std::vector<std::string> out(n);
  if (n == 0) return out;
  const Handle type = vlen_string_type();
  std::vector<char*> ptr(n, nullptr);
  check(H5Aread(a, type, ptr.data()), "cannot read " + where);
  for (std::size_t i = 0; i < n; ++i) out[i] = ptr[i] != nullptr ? ptr[i] : "";
  reclaim_strings(type, space, ptr.data());
  return out;
}

// Reads a 1-D (or scalar) numeric attribute whatever its length.
template <class T>
std::vector<T> read_attr_array(hid_t obj, const std::string& name) {
  const std::string where = "attribute " + name + " of " + path_of(obj, "");
  const Handle a(H5Aopen(obj, name.c_str(), H5P_DEFAULT), H5Aclose, "cannot open " + where);
  const Handle space(H5Aget_space(a), H5Sclose, "cannot read " + where);
  if (H5Sget_simple_extent_ndims(space) > 1) throw Failure(where + " is not 1-D");
  std::vector<T> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  if (!out.empty()) check(H5Aread(a, Hdf5Type<T>::mem(), out.data()), "cannot read " + where);
  return out;
}

// Current dimensions of dataset `loc/name`.
inline std::vector<hsize_t> dataset_dims(hid_t loc, const std::string& name) {
  const std::string where = "dataset " + path_of(loc, name);
  const Handle ds(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, "cannot open " + where);
  const Handle space(H5Dget_space(ds), H5Sclose, "cannot read " + where);
  const int rank = H5Sget_simple_extent_ndims(space);
  if (rank < 0) fail("cannot read " + where);
  std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
  check(H5Sget_simple_extent_dims(space, dims.data(), nullptr), "cannot read " + where);
  return dims;
}

// 2-D dataset [v.size() / cols, cols], chunked by `chunk_rows` rows, whose first dimension is unlimited
// (H5S_UNLIMITED) so it can be extended with H5Dset_extent. Missing groups of `name` ("a/b/c") are created.
// Returns the open dataset, for its attributes.
template <class T>
Handle write_extendible_dataset(hid_t loc, const std::string& name, std::span<const T> v, hsize_t cols,
                                hsize_t chunk_rows) {
  const std::string what = "cannot write dataset " + path_of(loc, name);
  const std::array<hsize_t, 2> dims{cols > 0 ? v.size() / cols : 0, cols};
  const std::array<hsize_t, 2> max_dims{H5S_UNLIMITED, cols};
  const std::array<hsize_t, 2> chunk{chunk_rows > 0 ? chunk_rows : 1, cols > 0 ? cols : 1};
  const Handle space(H5Screate_simple(2, dims.data(), max_dims.data()), H5Sclose, what);
  const Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose, what);
  check(H5Pset_create_intermediate_group(lcpl, 1), what);
  const Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, what);
  check(H5Pset_chunk(dcpl, 2, chunk.data()), what);
  Handle ds(H5Dcreate2(loc, name.c_str(), Hdf5Type<T>::file(), space, lcpl, dcpl, H5P_DEFAULT), H5Dclose,
            what);
  if (!v.empty()) check(H5Dwrite(ds, Hdf5Type<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), what);
  return ds;
}

// Sets the first dimension of the extendible 2-D dataset `loc/name` to `at` + v.size() / cols rows and
// writes v's rows from row `at` on. Rows beyond `at` already there are overwritten.
template <class T>
void append_rows(hid_t loc, const std::string& name, std::span<const T> v, hsize_t cols, hsize_t at) {
  const std::string what = "cannot append to dataset " + path_of(loc, name);
  const Handle ds(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, what);
  const std::array<hsize_t, 2> count{cols > 0 ? v.size() / cols : 0, cols};
  const std::array<hsize_t, 2> dims{at + count[0], cols};
  check(H5Dset_extent(ds, dims.data()), what);
  if (count[0] == 0 || cols == 0) return;
  const Handle file_space(H5Dget_space(ds), H5Sclose, what);
  const std::array<hsize_t, 2> start{at, 0};
  check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr), what);
  const Handle mem_space(H5Screate_simple(2, count.data(), nullptr), H5Sclose, what);
  check(H5Dwrite(ds, Hdf5Type<T>::mem(), mem_space, file_space, H5P_DEFAULT, v.data()), what);
}

}  // namespace radx::io::h5
