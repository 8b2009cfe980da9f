// The cloud index: k nearest, radius and ray-neighbourhood queries agree with brute force on
// random clouds and subsets (answers are indices into the full cloud), and the length scale h
// is the pitch of a regular grid, ignores duplicates and scales exactly with the input. A
// cloud indexed as a forest of chunks answers the same, its build counts its work, reports
// between chunks and stops on a cancel, and does not depend on the thread count.
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <string>
#include <utility>

#include "cloud_index.hpp"
#include "error.hpp"
#include "work_meter.hpp"

// cmocka last (its fail() macro would hide dbs::fail), with C linkage (its header does
// not declare it).
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs;

namespace {

std::vector<Vec3> random_cloud(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> pts(n);
  for (Vec3& p : pts) p = Vec3(unit(rng), unit(rng), 0.3 * unit(rng));
  return pts;
}

/// Brute-force k nearest among `candidates` (indices into pts), nearest first.
std::vector<std::pair<double, std::size_t>> brute_knn(const std::vector<Vec3>& pts, const std::vector<std::size_t>& candidates, const Vec3& q, std::size_t k) {
  std::vector<std::pair<double, std::size_t>> all;
  for (std::size_t i : candidates) all.emplace_back((pts[i] - q).squaredNorm(), i);
  std::sort(all.begin(), all.end());
  all.resize(std::min(k, all.size()));
  return all;
}

std::vector<std::size_t> iota(std::size_t n) {
  std::vector<std::size_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

void check_queries(const CloudIndex& index, const std::vector<std::size_t>& members, unsigned seed) {
  const std::vector<Vec3>& pts = index.points();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.2, 1.2);
  std::vector<std::size_t> idx;
  std::vector<double> d2;
  for (int query = 0; query < 60; ++query) {
    const Vec3 q(unit(rng), unit(rng), 0.5 * unit(rng));
    for (std::size_t k : {1u, 7u, 40u}) {
      index.knn(q, k, idx, d2);
      const auto expected = brute_knn(pts, members, q, k);
      assert_int_equal(idx.size(), expected.size());
      for (std::size_t i = 0; i < idx.size(); ++i) {
        assert_int_equal(idx[i], expected[i].second);
        assert_true(std::abs(d2[i] - expected[i].first) <= 1e-15);
      }
    }
    assert_int_equal(index.nearest(q), brute_knn(pts, members, q, 1)[0].second);

    const double r = 0.05 + 0.3 * (query % 5);
    index.radius(q, r, idx);
    std::vector<std::size_t> expected;
    for (std::size_t i : members)
      if ((pts[i] - q).norm() < r) expected.push_back(i);
    std::sort(idx.begin(), idx.end());
    assert_true(idx == expected);

    // The ray neighbourhood: |x - p| * distance(x, line) <= bound.
    const Vec3 n(unit(rng), unit(rng), unit(rng) + 2.0);
    const double bound = 0.002 * (1 + query % 7);
    index.near_ray(q, n, bound, idx);
    expected.clear();
    const Vec3 u = n.normalized();
    for (std::size_t i : members) {
      const Vec3 d = pts[i] - q;
      if (d.squaredNorm() * d.cross(u).squaredNorm() <= bound * bound) expected.push_back(i);
    }
    std::sort(idx.begin(), idx.end());
    assert_true(idx == expected);
    assert_true(expected.size() < members.size());  // the query prunes: not the whole cloud
  }
}

void whole_cloud_queries_match_brute_force(void**) {
  const std::vector<Vec3> pts = random_cloud(3000, 1);
  CloudIndex index(pts);
  assert_int_equal(index.size(), 3000);
  assert_int_equal(index.point_index(1234), 1234);
  check_queries(index, iota(pts.size()), 2);
}

void subset_queries_answer_full_cloud_indices(void**) {
  const std::vector<Vec3> pts = random_cloud(4000, 3);
  std::vector<std::size_t> subset;
  for (std::size_t i = 0; i < pts.size(); i += 3) subset.push_back(i);
  CloudIndex index(pts, subset);
  assert_int_equal(index.size(), subset.size());
  assert_int_equal(index.point_index(10), 30);
  check_queries(index, subset, 4);
}

/// nx x ny points of pitch a in a tilted plane through `origin`.
std::vector<Vec3> grid_cloud(int nx, int ny, double a, const Vec3& origin) {
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(0.4, Vec3(1, 1, 0).normalized()).toRotationMatrix();
  std::vector<Vec3> pts;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) pts.push_back(origin + tilt * Vec3(i * a, j * a, 0.0));
  return pts;
}

void spacing_is_the_pitch_of_a_grid(void**) {
  const double a = 0.37;
  const std::vector<Vec3> pts = grid_cloud(60, 45, a, Vec3(2, -1, 3));
  CloudIndex index(pts);
  assert_true(std::abs(cloud_spacing(index) - a) <= 1e-12 * a);
  assert_true(std::abs(cloud_spacing(index, 100) - a) <= 1e-12 * a);  // strided samples

  // Every point twice: exact duplicates are skipped, the next distinct neighbour counts.
  std::vector<Vec3> doubled = pts;
  doubled.insert(doubled.end(), pts.begin(), pts.end());
  CloudIndex doubled_index(doubled);
  assert_true(std::abs(cloud_spacing(doubled_index) - a) <= 1e-12 * a);
}

void spacing_scales_exactly(void**) {
  const std::vector<Vec3> pts = random_cloud(5000, 5);
  std::vector<Vec3> scaled;
  for (const Vec3& p : pts) scaled.push_back(1000.0 * p);
  CloudIndex index(pts), scaled_index(scaled);
  const double h = cloud_spacing(index), h_scaled = cloud_spacing(scaled_index);
  assert_true(h > 0.0);
  assert_true(std::abs(h_scaled - 1000.0 * h) <= 1e-12 * h_scaled);
  // Deterministic: the same cloud gives bitwise the same h.
  CloudIndex again(pts);
  assert_true(cloud_spacing(again) == h);
}

/// The ray neighbourhood of a cloud scaled by a power of two (every coordinate exact) at the
/// ends of the supported magnitudes is the unit cloud's, point for point and in order: at
/// about 1e-99 the test's products (length^4) would underflow to 0 and take every point of
/// the boxes visited, at about 1e73 they would come near overflowing.
void ray_neighbourhoods_are_the_same_at_any_magnitude(void**) {
  const std::vector<Vec3> pts = random_cloud(3000, 8);
  CloudIndex unit(pts);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int exponent : {-330, 242}) {
    const double s = std::ldexp(1.0, exponent);
    std::vector<Vec3> scaled;
    for (const Vec3& p : pts) scaled.push_back(s * p);
    CloudIndex index(scaled);
    std::vector<std::size_t> at_unit, at_scale;
    std::size_t found = 0;
    for (int query = 0; query < 40; ++query) {
      const Vec3 q(coordinate(rng), coordinate(rng), 0.2 * coordinate(rng)), n(coordinate(rng), coordinate(rng), coordinate(rng) + 2.0);
      const double bound = 0.002 * (1 + query % 7);
      unit.near_ray(q, n, bound, at_unit);
      index.near_ray(s * q, n, bound * s * s, at_scale);
      assert_true(at_scale == at_unit);
      assert_true(at_unit.size() < pts.size() / 4);
      found += at_unit.size();
    }
    assert_true(found > 40);
  }
}

void forest_queries_match_brute_force(void**) {
  const std::vector<Vec3> pts = random_cloud(6000, 7);
  IndexBuild build;
  build.chunk_points = 500;
  build.threads = 2;
  CloudIndex index(pts, build);
  assert_int_equal(index.chunks(), 16);  // 6000 halved four times: 375 points a chunk
  assert_int_equal(index.size(), 6000);
  assert_int_equal(index.point_index(4321), 4321);  // the input order, not the chunks'
  check_queries(index, iota(pts.size()), 8);

  std::vector<std::size_t> subset;
  for (std::size_t i = 1; i < pts.size(); i += 2) subset.push_back(i);
  CloudIndex part(pts, subset, build);
  assert_int_equal(part.chunks(), 8);
  assert_int_equal(part.point_index(10), 21);
  check_queries(part, subset, 9);
}

void forest_does_not_depend_on_threads(void**) {
  const std::vector<Vec3> pts = random_cloud(9000, 10);
  IndexBuild one, two;
  one.chunk_points = two.chunk_points = 700;
  two.threads = 2;
  CloudIndex a(pts, one), b(pts, two);
  assert_int_equal(a.chunks(), b.chunks());
  std::vector<std::size_t> ia, ib;
  std::vector<double> da, db;
  for (int q = 0; q < 50; ++q) {
    const Vec3 p = pts[static_cast<std::size_t>(q) * 173];
    a.knn(p, 20, ia, da);
    b.knn(p, 20, ib, db);
    assert_true(ia == ib && da == db);
    a.near_ray(p, Vec3(0.1, 0.2, 1.0), 0.01, ia);
    b.near_ray(p, Vec3(0.1, 0.2, 1.0), 0.01, ib);
    assert_true(ia == ib);  // the same points in the same order: sums over them agree bitwise
    assert_true(!ia.empty());
  }
}

void ray_neighbourhood_is_the_point_test_to_the_last_bit(void**) {
  // near_ray tests two points at a time: its answer must be that of the point test written
  // out (|d|^2 |d x u|^2 <= bound^2, the sums of squares taken x, y, then z; scaling by a
  // power of two, as the query does, changes no comparison), also for a point whose product
  // is the bound to within its last bits, which a test summing in another order misjudges.
  const std::vector<Vec3> pts = random_cloud(3001, 14);
  const CloudIndex index(pts);
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<std::size_t> got;
  std::size_t edge_points = 0;
  for (std::size_t q = 0; q < 3000; ++q) {
    const Vec3 p(unit(rng), unit(rng), 0.5 * unit(rng));
    const Vec3 n(unit(rng), unit(rng), unit(rng) + 2.0);
    const Vec3 u = n / n.norm();  // as near_ray makes it unit
    auto product = [&](const Vec3& x) {
      const double dx = x.x() - p.x(), dy = x.y() - p.y(), dz = x.z() - p.z();
      const double cx = dy * u.z() - dz * u.y(), cy = dz * u.x() - dx * u.z(), cz = dx * u.y() - dy * u.x();
      return (dx * dx + dy * dy + dz * dz) * (cx * cx + cy * cy + cz * cz);
    };
    // The bound at the product of one point, nudged by up to two ulps either way.
    double bound = std::sqrt(product(pts[q]));
    for (int step = 0, steps = static_cast<int>(q % 5) - 2; step < std::abs(steps); ++step) bound = std::nextafter(bound, steps > 0 ? 1.0 : 0.0);
    index.near_ray(p, n, bound, got);
    std::sort(got.begin(), got.end());
    std::vector<std::size_t> expected;
    for (std::size_t i = 0; i < pts.size(); ++i)
      if (product(pts[i]) <= bound * bound) expected.push_back(i);
    assert_true(got == expected);
    edge_points += std::binary_search(expected.begin(), expected.end(), q) ? 1 : 0;
  }
  assert_true(edge_points > 500 && edge_points < 2500);  // the edge point in, and out, often
}

void ray_columns_made_by_concurrent_first_queries(void**) {
  // Ray queries read a chunk's points from columns in leaf order, made by the first ray query
  // on it: two threads asking at once, on a fresh index, get what one thread gets (the
  // columns are made once, whole, before either reads them), with the same order, on one tree
  // and on a forest, including rays whose bound puts a point exactly on the region's edge.
  const std::vector<Vec3> pts = random_cloud(5001, 12);
  std::vector<Vec3> p(200), n(200);
  std::vector<double> bound(200);
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (std::size_t q = 0; q < 200; ++q) {
    p[q] = q % 4 == 0 ? pts[q * 17] : Vec3(unit(rng), unit(rng), 0.5 * unit(rng));
    n[q] = Vec3(unit(rng), unit(rng), unit(rng) + 2.0);
    bound[q] = 0.001 * static_cast<double>(1 + q % 9);
    if (q % 4 == 1) {
      const Vec3 d = pts[q * 13] - p[q];
      const Vec3 u = n[q].normalized();
      bound[q] = std::sqrt(d.squaredNorm() * d.cross(u).squaredNorm());
    }
  }
  for (std::size_t chunk_points : {IndexBuild::kDefaultChunkPoints, std::size_t{600}}) {
    IndexBuild build;
    build.chunk_points = chunk_points;
    const CloudIndex serial(pts, build);
    std::vector<std::vector<std::size_t>> expected(200);
    std::size_t answered = 0;
    for (std::size_t q = 0; q < 200; ++q) {
      serial.near_ray(p[q], n[q], bound[q], expected[q]);
      answered += expected[q].size();
    }
    assert_true(answered > 2000);  // the queries did find points
    const CloudIndex fresh(pts, build);
    std::vector<std::vector<std::size_t>> got[2];
    auto ask = [&](int t) {
      got[t].resize(200);
      for (std::size_t q = 0; q < 200; ++q) fresh.near_ray(p[q], n[q], bound[q], got[t][q]);
    };
    std::thread other(ask, 1);
    ask(0);
    other.join();
    assert_true(got[0] == expected && got[1] == expected);
  }
}

void forest_build_is_metered_and_cancellable(void**) {
  const std::vector<Vec3> pts = random_cloud(40000, 11);
  IndexBuild build;
  build.chunk_points = 2500;  // 16 chunks
  build.threads = 2;
  // Every halving pass and every tree counted: units as index_build_work says, reports
  // spread over the build (a report every 64 units, a chunk being 78).
  WorkMeter meter(64);
  int reports = 0;
  meter.set_report([&] { ++reports; });
  build.meter = &meter;
  {
    CloudIndex index(pts, build);
    assert_int_equal(index.chunks(), 16);
  }
  assert_int_equal(meter.done(), index_build_work(pts.size(), 2500));
  assert_int_equal(meter.done(), 40000 * 5 / 32);
  assert_true(reports >= 50);

  // A cancel from the third report stops the build: no index, the cancel's error.
  WorkMeter cancelling(64);
  int seen = 0;
  cancelling.set_report([&] {
    if (++seen == 3) throw Error(ErrorCode::Cancelled, "cancelled by the test");
  });
  build.meter = &cancelling;
  bool cancelled = false;
  try {
    CloudIndex index(pts, build);
  } catch (const Error& e) {
    cancelled = e.code() == ErrorCode::Cancelled;
  }
  assert_true(cancelled);
  assert_true(cancelling.done() < index_build_work(pts.size(), 2500));
}

void errors_name_the_problem(void**) {
  const std::vector<Vec3> pts = random_cloud(10, 6);
  bool thrown = false;
  try {
    CloudIndex bad(pts, std::vector<std::size_t>{1, 2, 10});
  } catch (const Error& e) {
    thrown = e.code() == ErrorCode::OutOfRange && std::string(e.what()).find("subset entry 2") != std::string::npos;
  }
  assert_true(thrown);

  CloudIndex empty(pts, std::vector<std::size_t>{});
  assert_int_equal(empty.size(), 0);
  std::vector<std::size_t> idx{1};
  std::vector<double> d2;
  empty.knn(Vec3::Zero(), 3, idx, d2);
  assert_true(idx.empty() && d2.empty());
  empty.near_ray(Vec3::Zero(), Vec3::UnitZ(), 1.0, idx);
  assert_true(idx.empty());
  thrown = false;
  try {
    empty.nearest(Vec3::Zero());
  } catch (const Error& e) {
    thrown = e.code() == ErrorCode::Empty;
  }
  assert_true(thrown);

  const std::vector<Vec3> same(5, Vec3(1, 2, 3));
  CloudIndex same_index(same);
  thrown = false;
  try {
    cloud_spacing(same_index);
  } catch (const Error& e) {
    thrown = e.code() == ErrorCode::Degenerate;
  }
  assert_true(thrown);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(whole_cloud_queries_match_brute_force),
      cmocka_unit_test(subset_queries_answer_full_cloud_indices),
      cmocka_unit_test(spacing_is_the_pitch_of_a_grid),
      cmocka_unit_test(spacing_scales_exactly),
      cmocka_unit_test(ray_neighbourhoods_are_the_same_at_any_magnitude),
      cmocka_unit_test(forest_queries_match_brute_force),
      cmocka_unit_test(forest_does_not_depend_on_threads),
      cmocka_unit_test(ray_neighbourhood_is_the_point_test_to_the_last_bit),
      cmocka_unit_test(ray_columns_made_by_concurrent_first_queries),
      cmocka_unit_test(forest_build_is_metered_and_cancellable),
      cmocka_unit_test(errors_name_the_problem),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
