#include "spline_displacement.hpp"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <string>
#include <vector>

#include "error.hpp"

namespace dbs {

namespace {

using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;

double clamp_unit(double x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }

// Control values c_0..c_{n+1} of the uniform cubic B-spline through n >= 2 values per
// column of `data` (n x m), with natural ends (zero second derivative). Interpolation at
// site i reads (c_i + 4 c_{i+1} + c_{i+2}) / 6 = d_i; at the ends together with the natural
// condition this gives c_1 = d_0 and c_n = d_{n-1}, set directly (so a zero end value
// gives an exactly zero coefficient); the inner c_2..c_{n-1} solve the symmetric
// tridiagonal system [1 4 1]. The outer c_0, c_{n+1} are left to the caller.
Rows interpolate_columns(const Rows& data) {
  const int n = static_cast<int>(data.rows());
  Rows c = Rows::Zero(n + 2, data.cols());
  c.row(1) = data.row(0);
  c.row(n) = data.row(n - 1);
  const int inner = n - 2;
  if (inner > 0) {
    Eigen::SparseMatrix<double> a(inner, inner);
    a.reserve(Eigen::VectorXi::Constant(inner, 3));
    for (int k = 0; k < inner; ++k) {
      a.insert(k, k) = 4.0;
      if (k > 0) a.insert(k, k - 1) = 1.0;
      if (k + 1 < inner) a.insert(k, k + 1) = 1.0;
    }
    a.makeCompressed();
    Rows rhs = 6.0 * data.middleRows(1, inner);
    rhs.row(0) -= c.row(1);
    rhs.row(inner - 1) -= c.row(n);
    // Strictly diagonally dominant, symmetric positive definite; the natural ordering of a
    // tridiagonal matrix has no fill-in.
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower, Eigen::NaturalOrdering<int>> solver(a);
    if (solver.info() != Eigen::Success) fail(ErrorCode::Numerical, "spline interpolation: tridiagonal factorization failed");
    c.middleRows(2, inner) = solver.solve(rhs);
  }
  return c;
}

// Natural end conditions: c_0 = 2 c_1 - c_2, c_{n+1} = 2 c_n - c_{n-1}.
void extend_natural(Rows& c) {
  const Eigen::Index last = c.rows() - 1;
  c.row(0) = 2.0 * c.row(1) - c.row(2);
  c.row(last) = 2.0 * c.row(last - 1) - c.row(last - 2);
}

// Uniform cubic B-spline basis on the knot span holding x in [0,1] for n sites (n-1 spans):
// the first control index, the four weights and (when asked) their derivatives in x.
struct SpanBasis {
  int first;
  double t;  // local parameter in the span, in [0,1]
  double w[4];
  double dw[4];
};

SpanBasis span_basis(double x, int n, bool with_derivatives) {
  SpanBasis b;
  const int spans = n - 1;
  const double xs = clamp_unit(x) * spans;
  b.first = std::min(static_cast<int>(xs), spans - 1);
  const double t = xs - b.first, s = 1.0 - t;
  b.t = t;
  const double t2 = t * t, t3 = t2 * t;
  b.w[0] = s * s * s / 6.0;
  b.w[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
  b.w[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  b.w[3] = t3 / 6.0;
  if (!with_derivatives) return b;
  b.dw[0] = -0.5 * s * s * spans;
  b.dw[1] = (1.5 * t2 - 2.0 * t) * spans;
  b.dw[2] = (-1.5 * t2 + t + 0.5) * spans;
  b.dw[3] = 0.5 * t2 * spans;
  return b;
}

// The spline along one direction from four consecutive controls. At a site (t = 0 or 1)
// it is (c_a + 4 c_b + c_c) / 6, summed so that c_a = -c_c, c_b = 0 (a zero border value
// under the natural condition) gives exactly zero, whatever the compiler fuses.
Vec3 blend(const SpanBasis& b, const Vec3& c0, const Vec3& c1, const Vec3& c2, const Vec3& c3) {
  if (b.t == 0.0) return ((c0 + c2) + 4.0 * c1) / 6.0;
  if (b.t == 1.0) return ((c1 + c3) + 4.0 * c2) / 6.0;
  return b.w[0] * c0 + b.w[1] * c1 + b.w[2] * c2 + b.w[3] * c3;
}

Vec3 blend_derivative(const SpanBasis& b, const Vec3& c0, const Vec3& c1, const Vec3& c2, const Vec3& c3) {
  return b.dw[0] * c0 + b.dw[1] * c1 + b.dw[2] * c2 + b.dw[3] * c3;
}

/// The second derivative in x of the spline along one direction (b from span_basis for n
/// sites): the weights' second derivatives are linear in t.
Vec3 blend_second(const SpanBasis& b, int n, const Vec3& c0, const Vec3& c1, const Vec3& c2, const Vec3& c3) {
  const double spans2 = static_cast<double>(n - 1) * (n - 1), t = b.t;
  return spans2 * ((1.0 - t) * c0 + (3.0 * t - 2.0) * c1 + (1.0 - 3.0 * t) * c2 + t * c3);
}

}  // namespace

SplineDisplacement::SplineDisplacement(const Grid& values) : nu_(values.nu), nv_(values.nv) {
  if (nu_ < 2 || nv_ < 2)
    fail(ErrorCode::InvalidArgument, "spline displacement needs a grid of at least 2 x 2 values, got " + std::to_string(nu_) + " x " +
                                         std::to_string(nv_));
  if (values.points.size() != static_cast<std::size_t>(nu_) * nv_)
    fail(ErrorCode::InvalidArgument, "spline displacement grid holds " + std::to_string(values.points.size()) + " points, not " +
                                         std::to_string(nu_) + " x " + std::to_string(nv_));
  // Along u: one column per (grid row j, coordinate), only the interpolating c_1..c_nu kept.
  Rows data_u(nu_, 3 * nv_);
  for (int j = 0; j < nv_; ++j)
    for (int i = 0; i < nu_; ++i) {
      const Vec3& p = values(i, j);
      if (!is_finite(p))
        fail(ErrorCode::NonFinite, "spline displacement value (" + std::to_string(i) + "," + std::to_string(j) + ") is not finite");
      data_u.block<1, 3>(i, 3 * j) = p.transpose();
    }
  const Rows cu = interpolate_columns(data_u).middleRows(1, nu_);  // nu x 3nv
  // Along v: one column per (control k = 1..nu, coordinate).
  Rows data_v(nv_, 3 * nu_);
  for (int j = 0; j < nv_; ++j)
    for (int k = 0; k < nu_; ++k) data_v.block<1, 3>(j, 3 * k) = cu.block<1, 3>(k, 3 * j);
  Rows cv = interpolate_columns(data_v);  // (nv+2) x 3nu
  extend_natural(cv);
  // Tensor-product controls; the outer u controls by the natural condition along u, so
  // that a zero grid border gives c_0 = -c_2 and c_1 = 0 exactly and the spline vanishes
  // exactly on the border.
  Rows all(nu_ + 2, 3 * (nv_ + 2));
  for (int l = 0; l < nv_ + 2; ++l)
    for (int k = 0; k < nu_; ++k) all.block<1, 3>(k + 1, 3 * l) = cv.block<1, 3>(l, 3 * k);
  extend_natural(all);
  coeffs_.resize(static_cast<std::size_t>(nu_ + 2) * (nv_ + 2));
  for (int l = 0; l < nv_ + 2; ++l)
    for (int k = 0; k < nu_ + 2; ++k) coeffs_[static_cast<std::size_t>(l) * (nu_ + 2) + k] = all.block<1, 3>(k, 3 * l).transpose();
}

Vec3 SplineDisplacement::eval(double u, double v) const {
  if (is_zero()) return Vec3::Zero();
  const SpanBasis bu = span_basis(u, nu_, false), bv = span_basis(v, nv_, false);
  Vec3 along_u[4];
  for (int b = 0; b < 4; ++b) {
    const Vec3* row = &coeffs_[static_cast<std::size_t>(bv.first + b) * (nu_ + 2) + bu.first];
    along_u[b] = blend(bu, row[0], row[1], row[2], row[3]);
  }
  return blend(bv, along_u[0], along_u[1], along_u[2], along_u[3]);
}

void SplineDisplacement::add_to_interior(Grid& grid) const {
  if (is_zero()) return;
  std::vector<SpanBasis> bu(static_cast<std::size_t>(grid.nu)), bv(static_cast<std::size_t>(grid.nv));
  for (int i = 0; i < grid.nu; ++i) bu[static_cast<std::size_t>(i)] = span_basis(grid.u(i), nu_, false);
  for (int j = 0; j < grid.nv; ++j) bv[static_cast<std::size_t>(j)] = span_basis(grid.v(j), nv_, false);
  // Each control row blended along u once at each interior column, then each grid row
  // blending four of those along v: the coefficients and weights of eval(), in its order (so
  // the same bits), without blending a control row again for every grid row that needs it.
  const std::size_t columns = static_cast<std::size_t>(grid.nu), control_rows = static_cast<std::size_t>(nv_ + 2);
  std::vector<Vec3> along_u(control_rows * columns);
  for (std::size_t r = 0; r < control_rows; ++r) {
    for (int i = 1; i + 1 < grid.nu; ++i) {
      const SpanBasis& b_u = bu[static_cast<std::size_t>(i)];
      const Vec3* row = &coeffs_[r * (nu_ + 2) + b_u.first];
      along_u[r * columns + static_cast<std::size_t>(i)] = blend(b_u, row[0], row[1], row[2], row[3]);
    }
  }
  for (int j = 1; j + 1 < grid.nv; ++j) {
    const SpanBasis& b_v = bv[static_cast<std::size_t>(j)];
    const Vec3* first = &along_u[static_cast<std::size_t>(b_v.first) * columns];
    for (int i = 1; i + 1 < grid.nu; ++i) grid(i, j) += blend(b_v, first[i], first[columns + i], first[2 * columns + i], first[3 * columns + i]);
  }
}

void SplineDisplacement::eval_derivs(double u, double v, Vec3& d, Vec3& du, Vec3& dv) const {
  if (is_zero()) {
    d = du = dv = Vec3::Zero();
    return;
  }
  const SpanBasis bu = span_basis(u, nu_, true), bv = span_basis(v, nv_, true);
  Vec3 along_u[4], along_u_du[4];
  for (int b = 0; b < 4; ++b) {
    const Vec3* row = &coeffs_[static_cast<std::size_t>(bv.first + b) * (nu_ + 2) + bu.first];
    along_u[b] = blend(bu, row[0], row[1], row[2], row[3]);
    along_u_du[b] = blend_derivative(bu, row[0], row[1], row[2], row[3]);
  }
  d = blend(bv, along_u[0], along_u[1], along_u[2], along_u[3]);
  du = blend(bv, along_u_du[0], along_u_du[1], along_u_du[2], along_u_du[3]);
  dv = blend_derivative(bv, along_u[0], along_u[1], along_u[2], along_u[3]);
}

SecondDerivatives SplineDisplacement::second_derivatives(double u, double v) const {
  if (is_zero()) return {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  const SpanBasis bu = span_basis(u, nu_, true), bv = span_basis(v, nv_, true);
  Vec3 along_u[4], along_u_du[4], along_u_duu[4];
  for (int b = 0; b < 4; ++b) {
    const Vec3* row = &coeffs_[static_cast<std::size_t>(bv.first + b) * (nu_ + 2) + bu.first];
    along_u[b] = blend(bu, row[0], row[1], row[2], row[3]);
    along_u_du[b] = blend_derivative(bu, row[0], row[1], row[2], row[3]);
    along_u_duu[b] = blend_second(bu, nu_, row[0], row[1], row[2], row[3]);
  }
  return {blend(bv, along_u_duu[0], along_u_duu[1], along_u_duu[2], along_u_duu[3]), blend_derivative(bv, along_u_du[0], along_u_du[1], along_u_du[2], along_u_du[3]),
          blend_second(bv, nv_, along_u[0], along_u[1], along_u[2], along_u[3])};
}

}  // namespace dbs
