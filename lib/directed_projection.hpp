// Directed projection of a point p along a direction n onto a point cloud (paper eqs.
// 1-5): the point p* = p + t n minimizing sum_mu a_mu |p* - p_mu|^2 with the weights of
// eq. (5). Distances in eq. (5) are measured in units of the cloud's length scale h, so the
// result does not depend on the input's units (DESIGN.md decision 3). The sums run over the
// points near the ray found with the k-d tree (decision 4); what they neglect is bounded
// (see DirectedProjector::kNeglectedWeight).
#pragma once
#include <vector>

#include "cloud_index.hpp"

namespace dbs {

/// Weighted moments of the cloud seen from one ray: c0 = sum a_mu and the weighted mean
/// m = (sum a_mu p_mu) / c0. Then E(p + t n) = c0 |p + t n - m|^2 + const, and the
/// minimizer is t = (m - p).n / |n|^2 (eq. 3).
struct RayMoments {
  double c0 = 0.0;
  Vec3 mean = Vec3::Zero();
  std::size_t points_used = 0;
};

class DirectedProjector {
 public:
  /// Upper bound on the weight of any single point the neighbourhood sum leaves out
  /// (eq. 5 weight, distances in units of h).
  static constexpr double kNeglectedWeight = 1e-4;

  /// `index` is the (sub)cloud projected onto; h its length scale (> 0).
  DirectedProjector(const CloudIndex& index, double h);

  const CloudIndex& index() const { return *index_; }
  double length_scale() const { return h_; }
  /// Moments over the neighbourhood of the ray (n need not be unit).
  RayMoments moments(const Vec3& p, const Vec3& n) const;
  /// Moments over every indexed point: the reference the neighbourhood is tested against.
  RayMoments moments_exact(const Vec3& p, const Vec3& n) const;
  /// Eq. (3): the offset t of the projection p + t n; false when no point carries weight.
  bool project(const Vec3& p, const Vec3& n, double& out_t) const;

 private:
  const CloudIndex* index_;
  double h_;
};

}  // namespace dbs
