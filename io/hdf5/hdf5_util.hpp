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
// - Every dataset with values is chunked and checksummed (HDF5's Fletcher32 filter), so a reader finds a
//   damaged byte of its values instead of reading it. Not covered: datasets of variable-length strings
//   (HDF5 filters do not take them), and the metadata (object headers, attributes) except in the files of
//   the 1.10 format (create_file's `marked`), whose metadata carries checksums.
// - Datasets are written with one H5Dwrite each, without fill and without the chunk cache (each chunk is
//   checksummed and written as H5Dwrite reaches it); memory and file types are both little-endian, so
//   HDF5 copies without conversion. That keeps large arrays fast to write.
// - A file open for writing is a WriteFile, never a bare Handle: see there why.
#pragma once

#include <fcntl.h>
#include <hdf5.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstring>
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

// An HDF5 message about a failed system call, "file write failed: time = Mon Dec  7 18:59:00 2026\n,
// filename = './P_000010.hdf.part', file descriptor = 5, errno = 28, error message = 'No space left on
// device', buf = 0x..., total write size = 760, ...", as what it says: "file write failed: No space left on
// device". Other messages are returned unchanged.
inline std::string condensed_system_error(const std::string& message) {
  const std::string key = "error message = '";
  const std::size_t at = message.find(key);
  const std::size_t colon = message.find(':');
  if (at == std::string::npos || colon == std::string::npos || colon > at) return message;
  const std::size_t end = message.find('\'', at + key.size());
  if (end == std::string::npos) return message;
  return message.substr(0, colon) + ": " + message.substr(at + key.size(), end - at - key.size());
}

// Innermost (most specific) message of the HDF5 error stack, e.g. "unable to open file: No such file or
// directory" (condensed_system_error) or "data error detected by Fletcher32 checksum". Clears the stack.
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
  if (detail.find("Fletcher32 checksum") != std::string::npos)
    return "checksum mismatch, the file is damaged: " + detail;
  return condensed_system_error(detail);
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

// The descriptor of the file of `obj` (a file, or an object in it) when the file is written by the sec2
// driver (the default one), else nullptr.
inline int* sec2_descriptor(hid_t obj) {
  const Handle file(H5Iget_file_id(obj), H5Fclose, "cannot find the file of an HDF5 object");
  const hid_t fapl = H5Fget_access_plist(file);
  const bool sec2 = fapl >= 0 && H5Pget_driver(fapl) == H5FD_SEC2;
  if (fapl >= 0) H5Pclose(fapl);
  int* fd = nullptr;
  if (!sec2 || H5Fget_vfd_handle(file, H5P_DEFAULT, reinterpret_cast<void**>(&fd)) < 0) fd = nullptr;
  H5Eclear2(H5E_DEFAULT);
  return fd;
}

// Sets aside, on descriptor `fd` of file `name` whose allocated space ends at `allocated`, the disk space of
// what is allocated and not yet written (its holes and what lies past its end) plus `bytes` more. Throws
// Failure naming the file and the system's reason when the space is not there: a full disk, a quota, or a
// file size beyond the process's limit (RLIMIT_FSIZE, whose writes would fail with "File too large"). File
// systems that cannot reserve space (fallocate) are written without.
inline void reserve_on(int fd, const std::string& name, std::uint64_t allocated, std::uint64_t bytes) {
  struct stat st {};
  if (::fstat(fd, &st) != 0) return;
  const auto eof = static_cast<std::uint64_t>(st.st_size);
  const std::uint64_t end = std::max<std::uint64_t>(eof, allocated) + bytes;
  const auto failure = [&](int error) {
    return Failure("cannot write file " + name + ": " + std::strerror(error));
  };
  // With 64 KiB to spare: HDF5 allocates the metadata of the groups and attributes created between two
  // reservations beyond `end`, and closing an abandoned file writes up to what was allocated, which must
  // stay within the limit.
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      end + (std::uint64_t{1} << 16) > limit.rlim_cur)
    throw failure(EFBIG);
  // From the first hole: HDF5 writes the metadata where it allocated it, among the raw data written since,
  // so a file being written has holes below its end until it is flushed. Space set aside is no hole any
  // more: each byte is reserved once.
  const off_t hole = ::lseek(fd, 0, SEEK_HOLE);
  const auto start = static_cast<std::uint64_t>(hole >= 0 ? hole : static_cast<off_t>(eof));
  if (start < end &&
      ::fallocate(fd, FALLOC_FL_KEEP_SIZE, static_cast<off_t>(start), static_cast<off_t>(end - start)) != 0 &&
      errno != EOPNOTSUPP && errno != ENOSYS && errno != EINVAL)
    throw failure(errno);
}

// reserve_on for the file of `obj` (a file open for writing, or an object in it), so that HDF5's writes to
// come do not fail for want of space (see WriteFile).
inline void reserve_space(hid_t obj, std::uint64_t bytes) {
  int* fd = sec2_descriptor(obj);
  haddr_t eoa = 0;
  std::string name;
  {
    const Handle file(H5Iget_file_id(obj), H5Fclose, "cannot find the file of an HDF5 object");
    const ssize_t n = H5Fget_name(file, nullptr, 0);
    if (fd == nullptr || n < 0 || H5Fget_eoa(file, &eoa) < 0) {
      H5Eclear2(H5E_DEFAULT);
      return;
    }
    name.resize(static_cast<std::size_t>(n));
    H5Fget_name(file, name.data(), name.size() + 1);
  }
  reserve_on(*fd, name, eoa, bytes);
}

// reserve_on for the existing file `path`, before it is opened for writing in place: a failure then leaves
// the file as it was, its "open for writing" flag (write_access) not set.
inline void reserve_space_at(const std::string& path, std::uint64_t bytes) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) return;  // the open for writing says why
  try {
    reserve_on(fd, path, 0, bytes);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
}

// Owner of an HDF5 file open for writing.
//
// Why not a Handle: when a write of HDF5 1.10 fails (a full disk, an I/O error) as it flushes or closes a
// file, the file can no longer be closed (a failed flush leaves its metadata cache in a state every later
// flush refuses), and a failed H5Fclose frees the file object but keeps its id, which HDF5 closes again as
// the library shuts down at exit: a crash (SIGSEGV, or "infinite loop closing library") after the error was
// reported. (HDF5 1.14.1 fixed the freeing.) So HDF5 must not meet a failed write as it flushes:
// - disk space is set aside (reserve_space) before each dataset is written, and before each flush for
//   what the flush writes: a full disk, or a file size beyond the process's limit (RLIMIT_FSIZE), fails
//   there, before HDF5 writes;
// - the raw data goes out with the H5Dwrite calls (datasets are written without chunk cache), whose
//   failure is harmless;
// - on an error path (the destructor runs, or the reservation fails) the file is abandoned: its descriptor
//   is pointed at an anonymous memory file, where the writes of the close succeed, and only then closed.
//   The file then holds on disk what was written before the failure (in the 1.10 format with its "open for
//   writing" flag set, see write_access): callers remove a `.part` file.
// File systems that cannot reserve space (fallocate) are written without: there a failure inside the flush
// itself is still possible.
//
// Objects of the file (datasets, groups, attributes) must be closed before it: declared after it, in an
// inner scope. They do no I/O as they close.
class WriteFile {
 public:
  WriteFile(hid_t id, std::string path, const std::string& what) : id_(id), path_(std::move(path)) {
    if (id_ < 0) fail(what);
  }
  WriteFile(WriteFile&& o) noexcept : id_(std::exchange(o.id_, -1)), path_(std::move(o.path_)) {}
  WriteFile(const WriteFile&) = delete;
  WriteFile& operator=(const WriteFile&) = delete;
  WriteFile& operator=(WriteFile&&) = delete;
  // Not closed: an error path. The file is abandoned, then closed.
  ~WriteFile() {
    if (id_ < 0) return;
    abandon();
    H5Fclose(std::exchange(id_, -1));
    H5Eclear2(H5E_DEFAULT);
  }
  operator hid_t() const { return id_; }  // NOLINT: used as an hid_t in HDF5 calls
  [[nodiscard]] const std::string& path() const { return path_; }

  // See reserve_space.
  void reserve(std::uint64_t bytes) const { reserve_space(id_, bytes); }

  // Writes what HDF5 holds of the file (the metadata; raw data is written as it comes).
  void flush() const {
    reserve(kFlushMargin);
    check(H5Fflush(id_, H5F_SCOPE_LOCAL), "cannot write file " + path_);
  }

  // Writes what is left and closes the file. Throws Failure naming the file and the system's reason when
  // a write fails (the file is then closed all the same, abandoned).
  void close() {
    try {
      flush();
    } catch (const Failure&) {
      abandon();
      H5Fclose(std::exchange(id_, -1));
      H5Eclear2(H5E_DEFAULT);
      throw;
    }
    check(H5Fclose(std::exchange(id_, -1)), "cannot write file " + path_);
    // Gives back what the reservation set aside past the end: truncating a file to its size frees it.
    struct stat st {};
    if (::stat(path_.c_str(), &st) == 0) static_cast<void>(::truncate(path_.c_str(), st.st_size));
  }

 private:
  // What a flush may write past what is allocated: the metadata cache's entries have their space already
  // (HDF5 allocates it as it creates them); the free-space and superblock updates of a flush are small.
  static constexpr std::uint64_t kFlushMargin = std::uint64_t{1} << 16;

  // Points the file's descriptor at an anonymous memory file, so the writes HDF5 makes as it closes the
  // file succeed and go nowhere.
  void abandon() const {
    int* fd = sec2_descriptor(id_);
    const int sink = fd != nullptr ? ::memfd_create("radx-abandoned-hdf5-file", MFD_CLOEXEC) : -1;
    if (sink < 0) return;
    ::dup2(sink, *fd);
    ::close(sink);
  }

  hid_t id_;
  std::string path_;
};

// File access of the files radx writes. The close degree SEMI makes closing the file fail, instead of
// being silently deferred, if an object of it were still open: a successful close() means all written.
// `marked` writes the 1.10 file format (superblock version 3, checksummed metadata), whose superblock holds
// a "file open for writing" flag: set as the file is opened for writing, cleared as it is closed, so a
// reader refuses a file whose writer was killed before closing it. (Not for the files ParaView reads: its
// 5.11 cannot read that format, docs/theory/results-format.md section 2.)
inline Handle write_access(const std::string& what, bool marked) {
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, what);
  check(H5Pset_fclose_degree(fapl, H5F_CLOSE_SEMI), what);
  if (marked) check(H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_V110), what);
  return fapl;
}

// Creates (truncates) `path` for writing. The chunk index of a dataset of the earliest file format is a
// B-tree whose nodes HDF5 sizes for 2 * 32 chunks by default, some 2 KiB a dataset: 4 (8 chunks a node)
// keeps a file of many small datasets from doubling, and a large array (a few hundred 1 MiB chunks) a
// shallow tree.
inline WriteFile create_file(const std::string& path, bool marked = false) {
  const std::string what = "cannot create file " + path;
  const Handle fapl = write_access(what, marked);
  const Handle fcpl(H5Pcreate(H5P_FILE_CREATE), H5Pclose, what);
  check(H5Pset_istore_k(fcpl, 4), what);
  return WriteFile(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl, fapl), path, what);
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
// format's "open for writing" flag in the superblock, which HDF5 sets at this open and clears at the close.
// `swmr`: as the single writer of SWMR (a 1.10-format file only): HDF5 then orders its metadata writes so
// that a SWMR reader sees a consistent file at every moment, also after the writer is killed.
inline WriteFile open_file_read_write(const std::string& path, bool swmr = false) {
  const std::string what = "cannot open file " + path;
  const Handle fapl = write_access(what, swmr);
  check(H5Pset_file_locking(fapl, false, true), what);
  return WriteFile(H5Fopen(path.c_str(), H5F_ACC_RDWR | (swmr ? H5F_ACC_SWMR_WRITE : 0u), fapl), path, what);
}

// Flushes a closed file's data to disk. Called before renaming `name.part` to `name`, so a system crash
// cannot leave a renamed but empty file.
inline void sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  const bool synced = fd >= 0 && ::fsync(fd) == 0;
  const int error = synced ? 0 : errno;
  if (fd >= 0) ::close(fd);
  if (!synced) throw Failure("cannot flush file " + path + " to disk: " + std::strerror(error));
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

// Bytes of a dataset chunk, about: big enough that a large array is a few chunks a megabyte each (a
// chunk costs a checksum, an index entry and a write), small enough that a reader of some rows reads
// little more than those. A smaller dataset is one chunk.
inline constexpr std::size_t kChunkBytes = std::size_t{1} << 20;

// Chunk shape of a dataset of `dims` (not empty) whose values have `value_size` bytes: whole rows (every
// dimension after the first in full), the rows shared evenly among as many chunks of at most about
// kChunkBytes as needed. Evenly, because HDF5 stores a dataset's last chunk whole however few of its rows
// the dataset has: chunks of kChunkBytes would waste up to one per dataset (a 1.05 MiB array stored in 2
// MiB).
inline std::vector<hsize_t> chunk_shape(const std::vector<hsize_t>& dims, std::size_t value_size) {
  std::vector<hsize_t> chunk = dims;
  hsize_t row_bytes = value_size;
  for (std::size_t d = 1; d < dims.size(); ++d) row_bytes *= std::max<hsize_t>(1, dims[d]);
  const hsize_t rows = std::max<hsize_t>(1, dims[0]);
  const hsize_t rows_per_chunk = std::max<hsize_t>(1, kChunkBytes / row_bytes);
  const hsize_t chunks = (rows + rows_per_chunk - 1) / rows_per_chunk;
  chunk[0] = (rows + chunks - 1) / chunks;
  return chunk;
}

// Creation properties of a checksummed dataset: chunks of `chunk`, each with a Fletcher32 checksum that
// HDF5 checks as it reads the chunk; no fill value written (every value is written).
inline Handle checksummed_chunks(const std::vector<hsize_t>& chunk, const std::string& what) {
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, what);
  check(H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data()), what);
  check(H5Pset_fletcher32(dcpl), what);
  check(H5Pset_fill_time(dcpl, H5D_FILL_TIME_NEVER), what);
  return dcpl;
}

// Access properties of a dataset being written: no chunk cache, so each chunk is written by the H5Dwrite
// that fills it, and a failed write is that call's failure; a chunk held in the cache would be written as
// the dataset closes, where HDF5 1.10 cannot fail cleanly (see WriteFile).
inline Handle uncached_access(const std::string& what) {
  Handle dapl(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose, what);
  check(H5Pset_chunk_cache(dapl, 0, 0, 1.0), what);
  return dapl;
}

// Creates a dataset of `dims` and writes it with a single H5Dwrite: checksummed chunks (checksummed_chunks)
// when it has values, contiguous when empty (nothing to check; a chunk cannot be larger than a fixed
// dimension of 0). `data` holds product(dims) values.
inline void write_raw(hid_t loc, const std::string& name, hid_t file_type, hid_t mem_type, const void* data,
                      const std::vector<hsize_t>& dims) {
  const std::string what = "cannot write dataset " + path_of(loc, name);
  const Handle space = simple_space(dims, what);
  hsize_t count = 1;
  for (const hsize_t d : dims) count *= d;
  const Handle dcpl = count > 0 ? checksummed_chunks(chunk_shape(dims, H5Tget_size(file_type)), what)
                                : Handle(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, what);
  const Handle dapl = uncached_access(what);
  // The values, a checksum a chunk, and the object header.
  reserve_space(loc, count * H5Tget_size(file_type) + 4 * (count / std::max<hsize_t>(1, kChunkBytes)) + 4096);
  const Handle ds(H5Dcreate2(loc, name.c_str(), file_type, space, H5P_DEFAULT, dcpl, dapl), H5Dclose, what);
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
  // Contiguous: HDF5 filters, the checksum among them, do not take variable-length data.
  std::uint64_t bytes = 4096;  // the object header and a global heap collection's header
  for (const std::string& t : v) bytes += t.size() + 32;
  reserve_space(loc, bytes);
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

// 2-D dataset [v.size() / cols, cols], in checksummed chunks of `chunk_rows` rows, whose first dimension is
// unlimited (H5S_UNLIMITED) so it can be extended with H5Dset_extent. Missing groups of `name` ("a/b/c") are
// created. Returns the open dataset, for its attributes.
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
  const Handle dcpl = checksummed_chunks({chunk[0], chunk[1]}, what);
  const Handle dapl = uncached_access(what);
  Handle ds(H5Dcreate2(loc, name.c_str(), Hdf5Type<T>::file(), space, lcpl, dcpl, dapl), H5Dclose, what);
  if (!v.empty()) check(H5Dwrite(ds, Hdf5Type<T>::mem(), H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()), what);
  return ds;
}

// Sets the first dimension of the extendible 2-D dataset `loc/name` to `at` + v.size() / cols rows and
// writes v's rows from row `at` on. Rows beyond `at` already there are overwritten.
template <class T>
void append_rows(hid_t loc, const std::string& name, std::span<const T> v, hsize_t cols, hsize_t at) {
  const std::string what = "cannot append to dataset " + path_of(loc, name);
  const Handle dapl = uncached_access(what);
  const Handle ds(H5Dopen2(loc, name.c_str(), dapl), H5Dclose, what);
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
