#include "turned_smoothing.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "cloud_index.hpp"
#include "error.hpp"
#include "leaf_refit.hpp"
#include "parallel.hpp"

namespace dbs {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The points to smooth: the turned ones and their kSmoothingNeighbours nearest.
std::vector<char> around_turned(const CloudIndex& index, const std::vector<Vec3>& points, const std::vector<char>& turned) {
  std::vector<char> out(points.size(), 0);
  std::vector<std::size_t> ids;
  std::vector<double> d2;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!turned[i]) continue;
    index.knn(points[i], kSmoothingNeighbours, ids, d2);
    for (std::size_t j : ids) out[j] = 1;
  }
  return out;
}

/// The (u,v) that the affine map of point i's neighbourhood predicts for it, moved from its own
/// by the flatness weight; NaN when it stays.
Vec2 predicted(const Result& result, const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const std::vector<char>& outlier, const CloudIndex& index, std::size_t i) {
  const Vec2 own(result.u[i], result.v[i]);
  const Vec2 stays(kNaN, kNaN);
  const Vec3& normal = normals[i];
  if (normal.squaredNorm() == 0.0) return stays;
  std::vector<std::size_t> ids;
  std::vector<double> d2;
  index.knn(points[i], kSmoothingNeighbours, ids, d2);
  std::vector<std::size_t> sheet;
  for (std::size_t j : ids)
    if (!outlier[j] && normals[j].dot(normal) > kSmoothingSheetCosine * normals[j].norm() * normal.norm()) sheet.push_back(j);
  if (sheet.size() < kMinSmoothingPoints) return stays;

  Vec3 centroid = Vec3::Zero();
  for (std::size_t j : sheet) centroid += points[j];
  centroid /= static_cast<double>(sheet.size());
  Eigen::Matrix3d moments = Eigen::Matrix3d::Zero();
  for (std::size_t j : sheet) {
    const Vec3 d = points[j] - centroid;
    moments.noalias() += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(moments);
  if (axes.info() != Eigen::Success) return stays;
  const double flatness = axes.eigenvalues()[0] / axes.eigenvalues()[1];
  const double weight = std::isfinite(flatness) ? std::clamp((kFlatNone - flatness) / (kFlatNone - kFlatFull), 0.0, 1.0) : 0.0;
  if (!(weight > 0.0)) return stays;
  const Vec3 t1 = axes.eigenvectors().col(2), t2 = axes.eigenvectors().col(1);

  // (u,v) ~ c + J x over the unfolded offsets x, least squares; c is the prediction at the
  // point (x = 0). The offsets in units of their RMS length keep the normal matrix well scaled.
  double spread2 = 0.0;
  for (std::size_t j : sheet) spread2 += (points[j] - points[i]).squaredNorm();
  if (!(spread2 > 0.0)) return stays;
  const double unit = 1.0 / std::sqrt(spread2 / static_cast<double>(sheet.size()));
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 2> rhs = Eigen::Matrix<double, 3, 2>::Zero();
  for (std::size_t j : sheet) {
    const Vec3 d = (points[j] - points[i]) * unit;
    double x = d.dot(t1), y = d.dot(t2);
    const double in_plane = std::hypot(x, y);
    if (in_plane > 0.0) {
      x *= d.norm() / in_plane;
      y *= d.norm() / in_plane;
    }
    const Eigen::Vector3d row(1.0, x, y);
    normal_matrix.noalias() += row * row.transpose();
    rhs.noalias() += row * Eigen::RowVector2d(result.u[j], result.v[j]);
  }
  const Eigen::Matrix<double, 3, 2> fit = normal_matrix.ldlt().solve(rhs);
  if (!fit.allFinite()) return stays;
  const Vec2 to = own + weight * (Vec2(fit(0, 0), fit(0, 1)) - own);
  return to.cwiseMax(0.0).cwiseMin(1.0);
}

}  // namespace

TurnedSmoothing smooth_turned_sheets(Result& result, const std::vector<Vec3>& points, const CloudIndex& index, const std::vector<char>& turned, const std::vector<Vec3>& normals,
                                     const std::vector<char>& outlier, int threads, WorkMeter* meter) {
  const std::size_t n = points.size();
  if (turned.size() != n || normals.size() != n || outlier.size() != n)
    fail(ErrorCode::InvalidArgument, "smooth_turned_sheets: " + std::to_string(turned.size()) + " turned flags, " + std::to_string(normals.size()) + " normals and " +
                                         std::to_string(outlier.size()) + " outlier flags for " + std::to_string(n) + " points");
  if (index.size() != n) fail(ErrorCode::InvalidArgument, "smooth_turned_sheets: the index holds " + std::to_string(index.size()) + " of the " + std::to_string(n) + " points");
  TurnedSmoothing out;
  if (std::find(turned.begin(), turned.end(), 1) == turned.end()) return out;
  const std::vector<char> candidate = around_turned(index, points, turned);
  auto stays = [&](std::size_t i) {
    const bool clamped = i < result.clamped.size() && result.clamped[i];
    const bool on_edge = !(result.u[i] > 0.0 && result.u[i] < 1.0 && result.v[i] > 0.0 && result.v[i] < 1.0);
    return !candidate[i] || outlier[i] || clamped || on_edge;
  };
  // Every prediction reads the (u,v) before any point moves.
  std::vector<Vec2> to(n, Vec2(kNaN, kNaN));
  metered_for(meter, n, threads, [&](std::size_t i) {
    if (!stays(i)) to[i] = predicted(result, points, normals, outlier, index, i);
    count_work(meter);
  });
  std::vector<char> moved(n, 0), touched(result.patches.size(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isnan(to[i].x()) || (to[i].x() == result.u[i] && to[i].y() == result.v[i])) continue;
    touched[static_cast<std::size_t>(result.patch[i])] = 1;
    place_on_leaf(result, points, i, to[i]);
    touched[static_cast<std::size_t>(result.patch[i])] = 1;
    moved[i] = 1;
    ++out.moved;
  }
  if (out.moved == 0) return out;
  out.refitted = refit_marked_leaves(result, points, outlier, moved, threads);
  for (int id : out.refitted) touched[static_cast<std::size_t>(id)] = 1;
  for (std::size_t id = 0; id < touched.size(); ++id)
    if (touched[id]) out.touched.push_back(static_cast<int>(id));
  return out;
}

}  // namespace dbs
