// NAME_summary.json: the end-of-run summary as JSON, for scripts and regression checks. Written by hand
// (no library): strings escaped (", \, control characters as \uXXXX; UTF-8 passed through), doubles with
// 17 significant digits (they read back to the same double), non-finite values as null. Written crash-safe:
// NAME_summary.json.part first, flushed to disk, then renamed over the real name.
//
// Keys: status ("normal", "error", "interrupted" by SIGTERM or SIGINT, or "running": written when the run
// starts, so a run killed outright leaves it), message, run_name, run_number, version, commit and arch (the
// build that ran: "0.1.0", the git commit "abc1234", "abc1234-dirty" or "unknown", and the instruction set
// "x86-64-v2"), units {mass, length, time} (the work units as /BEGIN names them and the listing states them,
// from when the model is read), cycles, time, dt, nodes,
// elements, threads, wall_seconds, us_per_element_cycle, element_loop_seconds and
// element_loop_us_per_element_cycle (the element loop's wall time: element forces, their sums, the assembly,
// the integration), initial_mass, mass, added_mass, momentum [x, y, z], energy {kinetic,
// kinetic_translational, kinetic_rotational, internal, hourglass, external_work, contact_elastic,
// contact_damping, contact_friction, contact_lagrange, initial_total, total, error_percent}, interfaces [{id,
// active_pairs, max_penetration, switched_pairs_max, switched_pairs_total, added_mass, removed_nodes,
// candidates_mean: the TYPE7 search's candidate pairs per cycle the interface was active, search_sorts: its
// sorts}], substitutions [text], warnings [text: the engine deck's warnings as the listing gives them, then
// "cycle N: ..." for those during the run, such as an energy error past 10 % and 50 %; at most 100, then one
// "... and N more"], and lagrange_solver {...} when a LAGDT interface could switch.
//
// read_summary_json reads a document back (for `radx regress`, which runs each deck in a child process and
// reads its figures from this file): a small strict JSON reader, no library.
#pragma once

#include <string>
#include <string_view>

#include "io/listing/engine_listing.hpp"

namespace radx::io {

// `s` as a JSON string literal, quotes included.
std::string json_string(std::string_view s);
// `v` with 17 significant digits (shortest exact form is not required), or null when not finite.
std::string json_number(double v);

// "normal", "error", "interrupted", "running".
std::string_view status_name(RunStatus s);

// The summary document (pretty-printed, ends with a line end).
std::string summary_json(const RunSummary& s);

// dir/ROOT_summary.json.
std::string summary_json_path(const std::string& dir, const std::string& output_root);

// Writes summary_json(s) to `path` through path + ".part" and a rename. False with `error` set on failure,
// naming the file and the system's reason (the .part file is removed). When the .part cannot be written,
// the summary at `path` (the "running" one of the run's start) is removed and the write tried once more:
// on a full disk that frees the space it needs, and either way no stale summary is left.
bool write_summary_json(const std::string& path, const RunSummary& s, std::string& error);

// Reads `path` into `s`: status, message, run_name, run_number, version, commit, arch, units, cycles, time,
// dt, nodes, elements, threads, wall_seconds, initial_mass, mass, added_mass, momentum, the energies by kind
// (the derived kinetic, total and error_percent are not stored) and the interfaces (lagrange_solver is not
// read). A null number reads as NaN. False with `error` set ("PATH: what is wrong") when the file cannot be
// read, is not JSON, or lacks status, cycles, time or energy.
bool read_summary_json(const std::string& path, RunSummary& s, std::string& error);

}  // namespace radx::io
