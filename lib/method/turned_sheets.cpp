#include "turned_sheets.hpp"

#include <Eigen/Geometry>
#include <string>

#include "error.hpp"
#include "fold_repair.hpp"
#include "parallel.hpp"

namespace dbs {

TurnedSheets turned_sheets(const Result& result, const std::vector<std::size_t>& judged, const FoldMeasure& folds, int threads) {
  const std::size_t n = folds.right_normal.size();
  if (!judged.empty() && judged.size() != n)
    fail(ErrorCode::InvalidArgument, "turned_sheets: " + std::to_string(judged.size()) + " judged points but " + std::to_string(n) + " normals");
  if (judged.empty() && n != result.u.size())
    fail(ErrorCode::InvalidArgument, "turned_sheets: " + std::to_string(n) + " normals for " + std::to_string(result.u.size()) + " points");
  for (std::size_t k = 0; k < judged.size(); ++k)
    if (judged[k] >= result.u.size())
      fail(ErrorCode::InvalidArgument, "turned_sheets: judged point " + std::to_string(judged[k]) + " is not one of the " + std::to_string(result.u.size()) + " points");
  // Per judged point: 0 not judged, 1 right, 2 turned (counted afterwards, in order).
  std::vector<char> verdict(n, 0);
  parallel_for(n, resolve_threads(threads), [&](std::size_t k) {
    const Vec3& right = folds.right_normal[k];
    if (right.isZero()) return;
    const std::size_t i = judged.empty() ? k : judged[k];
    if (beyond_repair_reach(result, i)) return;
    Vec3 su, sv;
    result.derivatives(result.u[i], result.v[i], su, sv);
    verdict[k] = su.cross(sv).dot(right) > 0.0 ? 1 : 2;
  });
  TurnedSheets out;
  for (std::size_t k = 0; k < n; ++k) {
    out.judged += verdict[k] != 0;
    if (verdict[k] == 2) out.points.push_back(judged.empty() ? k : judged[k]);
  }
  out.turned = out.points.size();
  out.share = out.judged == 0 ? 0.0 : static_cast<double>(out.turned) / static_cast<double>(out.judged);
  return out;
}

}  // namespace dbs
