// SAE J211-1 CFC filtering; the recursion, its constants and its frequency response are in cfc_filter.hpp.
#include "io/signal/cfc_filter.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace radx::io {

namespace {

constexpr double kDesignFactor = 2.0775;  // fd / CFC (J211 Appendix C)

// One pass of the recursion over `x`, forward (first to last) or backward, in place, at rest on the first
// value it meets.
void one_pass(const CfcCoefficients& c, std::vector<double>& x, bool forward) {
  const std::size_t n = x.size();
  if (n == 0) return;
  const std::size_t first = forward ? 0 : n - 1;
  double x1 = x[first], x2 = x[first], y1 = x[first], y2 = x[first];
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = forward ? k : n - 1 - k;
    const double xi = x[i];
    const double yi = c.a0 * xi + c.a1 * x1 + c.a2 * x2 + c.b1 * y1 + c.b2 * y2;
    x2 = x1;
    x1 = xi;
    y2 = y1;
    y1 = yi;
    x[i] = yi;
  }
}

// Linear interpolation of (t, v) at `at`, t increasing; clamped to the ends.
double interpolate(std::span<const double> t, std::span<const double> v, double at) {
  if (at <= t.front()) return v.front();
  if (at >= t.back()) return v.back();
  const auto it = std::upper_bound(t.begin(), t.end(), at);
  const auto j = static_cast<std::size_t>(it - t.begin());
  const double w = (at - t[j - 1]) / (t[j] - t[j - 1]);
  return v[j - 1] + w * (v[j] - v[j - 1]);
}

}  // namespace

std::optional<double> parse_cfc_class(std::string_view name) {
  for (const int c : {60, 180, 600, 1000})
    if (name == "CFC" + std::to_string(c)) return static_cast<double>(c);
  return std::nullopt;
}

CfcCoefficients cfc_coefficients(double cfc, double step_seconds) {
  const double fd = kDesignFactor * cfc;
  if (!(step_seconds > 0) || !(fd * step_seconds < 0.5)) {
    throw std::invalid_argument("a sampling step of " + std::to_string(step_seconds) +
                                " s does not resolve CFC " + std::to_string(static_cast<int>(cfc)) +
                                ": its design frequency " + std::to_string(fd) +
                                " Hz must lie below half the sampling frequency (a step below " +
                                std::to_string(0.5 / fd) + " s; J211 asks for at least 10 times F_H)");
  }
  const double wd = 2.0 * std::numbers::pi * fd;
  const double wa = std::sin(wd * step_seconds / 2) / std::cos(wd * step_seconds / 2);
  const double s2 = std::numbers::sqrt2;
  const double d = 1.0 + s2 * wa + wa * wa;
  CfcCoefficients c;
  c.a0 = wa * wa / d;
  c.a1 = 2.0 * c.a0;
  c.a2 = c.a0;
  c.b1 = -2.0 * (wa * wa - 1.0) / d;
  c.b2 = (-1.0 + s2 * wa - wa * wa) / d;
  return c;
}

double cfc_gain(double cfc, double step_seconds, double frequency) {
  const double wa = std::tan(std::numbers::pi * kDesignFactor * cfc * step_seconds);
  const double r = std::tan(std::numbers::pi * frequency * step_seconds) / wa;
  return 1.0 / (1.0 + r * r * r * r);
}

std::vector<double> cfc_filter(std::span<const double> values, double cfc, double step_seconds) {
  const CfcCoefficients c = cfc_coefficients(cfc, step_seconds);
  std::vector<double> y(values.begin(), values.end());
  one_pass(c, y, true);
  one_pass(c, y, false);
  return y;
}

std::optional<double> seconds_per_time_unit(std::string_view unit) {
  if (unit == "s") return 1.0;
  if (unit == "ms") return 1e-3;
  if (unit == "us" || unit == "mus") return 1e-6;
  if (unit == "ns") return 1e-9;
  double v = 0;
  const auto r = std::from_chars(unit.data(), unit.data() + unit.size(), v);
  if (r.ec == std::errc() && r.ptr == unit.data() + unit.size() && v > 0 && std::isfinite(v)) return v;
  return std::nullopt;
}

bool cfc_filter_channel(std::span<const double> times, std::span<const double> values, double cfc,
                        double seconds_per_unit, std::vector<double>& out, std::string& error,
                        bool* resampled) {
  if (resampled != nullptr) *resampled = false;
  const std::size_t n = times.size();
  if (n < 3 || values.size() != n) {
    error = "CFC filtering needs at least 3 rows (the channel has " + std::to_string(n) + ")";
    return false;
  }
  for (std::size_t i = 1; i < n; ++i) {
    if (!(times[i] > times[i - 1])) {
      error = "CFC filtering needs increasing times; rows " + std::to_string(i) + " and " +
              std::to_string(i + 1) + " have times " + std::to_string(times[i - 1]) + " and " +
              std::to_string(times[i]);
      return false;
    }
  }
  const double step = (times[n - 1] - times[0]) / static_cast<double>(n - 1);
  bool uniform = true;
  for (std::size_t i = 1; i < n && uniform; ++i)
    uniform = std::abs((times[i] - times[i - 1]) - step) <= 1e-6 * step;
  try {
    if (uniform) {
      out = cfc_filter(values, cfc, step * seconds_per_unit);
      return true;
    }
    std::vector<double> grid(n), on_grid(n);
    for (std::size_t i = 0; i < n; ++i) {
      grid[i] = i + 1 == n ? times[n - 1] : times[0] + static_cast<double>(i) * step;
      on_grid[i] = interpolate(times, values, grid[i]);
    }
    const auto filtered = cfc_filter(on_grid, cfc, step * seconds_per_unit);
    out.resize(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = interpolate(grid, filtered, times[i]);
    if (resampled != nullptr) *resampled = true;
    return true;
  } catch (const std::invalid_argument& e) {
    error = e.what();
    return false;
  }
}

}  // namespace radx::io
