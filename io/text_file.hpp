// Writing a text file whole: the starter's listing, a deck's regression reference (NAME.ref) and the reports
// of `radx regress`.
#pragma once

#include <string>

namespace radx::io {

// Writes `text` to `path` through `path`.part and a rename, so a reader never sees half a file and a failure
// leaves the old file whole. False with `error` set (the .part file removed) on failure.
bool write_text_atomically(const std::string& path, const std::string& text, std::string& error);

}  // namespace radx::io
