// Polyline: arc-length parameterization, exact ends and vertices, split, nearest point.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <vector>

#include "error.hpp"
#include "polyline.hpp"
#include "core_test_support.hpp"  // last of the dbs headers

// cmocka last (its fail() macro would hide dbs::fail), with C linkage (its header does
// not declare it).

using dbs::Polyline;
using dbs::Vec3;

namespace {

using core_test::error_code_of;

// Segments of lengths 1, 3, 0.5, 5 (total 9.5), turning in 3D.
std::vector<Vec3> uneven_points() {
  return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 3, 0), Vec3(1, 3, 0.5), Vec3(4, 7, 0.5)};
}

// The point at arc length a from the start, walked independently of Polyline.
Vec3 walk(const std::vector<Vec3>& pts, double a) {
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double len = (pts[i + 1] - pts[i]).norm();
    if (a <= len) return pts[i] + (a / len) * (pts[i + 1] - pts[i]);
    a -= len;
  }
  return pts.back();
}

double arc_length(const Polyline& p) {
  double len = 0;
  for (std::size_t i = 1; i < p.size(); ++i) len += (p.points()[i] - p.points()[i - 1]).norm();
  return len;
}

// A straight polyline whose segments shrink geometrically over six decades and then grow
// again, so that most vertices crowd into a few lookup buckets: at(s) must still be the
// point at arc length s L (any wrong segment would be far off), and every vertex parameter
// must give that vertex exactly.
void test_at_on_crowded_vertices(void**) {
  std::vector<Vec3> pts{Vec3(0, 0, 0)};
  double x = 0.0, step = 1.0;
  for (int k = 0; k < 400; ++k, step *= (k < 200 ? 0.933 : 1.0 / 0.933)) pts.emplace_back(x += step, 0.0, 0.0);
  const Polyline p(pts);
  const double length = p.length();
  double worst = 0.0;
  unsigned seed = 12345u;
  for (int k = 0; k < 20000; ++k) {
    seed = seed * 1103515245u + 12345u;
    const double s = static_cast<double>(seed >> 8) / static_cast<double>(1u << 24);
    worst = std::max(worst, std::fabs(p.at(s).x() - s * length));
  }
  assert_true(worst <= 1e-13 * length);
  double cumulative = 0.0;
  for (std::size_t i = 1; i + 1 < pts.size(); ++i) {
    cumulative += (pts[i] - pts[i - 1]).norm();
    assert_true(p.at(cumulative / length) == pts[i]);
  }
}

void test_length_and_ends(void**) {
  const std::vector<Vec3> pts = uneven_points();
  const Polyline p(pts);
  assert_int_equal(p.size(), 5);
  assert_true(std::fabs(p.length() - 9.5) < 1e-14);
  // Ends are the stored points bit for bit; s is clamped.
  assert_true(p.at(0.0) == pts.front());
  assert_true(p.at(1.0) == pts.back());
  assert_true(p.at(-3.0) == pts.front());
  assert_true(p.at(7.0) == pts.back());
}

void test_at_is_arc_length_fraction(void**) {
  const std::vector<Vec3> pts = uneven_points();
  const Polyline p(pts);
  const double length = 9.5;
  double worst = 0;
  for (int k = 0; k <= 1000; ++k) {
    const double s = k / 1000.0;
    worst = std::fmax(worst, (p.at(s) - walk(pts, s * length)).norm());
  }
  assert_true(worst < 1e-12 * length);
  // Known points: a quarter of 9.5 = 2.375 lies 1.375 up the second segment.
  assert_true((p.at(0.25) - Vec3(1, 1.375, 0)).norm() < 1e-12);
  // Half of 9.5 = 4.75 lies 0.25 into the last segment, along (3,4,0)/5.
  assert_true((p.at(0.5) - Vec3(1.15, 3.2, 0.5)).norm() < 1e-12);
}

void test_at_vertices_exact(void**) {
  const std::vector<Vec3> pts = uneven_points();
  const Polyline p(pts);
  double cumulative = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i > 0) cumulative += (pts[i] - pts[i - 1]).norm();
    assert_true(p.at(cumulative / p.length()) == pts[i]);
  }
}

void test_tangent(void**) {
  const Polyline p(uneven_points());
  assert_true((p.tangent(0.05) - Vec3(1, 0, 0)).norm() < 1e-15);
  assert_true((p.tangent(0.3) - Vec3(0, 1, 0)).norm() < 1e-15);
  assert_true((p.tangent(0.43) - Vec3(0, 0, 1)).norm() < 1e-15);
  assert_true((p.tangent(1.0) - Vec3(0.6, 0.8, 0)).norm() < 1e-15);
  // At a vertex the segment that starts there.
  assert_true((p.tangent(1.0 / 9.5) - Vec3(0, 1, 0)).norm() < 1e-15);
  // at(s, d_ds): the same point, and d_ds = length * tangent matches a finite difference.
  for (double s : {0.0, 0.07, 0.2, 1.0 / 9.5, 0.45, 0.8, 1.0}) {
    Vec3 d;
    assert_true(p.at(s, d) == p.at(s));
    assert_true((d - 9.5 * p.tangent(s)).norm() < 1e-14);
  }
  Vec3 d;
  p.at(0.8, d);
  assert_true((d - (p.at(0.8 + 1e-6) - p.at(0.8 - 1e-6)) / 2e-6).norm() < 1e-8);
}

void test_repeated_points(void**) {
  const Polyline p({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(2, 0, 0), Vec3(2, 2, 0), Vec3(2, 2, 0)});
  assert_true(std::fabs(p.length() - 4) < 1e-15);
  assert_true((p.at(0.75) - Vec3(2, 1, 0)).norm() < 1e-15);
  assert_true(p.at(0.5) == Vec3(2, 0, 0));
  assert_true((p.tangent(0.5) - Vec3(0, 1, 0)).norm() < 1e-15);
  assert_true((p.tangent(1.0) - Vec3(0, 1, 0)).norm() < 1e-15);
}

void test_split_lengths(void**) {
  const std::vector<Vec3> pts = uneven_points();
  const Polyline p(pts);
  for (double s : {0.5, 0.3, 0.01, 0.77, 0.999}) {
    const auto halves = p.split(s);
    const Polyline& a = halves.first;
    const Polyline& b = halves.second;
    assert_true(std::fabs(a.length() - s * 9.5) < 1e-12 * 9.5);
    assert_true(std::fabs(b.length() - (1 - s) * 9.5) < 1e-12 * 9.5);
    assert_true(std::fabs(arc_length(a) - a.length()) < 1e-15 * 9.5);
    // The split point ends one half and starts the other, bit for bit, and is at(s).
    assert_true(a.back() == b.front());
    assert_true(a.back() == p.at(s));
    assert_true(a.front() == pts.front());
    assert_true(b.back() == pts.back());
    // The halves trace the same curve: a.at(t) is p.at(t*s).
    for (int k = 0; k <= 20; ++k) {
      const double t = k / 20.0;
      assert_true((a.at(t) - p.at(t * s)).norm() < 1e-12 * 9.5);
      assert_true((b.at(t) - p.at(s + t * (1 - s))).norm() < 1e-12 * 9.5);
    }
  }
}

void test_split_at_vertex_no_duplicate(void**) {
  const std::vector<Vec3> pts = uneven_points();
  const Polyline p(pts);
  const double s = 4.0 / 9.5;  // the third vertex (1,3,0)
  const auto halves = p.split(s);
  assert_int_equal(halves.first.size(), 3);
  assert_int_equal(halves.second.size(), 3);
  assert_true(halves.first.back() == pts[2]);
  assert_true(halves.second.front() == pts[2]);
  assert_true(std::fabs(halves.first.length() - 4.0) < 1e-14);
  // Off a vertex the split point is new: one extra vertex in each half.
  const auto mid = p.split(0.5);
  assert_int_equal(mid.first.size(), 5);
  assert_int_equal(mid.second.size(), 2);
  // A two-point polyline split in the middle.
  const Polyline seg({Vec3(0, 0, 0), Vec3(0, 0, 8)});
  const auto h = seg.split(0.5);
  assert_true(h.first.back() == Vec3(0, 0, 4));
  assert_int_equal(h.first.size(), 2);
  assert_int_equal(h.second.size(), 2);
}

void test_split_outside_rejected(void**) {
  const Polyline p(uneven_points());
  assert_int_equal(error_code_of([&] { p.split(0.0); }), dbs::ErrorCode::InvalidArgument);
  assert_int_equal(error_code_of([&] { p.split(1.0); }), dbs::ErrorCode::InvalidArgument);
  assert_int_equal(error_code_of([&] { p.split(std::nan("")); }), dbs::ErrorCode::InvalidArgument);
}

void test_nearest(void**) {
  const Polyline p(uneven_points());
  double s = -1;
  Vec3 q = p.nearest(Vec3(0.5, -1, 0.2), &s);
  assert_true((q - Vec3(0.5, 0, 0)).norm() < 1e-15);
  assert_true(std::fabs(s - 0.5 / 9.5) < 1e-15);
  // Beyond the end: the last vertex, s exactly 1.
  q = p.nearest(Vec3(10, 20, 0.5), &s);
  assert_true(q == Vec3(4, 7, 0.5));
  assert_true(s == 1.0);
  // Before the start.
  q = p.nearest(Vec3(-2, -1, 0), &s);
  assert_true(q == Vec3(0, 0, 0));
  assert_true(s == 0.0);
  // Random queries: the returned point is at(s), bit for bit, and no sample is nearer.
  std::srand(7);
  for (int k = 0; k < 200; ++k) {
    const Vec3 x(std::rand() / (double)RAND_MAX * 6 - 1, std::rand() / (double)RAND_MAX * 9 - 1, std::rand() / (double)RAND_MAX * 2 - 1);
    const Vec3 n = p.nearest(x, &s);
    assert_true(n == p.at(s));
    const double d = (x - n).norm();
    for (int m = 0; m <= 400; ++m) assert_true(d <= (x - p.at(m / 400.0)).norm() + 1e-12);
  }
}

void test_with_ends(void**) {
  const Polyline p(uneven_points());
  const Polyline q = p.with_ends(Vec3(0, 0, 1), Vec3(4, 7, -0.5));
  assert_int_equal(q.size(), p.size());
  assert_true(q.front() == Vec3(0, 0, 1));
  assert_true(q.back() == Vec3(4, 7, -0.5));
  assert_true(std::fabs(q.length() - arc_length(q)) < 1e-15 * 10);
  assert_true(q.points()[2] == p.points()[2]);
}

void test_constructor_errors(void**) {
  assert_int_equal(error_code_of([] { Polyline({Vec3(1, 2, 3)}); }), dbs::ErrorCode::InvalidArgument);
  assert_int_equal(error_code_of([] { Polyline(std::vector<Vec3>{}); }), dbs::ErrorCode::InvalidArgument);
  assert_int_equal(error_code_of([] { Polyline({Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(1, 2, 3)}); }), dbs::ErrorCode::Degenerate);
  const double inf = std::numeric_limits<double>::infinity();
  assert_int_equal(error_code_of([&] { Polyline({Vec3(0, 0, 0), Vec3(inf, 0, 0)}); }), dbs::ErrorCode::NonFinite);
  try {
    Polyline({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, std::nan(""), 0)});
    fail();
  } catch (const dbs::Error& e) {
    assert_int_equal(e.code(), dbs::ErrorCode::NonFinite);
    assert_non_null(std::strstr(e.what(), "point 2"));
  }
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_length_and_ends),
      cmocka_unit_test(test_at_is_arc_length_fraction),
      cmocka_unit_test(test_at_vertices_exact),
      cmocka_unit_test(test_at_on_crowded_vertices),
      cmocka_unit_test(test_tangent),
      cmocka_unit_test(test_repeated_points),
      cmocka_unit_test(test_split_lengths),
      cmocka_unit_test(test_split_at_vertex_no_duplicate),
      cmocka_unit_test(test_split_outside_rejected),
      cmocka_unit_test(test_nearest),
      cmocka_unit_test(test_with_ends),
      cmocka_unit_test(test_constructor_errors),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
