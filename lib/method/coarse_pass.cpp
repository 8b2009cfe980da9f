#include "coarse_pass.hpp"

#include <algorithm>

namespace dbs {

namespace {

bool fit_first(const Options& options) { return options.coarse_pass == kCoarseFitFirst; }

}  // namespace

bool coarse_pass_wanted(const Options& options, const Result& plain) {
  return options.coarse_pass != 0 && !plain.patches.empty() && plain.patches.front().far_above && plain.levels > 1 && plain.turned_share > kCoarseTurnedShare;
}

double coarse_abandon_ratio(const Options& options) { return fit_first(options) ? 1.0 : kCoarseAbandonRatio; }

std::size_t unpassed_points(const Result& result) { return result.folded_points + result.undecided_points; }

bool coarse_is_better(const Options& options, const Result& plain, const Result& coarse) {
  if (coarse.turned_points >= plain.turned_points) return false;
  const double fit = std::max(plain.accuracy, plain.mean_distance);
  if (fit_first(options)) return coarse.mean_distance <= fit;
  if (unpassed_points(coarse) > unpassed_points(plain)) return false;
  if (coarse.mean_distance <= fit) return true;
  const double unpassed = static_cast<double>(unpassed_points(plain));
  const bool scrambled = unpassed > kCoarseScrambleRatio * static_cast<double>(unpassed_points(coarse)) && unpassed > kCoarseScrambledShare * static_cast<double>(plain.judged_points);
  return scrambled && coarse.mean_distance <= kCoarseFitSlack * fit;
}

}  // namespace dbs
