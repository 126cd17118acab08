// The J211 CFC filter against its closed-form response (io/signal/cfc_filter.hpp): sines of known frequency
// go through and their amplitude and phase, fitted away from the ends, are compared with G(f) and 0.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "io/signal/cfc_filter.hpp"

namespace {

using radx::io::cfc_filter;
using radx::io::cfc_gain;

constexpr double kPi = std::numbers::pi;

struct Fit {
  double gain = 0, phase = 0;
};

// Least-squares fit of y = A sin(w t) + B cos(w t) over samples [first, last): for the input sin(w t), the
// gain is |(A, B)| and the phase lead atan2(B, A).
Fit fit_sine(const std::vector<double>& y, double w, double step, std::size_t first, std::size_t last) {
  double ss = 0, sc = 0, cc = 0, ys = 0, yc = 0;
  for (std::size_t i = first; i < last; ++i) {
    const double t = static_cast<double>(i) * step, s = std::sin(w * t), c = std::cos(w * t);
    ss += s * s, sc += s * c, cc += c * c, ys += y[i] * s, yc += y[i] * c;
  }
  const double det = ss * cc - sc * sc;
  const double a = (ys * cc - yc * sc) / det, b = (yc * ss - ys * sc) / det;
  return {std::hypot(a, b), std::atan2(b, a)};
}

// The filtered sine of `frequency` (Hz), 60 periods sampled every `step` seconds, fitted over its middle
// third: the start-up of each pass has died out there (the filter's time constant is about 1 / fd, a
// fraction of a period for the frequencies tested).
Fit response(double cfc, double step, double frequency) {
  const double w = 2 * kPi * frequency;
  const auto n = static_cast<std::size_t>(60.0 / frequency / step);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::sin(w * static_cast<double>(i) * step);
  const auto y = cfc_filter(x, cfc, step);
  return fit_sine(y, w, step, n / 3, 2 * n / 3);
}

}  // namespace

TEST_CASE("CFC filter: gain at the design frequency is 1/2 and at F_H is 1/sqrt2, both phaseless") {
  // 10 kHz sampling, the rate J211 expects for CFC 60 and 180 (at least 10 F_H).
  const double step = 1e-4;
  for (const double cfc : {60.0, 180.0}) {
    const double fd = 2.0775 * cfc;
    // The gain of the closed form at fd is exactly 1/2 (tan(pi fd T) / wa = 1); measured to 1e-3, the
    // residue of the least-squares fit over whole and partial periods.
    const Fit at_fd = response(cfc, step, fd);
    CHECK(cfc_gain(cfc, step, fd) == Approx(0.5).epsilon(1e-12));
    CHECK(at_fd.gain == Approx(0.5).margin(1e-3));
    CHECK(std::abs(at_fd.phase) < 1e-3);  // radians: forward and backward lags cancel
    // F_H, the -3 dB point: tan(pi F_H T) = (sqrt2 - 1)^(1/4) tan(pi fd T).
    const double wa = std::tan(kPi * fd * step);
    const double f_h = std::atan(std::pow(std::sqrt(2.0) - 1.0, 0.25) * wa) / (kPi * step);
    CHECK(cfc_gain(cfc, step, f_h) == Approx(1 / std::sqrt(2.0)).epsilon(1e-12));
    const Fit at_fh = response(cfc, step, f_h);
    CHECK(at_fh.gain == Approx(1 / std::sqrt(2.0)).margin(1e-3));
    CHECK(std::abs(at_fh.phase) < 1e-3);
    // J211's table: F_H = 100 Hz for CFC 60 and 300 Hz for CFC 180, i.e. 5/3 CFC; the prewarping moves F_H
    // by (pi fd T)^2 / 3 relative at most, 0.7 % for CFC 180 at 10 kHz.
    CHECK(f_h == Approx(5.0 / 3.0 * cfc).epsilon(0.01));
  }
}

TEST_CASE("CFC filter: a low frequency passes unchanged, a high one is removed") {
  const double step = 1e-5;  // 100 kHz: CFC 600 and 1000
  for (const double cfc : {600.0, 1000.0}) {
    const double fd = 2.0775 * cfc;
    // fd / 20: G = 1 / (1 + 20^-4) = 0.999994; measured gain within 1e-4 of 1 and of G.
    const Fit low = response(cfc, step, fd / 20);
    CHECK(low.gain == Approx(1.0).margin(1e-4));
    CHECK(low.gain == Approx(cfc_gain(cfc, step, fd / 20)).margin(1e-4));
    CHECK(std::abs(low.phase) < 1e-4);
    // 5 fd: G = 1/626 (with prewarping a little less): the sine is cut to under 0.2 %.
    const Fit high = response(cfc, step, 5 * fd);
    CHECK(high.gain < 2e-3);
    CHECK(high.gain == Approx(cfc_gain(cfc, step, 5 * fd)).margin(1e-4));
  }
}

TEST_CASE("CFC filter: a symmetric pulse keeps its peak time, a constant passes unchanged") {
  const double step = 1e-4, cfc = 60;
  // A Gaussian pulse of 5 ms standard deviation centred at sample 500 of 1001.
  std::vector<double> x(1001);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = (static_cast<double>(i) - 500.0) * step;
    x[i] = std::exp(-0.5 * t * t / (5e-3 * 5e-3));
  }
  const auto y = cfc_filter(x, cfc, step);
  std::size_t peak = 0;
  for (std::size_t i = 1; i < y.size(); ++i)
    if (y[i] > y[peak]) peak = i;
  CHECK(peak == 500);  // a forward pass alone delays it by sqrt2 / wd = 1.8 ms (18 samples)
  // The pulse's spectrum, a Gaussian of standard deviation 1 / (2 pi 5 ms) = 32 Hz, lies below F_H = 100 Hz:
  // the peak loses about 3 (32 / fd)^4 = 1.3 % (G = 1 - (f / fd)^4 averaged over it), under 3 %.
  CHECK(y[peak] == Approx(1.0).margin(0.03));
  // Mirror symmetry around the peak, to the round-off of the two passes (the ends differ: each pass starts
  // at rest on its own first value, and both ends are 0 here).
  for (std::size_t k = 1; k < 300; ++k) CHECK(y[500 + k] == Approx(y[500 - k]).margin(1e-9));
  const std::vector<double> c(50, 3.25);
  for (const double v : cfc_filter(c, cfc, step)) CHECK(v == Approx(3.25).epsilon(1e-12));
}

TEST_CASE("CFC filter: a channel's step, its resampling and the steps it refuses") {
  using radx::io::cfc_filter_channel;
  std::string error;
  std::vector<double> out;
  bool resampled = true;
  // Uniform rows in ms: filtered as they are, with T = 0.1 ms.
  std::vector<double> t, v;
  for (int i = 0; i <= 2000; ++i) {
    t.push_back(0.1 * i);
    v.push_back(std::sin(2 * kPi * 0.0124650 * 0.1 * i));  // 12.465 Hz in ms: fd / 10 of CFC 60
  }
  REQUIRE(cfc_filter_channel(t, v, 60, 1e-3, out, error, &resampled));
  CHECK_FALSE(resampled);
  const auto direct = cfc_filter(v, 60, 1e-4);
  REQUIRE(out.size() == direct.size());
  for (std::size_t i = 0; i < out.size(); ++i) CHECK(out[i] == Approx(direct[i]).margin(1e-12));
  // A row moved by a quarter step: resampled; a constant stays what it was at every row.
  t[700] += 0.025;
  const std::vector<double> c(t.size(), -2.0);
  REQUIRE(cfc_filter_channel(t, c, 60, 1e-3, out, error, &resampled));
  CHECK(resampled);
  for (const double x : out) CHECK(x == Approx(-2.0).epsilon(1e-12));
  // A step of 5 ms cannot resolve CFC 60's 124.65 Hz (it needs a step below 4.01 ms).
  const std::vector<double> coarse_t{0, 5, 10, 15}, coarse_v{0, 1, 0, 1};
  CHECK_FALSE(cfc_filter_channel(coarse_t, coarse_v, 60, 1e-3, out, error));
  CHECK(error.find("does not resolve CFC 60") != std::string::npos);
  const std::vector<double> two{0, 1};
  CHECK_FALSE(cfc_filter_channel(two, two, 60, 1e-3, out, error));
  CHECK(radx::io::seconds_per_time_unit("ms") == 1e-3);
  CHECK(radx::io::seconds_per_time_unit("0.001") == 1e-3);
  CHECK_FALSE(radx::io::seconds_per_time_unit("fortnight"));
  CHECK(radx::io::parse_cfc_class("CFC180") == 180.0);
  CHECK_FALSE(radx::io::parse_cfc_class("CFC100"));
}
