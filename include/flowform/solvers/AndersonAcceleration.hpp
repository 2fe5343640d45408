// Anderson acceleration of a fixed-point iteration x ← g(x) (Walker & Ni, SIAM J. Numer. Anal.
// 49 (2011); docs/theory.md §3.2): with the residuals f_j = g(x_j) − x_j of the last m + 1 iterates,
//     ΔF = [f_{j+1} − f_j],  ΔX = [x_{j+1} − x_j]  (j over the last m pairs),
//     γ  = argmin |f_k − ΔF γ|₂,
//     x_{k+1} = x_k + β f_k − (ΔX + β ΔF) γ     (β the mixing: the plain step's relaxation),
// the step a secant (multisecant) method would take: on a linear map g(x) = Gx + c it is GMRES on
// (I − G)x = c, so a slow mode of G (a contraction ρ near 1, where the plain step needs
// log ε / log ρ iterations) is removed in a few iterations. The least-squares problem is solved by
// modified Gram–Schmidt on the columns of ΔF, newest first; a column that is (nearly) a
// combination of the newer ones is dropped (its norm after orthogonalization below
// kDropTolerance times its own), which keeps the step's coefficients bounded.
#pragma once

#include <deque>
#include <vector>

namespace flowform {

class AndersonAcceleration {
 public:
  /// `depth` m ≥ 1: how many differences the step uses at most.
  explicit AndersonAcceleration(int depth) : m_depth(depth) {}

  /// Forgets the history: the next step is the plain one, Δx = β f (the map changed, or its unknowns).
  void reset() {
    m_x.clear();
    m_f.clear();
  }

  /// The step Δx from the iterate x with residual f = g(x) − x (x + Δx is the next iterate), using
  /// the iterates given before (since the last reset; a change of size resets); `mixing` β.
  std::vector<double> step(const std::vector<double>& x, const std::vector<double>& f, double mixing);

  /// How many differences the last step used (0: the plain step).
  int columnsUsed() const { return m_used; }

  static constexpr double kDropTolerance = 1e-6;

 private:
  int m_depth;
  int m_used = 0;
  std::deque<std::vector<double>> m_x, m_f;  ///< the last m + 1 iterates and residuals, oldest first
};

}  // namespace flowform
