// Algorithm A4: distribute a parent's subcloud among its four children. A point's distance
// to a child is that of its projection onto the child (points whose foot is outside the child
// or missing use the nearest point of the child's boundary), or of the child's nearest
// sample where that is nearer; bounds of it decide most points without projecting, with the
// same outcome (subcloud.cpp). A point joins a child when its distance is within
// `near` x the child's bounding-box diagonal (measured in the frame of its corners, see
// corner_frame.hpp), and belongs only to that child when within
// `own` x that diagonal (when several children qualify, the nearest; ties go to the first in
// child order, so the split is deterministic). A point near no child joins the nearest one,
// so the parent's subcloud is the union of the children's. Each list keeps the order of
// `parent_subcloud`; the result does not depend on `threads`. `meter` (may be null) counts a
// unit per point.
#pragma once
#include <array>
#include <vector>

#include "base_surface.hpp"
#include "point_list.hpp"
#include "work_meter.hpp"

namespace dbs {

std::array<PointList, 4> split_subcloud(const std::vector<Vec3>& points, const PointList& parent_subcloud, const std::array<const BaseSurface*, 4>& children, double near, double own, int threads, WorkMeter* meter = nullptr);

}  // namespace dbs
