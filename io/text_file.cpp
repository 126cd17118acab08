#include "io/text_file.hpp"

#include <filesystem>
#include <fstream>

namespace radx::io {

namespace fs = std::filesystem;

bool write_text_atomically(const std::string& path, const std::string& text, std::string& error) {
  const std::string part = path + ".part";
  {
    std::ofstream f(part, std::ios::binary | std::ios::trunc);
    if (!f) {
      error = "cannot create " + part;
      return false;
    }
    f << text;
    f.flush();
    if (!f) {
      error = "cannot write " + part;
      std::error_code ec;
      fs::remove(part, ec);
      return false;
    }
  }
  std::error_code ec;
  fs::rename(part, path, ec);
  if (ec) {
    error = "cannot rename " + part + " to " + path + ": " + ec.message();
    fs::remove(part, ec);
    return false;
  }
  return true;
}

}  // namespace radx::io
