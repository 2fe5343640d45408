// Debian ships no Teuchos standard unit-test main (docs/toolchain.md): this one holds the
// Tpetra scope (MPI and Kokkos) for the whole run.
#include <Teuchos_UnitTestRepository.hpp>
#include <Tpetra_Core.hpp>

int main(int argc, char* argv[]) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  return Teuchos::UnitTestRepository::runUnitTestsFromMain(argc, argv);
}
