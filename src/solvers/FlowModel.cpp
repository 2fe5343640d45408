#include "flowform/solvers/FlowModel.hpp"

namespace flowform {

FlowModel::FlowModel(Assembler& assembler, std::unique_ptr<LinearSolver> linearSolver)
    : m_assembler(assembler), m_jacobian(assembler.createJacobian()), m_linearSolver(std::move(linearSolver)) {}

void FlowModel::residual(const Vector& x, Vector& f) {
  ++m_numResiduals;
  m_assembler.residual(x, f);
  if (m_shift) f.update(-m_shiftScale, *m_shift, 1.0);
}

void FlowModel::assembleJacobian(const Vector& x) {
  ++m_numJacobians;
  m_jacobianValid = false;
  m_assembler.jacobian(x, *m_jacobian, nullptr, m_useDual ? &m_dual : nullptr);
  if (m_jacobianPoint.is_null()) m_jacobianPoint = Teuchos::rcp(new Vector(x.getMap()));
  Tpetra::deep_copy(*m_jacobianPoint, x);
}

void FlowModel::factorJacobian() {
  m_jacobianValid = m_hasFactors = false;
  m_linearSolver->factor(m_jacobian);
  m_jacobianValid = m_hasFactors = true;
}

}  // namespace flowform
