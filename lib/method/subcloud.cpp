#include "subcloud.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>

#include <Eigen/LU>

#include "corner_frame.hpp"
#include "error.hpp"
#include "parallel.hpp"
#include "surface_projection.hpp"

namespace dbs {

namespace {

/// Samples per side used to bound a child surface (its bounding box is that of the surface,
/// which may bulge beyond the box of its boundary).
constexpr int kBoundsSamples = 33;
/// The sampled box is grown by this fraction of its diagonal so that it holds the surface
/// between the samples too; the distance to it is then a lower bound of the distance to the
/// surface (the chord error of 32 intervals is far below this even on a half cylinder).
constexpr double kBoxPadding = 0.02;

/// One child as A4 sees it: its projector, its limits, a box around its surface and the
/// affine map of its corners that guesses a point's parameters.
struct ChildTest {
  std::unique_ptr<SurfaceProjector> projector;
  Box3 box;           // padded
  double near_limit;  // near x the child's bounding-box diagonal
  double own_limit;   // own x that diagonal
  /// p ~ centre + (s - 1/2) across_u + (t - 1/2) across_v, from the corners; `inverse` is
  /// the inverse of the axes' Gram matrix (zero where they are parallel: the guess is then
  /// the centre).
  Vec3 centre, across_u, across_v;
  Eigen::Matrix2d inverse = Eigen::Matrix2d::Zero();

  ChildTest(const BaseSurface& surface, double near, double own) : projector(std::make_unique<SurfaceProjector>(surface, FootPrecision::Distance)) {
    // The limits come from the child's box in the frame of its corners (unchanged by a
    // rigid motion); the axis-aligned box only speeds up the search.
    CornerFrameBox turning(surface.boundary());
    box = surface.boundary().bounds();
    // A displacement with many sites (a large initial_grid) waves between 33 samples: then
    // four samples a site.
    const int samples = std::max(kBoundsSamples, 4 * surface.displacement_sites() + 1);
    for (const Vec3& p : surface.sample(samples, samples).points) {
      box.extend(p);
      turning.extend(p);
    }
    for (int s = 0; s < 4; ++s)
      for (const Vec3& p : surface.boundary().side(static_cast<Side>(s)).points()) turning.extend(p);
    const double diagonal = turning.diagonal();
    near_limit = near * diagonal;
    own_limit = own * diagonal;
    const double padding = kBoxPadding * box.diagonal();
    box.min.array() -= padding;
    box.max.array() += padding;

    const Boundary& b = surface.boundary();
    const Vec3 c00 = b.corner(0, 0), c10 = b.corner(1, 0), c01 = b.corner(0, 1), c11 = b.corner(1, 1);
    centre = 0.25 * (c00 + c10 + c01 + c11);
    across_u = 0.5 * ((c10 + c11) - (c00 + c01));
    across_v = 0.5 * ((c01 + c11) - (c00 + c10));
    Eigen::Matrix2d gram;
    gram << across_u.squaredNorm(), across_u.dot(across_v), across_u.dot(across_v), across_v.squaredNorm();
    const double det = gram.determinant();
    if (det > 1e-12 * gram(0, 0) * gram(1, 1)) inverse = gram.inverse();
  }

  /// The distance of p to a sample near its guessed parameters: an upper bound of its
  /// distance to the surface, without a tree query (SurfaceProjector::sample_near).
  double guessed_upper(const Vec3& p) const {
    const Vec3 d = p - centre;
    const Vec2 st = Vec2(0.5, 0.5) + inverse * Vec2(across_u.dot(d), across_v.dot(d));
    return projector->sample_near(p, st).distance;
  }

  /// A lower bound of the distance of p to the surface: its distance to the box.
  double lower_bound(const Vec3& p) const {
    const Vec3 outside = (box.min - p).cwiseMax(p - box.max).cwiseMax(0.0);
    return outside.norm();
  }
};

/// What is known of the distances of one point to the four children: bounds from each
/// child's box and, once looked up, its nearest sample (from above: that sample's distance;
/// from below: it less the sample cover), and the projected distance once needed. The
/// bounds decide most of A4's comparisons; a projection is made only where they cannot.
class ChildDistances {
 public:
  ChildDistances(const Vec3& p, const std::array<ChildTest, 4>& children) : p_(p), children_(children) {
    for (int i = 0; i < 4; ++i) {
      lower_[i] = children[i].lower_bound(p);
      upper_[i] = std::numeric_limits<double>::infinity();
    }
  }

  double lower(int i) const { return lower_[i]; }
  double upper(int i) const { return upper_[i]; }

  /// Tightens child i's bounds with its nearest sample (once).
  void look_up(int i) {
    if (sampled_[i]) return;
    sampled_[i] = true;
    const SurfaceProjector& projector = *children_[i].projector;
    sample_[i] = projector.nearest_sample(p_);
    upper_[i] = sample_[i].distance;
    lower_[i] = std::max(lower_[i], upper_[i] - projector.sample_cover());
  }

  /// The distance to child i (once): its projection from its nearest sample, or that
  /// sample where it is nearer (a descent that leaves the child ends on the nearest point of
  /// its boundary, which on a wavy child can lie farther than the sample it started from).
  double exact(int i) {
    if (!known_[i]) {
      look_up(i);
      lower_[i] = upper_[i] = std::min(upper_[i], children_[i].projector->project(p_, sample_[i]).distance);
      known_[i] = true;
    }
    return lower_[i];
  }

 private:
  const Vec3& p_;
  const std::array<ChildTest, 4>& children_;
  std::array<double, 4> lower_, upper_;
  std::array<SurfaceProjector::Sample, 4> sample_{};
  std::array<bool, 4> sampled_{}, known_{};
};

/// Which children (bit i = child i) point p joins: A4.3 and A4.4 with the rules of the
/// header. A distance is projected only when its bounds leave a comparison open, so a point
/// close to one child is usually not projected at all; the outcome is that of projecting on
/// all four.
std::uint8_t membership(const Vec3& p, const std::array<ChildTest, 4>& children) {
  ChildDistances d(p, children);
  // The children in the order of their lower bounds (ties: child order).
  std::array<int, 4> order{{0, 1, 2, 3}};
  auto by_lower = [&] { std::sort(order.begin(), order.end(), [&](int a, int b) { return d.lower(a) < d.lower(b) || (d.lower(a) == d.lower(b) && a < b); }); };
  by_lower();
  // Nearer of two children by projected distance; ties go to the first in child order.
  auto nearer = [&](int i, int j) { return j < 0 || d.exact(i) < d.exact(j) || (d.exact(i) == d.exact(j) && i < j); };

  // A4.4: within the "own" limit of some child the point belongs to that child alone. When
  // several children qualify (near a seam) the nearest one owns it, so a point is never
  // given only to a child it lies outside of.
  // Most points lie well inside one child: when the distance to its nearest sample is within
  // that child's limit and below every other child's lower bound, no other child can be
  // nearer, and the loop below would give the point to that child alone.
  const int first = order[0];
  if (d.lower(first) <= children[first].own_limit) {
    // The same test first with a sample found without a tree query: any sample's distance
    // bounds the distance from above, which is all the test needs. It decides 89% of the
    // points the rippled bench field splits and about half on the hard shapes of
    // dbs-bench-folds; the rest take the nearest sample.
    const double guessed = children[first].guessed_upper(p);
    bool alone = guessed <= children[first].own_limit;
    for (int k = 1; k < 4 && alone; ++k) alone = d.lower(order[k]) > guessed;
    if (alone) return static_cast<std::uint8_t>(1u << first);
    d.look_up(first);
    const double upper = d.upper(first);
    alone = upper <= children[first].own_limit;
    for (int k = 1; k < 4 && alone && d.lower(order[k]) <= upper; ++k) {
      d.look_up(order[k]);
      alone = d.lower(order[k]) > upper;
    }
    if (alone) return static_cast<std::uint8_t>(1u << first);
  }
  int owner = -1;
  for (int i : order) {
    const double limit = children[i].own_limit;
    // A child that cannot be within its limit, or is farther than the owner found, is passed.
    auto passed = [&] { return d.lower(i) > limit || (owner >= 0 && d.lower(i) > d.exact(owner)); };
    if (passed()) continue;
    d.look_up(i);
    if (passed()) continue;
    if (d.exact(i) <= limit && nearer(i, owner)) owner = i;
  }
  if (owner >= 0) return static_cast<std::uint8_t>(1u << owner);

  // A4.3: every child within the "near" limit.
  unsigned mask = 0;
  for (int i = 0; i < 4; ++i) {
    const double limit = children[i].near_limit;
    if (d.lower(i) > limit) continue;
    d.look_up(i);
    if (d.upper(i) <= limit || (d.lower(i) <= limit && d.exact(i) <= limit)) mask |= 1u << i;
  }
  // C(k) must be the union of the subclouds: a point near no child goes to the nearest
  // (projected in the order of their lower bounds, up to one that cannot be nearer). Such
  // points are common deep in the quadtree of an overhang: points of other sheets that a
  // subcloud holds since an earlier split.
  if (mask == 0) {
    for (int i = 0; i < 4; ++i) d.look_up(i);
    by_lower();
    int nearest = -1;
    for (int i : order) {
      if (nearest >= 0 && d.lower(i) > d.exact(nearest)) break;
      if (nearer(i, nearest)) nearest = i;
    }
    mask = 1u << nearest;
  }
  return static_cast<std::uint8_t>(mask);
}

}  // namespace

std::array<PointList, 4> split_subcloud(const std::vector<Vec3>& points, const PointList& parent_subcloud, const std::array<const BaseSurface*, 4>& children, double near, double own, int threads, WorkMeter* meter) {
  if (!(own >= 0.0 && near >= own)) fail(ErrorCode::InvalidArgument, "split_subcloud: need 0 <= own <= near, got own = " + std::to_string(own) + ", near = " + std::to_string(near));
  for (std::size_t k = 0; k < parent_subcloud.size(); ++k) {
    if (parent_subcloud[k] >= points.size()) fail(ErrorCode::OutOfRange, "split_subcloud: parent_subcloud[" + std::to_string(k) + "] = " + std::to_string(parent_subcloud[k]) + " is not below the point count " + std::to_string(points.size()));
  }
  for (int i = 0; i < 4; ++i) {
    if (children[i] == nullptr) fail(ErrorCode::InvalidArgument, "split_subcloud: child " + std::to_string(i) + " is null");
  }
  const std::array<ChildTest, 4> tests{{ChildTest(*children[0], near, own), ChildTest(*children[1], near, own), ChildTest(*children[2], near, own), ChildTest(*children[3], near, own)}};

  // A4.1-A4.2: the projector's foot is the orthogonal one when it exists inside the child,
  // otherwise the nearest boundary point, so its distance is the one A4.3 measures. Each
  // point writes only its own mask.
  std::vector<std::uint8_t> masks(parent_subcloud.size());
  metered_for(meter, parent_subcloud.size(), threads, [&](std::size_t k) {
    masks[k] = membership(points[parent_subcloud[k]], tests);
    count_work(meter);
  });

  // Sized first: filled by doubling, the four lists held up to twice their points at the
  // peak of a large run (rippled 300k: 8.1 MB of lists for 2.9 MB of indices).
  std::array<PointList, 4> subclouds;
  std::array<std::size_t, 4> sizes{{0, 0, 0, 0}};
  for (std::uint8_t mask : masks)
    for (int i = 0; i < 4; ++i) sizes[i] += (mask >> i) & 1u;
  for (int i = 0; i < 4; ++i) subclouds[i].reserve(sizes[i]);
  for (std::size_t k = 0; k < masks.size(); ++k) {
    for (int i = 0; i < 4; ++i) {
      if (masks[k] & (1u << i)) subclouds[i].push_back(parent_subcloud[k]);
    }
  }
  return subclouds;
}

}  // namespace dbs
