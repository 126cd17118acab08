// radx regress: finding the decks and reading their "# expect:" lines (io/regress/regress_decks.hpp).
#include "io/regress/regress_decks.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "io/regress/regress_text.hpp"
#include "solver/model/run_files.hpp"

namespace radx::io {

namespace fs = std::filesystem;

namespace {

// NAME_NNNN.rad: the run number NNNN (four digits), or -1.
int run_number_of(std::string_view file_name) {
  if (!file_name.ends_with(".rad") || file_name.size() < 10) return -1;
  const std::string_view digits = file_name.substr(file_name.size() - 8, 4);
  if (file_name[file_name.size() - 9] != '_' || !all_digits(digits)) return -1;
  return std::stoi(std::string(digits));
}

// The name of a folder as given ("a/b/" and "a/b/." are "b"; "." is the current folder's name).
std::string folder_name(const fs::path& dir) {
  std::error_code ec;
  fs::path p = fs::absolute(dir, ec).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return p.filename().empty() ? std::string("root") : p.filename().string();
}

}  // namespace

std::string ExpectedError::text() const {
  std::string t = code;
  if (line > 0) t += " line " + std::to_string(line);
  if (!file.empty()) t += " in " + file.filename().string();
  return warning ? t + " (warning)" : t;
}

std::vector<ExpectedError> read_expected_errors(const fs::path& deck, std::vector<std::string>& problems) {
  std::vector<ExpectedError> out;
  std::ifstream f(deck, std::ios::binary);
  std::string line;
  for (std::size_t no = 1; std::getline(f, line); ++no) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] != '#') break;  // the opening comment block only
    const std::string_view tag = "# expect:";
    if (line.compare(0, tag.size(), tag) != 0) continue;
    std::istringstream in(line.substr(tag.size()));
    std::vector<std::string> w;
    for (std::string t; in >> t;) w.push_back(t);
    ExpectedError e;
    bool ok = !w.empty() && w[0].size() > 2 && w[0].compare(0, 2, "RX") == 0 &&
              all_digits(std::string_view(w[0]).substr(2));
    if (ok) e.code = w[0];
    if (ok && w.back() == "warning") {
      e.warning = true;
      w.pop_back();
    }
    for (std::size_t k = 1; ok && k < w.size(); k += 2) {
      if (k + 1 >= w.size())
        ok = false;
      else if (w[k] == "line")
        ok = parse_line_number(w[k + 1], e.line) && e.line > 0;
      else if (w[k] == "file")
        e.file = (deck.parent_path() / w[k + 1]).lexically_normal();
      else
        ok = false;
    }
    if (!ok) {
      problems.push_back(deck.string() + ":" + std::to_string(no) +
                         ": an expectation is \"# expect: RXnnn [line L] [file PATH] [warning]\", L a line "
                         "number from 1");
      continue;
    }
    if (e.file.empty()) e.file = deck.lexically_normal();
    out.push_back(std::move(e));
  }
  return out;
}

namespace {

// The names of the .rad files of each folder under `dir`, `dir` included (hidden folders, symbolic links to
// folders and `skip_canonical` excepted).
std::map<fs::path, std::vector<std::string>> rad_files_under(const fs::path& dir,
                                                             const fs::path& skip_canonical) {
  std::map<fs::path, std::vector<std::string>> rad_files;  // folder -> the names of its .rad files
  const auto add_folder_files = [&](const fs::path& folder) {
    std::error_code e1;
    for (const auto& e : fs::directory_iterator(folder, fs::directory_options::skip_permission_denied, e1)) {
      std::error_code e2;
      const std::string name = e.path().filename().string();
      if (name.ends_with(".rad") && e.is_regular_file(e2)) rad_files[folder].push_back(name);
    }
  };
  add_folder_files(dir);
  std::error_code walk;
  for (auto it = fs::recursive_directory_iterator(dir, fs::directory_options::skip_permission_denied, walk);
       !walk && it != fs::recursive_directory_iterator(); it.increment(walk)) {
    std::error_code e1;
    if (it->is_symlink(e1) || !it->is_directory(e1)) continue;  // symbolic links are not followed
    const std::string name = it->path().filename().string();
    const bool hidden = !name.empty() && name[0] == '.';
    if (hidden || (!skip_canonical.empty() && fs::weakly_canonical(it->path(), e1) == skip_canonical)) {
      it.disable_recursion_pending();
      continue;
    }
    add_folder_files(it->path());
  }
  return rad_files;
}

// The decks among a folder's .rad files `names` (sorted).
std::vector<std::string> decks_in_folder(const fs::path& folder, const std::vector<std::string>& names) {
  std::vector<std::string> decks;
  for (const auto& n : names)
    if (run_number_of(n) == 0) decks.push_back(n);
  // Without a NAME_0000.rad: one-file decks, and starter decks that declare their diagnostics.
  if (decks.empty())
    for (const auto& n : names) {
      std::vector<std::string> ignored;
      if (run_number_of(n) < 0 && (model::is_one_file_deck((folder / n).string()) ||
                                   !read_expected_errors(folder / n, ignored).empty()))
        decks.push_back(n);
    }
  return decks;
}

// Where a folder of decks sits: DIR (the k-th of `dir_count`, 0-based) and the folder's .rad files and decks.
struct DeckFolder {
  const fs::path& dir;
  std::size_t k = 0, dir_count = 0;
  const std::string& dir_name;
  const fs::path& folder;
  const fs::path& rel;  // the folder relative to DIR (DIR's name for DIR itself)
  const std::vector<std::string>& names;
  const std::vector<std::string>& decks;
  bool has_reference = false;  // a ref.extract in the folder
};

// The deck `deck` (a name in f.decks) at `starter`: its label, work folder, expectations, references and
// notes.
RegressDeck make_deck(const DeckFolder& f, const std::string& deck, const fs::path& starter) {
  const auto& [dir, k, dir_count, dir_name, folder, rel, names, decks, has_reference] = f;
  std::error_code ec;
  RegressDeck d;
  d.starter_deck = starter;
  // Several DIRs: the label starts with DIR as given, the work folder with DIR's rank and name.
  d.label = dir_count > 1 ? (dir / folder.lexically_relative(dir)).lexically_normal().generic_string()
                          : rel.generic_string();
  while (d.label.size() > 1 && d.label.back() == '/') d.label.pop_back();
  d.work_subdir = dir_count > 1 ? fs::path(std::to_string(k + 1) + "_" + dir_name) / rel : rel;
  if (decks.size() > 1) {
    d.label += "/" + deck;
    d.work_subdir /= fs::path(deck).stem();
  }
  d.expected = read_expected_errors(starter, d.expect_problems);
  const std::string root = model::run_output_root(starter.string());
  d.own_reference = starter.parent_path() / (root + ".ref");
  d.has_own_reference = fs::is_regular_file(d.own_reference, ec);
  d.starter_only =
      !fs::exists(folder / (root + "_0001.rad"), ec) && !model::is_one_file_deck(starter.string());
  std::vector<std::string> notes;
  if (has_reference) {
    if (d.has_own_reference)
      notes.push_back("ref.extract not used: the deck has its own " + d.own_reference.filename().string());
    else if (decks.size() == 1)
      d.reference = folder / "ref.extract";
    else
      notes.push_back("ref.extract not used: the folder holds " + std::to_string(decks.size()) + " decks");
  }
  // Later engine decks of the same run (NAME_0002.rad, ...): OpenRadioss restarts, which radx lacks.
  if (run_number_of(deck) == 0) {
    const std::string prefix = deck.substr(0, deck.size() - 8);  // "NAME_"
    std::string later;
    for (const auto& n : model::later_engine_decks((folder / (prefix + "0001.rad")).string()))
      later += (later.empty() ? "" : ", ") + n;
    if (!later.empty())
      notes.push_back(later + " not run (radx runs " + prefix + "0001.rad only: it has no restart)");
  }
  for (const auto& n : notes) d.note += (d.note.empty() ? "" : "; ") + n;
  return d;
}

// One flat folder per deck: a deck's run folder must never hold another's, since each is cleared before
// its run and removed when it passes (deck A/ and deck A/B/ would otherwise share WORK/A).
void flatten_work_folders(std::vector<RegressDeck>& decks) {
  std::set<std::string> used;
  for (auto& d : decks) {
    std::string flat = d.work_subdir.generic_string();
    std::replace(flat.begin(), flat.end(), '/', '~');
    std::string name = flat;
    for (int k = 2; !used.insert(name).second; ++k) name = flat + "_" + std::to_string(k);
    d.work_subdir = name;
  }
}

}  // namespace

std::vector<RegressDeck> find_regress_decks(const std::vector<fs::path>& dirs, const fs::path& skip) {
  std::vector<RegressDeck> out;
  std::set<fs::path> seen;  // the same deck reached through overlapping DIRs runs once
  std::error_code ec;
  const fs::path skip_canonical = skip.empty() ? fs::path() : fs::weakly_canonical(skip, ec);
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    const fs::path& dir = dirs[k];
    const std::string dir_name = folder_name(dir);
    for (auto& [folder, names] : rad_files_under(dir, skip_canonical)) {
      std::sort(names.begin(), names.end());
      const std::vector<std::string> decks = decks_in_folder(folder, names);
      fs::path rel = folder.lexically_relative(dir);
      if (rel.empty() || rel == ".") rel = dir_name;
      const DeckFolder f{.dir = dir,
                         .k = k,
                         .dir_count = dirs.size(),
                         .dir_name = dir_name,
                         .folder = folder,
                         .rel = rel,
                         .names = names,
                         .decks = decks,
                         .has_reference = fs::is_regular_file(folder / "ref.extract", ec)};
      for (const auto& deck : decks) {
        const fs::path starter = fs::absolute(folder / deck, ec).lexically_normal();
        if (!seen.insert(fs::weakly_canonical(starter, ec)).second) continue;
        out.push_back(make_deck(f, deck, starter));
      }
    }
  }
  flatten_work_folders(out);
  return out;
}

bool label_matches(const std::string& label, const std::string& pattern) {
  if (pattern.find_first_of("*?[") == std::string::npos) return label.find(pattern) != std::string::npos;
  return fnmatch(pattern.c_str(), label.c_str(), 0) == 0;
}

}  // namespace radx::io
