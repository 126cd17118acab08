// libFuzzer target: the starter deck reader and the model builder after it, as the starter runs them, on
// any bytes. A crash, a sanitizer report, a hang or an
// exception escaping is a bug: the reader promises located diagnostics for every input.
#include <cstddef>
#include <cstdint>

#include "fuzz_input_file.hpp"
#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"
#include "parser/reading/diagnostics.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const radx::fuzz::InputFile input(data, size, "STARTER_0000.rad");
  const std::string& path = input.path();
  radx::Diagnostics diags;
  radx::ReadOptions opt;
  opt.allow_one_file = true;  // a one-file deck's starter part starts after /END/ENGINE
  const radx::Deck deck = radx::read_starter_deck(path, diags, opt);
  if (!deck.records.empty()) (void)radx::build_model(deck, diags);
  diags.sort();
  for (const auto& d : diags.items()) (void)radx::Diagnostics::format(d);
  return 0;
}
