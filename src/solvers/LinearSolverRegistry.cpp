#include "flowform/solvers/LinearSolverRegistry.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/solvers/GatheredSolver.hpp"
#include "flowform/solvers/Klu2Amd.hpp"
#include "flowform/solvers/Klu2NestedDissection.hpp"

namespace flowform {

namespace {

// --- KLU2 (Amesos2's sparse LU), one process; with Ordering ----------------------------------
enum class Klu2Ordering { NestedDissection, Amd };

void declareKlu2(Teuchos::ParameterList& valid) {
  Teuchos::setStringToIntegralParameter<Klu2Ordering>(
      "Ordering", "Nested Dissection",
      "fill-reducing ordering for KLU2: Nested Dissection (METIS), AMD (Amesos2's KLU2 as shipped)",
      Teuchos::tuple<std::string>("Nested Dissection", "AMD"),
      Teuchos::tuple<Klu2Ordering>(Klu2Ordering::NestedDissection, Klu2Ordering::Amd), &valid);
}

std::unique_ptr<LinearSolver> createKlu2(const Teuchos::ParameterList& list) {
  if (Teuchos::getIntegralValue<Klu2Ordering>(list, "Ordering") == Klu2Ordering::Amd)
    return std::make_unique<Klu2Amd>();
  return std::make_unique<Klu2NestedDissection>();
}

}  // namespace

const std::vector<LinearSolverType>& linearSolverTypes() {
  static const std::vector<LinearSolverType> types = {
      {"KLU2", "Amesos2's KLU2 sparse LU on one process (gathered to rank 0 under mpirun)", declareKlu2, createKlu2,
       false},
  };
  return types;
}

Teuchos::RCP<const Teuchos::ParameterList> validLinearSolverParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Linear Solver"));
  Teuchos::Array<std::string> names;
  std::string doc = "the direct solver:";
  for (const LinearSolverType& t : linearSolverTypes()) {
    names.push_back(t.name);
    doc += " " + t.name + " (" + t.description + ")";
  }
  Teuchos::setStringToIntegralParameter<int>("Type", names[0], doc, names(), valid.get());
  for (const LinearSolverType& t : linearSolverTypes()) t.declareParameters(*valid);
  return valid;
}

std::unique_ptr<LinearSolver> createLinearSolver(const Teuchos::ParameterList& list, const Comm& comm) {
  const std::string name = list.get<std::string>("Type");
  for (const LinearSolverType& t : linearSolverTypes()) {
    if (t.name != name) continue;
    std::unique_ptr<LinearSolver> solver = t.create(list);
    if (comm.getSize() > 1 && !t.distributed) return std::make_unique<GatheredSolver>(std::move(solver));
    return solver;
  }
  throw std::logic_error("createLinearSolver: '" + name + "' is not a registered linear solver");
}

}  // namespace flowform
