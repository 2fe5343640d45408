// The discrete flow problem as Newton sees it: F(x), the exact Jacobian J(x) and solves
// with its factorization. Keeps one Jacobian matrix and one factorization, and remembers
// at which x they were computed (the sensitivity solve needs the converged point's).
#pragma once

#include <Teuchos_RCP.hpp>

#include "flowform/Assembler.hpp"
#include "flowform/LinearSolver.hpp"
#include "flowform/TpetraTypes.hpp"

namespace flowform {

class FlowModel {
 public:
  explicit FlowModel(Assembler& assembler,
                     LinearSolver::Ordering ordering = LinearSolver::Ordering::NestedDissection);

  const Assembler& assembler() const { return m_assembler; }
  /// Changes the physics (a continuation stage); the factorization no longer matches.
  void setPhysics(const FlowPhysics& physics) {
    m_assembler.setPhysics(physics);
    m_jacobianValid = false;
  }
  Teuchos::RCP<const Map> map() const { return m_jacobian->getRowMap(); }

  /// f = F(x).
  void residual(const Vector& x, Vector& f);
  /// Assembles J(x) and factors it. Throws std::runtime_error when the factorization fails.
  void computeJacobian(const Vector& x);
  /// out = J⁻¹ in, with the factors of the last computeJacobian() (one back-substitution
  /// per column).
  void solve(const MultiVector& in, MultiVector& out);
  /// out = J in.
  void applyJacobian(const Vector& in, Vector& out) const;
  /// Forgets the factorization (the physics changed, so J no longer matches).
  void invalidateJacobian() { m_jacobianValid = false; }
  bool hasJacobian() const { return m_jacobianValid; }
  /// The x at which the current Jacobian and its factors were computed (null before the
  /// first). After NOX converges this is the previous iterate, not the converged x.
  Teuchos::RCP<const Vector> jacobianPoint() const { return m_jacobianPoint; }

  int numResiduals() const { return m_numResiduals; }
  int numJacobians() const { return m_numJacobians; }
  const LinearSolver& linearSolver() const { return m_linearSolver; }
  const FECrsMatrix& jacobian() const { return *m_jacobian; }

 private:
  Assembler& m_assembler;
  Teuchos::RCP<FECrsMatrix> m_jacobian;
  Teuchos::RCP<Vector> m_jacobianPoint;
  LinearSolver m_linearSolver;
  bool m_jacobianValid = false;
  int m_numResiduals = 0;
  int m_numJacobians = 0;
};

}  // namespace flowform
