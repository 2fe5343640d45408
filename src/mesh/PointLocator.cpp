#include "flowform/mesh/PointLocator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flowform {

PointLocator::PointLocator(const Mesh& mesh) : m_mesh(mesh) {
  double x1 = -std::numeric_limits<double>::max(), y1 = x1;
  m_x0 = m_y0 = std::numeric_limits<double>::max();
  for (const auto& p : mesh.coords) {
    m_x0 = std::min(m_x0, p[0]);
    m_y0 = std::min(m_y0, p[1]);
    x1 = std::max(x1, p[0]);
    y1 = std::max(y1, p[1]);
  }
  // About one cell per bin, bins as square as the bounding box allows.
  const double w = std::max(x1 - m_x0, 1e-300), h = std::max(y1 - m_y0, 1e-300);
  const double bins = std::max<double>(1.0, static_cast<double>(mesh.numCells()));
  m_nx = std::max(1, static_cast<int>(std::sqrt(bins * w / h)));
  m_ny = std::max(1, static_cast<int>(bins / m_nx));
  m_dx = w / m_nx;
  m_dy = h / m_ny;
  m_bins.assign(static_cast<size_t>(m_nx) * m_ny, {});
  const int npc = nodesPerCell(mesh.cellType);
  for (GO c = 0; c < mesh.numCells(); ++c) {
    double lx = std::numeric_limits<double>::max(), ly = lx, hx = -lx, hy = -lx;
    for (int a = 0; a < npc; ++a) {
      const auto& p = mesh.coords[mesh.cell(c)[a]];
      lx = std::min(lx, p[0]);
      ly = std::min(ly, p[1]);
      hx = std::max(hx, p[0]);
      hy = std::max(hy, p[1]);
    }
    for (int j = binOf(ly, m_y0, m_dy, m_ny); j <= binOf(hy, m_y0, m_dy, m_ny); ++j)
      for (int i = binOf(lx, m_x0, m_dx, m_nx); i <= binOf(hx, m_x0, m_dx, m_nx); ++i)
        m_bins[static_cast<size_t>(j) * m_nx + i].push_back(c);
  }
}

int PointLocator::binOf(double v, double lo, double size, int count) const {
  return std::clamp(static_cast<int>(std::floor((v - lo) / size)), 0, count - 1);
}

double PointLocator::weightsIn(GO c, const std::array<double, 2>& x, std::array<double, 4>& w) const {
  const GO* nodes = m_mesh.cell(c);
  w = {0.0, 0.0, 0.0, 0.0};
  if (m_mesh.cellType == CellType::Triangle3) {
    // Barycentric coordinates λ_a = area(x, b, c) / area(a, b, c).
    const auto& a = m_mesh.coords[nodes[0]];
    const auto& b = m_mesh.coords[nodes[1]];
    const auto& d = m_mesh.coords[nodes[2]];
    const double det = (b[0] - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (b[1] - a[1]);
    const double l1 = ((x[0] - a[0]) * (d[1] - a[1]) - (d[0] - a[0]) * (x[1] - a[1])) / det;
    const double l2 = ((b[0] - a[0]) * (x[1] - a[1]) - (x[0] - a[0]) * (b[1] - a[1])) / det;
    std::array<double, 3> l{1.0 - l1 - l2, l1, l2};
    const double outside = -std::min({l[0], l[1], l[2], 0.0});
    if (outside > 0.0) {
      // Clamp to the triangle: drop the negative coordinates and renormalize (a point of the
      // nearest edge or corner for the small excursions this serves).
      double sum = 0.0;
      for (double& v : l) sum += (v = std::max(v, 0.0));
      for (double& v : l) v /= sum;
    }
    w = {l[0], l[1], l[2], 0.0};
    return outside;
  }
  // Bilinear quadrilateral: x(ξ, η) = Σ N_a x_a, N_a = (1 + ξ_a ξ)(1 + η_a η)/4, inverted by Newton.
  static constexpr double xi[4] = {-1, 1, 1, -1}, et[4] = {-1, -1, 1, 1};
  double s = 0.0, t = 0.0;
  for (int it = 0; it < 20; ++it) {
    double fx = -x[0], fy = -x[1], a11 = 0, a12 = 0, a21 = 0, a22 = 0;
    for (int k = 0; k < 4; ++k) {
      const auto& p = m_mesh.coords[nodes[k]];
      const double n = (1 + xi[k] * s) * (1 + et[k] * t) / 4;
      const double ns = xi[k] * (1 + et[k] * t) / 4, nt = et[k] * (1 + xi[k] * s) / 4;
      fx += n * p[0];
      fy += n * p[1];
      a11 += ns * p[0];
      a12 += nt * p[0];
      a21 += ns * p[1];
      a22 += nt * p[1];
    }
    const double det = a11 * a22 - a12 * a21;
    const double ds = (a22 * fx - a12 * fy) / det, dt = (a11 * fy - a21 * fx) / det;
    s -= ds;
    t -= dt;
    if (std::abs(ds) + std::abs(dt) < 1e-14) break;
  }
  const double outside = std::max({std::abs(s) - 1.0, std::abs(t) - 1.0, 0.0});
  s = std::clamp(s, -1.0, 1.0);
  t = std::clamp(t, -1.0, 1.0);
  for (int k = 0; k < 4; ++k) w[k] = (1 + xi[k] * s) * (1 + et[k] * t) / 4;
  return outside;
}

CellPoint PointLocator::locate(const std::array<double, 2>& x) const {
  const int i0 = binOf(x[0], m_x0, m_dx, m_nx), j0 = binOf(x[1], m_y0, m_dy, m_ny);
  CellPoint best;
  double bestOutside = std::numeric_limits<double>::max();
  std::array<double, 4> w;
  // Rings of bins around the point's own; stop at the first ring after one that had a cell
  // holding the point, or when every bin has been seen.
  for (int ring = 0; ring <= std::max(m_nx, m_ny); ++ring) {
    for (int j = j0 - ring; j <= j0 + ring; ++j)
      for (int i = i0 - ring; i <= i0 + ring; ++i) {
        if (i < 0 || j < 0 || i >= m_nx || j >= m_ny) continue;
        if (std::max(std::abs(i - i0), std::abs(j - j0)) != ring) continue;
        for (GO c : m_bins[static_cast<size_t>(j) * m_nx + i]) {
          const double outside = weightsIn(c, x, w);
          if (outside < bestOutside) {
            bestOutside = outside;
            best.cell = c;
            best.weights = w;
          }
          if (outside <= 1e-12) {
            best.inside = true;
            return best;
          }
        }
      }
    // A nearest cell found and one more ring searched: a nearer one cannot lie further out.
    if (best.cell >= 0 && ring >= 1) break;
  }
  return best;
}

}  // namespace flowform
