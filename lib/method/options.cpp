#include "options.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <system_error>

#include "curve_refinement.hpp"
#include "error.hpp"
#include "number_text.hpp"

namespace dbs {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::max();

/// One row per OptionId, in id order. `min_exclusive` marks the one open lower end,
/// (0, 10] of subcloud_near: a zero "near" limit would give every child an empty subcloud.
struct OptionSpec {
  OptionInfo info;
  bool min_exclusive;
};

const OptionSpec kSpecs[] = {
    {{"accuracy", false, 0.0, kUnbounded}, false},
    {{"relative_accuracy", false, 1e-9, 1.0}, false},
    {{"max_level", true, 0.0, 8.0}, false},
    {{"initial_grid", true, 3.0, 100.0}, false},
    {{"max_grid", true, 3.0, 200.0}, false},
    {{"smoothing", false, 0.0, 0.99}, false},
    {{"solver", true, 0.0, 1.0}, false},
    {{"threads", true, 0.0, 256.0}, false},
    {{"subcloud_near", false, 0.0, 10.0}, true},
    {{"subcloud_own", false, 0.0, 10.0}, false},
    {{"noise_floor", true, 0.0, 1.0}, false},
    {{"repair", true, 0.0, 1.0}, false},
    {{"loss", true, 0.0, 3.0}, false},
    {{"loss_scale", false, 0.0, kUnbounded}, false},
    {{"ceres_max_iterations", true, 1.0, 1000.0}, false},
    {{"ceres_function_tolerance", false, 1e-16, 1.0}, false},
    {{"outline_neighbours", true, 6.0, 256.0}, false},
    {{"crop", true, 0.0, 1.0}, false},
    {{"strict", true, 0.0, 1.0}, false},
    {{"smooth_turned", true, 0.0, 1.0}, false},
    {{"coarse_pass", true, 0.0, 2.0}, false},
    {{"fit_to_target", true, 0.0, 1.0}, false},
};
constexpr int kOptionCount = static_cast<int>(sizeof(kSpecs) / sizeof(kSpecs[0]));

const OptionSpec& spec(int id) {
  if (id < 0 || id >= kOptionCount) fail(ErrorCode::InvalidArgument, "unknown option id " + std::to_string(id) + " (valid ids are 0 to " + std::to_string(kOptionCount - 1) + ")");
  return kSpecs[id];
}

/// Text that reads back as the same double, as short as %g allows ("0.25", "1e-9", "10"),
/// whatever the host's locale.
std::string number(double x) {
  for (int digits = 6;; ++digits) {
    const std::string text = significant_text(x, digits);
    double back = 0.0;
    const auto parsed = std::from_chars(text.data(), text.data() + text.size(), back);
    if (digits >= 17 || !std::isfinite(x) || (parsed.ec == std::errc() && back == x)) return text;
  }
}

std::string range_text(const OptionSpec& s) {
  if (s.info.max == kUnbounded) return ">= " + number(s.info.min);
  return (s.min_exclusive ? "(" : "[") + number(s.info.min) + ", " + number(s.info.max) + "]";
}

bool in_range(const OptionSpec& s, double value) {
  bool above_min = s.min_exclusive ? value > s.info.min : value >= s.info.min;
  return above_min && value <= s.info.max;
}

/// The Options field behind a real option, or nullptr.
double Options::*real_member(OptionId id) {
  switch (id) {
    case OptionId::Accuracy: return &Options::accuracy;
    case OptionId::RelativeAccuracy: return &Options::relative_accuracy;
    case OptionId::Smoothing: return &Options::smoothing;
    case OptionId::SubcloudNear: return &Options::subcloud_near;
    case OptionId::SubcloudOwn: return &Options::subcloud_own;
    case OptionId::LossScale: return &Options::loss_scale;
    case OptionId::CeresFunctionTolerance: return &Options::ceres_function_tolerance;
    default: return nullptr;
  }
}

/// The Options field behind an integer option other than the solver and the loss, or nullptr.
int Options::*integer_member(OptionId id) {
  switch (id) {
    case OptionId::MaxLevel: return &Options::max_level;
    case OptionId::InitialGrid: return &Options::initial_grid;
    case OptionId::MaxGrid: return &Options::max_grid;
    case OptionId::Threads: return &Options::threads;
    case OptionId::NoiseFloor: return &Options::noise_floor;
    case OptionId::Repair: return &Options::repair;
    case OptionId::CeresMaxIterations: return &Options::ceres_max_iterations;
    case OptionId::OutlineNeighbours: return &Options::outline_neighbours;
    case OptionId::Crop: return &Options::crop;
    case OptionId::Strict: return &Options::strict;
    case OptionId::SmoothTurned: return &Options::smooth_turned;
    case OptionId::CoarsePass: return &Options::coarse_pass;
    case OptionId::FitToTarget: return &Options::fit_to_target;
    default: return nullptr;
  }
}

/// The cross-option rules, checked whichever of the two options is being set.
void check_order(const char* lower_name, double lower, const char* upper_name, double upper) {
  if (lower > upper)
    fail(ErrorCode::OutOfRange, std::string(lower_name) + " = " + number(lower) + " and " + upper_name + " = " + number(upper) + " violate " + lower_name + " <= " + upper_name);
}

}  // namespace

OptionInfo option_info(int id) { return spec(id).info; }

void set_option(Options& options, int id, double value) {
  const OptionSpec& s = spec(id);
  std::string name = s.info.name;
  if (!std::isfinite(value)) fail(ErrorCode::NonFinite, "option " + name + " cannot be set to the non-finite value " + number(value));
  if (s.info.is_integer && value != std::floor(value)) fail(ErrorCode::InvalidArgument, "option " + name + " is an integer option; " + number(value) + " is not an integer");
  if (!in_range(s, value)) fail(ErrorCode::OutOfRange, "option " + name + " = " + number(value) + " is outside its range " + range_text(s));

  auto option = static_cast<OptionId>(id);
  switch (option) {
    case OptionId::Solver:
      if (static_cast<Solver>(static_cast<int>(value)) == Solver::Ceres && !ceres_available())
        fail(ErrorCode::Unsupported, "the Ceres solver is not available: this libdbs was built without Ceres");
      options.solver = static_cast<Solver>(static_cast<int>(value));
      return;
    case OptionId::Loss:
      options.loss = static_cast<LossKind>(static_cast<int>(value));
      return;
    case OptionId::InitialGrid: check_order("initial_grid", value, "max_grid", options.max_grid); break;
    case OptionId::MaxGrid: check_order("initial_grid", options.initial_grid, "max_grid", value); break;
    case OptionId::SubcloudOwn: check_order("subcloud_own", value, "subcloud_near", options.subcloud_near); break;
    case OptionId::SubcloudNear: check_order("subcloud_own", options.subcloud_own, "subcloud_near", value); break;
    default: break;
  }
  if (double Options::*real = real_member(option))
    options.*real = value;
  else
    options.*integer_member(option) = static_cast<int>(value);
}

double get_option(const Options& options, int id) {
  spec(id);  // rejects unknown ids
  auto option = static_cast<OptionId>(id);
  if (option == OptionId::Solver) return static_cast<double>(static_cast<int>(options.solver));
  if (option == OptionId::Loss) return static_cast<double>(static_cast<int>(options.loss));
  if (double Options::*real = real_member(option)) return options.*real;
  return static_cast<double>(options.*integer_member(option));
}

}  // namespace dbs
