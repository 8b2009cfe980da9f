// dbs_boundary_*: four-sided boundaries from arrays and files.
#include "arrays.hpp"
#include "boundary_from_loop.hpp"
#include "boundary_io.hpp"
#include "firewall.hpp"

using namespace dbs::capi;

namespace {

const dbs::Polyline& side_of(const dbs::Boundary& boundary, int32_t side) {
  require_index("side", side, 4);
  return boundary.side(static_cast<dbs::Side>(side));
}

}  // namespace

namespace {

dbs::Boundary::CornerTolerance corner_tolerance(double tolerance, int32_t relative) { return {tolerance, relative != 0}; }

/// dbs_boundary_create(_tolerant): the arguments checked, then the sides made a boundary.
dbs::Boundary boundary_of_sides(const double* bottom, size_t n_bottom, const double* right, size_t n_right, const double* top, size_t n_top, const double* left, size_t n_left,
                                dbs_boundary** out, dbs::Boundary::CornerTolerance tolerance) {
  require_non_null(bottom, "bottom");
  require_non_null(right, "right");
  require_non_null(top, "top");
  require_non_null(left, "left");
  require_non_null(out, "out");
  return dbs::Boundary(points_from(bottom, n_bottom), points_from(right, n_right), points_from(top, n_top), points_from(left, n_left), tolerance);
}

/// Hands `boundary` to the caller: *out, then *out_max_snap (may be null) once nothing can
/// fail any more, so that both stay untouched on failure.
void hand_out(dbs::Boundary boundary, double* out_max_snap, dbs_boundary** out) {
  const double snap = boundary.max_snap();
  *out = new dbs_boundary{std::move(boundary), {}};
  if (out_max_snap) *out_max_snap = snap;
}

}  // namespace

int dbs_boundary_create(const double* bottom, size_t n_bottom, const double* right, size_t n_right, const double* top, size_t n_top, const double* left, size_t n_left, dbs_boundary** out) {
  return guarded(__func__, [&] {
    hand_out(boundary_of_sides(bottom, n_bottom, right, n_right, top, n_top, left, n_left, out, {dbs::Boundary::kCornerTolerance, true}), nullptr, out);
  });
}

int dbs_boundary_create_tolerant(const double* bottom, size_t n_bottom, const double* right, size_t n_right, const double* top, size_t n_top, const double* left, size_t n_left, double tolerance, int32_t relative,
                                 double* out_max_snap, dbs_boundary** out) {
  return guarded(__func__, [&] {
    hand_out(boundary_of_sides(bottom, n_bottom, right, n_right, top, n_top, left, n_left, out, corner_tolerance(tolerance, relative)), out_max_snap, out);
  });
}

int dbs_boundary_load_tolerant(const char* path, double tolerance, int32_t relative, double* out_max_snap, dbs_boundary** out) {
  return guarded(__func__, [&] {
    require_non_null(path, "path");
    require_non_null(out, "out");
    hand_out(dbs::load_boundary(path, corner_tolerance(tolerance, relative)), out_max_snap, out);
  });
}

int dbs_boundary_from_loop(const double* xyz, size_t n, const size_t* corners, dbs_boundary** out) {
  return guarded(__func__, [&] {
    require_non_null(xyz, "xyz");
    require_non_null(corners, "corners");
    require_non_null(out, "out");
    *out = new dbs_boundary{dbs::boundary_from_loop(points_from(xyz, n), {corners[0], corners[1], corners[2], corners[3]}), {}};
  });
}

int dbs_boundary_load(const char* path, dbs_boundary** out) {
  return guarded(__func__, [&] {
    require_non_null(path, "path");
    require_non_null(out, "out");
    *out = new dbs_boundary{dbs::load_boundary(path), {}};
  });
}

int dbs_boundary_save(const dbs_boundary* boundary, const char* path) {
  return guarded(__func__, [&] {
    require_non_null(boundary, "boundary");
    require_non_null(path, "path");
    dbs::save_boundary(boundary->boundary, path);
  });
}

void dbs_boundary_destroy(dbs_boundary* boundary) { delete boundary; }

int dbs_boundary_side_count(const dbs_boundary* boundary, int32_t side, size_t* out) {
  return guarded(__func__, [&] {
    require_non_null(boundary, "boundary");
    require_non_null(out, "out");
    *out = side_of(boundary->boundary, side).size();
  });
}

int dbs_boundary_side_points(const dbs_boundary* boundary, int32_t side, double* out_xyz, size_t capacity) {
  return guarded(__func__, [&] {
    require_non_null(boundary, "boundary");
    require_non_null(out_xyz, "out_xyz");
    copy_points(side_of(boundary->boundary, side).points(), out_xyz, capacity, "out_xyz");
  });
}
