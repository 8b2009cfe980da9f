// Checks of the inputs against each other, the mistakes a run would otherwise finish with
// exit 0: a boundary in other units than the cloud (metres around millimetres), a cloud that
// covers only part of the boundary, a scan larger than its boundary, a boundary far from the
// cloud. Each is a number (a statistic of the result) and, beyond its threshold, a warning.
// The thresholds leave every hard shape of the fold-free work alone (overhangs, a 270-degree
// cap whose rim is small against the cloud, deep protrusions, creases): those are the tests'
// controls.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "boundary.hpp"
#include "cloud_index.hpp"
#include "result.hpp"

namespace dbs {

namespace input {
constexpr int kSidesSamples = 64;           ///< boundary samples per side for the gap
constexpr double kGapQuantile = 0.9;        ///< the gap: this quantile of the samples' distances to the cloud
constexpr double kMaxGap = 10.0;            ///< beyond this many point spacings: does the boundary belong to the cloud?
constexpr double kMaxSideGap = 4.0;         ///< beyond this many: sides cutting across the surface (the controls stay below 1.6)
constexpr std::size_t kSpacingNeighbour = 6;    ///< a point's local spacing: the distance to its 6th nearest point
constexpr double kMaxSpacingRatio = 4.0;        ///< a local spacing counts as at most this x the typical one (and at least its inverse): a fringe of stray points near the boundary does not hide its gap
constexpr double kMaxScaleRatio = 10.0;     ///< warn when the cloud's size / the boundary's is beyond this or below its inverse
constexpr std::size_t kPointsPerCell = 16;  ///< coverage grid: about this many points per cell on average
constexpr double kMinCoverage = 0.75;       ///< warn below this share of [0,1]^2 covered
constexpr double kMaxClampedShare = 0.01;   ///< warn when more than this share of the points is clamped ...
constexpr std::size_t kMinClamped = 10;     ///< ... and at least this many
}  // namespace input

/// The figures; see the DBS_STAT_* of the same names.
struct InputChecks {
  /// kGapQuantile of the distances of boundary samples to their nearest point, each in units
  /// of the local spacing there, scaled to spacings h (the local spacing over its median over
  /// all samples' nearest points, times h): a sparse part of a scan with a varying density
  /// does not count as a gap.
  double boundary_gap = 0.0;
  double scale_ratio = 1.0;    ///< the cloud's bounding-box diagonal / the boundary's
  double coverage = 1.0;       ///< share of a g x g grid over [0,1]^2 holding some point's (u,v)
  std::size_t clamped = 0;     ///< points whose (u,v) lies on the domain's edge and whose distance exceeds h
};

/// The boundary against the cloud, before the run: gap (h > 0 the cloud's spacing) and scale ratio.
void check_boundary_against_cloud(const CloudIndex& index, const Boundary& boundary, double h, InputChecks& checks);

/// The parameters, after A2 gave every point of the body its foot (before the repair moves
/// any): coverage and clamped points, over the body (result.outside_body left out); marks
/// the clamped points in result.clamped.
void check_parameters(Result& result, InputChecks& checks);

/// One message per figure beyond its threshold, with the numbers and the likely mistake.
std::vector<std::string> boundary_warnings(const InputChecks& checks);
/// `cropped`: the clamped points are cropped (Options::crop), so they are no mistake to warn of.
std::vector<std::string> parameter_warnings(const InputChecks& checks, std::size_t points, bool cropped);

}  // namespace dbs
