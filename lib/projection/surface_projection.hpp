// Orthogonal projection of points onto a base surface: the nearest foot, not a local
// minimum. Start from the nearest of a dense set of surface samples (GridNearest over them;
// the lowest sample index among equally near ones),
// refine with a Gauss-Newton iteration in (u,v) (step halving, clamped to [0,1]^2, a
// coordinate on the border held there while the descent points outwards); a foot pushed
// against the border becomes the nearest boundary point: each side is searched from its
// nearest sample, and the nearest of the four results wins. project() is const and keeps no
// scratch state: concurrent calls on one projector are safe (prepare() is not: it comes first).
#pragma once
#include <memory>
#include <vector>

#include "base_surface.hpp"

namespace dbs {

struct Foot {
  double u = 0.0;
  double v = 0.0;
  Vec3 point = Vec3::Zero();
  double distance = 0.0;
  /// True when the foot is an interior critical point (the orthogonal projection exists
  /// inside the patch); false when it was clamped to the boundary (A4.1.2/A4.1.3).
  bool inside = true;
};

/// How far the iteration goes: to the foot's parameters within rounding (the parameters a
/// result reports), or until the step is estimated below 1e-7 of the unit domain (seen:
/// parameters within 1.3e-6, the distance, stationary at the foot, within 1e-11 of the
/// patch size), which is all a measurement of distances or a choice between surfaces needs,
/// at fewer iterations. Distance and Measure settle a foot on a crease of the surface (the
/// Coons patch of polylines has one along each vertex's parameter line) on the crease,
/// where Parameters lets every Gauss-Newton step cross it and halve it back, up to the
/// iteration limit (on the hard shapes over 100 surface evaluations a point). Measure is the
/// name for a mean over many points (the error of a growing grid); Distance for a choice
/// between surfaces (the subclouds' membership). Settling the membership's feet too saved
/// about a tenth of the time on the hard shapes at 10k points and kept the folds within
/// their run-to-run spread (over six shapes at six densities 791 folded triangles
/// against 802, the bench clouds unchanged). Measure also turns to Newton's steps where
/// Gauss-Newton's shrink slowly (a point of another sheet, as far off as the surface's
/// radius of curvature: on the 10,201-point mushroom 6,225 of the 158,442 feet of these two
/// modes ran into the iteration limit), so those feet converge instead; Distance does not (a
/// foot Newton's steps find there may be another local minimum, and a membership with it:
/// the 10,201-point tall dome's mean distance rose from 0.000586 to 0.000755). Measure's
/// feet stop at 1e-5 in the parameters (the distance within about 3e-7 of the patch size):
/// Distance's 1e-7 took 4-5% more instructions on the mushroom and the rippled field and
/// gave every one of 69 runs compared the same result.
enum class FootPrecision { Parameters, Distance, Measure };

class SurfaceProjector {
 public:
  /// Samples `surface` (which must outlive the projector) on a samples x samples grid.
  explicit SurfaceProjector(const BaseSurface& surface, FootPrecision precision = FootPrecision::Parameters, int samples = 64);
  ~SurfaceProjector();
  SurfaceProjector(const SurfaceProjector&) = delete;
  SurfaceProjector& operator=(const SurfaceProjector&) = delete;

  Foot project(const Vec3& q) const;
  /// Before many project() calls (more than the samples): tabulates the surface and its
  /// derivatives at every sample, so that a descent from the nearest sample starts without
  /// evaluating the surface there. The same feet, bit for bit, one evaluation fewer each.
  void prepare(std::size_t projections);
  /// The surface sample nearest q (one tree query): its index, and its distance to q,
  /// an upper bound of the distance to the surface (and of project(q).distance, the
  /// descent starting there).
  struct Sample {
    std::size_t index;
    double distance;
  };
  Sample nearest_sample(const Vec3& q) const;
  /// A sample near q without a tree query: from the sample nearest the parameters `guess`
  /// (clamped to [0,1]^2), a walk to the nearest of the 8 neighbouring samples while that is
  /// nearer q (at most `max_steps` moves). Its distance bounds the distance of q to the
  /// surface from above, but the sample need not be the nearest one, so it gives no lower
  /// bound (sample_cover() does not apply to it).
  Sample sample_near(const Vec3& q, const Vec2& guess, int max_steps = 8) const;
  /// nearest_sample(q).distance.
  double sample_distance(const Vec3& q) const;
  /// How far a point of the surface may lie from its nearest sample, so that
  /// sample_distance(q) - sample_cover() bounds the distance of q to the surface from below
  /// (computed with the samples, on first use): with a margin, half the longest diagonal of
  /// a sample cell plus twice the farthest a boundary vertex lies from the chord between the
  /// samples of its side around it (the Coons patch carries a boundary's wiggles between
  /// samples into the interior). Infinite where the samples do not resolve the surface: a
  /// displacement with more than samples / 4 sites along a direction can bulge between
  /// samples by more than any margin.
  double sample_cover() const;
  /// project(q) from nearest_sample(q) found before: the same foot, without its query.
  Foot project(const Vec3& q, const Sample& nearest) const;
  /// The descent from `start` in [0,1]^2 (a foot of q found before on a nearby surface)
  /// instead of from the nearest sample: one tree query fewer and fewer steps, but the
  /// local foot nearest the start, which is the nearest foot only while the start is near it.
  Foot project_from(const Vec3& q, const Vec2& start) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace dbs
