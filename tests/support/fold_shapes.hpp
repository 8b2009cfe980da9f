// Analytic hard shapes for the fold-free work (issue 10): clouds with known parameters, their
// four boundary sides, reference triangles for scoring folds, and the noise-free surface.
//
// Plain C++17, std only (no libdbs internals, no Eigen), so that the core tests and the
// benchmark can both use it. Everything is deterministic: a fixed splitmix64 sequence (jitter
// and Box-Muller Gaussian noise), no std::*_distribution (whose output differs between
// standard libraries).
//
// Every shape is a surface S(a,b) over [0,1]^2, one-to-one, whose boundary is S on the sides
// of the square, oriented as dbs.h wants: bottom = S(t,0), right = S(1,t), top = S(t,1),
// left = S(0,t), t increasing; the corners are shared bitwise. Points sit on a jittered grid
// of (a,b) (nodes at cell centres, jitter +-0.3 cell, so none lies on the boundary); the
// reference triangles are two per grid cell, counter-clockwise in (a,b), split along the
// diagonal that gives the better smallest 3D angle; those with a smallest angle under 10
// degrees on the noise-free surface are dropped.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace dbs_folds {

using Point3 = std::array<double, 3>;
/// The noise-free surface: (a,b) in [0,1]^2 -> 3D point.
using SurfaceFunction = std::function<Point3(double a, double b)>;

struct FoldShape {
  std::string name;         // short id, e.g. "saddle-noisy"
  std::string description;  // one line
  std::vector<double> xyz;      // 3 per point (with noise when noise_sigma > 0)
  std::vector<double> uv_true;  // 2 per point: the (a,b) each point was sampled at
  // The boundary sides, 3 doubles per polyline point, dense (kBoundaryPoints each).
  std::vector<double> bottom, right, top, left;
  std::vector<int> triangles;  // 3 point indices per reference triangle, counter-clockwise in uv_true
  SurfaceFunction surface;     // the noise-free S(a,b)
  double diagonal = 0.0;       // bounding-box diagonal of the noise-free points
  double noise_sigma = 0.0;    // absolute sigma of the Gaussian noise along the normal (0 = none)
  std::size_t grid_a = 0, grid_b = 0;  // jittered grid size; point i + grid_a * j is node (i, j)

  std::size_t count() const { return xyz.size() / 3; }
  std::size_t triangle_count() const { return triangles.size() / 3; }
};

constexpr int kBoundaryPoints = 201;  // polyline points per side
constexpr double kMinAngleDegrees = 10.0;

// The shapes. `relative_noise` is sigma as a fraction of the bounding-box diagonal of the
// noise-free points; the noise is Gaussian along the surface normal. The point set, the
// parameters and the reference triangles do not depend on it.

/// (a) saddle z = 0.6 (x^2 - y^2) over [-1,1]^2.
FoldShape saddle(double relative_noise = 0.0);
/// (b) z = 0.2 sin(pi x) sin(pi y) + 0.012 sin(12 pi x) sin(12 pi y) on the unit square:
///     ripples one 11 x 11 grid cannot follow, even fitted to the points (6 periods a side; 4
///     were reached by the fit to the target, fit_to_target.hpp); noise-free, the default
///     options need 2 levels.
FoldShape rippled(double relative_noise = 0.0);
/// (c) a mushroom on a plate: stem radius 0.1, cap radius 0.24 whose rim overhangs the stem
///     by 0.14 (seen from the plate, the ring between stem and rim is covered three times); 0.38 tall.
FoldShape mushroom(double relative_noise = 0.0);
/// (d) a steep-walled dome on a plate: radius 0.1, height 0.6 (3x taller than wide).
FoldShape tall_dome(double relative_noise = 0.0);
/// (e) a 1.2 x 1 plate with three fingers 0.06 wide and 0.20, 0.25, 0.29 tall.
FoldShape fingers(double relative_noise = 0.0);
/// (f) an open box 1 x 1 x 0.4: floor in the middle of the square, walls in its border strips,
///     the rim the boundary; 90-degree creases floor/wall and wall/wall.
FoldShape open_box(double relative_noise = 0.0);
/// (g) a sharp cone (base radius 0.2, height 0.5: walls at 68 degrees) on a plate, its apex at
///     (a,b) = (1/2,1/2), where the quadtree's first centre falls.
FoldShape cone(double relative_noise = 0.0);
/// (h) 270 degrees of the unit sphere (polar angle <= 135 degrees), the rim split into four
///     90-degree arcs; (a,b) -> disk by the concentric (Shirley-Chiu) map, radius -> polar angle.
///     `degrees` (in (0, 360)) makes it more or less closed: 300 ("sphere-cap-300") and 330
///     ("sphere-cap-330", a head open only at its neck) close over ever smaller rims.
FoldShape sphere_cap(double relative_noise = 0.0, double degrees = 270.0);

/// The sigma for the noisy saddle: 0.5% of the diagonal.
constexpr double kSaddleNoise = 0.005;
/// Sigma of the noisy rippled field, relative: 0.0015 * 1.42 = 0.0021 < ripple amplitude / 3.
constexpr double kRippledNoise = 0.0015;
constexpr double kRippleAmplitude = 0.012;

/// Every shape once noise-free, plus the noisy saddle and the noisy rippled field (in the
/// order of the benchmark table).
std::vector<FoldShape> all_fold_shapes();
/// One shape of all_fold_shapes() by name; throws std::invalid_argument for an unknown name.
FoldShape fold_shape(const std::string& name);
/// The same with `density` times the points (each side of its jittered grid scaled by the
/// square root; in (0, 1000]), for measuring how the method scales.
FoldShape fold_shape(const std::string& name, double density);
/// The same with Gaussian noise along the normal of at least `noise` (sigma relative to the
/// diagonal, in [0, 0.05]; a noisy shape keeps its own where that is larger): the hard shapes
/// as a scanner sees them. Where that noise is the shape's, its name says so ("mushroom-noise0.005",
/// "saddle-noisy-noise0.01").
FoldShape fold_shape(const std::string& name, double density, double noise);
/// The names all_fold_shapes() uses, in its order.
std::vector<std::string> fold_shape_names();

// ---- scoring ---------------------------------------------------------------------------

struct FoldCount {
  std::size_t folded = 0;     // triangles with negative or collapsed signed (u,v) area
  std::size_t inverted = 0;   // ... of them with negative area
  std::size_t collapsed = 0;  // ... of them with an area in [0, 1e-3 median] (or NaN)
  std::size_t triangles = 0;  // triangles scored
  double share = 0.0;         // folded / triangles (0 when there are none)
};

/// Folded reference triangles of a parameterization: `uv` holds 2 doubles per point, the
/// triangles are counter-clockwise in the true parameters (as FoldShape::triangles). A
/// triangle is folded when its signed (u,v) area is negative or below 1e-3 of the median
/// |area| of all triangles under `uv` (a collapse counts as a fold).
FoldCount fold_share(const std::vector<double>& uv, const std::vector<int>& triangles);

/// Signed area of the triangle (i, j, k) in `uv` (2 doubles per point).
double signed_uv_area(const std::vector<double>& uv, int i, int j, int k);

/// A small k-d tree over 3D points (copied), for nearest-neighbour queries.
class KdTree {
 public:
  explicit KdTree(const std::vector<double>& xyz);
  std::size_t size() const { return points_.size() / 3; }
  /// The k nearest points to q (fewer if the tree is smaller), nearest first: their indices
  /// and squared distances. Ties are broken by index, so results are deterministic.
  void nearest(const double* q, std::size_t k, std::vector<std::size_t>& index, std::vector<double>& distance2) const;
  /// The nearest point's index (the tree must not be empty).
  std::size_t nearest(const double* q) const;

 private:
  struct Node {
    std::size_t begin, end;  // range in order_
    int axis;                // -1: leaf
    double split;
    std::size_t left, right;  // child nodes
  };
  std::size_t build(std::size_t begin, std::size_t end, int depth);
  void search(std::size_t node, const double* q, std::size_t k, std::vector<std::pair<double, std::size_t>>& heap) const;

  std::vector<double> points_;
  std::vector<std::size_t> order_;
  std::vector<Node> nodes_;
};

/// Distance of 3D points to a noise-free surface S over [0,1]^2: the nearest of a dense
/// sampling of S (resolution^2 cells), refined by a clamped Gauss-Newton search on (a,b).
/// Accurate to about 1e-9 of the shape's size on smooth parts; never above the distance to
/// the nearest sample.
class SurfaceDistance {
 public:
  explicit SurfaceDistance(SurfaceFunction surface, int resolution = 400);
  double operator()(const double* p) const;
  double operator()(const Point3& p) const { return (*this)(p.data()); }

 private:
  SurfaceFunction surface_;
  int resolution_;
  std::vector<double> ab_;  // 2 per sample
  KdTree tree_;
};

/// Mean distance to `shape.surface` of the points `xyz` (3 per point), e.g. the result
/// surface's S(u_i, v_i) for every cloud point.
double mean_distance_to_surface(const FoldShape& shape, const std::vector<double>& xyz);

/// Unit normal of a surface at (a,b) by central differences (one-sided at the square's
/// border); {0,0,0} where the surface is singular (an apex, a pole of the sphere map).
Point3 surface_normal(const SurfaceFunction& surface, double a, double b);

/// splitmix64 with uniform [0,1) and Box-Muller Gaussians: the same numbers everywhere.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform();   // [0, 1)
  double gaussian();  // N(0, 1)

 private:
  std::uint64_t state_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace dbs_folds
