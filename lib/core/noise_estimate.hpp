// The noise level of a cloud: the standard deviation sigma of the points' offsets along the
// surface normal, estimated from robust local quadric fits (issue 10, "a noise floor").
//
// On at most kNoiseMaxSamples points evenly strided over the index order, each point gets a
// least-squares quadric height function z = a x^2 + b xy + c y^2 + d x + e y + f fitted to k
// neighbours (the point itself and its duplicates excluded; of its 2k nearest, the k nearest
// to its normal line) in their PCA frame; the point's leave-one-out residual from it, divided
// by sqrt(1 + leverage), is an N(0, sigma^2) draw for Gaussian noise. Fits whose own residual
// exceeds kNoiseFitGate times the median (creases, details the quadric cannot follow) are
// dropped, and sigma is the kNoiseQuantile quantile of the remaining |residuals| over the
// quantile of |N(0,1)| there.
//
// One residual per sample, the centre's, left out of its own fit: the neighbours' in-sample
// residuals would be shrunk by their leverages, correlated with each other, and come mostly
// from the rim of the neighbourhood, where a crease or the quadric's misfit shows first.
//
// Where the noise is thick against the neighbourhood (median ratio of RMS normal to RMS
// tangent extent above kNoiseThickness), its points form a blob, not a sheet, and the fits
// cannot see the noise. The neighbourhood then grows in steps of twice the area, k = 24 and
// 48 on the cloud, then on sub-clouds of every 4th, 16th, ... point (kNoiseLevelFactor), each
// of at least kNoiseMinLevelPoints points; the first flat step gives the estimate (the
// coarsest allowed one when none is).
//
// Deterministic and bit-identical for any thread count (each sample is computed alone);
// scales with the cloud (a cloud x1000 gives sigma x1000 up to rounding); invariant to rigid
// motions up to rounding. Detail finer than the neighbourhood (see NoiseEstimate::radius)
// cannot be told from noise and counts as noise.
#pragma once
#include <cstddef>

#include "cloud_index.hpp"
#include "work_meter.hpp"

namespace dbs {

/// Sample size: at most this many points, evenly strided over the index order.
constexpr std::size_t kNoiseMaxSamples = 4000;
/// Sample size of the search for flat neighbourhoods (which looks at their thickness only).
constexpr std::size_t kNoiseSearchSamples = 500;
/// Neighbours of a sample point its local fit uses at first (the point itself excluded).
constexpr std::size_t kNoiseNeighbours = 24;
/// Fewest distinct neighbours a fit is made from (6 parameters and some redundancy).
constexpr std::size_t kNoiseMinFitPoints = 12;
/// Neighbourhoods count as flat (the noise is measurable in them) while the median ratio of
/// their RMS extent along the normal to their RMS tangent radius is at most this.
constexpr double kNoiseThickness = 0.35;
/// Each coarser sub-cloud keeps every kNoiseLevelFactor-th point of the cloud...
constexpr std::size_t kNoiseLevelFactor = 4;
/// ...and at least this many points.
constexpr std::size_t kNoiseMinLevelPoints = 500;
/// A fit whose own residual deviation exceeds this multiple of the median is not used.
constexpr double kNoiseFitGate = 2.0;
/// The quantile of the |residuals| taken (low: insensitive to what the fits miss).
constexpr double kNoiseQuantile = 0.25;
/// Divides the estimate: its measured ratio to the true sigma on noisy planes (see the
/// definition).
extern const double kNoiseCalibration;

struct NoiseEstimate {
  /// Estimated noise deviation along the normal, in cloud units; 0 on a cloud with fewer
  /// than kNoiseNeighbours + 1 points, or where no neighbourhood carries a quadric fit.
  double sigma = 0.0;
  /// Sample points whose residual entered the quantile (0 when sigma could not be estimated).
  std::size_t samples = 0;
  /// cloud_spacing(index): the mean nearest-neighbour distance (0 for fewer than 2 points).
  double spacing = 0.0;
  /// Median RMS tangent radius of the fitted neighbourhoods: the scale sigma was measured at.
  double radius = 0.0;
  /// Neighbours per fit, and the stride of the sub-cloud they came from (1: the whole
  /// cloud); 0 and 0 when sigma could not be estimated.
  std::size_t neighbours = 0;
  std::size_t stride = 0;
};

/// The noise estimate of the indexed points. threads as Options::threads (0 = hardware
/// concurrency). Throws Error(Degenerate) like cloud_spacing() on a cloud of two or more
/// points that are all the same point.
NoiseEstimate estimate_noise(const CloudIndex& index, int threads, WorkMeter* meter = nullptr);

}  // namespace dbs
