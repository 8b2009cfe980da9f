#include "harmonic_fill.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fold_measure.hpp"
#include "parallel.hpp"

namespace dbs {

namespace {

/// Point p's stretch: the sum of the 3D distances to its nearest points `around` over the
/// sum of their (u,v) distances (large where the (u,v) are crushed together).
double stretch(const Result& result, const std::vector<Vec3>& points, std::size_t p, const std::vector<std::size_t>& around) {
  double d3 = 0.0, d2 = 0.0;
  for (std::size_t m : around) {
    d3 += (points[m] - points[p]).norm();
    d2 += std::hypot(result.u[m] - result.u[p], result.v[m] - result.v[p]);
  }
  if (!(d3 > 0.0)) return 1.0;  // all its nearest points coincide with it: no stretch to tell
  return d3 / std::max(d2, 1e-12 * d3);
}

/// The connected regions of the fill (rows joined through neighbours that are rows too), as
/// lists of row numbers in increasing order of their first row.
std::vector<std::vector<std::size_t>> regions(const FillRows& rows, std::size_t point_count) {
  std::vector<std::size_t> row_of(point_count, SIZE_MAX);
  for (std::size_t r = 0; r < rows.ids.size(); ++r) row_of[rows.ids[r]] = r;
  std::vector<char> seen(rows.ids.size(), 0);
  std::vector<std::vector<std::size_t>> out;
  for (std::size_t first = 0; first < rows.ids.size(); ++first) {
    if (seen[first]) continue;
    seen[first] = 1;
    std::vector<std::size_t> members, stack{first};
    while (!stack.empty()) {
      const std::size_t r = stack.back();
      stack.pop_back();
      members.push_back(r);
      for (std::size_t m : rows.neighbours[r]) {
        const std::size_t other = row_of[m];
        if (other != SIZE_MAX && !seen[other]) {
          seen[other] = 1;
          stack.push_back(other);
        }
      }
    }
    std::sort(members.begin(), members.end());
    out.push_back(std::move(members));
  }
  return out;
}

/// The rows `members` of `rows`, as a fill of their own.
FillRows subset(const FillRows& rows, const std::vector<std::size_t>& members) {
  FillRows out;
  for (std::size_t r : members) {
    out.ids.push_back(rows.ids[r]);
    out.neighbours.push_back(rows.neighbours[r]);
    out.weights.push_back(rows.weights[r]);
  }
  return out;
}

/// Folded and collapsed points of the fold measure on the region's points and their
/// neighbours (a cloud of their own) at the result's current (u,v).
std::pair<std::size_t, std::size_t> judge(const Result& result, const std::vector<Vec3>& points, const std::vector<std::size_t>& cloud, int threads) {
  std::vector<Vec3> xyz;
  std::vector<double> u, v;
  for (std::size_t i : cloud) {
    xyz.push_back(points[i]);
    u.push_back(result.u[i]);
    v.push_back(result.v[i]);
  }
  const FoldMeasure m = measure_folds(xyz, u, v, result.noise, threads);
  return {m.folded, m.collapsed};
}

}  // namespace

void fill_sweeps(Result& result, const FillRows& rows, int sweeps) {
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (std::size_t r = 0; r < rows.ids.size(); ++r) {
      if (rows.neighbours[r].empty()) continue;
      double u = 0.0, v = 0.0;
      for (std::size_t m = 0; m < rows.neighbours[r].size(); ++m) {
        u += rows.weights[r][m] * result.u[rows.neighbours[r][m]];
        v += rows.weights[r][m] * result.v[rows.neighbours[r][m]];
      }
      result.u[rows.ids[r]] = u;
      result.v[rows.ids[r]] = v;
    }
  }
}

std::size_t balance_stretch(Result& result, const std::vector<Vec3>& points, const CloudIndex& index, const FillRows& rows, int threads) {
  if (rows.ids.empty()) return 0;
  // The points involved: the rows and their neighbours, each with its own nearest points.
  std::vector<std::size_t> involved;
  std::vector<char> in(points.size(), 0);
  auto take = [&](std::size_t i) {
    if (!in[i]) involved.push_back(i);
    in[i] = 1;
  };
  for (std::size_t r = 0; r < rows.ids.size(); ++r) {
    take(rows.ids[r]);
    for (std::size_t m : rows.neighbours[r]) take(m);
  }
  std::vector<std::vector<std::size_t>> around(involved.size());
  parallel_for(involved.size(), threads, [&](std::size_t k) {
    std::vector<double> d2;
    index.knn(points[involved[k]], kStretchNeighbours + 1, around[k], d2);
  });
  std::vector<double> sigma(points.size(), 1.0);
  auto measure_stretch = [&] {
    parallel_for(involved.size(), threads, [&](std::size_t k) { sigma[involved[k]] = stretch(result, points, involved[k], around[k]); });
  };
  measure_stretch();
  std::vector<char> is_row(points.size(), 0);
  for (std::size_t i : rows.ids) is_row[i] = 1;
  std::vector<double> all;
  for (std::size_t i : involved)
    if (!is_row[i]) all.push_back(sigma[i]);
  if (all.empty()) return 0;
  std::nth_element(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(all.size() / 2), all.end());
  const double crushed_above = kCrushedStretch * all[all.size() / 2];

  std::size_t changed = 0;
  for (const std::vector<std::size_t>& region : regions(rows, points.size())) {
    const std::size_t crushed = static_cast<std::size_t>(std::count_if(region.begin(), region.end(), [&](std::size_t r) { return sigma[rows.ids[r]] > crushed_above; }));
    if (static_cast<double>(crushed) < kCrushedShare * static_cast<double>(region.size())) continue;
    FillRows fill = subset(rows, region);
    std::vector<std::size_t> cloud;
    for (std::size_t r = 0; r < fill.ids.size(); ++r) {
      cloud.push_back(fill.ids[r]);
      cloud.insert(cloud.end(), fill.neighbours[r].begin(), fill.neighbours[r].end());
    }
    std::sort(cloud.begin(), cloud.end());
    cloud.erase(std::unique(cloud.begin(), cloud.end()), cloud.end());
    std::vector<double> harmonic_u, harmonic_v;
    for (std::size_t i : fill.ids) {
      harmonic_u.push_back(result.u[i]);
      harmonic_v.push_back(result.v[i]);
    }
    const auto before = judge(result, points, cloud, threads);
    for (int round = 0; round < kStretchRounds; ++round) {
      for (std::size_t r = 0; r < fill.ids.size(); ++r) {
        double sum = 0.0;
        for (std::size_t m = 0; m < fill.neighbours[r].size(); ++m) sum += (fill.weights[r][m] /= sigma[fill.neighbours[r][m]]);
        for (double& w : fill.weights[r]) w /= sum;
      }
      fill_sweeps(result, fill, kFillSweeps);
      measure_stretch();
    }
    const auto after = judge(result, points, cloud, threads);
    if (after.first <= before.first && after.second <= before.second) {
      changed += fill.ids.size();
      continue;
    }
    for (std::size_t r = 0; r < fill.ids.size(); ++r) {  // not better: the harmonic fill stays
      result.u[fill.ids[r]] = harmonic_u[r];
      result.v[fill.ids[r]] = harmonic_v[r];
    }
    measure_stretch();
  }
  return changed;
}

}  // namespace dbs
