// A surface's value and derivatives at one (u,v), shared by its parts (Coons patch,
// displacement) and their sum (BaseSurface).
#pragma once
#include "grid.hpp"

namespace dbs {

/// Value and first partial derivatives of a surface at one (u,v).
struct SurfacePoint {
  Vec3 p;
  Vec3 du;
  Vec3 dv;
};

/// The second partial derivatives of a surface at one (u,v) (Newton's steps for a foot).
struct SecondDerivatives {
  Vec3 uu;
  Vec3 uv;
  Vec3 vv;
};

}  // namespace dbs
