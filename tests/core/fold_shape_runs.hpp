// What the core tests of the fold-free work share about a run on a fold shape
// (tests/support/fold_shapes): its points and boundary as the library takes them, and the
// folded reference triangles (inverted or collapsed) of a result's (u,v).
#pragma once
#include <cstddef>
#include <vector>

#include "boundary.hpp"
#include "fold_shapes.hpp"
#include "result.hpp"

namespace fold_runs {

inline std::vector<dbs::Vec3> points_of(const std::vector<double>& xyz) {
  std::vector<dbs::Vec3> p;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) p.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  return p;
}

inline dbs::Boundary boundary_of(const dbs_folds::FoldShape& shape) {
  return dbs::Boundary(points_of(shape.bottom), points_of(shape.right), points_of(shape.top), points_of(shape.left));
}

inline std::size_t reference_folds(const dbs_folds::FoldShape& shape, const dbs::Result& r) {
  std::vector<double> uv;
  for (std::size_t i = 0; i < r.u.size(); ++i) uv.insert(uv.end(), {r.u[i], r.v[i]});
  return dbs_folds::fold_share(uv, shape.triangles).folded;
}

}  // namespace fold_runs
