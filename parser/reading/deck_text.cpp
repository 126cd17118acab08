#include "parser/reading/deck_text.hpp"

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

bool read_whole_file(const fs::path& p, std::string& out) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  in.seekg(0, std::ios::end);
  const auto size = in.tellg();
  if (size < 0) return false;
  // A file too large for memory is an input problem like any other, not a crash.
  try {
    out.resize(static_cast<std::size_t>(size));
  } catch (const std::exception&) {
    return false;
  }
  in.seekg(0, std::ios::beg);
  in.read(out.data(), size);
  return static_cast<bool>(in) || in.eof();
}

class Loader {
 public:
  Loader(DeckText& out, Diagnostics& diags) : out_(out), diags_(diags) {}

  bool load(const fs::path& path, const std::string& display, SourcePos included_from, bool top) {
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
                     "cannot read the included file '" + display + "': " + why + accepted +
                         " (include paths are relative to the including file)");
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
                     "cannot open the included file '" + display +
                         "': include paths are relative to the including file");
      }
      return false;
    }
    if (content.find('\0') != std::string::npos) {
      diags_.error(Diag::NotUtf8OrBinary, Where{display, 0, 0}, About{},
                   "the file holds NUL bytes: it is not a text deck");
      return false;
    }
    const auto file_index = static_cast<std::uint32_t>(out_.files.size());
    out_.files.push_back(display);
    out_.buffers.push_back(std::make_unique<std::string>(std::move(content)));
    const std::string_view text = *out_.buffers.back();
    stack_.push_back(canon);

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
      if (!line.empty() && (line.front() == '#' || line.front() == '$')) {
        if (line.rfind("#include", 0) == 0) {
          std::string name(trim(line.substr(8)));
          if (name.size() >= 2 && (name.front() == '"' || name.front() == '\'') &&
              name.back() == name.front())
            name = name.substr(1, name.size() - 2);
          if (name.empty()) {
            diags_.error(Diag::IncludeNotFound, out_.where(pos, 1), About{"#include"},
                         "#include needs a file name after it");
            continue;
          }
          const fs::path inc = path.parent_path() / name;
          const std::string inc_display =
              (fs::path(display).parent_path() / name).lexically_normal().string();
          load(inc, inc_display, pos, false);
        }
        continue;  // comment line
      }
      out_.lines.push_back(TextLine{line, pos});
    }
    stack_.pop_back();
    return true;
  }

 private:
  DeckText& out_;
  Diagnostics& diags_;
  std::vector<fs::path> stack_;
};

}  // namespace

bool load_deck_text(const std::string& path, DeckText& out, Diagnostics& diags) {
  Loader loader(out, diags);
  return loader.load(fs::path(path), path, SourcePos{}, true);
}

}  // namespace radx
