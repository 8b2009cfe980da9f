#include "fit_to_target.hpp"

#include <cmath>

#include "grid_fit.hpp"
#include "robust_loss.hpp"
#include "surface_projection.hpp"

namespace dbs {

bool fit_to_target(Patch& patch, const std::vector<Vec3>& points, std::size_t stride, const std::vector<Vec2>& feet, const EvolveSettings& settings, double& mean, double& max,
                   double& error) {
  if (!(error > settings.accuracy) || error > kFitReach * settings.accuracy) return false;
  std::vector<std::size_t> ids;
  std::vector<Vec2> st;
  for (std::size_t k = 0; k < feet.size() && k * stride < patch.subcloud.size(); ++k) {
    if (std::isnan(feet[k].x())) continue;
    ids.push_back(patch.subcloud[k * stride]);
    st.push_back(feet[k]);
  }
  const double moved_nodes = static_cast<double>(patch.grid.nu - 2) * static_cast<double>(patch.grid.nv - 2);
  if (static_cast<double>(ids.size()) < kFitPointsPerNode * moved_nodes) return false;
  Grid fitted_grid;
  if (!fit_grid_to_feet(patch.surface, patch.grid, ids, st, points, nullptr, fitted_grid)) return false;
  const BaseSurface fitted(patch.surface.boundary(), fitted_grid);
  // The sample on the fitted surface, each descent from its foot on the projected one; it
  // stops once certainly above what the fit must reach (the fit is then dropped).
  const SurfaceProjector projector(fitted, FootPrecision::Measure);
  const bool robust = settings.error_loss != LossKind::None;
  double fit_mean = 0.0, fit_max = 0.0, fit_loss = 0.0;
  std::vector<Vec2> fit_feet = feet;
  measure_distances(projector, points, patch.subcloud, stride, settings.threads, fit_mean, fit_max, settings.error_loss, settings.error_loss_scale, robust ? &fit_loss : nullptr,
                    settings.meter, &fit_feet, 1, kFitMargin * settings.accuracy);
  const double fit_error = robust ? fit_loss : fit_mean;
  if (!(fit_error <= kFitMargin * settings.accuracy)) return false;
  for (std::size_t k = 0; k < feet.size(); ++k) {
    if (std::isnan(feet[k].x()) || std::isnan(fit_feet[k].x())) continue;
    if (!(fitted.normal(fit_feet[k].x(), fit_feet[k].y()).dot(patch.surface.normal(feet[k].x(), feet[k].y())) > 0.0)) return false;
  }
  patch.surface = fitted;
  patch.grid = std::move(fitted_grid);
  mean = fit_mean;
  max = fit_max;
  error = fit_error;
  return true;
}

}  // namespace dbs
