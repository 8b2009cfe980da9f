// Floater-Reimers meshless reference parameterization: see meshless_reference.hpp.
#include "meshless_reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

namespace dbs_folds {

namespace {

/// A boundary side as a polyline with cumulative arc length.
struct Side {
  const std::vector<double>* xyz;
  std::vector<double> length;  // cumulative, length[0] = 0
};

Side make_side(const std::vector<double>& xyz) {
  const std::size_t n = xyz.size() / 3;
  if (n < 2 || xyz.size() % 3 != 0) throw std::invalid_argument("meshless_reference: a boundary side needs at least 2 points");
  Side side{&xyz, std::vector<double>(n, 0.0)};
  for (std::size_t i = 1; i < n; ++i) {
    const double dx = xyz[3 * i] - xyz[3 * i - 3], dy = xyz[3 * i + 1] - xyz[3 * i - 2], dz = xyz[3 * i + 2] - xyz[3 * i - 1];
    side.length[i] = side.length[i - 1] + std::sqrt(dx * dx + dy * dy + dz * dz);
  }
  return side;
}

/// Squared distance of p to the side and the arc-length fraction of its closest point.
double closest_on_side(const Side& side, const double* p, double& fraction) {
  const std::vector<double>& s = *side.xyz;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < side.length.size(); ++i) {
    const double* a = &s[3 * i];
    const double* b = &s[3 * i + 3];
    double ab[3], ap[3];
    for (int c = 0; c < 3; ++c) {
      ab[c] = b[c] - a[c];
      ap[c] = p[c] - a[c];
    }
    const double ab2 = ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2];
    double t = ab2 > 0.0 ? (ap[0] * ab[0] + ap[1] * ab[1] + ap[2] * ab[2]) / ab2 : 0.0;
    t = std::min(1.0, std::max(0.0, t));
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double e = ap[c] - t * ab[c];
      d2 += e * e;
    }
    if (d2 < best) {
      best = d2;
      fraction = (side.length[i] + t * (side.length[i + 1] - side.length[i])) / side.length.back();
    }
  }
  return best;
}

}  // namespace

MeshlessReference meshless_reference(const std::vector<double>& xyz, const std::vector<double>& bottom, const std::vector<double>& right,
                                     const std::vector<double>& top, const std::vector<double>& left, int k) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t n = xyz.size() / 3;
  if (k < 1 || n < static_cast<std::size_t>(k) + 1) throw std::invalid_argument("meshless_reference: needs more than k points");
  const Side sides[4] = {make_side(bottom), make_side(right), make_side(top), make_side(left)};
  const KdTree tree(xyz);

  MeshlessReference out;
  out.uv.assign(2 * n, 0.0);
  out.fixed.assign(n, 0);
  // The boundary projected into the cloud: the nearest point of every boundary vertex.
  for (const Side& side : sides) {
    const std::vector<double>& s = *side.xyz;
    for (std::size_t i = 0; i < s.size() / 3; ++i) out.fixed[tree.nearest(&s[3 * i])] = 1;
  }
  for (std::size_t p = 0; p < n; ++p) {
    if (!out.fixed[p]) continue;
    ++out.fixed_count;
    int best_side = 0;
    double best = std::numeric_limits<double>::infinity(), best_t = 0.0;
    for (int side = 0; side < 4; ++side) {
      double t = 0.0;
      const double d2 = closest_on_side(sides[side], &xyz[3 * p], t);
      if (d2 < best) {
        best = d2;
        best_side = side;
        best_t = t;
      }
    }
    static const double origin[4][2] = {{0, 0}, {1, 0}, {0, 1}, {0, 0}}, direction[4][2] = {{1, 0}, {0, 1}, {1, 0}, {0, 1}};
    out.uv[2 * p] = origin[best_side][0] + best_t * direction[best_side][0];
    out.uv[2 * p + 1] = origin[best_side][1] + best_t * direction[best_side][1];
  }

  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(n * (k + 1));
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), 2);
  std::vector<std::size_t> index;
  std::vector<double> distance2;
  for (std::size_t p = 0; p < n; ++p) {
    const auto row = static_cast<Eigen::Index>(p);
    entries.emplace_back(row, row, 1.0);
    if (out.fixed[p]) {
      rhs(row, 0) = out.uv[2 * p];
      rhs(row, 1) = out.uv[2 * p + 1];
      continue;
    }
    tree.nearest(&xyz[3 * p], static_cast<std::size_t>(k) + 1, index, distance2);
    std::vector<std::pair<std::size_t, double>> weights;
    double sum = 0.0, nearest = std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < index.size(); ++m) {
      if (index[m] != p && distance2[m] > 0.0) nearest = std::min(nearest, std::sqrt(distance2[m]));
    }
    for (std::size_t m = 0; m < index.size() && weights.size() < static_cast<std::size_t>(k); ++m) {
      if (index[m] == p) continue;
      // A duplicate point (distance 0) gets the weight of one at a hundredth of the nearest spacing.
      const double d = distance2[m] > 0.0 ? std::sqrt(distance2[m]) : 1e-2 * (std::isfinite(nearest) ? nearest : 1.0);
      weights.emplace_back(index[m], 1.0 / d);
      sum += 1.0 / d;
    }
    for (const auto& w : weights) entries.emplace_back(row, static_cast<Eigen::Index>(w.first), -w.second / sum);
  }
  Eigen::SparseMatrix<double> matrix(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> solver;
  solver.compute(matrix);
  if (solver.info() != Eigen::Success) throw std::runtime_error("meshless_reference: singular system (points with no neighbour path to the boundary)");
  const Eigen::MatrixXd solution = solver.solve(rhs);
  if (solver.info() != Eigen::Success || !solution.allFinite()) throw std::runtime_error("meshless_reference: the sparse solve failed");
  for (std::size_t p = 0; p < n; ++p) {
    out.uv[2 * p] = solution(static_cast<Eigen::Index>(p), 0);
    out.uv[2 * p + 1] = solution(static_cast<Eigen::Index>(p), 1);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

MeshlessReference meshless_reference(const FoldShape& shape, int k) {
  return meshless_reference(shape.xyz, shape.bottom, shape.right, shape.top, shape.left, k);
}

}  // namespace dbs_folds
