// One flowform run, a thin driver over the pieces: the validated case, its mesh and
// discretization, the flow solve with the contact-status loop, the responses, the
// sensitivities when asked for, and the results on disk (each piece reports its own part
// of summary.json). main.cpp is a command-line layer over this; tests drive it too.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>
#include <nlohmann/json.hpp>

#include "flowform/assembly/Assembler.hpp"
#include "flowform/responses/Responses.hpp"
#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/drivers/ContactStatusLoop.hpp"
#include "flowform/drivers/FreeSurfaceLoop.hpp"
#include "flowform/drivers/ShapeDerivative.hpp"
#include "flowform/freesurface/FreeSurface.hpp"
#include "flowform/drivers/TwoLevelEstimate.hpp"
#include "flowform/io/FieldSet.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/mesh/SizeField.hpp"
#include "flowform/sensitivity/FiniteDifferenceCheck.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"
#include "flowform/solvers/FlowModel.hpp"
#include "flowform/solvers/NonlinearSolver.hpp"

namespace flowform {

class Simulation {
 public:
  /// Every parameter a case may have, with doc strings and validators (`--help` prints it).
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// Validates `caseParams` (InputError naming the parameter and the allowed ones), reads
  /// the mesh (relative paths against `baseDir`) and builds maps, conditions and the model.
  /// Nothing is written.
  /// `sizeField`: mesh the case's .geo with these sizes instead of its own (the adaptive loop).
  Simulation(const Teuchos::ParameterList& caseParams, const std::string& baseDir,
             const Teuchos::RCP<const Comm>& comm, const SizeField* sizeField = nullptr);
  ~Simulation();

  /// Solves the flow problem (with its contact-status loop and, when the case has free surfaces,
  /// the free-surface loop), then, when the case asks, the sensitivities (DDM, on the converged
  /// shape) and their finite-difference check. The report says whether the flow solve converged.
  const SolveReport& run();

  /// Starts from `other`'s state (another mesh of the same case): its solution interpolated at
  /// this mesh's nodes, its walls' statuses carried to this mesh's wall nodes
  /// (ContactWall::takeStatusesFrom; with `decideZoneLimits` a node inside an old zone limit is
  /// active if it penetrates at the interpolated state), the penalty scales from that state.
  /// run() then re-solves from there, without the continuation (it falls back to it only if
  /// Newton fails).
  void startFrom(const Simulation& other, bool decideZoneLimits = true);

  /// Moves the mesh nodes to `coords` (same topology; every cell must stay positively
  /// oriented, else InputError naming the cell) and refreshes what caches geometry: the
  /// walls' curves and corners, the symmetry directions; the factors are dropped. The
  /// solution is kept as the next solve's start.
  void moveNodes(const std::vector<std::array<double, 2>>& coords);

  /// summary.json, solution.h5/.xdmf and the boundary CSVs in `outDir` (created).
  void writeOutput(const std::string& outDir) const;

  const Teuchos::ParameterList& parameters() const { return m_params; }
  const std::string& baseDirectory() const { return m_baseDir; }
  /// The size field this mesh was made with (empty: the .geo's own sizes).
  const SizeField& sizeField() const { return m_sizeField; }
  /// The error estimate of the responses (its `estimated` false when none was made).
  const ErrorEstimate& errorEstimate() const { return *m_estimate; }
  /// Estimates the responses' errors now (the two-level estimate), with nodal indicators for
  /// `indicatorResponses` (the adaptive loop's targets). run() calls it when the case's
  /// Error Estimation/Method asks.
  void estimateErrors(const std::vector<std::string>& indicatorResponses = {});
  /// The run met its numbers but not what was asked of it (the adaptive loop's target): exit
  /// status 3 with `why` as the summary's message.
  void setNotMet(const std::string& why) { m_notMet = why; }
  /// run() computes the DDM sensitivities but leaves their finite-difference check to a later
  /// checkSensitivities() (the adaptive loop checks the last cycle's only).
  void deferFiniteDifferenceCheck() { m_deferCheck = true; }
  /// The finite-difference check of the computed sensitivities, when the case asks for it.
  void checkSensitivities();
  /// A block the summary carries as it is under `key` (the adaptive loop's cycles).
  void addSummaryBlock(const std::string& key, const nlohmann::json& block) { m_extraSummary[key] = block; }
  const Mesh& mesh() const { return m_mesh; }
  /// The mesh with its nodes where the mesher put them (before any free-surface update moved
  /// them): the geometry of the case's .geo, which a size field for remeshing must cover.
  Mesh meshAsMade() const {
    Mesh made = m_mesh;
    made.coords = m_madeCoords;
    return made;
  }
  const DofMap& dofMap() const { return *m_dofMap; }
  const FlowPhysics& physics() const { return m_physics; }
  const Vector& solution() const { return *m_solution; }
  FlowModel& model() { return *m_model; }
  const Assembler& assembler() const { return *m_assembler; }
  const SolveReport& report() const { return m_report; }
  /// 0; 3 when the flow solve did not converge, dq/dh is not finite, or a run of the
  /// finite-difference check did not converge (the results are written all the same).
  int exitStatus() const;
  /// Why the run is not converged (summary.json "message", and stderr at exit 3); the
  /// solve's message (empty) when it is.
  std::string statusMessage() const;
  /// What to try when the first solve of a case with contact walls failed from every start.
  std::string firstSolveHints() const;
  const std::vector<ContactWall>& contactWalls() const { return m_walls; }
  int contactChanges() const { return m_contactChanges; }
  const FreeSurfaces& freeSurfaces() const { return *m_freeSurfaces; }
  const FreeSurfaceReport& freeSurfaceReport() const { return m_freeSurfaceReport; }
  /// The case's responses at the current solution (empty before run()).
  const std::map<std::string, double>& functionals() const { return m_functionals; }
  const Sensitivity& sensitivity() const { return *m_sensitivity; }
  /// The total derivatives through the moving free surfaces (computed false when not made).
  const ShapeDerivative& shapeDerivative() const { return m_shapeDerivative; }
  const Responses& responses() const { return *m_responses; }

  /// Nodal velocity and pressure, and the cell fields the case asks for, gathered on rank 0
  /// (other ranks get empty arrays).
  FieldSet gatherFields() const;

 private:
  /// Penalty scales of every wall from the current solution.
  void updateWallScales(const Vector& x);
  /// A Newton solver on the case's Solver sublist; `refreshScales` makes the walls take their
  /// penalty scales from the state before every Newton solve.
  NonlinearSolver newtonSolver(bool refreshScales);
  /// The groups marked Release After Free Surfaces are released (BoundaryConditions::releaseHeld):
  /// the flow is re-solved and the free-surface loop goes on from the converged shape; its report
  /// continues the held loop's (FreeSurfaceReport::continueFrom).
  void releaseHeldAndGoOn(NonlinearSolver& solver);
  /// The free-surface loop on the run's own state (convergeFreeSurfaces): its report is
  /// m_freeSurfaceReport, its Newton iterations and changes add to the run's, and a failure makes
  /// the run unconverged, `context` prefixed to its message.
  void loopFreeSurfaces(NonlinearSolver& solver, std::pair<int, double> unsettledAtStart, const std::string& context);
  /// The free-surface loop from the converged flow at `physics` (x, the walls and the mesh move);
  /// the re-solves use `solver`.
  /// `unsettledAtStart`: contact nodes the solve before it left cycling (SolveReport::unsettledContacts).
  FreeSurfaceReport convergeFreeSurfaces(NonlinearSolver& solver, Vector& x, const FlowPhysics& physics,
                                         std::pair<int, double> unsettledAtStart, double toleranceScale = 1.0);
  /// The free-surface tolerances of a finite-difference run relative to the case's.
  static constexpr double kFiniteDifferenceSurfaceTolerance = 1e-4;
  /// DDM sensitivities at the converged solution and, when asked, their FD check.
  void runSensitivity();
  /// The solve at h + delta from the converged state, with its contact loop; the case's
  /// physics, the walls' state and the model are restored afterwards.
  PerturbedRun solvePerturbed(const SensitivityParameter& h, double delta);

  Teuchos::ParameterList m_params;
  Teuchos::RCP<const Comm> m_comm;
  Mesh m_mesh;
  std::vector<std::array<double, 2>> m_madeCoords;  ///< the nodes as the mesher made them
  FlowPhysics m_physics;
  std::vector<ContactWall> m_walls;
  std::unique_ptr<Responses> m_responses;
  std::unique_ptr<Sensitivity> m_sensitivity;
  std::unique_ptr<FiniteDifferenceCheck> m_fdCheck;
  static constexpr int kFirstTryHalvings = 3;  ///< continuation halvings of the first start with walls
  std::map<std::string, double> m_functionals;
  std::unique_ptr<ErrorEstimate> m_estimate;
  std::string m_baseDir;
  SizeField m_sizeField;
  bool m_warmStart = false;   ///< startFrom() gave the state: run() re-solves from it
  bool m_deferCheck = false;  ///< run() leaves the FD check to checkSensitivities()
  std::string m_notMet;       ///< why the run did not meet what was asked (setNotMet), or empty
  nlohmann::json m_extraSummary = nlohmann::json::object();
  int m_contactChanges = 0;
  std::unique_ptr<DofMap> m_dofMap;
  std::unique_ptr<BoundaryConditions> m_bcs;
  std::unique_ptr<Assembler> m_assembler;
  std::unique_ptr<FlowModel> m_model;
  std::unique_ptr<ContactStatusLoop> m_statusLoop;
  std::unique_ptr<FreeSurfaces> m_freeSurfaces;
  FreeSurfaceReport m_freeSurfaceReport;
  ShapeDerivative m_shapeDerivative;  ///< derivatives through the moving surfaces, when made
  Teuchos::RCP<Vector> m_solution;
  SolveReport m_report;
  double m_setupSeconds = 0.0;
  double m_solveSeconds = 0.0;
  double m_sensitivitySeconds = 0.0;
};

}  // namespace flowform
