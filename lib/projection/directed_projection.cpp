#include "directed_projection.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <string>

#include "error.hpp"
#include "number_text.hpp"

namespace dbs {

namespace {

/// R of the header comment: a point is left out only when r rho > R (distances in h).
const double kProductBound = std::sqrt(1.0 / DirectedProjector::kNeglectedWeight - 1.0);

/// The sums of eq. (4), taken relative to p (c0 and sum a_mu (p_mu - p)) so that a cloud far
/// from the origin loses no digits.
class MomentSum {
 public:
  MomentSum(const Vec3& p, const Vec3& unit_n, double h) : p_(p), u_(unit_n), inv_h_(1.0 / h) {}

  void add(const Vec3& x) {
    const Vec3 d = (x - p_) * inv_h_;
    const double a = 1.0 / (1.0 + d.squaredNorm() * d.cross(u_).squaredNorm());
    c0_ += a;
    first_ += a * (x - p_);
    ++used_;
  }

  RayMoments result() const {
    RayMoments m;
    m.c0 = c0_;
    m.mean = c0_ > 0.0 ? Vec3(p_ + first_ / c0_) : p_;
    m.points_used = used_;
    return m;
  }

 private:
  Vec3 p_, u_;
  double inv_h_;
  double c0_ = 0.0;
  Vec3 first_ = Vec3::Zero();
  std::size_t used_ = 0;
};

Vec3 unit_direction(const Vec3& p, const Vec3& n) {
  if (!is_finite(p) || !is_finite(n)) fail(ErrorCode::NonFinite, "directed projection: non-finite point or direction");
  const double length = n.norm();
  if (!(length > 0.0)) fail(ErrorCode::Degenerate, "directed projection: zero direction");
  return n / length;
}

}  // namespace

DirectedProjector::DirectedProjector(const CloudIndex& index, double h) : index_(&index), h_(h) {
  if (!(h > 0.0) || !std::isfinite(h)) fail(ErrorCode::InvalidArgument, "DirectedProjector: length scale h = " + significant_text(h, 6) + " must be positive and finite");
}

RayMoments DirectedProjector::moments(const Vec3& p, const Vec3& n) const {
  const Vec3 u = unit_direction(p, n);
  // Scratch kept by each thread: a fresh list grew by doubling to its few hundred points on
  // every one of a run's hundreds of thousands of rays.
  thread_local std::vector<std::size_t> near;
  index_->near_ray(p, u, kProductBound * h_ * h_, near);
  MomentSum sum(p, u, h_);
  const std::vector<Vec3>& points = index_->points();
  for (std::size_t i : near) sum.add(points[i]);
  return sum.result();
}

RayMoments DirectedProjector::moments_exact(const Vec3& p, const Vec3& n) const {
  const Vec3 u = unit_direction(p, n);
  MomentSum sum(p, u, h_);
  const std::vector<Vec3>& points = index_->points();
  for (std::size_t k = 0; k < index_->size(); ++k) sum.add(points[index_->point_index(k)]);
  return sum.result();
}

bool DirectedProjector::project(const Vec3& p, const Vec3& n, double& out_t) const {
  const RayMoments m = moments(p, n);
  if (!(m.c0 > 0.0)) return false;
  out_t = (m.mean - p).dot(n) / n.squaredNorm();
  return true;
}

}  // namespace dbs
