#include "result.hpp"

#include <algorithm>

#include "error.hpp"
#include "parallel.hpp"

namespace dbs {

std::size_t Result::leaf_count() const {
  return static_cast<std::size_t>(std::count_if(patches.begin(), patches.end(), [](const Patch& p) { return p.is_leaf(); }));
}

std::vector<double> Result::counted_distances() const {
  std::vector<double> counted;
  counted.reserve(distance.size());
  for (std::size_t i = 0; i < distance.size(); ++i)
    if (!left_out(i)) counted.push_back(distance[i]);
  return counted;
}

std::vector<std::int32_t> Result::point_flags() const {
  std::vector<std::int32_t> flags(u.size(), 0);
  auto set = [&](const std::vector<char>& per_point, PointFlag bit) {
    for (std::size_t i = 0; i < per_point.size() && i < flags.size(); ++i)
      if (per_point[i]) flags[i] |= bit;
  };
  set(repaired, kPointRepaired);
  set(outside_body, kPointFar);
  set(clamped, kPointClamped);
  set(cropped, kPointCropped);
  set(turned, kPointTurned);
  return flags;
}

int Result::leaf_at(double u, double v) const {
  if (patches.empty()) fail(ErrorCode::Internal, "result has no patches");
  int id = 0;
  // Children split their parent's rectangle at its midpoint; a point on the split line goes
  // to the upper child, so every (u,v) has exactly one leaf.
  while (!patches[id].is_leaf()) {
    const Patch& p = patches[id];
    const double um = 0.5 * (p.rect.u0 + p.rect.u1), vm = 0.5 * (p.rect.v0 + p.rect.v1);
    const int child = (u >= um ? 1 : 0) + (v >= vm ? 2 : 0);
    id = p.children[child];
  }
  return id;
}

Vec3 Result::evaluate(double u, double v, Vec3* normal) const {
  const Patch& leaf = patches[leaf_at(u, v)];
  const Vec2 st = leaf.rect.to_local(u, v).cwiseMax(0.0).cwiseMin(1.0);
  if (normal) *normal = leaf.surface.normal(st.x(), st.y());
  return leaf.surface.eval(st.x(), st.y());
}

void Result::derivatives(double u, double v, Vec3& su, Vec3& sv) const {
  const Patch& leaf = patches[leaf_at(u, v)];
  const Vec2 st = leaf.rect.to_local(u, v).cwiseMax(0.0).cwiseMin(1.0);
  const SurfacePoint p = leaf.surface.eval_derivs(st.x(), st.y());
  su = p.du / (leaf.rect.u1 - leaf.rect.u0);
  sv = p.dv / (leaf.rect.v1 - leaf.rect.v0);
}

void Result::evaluate_many(const double* uv, std::size_t n, double* xyz, double* normal, double* su, double* sv, int threads) const {
  auto put = [](double* out, std::size_t k, const Vec3& value) {
    if (out) std::copy(value.data(), value.data() + 3, out + 3 * k);
  };
  parallel_for(n, resolve_threads(threads), [&](std::size_t k) {
    const double u = uv[2 * k], v = uv[2 * k + 1];
    Vec3 n_k;
    put(xyz, k, evaluate(u, v, normal ? &n_k : nullptr));
    put(normal, k, n_k);
    if (su || sv) {
      Vec3 du, dv;
      derivatives(u, v, du, dv);
      put(su, k, du);
      put(sv, k, dv);
    }
  });
}

}  // namespace dbs
