// OpenRadioss's ref.extract (io/regress/regression_extract.hpp): the reader and its errors, and the deviation
// arithmetic.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "io/regress/regression_extract.hpp"
#include "ref_extract_sample.hpp"

using radx::io::ExtractEnergy;
using radx::test::kExtract;
using radx::test::with_line;

namespace {

std::string parse_error(const std::string& text) {
  radx::io::RegressionExtract r;
  std::string error;
  CHECK_FALSE(radx::io::parse_regression_extract(text, "dir/ref.extract", r, error));
  return error;
}

}  // namespace

TEST_CASE("ref.extract: values, magnitudes, the keys radx skips", "[regress]") {
  radx::io::RegressionExtract r;
  std::string error;
  REQUIRE(radx::io::parse_regression_extract(kExtract, "ref.extract", r, error));
  CHECK(r.cycles == 29);
  CHECK(r.time == 2.5380e-02);
  CHECK(r[ExtractEnergy::Internal].value == 8.8150e-02);
  CHECK(r[ExtractEnergy::Internal].magnitude == 2.3330e-01);
  CHECK(r[ExtractEnergy::KineticTranslational].value == 1.4560e-01);
  CHECK(r[ExtractEnergy::KineticRotational].value == 7.0160e-18);
  CHECK(r[ExtractEnergy::KineticRotational].magnitude == 2.3330e-01);
  CHECK(r[ExtractEnergy::ExternalWork].value == 2.3330e-01);

  // Windows line ends, blank lines and a key radx does not know change nothing.
  std::string crlf;
  for (char c : "\n" + kExtract + "\n   14 NEWKEY 1 2 3\n")
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  radx::io::RegressionExtract r2;
  REQUIRE(radx::io::parse_regression_extract(crlf, "ref.extract", r2, error));
  CHECK(r2.cycles == 29);
  CHECK(r2[ExtractEnergy::ExternalWork].magnitude == 2.3330e-01);

  CHECK(radx::io::extract_key(ExtractEnergy::KineticRotational) == "KENERGYR");
  CHECK(radx::io::extract_label(ExtractEnergy::ExternalWork) == "EXT");
}

TEST_CASE("ref.extract: a malformed line is an error naming the file and the line", "[regress]") {
  using Catch::Matchers::Contains;
  using Catch::Matchers::StartsWith;
  CHECK_THAT(parse_error(with_line(8, "    8 IENERGY\t 8.8150e-02")),
             StartsWith("dir/ref.extract:8: IENERGY needs a value and a reference magnitude") &&
                 Contains("found \"8.8150e-02\""));
  CHECK_THAT(parse_error(with_line(9, "    9 KENERGYT\t 1.4x60e-01 2.3330e-01")),
             StartsWith("dir/ref.extract:9: KENERGYT needs") && Contains("1.4x60e-01"));
  CHECK_THAT(parse_error(with_line(11, "   11 EXTWORK\t 2.3330e-01 -1.0")),
             StartsWith("dir/ref.extract:11: EXTWORK") && Contains("magnitude \"-1.0\""));
  CHECK_THAT(parse_error(with_line(11, "   11 EXTWORK\t 2.3330e-01 2.3330e-01 7")),
             StartsWith("dir/ref.extract:11: EXTWORK"));
  CHECK_THAT(parse_error(with_line(10, "   10 KENERGYR\t inf 2.3330e-01")),
             StartsWith("dir/ref.extract:10: "));
  CHECK_THAT(parse_error(with_line(2, "    2 CYCLE\t 29.5")),
             StartsWith("dir/ref.extract:2: CYCLE needs one integer"));
  CHECK_THAT(parse_error(with_line(3, "    3 TIME")),
             StartsWith("dir/ref.extract:3: TIME needs one number") && Contains("found nothing"));
  CHECK_THAT(parse_error(with_line(3, "TIME 2.5e-2")),
             StartsWith("dir/ref.extract:3: expected a line number and a key"));
  CHECK_THAT(parse_error(with_line(5, "    5 CYCLE 30")),
             StartsWith("dir/ref.extract:5: a second CYCLE line (the first is line 2)"));
  CHECK_THAT(parse_error(with_line(10, "")), StartsWith("dir/ref.extract: no KENERGYR line"));
  CHECK_THAT(parse_error(""), Contains("no IENERGY, KENERGYT, KENERGYR, EXTWORK, CYCLE, TIME line"));

  radx::io::RegressionExtract r;
  std::string error;
  CHECK_FALSE(radx::io::read_regression_extract("/nonexistent/ref.extract", r, error));
  CHECK_THAT(error, StartsWith("/nonexistent/ref.extract: cannot open"));
}

TEST_CASE("regress: deviations are |radx - ref| / magnitude, the cycle count a ratio", "[regress]") {
  using radx::io::energy_deviation;
  CHECK(energy_deviation(0.1, 0.08815, 0.2333) == Approx((0.1 - 0.08815) / 0.2333).epsilon(1e-15));
  CHECK(energy_deviation(0.08, 0.08815, 0.2333) == Approx((0.08815 - 0.08) / 0.2333).epsilon(1e-15));
  // A tiny energy against a tiny reference is measured on the run's scale, not its own.
  CHECK(energy_deviation(2e-18, 7.016e-18, 0.2333) < 1e-16);
  CHECK(energy_deviation(0.0, 0.0, 0.0) == 0.0);
  CHECK(std::isinf(energy_deviation(1e-30, 0.0, 0.0)));
  CHECK(std::isnan(energy_deviation(std::nan(""), 1.0, 1.0)));
  CHECK(radx::io::relative_deviation(0.0254, 0.02538) == Approx(0.02 / 25.38).epsilon(1e-12));

  radx::io::RegressionExtract ref;
  std::string error;
  REQUIRE(radx::io::parse_regression_extract(kExtract, "ref.extract", ref, error));
  radx::io::RunFigures radx;
  radx.cycles = 58;
  radx.time = 2.5380e-02;
  radx.energy = {8.8150e-02 + 0.05 * 2.3330e-01, 1.4560e-01 - 0.01 * 2.3330e-01, 0.0, 2.3330e-01};
  const auto c = radx::io::compare_to_extract(radx, ref);
  CHECK(c.cycle_ratio == 2.0);
  CHECK(c.time == 0.0);
  CHECK(c.energy[0] == Approx(0.05).epsilon(1e-12));
  CHECK(c.energy[1] == Approx(0.01).epsilon(1e-12));
  CHECK(c.energy[2] == Approx(7.016e-18 / 0.2333).epsilon(1e-12));
  CHECK(c.energy[3] == 0.0);
  CHECK(c.within(0.0501));
  CHECK_FALSE(c.within(0.0499));
  auto nan = c;
  nan.energy[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK_FALSE(nan.within(1e9));  // a NaN energy never passes
}
