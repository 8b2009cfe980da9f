// Directed projection of a point p along a direction n onto a point cloud (paper eqs.
// 1-5): the point p* = p + t n minimizing sum_mu a_mu |p* - p_mu|^2 with the weights of
// eq. (5). Distances in eq. (5) are measured in units of the cloud's length scale h, so the
// result does not depend on the input's units (DESIGN.md decision 3). The sums run over the
// points near the ray found with the k-d tree (decision 4); what they neglect is bounded:
//
// With r = |p_mu - p| / h and rho = |(p_mu - p) x n| / (|n| h) (the distance to the line
// through p along n; eq. (5) with n made unit), a_mu = 1 / (1 + r^2 rho^2). So a_mu >= w
// exactly when r rho <= R = sqrt(1/w - 1) (R ~ 100 for w = kNeglectedWeight = 1e-4). The region
// r rho <= R holds the ball r <= sqrt(R) (~10 h) around p (there rho <= r) and, farther out,
// a tube around the line whose radius R / r shrinks with the distance from p; it is cut by
// the cloud itself, because the k-d tree descent (CloudIndex::near_ray) only keeps the nodes
// whose boxes can hold a point of the region. Every point left out has a_mu < w, hence
//   |c0 - c0_exact|                                  <= w * (points left out),
//   |c0 (m - p) - c0_exact (m_exact - p)|            <= w * sum over them of |p_mu - p|.
// The cost follows the region (a few hundred points on a surface cloud), not the cloud size.
#pragma once
#include <vector>

#include "cloud_index.hpp"

namespace dbs {

/// Weighted moments of the cloud seen from one ray: c0 = sum a_mu and the weighted mean
/// m = (sum a_mu p_mu) / c0 (p itself when c0 = 0). Then E(p + t n) = c0 |p + t n - m|^2
/// + const, and the minimizer is t = (m - p).n / |n|^2 (eq. 3).
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

  /// `index` is the (sub)cloud projected onto; h its length scale (> 0, finite; else
  /// Error(InvalidArgument)).
  DirectedProjector(const CloudIndex& index, double h);

  const CloudIndex& index() const { return *index_; }
  double length_scale() const { return h_; }
  /// Moments over the neighbourhood of the ray (n need not be unit: the weights depend on
  /// the line only). Error(NonFinite) for a non-finite p or n, Error(Degenerate) for n = 0.
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
