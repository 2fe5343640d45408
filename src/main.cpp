// flowform CASE.xml [-o OUTDIR] [--set Path/To/Param=value ...] [--quiet]
// Exit status: 0 converged, 2 bad input (nothing written), 3 not converged (results
// written, flagged in summary.json), 1 anything else that stops the run (an output file that
// cannot be written, an internal failure): the message says what.
#include <filesystem>
#include <mpi.h>
#include <unistd.h>
#include <iostream>
#include <string>
#include <vector>

#include <Teuchos_TimeMonitor.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Tpetra_Core.hpp>

#include "flowform/drivers/CaseOverrides.hpp"
#include "flowform/core/Budget.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/drivers/AdaptiveLoop.hpp"
#include "flowform/drivers/CaseParameters.hpp"
#include "flowform/drivers/Simulation.hpp"

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

/// The output directory must be a directory we can write, or creatable: its nearest existing
/// ancestor a writable directory. InputError otherwise (exit 2, before any work).
void checkOutputDirectory(const std::string& outDir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::absolute(outDir, ec);
  if (fs::exists(p, ec) && !fs::is_directory(p, ec))
    throw flowform::InputError("-o '" + outDir + "' exists and is not a directory");
  while (!fs::exists(p, ec) && p.has_parent_path() && p != p.parent_path()) p = p.parent_path();
  if (!fs::is_directory(p, ec))
    throw flowform::InputError("-o '" + outDir + "': '" + p.string() + "' is not a directory, so the output directory cannot be created");
  if (access(p.c_str(), W_OK | X_OK) != 0)
    throw flowform::InputError("-o '" + outDir + "': no permission to write in '" + p.string() + "'");
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
    checkOutputDirectory(outDir);  // before any work: a bad -o must not cost a solve

    Teuchos::RCP<Teuchos::ParameterList> params;
    try {
      params = Teuchos::getParametersFromXmlFile(casePath);
    } catch (const std::exception& e) {
      throw flowform::InputError("case file '" + casePath + "' is not a valid XML parameter list: " + e.what());
    }
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
    if (flowform::adaptivityRequested(*params)) {
      std::string message;
      const int status = flowform::runAdaptive(*params, baseDir.empty() ? "." : baseDir, comm, outDir, &message);
      return finish(status, message);
    }
    flowform::Simulation simulation(*params, baseDir.empty() ? "." : baseDir, comm);
    simulation.run();
    simulation.writeOutput(outDir);
    return finish(simulation.exitStatus(), simulation.statusMessage());
  } catch (const flowform::InputError& e) {
    if (comm->getRank() == 0) std::cerr << "flowform: input error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    // Not the input and not the numerics (those are reported and exit 3): an output that cannot
    // be written, an allocation, a library's failure. Said plainly rather than an abort.
    // On more ranks the others may wait in a collective for this one: stop them all.
    std::cerr << "flowform: error: " << e.what() << "\n";
    if (comm->getSize() > 1) MPI_Abort(MPI_COMM_WORLD, kExitFailure);
    return kExitFailure;
  }
}
