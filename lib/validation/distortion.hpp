// Method (b) of the paper's section 7, measured on the parameters themselves: how much each
// triangle of a mesh over the cloud is distorted between 3D and its (u,v) image. Works on any
// triangle list over the points (the Delaunay mesh of the parameters or a caller's mesh).
//
// The (u,v) domain is first scaled so that distortion measures shape, not the unit square:
// u' = scale_u * u, v' = scale_v * v, with the total (u',v') area of the measured triangles
// equal to their total 3D area. DomainScaling::Uniform scales both axes alike;
// DomainScaling::PerAxis first scales each axis by the surface's typical speed along it (the
// 3D-area-weighted median of |dP/du|, resp. |dP/dv|, over the triangles; a median so that a
// few triangles bridging across the surface do not decide it), which takes out the aspect
// ratio of the surface's sides, then scales both alike to match the areas.
//
// Per triangle, J is the linear map from the 3D triangle (in its own plane) to its (u',v')
// image, sigma1 >= sigma2 >= 0 its singular values.
#pragma once
#include <cstddef>
#include <vector>

#include "geometry.hpp"
#include "summary_stats.hpp"
#include "triangles.hpp"

namespace dbs {

enum class DomainScaling { Uniform = 0, PerAxis = 1 };

struct TriangleDistortion {
  double sigma1 = 0.0, sigma2 = 0.0;
  double conformal = 0.0;        // sigma1 / sigma2 >= 1; 1 = angles kept
  double area = 0.0;             // sigma1 * sigma2; 1 = area kept
  double stretch_l2 = 0.0;       // Sander et al.'s L2 stretch of (u',v') -> 3D: sqrt((1/sigma1^2 + 1/sigma2^2) / 2)
  double stretch_linf = 0.0;     // its largest stretch: 1 / sigma2
  double edge_difference = 0.0;  // largest |edge length in (u',v') - in 3D| / length in 3D of the three edges
  bool folded = false;           // orientation opposite to the majority of the triangles
  bool degenerate = false;       // zero area in 3D or in (u,v): no measures, in no summary
  bool cropped = false;          // a vertex has no (u,v) (a cropped point): no measures, in no summary
};

struct DistortionSummary {
  std::size_t triangles = 0;   // measured triangles (the cropped ones not included)
  std::size_t cropped = 0;     // triangles with a cropped vertex, left out
  std::size_t degenerate = 0;
  std::size_t folded = 0;
  double scale_u = 1.0, scale_v = 1.0;  // the domain scaling applied
  // over the non-degenerate triangles, each counted once (not area-weighted)
  MeasureSummary conformal, area, stretch_l2, stretch_linf, edge_difference, sigma1, sigma2;
  double mesh_stretch_l2 = 0.0;  // Sander's L2 stretch of the whole mesh (3D-area-weighted RMS); 1 = isometric
};

struct Distortion {
  std::vector<TriangleDistortion> triangles;  // in the order of the input triangles
  DistortionSummary summary;
};

/// Measures every triangle. A triangle's orientation is the sign of det J: the sign of its
/// (u,v) area, times the sign of (b-a) x (c-a) . n when `reference_normals` (one per
/// triangle, e.g. the base surface's normal there) are given; folded triangles are those whose
/// orientation differs from that of the majority (ties: counter-clockwise wins). Throws
/// Error(InvalidArgument) when u, v and points differ in size or reference_normals is neither
/// empty nor one per triangle, Error(OutOfRange) naming a triangle with a vertex outside the
/// points, Error(NonFinite) naming a non-finite parameter of a used vertex.
Distortion measure_distortion(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, DomainScaling scaling, const std::vector<Vec3>& reference_normals = {});

}  // namespace dbs
