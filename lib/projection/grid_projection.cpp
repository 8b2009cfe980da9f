#include "grid_projection.hpp"

#include <algorithm>

namespace dbs {

namespace {

/// A3 on one grid section (row or column): densify, project (and refine), read the offsets
/// of the section's own points. Its two ends lie on the boundary and stay fixed.
/// `point_moments[k]` are the ray moments of the interior points k (1 .. size - 2), taken
/// once in project_grid for the row and the column that cross there.
std::vector<double> project_section(const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const std::vector<const RayMoments*>& point_moments, const DirectedProjector& projector, double gamma,
                                    const RefinementSettings& refinement, RefinementCounts* counts, WorkMeter* meter) {
  double length = 0.0;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) length += (points[k + 1] - points[k]).norm();
  const double spacing = std::max(kNodeSpacing * projector.length_scale(), length / static_cast<double>(kMaxSectionNodes));
  std::vector<std::size_t> original;
  CurveProjectionInput input = densify_polygon(points, normals, spacing, original, kMaxSectionNodes);
  input.known_moments.assign(input.nodes.size(), nullptr);
  for (std::size_t k = 1; k + 1 < points.size(); ++k) input.known_moments[original[k]] = point_moments[k];
  const std::vector<double> node_offsets = solve_curve(projector, input, gamma, refinement, counts);
  count_work(meter, input.nodes.size() - (points.size() - 2));
  std::vector<double> offsets(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) offsets[k] = node_offsets[original[k]];
  return offsets;
}

}  // namespace

Grid project_grid(const BaseSurface& surface, int nu, int nv, const DirectedProjector& projector, double gamma, std::size_t* out_damped_nodes, const RefinementSettings& refinement, RefinementCounts* counts, int threads, WorkMeter* meter) {
  Grid grid = surface.sample(nu, nv);
  if (out_damped_nodes) *out_damped_nodes = 0;
  if (nu < 3 || nv < 3) return grid;
  Grid normals(nu, nv);
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) normals(i, j) = surface.normal(grid.u(i), grid.v(j));

  // The rays at the interior points, each shared by its row and its column: the node a
  // section puts there is the point itself with its unit normal (densify_polygon), so the
  // moments are those the section would take. On the small patches of a deep quadtree, whose
  // sections have few nodes between their points, they were half of all rays.
  std::vector<RayMoments> point_moments(grid.points.size());
  const std::size_t interior_u = static_cast<std::size_t>(nu - 2);
  metered_for(meter, interior_u * static_cast<std::size_t>(nv - 2), threads, [&](std::size_t k) {
    const std::size_t index = (k / interior_u + 1) * static_cast<std::size_t>(nu) + k % interior_u + 1;
    point_moments[index] = projector.moments(grid.points[index], normals.points[index].normalized());
    count_work(meter);
  });
  auto moments_of = [&](std::size_t first, std::size_t step, std::size_t count) {
    std::vector<const RayMoments*> out(count);
    for (std::size_t k = 0; k < count; ++k) out[k] = &point_moments[first + k * step];
    return out;
  };

  // Offsets of the interior points along their normals, from their row and their column.
  std::vector<double> row_offset(grid.points.size(), 0.0), column_offset(grid.points.size(), 0.0);
  // Each section writes only its own offsets and counts, so the sections run in parallel;
  // the counts are summed in section order.
  const std::size_t rows = static_cast<std::size_t>(nv - 2), columns = static_cast<std::size_t>(nu - 2);
  std::vector<RefinementCounts> section_counts(rows + columns);
  metered_for(meter, rows, threads, [&](std::size_t row) {
    const std::ptrdiff_t j = static_cast<std::ptrdiff_t>(row) + 1;
    const std::vector<Vec3> points(grid.points.begin() + j * nu, grid.points.begin() + (j + 1) * nu);
    const std::vector<Vec3> directions(normals.points.begin() + j * nu, normals.points.begin() + (j + 1) * nu);
    const std::vector<double> t = project_section(points, directions, moments_of(static_cast<std::size_t>(j) * nu, 1, nu), projector, gamma, refinement, &section_counts[row], meter);
    for (int i = 0; i < nu; ++i) row_offset[static_cast<std::size_t>(j) * nu + i] = t[i];
  });
  metered_for(meter, columns, threads, [&](std::size_t column) {
    const int i = static_cast<int>(column) + 1;
    std::vector<Vec3> points, directions;
    for (int j = 0; j < nv; ++j) {
      points.push_back(grid(i, j));
      directions.push_back(normals(i, j));
    }
    const std::vector<double> t = project_section(points, directions, moments_of(static_cast<std::size_t>(i), nu, nv), projector, gamma, refinement, &section_counts[rows + column], meter);
    for (int j = 0; j < nv; ++j) column_offset[static_cast<std::size_t>(j) * nu + i] = t[j];
  });
  if (counts) {
    for (const RefinementCounts& c : section_counts) {
      counts->curves += c.curves;
      counts->iterations += c.iterations;
    }
  }

  std::vector<double> offsets(grid.points.size());
  for (std::size_t k = 0; k < offsets.size(); ++k) offsets[k] = 0.5 * (row_offset[k] + column_offset[k]);
  GuardedMove move = move_without_pleats(grid, normals, offsets);
  if (out_damped_nodes) *out_damped_nodes = move.damped_nodes;
  return std::move(move.grid);
}

}  // namespace dbs
