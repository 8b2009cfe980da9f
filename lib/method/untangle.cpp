#include "untangle.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "parallel.hpp"

namespace dbs {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Point i's proposal: the (u,v) its neighbours predict, and whether it turns over fewer
/// triangles of its umbrella than the (u,v) it has.
struct Proposal {
  Vec2 uv;
  bool better = false;
};

/// Point i's proposal from the (u,v) of its neighbours `near` (its nearest points, at most
/// kUntangleNeighbours, nearest first).
Proposal propose(const std::vector<double>& u, const std::vector<double>& v, const std::vector<Vec3>& points, const std::vector<std::size_t>& near, std::size_t i) {
  if (near.size() < kUntangleUmbrella) return {};
  // Tangent frame by PCA of the neighbours (relative to the point).
  Vec3 mean = Vec3::Zero();
  for (std::size_t m : near) mean += points[m] - points[i];
  mean /= static_cast<double>(near.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t m : near) {
    const Vec3 d = points[m] - points[i] - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Vec3 lambda = eig.eigenvalues();  // increasing
  if (!(lambda(1) > 0.0) || lambda(0) > kUntangleFlatness * lambda(1)) return {};
  const Vec3 e1 = eig.eigenvectors().col(1), e2 = eig.eigenvectors().col(2);
  // uv_m = a + J t_m by least squares, t_m the tangent coordinates of neighbour m.
  const std::size_t k = near.size();
  Eigen::MatrixXd A(k, 3), B(k, 2);
  std::vector<Vec2> t(k);
  for (std::size_t m = 0; m < k; ++m) {
    const Vec3 d = points[near[m]] - points[i];
    t[m] = Vec2(d.dot(e1), d.dot(e2));
    A.row(static_cast<Eigen::Index>(m)) << 1.0, t[m].x(), t[m].y();
    B.row(static_cast<Eigen::Index>(m)) << u[near[m]], v[near[m]];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < 3) return {};
  const Eigen::MatrixXd coef = qr.solve(B);  // rows: a, then the columns of J
  const double det = coef(1, 0) * coef(2, 1) - coef(2, 0) * coef(1, 1);
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return {};
  const double sign = det > 0.0 ? 1.0 : -1.0;
  const Vec2 predicted = Vec2(coef(0, 0), coef(0, 1)).cwiseMax(0.0).cwiseMin(1.0);
  // The umbrella: the nearest neighbours by angle around the point.
  std::array<std::size_t, kUntangleUmbrella> order;
  std::array<double, kUntangleUmbrella> angle;
  for (std::size_t m = 0; m < kUntangleUmbrella; ++m) {
    order[m] = m;
    angle[m] = std::atan2(t[m].y(), t[m].x());
  }
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return angle[a] < angle[b] || (angle[a] == angle[b] && a < b); });
  auto turned = [&](const Vec2& at) {
    int count = 0;
    for (std::size_t m = 0; m < kUntangleUmbrella; ++m) {
      const std::size_t a = order[m], b = order[(m + 1) % kUntangleUmbrella];
      double gap = angle[b] - angle[a];
      if (gap < 0.0) gap += 2.0 * kPi;
      if (gap >= kPi) continue;
      const Vec2 ea = Vec2(u[near[a]], v[near[a]]) - at, eb = Vec2(u[near[b]], v[near[b]]) - at;
      if (sign * (ea.x() * eb.y() - ea.y() * eb.x()) <= 0.0) ++count;
    }
    return count;
  };
  const int now = turned(Vec2(u[i], v[i]));
  if (now == 0) return {};
  return {predicted, turned(predicted) < now};
}

}  // namespace

std::vector<std::size_t> untangle(Result& result, const std::vector<Vec3>& points, const CloudIndex& index, const std::vector<char>& candidate, int threads) {
  std::vector<std::size_t> ids;
  for (std::size_t i = 0; i < candidate.size(); ++i)
    if (candidate[i]) ids.push_back(i);
  // Each candidate's neighbours, in kUntangleNeighbours slots (fewer: the rest kNone).
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  std::vector<std::uint32_t> neighbours(ids.size() * kUntangleNeighbours, kNone);
  parallel_for(ids.size(), threads, [&](std::size_t k) {
    std::vector<std::size_t> found;
    std::vector<double> d2;
    index.knn(points[ids[k]], kUntangleNeighbours + 1, found, d2);
    std::size_t slot = 0;
    for (std::size_t m = 0; m < found.size() && slot < kUntangleNeighbours; ++m)
      if (found[m] != ids[k] && d2[m] > 0.0) neighbours[k * kUntangleNeighbours + slot++] = static_cast<std::uint32_t>(found[m]);
  });
  std::vector<char> moved(points.size(), 0), moved_last(points.size(), 0);
  // A proposal depends only on the (u,v) of the point and its neighbours: after the first
  // pass only candidates next to a point the last pass moved are proposed again (the others
  // would propose what they did, which was no move).
  std::vector<std::size_t> open(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k) open[k] = k;
  std::vector<Proposal> proposals(ids.size());
  for (int pass = 0; pass < kUntangleMaxPasses && !open.empty(); ++pass) {
    // Every proposal reads the (u,v) the pass started from; they are applied afterwards.
    parallel_for(open.size(), threads, [&](std::size_t o) {
      const std::size_t k = open[o];
      std::vector<std::size_t> near;
      for (std::size_t slot = 0; slot < kUntangleNeighbours; ++slot)
        if (neighbours[k * kUntangleNeighbours + slot] != kNone) near.push_back(neighbours[k * kUntangleNeighbours + slot]);
      proposals[k] = propose(result.u, result.v, points, near, ids[k]);
    });
    std::fill(moved_last.begin(), moved_last.end(), 0);
    for (std::size_t k : open) {
      if (!proposals[k].better) continue;
      result.u[ids[k]] = proposals[k].uv.x();
      result.v[ids[k]] = proposals[k].uv.y();
      moved[ids[k]] = moved_last[ids[k]] = 1;
    }
    std::vector<std::size_t> next;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      bool touched = moved_last[ids[k]] != 0;
      for (std::size_t slot = 0; slot < kUntangleNeighbours && !touched; ++slot) {
        const std::uint32_t m = neighbours[k * kUntangleNeighbours + slot];
        touched = m != kNone && moved_last[m] != 0;
      }
      if (touched) next.push_back(k);
    }
    open.swap(next);
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < moved.size(); ++i)
    if (moved[i]) out.push_back(i);
  return out;
}

}  // namespace dbs
