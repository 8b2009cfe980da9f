#include "corner_frame.hpp"

#include <Eigen/Geometry>

namespace dbs {

CornerFrameBox::CornerFrameBox(const Boundary& boundary) : axes_(Eigen::Matrix3d::Identity()) {
  const Vec3 origin = boundary.corner(0, 0);
  const Vec3 along_u = boundary.corner(1, 0) - origin, along_v = boundary.corner(0, 1) - origin;
  const double scale = along_u.norm() + along_v.norm();
  const Vec3 e1 = along_u.normalized();
  const Vec3 in_plane = along_v - along_v.dot(e1) * e1;
  // Relative test: corners that (nearly) line up give no plane to turn with.
  if (!(along_u.norm() > 1e-12 * scale) || !(in_plane.norm() > 1e-9 * scale)) return;
  const Vec3 e2 = in_plane.normalized();
  axes_.row(0) = e1.transpose();
  axes_.row(1) = e2.transpose();
  axes_.row(2) = e1.cross(e2).transpose();
}

}  // namespace dbs
