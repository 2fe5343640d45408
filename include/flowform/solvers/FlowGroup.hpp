// A thin NOX::Abstract::Group over FlowModel: NOX drives Newton and the line search, the
// model owns assembly and the Amesos2 factorization. Vectors are Tpetra vectors seen by
// NOX through NOX::Thyra::Vector. (A thin group rather than NOX::Thyra::Group with a
// Thyra model evaluator: we keep the one factorization under our control, so the
// sensitivity solves reuse it, and avoid the Thyra-Amesos2 issues of docs/toolchain.md.)
#pragma once

#include <NOX_Abstract_Group.H>
#include <NOX_Thyra_Vector.H>

#include "flowform/solvers/FlowModel.hpp"

namespace flowform {

/// Tpetra view of a NOX vector made by flowform (a NOX::Thyra::Vector over Tpetra).
Teuchos::RCP<Vector> tpetraVector(NOX::Abstract::Vector& v);
Teuchos::RCP<const Vector> tpetraVector(const NOX::Abstract::Vector& v);
/// A NOX vector that shares `v`'s storage.
Teuchos::RCP<NOX::Thyra::Vector> noxVector(const Teuchos::RCP<Vector>& v);

class FlowGroup : public NOX::Abstract::Group {
 public:
  /// Starts at x0 (copied); the model is shared by all clones.
  FlowGroup(FlowModel& model, const Vector& x0);
  FlowGroup(const FlowGroup& source, NOX::CopyType type);

  NOX::Abstract::Group& operator=(const NOX::Abstract::Group& source) override;
  void setX(const NOX::Abstract::Vector& y) override;
  void computeX(const NOX::Abstract::Group& grp, const NOX::Abstract::Vector& d, double step) override;

  ReturnType computeF() override;
  ReturnType computeJacobian() override;
  ReturnType computeNewton(Teuchos::ParameterList& params) override;
  ReturnType applyJacobian(const NOX::Abstract::Vector& input, NOX::Abstract::Vector& result) const override;
  ReturnType applyJacobianInverse(Teuchos::ParameterList& params, const NOX::Abstract::Vector& input,
                                  NOX::Abstract::Vector& result) const override;

  bool isF() const override { return m_isF; }
  bool isJacobian() const override { return m_isJacobian; }
  bool isNewton() const override { return m_isNewton; }

  const NOX::Abstract::Vector& getX() const override { return *m_x; }
  const NOX::Abstract::Vector& getF() const override { return *m_f; }
  double getNormF() const override { return m_normF; }
  const NOX::Abstract::Vector& getGradient() const override { return *m_gradient; }
  const NOX::Abstract::Vector& getNewton() const override { return *m_newton; }
  Teuchos::RCP<const NOX::Abstract::Vector> getXPtr() const override { return m_x; }
  Teuchos::RCP<const NOX::Abstract::Vector> getFPtr() const override { return m_f; }
  Teuchos::RCP<const NOX::Abstract::Vector> getGradientPtr() const override { return m_gradient; }
  Teuchos::RCP<const NOX::Abstract::Vector> getNewtonPtr() const override { return m_newton; }

  Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type = NOX::DeepCopy) const override;

 private:
  void resetFlags() { m_isF = m_isJacobian = m_isNewton = false; }

  FlowModel& m_model;
  Teuchos::RCP<NOX::Abstract::Vector> m_x, m_f, m_newton, m_gradient;
  double m_normF = 0.0;
  bool m_isF = false, m_isJacobian = false, m_isNewton = false;
};

}  // namespace flowform
