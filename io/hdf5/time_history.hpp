// Time history P_th.h5 (docs/theory/results-format.md section 7): one dataset per group of variables, rows in
// time, time as the first column, the variable names, object ids and units as attributes. The first flush
// creates the file through `P_th.h5.part` and an atomic rename; later flushes append the rows held since
// in place, so memory and the cost of a flush do not grow with the run. A run killed between flushes keeps
// what the last flush wrote; one killed inside a flush leaves a file HDF5 readers refuse, which
// read_time_history reads (the rows of the completed flushes) and rewrite_time_history makes whole again.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace radx::io {

// A group of columns written together: the global variables, or one /TH/... group of the deck.
struct ThGroupLayout {
  std::string path;                    // dataset path in the file, e.g. "global", "node/1", "part/2"
  std::string title;                   // the deck's title of the /TH group ("" for global)
  std::string object_kind;             // "node", "part", "interface", "rigid wall", "shell", "subset",
                                       // "brick", "3-node shell", "rigid body", "section"; "" for global
  std::vector<std::int64_t> objects;   // user ids, in column order (empty for global)
  std::vector<std::string> variables;  // names per object, e.g. DX DY DZ (the same for every object)
  std::vector<std::string> units;      // unit of each variable, same length as `variables`
  // Nodes: the skew (user id, 0 global axes) each object's vectors are written in, one per object; empty
  // when every object is on the global axes.
  std::vector<std::int64_t> skews;
};

// When append flushes by itself: once it holds max_rows rows or max_values values (time columns
// included; at least one row), or max_seconds of wall time after the last flush or the last row,
// whichever comes first.
// The defaults bound the rows held to about 2 MiB (narrow rows) and what a killed run loses to one second.
// Rows enough for a flush wait until min_seconds have passed since the last flush, up to a memory cap: at
// most max_values values (2 MiB) for rows narrower than that, cap_values (32 MiB; at least one row) for
// wider ones (a /TH of 40,000 nodes, which would otherwise flush every row). So the file is opened,
// extended and synced a few times a second at most unless the cap is reached.
struct ThFlushPolicy {
  std::size_t max_rows = 4096;
  std::size_t max_values = std::size_t{1} << 18;
  double max_seconds = 1.0;
  double min_seconds = 0.2;
  std::size_t cap_values = std::size_t{1} << 22;
};

// Whether append flushes now, holding `rows` rows of `row_values` values (time columns included), the last
// flush `since_flush` seconds ago and the row before the last `since_append` seconds before it.
bool th_flush_due(const ThFlushPolicy& policy, std::size_t rows, std::size_t row_values, double since_flush,
                  double since_append);

class TimeHistoryWriter {
 public:
  // `path` is the file to write; nothing is written before the first flush. `time_unit` labels column 0.
  // Throws std::invalid_argument for layouts the file cannot hold: a path that is empty, absolute, holds
  // ':' or lies inside another group's path; no variables; units not one per variable; a repeated
  // variable. A group with an object_kind has values per object, even with no objects (no columns).
  TimeHistoryWriter(std::string path, std::vector<ThGroupLayout> groups, std::string time_unit,
                    ThFlushPolicy policy = {});
  ~TimeHistoryWriter();
  TimeHistoryWriter(const TimeHistoryWriter&) = delete;
  TimeHistoryWriter& operator=(const TimeHistoryWriter&) = delete;

  // Appends a row at `time` to every group: values[g] holds objects.size() * variables.size() values of
  // group g (object-major: object 0's variables, then object 1's), or variables.size() for global.
  // Throws std::invalid_argument, storing nothing, when a value count is wrong or `time` is not finite
  // or earlier than the last row's (equal times are kept). Flushes when the policy says so, and throws
  // what flush throws, the row kept.
  void append(double time, const std::vector<std::span<const double>>& values);
  // Writes the rows held: the first flush creates the file (even with no rows), later ones extend its
  // datasets. Throws std::runtime_error naming the file; the rows stay held, and the next flush writes
  // them again at the same place.
  void flush();
  [[nodiscard]] std::size_t rows() const;           // appended in all
  [[nodiscard]] std::size_t buffered_rows() const;  // held in memory, not yet in the file
  [[nodiscard]] std::size_t max_buffered_rows() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Reading, for `radx th`: the groups of a file and their columns.
struct ThColumn {
  std::string name;  // "<group path>:<object id>:<variable>" or "global:<variable>"; "time" for column 0
  std::string unit;
};
struct ThGroupData {
  ThGroupLayout layout;
  std::vector<double> rows;  // [rows][1 + columns], time first
  std::size_t columns = 0;   // including time
  std::string time_unit;     // unit of column 0 (the file's root attribute time_unit)
};
// Reads every group of the file, in the order they were written. Returns false with `error` naming the
// file (and the HDF5 object) when the file cannot be read or is not a radx time history of version 1.
// Reads only the rows of completed flushes. A file whose run was killed inside a flush (HDF5 readers other
// than radx refuse it: its "open for writing" flag is set) is read too, and `*interrupted` is set then.
bool read_time_history(const std::string& path, std::vector<ThGroupData>& groups, std::string& error,
                       bool* interrupted = nullptr);

// Writes `groups` (as read_time_history gives them) as a new time history at `path`, replacing the file
// whole: how `radx th FILE --recover` makes the file of a run killed inside a flush readable again by every
// HDF5 reader, with the rows of the flushes that completed. Returns false with `error` naming the file.
bool rewrite_time_history(const std::string& path, const std::vector<ThGroupData>& groups,
                          std::string& error);

// The columns of a group, time first, named as ThColumn says (the `columns` attribute of the file holds
// the same names without the "<group path>:" prefix).
std::vector<ThColumn> th_columns(const ThGroupLayout& layout, const std::string& time_unit);

}  // namespace radx::io
