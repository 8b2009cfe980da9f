#include "outline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <tuple>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "cloud_index.hpp"
#include "error.hpp"
#include "parallel.hpp"

namespace dbs {

namespace {

constexpr double kTwoPi = 6.283185307179586;
/// A hole's perimeter is at least this many local spacings (a circle about 5 spacings
/// across); smaller loops are voids of the sampling.
constexpr double kMinHoleSpacings = 16.0;
/// ... and its points lie at most this many local spacings apart on average.
constexpr double kMaxHoleStep = 2.0;
/// Boundary points within this many local spacings of each other are linked (and a path's
/// ends that close: a loop).
constexpr double kBridgeSpacings = 4.0;
/// The smoothing sums over this many sigmas of arc length on either side.
constexpr double kWindowSigmas = 3.0;
/// The pushed loop is smoothed again over this many local spacings (sigma).
constexpr double kFinalSmoothing = 1.0;
/// The outermost points a loop point is pushed to lie within this many local spacings of it
/// (less than a hole's radius, or the push would reach across it).
constexpr double kPushSpacings = 2.5;
/// ... and within this many local spacings of the line it is pushed along.
constexpr double kPushWidth = 1.0;
/// The outline runs this many local spacings outside the outermost points: about the gap a
/// sampling leaves between them and the true edge.
constexpr double kOutwardMargin = 0.25;
/// Excursions of a path (without_excursions): ends within this many local spacings ...
constexpr double kShortcutSpacings = 3.0;
/// ... and more than this x that apart along the path.
constexpr double kExcursionRatio = 3.0;

/// Each point's nearest points (itself left out), the points that count it among theirs
/// (reverse nearest), and its local spacing. Flat arrays of 32-bit indices: a cloud of a million
/// points takes about 200 MB here.
struct Neighbourhoods {
  std::size_t k = 0;
  std::vector<std::uint32_t> nearest;        ///< k per point, nearest first
  std::vector<std::size_t> reverse_start;    ///< point i's reverse nearest: reverse[reverse_start[i] .. reverse_start[i+1])
  std::vector<std::uint32_t> reverse;
  std::vector<double> spacing;

  std::vector<std::size_t> nearest_of(std::size_t i) const { return {nearest.begin() + static_cast<std::ptrdiff_t>(i * k), nearest.begin() + static_cast<std::ptrdiff_t>((i + 1) * k)}; }
  /// The nearest and the reverse nearest of point i, sorted, each once.
  std::vector<std::size_t> around(std::size_t i) const {
    std::vector<std::size_t> a = nearest_of(i);
    a.insert(a.end(), reverse.begin() + static_cast<std::ptrdiff_t>(reverse_start[i]), reverse.begin() + static_cast<std::ptrdiff_t>(reverse_start[i + 1]));
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    return a;
  }
};

Neighbourhoods neighbourhoods(const CloudIndex& index, const std::vector<Vec3>& points, std::size_t k, int threads) {
  const std::size_t n = points.size();
  if (n > std::numeric_limits<std::uint32_t>::max()) fail(ErrorCode::OutOfRange, "outline: the cloud has " + std::to_string(n) + " points; at most 4294967295 are supported");
  Neighbourhoods nb;
  nb.k = k;
  nb.nearest.resize(n * k);
  nb.spacing.resize(n);
  parallel_for(n, threads, [&](std::size_t i) {
    std::vector<std::size_t> ids;
    std::vector<double> d2;
    index.knn(points[i], k + 1, ids, d2);
    std::size_t filled = 0;
    for (std::size_t m = 0; m < ids.size() && filled < k; ++m)
      if (ids[m] != i) nb.nearest[i * k + filled++] = static_cast<std::uint32_t>(ids[m]);
    nb.spacing[i] = std::sqrt(d2[std::min(kSpacingNeighbour, d2.size() - 1)]);
  });
  nb.reverse_start.assign(n + 1, 0);
  for (std::uint32_t j : nb.nearest) ++nb.reverse_start[j + 1];
  for (std::size_t i = 0; i < n; ++i) nb.reverse_start[i + 1] += nb.reverse_start[i];
  nb.reverse.resize(nb.nearest.size());
  std::vector<std::size_t> fill(nb.reverse_start.begin(), nb.reverse_start.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t m = 0; m < k; ++m) nb.reverse[fill[nb.nearest[i * k + m]]++] = static_cast<std::uint32_t>(i);
  return nb;
}

/// Unit normal of the plane fitted (PCA) to point i and its nearest points; sign arbitrary.
Vec3 fitted_normal(const std::vector<Vec3>& points, std::size_t i, const std::vector<std::size_t>& nearest) {
  Vec3 mean = points[i];
  for (std::size_t j : nearest) mean += points[j];
  mean /= static_cast<double>(nearest.size() + 1);
  Eigen::Matrix3d cov = (points[i] - mean) * (points[i] - mean).transpose();
  for (std::size_t j : nearest) cov += (points[j] - mean) * (points[j] - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(cov);
  return eigen.eigenvectors().col(0).normalized();
}

/// The widest angle between consecutive neighbours of point i around it in the plane
/// normal to `normal`.
double widest_gap(const std::vector<Vec3>& points, std::size_t i, const Vec3& normal, const std::vector<std::size_t>& around) {
  const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
  std::vector<double> angles;
  for (std::size_t j : around) {
    const Vec3 d = points[j] - points[i];
    const double x = d.dot(e1), y = d.dot(e2);
    if (x == 0.0 && y == 0.0) continue;
    angles.push_back(std::atan2(y, x));
  }
  if (angles.size() < 2) return kTwoPi;
  std::sort(angles.begin(), angles.end());
  double widest = kTwoPi - (angles.back() - angles.front());
  for (std::size_t m = 1; m < angles.size(); ++m) widest = std::max(widest, angles[m] - angles[m - 1]);
  return widest;
}

/// The boundary points joined to each other: two are linked when they lie within
/// kBridgeSpacings times the larger of their local spacings (farther than their nearest
/// points reach: where the sampling leaves the outline's band of boundary points thin, the
/// band has gaps of several spacings).
struct BoundaryGraph {
  std::vector<std::size_t> ids;                   ///< the boundary points, increasing
  std::vector<std::vector<std::uint32_t>> links;  ///< per slot (index into ids): linked slots, increasing
};

BoundaryGraph boundary_graph(const std::vector<Vec3>& points, const std::vector<char>& boundary, const std::vector<double>& spacing, int threads) {
  BoundaryGraph g;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (boundary[i]) g.ids.push_back(i);
  std::vector<std::uint32_t> slot(points.size(), 0);
  for (std::size_t s = 0; s < g.ids.size(); ++s) slot[g.ids[s]] = static_cast<std::uint32_t>(s);
  const CloudIndex index(points, g.ids);
  std::vector<std::vector<std::uint32_t>> reached(g.ids.size());
  parallel_for(g.ids.size(), threads, [&](std::size_t s) {
    std::vector<std::size_t> near;
    index.radius(points[g.ids[s]], kBridgeSpacings * spacing[g.ids[s]], near);
    for (std::size_t j : near)
      if (j != g.ids[s]) reached[s].push_back(slot[j]);
  });
  g.links.resize(g.ids.size());
  for (std::size_t s = 0; s < reached.size(); ++s) {
    for (std::uint32_t t : reached[s]) {
      g.links[s].push_back(t);
      g.links[t].push_back(static_cast<std::uint32_t>(s));
    }
  }
  parallel_for(g.links.size(), threads, [&](std::size_t s) {
    std::sort(g.links[s].begin(), g.links[s].end());
    g.links[s].erase(std::unique(g.links[s].begin(), g.links[s].end()), g.links[s].end());
  });
  return g;
}

/// The connected components of the boundary graph (slots, each component increasing), in
/// increasing order of their lowest slot.
std::vector<std::vector<std::uint32_t>> components(const BoundaryGraph& g) {
  std::vector<char> seen(g.ids.size(), 0);
  std::vector<std::vector<std::uint32_t>> out;
  for (std::size_t first = 0; first < g.ids.size(); ++first) {
    if (seen[first]) continue;
    std::vector<std::uint32_t> members, stack{static_cast<std::uint32_t>(first)};
    seen[first] = 1;
    while (!stack.empty()) {
      const std::uint32_t s = stack.back();
      stack.pop_back();
      members.push_back(s);
      for (std::uint32_t t : g.links[s]) {
        if (!seen[t]) {
          seen[t] = 1;
          stack.push_back(t);
        }
      }
    }
    std::sort(members.begin(), members.end());
    out.push_back(std::move(members));
  }
  return out;
}

/// The longest path (point indices) of the minimum spanning tree of a component (Prim from
/// its lowest slot; ties by slot): the loop less one edge, the band's side branches left out.
std::vector<std::size_t> longest_tree_path(const std::vector<Vec3>& points, const BoundaryGraph& g, const std::vector<std::uint32_t>& members, std::vector<std::uint32_t>& local) {
  // local[slot]: the member's place in `members` (scratch of the graph's size, reused).
  const std::size_t m = members.size();
  for (std::size_t k = 0; k < m; ++k) local[members[k]] = static_cast<std::uint32_t>(k);
  auto at = [&](std::size_t k) -> const Vec3& { return points[g.ids[members[k]]]; };
  std::vector<std::vector<std::uint32_t>> tree(m);
  std::vector<char> in_tree(m, 0);
  using Edge = std::tuple<double, std::uint32_t, std::uint32_t>;  // length, to, from (local)
  std::priority_queue<Edge, std::vector<Edge>, std::greater<Edge>> frontier;
  auto add = [&](std::uint32_t k) {
    in_tree[k] = 1;
    for (std::uint32_t t : g.links[members[k]]) {
      const std::uint32_t j = local[t];
      if (!in_tree[j]) frontier.emplace((at(j) - at(k)).norm(), j, k);
    }
  };
  add(0);
  while (!frontier.empty()) {
    const auto [length, to, from] = frontier.top();
    frontier.pop();
    if (in_tree[to]) continue;
    tree[from].push_back(to);
    tree[to].push_back(from);
    add(to);
  }
  // Farthest member along the tree from `start` (ties: the lower slot), with the parents.
  std::vector<double> dist(m, -1.0);
  std::vector<std::uint32_t> parent(m, std::numeric_limits<std::uint32_t>::max());
  auto farthest = [&](std::uint32_t start) {
    std::fill(dist.begin(), dist.end(), -1.0);
    dist[start] = 0.0;
    parent[start] = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> stack{start};
    std::uint32_t best = start;
    while (!stack.empty()) {
      const std::uint32_t k = stack.back();
      stack.pop_back();
      if (dist[k] > dist[best] || (dist[k] == dist[best] && k < best)) best = k;
      for (std::uint32_t j : tree[k]) {
        if (dist[j] >= 0.0) continue;
        dist[j] = dist[k] + (at(j) - at(k)).norm();
        parent[j] = k;
        stack.push_back(j);
      }
    }
    return best;
  };
  const std::uint32_t a = farthest(0);
  const std::uint32_t b = farthest(a);
  std::vector<std::size_t> path;
  for (std::uint32_t k = b; k != std::numeric_limits<std::uint32_t>::max(); k = parent[k]) path.push_back(g.ids[members[k]]);
  return path;
}

/// The closed path without its excursions: where two of its points lie within
/// kShortcutSpacings local spacings of each other but more than kExcursionRatio times that
/// apart along the path (less than half the perimeter), the path between them runs round a
/// void of the sampling that opens onto the outline (or a slot narrower than that) and is cut
/// off.
std::vector<std::size_t> without_excursions(const std::vector<Vec3>& points, const std::vector<std::size_t>& path, const std::vector<double>& spacing) {
  const std::size_t m = path.size();
  std::vector<Vec3> at_points(m);
  for (std::size_t i = 0; i < m; ++i) at_points[i] = points[path[i]];
  std::vector<double> at(m + 1, 0.0);
  for (std::size_t i = 0; i < m; ++i) at[i + 1] = at[i] + (at_points[(i + 1) % m] - at_points[i]).norm();
  const double perimeter = at[m];
  const CloudIndex index(at_points);
  std::vector<char> removed(m, 0);
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < m; ++i) {
    if (removed[i]) continue;
    const double r = kShortcutSpacings * spacing[path[i]];
    index.radius(at_points[i], r, near);
    std::size_t skip_to = i;
    double longest = kExcursionRatio * r;
    for (std::size_t j : near) {
      if (removed[j]) continue;
      const double ahead = j >= i ? at[j] - at[i] : perimeter - at[i] + at[j];
      if (ahead > longest && ahead < 0.5 * perimeter) {
        longest = ahead;
        skip_to = j;
      }
    }
    for (std::size_t k = (i + 1) % m; k != skip_to && skip_to != i; k = (k + 1) % m) removed[k] = 1;
  }
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < m; ++i)
    if (!removed[i]) kept.push_back(path[i]);
  return kept;
}

/// The closed path without its back-steps: a point where the path turns back (its two
/// segments at more than 90 degrees) is dropped, until there is none; where the band of
/// boundary points is two or three wide, the path crosses it to and fro.
std::vector<std::size_t> without_back_steps(const std::vector<Vec3>& points, std::vector<std::size_t> path) {
  for (bool changed = true; changed && path.size() > kMinLoopPoints;) {
    changed = false;
    std::vector<std::size_t> kept;
    const std::size_t m = path.size();
    for (std::size_t i = 0; i < m; ++i) {
      const Vec3& prev = points[kept.empty() ? path[m - 1] : kept.back()];
      const Vec3 in = points[path[i]] - prev, out = points[path[(i + 1) % m]] - points[path[i]];
      if (in.dot(out) < 0.0 && m - (i + 1 - kept.size()) > kMinLoopPoints) {
        changed = true;
        continue;
      }
      kept.push_back(path[i]);
    }
    path = std::move(kept);
  }
  return path;
}

/// The closed polyline `p` (point i of path[i]) smoothed by a Gaussian of arc length, sigma
/// `spacings` local spacings of each point.
std::vector<Vec3> gaussian_smoothed(const std::vector<Vec3>& p, const Neighbourhoods& nb, const std::vector<std::size_t>& path, double spacings) {
  const std::size_t m = p.size();
  std::vector<Vec3> out(m);
  for (std::size_t i = 0; i < m; ++i) {
    const double sigma = spacings * nb.spacing[path[i]], reach = kWindowSigmas * sigma;
    Vec3 sum = p[i];
    double weight = 1.0;
    if (!(sigma > 0.0)) {
      out[i] = p[i];
      continue;
    }
    for (int direction : {1, -1}) {
      double s = 0.0;
      std::size_t previous = i;
      for (std::size_t step = 1; step < m / 2; ++step) {
        const std::size_t j = direction > 0 ? (i + step) % m : (i + m - step) % m;
        s += (p[j] - p[previous]).norm();
        previous = j;
        if (s > reach) break;
        const double w = std::exp(-0.5 * (s / sigma) * (s / sigma));
        sum += w * p[j];
        weight += w;
      }
    }
    out[i] = sum / weight;
  }
  return out;
}

/// The closed path smoothed by a Gaussian of arc length (sigma kSmoothingSpacings local
/// spacings) and pushed out along the surface onto or past the outermost points near it (of
/// the whole cloud: where a void of the sampling opens onto the outline, the path runs round
/// it, and the push takes the outline back to the points beyond).
OutlineLoop smooth_loop(const std::vector<Vec3>& points, const std::vector<std::size_t>& path, const Neighbourhoods& nb, const std::vector<Vec3>& normal, const CloudIndex& index) {
  const std::size_t m = path.size();
  OutlineLoop loop;
  loop.sources = path;
  std::vector<Vec3> raw(m);
  for (std::size_t i = 0; i < m; ++i) raw[i] = points[path[i]];
  loop.points = gaussian_smoothed(raw, nb, path, kSmoothingSpacings);
  // Out along the surface, perpendicular to the loop, to the outermost point in front of it.
  std::vector<Vec3> outward(m, Vec3::Zero());
  std::vector<double> offset(m, 0.0);
  loop.normals.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 tangent = loop.points[(i + 1) % m] - loop.points[(i + m - 1) % m];
    Vec3 n = normal[path[i]];
    if (i > 0 && n.dot(loop.normals[i - 1]) < 0.0) n = -n;
    loop.normals[i] = n;
    // Outwards: from the centroid of the cloud around the point, across the loop's tangent
    // within the tangent plane.
    std::vector<std::size_t> near;
    index.radius(loop.points[i], kPushSpacings * nb.spacing[path[i]], near);
    if (near.empty() || !(tangent.norm() > 0.0)) continue;
    Vec3 centroid = Vec3::Zero();
    for (std::size_t j : near) centroid += points[j];
    centroid /= static_cast<double>(near.size());
    const Vec3 t = tangent.normalized();
    Vec3 out = loop.points[i] - centroid;
    out -= out.dot(n) * n + out.dot(t) * t;
    if (!(out.norm() > 0.0)) continue;
    outward[i] = out.normalized();
    // To the outermost point, and a margin of that point's own spacing beyond it (where the
    // density changes, the spacing of the points that stand out there, not the loop's).
    double reach_most = 0.0;
    std::size_t outermost = path[i];
    for (std::size_t j : near) {
      const Vec3 d = points[j] - loop.points[i];
      const double reach = d.dot(outward[i]);
      if ((d - reach * outward[i]).norm() > kPushWidth * nb.spacing[path[i]]) continue;  // not in front of it
      if (reach > reach_most || (reach == reach_most && j < outermost)) {
        reach_most = reach;
        outermost = j;
      }
    }
    offset[i] = reach_most + kOutwardMargin * nb.spacing[outermost];
  }
  std::vector<Vec3> pushed = loop.points;
  for (std::size_t i = 0; i < m; ++i) pushed[i] = loop.points[i] + offset[i] * outward[i];
  // A light smoothing of the pushed loop: it follows the outermost points without their
  // irregularity (whose wiggles would lengthen a side where the sampling is sparse, and
  // shift the arc length along it).
  if (kFinalSmoothing > 0.0) pushed = gaussian_smoothed(pushed, nb, path, kFinalSmoothing);
  loop.points = std::move(pushed);
  for (std::size_t i = 0; i < m; ++i) loop.perimeter += (loop.points[(i + 1) % m] - loop.points[i]).norm();
  return loop;
}


double signed_area(const std::vector<Vec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

/// Whether q lies inside the closed polygon (even-odd rule).
bool inside(const std::vector<Vec2>& polygon, const Vec2& q) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if ((a.y() > q.y()) != (b.y() > q.y()) && q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x()) in = !in;
  }
  return in;
}

/// find_outline on a cloud without coincident points.
Outline outline_of_distinct(const std::vector<Vec3>& points, std::size_t neighbours, int threads) {
  const std::size_t n = points.size();
  const CloudIndex index(points);
  const Neighbourhoods nb = neighbourhoods(index, points, neighbours, threads);
  Outline outline;
  outline.spacing = nb.spacing;
  outline.boundary.assign(n, 0);
  std::vector<Vec3> normal(n);
  parallel_for(n, threads, [&](std::size_t i) {
    normal[i] = fitted_normal(points, i, nb.nearest_of(i));
    outline.boundary[i] = widest_gap(points, i, normal[i], nb.around(i)) > kOutlineGap ? 1 : 0;
  });
  const std::size_t flagged = static_cast<std::size_t>(std::count(outline.boundary.begin(), outline.boundary.end(), 1));
  if (flagged == 0) fail(ErrorCode::Degenerate, "outline: no boundary point found (a closed surface has no outline)");
  // A neighbourhood that leaves most points with a gap does not span the surface (scan lines
  // far apart, a cloud too sparse for it): no outline can be told there.
  if (2 * flagged > n)
    fail(ErrorCode::Degenerate, "outline: " + std::to_string(flagged) + " of the " + std::to_string(n) + " points look like border points; the neighbourhood of " + std::to_string(neighbours) +
                                    " points does not span the surface (scan lines far apart?): try a larger DBS_OPT_OUTLINE_NEIGHBOURS");

  const BoundaryGraph graph = boundary_graph(points, outline.boundary, nb.spacing, threads);
  std::vector<std::uint32_t> local(graph.ids.size(), 0);
  std::vector<OutlineLoop> loops;
  for (const std::vector<std::uint32_t>& members : components(graph)) {
    if (members.size() < kMinLoopPoints) continue;
    const std::vector<std::size_t> path = without_back_steps(points, without_excursions(points, longest_tree_path(points, graph, members, local), nb.spacing));
    if (path.size() < kMinLoopPoints) continue;
    // A closed loop: its ends no farther apart than a link (the spanning tree left out one).
    if ((points[path.front()] - points[path.back()]).norm() > kBridgeSpacings * std::max(nb.spacing[path.front()], nb.spacing[path.back()])) continue;
    loops.push_back(smooth_loop(points, path, nb, normal, index));
  }
  if (loops.empty()) fail(ErrorCode::Degenerate, "outline: the boundary points of the cloud form no closed loop (a closed surface, or one whose border is sampled too thinly, has none)");
  // The outer loop encloses the largest area in the cloud's principal plane (a hole may be
  // longer than the outline: a gear cut out of a plate); every other loop must lie inside it.
  const PlaneFrame frame = principal_plane(points);
  std::vector<std::vector<Vec2>> flat(loops.size());
  std::size_t outer = 0;
  double largest = -1.0;
  for (std::size_t k = 0; k < loops.size(); ++k) {
    for (const Vec3& p : loops[k].points) flat[k].push_back(frame.project(p));
    const double area = std::abs(signed_area(flat[k]));
    if (area > largest) {
      largest = area;
      outer = k;
    }
  }
  for (std::size_t k = 0; k < loops.size(); ++k) {
    if (k == outer) {
      outline.outer = std::move(loops[k]);
      continue;
    }
    // A loop round a few spacings of nothing is a void of the sampling, not a hole; one whose
    // points lie several spacings apart joins scattered points, not a border.
    std::vector<double> spacings;
    for (std::size_t i : loops[k].sources) spacings.push_back(nb.spacing[i]);
    std::nth_element(spacings.begin(), spacings.begin() + static_cast<std::ptrdiff_t>(spacings.size() / 2), spacings.end());
    const double spacing = spacings[spacings.size() / 2], step = loops[k].perimeter / static_cast<double>(loops[k].points.size());
    if (loops[k].perimeter < kMinHoleSpacings * spacing || step > kMaxHoleStep * spacing) continue;
    Vec2 centre = Vec2::Zero();
    for (const Vec2& q : flat[k]) centre += q;
    centre /= static_cast<double>(flat[k].size());
    if (!inside(flat[outer], centre))
      fail(ErrorCode::Degenerate, "outline: the cloud has separate pieces (an outline loop of " + std::to_string(loops[k].points.size()) + " points lies outside the largest one); parameterize each piece on its own");
    outline.holes.push_back(std::move(loops[k]));
  }
  return outline;
}

}  // namespace

PlaneFrame principal_plane(const std::vector<Vec3>& points) {
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) cov += (p - mean) * (p - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(cov);
  return {mean, eigen.eigenvectors().col(2), eigen.eigenvectors().col(1)};
}

Outline find_outline(const std::vector<Vec3>& points, std::size_t neighbours, int threads) {
  const std::size_t n = points.size();
  if (neighbours < 6) fail(ErrorCode::InvalidArgument, "outline: " + std::to_string(neighbours) + " neighbours; at least 6 are needed");
  for (std::size_t i = 0; i < n; ++i)
    if (!is_finite(points[i])) fail(ErrorCode::NonFinite, "outline: point " + std::to_string(i) + " has a non-finite coordinate");
  // Coincident points (a scan merged from overlapping passes) would fill the nearest points
  // with copies: the outline is found on the distinct points, each standing for its copies.
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  auto less = [&](std::size_t a, std::size_t b) {
    const Vec3 &p = points[a], &q = points[b];
    if (p.x() != q.x()) return p.x() < q.x();
    if (p.y() != q.y()) return p.y() < q.y();
    if (p.z() != q.z()) return p.z() < q.z();
    return a < b;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<std::size_t> copy_of(n), first;  // distinct point of each point; lowest index of each distinct point
  std::vector<Vec3> distinct;
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    if (k == 0 || points[i] != points[order[k - 1]]) {
      distinct.push_back(points[i]);
      first.push_back(i);
    }
    copy_of[i] = distinct.size() - 1;
  }
  // The distinct points in the order of their lowest index, so that ties resolve as on the cloud.
  std::vector<std::size_t> by_index(distinct.size());
  for (std::size_t d = 0; d < distinct.size(); ++d) by_index[d] = d;
  std::sort(by_index.begin(), by_index.end(), [&](std::size_t a, std::size_t b) { return first[a] < first[b]; });
  std::vector<std::size_t> rank(distinct.size());
  std::vector<Vec3> cloud(distinct.size());
  for (std::size_t r = 0; r < by_index.size(); ++r) {
    rank[by_index[r]] = r;
    cloud[r] = distinct[by_index[r]];
  }
  if (cloud.size() < neighbours + 1)
    fail(ErrorCode::InvalidArgument, "outline: the cloud has " + std::to_string(cloud.size()) + " distinct points; at least " + std::to_string(neighbours + 1) + " are needed");
  Outline found = outline_of_distinct(cloud, neighbours, resolve_threads(threads));
  if (cloud.size() == n) return found;
  // Back to the cloud's own points: a copy shares its point's verdict and spacing.
  Outline out;
  out.boundary.resize(n);
  out.spacing.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.boundary[i] = found.boundary[rank[copy_of[i]]];
    out.spacing[i] = found.spacing[rank[copy_of[i]]];
  }
  auto remap = [&](OutlineLoop& loop) {
    for (std::size_t& s : loop.sources) s = first[by_index[s]];
  };
  out.outer = std::move(found.outer);
  remap(out.outer);
  out.holes = std::move(found.holes);
  for (OutlineLoop& hole : out.holes) remap(hole);
  return out;
}

}  // namespace dbs
