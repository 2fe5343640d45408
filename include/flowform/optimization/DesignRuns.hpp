// The solves of an optimization (docs/optimization.md): the case at a design, its responses and
// their derivatives by every design parameter (the DDM; through the moving free surfaces where the
// case has them, sensitivity/ShapeDerivative), each design solved once (the optimizer asks for the
// value and the gradient at the same design) and started from the previous design's solution
// and contact statuses (Problem::startFrom), from scratch when that start fails.
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/estimation/CaseRun.hpp"
#include "flowform/optimization/DesignParameters.hpp"

namespace flowform {

/// A design solved: the responses and dφ/dh (response → design parameter → value).
struct DesignSolution {
  std::vector<double> design;
  std::map<std::string, double> functionals;
  std::map<std::string, std::map<std::string, double>> derivatives;
  int newtonIterations = 0;
  double seconds = 0.0;
  bool warmStarted = false;
};

/// A design whose solve did not converge: the optimization stops there (exit status 3).
struct DesignNotSolved : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class DesignRuns {
 public:
  /// `responses`: what the objective reads, the only responses each solve differentiates.
  DesignRuns(const Teuchos::ParameterList& caseParams, CaseRunFactory factory, const DesignParameters& design,
             bool warmStart, const std::vector<std::string>& responses);

  /// The solution at `design` (solved now unless it is the last one solved).
  const DesignSolution& at(const std::vector<double>& design);
  /// Every design solved, in order.
  const std::vector<DesignSolution>& history() const { return m_history; }
  /// The last run (its problem is the next one's start).
  CaseRun* lastRun() { return m_last.get(); }

 private:
  std::unique_ptr<CaseRun> solve(const Teuchos::ParameterList& params, bool warm);

  Teuchos::ParameterList m_case;  ///< the case, its sensitivities the design's, no check, no estimate
  CaseRunFactory m_factory;
  const DesignParameters& m_design;
  bool m_warmStart;
  std::unique_ptr<CaseRun> m_last;
  std::vector<DesignSolution> m_history;
};

}  // namespace flowform
