#include "flowform/FlowModel.hpp"

namespace flowform {

FlowModel::FlowModel(Assembler& assembler, LinearSolver::Ordering ordering)
    : m_assembler(assembler), m_jacobian(assembler.createJacobian()), m_linearSolver(ordering) {}

void FlowModel::residual(const Vector& x, Vector& f) {
  ++m_numResiduals;
  m_assembler.residual(x, f);
}

void FlowModel::computeJacobian(const Vector& x) {
  ++m_numJacobians;
  m_jacobianValid = false;
  m_assembler.jacobian(x, *m_jacobian);
  m_linearSolver.factor(m_jacobian);
  if (m_jacobianPoint.is_null()) m_jacobianPoint = Teuchos::rcp(new Vector(x.getMap()));
  Tpetra::deep_copy(*m_jacobianPoint, x);
  m_jacobianValid = true;
}

void FlowModel::solve(const MultiVector& in, MultiVector& out) { m_linearSolver.solve(in, out); }

void FlowModel::applyJacobian(const Vector& in, Vector& out) const { m_jacobian->apply(in, out); }

}  // namespace flowform
