// report/plot: tick selection (linear, log, odd ranges) and the PNGs drawn
// from line plots, bar charts and work-precision diagrams.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "report/plot/plot.hpp"
#include "report/plot/ticks.hpp"
#include "report_test_helpers.hpp"
#include "support/approx.hpp"

using elbowsim::testing::approx;
using namespace elbowsim::plot;
namespace t = elbowsim::testing;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void check_ticks(const Ticks& ticks, double lo, double hi, const std::vector<std::string>& labels) {
  CHECK(approx(ticks.lo, lo, 1e-12 * std::abs(lo) + 1e-300));
  CHECK(approx(ticks.hi, hi, 1e-12 * std::abs(hi) + 1e-300));
  CHECK(ticks.labels == labels);
  REQUIRE(ticks.major.size() == labels.size());
  const double slack = 1e-12 * std::max(std::abs(ticks.lo), std::abs(ticks.hi));
  for (double v : ticks.major) CHECK((v >= ticks.lo - slack && v <= ticks.hi + slack));
}

Series line(std::vector<double> x, std::vector<double> y, Color color) {
  Series s;
  s.label = "data";
  s.x = std::move(x);
  s.y = std::move(y);
  s.color = color;
  s.width = 2.5;
  return s;
}

std::filesystem::path png(const std::string& name) {
  return t::scratch("report", "plot_" + name) / (name + ".png");
}

}  // namespace

TEST_CASE("nice_step picks 1, 2 or 5 x 10^k with at most `target` intervals") {
  CHECK(nice_step(1.0, 5) == doctest::Approx(0.2));
  CHECK(nice_step(7.0, 5) == doctest::Approx(2.0));
  CHECK(nice_step(10.0, 5) == doctest::Approx(2.0));
  CHECK(nice_step(0.03, 6) == doctest::Approx(0.005));
  CHECK(nice_step(4.2e-13, 6) == doctest::Approx(1e-13));
  CHECK(nice_step(9.9e6, 4) == doctest::Approx(5e6));
}

TEST_CASE("linear ticks at round numbers") {
  SUBCASE("unit range") {
    check_ticks(linear_ticks(0, 1), 0, 1, {"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"});
  }
  SUBCASE("odd range, loose: limits move out to ticks") {
    check_ticks(linear_ticks(-0.37, 2.2), -0.5, 2.5,
                {"-0.5", "0.0", "0.5", "1.0", "1.5", "2.0", "2.5"});
  }
  SUBCASE("odd range, tight (time axes): limits stay, round ticks inside") {
    check_ticks(linear_ticks(0.013, 1.987, 6, false), 0.013, 1.987, {"0.5", "1.0", "1.5"});
  }
  SUBCASE("binary fractions do not drift: 0.1 + 0.2 still ticks 0.3") {
    const Ticks ticks = linear_ticks(0.1, 0.1 + 0.2, 4);
    CHECK(ticks.labels == std::vector<std::string>{"0.10", "0.15", "0.20", "0.25", "0.30"});
  }
  SUBCASE("reversed bounds are sorted") {
    check_ticks(linear_ticks(3, -1), -1, 3, {"-1", "0", "1", "2", "3"});
  }
  SUBCASE("tiny values carry the axis' power of ten") {
    check_ticks(linear_ticks(1e-13, 3e-13), 1e-13, 3e-13,
                {"1.0×10⁻¹³", "1.5×10⁻¹³", "2.0×10⁻¹³", "2.5×10⁻¹³", "3.0×10⁻¹³"});
  }
  SUBCASE("large values too") {
    check_ticks(linear_ticks(123456, 987654), 0, 1e6,
                {"0", "0.2×10⁶", "0.4×10⁶", "0.6×10⁶", "0.8×10⁶", "1.0×10⁶"});
  }
  SUBCASE("a constant widens by 10 %, around zero by 1") {
    check_ticks(linear_ticks(5, 5), 4.4, 5.6, {"4.4", "4.6", "4.8", "5.0", "5.2", "5.4", "5.6"});
    check_ticks(linear_ticks(0, 0), -1, 1, {"-1.0", "-0.5", "0.0", "0.5", "1.0"});
  }
  SUBCASE("non-finite bounds give [0, 1]") {
    check_ticks(linear_ticks(kNaN, 3), 0, 1, {"0.0", "0.2", "0.4", "0.6", "0.8", "1.0"});
  }
}

TEST_CASE("log ticks at decades with 10ⁿ labels") {
  CHECK(format_power_of_ten(-12) == "10⁻¹²");
  CHECK(format_power_of_ten(0) == "10⁰");
  CHECK(format_power_of_ten(3) == "10³");
  SUBCASE("three decades: every decade, 2..9 minor ticks") {
    const Ticks ticks = log_ticks(1e-3, 0.9);
    check_ticks(ticks, 1e-3, 1, {"10⁻³", "10⁻²", "10⁻¹", "10⁰"});
    CHECK(ticks.minor.size() == 24);
    CHECK(ticks.minor.front() == doctest::Approx(2e-3));
  }
  SUBCASE("fifteen decades: every second decade, limits on multiples of 2") {
    check_ticks(log_ticks(2e-17, 3e-3), 1e-18, 1e-2,
                {"10⁻¹⁸", "10⁻¹⁶", "10⁻¹⁴", "10⁻¹²", "10⁻¹⁰", "10⁻⁸", "10⁻⁶", "10⁻⁴", "10⁻²"});
  }
  SUBCASE("a constant power of ten widens a decade each way; 2 and 5 labelled") {
    check_ticks(log_ticks(1e-3, 1e-3), 1e-4, 1e-2,
                {"10⁻⁴", "2×10⁻⁴", "5×10⁻⁴", "10⁻³", "2×10⁻³", "5×10⁻³", "10⁻²"});
  }
  SUBCASE("inside one decade") {
    check_ticks(log_ticks(3, 5), 1, 10, {"10⁰", "2×10⁰", "5×10⁰", "10¹"});
  }
  SUBCASE("bounds that are not positive give [1, 10]") {
    check_ticks(log_ticks(0, 5), 1, 10, {"10⁰", "2×10⁰", "5×10⁰", "10¹"});
  }
}

TEST_CASE("a line plot PNG has the requested size, contrast and axis labels") {
  LinePlot p;
  p.title = "sine";
  p.y = linear_axis("angle", "rad");
  p.width = 640, p.height = 360;
  std::vector<double> x, y;
  for (int k = 0; k <= 200; ++k) x.push_back(0.01 * k), y.push_back(std::sin(0.05 * k));
  p.series.push_back(line(x, y, {0.9, 0.1, 0.1}));
  p.lanes.push_back({"elbow", {{0.5, 1.0}}, Color{0.1, 0.1, 0.9}});
  const auto file = png("line");
  write_png(p, file);
  t::check_plot_png(file, 640, 360);
  const Image image = read_png(file);
  CHECK(t::color_pixels(image, {0.9, 0.1, 0.1}, 0, 0, 640, 360) > 300);  // the line
  CHECK(t::color_pixels(image, {0.1, 0.1, 0.9}, 0, 0, 640, 360) > 500);  // the lane
}

TEST_CASE("NaN samples leave a gap in the line") {
  // y = 0.5 on x in [0, 1] except NaN on (0.4, 0.6): no line at the centre of the plot.
  std::vector<double> x, y;
  for (int k = 0; k <= 100; ++k) x.push_back(0.01 * k), y.push_back(k > 40 && k < 60 ? kNaN : 0.5);
  LinePlot p;
  p.title = "gap";
  p.y = linear_axis("y", "");
  p.y.min = 0, p.y.max = 1;
  p.width = 640, p.height = 360;
  p.series.push_back(line(x, y, {0.9, 0.1, 0.1}));
  const auto file = png("gap");
  write_png(p, file);
  const Image image = read_png(file);
  const Color red{0.9, 0.1, 0.1};
  CHECK(t::color_pixels(image, red, 150, 0, 200, 360) > 50);  // x ~ 0.2: drawn
  CHECK(t::color_pixels(image, red, 320, 0, 345, 360) == 0);  // x ~ 0.5: gap
  CHECK(t::color_pixels(image, red, 500, 0, 550, 360) > 50);  // x ~ 0.8: drawn
}

TEST_CASE("a constant series plots as a flat line, not an error") {
  LinePlot p;
  p.title = "constant";
  p.y = linear_axis("force", "N");
  p.series.push_back(line({0, 1, 2}, {3, 3, 3}, {0.9, 0.1, 0.1}));
  const auto file = png("constant");
  write_png(p, file);
  t::check_plot_png(file, p.width, p.height);
  CHECK(t::color_pixels(read_png(file), {0.9, 0.1, 0.1}, 0, 0, p.width, p.height) > 300);
}

TEST_CASE("a plot with no drawable data says so in the image") {
  LinePlot p;
  p.title = "nothing";
  p.y = log_axis("|d|", "m");
  p.series.push_back(line({0, 1, 2}, {0, 0, 0}, {0.9, 0.1, 0.1}));  // 0 has no place on a log axis
  p.empty_message = "no data: |d| is 0";
  const auto file = png("empty");
  REQUIRE_NOTHROW(write_png(p, file));
  const Image image = read_png(file);
  // The message, in grey, in the middle of the plot area.
  const int cx = p.width / 2, cy = p.height / 2;
  CHECK(t::dark_pixels(image, cx - 120, cy - 30, cx + 120, cy + 10, 160) > 30);
  // The legend still names the series; the plot area has none of it.
  CHECK(t::color_pixels(image, {0.9, 0.1, 0.1}, 0, 80, p.width, p.height) == 0);
}

TEST_CASE("a log plot draws positive values and skips zeros") {
  LinePlot p;
  p.title = "residual";
  p.y = log_axis("|r|", "J");
  std::vector<double> x, y;
  for (int k = 0; k <= 100; ++k)
    x.push_back(k), y.push_back(k == 0 ? 0.0 : std::pow(10.0, -12 + 0.1 * k));
  p.series.push_back(line(x, y, {0.9, 0.1, 0.1}));
  const auto file = png("log");
  write_png(p, file);
  t::check_plot_png(file, p.width, p.height);
  CHECK(t::color_pixels(read_png(file), {0.9, 0.1, 0.1}, 0, 0, p.width, p.height) > 300);
}

TEST_CASE("bar chart: one colour per group, bars from zero") {
  BarChart chart;
  chart.title = "totals";
  chart.y = linear_axis("energy", "J");
  chart.categories = {"elbow-on", "elbow-off"};
  chart.groups = {{"E_in", {4.1, 6.6}}, {"Joule", {3.9, kNaN}}};
  const auto file = png("bars");
  write_png(chart, file);
  t::check_plot_png(file, chart.width, chart.height);
  const Image image = read_png(file);
  CHECK(t::color_pixels(image, palette(0), 0, 0, chart.width, chart.height, 8) > 5000);
  CHECK(t::color_pixels(image, palette(1), 0, 0, chart.width, chart.height, 8) > 2000);
}

TEST_CASE("work-precision: log-log, one marked line per method") {
  const LinePlot p = work_precision_plot({{"rk4", {1e-3, 3e-3, 1e-2}, {1e-4, 1e-7, 1e-10}},
                                          {"euler", {5e-4, 2e-3, 8e-3}, {1e-2, 3e-3, 8e-4}}},
                                         "Work-precision", "hand error", "m");
  CHECK(p.x.scale == Scale::log);
  CHECK(p.y.scale == Scale::log);
  CHECK(p.x.unit == "s");
  REQUIRE(p.series.size() == 2);
  CHECK(p.series[0].label == "rk4");
  CHECK(p.series[1].markers);
  const auto file = png("work_precision");
  write_png(p, file);
  t::check_plot_png(file, p.width, p.height);
  const Image image = read_png(file);
  CHECK(t::color_pixels(image, palette(0), 0, 0, p.width, p.height, 10) > 200);
  CHECK(t::color_pixels(image, palette(1), 0, 0, p.width, p.height, 10) > 200);
  // No method with data: the image says so.
  REQUIRE_NOTHROW(write_png(work_precision_plot({}, "none", "error", "m"), png("wp_empty")));
}

TEST_CASE("an unwritable PNG path is an error naming the file") {
  LinePlot p;
  p.series.push_back(line({0, 1}, {0, 1}, {0, 0, 0}));
  CHECK_THROWS_WITH_AS(write_png(p, "/nonexistent-folder/x.png"),
                       doctest::Contains("/nonexistent-folder/x.png"), std::runtime_error);
  CHECK_THROWS_AS(read_png("/nonexistent-folder/x.png"), std::runtime_error);
}

TEST_CASE("tornado: each end's bar runs from the centre toward its value, in its own colour") {
  // One factor, its low end below the centre and its high end above; then the
  // other way round. Blue (low end) and orange (high end) are looked for in the
  // row's band only (the legend above has both colours too).
  const Color blue{0.122, 0.467, 0.706}, orange{0.937, 0.541, 0.180}, red{0.80, 0.10, 0.10};
  const auto mean_x = [](const Image& image, Color c, int y0, int y1) {
    double sum = 0;
    long n = 0;
    for (int x = 0; x < image.width; ++x) {
      const long here = t::color_pixels(image, c, x, y0, x + 1, y1, 30);
      sum += here * x, n += here;
    }
    return n ? sum / n : -1.0;
  };
  for (const bool rising : {true, false}) {
    Tornado chart;
    chart.title = "tornado";
    chart.x = linear_axis("ratio", "");
    chart.centre = 0.9;
    chart.reference = 1.0;
    chart.rows.push_back({"factor", rising ? 0.6 : 1.2, rising ? 1.2 : 0.6, "low", "high"});
    const auto file = png(rising ? "tornado_rising" : "tornado_falling");
    write_png(chart, file);
    const int height = tornado_height(1);
    t::check_plot_png(file, chart.width, height);
    const Image image = read_png(file);
    const int band_bottom = height - 58, band_top = band_bottom - 34;
    const double low_x = mean_x(image, blue, band_top, band_bottom);
    const double high_x = mean_x(image, orange, band_top, band_bottom);
    REQUIRE(low_x > 0);
    REQUIRE(high_x > 0);
    if (rising) CHECK(low_x < high_x);
    else CHECK(low_x > high_x);
    // The bars' lengths: 0.3 below the centre and 0.3 above it, so equal widths.
    CHECK(t::color_pixels(image, blue, 0, band_top, image.width, band_bottom, 30) ==
          doctest::Approx(t::color_pixels(image, orange, 0, band_top, image.width, band_bottom, 30)).epsilon(0.15));
    CHECK(t::color_pixels(image, red, 0, band_top, image.width, band_bottom, 30) > 5);  // the dashed 1
  }
}
