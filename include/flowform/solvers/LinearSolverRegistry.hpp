// The direct solvers a case can choose (Solver → Linear Solver → Type) and how each is made.
// A new solver is one new file (a LinearSolver) and one entry in LinearSolverRegistry.cpp:
// its name, what its parameters are in the "Linear Solver" sublist, how it is created, and
// whether it factors a distributed matrix itself (else it runs behind a GatheredSolver
// under mpirun).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/solvers/LinearSolver.hpp"

namespace flowform {

struct LinearSolverType {
  std::string name;
  std::string description;
  /// Adds the type's own entries to the "Linear Solver" sublist's valid parameters.
  std::function<void(Teuchos::ParameterList& valid)> declareParameters;
  /// A solver from the validated "Linear Solver" sublist.
  std::function<std::unique_ptr<LinearSolver>(const Teuchos::ParameterList& list)> create;
  /// Whether it factors a matrix distributed over several ranks itself.
  bool distributed = false;
};

/// Every registered type; the first is the default.
const std::vector<LinearSolverType>& linearSolverTypes();

/// The "Linear Solver" sublist: Type (the registered names) and each type's entries.
Teuchos::RCP<const Teuchos::ParameterList> validLinearSolverParameters();

/// The solver the validated `list` names, for matrices distributed over `comm`.
std::unique_ptr<LinearSolver> createLinearSolver(const Teuchos::ParameterList& list, const Comm& comm);

}  // namespace flowform
