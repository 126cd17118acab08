// NAME_energy.csv and NAME_energy.png (io/listing/energy_plot.hpp): the CSV written here, the chart drawn by
// the embedded io/listing/plot_energy.py in a child /usr/bin/python3 started without a shell (arguments pass
// byte for byte, io/spawn_process.hpp), its standard output and error captured through a pipe to word the
// warning on failure.
#include "io/listing/energy_plot.hpp"

#include <unistd.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "io/spawn_process.hpp"

namespace radx::io {

namespace {

namespace fs = std::filesystem;

// The first matplotlib run under a new home builds its font cache (seconds); a normal chart takes about a
// second. A hung interpreter must still not hold the end of a run for ever.
constexpr std::chrono::seconds kScriptTimeout{120};
// Exit code of plot_energy.py when matplotlib cannot be imported (see the script's docstring).
constexpr int kExitNoMatplotlib = 3;
// Only the end of the script's output is kept: a Python traceback ends with the line that explains it.
constexpr std::size_t kMaxCapturedOutput = 16 * 1024;
constexpr const char* kInstallHint = "apt-get install python3-matplotlib";

// A unit as it may appear inside a CSV header field: the characters that would end the field or the line
// are replaced, since the header is split on commas by every reader.
std::string header_unit(const std::string& unit) {
  std::string u = unit;
  for (char& c : u)
    if (c == ',' || c == '"' || c == '\n' || c == '\r') c = ' ';
  return u;
}

std::string header_field(const char* name, const std::string& unit) {
  std::string f = name;
  if (!unit.empty()) f += " [" + header_unit(unit) + "]";
  return f;
}

// 17 significant digits: enough for any double to read back to the same value.
void append_number(std::string& out, double v) {
  std::array<char, 40> buf{};
  const auto res = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::general, 17);
  out.append(buf.data(), res.ptr);
}

// The last few non-empty lines of `text`, joined with " | ": enough to show a Python error on one line.
std::string last_lines(const std::string& text, int count) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (!line.empty()) lines.push_back(line);
    start = end + 1;
  }
  std::string out;
  const std::size_t first = lines.size() > static_cast<std::size_t>(count) ? lines.size() - count : 0;
  for (std::size_t i = first; i < lines.size(); ++i) {
    if (!out.empty()) out += " | ";
    out += lines[i];
  }
  return out;
}

// The caller's environment with MPLBACKEND=Agg, so matplotlib never looks for a display.
std::vector<std::string> plot_environment() {
  std::vector<std::string> env;
  for (char** e = environ; e != nullptr && *e != nullptr; ++e)
    if (std::strncmp(*e, "MPLBACKEND=", 11) != 0) env.emplace_back(*e);
  env.emplace_back("MPLBACKEND=Agg");
  return env;
}

}  // namespace

bool write_energy_csv(const EnergyPlotRequest& r, std::string& error) {
  // Through a temporary name: a reader never sees half a table, and the previous one stays until then.
  const std::string part = r.csv_path + ".part";
  std::FILE* f = std::fopen(part.c_str(), "wb");
  if (f == nullptr) {
    error = "cannot write " + r.csv_path + ": " + std::strerror(errno);
    return false;
  }
  // Line by line: the table of a long run (16,384 samples, some 3 MB of text) is never held whole, so the
  // end of a run costs no more memory than its middle.
  std::string text = header_field("time", r.time_unit);
  for (const char* name : {"kinetic", "internal", "hourglass", "contact", "external_work", "total"}) {
    text += ',';
    text += header_field(name, r.energy_unit);
  }
  text += '\n';
  bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  for (std::size_t k = 0; written && k < r.samples.size(); ++k) {
    const EnergySample& s = r.samples[k];
    text.clear();
    bool first = true;
    for (const double v : {s.time, s.kinetic, s.internal, s.hourglass, s.contact, s.external_work, s.total}) {
      if (!first) text += ',';
      first = false;
      append_number(text, v);
    }
    text += '\n';
    written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  }
  const int failure = written ? 0 : errno;
  const bool closed = std::fclose(f) == 0;
  std::error_code ec;
  if (!written || !closed) {
    error = "cannot write " + r.csv_path + ": " + std::strerror(failure != 0 ? failure : errno);
    fs::remove(part, ec);
    return false;
  }
  fs::rename(part, r.csv_path, ec);
  if (ec) {
    error = "cannot rename " + part + " to " + r.csv_path + ": " + ec.message();
    fs::remove(part, ec);
    return false;
  }
  return true;
}

bool draw_energy_png(const EnergyPlotRequest& r, const std::string& python, std::string& warning) {
  const auto fail = [&](const std::string& reason) {
    warning = "energy chart " + r.png_path + " not drawn: " + reason + "; the energies are in " + r.csv_path;
    return false;
  };
  fs::path folder = fs::path(r.png_path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return fail("folder " + folder.string() + " does not exist");
  if (access(python.c_str(), X_OK) != 0)
    return fail(python + " not found (install it with: " + std::string(kInstallHint) + ")");

  // matplotlib picks the format from the name, hence ".part.png" rather than ".part".
  const std::string part = r.png_path + ".part.png";
  fs::remove(part, ec);  // left by a run that was killed while drawing
  ProcessRequest request;
  // -I: isolated mode. PYTHONPATH, PYTHONHOME and user site-packages of the caller's environment (often set
  // for another Python) must not change which matplotlib /usr/bin/python3 imports.
  request.argv = {python,  "-I",        "-c",         std::string(energy_plot_script()), r.csv_path, part,
                  r.title, r.time_unit, r.energy_unit};
  request.environment = plot_environment();
  request.max_output = kMaxCapturedOutput;
  request.timeout = kScriptTimeout;
  const ProcessResult p = run_process(request);

  std::string reason;
  if (!p.error.empty()) {
    reason = p.error;  // "cannot start PYTHON: ..."
  } else if (p.timed_out) {
    reason = "the plotting script did not finish within " + std::to_string(kScriptTimeout.count()) + " s";
  } else if (p.exit_code == kExitNoMatplotlib) {
    reason = "matplotlib is not available to " + python + " (install it with: " + kInstallHint + ")";
  } else if (p.signal != 0) {
    reason = "the plotting script was ended by signal " + std::to_string(p.signal);
  } else if (p.exit_code != 0) {
    reason = "the plotting script failed (exit " + std::to_string(p.exit_code) + ")";
    const std::string why = last_lines(p.output, 3);
    if (!why.empty()) reason += ": " + why;
  } else if (!fs::is_regular_file(part, ec) || fs::file_size(part, ec) == 0) {
    reason = "the plotting script wrote no image";
  } else {
    fs::rename(part, r.png_path, ec);  // atomic: the previous chart is replaced only by a complete one
    if (ec) reason = "cannot rename " + part + " to " + r.png_path + ": " + ec.message();
  }
  if (reason.empty()) return true;
  fs::remove(part, ec);
  return fail(reason);
}

bool write_energy_plot(const EnergyPlotRequest& r, std::string& warning) {
  std::string error;
  if (!write_energy_csv(r, error)) {
    warning = "energy balance not written: " + error;
    return false;
  }
  return draw_energy_png(r, kDebianPython, warning);
}

}  // namespace radx::io
