// What the fold measure (fold_measure.hpp) finds around one point, and which of its graph
// edges join points of one sheet: shared by the measure's orientation of the normals and by
// its marking of torn points (torn_points.hpp).
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "fold_measure.hpp"
#include "geometry.hpp"

namespace dbs::fold_detail {

/// An empty slot of the orientation graph (fewer neighbours than kGraphNeighbours).
constexpr std::uint32_t kNoNeighbour = std::numeric_limits<std::uint32_t>::max();

/// What the local analysis of one point found.
struct Local {
  Vec3 normal = Vec3::Zero();  // PCA normal (unoriented); e1 x e2 = normal for the sign below
  bool surface_like = false;   // takes part in the orientation graph
  std::int8_t sign = 0;        // sign(det J) against `normal`; 0 = undecided
  bool collapsed = false;      // undecided because its neighbourhood is squeezed in (u,v)
  bool scrambled = false;      // undecided because no linear map explains its neighbours' (u,v)
  double abs_det = 0.0;        // |det J| when sign != 0
  double stretch = 0.0;        // median |(du,dv)| / |dp| over the neighbours; 0 = unknown
};

/// Whether the graph edge from i to j joins two points of one sheet: both surface-like, their
/// normals within 60 degrees and the edge along both tangent planes (the orientation's edges).
inline bool same_sheet(const std::vector<Vec3>& points, const std::vector<Local>& local, std::size_t i, std::size_t j) {
  if (!local[i].surface_like || !local[j].surface_like) return false;
  const Vec3& ni = local[i].normal;
  const Vec3& nj = local[j].normal;
  if (std::abs(ni.dot(nj)) < fold::kMinEdgeCosine) return false;
  const Vec3 d = (points[j] - points[i]).normalized();
  return std::abs(ni.dot(d)) <= fold::kMaxEdgeNormalCosine && std::abs(nj.dot(d)) <= fold::kMaxEdgeNormalCosine;
}

}  // namespace dbs::fold_detail
