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
  explicit FlowModel(Assembler& assembler);

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
  /// out = J⁻¹ in, with the factors of the last computeJacobian().
  void solve(const Vector& in, Vector& out);
  /// out = J in.
  void applyJacobian(const Vector& in, Vector& out) const;
  /// Forgets the factorization (the physics changed, so J no longer matches).
  void invalidateJacobian() { m_jacobianValid = false; }
  bool hasJacobian() const { return m_jacobianValid; }

  int numResiduals() const { return m_numResiduals; }
  int numJacobians() const { return m_numJacobians; }
  const LinearSolver& linearSolver() const { return m_linearSolver; }
  const FECrsMatrix& jacobian() const { return *m_jacobian; }

 private:
  Assembler& m_assembler;
  Teuchos::RCP<FECrsMatrix> m_jacobian;
  LinearSolver m_linearSolver;
  bool m_jacobianValid = false;
  int m_numResiduals = 0;
  int m_numJacobians = 0;
};

}  // namespace flowform
