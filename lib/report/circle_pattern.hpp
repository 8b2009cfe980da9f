// Method (c) of the paper's section 7: a pattern of black disks on white laid out in the
// parameter domain. Where the parameterization is good the disks look round on the surface;
// where it distorts they become ellipses of varying size.
#pragma once
#include "rgb_image.hpp"

namespace dbs {

class CirclePattern {
 public:
  /// `scale_u`, `scale_v` (> 0): the domain scaling that makes (u,v) lengths comparable to
  /// 3D lengths (DistortionSummary's, per axis), so disks of the pattern are round on a
  /// surface parameterized without distortion. `across`: disks along the longer scaled side.
  CirclePattern(double scale_u, double scale_v, int across = 16);

  /// True when (u,v) lies inside a disk: disks of radius 0.3 periods centred in the cells of
  /// a square grid of the scaled domain, cell (0,0) starting at (u,v) = (0,0).
  bool black(double u, double v) const;
  /// Centre (u,v) of disk (i, j).
  void disk_centre(int i, int j, double& out_u, double& out_v) const;
  /// The pattern over [0,1]^2 as a texture image: `long_side` pixels along the longer scaled
  /// side, the other side in proportion (at least 1), so a texture mapper stretching it over
  /// [0,1]^2 keeps the disks round. Row 0 is v = 1 (images run top down, texture v up).
  RgbImage texture(int long_side) const;

 private:
  double scale_u_, scale_v_, period_;
};

}  // namespace dbs
