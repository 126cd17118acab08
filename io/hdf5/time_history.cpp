// Time-history file P_th.h5 (docs/theory/results-format.md section 7;
// layout: docs/results.md "Time history").
//
// Layout, one HDF5 file:
// - root attributes: radx_th_format_version (int64, 1), time_unit (string), groups (string array: the
//   dataset path of every group, in the order they were written, which is the order of the columns of
//   `radx th --csv`).
// - one float64 dataset [rows, 1 + columns] per group at the group's path ("global", "node/1"; the
//   groups on the way are created), column 0 the time; chunked (about 16 KiB per chunk, each with a
//   Fletcher32 checksum) with an unlimited first dimension, extended at each flush.
// - dataset attributes: columns (string array, one name per column: "time", then "<object id>:<variable>"
//   object-major, or "<variable>" for the global group), units (string array, one per column), variables
//   (string array), variable_units (string array, one per variable: the units of a group without objects
//   are kept too), objects (int64 array of user ids; absent when there is none), skews (int64 array, one
//   skew user id per object, 0 for the global axes; only on a group with an object in a skew), object_kind
//   (string, "" for the global group, which has one value per variable), title (string).
//
// - root attribute radx_rows (int64): the rows of every group written by the flushes that completed.
//
// Why append in place: a long run (an end time of 1e30, a row every cycle) would otherwise hold every row
// in memory and rewrite a file growing without bound. The first flush goes through `.part` and a rename (a
// new file, or an earlier run's replaced whole); each later flush opens the file, extends every dataset,
// writes the rows held, closes and syncs it. No HDF5 handle stays open between flushes, so other programs
// can read the file during the run, and a run killed between two flushes leaves the file as the last flush
// closed it.
//
// A kill inside a flush. HDF5 writes dataset extents, chunk indexes and the end of file as it closes, in no
// order of its own: killed in the earliest file format, a reader saw one group with 4,097 rows (3,990 of
// them zeros) and the others with 1, or "addr overflow". Measured alternatives (a SIGKILL at every pwrite
// of two flushes, tests/scripts/check_th_kill_sweep.py): the 1.10 format alone marks the file "open for
// writing" while a flush runs, so HDF5 readers refuse a file killed inside one (HDF5's own message, naming
// h5clear), but `h5clear -s` then shows the torn flush (groups of 1 and 4,097 rows). So each flush opens
// the file as a SWMR writer (the 1.10 format): HDF5 then orders its metadata writes so that a SWMR reader
// sees consistent metadata whenever the writer dies, though an extent may run ahead of the rows written
// (those read as zeros). The rows go in and are flushed first, then radx_rows is raised (in the root's
// object header, written whole), then the file is closed, which clears the mark. Readers:
// - plain HDF5 readers (h5py) read a file closed by its last flush: every row of the completed flushes,
//   radx_rows equal to the datasets' rows; a file killed inside a flush (some milliseconds a flush, a few
//   flushes a second at most) they refuse with HDF5's "file is already open for write";
// - read_time_history (`radx th`) reads such a file too, as a SWMR reader, keeping radx_rows rows, and
//   says the run was killed inside a flush; `radx th FILE --recover` rewrites the file with those rows, for
//   every reader. h5clear would expose the torn flush instead.
// - a read during a flush is refused like a killed file (plain readers) or reads the completed flushes.
// Cost: per flush, an open, the extends, one extra metadata flush and an fsync; nothing grows with the run.
#include "io/hdf5/time_history.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "io/hdf5/hdf5_util.hpp"

namespace radx::io {

namespace {

constexpr std::int64_t kFormatVersion = 1;
// Root attribute (int64): the rows of every group written by completed flushes.
constexpr const char* kRowsAttr = "radx_rows";

// A group of objects (a /TH group: it has an object kind) has variables per object, possibly no object
// at all (a deck may list none, with a warning); a group without a kind (the global variables) has one
// value per variable.
bool per_object(const ThGroupLayout& g) {
  return !g.object_kind.empty() || !g.objects.empty();
}

// Values per row of a group, time excluded.
std::size_t value_count(const ThGroupLayout& g) {
  return g.variables.size() * (per_object(g) ? g.objects.size() : 1);
}

// Column names inside the group (the `columns` attribute): ThColumn::name without "<path>:".
std::vector<std::string> local_column_names(const ThGroupLayout& g) {
  std::vector<std::string> names{"time"};
  names.reserve(1 + value_count(g));
  if (!per_object(g)) {
    names.insert(names.end(), g.variables.begin(), g.variables.end());
  } else {
    for (const auto id : g.objects) {
      for (const auto& v : g.variables) names.push_back(std::to_string(id) + ':' + v);
    }
  }
  return names;
}

std::vector<std::string> column_units(const ThGroupLayout& g, const std::string& time_unit) {
  std::vector<std::string> units{time_unit};
  const std::size_t repeat = per_object(g) ? g.objects.size() : 1;
  for (std::size_t o = 0; o < repeat; ++o) units.insert(units.end(), g.units.begin(), g.units.end());
  return units;
}

// Names are split at ':' (column names, `radx th` selectors) and paths at '/', so a group path must be
// a plain relative HDF5 path without ':', and no group may sit inside another group's dataset. A
// repeated object is accepted (the deck may list a node twice): its columns repeat, under the same names.
void validate(const std::string& file, const std::vector<ThGroupLayout>& groups) {
  auto bad = [&](const std::string& why) {
    throw std::invalid_argument("time history " + file + ": " + why);
  };
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const auto& g = groups[i];
    const std::string& p = g.path;
    if (p.empty() || p.front() == '/' || p.back() == '/' || p.find("//") != std::string::npos ||
        p.find(':') != std::string::npos || p == "." || p.starts_with("./") ||
        p.find("/./") != std::string::npos || p.ends_with("/.")) {
      bad("group path '" + p + "' is not a relative path of names without ':'");
    }
    if (g.variables.empty()) bad("group " + p + " has no variables");
    if (!g.skews.empty() && g.skews.size() != g.objects.size())
      bad("group " + p + " has " + std::to_string(g.skews.size()) + " skews for " +
          std::to_string(g.objects.size()) + " objects");
    if (g.units.size() != g.variables.size()) {
      bad("group " + p + " has " + std::to_string(g.variables.size()) + " variables but " +
          std::to_string(g.units.size()) + " units");
    }
    for (std::size_t v = 0; v < g.variables.size(); ++v) {
      const auto& name = g.variables[v];
      if (name.empty() || name.find(':') != std::string::npos) {
        bad("group " + p + " has a variable name that is empty or holds ':' ('" + name + "')");
      }
      for (std::size_t w = 0; w < v; ++w) {
        if (g.variables[w] == name) bad("group " + p + " lists variable " + name + " twice");
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      const std::string& q = groups[j].path;
      if (q == p) bad("two groups have the path " + p);
      if (p.starts_with(q + '/') || q.starts_with(p + '/'))
        bad("group " + p + " and group " + q + " overlap");
    }
  }
}

// Rows per chunk, fixed when the file is created: about 16 KiB per chunk (at least one row). A short
// history wastes at most one partly filled chunk per group; a long one is not cut into tiny chunks.
hsize_t chunk_rows(std::size_t cols) {
  return static_cast<hsize_t>(std::max<std::size_t>(1, 2048 / cols));
}

}  // namespace

std::vector<ThColumn> th_columns(const ThGroupLayout& layout, const std::string& time_unit) {
  const auto names = local_column_names(layout);
  const auto units = column_units(layout, time_unit);
  std::vector<ThColumn> out;
  out.reserve(names.size());
  out.push_back({names[0], units[0]});
  for (std::size_t c = 1; c < names.size(); ++c) out.push_back({layout.path + ':' + names[c], units[c]});
  return out;
}

struct TimeHistoryWriter::Impl {
  std::string path;
  std::vector<ThGroupLayout> groups;
  std::string time_unit;
  ThFlushPolicy policy;
  std::size_t max_buffered = 1;           // rows held before append flushes them
  std::size_t row_values = 1;             // values a row, time columns included
  std::vector<std::vector<double>> data;  // per group, the rows not yet in the file: [rows][1 + values]
  std::size_t rows = 0;                   // appended in all
  std::size_t on_disk = 0;                // rows in the file
  bool created = false;
  double last_time = 0;
  std::chrono::steady_clock::time_point last_flush = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_append = last_flush;

  [[nodiscard]] std::size_t buffered() const { return rows - on_disk; }
  [[nodiscard]] std::uint64_t flush_bytes() const;
  void create_file() const;
  void extend_file() const;
};

// The first flush writes a new file through `.part` and a rename, so an earlier run's file is replaced
// whole and never mixed with this run's rows.
void TimeHistoryWriter::Impl::create_file() const {
  const std::string part = path + ".part";
  try {
    {
      h5::WriteFile file = h5::create_file(part, true);
      h5::write_attr(file, "radx_th_format_version", &kFormatVersion);
      h5::write_string_attr(file, "time_unit", time_unit);
      std::vector<std::string> paths;
      for (const auto& g : groups) paths.push_back(g.path);
      h5::write_string_array_attr(file, "groups", paths);
      const auto complete = static_cast<std::int64_t>(buffered());
      h5::write_attr(file, kRowsAttr, &complete);
      for (std::size_t i = 0; i < groups.size(); ++i) {
        const ThGroupLayout& g = groups[i];
        const std::size_t cols = 1 + value_count(g);
        const h5::Handle ds =
            h5::write_extendible_dataset<double>(file, g.path, data[i], cols, chunk_rows(cols));
        h5::write_string_array_attr(ds, "columns", local_column_names(g));
        h5::write_string_array_attr(ds, "units", column_units(g, time_unit));
        h5::write_string_array_attr(ds, "variables", g.variables);
        h5::write_string_array_attr(ds, "variable_units", g.units);
        if (!g.objects.empty()) {
          h5::write_attr(ds, "objects", g.objects.data(), static_cast<hsize_t>(g.objects.size()));
        }
        if (!g.skews.empty()) {
          h5::write_attr(ds, "skews", g.skews.data(), static_cast<hsize_t>(g.skews.size()));
        }
        h5::write_string_attr(ds, "object_kind", g.object_kind);
        h5::write_string_attr(ds, "title", g.title);
      }
      file.close();
    }
    h5::sync_file(part);
    h5::replace_file(part, path);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(part, ignored);
    throw;
  }
}

// Disk space an in-place flush may take past the file's end, generously: the rows held twice (a partly
// filled chunk is written anew elsewhere), two chunks more per group, and 64 KiB for the metadata that
// grows with them (chunk indexes, object headers).
std::uint64_t TimeHistoryWriter::Impl::flush_bytes() const {
  std::uint64_t bytes = std::uint64_t{1} << 16;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const std::size_t cols = 1 + value_count(groups[i]);
    bytes += 2 * sizeof(double) * (data[i].size() + 2 * chunk_rows(cols) * cols);
  }
  return bytes;
}

// Later flushes extend every dataset in place to the same absolute row count and write the new rows at
// the same absolute offset, so a failed flush retried later writes the same rows to the same places.
// The rows go in first and are flushed (SWMR orders those writes); only then is the count of complete rows
// raised, one 8-byte write, so a reader that honours the count never reads a row of an unfinished flush.
void TimeHistoryWriter::Impl::extend_file() const {
  {
    h5::reserve_space_at(path, flush_bytes());
    h5::WriteFile file = h5::open_file_read_write(path, true);
    for (std::size_t i = 0; i < groups.size(); ++i) {
      const std::size_t cols = 1 + value_count(groups[i]);
      h5::append_rows<double>(file, groups[i].path, data[i], cols, static_cast<hsize_t>(on_disk));
    }
    file.flush();
    {
      const std::int64_t complete = static_cast<std::int64_t>(rows);
      const std::string what = std::string("cannot write attribute ") + kRowsAttr + " of " + path;
      const h5::Handle attr(H5Aopen(file, kRowsAttr, H5P_DEFAULT), H5Aclose, what);
      h5::check(H5Awrite(attr, H5T_NATIVE_INT64, &complete), what);
    }
    file.close();
  }
  h5::sync_file(path);
}

// Rows enough for a flush are written only min_seconds after the last flush (it costs an open, an extend
// and a sync, whatever the rows), unless they reach the memory cap; a long pause flushes what is held.
bool th_flush_due(const ThFlushPolicy& policy, std::size_t rows, std::size_t row_values, double since_flush,
                  double since_append) {
  if (rows == 0) return false;
  if (since_flush >= policy.max_seconds || since_append >= policy.max_seconds) return true;
  row_values = std::max<std::size_t>(1, row_values);
  // The memory cap: max_values for rows narrower than that (flushed as before, whatever the time: a fast
  // run's rows must not pile up), cap_values for wider ones.
  const std::size_t cap = row_values < policy.max_values ? policy.max_values : policy.cap_values;
  if (rows >= std::max<std::size_t>(1, cap / row_values)) return true;
  const std::size_t enough =
      std::max<std::size_t>(1, std::min(policy.max_rows, policy.max_values / row_values));
  return rows >= enough && since_flush >= policy.min_seconds;
}

TimeHistoryWriter::TimeHistoryWriter(std::string path, std::vector<ThGroupLayout> groups,
                                     std::string time_unit, ThFlushPolicy policy)
    : impl_(std::make_unique<Impl>()) {
  validate(path, groups);
  impl_->path = std::move(path);
  impl_->groups = std::move(groups);
  impl_->time_unit = std::move(time_unit);
  impl_->policy = policy;
  std::size_t row_values = 0;
  for (const auto& g : impl_->groups) row_values += 1 + value_count(g);
  impl_->row_values = row_values;
  impl_->max_buffered = std::max<std::size_t>(1, std::min(policy.max_rows, policy.max_values / row_values));
  impl_->data.resize(impl_->groups.size());
}

TimeHistoryWriter::~TimeHistoryWriter() = default;

// Checked before anything is stored, so a bad call leaves every group with the same rows.
void TimeHistoryWriter::append(double time, const std::vector<std::span<const double>>& values) {
  Impl& m = *impl_;
  const std::string where = "time history " + m.path + ": ";
  if (values.size() != m.groups.size()) {
    throw std::invalid_argument(where + "append got " + std::to_string(values.size()) + " value sets for " +
                                std::to_string(m.groups.size()) + " groups");
  }
  if (!std::isfinite(time)) throw std::invalid_argument(where + "append got a time that is not finite");
  // Times must not go back: the CSV export and plots read each column as a function of time.
  if (m.rows > 0 && time < m.last_time) {
    throw std::invalid_argument(where + "append got a time earlier than the last row's");
  }
  for (std::size_t g = 0; g < m.groups.size(); ++g) {
    if (values[g].size() != value_count(m.groups[g])) {
      throw std::invalid_argument(where + "group " + m.groups[g].path + " needs " +
                                  std::to_string(value_count(m.groups[g])) + " values per row, got " +
                                  std::to_string(values[g].size()));
    }
  }
  for (std::size_t g = 0; g < m.groups.size(); ++g) {
    m.data[g].push_back(time);
    m.data[g].insert(m.data[g].end(), values[g].begin(), values[g].end());
  }
  ++m.rows;
  m.last_time = time;
  // A row that comes max_seconds or more after the previous one is written at once: rows that rare are
  // likely followed by a long wait, during which a held row would be lost to a kill.
  const auto now = std::chrono::steady_clock::now();
  const auto seconds_since = [&](std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(now - t).count();
  };
  const bool due = th_flush_due(m.policy, m.buffered(), m.row_values, seconds_since(m.last_flush),
                                seconds_since(m.last_append));
  m.last_append = now;
  if (due) flush();
}

void TimeHistoryWriter::flush() {
  Impl& m = *impl_;
  m.last_flush = std::chrono::steady_clock::now();
  if (m.created && m.buffered() == 0) return;
  const h5::QuietHdf5 quiet;
  try {
    if (m.created)
      m.extend_file();
    else
      m.create_file();
  } catch (const std::exception& e) {
    throw std::runtime_error("cannot write the time history " + m.path + ": " + e.what());
  }
  m.created = true;
  m.on_disk = m.rows;
  // clear() keeps the capacity: the buffer's memory stays at its bound instead of being allocated again.
  for (auto& d : m.data) d.clear();
}

std::size_t TimeHistoryWriter::buffered_rows() const {
  return impl_->buffered();
}

std::size_t TimeHistoryWriter::max_buffered_rows() const {
  return impl_->max_buffered;
}

std::size_t TimeHistoryWriter::rows() const {
  return impl_->rows;
}

namespace {

// A file whose "open for writing" flag is set (its run was killed inside a flush, or a flush is under way) is
// opened as a SWMR reader, which HDF5 allows because the writer was a SWMR writer.
h5::Handle open_for_reading(const std::string& path, bool& interrupted) {
  interrupted = false;
  try {
    return h5::open_file_read_only(path);
  } catch (const h5::Failure& e) {
    if (!h5::open_for_write_refusal(e.what())) throw;
  }
  interrupted = true;
  try {
    return h5::open_file_swmr_read(path);
  } catch (const h5::Failure& e) {
    throw h5::Failure(std::string("the file was being written when its run was killed (or a flush is under "
                                  "way: retry in a moment), and cannot be read even so: ") +
                      e.what() + "; run the engine again to write it anew");
  }
}

}  // namespace

bool read_time_history(const std::string& path, std::vector<ThGroupData>& groups, std::string& error,
                       bool* interrupted) {
  groups.clear();
  if (interrupted != nullptr) *interrupted = false;
  const h5::QuietHdf5 quiet;
  try {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) throw h5::Failure("no such file");
    bool killed = false;
    const h5::Handle file = open_for_reading(path, killed);
    if (interrupted != nullptr) *interrupted = killed;
    if (!h5::has_attr(file, "radx_th_format_version")) {
      throw h5::Failure("not a radx time-history file (no root attribute radx_th_format_version)");
    }
    const auto version = h5::read_attr<std::int64_t>(file, "radx_th_format_version");
    if (version != kFormatVersion) {
      throw h5::Failure("time-history format version " + std::to_string(version) +
                        ", this radx reads version " + std::to_string(kFormatVersion));
    }
    const std::string time_unit = h5::read_string_attr(file, "time_unit");
    // Files written before the count was kept have none: their rows are those of the datasets.
    std::int64_t complete = -1;
    if (h5::has_attr(file, kRowsAttr)) {
      complete = h5::read_attr<std::int64_t>(file, kRowsAttr);
      if (complete < 0) throw h5::Failure(std::string("root attribute ") + kRowsAttr + " is negative");
    }
    for (const auto& p : h5::read_string_array_attr(file, "groups")) {
      ThGroupData d;
      d.time_unit = time_unit;
      d.layout.path = p;
      const std::string where = "dataset /" + p;
      const h5::Handle ds(H5Dopen2(file, p.c_str(), H5P_DEFAULT), H5Dclose, "cannot open " + where);
      d.layout.title = h5::read_string_attr(ds, "title");
      d.layout.object_kind = h5::read_string_attr(ds, "object_kind");
      d.layout.variables = h5::read_string_array_attr(ds, "variables");
      if (h5::has_attr(ds, "objects")) d.layout.objects = h5::read_attr_array<std::int64_t>(ds, "objects");
      if (h5::has_attr(ds, "skews")) d.layout.skews = h5::read_attr_array<std::int64_t>(ds, "skews");
      d.layout.units = h5::read_string_array_attr(ds, "variable_units");
      const auto units = h5::read_string_array_attr(ds, "units");
      const auto columns = h5::read_string_array_attr(ds, "columns");
      const auto dims = h5::dataset_dims(file, p);
      const std::size_t cols = 1 + value_count(d.layout);
      if (d.layout.variables.empty() || d.layout.units.size() != d.layout.variables.size() ||
          dims.size() != 2 || dims[1] != cols ||
          (!d.layout.skews.empty() && d.layout.skews.size() != d.layout.objects.size())) {
        throw h5::Failure(where + ": its shape, variables, variable units and objects do not agree");
      }
      // The column names and units follow from the variables and objects; attributes that say otherwise
      // mean a file written by something else, whose columns we would mislabel.
      if (columns != local_column_names(d.layout) || units != column_units(d.layout, time_unit)) {
        throw h5::Failure(where + ": attributes columns and units do not follow its variables and objects");
      }
      d.columns = cols;
      d.rows = h5::read_dataset<double>(file, p, cols);
      // Rows past the count belong to a flush that did not complete (a killed run): left out.
      if (complete >= 0) {
        const auto want = static_cast<std::size_t>(complete) * cols;
        if (d.rows.size() < want) {
          throw h5::Failure(where + " has " + std::to_string(d.rows.size() / cols) +
                            " rows, fewer than the " + std::to_string(complete) + " of " + kRowsAttr);
        }
        d.rows.resize(want);
      }
      groups.push_back(std::move(d));
    }
  } catch (const std::exception& e) {
    groups.clear();
    error = path + ": " + e.what();
    return false;
  }
  return true;
}

bool rewrite_time_history(const std::string& path, const std::vector<ThGroupData>& groups,
                          std::string& error) {
  if (groups.empty()) {
    error = path + ": no group to write";
    return false;
  }
  try {
    std::vector<ThGroupLayout> layouts;
    for (const auto& g : groups) layouts.push_back(g.layout);
    // One flush at the end: the file is replaced whole, through `.part` and a rename, or not at all.
    const ThFlushPolicy once{.max_rows = SIZE_MAX,
                             .max_values = SIZE_MAX,
                             .max_seconds = 1e300,
                             .min_seconds = 0,
                             .cap_values = SIZE_MAX};
    TimeHistoryWriter w(path, layouts, groups.front().time_unit, once);
    const std::size_t n =
        groups.front().columns == 0 ? 0 : groups.front().rows.size() / groups.front().columns;
    std::vector<std::span<const double>> row(groups.size());
    for (std::size_t r = 0; r < n; ++r) {
      for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::size_t c = groups[g].columns;
        row[g] = std::span<const double>(groups[g].rows).subspan(r * c + 1, c - 1);
      }
      w.append(groups.front().rows[r * groups.front().columns], row);
    }
    w.flush();
  } catch (const std::exception& e) {
    error = path + ": " + e.what();
    return false;
  }
  return true;
}

}  // namespace radx::io
