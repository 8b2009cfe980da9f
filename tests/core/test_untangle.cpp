// Untangling (untangle.hpp): points whose (u,v) turn their umbrella over move to the (u,v)
// their neighbours predict; a sound map is left alone, creases are not judged, and the
// result does not depend on the thread count, a rigid motion or a uniform scale.
#include <cmath>
#include <cstdint>
#include <vector>

#include "cloud_index.hpp"
#include "result.hpp"
#include "untangle.hpp"

#include "core_test_support.hpp"

namespace {

using dbs::Vec3;

constexpr int kSide = 40;  // points per side of the jittered grid

/// A deterministic jitter in [-0.3, 0.3] cell.
double jitter(std::uint64_t k) {
  k = (k + 0x9e3779b97f4a7c15ULL) * 0xbf58476d1ce4e5b9ULL;
  k ^= k >> 31;
  return 0.6 * (static_cast<double>(k % 1000003) / 1000003.0) - 0.3;
}

/// A jittered grid on a tilted plane (or, `crease`, on two half-planes meeting at 90 degrees
/// along a = 0.5), with its true (u,v).
struct Sheet {
  std::vector<Vec3> points;
  dbs::Result result;  // u, v only
};

Sheet sheet(bool crease = false, double scale = 1.0, const Vec3& shift = Vec3::Zero()) {
  Sheet s;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      const std::size_t k = static_cast<std::size_t>(i + kSide * j);
      const double a = (i + 0.5 + jitter(2 * k)) / kSide, b = (j + 0.5 + jitter(2 * k + 1)) / kSide;
      Vec3 p(a, b, 0.1 * a + 0.05 * b);
      if (crease) p = a <= 0.5 ? Vec3(a, b, 0.0) : Vec3(0.5, b, a - 0.5);
      s.points.push_back(scale * p + shift);
      s.result.u.push_back(a);
      s.result.v.push_back(b);
    }
  return s;
}

std::size_t at(int i, int j) { return static_cast<std::size_t>(i + kSide * j); }

/// Reference triangles of the grid (two a cell, counter-clockwise in the true (u,v)) whose
/// (u,v) area is not positive.
std::size_t turned_triangles(const dbs::Result& r) {
  auto area = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (r.u[b] - r.u[a]) * (r.v[c] - r.v[a]) - (r.v[b] - r.v[a]) * (r.u[c] - r.u[a]);
  };
  std::size_t count = 0;
  for (int j = 0; j + 1 < kSide; ++j)
    for (int i = 0; i + 1 < kSide; ++i) {
      count += area(at(i, j), at(i + 1, j), at(i + 1, j + 1)) <= 0.0;
      count += area(at(i, j), at(i + 1, j + 1), at(i, j + 1)) <= 0.0;
    }
  return count;
}

/// Swaps the (u,v) of point (i, j) with its right neighbour's: both turn triangles over.
void swap_right(dbs::Result& r, int i, int j) {
  std::swap(r.u[at(i, j)], r.u[at(i + 1, j)]);
  std::swap(r.v[at(i, j)], r.v[at(i + 1, j)]);
}

const std::vector<std::pair<int, int>> kSwapped = {{8, 8}, {20, 9}, {31, 8}, {9, 20}, {25, 22}, {10, 31}, {30, 30}};

std::vector<std::size_t> untangle_all(Sheet& s, int threads) {
  const dbs::CloudIndex index(s.points);
  return dbs::untangle(s.result, s.points, index, std::vector<char>(s.points.size(), 1), threads);
}

void swapped_points_go_back(void**) {
  Sheet s = sheet();
  const dbs::Result truth = s.result;
  for (const auto& [i, j] : kSwapped) swap_right(s.result, i, j);
  const std::size_t before = turned_triangles(s.result);
  const std::vector<std::size_t> moved = untangle_all(s, 2);
  std::printf("%zu turned triangles before, %zu after, %zu points moved\n", before, turned_triangles(s.result), moved.size());
  assert_true(before >= 2 * kSwapped.size());
  assert_int_equal(turned_triangles(s.result), 0);
  assert_true(moved.size() >= 2 * kSwapped.size());
  // Every point within half a cell of its true (u,v); far from the swaps, untouched.
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    assert_true(std::hypot(s.result.u[k] - truth.u[k], s.result.v[k] - truth.v[k]) < 0.5 / kSide);
    const int i = static_cast<int>(k % kSide), j = static_cast<int>(k / kSide);
    bool near = false;
    for (const auto& [si, sj] : kSwapped) near = near || (std::abs(i - si) <= 3 && std::abs(j - sj) <= 3);
    if (!near) assert_true(s.result.u[k] == truth.u[k] && s.result.v[k] == truth.v[k]);
  }
}

void a_sound_map_is_left_alone(void**) {
  Sheet s = sheet();
  const dbs::Result truth = s.result;
  assert_int_equal(turned_triangles(s.result), 0);
  assert_true(untangle_all(s, 2).empty());
  assert_true(s.result.u == truth.u && s.result.v == truth.v);
  // Only candidates move: with none flagged, the tangle stays.
  for (const auto& [i, j] : kSwapped) swap_right(s.result, i, j);
  const dbs::Result tangled = s.result;
  const dbs::CloudIndex index(s.points);
  assert_true(dbs::untangle(s.result, s.points, index, std::vector<char>(s.points.size(), 0), 2).empty());
  assert_true(s.result.u == tangled.u && s.result.v == tangled.v);
}

void creases_are_not_judged(void**) {
  // Points on the crease line: their neighbourhoods span both faces, no tangent plane
  // orders them, and a swap there stays.
  // A swap on a face, far from the crease, is undone all the same.
  Sheet s = sheet(true);
  const dbs::Result truth = s.result;
  const int crease = kSide / 2 - 1;  // the last column with a <= 0.5, give or take the jitter
  swap_right(s.result, crease, 20);
  swap_right(s.result, 6, 10);
  const std::vector<std::size_t> moved = untangle_all(s, 2);
  for (std::size_t k : moved) {
    const int i = static_cast<int>(k % kSide);
    assert_true(std::abs(i - crease) > 2);  // none of the crease's points
  }
  assert_true(s.result.u[at(crease, 20)] == truth.u[at(crease + 1, 20)] && s.result.v[at(crease, 20)] == truth.v[at(crease + 1, 20)]);
  assert_true(s.result.u[at(crease + 1, 20)] == truth.u[at(crease, 20)] && s.result.v[at(crease + 1, 20)] == truth.v[at(crease, 20)]);
  assert_true(std::hypot(s.result.u[at(6, 10)] - truth.u[at(6, 10)], s.result.v[at(6, 10)] - truth.v[at(6, 10)]) < 0.5 / kSide);
  assert_true(std::hypot(s.result.u[at(7, 10)] - truth.u[at(7, 10)], s.result.v[at(7, 10)] - truth.v[at(7, 10)]) < 0.5 / kSide);
}

void invariant_to_threads_motion_and_scale(void**) {
  Sheet one = sheet(), two = sheet(), moved_scaled = sheet(false, 1000.0, Vec3(-3.0e4, 2.0e4, 5.0e3));
  for (Sheet* s : {&one, &two, &moved_scaled})
    for (const auto& [i, j] : kSwapped) swap_right(s->result, i, j);
  const std::vector<std::size_t> a = untangle_all(one, 1), b = untangle_all(two, 2), c = untangle_all(moved_scaled, 2);
  assert_true(a == b);
  assert_true(one.result.u == two.result.u && one.result.v == two.result.v);
  assert_true(a == c);
  for (std::size_t k = 0; k < one.points.size(); ++k) {
    assert_true(std::abs(one.result.u[k] - moved_scaled.result.u[k]) <= 1e-9);
    assert_true(std::abs(one.result.v[k] - moved_scaled.result.v[k]) <= 1e-9);
  }
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(swapped_points_go_back),
      cmocka_unit_test(a_sound_map_is_left_alone),
      cmocka_unit_test(creases_are_not_judged),
      cmocka_unit_test(invariant_to_threads_motion_and_scale),
  };
  return cmocka_run_group_tests_name("untangle", tests, nullptr, nullptr);
}
