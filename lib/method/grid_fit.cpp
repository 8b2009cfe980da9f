#include "grid_fit.hpp"

#include <Eigen/Dense>

#include "base_surface.hpp"
#include "spline_displacement.hpp"

namespace dbs {

void GridFitBasis::add(int nu, int nv) {
  // A grid the fit refuses needs none (and a large one's would be large).
  if (nu < 3 || nv < 3 || (nu - 2) * (nv - 2) > kMaxRefitNodes || made_.count({nu, nv}) != 0) return;
  Cardinals c;
  c.phi.reserve(static_cast<std::size_t>(nu - 2));
  c.psi.reserve(static_cast<std::size_t>(nv - 2));
  for (int i = 1; i + 1 < nu; ++i) {
    Grid unit(nu, nv);
    unit(i, 1) = Vec3(1.0, 0.0, 0.0);
    c.phi.emplace_back(unit);
  }
  for (int j = 1; j + 1 < nv; ++j) {
    Grid unit(nu, nv);
    unit(1, j) = Vec3(1.0, 0.0, 0.0);
    c.psi.emplace_back(unit);
  }
  made_.emplace(std::make_pair(nu, nv), std::move(c));
}

const GridFitBasis::Cardinals* GridFitBasis::find(int nu, int nv) const {
  const auto found = made_.find({nu, nv});
  return found == made_.end() ? nullptr : &found->second;
}

bool fit_grid_to_feet(const BaseSurface& surface, const Grid& grid, const std::vector<std::size_t>& ids, const std::vector<Vec2>& st, const std::vector<Vec3>& points,
                      const GridFitBasis* basis, Grid& out) {
  const int nu = grid.nu, nv = grid.nv;
  if (nu < 3 || nv < 3 || ids.empty() || st.size() != ids.size()) return false;
  const int mi = nu - 2, mj = nv - 2, m = mi * mj;
  if (m > kMaxRefitNodes) return false;  // a dense m x m system beyond this costs more than it is worth
  const BaseSurface coons(surface.boundary());
  GridFitBasis own;
  const GridFitBasis::Cardinals* cardinals = basis ? basis->find(nu, nv) : nullptr;
  if (!cardinals) {
    own.add(nu, nv);
    cardinals = own.find(nu, nv);
  }
  const std::vector<SplineDisplacement>& phi = cardinals->phi;
  const std::vector<SplineDisplacement>& psi = cardinals->psi;
  // The normal equations, accumulated over blocks of kRefitBlock points (no n x m matrix: a
  // leaf may hold most of a large cloud; a block is one rank-k update).
  constexpr int kRefitBlock = 128;
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(m, m), rhs = Eigen::MatrixXd::Zero(m, 3), g0(m, 3);
  Eigen::MatrixXd rows(m, kRefitBlock), residual(kRefitBlock, 3);
  Eigen::VectorXd ph(mi), ps(mj);
  int filled = 0;
  auto flush = [&] {
    normal.selfadjointView<Eigen::Lower>().rankUpdate(rows.leftCols(filled));
    rhs.noalias() += rows.leftCols(filled) * residual.topRows(filled);
    filled = 0;
  };
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const Vec2 at = st[k].cwiseMax(0.0).cwiseMin(1.0);
    for (int i = 0; i < mi; ++i) ph[i] = phi[static_cast<std::size_t>(i)].eval(at.x(), grid.v(1)).x();
    for (int j = 0; j < mj; ++j) ps[j] = psi[static_cast<std::size_t>(j)].eval(grid.u(1), at.y()).x();
    for (int c = 0; c < m; ++c) rows(c, filled) = ph[c % mi] * ps[c / mi];
    residual.row(filled) = (points[ids[k]] - coons.eval(at.x(), at.y())).transpose();
    if (++filled == kRefitBlock) flush();
  }
  if (filled > 0) flush();
  for (int c = 0; c < m; ++c) {
    const int i = 1 + c % mi, j = 1 + c / mi;
    g0.row(c) = (grid(i, j) - coons.eval(grid.u(i), grid.v(j))).transpose();
  }
  const double lambda = kRefitRegularization * normal.diagonal().mean();
  if (!(lambda > 0.0)) return false;  // no data reaches a node
  normal.diagonal().array() += lambda;
  // LDLT reads the lower triangle, the one accumulated.
  const Eigen::MatrixXd g = normal.ldlt().solve(rhs + lambda * g0);
  if (!g.allFinite()) return false;
  out = grid;
  for (int c = 0; c < m; ++c) {
    const int i = 1 + c % mi, j = 1 + c / mi;
    out(i, j) = coons.eval(grid.u(i), grid.v(j)) + Vec3(g(c, 0), g(c, 1), g(c, 2));
  }
  return true;
}

bool fit_grid_to_parameters(Patch& leaf, const std::vector<std::size_t>& ids, const std::vector<Vec3>& points, const std::vector<double>& u, const std::vector<double>& v,
                            const GridFitBasis* basis) {
  std::vector<Vec2> st(ids.size());
  for (std::size_t k = 0; k < ids.size(); ++k) st[k] = leaf.rect.to_local(u[ids[k]], v[ids[k]]);
  Grid fitted;
  if (!fit_grid_to_feet(leaf.surface, leaf.grid, ids, st, points, basis, fitted)) return false;
  leaf.surface = BaseSurface(leaf.surface.boundary(), fitted);
  leaf.grid = std::move(fitted);
  return true;
}

}  // namespace dbs
