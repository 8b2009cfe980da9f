// The input checks (lib/method/input_checks): each mistake a run would otherwise finish with
// exit 0 is named by a warning with its numbers, on the saddle of tests/support/fold_shapes
// (a single patch, fast): a boundary in other units than the cloud, a cloud covering half of
// its boundary, a scan larger than its boundary, a boundary far from its cloud. The controls
// (the hard shapes, which must not warn) are every run of test_fold_free.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "delaunay_mesh.hpp"
#include "distance_stats.hpp"
#include "distortion.hpp"
#include "error.hpp"
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

Checked run(const std::vector<Vec3>& points, const dbs::Boundary& boundary, int max_level = 1) {
  Checked c;
  dbs::Options options;
  options.max_level = max_level;
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

void points_far_outside_decide_nothing(void**) {
  // The saddle with glitches 1e9, 1e160 and 1e300 away (finite, the last near the largest
  // doubles): left out of the target, the spacing and the surfaces, so every other point gets
  // the (u,v) of the clean run; each takes the (u,v) of its nearest point and a finite
  // distance; the statistics are those of the clean run; a warning names them.
  const FoldShape s = dbs_folds::saddle();
  const std::vector<Vec3> clean = points_of(s.xyz);
  std::vector<Vec3> glitched = clean;
  glitched.insert(glitched.begin() + 100, Vec3(1e9, 0.0, 0.0));
  glitched.push_back(Vec3(-3e160, 2e160, 1e160));
  glitched.push_back(Vec3(1e300, -1e300, 1e300));
  const Checked a = run(clean, boundary_of(s)), b = run(glitched, boundary_of(s));
  assert_int_equal(b.result.far_points, 3);
  assert_int_equal(a.result.far_points, 0);
  assert_true(b.result.requested_accuracy == a.result.requested_accuracy);
  assert_true(b.result.length_scale == a.result.length_scale);
  assert_true(b.result.mean_distance == a.result.mean_distance && b.result.max_distance == a.result.max_distance);
  assert_int_equal(b.result.clamped_points, a.result.clamped_points);
  // The validation's distance statistics leave them out too.
  const dbs::DistanceReport da = dbs::distance_statistics(a.result, 0.0), db = dbs::distance_statistics(b.result, 0.0);
  assert_int_equal(db.overall.count, da.overall.count);
  assert_true(db.overall.mean == da.overall.mean && db.overall.max == da.overall.max && db.overall.p99 == da.overall.p99);
  assert_true(b.result.coverage == a.result.coverage);
  assert_true(has(b.warnings, "3 point(s) lie far outside the cloud (beyond 10 times its extent"));
  for (std::size_t i = 0, k = 0; i < glitched.size(); ++i) {
    assert_true(std::isfinite(b.result.distance[i]) && std::isfinite(b.result.u[i]) && std::isfinite(b.result.v[i]));
    assert_true(b.result.patch[i] >= 0 && static_cast<std::size_t>(b.result.patch[i]) < b.result.patches.size());
    if (b.result.outside_body[i]) {
      assert_true(b.result.distance[i] > 1e8);
      continue;
    }
    assert_true(b.result.u[i] == a.result.u[k] && b.result.v[i] == a.result.v[k] && b.result.distance[i] == a.result.distance[k]);
    ++k;
  }
  // The 1e9 point lies along +x of the saddle: it takes the (u,v) of a point at the
  // boundary's u = 1 side.
  assert_true(b.result.u[100] > 0.95);
}

void far_points_through_a_refit(void**) {
  // Where the repair refits leaves (the mushroom, whose surfaces miss the underside of its
  // cap), a glitch is no data of the fit and keeps a finite distance; every leaf's figures
  // are those of the clean run.
  const FoldShape m = dbs_folds::mushroom();
  std::vector<Vec3> mushroom = points_of(m.xyz);
  const Checked plain = run(mushroom, boundary_of(m), dbs::Options().max_level);
  mushroom.push_back(Vec3(1e160, 1e160, 1e160));
  const Checked glitch = run(mushroom, boundary_of(m), dbs::Options().max_level);
  assert_true(plain.result.repaired_points > 0);
  assert_int_equal(glitch.result.repaired_points, plain.result.repaired_points);
  assert_true(glitch.result.mean_distance == plain.result.mean_distance);
  assert_true(glitch.result.accuracy_met == plain.result.accuracy_met);
  for (std::size_t p = 0; p < plain.result.patches.size(); ++p) assert_true(glitch.result.patches[p].mean_distance == plain.result.patches[p].mean_distance);
  assert_true(std::isfinite(glitch.result.distance.back()) && glitch.result.distance.back() > 1e159);
}

void supported_magnitudes_work_and_others_are_refused(void**) {
  // Sizes from 1e-100 to 1e75 work, the distortion of their Delaunay mesh included; beyond
  // that range the run says so instead of failing with a geometry message.
  const FoldShape s = dbs_folds::saddle();
  const Checked unit = run(points_of(s.xyz), boundary_of(s));
  const dbs::Distortion unit_distortion =
      dbs::measure_distortion(points_of(s.xyz), unit.result.u, unit.result.v, dbs::delaunay_triangulate(unit.result.u, unit.result.v), dbs::DomainScaling::PerAxis, {});
  for (double scale : {1e-100 / s.diagonal, 1e73 / s.diagonal}) {
    const Checked c = run(points_of(s.xyz, scale), boundary_of(s, scale));
    double worst = 0.0;
    for (std::size_t i = 0; i < s.count(); ++i) worst = std::max({worst, std::abs(c.result.u[i] - unit.result.u[i]), std::abs(c.result.v[i] - unit.result.v[i])});
    std::printf("size %.3g: (u,v) within %.3g of the unit run's, %zu folded\n", scale * s.diagonal, worst, c.result.folded_points);
    assert_true(worst < 1e-4);
    // The fold measure judges them as at unit size (its power-of-two scaling).
    assert_int_equal(c.result.judged_points, unit.result.judged_points);
    assert_int_equal(c.result.folded_points, unit.result.folded_points);
    assert_int_equal(c.result.undecided_points, unit.result.undecided_points);
    assert_true(c.warnings.empty());
    const std::vector<Vec3> points = points_of(s.xyz, scale);
    const std::vector<dbs::Triangle> triangles = dbs::delaunay_triangulate(c.result.u, c.result.v);
    const dbs::Distortion d = dbs::measure_distortion(points, c.result.u, c.result.v, triangles, dbs::DomainScaling::PerAxis, {});
    assert_int_equal(d.summary.degenerate, 0);
    assert_int_equal(d.summary.folded, unit_distortion.summary.folded);
    assert_true(std::abs(d.summary.conformal.p95 - unit_distortion.summary.conformal.p95) < 1e-3);
    assert_true(std::abs(d.summary.scale_u / (scale * unit_distortion.summary.scale_u) - 1.0) < 1e-3);
  }
  for (double scale : {1e-110, 1e80}) {
    bool refused = false;
    try {
      run(points_of(s.xyz, scale), boundary_of(s, scale));
    } catch (const dbs::Error& e) {
      refused = e.code() == dbs::ErrorCode::OutOfRange && std::string(e.what()).find("is outside the supported range [1e-100, 1e+75]: scale the input") != std::string::npos;
    }
    assert_true(refused);
  }
}

}  // namespace

int main(int argc, char** argv) {
  // "--quick": without the mushroom's whole runs, for the sanitizer build.
  const bool quick = argc > 1 && std::string(argv[1]) == "--quick";
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(fitting_inputs_say_nothing),
      cmocka_unit_test(boundary_in_other_units),
      cmocka_unit_test(cloud_covering_half_its_boundary),
      cmocka_unit_test(scan_larger_than_its_boundary),
      cmocka_unit_test(boundary_far_from_its_cloud),
      cmocka_unit_test(points_far_outside_decide_nothing),
      cmocka_unit_test(supported_magnitudes_work_and_others_are_refused),
  };
  const struct CMUnitTest slow[] = {
      cmocka_unit_test(far_points_through_a_refit),
  };
  int failed = cmocka_run_group_tests_name("input_checks", tests, nullptr, nullptr);
  if (!quick) failed += cmocka_run_group_tests_name("input_checks_repair", slow, nullptr, nullptr);
  return failed;
}
