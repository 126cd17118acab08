#include "solver/model/run_files.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace radx::model {

std::string split_run_suffix(const std::string& path, int& number) {
  std::string stem = std::filesystem::path(path).stem().string();
  number = -1;
  const std::size_t n = stem.size();
  if (n > 5 && stem[n - 5] == '_' && std::all_of(stem.end() - 4, stem.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
      })) {
    number = std::stoi(stem.substr(n - 4));
    stem.resize(n - 5);
  }
  return stem;
}

std::string run_output_root(const std::string& engine_deck_path) {
  int number = 0;
  return split_run_suffix(engine_deck_path, number);
}

std::string starter_output_root(const std::string& deck) {
  std::string stem = std::filesystem::path(deck).stem().string();
  if (stem.size() > 5 && stem.compare(stem.size() - 5, 5, "_0000") == 0) return stem;
  return stem + "_0000";
}

std::vector<std::string> later_engine_decks(const std::string& engine_deck) {
  namespace fs = std::filesystem;
  const fs::path p(engine_deck);
  int number = -1;
  const std::string root = split_run_suffix(engine_deck, number);
  std::vector<std::string> found;
  if (number != 1) return found;
  std::error_code ec;
  const fs::path dir = p.parent_path().empty() ? fs::path(".") : p.parent_path();
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    int later = -1;
    if (e.path().extension() == p.extension() && split_run_suffix(name, later) == root && later >= 2)
      found.push_back(name);
  }
  std::sort(found.begin(), found.end());
  return found;
}

bool is_one_file_deck(const std::string& path) {
  // Only a regular file can be one: opening a FIFO would block, /dev/zero would never end (the reader
  // reports such a path as an error).
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  std::ifstream in(path);
  std::string line;
  const std::string_view keyword = "/END/ENGINE";
  while (std::getline(in, line)) {
    // The line's start after blanks, in upper case, as the deck reader reads a keyword line.
    const std::size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    std::string head = line.substr(first, keyword.size());
    for (auto& c : head) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (head == keyword) return true;
  }
  return false;
}

}  // namespace radx::model
