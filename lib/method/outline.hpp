// The outline of an open scan: its boundary points, ordered into closed loops, smoothed.
//
// A point is a boundary point when its neighbourhood leaves an angular gap wider than
// kOutlineGap in its local tangent plane (PCA over its nearest points). Its neighbourhood is
// its `neighbours` nearest points together with the points that count it among theirs (the
// reverse neighbours): where the density changes, a point on the sparse side has all its
// nearest points on the dense side, but the sparse points around it name it, so it is not
// taken for a boundary point.
//
// Boundary points within kBridgeSpacings (outline.cpp) local spacings of each other are linked
// (the band of boundary points along a randomly sampled outline is thin and has gaps of
// several spacings); each component of at least kMinLoopPoints points is ordered by the
// longest path of its minimum spanning tree (the loop less its longest edge; the band, two or
// three wide, leaves only short branches), rid of excursions round voids that open onto it
// and of back-steps across the band, smoothed by a Gaussian over kSmoothingSpacings local
// spacings of arc length, pushed out along the surface so that it runs on or just outside the
// outermost points (no genuine point outside it), and smoothed once more lightly. The loop of
// the longest perimeter is the outer one, the others are holes, unless they are voids of the
// sampling (a perimeter below 16 local spacings, or points more than 2 spacings apart).
//
// Deterministic (ties by point index) and invariant to scale and rigid motion (only ratios of
// distances are used).
#pragma once
#include <cstddef>
#include <vector>

#include "geometry.hpp"

namespace dbs {

constexpr double kOutlineGap = 2.0943951023931957;  ///< a boundary point's angular gap exceeds this (120 degrees)
constexpr std::size_t kMinLoopPoints = 8;            ///< smaller components are noise
constexpr double kSmoothingSpacings = 2.0;           ///< Gaussian window (sigma) of the smoothing, in local spacings
constexpr std::size_t kSpacingNeighbour = 6;         ///< the local spacing: the distance to this nearest neighbour

/// One closed loop of the outline.
struct OutlineLoop {
  std::vector<Vec3> points;          ///< smoothed, in order, first point not repeated
  std::vector<std::size_t> sources;  ///< per point: the cloud point it was smoothed from
  std::vector<Vec3> normals;         ///< per point: the cloud's unit normal there, oriented consistently along the loop
  double perimeter = 0.0;
};

struct Outline {
  std::vector<char> boundary;        ///< per cloud point: 1 for a boundary point
  std::vector<double> spacing;       ///< per cloud point: its local spacing
  OutlineLoop outer;                 ///< the loop enclosing the largest area in the cloud's principal plane
  std::vector<OutlineLoop> holes;    ///< the others inside it, in the order of the lowest point index of their boundary points
};

/// The plane of a cloud's two principal axes (PCA), where outlines are compared and
/// rectangles fitted.
struct PlaneFrame {
  Vec3 origin, e1, e2;
  Vec2 project(const Vec3& p) const { return {(p - origin).dot(e1), (p - origin).dot(e2)}; }
};
PlaneFrame principal_plane(const std::vector<Vec3>& points);

/// The outline of `points` with neighbourhoods of `neighbours` nearest points (at least 6),
/// found on the distinct points (copies share their point's verdict; sources name the lowest
/// index of a copy). threads as Options::threads (0 = all cores); the result does not depend
/// on it. Throws Error: InvalidArgument (fewer than neighbours + 1 distinct points,
/// neighbours < 6), NonFinite, OutOfRange (more than 2^32 points), Degenerate (no closed loop:
/// the cloud has no outline, e.g. a closed surface; most points look like border points;
/// separate pieces, a loop outside the outer one).
Outline find_outline(const std::vector<Vec3>& points, std::size_t neighbours, int threads);

}  // namespace dbs
