// Analytic hard shapes for the fold-free work: see fold_shapes.hpp.
#include "fold_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace dbs_folds {

namespace {

constexpr double kPi = 3.14159265358979323846;

Point3 sub(const Point3& p, const Point3& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
double dot(const Point3& p, const Point3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
double norm(const Point3& p) { return std::sqrt(dot(p, p)); }
Point3 cross(const Point3& p, const Point3& q) { return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]}; }

// ---- profiles of surfaces of revolution ------------------------------------------------

/// A G1 profile curve in the (rho, z) half plane drawn like a turtle: lines, circular arcs
/// and (for sharp edges) turns on the spot. Evaluated exactly at any arc length.
class Profile {
 public:
  Profile(double rho, double z, double heading) : rho_(rho), z_(z), heading_(heading) {}

  Profile& forward(double length) { return add(length, 0.0); }
  /// An arc of `radius` turning the heading by `turn` radians (> 0: counter-clockwise).
  Profile& arc(double radius, double turn) { return add(radius * std::abs(turn), turn > 0 ? 1.0 / radius : -1.0 / radius); }
  /// A sharp edge: the heading jumps by `angle`.
  Profile& turn(double angle) {
    heading_ += angle;
    return *this;
  }
  /// Shifts the profile so that it ends at z = 0, checks that it ends heading along +rho
  /// inside `outer`, and continues it flat to rho = outer.
  Profile& land(double outer) {
    const double dz = -z_;
    for (Piece& p : pieces_) p.z0 += dz;
    z_ = 0.0;
    const double turns = heading_ / (2 * kPi);
    if (std::abs(turns - std::round(turns)) > 1e-9) throw std::logic_error("fold_shapes: profile does not end heading outward");
    heading_ = 0.0;
    if (!(rho_ < outer)) throw std::logic_error("fold_shapes: profile ends outside its disk");
    return forward(outer - rho_);
  }

  double length() const { return length_; }
  double end_rho() const { return rho_; }

  void at(double s, double& rho, double& z) const {
    std::size_t k = 0;
    while (k + 1 < pieces_.size() && s > pieces_[k].s0 + pieces_[k].length) ++k;
    const Piece& p = pieces_[k];
    const double t = std::min(std::max(s - p.s0, 0.0), p.length);
    if (p.curvature == 0.0) {
      rho = p.rho0 + t * std::cos(p.heading0);
      z = p.z0 + t * std::sin(p.heading0);
    } else {
      const double h = p.heading0 + p.curvature * t;
      rho = p.rho0 + (std::sin(h) - std::sin(p.heading0)) / p.curvature;
      z = p.z0 - (std::cos(h) - std::cos(p.heading0)) / p.curvature;
    }
  }

 private:
  struct Piece {
    double s0, rho0, z0, heading0, length, curvature;
  };
  Profile& add(double length, double curvature) {
    pieces_.push_back({length_, rho_, z_, heading_, length, curvature});
    length_ += length;
    at(length_, rho_, z_);
    heading_ += curvature * length;
    return *this;
  }

  std::vector<Piece> pieces_;
  double rho_, z_, heading_;
  double length_ = 0.0;
};

/// A surface of revolution on a plate: the disk of radius `outer` around `centre` (plate
/// coordinates) carries the profile, which ends flat at rho = outer, so outside the disk the
/// plate continues unchanged. A plate point at distance r from the centre goes to the
/// profile's point at arc length s = L r / outer (L the profile's length): uniform spacing
/// along the profile. (An area-preserving r(s) gives tall features fewer points on their
/// walls and more slivers at their foot.)
class RadialFeature {
 public:
  RadialFeature(double cx, double cy, double outer, Profile profile) : cx_(cx), cy_(cy), outer_(outer), profile_(std::move(profile)) {}

  /// The feature's point for plate point (x, y), or false when (x, y) is outside its disk.
  bool map(double x, double y, Point3& out) const {
    const double dx = x - cx_, dy = y - cy_;
    const double r = std::hypot(dx, dy);
    if (!(r < outer_)) return false;
    double rho = 0.0, z = 0.0;
    profile_.at(profile_.length() * (r / outer_), rho, z);
    if (r > 0.0) out = {cx_ + rho * dx / r, cy_ + rho * dy / r, z};
    else out = {cx_, cy_, z};
    return true;
  }

 private:
  double cx_, cy_, outer_;
  Profile profile_;
};

/// A width x depth plate in z = 0 carrying disjoint radial features.
SurfaceFunction plate(double width, double depth, std::vector<RadialFeature> features) {
  auto shared = std::make_shared<const std::vector<RadialFeature>>(std::move(features));
  return [=](double a, double b) {
    const double x = width * a, y = depth * b;
    Point3 p{x, y, 0.0};
    for (const RadialFeature& f : *shared) {
      if (f.map(x, y, p)) break;
    }
    return p;
  };
}

/// A finger (or dome) of radius `radius`: a hemispherical tip, a vertical wall of `wall`,
/// a fillet of radius `fillet` to the plate.
Profile finger_profile(double radius, double wall, double fillet, double outer) {
  Profile p(0.0, 0.0, 0.0);
  p.arc(radius, -kPi / 2).forward(wall).arc(fillet, kPi / 2).land(outer);
  return p;
}

// ---- sampling -------------------------------------------------------------------------

std::vector<double> side(const SurfaceFunction& s, double a0, double b0, double a1, double b1) {
  std::vector<double> out;
  out.reserve(3 * kBoundaryPoints);
  for (int k = 0; k < kBoundaryPoints; ++k) {
    // t is exactly 0 and 1 at the ends, so the corners are evaluated at the same (a,b).
    const double t = k == kBoundaryPoints - 1 ? 1.0 : static_cast<double>(k) / (kBoundaryPoints - 1);
    const Point3 p = s(a0 + t * (a1 - a0), b0 + t * (b1 - b0));
    out.insert(out.end(), p.begin(), p.end());
  }
  return out;
}

double smallest_angle(const Point3& p, const Point3& q, const Point3& r) {
  const Point3* v[3] = {&p, &q, &r};
  double smallest = kPi;
  for (int i = 0; i < 3; ++i) {
    const Point3 e1 = sub(*v[(i + 1) % 3], *v[i]), e2 = sub(*v[(i + 2) % 3], *v[i]);
    const double n1 = norm(e1), n2 = norm(e2);
    if (n1 == 0.0 || n2 == 0.0) return 0.0;
    const double c = std::max(-1.0, std::min(1.0, dot(e1, e2) / (n1 * n2)));
    smallest = std::min(smallest, std::acos(c));
  }
  return smallest;
}

/// Points of the shapes built on this thread, as a multiple of their usual count (each side of
/// the jittered grid scaled by its square root); set only by fold_shape(name, density).
thread_local double shape_density = 1.0;
/// Normal noise added to the shapes built on this thread, relative to the diagonal (the larger
/// of it and the shape's own); set only by fold_shape(name, density, noise).
thread_local double shape_noise = 0.0;

FoldShape build(std::string name, std::string description, SurfaceFunction surface, std::size_t grid_a, std::size_t grid_b, double relative_noise,
                std::uint64_t seed) {
  if (shape_density != 1.0) {
    grid_a = static_cast<std::size_t>(std::lround(static_cast<double>(grid_a) * std::sqrt(shape_density)));
    grid_b = static_cast<std::size_t>(std::lround(static_cast<double>(grid_b) * std::sqrt(shape_density)));
  }
  FoldShape shape;
  shape.name = std::move(name);
  shape.description = std::move(description);
  shape.surface = surface;
  shape.grid_a = grid_a;
  shape.grid_b = grid_b;
  const std::size_t n = grid_a * grid_b;
  Random jitter(seed);
  std::vector<Point3> clean(n);
  shape.uv_true.resize(2 * n);
  Point3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (std::size_t j = 0; j < grid_b; ++j) {
    for (std::size_t i = 0; i < grid_a; ++i) {
      const std::size_t k = i + grid_a * j;
      const double a = (i + 0.5 + 0.6 * (jitter.uniform() - 0.5)) / grid_a;
      const double b = (j + 0.5 + 0.6 * (jitter.uniform() - 0.5)) / grid_b;
      shape.uv_true[2 * k] = a;
      shape.uv_true[2 * k + 1] = b;
      clean[k] = surface(a, b);
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], clean[k][c]);
        hi[c] = std::max(hi[c], clean[k][c]);
      }
    }
  }
  shape.diagonal = norm(sub(hi, lo));
  shape.noise_sigma = std::max(relative_noise, shape_noise) * shape.diagonal;
  Random noise(seed ^ 0x6a09e667f3bcc909ULL);
  shape.xyz.resize(3 * n);
  for (std::size_t k = 0; k < n; ++k) {
    Point3 p = clean[k];
    if (shape.noise_sigma > 0.0) {
      const Point3 normal = surface_normal(surface, shape.uv_true[2 * k], shape.uv_true[2 * k + 1]);
      const double g = shape.noise_sigma * noise.gaussian();
      for (int c = 0; c < 3; ++c) p[c] += g * normal[c];
    }
    for (int c = 0; c < 3; ++c) shape.xyz[3 * k + c] = p[c];
  }
  const double min_angle = kMinAngleDegrees * kPi / 180.0;
  for (std::size_t j = 0; j + 1 < grid_b; ++j) {
    for (std::size_t i = 0; i + 1 < grid_a; ++i) {
      const int p00 = static_cast<int>(i + grid_a * j), p10 = p00 + 1;
      const int p01 = static_cast<int>(p00 + grid_a), p11 = p01 + 1;
      // Of the cell's two diagonals, the one whose worse triangle has the larger smallest
      // 3D angle (the Delaunay-like choice: no needlessly thin reference triangles).
      const int along[2][3] = {{p00, p10, p11}, {p00, p11, p01}}, across[2][3] = {{p00, p10, p01}, {p10, p11, p01}};
      auto worst = [&](const int (&t)[2][3]) {
        return std::min(smallest_angle(clean[t[0][0]], clean[t[0][1]], clean[t[0][2]]), smallest_angle(clean[t[1][0]], clean[t[1][1]], clean[t[1][2]]));
      };
      const auto& tri = worst(along) >= worst(across) ? along : across;
      for (const auto& t : tri) {
        if (signed_uv_area(shape.uv_true, t[0], t[1], t[2]) <= 0.0) continue;
        if (smallest_angle(clean[t[0]], clean[t[1]], clean[t[2]]) < min_angle) continue;
        shape.triangles.insert(shape.triangles.end(), t, t + 3);
      }
    }
  }
  shape.bottom = side(surface, 0, 0, 1, 0);
  shape.right = side(surface, 1, 0, 1, 1);
  shape.top = side(surface, 0, 1, 1, 1);
  shape.left = side(surface, 0, 0, 0, 1);
  return shape;
}

std::string noise_suffix(double relative_noise) { return relative_noise > 0.0 ? "-noisy" : ""; }

}  // namespace

// ---- random numbers --------------------------------------------------------------------

std::uint64_t Random::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double Random::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

double Random::gaussian() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  const double u1 = 1.0 - uniform();  // (0, 1]
  const double u2 = uniform();
  const double r = std::sqrt(-2.0 * std::log(u1));
  spare_ = r * std::sin(2 * kPi * u2);
  has_spare_ = true;
  return r * std::cos(2 * kPi * u2);
}

// ---- shapes ---------------------------------------------------------------------------

FoldShape saddle(double relative_noise) {
  auto s = [](double a, double b) {
    const double x = 2 * a - 1, y = 2 * b - 1;
    return Point3{x, y, 0.6 * (x * x - y * y)};
  };
  return build("saddle" + noise_suffix(relative_noise), "z = 0.6 (x^2 - y^2) over [-1,1]^2", s, 64, 64, relative_noise, 0x5add1e);
}

FoldShape rippled(double relative_noise) {
  auto s = [](double a, double b) {
    return Point3{a, b, 0.2 * std::sin(kPi * a) * std::sin(kPi * b) + kRippleAmplitude * std::sin(12 * kPi * a) * std::sin(12 * kPi * b)};
  };
  return build("rippled" + noise_suffix(relative_noise), "z = 0.2 sin(pi x) sin(pi y) + 0.012 sin(12 pi x) sin(12 pi y)", s, 64, 64, relative_noise,
               0x819913d);
}

FoldShape mushroom(double relative_noise) {
  // From the apex outward: the cap's top (radius 0.3, 50 degrees), the rim (radius 0.04) turning
  // back under the cap, the underside inward, a fillet down into the stem (radius 0.1), the stem,
  // a fillet out to the plate.
  Profile p(0.0, 0.0, 0.0);
  const double top_turn = 50.0 * kPi / 180.0;
  p.arc(0.3, -top_turn).arc(0.04, -(kPi - top_turn));  // heading now -pi: inward, under the cap
  const double under = p.end_rho() - 0.1 - 0.03;       // to the fillet into the stem
  p.forward(under).arc(0.03, kPi / 2).forward(0.15).arc(0.03, kPi / 2).land(0.45);
  std::vector<RadialFeature> f;
  f.emplace_back(0.5, 0.5, 0.45, p);
  return build("mushroom" + noise_suffix(relative_noise), "plate with a mushroom: stem radius 0.1, cap radius 0.24 overhanging it by 0.14", plate(1, 1, std::move(f)),
               64, 64, relative_noise, 0x3005);
}

FoldShape tall_dome(double relative_noise) {
  std::vector<RadialFeature> f;
  f.emplace_back(0.5, 0.5, 0.45, finger_profile(0.1, 0.46, 0.04, 0.45));
  return build("tall-dome" + noise_suffix(relative_noise), "plate with a dome of radius 0.1, 0.6 tall, vertical walls", plate(1, 1, std::move(f)), 64, 64,
               relative_noise, 0xd0e);
}

FoldShape fingers(double relative_noise) {
  const double radius = 0.03, fillet = 0.015, outer = 0.22;
  std::vector<RadialFeature> f;
  // heights 0.20, 0.25, 0.29: 3.3, 4.2 and 4.8 times the width 0.06
  f.emplace_back(0.3, 0.3, outer, finger_profile(radius, 0.20 - radius - fillet, fillet, outer));
  f.emplace_back(0.9, 0.3, outer, finger_profile(radius, 0.25 - radius - fillet, fillet, outer));
  f.emplace_back(0.6, 0.72, outer, finger_profile(radius, 0.29 - radius - fillet, fillet, outer));
  return build("fingers" + noise_suffix(relative_noise), "1.2 x 1 plate with three fingers 0.06 wide, 0.20/0.25/0.29 tall", plate(1.2, 1.0, std::move(f)),
               70, 58, relative_noise, 0xf1);
}

FoldShape open_box(double relative_noise) {
  const double side = 1.0, height = 0.4;
  // Floor and walls sampled at the same density: floor share d0^2 of the square.
  const double d0 = std::sqrt(side / (4 * height) / (1 + side / (4 * height)));
  auto s = [=](double a, double b) {
    const double x = 2 * a - 1, y = 2 * b - 1;  // [-1,1]^2
    const double c = std::max(std::abs(x), std::abs(y));
    if (c <= d0) return Point3{0.5 * side * x / d0, 0.5 * side * y / d0, 0.0};
    // On a wall: the floor's edge point in this direction, raised.
    return Point3{0.5 * side * x / c, 0.5 * side * y / c, height * (c - d0) / (1 - d0)};
  };
  return build("open-box" + noise_suffix(relative_noise), "open box 1 x 1 x 0.4, the rim as boundary, 90-degree creases", s, 64, 64, relative_noise, 0xb0c5);
}

FoldShape cone(double relative_noise) {
  const double base = 0.2, height = 0.5;
  Profile p(0.0, 0.0, -std::atan2(height, base));
  p.forward(std::hypot(base, height)).turn(std::atan2(height, base)).land(0.42);
  std::vector<RadialFeature> f;
  f.emplace_back(0.5, 0.5, 0.42, p);
  return build("cone" + noise_suffix(relative_noise), "plate with a sharp cone (base radius 0.2, height 0.5), apex at (1/2,1/2)", plate(1, 1, std::move(f)),
               64, 64, relative_noise, 0xc0e);
}

FoldShape sphere_cap(double relative_noise, double degrees) {
  if (!(degrees > 0.0 && degrees < 360.0)) throw std::invalid_argument("sphere_cap: " + std::to_string(degrees) + " degrees is outside (0, 360)");
  const double polar_max = 0.5 * degrees * kPi / 180.0;
  auto s = [=](double a, double b) {
    // Concentric (Shirley-Chiu) map of [-1,1]^2 onto the unit disk: the sides go to quarter arcs.
    const double x = 2 * a - 1, y = 2 * b - 1;
    double r = 0.0, phi = 0.0;
    if (x == 0.0 && y == 0.0) return Point3{0.0, 0.0, 1.0};
    if (std::abs(x) > std::abs(y)) {
      r = x;
      phi = kPi / 4 * (y / x);
    } else {
      r = y;
      phi = kPi / 2 - kPi / 4 * (x / y);
    }
    const double dx = r * std::cos(phi), dy = r * std::sin(phi);
    const double radius = std::hypot(dx, dy), theta = polar_max * radius;
    return Point3{std::sin(theta) * dx / radius, std::sin(theta) * dy / radius, std::cos(theta)};
  };
  const int angle = static_cast<int>(std::lround(degrees));
  const std::string name = angle == 270 ? "sphere-cap" : "sphere-cap-" + std::to_string(angle);
  return build(name + noise_suffix(relative_noise), std::to_string(angle) + " degrees of the unit sphere, open at polar angle " + std::to_string(angle / 2) + " degrees", s, 64, 64,
               relative_noise, 0x5f3e);
}

std::vector<std::string> fold_shape_names() {
  return {"saddle", "saddle-noisy", "rippled", "rippled-noisy", "mushroom", "tall-dome", "fingers", "open-box", "cone", "sphere-cap", "sphere-cap-300", "sphere-cap-330"};
}

FoldShape fold_shape(const std::string& name, double density) {
  if (!(density > 0.0) || density > 1000.0) throw std::invalid_argument("fold_shape: density " + std::to_string(density) + " is outside (0, 1000]");
  struct Restore {
    ~Restore() { shape_density = 1.0; }
  } restore;
  shape_density = density;
  return fold_shape(name);
}

FoldShape fold_shape(const std::string& name, double density, double noise) {
  if (!(noise >= 0.0) || noise > 0.05) throw std::invalid_argument("fold_shape: noise " + std::to_string(noise) + " is outside [0, 0.05]");
  struct Restore {
    ~Restore() { shape_noise = 0.0; }
  } restore;
  shape_noise = noise;
  FoldShape shape = fold_shape(name, density);
  if (noise > 0.0 && shape.noise_sigma == noise * shape.diagonal) {  // the noise asked for, not the shape's own
    std::ostringstream suffix;
    suffix << "-noise" << noise;
    shape.name += suffix.str();
  }
  return shape;
}

FoldShape fold_shape(const std::string& name) {
  if (name == "saddle") return saddle();
  if (name == "saddle-noisy") return saddle(kSaddleNoise);
  if (name == "rippled") return rippled();
  if (name == "rippled-noisy") return rippled(kRippledNoise);
  if (name == "mushroom") return mushroom();
  if (name == "tall-dome") return tall_dome();
  if (name == "fingers") return fingers();
  if (name == "open-box") return open_box();
  if (name == "cone") return cone();
  if (name == "sphere-cap") return sphere_cap();
  if (name == "sphere-cap-300") return sphere_cap(0.0, 300.0);
  if (name == "sphere-cap-330") return sphere_cap(0.0, 330.0);
  throw std::invalid_argument("fold_shape: unknown shape '" + name + "'");
}

std::vector<FoldShape> all_fold_shapes() {
  std::vector<FoldShape> out;
  for (const std::string& name : fold_shape_names()) out.push_back(fold_shape(name));
  return out;
}

// ---- scoring ---------------------------------------------------------------------------

double signed_uv_area(const std::vector<double>& uv, int i, int j, int k) {
  const double ux = uv[2 * j] - uv[2 * i], uy = uv[2 * j + 1] - uv[2 * i + 1];
  const double vx = uv[2 * k] - uv[2 * i], vy = uv[2 * k + 1] - uv[2 * i + 1];
  return 0.5 * (ux * vy - uy * vx);
}

FoldCount fold_share(const std::vector<double>& uv, const std::vector<int>& triangles) {
  FoldCount count;
  count.triangles = triangles.size() / 3;
  if (count.triangles == 0) return count;
  std::vector<double> area(count.triangles), magnitude(count.triangles);
  for (std::size_t t = 0; t < count.triangles; ++t) {
    area[t] = signed_uv_area(uv, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]);
    magnitude[t] = std::abs(area[t]);
  }
  auto middle = magnitude.begin() + magnitude.size() / 2;
  std::nth_element(magnitude.begin(), middle, magnitude.end());
  const double threshold = 1e-3 * *middle;
  for (double a : area) {
    if (a > threshold) continue;
    ++count.folded;
    if (a < 0.0) ++count.inverted;
    else ++count.collapsed;  // tiny, zero or NaN
  }
  count.share = static_cast<double>(count.folded) / count.triangles;
  return count;
}

Point3 surface_normal(const SurfaceFunction& surface, double a, double b) {
  const double h = 1e-6;
  const double a0 = std::max(0.0, a - h), a1 = std::min(1.0, a + h);
  const double b0 = std::max(0.0, b - h), b1 = std::min(1.0, b + h);
  const Point3 sa = sub(surface(a1, b), surface(a0, b)), sb = sub(surface(a, b1), surface(a, b0));
  const Point3 n = cross(sa, sb);
  const double length = norm(n);
  // Relative to the tangents' lengths: below this the surface is singular here.
  if (!(length > 1e-12 * norm(sa) * norm(sb)) || length == 0.0) return {0.0, 0.0, 0.0};
  return {n[0] / length, n[1] / length, n[2] / length};
}

// ---- k-d tree --------------------------------------------------------------------------

KdTree::KdTree(const std::vector<double>& xyz) : points_(xyz), order_(xyz.size() / 3) {
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
  if (!order_.empty()) build(0, order_.size(), 0);
}

std::size_t KdTree::build(std::size_t begin, std::size_t end, int depth) {
  const std::size_t id = nodes_.size();
  nodes_.push_back({begin, end, -1, 0.0, 0, 0});
  if (end - begin <= 8 || depth > 60) return id;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t k = begin; k < end; ++k) {
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::min(lo[c], points_[3 * order_[k] + c]);
      hi[c] = std::max(hi[c], points_[3 * order_[k] + c]);
    }
  }
  int axis = 0;
  for (int c = 1; c < 3; ++c) {
    if (hi[c] - lo[c] > hi[axis] - lo[axis]) axis = c;
  }
  const std::size_t mid = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end, [&](std::size_t i, std::size_t j) {
    const double pi = points_[3 * i + axis], pj = points_[3 * j + axis];
    return pi < pj || (pi == pj && i < j);
  });
  const double split = points_[3 * order_[mid] + axis];
  const std::size_t left = build(begin, mid, depth + 1);
  const std::size_t right = build(mid, end, depth + 1);
  nodes_[id].axis = axis;
  nodes_[id].split = split;
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

void KdTree::search(std::size_t id, const double* q, std::size_t k, std::vector<std::pair<double, std::size_t>>& heap) const {
  const Node& node = nodes_[id];
  if (node.axis < 0) {
    for (std::size_t m = node.begin; m < node.end; ++m) {
      const std::size_t i = order_[m];
      const double dx = points_[3 * i] - q[0], dy = points_[3 * i + 1] - q[1], dz = points_[3 * i + 2] - q[2];
      const std::pair<double, std::size_t> item(dx * dx + dy * dy + dz * dz, i);
      if (heap.size() < k) {
        heap.push_back(item);
        std::push_heap(heap.begin(), heap.end());
      } else if (item < heap.front()) {
        std::pop_heap(heap.begin(), heap.end());
        heap.back() = item;
        std::push_heap(heap.begin(), heap.end());
      }
    }
    return;
  }
  const double d = q[node.axis] - node.split;
  const std::size_t near = d < 0 ? node.left : node.right, far = d < 0 ? node.right : node.left;
  search(near, q, k, heap);
  if (heap.size() < k || d * d <= heap.front().first) search(far, q, k, heap);
}

void KdTree::nearest(const double* q, std::size_t k, std::vector<std::size_t>& index, std::vector<double>& distance2) const {
  std::vector<std::pair<double, std::size_t>> heap;
  heap.reserve(k + 1);
  if (k > 0 && !nodes_.empty()) search(0, q, k, heap);
  std::sort_heap(heap.begin(), heap.end());
  index.resize(heap.size());
  distance2.resize(heap.size());
  for (std::size_t m = 0; m < heap.size(); ++m) {
    distance2[m] = heap[m].first;
    index[m] = heap[m].second;
  }
}

std::size_t KdTree::nearest(const double* q) const {
  std::vector<std::size_t> index;
  std::vector<double> distance2;
  nearest(q, 1, index, distance2);
  if (index.empty()) throw std::logic_error("KdTree::nearest on an empty tree");
  return index[0];
}

// ---- distance to the noise-free surface -------------------------------------------------

namespace {

std::vector<double> sample_surface(const SurfaceFunction& surface, int resolution, std::vector<double>& ab) {
  std::vector<double> xyz;
  const int n = resolution + 1;
  xyz.reserve(3 * n * n);
  ab.reserve(2 * n * n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double a = i == resolution ? 1.0 : static_cast<double>(i) / resolution;
      const double b = j == resolution ? 1.0 : static_cast<double>(j) / resolution;
      const Point3 p = surface(a, b);
      xyz.insert(xyz.end(), p.begin(), p.end());
      ab.push_back(a);
      ab.push_back(b);
    }
  }
  return xyz;
}

}  // namespace

SurfaceDistance::SurfaceDistance(SurfaceFunction surface, int resolution)
    : surface_(std::move(surface)), resolution_(resolution), tree_(sample_surface(surface_, resolution, ab_)) {}

double SurfaceDistance::operator()(const double* query) const {
  const Point3 p{query[0], query[1], query[2]};
  std::vector<std::size_t> index;
  std::vector<double> distance2;
  tree_.nearest(query, 4, index, distance2);
  double best = std::sqrt(distance2[0]);
  const double h = 1e-7;
  auto clamp = [](double t) { return std::min(1.0, std::max(0.0, t)); };
  for (std::size_t start : index) {
    double a = ab_[2 * start], b = ab_[2 * start + 1];
    Point3 s = surface_(a, b);
    double d = norm(sub(s, p));
    for (int iteration = 0; iteration < 30; ++iteration) {
      const double a0 = std::max(0.0, a - h), a1 = std::min(1.0, a + h), b0 = std::max(0.0, b - h), b1 = std::min(1.0, b + h);
      Point3 sa = sub(surface_(a1, b), surface_(a0, b)), sb = sub(surface_(a, b1), surface_(a, b0));
      for (int c = 0; c < 3; ++c) {
        sa[c] /= (a1 - a0);
        sb[c] /= (b1 - b0);
      }
      const Point3 r = sub(s, p);
      const double m00 = dot(sa, sa), m01 = dot(sa, sb), m11 = dot(sb, sb);
      const double g0 = dot(sa, r), g1 = dot(sb, r);
      const double det = m00 * m11 - m01 * m01;
      if (!(det > 1e-300) || !(std::abs(det) > 1e-14 * m00 * m11)) break;
      const double da = -(m11 * g0 - m01 * g1) / det, db = -(m00 * g1 - m01 * g0) / det;
      bool improved = false;
      for (double t = 1.0; t > 1e-4; t *= 0.5) {
        const double na = clamp(a + t * da), nb = clamp(b + t * db);
        const Point3 ns = surface_(na, nb);
        const double nd = norm(sub(ns, p));
        if (nd < d) {
          improved = d - nd > 1e-15 * (1.0 + d);
          a = na;
          b = nb;
          s = ns;
          d = nd;
          break;
        }
      }
      if (!improved) break;
    }
    best = std::min(best, d);
  }
  return best;
}

double mean_distance_to_surface(const FoldShape& shape, const std::vector<double>& xyz) {
  const SurfaceDistance distance(shape.surface);
  const std::size_t n = xyz.size() / 3;
  if (n == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += distance(&xyz[3 * i]);
  return sum / n;
}

}  // namespace dbs_folds
