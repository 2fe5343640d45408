// The built-in finite-difference check of the sensitivities (docs/theory.md §4): for every parameter
// h, two more nonlinear solves at h + δ and h − δ, each from the converged state and with
// its full contact-status loop, and the central difference
//
//     φ'_FD = (φ(h + δ) − φ(h − δ)) / (2δ)
//
// of every response and of the velocity and pressure fields, compared with the DDM value.
// Where the contact status, the friction branch (stick, slip, no friction) or the sign of
// the pressure (p⁺ in ν p⁺) of any wall node differs between the base run and the run at
// h + δ or h − δ, the function has a kink
// within [h − δ, h + δ]: the entry says one_sided and lists the nodes that changed, and the
// one-sided difference on the side where nothing changed is reported too.
//
// With free surfaces the DDM differentiates on the frozen (converged) shape; the runs at h ± δ
// are then made twice: on the frozen shape (the check of the DDM) and with the surfaces
// re-converged (fd_moving_shape: the total derivative), and the entry reports the gap between
// the two (docs/theory.md §3.5) and, when the total derivative was computed, its difference from
// fd_moving_shape (ddm_total_shape, rel_diff_total_shape).
//
// A run that does not converge makes its entries "not_converged" and the run's exit status
// 3 (the primal results and the DDM sensitivities are still valid and written).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include <Teuchos_RCP.hpp>
#include <nlohmann/json_fwd.hpp>

#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"
#include "flowform/core/TpetraTypes.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/contact/WallStates.hpp"

namespace flowform {

/// A converged state and what the check compares: the base run, or a run at h ± δ.
struct PerturbedRun {
  bool converged = false;
  std::string message;
  Teuchos::RCP<const Vector> x;
  std::map<std::string, double> functionals;
  std::vector<std::vector<WallNodeState>> states;  ///< [wall][node]
  int newtonIterations = 0;
  int contactChanges = 0;
  /// With free surfaces: the responses after the surfaces are re-converged at h ± δ (the total
  /// derivative through the shape); `functionals` are those on the frozen shape (the partial
  /// derivative the DDM computes). Empty without free surfaces.
  std::map<std::string, double> movingFunctionals;
};

class FiniteDifferenceCheck {
 public:
  /// Solves at h + delta from the converged state (the caller restores everything after).
  using Runner = std::function<PerturbedRun(const SensitivityParameter& h, double delta)>;

  /// Runs both perturbed solves for every parameter of `sensitivity` (after its compute())
  /// and compares. `base` is the converged run; `physics` gives the relative steps' scales.
  FiniteDifferenceCheck(const Sensitivity& sensitivity, const PerturbedRun& base, const FlowPhysics& physics,
                        const std::vector<ContactWall>& walls, const Mesh& mesh, const DofMap& dofMap,
                        const Runner& run);

  bool allConverged() const { return m_allConverged; }
  /// The number of perturbed nonlinear solves and their Newton iterations.
  int runs() const { return m_runs; }
  int newtonIterations() const { return m_newtonIterations; }

  /// Column j: the central difference (q(h_j + δ) − q(h_j − δ)) / (2δ), for the fields
  /// du_d<h>_fd, dp_d<h>_fd beside the DDM's (zero where a run did not converge).
  const MultiVector& solutionDifferences() const { return *m_differences; }

  /// "fd_check": response (or velocity_field, pressure_field) → parameter → entry, and the
  /// runs' record under "sensitivity"/"finite_difference".
  void report(nlohmann::json& summary) const;

 private:
  /// A response: its derivative by DDM and by central, forward and backward differences,
  /// and |DDM − FD| for each. A field: the max norms of each and of the differences.
  struct Entry {
    double ddm = 0.0, fd = 0.0, forward = 0.0, backward = 0.0;
    double diff = 0.0, forwardDiff = 0.0, backwardDiff = 0.0;
    bool hasMoving = false;
    double fdMoving = 0.0;  ///< central difference with re-converged free surfaces
    bool hasTotal = false;
    double ddmTotal = 0.0;  ///< the derivative through the moving shape (sensitivity/ShapeDerivative)
  };
  /// A wall node whose status or friction branch differs between the runs.
  struct ChangedNode {
    std::string wall;
    GO node;
    double x, y;
    WallNodeState base, minus, plus;
  };
  struct ParameterRuns {
    std::string name;
    double value = 0.0, delta = 0.0;
    bool converged = false;
    std::string message;
    int newtonIterations = 0, contactChanges = 0;
    std::vector<ChangedNode> changed;
    std::string unchangedSide;  ///< "both" (nothing changed), "plus", "minus" or "none"
  };

  std::vector<ParameterRuns> m_parameters;
  Teuchos::RCP<MultiVector> m_differences;
  std::vector<std::string> m_names;  ///< the checked responses and the two fields
  std::map<std::string, std::map<std::string, Entry>> m_entries;  ///< response → parameter → entry
  std::map<std::string, std::map<std::string, double>> m_ddm;     ///< response → parameter → DDM value
  bool m_allConverged = true;
  int m_runs = 0, m_newtonIterations = 0;
};

}  // namespace flowform
