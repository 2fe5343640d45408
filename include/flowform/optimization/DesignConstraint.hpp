// The constraints ROL holds the design to (docs/optimization.md §1): responses within bounds,
//   lower_i <= φ_i(h(z)) <= upper_i,
// on the scaled design z of DesignObjective, each response divided by the magnitude of its bound
// (c_i = φ_i / s_i, s_i = the larger finite |bound|, 1 if that is 0), so that one feasibility
// tolerance fits constraints of any unit. The Jacobian comes from the same solve's DDM derivatives,
// dc_i/dz_j = (dφ_i/dh_j)(upper_j − lower_j)/s_i; the constraints' second derivatives are not
// known (ROL's augmented Lagrangian is asked for its Gauss–Newton level, which does not read them).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <ROL_Bounds.hpp>
#include <ROL_Constraint.hpp>

#include "flowform/optimization/DesignObjective.hpp"

namespace flowform {

class DesignConstraint : public ROL::Constraint<double> {
 public:
  DesignConstraint(const OptimizationSettings& settings, DesignRuns& runs, const DesignObjective& objective);

  void value(ROL::Vector<double>& c, const ROL::Vector<double>& z, double& tol) override;
  void applyJacobian(ROL::Vector<double>& jv, const ROL::Vector<double>& v, const ROL::Vector<double>& z,
                     double& tol) override;
  void applyAdjointJacobian(ROL::Vector<double>& ajv, const ROL::Vector<double>& v, const ROL::Vector<double>& z,
                            double& tol) override;
  /// Not known: zero (the Gauss–Newton model of the constraints).
  void applyAdjointHessian(ROL::Vector<double>& ahuv, const ROL::Vector<double>& u, const ROL::Vector<double>& v,
                           const ROL::Vector<double>& z, double& tol) override;

  /// The scaled bounds [lower_i/s_i, upper_i/s_i] (±inf where a side has none).
  ROL::Ptr<ROL::Bounds<double>> bounds() const;
  /// A zero vector of the constraints' space.
  ROL::Ptr<ROL::Vector<double>> zero() const;
  /// s_i.
  const std::vector<double>& scales() const { return m_scale; }
  /// The largest violation of a bound at a solved design, scaled (0 when every bound holds).
  double violation(const std::map<std::string, double>& functionals) const;
  /// c_i and dc_i/dz_j at the scaled design z (solved now unless solved before).
  std::vector<double> values(const std::vector<double>& z);
  std::vector<std::vector<double>> jacobian(const std::vector<double>& z);
  /// The scaled bounds lower_i/s_i, upper_i/s_i (±inf where a side has none).
  std::vector<double> scaledLower() const;
  std::vector<double> scaledUpper() const;

 private:

  const OptimizationSettings& m_settings;
  DesignRuns& m_runs;
  const DesignObjective& m_objective;
  std::vector<double> m_scale;
};

}  // namespace flowform
