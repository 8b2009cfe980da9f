// End-to-end tests of the recursive method: it reaches an accuracy one patch cannot, seams
// agree, every point gets one (u,v) without jumps across seams, holes / thick clouds /
// density changes do not fold, callbacks come in order and cancel cleanly, and the output does
// not depend on the thread count.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "analytic_clouds.hpp"
#include "boundary_io.hpp"
#include "cloud_index.hpp"
#include "cloud_io.hpp"
#include "error.hpp"
#include "parameterize.hpp"
#include "surface_projection.hpp"

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

Options recursive(int threads = 2) {
  Options o;
  o.relative_accuracy = 2e-4;
  o.max_level = 3;
  o.threads = threads;
  return o;
}

void shoe_last_needs_the_quadtree(void**) {
  const PointCloud cloud = load_cloud(DBS_TEST_DATA_DIR "/shoe_last.xyz");
  const Boundary boundary = load_boundary(DBS_TEST_DATA_DIR "/shoe_last_boundary.txt");
  Options o;
  o.accuracy = 0.1;
  o.max_level = 0;
  const Result one = parameterize(cloud, boundary, o);
  print_message("shoe last, one patch: %.4f\n", one.mean_distance);
  assert_true(one.mean_distance > 0.1);  // one patch at the largest grid cannot fit it
  assert_int_equal(one.patches.size(), 1);
  assert_int_equal(one.patches[0].grid.nu, o.max_grid);  // it grew to the largest grid first
  assert_int_equal(one.patches[0].grid.nv, o.max_grid);
  o.max_level = 4;
  const Result tree = parameterize(cloud, boundary, o);
  assert_true(tree.mean_distance <= 0.1);
  assert_true(tree.levels >= 2 && tree.levels <= 5);
  print_message("shoe last: one patch %.4f, quadtree %.4f with %d levels, %zu leaves\n", one.mean_distance, tree.mean_distance, tree.levels, tree.leaf_count());
}

/// The leaves next to `leaf` across its side `side`, sampled at `samples` points; every pair of
/// neighbouring leaves must evaluate to the same 3D points along their common edge.
double worst_seam_gap(const Result& r, int samples) {
  double worst = 0.0;
  for (const Patch& a : r.patches) {
    if (!a.is_leaf()) continue;
    for (int k = 1; k < samples; ++k) {
      const double t = static_cast<double>(k) / samples;
      // Right and top edges; the neighbour is the leaf on the other side (leaf_at sends seam
      // points to the upper leaf).
      if (a.rect.u1 < 1.0) {
        const double v = a.rect.v0 + t * (a.rect.v1 - a.rect.v0);
        const Patch& b = r.patches[r.leaf_at(a.rect.u1, v)];
        assert_true(b.rect.u0 == a.rect.u1);
        const Vec2 sa = a.rect.to_local(a.rect.u1, v), sb = b.rect.to_local(a.rect.u1, v);
        worst = std::max(worst, (a.surface.eval(sa.x(), sa.y()) - b.surface.eval(sb.x(), sb.y())).norm());
      }
      if (a.rect.v1 < 1.0) {
        const double u = a.rect.u0 + t * (a.rect.u1 - a.rect.u0);
        const Patch& b = r.patches[r.leaf_at(u, a.rect.v1)];
        assert_true(b.rect.v0 == a.rect.v1);
        const Vec2 sa = a.rect.to_local(u, a.rect.v1), sb = b.rect.to_local(u, a.rect.v1);
        worst = std::max(worst, (a.surface.eval(sa.x(), sa.y()) - b.surface.eval(sb.x(), sb.y())).norm());
      }
    }
  }
  return worst;
}

/// The bumpy field's random points, then points on the boundary polylines themselves
/// (from `first_side` on, four per step: bottom, right, top, left).
std::vector<Vec3> bumpy_points(const Boundary& boundary, std::size_t& first_side) {
  std::vector<Vec3> pts = random_points(bumpy_field(), 15000, 11);
  first_side = pts.size();
  for (int k = 1; k < 40; ++k) {
    const double t = k / 40.0;
    pts.push_back(boundary.bottom().at(t));
    pts.push_back(boundary.right().at(t));
    pts.push_back(boundary.top().at(t));
    pts.push_back(boundary.left().at(t));
  }
  return pts;
}

void repair_leaves_a_reached_cloud_as_it_is(void**) {
  // At this strict target 36 points on the bump's flanks are farther than 10x the target
  // from their leaf: the repair (on by default) fills their (u,v), but refitting their leaf
  // would move the surface away from most of its points, so the refit is not kept and they
  // go back to their feet: the result is the one without the repair, bit for bit, seams
  // shared exactly and every distance that of the surface at the point's (u,v).
  const Boundary boundary = boundary_of(bumpy_field(), 40);
  std::size_t first_side = 0;
  const std::vector<Vec3> pts = bumpy_points(boundary, first_side);
  const PointCloud cloud(pts);
  Options off = recursive();
  off.repair = 0;
  const Result r = parameterize(cloud, boundary, recursive()), plain = parameterize(cloud, boundary, off);
  std::printf("bumpy field: repaired %zu points, mean distance %.4g (without the repair %.4g)\n", r.repaired_points, r.mean_distance, plain.mean_distance);
  std::size_t far = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) far += plain.distance[i] > 10.0 * plain.accuracy && plain.distance[i] > plain.length_scale;
  assert_true(far >= 20);  // there is something the repair could take (36 today)
  assert_int_equal(r.repaired_points, 0);
  assert_true(r.u == plain.u && r.v == plain.v && r.distance == plain.distance && r.patch == plain.patch);
  assert_true(worst_seam_gap(r, 64) <= 1e-12 * boundary.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    assert_true(std::abs((r.evaluate(r.u[i], r.v[i]) - pts[i]).norm() - r.distance[i]) <= 1e-9 * boundary.size());
    assert_true(r.u[i] >= 0.0 && r.u[i] <= 1.0 && r.v[i] >= 0.0 && r.v[i] <= 1.0);
  }
  // Points on the boundary are never far from it: they keep their place on the sides.
  for (std::size_t i = first_side; i < pts.size(); i += 4) {
    assert_true(std::abs(r.v[i]) < 1e-9);
    assert_true(std::abs(r.u[i + 1] - 1.0) < 1e-9);
  }
}

void seams_agree_and_points_are_placed_once(void**) {
  // A2 itself: the repair (which gives some points a (u,v) other than their foot) is off.
  // Points on the boundary polylines themselves are included (the analytic sides differ
  // from their polylines by the chord error).
  const Boundary boundary = boundary_of(bumpy_field(), 40);
  std::size_t first_side = 0;
  const std::vector<Vec3> pts = bumpy_points(boundary, first_side);
  const PointCloud cloud(pts);
  Options options = recursive();
  options.repair = 0;
  const Result r = parameterize(cloud, boundary, options);
  assert_true(r.levels >= 2);
  assert_true(r.mean_distance <= r.accuracy);

  // The leaves tile [0,1]^2 exactly.
  double area = 0.0;
  for (const Patch& p : r.patches)
    if (p.is_leaf()) area += (p.rect.u1 - p.rect.u0) * (p.rect.v1 - p.rect.v0);
  assert_true(area == 1.0);
  assert_true(worst_seam_gap(r, 64) <= 1e-12 * boundary.size());

  assert_int_equal(r.u.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    assert_true(r.u[i] >= 0.0 && r.u[i] <= 1.0 && r.v[i] >= 0.0 && r.v[i] <= 1.0);
    assert_true(r.patch[i] >= 0 && r.patches[r.patch[i]].is_leaf());
    assert_true(r.patches[r.patch[i]].rect.contains(r.u[i], r.v[i]));
  }
  for (std::size_t i = first_side; i < pts.size(); i += 4) {
    assert_true(std::abs(r.v[i]) < 1e-9);
    assert_true(std::abs(r.u[i + 1] - 1.0) < 1e-9);
    assert_true(std::abs(r.v[i + 2] - 1.0) < 1e-9);
    assert_true(std::abs(r.u[i + 3]) < 1e-9);
  }

  // No jump across seams: nearest neighbours in 3D on different leaves stay near in (u,v).
  // The surface is a graph over the unit square with slopes below 1.2, so |d(u,v)| is at most
  // about |dp|; a point put on the wrong side of a seam would be off by a leaf's width.
  CloudIndex index(cloud.points());
  std::vector<std::size_t> nn;
  std::vector<double> d2;
  std::size_t crossing = 0;
  double worst_ratio = 0.0;
  for (std::size_t i = 0; i < first_side; ++i) {
    index.knn(pts[i], 2, nn, d2);
    const std::size_t j = nn[0] == i ? nn[1] : nn[0];
    if (r.patch[i] == r.patch[j] || d2[1] <= 0.0) continue;
    ++crossing;
    const double duv = std::hypot(r.u[i] - r.u[j], r.v[i] - r.v[j]);
    worst_ratio = std::max(worst_ratio, duv / (pts[i] - pts[j]).norm());
  }
  assert_true(crossing > 100);
  assert_true(worst_ratio < 3.0);

  // Each point's distance is the distance to the surface at its (u,v); the global evaluation
  // is the leaf's own surface, seams included (leaf_at picks the upper leaf there).
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double gap = (r.evaluate(r.u[i], r.v[i]) - pts[i]).norm();
    assert_true(std::abs(gap - r.distance[i]) <= 1e-9 * boundary.size());
  }
  for (const Patch& leaf : r.patches) {
    if (!leaf.is_leaf()) continue;
    for (double a : {0.0, 0.3, 1.0})
      for (double b : {0.0, 0.7, 1.0}) {
        const double u = leaf.rect.u0 + a * (leaf.rect.u1 - leaf.rect.u0), v = leaf.rect.v0 + b * (leaf.rect.v1 - leaf.rect.v0);
        const Vec2 s = leaf.rect.to_local(u, v);
        assert_true((r.evaluate(u, v) - leaf.surface.eval(s.x(), s.y())).norm() <= 1e-12 * boundary.size());
      }
  }
  // A2: no leaf whose subcloud holds a point comes closer to it than the leaf it was given.
  std::size_t checked = 0;
  for (const Patch& leaf : r.patches) {
    if (!leaf.is_leaf()) continue;
    SurfaceProjector projector(leaf.surface);
    for (std::size_t k = 0; k < leaf.subcloud.size(); k += 7) {
      const std::size_t i = leaf.subcloud[k];
      assert_true(projector.project(pts[i]).distance >= r.distance[i] - 1e-12 * boundary.size());
      ++checked;
    }
  }
  assert_true(checked > pts.size() / 7);
}

/// Points on a structured grid of analytic parameters (a_i, b_j), with the grid's triangles
/// as reference: a parameterization folds where a triangle's (u,v) orientation flips.
struct GridCloud {
  std::vector<Vec3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

/// Triangles join every `stride`-th grid node, so they can be made larger than the noise.
GridCloud grid_cloud(const Surface& s, const std::vector<double>& as, const std::vector<double>& bs, const std::function<bool(double, double)>& keep, double noise, unsigned seed, std::size_t stride = 1) {
  GridCloud g;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<long> id(as.size() * bs.size(), -1);
  for (std::size_t j = 0; j < bs.size(); ++j)
    for (std::size_t i = 0; i < as.size(); ++i) {
      if (!keep(as[i], bs[j])) continue;
      Vec3 p = s(as[i], bs[j]);
      if (noise > 0.0) {
        const double e = 1e-6;
        const Vec3 n = (s(as[i] + e, bs[j]) - s(as[i] - e, bs[j])).cross(s(as[i], bs[j] + e) - s(as[i], bs[j] - e)).normalized();
        p += noise * gauss(rng) * n;
      }
      id[j * as.size() + i] = static_cast<long>(g.points.size());
      g.points.push_back(p);
    }
  for (std::size_t j = 0; j + stride < bs.size(); j += stride)
    for (std::size_t i = 0; i + stride < as.size(); i += stride) {
      const std::size_t w = as.size();
      const long a = id[j * w + i], b = id[j * w + i + stride], c = id[(j + stride) * w + i], d = id[(j + stride) * w + i + stride];
      if (a < 0 || b < 0 || c < 0 || d < 0) continue;
      g.triangles.push_back({{std::size_t(a), std::size_t(b), std::size_t(d)}});
      g.triangles.push_back({{std::size_t(a), std::size_t(d), std::size_t(c)}});
    }
  return g;
}

std::vector<double> uniform(int n) {
  std::vector<double> t(n);
  for (int i = 0; i < n; ++i) t[i] = static_cast<double>(i) / (n - 1);
  return t;
}

std::size_t folded(const GridCloud& g, const Result& r) {
  std::size_t count = 0;
  for (const auto& t : g.triangles) {
    const double area = (r.u[t[1]] - r.u[t[0]]) * (r.v[t[2]] - r.v[t[0]]) - (r.u[t[2]] - r.u[t[0]]) * (r.v[t[1]] - r.v[t[0]]);
    if (!(area > 0.0)) ++count;
  }
  return count;
}

void large_hole_does_not_fold(void**) {
  const GridCloud g = grid_cloud(bumpy_field(), uniform(120), uniform(120), [](double a, double b) { return std::hypot(a - 0.45, b - 0.4) > 0.22; }, 0.0, 1);
  const Result r = parameterize(PointCloud(g.points), boundary_of(bumpy_field(), 40), recursive());
  assert_true(r.levels >= 2);
  assert_int_equal(folded(g, r), 0);
  assert_true(r.mean_distance <= r.accuracy);
}

void patches_over_a_hole_stay_empty_and_do_not_fold(void**) {
  // The ripples make the patches subdivide; the hole swallows whole patches,
  // which get no points and keep their parent's shape: not exactly, as their sides include
  // the parent's middle curves, projected onto the points around the hole.
  const Surface s = rippled_bumpy_field();
  const GridCloud g = grid_cloud(s, uniform(241), uniform(241), [](double a, double b) { return std::hypot(a - 0.4, b - 0.4) > 0.28; }, 0.0, 4, 2);
  const Boundary boundary = boundary_of(s, 40);
  Options o = recursive();
  // Tight enough that a patch lies over the hole alone: at 6e-4 the fit to the target
  // (fit_to_target.hpp) ends the quadtree before one does.
  o.accuracy = 2e-4;
  const Result r = parameterize(PointCloud(g.points), boundary, o);
  std::size_t empty = 0;
  double worst = 0.0;
  for (const Patch& p : r.patches) {
    if (p.point_count != 0) continue;
    ++empty;
    assert_true(p.is_leaf());  // nothing to refine
    assert_int_equal(p.iterations, 0);
    // Its surface is its parent's over its rectangle.
    const Patch& parent = r.patches[p.parent];
    for (double a : {0.1, 0.5, 0.9})
      for (double b : {0.2, 0.6}) {
        const double u = p.rect.u0 + a * (p.rect.u1 - p.rect.u0), v = p.rect.v0 + b * (p.rect.v1 - p.rect.v0);
        const Vec2 lc = p.rect.to_local(u, v), lp = parent.rect.to_local(u, v);
        worst = std::max(worst, (p.surface.eval(lc.x(), lc.y()) - parent.surface.eval(lp.x(), lp.y())).norm());
      }
  }
  print_message("%zu empty patches, up to %.2g from their parents\n", empty, worst);
  assert_true(worst <= 0.01 * boundary.size());
  assert_true(empty >= 1);
  assert_int_equal(folded(g, r), 0);
  assert_true(r.mean_distance <= r.accuracy);
}

void thick_cloud_does_not_fold(void**) {
  // Normal noise of 0.5% of the size; the target sits above what the noise allows. The
  // reference triangles join every 4th point (edges about 5 noise deviations long): finer
  // ones would fold in the cloud itself, whatever the parameterization.
  const double size = std::sqrt(2.0), noise = 0.005 * size;
  const Surface sharp = sharply_rippled_field();  // one patch cannot reach the target
  const GridCloud g = grid_cloud(sharp, uniform(109), uniform(109), [](double, double) { return true; }, noise, 2, 4);
  Options o = recursive();
  o.accuracy = noise;  // the mean absolute noise is 0.8 sigma
  const Result r = parameterize(PointCloud(g.points), boundary_of(sharp, 40), o);
  assert_true(r.levels >= 2);
  assert_int_equal(folded(g, r), 0);
  assert_true(r.mean_distance <= o.accuracy);
}

void density_change_does_not_fold(void**) {
  // Columns 30 times denser for a < 0.3 than beyond.
  std::vector<double> as;
  for (double a = 0.0; a < 0.3; a += 0.3 / 300) as.push_back(a);
  for (double a = 0.3; a < 1.0; a += 0.3 / 10) as.push_back(a);
  as.push_back(1.0);
  const GridCloud g = grid_cloud(bumpy_field(), as, uniform(60), [](double, double) { return true; }, 0.0, 3);
  Options o = recursive();
  o.relative_accuracy = 1e-4;
  // One patch does not reach the target, even fitted to its points (fit_to_target.hpp; with
  // 11 x 11 grids the fit meets it at the root). With 9 x 9 grids one reference triangle folds
  // here, with or without the fit.
  o.max_grid = 8;
  const Result r = parameterize(PointCloud(g.points), boundary_of(bumpy_field(), 40), o);
  std::printf("density change: %d levels, %zu leaves, mean distance %.3g, target %.3g\n", r.levels, r.leaf_count(), r.mean_distance, r.accuracy);
  assert_true(r.levels >= 2);
  assert_int_equal(folded(g, r), 0);
  assert_true(r.mean_distance <= r.accuracy);
}

void quadtree_is_invariant_to_scale_and_rigid_motion(void**) {
  // Every limit is relative (the accuracy to the cloud's box, the subcloud limits to the
  // child's box, both boxes in the frame of the corners; distances to the length scale), so
  // the same quadtree and (u,v) come out.
  const Surface s = bumpy_field();
  const Surface moved = [&](double a, double b) { return move_and_scale(s(a, b), 1000.0); };
  const Result a = parameterize(PointCloud(random_points(s, 8000, 19)), boundary_of(s, 40), recursive());
  const Result b = parameterize(PointCloud(random_points(moved, 8000, 19)), boundary_of(moved, 40), recursive());
  assert_true(a.levels >= 2);
  assert_int_equal(a.levels, b.levels);
  assert_int_equal(a.patches.size(), b.patches.size());
  for (std::size_t k = 0; k < a.patches.size(); ++k) {
    assert_int_equal(a.patches[k].point_count, b.patches[k].point_count);
    assert_int_equal(a.patches[k].grid.nu, b.patches[k].grid.nu);
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < a.u.size(); ++i) {
    assert_int_equal(a.patch[i], b.patch[i]);
    worst = std::max({worst, std::abs(a.u[i] - b.u[i]), std::abs(a.v[i] - b.v[i]), std::abs(a.distance[i] * 1000.0 - b.distance[i]) / 1000.0});
  }
  print_message("scaled and moved quadtree: (u,v) differ by %.2g\n", worst);
  assert_true(worst < 1e-9);
}

void thread_count_does_not_change_output(void**) {
  const PointCloud cloud(random_points(bumpy_field(), 12000, 13));
  const Boundary boundary = boundary_of(bumpy_field(), 40);
  const Result a = parameterize(cloud, boundary, recursive(1));
  const Result b = parameterize(cloud, boundary, recursive(2));
  const Result c = parameterize(cloud, boundary, recursive(5));
  assert_true(a.levels >= 2);
  for (const Result* o : {&b, &c}) {
    assert_int_equal(a.patches.size(), o->patches.size());
    assert_memory_equal(a.u.data(), o->u.data(), a.u.size() * sizeof(double));
    assert_memory_equal(a.v.data(), o->v.data(), a.v.size() * sizeof(double));
    assert_memory_equal(a.distance.data(), o->distance.data(), a.distance.size() * sizeof(double));
    assert_memory_equal(a.patch.data(), o->patch.data(), a.patch.size() * sizeof(std::int32_t));
  }
}

void callbacks_in_order_and_cancel_everywhere(void**) {
  const PointCloud cloud(random_points(bumpy_field(), 4000, 17));
  const Boundary boundary = boundary_of(bumpy_field(), 30);
  Options o = recursive();
  std::vector<double> fractions;
  std::vector<std::string> stages;
  std::vector<std::pair<int, std::size_t>> levels;
  o.progress = [&](double f, const char* stage) {
    fractions.push_back(f);
    stages.emplace_back(stage);
    return false;
  };
  o.on_level = [&](int level, const std::vector<const Patch*>& patches) {
    levels.emplace_back(level, patches.size());
    for (const Patch* p : patches) assert_int_equal(p->level, level);
    return false;
  };
  const Result r = parameterize(cloud, boundary, o);
  assert_true(r.levels >= 2);
  assert_true(fractions.back() == 1.0);
  assert_string_equal(stages.back().c_str(), "done");
  for (std::size_t k = 1; k < fractions.size(); ++k) assert_true(fractions[k] >= fractions[k - 1]);
  assert_int_equal(levels.size(), r.levels);
  for (int l = 0; l < r.levels; ++l) {
    assert_int_equal(levels[l].first, l);
    const auto count = std::count_if(r.patches.begin(), r.patches.end(), [&](const Patch& p) { return p.level == l; });
    assert_int_equal(levels[l].second, count);
  }
  // Cancelling at the first call of every stage, at the last call and after every level ends
  // in Error(Cancelled) (leaks would show under ASan).
  std::vector<std::size_t> stops{fractions.size() - 1};
  for (std::size_t k = 0; k < stages.size(); ++k)
    if (k == 0 || stages[k] != stages[k - 1]) stops.push_back(k);
  assert_true(stops.size() >= 6);  // index, evolve, subdivide, evolve, ..., parameterize, done
  for (std::size_t stop : stops) {
    std::size_t seen = 0;
    Options c = o;
    c.on_level = nullptr;
    c.progress = [&](double, const char*) { return seen++ == stop; };
    try {
      parameterize(cloud, boundary, c);
      fail_msg("not cancelled at progress call %zu", stop);
    } catch (const Error& e) {
      assert_int_equal(static_cast<int>(e.code()), static_cast<int>(ErrorCode::Cancelled));
    }
  }
  for (int stop = 0; stop < r.levels; ++stop) {
    Options c = o;
    c.progress = nullptr;
    c.on_level = [&](int level, const std::vector<const Patch*>&) { return level == stop; };
    try {
      parameterize(cloud, boundary, c);
      fail_msg("not cancelled at level %d", stop);
    } catch (const Error& e) {
      assert_int_equal(static_cast<int>(e.code()), static_cast<int>(ErrorCode::Cancelled));
    }
  }
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(shoe_last_needs_the_quadtree),
      cmocka_unit_test(seams_agree_and_points_are_placed_once),
      cmocka_unit_test(repair_leaves_a_reached_cloud_as_it_is),
      cmocka_unit_test(large_hole_does_not_fold),
      cmocka_unit_test(patches_over_a_hole_stay_empty_and_do_not_fold),
      cmocka_unit_test(thick_cloud_does_not_fold),
      cmocka_unit_test(density_change_does_not_fold),
      cmocka_unit_test(quadtree_is_invariant_to_scale_and_rigid_motion),
      cmocka_unit_test(thread_count_does_not_change_output),
      cmocka_unit_test(callbacks_in_order_and_cancel_everywhere),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
