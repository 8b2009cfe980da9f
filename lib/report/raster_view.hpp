// A small software rasterizer for the validation pictures: a triangle mesh over the cloud,
// seen orthographically, z-buffered, Lambert-shaded with smooth vertex normals and textured
// with the circle pattern through each vertex's (u,v). Enough to show method (c) of the
// paper's section 7 without another program.
#pragma once
#include <vector>

#include "circle_pattern.hpp"
#include "geometry.hpp"
#include "rgb_image.hpp"
#include "triangles.hpp"

namespace dbs {

/// An orthographic camera: `forward` is the viewing direction (into the scene), `right` and
/// `up` span the image plane; the three are orthonormal with right = forward x up.
struct ViewCamera {
  Vec3 forward = Vec3(0, 0, -1);
  Vec3 up = Vec3(0, 1, 0);
  Vec3 right = Vec3(1, 0, 0);
};

/// The camera looking at a mesh from a three-quarter view: from the side its triangles' normals
/// face (area-weighted), along the points' smallest principal axis turned by 30 degrees about
/// the largest and 20 about the middle one (in the directions that see the most surface from
/// the front), with the largest principal axis horizontal.
/// Throws Error(Empty) for no triangles.
ViewCamera default_view(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles);

/// Renders the triangles (indices assumed valid) into a width x height image on a light grey
/// background, fitted to the used points with a small margin.
RgbImage render_view(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const CirclePattern& pattern, const ViewCamera& camera, int width, int height);

}  // namespace dbs
