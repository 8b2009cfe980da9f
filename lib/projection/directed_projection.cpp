#include "directed_projection.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <string>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

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

  /// Eq. (5)'s weight of x, the operations written out in the order add_all's SSE2 code
  /// takes them (Eigen's own sums of three squares run in another order where it does not
  /// vectorize).
  void add(const Vec3& x) {
    const double dx = (x.x() - p_.x()) * inv_h_, dy = (x.y() - p_.y()) * inv_h_, dz = (x.z() - p_.z()) * inv_h_;
    const double cx = dy * u_.z() - dz * u_.y(), cy = dz * u_.x() - dx * u_.z(), cz = dx * u_.y() - dy * u_.x();
    accumulate(1.0 / (1.0 + (dx * dx + dy * dy + dz * dz) * (cx * cx + cy * cy + cz * cz)), x);
  }

  /// x with its weight a.
  void accumulate(double a, const Vec3& x) {
    c0_ += a;
    first_ += a * (x - p_);
    ++used_;
  }

  /// add() of points[i] for each i of `near`, in that order. The weights of two points are
  /// computed at once where SSE2 is there, with add()'s operations in the same order (no fused
  /// multiply-add: -ffp-contract=off, lib/CMakeLists.txt); the sums take them one by one.
  void add_all(const std::vector<Vec3>& points, const std::vector<std::size_t>& near) {
    std::size_t k = 0;
#ifdef __SSE2__
    const __m128d px = _mm_set1_pd(p_.x()), py = _mm_set1_pd(p_.y()), pz = _mm_set1_pd(p_.z());
    const __m128d ux = _mm_set1_pd(u_.x()), uy = _mm_set1_pd(u_.y()), uz = _mm_set1_pd(u_.z());
    const __m128d inv_h = _mm_set1_pd(inv_h_), one = _mm_set1_pd(1.0);
    for (; k + 2 <= near.size(); k += 2) {
      const Vec3 &x0 = points[near[k]], &x1 = points[near[k + 1]];
      const __m128d ex = _mm_sub_pd(_mm_set_pd(x1.x(), x0.x()), px), ey = _mm_sub_pd(_mm_set_pd(x1.y(), x0.y()), py), ez = _mm_sub_pd(_mm_set_pd(x1.z(), x0.z()), pz);
      const __m128d dx = _mm_mul_pd(ex, inv_h), dy = _mm_mul_pd(ey, inv_h), dz = _mm_mul_pd(ez, inv_h);
      const __m128d cx = _mm_sub_pd(_mm_mul_pd(dy, uz), _mm_mul_pd(dz, uy));
      const __m128d cy = _mm_sub_pd(_mm_mul_pd(dz, ux), _mm_mul_pd(dx, uz));
      const __m128d cz = _mm_sub_pd(_mm_mul_pd(dx, uy), _mm_mul_pd(dy, ux));
      const __m128d r2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), _mm_mul_pd(dz, dz));
      const __m128d rho2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(cx, cx), _mm_mul_pd(cy, cy)), _mm_mul_pd(cz, cz));
      alignas(16) double a[2];
      _mm_store_pd(a, _mm_div_pd(one, _mm_add_pd(one, _mm_mul_pd(r2, rho2))));
      accumulate(a[0], x0);
      accumulate(a[1], x1);
    }
#endif
    for (; k < near.size(); ++k) add(points[near[k]]);
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
  sum.add_all(index_->points(), near);
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
