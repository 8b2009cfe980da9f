#include "report_pictures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "bitmap_font.hpp"
#include "error.hpp"
#include "number_text.hpp"

namespace dbs {
namespace {

constexpr Rgb kInk = {30, 30, 30};
constexpr Rgb kGrid = {60, 60, 60};
constexpr Rgb kFolded = {230, 0, 200};
constexpr Rgb kSuspicious = {0, 0, 0};
constexpr Rgb kDegenerate = {150, 150, 150};
constexpr Rgb kTurned = {255, 140, 0};

std::string format(double value) { return significant_text(value, 3); }

// Calls paint(x, y) for every pixel whose centre lies in the triangle (pixel coordinates);
// for a triangle that holds no pixel centre, for the pixel of its centroid.
template <class Paint>
void cover_triangle(const double px[3], const double py[3], int width, int height, Paint&& paint) {
  double area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]);
  int xa = std::max(0, static_cast<int>(std::floor(std::min({px[0], px[1], px[2]}))));
  int xb = std::min(width - 1, static_cast<int>(std::ceil(std::max({px[0], px[1], px[2]}))));
  int ya = std::max(0, static_cast<int>(std::floor(std::min({py[0], py[1], py[2]}))));
  int yb = std::min(height - 1, static_cast<int>(std::ceil(std::max({py[0], py[1], py[2]}))));
  bool any = false;
  if (area != 0.0) {
    for (int y = ya; y <= yb; ++y) {
      for (int x = xa; x <= xb; ++x) {
        double sx = x + 0.5, sy = y + 0.5;
        double w0 = ((px[1] - sx) * (py[2] - sy) - (py[1] - sy) * (px[2] - sx)) / area;
        double w1 = ((px[2] - sx) * (py[0] - sy) - (py[2] - sy) * (px[0] - sx)) / area;
        if (w0 < 0.0 || w1 < 0.0 || w0 + w1 > 1.0) continue;
        paint(x, y);
        any = true;
      }
    }
  }
  if (!any) {
    int x = static_cast<int>(std::floor((px[0] + px[1] + px[2]) / 3.0)), y = static_cast<int>(std::floor((py[0] + py[1] + py[2]) / 3.0));
    if (x >= 0 && y >= 0 && x < width && y < height) paint(x, y);
  }
}

// Colours in bands: easier to read off against the legend than a continuous ramp, and the
// picture compresses well although the measure varies from triangle to triangle.
constexpr int kColourBands = 16;
double banded(double t) { return std::floor(std::clamp(t, 0.0, 1.0) * kColourBands * (1.0 - 1e-12)) / (kColourBands - 1); }

// The tick spacing of an axis: 1, 2 or 5 times a power of ten, the smallest not below `raw`.
double nice_step(double raw) {
  double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * decade >= raw * (1.0 - 1e-9)) return m * decade;
  }
  return 10.0 * decade;
}

void fill_rect(RgbImage& image, int x0, int y0, int x1, int y1, Rgb colour) {
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) image.plot(x, y, colour);
}

void frame_rect(RgbImage& image, int x0, int y0, int x1, int y1, Rgb colour) {
  for (int x = x0; x <= x1; ++x) image.plot(x, y0, colour), image.plot(x, y1, colour);
  for (int y = y0; y <= y1; ++y) image.plot(x0, y, colour), image.plot(x1, y, colour);
}

}  // namespace

Rgb ramp_colour(double t) {
  // ColorBrewer RdYlBu, reversed: blue for good, red for bad.
  static const double stops[6][3] = {{49, 54, 149}, {69, 117, 180}, {171, 217, 233}, {254, 224, 144}, {244, 109, 67}, {165, 0, 38}};
  t = std::clamp(std::isfinite(t) ? t : 1.0, 0.0, 1.0) * 5.0;
  int k = std::min(4, static_cast<int>(t));
  double w = t - k;
  Rgb c;
  for (int i = 0; i < 3; ++i) c[i] = static_cast<std::uint8_t>(std::lround(stops[k][i] + w * (stops[k + 1][i] - stops[k][i])));
  return c;
}

RgbImage draw_parameter_domain(const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const std::vector<TriangleDistortion>& distortion, const std::vector<std::size_t>& suspicious, const std::vector<std::size_t>& turned, const std::vector<Rect>& leaves, int size) {
  if (distortion.size() != triangles.size()) fail(ErrorCode::InvalidArgument, "draw_parameter_domain: " + std::to_string(distortion.size()) + " distortion entries for " + std::to_string(triangles.size()) + " triangles");
  if (size < 200) fail(ErrorCode::OutOfRange, "draw_parameter_domain: size " + std::to_string(size) + " (at least 200)");
  const int margin = size / 25, title = 24, legend = 64;
  const int plot = size - 2 * margin;
  RgbImage image(size, title + plot + 2 * margin + legend);
  const int left = margin, top = title + margin;
  auto to_pixel = [&](std::int32_t i, double& x, double& y) {
    x = left + u[i] * plot;
    y = top + (1.0 - v[i]) * plot;
  };

  std::vector<double> sum(static_cast<std::size_t>(plot) * plot, 0.0);
  std::vector<int> count(sum.size(), 0);
  const double log_limit = std::log(kConformalColourLimit);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (distortion[t].degenerate) continue;
    double px[3], py[3];
    for (int k = 0; k < 3; ++k) to_pixel(triangles[t][k], px[k], py[k]), px[k] -= left, py[k] -= top;
    double value = std::log(distortion[t].conformal) / log_limit;
    cover_triangle(px, py, plot, plot, [&](int x, int y) {
      sum[static_cast<std::size_t>(y) * plot + x] += value;
      ++count[static_cast<std::size_t>(y) * plot + x];
    });
  }
  for (int y = 0; y < plot; ++y)
    for (int x = 0; x < plot; ++x) {
      std::size_t i = static_cast<std::size_t>(y) * plot + x;
      if (count[i] > 0) image.set(left + x, top + y, ramp_colour(banded(sum[i] / count[i])));
    }
  // Marked triangles over the colours: degenerate, then suspicious, then folded on top; each
  // also gets a 3 x 3 dot at its centroid, so a triangle smaller than a pixel still shows.
  auto mark = [&](std::size_t t, Rgb colour) {
    double px[3], py[3];
    for (int k = 0; k < 3; ++k) to_pixel(triangles[t][k], px[k], py[k]);
    cover_triangle(px, py, image.width(), image.height(), [&](int x, int y) { image.set(x, y, colour); });
    int cx = static_cast<int>(std::floor((px[0] + px[1] + px[2]) / 3.0)), cy = static_cast<int>(std::floor((py[0] + py[1] + py[2]) / 3.0));
    fill_rect(image, cx - 1, cy - 1, cx + 2, cy + 2, colour);
  };
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (distortion[t].degenerate) mark(t, kDegenerate);
  for (std::size_t t : suspicious) mark(t, kSuspicious);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (distortion[t].folded) mark(t, kFolded);

  for (const Rect& r : leaves) {
    int x0 = left + static_cast<int>(std::lround(r.u0 * plot)), x1 = left + static_cast<int>(std::lround(r.u1 * plot));
    int y0 = top + static_cast<int>(std::lround((1.0 - r.v1) * plot)), y1 = top + static_cast<int>(std::lround((1.0 - r.v0) * plot));
    frame_rect(image, x0, y0, std::min(x1, left + plot), std::min(y1, top + plot), kGrid);
  }
  // The turned points last, over the leaves' lines.
  for (std::size_t i : turned) {
    if (i >= u.size()) fail(ErrorCode::InvalidArgument, "draw_parameter_domain: turned point " + std::to_string(i) + " is not one of the " + std::to_string(u.size()) + " points");
    double x = 0.0, y = 0.0;
    to_pixel(static_cast<std::int32_t>(i), x, y);
    const int cx = static_cast<int>(std::floor(x)), cy = static_cast<int>(std::floor(y));
    fill_rect(image, cx - 1, cy - 1, cx + 2, cy + 2, kTurned);
  }
  draw_text(image, left, 8, "PARAMETER DOMAIN (U RIGHT, V UP): CONFORMAL DISTORTION", kInk);

  // Legend: the colour ramp with ticks, then the marks.
  const int bar_top = top + plot + margin + 4, bar_height = 14;
  for (int x = 0; x < plot; ++x) fill_rect(image, left + x, bar_top, left + x + 1, bar_top + bar_height, ramp_colour(banded(static_cast<double>(x) / (plot - 1))));
  for (double tick : {1.0, 1.25, 1.5, 2.0, 3.0}) {
    int x = left + static_cast<int>(std::lround(std::log(tick) / log_limit * (plot - 1)));
    fill_rect(image, x, bar_top + bar_height, x + 1, bar_top + bar_height + 4, kInk);
    std::string label = format(tick) + (tick == kConformalColourLimit ? "+" : "");
    draw_text(image, std::clamp(x - text_width(label) / 2, 0, image.width() - text_width(label)), bar_top + bar_height + 6, label, kInk);
  }
  const int marks_top = bar_top + bar_height + 20;
  int x = left;
  for (auto [name, colour] : {std::pair<const char*, Rgb>{"FOLDED", kFolded}, {"TURNED", kTurned}, {"SUSPICIOUS", kSuspicious}, {"DEGENERATE", kDegenerate}, {"LEAF PATCHES", kGrid}}) {
    if (std::string(name) == "LEAF PATCHES") frame_rect(image, x, marks_top, x + 10, marks_top + 8, colour);
    else fill_rect(image, x, marks_top, x + 11, marks_top + 9, colour);
    draw_text(image, x + 16, marks_top + 1, name, kInk);
    x += 16 + text_width(name) + 18;
  }
  return image;
}

RgbImage draw_distance_histogram(const std::vector<double>& distances, const DistanceStats& stats, double tolerance, int width, int height) {
  if (width < 200 || height < 150) fail(ErrorCode::OutOfRange, "draw_distance_histogram: size " + std::to_string(width) + " x " + std::to_string(height) + " (at least 200 x 150)");
  constexpr int kBins = 50;
  RgbImage image(width, height);
  const int left = 56, right = 16, top = 44, bottom = 34;
  const int plot_w = width - left - right, plot_h = height - top - bottom;
  double limit = std::max(stats.p99 * 1.2, tolerance * 1.5);
  if (stats.max <= limit || !(limit > 0.0)) limit = stats.max;
  if (!(limit > 0.0)) limit = 1.0;  // all distances zero
  std::vector<std::size_t> bins(kBins, 0);
  for (double d : distances) {
    // In doubles first: a distance far beyond the limit (a point far outside the cloud)
    // would overflow an int.
    const double x = d / limit * kBins;
    bins[x >= 0.0 && x < kBins - 1 ? static_cast<int>(x) : x >= 0.0 ? kBins - 1 : 0] += 1;
  }
  const std::size_t highest = std::max<std::size_t>(1, *std::max_element(bins.begin(), bins.end()));

  for (int b = 0; b < kBins; ++b) {
    int x0 = left + b * plot_w / kBins, x1 = left + (b + 1) * plot_w / kBins - 1;
    int h = static_cast<int>(std::lround(static_cast<double>(bins[b]) / highest * plot_h));
    fill_rect(image, x0, top + plot_h - h, x1, top + plot_h, {70, 110, 170});
  }
  auto x_of = [&](double d) { return left + static_cast<int>(std::lround(std::clamp(d / limit, 0.0, 1.0) * plot_w)); };
  if (tolerance <= limit) fill_rect(image, x_of(tolerance) - 1, top, x_of(tolerance) + 1, top + plot_h, {0, 160, 60});
  for (int y = top; y < top + plot_h; y += 6) fill_rect(image, x_of(stats.mean), y, x_of(stats.mean) + 2, y + 3, {240, 130, 0});
  frame_rect(image, left - 1, top - 1, left + plot_w, top + plot_h, kInk);
  const double step = nice_step(limit / 4.0);
  for (int k = 0; k * step <= limit * (1.0 + 1e-9); ++k) {
    double d = k * step;
    std::string label = format(d);
    int x = x_of(d);
    fill_rect(image, x, top + plot_h, x + 1, top + plot_h + 4, kInk);
    draw_text(image, std::clamp(x - text_width(label) / 2, 0, width - text_width(label)), top + plot_h + 7, label, kInk);
  }
  std::string top_count = std::to_string(highest);
  draw_text(image, left - 6 - text_width(top_count), top, top_count, kInk);
  draw_text(image, left - 6 - text_width("0"), top + plot_h - kGlyphHeight, "0", kInk);
  if (stats.max > limit) draw_text(image, left + plot_w - text_width("LAST BIN: >= " + format(limit * (kBins - 1) / kBins)), top + 4, "LAST BIN: >= " + format(limit * (kBins - 1) / kBins), kInk);

  draw_text(image, left, 6, "DISTANCE TO THE BASE SURFACE", kInk);
  char line[160];
  std::snprintf(line, sizeof line, "%s%% OF %zu POINTS WITHIN %s (GREEN)  MEAN %s (ORANGE)  P95 %s  MAX %s", significant_text(100.0 * stats.within, 3).c_str(), stats.count, format(tolerance).c_str(), format(stats.mean).c_str(), format(stats.p95).c_str(), format(stats.max).c_str());
  draw_text(image, left, 22, line, kInk);
  draw_text(image, left + plot_w - text_width("DISTANCE"), height - 10, "DISTANCE", kInk);
  return image;
}

}  // namespace dbs
