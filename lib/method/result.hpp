// The outcome of a parameterization: per-point parameters in input order, the quadtree of
// patches, and summary statistics.
#pragma once
#include <cstdint>
#include <vector>

#include "patch.hpp"

namespace dbs {

struct Result {
  // per point, input order
  std::vector<double> u, v, distance;
  std::vector<std::int32_t> patch, level;
  /// Per point: 1 when the last-resort repair (fold_repair.hpp) gave it its (u,v) from its
  /// neighbours (its distance is then to the surface at that (u,v)); all 0 when it was off.
  std::vector<char> repaired;
  std::size_t repaired_points = 0;
  // the quadtree; patches[id].id == id; patches[0] is the root
  std::vector<Patch> patches;
  // summary
  double mean_distance = 0.0, max_distance = 0.0, rms_distance = 0.0;
  double accuracy = 0.0;      // target used (the effective one), cloud units
  bool accuracy_met = false;  // every leaf met it
  double requested_accuracy = 0.0;      // the caller's target (absolute or relative), cloud units
  bool requested_accuracy_met = false;  // every leaf met the requested target
  double noise = 0.0;                   // estimated noise deviation sigma along the normal, cloud units
  // The fold measure of the (u,v) (fold_measure.hpp): no connectivity, no trust in the surface.
  // It judges at most 20,000 points of the body, evenly spread over the input order; counts are of those.
  std::size_t judged_points = 0, folded_points = 0, undecided_points = 0, coincident_points = 0;
  std::size_t collapsed_points = 0;  // of the undecided: neighbourhood squeezed in (u,v)
  double folded_share = 0.0;  // folded / decided points
  int levels = 0;             // quadtree levels present (1 = root only)
  int iterations = 0;         // grid evolutions over all patches
  int solver = 0;             // the solver that ran (Solver: 0 linear, 1 Ceres)
  std::size_t refined_curves = 0;    // grid sections the Ceres solver refined, all patches
  std::size_t ceres_iterations = 0;  // Ceres iterations over them
  double loss_scale = 0.0;    // the robust loss's scale used, cloud units; 0 without a loss
  double length_scale = 0.0;  // h
  // The inputs checked against each other (input_checks.hpp).
  double boundary_gap = 0.0;    // the boundary's distance to the cloud, in spacings h
  double scale_ratio = 1.0;     // the cloud's size / the boundary's
  double coverage = 1.0;        // share of [0,1]^2 covered by the points' (u,v)
  std::size_t clamped_points = 0;  // points outside the boundary by more than h, clamped onto the domain's edge
  /// Per point: 1 when far outside the cloud's body (cloud_body.hpp): it took the (u,v) of its
  /// nearest point of the body and is left out of the surfaces, the repair and the statistics.
  std::vector<char> outside_body;
  std::size_t far_points = 0;
  double seconds = 0.0;
  /// Wall-clock time of each stage (their sum is about `seconds`).
  struct StageSeconds {
    double index = 0.0, evolve = 0.0, subdivide = 0.0, parameterize = 0.0, folds = 0.0;
  } stage_seconds;

  std::size_t leaf_count() const;
  /// The leaf whose rectangle contains (u,v); on a seam the one with the larger u (then v)
  /// start, so every (u,v) has exactly one leaf.
  int leaf_at(double u, double v) const;
  /// Surface point (and unit normal) at global (u,v) in [0,1]^2.
  Vec3 evaluate(double u, double v, Vec3* normal = nullptr) const;
};

}  // namespace dbs
