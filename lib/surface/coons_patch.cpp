#include "coons_patch.hpp"

namespace dbs {

namespace {

// The patch point from the sides' points at u and v and the corners c[v][u]. On a side it
// is that side's point as such: bit for bit the polyline's own at(), which sibling
// patches sharing the side also return.
Vec3 patch_point(double u, double v, const Vec3& bottom, const Vec3& top, const Vec3& left, const Vec3& right, const Vec3 (&c)[2][2]) {
  if (v == 0.0) return bottom;
  if (v == 1.0) return top;
  if (u == 0.0) return left;
  if (u == 1.0) return right;
  const Vec3 corners = (1 - u) * ((1 - v) * c[0][0] + v * c[1][0]) + u * ((1 - v) * c[0][1] + v * c[1][1]);
  return (1 - v) * bottom + v * top + (1 - u) * left + u * right - corners;
}

}  // namespace

CoonsPatch::CoonsPatch(Boundary boundary)
    : boundary_(std::move(boundary)),
      c00_(boundary_.corner(0, 0)),
      c10_(boundary_.corner(1, 0)),
      c01_(boundary_.corner(0, 1)),
      c11_(boundary_.corner(1, 1)) {}

Vec3 CoonsPatch::eval(double u, double v) const {
  const Vec3 c[2][2] = {{c00_, c10_}, {c01_, c11_}};
  return patch_point(u, v, boundary_.bottom().at(u), boundary_.top().at(u), boundary_.left().at(v), boundary_.right().at(v), c);
}

Grid CoonsPatch::sample(int nu, int nv) const {
  Grid g(nu, nv);
  std::vector<Vec3> bottom(static_cast<std::size_t>(nu)), top(static_cast<std::size_t>(nu)), left(static_cast<std::size_t>(nv)), right(static_cast<std::size_t>(nv));
  for (int i = 0; i < nu; ++i) {
    bottom[static_cast<std::size_t>(i)] = boundary_.bottom().at(g.u(i));
    top[static_cast<std::size_t>(i)] = boundary_.top().at(g.u(i));
  }
  for (int j = 0; j < nv; ++j) {
    left[static_cast<std::size_t>(j)] = boundary_.left().at(g.v(j));
    right[static_cast<std::size_t>(j)] = boundary_.right().at(g.v(j));
  }
  const Vec3 c[2][2] = {{c00_, c10_}, {c01_, c11_}};
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      g(i, j) = patch_point(g.u(i), g.v(j), bottom[static_cast<std::size_t>(i)], top[static_cast<std::size_t>(i)], left[static_cast<std::size_t>(j)], right[static_cast<std::size_t>(j)], c);
  return g;
}

SecondDerivatives CoonsPatch::second_derivatives(double u, double v) const {
  Vec3 d_bottom, d_top, d_left, d_right;
  boundary_.bottom().at(u, d_bottom);
  boundary_.top().at(u, d_top);
  boundary_.left().at(v, d_left);
  boundary_.right().at(v, d_right);
  return {Vec3::Zero(), (d_top - d_bottom) + (d_right - d_left) - ((c11_ - c01_) - (c10_ - c00_)), Vec3::Zero()};
}

SurfacePoint CoonsPatch::eval_derivs(double u, double v) const {
  Vec3 d_bottom, d_top, d_left, d_right;
  const Vec3 bottom = boundary_.bottom().at(u, d_bottom), top = boundary_.top().at(u, d_top);
  const Vec3 left = boundary_.left().at(v, d_left), right = boundary_.right().at(v, d_right);
  const Vec3 c[2][2] = {{c00_, c10_}, {c01_, c11_}};
  SurfacePoint sp;
  sp.p = patch_point(u, v, bottom, top, left, right, c);
  sp.du = (1 - v) * d_bottom + v * d_top + (right - left) - ((1 - v) * (c10_ - c00_) + v * (c11_ - c01_));
  sp.dv = (1 - u) * d_left + u * d_right + (top - bottom) - ((1 - u) * (c01_ - c00_) + u * (c11_ - c10_));
  return sp;
}

}  // namespace dbs
