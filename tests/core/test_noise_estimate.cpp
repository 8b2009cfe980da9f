// The noise estimate (issue 10, "a noise floor"): calibrated on noisy planes, within 10% of
// sigma on a saddle with noise along its normal at 0.1%, 0.5% and 2% of the diagonal (the
// last, and a dense noisy cloud, widen the neighbourhoods), near zero on the clean saddle, on an open box with sharp
// creases and on a rippled height field, scale- and motion-equivariant, bit-identical for any
// thread count, and 0 with a documented rule on clouds too small or too degenerate to fit.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "analytic_clouds.hpp"
#include "cloud_index.hpp"
#include "noise_estimate.hpp"

// cmocka last: its fail() macro would hide dbs::fail.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;
using namespace dbs_test;

namespace {

/// z = 0.5 (x^2 - y^2) over [-1,1]^2 (diagonal 3), and its unit normal.
Vec3 saddle_at(double x, double y) { return Vec3(x, y, 0.5 * (x * x - y * y)); }
Vec3 saddle_normal(double x, double y) { return Vec3(-x, y, 1.0).normalized(); }

/// `count` random points of the saddle moved along its normal by N(0, sigma^2).
std::vector<Vec3> noisy_saddle(std::size_t count, double sigma, unsigned seed) {
  const Surface s = [](double a, double b) { return saddle_at(2 * a - 1, 2 * b - 1); };
  std::vector<Vec2> ab;
  std::vector<Vec3> pts = random_points(s, count, seed, &ab);
  std::mt19937_64 rng(seed + 1000);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] += sigma * gauss(rng) * saddle_normal(2 * ab[i].x() - 1, 2 * ab[i].y() - 1);
  return pts;
}

/// An open unit box, floor z = 0 and four walls of height 0.5 (90-degree creases along the
/// floor's edges and the walls' vertical edges), area-uniform, each point moved by N(0, sigma^2)
/// along its face's normal.
std::vector<Vec3> open_box(std::size_t count, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Vec3> pts;
  for (std::size_t i = 0; i < count; ++i) {
    const double face = 3.0 * unit(rng), a = unit(rng), c = unit(rng), e = sigma * gauss(rng);
    if (face < 1.0)
      pts.emplace_back(a, c, e);  // floor
    else if (face < 1.5)
      pts.emplace_back(a, e, 0.5 * c);
    else if (face < 2.0)
      pts.emplace_back(a, 1.0 + e, 0.5 * c);
    else if (face < 2.5)
      pts.emplace_back(e, a, 0.5 * c);
    else
      pts.emplace_back(1.0 + e, a, 0.5 * c);
  }
  return pts;
}

/// The height field z = 0.2 sin(pi x) sin(pi y) + 0.01 sin(16 pi x) sin(16 pi y) over [0,1]^2.
std::vector<Vec3> rippled(std::size_t count, unsigned seed) {
  const Surface s = [](double x, double y) { return Vec3(x, y, 0.2 * std::sin(M_PI * x) * std::sin(M_PI * y) + 0.01 * std::sin(16 * M_PI * x) * std::sin(16 * M_PI * y)); };
  return random_points(s, count, seed);
}

/// The unit square z = 0 with N(0, sigma^2) along z.
std::vector<Vec3> noisy_plane(std::size_t count, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Vec3> pts;
  for (std::size_t i = 0; i < count; ++i) {
    const double x = unit(rng), y = unit(rng);
    pts.emplace_back(x, y, sigma * gauss(rng));
  }
  return pts;
}

NoiseEstimate estimate(const std::vector<Vec3>& pts, int threads = 2) {
  const CloudIndex index(pts);
  return estimate_noise(index, threads);
}

void calibrated_on_noisy_planes(void**) {
  // The leave-one-out residual of the centre divided by sqrt(1 + leverage) corrects for the
  // fit's 6 parameters exactly under Gaussian noise, so kNoiseCalibration is 1; this is the
  // measurement behind it (over 40 planes of 20000 points it was 0.995 +- 0.004 at sigma
  // 0.05-0.2 spacings). Planes tilted and moved (noise along their normal): a rigid motion
  // changes nothing.
  const std::size_t n = 20000;
  double sum = 0.0;
  const int planes = 8;
  for (int p = 0; p < planes; ++p) {
    const double sigma = 0.2 * 0.5 / std::sqrt(static_cast<double>(n));  // 0.2 of the mean spacing
    std::vector<Vec3> pts = noisy_plane(n, sigma, 100 + p);
    for (Vec3& q : pts) q = move_and_scale(q, 1.0);
    const NoiseEstimate e = estimate(pts);
    assert_int_equal(e.neighbours, kNoiseNeighbours);
    sum += e.sigma / sigma;
  }
  const double ratio = sum / planes;
  print_message("noisy planes: estimate / sigma %.4f on average (kNoiseCalibration %.4f)\n", ratio, kNoiseCalibration);
  assert_true(std::abs(ratio - 1.0) < 0.02);
}

void within_ten_percent_on_noisy_saddle(void**) {
  const double diagonal = bounds_of(noisy_saddle(4000, 0.0, 7)).diagonal();
  assert_true(std::abs(diagonal - 3.0) < 0.01);
  for (double relative : {0.001, 0.005, 0.02}) {
    const double sigma = relative * diagonal;
    const NoiseEstimate e = estimate(noisy_saddle(4000, sigma, 7));
    print_message("saddle, noise %.1f%% of the diagonal: estimate / sigma %.3f (%zu samples, %zu neighbours, stride %zu)\n", 100 * relative, e.sigma / sigma, e.samples,
                  e.neighbours, e.stride);
    assert_true(std::abs(e.sigma / sigma - 1.0) < 0.10);
    assert_true(e.samples > 3000);
    assert_true(e.spacing > 0.0);
  }
}

void thick_noise_widens_the_neighbourhood(void**) {
  // sigma of 4 mean spacings: 24 neighbours form a blob, not a sheet, and the estimate only
  // holds with wider neighbourhoods.
  const std::size_t n = 4000;
  const double sigma = 4.0 * 0.5 / std::sqrt(static_cast<double>(n));
  NoiseEstimate e = estimate(noisy_plane(n, sigma, 3));
  print_message("plane, sigma 4 spacings: estimate / sigma %.3f with %zu neighbours, stride %zu\n", e.sigma / sigma, e.neighbours, e.stride);
  assert_true(e.neighbours * e.stride > kNoiseNeighbours);
  assert_true(std::abs(e.sigma / sigma - 1.0) < 0.10);
  // A dense scan: 200000 points of the saddle with noise 0.5% of the diagonal, about 6 mean
  // spacings; the neighbours come from a sub-cloud.
  const double dense_sigma = 0.005 * 3.0;
  e = estimate(noisy_saddle(200000, dense_sigma, 21));
  print_message("saddle, 200000 points, noise 0.5%% of the diagonal (%.1f measured spacings): estimate / sigma %.3f with %zu neighbours, stride %zu\n", dense_sigma / e.spacing,
                e.sigma / dense_sigma, e.neighbours, e.stride);
  assert_true(e.stride > 1);
  assert_true(std::abs(e.sigma / dense_sigma - 1.0) < 0.10);
}

void small_on_clean_surfaces(void**) {
  // Below 10% of an accuracy target of 1e-3 of the diagonal.
  {
    const std::vector<Vec3> pts = noisy_saddle(4000, 0.0, 7);
    const NoiseEstimate e = estimate(pts);
    const double relative = e.sigma / bounds_of(pts).diagonal();
    print_message("clean saddle: estimate %.3g of the diagonal\n", relative);
    assert_true(relative < 1e-4);
    assert_true(e.samples > 3000);
  }
  {
    // The fits across the creases are dropped or above the low quantile.
    const std::vector<Vec3> pts = open_box(4000, 0.0, 5);
    const NoiseEstimate e = estimate(pts);
    const double relative = e.sigma / bounds_of(pts).diagonal();
    print_message("clean open box: estimate %.3g of the diagonal\n", relative);
    assert_true(relative < 1e-4);
  }
  // A ripple of amplitude 0.01 and wavelength 1/8: the 24 neighbours span about 0.7 of a
  // wavelength with 4000 points (the quadric follows it only roughly), 0.3 with 20000.
  for (std::size_t n : {4000u, 20000u}) {
    const NoiseEstimate e = estimate(rippled(n, 9));
    print_message("clean ripple, %zu points: estimate %.3g of the ripple amplitude\n", n, e.sigma / 0.01);
    assert_true(e.sigma < (n == 4000 ? 0.2 : 0.05) * 0.01);
  }
}

void creases_do_not_raise_noise(void**) {
  const double diagonal = bounds_of(open_box(4000, 0.0, 5)).diagonal();
  for (double relative : {0.001, 0.005}) {
    const double sigma = relative * diagonal;
    const NoiseEstimate e = estimate(open_box(4000, sigma, 5));
    print_message("open box, noise %.1f%% of the diagonal: estimate / sigma %.3f\n", 100 * relative, e.sigma / sigma);
    assert_true(std::abs(e.sigma / sigma - 1.0) < 0.15);
  }
}

void scale_and_motion_equivariant(void**) {
  const std::vector<Vec3> pts = noisy_saddle(4000, 0.015, 11);
  const NoiseEstimate base = estimate(pts);
  for (double scale : {1e-3, 1000.0}) {
    std::vector<Vec3> scaled = pts, moved = pts;
    for (Vec3& p : scaled) p *= scale;
    for (Vec3& p : moved) p = move_and_scale(p, scale);
    for (const std::vector<Vec3>* cloud : {&scaled, &moved}) {
      const NoiseEstimate e = estimate(*cloud);
      assert_true(std::abs(e.sigma / (scale * base.sigma) - 1.0) < 1e-9);
      assert_true(std::abs(e.spacing / (scale * base.spacing) - 1.0) < 1e-9);
      assert_int_equal(e.samples, base.samples);
      assert_int_equal(e.neighbours, base.neighbours);
      assert_int_equal(e.stride, base.stride);
      assert_true(std::abs(e.radius / (scale * base.radius) - 1.0) < 1e-9);
    }
  }
}

void thread_count_changes_nothing(void**) {
  // Also with widened neighbourhoods (2% noise).
  for (double sigma : {0.015, 0.06}) {
    const std::vector<Vec3> pts = noisy_saddle(4000, sigma, 13);
    const NoiseEstimate one = estimate(pts, 1);
    for (int threads : {2, 3, 8, 0}) {
      const NoiseEstimate e = estimate(pts, threads);
      assert_memory_equal(&e.sigma, &one.sigma, sizeof(double));
      assert_memory_equal(&e.spacing, &one.spacing, sizeof(double));
      assert_int_equal(e.samples, one.samples);
      assert_int_equal(e.neighbours, one.neighbours);
      assert_int_equal(e.stride, one.stride);
    }
  }
}

void too_small_or_degenerate_gives_zero(void**) {
  // Fewer than kNoiseNeighbours + 1 points: sigma 0, no samples, the spacing still measured.
  const std::vector<Vec3> few = noisy_saddle(kNoiseNeighbours, 0.01, 3);
  NoiseEstimate e = estimate(few);
  assert_true(e.sigma == 0.0);
  assert_int_equal(e.samples, 0);
  assert_int_equal(e.neighbours, 0);
  assert_int_equal(e.stride, 0);
  assert_true(e.spacing > 0.0);
  // One more point and the estimate exists.
  e = estimate(noisy_saddle(kNoiseNeighbours + 1, 0.01, 3));
  assert_true(e.sigma > 0.0);
  assert_true(e.samples > 0);
  // Empty and single-point clouds.
  e = estimate({});
  assert_true(e.sigma == 0.0 && e.spacing == 0.0 && e.samples == 0);
  e = estimate({Vec3(1, 2, 3)});
  assert_true(e.sigma == 0.0 && e.spacing == 0.0 && e.samples == 0);
  // Collinear points carry no quadric: sigma 0, no samples.
  std::vector<Vec3> line;
  for (int i = 0; i < 500; ++i) line.emplace_back(0.01 * i, 0.02 * i, -0.03 * i);
  e = estimate(line);
  assert_true(e.sigma == 0.0);
  assert_int_equal(e.samples, 0);
  // Every point twice: the centre's duplicate is left out of its own fit, so the estimate
  // does not collapse to 0.
  std::vector<Vec3> doubled = noisy_saddle(4000, 0.015, 17);
  doubled.insert(doubled.end(), doubled.begin(), doubled.end());
  e = estimate(doubled);
  print_message("saddle, every point twice: estimate / sigma %.3f\n", e.sigma / 0.015);
  assert_true(e.sigma > 0.5 * 0.015);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(calibrated_on_noisy_planes),
      cmocka_unit_test(within_ten_percent_on_noisy_saddle),
      cmocka_unit_test(thick_noise_widens_the_neighbourhood),
      cmocka_unit_test(small_on_clean_surfaces),
      cmocka_unit_test(creases_do_not_raise_noise),
      cmocka_unit_test(scale_and_motion_equivariant),
      cmocka_unit_test(thread_count_changes_nothing),
      cmocka_unit_test(too_small_or_degenerate_gives_zero),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
