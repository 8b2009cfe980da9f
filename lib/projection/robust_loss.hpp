// Robust losses of the Ceres refinement (issue 11), written out so that code without Ceres
// (the stopping rule's error measure) uses the very functions the refinement minimizes.
// rho acts on a squared distance s with a scale a (a distance): rho(s) = s for s << a^2 and
// grows more slowly beyond, as in Ceres (HuberLoss, CauchyLoss, SoftLOneLoss):
//   Huber    s <= a^2: s,  else 2 a sqrt(s) - a^2
//   Cauchy   a^2 log(1 + s / a^2)
//   soft-L1  2 a^2 (sqrt(1 + s / a^2) - 1)
#pragma once

namespace dbs {

/// Values equal the DBS_LOSS_* numbers of the C API.
enum class LossKind { None = 0, Huber = 1, Cauchy = 2, SoftL1 = 3 };

/// rho(s) of the header for a squared distance s >= 0 and a scale a > 0; s itself for
/// LossKind::None.
double robust_rho(LossKind kind, double scale, double squared);

/// The distance a point at distance d >= 0 counts for under the loss: sqrt(rho(d^2)), which
/// is d itself up to about the scale (Huber: exactly d for d <= a) and grows like sqrt(2 a d)
/// (Huber, soft-L1) or a sqrt(2 log(d / a)) (Cauchy) beyond it. d for LossKind::None.
double robust_distance(LossKind kind, double scale, double distance);

}  // namespace dbs
