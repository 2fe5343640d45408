// The loop that makes free surfaces streamlines (docs/theory.md §3, paper §2.1): from a converged
// flow (contact statuses settled), update every free surface from the velocity field
// (FreeSurfaces::step), move the interior nodes (extendBoundaryDisplacement), re-solve the flow
// from the previous solution with its contact-status loop, and repeat until
//     max |ū·n|/|ū| on the surfaces ≤ Flow Angle Tolerance  and
//     the largest surface node move ≤ Move Tolerance × the surface's chord length.
// The contact statuses and the shape are coupled through it (a released node put back on its
// tool may be activated by the status loop, an active node in tension or not reached by the
// surface released, so a run starts elsewhere); the loop counts its iterations and gives up, with
// the reason, at Maximum Iterations — it cannot cycle silently. A move that would invert a cell
// is halved (up to kMaxHalvings times) first. The update's step (Relaxation, docs/theory.md §3.2):
// the plain one onto the streamlines, Aitken's ω times it, Anderson's multisecant step from the
// last updates with Aitken's ω as its mixing (the default), or Newton on the positions.
#pragma once

#include <array>
#include <functional>
#include <utility>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <nlohmann/json.hpp>

#include "flowform/freesurface/FreeSurface.hpp"

namespace flowform {

class AndersonAcceleration;

struct FreeSurfaceReport {
  bool converged = false;
  int iterations = 0;          ///< surface updates made (each followed by a flow re-solve)
  int newtonIterations = 0;    ///< of the re-solves
  int contactChanges = 0;      ///< of the re-solves' status loops
  double flowAngle = 0.0;      ///< max |ū·n|/|ū| at the returned state
  double move = 0.0;           ///< the update's largest node move at the returned state
  double seconds = 0.0;         ///< the whole loop
  double motionSeconds = 0.0;   ///< of which the surface updates and the mesh motion
  double resolveSeconds = 0.0;  ///< of which the flow re-solves (with their status loops)
  std::string message;         ///< why it did not converge
  /// Contact nodes the converged state leaves cycling between active and free with a violation
  /// within kGrazing times the status tolerances (they graze the tool).
  int grazingContacts = 0;
  /// Times an accelerated loop (Aitken, Anderson) made no progress for kStallUpdates updates and
  /// went on with the plain update.
  int plainFallbacks = 0;
  nlohmann::json history = nlohmann::json::array();  ///< per iteration: angle, move, Newton, changes
  /// free_surface_iterations and the "free_surface" block of summary.json.
  void report(nlohmann::json& summary) const;
  /// This report, a later loop of the same run, takes in an earlier one: counts and seconds add,
  /// the history is the earlier's then this one's (each entry tagged with its loop, 0 the first);
  /// the state (converged, flow angle, move, grazing contacts, message) stays this loop's.
  void continueFrom(const FreeSurfaceReport& earlier);
};

class FreeSurfaceLoop {
 public:
  /// Valid entries of the case's "Free Surface" sublist.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// What the loop needs from the run: the current nodal velocities (replicated, collective), a
  /// move of the mesh nodes (InputError when a cell would invert), and a re-solve of the flow with
  /// its status loop that says whether it converged and adds its Newton iterations and status
  /// changes.
  struct Hooks {
    std::function<std::vector<double>()> velocities;
    std::function<void(const std::vector<std::array<double, 2>>&)> moveNodes;
    std::function<bool(int& newtonIterations, int& contactChanges, std::string& message)> resolve;
    /// Releases node k of wall w (an active node a separated surface does not reach).
    std::function<void(int w, int k)> release;
    /// Contact nodes the last solve left cycling (ContactStatusLoop::tolerateCycling) and their
    /// largest violation over its tolerance. The loop does not converge while any violates by more
    /// than kGrazing times its tolerance (a node that only grazes the tool, with a tension or a
    /// penetration of the order of the status tolerances, may stay; the report counts it).
    /// Optional (none).
    std::function<std::pair<int, double>()> unsettledContacts;
    /// Relaxation = Newton: the move of each entry of step.moves for one Newton step on the
    /// positions, from the linearized update at the current state (UpdateLinearization); false
    /// (with the reason) when it cannot be made.
    std::function<bool(const FreeSurfaceStep& step, std::vector<std::array<double, 2>>& moves, std::string& why)>
        newtonMoves;
  };

  /// A contact node left cycling whose tension or penetration is within this many times the
  /// status tolerances only grazes the tool: a converged state may keep it (Hooks::unsettledContacts).
  static constexpr double kGrazing = 30.0;
  /// Whether the contact nodes left cycling ({count, largest violation over its tolerance}) may
  /// stay in a converged state: none, or all only grazing.
  static bool settled(std::pair<int, double> unsettled) {
    return unsettled.first == 0 || unsettled.second <= kGrazing;
  }

  /// `settings` is the validated "Free Surface" sublist.
  FreeSurfaceLoop(const FreeSurfaces& surfaces, const Teuchos::ParameterList& settings);

  /// Runs the loop from the converged state the hooks see. `toleranceScale` < 1 tightens both
  /// tolerances (and allows 3× the iterations): a finite-difference run with re-converged
  /// surfaces must resolve shape changes of the order of its step, far below the case's tolerances.
  FreeSurfaceReport run(const Mesh& mesh, const DofMap& dofMap, const std::vector<ContactWall>& walls,
                        Geometry geometry, const Hooks& hooks, double toleranceScale = 1.0) const;

 private:
  /// Relaxation = Anderson: replaces the step's moves by Anderson's step (mixing ω, Aitken's) from
  /// the positions and residuals so far (`restart`: forget them first); returns |step|∞/|plain
  /// update|∞.
  double andersonStep(const Mesh& mesh, FreeSurfaceStep& step, AndersonAcceleration& anderson, bool restart,
                      double omega) const;
  static constexpr double kMinRelaxation = 0.1, kMaxRelaxation = 1.5;  ///< Aitken's ω kept in here
  /// Anderson's step is at most this many times the plain update's (else the plain update).
  static constexpr double kMaxAndersonGain = 10.0;
  static constexpr int kMaxHalvings = 6;  ///< of a move that would invert a cell
  /// Updates without a better max flow angle after which Aitken or Anderson gives way to the
  /// plain update (an exact 2-cycle, a wander; the converging runs measured better it every few).
  static constexpr int kStallUpdates = 15;
  const FreeSurfaces& m_surfaces;
  int m_maxIterations;
  double m_angleTolerance, m_moveTolerance;
  int m_andersonDepth;
  enum class Relaxation { None, Aitken, Anderson, Newton } m_relaxation;
};

}  // namespace flowform
