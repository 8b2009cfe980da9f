#include "meshless_seed.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include "cloud_index.hpp"
#include "grid_fit.hpp"

namespace dbs {

namespace {

/// The (u,v) of the boundary position nearest q: sides bottom (s,0), right (1,s), top (s,1),
/// left (0,s), s the arc-length fraction along the side.
Vec2 boundary_parameters(const Boundary& boundary, const Vec3& q) {
  static const Vec2 origin[4] = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(0, 0)};
  static const Vec2 along[4] = {Vec2(1, 0), Vec2(0, 1), Vec2(1, 0), Vec2(0, 1)};
  double best = std::numeric_limits<double>::infinity();
  Vec2 uv(0.0, 0.0);
  for (int side = 0; side < 4; ++side) {
    double s = 0.0;
    const double d = (boundary.side(static_cast<Side>(side)).nearest(q, &s) - q).squaredNorm();
    if (d < best) {
      best = d;
      uv = origin[side] + std::clamp(s, 0.0, 1.0) * along[side];
    }
  }
  return uv;
}

}  // namespace

bool seed_from_meshless_map(Patch& patch, const std::vector<Vec3>& points, int grid) {
  const std::size_t n = patch.subcloud.size();
  if (n < 4 * kSeedNeighbours || grid < 3) return false;
  const std::size_t stride = (n + kSeedPoints - 1) / kSeedPoints;
  std::vector<Vec3> sample;
  for (std::size_t k = 0; k < n; k += stride) sample.push_back(points[patch.subcloud[k]]);
  const std::size_t m = sample.size();
  const CloudIndex index(sample);
  const Boundary& boundary = patch.surface.boundary();

  // The boundary taken into the cloud: the sample point nearest each of its vertices. The map
  // needs the boundary on the cloud (its fixed points are boundary points).
  std::vector<char> fixed(m, 0);
  std::vector<double> u(m, 0.0), v(m, 0.0);
  const double reach = kSeedBoundarySpacings * cloud_spacing(index);
  std::size_t vertices = 0, on_cloud = 0;
  for (int side = 0; side < 4; ++side) {
    for (const Vec3& q : boundary.side(static_cast<Side>(side)).points()) {
      const std::size_t nearest = index.nearest(q);
      fixed[nearest] = 1;
      ++vertices;
      on_cloud += (sample[nearest] - q).norm() <= reach;
    }
  }
  if (!(static_cast<double>(on_cloud) >= kSeedBoundaryShare * static_cast<double>(vertices))) return false;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m), 2);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(m * (kSeedNeighbours + 1));
  std::vector<std::size_t> near;
  std::vector<double> d2;
  for (std::size_t i = 0; i < m; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    entries.emplace_back(row, row, 1.0);
    if (fixed[i]) {
      const Vec2 uv = boundary_parameters(boundary, sample[i]);
      rhs(row, 0) = uv.x();
      rhs(row, 1) = uv.y();
      continue;
    }
    index.knn(sample[i], kSeedNeighbours + 1, near, d2);
    // Inverse-distance weights; a coincident neighbour weighs as one at a hundredth of the
    // nearest distinct one.
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < near.size(); ++k)
      if (near[k] != i && d2[k] > 0.0) nearest = std::min(nearest, std::sqrt(d2[k]));
    if (!std::isfinite(nearest)) return false;  // all its neighbours coincide with it
    double sum = 0.0;
    std::vector<std::pair<std::size_t, double>> weights;
    for (std::size_t k = 0; k < near.size() && weights.size() < kSeedNeighbours; ++k) {
      if (near[k] == i) continue;
      const double w = 1.0 / (d2[k] > 0.0 ? std::sqrt(d2[k]) : 1e-2 * nearest);
      weights.emplace_back(near[k], w);
      sum += w;
    }
    for (const auto& [j, w] : weights) entries.emplace_back(row, static_cast<Eigen::Index>(j), -w / sum);
  }
  Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> solver;
  solver.compute(matrix);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::MatrixXd solution = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !solution.allFinite()) return false;
  for (std::size_t i = 0; i < m; ++i) {
    u[i] = std::clamp(solution(static_cast<Eigen::Index>(i), 0), 0.0, 1.0);
    v[i] = std::clamp(solution(static_cast<Eigen::Index>(i), 1), 0.0, 1.0);
  }

  Patch seeded = patch;
  seeded.grid = seeded.surface.sample(grid, grid);
  seeded.surface = BaseSurface(boundary, seeded.grid);
  std::vector<std::size_t> ids(m);
  for (std::size_t i = 0; i < m; ++i) ids[i] = i;
  if (!fit_grid_to_parameters(seeded, ids, sample, u, v)) return false;
  patch.surface = std::move(seeded.surface);
  patch.grid = std::move(seeded.grid);
  return true;
}

}  // namespace dbs
