// Shared by the flow-kernel tests (FlowKernelTest: hand values; FlowKernelDerivativeTest:
// AD derivatives and rigid motions): one cell with its quadrature and kernel settings.
#pragma once

#include <Teuchos_UnitTestHarness.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "flowform/physics/Material.hpp"
#include "flowform/physics/FlowResidual.hpp"
#include "flowform/discretization/ShapeFunctions.hpp"


namespace {

using flowform::CellQuadrature;
using flowform::CellType;
using flowform::FlowKernelSettings;
using flowform::Geometry;
constexpr int kDofsPerNode = flowform::EqualOrderLayout::kFieldsPerNode;  // the equal-order element layout
using flowform::MaterialParameters;

using XY = std::array<double, 2>;

const MaterialParameters<double> kNewtonian = flowform::powerLaw(0.0, 1.0, 1.0, 1e-3);  // μ = 1/(3γ) = 1/3
const MaterialParameters<double> kNonlinear = flowform::powerLaw(0.5, 1.0, 5.0, 1e-2);  // σ0, γ, n, e0

/// One cell with its quadrature, as the assembler sets it up: the centroid rule for P1 in
/// plane strain (constant integrands), the 3-point / 2×2 rule otherwise.
struct Cell {
  CellType type;
  std::vector<XY> xy;
  CellQuadrature rule, centroid;
  double h = 0.0;

  Cell(CellType t, std::vector<XY> nodes, Geometry geometry, int order = 0) : type(t), xy(std::move(nodes)) {
    if (order == 0) order = (type == CellType::Triangle3 && geometry == Geometry::PlaneStrain) ? 1 : 2;
    const bool ok = flowform::computeCellQuadrature(type, xy.data(), order, rule) &&
                    flowform::computeCellQuadrature(type, xy.data(), 1, centroid);
    if (!ok) throw std::logic_error("test cell is inverted");
    h = flowform::cellDiameter(type, xy.data());
  }
  int numDofs() const { return kDofsPerNode * static_cast<int>(xy.size()); }
};

template <typename Scalar, typename PScalar>
inline std::vector<Scalar> residual(const Cell& cell, const FlowKernelSettings& settings,
                             const MaterialParameters<PScalar>& material, const std::vector<Scalar>& dofs) {
  std::vector<Scalar> r(cell.numDofs(), Scalar(0.0));
  flowform::addFlowResidual(cell.rule, cell.centroid, cell.h, settings, material, dofs.data(), r.data());
  return r;
}

inline FlowKernelSettings makeSettings(Geometry geometry, double beta, double fx, double fy) {
  FlowKernelSettings s;
  s.geometry = geometry;
  s.beta = beta;
  s.bodyForce[0] = fx;
  s.bodyForce[1] = fy;
  return s;
}

/// μ(D:D) written out with pow (independent of Material.hpp's exp∘log form).
inline double handViscosity(double ddot, const MaterialParameters<double>& m) {
  const double er = std::sqrt(2.0 / 3.0 * ddot + m.cutoff * m.cutoff);
  const auto& v = m.values;  // the power law: σ0, γ, n
  return (v[0] + std::pow(er / v[1], 1.0 / v[2])) / (3.0 * er);
}

inline double maxAbs(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

/// Every entry of `lib` equals `hand` to `tol` × max|hand| (entries may be near zero, so
/// the comparison is relative to the vector's scale, not entry by entry).
inline bool sameVector(const std::vector<double>& lib, const std::vector<double>& hand, double tol,
                Teuchos::FancyOStream& out) {
  const double scale = maxAbs(hand);
  bool ok = lib.size() == hand.size();
  for (size_t i = 0; ok && i < hand.size(); ++i) {
    const double err = std::abs(lib[i] - hand[i]);
    if (!(err <= tol * scale)) {
      out << "entry " << i << ": kernel " << lib[i] << ", hand " << hand[i] << ", |diff| " << err
          << " > " << tol << " * " << scale << "\n";
      ok = false;
    }
  }
  return ok;
}

}  // namespace
