// The pictures of a validation report, drawn in software: the parameter domain with the
// quadtree's leaf rectangles and the triangles coloured by distortion, and a histogram of
// the point-to-surface distances. (The textured 3D view is raster_view's.)
#pragma once
#include <cstddef>
#include <vector>

#include "distance_stats.hpp"
#include "distortion.hpp"
#include "geometry.hpp"
#include "rgb_image.hpp"
#include "triangles.hpp"

namespace dbs {

/// Conformal distortion drawn at full colour (dark red); 1 is dark blue, log scale between.
constexpr double kConformalColourLimit = 3.0;

/// Colour of a value t in [0, 1] (clamped) on a blue-yellow-red ramp.
Rgb ramp_colour(double t);

/// The domain [0,1]^2, u to the right and v up, `size` pixels wide: every pixel coloured by
/// the mean log conformal distortion of the triangles in it, in 16 colour bands (a triangle that covers no pixel
/// centre counts in the pixel of its centroid), degenerate triangles grey, suspicious ones
/// black, folded ones magenta over them (each also as a 3 x 3 dot, so that the smallest show),
/// the points `turned` (indices into u and v: points on a sheet of the surface turned against
/// the cloud, Result::turned) as orange 3 x 3 dots, leaf rectangles as dark lines; a title and
/// a legend. `distortion` has one entry per triangle.
RgbImage draw_parameter_domain(const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const std::vector<TriangleDistortion>& distortion, const std::vector<std::size_t>& suspicious, const std::vector<std::size_t>& turned, const std::vector<Rect>& leaves, int size);

/// Histogram of `distances` (50 bins from 0 to about the 99th percentile, larger values in the
/// last bin) with the tolerance (green) and the mean (orange) marked, and the figures of
/// `stats` written above it. width >= 200, height >= 150.
RgbImage draw_distance_histogram(const std::vector<double>& distances, const DistanceStats& stats, double tolerance, int width, int height);

}  // namespace dbs
