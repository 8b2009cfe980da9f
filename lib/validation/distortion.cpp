#include "distortion.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "error.hpp"

namespace dbs {
namespace {

// A triangle whose doubled area is below this fraction of its squared edge lengths is flat.
constexpr double kFlatArea = 1e-14;

// What the two passes need of one triangle: its edges in 3D and in the unscaled (u,v).
struct Edges {
  Vec3 e1, e2;            // b - a, c - a in 3D
  Eigen::Matrix2d q;      // columns: (u,v) of b - a, c - a
  Vec3 normal;            // e1 x e2
  double orientation = 1.0;
  bool degenerate = false;
};

void singular_values(const Eigen::Matrix2d& m, double& s1, double& s2) {
  // Closed form for 2x2 matrices (Blinn): stable, and exact for similarities up to round-off.
  double e = 0.5 * (m(0, 0) + m(1, 1)), f = 0.5 * (m(0, 0) - m(1, 1));
  double g = 0.5 * (m(1, 0) + m(0, 1)), h = 0.5 * (m(1, 0) - m(0, 1));
  double q = std::hypot(e, h), r = std::hypot(f, g);
  s1 = q + r;
  s2 = std::abs(q - r);
}

/// The triangle's edges in units of `unit` (a typical edge length), so that the areas of a
/// mesh 1e-100 across neither underflow nor those of one 1e75 across overflow.
Edges edges_of(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const Triangle& t, double unit) {
  Edges ed;
  const Vec3& a = points[t[0]];
  ed.e1 = (points[t[1]] - a) / unit;
  ed.e2 = (points[t[2]] - a) / unit;
  ed.normal = ed.e1.cross(ed.e2);
  ed.q << u[t[1]] - u[t[0]], u[t[2]] - u[t[0]], v[t[1]] - v[t[0]], v[t[2]] - v[t[0]];
  double det_q = ed.q.determinant();
  double flat3 = kFlatArea * (ed.e1.squaredNorm() + ed.e2.squaredNorm());
  double flat2 = kFlatArea * (ed.q.col(0).squaredNorm() + ed.q.col(1).squaredNorm());
  ed.degenerate = !(ed.normal.norm() > flat3) || !(std::abs(det_q) > flat2);
  ed.orientation = det_q < 0.0 ? -1.0 : 1.0;
  return ed;
}

// Median of `values` weighted by `weights` (both non-empty, weights >= 0, not all zero).
double weighted_median(std::vector<std::pair<double, double>> value_weight) {
  std::sort(value_weight.begin(), value_weight.end());
  double total = 0.0;
  for (const auto& vw : value_weight) total += vw.second;
  double running = 0.0;
  for (const auto& vw : value_weight) {
    running += vw.second;
    if (running >= 0.5 * total) return vw.first;
  }
  return value_weight.back().first;
}

// u' = scale_u u, v' = scale_v v with total (u',v') area = total 3D area (see the header).
/// False (scales 1) when no triangle has area to fit them to.
bool fit_domain_scale(const std::vector<Edges>& edges, DomainScaling scaling, double& scale_u, double& scale_v) {
  double area3 = 0.0, area2 = 0.0;
  std::vector<std::pair<double, double>> speed_u, speed_v;  // (|dP/du|, 3D area) per triangle
  for (const Edges& ed : edges) {
    if (ed.degenerate) continue;
    double a3 = 0.5 * ed.normal.norm();
    area3 += a3;
    area2 += 0.5 * std::abs(ed.q.determinant());
    if (scaling == DomainScaling::PerAxis) {
      // Surface speeds dP/du, dP/dv of the linear map (u,v) -> 3D on this triangle.
      Eigen::Matrix<double, 3, 2> p;
      p.col(0) = ed.e1;
      p.col(1) = ed.e2;
      Eigen::Matrix<double, 3, 2> speeds = p * ed.q.inverse();
      speed_u.emplace_back(speeds.col(0).norm(), a3);
      speed_v.emplace_back(speeds.col(1).norm(), a3);
    }
  }
  scale_u = scale_v = 1.0;
  if (!(area3 > 0.0) || !(area2 > 0.0)) return false;
  if (scaling == DomainScaling::PerAxis) {
    // Medians, not means: a few triangles bridging across the surface have huge speeds.
    scale_u = weighted_median(std::move(speed_u));
    scale_v = weighted_median(std::move(speed_v));
  }
  double common = std::sqrt(area3 / (area2 * scale_u * scale_v));
  scale_u *= common;
  scale_v *= common;
  return true;
}

TriangleDistortion measure(const Edges& ed, double scale_u, double scale_v) {
  TriangleDistortion d;
  // The 3D triangle in its own plane: x along e1, y completing a frame with the normal, so the
  // triangle is counter-clockwise there and det J carries the (u,v) orientation.
  double len1 = ed.e1.norm();
  Vec3 x = ed.e1 / len1;
  Vec3 y = ed.normal.normalized().cross(x);
  Eigen::Matrix2d plane;
  plane << len1, ed.e2.dot(x), 0.0, ed.e2.dot(y);
  Eigen::Matrix2d image = Eigen::Vector2d(scale_u, scale_v).asDiagonal() * ed.q;
  Eigen::Matrix2d jacobian = image * plane.inverse();
  singular_values(jacobian, d.sigma1, d.sigma2);
  d.conformal = d.sigma1 / d.sigma2;
  d.area = d.sigma1 * d.sigma2;
  d.stretch_l2 = std::sqrt(0.5 * (1.0 / (d.sigma1 * d.sigma1) + 1.0 / (d.sigma2 * d.sigma2)));
  d.stretch_linf = 1.0 / d.sigma2;
  const Vec3 edges3[3] = {ed.e1, ed.e2 - ed.e1, ed.e2};
  const Eigen::Vector2d edges2[3] = {image.col(0), image.col(1) - image.col(0), image.col(1)};
  for (int k = 0; k < 3; ++k) {
    double len3 = edges3[k].norm();
    d.edge_difference = std::max(d.edge_difference, std::abs(edges2[k].norm() - len3) / len3);
  }
  return d;
}

}  // namespace

Distortion measure_distortion(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, DomainScaling scaling, const std::vector<Vec3>& reference_normals) {
  if (u.size() != points.size() || v.size() != points.size()) fail(ErrorCode::InvalidArgument, "measure_distortion: " + std::to_string(points.size()) + " points but " + std::to_string(u.size()) + " u and " + std::to_string(v.size()) + " v values");
  if (!reference_normals.empty() && reference_normals.size() != triangles.size()) fail(ErrorCode::InvalidArgument, "measure_distortion: " + std::to_string(reference_normals.size()) + " reference normals for " + std::to_string(triangles.size()) + " triangles");

  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (std::int32_t vertex : triangles[t]) {
      if (vertex < 0 || static_cast<std::size_t>(vertex) >= points.size()) fail(ErrorCode::OutOfRange, "triangle " + std::to_string(t) + " has vertex index " + std::to_string(vertex) + " outside the " + std::to_string(points.size()) + " points");
      if (!std::isfinite(u[vertex]) || !std::isfinite(v[vertex])) fail(ErrorCode::NonFinite, "parameter (u,v) of point " + std::to_string(vertex) + " (a vertex of triangle " + std::to_string(t) + ") is not finite");
    }
  }
  // The unit of length: the median first edge (every measure is a ratio but the domain's
  // scales, which are reported back in cloud units).
  double unit = 1.0;
  if (!triangles.empty()) {
    std::vector<double> lengths(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) lengths[t] = (points[triangles[t][1]] - points[triangles[t][0]]).stableNorm();
    std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2), lengths.end());
    const double median = lengths[lengths.size() / 2];
    if (median > 0.0 && std::isfinite(median)) unit = median;
  }
  std::vector<Edges> edges(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    edges[t] = edges_of(points, u, v, triangles[t], unit);
    if (!reference_normals.empty() && edges[t].normal.dot(reference_normals[t]) < 0.0) edges[t].orientation = -edges[t].orientation;
  }

  Distortion result;
  DistortionSummary& s = result.summary;
  s.triangles = triangles.size();
  const bool fitted = fit_domain_scale(edges, scaling, s.scale_u, s.scale_v);

  std::size_t negative = 0, positive = 0;
  for (const Edges& ed : edges) {
    if (ed.degenerate) continue;
    (ed.orientation < 0.0 ? negative : positive) += 1;
  }
  const double majority = negative > positive ? -1.0 : 1.0;

  result.triangles.resize(triangles.size());
  std::vector<double> conformal, area, stretch_l2, stretch_linf, edge_difference, sigma1, sigma2;
  double stretch_sum = 0.0, area3_sum = 0.0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Edges& ed = edges[t];
    TriangleDistortion& d = result.triangles[t];
    if (ed.degenerate) {
      d.degenerate = true;
      ++s.degenerate;
      continue;
    }
    d = measure(ed, s.scale_u, s.scale_v);
    d.folded = ed.orientation != majority;
    if (d.folded) ++s.folded;
    conformal.push_back(d.conformal);
    area.push_back(d.area);
    stretch_l2.push_back(d.stretch_l2);
    stretch_linf.push_back(d.stretch_linf);
    edge_difference.push_back(d.edge_difference);
    sigma1.push_back(d.sigma1);
    sigma2.push_back(d.sigma2);
    double a3 = 0.5 * ed.normal.norm();
    stretch_sum += a3 * d.stretch_l2 * d.stretch_l2;
    area3_sum += a3;
  }
  s.conformal = summarize(std::move(conformal));
  s.area = summarize(std::move(area));
  s.stretch_l2 = summarize(std::move(stretch_l2));
  s.stretch_linf = summarize(std::move(stretch_linf));
  s.edge_difference = summarize(std::move(edge_difference));
  s.sigma1 = summarize(std::move(sigma1));
  s.sigma2 = summarize(std::move(sigma2));
  s.mesh_stretch_l2 = area3_sum > 0.0 ? std::sqrt(stretch_sum / area3_sum) : 0.0;
  if (fitted) {  // in cloud units; unfitted scales stay 1
    s.scale_u *= unit;
    s.scale_v *= unit;
  }
  return result;
}

}  // namespace dbs
