// What `radx th` does with a time-history file once read (io/hdf5/time_history.hpp): a listing of its groups,
// the choice of columns by selectors, their SAE J211 CFC filtering, and the CSV export of the chosen columns
// on shared time rows.
//
// Selectors name columns by their full names (ThColumn::name): "global:IE", "node/1:12:DX". A selector
// also matches every column whose name it matches up to a ':' boundary, so "node/1" takes the whole
// group and "node/1:12" every variable of object 12. '*' (any run of characters, ':' and '/' included)
// and '?' (one character) are wildcards: "*:DX" is every DX column of every group.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "io/hdf5/time_history.hpp"

namespace radx::io {

// Writes, for each group: path, title, object kind, object ids, variables with units, row count and time
// range. `file` is only used for the heading.
void list_time_history(const std::string& file, const std::vector<ThGroupData>& groups, std::ostream& os);

// One chosen column: groups[group], column `column` of its rows (1 or more: column 0 is the time).
struct ThColumnRef {
  std::size_t group = 0;
  std::size_t column = 0;
};

// Resolves `selectors` (all columns but the times when empty) in selector order, each selector's
// matches in file order, a column chosen twice kept at its first place. Returns false when a selector
// matches nothing, with `error` naming it and listing what the file holds.
bool select_th_columns(const std::vector<ThGroupData>& groups, const std::vector<std::string>& selectors,
                       std::vector<ThColumnRef>& chosen, std::string& error);

// Replaces the values of the chosen columns by their SAE J211 CFC filtering (io/signal/cfc_filter.hpp:
// class `cfc`, 60, 180, 600 or 1000; the time unit of the file converted to seconds), each column on its own.
// Rows not evenly spaced are resampled for the filter and read back at their times; `*resampled` says so.
// `*coarse`: a column's sampling rate is below the 10 F_H that SAE J211 asks for (F_H = 5/3 CFC), though fine
// enough for the filter to run.
// False with `error` when the time unit is not one radx converts to seconds, or a column cannot be filtered
// (fewer than 3 rows, a step too coarse for the class): the groups are then unchanged.
bool filter_th_columns(std::vector<ThGroupData>& groups, const std::vector<ThColumnRef>& chosen, double cfc,
                       std::string& error, bool* resampled = nullptr, bool* coarse = nullptr);

// Writes one header line "time [s],global:IE [J],..." (a unit in brackets when it has one; a field with
// a comma or a quote is quoted as RFC 4180 says) and one line per time row, values with 17 significant
// digits (they read back to the same doubles). The groups of the chosen columns must hold the same
// times (the writer appends every group at once); returns false with `error` otherwise.
// `label`, when not empty, follows each chosen column's name in the header ("node/1:61:AX [m/s2] CFC60").
bool write_th_csv(const std::vector<ThGroupData>& groups, const std::vector<ThColumnRef>& chosen,
                  std::ostream& os, std::string& error, const std::string& label = "");

// The same into the file `path`, through `path.part` and a rename, so a failed export never leaves a
// truncated file behind. Returns false with `error` naming the file on failure.
bool write_th_csv_file(const std::vector<ThGroupData>& groups, const std::vector<ThColumnRef>& chosen,
                       const std::string& path, std::string& error, const std::string& label = "");

}  // namespace radx::io
