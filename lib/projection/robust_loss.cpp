#include "robust_loss.hpp"

#include <cmath>

namespace dbs {

double robust_rho(LossKind kind, double scale, double squared) {
  const double a2 = scale * scale;
  switch (kind) {
    case LossKind::Huber: return squared <= a2 ? squared : 2.0 * scale * std::sqrt(squared) - a2;
    case LossKind::Cauchy: return a2 * std::log1p(squared / a2);
    case LossKind::SoftL1: return 2.0 * a2 * (std::sqrt(1.0 + squared / a2) - 1.0);
    case LossKind::None: break;
  }
  return squared;
}

double robust_distance(LossKind kind, double scale, double distance) {
  if (kind == LossKind::None) return distance;
  return std::sqrt(robust_rho(kind, scale, distance * distance));
}

}  // namespace dbs
