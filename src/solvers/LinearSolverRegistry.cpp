#include "flowform/solvers/LinearSolverRegistry.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/solvers/GatheredSolver.hpp"
#include "flowform/solvers/Klu2Amd.hpp"
#include "flowform/solvers/Klu2NestedDissection.hpp"
#include "flowform/solvers/Mumps.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

namespace {

// The fill-reducing ordering, one parameter for every solver that takes one.
enum class FillOrdering { NestedDissection, Amd };

void declareOrdering(Teuchos::ParameterList& valid) {
  Teuchos::setStringToIntegralParameter<FillOrdering>(
      "Ordering", "Nested Dissection",
      "fill-reducing ordering: Nested Dissection (METIS; KLU2: METIS_NodeND, MUMPS: ICNTL(7) = 5) or AMD "
      "(KLU2: Amesos2's KLU2 as shipped, no transposed solve; MUMPS: ICNTL(7) = 0)",
      Teuchos::tuple<std::string>("Nested Dissection", "AMD"),
      Teuchos::tuple<FillOrdering>(FillOrdering::NestedDissection, FillOrdering::Amd), &valid);
}

FillOrdering orderingOf(const Teuchos::ParameterList& list) {
  return Teuchos::getIntegralValue<FillOrdering>(list, "Ordering");
}

// --- KLU2 (Amesos2's sparse LU), one process -------------------------------------------------
std::unique_ptr<LinearSolver> createKlu2(const Teuchos::ParameterList& list) {
  if (orderingOf(list) == FillOrdering::Amd) return std::make_unique<Klu2Amd>();
  return std::make_unique<Klu2NestedDissection>();
}

// --- MUMPS, every rank ---------------------------------------------------------------------------
std::unique_ptr<LinearSolver> createMumps(const Teuchos::ParameterList& list) {
  return std::make_unique<Mumps>(orderingOf(list) == FillOrdering::Amd ? Mumps::Ordering::Amd : Mumps::Ordering::Metis);
}

}  // namespace

const std::vector<LinearSolverType>& linearSolverTypes() {
  static const std::vector<LinearSolverType> types = {
      // MUMPS first, the default: its factorization is ~10× faster than KLU2's at 10⁶ dofs and
      // it factors the distributed matrix (docs/BENCHMARKS.md).
      {"MUMPS", "multifrontal LU on every rank, the matrix given distributed", declareOrdering, createMumps, true},
      {"KLU2", "Amesos2's KLU2 sparse LU on one process (gathered to rank 0 under mpirun)", declareOrdering,
       createKlu2, false},
  };
  return types;
}

static void buildValidLinearSolverParameters(const ValidList& valid) {
  Teuchos::Array<std::string> names;
  std::string doc = "the direct solver:";
  for (const LinearSolverType& t : linearSolverTypes()) {
    names.push_back(t.name);
    doc += " " + t.name + " (" + t.description + ")";
  }
  Teuchos::setStringToIntegralParameter<int>("Type", names[0], doc, names(), valid.get());
  // Types may share an entry (Ordering): declaring it again sets the same.
  for (const LinearSolverType& t : linearSolverTypes()) t.declareParameters(*valid);
}

Teuchos::RCP<const Teuchos::ParameterList> validLinearSolverParameters() {
  return validListOnce<buildValidLinearSolverParameters>("Linear Solver");
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
