#include "delaunay_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <utility>

#include "error.hpp"

#include <libqhull_r/libqhull_r.h>

namespace dbs {
namespace {

// Qhull writes its diagnostics to a FILE*; a temporary file keeps them off the host's
// stderr and lets the error message quote them.
struct TempFile {
  std::FILE* file = std::tmpfile();
  ~TempFile() {
    if (file) std::fclose(file);
  }
  std::string first_line() const {
    if (!file) return "";
    std::rewind(file);
    char line[512] = "";
    if (!std::fgets(line, sizeof line, file)) return "";
    std::string text(line);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    return text;
  }
};

// Frees Qhull's memory however the triangulation ends.
struct QhullRun {
  qhT qh;
  explicit QhullRun(std::FILE* errfile) { qh_zero(&qh, errfile); }
  ~QhullRun() {
    int curlong = 0, totlong = 0;
    qh_freeqhull(&qh, !qh_ALL);
    qh_memfreeshort(&qh, &curlong, &totlong);
  }
};

// Interleaves the bits of x (the even bits of the result) with zeros.
std::uint64_t spread_bits(std::uint32_t x) {
  std::uint64_t b = x;
  b = (b | (b << 16)) & 0x0000FFFF0000FFFFull;
  b = (b | (b << 8)) & 0x00FF00FF00FF00FFull;
  b = (b | (b << 4)) & 0x0F0F0F0F0F0F0F0Full;
  b = (b | (b << 2)) & 0x3333333333333333ull;
  b = (b | (b << 1)) & 0x5555555555555555ull;
  return b;
}

// The points in Morton (Z-curve) order of their (u,v): Qhull then works on neighbouring
// memory and runs markedly faster on large inputs than in the cloud's (often random) order.
std::vector<std::int32_t> spatial_order(const std::vector<double>& u, const std::vector<double>& v) {
  double u0 = *std::min_element(u.begin(), u.end()), u1 = *std::max_element(u.begin(), u.end());
  double v0 = *std::min_element(v.begin(), v.end()), v1 = *std::max_element(v.begin(), v.end());
  double su = u1 > u0 ? 65535.0 / (u1 - u0) : 0.0, sv = v1 > v0 ? 65535.0 / (v1 - v0) : 0.0;
  std::vector<std::pair<std::uint64_t, std::int32_t>> keyed(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    auto qu = static_cast<std::uint32_t>((u[i] - u0) * su), qv = static_cast<std::uint32_t>((v[i] - v0) * sv);
    keyed[i] = {spread_bits(qu) | (spread_bits(qv) << 1), static_cast<std::int32_t>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::int32_t> order(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) order[i] = keyed[i].second;
  return order;
}

double orient(const std::vector<double>& u, const std::vector<double>& v, const Triangle& t) {
  double au = u[t[1]] - u[t[0]], av = v[t[1]] - v[t[0]];
  double bu = u[t[2]] - u[t[0]], bv = v[t[2]] - v[t[0]];
  return au * bv - av * bu;
}

}  // namespace

std::vector<Triangle> delaunay_triangulate(const std::vector<double>& u, const std::vector<double>& v) {
  if (u.size() != v.size()) fail(ErrorCode::InvalidArgument, "delaunay_triangulate: " + std::to_string(u.size()) + " u values but " + std::to_string(v.size()) + " v values");
  if (u.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) fail(ErrorCode::InvalidArgument, "delaunay_triangulate: " + std::to_string(u.size()) + " points exceed the 32-bit vertex index");
  const std::size_t n = u.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(u[i]) || !std::isfinite(v[i])) fail(ErrorCode::NonFinite, "delaunay_triangulate: parameter (u,v) of point " + std::to_string(i) + " is not finite");
  }
  if (n < 3) fail(ErrorCode::Degenerate, "delaunay_triangulate: " + std::to_string(n) + " points cannot be triangulated (at least 3 distinct ones are needed)");
  const std::vector<std::int32_t> order = spatial_order(u, v);  // Qhull's point k is point order[k]
  std::vector<coordT> coords(2 * n);
  for (std::size_t k = 0; k < n; ++k) {
    coords[2 * k] = u[order[k]];
    coords[2 * k + 1] = v[order[k]];
  }

  TempFile diagnostics;
  QhullRun run(diagnostics.file);
  qhT* qh = &run.qh;
  // d: Delaunay; Qbb: scale the lifted coordinate; Qc: keep coincident points with a facet
  // (they are no vertex); Qz: a point at infinity for cocircular input (grids); Q12: allow
  // wide facets; Qt: triangulate non-simplicial facets.
  char command[] = "qhull d Qbb Qc Qz Q12 Qt";
  int exitcode = qh_new_qhull(qh, 2, static_cast<int>(n), coords.data(), False, command, nullptr, diagnostics.file);
  if (exitcode == qh_ERRmem) throw std::bad_alloc();
  if (exitcode == qh_ERRsingular || exitcode == qh_ERRprec || exitcode == qh_ERRinput) {
    fail(ErrorCode::Degenerate, "delaunay_triangulate: the " + std::to_string(n) + " parameter points do not span the plane (fewer than 3 distinct or all on one line); Qhull: " + diagnostics.first_line());
  }
  if (exitcode != 0) fail(ErrorCode::Numerical, "delaunay_triangulate: Qhull failed with code " + std::to_string(exitcode) + ": " + diagnostics.first_line());

  std::vector<Triangle> triangles;
  triangles.reserve(2 * n);
  facetT* facet;
  FORALLfacets {
    if (facet->upperdelaunay) continue;
    Triangle t{};
    int k = 0;
    vertexT *vertex, **vertexp;
    FOREACHvertex_(facet->vertices) {
      int id = qh_pointid(qh, vertex->point);
      if (id < 0 || static_cast<std::size_t>(id) >= n) fail(ErrorCode::Internal, "delaunay_triangulate: Qhull returned a lower Delaunay facet with point id " + std::to_string(id) + " of " + std::to_string(n));
      if (k < 3) t[k] = order[id];
      ++k;
    }
    if (k != 3) fail(ErrorCode::Internal, "delaunay_triangulate: Qhull returned a facet with " + std::to_string(k) + " vertices despite option Qt");
    double area2 = orient(u, v, t);
    if (area2 == 0.0) continue;  // Qt may leave flat simplices where facets were merged
    if (area2 < 0.0) std::swap(t[1], t[2]);
    triangles.push_back(t);
  }
  if (triangles.empty()) fail(ErrorCode::Degenerate, "delaunay_triangulate: the " + std::to_string(n) + " parameter points all lie on one line");
  return triangles;
}

}  // namespace dbs
