// What a StepControl names in messages: the entity that sets the step ("3-node shell 12", "interface 3
// (secondary node 40)") and the /DT/<family>/STOP keyword that would stop a run at it. One place for the
// engine's /DT/.../STOP message and the pipeline's runaway warning.
#pragma once

#include <string>

#include "solver/engine/explicit_engine.hpp"

namespace radx::solver {

[[nodiscard]] std::string step_control_name(const StepControl& c);
[[nodiscard]] std::string step_stop_keyword(StepControl::Kind kind);

}  // namespace radx::solver
