// The program check_install.py builds against an installed radx through find_package(radx): reads a starter
// deck with the library's reader and model builder and prints "nodes N elements M".
#include <iostream>

#include "parser/building/model_builder.hpp"
#include "parser/reading/deck.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: count_deck NAME_0000.rad\n";
    return 2;
  }
  radx::Diagnostics diags;
  const radx::Deck deck = radx::read_starter_deck(argv[1], diags);
  const radx::model::Model model = radx::build_model(deck, diags);
  if (diags.has_errors()) {
    diags.print(std::cerr);
    return 1;
  }
  std::cout << "nodes " << model.nodes.size() << " elements " << model.element_count() << '\n';
  return 0;
}
