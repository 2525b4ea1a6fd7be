// Shared by the report tests: looking at decoded PNGs, running the elbowsim
// binary; scratch folders come from support/scratch.hpp.
#pragma once

#include <doctest/doctest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include "report/plot/plot.hpp"
#include "support/process.hpp"
#include "support/scratch.hpp"

namespace elbowsim::testing {

inline double luminance(std::uint32_t rgb) {
  return 0.299 * ((rgb >> 16) & 0xFF) + 0.587 * ((rgb >> 8) & 0xFF) + 0.114 * (rgb & 0xFF);
}

// Variance of the luminance over the whole image: 0 for a blank one.
inline double luminance_variance(const plot::Image& image) {
  double sum = 0, square = 0;
  for (std::uint32_t p : image.rgb) sum += luminance(p), square += luminance(p) * luminance(p);
  const double n = static_cast<double>(image.rgb.size());
  return square / n - (sum / n) * (sum / n);
}

// Pixels darker than `below` (text, axes) in the box [x0, x1) x [y0, y1).
inline long dark_pixels(const plot::Image& image, int x0, int y0, int x1, int y1,
                        double below = 110) {
  long n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) n += luminance(image.at(x, y)) < below;
  return n;
}

// Pixels within `tolerance` (per channel) of an 8-bit colour, in a box.
inline long color_pixels(const plot::Image& image, plot::Color c, int x0, int y0, int x1, int y1,
                         int tolerance = 40) {
  const int r = static_cast<int>(c.r * 255 + 0.5), g = static_cast<int>(c.g * 255 + 0.5),
            b = static_cast<int>(c.b * 255 + 0.5);
  long n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::uint32_t p = image.at(x, y);
      n += std::abs(static_cast<int>((p >> 16) & 0xFF) - r) <= tolerance &&
           std::abs(static_cast<int>((p >> 8) & 0xFF) - g) <= tolerance &&
           std::abs(static_cast<int>(p & 0xFF) - b) <= tolerance;
    }
  return n;
}

// A decoded PNG of the expected size that is not blank: some contrast, and
// dark text in the y-label strip (left) and x-label strip (bottom).
inline void check_plot_png(const std::filesystem::path& png, int width, int height) {
  INFO(png.string());
  const plot::Image image = plot::read_png(png);
  REQUIRE(image.width == width);
  REQUIRE(image.height == height);
  CHECK(luminance_variance(image) > 50);
  CHECK(dark_pixels(image, 0, height / 4, 40, 3 * height / 4) > 20);              // y label
  CHECK(dark_pixels(image, width / 4, height - 50, 3 * width / 4, height) > 40);  // x ticks, label
}

// Every src="..." of <img> and <video>, relative to the page.
inline std::vector<std::string> sources(const std::string& html, const std::string& tag) {
  static const std::regex src("<(img|video)[^>]* src=\"([^\"]*)\"");
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), src); it != std::sregex_iterator();
       ++it)
    if ((*it)[1] == tag) out.push_back((*it)[2]);
  return out;
}

// Every <video src> and local <a href> names a file that is there.
inline void check_links(const std::filesystem::path& folder, const std::string& html) {
  for (const std::string& src : sources(html, "video"))
    CHECK_MESSAGE(std::filesystem::exists(folder / src), src);
  static const std::regex href("<a href=\"([^\"#][^\"]*)\"");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), href); it != std::sregex_iterator();
       ++it)
    CHECK_MESSAGE(std::filesystem::exists(folder / (*it)[1].str()), (*it)[1].str());
}

// Every <img> names a PNG in the folder that decodes, at its declared size, not blank.
inline void check_images(const std::filesystem::path& folder, const std::string& html,
                         std::size_t at_least) {
  const auto images = sources(html, "img");
  CHECK(images.size() >= at_least);
  for (const std::string& src : images) {
    INFO(src);
    REQUIRE(std::filesystem::exists(folder / src));
    std::smatch m;
    REQUIRE(std::regex_search(
        html, m, std::regex("src=\"" + src + "\"[^>]* width=\"(\\d+)\" height=\"(\\d+)\"")));
    check_plot_png(folder / src, std::stoi(m[1]), std::stoi(m[2]));
  }
}

using elbowsim::testing::Outcome;
using elbowsim::testing::run_elbowsim;
using elbowsim::testing::slurp;

}  // namespace elbowsim::testing
