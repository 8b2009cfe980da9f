#include "boundary_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/Geometry>

#include "bitmap_font.hpp"
#include "cloud_body.hpp"
#include "error.hpp"
#include "json_writer.hpp"
#include "outline.hpp"
#include "png_file.hpp"
#include "report_directory.hpp"
#include "text_io.hpp"

namespace dbs {
namespace {

constexpr int kMargin = 28;  // pixels around each view's drawing, room for the corner labels
const Rgb kPointGrey{175, 175, 175};
const Rgb kHoleMagenta{190, 40, 190};
const Rgb kBlack{0, 0, 0};
/// bottom (v = 0), right (u = 1), top (v = 1), left (u = 0): Side order.
const std::array<Rgb, 4> kSideColours{{{205, 35, 35}, {30, 150, 40}, {40, 80, 210}, {235, 140, 20}}};
const std::array<const char*, 4> kSideNames{{"bottom v=0", "right u=1", "top v=1", "left u=0"}};
const std::array<const char*, 4> kCornerNames{{"(0,0)", "(1,0)", "(1,1)", "(0,1)"}};

/// Corner c (0..3: (0,0), (1,0), (1,1), (0,1)) of the boundary.
Vec3 corner_of(const Boundary& boundary, int c) { return boundary.corner(c == 1 || c == 2 ? 1 : 0, c >= 2 ? 1 : 0); }

/// One view: points mapped by two axes of the cloud's frame into a square of pixels.
class View {
 public:
  View(const PlaneFrame& frame, const Vec3& across, int left, const std::vector<Vec3>& everything) : frame_(frame), across_(across), left_(left) {
    Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
    for (const Vec3& p : everything) {
      const Vec2 q = coordinates(p);
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
    scale_ = extent > 0.0 ? (kBoundaryViewSize - 2 * kMargin) / extent : 1.0;
    centre_ = 0.5 * (lo + hi);
  }

  /// Pixel coordinates (x right, y down) of p.
  Vec2 pixel(const Vec3& p) const {
    const Vec2 q = (coordinates(p) - centre_) * scale_;
    return {left_ + 0.5 * kBoundaryViewSize + q.x(), 0.5 * kBoundaryViewSize - q.y()};
  }

  /// Within reach of the picture (and finite): its pixel coordinates fit an int.
  static bool on_canvas(const Vec2& p) { return std::abs(p.x()) < 1e5 && std::abs(p.y()) < 1e5; }

  void dot(RgbImage& image, const Vec3& p, Rgb colour, int radius) const {
    const Vec2 c = pixel(p);
    if (!on_canvas(c)) return;
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) image.plot(static_cast<int>(std::lround(c.x())) + dx, static_cast<int>(std::lround(c.y())) + dy, colour);
  }

  /// A polyline 3 pixels wide (closed: back to its first point).
  void polyline(RgbImage& image, const std::vector<Vec3>& points, Rgb colour, bool closed) const {
    for (std::size_t k = 0; k + 1 < points.size() + (closed ? 1 : 0); ++k) segment(image, pixel(points[k]), pixel(points[(k + 1) % points.size()]), colour);
  }

 private:
  Vec2 coordinates(const Vec3& p) const { return {(p - frame_.origin).dot(frame_.e1), (p - frame_.origin).dot(across_)}; }

  static void segment(RgbImage& image, const Vec2& a, const Vec2& b, Rgb colour) {
    if (!on_canvas(a) || !on_canvas(b)) return;
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).lpNorm<Eigen::Infinity>())));
    for (int s = 0; s <= steps; ++s) {
      const Vec2 p = a + (b - a) * (static_cast<double>(s) / steps);
      const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) image.plot(x + dx, y + dy, colour);
    }
  }

  PlaneFrame frame_;
  Vec3 across_;
  int left_;
  double scale_ = 1.0;
  Vec2 centre_ = Vec2::Zero();
};

void draw_view(RgbImage& image, const View& view, const std::vector<Vec3>& points, const Boundary& boundary, const std::vector<std::vector<Vec3>>& holes, const std::string& title, int left) {
  for (const Vec3& p : points) view.dot(image, p, kPointGrey, 0);
  for (const std::vector<Vec3>& hole : holes) view.polyline(image, hole, kHoleMagenta, true);
  for (int s = 0; s < 4; ++s) view.polyline(image, boundary.side(static_cast<Side>(s)).points(), kSideColours[static_cast<std::size_t>(s)], false);
  for (int c = 0; c < 4; ++c) {
    const Vec3 corner = corner_of(boundary, c);
    view.dot(image, corner, kBlack, 3);
    const Vec2 at = view.pixel(corner);
    if (!View::on_canvas(at)) continue;
    draw_text(image, static_cast<int>(at.x()) + 6, static_cast<int>(at.y()) - 12, kCornerNames[static_cast<std::size_t>(c)], kBlack);
  }
  draw_text(image, left + 6, 6, title, kBlack);
}

}  // namespace

RgbImage draw_boundary_picture(const std::vector<Vec3>& all_points, const Boundary& boundary, const std::vector<std::vector<Vec3>>& holes) {
  if (all_points.empty()) fail(ErrorCode::InvalidArgument, "the boundary's picture needs the cloud's points: the cloud is empty");
  // Framed on the cloud's body: one glitch 1e6 away must not shrink the scan to a pixel.
  const CloudBody body = cloud_body(all_points, boundary);
  std::vector<Vec3> points;
  points.reserve(body.body.size());
  for (std::size_t i : body.body) points.push_back(all_points[i]);
  const PlaneFrame frame = principal_plane(points);
  const Vec3 normal = frame.e1.cross(frame.e2).normalized();
  std::vector<Vec3> everything = points;
  for (int s = 0; s < 4; ++s) {
    const std::vector<Vec3>& side = boundary.side(static_cast<Side>(s)).points();
    everything.insert(everything.end(), side.begin(), side.end());
  }
  for (const std::vector<Vec3>& hole : holes) everything.insert(everything.end(), hole.begin(), hole.end());
  RgbImage image(2 * kBoundaryViewSize, kBoundaryViewSize + kBoundaryLegendHeight);
  draw_view(image, View(frame, frame.e2, 0, everything), points, boundary, holes, "from above (along the least principal axis)", 0);
  draw_view(image, View(frame, normal, kBoundaryViewSize, everything), points, boundary, holes, "from the side", kBoundaryViewSize);
  for (int y = 0; y < kBoundaryViewSize; ++y) image.plot(kBoundaryViewSize, y, kBlack);
  // Legend: the sides' colours, the holes, the points.
  int x = 8;
  const int y = kBoundaryViewSize + 14;
  for (int s = 0; s < 4; ++s) {
    const std::string name = kSideNames[static_cast<std::size_t>(s)];
    draw_text(image, x, y, name, kSideColours[static_cast<std::size_t>(s)], 2);
    x += text_width(name, 2) + 24;
  }
  std::string rest = std::to_string(holes.size()) + (holes.size() == 1 ? " hole" : " holes") + ", " + std::to_string(points.size()) + " points";
  if (points.size() < all_points.size()) rest += " (" + std::to_string(all_points.size() - points.size()) + " far outside not drawn)";
  draw_text(image, x, y, rest, holes.empty() ? kBlack : kHoleMagenta, 2);
  return image;
}

void write_boundary_report(const std::vector<Vec3>& points, const Boundary& boundary, const std::vector<std::vector<Vec3>>& holes, const std::string& dir) {
  const RgbImage picture = draw_boundary_picture(points, boundary, holes);
  make_report_directory(dir);
  write_png(dir + "/boundary.png", picture);
  JsonWriter json;
  json.begin_object();
  json.integer("points", static_cast<long long>(points.size()));
  json.number("size", boundary.size());
  json.begin_array("sides");
  for (int s = 0; s < 4; ++s) {
    const Polyline& side = boundary.side(static_cast<Side>(s));
    json.begin_object();
    json.string("name", kSideNames[static_cast<std::size_t>(s)]);
    json.integer("points", static_cast<long long>(side.points().size()));
    json.number("length", side.length());
    json.end_object();
  }
  json.end_array();
  json.begin_array("corners");
  for (int c = 0; c < 4; ++c) {
    const Vec3 corner = corner_of(boundary, c);
    json.begin_array();
    for (double x : {corner.x(), corner.y(), corner.z()}) json.number(x);
    json.end_array();
  }
  json.end_array();
  json.begin_array("holes");
  for (const std::vector<Vec3>& hole : holes) {
    double length = 0.0;
    for (std::size_t k = 0; k < hole.size(); ++k) length += (hole[(k + 1) % hole.size()] - hole[k]).norm();
    json.begin_object();
    json.integer("points", static_cast<long long>(hole.size()));
    json.number("length", length);
    json.end_object();
  }
  json.end_array();
  json.end_object();
  write_file_bytes(dir + "/boundary.json", json.text() + "\n");
}

}  // namespace dbs
