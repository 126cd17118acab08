// The element formulations a deck can ask for (/PROP/SHELL Ishell and Ish3n, /PROP/SOLID Isolid), named once:
// the starter's formulation check (parser/building/check_formulations.cpp) names what it refuses or
// substitutes with them, and the starter listing names what each property runs with them. Which values radx
// runs is said here too, so that the listing never names a formulation the engine does not run.
#pragma once

#include <string>

namespace radx::model {

// Radioss's name of each value ("QEPH, physical hourglass"); "formulation N" for a value radx does not know.
std::string ishell_name(int ishell);
std::string ish3n_name(int ish3n);
std::string isolid_name(int isolid);

// Whether radx runs the value as its own formulation (docs/theory/elements.md): Ishell 1, 4, 12, 24; Ish3n 1,
// 2; Isolid 1, 2, 12, 14, 17, 18, 24. A property with another value is refused, or substituted under
// --allow-substitutions (and then holds the value that runs).
bool runs_ishell(int ishell);
bool runs_ish3n(int ish3n);
bool runs_isolid(int isolid);

}  // namespace radx::model
