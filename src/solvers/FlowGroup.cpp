#include "flowform/solvers/FlowGroup.hpp"

#include <cmath>

#include <Thyra_TpetraThyraWrappers.hpp>

#include "flowform/core/Log.hpp"

namespace flowform {

using Extraction = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;

Teuchos::RCP<Vector> tpetraVector(NOX::Abstract::Vector& v) {
  auto& thyra = dynamic_cast<NOX::Thyra::Vector&>(v);
  return Extraction::getTpetraVector(thyra.getThyraRCPVector());
}

Teuchos::RCP<const Vector> tpetraVector(const NOX::Abstract::Vector& v) {
  const auto& thyra = dynamic_cast<const NOX::Thyra::Vector&>(v);
  return Extraction::getConstTpetraVector(thyra.getThyraRCPVector());
}

Teuchos::RCP<NOX::Thyra::Vector> noxVector(const Teuchos::RCP<Vector>& v) {
  auto space = Thyra::createVectorSpace<double, LO, GO, Node>(v->getMap());
  return Teuchos::rcp(new NOX::Thyra::Vector(Thyra::createVector(v, space)));
}

FlowGroup::FlowGroup(FlowModel& model, const Vector& x0) : m_model(model) {
  auto x = Teuchos::rcp(new Vector(x0, Teuchos::Copy));
  m_x = noxVector(x);
  m_f = m_x->clone(NOX::ShapeCopy);
  m_newton = m_x->clone(NOX::ShapeCopy);
  m_gradient = m_x->clone(NOX::ShapeCopy);
}

FlowGroup::FlowGroup(const FlowGroup& source, NOX::CopyType type) : m_model(source.m_model) {
  m_x = source.m_x->clone(type);
  m_f = source.m_f->clone(type);
  m_newton = source.m_newton->clone(type);
  m_gradient = source.m_gradient->clone(type);
  if (type == NOX::DeepCopy) {
    m_normF = source.m_normF;
    m_isF = source.m_isF;
    m_isJacobian = source.m_isJacobian;
    m_isNewton = source.m_isNewton;
  }
}

Teuchos::RCP<NOX::Abstract::Group> FlowGroup::clone(NOX::CopyType type) const {
  return Teuchos::rcp(new FlowGroup(*this, type));
}

NOX::Abstract::Group& FlowGroup::operator=(const NOX::Abstract::Group& source) {
  const auto& src = dynamic_cast<const FlowGroup&>(source);
  *m_x = *src.m_x;
  *m_f = *src.m_f;
  *m_newton = *src.m_newton;
  m_normF = src.m_normF;
  m_isF = src.m_isF;
  // The model holds one factorization, that of the last computeJacobian(): this group's
  // copy of the flag is only as good as that.
  m_isJacobian = src.m_isJacobian;
  m_isNewton = src.m_isNewton;
  return *this;
}

void FlowGroup::setX(const NOX::Abstract::Vector& y) {
  resetFlags();
  *m_x = y;
}

void FlowGroup::computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d, double step) {
  resetFlags();
  const auto& src = dynamic_cast<const FlowGroup&>(grp);
  m_x->update(1.0, *src.m_x, step, d, 0.0);
}

NOX::Abstract::Group::ReturnType FlowGroup::computeF() {
  if (m_isF) return Ok;
  m_model.residual(*tpetraVector(*m_x), *tpetraVector(*m_f));
  m_normF = m_f->norm();
  m_isF = true;
  // A non-finite norm is left to NOX's FiniteValue status test, which stops with Failed.
  return Ok;
}

NOX::Abstract::Group::ReturnType FlowGroup::computeJacobian() {
  if (m_isJacobian) return Ok;
  try {
    m_model.computeJacobian(*tpetraVector(*m_x));
  } catch (const std::exception& e) {
    log() << "  Jacobian failed: " << e.what() << "\n";
    return Failed;
  }
  m_isJacobian = true;
  return Ok;
}

NOX::Abstract::Group::ReturnType FlowGroup::computeNewton(Teuchos::ParameterList&) {
  if (m_isNewton) return Ok;
  if (!m_isF && computeF() != Ok) return Failed;
  if (!m_isJacobian && computeJacobian() != Ok) return Failed;
  // J dx = −F
  m_model.solve(*tpetraVector(*m_f), *tpetraVector(*m_newton));
  m_newton->scale(-1.0);
  if (!std::isfinite(m_newton->norm())) return Failed;
  m_isNewton = true;
  return Ok;
}

NOX::Abstract::Group::ReturnType FlowGroup::applyJacobian(const NOX::Abstract::Vector& input,
                                                          NOX::Abstract::Vector& result) const {
  if (!m_isJacobian) return BadDependency;
  m_model.applyJacobian(*tpetraVector(input), *tpetraVector(result));
  return Ok;
}

NOX::Abstract::Group::ReturnType FlowGroup::applyJacobianInverse(Teuchos::ParameterList&,
                                                                 const NOX::Abstract::Vector& input,
                                                                 NOX::Abstract::Vector& result) const {
  if (!m_isJacobian) return BadDependency;
  m_model.solve(*tpetraVector(input), *tpetraVector(result));
  return Ok;
}

}  // namespace flowform
