// Newton's status tests and its log (NonlinearSolver's NOX solves): the residual-and-step
// convergence test with its round-off rules, the wall-clock budget test, the per-iteration log.
#pragma once

#include <iomanip>
#include <limits>
#include <string>
#include <vector>

#include <NOX_Observer.hpp>
#include <NOX_Solver_LineSearchBased.H>
#include <NOX_StatusTest_Generic.H>

#include "flowform/core/Budget.hpp"
#include "flowform/core/Log.hpp"

namespace flowform {

/// Converged when the residual is small, absolutely or relative to the stage's first
/// residual, AND the last Newton update is small relative to the solution:
///   (||F|| ≤ atol  or  ||F|| ≤ rtol ||F_0||)  and  ||Δx|| ≤ utol (||x|| + utol),
/// or when Newton has reached the round-off floor: a full step (no line-search cut) with
///   ||Δx|| ≤ 10³ ε ||x||,
/// a correction at the rounding level of x itself, which further iterations cannot improve.
/// The residual then stays at about ε ||J|| ||x||, which atol (an absolute number) does not
/// know: with velocities of order 10³ (channel, γ = 10³) it is 2.6·10⁻¹⁰ against
/// atol = 10⁻¹⁰, and Newton would stagnate there until the iteration limit.
/// The floor is also recognized when the line search cuts the steps (the residual is noise
/// there, so it cannot decrease): converged when ||F|| has not halved over the last three
/// iterations, the full Newton step ||Δx||/step is within the update tolerance, and ||F||
/// is already below 10⁻⁶ ||F_0|| (so a Newton stuck far from a solution is never taken for
/// it). Seen on the channel with n = 7, e0 = 10⁻⁵ (velocities ~10³): ||F|| stalls at
/// 2·10⁻⁹ with full steps of 10⁻⁸ against ||x|| ~ 10⁴.
class ResidualAndStepTest : public NOX::StatusTest::Generic {
 public:
  ResidualAndStepTest(double atol, double rtol, double utol) : m_atol(atol), m_rtol(rtol), m_utol(utol) {}

  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override {
    const auto& group = solver.getSolutionGroup();
    m_normF = group.getNormF();
    if (solver.getNumIterations() == 0) {
      m_normStart = m_normF;
      m_normF0 = m_reference > 0.0 ? m_reference : m_normF;
      m_history.assign(1, m_normF);
      m_status = m_normF <= m_atol ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
      return m_status;
    }
    if (m_scratch.is_null()) m_scratch = group.getX().clone(NOX::ShapeCopy);
    m_scratch->update(1.0, group.getX(), -1.0, solver.getPreviousSolutionGroup().getX(), 0.0);
    m_normDx = m_scratch->norm();
    const double normX = group.getX().norm();
    const bool residualOk = m_normF <= m_atol || m_normF <= m_rtol * m_normF0;
    const bool stepOk = m_normDx <= m_utol * (normX + m_utol);
    m_step = 1.0;
    if (auto ls = dynamic_cast<const NOX::Solver::LineSearchBased*>(&solver)) m_step = ls->getStepSize();
    m_atRoundoff = !residualOk && m_step == 1.0 && m_normDx <= kRoundoffSteps * kEpsilon * normX;
    m_history.push_back(m_normF);
    const size_t k = m_history.size();
    const bool fullStepOk = m_step > 0.0 && m_normDx / m_step <= m_utol * (normX + m_utol);
    m_stagnated = !residualOk && k > 3 && m_normF > 0.5 * m_history[k - 4] && fullStepOk &&
                  m_normF <= kFloorReduction * m_normF0;
    m_status = (residualOk && stepOk) || m_atRoundoff || m_stagnated ? NOX::StatusTest::Converged
                                                                     : NOX::StatusTest::Unconverged;
    return m_status;
  }
  NOX::StatusTest::StatusType getStatus() const override { return m_status; }
  std::ostream& print(std::ostream& os, int indent) const override {
    os << std::string(indent, ' ') << "residual " << m_normF << " (atol " << m_atol << ", rtol " << m_rtol
       << "), update " << m_normDx << " (utol " << m_utol << ")\n";
    return os;
  }
  /// The ||F_0|| the relative tolerance scales with, when the solve continues an earlier one.
  void setReference(double normF0) { m_reference = normF0; }
  double normDx() const { return m_normDx; }
  /// ||F|| where this solve started (the same as initialNorm() unless it continues another).
  double startNorm() const { return m_normStart; }
  double initialNorm() const { return m_normF0; }
  /// The line-search step of the last iteration (1 for a full Newton step).
  double step() const { return m_step; }
  /// The last check converged by the round-off rule (the residual tests failed).
  bool atRoundoff() const { return m_atRoundoff; }
  /// The last check converged because the residual stagnated at its floor.
  bool stagnated() const { return m_stagnated; }

 private:
  static constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
  static constexpr double kRoundoffSteps = 1e3;
  static constexpr double kFloorReduction = 1e-6;
  std::vector<double> m_history;  ///< ||F|| of this solve's iterations
  bool m_stagnated = false;
  double m_atol, m_rtol, m_utol;
  bool m_atRoundoff = false;
  double m_step = 1.0;
  double m_normF = 0.0, m_normF0 = 0.0, m_normDx = 0.0;
  double m_reference = 0.0, m_normStart = 0.0;
  NOX::StatusTest::StatusType m_status = NOX::StatusTest::Unevaluated;
  Teuchos::RCP<NOX::Abstract::Vector> m_scratch;
};

/// Fails Newton when the run's wall-clock budget is spent (Solver/Time Limit, core/Budget.hpp);
/// counts the iterations for the budget's message.
class BudgetTest : public NOX::StatusTest::Generic {
 public:
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override {
    m_iterations = solver.getNumIterations();
    m_status = budgetSpent() ? NOX::StatusTest::Failed : NOX::StatusTest::Unconverged;
    return m_status;
  }
  NOX::StatusTest::StatusType getStatus() const override { return m_status; }
  std::ostream& print(std::ostream& os, int indent) const override {
    return os << std::string(indent, ' ') << "wall-clock budget\n";
  }
  int iterations() const { return m_iterations; }

 private:
  int m_iterations = 0;
  NOX::StatusTest::StatusType m_status = NOX::StatusTest::Unevaluated;
};

/// Fails Newton when its residual has grown past kGrowth times the stage's first one: the iterates
/// have run away and no step will bring them back (measured: xml/drawing.xml at h = 0.025 went from
/// ||F|| = 1.7 to 10³⁹ in 40 iterations whose factorizations of ever worse Jacobians took 320 s;
/// the stage's halving then converged in 9). Every converging solve of the test suite stays far
/// below this growth.
class DivergenceTest : public NOX::StatusTest::Generic {
 public:
  static constexpr double kGrowth = 1e10;
  explicit DivergenceTest(double growth = kGrowth) : m_growth(growth) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override {
    const double normF = solver.getSolutionGroup().getNormF();
    if (solver.getNumIterations() == 0) m_start = normF;
    m_status = m_start > 0.0 && normF > m_growth * m_start ? NOX::StatusTest::Failed : NOX::StatusTest::Unconverged;
    if (m_status == NOX::StatusTest::Failed)
      log() << "  Newton diverged: |F| = " << normF << " > " << m_growth << " x its start " << m_start << "\n";
    return m_status;
  }
  NOX::StatusTest::StatusType getStatus() const override { return m_status; }
  std::ostream& print(std::ostream& os, int indent) const override {
    return os << std::string(indent, ' ') << "divergence (||F|| > " << m_growth << " ||F_0||)\n";
  }

 private:
  double m_growth;
  double m_start = 0.0;
  NOX::StatusTest::StatusType m_status = NOX::StatusTest::Unevaluated;
};

/// Logs one line per Newton iteration: ||F||, ||Δx|| and the line-search step.
class NewtonLogger : public NOX::Observer {
 public:
  explicit NewtonLogger(const ResidualAndStepTest& test) : m_test(test) {}
  void runPostIterate(const NOX::Solver::Generic& solver) override {
    const double normF = solver.getSolutionGroup().getNormF();
    // |dx| and the step from the status test, which ran just before (docs/toolchain.md).
    log() << "    newton " << std::setw(2) << solver.getNumIterations() << "  |F| = " << std::scientific
          << std::setprecision(3) << normF << "  |dx| = " << m_test.normDx() << "  step = " << std::defaultfloat
          << m_test.step() << (m_test.atRoundoff() ? "  (converged: update at round-off)" : "")
          << (m_test.stagnated() ? "  (converged: residual stagnated at its round-off floor)" : "") << "\n";
  }

 private:
  const ResidualAndStepTest& m_test;
};

}  // namespace flowform
