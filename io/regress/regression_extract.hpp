// The regression extract of OpenRadioss's QA decks (`ref.extract` beside a deck) and the comparison of a
// radx run against it, for `radx regress` (docs/regress.md).
//
// A ref.extract is one value per line, fields separated by blanks or tabs: a line number, a key, the value
// and, for the four energies, a reference magnitude (the run's largest energy, the scale deviations are
// measured on):
//     2 CYCLE	        29
//     3 TIME	 2.5380e-02
//     8 IENERGY	 8.8150e-02 2.3330e-01
// radx compares CYCLE, TIME, IENERGY (internal energy, the listing's I-ENERGY: no hourglass, no contact),
// KENERGYT and KENERGYR (translational and rotational kinetic energy) and EXTWORK (external work). The other
// keys OpenRadioss writes (Start, Stop, TSTEP, ELEMENT, ELTID, ERROR, MASERR) and any key radx does not know
// are skipped without reading their values: radx's time-step control and its energy error differ from
// OpenRadioss on purpose (docs/engine.md), so they are no yardstick.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace radx::io {

// The energies of an extract radx compares, in the order of the extract and of the report.
enum class ExtractEnergy : std::uint8_t { Internal, KineticTranslational, KineticRotational, ExternalWork };
inline constexpr std::array<ExtractEnergy, 4> kExtractEnergies{
    ExtractEnergy::Internal, ExtractEnergy::KineticTranslational, ExtractEnergy::KineticRotational,
    ExtractEnergy::ExternalWork};
// "IENERGY", "KENERGYT", "KENERGYR", "EXTWORK".
std::string_view extract_key(ExtractEnergy e);
// The report's short names: "IE", "KE", "KER", "EXT".
std::string_view extract_label(ExtractEnergy e);

struct ReferenceEnergy {
  double value = 0;
  double magnitude = 0;  // >= 0, the denominator of the deviation
};

// What a ref.extract says about the end of the OpenRadioss run.
struct RegressionExtract {
  std::int64_t cycles = 0;
  double time = 0;
  std::array<ReferenceEnergy, 4> energy;  // indexed by ExtractEnergy
  [[nodiscard]] const ReferenceEnergy& operator[](ExtractEnergy e) const {
    return energy[static_cast<std::size_t>(e)];
  }
};

// Parses the text of a ref.extract. Every line that is not blank needs a line number (an integer) and a
// key; CYCLE needs one integer, TIME one number, each energy a value and a magnitude (finite, the magnitude
// not negative), with nothing after them; each of the six appears once. False with `error` naming the
// file (`name`) and the line ("ref.extract:8: IENERGY needs ...") or, for a missing key, the file alone.
bool parse_regression_extract(std::string_view text, const std::string& name, RegressionExtract& out,
                              std::string& error);
// Reads and parses the file at `path` (errors name it as given).
bool read_regression_extract(const std::string& path, RegressionExtract& out, std::string& error);

// radx's figures at the end of a run, as compared (from NAME_summary.json).
struct RunFigures {
  std::int64_t cycles = 0;
  double time = 0;
  std::array<double, 4> energy{};  // indexed by ExtractEnergy
};

// |radx - ref| / magnitude, a fraction. A zero magnitude (every reference energy zero) gives 0 when the two
// are equal and +infinity otherwise: there is no scale to call a difference small. NaN in, NaN out.
double energy_deviation(double radx, double ref, double magnitude);
// |radx - ref| / |ref|, with the same rule when ref is 0.
double relative_deviation(double radx, double ref);

struct ExtractComparison {
  std::array<double, 4> energy{};  // energy_deviation of each energy (fractions), indexed by ExtractEnergy
  double time = 0;                 // relative_deviation of the final time (informative)
  double cycle_ratio = 0;  // radx cycles / reference cycles (informative; NaN when the reference has 0)
  // Every energy deviation <= tolerance (a fraction); NaN fails.
  [[nodiscard]] bool within(double tolerance) const;
};

ExtractComparison compare_to_extract(const RunFigures& radx, const RegressionExtract& ref);

}  // namespace radx::io
