// Writing parameterization results (FORMATS.md): .csv, .ply (binary little-endian, with
// float u, v, distance and int patch properties) and .drc (Draco, POSITION + TEX_COORD).
// Cropped points (Result::cropped) keep their rows in .csv and .ply, with NaN u, v and
// distance and patch (and level) -1; the .drc, whose quantized texture coordinates hold no
// NaN, lists the other points in input order.
#pragma once
#include <string>

#include "point_cloud.hpp"
#include "result.hpp"

namespace dbs {

/// By extension. Error(InvalidArgument) when the cloud's size differs from the result's,
/// Error(Unsupported) for an unknown extension, Error(Io) naming the file when writing fails.
void save_result(const Result& result, const PointCloud& cloud, const std::string& path);

}  // namespace dbs
