#include "fold_repair.hpp"

#include <algorithm>
#include <cmath>

#include "cloud_index.hpp"
#include "parallel.hpp"

namespace dbs {

namespace {

Vec2 clamp_unit(const Vec2& x) { return x.cwiseMax(0.0).cwiseMin(1.0); }

/// Gauss-Newton towards the orthogonal foot of q on the result surface (the leaf at each
/// (u,v), derivatives by central differences), within `radius` of `start` and inside [0,1]^2;
/// a step is kept only when it brings the surface closer.
Vec2 step_towards_foot(const Result& result, const Vec3& q, const Vec2& start, double radius) {
  if (!(radius > 0.0)) return start;
  auto trust = [&](Vec2 x) {
    Vec2 d = x - start;
    const double length = d.norm();
    if (length > radius) d *= radius / length;
    return clamp_unit(start + d);
  };
  auto surface = [&](const Vec2& x) { return result.evaluate(x.x(), x.y()); };
  Vec2 x = start;
  double best = (surface(x) - q).norm();
  const double eps = 1e-3 * radius;
  for (int it = 0; it < 8; ++it) {
    const Vec2 u0 = trust(Vec2(x.x() - eps, x.y())), u1 = trust(Vec2(x.x() + eps, x.y()));
    const Vec2 v0 = trust(Vec2(x.x(), x.y() - eps)), v1 = trust(Vec2(x.x(), x.y() + eps));
    if (!(u1.x() > u0.x()) || !(v1.y() > v0.y())) break;
    const Vec3 su = (surface(u1) - surface(u0)) / (u1.x() - u0.x());
    const Vec3 sv = (surface(v1) - surface(v0)) / (v1.y() - v0.y());
    const Vec3 r = q - surface(x);
    const double a = su.dot(su), b = su.dot(sv), c = sv.dot(sv), det = a * c - b * b;
    if (!(det > 0.0)) break;
    const double gu = su.dot(r), gv = sv.dot(r);
    const Vec2 next = trust(x + Vec2((c * gu - b * gv) / det, (a * gv - b * gu) / det));
    const double d = (surface(next) - q).norm();
    if (!(d < best)) break;
    best = d;
    x = next;
  }
  return x;
}

}  // namespace

std::size_t repair_far_points(Result& result, const std::vector<Vec3>& points, int threads) {
  const std::size_t n = points.size();
  result.repaired.assign(n, 0);
  std::vector<std::size_t> far;
  for (std::size_t i = 0; i < n; ++i)
    if (result.distance[i] > kRepairFactor * result.accuracy && result.distance[i] > kRepairSpacings * result.length_scale) far.push_back(i);
  if (far.empty() || far.size() == n) return 0;  // nothing to repair, or nothing to repair from

  // Each far point's neighbours and their normalized inverse-distance weights.
  const CloudIndex index(points);
  std::vector<std::vector<std::size_t>> neighbours(far.size());
  std::vector<std::vector<double>> weights(far.size());
  parallel_for(far.size(), threads, [&](std::size_t f) {
    std::vector<std::size_t> ids;
    std::vector<double> d2;
    index.knn(points[far[f]], kRepairNeighbours + 1, ids, d2);
    double sum = 0.0;
    for (std::size_t m = 0; m < ids.size(); ++m) {
      if (ids[m] == far[f] || !(d2[m] > 0.0)) continue;
      neighbours[f].push_back(ids[m]);
      weights[f].push_back(1.0 / std::sqrt(d2[m]));
      sum += weights[f].back();
    }
    for (double& w : weights[f]) w /= sum;
  });
  // The harmonic fill: Gauss-Seidel in point order, so the result does not depend on threads.
  for (int sweep = 0; sweep < kRepairSweeps; ++sweep) {
    for (std::size_t f = 0; f < far.size(); ++f) {
      if (neighbours[f].empty()) continue;
      double u = 0.0, v = 0.0;
      for (std::size_t m = 0; m < neighbours[f].size(); ++m) {
        u += weights[f][m] * result.u[neighbours[f][m]];
        v += weights[f][m] * result.v[neighbours[f][m]];
      }
      result.u[far[f]] = u;
      result.v[far[f]] = v;
    }
  }
  // Towards the foot, within a fraction of the spread of the neighbours' (u,v).
  std::vector<Vec2> moved(far.size());
  parallel_for(far.size(), threads, [&](std::size_t f) {
    const Vec2 start(result.u[far[f]], result.v[far[f]]);
    double spread = 0.0;
    for (std::size_t m : neighbours[f]) spread += (Vec2(result.u[m], result.v[m]) - start).norm();
    const double radius = neighbours[f].empty() ? 0.0 : kRepairTrust * spread / static_cast<double>(neighbours[f].size());
    moved[f] = step_towards_foot(result, points[far[f]], start, radius);
  });
  std::size_t repaired = 0;
  for (std::size_t f = 0; f < far.size(); ++f) {
    if (neighbours[f].empty()) continue;  // all its neighbours coincide with it: nothing to repair from
    const std::size_t i = far[f];
    ++repaired;
    result.u[i] = moved[f].x();
    result.v[i] = moved[f].y();
    const int leaf = result.leaf_at(result.u[i], result.v[i]);
    result.distance[i] = (result.evaluate(result.u[i], result.v[i]) - points[i]).norm();
    result.patch[i] = leaf;
    result.level[i] = result.patches[leaf].level;
    result.repaired[i] = 1;
  }
  return repaired;
}

}  // namespace dbs
