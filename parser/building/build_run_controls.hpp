// Engine deck -> model::RunControls (docs/theory/deck-format.md section 3): every engine keyword resolved
// with its defaults (Tscale 0 -> 0.9, /PRINT -100, no /TFILE -> 1e30, /ANIM/DT Tstop 0 -> 1e20, /STOP
// values 0 -> 1e30), each /DT option mapped to its action, the /ANIM field names checked against the names
// radx writes, and every problem reported at the keyword line with a code. Times are taken as written:
// engine decks are in the starter's work units.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "parser/reading/deck.hpp"
#include "parser/reading/diagnostics.hpp"
#include "solver/model/run_controls.hpp"

namespace radx {

// One /ANIM field name radx maps to a results array (docs/theory/results-format.md section 3).
struct AnimFieldName {
  std::string_view family;                // "/ANIM/ELEM", "/ANIM/VECT", "/ANIM/TENS" or "/ANIM/NODA"
  std::string_view name;                  // the name radx stores in RunControls (canonical spelling)
  std::vector<std::string_view> aliases;  // other accepted spellings (e.g. DIS for DISP)
  std::string_view array;                 // the results array it fills
  std::string_view meaning;
  // Radioss reads a name on its first `significant` letters (0: the whole name), so HOURG is HOUR and PRES
  // is P; names starting with one of `excluded` are other Radioss fields (DENS3 is not DENS).
  std::size_t significant = 0;
  std::vector<std::string_view> excluded;
};

// The data table of every /ANIM name radx maps.
const std::vector<AnimFieldName>& anim_field_names();

// The entry for `written` (upper case, as the reader stores it) in `family`, matched as Radioss matches it
// (its name, an alias, or its significant letters); nullptr when radx does not map that name.
const AnimFieldName* find_anim_field(std::string_view family, std::string_view written);

// Whether the Radioss engine knows `written` as a field of `family` (and so would write it): a name radx
// does not write but Radioss knows is a warning; one Radioss does not know either is a misspelling, an error.
bool radioss_knows_anim_field(std::string_view family, std::string_view written);

// The names of `family` to suggest for a misspelt one: radx's first, then the other Radioss names.
std::vector<std::string> anim_names_of_family(std::string_view family);

// The accepted names of a family, blank separated, aliases in parentheses: "VEL DISP (DIS) ACC ...".
std::string accepted_anim_names(std::string_view family);

// Resolves every engine keyword of `deck` into run controls. Problems go to `diags` (errors for values
// radx cannot run with, warnings for values it ignores); the returned controls hold defaults wherever a
// value was wrong, so callers must check diags.has_errors() before running.
model::RunControls build_run_controls(const EngineDeck& deck, Diagnostics& diags);

// Warning RX803 at the /RUN line when the /RUN name differs from model::run_output_root(engine_deck_path)
// (solver/model/run_files.hpp; compared without case: the engine reader stores keyword fields in upper
// case), or when the file name carries a run number (NAME_0003.rad) different from the /RUN number.
void check_run_name(const EngineDeck& deck, const model::RunControls& controls,
                    const std::string& engine_deck_path, Diagnostics& diags);

// read_engine_deck + build_run_controls + check_run_name: what the engine calls. `deck`, when given,
// receives the deck read, for the checks against the model below.
model::RunControls read_run_controls(const std::string& engine_deck_path, Diagnostics& diags,
                                     EngineDeck* deck = nullptr);

// /RBODY/ON and /RBODY/OFF against the model: every id that names none of `model_rigid_body_ids` is a
// warning (RX402) at the line that holds it and is dropped from `controls`, so it switches nothing. Radioss
// passes over such ids and goes on; radx goes on too, but says so.
void check_rigid_body_switches(const EngineDeck& deck, std::span<const std::int64_t> model_rigid_body_ids,
                               model::RunControls& controls, Diagnostics& diags);

}  // namespace radx
