// A frame that turns with a patch: axes taken from the patch's corners. A box measured in it
// (and so every limit taken from its diagonal: the relative accuracy, the subcloud limits)
// is the same after any rigid motion of the input, which an axis-aligned box is not (its
// diagonal changes by up to sqrt(3) under a rotation).
#pragma once
#include <Eigen/Core>

#include "boundary.hpp"
#include "geometry.hpp"

namespace dbs {

class CornerFrameBox {
 public:
  /// Axes: e1 along corner(1,0) - corner(0,0), e2 the part of corner(0,1) - corner(0,0)
  /// orthogonal to e1, e3 = e1 x e2; the coordinate axes when the corners span no plane.
  explicit CornerFrameBox(const Boundary& boundary);

  void extend(const Vec3& p) { box_.extend(axes_ * p); }
  /// p in the frame's axes (a rotation: distances are kept).
  Vec3 local(const Vec3& p) const { return axes_ * p; }
  /// Diagonal of the box of the points added so far, in the frame.
  double diagonal() const { return box_.diagonal(); }

 private:
  Eigen::Matrix3d axes_;  // rows e1, e2, e3
  Box3 box_;
};

}  // namespace dbs
