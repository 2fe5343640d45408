#include "flowform/optimization/OptimizationLoop.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include <ROL_Bounds.hpp>
#include <Teuchos_LAPACK.hpp>
#include <ROL_OptimizationProblem.hpp>
#include <ROL_OptimizationSolver.hpp>
#include <ROL_Problem.hpp>
#include <ROL_Solver.hpp>
#include <nlohmann/json.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/optimization/DenseQp.hpp"
#include "flowform/optimization/DesignConstraint.hpp"
#include "flowform/optimization/DesignObjective.hpp"
#include "flowform/optimization/DesignParameters.hpp"
#include "flowform/optimization/DesignRuns.hpp"
#include "flowform/optimization/DesignVectors.hpp"
#include "flowform/optimization/OptimizationSettings.hpp"
#include "flowform/optimization/TrustRegionSqp.hpp"

namespace flowform {

namespace {

/// A cycle that moved a shape parameter by more than this fraction of its bounds' range is
/// followed by one on a mesh made at its result: the moved mesh keeps the start's resolution, and
/// so its discretization error (1.2 % of the drawing force from 14° to 7.8°, docs/optimization.md).
constexpr double kRemeshDistance = 0.02;

/// ROL's parameters from the settings (ROL's own examples are the reference: packages/rol/example).
Teuchos::ParameterList rolParameters(const OptimizationSettings& s) {
  Teuchos::ParameterList list("ROL");
  list.sublist("General").set("Output Level", 0);
  Teuchos::ParameterList& secant = list.sublist("General").sublist("Secant");
  secant.set("Type", "Limited-Memory BFGS");
  secant.set("Maximum Storage", 10);
  secant.set("Use as Hessian", !s.isMisfit());  // the misfit has Gauss-Newton's
  Teuchos::ParameterList& step = list.sublist("Step");
  step.set("Type", s.algorithm);
  Teuchos::ParameterList& region = step.sublist("Trust Region");
  region.set("Subproblem Solver", "Truncated CG");
  region.set("Initial Radius", s.initialRadius);
  // Coleman-Li's affine-scaled model for the bounds: on the misfits 5-7 solves where ROL's default
  // (Kelley-Sachs) took 13-30, its projected trial steps visiting the box's corners; Lin-More
  // stopped with an error in ROL 13.2.
  region.set("Subproblem Model", "Coleman-Li");
  Teuchos::ParameterList& descent = step.sublist("Line Search").sublist("Descent Method");
  descent.set("Type", s.isMisfit() ? "Newton-Krylov" : "Quasi-Newton Method");
  Teuchos::ParameterList& status = list.sublist("Status Test");
  status.set("Gradient Tolerance", s.gradientTolerance);
  status.set("Step Tolerance", s.stepTolerance);
  status.set("Iteration Limit", s.iterationLimit);
  if (s.isConstrained()) {
    // ROL's general-constraint algorithms (TypeG), each subproblem on the design's bounds solved by
    // the Algorithm (TypeB: Trust Region = Lin-More's projected Newton, Line Search). The
    // constraints' curvature is not known (DesignConstraint): the augmented Lagrangian's
    // Gauss–Newton level (objective Hessian + μ AᵀA).
    step.set("Type", s.constraintAlgorithm);
    Teuchos::ParameterList& al = step.sublist("Augmented Lagrangian");
    al.set("Subproblem Step Type", s.algorithm);
    al.set("Subproblem Iteration Limit", s.iterationLimit);
    al.set("Level of Hessian Approximation", 2);
    Teuchos::ParameterList& lcl = step.sublist("Stabilized LCL");
    lcl.set("Subproblem Step Type", s.algorithm);
    lcl.set("Subproblem Iteration Limit", s.iterationLimit);
    step.sublist("Interior Point").sublist("Subproblem").set("Iteration Limit", s.iterationLimit);
    status.set("Constraint Tolerance", s.constraintTolerance);
  }
  return list;
}

/// What the measurements resolve (docs/optimization.md §3): the eigen-decomposition of the
/// Gauss–Newton Hessian AᵀA in the design scaled by its bounds (z_j = h_j / (upper_j − lower_j)).
/// A direction v with eigenvalue λ is known to the standard error 1/√λ of the bounds' range; it is
/// resolved when that is below 1 (the data pin it inside the range). Per parameter: the share of it
/// that lies in unresolved directions (Σ_unresolved v_j²: 0 resolved, 1 not at all), and its
/// standard error over the resolved directions only (physical units).
nlohmann::json resolution(const std::vector<std::vector<double>>& A, const OptimizationSettings& settings) {
  const int n = static_cast<int>(settings.design.size());
  std::vector<double> range(n), H(n * n, 0.0), eigenvalues(n), work(std::max(1, 3 * n));
  for (int j = 0; j < n; ++j) range[j] = settings.upper[j] - settings.lower[j];
  for (const auto& row : A)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) H[i + n * j] += row[i] * range[i] * row[j] * range[j];
  int info = 0;
  Teuchos::LAPACK<int, double>().SYEV('V', 'U', n, H.data(), n, eigenvalues.data(), work.data(),
                                      static_cast<int>(work.size()), &info);
  nlohmann::json out;
  if (info != 0) return out;
  nlohmann::json directions = nlohmann::json::array();
  std::vector<double> unresolved(n, 0.0), variance(n, 0.0);
  int resolved = 0;
  for (int k = 0; k < n; ++k) {
    const double lambda = std::max(eigenvalues[k], 0.0);
    const bool known = lambda > 1.0;  // 1/√λ < 1: a standard error below the bounds' range
    resolved += known;
    nlohmann::json v = nlohmann::json::object();
    for (int j = 0; j < n; ++j) {
      const double c = H[j + n * k];
      v[settings.design[j]] = c;
      if (known) variance[j] += c * c * range[j] * range[j] / lambda;
      else unresolved[j] += c * c;
    }
    directions.push_back({{"eigenvalue", lambda},
                          {"standard_error", lambda > 0.0 ? nlohmann::json(1.0 / std::sqrt(lambda)) : nlohmann::json(nullptr)},
                          {"resolved", known},
                          {"direction", v}});
  }
  out["directions"] = directions;
  out["resolved_directions"] = resolved;
  for (int j = 0; j < n; ++j) {
    out["unresolved_share"][settings.design[j]] = unresolved[j];
    out["resolved_standard_error"][settings.design[j]] = std::sqrt(variance[j]);
  }
  return out;
}

/// (AᵀA)⁻¹ by Cholesky (n small: the design's size); empty when AᵀA is not positive definite
/// (the data do not determine every design parameter).
std::vector<std::vector<double>> gaussNewtonCovariance(const std::vector<std::vector<double>>& A, std::size_t n) {
  std::vector<std::vector<double>> M(n, std::vector<double>(n, 0.0)), inv = M;
  for (const auto& row : A)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) M[i][j] += row[i] * row[j];
  for (std::size_t c = 0; c < n; ++c) {  // column c: M x = e_c
    std::vector<double> x(n, 0.0);
    x[c] = 1.0;
    if (!choleskySolve(M, x, 1e-12)) return {};
    for (std::size_t i = 0; i < n; ++i) inv[i][c] = x[i];
  }
  return inv;
}

double norm(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return std::sqrt(s);
}

/// The projected gradient's norm on the scaled box [0, 1]^n (what the optimizer's tolerance is on).
double projectedGradientNorm(const std::vector<double>& z, const std::vector<double>& g) {
  std::vector<double> p(z.size());
  for (std::size_t i = 0; i < z.size(); ++i) p[i] = std::clamp(z[i] - g[i], 0.0, 1.0) - z[i];
  return norm(p);
}

}  // namespace

int runOptimization(const Teuchos::ParameterList& caseParams, const CaseRunFactory& factory, const std::string& outDir,
                    std::string* message) {
  const OptimizationSettings settings(caseParams);
  const DesignParameters design(settings.design, caseParams);
  for (std::size_t i = 0; i < design.size(); ++i)
    if (design.initial()[i] < settings.lower[i] || design.initial()[i] > settings.upper[i])
      throw InputError("Optimization: '" + settings.design[i] + "' starts at the case's value " +
                       std::to_string(design.initial()[i]) + ", outside its bounds [" + std::to_string(settings.lower[i]) +
                       ", " + std::to_string(settings.upper[i]) + "]");

  // Remeshing cycles (with a shape parameter): each cycle's designs are its start's mesh moved
  // (DesignRuns); a cycle that moved the design by more than kRemeshDistance of a bound's range is
  // followed by one from a mesh made at its result.
  const int cycles = design.movesShape() ? settings.remeshingCycles : 1;
  const std::size_t n = design.size();
  std::vector<double> hStart = design.initial(), hFinal = hStart;
  std::vector<std::unique_ptr<DesignRuns>> allRuns;
  ROL::Ptr<DesignObjective> objective;
  ROL::Ptr<DesignConstraint> constraint;
  double scale = 0.0, gnorm = 0.0, cnorm = 0.0;
  std::string sqpStatus;             ///< the SQP's stop (ROL's status names have no place for its own)
  std::vector<double> multipliers;   ///< the SQP's λ_i of the constraints (scaled)
  int iterations = 0;
  std::string status, failure;
  bool converged = false;
  nlohmann::json solves = nlohmann::json::array(), cycleLog = nlohmann::json::array();
  for (int cycle = 0; cycle < cycles; ++cycle) {
    const Teuchos::ParameterList cycleCase = design.applied(caseParams, hStart);
    const DesignParameters cycleDesign(settings.design, cycleCase);
    allRuns.push_back(std::make_unique<DesignRuns>(cycleCase, factory, cycleDesign, settings.warmStart,
                                                   settings.responsesRead()));
    DesignRuns& runs = *allRuns.back();
    objective = ROL::makePtr<DesignObjective>(settings, runs, scale);
    auto z = stdVector(objective->scaled(hStart));
    auto bounds = ROL::makePtr<ROL::Bounds<double>>(stdVector(std::vector<double>(n, 0.0)),
                                                    stdVector(std::vector<double>(n, 1.0)));
    Teuchos::ParameterList rol = rolParameters(settings);
    std::ostringstream rolLog;
    ROL::Ptr<const ROL::AlgorithmState<double>> state;
    // ROL's solve; a design that did not solve ends it (the record keeps what was solved).
    auto solveWith = [&](auto& solver) {
      try {
        solver.solve(rolLog);
      } catch (const DesignNotSolved& e) {
        failure = e.what();
      }
      state = solver.getAlgorithmState();
    };
    if (settings.isConstrained()) constraint = ROL::makePtr<DesignConstraint>(settings, runs, *objective);
    if (!constraint) {
      ROL::OptimizationProblem<double> problem(objective, z, bounds);
      ROL::OptimizationSolver<double> solver(problem, rol);
      solveWith(solver);
    } else if (settings.constraintAlgorithm == "Trust Region SQP") {
      auto sqpState = ROL::makePtr<ROL::AlgorithmState<double>>();
      try {
        const SqpResult sqp = runTrustRegionSqp(*objective, *constraint, *z->getVector(), settings, log());
        *z->getVector() = sqp.z;
        sqpState->iter = sqp.iterations;
        sqpState->gnorm = sqp.criticality;
        sqpState->cnorm = sqp.violation;
        sqpState->statusFlag = sqp.converged ? ROL::EXITSTATUS_CONVERGED : ROL::EXITSTATUS_STEPTOL;
        sqpStatus = sqp.status;
        multipliers = sqp.multipliers;
      } catch (const DesignNotSolved& e) {
        failure = e.what();
      }
      state = sqpState;
    } else {
      auto problem = ROL::makePtr<ROL::Problem<double>>(objective, z);
      problem->addBoundConstraint(bounds);
      const ROL::Ptr<ROL::BoundConstraint<double>> constraintBounds = constraint->bounds();
      problem->addConstraint("responses", ROL::Ptr<ROL::Constraint<double>>(constraint), constraint->zero(),
                             constraintBounds);
      problem->finalize(false, false);
      ROL::Solver<double> solver(problem, rol);
      solveWith(solver);
    }
    log() << rolLog.str();
    if (!runs.history().empty()) scale = objective->scale();
    hFinal = objective->design(*z->getVector());
    iterations += state->iter;
    gnorm = state->gnorm;
    status = !failure.empty()      ? "a solve did not converge"
             : !sqpStatus.empty() ? sqpStatus
                                  : ROL::EExitStatusToString(state->statusFlag);
    converged = failure.empty() && state->statusFlag == ROL::EXITSTATUS_CONVERGED;
    if (constraint) {  // ROL's own test is on the slack-augmented constraint; the responses' bounds decide
      cnorm = state->cnorm;
      if (converged && !runs.history().empty())
        converged = constraint->violation(runs.at(objective->design(*z->getVector())).functionals) <=
                    settings.constraintTolerance;
    }
    // The record of every solve: design, objective, projected gradient (scaled), Newton, seconds.
    for (const DesignSolution& s : runs.history()) {
      nlohmann::json entry = {{"solve", solves.size() + 1}, {"cycle", cycle}, {"newton_iterations", s.newtonIterations},
                              {"seconds", s.seconds}, {"warm_start", s.warmStarted}};
      for (std::size_t i = 0; i < n; ++i) entry["design"][settings.design[i]] = s.design[i];
      try {
        entry["objective"] = objective->objective(s);
        entry["gradient_norm"] = projectedGradientNorm(objective->scaled(s.design), objective->scaledGradient(s));
        if (constraint) entry["constraint_violation"] = constraint->violation(s.functionals);
      } catch (const DesignNotSolved&) {
      }
      solves.push_back(entry);
    }
    double moved = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      moved = std::max(moved, std::abs(hFinal[i] - hStart[i]) / (settings.upper[i] - settings.lower[i]));
    nlohmann::json entry = {{"cycle", cycle}, {"iterations", state->iter}, {"solves", runs.history().size()},
                            {"status", status}, {"moved", moved}};
    for (std::size_t i = 0; i < n; ++i) entry["design"][settings.design[i]] = hFinal[i];
    cycleLog.push_back(entry);
    log() << "optimization: cycle " << cycle << ": " << status << " after " << state->iter << " iteration(s), "
          << runs.history().size() << " solve(s), the design moved by " << moved << " of its range\n";
    if (!failure.empty() || !converged || moved <= kRemeshDistance) break;
    if (cycle + 1 < cycles) log() << "optimization: the mesh made again at the design found\n";
    hStart = hFinal;
  }
  DesignRuns& runs = *allRuns.back();
  const std::size_t totalSolves = solves.size();

  nlohmann::json block;
  for (std::size_t i = 0; i < n; ++i) {
    block["design"][settings.design[i]] = hFinal[i];
    block["initial_design"][settings.design[i]] = design.initial()[i];
    block["bounds"][settings.design[i]] = {settings.lower[i], settings.upper[i]};
  }
  block["algorithm"] = settings.algorithm;
  block["iterations"] = iterations;
  block["solves"] = totalSolves;
  block["converged"] = converged;
  block["status"] = status;
  block["gradient_norm"] = gnorm;
  block["history"] = solves;
  block["cycles"] = cycleLog;
  if (settings.isMisfit()) {
    block["objective_kind"] = "least-squares misfit";
  } else {
    block["objective_kind"] = settings.maximize ? "maximize" : "minimize";
    block["objective_response"] = settings.objective;
    block["objective_scale"] = scale;
  }

  if (!failure.empty()) {  // the last design solved is the record; nothing better to write
    *message = "optimization: " + failure;
    CaseRun* last = runs.lastRun();
    if (!last) throw DesignNotSolved(*message);  // not even the start converged
    block["objective"] = nullptr;
    last->setNotMet(*message);
    last->addSummaryBlock("optimization", block);
    last->writeOutput(outDir);
    return 3;
  }

  // The final design, solved as the case asks (its own sensitivities, check and estimate), on the
  // last cycle's topology (its reference Geo Parameters): the final values are the ones the
  // optimizer saw; after a cycle that did not move the design, that is the mesh made at the
  // design itself.
  log() << "optimization: " << status << " after " << iterations << " iteration(s), " << totalSolves
        << " solve(s); the final design solved as the case asks\n";
  std::unique_ptr<CaseRun> final =
      factory(design.applied(design.onReferenceTopology(caseParams, hStart), hFinal), nullptr);
  if (settings.warmStart && runs.lastRun())
    final->problem().startFrom(runs.lastRun()->problem(), true, !design.movesShape());
  final->run();
  const auto& f = final->functionals();
  if (final->exitStatus() == 0 && settings.isMisfit()) {
    DesignSolution s;
    s.functionals = f;
    s.derivatives = runs.at(hFinal).derivatives;  // the design's (solved, cached)
    const auto r = objective->residuals(s);
    double J = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      J += 0.5 * r[i] * r[i];
      block["measured"][settings.measured[i]] = {{"measured", settings.values[i]},
                                                 {"error", settings.errors[i]},
                                                 {"value", f.at(settings.measured[i])},
                                                 {"residual", r[i]}};
    }
    block["objective"] = J;
    const auto A = objective->residualJacobian(s);
    const auto covariance = gaussNewtonCovariance(A, n);
    block["resolution"] = resolution(A, settings);
    block["identifiable"] = !covariance.empty();
    if (covariance.empty()) block["covariance"] = nullptr;
    for (std::size_t i = 0; i < covariance.size(); ++i) {
      const double sd = std::sqrt(covariance[i][i]);
      block["standard_error"][settings.design[i]] = sd;
      block["confidence_95"][settings.design[i]] = {hFinal[i] - 1.96 * sd, hFinal[i] + 1.96 * sd};
      for (std::size_t j = 0; j < n; ++j) block["covariance"][settings.design[i]][settings.design[j]] = covariance[i][j];
    }
  } else if (final->exitStatus() == 0) {
    block["objective"] = f.at(settings.objective);
  }
  double violation = 0.0;
  if (constraint && final->exitStatus() == 0) {
    violation = constraint->violation(f);
    block["constraint_violation"] = violation;
    block["constraint_norm"] = cnorm;
    for (std::size_t i = 0; i < settings.constrained.size(); ++i) {
      const double lo = settings.constraintLower[i], hi = settings.constraintUpper[i], phi = f.at(settings.constrained[i]);
      const double tol = settings.constraintTolerance * constraint->scales()[i];
      const double near = kActiveFactor * tol;  // the SQP's multipliers take the bounds this near as active
      block["constraints"][settings.constrained[i]] = {
          {"value", phi},
          {"lower", std::isfinite(lo) ? nlohmann::json(lo) : nlohmann::json(nullptr)},
          {"upper", std::isfinite(hi) ? nlohmann::json(hi) : nlohmann::json(nullptr)},
          {"met", phi >= lo - tol && phi <= hi + tol},
          {"active", std::abs(phi - lo) <= near || std::abs(phi - hi) <= near}};
      // The SQP's multiplier as a shadow price: −λ_i is dJ*/d(bound), J scaled; in the objective's
      // units per unit of the response (J = ±φ/|φ(h_0)|; the misfit is its own unit).
      if (i < multipliers.size()) {
        const double perScaled = -multipliers[i] / constraint->scales()[i];
        block["constraints"][settings.constrained[i]]["shadow_price"] =
            settings.isMisfit() ? perScaled : (settings.maximize ? -1.0 : 1.0) * scale * perScaled;
      }
    }
  }
  block["solves"] = totalSolves + 1;  // the final one too
  final->addSummaryBlock("optimization", block);
  if (final->exitStatus() == 0 && violation > settings.constraintTolerance) {
    std::ostringstream why;
    why << "the final design violates a constraint by " << violation
        << " of its bound, above Optimization/Constraint Tolerance " << settings.constraintTolerance;
    final->setNotMet(why.str());
  } else if (!converged && final->exitStatus() == 0) {
    std::ostringstream why;
    why << "the optimizer stopped (" << status << ") with the projected gradient " << gnorm
        << " above Optimization/Gradient Tolerance " << settings.gradientTolerance;
    if (constraint) why << " or the constraint violation " << cnorm << " above Optimization/Constraint Tolerance";
    final->setNotMet(why.str());
  }
  final->writeOutput(outDir);
  *message = final->statusMessage();
  return final->exitStatus();
}

}  // namespace flowform
