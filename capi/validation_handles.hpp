// The real types behind the validation handles of dbs.h (mesh, distortion, distances),
// defined before dbs.h is included (through firewall.hpp) so the compiler checks every
// prototype against them.
#pragma once
#include <vector>

#include "distance_stats.hpp"
#include "distortion.hpp"
#include "point_cloud.hpp"
#include "validation_mesh.hpp"

/// The Delaunay mesh with copies of what it is over, so it outlives its result and cloud.
struct dbs_mesh {
  dbs::PointCloud cloud;
  std::vector<double> u, v;
  dbs::ValidationMesh mesh;
};

struct dbs_distortion {
  dbs::Distortion distortion;
};

struct dbs_distances {
  dbs::DistanceReport report;
};

#include "firewall.hpp"
