// Sensitivity by direct differentiation (docs/theory.md §4, paper §3). At the converged solution q of
// R(q; h) = 0 the derivative of the equations along h is (paper eqs. 24–27)
//
//     K_t dq/dh = −∂R/∂h,        K_t = ∂R/∂q at the converged q,
//
// and a functional φ(q; h) has (eq. 21) dφ/dh = ∂φ/∂h + ∂φ/∂q dq/dh. ∂R/∂h comes from the
// same templated residual with h seeded (Assembler::parameterDerivative); dφ/dh from the
// responses evaluated on a directional-derivative Fad (Responses::derivatives).
//
// Cost: K_t is factored once for all parameters and each parameter costs one back-
// substitution (all right-hand sides go to the direct solver as one MultiVector).
//
// Method = Adjoint (docs/sensitivity.md "Adjoint"): with λ_φ from K_tᵀ λ_φ = (∂φ/∂q)ᵀ, one
// transposed back-substitution per response,
//     dφ/dh = ∂φ/∂h − λ_φ · ∂R/∂h,
// the same number in exact arithmetic, for many parameters and few responses; no dq/dh is made
// (no sensitivity fields; no total derivative through free surfaces; no Rigid Inflow).
// "Jacobian" chooses the factors: "Converged" assembles and factors K_t at the converged q
// (one factorization); "Last Newton Iterate" reuses the factors NOX leaves, which belong to
// the iterate before the converged one (no factorization; docs/sensitivity.md measures what
// this costs in accuracy).
//
// Held fixed (docs/sensitivity.md): the contact penalty scales μ_k and the Tresca σ̄_k, which
// the solver takes from the solution at the start of each Newton solve (ContactWall::
// setScales); dq/dh is that of the problem with these scales frozen. The contact status is
// fixed too: the derivative is that of the converged branch of every node.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <nlohmann/json_fwd.hpp>

#include "flowform/discretization/DofMap.hpp"
#include "flowform/solvers/FlowModel.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/responses/Responses.hpp"
#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/sensitivity/GeoParameterMotion.hpp"

namespace flowform {

struct RigidInflowLinearization;  // problem/Problem.hpp

class Sensitivity {
 public:
  /// The "Sensitivity" sublist: Parameters, Jacobian, and the finite-difference check.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// `list` is the case's validated "Sensitivity" sublist, or null when the case has none
  /// (then nothing is requested and compute() is never called). InputError for a bad
  /// parameter name, a repeated one, or a response whose name a check entry uses.
  /// `materialLaw` (an index of materialLaws()) gives the material's sensitivity parameters.
  /// `geo`: the case's Mesh/Geo Parameters, which "Geo Parameter:<name>" may name.
  Sensitivity(const Teuchos::ParameterList* list, const std::vector<ContactWall>& walls, const Responses& responses,
              int materialLaw, const GeoParameterValues& geo = {}, const BoundaryValues& boundary = {},
              const FieldRegistry& fields = FieldRegistry::flow());

  bool requested() const { return !m_parameters.empty(); }
  const std::vector<SensitivityParameter>& parameters() const { return m_parameters; }
  bool checkRequested() const { return requested() && m_check; }
  /// The requested finite-difference step (absolute for ν and m, relative for the material parameters).
  double step() const { return m_step; }
  /// Whether the finite-difference runs hold the base run's contact penalty scales.
  bool holdScalesInCheck() const { return m_holdScales; }
  /// With free surfaces: whether the derivatives through the moving shape are wanted.
  bool totalShapeRequested() const { return m_totalShapeRequested; }
  /// The derivatives through the moving free surfaces (sensitivity/ShapeDerivative), when made:
  /// response → parameter → value (the finite-difference check compares them with its
  /// re-converged runs).
  void setTotalShapeDerivatives(std::map<std::string, std::map<std::string, double>> d) { m_totalShape = std::move(d); }
  const std::map<std::string, std::map<std::string, double>>& totalShapeDerivatives() const { return m_totalShape; }

  /// dq/dh for every parameter at the converged x, then dφ/dh for every response. With `inflow`
  /// (a Rigid Inflow's speed U, an unknown of the flow: Problem::rigidInflowLinearization), dq/dh
  /// is the bordered system's, (dq/dh)_U + (dU/dh) g with K g = −∂f/∂U, dU/dh = −(dF/dh)_U / (dF/dU).
  /// A Geo Parameter's ∂R/∂h, ∂φ/∂h (and ∂F/∂h of the inflow's balance) come from `geo` (the mesh
  /// moved along the parameter's motion: GeoParameterMotion), needed when one is asked for.
  void compute(FlowModel& model, const Vector& x, const Responses& responses, const Mesh& mesh, const DofMap& dofMap,
               const std::vector<ContactWall>& walls, const RigidInflowLinearization* inflow = nullptr,
               const GeoPartialsSource* geo = nullptr);
  /// The mesh velocity V = dX/dh of each Geo Parameter (by name), after compute().
  const std::map<std::string, std::vector<std::array<double, 2>>>& geoMotions() const { return m_geoMotions; }

  /// Whether the derivatives were computed (compute() ran and they are finite).
  bool computed() const { return m_computed; }
  /// Method = Adjoint: the responses' derivatives by λ_φ, without dq/dh.
  bool adjoint() const { return m_adjoint; }
  /// InputError when the case needs dq/dh and the method gives none: Method = Adjoint with a Rigid
  /// Inflow (`rigidInflow`), or with free surfaces (`freeSurfaces`) and Shape Derivative = Total.
  void checkMethod(bool rigidInflow, bool freeSurfaces) const;
  /// Whether dq/dh was made (Method = Direct, after compute()).
  bool hasSolutionDerivatives() const { return !m_dqdh.is_null(); }
  /// Column j is dq/dh_j (owned map). Only when hasSolutionDerivatives().
  const MultiVector& solutionDerivatives() const { return *m_dqdh; }
  /// dφ/dh: response name → parameter name → value.
  const std::map<std::string, std::map<std::string, double>>& responseDerivatives() const {
    return m_responseDerivatives;
  }
  /// False when K_t could not be factored or a dq/dh holds NaN or Inf (singular K_t): the
  /// run then exits 3, without sensitivities.
  bool finite() const { return m_finite; }

  /// "sensitivities" (response → parameter → dφ/dh) and "sensitivity" (what was done and
  /// what it cost: factorizations, solves, the Jacobian used) into the summary.
  void report(nlohmann::json& summary) const;

 private:
  std::vector<SensitivityParameter> m_parameters;
  bool m_check = false;
  double m_step = 2e-4;
  bool m_holdScales = true;
  bool m_lastNewtonJacobian = false;
  bool m_totalShapeRequested = true;
  bool m_adjoint = false;
  bool m_computed = false;
  std::map<std::string, std::map<std::string, double>> m_totalShape;
  /// The responses to differentiate (Responses; all the differentiable ones by default); with
  /// Method = Adjoint, one adjoint λ_φ each.
  std::vector<std::string> m_responseNames;

  Teuchos::RCP<MultiVector> m_dqdh;
  std::map<std::string, std::map<std::string, double>> m_responseDerivatives;
  bool m_finite = true;
  int m_factorizations = 0, m_solves = 0;
  std::string m_jacobianUsed;
  double m_jacobianOffset = 0.0;  ///< ||q − q_J|| / ||q||, q_J where the factors were computed
  std::vector<double> m_rhsNorms, m_solutionNorms;
  /// With a Rigid Inflow: dF/dU (the DDM's, at fixed statuses) and dU/dh per parameter.
  bool m_inflow = false;
  double m_inflowForceSlope = 0.0;
  std::map<std::string, double> m_inflowSpeedDerivatives;
  std::map<std::string, std::vector<std::array<double, 2>>> m_geoMotions;

  /// −∂R/∂h_j into column j of `rhs` for every parameter (the mesh's partials where given).
  void assembleParameterLoads(FlowModel& model, const Vector& x, const std::map<std::string, MeshPartials>& partials,
                              MultiVector& rhs) const;
  /// Method = Adjoint: dφ/dh = ∂φ/∂h − λ_φ·∂R/∂h with K_t factored at x.
  void computeByAdjoint(FlowModel& model, const Vector& x, const Responses& responses, const Mesh& mesh,
                        const DofMap& dofMap, const std::vector<ContactWall>& walls,
                        const std::map<std::string, MeshPartials>& partials);
};

}  // namespace flowform
