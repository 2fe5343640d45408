// flowform CASE.xml [-o OUTDIR] [--set Path/To/Param=value ...] [--quiet]
// Exit status: 0 converged, 2 bad input (nothing written), 3 not converged (results
// written, flagged in summary.json), 1 anything else that stops the run (an output file that
// cannot be written, an internal failure): the message says what.
#include <chrono>
#include <filesystem>
#include <mpi.h>
#include <thread>
#include <iostream>
#include <string>
#include <vector>

#include <Teuchos_TimeMonitor.hpp>
#include <Tpetra_Core.hpp>

#include "flowform/drivers/CaseOverrides.hpp"
#include "flowform/core/Budget.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/estimation/AdaptiveLoop.hpp"
#include "flowform/drivers/CaseParameters.hpp"
#include "flowform/drivers/Simulation.hpp"
#include "flowform/io/CaseFile.hpp"
#include "flowform/io/ResultDirectory.hpp"
#include "flowform/optimization/OptimizationLoop.hpp"
#include "flowform/optimization/OptimizationSettings.hpp"

namespace {

constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;

void printHelp() {
  std::cout <<
      "flowform — steady-state rigid-viscoplastic flow with frictional contact\n\n"
      "usage: flowform CASE.xml [-o OUTDIR] [--set Path/To/Param=value ...] [--quiet]\n\n"
      "  CASE.xml          a Teuchos XML parameter list (see xml/ for documented cases)\n"
      "  -o OUTDIR         where results go (default: out/<case name>)\n"
      "  --set P=V         override parameter P (a path of sublists, e.g.\n"
      "                    'Material/Rate Exponent=5' or 'Mesh/Uniform Refinements=2');\n"
      "                    repeatable, for sweeps\n"
      "  --quiet           no progress output\n"
      "  --help            this text and every valid parameter with its documentation\n\n"
      "outputs in OUTDIR: summary.json, solution.h5 + solution.xdmf (ParaView),\n"
      "boundary_<group>.csv per named boundary group\n"
      "exit status: 0 converged, 2 bad input, 3 not converged (results written, flagged),\n"
      "1 any other failure (an output file that cannot be written, ...; the message says what)\n\n"
      "valid parameters:\n";
  flowform::Simulation::validParameters()->print(
      std::cout, Teuchos::ParameterList::PrintOptions().showDoc(true).indent(2).showTypes(true));
}

}  // namespace

namespace {

/// Ends the run for an error caught on this rank, with `status` on every rank and the message
/// said once. When every rank fails alike (input validated on every rank, or an error
/// broadcast from rank 0) they all arrive here and meet in a barrier on a communicator of
/// their own; rank 0 says the message and all leave with `status`. When the barrier does not
/// complete within a few seconds, some rank is still at work or waiting in a collective for
/// this one: this rank says the message and MPI_Abort(status) ends every rank. Never a rank
/// left waiting (README, "Exit status").
int endWithError(const std::string& message, int status, MPI_Comm errorComm, int rank, int size) {
  if (size == 1) {
    std::cerr << message << "\n";
    return status;
  }
  MPI_Request request;
  MPI_Ibarrier(errorComm, &request);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  int done = 0;
  while (!done && std::chrono::steady_clock::now() < deadline) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (done) {
    if (rank == 0) std::cerr << message << "\n";
    return status;
  }
  std::cerr << message << " (on rank " << rank << "; stopping the other ranks)\n" << std::flush;
  MPI_Abort(MPI_COMM_WORLD, status);
  return status;
}

}  // namespace

int main(int argc, char* argv[]) {
  flowform::budgetMarkStart();  // Solver/Time Limit counts from here
  // Before Kokkos starts: it answers --help with its own text.
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      printHelp();
      return 0;
    }
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  flowform::setLogRank(comm->getRank());
  MPI_Comm errorComm;  // endWithError's own: its barrier meets no other collective
  MPI_Comm_dup(MPI_COMM_WORLD, &errorComm);
  // Progress lines reach a log file or pipe as they are written (a long run shows where it is).
  std::cout << std::unitbuf;

  std::string casePath, outDir;
  std::vector<std::string> overrides;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "-o") {
        if (++i >= argc) throw flowform::InputError("-o needs a directory");
        outDir = argv[i];
        if (outDir.empty()) throw flowform::InputError("-o needs a directory name (it is empty)");
      } else if (arg == "--set") {
        if (++i >= argc) throw flowform::InputError("--set needs Path/To/Param=value");
        overrides.push_back(argv[i]);
      } else if (arg == "--quiet") {
        flowform::setLogEnabled(false);
      } else if (!arg.empty() && arg[0] == '-') {
        throw flowform::InputError("unknown option '" + arg + "' (see flowform --help)");
      } else if (casePath.empty()) {
        casePath = arg;
      } else {
        throw flowform::InputError("more than one case file given: '" + casePath + "' and '" + arg + "'");
      }
    }
    if (casePath.empty()) throw flowform::InputError("no case file given (usage: flowform CASE.xml; see --help)");
    if (!std::filesystem::exists(casePath)) throw flowform::InputError("case file '" + casePath + "' does not exist");
    if (outDir.empty()) outDir = "out/" + std::filesystem::path(casePath).stem().string();
    flowform::checkResultDirectory(outDir);  // before any work: a bad -o must not cost a solve

    // Duplicates, ill-typed and non-finite values, a byte-order mark: flowform/io/CaseFile.hpp.
    Teuchos::RCP<Teuchos::ParameterList> params = flowform::readCaseFile(casePath);
    for (const auto& o : overrides) flowform::applyOverride(*params, o, *flowform::Simulation::validParameters());

    const std::string baseDir = std::filesystem::path(casePath).parent_path().string();
    flowform::validateCase(*params);  // the Simulation validates its copy again
    flowform::startBudget(params->sublist("Solver").get<double>("Time Limit"), comm);
    // Exit 3: the reason on stderr too (it is in summary.json "message"), shown with --quiet.
    auto finish = [&](int status, const std::string& message) {
      if (comm->getRank() == 0) {
        flowform::log() << "flowform: results in " << outDir << "\n";
        if (status == 3) std::cerr << "flowform: not converged: " << message << "\n";
      }
      return status;
    };
    if (flowform::optimizationRequested(*params)) {
      std::string message;
      const int status = flowform::runOptimization(
          *params, flowform::Simulation::factory(baseDir.empty() ? "." : baseDir, comm), outDir, &message);
      return finish(status, message);
    }
    if (flowform::adaptivityRequested(*params)) {
      std::string message;
      const int status = flowform::runAdaptive(
          *params, flowform::Simulation::factory(baseDir.empty() ? "." : baseDir, comm), outDir, &message);
      return finish(status, message);
    }
    flowform::Simulation simulation(*params, baseDir.empty() ? "." : baseDir, comm);
    simulation.run();
    simulation.writeOutput(outDir);
    return finish(simulation.exitStatus(), simulation.statusMessage());
  } catch (const flowform::InputError& e) {
    return endWithError(std::string("flowform: input error: ") + e.what(), kExitBadInput, errorComm,
                        comm->getRank(), comm->getSize());
  } catch (const std::exception& e) {
    // Not the input and not the numerics (those are reported and exit 3): an output that cannot
    // be written, an allocation, a library's failure. Said plainly rather than an abort.
    return endWithError(std::string("flowform: error: ") + e.what(), kExitFailure, errorComm, comm->getRank(),
                        comm->getSize());
  }
}
