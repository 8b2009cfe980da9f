// Checks of the fold-free work's measuring tools themselves (tests/support/fold_shapes.*,
// meshless_reference.*), not of the method: the shapes are what they claim (point counts,
// boundary sides equal to S on the square's sides with bitwise shared corners, noise of the
// stated sigma along the normal, the overhang of the mushroom), the fold count sees 0 folds
// under the true parameters and every triangle under a mirrored map, collapses count as
// folds, the distance to the surface is right, noise can be added to any shape, and the
// meshless reference does not fold the noise-free saddle.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "fold_shapes.hpp"
#include "meshless_reference.hpp"

// cmocka last: its fail() macro would hide dbs::fail.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

using namespace dbs_folds;

namespace {

bool same_point(const std::vector<double>& a, std::size_t i, const std::vector<double>& b, std::size_t j) {
  return std::memcmp(&a[3 * i], &b[3 * j], 3 * sizeof(double)) == 0;
}

void shapes_have_their_size_and_boundary(void**) {
  const std::vector<FoldShape> shapes = all_fold_shapes();
  assert_int_equal(shapes.size(), fold_shape_names().size());
  for (const FoldShape& s : shapes) {
    const std::size_t n = s.count();
    assert_true(n >= 3000 && n <= 5000);
    assert_int_equal(s.xyz.size(), 3 * n);
    assert_int_equal(s.uv_true.size(), 2 * n);
    assert_int_equal(s.grid_a * s.grid_b, n);
    for (double x : s.xyz) assert_true(std::isfinite(x));
    for (double t : s.uv_true) assert_true(t > 0.0 && t < 1.0);
    // Most grid triangles survive the 10-degree filter, all of them well formed; the more
    // closed sphere caps squeeze the corners of the square onto their small rim, and the
    // filter drops 5% (300 degrees) and 16% (330 degrees) of their triangles there.
    const std::size_t cells = 2 * (s.grid_a - 1) * (s.grid_b - 1);
    const double survive = s.name.rfind("sphere-cap-", 0) == 0 ? 0.8 : 0.95;
    assert_true(s.triangle_count() >= survive * cells && s.triangle_count() <= cells);
    for (int index : s.triangles) assert_true(index >= 0 && static_cast<std::size_t>(index) < n);
    const std::vector<double>* sides[4] = {&s.bottom, &s.right, &s.top, &s.left};
    for (const std::vector<double>* side : sides) assert_int_equal(side->size(), 3 * kBoundaryPoints);
    const std::size_t last = kBoundaryPoints - 1;
    assert_true(same_point(s.bottom, 0, s.left, 0));
    assert_true(same_point(s.bottom, last, s.right, 0));
    assert_true(same_point(s.top, 0, s.left, last));
    assert_true(same_point(s.top, last, s.right, last));
    // The sides are S on the square's sides, oriented as dbs.h wants.
    for (std::size_t k = 0; k <= last; k += 25) {
      const double t = static_cast<double>(k) / last;
      const Point3 expect[4] = {s.surface(t, 0), s.surface(1, t), s.surface(t, 1), s.surface(0, t)};
      for (int side = 0; side < 4; ++side) {
        for (int c = 0; c < 3; ++c) assert_true(std::abs((*sides[side])[3 * k + c] - expect[side][c]) <= 1e-12 * s.diagonal);
      }
    }
  }
}

void shapes_are_deterministic(void**) {
  const FoldShape a = fingers(0.002), b = fingers(0.002);
  assert_true(a.xyz == b.xyz && a.uv_true == b.uv_true && a.triangles == b.triangles);
  // The noise moves the points but not their parameters or the triangles.
  const FoldShape clean = fingers();
  assert_true(clean.uv_true == a.uv_true && clean.triangles == a.triangles);
  assert_true(clean.xyz != a.xyz);
}

void reference_triangles_fold_only_when_mirrored(void**) {
  for (const FoldShape& s : all_fold_shapes()) {
    const FoldCount own = fold_share(s.uv_true, s.triangles);
    assert_int_equal(own.triangles, s.triangle_count());
    assert_int_equal(own.folded, 0);
    std::vector<double> mirrored = s.uv_true;
    for (std::size_t i = 0; i < s.count(); ++i) mirrored[2 * i] = 1.0 - mirrored[2 * i];
    const FoldCount flipped = fold_share(mirrored, s.triangles);
    assert_int_equal(flipped.folded, flipped.triangles);
    assert_int_equal(flipped.inverted, flipped.triangles);
    assert_true(flipped.share == 1.0);
  }
}

void collapsed_triangles_count_as_folds(void**) {
  const FoldShape s = saddle();
  std::vector<double> uv = s.uv_true;
  // Collapse every point of the first triangle onto one (u,v): it and its neighbours sharing
  // two of those points have zero area.
  const int* t = &s.triangles[0];
  for (int c = 1; c < 3; ++c) {
    uv[2 * t[c]] = uv[2 * t[0]];
    uv[2 * t[c] + 1] = uv[2 * t[0] + 1];
  }
  const FoldCount count = fold_share(uv, s.triangles);
  assert_true(count.collapsed >= 1 && count.folded == count.inverted + count.collapsed);
  std::size_t zero = 0;
  for (std::size_t k = 0; k < s.triangle_count(); ++k) {
    if (signed_uv_area(uv, s.triangles[3 * k], s.triangles[3 * k + 1], s.triangles[3 * k + 2]) <= 0.0) ++zero;
  }
  assert_int_equal(count.folded, zero);
  // Ten separate unit right triangles, the last one shrunk: to 1e-2 of the others' area it
  // is not folded, to 1e-4 (positive, below 1e-3 of the median) it is a collapse.
  for (double factor : {1e-2, 1e-4}) {
    std::vector<double> tens;
    std::vector<int> ten_triangles;
    for (int k = 0; k < 10; ++k) {
      const double scale = k == 9 ? std::sqrt(factor) : 1.0;
      const double corner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
      for (const auto& c : corner) {
        tens.push_back(2.0 * k + scale * c[0]);
        tens.push_back(scale * c[1]);
        ten_triangles.push_back(static_cast<int>(ten_triangles.size()));
      }
    }
    const FoldCount c = fold_share(tens, ten_triangles);
    assert_int_equal(c.triangles, 10);
    assert_int_equal(c.folded, factor == 1e-4 ? 1 : 0);
    assert_int_equal(c.collapsed, c.folded);
  }
  assert_int_equal(fold_share(uv, {}).triangles, 0);
}

void noise_has_its_sigma_along_the_normal(void**) {
  const FoldShape noisy = saddle(kSaddleNoise), clean = saddle();
  assert_true(std::abs(noisy.noise_sigma - kSaddleNoise * noisy.diagonal) <= 1e-15);
  assert_true(clean.noise_sigma == 0.0);
  // Offsets along the normal: their signed lengths have the sample sigma and mean ~0.
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < noisy.count(); ++i) {
    const Point3 n = surface_normal(noisy.surface, noisy.uv_true[2 * i], noisy.uv_true[2 * i + 1]);
    double along = 0.0, off = 0.0;
    for (int c = 0; c < 3; ++c) along += (noisy.xyz[3 * i + c] - clean.xyz[3 * i + c]) * n[c];
    for (int c = 0; c < 3; ++c) off = std::max(off, std::abs(noisy.xyz[3 * i + c] - clean.xyz[3 * i + c] - along * n[c]));
    assert_true(off <= 1e-9 * noisy.diagonal);
    sum += along;
    sum2 += along * along;
  }
  const double mean = sum / noisy.count(), sigma = std::sqrt(sum2 / noisy.count() - mean * mean);
  assert_true(std::abs(sigma / noisy.noise_sigma - 1.0) < 0.05);
  assert_true(std::abs(mean) < 0.1 * noisy.noise_sigma);
  // The noisy points' distance to the surface: about sigma sqrt(2/pi); the clean ones' 0.
  const double expected = noisy.noise_sigma * std::sqrt(2.0 / M_PI);
  assert_true(std::abs(mean_distance_to_surface(noisy, noisy.xyz) / expected - 1.0) < 0.05);
  assert_true(mean_distance_to_surface(clean, clean.xyz) < 1e-12 * clean.diagonal);
  // The rippled field's noise stays below a third of the ripples.
  const FoldShape ripples = rippled(kRippledNoise);
  assert_true(ripples.noise_sigma > 0.0 && ripples.noise_sigma < kRippleAmplitude / 3.0);
}

void noise_added_to_any_shape(void**) {
  // fold_shape(name, density, noise): the same points, parameters and triangles as the clean
  // shape, moved along the normal with the sigma asked for (named with it); a shape noisier of
  // its own keeps its noise and name; the noise must lie in [0, 0.05].
  const FoldShape clean = fold_shape("mushroom", 1.5), noisy = fold_shape("mushroom", 1.5, 0.004);
  assert_string_equal(noisy.name.c_str(), "mushroom-noise0.004");
  assert_true(noisy.uv_true == clean.uv_true && noisy.triangles == clean.triangles && noisy.diagonal == clean.diagonal);
  assert_true(std::abs(noisy.noise_sigma - 0.004 * noisy.diagonal) <= 1e-15);
  const double expected = noisy.noise_sigma * std::sqrt(2.0 / M_PI);
  assert_true(std::abs(mean_distance_to_surface(noisy, noisy.xyz) / expected - 1.0) < 0.05);
  const FoldShape own = fold_shape("saddle-noisy", 1.0, 0.001);
  assert_string_equal(own.name.c_str(), "saddle-noisy");
  assert_true(std::abs(own.noise_sigma - kSaddleNoise * own.diagonal) <= 1e-15);
  assert_string_equal(fold_shape("saddle-noisy", 1.0, 0.01).name.c_str(), "saddle-noisy-noise0.01");
  assert_true(fold_shape("cone", 1.0, 0.0).xyz == fold_shape("cone").xyz);
  for (double bad : {-0.001, 0.051, std::nan("")}) {
    bool refused = false;
    try {
      fold_shape("cone", 1.0, bad);
    } catch (const std::invalid_argument&) {
      refused = true;
    }
    assert_true(refused);
  }
  // A call refused after the noise was set (an unknown shape, a density out of range) leaves
  // no noise behind for the next shape built on this thread.
  for (const auto& [name, density] : {std::pair<const char*, double>{"no-such-shape", 1.0}, {"cone", 2000.0}}) {
    bool refused = false;
    try {
      fold_shape(name, density, 0.004);
    } catch (const std::invalid_argument&) {
      refused = true;
    }
    assert_true(refused);
    assert_true(fold_shape("cone").noise_sigma == 0.0);
  }
}

void distance_to_surface_is_exact_off_the_surface(void**) {
  // Points moved 0.01 along the normal of the mushroom's cap, rim and stem are 0.01 away
  // (their nearest surface point is where they came from: the surface's radii of curvature
  // there are >= 0.03).
  const FoldShape s = mushroom();
  const SurfaceDistance distance(s.surface);
  int tested = 0;
  for (double r : {0.02, 0.1, 0.16, 0.24, 0.4}) {
    for (double angle : {0.3, 2.0, 4.4}) {
      const double a = 0.5 + r * std::cos(angle), b = 0.5 + r * std::sin(angle);
      const Point3 p = s.surface(a, b), n = surface_normal(s.surface, a, b);
      for (double offset : {0.01, -0.01}) {
        const Point3 q{p[0] + offset * n[0], p[1] + offset * n[1], p[2] + offset * n[2]};
        assert_true(std::abs(distance(q) - 0.01) < 1e-6);
        ++tested;
      }
    }
  }
  assert_int_equal(tested, 30);
}

void hard_shapes_are_hard(void**) {
  // The mushroom overhangs: a share of its surface faces down, away from the plate's normal.
  const FoldShape m = mushroom();
  std::size_t down = 0;
  for (std::size_t i = 0; i < m.count(); ++i) {
    if (surface_normal(m.surface, m.uv_true[2 * i], m.uv_true[2 * i + 1])[2] < -0.5) ++down;
  }
  assert_true(down > m.count() / 50);
  // The dome is 3 times taller than wide, the fingers 3 to 5 times.
  const FoldShape dome = tall_dome();
  double top = 0.0;
  for (std::size_t i = 0; i < dome.count(); ++i) top = std::max(top, dome.xyz[3 * i + 2]);
  assert_true(top > 0.55 && top <= 0.6);
  const FoldShape f = fingers();
  for (const Point3 centre : {Point3{0.3, 0.3, 0.20}, Point3{0.9, 0.3, 0.25}, Point3{0.6, 0.72, 0.29}}) {
    const Point3 tip = f.surface(centre[0] / 1.2, centre[1]);
    assert_true(std::abs(tip[2] - centre[2]) < 1e-12);
    assert_true(tip[2] / 0.06 >= 3.0 && tip[2] / 0.06 <= 5.0);
  }
  // The sphere cap's rim is the circle at polar angle 135 degrees.
  const FoldShape cap = sphere_cap();
  for (std::size_t k = 0; k < cap.bottom.size() / 3; ++k) assert_true(std::abs(cap.bottom[3 * k + 2] + std::sqrt(0.5)) < 1e-12);
  // The open box's rim is at the walls' top, the floor at z = 0.
  const FoldShape box = open_box();
  assert_true(box.surface(0.5, 0.5)[2] == 0.0 && std::abs(box.left[3 * 7 + 2] - 0.4) < 1e-12);
}

void meshless_reference_does_not_fold_the_saddle(void**) {
  const FoldShape s = saddle();
  const MeshlessReference r = meshless_reference(s);
  assert_int_equal(r.uv.size(), 2 * s.count());
  assert_true(r.fixed_count > 200);
  for (std::size_t i = 0; i < s.count(); ++i) {
    assert_true(r.uv[2 * i] >= 0.0 && r.uv[2 * i] <= 1.0 && r.uv[2 * i + 1] >= 0.0 && r.uv[2 * i + 1] <= 1.0);
    // Fixed points sit on the square's sides.
    if (r.fixed[i]) {
      const double u = r.uv[2 * i], v = r.uv[2 * i + 1];
      assert_true(u == 0.0 || u == 1.0 || v == 0.0 || v == 1.0);
    }
  }
  assert_int_equal(fold_share(r.uv, s.triangles).folded, 0);
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(shapes_have_their_size_and_boundary),
      cmocka_unit_test(shapes_are_deterministic),
      cmocka_unit_test(reference_triangles_fold_only_when_mirrored),
      cmocka_unit_test(collapsed_triangles_count_as_folds),
      cmocka_unit_test(noise_has_its_sigma_along_the_normal),
      cmocka_unit_test(noise_added_to_any_shape),
      cmocka_unit_test(distance_to_surface_is_exact_off_the_surface),
      cmocka_unit_test(hard_shapes_are_hard),
      cmocka_unit_test(meshless_reference_does_not_fold_the_saddle),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
