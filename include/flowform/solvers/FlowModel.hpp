// The discrete flow problem as Newton sees it: F(x), the exact Jacobian J(x) and solves
// with its factorization. Keeps one Jacobian matrix and one factorization, and remembers
// at which x they were computed (the sensitivity solve needs the converged point's).
// Assembling J and factoring it are separate steps (assembleJacobian, factorJacobian);
// the factors belong to the linear solver, chosen by the case (LinearSolverRegistry).
#pragma once

#include <memory>

#include <Teuchos_RCP.hpp>

#include "flowform/assembly/Assembler.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/solvers/LinearSolver.hpp"

namespace flowform {

class FlowModel {
 public:
  FlowModel(Assembler& assembler, std::unique_ptr<LinearSolver> linearSolver);

  const Assembler& assembler() const { return m_assembler; }
  /// Changes the physics (a continuation stage); the factorization no longer matches.
  void setPhysics(const FlowPhysics& physics) {
    m_assembler.setPhysics(physics);
    m_jacobianValid = false;
  }
  Teuchos::RCP<const Map> map() const { return m_jacobian->getRowMap(); }

  /// f = F(x) − c s with the residual shift (s, c) set by setResidualShift (none by default).
  void residual(const Vector& x, Vector& f);
  /// The residual homotopy's shift (NonlinearSolver::residualHomotopy): residual() subtracts
  /// `scale` × `shift` (a constant vector: the Jacobian is unchanged). nullptr removes it.
  void setResidualShift(const Vector* shift, double scale) {
    m_shift = shift;
    m_shiftScale = scale;
  }
  /// Assembles J(x) (the factors no longer match until factorJacobian()).
  void assembleJacobian(const Vector& x);
  /// Factors the assembled J. Throws std::runtime_error when the factorization fails.
  void factorJacobian();
  /// assembleJacobian(x), then factorJacobian().
  void computeJacobian(const Vector& x) {
    assembleJacobian(x);
    factorJacobian();
  }
  /// out = J⁻¹ in, with the factors of the last factorJacobian() (one back-substitution
  /// per column).
  void solve(const MultiVector& in, MultiVector& out) { m_linearSolver->solve(in, out); }
  /// out = J⁻ᵀ in, with the same factors (adjoints).
  void solveTranspose(const MultiVector& in, MultiVector& out) { m_linearSolver->solveTranspose(in, out); }
  /// out = J in.
  void applyJacobian(const Vector& in, Vector& out) const { m_jacobian->apply(in, out); }
  /// Newton's linearization of the viscoplastic stress and of the slip: the dual methods
  /// (assembly/NewtonDual.hpp) when true, the exact tangent when false.
  void useDualLinearization(bool on) {
    m_useDual = on;
    m_dual.clear();
  }
  /// Starts a new Newton solve: the next Jacobian is the exact tangent at its point (the
  /// dual restarts from D/e_r there). The sensitivity solve calls it too, so its K_t is exact.
  void restartLinearization() { m_dual.clear(); }
  /// Forgets the factorization (the physics changed, so J no longer matches).
  void invalidateJacobian() { m_jacobianValid = false; }
  bool hasJacobian() const { return m_jacobianValid; }
  /// Whether the linear solver holds the factors of some earlier Jacobian of this model (they
  /// may no longer match: another x, mesh or physics), which solve() applies.
  bool hasFactors() const { return m_hasFactors; }
  /// The x at which the current Jacobian and its factors were computed (null before the
  /// first). After NOX converges this is the previous iterate, not the converged x.
  Teuchos::RCP<const Vector> jacobianPoint() const { return m_jacobianPoint; }

  int numResiduals() const { return m_numResiduals; }
  int numJacobians() const { return m_numJacobians; }
  const LinearSolver& linearSolver() const { return *m_linearSolver; }
  const FECrsMatrix& jacobian() const { return *m_jacobian; }

 private:
  Assembler& m_assembler;
  Teuchos::RCP<FECrsMatrix> m_jacobian;
  Teuchos::RCP<Vector> m_jacobianPoint;
  const Vector* m_shift = nullptr;
  double m_shiftScale = 0.0;
  std::unique_ptr<LinearSolver> m_linearSolver;
  bool m_jacobianValid = false;
  bool m_hasFactors = false;
  bool m_useDual = false;
  NewtonDual m_dual;
  int m_numResiduals = 0;
  int m_numJacobians = 0;
};

}  // namespace flowform
