// Directed projection (eqs. 1-5): the k-d tree neighbourhood sums agree with the sums over
// the whole cloud within the bound that kNeglectedWeight implies, a ray lands on a planar
// cloud, and the projection is invariant to scaling the input by 1000 plus a rigid motion.
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "cloud_index.hpp"
#include "directed_projection.hpp"
#include "error.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

// cmocka last (its fail() macro would hide dbs::fail), with C linkage (its header does
// not declare it).

using namespace dbs;

namespace {

using core_test::throws;

constexpr double kW = DirectedProjector::kNeglectedWeight;

std::vector<Vec3> plane_grid(int n, double pitch) {
  std::vector<Vec3> pts;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) pts.emplace_back(i * pitch, j * pitch, 0.0);
  return pts;
}

double bump(double x, double y) { return 0.15 * std::sin(3.0 * x) * std::cos(2.0 * y); }

/// Random points on the surface z = bump(x,y) over [0,1]^2, thickened by `noise`.
std::vector<Vec3> bump_cloud(std::size_t n, double noise, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-1.0, 1.0);
  std::vector<Vec3> pts;
  for (std::size_t i = 0; i < n; ++i) {
    const double x = unit(rng), y = unit(rng);
    pts.emplace_back(x, y, bump(x, y) + noise * jitter(rng));
  }
  return pts;
}

struct Worst {
  double c0 = 0.0, mean = 0.0, t = 0.0;  // relative error of c0; errors of the mean and of t in h
};

/// Compares moments() with moments_exact() for one ray and asserts the bounds of the header:
/// every omitted point weighs < w, so |c0 - c0_exact| <= w * omitted and the first moments
/// about p differ by at most w * sum |p_mu - p| over the points lighter than w.
void check_ray(const DirectedProjector& pr, const Vec3& p, const Vec3& n, Worst& worst) {
  const RayMoments near = pr.moments(p, n), exact = pr.moments_exact(p, n);
  const std::vector<Vec3>& pts = pr.index().points();
  const double h = pr.length_scale();
  const Vec3 u = n.normalized();
  double light_distance_sum = 0.0;
  for (std::size_t k = 0; k < pr.index().size(); ++k) {
    const Vec3 d = pts[pr.index().point_index(k)] - p;
    const Vec3 dh = d / h;
    const double a = 1.0 / (1.0 + dh.squaredNorm() * dh.cross(u).squaredNorm());
    if (a < kW * (1 + 1e-9)) light_distance_sum += d.norm();
  }
  const std::size_t omitted = pr.index().size() - near.points_used;
  assert_int_equal(exact.points_used, pr.index().size());
  assert_true(near.c0 <= exact.c0 * (1 + 1e-12));
  assert_true(exact.c0 - near.c0 <= kW * omitted + 1e-12 * exact.c0);
  const Vec3 first_near = near.c0 * (near.mean - p), first_exact = exact.c0 * (exact.mean - p);
  assert_true((first_near - first_exact).norm() <= kW * light_distance_sum * (1 + 1e-9));
  worst.c0 = std::max(worst.c0, (exact.c0 - near.c0) / exact.c0);
  worst.mean = std::max(worst.mean, (near.mean - exact.mean).norm() / h);
  worst.t = std::max(worst.t, std::abs((near.mean - exact.mean).dot(u)) / h);
}

void neighbourhood_matches_exact_sum_on_random_cloud(void**) {
  const std::vector<Vec3> pts = bump_cloud(4000, 0.02, 1);
  CloudIndex index(pts);
  const DirectedProjector pr(index, cloud_spacing(index));
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> unit(0.0, 1.0), tilt(-0.4, 0.4);
  Worst worst, worst_near_surface;
  std::size_t partial = 0;
  for (int k = 0; k < 150; ++k) {
    const double x = unit(rng), y = unit(rng);
    const double lift = (k % 5) * 3.0 * pr.length_scale();
    const Vec3 p(x, y, bump(x, y) + lift);
    const Vec3 n(tilt(rng), tilt(rng), -1.0);
    check_ray(pr, p, n, k % 5 == 0 ? worst_near_surface : worst);
    if (pr.moments(p, n).points_used < pts.size()) ++partial;
  }
  assert_true(partial == 150);  // every ray left points out: the bound was exercised
  std::printf("random cloud, p on the surface: worst relative c0 error %.3g, mean error %.3g h, t error %.3g h\n", worst_near_surface.c0, worst_near_surface.mean, worst_near_surface.t);
  std::printf("random cloud, p 3-12 h off: worst relative c0 error %.3g, mean error %.3g h, t error %.3g h\n", worst.c0, worst.mean, worst.t);
  assert_true(worst_near_surface.c0 < 0.05);
}

void moments_are_the_plain_sums_bit_for_bit(void**) {
  // moments() weighs two points at a time where it can; its c0 and mean must be those of the
  // plain sums of eq. (4) over the ray's neighbourhood in its order, bit for bit (the folds of
  // the hard shapes move with a single rounding of them). An odd and an even count of points.
  const std::vector<Vec3> pts = bump_cloud(3000, 0.01, 5);
  CloudIndex index(pts);
  const double h = cloud_spacing(index);
  const DirectedProjector pr(index, h);
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> unit(0.0, 1.0), tilt(-0.4, 0.4);
  const double bound = std::sqrt(1.0 / kW - 1.0) * h * h;
  bool odd = false, even = false;
  for (int k = 0; k < 200; ++k) {
    const double x = unit(rng), y = unit(rng);
    const Vec3 p(x, y, bump(x, y) + (k % 4) * h);
    const Vec3 n(tilt(rng), tilt(rng), -1.0);
    std::vector<std::size_t> near;
    index.near_ray(p, n, bound, near);
    const Vec3 u = n / n.norm();
    double c0 = 0.0;
    Vec3 first = Vec3::Zero();
    const double inv_h = 1.0 / h;
    for (std::size_t i : near) {
      // Eq. (5)'s weight, the sums of squares taken x, y, then z.
      const double dx = (pts[i].x() - p.x()) * inv_h, dy = (pts[i].y() - p.y()) * inv_h, dz = (pts[i].z() - p.z()) * inv_h;
      const double cx = dy * u.z() - dz * u.y(), cy = dz * u.x() - dx * u.z(), cz = dx * u.y() - dy * u.x();
      const double a = 1.0 / (1.0 + (dx * dx + dy * dy + dz * dz) * (cx * cx + cy * cy + cz * cz));
      c0 += a;
      first += a * (pts[i] - p);
    }
    const RayMoments m = pr.moments(p, n);
    assert_int_equal(m.points_used, near.size());
    assert_true(m.c0 == c0);
    assert_true(m.mean == Vec3(p + first / c0));
    (near.size() % 2 ? odd : even) = true;
  }
  assert_true(odd && even);
}

void neighbourhood_matches_exact_sum_on_plane(void**) {
  const std::vector<Vec3> pts = plane_grid(70, 0.5);
  CloudIndex index(pts);
  const DirectedProjector pr(index, cloud_spacing(index));
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> across(5.0, 30.0), tilt(-0.3, 0.3);
  Worst worst;
  for (int k = 0; k < 100; ++k) {
    const Vec3 p(across(rng), across(rng), (k % 4) * 2.0);
    check_ray(pr, p, Vec3(tilt(rng), tilt(rng), -1.0), worst);
  }
  std::printf("plane, p 0-6 h off: worst relative c0 error %.3g, mean error %.3g h, t error %.3g h\n", worst.c0, worst.mean, worst.t);
}

void ray_lands_on_planar_cloud(void**) {
  const double pitch = 0.5;
  const std::vector<Vec3> pts = plane_grid(80, pitch);
  CloudIndex index(pts);
  const double h = cloud_spacing(index);
  assert_true(std::abs(h - pitch) <= 1e-12);
  const DirectedProjector pr(index, h);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> across(10.0, 30.0), tilt(-0.25, 0.25);
  double worst_vertical = 0.0, worst_tilted = 0.0;
  for (int k = 0; k < 100; ++k) {
    const Vec3 p(across(rng), across(rng), (k % 5) * 2.5 * h);
    double t = 0.0;
    assert_true(pr.project(p, Vec3(0, 0, -2.0), t));
    worst_vertical = std::max(worst_vertical, std::abs((p + t * Vec3(0, 0, -2.0)).z()));
    const Vec3 n = Vec3(tilt(rng), tilt(rng), -1.0).normalized();
    assert_true(pr.project(p, n, t));
    worst_tilted = std::max(worst_tilted, std::abs((p + t * n).z()));
  }
  std::printf("plane: projected rays miss the plane by %.3g h (vertical), %.3g h (tilted up to 19 deg)\n", worst_vertical / h, worst_tilted / h);
  assert_true(worst_vertical <= 1e-12 * h);
  assert_true(worst_tilted <= 0.25 * h);
}

void projection_is_invariant_to_scale_and_rigid_motion(void**) {
  const std::vector<Vec3> pts = bump_cloud(5000, 0.01, 5);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 shift(50.0, -30.0, 20.0);
  auto move = [&](const Vec3& p) { return Vec3(1000.0 * (rotation * p + shift)); };
  std::vector<Vec3> moved;
  for (const Vec3& p : pts) moved.push_back(move(p));
  CloudIndex index(pts), moved_index(moved);
  const double h = cloud_spacing(index), h_moved = cloud_spacing(moved_index);
  assert_true(std::abs(h_moved - 1000.0 * h) <= 1e-12 * h_moved);
  const DirectedProjector pr(index, h), moved_pr(moved_index, h_moved);

  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> unit(0.05, 0.95), tilt(-0.3, 0.3);
  double worst_t = 0.0, worst_c0 = 0.0;
  for (int k = 0; k < 100; ++k) {
    const double x = unit(rng), y = unit(rng);
    const Vec3 p(x, y, bump(x, y) + (k % 3 - 1) * 4.0 * h);
    const Vec3 n = Vec3(tilt(rng), tilt(rng), -1.0).normalized();
    double t = 0.0, t_moved = 0.0;
    assert_true(pr.project(p, n, t));
    assert_true(moved_pr.project(move(p), rotation * n, t_moved));
    worst_t = std::max(worst_t, std::abs(t_moved / 1000.0 - t) / h);
    const RayMoments m = pr.moments(p, n), m_moved = moved_pr.moments(move(p), rotation * n);
    assert_int_equal(m.points_used, m_moved.points_used);
    worst_c0 = std::max(worst_c0, std::abs(m_moved.c0 - m.c0) / m.c0);
  }
  assert_true(worst_t <= 1e-9);
  assert_true(worst_c0 <= 1e-9);
}

void bad_input_and_empty_rays(void**) {
  const std::vector<Vec3> pts = plane_grid(40, 1.0);
  CloudIndex index(pts);
  assert_true(throws(ErrorCode::InvalidArgument, [&] { DirectedProjector(index, 0.0); }));
  assert_true(throws(ErrorCode::InvalidArgument, [&] { DirectedProjector(index, NAN); }));
  const DirectedProjector pr(index, 1.0);
  assert_true(throws(ErrorCode::Degenerate, [&] { pr.moments(Vec3(1, 1, 1), Vec3::Zero()); }));
  assert_true(throws(ErrorCode::NonFinite, [&] { pr.moments(Vec3(1, NAN, 1), Vec3::UnitZ()); }));

  // A ray 1000 h above the cloud and parallel to it: every point has r rho > 1000 h^2, so
  // the neighbourhood is empty and there is no projection, though the exact sum is not zero.
  const Vec3 p(20, 20, 1000), n(1, 0, 0);
  double t = 42.0;
  assert_false(pr.project(p, n, t));
  assert_true(t == 42.0);
  const RayMoments m = pr.moments(p, n);
  assert_true(m.c0 == 0.0 && m.points_used == 0 && m.mean == p);
  const RayMoments e = pr.moments_exact(p, n);
  assert_true(e.c0 > 0.0 && e.c0 < kW * pts.size());
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(neighbourhood_matches_exact_sum_on_random_cloud),
      cmocka_unit_test(moments_are_the_plain_sums_bit_for_bit),
      cmocka_unit_test(neighbourhood_matches_exact_sum_on_plane),
      cmocka_unit_test(ray_lands_on_planar_cloud),
      cmocka_unit_test(projection_is_invariant_to_scale_and_rigid_motion),
      cmocka_unit_test(bad_input_and_empty_rays),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
