// Cropping points outside the boundary (Options::crop) and strict input checks
// (Options::strict), on the saddle of tests/support/fold_shapes with the boundary of its
// middle [0.2, 0.8]^2: a scan larger than its boundary. Cropped points have no (u,v) and
// every consumer (statistics, fold measure, validation, files) leaves them out; the other
// points keep exactly the (u,v) they get without cropping. Strict turns each gross mismatch
// into an error naming its numbers, and stays quiet on inputs that fit (the controls).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "distance_stats.hpp"
#include "error.hpp"
#include "fold_shapes.hpp"
#include "mesh_files.hpp"
#include "parameterize.hpp"
#include "point_cloud.hpp"
#include "result_io.hpp"
#include "validation_mesh.hpp"

#include "core_test_support.hpp"

namespace {

using dbs::Vec3;
using dbs_folds::FoldShape;

constexpr double kInner0 = 0.2, kInner1 = 0.8;  // the boundary's square in the saddle's (a,b)

std::vector<Vec3> points_of(const std::vector<double>& xyz, double scale = 1.0) {
  std::vector<Vec3> p;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) p.push_back(scale * Vec3(xyz[i], xyz[i + 1], xyz[i + 2]));
  return p;
}

/// The boundary of the square [a0, a1]^2 of a shape's (a,b), each side a straight line in
/// (a,b) mapped onto the surface (`straight`: a straight 3D line between the corners instead).
dbs::Boundary square_boundary(const FoldShape& s, double a0, double a1, bool straight = false, double scale = 1.0) {
  std::vector<Vec3> sides[4];
  auto at = [&](double a, double b) {
    const dbs_folds::Point3 p = s.surface(a, b);
    return Vec3(scale * p[0], scale * p[1], scale * p[2]);
  };
  const Vec3 c00 = at(a0, a0), c10 = at(a1, a0), c11 = at(a1, a1), c01 = at(a0, a1);
  for (int k = 0; k <= 50; ++k) {
    const double f = k / 50.0, t = a0 + (a1 - a0) * f;
    if (straight) {
      sides[0].push_back(c00 + f * (c10 - c00));
      sides[1].push_back(c10 + f * (c11 - c10));
      sides[2].push_back(c01 + f * (c11 - c01));
      sides[3].push_back(c00 + f * (c01 - c00));
    } else {
      sides[0].push_back(at(t, a0));
      sides[1].push_back(at(a1, t));
      sides[2].push_back(at(t, a1));
      sides[3].push_back(at(a0, t));
    }
  }
  return dbs::Boundary(sides[0], sides[1], sides[2], sides[3]);
}

struct Run {
  dbs::Result result;
  std::vector<std::string> warnings;
};

Run run(const std::vector<Vec3>& points, const dbs::Boundary& boundary, int crop, int strict, int repair = 1) {
  Run r;
  dbs::Options options;
  options.max_level = 1;
  options.crop = crop;
  options.strict = strict;
  options.repair = repair;
  options.warning = [&r](const char* message) { r.warnings.emplace_back(message); };
  r.result = dbs::parameterize(dbs::PointCloud(points), boundary, options);
  std::printf("crop %d strict %d repair %d: clamped %zu, cropped %zu, mean distance %.6g, judged %zu, %zu warning(s)\n", crop, strict, repair, r.result.clamped_points,
              r.result.cropped_points, r.result.mean_distance, r.result.judged_points, r.warnings.size());
  return r;
}

/// The message of the dbs::Error a run throws with `code`, or "" when it throws none.
std::string failure(const std::vector<Vec3>& points, const dbs::Boundary& boundary, int crop, int strict, dbs::ErrorCode code) {
  try {
    run(points, boundary, crop, strict);
  } catch (const dbs::Error& e) {
    std::printf("refused: %s\n", e.what());
    return e.code() == code ? e.what() : "wrong code: " + std::string(e.what());
  }
  return "";
}

/// How far outside [kInner0, kInner1]^2 the point sampled at (a,b) lies, in (a,b) units.
double outside_by(double a, double b) {
  const double da = std::max({kInner0 - a, a - kInner1, 0.0}), db = std::max({kInner0 - b, b - kInner1, 0.0});
  return std::max(da, db);
}

void cropped_points_lose_their_parameters_and_the_others_keep_theirs(void**) {
  const FoldShape s = dbs_folds::saddle();
  const std::vector<Vec3> points = points_of(s.xyz);
  const dbs::Boundary boundary = square_boundary(s, kInner0, kInner1);
  // Without the repair the other points' (u,v) are exactly those of the clamping run.
  const Run clamped = run(points, boundary, 0, 0, 0), cropped = run(points, boundary, 1, 0, 0);
  assert_true(clamped.result.clamped_points > s.count() / 3);
  assert_int_equal(cropped.result.cropped_points, clamped.result.clamped_points);
  assert_int_equal(cropped.result.clamped_points, clamped.result.clamped_points);
  const std::vector<std::int32_t> flags = cropped.result.point_flags();
  double sum = 0.0;
  std::size_t kept = 0, truly_inside_cropped = 0, far_outside_kept = 0;
  for (std::size_t i = 0; i < s.count(); ++i) {
    const double by = outside_by(s.uv_true[2 * i], s.uv_true[2 * i + 1]);
    if (cropped.result.is_cropped(i)) {
      assert_true(std::isnan(cropped.result.u[i]) && std::isnan(cropped.result.v[i]) && std::isnan(cropped.result.distance[i]));
      assert_int_equal(cropped.result.patch[i], -1);
      assert_int_equal(cropped.result.level[i], -1);
      assert_int_equal(flags[i], dbs::kPointCropped | dbs::kPointClamped);
      assert_true(clamped.result.clamped[i]);
      if (by == 0.0) ++truly_inside_cropped;
      continue;
    }
    assert_int_equal(flags[i], 0);
    assert_true(cropped.result.u[i] == clamped.result.u[i] && cropped.result.v[i] == clamped.result.v[i]);
    assert_true(cropped.result.distance[i] == clamped.result.distance[i]);
    assert_int_equal(cropped.result.patch[i], clamped.result.patch[i]);
    assert_int_equal(cropped.result.level[i], clamped.result.level[i]);
    if (by > 0.02) ++far_outside_kept;
    sum += cropped.result.distance[i];
    ++kept;
  }
  std::printf("%zu kept, %zu cropped though inside the boundary, %zu kept though 0.02 outside it\n", kept, truly_inside_cropped, far_outside_kept);
  // Cropped are points outside the boundary, and every point well outside it is cropped.
  assert_int_equal(truly_inside_cropped, 0);
  assert_int_equal(far_outside_kept, 0);
  assert_true(std::abs(cropped.result.mean_distance - sum / static_cast<double>(kept)) <= 1e-12 * cropped.result.mean_distance);
  // The fold measure judges the kept points only; no clamped-points warning.
  assert_int_equal(cropped.result.judged_points, kept);
  for (const std::string& w : cropped.warnings) assert_true(w.find("clamped") == std::string::npos);
  bool warned = false;
  for (const std::string& w : clamped.warnings) warned = warned || w.find("clamped onto the domain's edge") != std::string::npos;
  assert_true(warned);

  // Each leaf is judged on its kept points only (not on points it gives no (u,v)).
  std::vector<double> sum_of(cropped.result.patches.size(), 0.0), max_of(cropped.result.patches.size(), 0.0);
  std::vector<std::size_t> count_of(cropped.result.patches.size(), 0);
  for (std::size_t i = 0; i < s.count(); ++i) {
    if (cropped.result.is_cropped(i)) continue;
    const std::size_t id = static_cast<std::size_t>(cropped.result.patch[i]);
    sum_of[id] += cropped.result.distance[i];
    max_of[id] = std::max(max_of[id], cropped.result.distance[i]);
    ++count_of[id];
  }
  for (const dbs::Patch& leaf : cropped.result.patches) {
    if (!leaf.is_leaf()) continue;
    const std::size_t id = static_cast<std::size_t>(leaf.id);
    const double mean = count_of[id] ? sum_of[id] / static_cast<double>(count_of[id]) : 0.0;
    assert_true(std::abs(leaf.mean_distance - mean) <= 1e-12 * std::max(mean, 1e-300) && leaf.max_distance == max_of[id]);
  }

  // With the repair (the default) cropped points are neither repaired nor fitted: the kept
  // points' mean distance is that of points inside the boundary.
  const Run repaired = run(points, boundary, 1, 0, 1);
  assert_int_equal(repaired.result.cropped_points, cropped.result.cropped_points);
  for (std::size_t i = 0; i < s.count(); ++i) assert_true(repaired.result.is_cropped(i) == cropped.result.is_cropped(i));
  assert_true(repaired.result.mean_distance <= 1.01 * cropped.result.mean_distance);
}

void the_validation_and_the_files_leave_cropped_points_out(void**) {
  const FoldShape s = dbs_folds::saddle();
  const std::vector<Vec3> points = points_of(s.xyz);
  const dbs::PointCloud cloud(points);
  const Run r = run(points, square_boundary(s, kInner0, kInner1), 1, 0);
  const std::size_t kept = s.count() - r.result.cropped_points;
  assert_true(r.result.cropped_points > 0);
  // Distance statistics
  const dbs::DistanceReport d = dbs::distance_statistics(r.result, 0.0);
  assert_int_equal(d.overall.count, kept);
  // what the report's histogram draws: the kept points' distances only, all finite
  const std::vector<double> counted = r.result.counted_distances();
  assert_int_equal(counted.size(), kept);
  for (double x : counted) assert_true(std::isfinite(x));
  assert_true(std::abs(d.overall.mean - r.result.mean_distance) <= 1e-12 * r.result.mean_distance);
  // The Delaunay mesh: over the kept points only, in the cloud's vertex numbers.
  const dbs::ValidationMesh mesh = dbs::build_validation_mesh(r.result, cloud, 1);
  assert_true(mesh.triangles.size() > kept);  // about two per point
  for (const dbs::Triangle& t : mesh.triangles)
    for (std::int32_t vertex : t) assert_false(r.result.is_cropped(static_cast<std::size_t>(vertex)));
  // A caller's triangles with cropped vertices: left out and counted, the rest measured.
  std::vector<dbs::Triangle> theirs = mesh.triangles;
  std::size_t first_cropped = 0;
  while (!r.result.is_cropped(first_cropped)) ++first_cropped;
  theirs.insert(theirs.begin(), dbs::Triangle{static_cast<std::int32_t>(first_cropped), theirs[0][1], theirs[0][2]});
  theirs.push_back(dbs::Triangle{theirs[1][0], static_cast<std::int32_t>(first_cropped), theirs[1][2]});
  const dbs::Distortion whole = dbs::measure_result_distortion(r.result, cloud, mesh.triangles, dbs::DomainScaling::PerAxis, 1);
  const dbs::Distortion with_cropped = dbs::measure_result_distortion(r.result, cloud, theirs, dbs::DomainScaling::PerAxis, 1);
  assert_int_equal(with_cropped.summary.cropped, 2);
  assert_int_equal(with_cropped.summary.triangles, whole.summary.triangles);
  assert_int_equal(with_cropped.triangles.size(), theirs.size());
  assert_true(with_cropped.triangles.front().cropped && with_cropped.triangles.back().cropped);
  assert_false(with_cropped.triangles[1].cropped);
  assert_true(with_cropped.summary.conformal.p95 == whole.summary.conformal.p95);
  assert_int_equal(with_cropped.summary.folded, whole.summary.folded);

  // Files: a row per point (a cropped one with nan and -1), mesh vertices renumbered.
  const std::string csv = "test_crop_result.csv", ply = "test_crop_mesh.ply";
  dbs::save_result(r.result, cloud, csv);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::size_t rows = 0;
  while (std::getline(in, line)) {
    // every point has its row, in input order; a cropped one with nan and -1
    assert_int_equal(std::stoul(line.substr(0, line.find(','))), rows);
    const bool none = line.find(",nan,nan,nan,-1,-1") != std::string::npos;
    assert_true(none == r.result.is_cropped(rows));
    ++rows;
  }
  assert_int_equal(rows, s.count());
  dbs::write_ply_mesh(ply, points, r.result.u, r.result.v, mesh.triangles);
  std::ifstream mesh_in(ply, std::ios::binary);
  std::stringstream header;
  while (std::getline(mesh_in, line) && line != "end_header") header << line << '\n';
  assert_true(header.str().find("element vertex " + std::to_string(kept) + "\n") != std::string::npos);
  std::remove(csv.c_str());
  std::remove(ply.c_str());
}

void strict_turns_each_gross_mismatch_into_an_error(void**) {
  const FoldShape s = dbs_folds::saddle();
  const std::vector<Vec3> points = points_of(s.xyz);
  // Controls: fitting inputs pass, and a larger scan passes when its outside is cropped.
  assert_int_equal(run(points, square_boundary(s, 0.0, 1.0), 0, 1).warnings.size(), 0);
  const Run cropped = run(points, square_boundary(s, kInner0, kInner1), 1, 1);
  assert_true(cropped.result.cropped_points > 0);
  // A boundary in metres around a cloud in millimetres.
  std::string message = failure(points, square_boundary(s, 0.0, 1.0, false, 1000.0), 0, 1, dbs::ErrorCode::Degenerate);
  assert_true(message.find("strict input checks: the cloud is 0.000992 times the size of the boundary") != std::string::npos);
  // A scan larger than its boundary, not cropped.
  message = failure(points, square_boundary(s, kInner0, kInner1), 0, 1, dbs::ErrorCode::Degenerate);
  assert_true(message.find("strict input checks: ") == 0);
  assert_true(message.find("points lie outside the boundary by more than a point spacing and were clamped onto the domain's edge") != std::string::npos);
  // A cloud with a wide hole in its middle: its edges follow the boundary (no gap), but the
  // points cover under 3/4 of the domain.
  std::vector<Vec3> holed;
  for (std::size_t i = 0; i < s.count(); ++i)
    if (std::hypot(s.uv_true[2 * i] - 0.5, s.uv_true[2 * i + 1] - 0.5) > 0.45) holed.push_back(points[i]);
  message = failure(holed, square_boundary(s, 0.0, 1.0), 0, 1, dbs::ErrorCode::Degenerate);
  assert_true(message.find("strict input checks: the points cover ") == 0);
  assert_true(message.find("% of the domain [0,1]^2: the cloud covers only part of the boundary") != std::string::npos);
  // A cloud covering half of its boundary.
  std::vector<Vec3> half;
  for (std::size_t i = 0; i < s.count(); ++i)
    if (s.uv_true[2 * i] < 0.5) half.push_back(points[i]);
  message = failure(half, square_boundary(s, 0.0, 1.0), 0, 1, dbs::ErrorCode::Degenerate);
  assert_true(message.find("point spacings from the cloud") != std::string::npos);
}

void every_point_cropped_is_an_error(void**) {
  // A boundary on a far part of the saddle's surface: no point lies inside it.
  const FoldShape s = dbs_folds::saddle();
  std::vector<Vec3> corner;
  for (std::size_t i = 0; i < s.count(); ++i)
    if (s.uv_true[2 * i] < 0.3 && s.uv_true[2 * i + 1] < 0.3) corner.emplace_back(s.xyz[3 * i], s.xyz[3 * i + 1], s.xyz[3 * i + 2]);
  const std::string message = failure(corner, square_boundary(s, 0.6, 1.0), 1, 0, dbs::ErrorCode::Degenerate);
  assert_true(message.find("points lie outside the boundary") != std::string::npos);
  assert_true(message.find("were cropped") != std::string::npos);
}

void straight_lines_between_the_corners_of_a_curved_part_are_caught(void**) {
  // Four straight lines between the corners of a curved part (the 270-degree cap, whose
  // sides are arcs): they run through the air, which the boundary's gap reports, and
  // strict refuses.
  const FoldShape cap = dbs_folds::sphere_cap();
  const std::vector<Vec3> points = points_of(cap.xyz);
  const Run fitting = run(points, square_boundary(cap, 0.0, 1.0), 0, 0);
  assert_int_equal(fitting.warnings.size(), 0);
  const Run straight = run(points, square_boundary(cap, 0.0, 1.0, true), 0, 0);
  std::printf("gap: %.3g spacings with the true sides, %.3g with straight lines\n", fitting.result.boundary_gap, straight.result.boundary_gap);
  assert_true(fitting.result.boundary_gap < 1.6);
  assert_true(straight.result.boundary_gap > 5.0);
  const std::string warning = "point spacings from the cloud (90% of it within that): do its sides follow the edges of the scan, not straight lines between the corners of a curved part?";
  bool warned = false;
  for (const std::string& w : straight.warnings) warned = warned || w.find(warning) != std::string::npos;
  assert_true(warned);
  assert_true(failure(points, square_boundary(cap, 0.0, 1.0, true), 0, 1, dbs::ErrorCode::Degenerate).find(warning) != std::string::npos);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(cropped_points_lose_their_parameters_and_the_others_keep_theirs),
      cmocka_unit_test(the_validation_and_the_files_leave_cropped_points_out),
      cmocka_unit_test(strict_turns_each_gross_mismatch_into_an_error),
      cmocka_unit_test(every_point_cropped_is_an_error),
      cmocka_unit_test(straight_lines_between_the_corners_of_a_curved_part_are_caught),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
