// One flowform run: the validated case, its mesh and discretization, the solve, and the
// results on disk. main.cpp is a thin command-line layer over this; tests drive it too.
#pragma once

#include <memory>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "flowform/Assembler.hpp"
#include "flowform/BoundaryConditions.hpp"
#include "flowform/DofMap.hpp"
#include "flowform/FlowModel.hpp"
#include "flowform/Mesh.hpp"
#include "flowform/NonlinearSolver.hpp"
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

  /// Nodal velocity and pressure, and the cell fields the case asks for, gathered on rank 0
  /// (other ranks get empty arrays).
  FieldSet gatherFields() const;

 private:
  Teuchos::ParameterList m_params;
  Teuchos::RCP<const Comm> m_comm;
  Mesh m_mesh;
  FlowPhysics m_physics;
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
