// SAE J211-1 channel frequency class (CFC) filtering of a sampled channel, as its Appendix C specifies: a
// 2-pole Butterworth low-pass run forward, then backward over the forward pass's output (phaseless: the
// backward pass undoes the forward pass's phase lag; the two passes make a 4-pole response).
//
// One pass, for a sampling step T (seconds) and a class CFC:
//   wd = 2 pi 2.0775 CFC                       (design frequency fd = 2.0775 CFC, in Hz)
//   wa = sin(wd T / 2) / cos(wd T / 2)         (the design frequency prewarped for the bilinear transform)
//   a0 = wa^2 / (1 + sqrt2 wa + wa^2),  a1 = 2 a0,  a2 = a0
//   b1 = -2 (wa^2 - 1) / (1 + sqrt2 wa + wa^2),  b2 = (-1 + sqrt2 wa - wa^2) / (1 + sqrt2 wa + wa^2)
//   Y_t = a0 X_t + a1 X_{t-1} + a2 X_{t-2} + b1 Y_{t-1} + b2 Y_{t-2}
// Frequency response of the forward-backward filter at a frequency f (the square of one pass's, which is
// the bilinear image of the analogue 2-pole Butterworth):
//   G(f) = 1 / (1 + (tan(pi f T) / wa)^4),  no phase.
// So G(fd) = 1/2 (-6.02 dB) and the -3 dB frequency F_H, where G = 1/sqrt2, has tan(pi F_H T) =
// (sqrt2 - 1)^(1/4) wa; for T -> 0, F_H = 0.8023 fd = 1.667 CFC: CFC 60, 180, 600, 1000 have F_H = 100,
// 300, 1000, 1667 Hz (J211's table gives 100, 300, 1000 and 1650 Hz), and a frequency well below F_H passes
// with a gain near 1 (G = 1 - (f / fd)^4 to first order).
//
// Each pass starts at rest on its first value (X_{-1} = X_{-2} = Y_{-1} = Y_{-2} = X_0), so a constant
// passes unchanged and the ends show no start-up step; a simulation has no pre-test data to pad with.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace radx::io {

struct CfcCoefficients {
  double a0 = 0, a1 = 0, a2 = 0, b1 = 0, b2 = 0;
};

// The classes J211 names; `radx th --filter` takes CFC60, CFC180, CFC600, CFC1000.
// The class of a name ("CFC60", case as written), or empty.
std::optional<double> parse_cfc_class(std::string_view name);

// The coefficients of one pass. Throws std::invalid_argument when the step does not resolve the design
// frequency (fd T >= 1/2: wa would not be finite or positive) or is not positive.
CfcCoefficients cfc_coefficients(double cfc, double step_seconds);

// G(f) above: the gain of the forward-backward filter at `frequency` (Hz).
double cfc_gain(double cfc, double step_seconds, double frequency);

// Filters values sampled every step_seconds, forward then backward.
std::vector<double> cfc_filter(std::span<const double> values, double cfc, double step_seconds);

// Seconds per time unit of a time-history file's unit label: s, ms, us (or mus), ns, or a number (the
// factor to seconds, as a deck may declare its time unit). Empty when the label is none of these.
std::optional<double> seconds_per_time_unit(std::string_view unit);

// A time-history channel, values at `times` (in the file's time unit, `seconds_per_unit` seconds each),
// filtered. The recursion needs a uniform step: rows that are uniform to 1e-6 of the mean step are filtered
// as they are; other rows (a row is written on the first cycle that reaches each output time, and the run's
// last cycle ends on its end time) are resampled linearly on the uniform grid of the same span and as many
// points, filtered there, and read back at the rows' times by linear interpolation; `*resampled` says so.
// False with `error` when there are fewer than 3 rows, the times do not increase, or the step does not
// resolve the class (see cfc_coefficients).
bool cfc_filter_channel(std::span<const double> times, std::span<const double> values, double cfc,
                        double seconds_per_unit, std::vector<double>& out, std::string& error,
                        bool* resampled = nullptr);

}  // namespace radx::io
