// A parameter t raised to 1 by adaptive steps, the step control that the solver's homotopies
// share (the friction continuation of a first solve, Problem::continueInFriction; the residual
// homotopy of a re-solve, NonlinearSolver::residualHomotopy): the next value is t + step, at
// most 1; a converged stage moves t there and doubles the step, a failed one halves the
// increase it tried.
#pragma once

#include <algorithm>

namespace flowform {

struct ParameterRamp {
  double t;     ///< the last value reached (converged)
  double step;  ///< the next increase
  int failures = 0;

  double next() const { return std::min(1.0, t + step); }
  bool reachedEnd() const { return t >= 1.0; }
  void accept(double reached) {
    t = reached;
    step *= 2.0;
  }
  void reject(double tried) {
    step = (tried - t) / 2.0;
    ++failures;
  }
};

}  // namespace flowform
