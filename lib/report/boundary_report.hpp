// The report of a boundary against its cloud (dbs_boundary_report_write, dbs-boundary
// --report): a picture of the points with the four sides in their colours, the corners
// labelled with their (u,v) and the holes, seen along the cloud's least principal axis (the
// scan from above) and from the side, so a user sees at once whether the outline was found
// where they expect, where each side runs and which corner is (0,0); and boundary.json with
// the figures.
#pragma once
#include <string>
#include <vector>

#include "boundary.hpp"
#include "geometry.hpp"
#include "rgb_image.hpp"

namespace dbs {

/// Pixels of the picture: two views side by side, each kViewSize square, with a legend below.
constexpr int kBoundaryViewSize = 480;
constexpr int kBoundaryLegendHeight = 40;

/// The picture of `points` (at least one) with `boundary` and `holes` (closed loops).
RgbImage draw_boundary_picture(const std::vector<Vec3>& points, const Boundary& boundary, const std::vector<std::vector<Vec3>>& holes);

/// Writes boundary.png (draw_boundary_picture) and boundary.json (the sides' lengths and point
/// counts, the corners, the holes' sizes) into `dir`, created if missing; files there are
/// replaced. Error(Io) when the directory or a file cannot be written, Error(InvalidArgument)
/// for no points.
void write_boundary_report(const std::vector<Vec3>& points, const Boundary& boundary, const std::vector<std::vector<Vec3>>& holes, const std::string& dir);

}  // namespace dbs
