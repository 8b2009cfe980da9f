#include "report_directory.hpp"

#include <cerrno>
#include <filesystem>
#include <system_error>

#include "error.hpp"

namespace dbs {

void make_report_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  // A file in the way: no errno of its own, ENOTDIR is what the system would say.
  if (ec || !std::filesystem::is_directory(dir)) fail_io("cannot create the report directory '" + dir + "'" + (ec ? ": " + ec.message() : ""), ec ? ec.value() : ENOTDIR);
}

}  // namespace dbs
