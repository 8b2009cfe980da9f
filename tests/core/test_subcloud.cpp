// Distribution of a parent's subcloud among four children (algorithm A4): the children are
// the quarters of the unit square, so every point's distance to each child is known in
// closed form and the expected membership of every point can be computed exactly.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <utility>

#include "corner_frame.hpp"
#include "error.hpp"
#include "subcloud.hpp"
#include "surface_projection.hpp"

// cmocka last: its fail() macro would clash with dbs::fail and <ios>. It is a C library.
extern "C" {
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
}

using namespace dbs;

namespace {

constexpr double kNear = 0.25, kOwn = 0.05;
// Bounding-box diagonal of a flat 0.5 x 0.5 quarter.
const double kDiagonal = std::sqrt(0.5);

/// The quarter [u0,u0+1/2] x [v0,v0+1/2] of the unit square in the plane z = 0, its sides
/// sampled with a few vertices.
BaseSurface quarter(double u0, double v0) {
  auto side = [](Vec3 a, Vec3 b) {
    std::vector<Vec3> pts;
    for (int k = 0; k <= 4; ++k) pts.push_back(a + (k / 4.0) * (b - a));
    return pts;
  };
  const Vec3 p00(u0, v0, 0), p10(u0 + 0.5, v0, 0), p01(u0, v0 + 0.5, 0), p11(u0 + 0.5, v0 + 0.5, 0);
  return BaseSurface(Boundary(side(p00, p10), side(p10, p11), side(p01, p11), side(p00, p01)));
}

struct Children {
  BaseSurface s[4] = {quarter(0, 0), quarter(0.5, 0), quarter(0, 0.5), quarter(0.5, 0.5)};
  std::array<const BaseSurface*, 4> pointers() const { return {{&s[0], &s[1], &s[2], &s[3]}}; }
};

/// Exact distance of p to child i (the nearest point of the flat quarter).
double distance_to_child(const Vec3& p, int i) {
  const double u0 = (i % 2) * 0.5, v0 = (i / 2) * 0.5;
  const double dx = std::max({u0 - p.x(), 0.0, p.x() - (u0 + 0.5)});
  const double dy = std::max({v0 - p.y(), 0.0, p.y() - (v0 + 0.5)});
  return std::sqrt(dx * dx + dy * dy + p.z() * p.z());
}

/// A4 membership from exact distances; `ambiguous` is set when a distance is within `margin`
/// of a limit or a tie decides, where the projector's rounding may legitimately flip it.
unsigned expected_mask(const Vec3& p, double margin, bool& ambiguous) {
  double d[4];
  for (int i = 0; i < 4; ++i) d[i] = distance_to_child(p, i);
  ambiguous = false;
  int owner = -1, nearest = 0;
  unsigned mask = 0;
  for (int i = 0; i < 4; ++i) {
    const double own = kOwn * kDiagonal, near = kNear * kDiagonal;
    if (std::abs(d[i] - own) < margin || std::abs(d[i] - near) < margin) ambiguous = true;
    if (d[i] <= own && (owner < 0 || d[i] < d[owner])) owner = i;
    if (d[i] <= near) mask |= 1u << i;
    if (d[i] < d[nearest]) nearest = i;
  }
  for (int i = 0; i < 4; ++i) {
    if (i != nearest && std::abs(d[i] - d[nearest]) < margin && (d[i] <= kOwn * kDiagonal || mask == 0)) ambiguous = true;
  }
  if (owner >= 0) return 1u << owner;
  return mask == 0 ? 1u << nearest : mask;
}

/// Points on a jittered grid over [-0.1,1.1]^2 in layers at several heights: z = 0 (each
/// point in exactly its quarter), 0.02 (< own: owned), -0.1 (between own and near: shared
/// near the seams) and 0.3 (beyond near: only the nearest child).
std::vector<Vec3> layered_cloud() {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  std::vector<Vec3> pts;
  for (double z : {0.0, 0.02, -0.1, 0.3}) {
    for (int j = 0; j < 37; ++j) {
      for (int i = 0; i < 37; ++i) pts.emplace_back(-0.1 + (i + 0.5 + jitter(rng)) * 1.2 / 37, -0.1 + (j + 0.5 + jitter(rng)) * 1.2 / 37, z);
    }
  }
  // Hand-placed cases (indices from the end): deep inside child 0; inside child 1 close to
  // the seam with child 0 (both within "own": the nearest, child 1, owns it); above the seam
  // between own and near (shared by 0 and 1); far above child 0 (near no child: nearest).
  pts.emplace_back(0.2, 0.2, 0.0);
  pts.emplace_back(0.51, 0.25, 0.0);
  pts.emplace_back(0.45, 0.2, 0.1);
  pts.emplace_back(0.25, 0.25, 1.0);
  return pts;
}

std::vector<unsigned> masks_of(const std::array<PointList, 4>& parts, std::size_t n) {
  std::vector<unsigned> mask(n, 0);
  for (int i = 0; i < 4; ++i) {
    for (std::size_t p : parts[i]) mask[p] |= 1u << i;
  }
  return mask;
}

void points_join_children_by_the_a4_rules(void**) {
  const std::vector<Vec3> pts = layered_cloud();
  const Children children;
  // The parent's subcloud skips every seventh layer point (not the four hand-placed ones):
  // those must appear in no child.
  const std::size_t n = pts.size();
  auto skipped = [n](std::size_t k) { return k + 4 < n && k % 7 == 3; };
  PointList parent;
  for (std::size_t k = 0; k < n; ++k) {
    if (!skipped(k)) parent.push_back(static_cast<std::uint32_t>(k));
  }
  const auto parts = split_subcloud(pts, parent, children.pointers(), kNear, kOwn, 2);
  const std::vector<unsigned> mask = masks_of(parts, pts.size());

  std::size_t checked = 0, ambiguous_count = 0, shared = 0, mismatches = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (skipped(k)) {
      assert_int_equal(mask[k], 0);
      continue;
    }
    assert_true(mask[k] != 0);  // union of the children == parent
    if (mask[k] & (mask[k] - 1)) ++shared;
    bool ambiguous = false;
    const unsigned expected = expected_mask(pts[k], 1e-7, ambiguous);
    if (ambiguous) {
      ++ambiguous_count;
      continue;
    }
    ++checked;
    if (mask[k] != expected) {
      ++mismatches;
      std::printf("point %zu (%g %g %g): mask %u, expected %u\n", k, pts[k].x(), pts[k].y(), pts[k].z(), mask[k], expected);
    }
  }
  std::printf("subcloud: %zu points, %zu checked against exact distances, %zu ambiguous, %zu shared, sizes %zu %zu %zu %zu\n", parent.size(), checked, ambiguous_count, shared, parts[0].size(), parts[1].size(), parts[2].size(), parts[3].size());
  assert_int_equal(mismatches, 0);
  assert_true(checked + ambiguous_count == parent.size());
  assert_true(ambiguous_count < 50);
  assert_true(shared > 100);  // the z = -0.1 layer shares a band along each seam

  assert_int_equal(mask[n - 4], 1u);         // deep inside child 0: only child 0
  assert_int_equal(mask[n - 3], 2u);         // inside child 1 next to the seam: only child 1
  assert_int_equal(mask[n - 2], 1u | 2u);    // above the seam: shared by children 0 and 1
  assert_int_equal(mask[n - 1], 1u);         // near no child: the nearest, child 0

  // Lists ascend (the parent's order), hold no duplicates and only parent points.
  for (int i = 0; i < 4; ++i) {
    assert_true(std::is_sorted(parts[i].begin(), parts[i].end()));
    assert_true(std::adjacent_find(parts[i].begin(), parts[i].end()) == parts[i].end());
  }
}

void thread_count_does_not_change_the_split(void**) {
  const std::vector<Vec3> pts = layered_cloud();
  const Children children;
  PointList parent(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k) parent[k] = static_cast<std::uint32_t>(k);
  const auto one = split_subcloud(pts, parent, children.pointers(), kNear, kOwn, 1);
  for (int threads : {2, 3}) {
    const auto many = split_subcloud(pts, parent, children.pointers(), kNear, kOwn, threads);
    for (int i = 0; i < 4; ++i) assert_true(one[i] == many[i]);
  }
}

/// The quarter at (u0, v0) lifted by a ripple of `amplitude` with 31.5 waves across u, on a
/// displacement grid of `sites` x `sites` (0: the flat quarter).
BaseSurface rippled_quarter(double u0, double v0, double amplitude, int sites) {
  const BaseSurface flat = quarter(u0, v0);
  if (sites == 0) return flat;
  Grid grid = flat.sample(sites, sites);
  for (int j = 1; j + 1 < sites; ++j)
    for (int i = 1; i + 1 < sites; ++i) grid(i, j).z() += amplitude * std::sin(2 * M_PI * 31.5 * grid.u(i)) * std::sin(M_PI * grid.v(j));
  return BaseSurface(flat.boundary(), grid);
}

/// A4 from the distances of every point projected onto every child (or to its nearest
/// sample where that is nearer), with the children's limits measured as split_subcloud
/// measures them.
std::vector<unsigned> masks_by_projection(const std::vector<Vec3>& pts, const std::array<const BaseSurface*, 4>& children) {
  std::vector<std::unique_ptr<SurfaceProjector>> projectors;
  std::array<double, 4> own, near;
  for (int i = 0; i < 4; ++i) {
    projectors.push_back(std::make_unique<SurfaceProjector>(*children[i], FootPrecision::Distance));
    CornerFrameBox box(children[i]->boundary());
    const int samples = std::max(33, 4 * children[i]->displacement_sites() + 1);
    for (const Vec3& p : children[i]->sample(samples, samples).points) box.extend(p);
    for (int side = 0; side < 4; ++side)
      for (const Vec3& p : children[i]->boundary().side(static_cast<Side>(side)).points()) box.extend(p);
    own[i] = kOwn * box.diagonal();
    near[i] = kNear * box.diagonal();
  }
  std::vector<unsigned> masks;
  for (const Vec3& p : pts) {
    double d[4];
    for (int i = 0; i < 4; ++i) d[i] = std::min(projectors[i]->project(p).distance, projectors[i]->sample_distance(p));
    int owner = -1, nearest = 0;
    unsigned mask = 0;
    for (int i = 0; i < 4; ++i) {
      if (d[i] <= own[i] && (owner < 0 || d[i] < d[owner])) owner = i;
      if (d[i] <= near[i]) mask |= 1u << i;
      if (d[i] < d[nearest]) nearest = i;
    }
    masks.push_back(owner >= 0 ? 1u << owner : mask == 0 ? 1u << nearest : mask);
  }
  return masks;
}

// The split decides most points on bounds of their distances (boxes, nearest samples less
// the sample cover) and must still give every point the membership that projecting it onto
// all four children gives: on a child whose ripples the projector's 64 x 64 samples do not
// resolve (100 sites a side; a cover from the samples alone let 792 of these points through
// wrongly) and on one they do (9 sites, a bump between the samples).
void bounds_give_the_memberships_of_projections(void**) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(0.0, 0.5), z(-0.25, 0.25);
  std::vector<Vec3> pts;
  PointList parent;
  for (std::uint32_t k = 0; k < 20000; ++k) {
    pts.emplace_back(u(rng), u(rng), z(rng));
    parent.push_back(k);
  }
  for (const auto& [amplitude, sites] : {std::pair<double, int>{0.03, 100}, {0.05, 9}}) {
    const BaseSurface child[4] = {rippled_quarter(0, 0, amplitude, sites), quarter(0.5, 0), quarter(0, 0.5), quarter(0.5, 0.5)};
    const std::array<const BaseSurface*, 4> children{{&child[0], &child[1], &child[2], &child[3]}};
    const std::vector<unsigned> expected = masks_by_projection(pts, children);
    const std::vector<unsigned> got = masks_of(split_subcloud(pts, parent, children, kNear, kOwn, 2), pts.size());
    std::size_t mismatches = 0, shared = 0;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      mismatches += got[k] != expected[k];
      shared += (expected[k] & (expected[k] - 1)) != 0;
    }
    std::printf("rippled child (%d sites): %zu mismatches, %zu shared points\n", sites, mismatches, shared);
    assert_int_equal(mismatches, 0);
    assert_true(shared > 1000);  // the points off the sheets are shared: the rules all act
  }
}

void bad_arguments_are_named(void**) {
  const std::vector<Vec3> pts = {{0.1, 0.1, 0}, {0.9, 0.9, 0}};
  const Children children;
  try {
    split_subcloud(pts, {0, 2}, children.pointers(), kNear, kOwn, 1);
    fail_msg("index 2 accepted");
  } catch (const Error& e) {
    assert_int_equal(static_cast<int>(e.code()), static_cast<int>(ErrorCode::OutOfRange));
    assert_non_null(std::strstr(e.what(), "parent_subcloud[1]"));
  }
  try {
    split_subcloud(pts, {0, 1}, children.pointers(), 0.05, 0.25, 1);
    fail_msg("own > near accepted");
  } catch (const Error& e) {
    assert_int_equal(static_cast<int>(e.code()), static_cast<int>(ErrorCode::InvalidArgument));
  }
  std::array<const BaseSurface*, 4> missing = children.pointers();
  missing[2] = nullptr;
  try {
    split_subcloud(pts, {0, 1}, missing, kNear, kOwn, 1);
    fail_msg("null child accepted");
  } catch (const Error& e) {
    assert_int_equal(static_cast<int>(e.code()), static_cast<int>(ErrorCode::InvalidArgument));
    assert_non_null(std::strstr(e.what(), "child 2"));
  }
  // An empty parent subcloud gives four empty children.
  const auto parts = split_subcloud(pts, {}, children.pointers(), kNear, kOwn, 2);
  for (const auto& part : parts) assert_true(part.empty());
}

}  // namespace

int main() {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(points_join_children_by_the_a4_rules),
      cmocka_unit_test(thread_count_does_not_change_the_split),
      cmocka_unit_test(bounds_give_the_memberships_of_projections),
      cmocka_unit_test(bad_arguments_are_named),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
