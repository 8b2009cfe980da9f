#include "fold_measure.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <tuple>
#include <utility>

#include "cloud_index.hpp"
#include "error.hpp"
#include "fold_local.hpp"
#include "indexed_heap.hpp"
#include "parallel.hpp"
#include "torn_points.hpp"

namespace dbs {

using namespace fold;
using fold_detail::kNoNeighbour;
using fold_detail::Local;
using fold_detail::same_sheet;

namespace {

constexpr double kTornWeight = 2.0;  // above any untorn edge's 1 - |n_i.n_j| <= 1 - kMinEdgeCosine


/// Eigenvalues (ascending) of the symmetric 2x2 [a b; b c].
std::pair<double, double> eigen2(double a, double b, double c) {
  const double mean = 0.5 * (a + c), half = 0.5 * (a - c);
  const double r = std::hypot(half, b);
  return {mean - r, mean + r};
}

/// The cloud indexed whole (level 0) and thinned to every 4^k-th point (level k), so that a
/// wide neighbourhood costs about kMaxNeighbourhood points whatever its radius.
class Levels {
 public:
  Levels(const std::vector<Vec3>& points, const CloudIndex& whole) : whole_(whole) {
    for (std::size_t stride = 4; points.size() / stride >= kMaxNeighbourhood; stride *= 4) {
      std::vector<std::size_t> subset;
      for (std::size_t i = 0; i < points.size(); i += stride) subset.push_back(i);
      thinned_.push_back(std::make_unique<CloudIndex>(points, std::move(subset)));
      strides_.push_back(stride);
    }
  }

  /// Points within `radius` of points[i] (i itself included once), ascending by index; about
  /// kMaxNeighbourhood at most. `expected` estimates how many the whole cloud holds there; the
  /// search starts one level coarser than that suggests and goes finer while it finds fewer
  /// than a quarter of kMaxNeighbourhood; what it finds is then thinned evenly by index.
  void within(std::size_t i, double radius, double expected, std::vector<std::size_t>& out) const {
    const Vec3& p = whole_.points()[i];
    const double enough = 0.25 * static_cast<double>(kMaxNeighbourhood);
    std::size_t level = 0;
    while (level < strides_.size() && expected / static_cast<double>(strides_[level]) > static_cast<double>(kMaxNeighbourhood)) ++level;
    level = std::min(level + 1, strides_.size());
    for (;; --level) {
      (level == 0 ? whole_ : *thinned_[level - 1]).radius(p, radius, out);
      if (level == 0 || static_cast<double>(out.size()) >= enough) break;
    }
    out.push_back(i);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    const std::size_t m = out.size();
    if (m > kMaxNeighbourhood) {
      std::size_t kept = 0;
      bool has_i = false;
      for (std::size_t t = 0; t < kMaxNeighbourhood; ++t) {
        out[kept] = out[t * m / kMaxNeighbourhood];
        has_i = has_i || out[kept] == i;
        ++kept;
      }
      out.resize(kept);
      if (!has_i) out.insert(std::lower_bound(out.begin(), out.end(), i), i);
    }
  }

 private:
  const CloudIndex& whole_;
  std::vector<std::unique_ptr<CloudIndex>> thinned_;
  std::vector<std::size_t> strides_;
};

/// One neighbour of the point being analysed.
struct Neighbour {
  Vec3 d;        // position relative to the point
  double du, dv;  // parameters relative to the point's
  double ratio;   // |(du,dv)| / |d|; infinite for a duplicate point elsewhere in (u,v)
};

/// PCA frame and the sign of the local linear map to (u,v) at point i.
Local analyse(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, std::size_t i, const std::vector<std::size_t>& nb,
              std::vector<Neighbour>& near, std::vector<double>& ratios) {
  Local out;
  if (nb.size() < 4) return out;
  // Tears: neighbours much farther in (u,v) than their distance suggests (the other side of a
  // thin flap, a seam, a flipped patch's rim) are left out of the frame and the fit. The
  // typical stretch is a low quantile, so that up to most of the neighbours may be torn.
  const Vec3& p = points[i];
  near.clear();
  ratios.clear();
  for (std::size_t j : nb) {
    if (j == i) continue;
    Neighbour q{points[j] - p, u[j] - u[i], v[j] - v[i], 0.0};
    const double dp = q.d.norm(), duv = std::sqrt(q.du * q.du + q.dv * q.dv);
    if (dp > 0.0) {
      q.ratio = duv / dp;
      ratios.push_back(q.ratio);
    } else if (duv > 0.0) {
      q.ratio = std::numeric_limits<double>::infinity();
    } else {
      continue;  // a duplicate with the same (u,v): no information
    }
    near.push_back(q);
  }
  double tear = std::numeric_limits<double>::infinity();
  if (ratios.size() >= 4) {
    const auto at = ratios.begin() + static_cast<std::ptrdiff_t>(static_cast<double>(ratios.size() - 1) * kStretchQuantile);
    std::nth_element(ratios.begin(), at, ratios.end());
    out.stretch = *at;
    if (out.stretch > 0.0) tear = kTearRatio * out.stretch;
  }
  // The frame: PCA over the point and its untorn neighbours (all of them without a stretch).
  Vec3 centroid = Vec3::Zero();
  std::size_t untorn = 0;
  for (const Neighbour& q : near)
    if (q.ratio <= tear) centroid += q.d, ++untorn;
  if (untorn + 1 < 4) return out;
  centroid /= static_cast<double>(untorn + 1);  // p itself sits at d = 0
  Eigen::Matrix3d cov = centroid * centroid.transpose();
  for (const Neighbour& q : near)
    if (q.ratio <= tear) {
      const Vec3 d = q.d - centroid;
      cov.noalias() += d * d.transpose();
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  if (eig.info() != Eigen::Success) return out;
  const Vec3 lambda = eig.eigenvalues();  // ascending
  if (!(lambda[1] > 0.0) || lambda[0] > kMaxFlatness * lambda[1]) return out;
  out.normal = eig.eigenvectors().col(0);
  out.surface_like = true;
  if (!(out.stretch > 0.0)) {  // collapsed: most neighbours share the point's (u,v)
    out.collapsed = ratios.size() >= 4;
    return out;
  }
  const Vec3 e1 = eig.eigenvectors().col(2);
  const Vec3 e2 = out.normal.cross(e1);

  // Least squares duv = J xy over the kept neighbours, relative to the point.
  double axx = 0, axy = 0, ayy = 0;          // A = sum xy xy^T
  double bux = 0, buy = 0, bvx = 0, bvy = 0;  // B = sum duv xy^T
  double total = 0;                            // sum |duv|^2
  std::size_t kept = 0;
  for (Neighbour& q : near) {
    if (!(q.ratio <= tear)) continue;
    const double x = q.d.dot(e1), y = q.d.dot(e2);
    q.d.x() = x, q.d.y() = y;  // tangent coordinates, for the residual below
    axx += x * x, axy += x * y, ayy += y * y;
    bux += q.du * x, buy += q.du * y, bvx += q.dv * x, bvy += q.dv * y;
    total += q.du * q.du + q.dv * q.dv;
    ++kept;
  }
  if (kept < 6 || !(total > 0.0)) return out;
  const auto [a_min, a_max] = eigen2(axx, axy, ayy);
  if (!(a_min > kMinSpread * a_max)) return out;
  const double det_a = axx * ayy - axy * axy;
  // J = B A^-1
  const double j11 = (bux * ayy - buy * axy) / det_a, j12 = (buy * axx - bux * axy) / det_a;
  const double j21 = (bvx * ayy - bvy * axy) / det_a, j22 = (bvy * axx - bvx * axy) / det_a;
  double residual = 0;
  for (const Neighbour& q : near) {
    if (!(q.ratio <= tear)) continue;
    const double x = q.d.x(), y = q.d.y();
    const double ru = q.du - (j11 * x + j12 * y), rv = q.dv - (j21 * x + j22 * y);
    residual += ru * ru + rv * rv;
  }
  if (residual > kMaxResidual * total) {
    out.scrambled = true;
    return out;
  }
  const double det = j11 * j22 - j12 * j21;
  const double frob2 = j11 * j11 + j12 * j12 + j21 * j21 + j22 * j22;
  const double s_max = std::sqrt(0.5 * (frob2 + std::sqrt(std::max(0.0, frob2 * frob2 - 4.0 * det * det))));
  if (!(s_max > 0.0)) return out;
  const double s_min = std::abs(det) / s_max;
  // Standard error of J's entries along the least constrained tangent direction.
  const double sigma_r = std::sqrt(residual / (2.0 * static_cast<double>(kept - 2)));
  const double stderr_j = sigma_r / std::sqrt(a_min);
  if (s_min <= s_max / kMaxCondition) {  // squeezed onto a line (or a point)
    out.collapsed = true;
    return out;
  }
  if (s_min <= kSignificance * stderr_j) return out;
  out.sign = det > 0.0 ? 1 : -1;
  out.abs_det = std::abs(det);
  return out;
}

/// Orientation of the normals: Prim's minimum spanning tree over the surface-like points of
/// the graph, weight 1 - |n_i.n_j|, each component from its lowest index. A torn edge (its
/// |(du,dv)| / |dp| above kTearRatio x the larger stretch of its ends) weighs kTornWeight more,
/// so the normals follow the parameterization's continuous paths where it has them (around a
/// thin flap rather than across it) and cross a tear only to reach what nothing else reaches.
/// out_orient[i] is +1 or -1 (0 for a point outside the graph), out_component[i] the
/// component (or kNoNeighbour).
void orient(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Local>& local, const std::vector<std::uint32_t>& graph, std::vector<std::int8_t>& out_orient,
            std::vector<std::uint32_t>& out_component, std::uint32_t& out_components) {
  const std::size_t n = local.size();
  // Kept edges of each point's nearest, both directions, then per point sorted and unique.
  auto keep = [&](std::size_t i, std::uint32_t j) { return same_sheet(points, local, i, j); };
  std::vector<std::uint8_t> kept(graph.size(), 0);
  std::vector<std::size_t> start(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!local[i].surface_like) continue;
    for (std::size_t t = 0; t < kGraphNeighbours; ++t) {
      const std::uint32_t j = graph[i * kGraphNeighbours + t];
      if (j == kNoNeighbour) break;
      if (keep(i, j)) kept[i * kGraphNeighbours + t] = 1, ++start[i + 1], ++start[j + 1];
    }
  }
  for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<std::uint32_t> adjacent(start[n]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t t = 0; t < kGraphNeighbours; ++t)
      if (kept[i * kGraphNeighbours + t]) {
        const std::uint32_t j = graph[i * kGraphNeighbours + t];
        adjacent[fill[i]++] = j, adjacent[fill[j]++] = static_cast<std::uint32_t>(i);
      }
  std::vector<std::size_t> end(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto first = adjacent.begin() + static_cast<std::ptrdiff_t>(start[i]), last = adjacent.begin() + static_cast<std::ptrdiff_t>(start[i + 1]);
    std::sort(first, last);
    end[i] = start[i] + static_cast<std::size_t>(std::unique(first, last) - first);
  }

  out_orient.assign(n, 0);
  out_component.assign(n, kNoNeighbour);
  out_components = 0;
  // Each unoriented point's lightest edge from an oriented one (weight, then from): the
  // edges in Prim's order, lightest first, ties by (to, from).
  IndexedMinHeap heap(n);
  auto push_edges = [&](std::uint32_t from) {
    for (std::size_t e = start[from]; e < end[from]; ++e) {
      const std::uint32_t to = adjacent[e];
      if (out_orient[to] != 0) continue;
      double w = 1.0 - std::abs(local[from].normal.dot(local[to].normal));
      const double stretch = std::max(local[from].stretch, local[to].stretch);
      const double du = u[to] - u[from], dv = v[to] - v[from];
      const Vec3 d = points[to] - points[from];
      if (stretch > 0.0 && std::sqrt(du * du + dv * dv) > kTearRatio * stretch * d.norm()) w += kTornWeight;
      heap.offer(to, w, from);
    }
  };
  for (std::size_t s = 0; s < n; ++s) {
    if (!local[s].surface_like || out_orient[s] != 0) continue;
    const std::uint32_t component = out_components++;
    out_orient[s] = 1;
    out_component[s] = component;
    push_edges(static_cast<std::uint32_t>(s));
    while (!heap.empty()) {
      const IndexedMinHeap::Entry edge = heap.pop();
      const std::uint32_t to = edge.id, from = edge.payload;
      const double agree = (static_cast<double>(out_orient[from]) * local[from].normal).dot(local[to].normal);
      out_orient[to] = agree >= 0.0 ? 1 : -1;
      out_component[to] = component;
      push_edges(to);
    }
  }
}

void check_sizes(std::size_t points, const std::vector<double>& u, const std::vector<double>& v, const char* what) {
  if (u.size() != points || v.size() != points)
    fail(ErrorCode::InvalidArgument, std::string(what) + ": " + std::to_string(points) + " points but " + std::to_string(u.size()) + " u and " + std::to_string(v.size()) + " v values");
}

}  // namespace

std::size_t count_coincident(const std::vector<double>& u, const std::vector<double>& v) {
  check_sizes(u.size(), u, v, "count_coincident");
  const std::size_t n = u.size();
  // Sorted by (cell of u, v, index), cells kCoincident wide: a partner of (u,v) lies in the
  // cells from cell(u - eps) to cell(u + eps) (floor and division are monotonic), within
  // v +- eps there.
  auto cell = [](double x) { return std::floor(x / kCoincident); };
  std::vector<std::tuple<double, double, std::size_t>> keys(n);
  for (std::size_t i = 0; i < n; ++i) keys[i] = {cell(u[i]), v[i], i};
  std::sort(keys.begin(), keys.end());
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    bool found = false;
    const double c_hi = cell(u[i] + kCoincident);
    for (double c = cell(u[i] - kCoincident); c <= c_hi && !found;) {
      auto it = std::lower_bound(keys.begin(), keys.end(), std::make_tuple(c, v[i] - kCoincident, std::size_t{0}));
      for (; it != keys.end() && std::get<0>(*it) == c && std::get<1>(*it) <= v[i] + kCoincident; ++it) {
        const std::size_t j = std::get<2>(*it);
        if (j != i && std::abs(u[j] - u[i]) <= kCoincident && std::abs(v[j] - v[i]) <= kCoincident) {
          found = true;
          break;
        }
      }
      const double next = c + 1.0;
      if (!(next > c)) break;  // |u| beyond 2^53 cells: one cell holds every partner
      c = next;
    }
    if (found) ++count;
  }
  return count;
}

/// A cloud and what the measure finds from it alone. Clouds of extreme sizes are judged
/// scaled by a power of two near the inverse of their size, which is exact: products of four
/// lengths (the determinant of the tangent moments) under- or overflow for a cloud 1e-100 or
/// 1e75 across, and the verdicts are those of the same cloud at unit size. Clouds of ordinary
/// sizes are judged as they are.
struct FoldNeighbourhoods::Impl {
  const std::vector<Vec3>* points = nullptr;  // the caller's, or `scaled`
  std::vector<Vec3> scaled;
  double sigma = 0.0;
  bool keep = false;  // neighbourhoods kept from one judge to the next (FoldNeighbourhoods)
  // Null for fewer than 4 points or fewer than two distinct ones (every point undecided).
  std::unique_ptr<CloudIndex> index;
  std::unique_ptr<Levels> levels;
  double radius = 0.0;
  // Per point: the orientation graph's edges and the reach of its k nearest (found with its
  // first neighbourhood); kept, the neighbourhood and the wider one tried when that is not
  // surface-like.
  std::vector<std::uint32_t> graph;
  std::vector<double> knn_reach;
  std::vector<char> found, retried;
  std::vector<std::vector<std::size_t>> first, wider;

  Impl(const std::vector<Vec3>& cloud, double noise_sigma, bool keep_neighbourhoods) : keep(keep_neighbourhoods) {
    if (!std::isfinite(noise_sigma)) fail(ErrorCode::NonFinite, "measure_folds: the noise level is not finite");
    if (noise_sigma < 0.0) fail(ErrorCode::InvalidArgument, "measure_folds: the noise level " + std::to_string(noise_sigma) + " is negative");
    for (std::size_t i = 0; i < cloud.size(); ++i)
      if (!is_finite(cloud[i])) fail(ErrorCode::NonFinite, "measure_folds: point " + std::to_string(i) + " is not finite");
    points = &cloud;
    sigma = noise_sigma;
    const double size = bounds_of(cloud).diagonal();
    if (size > 0.0 && (size < 0x1p-20 || size > 0x1p20)) {
      const double scale = std::ldexp(1.0, -std::ilogb(size));
      scaled.resize(cloud.size());
      for (std::size_t i = 0; i < cloud.size(); ++i) scaled[i] = cloud[i] * scale;
      points = &scaled;
      sigma = noise_sigma * scale;
    }
    const std::size_t n = cloud.size();
    if (n < 4) return;
    index = std::make_unique<CloudIndex>(*points);
    double spacing = 0.0;
    try {
      spacing = cloud_spacing(*index);
    } catch (const Error& e) {
      if (e.code() != ErrorCode::Degenerate) throw;
      index.reset();  // fewer than two distinct points
      return;
    }
    radius = std::max(kSpacingRadius * spacing, kNoiseRadius * sigma);
    levels = std::make_unique<Levels>(*points, *index);
    graph.assign(n * kGraphNeighbours, kNoNeighbour);
    knn_reach.assign(n, 0.0);
    found.assign(n, 0);
    if (keep) {
      retried.assign(n, 0);
      first.resize(n);
      wider.resize(n);
    }
  }

  /// Points expected within r of point i, from its k nearest on a surface (~r^2; more in a
  /// thick cloud).
  double expected(std::size_t i, double r) const {
    const double reach = knn_reach[i];
    return reach > 0.0 ? static_cast<double>(kNeighbours) * (r / reach) * (r / reach) : 0.0;
  }

  /// Point i's neighbourhood: the k nearest, or every point within the radius when that
  /// reaches farther. Its first search also finds the point's graph edges.
  void neighbourhood(std::size_t i, std::vector<std::size_t>& nb, std::vector<double>& d2) {
    if (keep && found[i]) {
      nb = first[i];
      return;
    }
    const std::vector<Vec3>& p = *points;
    index->knn(p[i], kNeighbours, nb, d2);
    std::size_t t = 0;
    for (std::size_t j : nb) {  // nearest first
      if (t == kGraphNeighbours) break;
      if (j != i && p[j] != p[i]) graph[i * kGraphNeighbours + t++] = static_cast<std::uint32_t>(j);
    }
    knn_reach[i] = std::sqrt(d2.back());
    if (radius > knn_reach[i]) levels->within(i, radius, expected(i, radius), nb);
    found[i] = 1;
    if (keep) first[i] = nb;
  }

  /// Point i's neighbourhood kRetryRadius x wider than its reach (one-sided at a border, or
  /// noisy for its size).
  void wider_neighbourhood(std::size_t i, std::vector<std::size_t>& nb) {
    if (keep && retried[i]) {
      nb = wider[i];
      return;
    }
    const double reach = std::max(knn_reach[i], radius);
    levels->within(i, kRetryRadius * reach, expected(i, kRetryRadius * reach), nb);
    if (keep) wider[i] = nb, retried[i] = 1;
  }

  FoldMeasure judge(const std::vector<double>& u, const std::vector<double>& v, int threads, WorkMeter* meter);
};

FoldNeighbourhoods::FoldNeighbourhoods(const std::vector<Vec3>& points, double noise_sigma) : impl_(std::make_unique<Impl>(points, noise_sigma, true)) {}

FoldNeighbourhoods::~FoldNeighbourhoods() = default;

std::size_t FoldNeighbourhoods::size() const { return impl_->points->size(); }

FoldMeasure FoldNeighbourhoods::judge(const std::vector<double>& u, const std::vector<double>& v, int threads, WorkMeter* meter) { return impl_->judge(u, v, threads, meter); }

FoldMeasure measure_folds(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, double noise_sigma, int threads, WorkMeter* meter) {
  check_sizes(points.size(), u, v, "measure_folds");
  return FoldNeighbourhoods::Impl(points, noise_sigma, false).judge(u, v, threads, meter);
}

FoldMeasure FoldNeighbourhoods::Impl::judge(const std::vector<double>& u, const std::vector<double>& v, int threads, WorkMeter* meter) {
  const std::vector<Vec3>& p = *points;
  const std::size_t n = p.size();
  check_sizes(n, u, v, "measure_folds");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(u[i]) || !std::isfinite(v[i])) fail(ErrorCode::NonFinite, "measure_folds: the (u,v) of point " + std::to_string(i) + " is not finite");

  FoldMeasure m;
  m.points = n;
  m.state.assign(n, kFoldUndecided);
  m.right_normal.assign(n, Vec3::Zero());
  m.coincident = count_coincident(u, v);
  m.undecided = n;
  if (!index) return m;
  const int workers = resolve_threads(threads);

  // 1. Local frames and signs (the orientation graph's edges come with the neighbourhoods).
  std::vector<Local> local(n);
  const std::size_t chunks = std::min<std::size_t>(static_cast<std::size_t>(workers), n);
  metered_for(meter, chunks, workers, [&](std::size_t c) {
    std::vector<std::size_t> nb;
    std::vector<double> d2, ratios;
    std::vector<Neighbour> near;
    for (std::size_t i = n * c / chunks; i < n * (c + 1) / chunks; ++i) {
      neighbourhood(i, nb, d2);
      local[i] = analyse(p, u, v, i, nb, near, ratios);
      if (!local[i].surface_like && std::max(knn_reach[i], radius) > 0.0) {
        wider_neighbourhood(i, nb);
        local[i] = analyse(p, u, v, i, nb, near, ratios);
      }
      count_work(meter);
    }
  });

  // 2. Maps squeezed far below the typical |det J| are not judged.
  std::vector<double> dets;
  for (const Local& l : local)
    if (l.sign != 0) dets.push_back(l.abs_det);
  if (!dets.empty()) {
    std::nth_element(dets.begin(), dets.begin() + static_cast<std::ptrdiff_t>(dets.size() / 2), dets.end());
    const double floor = kMinDetShare * dets[dets.size() / 2];
    for (Local& l : local)
      if (l.sign != 0 && l.abs_det < floor) {
        l.sign = 0;
        l.collapsed = true;
      }
  }

  // 3. Consistent normals, then each component's majority sign is the right one.
  std::vector<std::int8_t> orientation;
  std::vector<std::uint32_t> component;
  std::uint32_t components = 0;
  orient(p, u, v, local, graph, orientation, component, components);
  std::vector<std::int64_t> balance(components, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (local[i].sign != 0 && orientation[i] != 0) balance[component[i]] += local[i].sign * orientation[i];
  m.undecided = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (orientation[i] != 0 && balance[component[i]] != 0)
      m.right_normal[i] = (orientation[i] * (balance[component[i]] > 0 ? 1.0 : -1.0)) * local[i].normal;
    const int sign = local[i].sign * orientation[i];
    const std::int64_t b = sign == 0 ? 0 : balance[component[i]];
    if (sign == 0 || b == 0) {
      m.state[i] = local[i].collapsed ? kFoldCollapsed : local[i].scrambled ? kFoldScrambled : kFoldUndecided;
      ++m.undecided;
      if (local[i].collapsed) ++m.collapsed;
    } else if ((sign > 0) == (b > 0)) {
      m.state[i] = kFoldOk;
    } else {
      m.state[i] = kFolded;
      ++m.folded;
    }
  }
  fold_detail::mark_torn(p, u, v, local, graph, m);
  const std::size_t decided = n - m.undecided;
  m.folded_share = decided == 0 ? 0.0 : static_cast<double>(m.folded) / static_cast<double>(decided);
  return m;
}

template <class T>
std::vector<T> spread_from_judged(const std::vector<Vec3>& points, const std::vector<std::size_t>& judged, const std::vector<T>& values, int threads, WorkMeter* meter) {
  if (judged.size() != values.size() || judged.empty())
    fail(ErrorCode::InvalidArgument, "spread_from_judged: " + std::to_string(judged.size()) + " judged points but " + std::to_string(values.size()) + " values");
  const std::size_t n = points.size();
  std::vector<std::size_t> slot(n, 0);
  for (std::size_t k = 0; k < judged.size(); ++k) {
    if (judged[k] >= n) fail(ErrorCode::InvalidArgument, "spread_from_judged: judged point " + std::to_string(judged[k]) + " is not one of the " + std::to_string(n) + " points");
    slot[judged[k]] = k;
  }
  const CloudIndex index(points, judged);
  std::vector<T> out(n);
  auto body = [&](std::size_t i) {
    out[i] = values[slot[index.nearest(points[i])]];
    if (meter) meter->add();
  };
  if (meter) meter->run(n, threads, body);
  else parallel_for(n, threads, body);
  return out;
}

template std::vector<std::int8_t> spread_from_judged(const std::vector<Vec3>&, const std::vector<std::size_t>&, const std::vector<std::int8_t>&, int, WorkMeter*);
template std::vector<Vec3> spread_from_judged(const std::vector<Vec3>&, const std::vector<std::size_t>&, const std::vector<Vec3>&, int, WorkMeter*);

std::vector<std::int8_t> spread_verdicts(const std::vector<Vec3>& points, const std::vector<std::size_t>& judged, const std::vector<std::int8_t>& state, int threads, WorkMeter* meter) {
  return spread_from_judged(points, judged, state, threads, meter);
}

}  // namespace dbs
