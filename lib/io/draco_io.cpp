#include "draco_io.hpp"

#include "error.hpp"

#ifdef DBS_HAVE_DRACO
#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/core/decoder_buffer.h>
#include <draco/core/encoder_buffer.h>
#include <draco/point_cloud/point_cloud.h>
#include <draco/point_cloud/point_cloud_builder.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "text_io.hpp"
#endif

namespace dbs {

#ifdef DBS_HAVE_DRACO

namespace {

// Quantization of the written .drc: 16 bits over the cloud's largest extent E put every
// coordinate within E / (2 * 65535) ~ 7.6e-6 E of its input (u, v likewise over their
// range), well below 1e-4 of the bounding box.
constexpr int kPositionBits = 16;
constexpr int kTexCoordBits = 16;
// Draco's speed settings run from 0 (smallest file) to 10 (fastest); 5 is its default and
// matters little for the sequential encoding.
constexpr int kEncodingSpeed = 5;
constexpr int kDecodingSpeed = 5;

[[noreturn]] void non_finite(const std::string& where, const char* element, std::size_t k) {
  fail(ErrorCode::NonFinite, where + ": " + element + " " + std::to_string(k) + " has a non-finite coordinate");
}

/// Points a .drc file of `size` bytes may claim: Draco's densest point cloud encodings take
/// well over 1/1024 byte per point, so a header claiming more lies (a damaged or hostile
/// file) and would make Draco allocate for it before finding the data missing.
constexpr std::uint64_t kMaxPointsPerByte = 1024;

/// The point count of a point-cloud .drc header ("DRACO", version, encoder type 0 = point
/// cloud, method, 16-bit flags, then the count as a 32-bit integer), checked against the
/// file's size. Files with metadata or of meshes keep their count elsewhere and are left
/// to Draco.
void check_claimed_count(const std::string& bytes, const std::string& path) {
  constexpr std::size_t kCountOffset = 11;
  constexpr unsigned kMetadataFlag = 0x8000;
  if (bytes.size() < kCountOffset + 4 || bytes.compare(0, 5, "DRACO") != 0) return;  // Draco reports it
  const unsigned encoder_type = static_cast<unsigned char>(bytes[7]);
  const unsigned flags = static_cast<unsigned char>(bytes[9]) | (static_cast<unsigned>(static_cast<unsigned char>(bytes[10])) << 8);
  if (encoder_type != 0 || (flags & kMetadataFlag)) return;
  std::uint32_t count = 0;
  for (int i = 3; i >= 0; --i) count = (count << 8) | static_cast<unsigned char>(bytes[kCountOffset + static_cast<std::size_t>(i)]);
  // Draco stores the count as a signed 32-bit integer: above INT32_MAX it is negative.
  if (count > 0x7fffffffu || static_cast<std::uint64_t>(count) > kMaxPointsPerByte * bytes.size())
    fail(ErrorCode::Parse, path + ": the Draco header claims " + std::to_string(count) + " points, more than a file of " + std::to_string(bytes.size()) + " bytes can hold (at most " +
                               std::to_string(kMaxPointsPerByte) + " per byte)");
}

std::unique_ptr<draco::PointCloud> decode_drc(const std::string& path) {
  const std::string bytes = read_file_bytes(path);
  if (bytes.empty()) fail(ErrorCode::Empty, path + ": no points (the file is empty)");
  check_claimed_count(bytes, path);
  draco::DecoderBuffer buffer;
  buffer.Init(bytes.data(), bytes.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodePointCloudFromBuffer(&buffer);
  if (!decoded.ok()) fail(ErrorCode::Parse, path + ": not a valid Draco file: " + decoded.status().error_msg_string());
  std::unique_ptr<draco::PointCloud> cloud = std::move(decoded).value();
  if (cloud->num_points() == 0) fail(ErrorCode::Empty, path + ": no points (the Draco file holds 0 points)");
  return cloud;
}

// The attribute's `components` first values for every point, through the point -> value
// map (Draco stores each distinct value once).
std::vector<double> values_per_point(const draco::PointCloud& cloud, draco::GeometryAttribute::Type type, int components, const std::string& path) {
  const draco::PointAttribute* attribute = cloud.GetNamedAttribute(type);
  const std::string name = draco::GeometryAttribute::TypeToString(type);
  if (attribute == nullptr) fail(ErrorCode::Parse, path + ": the Draco file has no " + name + " attribute");
  if (attribute->num_components() < components) fail(ErrorCode::Parse, path + ": the Draco " + name + " attribute has too few components");
  std::vector<double> values(static_cast<std::size_t>(cloud.num_points()) * components);
  for (draco::PointIndex i(0); i < cloud.num_points(); ++i) {
    if (!attribute->ConvertValue<double>(attribute->mapped_index(i), static_cast<int8_t>(components), &values[i.value() * components]))
      fail(ErrorCode::Parse, path + ": point " + std::to_string(i.value()) + " has an unreadable " + name + " value");
  }
  return values;
}

std::vector<Vec3> read_drc(const std::string& path) {
  const std::vector<double> xyz = values_per_point(*decode_drc(path), draco::GeometryAttribute::POSITION, 3, path);
  std::vector<Vec3> points(xyz.size() / 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    if (!is_finite(points[i])) non_finite(path, "point", i);
  }
  return points;
}

}  // namespace

bool draco_available() { return true; }

std::vector<Vec3> read_positions_with_draco(const std::string& path) { return read_drc(path); }

std::vector<Vec2> read_tex_coords_with_draco(const std::string& path) {
  const std::vector<double> uv = values_per_point(*decode_drc(path), draco::GeometryAttribute::TEX_COORD, 2, path);
  std::vector<Vec2> out(uv.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec2(uv[2 * i], uv[2 * i + 1]);
  return out;
}

void write_draco_point_cloud(const std::string& path, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v) {
  if (points.empty()) fail(ErrorCode::Empty, "cannot write '" + path + "': no points");
  if (u.size() != points.size() || v.size() != points.size())
    fail(ErrorCode::InvalidArgument, "cannot write '" + path + "': " + std::to_string(points.size()) + " points but " + std::to_string(u.size()) + " u and " + std::to_string(v.size()) + " v values");
  const auto count = static_cast<draco::PointIndex::ValueType>(points.size());
  draco::PointCloudBuilder builder;
  builder.Start(count);
  const int position_id = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int texcoord_id = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
  for (draco::PointIndex i(0); i < count; ++i) {
    const std::size_t k = i.value();
    if (!is_finite(points[k])) fail(ErrorCode::NonFinite, "cannot write '" + path + "': point " + std::to_string(k) + " has a non-finite coordinate");
    if (!std::isfinite(u[k]) || !std::isfinite(v[k])) fail(ErrorCode::NonFinite, "cannot write '" + path + "': point " + std::to_string(k) + " has a non-finite (u,v)");
    const float position[3] = {static_cast<float>(points[k].x()), static_cast<float>(points[k].y()), static_cast<float>(points[k].z())};
    const float texcoord[2] = {static_cast<float>(u[k]), static_cast<float>(v[k])};
    if (!std::isfinite(position[0]) || !std::isfinite(position[1]) || !std::isfinite(position[2]) || !std::isfinite(texcoord[0]) || !std::isfinite(texcoord[1]))
      fail(ErrorCode::OutOfRange, "cannot write '" + path + "': point " + std::to_string(k) + " is beyond the 32-bit float range of .drc attributes");
    builder.SetAttributeValueForPoint(position_id, i, position);
    builder.SetAttributeValueForPoint(texcoord_id, i, texcoord);
  }
  const std::unique_ptr<draco::PointCloud> cloud = builder.Finalize(false);
  if (!cloud) fail(ErrorCode::Internal, "cannot write '" + path + "': Draco could not build the point cloud");

  draco::Encoder encoder;
  // Sequential encoding keeps the points in input order (the k-d tree encoding reorders them).
  encoder.SetEncodingMethod(draco::POINT_CLOUD_SEQUENTIAL_ENCODING);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, kPositionBits);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, kTexCoordBits);
  encoder.SetSpeedOptions(kEncodingSpeed, kDecodingSpeed);
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodePointCloudToBuffer(*cloud, &buffer);
  if (!status.ok()) fail(ErrorCode::Internal, "cannot write '" + path + "': Draco could not encode: " + status.error_msg_string());
  write_file_bytes(path, std::string_view(buffer.data(), buffer.size()));
}

#else  // built without Draco

bool draco_available() { return false; }

std::vector<Vec3> read_positions_with_draco(const std::string& path) {
  fail(ErrorCode::Unsupported, path + ": .drc files are read through Draco, and libdbs was built without Draco");
}

std::vector<Vec2> read_tex_coords_with_draco(const std::string& path) {
  fail(ErrorCode::Unsupported, path + ": .drc files are read through Draco, and libdbs was built without Draco");
}

void write_draco_point_cloud(const std::string& path, const std::vector<Vec3>&, const std::vector<double>&, const std::vector<double>&) {
  fail(ErrorCode::Unsupported, path + ": .drc files are written through Draco, and libdbs was built without Draco");
}

#endif

}  // namespace dbs
