#include "flowform/optimization/DesignRuns.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "flowform/core/Log.hpp"

namespace flowform {

DesignRuns::DesignRuns(const Teuchos::ParameterList& caseParams, CaseRunFactory factory,
                       const DesignParameters& design, bool warmStart, const std::vector<std::string>& responses)
    // A shape parameter keeps the start's mesh topology: every design's mesh is the start's moved
    // to its shape (freesurface/ReferenceTopology), so the responses vary smoothly with the design.
    : m_case(design.onReferenceTopology(caseParams, design.initial())),
      m_factory(std::move(factory)),
      m_design(design),
      m_warmStart(warmStart) {
  // Each solve computes what the optimizer needs and nothing else: the design's derivatives, no
  // finite-difference check, no error estimate (the final design is re-solved as the case asks).
  Teuchos::ParameterList& sensitivity = m_case.sublist("Sensitivity");
  sensitivity.set("Parameters", Teuchos::Array<std::string>(design.names().begin(), design.names().end()));
  sensitivity.set("Finite Difference Check", false);
  // Only the responses the objective reads (an adjoint each with Method = Adjoint).
  sensitivity.set("Responses", Teuchos::Array<std::string>(responses.begin(), responses.end()));
  m_case.sublist("Error Estimation").set("Method", "None");
}

std::unique_ptr<CaseRun> DesignRuns::solve(const Teuchos::ParameterList& params, bool warm) {
  std::unique_ptr<CaseRun> run = m_factory(params, nullptr);
  if (warm) run->problem().startFrom(m_last->problem(), true, !m_design.movesShape());
  run->run();
  return run;
}

const DesignSolution& DesignRuns::at(const std::vector<double>& design) {
  for (auto s = m_history.rbegin(); s != m_history.rend(); ++s)  // the last one, or one it comes back to
    if (s->design == design) return *s;
  for (double h : design)
    if (!std::isfinite(h)) throw DesignNotSolved("the optimizer proposed a design that is not a number");
  const auto start = std::chrono::steady_clock::now();
  const Teuchos::ParameterList params = m_design.applied(m_case, design);
  std::ostringstream where;
  for (std::size_t i = 0; i < design.size(); ++i)
    where << (i ? ", " : "") << m_design.names()[i] << " = " << design[i];
  log() << "optimization: solve " << m_history.size() + 1 << " at " << where.str() << "\n";
  std::unique_ptr<CaseRun> run;
  bool warm = m_warmStart && m_last;
  if (warm) {
    try {
      run = solve(params, true);
    } catch (const std::exception& e) {  // the previous shape does not carry over (a cell inverted)
      log() << "optimization: the start from the previous design failed (" << e.what() << "); from scratch\n";
      run.reset();
    }
    if (run && run->exitStatus() != 0) {
      log() << "optimization: the solve from the previous design did not converge; from scratch\n";
      run.reset();
    }
    warm = static_cast<bool>(run);
  }
  if (!run) run = solve(params, false);
  if (run->exitStatus() != 0)
    throw DesignNotSolved("the solve at " + where.str() + " did not converge: " + run->statusMessage());

  DesignSolution s;
  s.design = design;
  s.functionals = run->functionals();
  s.derivatives = run->sensitivity().responseDerivatives();
  if (run->shapeDerivative().computed)  // through the moving free surfaces
    for (const auto& [response, byParameter] : run->shapeDerivative().responses)
      for (const auto& [parameter, value] : byParameter) s.derivatives[response][parameter] = value;
  s.newtonIterations = run->problem().report().newtonIterations;
  s.warmStarted = warm;
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m_last = std::move(run);
  m_history.push_back(std::move(s));
  return m_history.back();
}

}  // namespace flowform
