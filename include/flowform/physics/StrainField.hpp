// The equivalent strain as a field carried by the flow (a case with Material/Strain Field;
// docs/theory.md §1.1). In the Eulerian steady state a material point's strain is what it gathered
// along its streamline, so ε obeys
//
//   u·∇ε = ė,   ė = e_r − e0 = e² / (e_r + e0)
//
// ė is the equivalent strain rate e = sqrt(2/3 D:D) without the cutoff's floor (e_r = sqrt(e² +
// e0²) would make a rigid zone strain at the rate e0); written through e_r it is smooth at D = 0.
// ε = ε_b on the groups that give `Strain` (the inflow: the billet enters with its strain), and
// k ∂ε/∂n = 0 elsewhere. The rows are physics/TransportResidual.hpp's with capacity 1, source ė and
// the cell diffusivity
//
//   κ_K = e0 h_K²,
//
// which gives a dead zone (u ≈ 0: no streamline from the inflow reaches it, and u·∇ε = ė alone
// leaves its ε undetermined) the strain of its surroundings; where the metal flows its cell Péclet
// number |u| / (2 e0 h_K) is 10³–10⁵ and it is negligible (an O(h²) consistency error).
//
// A law with a "Strain" parameter (Hensel–Spittel) reads, at each cell's centroid,
//
//   ε̃ = ( r^−8 + ε_max^−8 )^(−1/8),   r = sqrt(ε_K² + ε_min²)
//
// — ε_K held smoothly within [ε_min, ε_max], the range hot-working constants are fitted over
// (beyond it forming codes hold the law constant). Minimum Strain ε_min > 0: the fitted laws'
// ε^m2 e^(m4/ε) have no limit at ε → 0, and the stabilized ε_h may dip below 0 near steep layers.
// Maximum Strain ε_max: a dead zone's strain is large and ill-determined (the field's rows there
// are κ_K's alone), and Newton's steps move it by 10⁴ while the flow is far from converged; read
// unbounded, those excursions soften the law to nothing and Newton stalled on every refined mesh
// of the hot Hensel–Spittel extrusion. ε̃ = ε within 0.3 % for 13 ε_min ≤ ε ≤ 0.6 ε_max. Its
// derivative with respect to the strain dofs is the Jacobian's block ∂R_u/∂ε (Sacado).
//
// The coupling is switched on by the solver's continuation (NonlinearSolver): at its parameter
// λ ∈ [0, 1] the law reads ε̂ = ε_u^(1−λ) ε̃^λ, ε_u the law's own uniform Strain, so that the first
// stages solve a flow that does not yet feel the strain field (its strain is still computed) and
// λ = 1 is the coupled problem exactly. Hardening at small strain (m4 < 0) makes the metal entering
// the deformation zone half as strong as the rest; started from the Newtonian predictor with the
// full coupling, Newton diverged on the hot Hensel–Spittel extrusion.
#pragma once

#include <cmath>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/physics/TransportResidual.hpp"

namespace flowform {

/// Material/Strain Field.
struct StrainFieldSettings {
  double minimumStrain = 0.05;  ///< ε_min > 0
  double maximumStrain = 5.0;   ///< ε_max > ε_min
  double coupling = 1.0;        ///< λ: the law reads ε_u^(1−λ) ε̃^λ (the solver's continuation sets it)

  /// The entries of Material/Strain Field, with their ranges.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// From a validated Material/Strain Field sublist.
  static StrainFieldSettings fromParameters(const Teuchos::ParameterList& list);
};

/// ε̃ = sqrt(ε² + ε_min²) held below ε_max: (ε̃^−8 + ε_max^−8)^(−1/8), the strain a law reads.
template <typename Scalar>
Scalar lawStrain(const Scalar& strain, const StrainFieldSettings& settings) {
  using std::pow;
  using std::sqrt;
  const double emin = settings.minimumStrain, emax = settings.maximumStrain;
  const Scalar regularized = sqrt(strain * strain + emin * emin);
  return pow(pow(regularized, -8.0) + std::pow(emax, -8.0), -0.125);
}

/// ε̂ = ε_u^(1−λ) ε̃^λ, the strain the law reads at coupling λ (ε̃ itself at λ = 1).
template <typename Scalar, typename PScalar>
Scalar coupledLawStrain(const Scalar& fieldStrain, const PScalar& uniformStrain, const StrainFieldSettings& settings) {
  using std::exp;
  using std::log;
  const Scalar regularized = lawStrain(fieldStrain, settings);
  if (settings.coupling == 1.0) return regularized;
  return exp((1.0 - settings.coupling) * log(uniformStrain) + settings.coupling * log(regularized));
}

/// Adds the strain rows R_ε (TransportResidual.hpp: capacity 1, κ_K = e0 h_K², source e_r − e0) into
/// `residual`; `strainRate[q]` is e_r at point q of `cq` (addFlowResidual's output), `cutoff` e0.
template <typename Scalar, typename PScalar>
void addStrainResidual(const CellQuadrature& cq, Geometry geometry, double hK, const PScalar& cutoff,
                       const Scalar* values, int stride, int slot, const Scalar* strainRate, Scalar* residual) {
  Scalar rate[kMaxQuadraturePoints];
  for (int q = 0; q < cq.numPoints; ++q) rate[q] = strainRate[q] - cutoff;
  const PScalar diffusivity = cutoff * (hK * hK);
  addTransportResidual(cq, geometry, hK, 1.0, diffusivity, values, stride, slot, rate, residual);
}

}  // namespace flowform
