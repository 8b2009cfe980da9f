#include "torn_points.hpp"

#include <algorithm>
#include <cmath>

namespace dbs::fold_detail {

using namespace fold;

namespace {

/// Distance of (u,v) to the border of the unit square.
double to_border(double u, double v) { return std::min(std::min(u, 1.0 - u), std::min(v, 1.0 - v)); }

}  // namespace

void mark_torn(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Local>& local,
               const std::vector<std::uint32_t>& graph, FoldMeasure& m) {
  std::vector<std::uint8_t> seen(local.size(), 0);
  for (std::size_t i = 0; i < local.size(); ++i) {
    if (m.state[i] != kFoldOk || !(local[i].stretch > 0.0)) continue;
    for (std::size_t t = 0; t < kGraphNeighbours; ++t) {
      const std::uint32_t j = graph[i * kGraphNeighbours + t];
      if (j == kNoNeighbour) break;
      if (!same_sheet(points, local, i, j)) continue;
      const double du = u[j] - u[i], dv = v[j] - v[i], duv = std::sqrt(du * du + dv * dv);
      // Both nearer the domain's border than to each other: the sheet may be cut there (a
      // cloud closing over a small rim meets itself across the boundary), a tear in order.
      if (to_border(u[i], v[i]) < duv && to_border(u[j], v[j]) < duv) continue;
      if (duv > kTearRatio * local[i].stretch * (points[j] - points[i]).norm() && seen[j] < 255) ++seen[j];
    }
  }
  for (std::size_t j = 0; j < local.size(); ++j)
    if (m.state[j] == kFoldOk && seen[j] >= kTornNeighbours) {
      m.state[j] = kFoldTorn;
      ++m.torn;
    }
}

}  // namespace dbs::fold_detail
