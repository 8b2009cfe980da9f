#include "cloud_index.hpp"

#include <Eigen/Geometry>
#include <nanoflann.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#ifdef __SSE2__
#include <emmintrin.h>
#endif
#include <string>
#include <utility>

#include "error.hpp"
#include "parallel.hpp"
#include "spatial_chunks.hpp"
#include "work_meter.hpp"

// near_ray() walks nanoflann's tree itself: its public members (the permutation vAcc, the root
// node and the root's bounding box) and the nodes' node_type.lr / node_type.sub unions and
// child1 / child2 pointers. nanoflann 1.5 gave the three tree members a trailing underscore,
// renamed SearchParams (whose first, ignored "checks" argument went away) to SearchParameters
// and returns radius results as ResultItem instead of std::pair; the nodes kept their layout
// (checked against 1.5.5 and 1.7.1). These names are the only version-dependent code of
// libdbs, kept here; both series build the same tree (the same middle split), so near_ray,
// radius and knn give the same points with either.
#if !defined(NANOFLANN_VERSION) || NANOFLANN_VERSION < 0x130
#error "cloud_index.cpp needs nanoflann 1.3 or later"
#elif NANOFLANN_VERSION >= 0x150
#define DBS_NANOFLANN_MEMBER(name) name##_
#else
#define DBS_NANOFLANN_MEMBER(name) name
#endif

namespace dbs {

namespace {

/// The nanoflann dataset of one chunk: the points points[slots[k]], k < count. While the
/// tree is built, `columns` holds their coordinates one axis after the other (x of every
/// point, then y, then z): the build reads one axis at a time in the order of a permutation,
/// and a dense column of 8 bytes a point stays in cache far better than the 24-byte points,
/// which cuts most of its time. The same numbers: the same tree.
struct Dataset {
  const std::vector<Vec3>* points;
  const std::uint32_t* slots;
  std::size_t count = 0;
  const double* columns = nullptr;  // during the build only

  std::size_t map(std::size_t k) const { return slots[k]; }
  std::size_t kdtree_get_point_count() const { return count; }
  double kdtree_get_pt(std::uint32_t k, std::size_t dim) const {
    if (columns) return columns[dim * count + k];
    return (*points)[slots[k]][static_cast<Eigen::Index>(dim)];
  }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Metric = nanoflann::L2_Simple_Adaptor<double, Dataset, double, std::uint32_t>;
using Tree = nanoflann::KDTreeSingleIndexAdaptor<Metric, Dataset, 3, std::uint32_t>;
constexpr std::size_t kLeafSize = 12;

#if NANOFLANN_VERSION >= 0x150
using RadiusMatch = nanoflann::ResultItem<std::uint32_t, double>;
// exact searches (eps 0); `sorted` matters to radius searches only
nanoflann::SearchParameters exact_search(bool sorted) { return nanoflann::SearchParameters(0.0f, sorted); }
#else
using RadiusMatch = std::pair<std::uint32_t, double>;
nanoflann::SearchParams exact_search(bool sorted) { return nanoflann::SearchParams(32, 0.0f, sorted); }
#endif

/// Lower bounds over an axis-aligned box of |x - p| (the box's distance to p) and of the
/// distance of x to the line p + s u (u unit). For the latter, any axis a perpendicular to u
/// separates: the line projects onto a to the single value a.p, the box to an interval of
/// half-width sum_i |a_i| e_i around a.c, and their gap bounds the distance from below. The
/// axes tried are the direction from the line to the box centre and u x (each coordinate axis).
struct RayBoxBound {
  Vec3 p, u;
  /// The axes u x (each coordinate axis), their absolute values and squared lengths: the same for
  /// every box of one query, computed once.
  std::array<Vec3, 3> cross, cross_abs;
  std::array<double, 3> cross_length2;

  /// A point's own test, |d|^2 |d x u|^2 <= bound^2, scales as length^4: for a cloud near
  /// 1e-100 across both sides underflow to 0 (and every point passed), near 1e75 they come
  /// close to overflowing. So d is first scaled by `scale`, the power of two nearest
  /// 1/sqrt(bound): scaling by a power of two is exact, so wherever the unscaled test did not
  /// underflow or overflow it gives the same answer, bit for bit.
  double scale = 1.0;
  double scaled_bound, scaled_bound2;

  RayBoxBound(const Vec3& point, const Vec3& unit, double b) : p(point), u(unit) {
    cross = {{Vec3(0.0, -u.z(), u.y()), Vec3(u.z(), 0.0, -u.x()), Vec3(-u.y(), u.x(), 0.0)}};
    for (int a = 0; a < 3; ++a) {
      cross_abs[a] = cross[a].cwiseAbs();
      cross_length2[a] = cross[a].squaredNorm();
    }
    if (b > 0.0 && std::isfinite(b)) scale = std::ldexp(1.0, -std::ilogb(b) / 2);
    scaled_bound = b * scale * scale;
    scaled_bound2 = scaled_bound * scaled_bound;
  }

  /// The point test on d = x - p, written out: the leaves' column scan (LeafColumns::scan)
  /// runs this very arithmetic on two points at once, so both give the same answers.
  bool holds(double dx, double dy, double dz) const {
    const double sx = dx * scale, sy = dy * scale, sz = dz * scale;
    const double cx = sy * u.z() - sz * u.y(), cy = sz * u.x() - sx * u.z(), cz = sx * u.y() - sy * u.x();
    return (sx * sx + sy * sy + sz * sz) * (cx * cx + cy * cy + cz * cz) <= scaled_bound2;
  }

  /// Whether the box [lo, hi] may hold a point that holds(): false once r rho > bound for
  /// r the box's least distance to p and rho a lower bound of its distance to the line, the
  /// separation of the box along one axis (the part of its centre's offset across the line,
  /// or u x a coordinate axis) less its half-extent there. Compared squared, in the scaled
  /// units of holds() (where the bound is near 1, so the squares neither underflow nor
  /// overflow): one division instead of a square root and a division an axis.
  bool may_hold(const Vec3& lo, const Vec3& hi) const {
    const Vec3 outside = scale * (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
    // The box point nearest p has r rho <= r^2 (distance to the line <= distance to p), so a
    // box this close to p is kept without looking at the line.
    const double r2_min = outside.squaredNorm();
    if (r2_min <= scaled_bound) return true;
    // rho^2 above this refuses the box.
    const double rho2_limit = scaled_bound2 / r2_min;
    const Vec3 half = (0.5 * scale) * (hi - lo);
    const Vec3 offset = scale * (0.5 * (lo + hi) - p);
    auto separates = [&](const Vec3& axis, const Vec3& axis_abs, double length2) {
      const double gap = std::abs(axis.dot(offset)) - axis_abs.dot(half);  // rho times |axis|
      return gap > 0.0 && gap * gap > rho2_limit * length2;
    };
    const Vec3 across = offset - offset.dot(u) * u;
    if (separates(across, across.cwiseAbs(), across.squaredNorm())) return false;
    for (int a = 0; a < 3; ++a)
      if (separates(cross[a], cross_abs[a], cross_length2[a])) return false;
    return true;
  }
};

/// A chunk's points in the order of its tree's leaves (the permutation vAcc), as columns of
/// coordinates beside their point numbers: a leaf of the ray query is then a contiguous run
/// of each column, tested a few points at a time, instead of two indirections a point.
class LeafColumns {
 public:
  void resize(std::size_t n) {
    x_.resize(n);
    y_.resize(n);
    z_.resize(n);
    id_.resize(n);
  }
  void set(std::size_t k, std::uint32_t id, const Vec3& point) {
    x_[k] = point.x();
    y_[k] = point.y();
    z_[k] = point.z();
    id_[k] = id;
  }
  /// Appends to `out` the points among [begin, end) that query.holds(), in that order.
  void scan(std::size_t begin, std::size_t end, const RayBoxBound& query, std::vector<std::size_t>& out) const {
    std::size_t k = begin;
#ifdef __SSE2__
    // Two points at a time, with the operations of holds() in the same order (no fused
    // multiply-add: -ffp-contract=off, lib/CMakeLists.txt): the same answer for each point.
    const __m128d px = _mm_set1_pd(query.p.x()), py = _mm_set1_pd(query.p.y()), pz = _mm_set1_pd(query.p.z());
    const __m128d ux = _mm_set1_pd(query.u.x()), uy = _mm_set1_pd(query.u.y()), uz = _mm_set1_pd(query.u.z());
    const __m128d scale = _mm_set1_pd(query.scale), bound2 = _mm_set1_pd(query.scaled_bound2);
    for (; k + 2 <= end; k += 2) {
      const __m128d sx = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(&x_[k]), px), scale);
      const __m128d sy = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(&y_[k]), py), scale);
      const __m128d sz = _mm_mul_pd(_mm_sub_pd(_mm_loadu_pd(&z_[k]), pz), scale);
      const __m128d cx = _mm_sub_pd(_mm_mul_pd(sy, uz), _mm_mul_pd(sz, uy));
      const __m128d cy = _mm_sub_pd(_mm_mul_pd(sz, ux), _mm_mul_pd(sx, uz));
      const __m128d cz = _mm_sub_pd(_mm_mul_pd(sx, uy), _mm_mul_pd(sy, ux));
      const __m128d r2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(sx, sx), _mm_mul_pd(sy, sy)), _mm_mul_pd(sz, sz));
      const __m128d rho2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(cx, cx), _mm_mul_pd(cy, cy)), _mm_mul_pd(cz, cz));
      const int kept = _mm_movemask_pd(_mm_cmple_pd(_mm_mul_pd(r2, rho2), bound2));
      if (kept & 1) out.push_back(id_[k]);
      if (kept & 2) out.push_back(id_[k + 1]);
    }
#endif
    for (; k < end; ++k)
      if (query.holds(x_[k] - query.p.x(), y_[k] - query.p.y(), z_[k] - query.p.z())) out.push_back(id_[k]);
  }

 private:
  std::vector<double> x_, y_, z_;
  std::vector<std::uint32_t> id_;
};

/// A nanoflann KNN result set shared by the trees of a forest: each tree reports its own
/// point numbers, which become positions in the forest's slots (the chunk's first slot
/// added), so one set keeps the k nearest over every tree and prunes with the best so far.
struct ForestKnn {
  nanoflann::KNNResultSet<double, std::uint32_t>& found;
  std::uint32_t first_slot = 0;

  bool addPoint(double d2, std::uint32_t k) { return found.addPoint(d2, first_slot + k); }
  double worstDist() const { return found.worstDist(); }
  bool full() const { return found.full(); }
};

/// The squared distance of q to a box (0 inside).
double box_distance2(const Vec3& q, const Vec3& lo, const Vec3& hi) { return (lo - q).cwiseMax(q - hi).cwiseMax(0.0).squaredNorm(); }

}  // namespace

struct CloudIndex::Impl {
  /// One tree over a contiguous range of the slots.
  struct Chunk {
    Dataset dataset;
    std::unique_ptr<Tree> tree;
    std::uint32_t first_slot = 0;
    Vec3 lo, hi;  // the tree's root box
    /// The chunk's points in the tree's leaf order, for the ray queries, made by the first one
    /// (28 bytes a point; only indexes rays are cast on make them) and freed by
    /// release_ray_columns: `columns` is set once they are whole, under `columns_mutex`.
    mutable std::unique_ptr<LeafColumns> owned_columns;
    mutable std::atomic<const LeafColumns*> columns{nullptr};
    mutable std::mutex columns_mutex;

    const Tree::Node* root() const { return tree->DBS_NANOFLANN_MEMBER(root_node); }
    const LeafColumns& leaf_columns(const std::vector<Vec3>& points) const {
      if (const LeafColumns* made = columns.load(std::memory_order_acquire)) return *made;
      std::lock_guard<std::mutex> lock(columns_mutex);
      if (const LeafColumns* made = columns.load(std::memory_order_relaxed)) return *made;
      const auto& order = tree->DBS_NANOFLANN_MEMBER(vAcc);
      auto made = std::make_unique<LeafColumns>();
      made->resize(order.size());
      for (std::size_t k = 0; k < order.size(); ++k) made->set(k, static_cast<std::uint32_t>(dataset.map(order[k])), points[dataset.map(order[k])]);
      owned_columns = std::move(made);
      columns.store(owned_columns.get(), std::memory_order_release);
      return *owned_columns;
    }
    void release_columns() {
      columns.store(nullptr, std::memory_order_relaxed);
      owned_columns.reset();
    }
  };

  const std::vector<Vec3>& points;
  std::vector<std::uint32_t> subset;  // point_index order; empty for the whole cloud
  std::vector<std::uint32_t> slots;   // the indexed points, chunk after chunk
  std::vector<std::unique_ptr<Chunk>> chunks;

  Impl(const std::vector<Vec3>& pts, std::vector<std::uint32_t> sub, bool whole_cloud, const IndexBuild& build) : points(pts), subset(std::move(sub)) {
    if (whole_cloud) {
      slots.resize(points.size());
      for (std::size_t k = 0; k < slots.size(); ++k) slots[k] = static_cast<std::uint32_t>(k);
    } else {
      slots = subset;
    }
    const std::vector<ChunkRange> ranges = cut_into_chunks(points, slots, build.chunk_points, build.threads, build.meter);
    chunks.resize(ranges.size());
    metered_for(build.meter, ranges.size(), build.threads, [&](std::size_t c) {
      chunks[c] = make_chunk(ranges[c]);
      count_work(build.meter, index_units(ranges[c].begin, ranges[c].end));
    });
  }

  std::unique_ptr<Chunk> make_chunk(const ChunkRange& range) const {
    auto chunk = std::make_unique<Chunk>();
    chunk->first_slot = static_cast<std::uint32_t>(range.begin);
    chunk->dataset = Dataset{&points, slots.data() + range.begin, range.end - range.begin};
    const std::vector<double> columns = by_axis(chunk->dataset);
    chunk->dataset.columns = columns.data();
    chunk->tree = std::make_unique<Tree>(3, chunk->dataset, nanoflann::KDTreeSingleIndexAdaptorParams(kLeafSize));
    chunk->dataset.columns = nullptr;
    const auto& box = chunk->tree->DBS_NANOFLANN_MEMBER(root_bbox);
    chunk->lo = Vec3(box[0].low, box[1].low, box[2].low);
    chunk->hi = Vec3(box[0].high, box[1].high, box[2].high);
    return chunk;
  }

  /// The columns of `data` for its build.
  static std::vector<double> by_axis(const Dataset& data) {
    const std::size_t n = data.count;
    std::vector<double> out(3 * n);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& p = (*data.points)[data.map(k)];
      for (int axis = 0; axis < 3; ++axis) out[static_cast<std::size_t>(axis) * n + k] = p[axis];
    }
    return out;
  }

  void collect_near_ray(const LeafColumns& columns, const Tree::Node* node, Vec3 lo, Vec3 hi, const RayBoxBound& query, std::vector<std::size_t>& out) const {
    // A leaf is scanned without its box test: testing its few points costs about as much.
    if (node->child1 == nullptr && node->child2 == nullptr) {
      columns.scan(node->node_type.lr.left, node->node_type.lr.right, query, out);
      return;
    }
    if (!query.may_hold(lo, hi)) return;
    const int axis = node->node_type.sub.divfeat;
    Vec3 hi_low = hi, lo_high = lo;
    hi_low[axis] = node->node_type.sub.divlow;
    lo_high[axis] = node->node_type.sub.divhigh;
    collect_near_ray(columns, node->child1, lo, hi_low, query, out);
    collect_near_ray(columns, node->child2, lo_high, hi, query, out);
  }

  /// The k nearest over every chunk into `found`: the chunks nearest to q first, a chunk
  /// whose box is farther than the k-th point found so far skipped.
  void knn(const Vec3& q, nanoflann::KNNResultSet<double, std::uint32_t>& found) const {
    if (chunks.size() == 1) {  // a surface's sample tree, a patch's subcloud: nothing to order
      ForestKnn shared{found, chunks[0]->first_slot};
      chunks[0]->tree->findNeighbors(shared, q.data(), exact_search(true));
      return;
    }
    thread_local std::vector<std::pair<double, std::size_t>> order;
    order.clear();
    for (std::size_t c = 0; c < chunks.size(); ++c) order.emplace_back(box_distance2(q, chunks[c]->lo, chunks[c]->hi), c);
    std::sort(order.begin(), order.end());
    for (const auto& [d2, c] : order) {
      if (found.full() && d2 > found.worstDist()) break;
      ForestKnn shared{found, chunks[c]->first_slot};
      chunks[c]->tree->findNeighbors(shared, q.data(), exact_search(true));
    }
  }
};

namespace {

template <class Index>
std::vector<std::uint32_t> checked_subset(const std::vector<Vec3>& points, const std::vector<Index>& subset) {
  if (points.size() > std::numeric_limits<std::uint32_t>::max()) fail(ErrorCode::OutOfRange, "CloudIndex: more than 2^32-1 points");
  std::vector<std::uint32_t> checked(subset.size());
  for (std::size_t k = 0; k < subset.size(); ++k) {
    if (subset[k] >= points.size())
      fail(ErrorCode::OutOfRange, "CloudIndex: subset entry " + std::to_string(k) + " = " + std::to_string(subset[k]) + " is not below the point count " + std::to_string(points.size()));
    checked[k] = static_cast<std::uint32_t>(subset[k]);
  }
  return checked;
}

}  // namespace

std::uint64_t index_build_work(std::size_t n, std::size_t chunk_points) {
  // Every halving pass reads all n points (all but a few when the halves differ by one point
  // and only the larger is halved again), and so does the build of the trees.
  return index_units(0, n) * static_cast<std::uint64_t>(halving_passes(n, chunk_points) + 1);
}

CloudIndex::CloudIndex(const std::vector<Vec3>& points, const IndexBuild& build) : impl_(std::make_unique<Impl>(points, checked_subset(points, PointList()), true, build)) {}

CloudIndex::CloudIndex(const std::vector<Vec3>& points, const std::vector<std::size_t>& subset, const IndexBuild& build)
    : impl_(std::make_unique<Impl>(points, checked_subset(points, subset), false, build)) {}

CloudIndex::CloudIndex(const std::vector<Vec3>& points, const PointList& subset, const IndexBuild& build)
    : impl_(std::make_unique<Impl>(points, checked_subset(points, subset), false, build)) {}

CloudIndex::~CloudIndex() = default;

const std::vector<Vec3>& CloudIndex::points() const { return impl_->points; }

std::size_t CloudIndex::size() const { return impl_->slots.size(); }

std::size_t CloudIndex::chunks() const { return impl_->chunks.size(); }

std::size_t CloudIndex::point_index(std::size_t k) const { return impl_->subset.empty() ? k : impl_->subset[k]; }

std::size_t CloudIndex::nearest(const Vec3& q) const {
  if (size() == 0) fail(ErrorCode::Empty, "CloudIndex::nearest: the index holds no points");
  std::uint32_t k = 0;
  double d2 = 0.0;
  nanoflann::KNNResultSet<double, std::uint32_t> result(1);
  result.init(&k, &d2);
  impl_->knn(q, result);
  return impl_->slots[k];
}

void CloudIndex::knn(const Vec3& q, std::size_t k, std::vector<std::size_t>& out_idx, std::vector<double>& out_d2) const {
  out_idx.clear();
  out_d2.clear();
  k = std::min(k, size());
  if (k == 0) return;
  thread_local std::vector<std::uint32_t> found;  // scratch: no allocation per query
  found.resize(k);
  out_d2.resize(k);
  nanoflann::KNNResultSet<double, std::uint32_t> result(k);
  result.init(found.data(), out_d2.data());
  impl_->knn(q, result);
  const std::size_t count = result.size();
  out_d2.resize(count);
  out_idx.resize(count);
  for (std::size_t i = 0; i < count; ++i) out_idx[i] = impl_->slots[found[i]];
}

void CloudIndex::radius(const Vec3& q, double r, std::vector<std::size_t>& out_idx) const {
  out_idx.clear();
  if (size() == 0 || !(r >= 0.0)) return;
  thread_local std::vector<RadiusMatch> found;
  for (const auto& chunk : impl_->chunks) {
    if (box_distance2(q, chunk->lo, chunk->hi) > r * r) continue;
    found.clear();
    chunk->tree->radiusSearch(q.data(), r * r, found, exact_search(false));
    for (const auto& f : found) out_idx.push_back(chunk->dataset.map(f.first));
  }
}

void CloudIndex::near_ray(const Vec3& p, const Vec3& n, double bound, std::vector<std::size_t>& out_idx) const {
  out_idx.clear();
  const double length = n.norm();
  if (size() == 0 || !(length > 0.0)) return;
  const RayBoxBound query{p, n / length, bound};
  for (const auto& chunk : impl_->chunks) impl_->collect_near_ray(chunk->leaf_columns(impl_->points), chunk->root(), chunk->lo, chunk->hi, query, out_idx);
}

void CloudIndex::release_ray_columns() {
  for (const auto& chunk : impl_->chunks) chunk->release_columns();
}

double cloud_spacing(const CloudIndex& index, std::size_t max_samples, int threads) {
  const std::size_t n = index.size();
  const std::size_t samples = std::min(n, std::max<std::size_t>(max_samples, 1));
  const std::vector<Vec3>& points = index.points();
  // Each sample's distance alone (0: no distinct neighbour), summed in order afterwards:
  // the same sum for any thread count.
  std::vector<double> nearest(samples, 0.0);
  parallel_for(samples, threads, [&](std::size_t s) {
    thread_local std::vector<std::size_t> idx;
    thread_local std::vector<double> d2;
    const Vec3& q = points[index.point_index(s * n / samples)];
    // Widen the query until it reaches a point distinct from q (duplicates sit at d2 == 0).
    for (std::size_t k = 2;; k = std::min(2 * k, n)) {
      index.knn(q, k, idx, d2);
      const auto distinct = std::find_if(d2.begin(), d2.end(), [](double v) { return v > 0.0; });
      if (distinct != d2.end()) {
        nearest[s] = std::sqrt(*distinct);
        break;
      }
      if (k >= n) break;
    }
  });
  double sum = 0.0;
  std::size_t counted = 0;
  for (double d : nearest)
    if (d > 0.0) {
      sum += d;
      ++counted;
    }
  if (counted == 0) fail(ErrorCode::Degenerate, "the cloud has fewer than two distinct points (" + std::to_string(n) + " points indexed)");
  return sum / static_cast<double>(counted);
}

}  // namespace dbs
