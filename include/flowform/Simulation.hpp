// One flowform run: the validated case, its mesh and discretization, the solve, and the
// results on disk. main.cpp is a thin command-line layer over this; tests drive it too.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/Assembler.hpp"
#include "flowform/BoundaryConditions.hpp"
#include "flowform/DofMap.hpp"
#include "flowform/FlowModel.hpp"
#include "flowform/Mesh.hpp"
#include "flowform/NonlinearSolver.hpp"
#include "flowform/Responses.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/io/FieldSet.hpp"

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

  /// Solves the flow problem. The report says whether it converged.
  const SolveReport& run();

  /// summary.json, solution.h5/.xdmf and the boundary CSVs in `outDir` (created).
  void writeOutput(const std::string& outDir) const;

  const Teuchos::ParameterList& parameters() const { return m_params; }
  const Mesh& mesh() const { return m_mesh; }
  const DofMap& dofMap() const { return *m_dofMap; }
  const FlowPhysics& physics() const { return m_physics; }
  const Vector& solution() const { return *m_solution; }
  FlowModel& model() { return *m_model; }
  const SolveReport& report() const { return m_report; }
  int exitStatus() const { return m_report.converged ? 0 : 3; }
  const std::vector<ContactWall>& contactWalls() const { return m_walls; }
  int contactChanges() const { return m_contactChanges; }
  /// The case's responses at the current solution (empty before run()).
  const std::map<std::string, double>& functionals() const { return m_functionals; }

  /// Nodal velocity and pressure, and the cell fields the case asks for, gathered on rank 0
  /// (other ranks get empty arrays).
  FieldSet gatherFields() const;

 private:
  /// Contact-status loop (SPEC §2): one change at a time, re-solving after each.
  void runContactLoop(NonlinearSolver& solver);
  /// Penalty scales of every wall from the current solution.
  void updateWallScales(const Vector& x);
  /// Pressure and velocity at every node of `wall`, on every rank.
  void wallValues(const ContactWall& wall, std::vector<double>& p, std::vector<std::array<double, 2>>& u) const;

  Teuchos::ParameterList m_params;
  Teuchos::RCP<const Comm> m_comm;
  Mesh m_mesh;
  FlowPhysics m_physics;
  std::vector<ContactWall> m_walls;
  std::unique_ptr<Responses> m_responses;
  std::map<std::string, double> m_functionals;
  int m_contactChanges = 0;
  std::unique_ptr<DofMap> m_dofMap;
  std::unique_ptr<BoundaryConditions> m_bcs;
  std::unique_ptr<Assembler> m_assembler;
  std::unique_ptr<FlowModel> m_model;
  Teuchos::RCP<Vector> m_solution;
  SolveReport m_report;
  double m_setupSeconds = 0.0;
  double m_solveSeconds = 0.0;
};

}  // namespace flowform
