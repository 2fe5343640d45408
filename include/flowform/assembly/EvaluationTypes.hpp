// The evaluation types of the one templated assembly loop (Albany's EvalT and gather/
// scatter, without Phalanx):
//
//   ResidualEval   double                    values: F(x)
//   JacobianEval   Sacado SFad<double, N>    N = the dofs of a cell (or of a wall node's
//                                            stencil): F(x) and J = dF/dx
//   TangentEval    TangentFad = SFad<1>      x seeded along a direction dx and a parameter h
//                                            seeded (derivative 1): J dx + ∂F/∂h in one pass,
//                                            ∂F/∂h with dx = 0
//   (responses)    GradientFad = DFad        every dof of a workset its own independent variable
//                                            (slot = offset + dof): a response's gradient ∂φ/∂q,
//                                            the adjoint's right-hand side (responses/Responses.hpp)
//
// gather() reads an element's dofs from the workset and seeds them as the type wants;
// scatter() adds the element rows back (values, matrix rows, or directional derivatives).
// These two and the parameter seeding below are the only places that seed or read
// derivatives; the kernels and the friction laws never do.
#pragma once

#include <type_traits>
#include <vector>

#include <Sacado.hpp>

#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/physics/Material.hpp"
#include "flowform/assembly/NewtonDual.hpp"

namespace flowform {

using TangentFad = Sacado::Fad::SFad<double, 1>;
/// A response's gradient: one derivative component per dof a response may read (its size is set
/// by the workset, Workset::gradientSize).
using GradientFad = Sacado::Fad::DFad<double>;

struct ResidualEval {
  template <int N>
  using Scalar = double;
  using ParamScalar = double;
};
struct JacobianEval {
  template <int N>
  using Scalar = Sacado::Fad::SFad<double, N>;
  using ParamScalar = double;
};
struct TangentEval {
  template <int N>
  using Scalar = TangentFad;
  using ParamScalar = TangentFad;
};

/// A value with one directional derivative (val, d) for the tangent evaluations.
template <typename T>
T dual(double value, double derivative) {
  T t(1, value);
  t.fastAccessDx(0) = derivative;
  return t;
}

/// The material with h seeded (PScalar TangentFad); PScalar double: the values.
template <typename PScalar>
MaterialParameters<PScalar> materialFor(const MaterialParameters<double>& m, const SensitivityParameter* h) {
  if constexpr (std::is_same_v<PScalar, double>) {
    return m;
  } else {
    MaterialParameters<PScalar> p;
    p.law = m.law;
    for (int i = 0; i < kMaxMaterialParameters; ++i)
      p.values[i] = h && h->kind == ParameterKind::Material && h->material == i ? PScalar(1, 0, m.values[i])
                                                                                 : PScalar(m.values[i]);
    p.cutoff = PScalar(m.cutoff);
    return p;
  }
}

/// k, ρc, η of `p`, with h seeded when it is one of them ("Thermal:<name>"; PScalar TangentFad).
template <typename PScalar>
ThermalParameters<PScalar> thermalFor(const ThermalProperties& p, const SensitivityParameter* h) {
  if constexpr (std::is_same_v<PScalar, double>) {
    return {p.conductivity, p.capacity(), p.heatFraction};
  } else {
    auto seed = [&](int i) {
      return h && h->kind == ParameterKind::Thermal && h->thermal == i ? PScalar(1, 0, p.value(i)) : PScalar(p.value(i));
    };
    return {seed(kConductivity), seed(kDensity) * seed(kSpecificHeat), seed(kHeatFraction)};
  }
}

/// Wall `w`'s ν and m, with h seeded where h enters that wall (PScalar TangentFad).
template <typename PScalar>
FrictionParameters<PScalar> frictionFor(const ContactWall& wall, int w, const SensitivityParameter* h) {
  const FrictionParameters<double> fp = wall.frictionParameters();
  if constexpr (std::is_same_v<PScalar, double>) {
    return fp;
  } else {
    const bool seeded = h && h->entersWall(w, wall);
    auto seed = [&](double value, ParameterKind kind) {
      return seeded && h->kind == kind ? PScalar(1, 0, value) : PScalar(value);
    };
    FrictionParameters<PScalar> out{seed(fp.frictionCoefficient, ParameterKind::FrictionCoefficient),
                                    seed(fp.shearFactor, ParameterKind::ShearFactor)};
    if (seeded && h->kind == ParameterKind::FrictionField) out.seededStation = h->station;
    return out;
  }
}

using HostView = decltype(std::declval<const Vector&>().getLocalViewHost(Tpetra::Access::ReadOnly));
using HostViewRW = decltype(std::declval<Vector&>().getLocalViewHost(Tpetra::Access::ReadWrite));

/// What one evaluation reads and writes, on the overlap map: x, the direction dx (tangent
/// only), the residual f and the matrix (each optional).
struct Workset {
  const DofMap* dofMap = nullptr;
  HostView x, dx;
  bool hasDirection = false;
  HostViewRW f;
  bool hasResidual = false;
  FECrsMatrix* jacobian = nullptr;
  NewtonDual* dual = nullptr;  ///< Jacobian only: the dual linearizations (null: exact)
  /// GradientFad only: dof d is independent variable gradientOffset + d of gradientSize.
  int gradientSize = 0, gradientOffset = 0;
};

/// The element's dofs at overlap dofs `dofs[0..n)` (−1: an absent neighbour, value 0 and
/// no derivative), seeded for Scalar: SFad<n> seeds dof i as independent variable i; the
/// tangent type carries dx along.
template <typename Scalar>
void gather(const Workset& ws, const LO* dofs, int n, Scalar* out) {
  for (int i = 0; i < n; ++i) {
    const LO d = dofs[i];
    if (d < 0) {
      out[i] = Scalar(0.0);
    } else if constexpr (std::is_same_v<Scalar, double>) {
      out[i] = ws.x(d, 0);
    } else if constexpr (std::is_same_v<Scalar, TangentFad>) {
      out[i] = dual<TangentFad>(ws.x(d, 0), ws.hasDirection ? ws.dx(d, 0) : 0.0);
    } else if constexpr (std::is_same_v<Scalar, GradientFad>) {
      out[i] = GradientFad(ws.gradientSize, ws.gradientOffset + d, ws.x(d, 0));
    } else {
      out[i] = Scalar(n, i, ws.x(d, 0));
    }
  }
}

/// Adds element rows res[0..nrows) into overlap rows `rows`: values (double), directional
/// derivatives (TangentFad), or matrix rows over the columns of the gathered `dofs[0..n)`
/// (absent ones skipped) and, when the workset has a residual, the values (SFad).
template <typename Scalar>
void scatter(Workset& ws, const LO* rows, int nrows, const LO* dofs, int n, const Scalar* res) {
  if constexpr (std::is_same_v<Scalar, double>) {
    for (int r = 0; r < nrows; ++r) ws.f(rows[r], 0) += res[r];
  } else if constexpr (std::is_same_v<Scalar, TangentFad>) {
    for (int r = 0; r < nrows; ++r) ws.f(rows[r], 0) += res[r].dx(0);
  } else {
    constexpr int kMax = Sacado::StaticSize<Scalar>::value;  // SFad<double, N>: N
    LO cols[kMax];
    double values[kMax];
    for (int r = 0; r < nrows; ++r) {
      int m = 0;
      for (int j = 0; j < n; ++j) {
        if (dofs[j] < 0) continue;
        cols[m] = ws.dofMap->column(dofs[j]);
        values[m++] = res[r].dx(j);
      }
      ws.jacobian->sumIntoLocalValues(rows[r], m, values, cols);
      if (ws.hasResidual) ws.f(rows[r], 0) += res[r].val();
    }
  }
}

}  // namespace flowform
