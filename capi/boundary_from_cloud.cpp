#include "dbs.h"
// dbs_boundary_detect, dbs_boundary_from_corners and the holes they find.
#include "boundary_detect.hpp"
#include "firewall.hpp"
#include "arrays.hpp"

using namespace dbs::capi;

namespace {

/// The settings of an outline: the options' (or the defaults when NULL).
const dbs::Options& outline_options(const dbs_options* options) {
  static const dbs::Options defaults;
  return options ? options->options : defaults;
}

void hand_out(dbs::DetectedBoundary detected, dbs_boundary** out) { *out = new dbs_boundary{std::move(detected.boundary), std::move(detected.holes)}; }

const std::vector<dbs::Vec3>& hole_of(const dbs_boundary* boundary, size_t hole) {
  require_non_null(boundary, "boundary");
  require_size_index("hole", hole, boundary->holes.size());
  return boundary->holes[hole];
}

}  // namespace

int dbs_boundary_detect(const dbs_cloud* cloud, const dbs_options* options, dbs_boundary** out) {
  return guarded(__func__, [&] {
    require_non_null(cloud, "cloud");
    require_non_null(out, "out");
    const dbs::Options& o = outline_options(options);
    hand_out(dbs::detect_boundary(cloud->cloud.points(), static_cast<std::size_t>(o.outline_neighbours), o.threads), out);
  });
}

int dbs_boundary_from_corners(const dbs_cloud* cloud, const double* corners_xyz, dbs_boundary** out) {
  return guarded(__func__, [&] {
    require_non_null(cloud, "cloud");
    require_non_null(corners_xyz, "corners_xyz");
    require_non_null(out, "out");
    std::array<dbs::Vec3, 4> corners;
    for (int c = 0; c < 4; ++c) corners[static_cast<std::size_t>(c)] = dbs::Vec3(corners_xyz[3 * c], corners_xyz[3 * c + 1], corners_xyz[3 * c + 2]);
    const dbs::Options& o = outline_options(nullptr);
    hand_out(dbs::boundary_from_corners(cloud->cloud.points(), corners, static_cast<std::size_t>(o.outline_neighbours), o.threads), out);
  });
}

int dbs_boundary_hole_count(const dbs_boundary* boundary, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(boundary, "boundary");
    require_non_null(out, "out");
    *out = boundary->holes.size();
  });
}

int dbs_boundary_hole_size(const dbs_boundary* boundary, size_t hole, size_t* out) {
  return guarded(__func__, [&] {
    const std::vector<dbs::Vec3>& points = hole_of(boundary, hole);
    require_non_null(out, "out");
    *out = points.size();
  });
}

int dbs_boundary_hole_points(const dbs_boundary* boundary, size_t hole, double* out_xyz, size_t capacity) {
  return guarded(__func__, [&] {
    const std::vector<dbs::Vec3>& points = hole_of(boundary, hole);
    require_non_null(out_xyz, "out_xyz");
    copy_points(points, out_xyz, capacity, "out_xyz");
  });
}
