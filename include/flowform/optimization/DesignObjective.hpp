// The objective ROL minimizes (docs/optimization.md §1), on the scaled design z ∈ [0, 1]^n,
// h_i = lower_i + z_i (upper_i − lower_i), so that one tolerance and one trust-region radius fit
// parameters of any unit:
//   a response:  J(z) = ± φ(h(z)) / |φ(h_0)|     (+ to minimize, − to maximize; |φ(h_0)| = 1 if 0)
//   a misfit:    J(z) = ½ Σ_i r_i²,  r_i = (φ_i(h(z)) − m_i) / σ_i
// with ∇J from the DDM derivatives (DesignRuns): dJ/dz_j = dJ/dh_j (upper_j − lower_j). The
// misfit's Hessian is Gauss–Newton's, H v = Aᵀ(A v), A_ij = dr_i/dz_j: exact to first order in
// the residuals and free (no solve); a response's is ROL's secant (L-BFGS).
#pragma once

#include <ROL_Objective.hpp>

#include "flowform/optimization/DesignRuns.hpp"
#include "flowform/optimization/OptimizationSettings.hpp"

namespace flowform {

class DesignObjective : public ROL::Objective<double> {
 public:
  /// `scale`: |φ(h_0)| when known (a later remeshing cycle keeps the first one's), else 0: the
  /// first solve's.
  DesignObjective(const OptimizationSettings& settings, DesignRuns& runs, double scale = 0.0);

  double value(const ROL::Vector<double>& z, double& tol) override;
  void gradient(ROL::Vector<double>& g, const ROL::Vector<double>& z, double& tol) override;
  void hessVec(ROL::Vector<double>& hv, const ROL::Vector<double>& v, const ROL::Vector<double>& z,
               double& tol) override;

  /// The physical design of a scaled one, and back.
  std::vector<double> design(const std::vector<double>& z) const;
  std::vector<double> scaled(const std::vector<double>& h) const;
  /// J and the misfit's residuals r_i and their Jacobian dr_i/dh_j (physical h) at a solved design.
  double objective(const DesignSolution& s) const;
  std::vector<double> residuals(const DesignSolution& s) const;
  std::vector<std::vector<double>> residualJacobian(const DesignSolution& s) const;
  /// dJ/dz at a solved design.
  std::vector<double> scaledGradient(const DesignSolution& s) const;
  /// |φ(h_0)|, the response objective's scale.
  double scale() const { return m_scale; }
  /// dφ/dh of a solved design (DesignNotSolved when the solve did not differentiate φ by h).
  double derivative(const DesignSolution& s, const std::string& response, const std::string& parameter) const;

 private:
  const DesignSolution& solved(const ROL::Vector<double>& z);

  const OptimizationSettings& m_settings;
  DesignRuns& m_runs;
  double m_scale = 1.0;
  bool m_scaleKnown = false;
};

}  // namespace flowform
