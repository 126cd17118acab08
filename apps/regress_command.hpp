// `radx regress DIR...`: the batch runner's command (docs/regress.md). It finds every deck under the folders
// given (io/regress/regress_decks.hpp), runs them N at a time, each in its own child process with a time
// limit (io/regress/regress_run.hpp), prints one line per deck as it finishes, then a table and totals, and
// optionally writes the table as JSON and as JUnit XML (io/regress/regress_report.hpp).
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

namespace radx::app {

// The command: parses `args` (DIR... and the options), runs, reports. 0 when every deck passes, 1 when one
// fails (or none was found), 2 for usage errors. `executable` is the radx driver to run the decks with.
int regress_command(const std::vector<std::string>& args, const std::filesystem::path& executable,
                    std::ostream& out, std::ostream& err);

}  // namespace radx::app
