// The input checks (lib/method/input_checks): each mistake a run would otherwise finish with
// exit 0 is named by a warning with its numbers, on the saddle of tests/support/fold_shapes
// (a single patch, fast): a boundary in other units than the cloud, a cloud covering half of
// its boundary, a scan larger than its boundary, a boundary far from its cloud. The controls
// (the hard shapes, which must not warn) are every run of test_fold_free.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "fold_shapes.hpp"
#include "input_checks.hpp"
#include "number_text.hpp"
#include "parameterize.hpp"
#include "point_cloud.hpp"

#include "core_test_support.hpp"

namespace {

using dbs::Vec3;
using dbs_folds::FoldShape;

struct Checked {
  dbs::Result result;
  std::vector<std::string> warnings;
};

std::vector<Vec3> points_of(const std::vector<double>& xyz, double scale = 1.0, Vec3 shift = Vec3::Zero()) {
  std::vector<Vec3> p;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) p.push_back(scale * Vec3(xyz[i], xyz[i + 1], xyz[i + 2]) + shift);
  return p;
}

Checked run(const std::vector<Vec3>& points, const dbs::Boundary& boundary) {
  Checked c;
  dbs::Options options;
  options.max_level = 1;
  options.warning = [&c](const char* message) { c.warnings.emplace_back(message); };
  c.result = dbs::parameterize(dbs::PointCloud(points), boundary, options);
  std::printf("gap %.3g spacings, size ratio %.4g, coverage %.3f, clamped %zu; %zu warning(s)\n", c.result.boundary_gap, c.result.scale_ratio, c.result.coverage, c.result.clamped_points, c.warnings.size());
  for (const std::string& w : c.warnings) std::printf("  %s\n", w.c_str());
  return c;
}

dbs::Boundary boundary_of(const FoldShape& s, double scale = 1.0, Vec3 shift = Vec3::Zero()) {
  return dbs::Boundary(points_of(s.bottom, scale, shift), points_of(s.right, scale, shift), points_of(s.top, scale, shift), points_of(s.left, scale, shift));
}

bool has(const std::vector<std::string>& warnings, const std::string& needle) {
  for (const std::string& w : warnings)
    if (w.find(needle) != std::string::npos) return true;
  return false;
}

void fitting_inputs_say_nothing(void**) {
  const FoldShape s = dbs_folds::saddle();
  const Checked c = run(points_of(s.xyz), boundary_of(s));
  assert_true(c.warnings.empty());
  assert_true(c.result.boundary_gap < 2.0);
  assert_true(std::abs(c.result.scale_ratio - 1.0) < 0.02);
  assert_true(c.result.coverage == 1.0);
  assert_int_equal(c.result.clamped_points, 0);
}

void boundary_in_other_units(void**) {
  // The boundary in metres around a cloud in millimetres: 1000 times larger.
  const FoldShape s = dbs_folds::saddle();
  const Checked c = run(points_of(s.xyz), boundary_of(s, 1000.0));
  assert_true(std::abs(c.result.scale_ratio * 1000.0 - 1.0) < 0.02);
  assert_true(has(c.warnings, "the cloud is " + dbs::significant_text(c.result.scale_ratio, 3) + " times the size of the boundary (bounding-box diagonals): are they in the same units?"));
  assert_true(has(c.warnings, "point spacings from the cloud"));
}

void cloud_covering_half_its_boundary(void**) {
  // Only the points of a < 1/2: the boundary's right half runs through the air and the
  // points' (u,v) leave much of the domain empty.
  const FoldShape s = dbs_folds::saddle();
  std::vector<Vec3> half;
  for (std::size_t i = 0; i < s.count(); ++i)
    if (s.uv_true[2 * i] < 0.5) half.emplace_back(s.xyz[3 * i], s.xyz[3 * i + 1], s.xyz[3 * i + 2]);
  const Checked c = run(half, boundary_of(s));
  assert_true(c.result.coverage < 0.75);
  assert_true(has(c.warnings, "of the domain [0,1]^2: the cloud covers only part of the boundary"));
  assert_true(c.result.boundary_gap > dbs::input::kMaxGap);
  assert_true(has(c.warnings, "point spacings from the cloud (90% of it within that): does it belong to this cloud?"));
}

void scan_larger_than_its_boundary(void**) {
  // The boundary of the middle [0.2, 0.8]^2 of the saddle around all of it: 64% of the points
  // lie outside and are clamped onto the domain's edge.
  const FoldShape s = dbs_folds::saddle();
  std::vector<Vec3> sides[4];
  for (int k = 0; k <= 50; ++k) {
    const double t = 0.2 + 0.6 * k / 50.0;
    const dbs_folds::Point3 b = s.surface(t, 0.2), r = s.surface(0.8, t), top = s.surface(t, 0.8), l = s.surface(0.2, t);
    sides[0].emplace_back(b[0], b[1], b[2]);
    sides[1].emplace_back(r[0], r[1], r[2]);
    sides[2].emplace_back(top[0], top[1], top[2]);
    sides[3].emplace_back(l[0], l[1], l[2]);
  }
  const Checked c = run(points_of(s.xyz), dbs::Boundary(sides[0], sides[1], sides[2], sides[3]));
  assert_true(c.result.clamped_points > s.count() / 3);
  assert_true(has(c.warnings, " of " + std::to_string(s.count()) + " points lie outside the boundary by more than a point spacing and were clamped onto the domain's edge: is the scan larger than its boundary?"));
}

void boundary_far_from_its_cloud(void**) {
  // The right boundary, moved 10 diagonals away: the same size, nowhere near the points.
  const FoldShape s = dbs_folds::saddle();
  const Checked c = run(points_of(s.xyz), boundary_of(s, 1.0, Vec3(10.0 * s.diagonal, 0.0, 0.0)));
  assert_true(std::abs(c.result.scale_ratio - 1.0) < 0.02);
  assert_true(c.result.boundary_gap > 100.0);
  assert_true(has(c.warnings, "does it belong to this cloud?"));
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(fitting_inputs_say_nothing),
      cmocka_unit_test(boundary_in_other_units),
      cmocka_unit_test(cloud_covering_half_its_boundary),
      cmocka_unit_test(scan_larger_than_its_boundary),
      cmocka_unit_test(boundary_far_from_its_cloud),
  };
  return cmocka_run_group_tests_name("input_checks", tests, nullptr, nullptr);
}
