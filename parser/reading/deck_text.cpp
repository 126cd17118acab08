#include "parser/reading/deck_text.hpp"

#include <algorithm>
#include <cctype>
#include <exception>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "parser/reading/field_parse.hpp"

namespace radx {

namespace fs = std::filesystem;

namespace {

// What keeps `p` from being read as a deck, empty when it is a regular file. Only regular files are read:
// a directory makes tellg() fail (and the size wrap), a FIFO blocks the open until a writer comes, and
// /dev/zero never ends.
std::string not_a_deck_file(const fs::path& p) {
  std::error_code ec;
  const fs::file_status st = fs::status(p, ec);
  if (ec || !fs::exists(st)) return {};  // the open fails and says so
  switch (st.type()) {
    case fs::file_type::regular: return {};
    case fs::file_type::directory: return "it is a directory";
    case fs::file_type::fifo: return "it is a FIFO (named pipe)";
    case fs::file_type::socket: return "it is a socket";
    case fs::file_type::character:
    case fs::file_type::block: return "it is a device";
    default: return "it is not a regular file";
  }
}

// Read to the end rather than to the size the system reports: files of /proc and pipes report 0 and still
// hold text, which would otherwise be read as an empty file without a word.
bool read_whole_file(const fs::path& p, std::string& out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  std::error_code ec;
  const auto reported = fs::file_size(p, ec);
  // A file too large for memory is an input problem like any other, not a crash.
  try {
    if (!ec) out.reserve(static_cast<std::size_t>(reported));
    constexpr std::size_t kChunk = 1 << 16;
    std::size_t used = 0;
    while (in) {
      out.resize(used + kChunk);
      in.read(out.data() + used, static_cast<std::streamsize>(kChunk));
      used += static_cast<std::size_t>(in.gcount());
    }
    out.resize(used);
  } catch (const std::exception&) {
    return false;
  }
  return in.eof() && !in.bad();
}

class Loader {
 public:
  Loader(DeckText& out, Diagnostics& diags) : out_(out), diags_(diags) {}

  // hint: said after a failure to read an included file (where its name was looked for); empty for the
  // main deck and for absolute include names.
  bool load(const fs::path& path, const std::string& display, SourcePos included_from, bool top,
            const std::string& hint = {}) {
    std::error_code ec;
    const fs::path canon = fs::weakly_canonical(path, ec);
    for (const auto& open : stack_) {
      if (open == canon) {
        diags_.error(Diag::IncludeLoop, out_.where(included_from, 1), About{"#include"},
                     "including '" + display +
                         "' closes an include loop: that file is already being read; "
                         "a file may be included only once along a chain");
        return false;
      }
    }
    if (const std::string why = not_a_deck_file(path); !why.empty()) {
      const std::string accepted = "; a deck and the files it includes are regular text files";
      if (top) {
        diags_.error(Diag::FileNotFound, Where{display, 0, 0}, About{},
                     "cannot read the deck file '" + display + "': " + why + accepted);
      } else {
        diags_.error(Diag::IncludeNotFound, out_.where(included_from, 1), About{"#include"},
                     "cannot read the included file '" + display + "': " + why + accepted + hint);
      }
      return false;
    }
    std::string content;
    if (!read_whole_file(path, content)) {
      if (top) {
        diags_.error(Diag::FileNotFound, Where{display, 0, 0}, About{},
                     "cannot open the deck file '" + display + "': check the path and the permissions");
      } else {
        diags_.error(Diag::IncludeNotFound, out_.where(included_from, 1), About{"#include"},
                     "cannot open the included file '" + display + "'" + hint);
      }
      return false;
    }
    if (content.find('\0') != std::string::npos) {
      diags_.error(Diag::NotUtf8OrBinary, Where{display, 0, 0}, About{},
                   "the file holds NUL bytes: it is not a text deck");
      return false;
    }
    if (!top && content.find_first_not_of(" \t\r\n") == std::string::npos) {
      diags_.warning(Diag::IncludeForm, out_.where(included_from, 1), About{"#include"},
                     "the included file '" + display + "' is empty: nothing is read from it");
    }
    const auto file_index = static_cast<std::uint32_t>(out_.files.size());
    out_.files.push_back(display);
    out_.buffers.push_back(std::make_unique<std::string>(std::move(content)));
    const std::string_view text = *out_.buffers.back();
    stack_.push_back(canon);
    if (top) {
      top_path_ = path;
      top_display_ = display;
    }

    std::size_t start = 0;
    std::uint32_t line_no = 0;
    while (start < text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(start, end - start);
      start = end + 1;
      ++line_no;
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.remove_suffix(1);
      const SourcePos pos{file_index, line_no};
      // Radioss ends an included file at its /END (taken for #enddata) or #enddata; in the main file
      // #enddata is a comment and /END is the starter's business.
      if (!top && (is_end_line(line) || starts_with_nocase(line, "#enddata"))) {
        report_file_end(line, pos, text.substr(std::min(start, text.size())), included_from);
        if (line.front() == '/') out_.ended_in_include = true;
        break;
      }
      if (!line.empty() && (line.front() == '#' || line.front() == '$')) {
        // Radioss takes `#include` in any case (#INCLUDE, #Include) as the include line.
        if (starts_with_nocase(line, "#include")) include(line.substr(8), path, display, pos);
        continue;  // comment line
      }
      out_.lines.push_back(TextLine{line, pos});
    }
    stack_.pop_back();
    return true;
  }

 private:
  static bool starts_with_nocase(std::string_view line, std::string_view word) {
    if (line.size() < word.size()) return false;
    for (std::size_t k = 0; k < word.size(); ++k)
      if (std::tolower(static_cast<unsigned char>(line[k])) != word[k]) return false;
    return true;
  }

  static bool is_end_line(std::string_view line) {
    if (line.empty() || line.front() != '/') return false;
    const auto tokens = keyword_fields(line);
    return tokens.size() == 1 && tokens[0] == "END";
  }

  // The /END or #enddata of an included file: a note when nothing follows it, a warning naming what is not
  // read when something does.
  void report_file_end(std::string_view line, SourcePos pos, std::string_view rest, SourcePos included_from) {
    std::size_t dropped = 0;
    std::size_t first_dropped = 0;
    std::uint32_t k = pos.line;
    for (std::size_t at = 0; at < rest.size();) {
      std::size_t e = rest.find('\n', at);
      if (e == std::string_view::npos) e = rest.size();
      const std::string_view l = trim(rest.substr(at, e - at));
      ++k;
      if (!l.empty() && l.front() != '#' && l.front() != '$' && dropped++ == 0) first_dropped = k;
      at = e + 1;
    }
    const std::string what = line.front() == '/' ? "/END" : "#enddata";
    const std::string where_back =
        out_.files.at(included_from.file) + ":" + std::to_string(included_from.line);
    std::string msg = what + " in an included file ends that file only, as Radioss reads it" +
                      (what == "/END" ? std::string(" (it takes it for #enddata)") : std::string()) +
                      ": the deck goes on after the #include line at " + where_back;
    if (dropped == 0) {
      diags_.note(Diag::IncludedFileEnded, out_.where(pos, 1), About{what}, msg);
    } else {
      diags_.warning(Diag::IncludedFileEnded, out_.where(pos, 1), About{what},
                     msg + "; the " + std::to_string(dropped) +
                         " data or keyword line(s) after it in this file " + "(from line " +
                         std::to_string(first_dropped) + ") are not read");
    }
  }

  // `#include NAME` (what follows the 8 letters in `rest`): the name is read as Radioss reads it, single
  // quotes taken off, relative to the including file, else to the main deck (Radioss looks there next).
  void include(std::string_view rest, const fs::path& path, const std::string& display, SourcePos pos) {
    std::string name(trim(rest));
    std::erase(name, '\'');
    if (name.size() >= 2 && name.front() == '"' && name.back() == '"') {
      name = name.substr(1, name.size() - 2);
      diags_.warning(
          Diag::IncludeForm, out_.where(pos, 1), About{"#include"},
          "a double-quoted include name: radx reads '" + name +
              "', OpenRadioss does not (it looks for a file whose name holds the quotes and stops); "
              "write the name without quotes, or in single quotes, for the deck to run in Radioss");
    }
    if (name.empty()) {
      diags_.error(Diag::IncludeNotFound, out_.where(pos, 1), About{"#include"},
                   "#include needs a file name after it");
      return;
    }
    fs::path inc = path.parent_path() / name;
    std::string inc_display = (fs::path(display).parent_path() / name).lexically_normal().string();
    std::error_code ec;
    if (!fs::exists(inc, ec) && stack_.size() > 1 && fs::path(name).is_relative()) {
      const fs::path beside_main = top_path_.parent_path() / name;
      if (fs::exists(beside_main, ec)) {
        inc_display = (fs::path(top_display_).parent_path() / name).lexically_normal().string();
        diags_.note(Diag::IncludeForm, out_.where(pos, 1), About{"#include"},
                    "'" + name +
                        "' is not beside the including file; it is read from beside the main deck (" +
                        inc_display + "), where Radioss looks next");
        inc = beside_main;
      }
    }
    const std::string hint = fs::path(name).is_relative()
                                 ? " (a relative include name is looked for beside the including file, then "
                                   "beside the main deck)"
                                 : "";
    load(inc, inc_display, pos, false, hint);
  }

  DeckText& out_;
  Diagnostics& diags_;
  std::vector<fs::path> stack_;
  fs::path top_path_;  // the main deck, where an include not found beside its includer is looked for
  std::string top_display_;
};

}  // namespace

bool load_deck_text(const std::string& path, DeckText& out, Diagnostics& diags) {
  Loader loader(out, diags);
  return loader.load(fs::path(path), path, SourcePos{}, true);
}

}  // namespace radx
