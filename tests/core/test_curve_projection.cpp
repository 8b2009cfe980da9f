// Smooth polygonal-curve projection (A3, eqs. 6-9) and its densification (A3.1): a lifted
// polyline lands on a planar cloud, a flat one follows a sine-shaped cloud, a gap without
// points is bridged smoothly inside its neighbours' range, fixed nodes stay exactly put, and
// the offsets are invariant to scaling by 1000 plus a rigid motion; moments given for some
// nodes stand in for their rays.
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>

#include "cloud_index.hpp"
#include "curve_projection.hpp"
#include "error.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

// cmocka last (its fail() macro would hide dbs::fail), with C linkage (its header does
// not declare it).

using namespace dbs;

namespace {

using core_test::throws;

constexpr double kGamma = 0.5;

/// A jittered grid of pitch 1 over [0,80] x [0,20], z = f(x), without the points where
/// `keep` is false.
std::vector<Vec3> strip_cloud(const std::function<double(double)>& f, const std::function<bool(double)>& keep = [](double) { return true; }) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<Vec3> pts;
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 80; ++i) {
      const double x = i + jitter(rng), y = j + jitter(rng);
      if (keep(x)) pts.emplace_back(x, y, f(x));
    }
  return pts;
}

/// Nodes along y = 10 at x = 0, 1, ..., 80 with heights z(x), projected vertically.
CurveProjectionInput line_at(const std::function<double(double)>& z) {
  CurveProjectionInput in;
  for (int i = 0; i <= 80; ++i) {
    in.nodes.emplace_back(i, 10.0, z(i));
    in.directions.emplace_back(0.0, 0.0, 1.0);
  }
  return in;
}

std::vector<Vec3> projected(const CurveProjectionInput& in, const std::vector<double>& t) {
  std::vector<Vec3> out;
  for (std::size_t k = 0; k < t.size(); ++k) out.push_back(in.nodes[k] + t[k] * in.directions[k]);
  return out;
}

struct Cloud {
  std::vector<Vec3> points;
  CloudIndex index;
  DirectedProjector projector;
  explicit Cloud(std::vector<Vec3> pts) : points(std::move(pts)), index(points), projector(index, cloud_spacing(index)) {}
};

void lifted_polyline_lands_on_plane(void**) {
  const Cloud cloud(strip_cloud([](double) { return 0.0; }));
  const double h = cloud.projector.length_scale();
  // Ends on the plane (they stay fixed), every interior node 6 units above it.
  const CurveProjectionInput in = line_at([](double x) { return x == 0.0 || x == 80.0 ? 0.0 : 6.0; });
  const std::vector<Vec3> q = projected(in, project_curve(cloud.projector, in, kGamma));
  double worst = 0.0;
  for (const Vec3& p : q) worst = std::max(worst, std::abs(p.z()));
  assert_true(worst <= 1e-9 * h);
}

double wave(double x) { return 4.0 * std::sin(2.0 * M_PI * x / 40.0); }

void flat_polyline_follows_sine_cloud(void**) {
  const Cloud cloud(strip_cloud(wave));
  const CurveProjectionInput in = line_at([](double) { return 0.0; });
  const std::vector<Vec3> q = projected(in, project_curve(cloud.projector, in, kGamma));
  double worst = 0.0, sum = 0.0;
  for (const Vec3& p : q) {
    const double e = std::abs(p.z() - wave(p.x()));
    worst = std::max(worst, e);
    sum += e;
  }
  const double h = cloud.projector.length_scale();
  std::printf("sine cloud (amplitude %.2f h, wavelength %.1f h): projected curve off by %.3f h at most, %.3f h on average\n", 4.0 / h, 40.0 / h, worst / h, sum / q.size() / h);
  assert_true(worst <= 0.4 * h);
  assert_true(sum / q.size() <= 0.25 * h);
}

void balance_does_not_depend_on_node_spacing(void**) {
  const Cloud cloud(strip_cloud(wave));
  const double h = cloud.projector.length_scale();
  CurveProjectionInput coarse, fine;
  for (int i = 0; i <= 160; ++i) {
    const Vec3 node(0.5 * i, 10.0, 0.0);
    fine.nodes.push_back(node);
    fine.directions.emplace_back(0.0, 0.0, 1.0);
    if (i % 4 == 0) {
      coarse.nodes.push_back(node);
      coarse.directions.emplace_back(0.0, 0.0, 1.0);
    }
  }
  // Nodes 0.6 h and 2.5 h apart: the same curve where they coincide.
  const std::vector<double> t_fine = project_curve(cloud.projector, fine, kGamma);
  const std::vector<double> t_coarse = project_curve(cloud.projector, coarse, kGamma);
  double worst = 0.0;
  for (std::size_t k = 0; k < t_coarse.size(); ++k) worst = std::max(worst, std::abs(t_coarse[k] - t_fine[4 * k]));
  std::printf("node spacing 0.6 h vs 2.5 h: projected curves differ by %.3f h at most\n", worst / h);
  assert_true(worst <= 0.1 * h);
}

double ramp(double x) { return 3.0 * std::tanh((x - 40.0) / 10.0); }

void gap_is_bridged_smoothly(void**) {
  // No points with 32 < x < 48: 16 units (about 19 h) of the ramp are missing.
  const Cloud cloud(strip_cloud(ramp, [](double x) { return x < 32.0 || x > 48.0; }));
  const double h = cloud.projector.length_scale();
  const CurveProjectionInput in = line_at([](double x) { return ramp(0.0) + (ramp(80.0) - ramp(0.0)) * x / 80.0; });
  const std::vector<Vec3> q = projected(in, project_curve(cloud.projector, in, kGamma));
  for (const Vec3& p : q) assert_true(is_finite(p));
  // Outside the gap the curve is on the cloud.
  for (const Vec3& p : q)
    if (p.x() <= 28.0 || p.x() >= 52.0) assert_true(std::abs(p.z() - ramp(p.x())) <= 0.3 * h);
  // Across the gap: inside the range of the landed neighbours, rising, and smooth.
  const double low = q[32].z(), high = q[48].z();
  double worst_bend = 0.0;
  for (int i = 33; i < 48; ++i) {
    assert_true(q[i].z() >= low && q[i].z() <= high);
    assert_true(q[i].z() > q[i - 1].z());
    worst_bend = std::max(worst_bend, std::abs(q[i - 1].z() - 2.0 * q[i].z() + q[i + 1].z()));
  }
  std::printf("gap of %.1f h: bridged within [%.3f, %.3f], largest second difference %.3f h\n", 16.0 / h, low, high, worst_bend / h);
  assert_true(worst_bend <= 0.1 * h);
}

void fixed_nodes_stay_put(void**) {
  const Cloud cloud(strip_cloud(wave));
  CurveProjectionInput in = line_at([](double) { return 0.0; });
  in.nodes[25].z() = 1.5;  // off the cloud on purpose
  in.fixed = {25, 60};
  const std::vector<double> t = project_curve(cloud.projector, in, kGamma);
  assert_true(t[25] == 0.0 && t[60] == 0.0 && t.front() == 0.0 && t.back() == 0.0);
  for (double v : t) assert_true(std::isfinite(v));
  // The free nodes still follow the cloud away from the pinned one.
  assert_true(std::abs(in.nodes[10].z() + t[10] - wave(10.0)) <= 0.35 * cloud.projector.length_scale());
}

void offsets_are_invariant_to_scale_and_rigid_motion(void**) {
  const std::vector<Vec3> pts = strip_cloud(wave);
  const CurveProjectionInput in = line_at([](double) { return 0.0; });
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(-1.1, Vec3(2, -1, 1).normalized()).toRotationMatrix();
  auto move = [&](const Vec3& p) { return Vec3(1000.0 * (rotation * p + Vec3(-20, 7, 300))); };
  std::vector<Vec3> moved_pts;
  for (const Vec3& p : pts) moved_pts.push_back(move(p));
  CurveProjectionInput moved_in;
  for (std::size_t k = 0; k < in.nodes.size(); ++k) {
    moved_in.nodes.push_back(move(in.nodes[k]));
    moved_in.directions.push_back(rotation * in.directions[k]);
  }
  const Cloud cloud(pts), moved(moved_pts);
  const std::vector<double> t = project_curve(cloud.projector, in, kGamma);
  const std::vector<double> t_moved = project_curve(moved.projector, moved_in, kGamma);
  const double h = cloud.projector.length_scale();
  for (std::size_t k = 0; k < t.size(); ++k) assert_true(std::abs(t_moved[k] / 1000.0 - t[k]) <= 1e-9 * h);
}

void pure_smoothing_keeps_a_straight_line(void**) {
  const Cloud cloud(strip_cloud(wave));
  const CurveProjectionInput in = line_at([](double) { return 0.0; });
  for (double v : project_curve(cloud.projector, in, 1.0)) assert_true(std::abs(v) <= 1e-12);
}

void densify_keeps_every_point_and_spacing(void**) {
  const std::vector<Vec3> pts = {{0, 0, 0}, {1, 0, 0}, {1, 2.5, 0}, {1.2, 2.5, 0}};
  const std::vector<Vec3> dirs = {{0, 0, 1}, {0, 0, 2}, {1, 0, 0}, {0, 0, 1}};
  std::vector<std::size_t> original;
  const CurveProjectionInput out = densify_polygon(pts, dirs, 0.5, original);
  // round(1/0.5) = 2, round(2.5/0.5) = 5, round(0.2/0.5) = 0 -> 1 sub-segments.
  assert_int_equal(out.nodes.size(), 9);
  assert_true((original == std::vector<std::size_t>{0, 2, 7, 8}));
  for (std::size_t i = 0; i < pts.size(); ++i) assert_true(out.nodes[original[i]] == pts[i]);
  for (const Vec3& d : out.directions) assert_true(std::abs(d.norm() - 1.0) <= 1e-15);
  for (std::size_t k = 2; k < 7; ++k) assert_true(std::abs((out.nodes[k + 1] - out.nodes[k]).norm() - 0.5) <= 1e-15);
  // Halfway between (0,0,1) and (1,0,0): their normalized mean.
  assert_true((out.directions[2 + 2] - Vec3(0.4, 0, 0.6).normalized()).norm() <= 1e-15);
  assert_true(out.fixed.empty());

  // A per-segment cap: 10 units at spacing 0.01 would need 1000 sub-segments.
  const CurveProjectionInput capped = densify_polygon({{0, 0, 0}, {10, 0, 0}}, {{0, 0, 1}, {0, 0, 1}}, 0.01, original, 16);
  assert_int_equal(capped.nodes.size(), 17);
}

/// Moments given for some nodes (as a grid's row and column share those of the points where
/// they cross) stand in for the rays there: the same moments give the same offsets bit for
/// bit, different ones move the node.
void known_moments_stand_in_for_the_rays(void**) {
  const Cloud cloud(strip_cloud(wave));
  const CurveProjectionInput in = line_at([](double) { return 0.0; });
  const std::vector<double> plain = project_curve(cloud.projector, in, kGamma);
  std::vector<RayMoments> moments(in.nodes.size());
  for (std::size_t k = 0; k < moments.size(); ++k) moments[k] = cloud.projector.moments(in.nodes[k], in.directions[k]);
  CurveProjectionInput given = in;
  given.known_moments.assign(in.nodes.size(), nullptr);
  for (std::size_t k = 0; k < moments.size(); k += 3) given.known_moments[k] = &moments[k];
  assert_true(project_curve(cloud.projector, given, kGamma) == plain);
  for (std::size_t k = 0; k < moments.size(); ++k) given.known_moments[k] = &moments[k];
  assert_true(project_curve(cloud.projector, given, kGamma) == plain);
  // Node 40's moments with the weighted mean 3 units higher: the node follows them up.
  RayMoments raised = moments[40];
  raised.mean.z() += 3.0;
  given.known_moments[40] = &raised;
  const std::vector<double> moved = project_curve(cloud.projector, given, kGamma);
  assert_true(moved[40] > plain[40] + 0.5);
  given.known_moments.pop_back();
  core_test::expect_error([&] { project_curve(cloud.projector, given, kGamma); }, ErrorCode::InvalidArgument, {"80 known moments", "81 nodes"});
}

void bad_input_is_rejected(void**) {
  const Cloud cloud(strip_cloud([](double) { return 0.0; }, [](double x) { return x < 40.0; }));
  CurveProjectionInput in = line_at([](double) { return 0.0; });
  assert_true(throws(ErrorCode::OutOfRange, [&] { project_curve(cloud.projector, in, 1.5); }));
  CurveProjectionInput bad = in;
  bad.fixed = {81};
  assert_true(throws(ErrorCode::OutOfRange, [&] { project_curve(cloud.projector, bad, kGamma); }));
  bad = in;
  bad.directions.pop_back();
  assert_true(throws(ErrorCode::InvalidArgument, [&] { project_curve(cloud.projector, bad, kGamma); }));
  bad.nodes.resize(1);
  bad.directions.resize(1);
  assert_true(throws(ErrorCode::InvalidArgument, [&] { project_curve(cloud.projector, bad, kGamma); }));
  // Without smoothing, a node far beyond the cloud (x > 40 has no points) has nothing to hold it.
  in.nodes[70].z() = 500.0;
  assert_true(throws(ErrorCode::Numerical, [&] { project_curve(cloud.projector, in, 0.0); }));

  std::vector<std::size_t> original;
  assert_true(throws(ErrorCode::InvalidArgument, [&] { densify_polygon({{0, 0, 0}}, {{0, 0, 1}}, 1.0, original); }));
  assert_true(throws(ErrorCode::InvalidArgument, [&] { densify_polygon({{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 0, 1}}, 0.0, original); }));
  assert_true(throws(ErrorCode::Degenerate, [&] { densify_polygon({{0, 0, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, 0, 0}}, 1.0, original); }));
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(lifted_polyline_lands_on_plane),
      cmocka_unit_test(flat_polyline_follows_sine_cloud),
      cmocka_unit_test(balance_does_not_depend_on_node_spacing),
      cmocka_unit_test(gap_is_bridged_smoothly),
      cmocka_unit_test(fixed_nodes_stay_put),
      cmocka_unit_test(offsets_are_invariant_to_scale_and_rigid_motion),
      cmocka_unit_test(pure_smoothing_keeps_a_straight_line),
      cmocka_unit_test(densify_keeps_every_point_and_spacing),
      cmocka_unit_test(known_moments_stand_in_for_the_rays),
      cmocka_unit_test(bad_input_is_rejected),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
