#include "meshless_seed.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include "cloud_index.hpp"
#include "grid_fit.hpp"
#include "index_hash.hpp"

namespace dbs {

namespace {

/// The local (u,v) of the boundary position nearest q: sides bottom (s,0), right (1,s), top
/// (s,1), left (0,s), s the arc-length fraction along the side.
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

/// Each sample point's kSeedNeighbours nearest others (coincident ones included) and their
/// distances.
struct Neighbours {
  std::vector<std::vector<std::size_t>> index;
  std::vector<std::vector<double>> distance;
};

Neighbours nearest_others(const CloudIndex& index, const std::vector<Vec3>& sample, WorkMeter* meter) {
  Neighbours out;
  out.index.resize(sample.size());
  out.distance.resize(sample.size());
  std::vector<std::size_t> near;
  std::vector<double> d2;
  for (std::size_t i = 0; i < sample.size(); ++i) {
    index.knn(sample[i], kSeedNeighbours + 1, near, d2);
    for (std::size_t k = 0; k < near.size() && out.index[i].size() < kSeedNeighbours; ++k) {
      if (near[k] == i) continue;
      out.index[i].push_back(near[k]);
      out.distance[i].push_back(std::sqrt(d2[k]));
    }
    count_work(meter);
  }
  return out;
}

/// The share of the kSeedBorderNeighbours sample points nearest a boundary position q on the
/// minority side of the boundary there: the plane through q spanned by the boundary's
/// tangent and the cloud's normal (PCA of those points) parts them; on the cloud's border
/// they all lie on one side (0), where the boundary crosses the cloud about half on each.
double share_beyond(const CloudIndex& index, const std::vector<Vec3>& sample, const Vec3& q, const Vec3& tangent) {
  std::vector<std::size_t> near;
  std::vector<double> d2;
  index.knn(q, kSeedBorderNeighbours, near, d2);
  if (near.size() < 3) return 0.0;
  Vec3 centre = Vec3::Zero();
  for (std::size_t j : near) centre += sample[j];
  centre /= static_cast<double>(near.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t j : near) covariance += (sample[j] - centre) * (sample[j] - centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(covariance);
  const Vec3 across = tangent.cross(Vec3(pca.eigenvectors().col(0)));
  std::size_t plus = 0, minus = 0;
  for (std::size_t j : near) {
    const double side = (sample[j] - q).dot(across);
    plus += side > 0.0;
    minus += side < 0.0;
  }
  return static_cast<double>(std::min(plus, minus)) / static_cast<double>(near.size());
}

/// The sample's spacing: the mean distance to the nearest distinct point (0 when every point
/// has only coincident neighbours).
double sample_spacing(const Neighbours& near) {
  double spacing = 0.0;
  std::size_t spaced = 0;
  for (const std::vector<double>& d : near.distance) {
    const auto distinct = std::find_if(d.begin(), d.end(), [](double x) { return x > 0.0; });
    if (distinct == d.end()) continue;
    spacing += *distinct;
    ++spaced;
  }
  return spaced == 0 ? 0.0 : spacing / static_cast<double>(spaced);
}

/// The boundary taken into the cloud: each side walked at the sample's spacing, the sample
/// point nearest each position fixed (`fixed`, one flag per sample point) where it lies within
/// kSeedBoundarySpacings. False when the map cannot use the boundary: it is not on the cloud
/// (fewer than kSeedBoundaryShare of the positions within reach; its fixed points must be
/// boundary points) or not the cloud's border (a median share above kSeedBeyondShare of the
/// points near its positions beyond it: points beyond a boundary crossing the cloud have no
/// (u,v) to take).
bool fix_boundary_points(const Boundary& boundary, const CloudIndex& index, const std::vector<Vec3>& sample, double spacing, std::vector<char>& fixed, WorkMeter* meter) {
  const std::size_t m = sample.size();
  fixed.assign(m, 0);
  std::size_t positions = 0, on_cloud = 0;
  std::vector<double> beyond;
  for (int side = 0; side < 4; ++side) {
    const Polyline& line = boundary.side(static_cast<Side>(side));
    const std::size_t steps = static_cast<std::size_t>(std::clamp(std::ceil(line.length() / spacing), 1.0, static_cast<double>(m)));
    for (std::size_t k = 0; k <= steps; ++k) {
      const double s = static_cast<double>(k) / static_cast<double>(steps);
      const Vec3 q = line.at(s);
      const std::size_t nearest = index.nearest(q);
      ++positions;
      count_work(meter);
      if (!((sample[nearest] - q).norm() <= kSeedBoundarySpacings * spacing)) continue;
      fixed[nearest] = 1;
      ++on_cloud;
      beyond.push_back(share_beyond(index, sample, q, line.tangent(s)));
    }
  }
  if (!(static_cast<double>(on_cloud) >= kSeedBoundaryShare * static_cast<double>(positions))) return false;
  const auto middle = beyond.begin() + static_cast<std::ptrdiff_t>(beyond.size() / 2);
  std::nth_element(beyond.begin(), middle, beyond.end());
  return *middle <= kSeedBeyondShare;
}

/// The points whose (u,v) the map determines: the fixed ones and, by a path of neighbours,
/// those that reach one (a clump of points that are only each other's neighbours would
/// leave its block of the system without a fixed value).
std::vector<char> reaching_fixed(const Neighbours& near, const std::vector<char>& fixed) {
  const std::size_t m = fixed.size();
  std::vector<std::vector<std::size_t>> referenced_by(m);
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j : near.index[i]) referenced_by[j].push_back(i);
  std::vector<char> reached = fixed;
  std::vector<std::size_t> queue;
  for (std::size_t i = 0; i < m; ++i)
    if (fixed[i]) queue.push_back(i);
  while (!queue.empty()) {
    const std::size_t j = queue.back();
    queue.pop_back();
    for (std::size_t i : referenced_by[j]) {
      if (reached[i]) continue;
      reached[i] = 1;
      queue.push_back(i);
    }
  }
  return reached;
}

}  // namespace

bool seed_from_meshless_map(Patch& patch, const std::vector<Vec3>& points, int grid, WorkMeter* meter) {
  const std::size_t n = patch.subcloud.size();
  if (n < 4 * kSeedNeighbours || grid < 3 || grid > kMaxSeedGrid) return false;
  // About kSeedPoints of them, chosen by a hash of their position in the subcloud: a stride
  // would sample a scan stored row by row in stripes (every other point of each row), and
  // the map over such a sample spreads along the rows only.
  const std::uint64_t keep_one_in = (n + kSeedPoints - 1) / kSeedPoints;
  std::vector<Vec3> sample;
  for (std::size_t k = 0; k < n; ++k)
    if (keep_one_in == 1 || index_hash(k) % keep_one_in == 0) sample.push_back(points[patch.subcloud[k]]);
  if (sample.size() < 4 * kSeedNeighbours) return false;
  const std::size_t m = sample.size();
  const CloudIndex index(sample);
  const Neighbours near = nearest_others(index, sample, meter);
  const double spacing = sample_spacing(near);
  if (!(spacing > 0.0)) return false;  // every point has only coincident neighbours
  const Boundary& boundary = patch.surface.boundary();
  std::vector<char> fixed;
  if (!fix_boundary_points(boundary, index, sample, spacing, fixed, meter)) return false;

  // One row per point the map determines (kept): fixed, or the inverse-distance mean of its
  // kept neighbours, a coincident one weighing as one at a hundredth of the spacing.
  const std::vector<char> kept = reaching_fixed(near, fixed);
  std::vector<Eigen::Index> row_of(m, -1);
  Eigen::Index rows = 0;
  for (std::size_t i = 0; i < m; ++i)
    if (kept[i]) row_of[i] = rows++;
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(rows, 2);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(rows) * (kSeedNeighbours + 1));
  for (std::size_t i = 0; i < m; ++i) {
    const Eigen::Index row = row_of[i];
    if (row < 0) continue;
    entries.emplace_back(row, row, 1.0);
    if (fixed[i]) {
      const Vec2 uv = boundary_parameters(boundary, sample[i]);
      rhs(row, 0) = uv.x();
      rhs(row, 1) = uv.y();
      continue;
    }
    double sum = 0.0;
    for (std::size_t k = 0; k < near.index[i].size(); ++k)
      if (kept[near.index[i][k]]) sum += 1.0 / std::max(near.distance[i][k], 1e-2 * spacing);
    for (std::size_t k = 0; k < near.index[i].size(); ++k) {
      const std::size_t j = near.index[i][k];
      if (kept[j]) entries.emplace_back(row, row_of[j], -1.0 / std::max(near.distance[i][k], 1e-2 * spacing) / sum);
    }
  }
  Eigen::SparseMatrix<double> matrix(rows, rows);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> solver;
  solver.compute(matrix);
  if (solver.info() != Eigen::Success) return false;
  const Eigen::MatrixXd solution = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !solution.allFinite()) return false;

  // The grid fitted to the kept points at their (u,v), mapped onto the patch's rectangle.
  std::vector<std::size_t> ids;
  std::vector<double> u(m, 0.0), v(m, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    if (row_of[i] < 0) continue;
    const Vec2 uv = patch.rect.to_global(std::clamp(solution(row_of[i], 0), 0.0, 1.0), std::clamp(solution(row_of[i], 1), 0.0, 1.0));
    u[i] = uv.x();
    v[i] = uv.y();
    ids.push_back(i);
  }
  Patch seeded{patch.surface};
  seeded.rect = patch.rect;
  seeded.grid = patch.surface.sample(grid, grid);
  seeded.surface = BaseSurface(boundary, seeded.grid);
  if (!fit_grid_to_parameters(seeded, ids, sample, u, v)) return false;
  patch.surface = std::move(seeded.surface);
  patch.grid = std::move(seeded.grid);
  return true;
}

}  // namespace dbs
