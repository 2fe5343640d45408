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

#include "flowform/assembly/Assembler.hpp"
#include "flowform/assembly/Responses.hpp"
#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/drivers/ContactStatusLoop.hpp"
#include "flowform/io/FieldSet.hpp"
#include "flowform/mesh/Mesh.hpp"
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
  Simulation(const Teuchos::ParameterList& caseParams, const std::string& baseDir,
             const Teuchos::RCP<const Comm>& comm);
  ~Simulation();

  /// Solves the flow problem, then, when the case asks, the sensitivities (DDM) and their
  /// finite-difference check. The report says whether the flow solve converged.
  const SolveReport& run();

  /// Moves the mesh nodes to `coords` (same topology; every cell must stay positively
  /// oriented, else InputError naming the cell) and refreshes what caches geometry: the
  /// walls' curves and corners, the symmetry directions; the factors are dropped. The
  /// solution is kept as the next solve's start.
  void moveNodes(const std::vector<std::array<double, 2>>& coords);

  /// summary.json, solution.h5/.xdmf and the boundary CSVs in `outDir` (created).
  void writeOutput(const std::string& outDir) const;

  const Teuchos::ParameterList& parameters() const { return m_params; }
  const Mesh& mesh() const { return m_mesh; }
  const DofMap& dofMap() const { return *m_dofMap; }
  const FlowPhysics& physics() const { return m_physics; }
  const Vector& solution() const { return *m_solution; }
  FlowModel& model() { return *m_model; }
  const Assembler& assembler() const { return *m_assembler; }
  const SolveReport& report() const { return m_report; }
  /// 0; 3 when the flow solve did not converge, dq/dh is not finite, or a run of the
  /// finite-difference check did not converge (the results are written all the same).
  int exitStatus() const;
  const std::vector<ContactWall>& contactWalls() const { return m_walls; }
  int contactChanges() const { return m_contactChanges; }
  /// The case's responses at the current solution (empty before run()).
  const std::map<std::string, double>& functionals() const { return m_functionals; }
  const Sensitivity& sensitivity() const { return *m_sensitivity; }

  /// Nodal velocity and pressure, and the cell fields the case asks for, gathered on rank 0
  /// (other ranks get empty arrays).
  FieldSet gatherFields() const;

 private:
  /// Penalty scales of every wall from the current solution.
  void updateWallScales(const Vector& x);
  /// A Newton solver on the case's Solver sublist; `refreshScales` makes the walls take their
  /// penalty scales from the state before every Newton solve.
  NonlinearSolver newtonSolver(bool refreshScales);
  /// DDM sensitivities at the converged solution and, when asked, their FD check.
  void runSensitivity();
  /// The solve at h + delta from the converged state, with its contact loop; the case's
  /// physics, the walls' state and the model are restored afterwards.
  PerturbedRun solvePerturbed(const SensitivityParameter& h, double delta);

  Teuchos::ParameterList m_params;
  Teuchos::RCP<const Comm> m_comm;
  Mesh m_mesh;
  FlowPhysics m_physics;
  std::vector<ContactWall> m_walls;
  std::unique_ptr<Responses> m_responses;
  std::unique_ptr<Sensitivity> m_sensitivity;
  std::unique_ptr<FiniteDifferenceCheck> m_fdCheck;
  static constexpr int kFirstTryHalvings = 3;  ///< continuation halvings of the first start with walls
  std::map<std::string, double> m_functionals;
  std::map<std::string, double> m_errorEstimates;  ///< φ(u) − φ(u_h) estimated (estimation/DualWeightedResidual)
  int m_contactChanges = 0;
  std::unique_ptr<DofMap> m_dofMap;
  std::unique_ptr<BoundaryConditions> m_bcs;
  std::unique_ptr<Assembler> m_assembler;
  std::unique_ptr<FlowModel> m_model;
  std::unique_ptr<ContactStatusLoop> m_statusLoop;
  Teuchos::RCP<Vector> m_solution;
  SolveReport m_report;
  double m_setupSeconds = 0.0;
  double m_solveSeconds = 0.0;
  double m_sensitivitySeconds = 0.0;
};

}  // namespace flowform
