// The rules of the coarse pass (Options::coarse_pass, DBS_OPT_COARSE_PASS): when the method
// runs a second time from a coarse root, when that pass is given up, and which result is kept.
//
// A root grown to its largest grid pleats over a steep wall or an overhang, and its children
// inherit the pleats. Where the plain pass pleated, the coarse pass stops the root's grid once
// its error is far above the target (kCoarseStop) and subdivides from there, so the children
// start from a smoother surface and climb the feature themselves. Two ways to choose:
// - fit first (kCoarseFitFirst): the coarse result is kept only when it fits as well, and the
//   pass is given up as soon as its first level fits worse than the plain pass's;
// - folds first (kCoarseFoldsFirst, the default): it may fit worse where the plain result is
//   scrambled. On an overhang like the mushroom's cap, the coarse surfaces leave the cap
//   unreached, to the repair, and fit worse; the plain surfaces reach it by pleating and scatter
//   its points in (u,v), which the fold measure cannot pass (1,314 of 19,600 points against 47,
//   368 folded reference triangles against 56). The level-1 fit does not tell those apart
//   (1.0-1.7 times worse for both kept and dropped coarse results), so the pass is given up only
//   when that level fits far worse (a coarse root that misses a steep wall: 4.5-5.5 times).
#pragma once
#include <cstddef>

#include "options.hpp"
#include "result.hpp"

namespace dbs {

/// Options::coarse_pass values (0: the plain pass only).
constexpr int kCoarseFoldsFirst = 1;
constexpr int kCoarseFitFirst = 2;

/// The coarse root stops growing its grid once its error is above this many times the target ...
constexpr double kCoarseStop = 20.0;
/// ... and the pass runs when the plain pass's root got that far above and more than this share
/// of the points judged lies on turned sheets.
constexpr double kCoarseTurnedShare = 0.03;
/// Folds first, the pass is given up after its first level when that level's error (its
/// patches' mean, weighted by their points) is above this many times the plain pass's; fit
/// first, when it is above the plain pass's.
constexpr double kCoarseAbandonRatio = 2.0;
/// A result is scrambled against another when it has more than this many times its points the
/// fold measure cannot pass (unpassed_points), and more than kCoarseScrambledShare of the points
/// judged (not a few points at a border) ...
constexpr double kCoarseScrambleRatio = 2.0;
constexpr double kCoarseScrambledShare = 0.005;
/// ... and folds first, the coarse result may then fit worse, up to this many times the larger
/// of the plain pass's mean distance and the target.
constexpr double kCoarseFitSlack = 4.0;

/// Whether the coarse pass runs after `plain`: the option on, the plain root far above its
/// target at one of its grids (Patch::far_above) and subdivided, and more than
/// kCoarseTurnedShare of the judged points on turned sheets.
bool coarse_pass_wanted(const Options& options, const Result& plain);

/// The ratio of the coarse pass's first-level error to the plain pass's above which it is given up.
double coarse_abandon_ratio(const Options& options);

/// The points of `result` the fold measure could not pass: folded or undecided.
std::size_t unpassed_points(const Result& result);

/// Whether `coarse` is kept instead of `plain`. Always: fewer points on turned sheets. Fit
/// first: a mean distance at most the larger of the plain's and the target. Folds first: no
/// more unpassed points than the plain result either, and that fit, or, where the plain result
/// is scrambled against the coarse one, kCoarseFitSlack times it.
bool coarse_is_better(const Options& options, const Result& plain, const Result& coarse);

}  // namespace dbs
