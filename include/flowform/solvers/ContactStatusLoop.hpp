// The contact-status loop (docs/theory.md §2, paper §2.1): after a converged flow solve, change one
// wall node's status — an active node in tension is released, a free node that penetrates
// is activated, at the current limit of the contact zone — and solve again, until no
// change is needed. Every change is logged. Used by the primal run and by each
// finite-difference run of the sensitivity check, which starts from the converged state.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/contact/ContactWall.hpp"
#include "flowform/contact/WallStates.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/solvers/NonlinearSolver.hpp"

namespace flowform {

class ContactStatusLoop {
 public:
  /// `contact` is the validated "Contact" sublist.
  ContactStatusLoop(const Teuchos::ParameterList& contact, const Mesh& mesh, const DofMap& dofMap);

  /// Runs the loop from the converged x: changes statuses in `walls`, re-solves with
  /// `solver` at `physics`, and adds the Newton iterations, the convergence and the
  /// message to `report`. Returns the number of changes made.
  int run(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics, std::vector<ContactWall>& walls,
          SolveReport& report) const;

  /// While free surfaces move, a node at a separation point may cycle because the shape is not
  /// yet the flow's (free, it sits on the tool and the flow pushes in; active, it pulls): with
  /// this set, such nodes are left as they are, counted in SolveReport::unsettledContacts, and the
  /// run stays converged; the free-surface loop does not converge while any are left.
  void tolerateCycling(bool on) { m_tolerateCycling = on; }

  /// Status Update = Complementarity: the walls decide their contact zones inside Newton
  /// (ContactWall::enterComplementarity); this loop decides only the nodes that keep a status
  /// (open convex tool corners, walls whose released nodes are a free surface) and reads the
  /// complementarity nodes' contact at the end.
  bool complementarity() const { return m_complementarity; }
  /// After a failed complementarity solve: this loop decides every node (Certain Iterate).
  void fallBackToStatuses() {
    m_complementarity = false;
    m_certainIterate = true;
  }

 private:
  /// One decision of the loop: the change (wall −1: none), the runner-up's violation in the
  /// class the change came from, and the nodes that may not change again but violate.
  struct Decision {
    int wall = -1;
    StatusChange change;
    double runnerUp = 0.0;
    int unsettled = 0;
    double unsettledRatio = 0.0;  ///< their largest violation over its tolerance
  };
  /// p and u at every node of one wall (replicated on every rank: wallValues).
  struct WallValues {
    std::vector<double> p;
    std::vector<std::array<double, 2>> u;
  };
  /// Every wall's values at x (one collective import per wall).
  std::vector<WallValues> gatherWallValues(const std::vector<ContactWall>& walls, const Vector& x) const;
  /// The decision at the walls' values with both tolerances moved by the shifts (> 0: fewer
  /// candidates).
  Decision decide(const std::vector<ContactWall>& walls, const std::vector<WallValues>& values,
                  double pressureShift = 0.0, double penetrationShift = 0.0) const;
  /// Whether every state within the error bounds of the values (pressure, velocity at the wall
  /// nodes) gives the decision d.
  bool certain(const std::vector<ContactWall>& walls, const std::vector<WallValues>& values, const Decision& d,
               double pressureError, double penetrationError) const;

  /// The not-converged message for `total` nodes that cycle: which walls, where, and what to try.
  std::string cyclingMessage(const std::vector<ContactWall>& walls, const std::vector<WallValues>& values,
                             int total) const;

  static constexpr int kMaxStepsPerChange = 8;  ///< then the re-solve is converged in one go
  static constexpr long kPassesPerChange = 4 * (kMaxStepsPerChange + 4);  ///< loop passes per change at most
  static constexpr double kContraction = 0.5;  ///< ||F|| reduction of a step that makes an iterate readable
  int m_maxChanges, m_maxPerNode;
  bool m_tolerateCycling = false;
  double m_pressureTolerance, m_penetrationTolerance;
  double m_resolveTolerance;  ///< relative residual of the intermediate re-solves (0: tight)
  bool m_certainIterate;      ///< Status Update = Certain Iterate
  bool m_complementarity;     ///< Status Update = Complementarity
  const Mesh& m_mesh;
  const DofMap& m_dofMap;
};

}  // namespace flowform
