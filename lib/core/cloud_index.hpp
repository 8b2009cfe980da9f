// Nearest-neighbour queries over a point cloud or a subset of it. nanoflann stays
// behind the pimpl: only cloud_index.cpp includes it.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "geometry.hpp"

namespace dbs {

class CloudIndex {
 public:
  /// Indexes all of `points` (which must outlive the index).
  explicit CloudIndex(const std::vector<Vec3>& points);
  /// Indexes only points[subset[k]]; queries still answer with indices into `points`.
  CloudIndex(const std::vector<Vec3>& points, std::vector<std::size_t> subset);
  ~CloudIndex();
  CloudIndex(const CloudIndex&) = delete;
  CloudIndex& operator=(const CloudIndex&) = delete;

  const std::vector<Vec3>& points() const;
  /// Number of indexed points.
  std::size_t size() const;
  /// Index into points() of the k-th indexed point (k < size()): k itself for a whole-cloud
  /// index, subset[k] for a subset index.
  std::size_t point_index(std::size_t k) const;
  /// Index (into points()) of the indexed point nearest to q. Requires size() > 0.
  std::size_t nearest(const Vec3& q) const;
  /// The k nearest indexed points, nearest first; out_d2 gets squared distances.
  void knn(const Vec3& q, std::size_t k, std::vector<std::size_t>& out_idx, std::vector<double>& out_d2) const;
  /// All indexed points within distance r of q (unordered; appended to out_idx after clearing).
  void radius(const Vec3& q, double r, std::vector<std::size_t>& out_idx) const;
  /// All indexed points x with |x - p| * dist(x, line) <= bound, where line is the whole
  /// line through p along n (n != 0, need not be unit) and bound has the dimension of an
  /// area: the region where the weight of eq. (5) can exceed a threshold (see
  /// DirectedProjector). A dedicated k-d tree descent prunes every node whose box cannot
  /// hold such a point, so the cost follows the region, not the cloud. Unordered but
  /// deterministic; appended to out_idx after clearing.
  void near_ray(const Vec3& p, const Vec3& n, double bound, std::vector<std::size_t>& out_idx) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Length scale h of a cloud: the mean distance of a point to its nearest neighbour,
/// estimated deterministically on at most `max_samples` evenly strided points. Duplicate
/// points are skipped (the next distinct neighbour counts). Scales exactly with the input.
/// threads as Options::threads; the same result for any thread count.
double cloud_spacing(const CloudIndex& index, std::size_t max_samples = 20000, int threads = 1);

}  // namespace dbs
