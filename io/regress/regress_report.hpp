// The report of `radx regress` (docs/regress.md): the line printed as each deck finishes, the table with its
// totals and most frequent refusals, the JSON summary and the JUnit XML report.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "io/regress/regress_run.hpp"

namespace radx::io {

// The line printed when a deck finishes (no line end): status, first refusal or deviations, seconds.
std::string format_regress_line(const RegressResult& r);
// The table (one row per deck), the totals and the most frequent first refusals.
void write_regress_table(std::ostream& os, const std::vector<RegressResult>& results, double tolerance);
// The same as a JSON document (docs/regress.md lists its keys).
std::string regress_summary_json(const std::vector<RegressResult>& results, const RegressSettings& settings,
                                 bool work_dir_kept);

// The JUnit XML report: one testsuite, one testcase per deck (a failure for deviates and unexpected, an
// error for read-error, run-error and ref-error).
std::string regress_junit_xml(const std::vector<RegressResult>& results, double total_seconds);

}  // namespace radx::io
