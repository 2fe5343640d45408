// The state of one solve of a case, and the solve itself: the mesh (and the mesh as the mesher
// made it), the dof map, the boundary conditions, the contact walls with their statuses, the free
// surfaces, the responses, the assembler and the model (f, W) on them, the solution, and what the
// solve reported. The algorithms that work on a solved state take a Problem (or the narrower
// pieces they need): the sensitivities, the total shape derivative and the finite-difference
// runs (sensitivity/), the two-level estimate and the adaptive loop (estimation/, through
// CaseRun). The driver (drivers/Simulation) makes one per run and only orchestrates.
//
// The solve (Problem::solve, docs/contact.md): Newton with continuation from the zero state
// (or from a state carried from another mesh, startFrom), restarted from walls that stick at
// rest and then from frictionless walls when it fails; the contact-status loop
// (solvers/ContactStatusLoop) once converged; with free surfaces the free-surface loop
// (freesurface/FreeSurfaceLoop) and, when groups are held until the surfaces converged, their
// release and the loop again.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/assembly/Assembler.hpp"
#include "flowform/responses/Responses.hpp"
#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/bc/ThermalBoundaryConditions.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/freesurface/FreeSurface.hpp"
#include "flowform/freesurface/FreeSurfaceLoop.hpp"
#include "flowform/freesurface/UpdateLinearization.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/mesh/SizeField.hpp"
#include "flowform/physics/FlowPhysics.hpp"
#include "flowform/solvers/ContactStatusLoop.hpp"
#include "flowform/solvers/FlowModel.hpp"
#include "flowform/solvers/NonlinearSolver.hpp"

namespace flowform {

/// What the search for a Rigid Inflow's speed did (Problem::balanceRigidInflow).
struct RigidInflowReport {
  std::string group;  ///< empty: no rigid inflow
  double startSpeed = 0.0, speed = 0.0;
  double force = 0.0;       ///< d·Σ R_i at the final speed (0 at balance)
  double forceScale = 0.0;  ///< Σ|R_i| over the nodes with a prescribed component
  int solves = 0, newtonIterations = 0, contactChanges = 0;
  std::vector<int> newtonPerSolve;
  bool converged = false;
  bool jump = false;  ///< accepted at a jump of the force balance (the imbalance is `force`)
  std::string message;
  std::vector<std::array<double, 2>> history;  ///< (U, force) of every trial speed
};

/// A Rigid Inflow's speed U as a sensitivity sees it: the bordered system [f(q, U, h) = 0,
/// F(q, h) = 0] (F the group's force balance) gives dq/dh = (dq/dh)_U + (dU/dh) g with
/// K g = −∂f/∂U and dU/dh = −(dF/dh)_U / (dF/dq g) (docs/rolling.md).
struct RigidInflowLinearization {
  Teuchos::RCP<Vector> minusDfDU;  ///< −∂f/∂U (owned map): nonzero in the group's constraint rows only
  /// dF along (dq, h) at the converged state: d·Σ_{i∈group} (∂R_i/∂q dq + ∂R_i/∂h); h null: none.
  std::function<double(const Vector& dq, const SensitivityParameter* h)> dForce;
};

class Problem {
 public:
  /// Reads the mesh of the validated case `caseParams` (relative paths against `baseDir`) and
  /// builds the walls, responses, maps, conditions, free surfaces and the model at `physics`
  /// (the case's bulk physics). `sizeField`: mesh the case's .geo with these sizes instead of its
  /// own (the adaptive loop). InputError for what the case's lists cannot make.
  Problem(const Teuchos::ParameterList& caseParams, const FlowPhysics& physics, const std::string& baseDir,
          const Teuchos::RCP<const Comm>& comm, const SizeField* sizeField = nullptr);
  ~Problem();
  Problem(const Problem&) = delete;
  Problem& operator=(const Problem&) = delete;

  /// Solves the flow (the first solve with its restarts, the contact-status loop, the
  /// free-surface loop and the release of held groups). The report says whether it converged.
  const SolveReport& solve();

  /// Starts from `other`'s state (another mesh of the same case): its solution interpolated at
  /// this mesh's nodes, its walls' statuses carried to this mesh's wall nodes
  /// (ContactWall::takeStatusesFrom; with `decideZoneLimits` a node inside an old zone limit is
  /// active if it penetrates at the interpolated state), the penalty scales from that state.
  /// solve() then re-solves from there, without the continuation; should that fail, it solves
  /// again from this problem's own start, as a run from scratch on this mesh would
  /// (restoreColdStart).
  /// `carryShapes` false: this mesh keeps its free surfaces as made (another domain's, e.g. a
  /// design whose shape parameter moved the tools: their shape would not fit this one).
  void startFrom(const Problem& other, bool decideZoneLimits = true, bool carryShapes = true);
  /// startFrom() gave this problem its start (solve() re-solves from there).
  bool startsFromOtherState() const { return m_warmStart; }

  /// Moves the mesh nodes to `coords` (same topology; every cell must stay positively
  /// oriented, else InputError naming the cell) and refreshes what caches geometry: the
  /// walls' curves and corners, the symmetry directions; the factors are dropped. The
  /// solution is kept as the next solve's start.
  void moveNodes(const std::vector<std::array<double, 2>>& coords);
  /// A shape parameter's move: the tools (what the walls measure their gap from, the faces that
  /// `Parallel To` follows) to the mesh as made moved to `madeCoords`, then the nodes to `coords`
  /// (the free surfaces' displacements carried by the caller). moveShape(meshAsMade().coords,
  /// mesh().coords) puts the tools back where they were made.
  void moveShape(const std::vector<std::array<double, 2>>& madeCoords,
                 const std::vector<std::array<double, 2>>& coords);

  /// A Newton solver on the case's Solver sublist; `refreshScales` makes the walls take their
  /// penalty scales from the state before every Newton solve.
  NonlinearSolver newtonSolver(bool refreshScales);

  /// The free-surface loop from the converged flow x at `physics` (x, the walls and the mesh move);
  /// the re-solves use `solver`. `unsettledAtStart`: contact nodes the solve before it left cycling
  /// (SolveReport::unsettledContacts); `toleranceScale` < 1 tightens the loop (FreeSurfaceLoop::run).
  FreeSurfaceReport convergeFreeSurfaces(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics,
                                         std::pair<int, double> unsettledAtStart, double toleranceScale = 1.0);
  /// After a free-surface move: each contact wall node's velocity in x turned by the angle its
  /// normal turned from `normalsBefore` (per wall, per node), keeping (u − v_w)·n and the slip.
  void turnWallVelocities(Vector& x, const std::vector<std::vector<std::array<double, 2>>>& normalsBefore) const;

  /// The responses at x on the current mesh and walls.
  std::map<std::string, double> evaluateResponses(const Vector& x) const {
    return m_responses->evaluate(x, m_mesh, *m_dofMap, *m_assembler, m_walls);
  }

  /// A Rigid Inflow group (BoundaryConditions::rigidInflow): its speed U is sought from the converged
  /// flow x at `physics` until the group's reaction along its direction balances its traction load,
  /// each trial speed a converged re-solve of x with the contact statuses; the group's speed stays at
  /// the last trial (problem/RigidInflowBalance.cpp). Not converged (no root: the roll cannot draw
  /// the strip in; a re-solve that fails): the report says why.
  RigidInflowReport balanceRigidInflow(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics);
  /// Sets a Rigid Inflow's speed (a finite-difference run puts the base run's back).
  void setRigidInflowSpeed(double speed);
  /// Adds `delta` to entry `entry` of boundary group `group`'s condition (a ram speed, a billet's
  /// temperature, a heat transfer coefficient) and rebuilds the flow's constraints and the thermal
  /// conditions; the solution is kept (a boundary value's sensitivity and its check).
  void shiftBoundaryValue(const std::string& group, const std::string& entry, double delta);
  /// The linearization of a Rigid Inflow's balance at the converged state, for the sensitivities
  /// (none without a rigid inflow).
  std::optional<RigidInflowLinearization> rigidInflowLinearization();
  /// −∂f/∂U at x: f(x; U) − f(x; U + 1), f being affine in U (the group's prescribed rows).
  Teuchos::RCP<Vector> rigidInflowSpeedLoad(const Vector& x);
  /// The force balance's F at x: d·Σ_{i∈group} R_i of the unconstrained residual (the group's
  /// reaction along its direction with the traction load); with `scale`, also the force scale
  /// Σ|R_i| over the nodes with a prescribed component (collective).
  double rigidInflowForce(const Vector& x, double* scale = nullptr);
  /// The same F from the unconstrained residual `reactions` the caller assembled, or its tangent
  /// from the residual's tangent (collective).
  double rigidInflowForceFrom(const Vector& reactions);
  /// The force balance's tangent at x along (dq, h): d·Σ_{i∈group} (∂R_i/∂q dq + ∂R_i/∂h), the
  /// unconstrained residual's rows of the Rigid Inflow group (h null: none).
  double rigidInflowForceTangent(const Vector& x, const Vector& dq, const SensitivityParameter* h);

  /// Rounds of a Rigid Inflow's balance and the free-surface loop at most (solve(), and the
  /// finite-difference runs with re-converged surfaces).
  static constexpr int kMaxInflowRounds = 10;

  /// What the linearized free-surface update reads and moves: this problem's state; `withInflow`:
  /// a Rigid Inflow's speed follows the surface (the total shape derivative; the loop holds it).
  SurfaceLinearizationState linearizationState(bool withInflow = false);

  /// Contact/Status Update = Complementarity: from the converged first solve, the walls decide
  /// their contact zones inside Newton; if that fails, the status loop decides them. With
  /// `looseStart` (the first solve stopped at kLooseFirstSolve) a failure first converges the
  /// first solve tightly and tries once more from there.
  void enterComplementarity(NonlinearSolver& solver, bool looseStart = false);
  /// The relative residual at which the first solve stops when enterComplementarity follows
  /// (measured on the plane extrusion's fixed meshes (0.1, 0.025) … (0.025, 0.001): 3e-2 takes 17,
  /// 16, 17, 18, 19 Newton iterations in all where 1e-2 took 18, 18, 19, 19, 21 and 1e-3 19–23, the
  /// same contact changes, F equal to 7·10⁻⁷; the axisymmetric family's first four 27, 18, 18, 21
  /// against 27, 20, 20, 23, F to 2·10⁻⁷; ν = 0, 0.3, 0.5 on (0.1, 0.025) one or two fewer; 1e-1
  /// left the axisymmetric die lip closed, F 11 % high).
  static constexpr double kLooseFirstSolve = 3e-2;
  /// The same where walls heat the workpiece by friction: their heat at a loose state's slips throws
  /// the temperatures off, and the complementarity Newton from there diverged (xml/hot_extrusion.xml:
  /// 44 Newton iterations with the retry from the tight state at 3e-2; 20, 22, 23, 23 at 1e-2, 3e-3,
  /// 1e-3, 1e-4; the round bar 30 and 18).
  static constexpr double kLooseFirstSolveFrictionHeat = 1e-2;
  /// The last start of a first solve with Coulomb-type walls: continuation in the friction
  /// coefficients from kFrictionContinuationStart × ν up to ν; restores `initial` first. Returns
  /// whether it converged (m_report then its report; otherwise m_report keeps the failure).
  bool continueInFriction(NonlinearSolver& solver, const Vector& initial);
  static constexpr double kFrictionContinuationStart = 0.125;
  /// What to try when the first solve of a case with contact walls failed from every start.
  std::string firstSolveHints() const;

  /// The validated case this problem was made from.
  const Teuchos::ParameterList& parameters() const { return m_params; }
  const std::string& baseDirectory() const { return m_baseDir; }
  const Teuchos::RCP<const Comm>& comm() const { return m_comm; }
  /// The size field this mesh was made with (empty: the .geo's own sizes).
  const SizeField& sizeField() const { return m_sizeField; }
  const Mesh& mesh() const { return m_mesh; }
  /// The mesh with its nodes where the mesher put them (before any free-surface update moved
  /// them): the geometry of the case's .geo, which a size field for remeshing must cover.
  Mesh meshAsMade() const {
    Mesh made = m_mesh;
    made.coords = m_madeCoords;
    return made;
  }
  const DofMap& dofMap() const { return *m_dofMap; }
  const BoundaryConditions& boundaryConditions() const { return *m_bcs; }
  /// The case's bulk physics (the model is put back to it after a perturbed solve).
  const FlowPhysics& physics() const { return m_physics; }
  const Vector& solution() const { return *m_solution; }
  const Teuchos::RCP<Vector>& solutionPtr() const { return m_solution; }
  FlowModel& model() { return *m_model; }
  const FlowModel& model() const { return *m_model; }
  const Assembler& assembler() const { return *m_assembler; }
  const Responses& responses() const { return *m_responses; }
  std::vector<ContactWall>& contactWalls() { return m_walls; }
  const std::vector<ContactWall>& contactWalls() const { return m_walls; }
  const ContactStatusLoop& statusLoop() const { return *m_statusLoop; }
  const FreeSurfaces& freeSurfaces() const { return *m_freeSurfaces; }
  /// The solve's report, its contact-status changes and its free-surface loop.
  const SolveReport& report() const { return m_report; }
  int contactChanges() const { return m_contactChanges; }
  const FreeSurfaceReport& freeSurfaceReport() const { return m_freeSurfaceReport; }
  const RigidInflowReport& rigidInflowReport() const { return m_rigidInflowReport; }

 private:
  /// The wall nodes whose normal velocity a velocity condition holds (ContactWall::setNormalHeld):
  /// after the conditions are built, after every move and after a release (releaseHeldConditions).
  void markHeldNormals();
  /// BoundaryConditions::releaseHeld and the held normals marked again; whether anything was released.
  bool releaseHeldConditions();
  /// Penalty scales of every wall from the state x.
  void updateWallScales(const Vector& x);
  /// The Temperature field's start (constructor): the law's reference temperature or the mean
  /// prescribed one, the prescribed values (of `conditions`) at their nodes.
  void startTemperature(const ThermalBoundaryConditions& conditions);
  /// The Strain field's start (constructor): the law's own Strain or the mean inflow strain, the
  /// inflow's values at their nodes.
  void startStrain();
  /// The inflow strains as the assembler's prescribed values (empty without a Strain field).
  std::vector<Assembler::PrescribedValue> prescribedStrains() const;
  /// The thermal conditions of the case's Boundary Conditions given to the assembler: the
  /// prescribed temperatures (with the inflow strains) and the heat-transferring edges (a case
  /// with the field only); returned for the field's start.
  ThermalBoundaryConditions applyThermalConditions();
  /// The groups marked Release After Free Surfaces are released (BoundaryConditions::releaseHeld):
  /// the flow is re-solved and the free-surface loop goes on from the converged shape; its report
  /// continues the held loop's (FreeSurfaceReport::continueFrom).
  void releaseHeldAndGoOn(NonlinearSolver& solver);
  /// balanceRigidInflow on the problem's own state: its report joins m_rigidInflowReport (the
  /// rounds with free surfaces), its Newton iterations and contact changes add to the solve's, and a
  /// failure makes the solve unconverged.
  void balanceRigidInflow(NonlinearSolver& solver);

  /// The free-surface loop on the problem's own state (convergeFreeSurfaces): its report is
  /// m_freeSurfaceReport, its Newton iterations and changes add to the solve's, and a failure makes
  /// the solve unconverged, `context` prefixed to its message.
  void loopFreeSurfaces(NonlinearSolver& solver, std::pair<int, double> unsettledAtStart, const std::string& context);
  /// The contact-status loop with the case's strategy (Contact/Status Update), cycling tolerated
  /// where a wall's released nodes are a free surface.
  void makeStatusLoop();
  /// Back to the start startFrom() replaced (m_coldStart): the solution, the walls' statuses out of
  /// complementarity, the rigid inflow's speed, the case's contact strategy; the problem is no
  /// longer warm-started. The free surfaces keep the carried shape.
  void restoreColdStart();

  static constexpr int kFirstTryHalvings = 3;  ///< continuation halvings of the first start with walls
  Teuchos::ParameterList m_params;
  Teuchos::RCP<const Comm> m_comm;
  std::string m_baseDir;
  SizeField m_sizeField;
  Mesh m_mesh;
  std::vector<std::array<double, 2>> m_madeCoords;  ///< the nodes as the mesher made them
  FlowPhysics m_physics;
  std::vector<ContactWall> m_walls;
  std::unique_ptr<Responses> m_responses;
  std::unique_ptr<DofMap> m_dofMap;
  std::unique_ptr<BoundaryConditions> m_bcs;
  std::unique_ptr<Assembler> m_assembler;
  std::unique_ptr<FlowModel> m_model;
  std::unique_ptr<ContactStatusLoop> m_statusLoop;
  std::unique_ptr<FreeSurfaces> m_freeSurfaces;
  Teuchos::RCP<Vector> m_solution;
  bool m_warmStart = false;  ///< startFrom() gave the state: solve() re-solves from it
  /// What startFrom() replaced: this problem's own start (solution, wall states, rigid-inflow
  /// speed), for the solve from scratch when the warm start fails.
  struct ColdStart {
    Teuchos::RCP<Vector> solution;
    std::vector<ContactWall::State> walls;
    double rigidInflowSpeed = 0.0;
  };
  std::optional<ColdStart> m_coldStart;
  std::vector<NodeValue> m_strainInflow;  ///< the groups' `Strain` values (a case with a Strain field)
  SolveReport m_report;
  int m_contactChanges = 0;
  FreeSurfaceReport m_freeSurfaceReport;
  RigidInflowReport m_rigidInflowReport;
};

}  // namespace flowform
