// Nearest-neighbour queries over a point cloud or a subset of it. nanoflann stays
// behind the pimpl: only cloud_index.cpp includes it. A large cloud is indexed as a forest:
// one nanoflann tree per spatial chunk (spatial_chunks.hpp), built in parallel with progress
// reported and a cancel taking effect after every chunk; queries visit the chunks whose boxes
// can hold an answer and give the same points as one tree would.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry.hpp"
#include "point_list.hpp"

namespace dbs {

class WorkMeter;

/// How an index is built: on how many threads, counting its work (one unit per
/// kPointsPerIndexUnit points of a pass) on an optional meter, in chunks of at most
/// chunk_points points (smaller than the default in tests only: the answers are the same).
struct IndexBuild {
  static constexpr std::size_t kDefaultChunkPoints = std::size_t{1} << 16;
  int threads = 1;
  WorkMeter* meter = nullptr;
  std::size_t chunk_points = kDefaultChunkPoints;
};

/// The units of work IndexBuild counts for an index of n points: exact when every halving
/// pass halves every range, an upper bound by a few units a pass otherwise.
std::uint64_t index_build_work(std::size_t n, std::size_t chunk_points = IndexBuild::kDefaultChunkPoints);

class CloudIndex {
 public:
  /// Indexes all of `points` (which must outlive the index).
  explicit CloudIndex(const std::vector<Vec3>& points, const IndexBuild& build = IndexBuild());
  /// Indexes only points[subset[k]]; queries still answer with indices into `points`.
  CloudIndex(const std::vector<Vec3>& points, const std::vector<std::size_t>& subset, const IndexBuild& build = IndexBuild());
  CloudIndex(const std::vector<Vec3>& points, const PointList& subset, const IndexBuild& build = IndexBuild());
  ~CloudIndex();
  CloudIndex(const CloudIndex&) = delete;
  CloudIndex& operator=(const CloudIndex&) = delete;

  const std::vector<Vec3>& points() const;
  /// Number of indexed points and of the chunks (trees) holding them.
  std::size_t size() const;
  std::size_t chunks() const;
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
  /// DirectedProjector). A dedicated k-d tree descent prunes every inner node whose box
  /// cannot hold such a point and tests every point of the leaves it reaches, so the cost
  /// follows the region, not the cloud. Unordered but deterministic; appended to out_idx
  /// after clearing. The first ray query copies the points into columns in the trees' leaf
  /// order (28 bytes a point), which later ones read.
  void near_ray(const Vec3& p, const Vec3& n, double bound, std::vector<std::size_t>& out_idx) const;
  /// Frees the columns near_ray made (the next ray query makes them again): for an index kept
  /// for a few more rays while others are made. Not while another thread queries the index.
  void release_ray_columns();

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
