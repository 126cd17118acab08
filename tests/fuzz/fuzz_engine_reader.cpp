// libFuzzer target: the engine deck reader and the run controls built from it, on any bytes. A crash, a
// sanitizer report, a hang or an exception escaping is a bug: the reader promises located diagnostics.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "parser/building/build_run_controls.hpp"
#include "parser/reading/deck.hpp"
#include "parser/reading/diagnostics.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const radx::fuzz::InputFile input(data, size, "ENGINE_0001.rad");
  const std::string& path = input.path();
  radx::Diagnostics diags;
  radx::EngineDeck deck;
  const radx::model::RunControls controls = radx::read_run_controls(path, diags, &deck);
  (void)controls;
  diags.sort();
  for (const auto& d : diags.items()) (void)radx::Diagnostics::format(d);
  return 0;
}
