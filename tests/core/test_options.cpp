// Options: the core's checks that the C API cannot reach (an integer option given a real
// value through set_option), names, and get/set round trips.
#include <cmath>
#include <cstring>
#include <string>

#include "error.hpp"
#include "curve_refinement.hpp"
#include "options.hpp"

// cmocka last (its fail() macro would hide dbs::fail), with C linkage.
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
extern "C" {
#include <cmocka.h>
}

namespace {

/// The code of the dbs::Error that set_option throws, and its message in `message`.
dbs::ErrorCode set_error(dbs::Options& options, int id, double value, std::string& message) {
  try {
    dbs::set_option(options, id, value);
  } catch (const dbs::Error& e) {
    message = e.what();
    return e.code();
  }
  message.clear();
  return dbs::ErrorCode::Internal;  // no error: never what a caller here expects
}

void names_and_types(void**) {
  const char* names[] = {"accuracy", "relative_accuracy", "max_level", "initial_grid", "max_grid", "smoothing", "solver", "threads", "subcloud_near", "subcloud_own"};
  const bool integer[] = {false, false, true, true, true, false, true, true, false, false};
  for (int id = 0; id < 10; ++id) {
    dbs::OptionInfo info = dbs::option_info(id);
    assert_string_equal(info.name, names[id]);
    assert_int_equal(info.is_integer, integer[id]);
    assert_true(info.min <= info.max);
  }
  std::string message;
  try {
    dbs::option_info(22);
  } catch (const dbs::Error& e) {
    assert_int_equal(static_cast<int>(e.code()), static_cast<int>(dbs::ErrorCode::InvalidArgument));
    message = e.what();
  }
  assert_non_null(std::strstr(message.c_str(), "unknown option id 22"));
}

void integer_options_take_only_integral_values(void**) {
  dbs::Options options;
  std::string message;
  assert_int_equal(static_cast<int>(set_error(options, static_cast<int>(dbs::OptionId::MaxLevel), 2.5, message)), static_cast<int>(dbs::ErrorCode::InvalidArgument));
  assert_non_null(std::strstr(message.c_str(), "max_level"));
  assert_non_null(std::strstr(message.c_str(), "2.5"));
  assert_int_equal(options.max_level, 4);
  assert_int_equal(static_cast<int>(set_error(options, static_cast<int>(dbs::OptionId::Threads), 1e-300, message)), static_cast<int>(dbs::ErrorCode::InvalidArgument));
  assert_int_equal(options.threads, 0);
  // an integral double is an integer
  dbs::set_option(options, static_cast<int>(dbs::OptionId::MaxLevel), 3.0);
  assert_int_equal(options.max_level, 3);
  assert_true(dbs::get_option(options, static_cast<int>(dbs::OptionId::MaxLevel)) == 3.0);
}

void every_field_round_trips(void**) {
  dbs::Options options;
  const double values[] = {0.125, 0.5, 7, 4, 150, 0.875, 0, 3, 2.5, 1.5};
  dbs::set_option(options, static_cast<int>(dbs::OptionId::MaxGrid), 150);  // room for initial_grid
  for (int id = 0; id < 10; ++id) dbs::set_option(options, id, values[id]);
  for (int id = 0; id < 10; ++id) assert_true(dbs::get_option(options, id) == values[id]);
  assert_true(options.accuracy == 0.125 && options.relative_accuracy == 0.5 && options.max_level == 7);
  assert_true(options.initial_grid == 4 && options.max_grid == 150 && options.smoothing == 0.875);
  assert_true(options.solver == dbs::Solver::Linear && options.threads == 3);
  assert_true(options.subcloud_near == 2.5 && options.subcloud_own == 1.5);
}

void order_of_checks(void**) {
  dbs::Options options;
  std::string message;
  const int max_level = static_cast<int>(dbs::OptionId::MaxLevel);
  // NaN is non-finite before it is anything else; a non-integer before out of range
  assert_int_equal(static_cast<int>(set_error(options, max_level, std::nan(""), message)), static_cast<int>(dbs::ErrorCode::NonFinite));
  assert_int_equal(static_cast<int>(set_error(options, max_level, 99.5, message)), static_cast<int>(dbs::ErrorCode::InvalidArgument));
  assert_int_equal(static_cast<int>(set_error(options, max_level, 99, message)), static_cast<int>(dbs::ErrorCode::OutOfRange));
  assert_non_null(std::strstr(message.c_str(), "max_level = 99 is outside its range [0, 8]"));
  // the Ceres solver: taken exactly when this build has it
  const dbs::ErrorCode ceres = set_error(options, static_cast<int>(dbs::OptionId::Solver), 1, message);
  assert_int_equal(static_cast<int>(ceres), static_cast<int>(dbs::ceres_available() ? dbs::ErrorCode::Internal : dbs::ErrorCode::Unsupported));
  assert_true(options.solver == (dbs::ceres_available() ? dbs::Solver::Ceres : dbs::Solver::Linear));
}

void ceres_options_round_trip(void**) {
  dbs::Options options;
  const int loss = static_cast<int>(dbs::OptionId::Loss), scale = static_cast<int>(dbs::OptionId::LossScale);
  const int iterations = static_cast<int>(dbs::OptionId::CeresMaxIterations), tolerance = static_cast<int>(dbs::OptionId::CeresFunctionTolerance);
  assert_string_equal(dbs::option_info(loss).name, "loss");
  assert_true(dbs::option_info(loss).is_integer && dbs::option_info(iterations).is_integer);
  assert_false(dbs::option_info(scale).is_integer || dbs::option_info(tolerance).is_integer);
  assert_true(options.loss == dbs::LossKind::None && options.loss_scale == 0.0 && options.ceres_max_iterations == 25 && options.ceres_function_tolerance == 1e-6);
  dbs::set_option(options, loss, 2);
  dbs::set_option(options, scale, 0.25);
  dbs::set_option(options, iterations, 7);
  dbs::set_option(options, tolerance, 1e-9);
  assert_true(options.loss == dbs::LossKind::Cauchy && options.loss_scale == 0.25 && options.ceres_max_iterations == 7 && options.ceres_function_tolerance == 1e-9);
  assert_true(dbs::get_option(options, loss) == 2 && dbs::get_option(options, scale) == 0.25 && dbs::get_option(options, iterations) == 7 && dbs::get_option(options, tolerance) == 1e-9);
  std::string message;
  assert_int_equal(static_cast<int>(set_error(options, loss, 4, message)), static_cast<int>(dbs::ErrorCode::OutOfRange));
  assert_non_null(std::strstr(message.c_str(), "loss = 4 is outside its range [0, 3]"));
  assert_int_equal(static_cast<int>(set_error(options, iterations, 0, message)), static_cast<int>(dbs::ErrorCode::OutOfRange));
  assert_int_equal(static_cast<int>(set_error(options, tolerance, 0, message)), static_cast<int>(dbs::ErrorCode::OutOfRange));
  assert_int_equal(static_cast<int>(set_error(options, scale, -1e-3, message)), static_cast<int>(dbs::ErrorCode::OutOfRange));
  assert_true(options.loss == dbs::LossKind::Cauchy && options.loss_scale == 0.25 && options.ceres_max_iterations == 7);
}

}  // namespace

int main() {
  const CMUnitTest tests[] = {
      cmocka_unit_test(names_and_types),
      cmocka_unit_test(integer_options_take_only_integral_values),
      cmocka_unit_test(every_field_round_trips),
      cmocka_unit_test(order_of_checks),
      cmocka_unit_test(ceres_options_round_trip),
  };
  return cmocka_run_group_tests(tests, nullptr, nullptr);
}
