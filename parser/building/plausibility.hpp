// Plausibility warnings on a model that is valid but whose run would be absurd: an initial step too
// small to be physical, or an end time that needs more cycles than any run can take. Both are warnings
// (RX513): the run proceeds, and the message says what is typical so that a unit slip shows.
#pragma once

#include "parser/reading/deck.hpp"
#include "parser/reading/diagnostics.hpp"
#include "solver/model/model.hpp"
#include "solver/model/run_controls.hpp"
#include "solver/model/stable_step.hpp"

namespace radx {

inline constexpr double kImplausibleStepSeconds = 1e-12;
inline constexpr double kImplausibleCycles = 1e9;

// Warning at the element that sets the step when the estimated initial step is below 1e-12 s.
void check_initial_step(const Deck& deck, const model::Model& m, const model::StepEstimate& step,
                        Diagnostics& diags);

// Warning at an interface whose pairs, once in contact, would vote a step below 1/100 of the estimated
// element step: the bounded stiffness of its /CTCLAW normal law (Kc A_s; KcMax A_s; a table's steepest
// segment A_s), or its penalty K, against the secondary node's mass, sqrt(2 m_s / k). Stiffness cannot be
// made implicit as friction is (docs/theory/contact-laws.md 3.5): a steep law is said before the run.
// LAGDT interfaces are left out (their stiff pairs switch to multipliers under /DT/INTER/CST or /LAG).
void check_contact_step(const Deck& deck, const model::Model& m, const model::StepEstimate& step,
                        Diagnostics& diags);

// The cycles the whole run takes at the estimated initial step: t_stop / dt, dt the estimate after the /DT
// (or /DT/NODA) scale, a /DT/NODA/CST Tmin and the /DTIX bound. Both 0 when there is no estimate.
struct RunCycles {
  double dt = 0;      // work time units
  double cycles = 0;  // t_stop / dt
};
[[nodiscard]] RunCycles estimate_run_cycles(const model::RunControls& controls,
                                            const model::StepEstimate& step);

// Warning at the /RUN line when the end time needs more than 1e9 cycles of the estimated step (after
// the /DT scale and the /DTIX bound).
void check_cycle_count(const EngineDeck& engine, const model::RunControls& controls, const model::Model& m,
                       const model::StepEstimate& step, Diagnostics& diags);

// More /ANIM/DT states than any study reads: the warning states how many the run would write, at most one a
// cycle of the estimated step.
inline constexpr double kManyAnimStates = 1e5;
void check_output_count(const EngineDeck& engine, const model::RunControls& controls, const model::Model& m,
                        const model::StepEstimate& step, Diagnostics& diags);

}  // namespace radx
