#include "report_directory.hpp"

#include <filesystem>
#include <system_error>

#include "error.hpp"

namespace dbs {

void make_report_directory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) fail(ErrorCode::Io, "cannot create the report directory '" + dir + "'" + (ec ? ": " + ec.message() : ""));
}

}  // namespace dbs
