#include "noise_estimate.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "parallel.hpp"

namespace dbs {

// Calibrated by simulation: over 40 planes of 20000 points with Gaussian noise along the
// normal of 0.05 to 1 mean spacings, the mean of estimate / sigma with this constant at 1 was
// 0.995 +- 0.004 (0.989 at 1 spacing), indistinguishable from 1: dividing each leave-one-out
// residual by sqrt(1 + leverage) already corrects for the 6 parameters the fit absorbs. (The
// raw leave-one-out residual of the centre, without that division, measured 1.095: 24 points,
// typical leverage 0.2.) tests/core/test_noise_estimate.cpp repeats it on 8 planes.
const double kNoiseCalibration = 1.0;

namespace {

using Matrix6 = Eigen::Matrix<double, Eigen::Dynamic, 6>;
using Vector6 = Eigen::Matrix<double, 6, 1>;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// What one local fit gives.
struct Sample {
  double residual = kNaN;   // the centre's standardized leave-one-out residual (cloud units)
  double fit_sigma = kNaN;  // the fit's own residual deviation sqrt(RSS / (m - 6)) (cloud units)
  double radius = kNaN;     // RMS tangent radius of the fitted neighbourhood (cloud units)
  double thickness = kNaN;  // RMS normal over RMS tangent radius of the neighbourhood
};

Vector6 quadric_row(double x, double y) {
  Vector6 row;
  row << x * x, x * y, y * y, x, y, 1.0;
  return row;
}

/// Centroid and principal axes (eigenvalues ascending: column 0 is the normal) of points[idx[0..m)].
bool principal_frame(const std::vector<Vec3>& points, const std::vector<std::size_t>& idx, std::size_t m, Vec3& centroid, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& eig) {
  centroid = Vec3::Zero();
  for (std::size_t i = 0; i < m; ++i) centroid += points[idx[i]];
  centroid /= static_cast<double>(m);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 d = points[idx[i]] - centroid;
    cov.noalias() += d * d.transpose();
  }
  eig.compute(cov);
  return eig.info() == Eigen::Success;
}

/// The local fit around the point q: the quadric height function z = a x^2 + b xy + c y^2 +
/// d x + e y + f, least squares over k neighbours of q in `index` (q itself and its duplicates
/// excluded) in their PCA frame, and q's offset from it. Neither the frame nor the fit sees
/// q (leave one out), so its noise e_q is independent of the prediction, whose error has
/// variance sigma^2 h for the leverage h = a_q^T (A^T A)^-1 a_q: the residual divided by
/// sqrt(1 + h) has deviation sigma exactly for Gaussian noise along the local z (this is the
/// correction for the fit's 6 degrees of freedom, exact per point instead of a constant). The
/// vertical offset is turned into one along the quadric's normal (divided by
/// sqrt(1 + |grad f|^2) at q). The k neighbours are, of the 2k nearest to q, the k nearest to
/// the line through q along the normal of those 2k: a ball around a noisy centre holds more
/// of the neighbours lying on the centre's side of the surface (it reaches further along the
/// normal there), which pulls the fit towards the centre; a cylinder does not. NaN when the
/// neighbourhood cannot carry the fit.
Sample fit_sample(const CloudIndex& index, const Vec3& q, std::size_t k, std::vector<std::size_t>& idx, std::vector<double>& d2,
                  std::vector<std::pair<double, std::size_t>>& by_tangent) {
  Sample out;
  const std::vector<Vec3>& points = index.points();
  index.knn(q, 2 * k + 1, idx, d2);
  // Neighbours distinct from the centre (the centre itself and its duplicates sit at d2 == 0).
  std::size_t m = 0;
  for (std::size_t i = 0; i < idx.size() && m < 2 * k; ++i)
    if (d2[i] > 0.0) idx[m++] = idx[i];
  if (m < kNoiseMinFitPoints) return out;

  Vec3 centroid;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  if (m > k) {
    if (!principal_frame(points, idx, m, centroid, eig)) return out;
    const Vec3 normal = eig.eigenvectors().col(0);
    by_tangent.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
      const Vec3 d = points[idx[i]] - q;
      const double along = d.dot(normal);
      by_tangent[i] = {d.squaredNorm() - along * along, idx[i]};
    }
    std::partial_sort(by_tangent.begin(), by_tangent.begin() + static_cast<std::ptrdiff_t>(k), by_tangent.end());
    for (std::size_t i = 0; i < k; ++i) idx[i] = by_tangent[i].second;
    m = k;
  }
  if (!principal_frame(points, idx, m, centroid, eig)) return out;
  // Local coordinates divided by the RMS tangent radius keep the design matrix O(1) in any
  // units; lengths are scaled back at the end, so the estimate scales with the cloud.
  const double scale = std::sqrt((eig.eigenvalues()(1) + eig.eigenvalues()(2)) / static_cast<double>(m));
  if (!(scale > 0.0) || !std::isfinite(scale)) return out;
  const Eigen::Matrix3d frame = eig.eigenvectors().transpose() / scale;  // rows: normal, t1, t2

  Matrix6 a(static_cast<Eigen::Index>(m), 6);
  Eigen::VectorXd z(static_cast<Eigen::Index>(m));
  for (std::size_t i = 0; i < m; ++i) {
    const Vec3 l = frame * (points[idx[i]] - centroid);
    a.row(static_cast<Eigen::Index>(i)) = quadric_row(l(1), l(2)).transpose();
    z(static_cast<Eigen::Index>(i)) = l(0);
  }
  Eigen::ColPivHouseholderQR<Matrix6> qr;
  qr.setThreshold(1e-9);  // columns are O(1): a smaller pivot means collinear or conic-aligned neighbours
  qr.compute(a);
  if (qr.rank() < 6) return out;
  const Vector6 coef = qr.solve(z);
  const Vec3 lq = frame * (q - centroid);
  const Vector6 aq = quadric_row(lq(1), lq(2));
  // h = |R^-T P^T a_q|^2 for A P = Q R.
  const Vector6 w = qr.colsPermutation().transpose() * aq;
  const double leverage = qr.matrixR().topLeftCorner<6, 6>().triangularView<Eigen::Upper>().transpose().solve(w).squaredNorm();
  const double fx = 2.0 * coef(0) * lq(1) + coef(1) * lq(2) + coef(3);
  const double fy = coef(1) * lq(1) + 2.0 * coef(2) * lq(2) + coef(4);
  const double slope = std::sqrt(1.0 + fx * fx + fy * fy);
  out.residual = scale * (lq(0) - aq.dot(coef)) / (slope * std::sqrt(1.0 + leverage));
  out.fit_sigma = scale * (a * coef - z).norm() / (slope * std::sqrt(static_cast<double>(m - 6)));
  out.radius = scale;
  out.thickness = std::sqrt(std::max(eig.eigenvalues()(0), 0.0) / static_cast<double>(m)) / scale;
  return out;
}

/// The q-quantile (linear between order statistics) of a non-empty `values`, reordered in place.
double quantile(std::vector<double>& values, double q) {
  const double pos = q * static_cast<double>(values.size() - 1);
  const std::size_t lo = static_cast<std::size_t>(pos);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(lo), values.end());
  const double v_lo = values[lo];
  if (lo + 1 >= values.size()) return v_lo;
  const double v_hi = *std::min_element(values.begin() + static_cast<std::ptrdiff_t>(lo) + 1, values.end());
  return v_lo + (pos - static_cast<double>(lo)) * (v_hi - v_lo);
}

/// The q-quantile of |N(0,1)|, Phi^-1((1 + q) / 2): bisection on erf, exact to rounding.
double half_normal_quantile(double q) {
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::erf(mid / std::sqrt(2.0)) < q ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Pass {
  double sigma = 0.0;
  std::size_t samples = 0;
  double radius = 0.0;     // median RMS tangent radius of the neighbourhoods
  double thickness = 1.0;  // median RMS normal over RMS tangent radius of the neighbourhoods
};

/// One estimate: the fits around `max_samples` points strided over `cloud`, with k neighbours
/// from `level` (the cloud itself or a strided sub-cloud of it).
Pass estimate_pass(const CloudIndex& cloud, const CloudIndex& level, std::size_t k, std::size_t max_samples, int threads, WorkMeter* meter) {
  const std::size_t n = cloud.size();
  const std::size_t count = std::min(n, max_samples);
  const std::vector<Vec3>& points = cloud.points();
  std::vector<Sample> samples(count);
  metered_for(meter, count, threads, [&](std::size_t s) {
    // Scratch only: each sample's result depends on its own centre alone.
    thread_local std::vector<std::size_t> idx;
    thread_local std::vector<double> d2;
    thread_local std::vector<std::pair<double, std::size_t>> by_tangent;
    samples[s] = fit_sample(level, points[cloud.point_index(s * n / count)], k, idx, d2, by_tangent);
    count_work(meter);
  });
  std::vector<double> fit_sigma, radius, thickness, residual;
  for (const Sample& s : samples)
    if (std::isfinite(s.residual)) {
      fit_sigma.push_back(s.fit_sigma);
      radius.push_back(s.radius);
      thickness.push_back(s.thickness);
    }
  Pass pass;
  if (fit_sigma.empty()) return pass;
  pass.radius = quantile(radius, 0.5);
  pass.thickness = quantile(thickness, 0.5);
  // Fits across a crease (or any detail the quadric cannot follow) have a large residual of
  // their own; for Gaussian noise the centre's residual is independent of the fit's, so
  // dropping them does not bias the rest.
  const double gate = kNoiseFitGate * quantile(fit_sigma, 0.5);
  for (const Sample& s : samples)
    if (std::isfinite(s.residual) && s.fit_sigma <= gate) residual.push_back(std::abs(s.residual));
  pass.samples = residual.size();
  if (residual.empty()) return pass;
  pass.sigma = quantile(residual, kNoiseQuantile) / (half_normal_quantile(kNoiseQuantile) * kNoiseCalibration);
  return pass;
}

}  // namespace

NoiseEstimate estimate_noise(const CloudIndex& index, int threads, WorkMeter* meter) {
  NoiseEstimate out;
  const std::size_t n = index.size();
  threads = resolve_threads(threads);
  if (n >= 2) out.spacing = cloud_spacing(index, 20000, threads);
  if (n < kNoiseNeighbours + 1) return out;
  // Where the noise is thick against the neighbourhood, its points form a blob rather than a
  // sheet: the PCA frame turns random and the centre sits in the middle of its neighbours
  // whatever its noise, so the residuals shrink. Steps of twice the neighbourhood's area
  // (k = 24, 48 on the cloud, then on sub-clouds of every 4th, 16th, ... point) are tried from
  // the finest until the neighbourhoods are flat (median thickness at most kNoiseThickness),
  // and the first flat one gives the estimate (the finest: detail finer than the
  // neighbourhood counts as noise). A sub-cloud keeps at least kNoiseMinLevelPoints points;
  // when none is flat, the coarsest step is used. The search looks at the thickness only, on
  // a smaller sample; the estimate is then made on the full sample.
  std::unique_ptr<CloudIndex> previous, current;  // the last two sub-clouds built
  const CloudIndex* level = &index;
  std::size_t stride = 1;
  const CloudIndex* best_level = nullptr;
  std::size_t best_k = 0, best_stride = 0;
  for (;;) {
    bool flat = false, stalled = false;
    for (std::size_t k = kNoiseNeighbours; k <= 2 * kNoiseNeighbours && !flat; k *= 2) {
      if (k + 1 > level->size()) break;
      const Pass search = estimate_pass(index, *level, k, kNoiseSearchSamples, threads, meter);
      if (search.samples == 0) {  // no neighbourhood carries a fit: keep the last step that did
        stalled = true;
        break;
      }
      best_level = level;
      best_k = k;
      best_stride = stride;
      flat = search.thickness <= kNoiseThickness;
    }
    if (flat || stalled || best_level == nullptr || n / (stride * kNoiseLevelFactor) < kNoiseMinLevelPoints) break;
    stride *= kNoiseLevelFactor;
    std::vector<std::size_t> subset;
    subset.reserve(n / stride + 1);
    for (std::size_t m = 0; m < n; m += stride) subset.push_back(index.point_index(m));
    previous = std::move(current);
    current = std::make_unique<CloudIndex>(index.points(), std::move(subset));
    level = current.get();
  }
  if (best_level == nullptr) return out;
  const Pass pass = estimate_pass(index, *best_level, best_k, kNoiseMaxSamples, threads, meter);
  if (pass.samples == 0) return out;
  out.sigma = pass.sigma;
  out.samples = pass.samples;
  out.radius = pass.radius;
  out.neighbours = best_k;
  out.stride = best_stride;
  return out;
}

}  // namespace dbs
