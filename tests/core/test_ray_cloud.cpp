// The sample a dense patch's rays see (ray_cloud.hpp): a small subcloud is taken whole, a
// large one is sampled to about the bound, evenly over the surface whatever the points'
// order, with the length scale of the sample; a run whose patches are sampled meets the
// same target about as closely, and stays invariant to the thread count, the scale and a
// rigid motion.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>

#include "analytic_clouds.hpp"
#include "parameterize.hpp"
#include "ray_cloud.hpp"

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

PointList all_points(std::size_t n) {
  PointList list(n);
  std::iota(list.begin(), list.end(), 0u);
  return list;
}

void a_small_subcloud_is_taken_whole(void**) {
  const RayCloud whole = ray_cloud(all_points(kMaxRayPoints), 0.25);
  assert_false(whole.sampled());
  assert_true(whole.length_scale == 0.25);
  const RayCloud empty = ray_cloud(PointList(), 0.25);
  assert_false(empty.sampled());
}

void a_large_subcloud_is_sampled_evenly(void**) {
  // Points of a 1000 x 1000 grid in row order, as a scan delivers them: index i is the point
  // (i mod 1000, i / 1000). A sample taken by stride would fall into columns; this one must
  // hold the expected share of every 100 x 100 block.
  const std::size_t side = 1000, n = side * side, bound = 32768;
  const RayCloud sample = ray_cloud(all_points(n), 1.0, bound);
  assert_true(sample.sampled());
  const double m = static_cast<double>(sample.points.size());
  print_message("%zu of %zu points kept for a bound of %zu\n", sample.points.size(), n, bound);
  assert_true(std::abs(m - bound) < 0.03 * bound);
  assert_true(std::abs(sample.length_scale - std::sqrt(n / m)) < 1e-12 * sample.length_scale);
  assert_true(std::is_sorted(sample.points.begin(), sample.points.end()));
  assert_true(std::adjacent_find(sample.points.begin(), sample.points.end()) == sample.points.end());
  std::vector<int> blocks(100, 0), columns(side, 0);
  for (std::uint32_t i : sample.points) {
    ++blocks[(i / side / 100) * 10 + (i % side) / 100];
    ++columns[i % side];
  }
  const double per_block = m / 100.0;
  const auto [fewest, most] = std::minmax_element(blocks.begin(), blocks.end());
  print_message("per 100 x 100 block: %d to %d points (expected %.0f)\n", *fewest, *most, per_block);
  assert_true(*fewest > 0.75 * per_block && *most < 1.25 * per_block);
  // Every column of the grid is visited (a stride of 1000 / k would leave most empty).
  assert_true(std::count(columns.begin(), columns.end(), 0) == 0);
}

void the_sample_does_not_depend_on_the_order(void**) {
  const std::size_t n = 400000, bound = 20000;
  PointList shuffled = all_points(n);
  std::mt19937 rng(5);
  std::shuffle(shuffled.begin(), shuffled.end(), rng);
  const RayCloud in_order = ray_cloud(all_points(n), 2.0, bound);
  RayCloud reordered = ray_cloud(shuffled, 2.0, bound);
  assert_true(reordered.length_scale == in_order.length_scale);
  std::sort(reordered.points.begin(), reordered.points.end());
  assert_true(reordered.points == in_order.points);
  // A subcloud (the even points) is sampled from its own points only.
  PointList even;
  for (std::uint32_t i = 0; i < n; i += 2) even.push_back(i);
  const RayCloud of_even = ray_cloud(even, 2.0, bound);
  assert_true(of_even.sampled());
  for (std::uint32_t i : of_even.points) assert_int_equal(i % 2, 0);
  assert_true(std::abs(static_cast<double>(of_even.points.size()) - bound) < 0.05 * bound);
}

Options sampled(std::size_t max_ray_points, int threads = 2) {
  Options o;
  o.relative_accuracy = 5e-4;
  o.max_level = 3;
  o.threads = threads;
  o.max_ray_points = max_ray_points;
  return o;
}

void sampled_rays_fit_as_closely_and_stay_invariant(void**) {
  // 12,000 points: with a bound of 2,000 the root and its children are evolved against
  // samples (about 6 and 1.5 times sparser), the deeper patches against all their points.
  const Surface s = rippled_bumpy_field();
  const PointCloud cloud(random_points(s, 12000, 23));
  const Boundary boundary = boundary_of(s, 40);
  const Result whole = parameterize(cloud, boundary, sampled(kMaxRayPoints));
  const Result a = parameterize(cloud, boundary, sampled(2000));
  print_message("levels %d / %d, patches %zu / %zu, mean distance %.3g / %.3g (target %.3g), max %.3g / %.3g\n", whole.levels, a.levels, whole.patches.size(), a.patches.size(),
                whole.mean_distance, a.mean_distance, a.accuracy, whole.max_distance, a.max_distance);
  assert_true(whole.levels >= 2);
  assert_int_equal(a.levels, whole.levels);
  // The bound acted (a run that ignored it would equal the whole one) ...
  assert_true(a.u != whole.u);
  // ... and the sampled surfaces meet the same target.
  assert_true(a.mean_distance <= a.accuracy);
  assert_true(a.mean_distance < 1.25 * whole.mean_distance);
  // The largest distance is one point's, at the narrow bump: 1.63 times when this was written.
  assert_true(a.max_distance < 2.0 * whole.max_distance);
  // The sample is made of point indices alone: the thread count changes nothing.
  const Result one = parameterize(cloud, boundary, sampled(2000, 1));
  assert_memory_equal(one.u.data(), a.u.data(), a.u.size() * sizeof(double));
  assert_memory_equal(one.v.data(), a.v.data(), a.v.size() * sizeof(double));
  assert_memory_equal(one.distance.data(), a.distance.data(), a.distance.size() * sizeof(double));
  // Nor do the cloud's units and position: the sample's length scale scales with the cloud.
  const Surface moved = [&](double x, double y) { return move_and_scale(s(x, y), 1000.0); };
  const Result b = parameterize(PointCloud(random_points(moved, 12000, 23)), boundary_of(moved, 40), sampled(2000));
  assert_int_equal(a.patches.size(), b.patches.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.u.size(); ++i) worst = std::max({worst, std::abs(a.u[i] - b.u[i]), std::abs(a.v[i] - b.v[i])});
  print_message("scaled and moved: (u,v) differ by %.2g\n", worst);
  assert_true(worst < 1e-9);
}

}  // namespace

int main(void) {
  const struct CMUnitTest all[] = {
      cmocka_unit_test(a_small_subcloud_is_taken_whole),
      cmocka_unit_test(a_large_subcloud_is_sampled_evenly),
      cmocka_unit_test(the_sample_does_not_depend_on_the_order),
      cmocka_unit_test(sampled_rays_fit_as_closely_and_stay_invariant),
  };
  return cmocka_run_group_tests(all, nullptr, nullptr);
}
