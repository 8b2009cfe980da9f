#include "raster_view.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "error.hpp"

namespace dbs {
namespace {

constexpr Rgb kBackground = {236, 238, 242};
constexpr double kAmbient = 0.22;
constexpr double kMargin = 0.04;  // of the image's smaller side

Vec3 face_normal(const std::vector<Vec3>& points, const Triangle& t) { return (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]); }

Vec3 rotated(const Vec3& x, const Vec3& axis, double degrees) { return Eigen::AngleAxisd(degrees * M_PI / 180.0, axis) * x; }

}  // namespace

ViewCamera default_view(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles) {
  if (triangles.empty()) fail(ErrorCode::Empty, "default_view: no triangles to look at");
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& p : points) cov += (p - mean) * (p - mean).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);  // eigenvalues ascending
  Vec3 smallest = eig.eigenvectors().col(0), middle = eig.eigenvectors().col(1), largest = eig.eigenvectors().col(2);
  Vec3 normal_sum = Vec3::Zero();
  for (const Triangle& t : triangles) normal_sum += face_normal(points, t);
  if (normal_sum.dot(smallest) < 0.0) smallest = -smallest;
  // Look against the normals, turned for a three-quarter view: of the four ways to turn,
  // the one that sees the most surface from the front (3D area times the cosine of the
  // viewing angle, back faces counting against it), ties going to the first.
  Vec3 forward = -smallest;
  double best = -std::numeric_limits<double>::infinity();
  for (double about_largest : {30.0, -30.0}) {
    for (double about_middle : {20.0, -20.0}) {
      Vec3 candidate = rotated(rotated(-smallest, largest, about_largest), middle, about_middle).normalized();
      double seen = 0.0;
      for (const Triangle& t : triangles) seen -= 0.5 * face_normal(points, t).dot(candidate);
      if (seen > best) best = seen, forward = candidate;
    }
  }
  Vec3 up = middle - middle.dot(forward) * forward;
  if (up.norm() < 1e-9) up = smallest - smallest.dot(forward) * forward;
  up.normalize();
  ViewCamera camera;
  camera.forward = forward;
  camera.up = up;
  camera.right = forward.cross(up).normalized();
  return camera;
}

RgbImage render_view(const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v, const std::vector<Triangle>& triangles, const CirclePattern& pattern, const ViewCamera& camera, int width, int height) {
  RgbImage image(width, height, kBackground);
  if (triangles.empty()) return image;

  // Smooth normals: area-weighted face normals summed at the vertices.
  std::vector<Vec3> normals(points.size(), Vec3::Zero());
  std::vector<char> used(points.size(), 0);
  for (const Triangle& t : triangles) {
    Vec3 n = face_normal(points, t);
    for (std::int32_t k : t) {
      normals[k] += n;
      used[k] = 1;
    }
  }
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!used[i]) continue;
    double x = points[i].dot(camera.right), y = points[i].dot(camera.up);
    x0 = std::min(x0, x), x1 = std::max(x1, x);
    y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  double margin = kMargin * std::min(width, height);
  double extent = std::max(x1 - x0, y1 - y0);
  double scale = extent > 0.0 ? std::min((width - 2 * margin) / std::max(x1 - x0, 1e-300), (height - 2 * margin) / std::max(y1 - y0, 1e-300)) : 1.0;
  double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  auto to_pixel = [&](const Vec3& p, double& px, double& py) {
    px = 0.5 * width + (p.dot(camera.right) - cx) * scale;
    py = 0.5 * height - (p.dot(camera.up) - cy) * scale;
  };
  // Light from over the viewer's left shoulder.
  const Vec3 light = (-camera.forward + 0.45 * camera.up - 0.3 * camera.right).normalized();

  std::vector<double> depth(static_cast<std::size_t>(width) * height, std::numeric_limits<double>::infinity());
  for (const Triangle& t : triangles) {
    double px[3], py[3], pz[3];
    for (int k = 0; k < 3; ++k) {
      to_pixel(points[t[k]], px[k], py[k]);
      pz[k] = points[t[k]].dot(camera.forward);
    }
    double area = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]);
    if (area == 0.0) continue;
    int xa = std::max(0, static_cast<int>(std::floor(std::min({px[0], px[1], px[2]}))));
    int xb = std::min(width - 1, static_cast<int>(std::ceil(std::max({px[0], px[1], px[2]}))));
    int ya = std::max(0, static_cast<int>(std::floor(std::min({py[0], py[1], py[2]}))));
    int yb = std::min(height - 1, static_cast<int>(std::ceil(std::max({py[0], py[1], py[2]}))));
    for (int y = ya; y <= yb; ++y) {
      for (int x = xa; x <= xb; ++x) {
        double sx = x + 0.5, sy = y + 0.5;
        // barycentric weights; same sign as `area` inside, whichever way the triangle turns
        double w0 = ((px[1] - sx) * (py[2] - sy) - (py[1] - sy) * (px[2] - sx)) / area;
        double w1 = ((px[2] - sx) * (py[0] - sy) - (py[2] - sy) * (px[0] - sx)) / area;
        double w2 = 1.0 - w0 - w1;
        if (w0 < 0.0 || w1 < 0.0 || w2 < 0.0) continue;
        double z = w0 * pz[0] + w1 * pz[1] + w2 * pz[2];
        double& stored = depth[static_cast<std::size_t>(y) * width + x];
        if (z >= stored) continue;
        stored = z;
        Vec3 n = w0 * normals[t[0]] + w1 * normals[t[1]] + w2 * normals[t[2]];
        double nn = n.norm();
        double lambert = nn > 0.0 ? std::abs(n.dot(light)) / nn : 1.0;  // two-sided
        double shade = kAmbient + (1.0 - kAmbient) * lambert;
        double tu = w0 * u[t[0]] + w1 * u[t[1]] + w2 * u[t[2]];
        double tv = w0 * v[t[0]] + w1 * v[t[1]] + w2 * v[t[2]];
        double albedo = pattern.black(tu, tv) ? 0.12 : 0.97;
        auto level = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(shade * albedo, 0.0, 1.0)));
        // a warm tint on the white so the surface stands out from the background
        image.set(x, y, {level, static_cast<std::uint8_t>(level * 0.96), static_cast<std::uint8_t>(level * 0.88)});
      }
    }
  }
  return image;
}

}  // namespace dbs
