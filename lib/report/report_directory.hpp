// The folder a report writes into.
#pragma once
#include <string>

namespace dbs {

/// Creates `dir` with its parents when missing; Error(Io) naming it when that fails or it is
/// not a directory.
void make_report_directory(const std::string& dir);

}  // namespace dbs
