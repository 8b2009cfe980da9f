// The four-sided boundary of a patch, with the conventions of FORMATS.md:
// bottom S(u,0) and top S(u,1) run in increasing u; left S(0,v) and right S(1,v) in
// increasing v; corners shared.
#pragma once
#include <array>

#include "polyline.hpp"

namespace dbs {

enum class Side { Bottom = 0, Right = 1, Top = 2, Left = 3 };

const char* side_name(Side side);

class Boundary {
 public:
  /// Relative corner tolerance: corners may miss by this fraction of the boundary's
  /// bounding-box diagonal and are then made to coincide exactly (their mean).
  static constexpr double kCornerTolerance = 1e-6;

  /// The largest relative corner tolerance accepted (CornerTolerance): a tenth of the size.
  static constexpr double kMaxCornerTolerance = 0.1;

  /// How far corners may miss each other: `value` in the boundary's units, or times its
  /// bounding-box diagonal when `relative`.
  struct CornerTolerance {
    double value;
    bool relative;
  };

  Boundary() = default;
  /// Validates: >= 2 finite points per side (Error(InvalidArgument)/NonFinite naming the
  /// side and point), corners within `tolerance` (Degenerate, naming the corner and the
  /// miss, and the fix where one is evident: a side running backwards, left and right or
  /// bottom and top swapped), no side shorter than the tolerance, non-zero spanned area
  /// (Degenerate). Corners within it are made to coincide exactly (their mean); max_snap()
  /// says how far the farthest moved. A tolerance that is negative, not finite or above
  /// kMaxCornerTolerance of the size is Error(OutOfRange).
  Boundary(std::vector<Vec3> bottom, std::vector<Vec3> right, std::vector<Vec3> top, std::vector<Vec3> left, CornerTolerance tolerance);
  /// The same with the default tolerance, kCornerTolerance of the size.
  Boundary(std::vector<Vec3> bottom, std::vector<Vec3> right, std::vector<Vec3> top, std::vector<Vec3> left)
      : Boundary(std::move(bottom), std::move(right), std::move(top), std::move(left), CornerTolerance{kCornerTolerance, true}) {}
  /// Already-consistent sides (e.g. halves of a parent's sides): corners must coincide
  /// exactly; checked, not repaired.
  Boundary(Polyline bottom, Polyline right, Polyline top, Polyline left);

  const Polyline& side(Side s) const { return sides_[static_cast<int>(s)]; }
  const Polyline& bottom() const { return side(Side::Bottom); }
  const Polyline& right() const { return side(Side::Right); }
  const Polyline& top() const { return side(Side::Top); }
  const Polyline& left() const { return side(Side::Left); }
  /// Corner S(u,v) for u,v in {0,1}.
  Vec3 corner(int u, int v) const;
  /// Bounding box of all side points.
  Box3 bounds() const;
  /// Diagonal of bounds(): the boundary's size.
  double size() const { return bounds().diagonal(); }
  /// How far the constructor moved the farthest corner end to make the corners coincide
  /// (half the largest miss; 0 for sides that met exactly, or made from polylines).
  double max_snap() const { return max_snap_; }

 private:
  std::array<Polyline, 4> sides_;
  double max_snap_ = 0.0;
};

}  // namespace dbs
