// NAME.ref: a deck's own regression reference for `radx regress` (docs/regress.md, "A deck's own
// reference"): the figures of a run that a team wants to see unchanged, each with its own tolerance.
//
// Text, one quantity per line, fields separated by blanks:
//     QUANTITY  VALUE  REL_TOL  ABS_FLOOR   # why this tolerance
// '#' starts a comment (to the end of the line); blank lines are skipped. VALUE is a number, or '-' for a
// quantity chosen but not recorded yet (`radx regress --update` records it). A quantity passes when
//     |radx - value| <= allowed = max(REL_TOL |value|, ABS_FLOOR)
// and its score is |radx - value| / allowed (at most 1 passes; the deck's worst quantity is the one with
// the largest score). A tolerance is relative with an absolute floor so that a value near zero (a
// rotational kinetic energy, a residual velocity) is judged on the run's scale, not on its round-off.
//
// Quantities: the summary figures of kReferenceScalars (NAME_summary.json), and time-history values
// th:COLUMN@TIME, COLUMN as `radx th` names it ("node/1:61:DZ", "global:KE"), interpolated linearly in
// time between the rows of NAME_th.h5.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/hdf5/time_history.hpp"
#include "io/listing/engine_listing.hpp"

namespace radx::io {

// The summary quantities a reference may hold, in the order a new reference lists them.
inline constexpr std::array<std::string_view, 24> kReferenceScalars{
    "cycles",
    "time",
    "dt",
    "initial_mass",
    "mass",
    "added_mass",
    "energy.kinetic_translational",
    "energy.kinetic_rotational",
    "energy.internal",
    "energy.hourglass",
    "energy.external_work",
    "energy.contact_elastic",
    "energy.contact_damping",
    "energy.contact_friction",
    "energy.contact_lagrange",
    "energy.total",
    "energy.error_percent",
    "max_penetration",       // the largest over the interfaces
    "switched_pairs_max",    // LAGDT: most pairs solved with multipliers in one cycle, over the interfaces
    "switched_pairs_total",  // LAGDT: pair-cycles solved with multipliers, summed over the interfaces
    "removed_nodes",         // secondary nodes removed from contact, summed over the interfaces
    "momentum.x",
    "momentum.y",
    "momentum.z"};

struct ReferenceQuantity {
  std::string name;             // "energy.internal", "th:node/1:61:DZ@1e-3"
  std::optional<double> value;  // empty: '-', not recorded yet
  double rel_tol = 0;
  double abs_floor = 0;
  std::size_t line = 0;  // 1-based line of the file
};

struct RegressReference {
  std::vector<std::string> lines;  // the file's lines as read, kept by an update
  std::vector<ReferenceQuantity> quantities;
};

// Whether `name` is a quantity: one of kReferenceScalars, or th:COLUMN@TIME with a COLUMN and a finite TIME.
// False with `why` saying what is accepted.
bool valid_reference_quantity(std::string_view name, std::string& why);

// Parses the text of a reference. Every problem is collected in `errors` as "FILE:LINE: what is wrong; what
// is accepted" (a repeated quantity, an unknown one, a value or tolerance that is not a number, a negative
// tolerance, a line with too few or too many fields); false when there is one.
bool parse_regress_reference(std::string_view text, const std::string& file, RegressReference& out,
                             std::vector<std::string>& errors);
bool read_regress_reference(const std::string& path, RegressReference& out, std::vector<std::string>& errors);

// The run's value of a quantity, from its summary and its time history (null: the run wrote none).
// Empty with `why` when the run has no such value: an unknown quantity, no interface for max_penetration,
// no time history, no such column, a time outside the rows, a value that is not finite.
std::optional<double> run_quantity(std::string_view name, const RunSummary& s,
                                   const std::vector<ThGroupData>* th, std::string& why);

struct QuantityCheck {
  std::string name;
  std::optional<double> reference;  // empty: not recorded
  std::optional<double> radx;       // empty: the run has no value (`why`)
  std::string why;
  double allowed = 0;  // max(rel_tol |reference|, abs_floor)
  double score = 0;    // |radx - reference| / allowed; +infinity when either is missing or allowed is 0 and
                       // they differ; NaN in, +infinity out
  [[nodiscard]] bool passed() const { return score <= 1.0; }
};

std::vector<QuantityCheck> check_reference(const RegressReference& ref, const RunSummary& s,
                                           const std::vector<ThGroupData>* th);

// The text of `ref` with each quantity's value replaced by `values[i]` (i as in ref.quantities; NaN keeps
// the line as it is). Everything else is kept: comments, blank lines, order, tolerances; the value field
// keeps its column when the new text fits.
std::string updated_reference_text(const RegressReference& ref, const std::vector<double>& values);

// The reference of a deck that has none, from a run: cycles, time, mass, added mass, the energies that are
// not zero, the energy error and, with interfaces, the largest penetration (and the switched pairs when
// any switched), each with the default tolerance docs/regress.md states and its meaning as a comment.
std::string new_reference_text(const std::string& deck_name, const RunSummary& s);

// A value as the reference writes it: 10 significant digits (tolerances are far wider than that).
std::string reference_number(double v);

}  // namespace radx::io
