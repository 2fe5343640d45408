#include "flowform/core/Budget.hpp"
#include "flowform/sensitivity/FiniteDifferenceCheck.hpp"

#include <algorithm>
#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <nlohmann/json.hpp>

#include "flowform/core/Log.hpp"

namespace flowform {

namespace {

/// |a − b| / max(|a|, |b|), 0 when both vanish.
double relativeDifference(double diff, double a, double b) {
  const double scale = std::max(std::abs(a), std::abs(b));
  return scale > 0.0 ? diff / scale : 0.0;
}

/// Max norms over the velocity (component 0, 1) or pressure (2) dofs of: the DDM field, the
/// central, forward and backward differences, and their differences from the DDM field.
void fieldNorms(const DofMap& dofMap, const Vector& ddm, const Vector& plus, const Vector& minus, const Vector& base,
                double delta, bool velocity, double* norms /* [7] */) {
  auto d = ddm.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto p = plus.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto m = minus.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto b = base.getLocalViewHost(Tpetra::Access::ReadOnly);
  const Map& map = *ddm.getMap();
  double local[7] = {0, 0, 0, 0, 0, 0, 0};
  for (size_t i = 0; i < ddm.getLocalLength(); ++i) {
    const bool isPressure = dofMap.fieldOfGlobalDof(map.getGlobalElement(static_cast<LO>(i))) == kP;
    if (isPressure == velocity) continue;
    const double central = (p(i, 0) - m(i, 0)) / (2 * delta);
    const double forward = (p(i, 0) - b(i, 0)) / delta, backward = (b(i, 0) - m(i, 0)) / delta;
    const double values[7] = {d(i, 0), central, forward, backward, d(i, 0) - central, d(i, 0) - forward,
                              d(i, 0) - backward};
    for (int k = 0; k < 7; ++k) local[k] = std::max(local[k], std::abs(values[k]));
  }
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_MAX, 7, local, norms);
}

}  // namespace

FiniteDifferenceCheck::FiniteDifferenceCheck(const Sensitivity& sensitivity, const PerturbedRun& base,
                                             const FlowPhysics& physics, const std::vector<ContactWall>& walls,
                                             const Mesh& mesh, const DofMap& dofMap, const Runner& run) {
  Teuchos::TimeMonitor timer(*Teuchos::TimeMonitor::getNewTimer("flowform: finite-difference check"));
  const auto& parameters = sensitivity.parameters();
  for (const auto& [response, value] : base.functionals)
    if (sensitivity.responseDerivatives().count(response)) m_names.push_back(response);
  const bool fields = sensitivity.hasSolutionDerivatives();  // not with Method = Adjoint
  if (fields) {
    m_names.push_back("velocity_field");
    m_names.push_back("pressure_field");
  }
  m_ddm = sensitivity.responseDerivatives();
  m_differences = Teuchos::rcp(new MultiVector(base.x->getMap(), parameters.size()));
  const BudgetScope scope("the finite-difference check", [&] { return std::to_string(m_runs) + " run(s)"; });
  for (size_t j = 0; j < parameters.size(); ++j) {
    const SensitivityParameter& h = parameters[j];
    ParameterRuns pr;
    pr.name = h.name;
    pr.value = parameterValue(h, physics, walls);
    pr.delta = h.finiteDifferenceStep(sensitivity.step(), physics);
    log() << "fd check: " << h.name << " = " << pr.value << " ± " << pr.delta << "\n";
    const PerturbedRun plus = run(h, pr.delta);
    const PerturbedRun minus = run(h, -pr.delta);
    m_runs += 2;
    pr.newtonIterations = plus.newtonIterations + minus.newtonIterations;
    pr.contactChanges = plus.contactChanges + minus.contactChanges;
    m_newtonIterations += pr.newtonIterations;
    pr.converged = plus.converged && minus.converged;
    if (!pr.converged) {
      m_allConverged = false;
      pr.message = !plus.converged ? "h + δ: " + plus.message : "h − δ: " + minus.message;
      log() << "fd check: " << h.name << " NOT CONVERGED (" << pr.message << ")\n";
      m_parameters.push_back(pr);
      continue;
    }

    // Kinks: a node whose status, friction branch or pressure sign differs from the base run's.
    bool plusChanged = false, minusChanged = false;
    for (size_t w = 0; w < walls.size(); ++w)
      for (int k = 0; k < walls[w].numNodes(); ++k) {
        const WallNodeState b0 = base.states[w][k], bp = plus.states[w][k], bm = minus.states[w][k];
        if (b0 == bp && b0 == bm) continue;
        plusChanged |= bp != b0;
        minusChanged |= bm != b0;
        const GO node = walls[w].curve().nodes[k];
        pr.changed.push_back({walls[w].name(), node, mesh.coords[node][0], mesh.coords[node][1], b0, bm, bp});
      }
    pr.unchangedSide = !plusChanged && !minusChanged ? "both" : !plusChanged ? "plus" : !minusChanged ? "minus" : "none";

    for (const auto& [response, value] : base.functionals) {
      const auto ddm = sensitivity.responseDerivatives().find(response);
      if (ddm == sensitivity.responseDerivatives().end()) continue;  // not differentiable
      Entry e;
      e.ddm = ddm->second.at(h.name);
      e.fd = (plus.functionals.at(response) - minus.functionals.at(response)) / (2 * pr.delta);
      e.forward = (plus.functionals.at(response) - value) / pr.delta;
      e.backward = (value - minus.functionals.at(response)) / pr.delta;
      e.diff = std::abs(e.ddm - e.fd);
      e.forwardDiff = std::abs(e.ddm - e.forward);
      e.backwardDiff = std::abs(e.ddm - e.backward);
      if (plus.movingFunctionals.count(response) && minus.movingFunctionals.count(response)) {
        e.hasMoving = true;
        const auto total = sensitivity.totalShapeDerivatives().find(response);
        if (total != sensitivity.totalShapeDerivatives().end() && total->second.count(h.name)) {
          e.hasTotal = true;
          e.ddmTotal = total->second.at(h.name);
        }
        e.fdMoving = (plus.movingFunctionals.at(response) - minus.movingFunctionals.at(response)) / (2 * pr.delta);
        log() << "fd check:   d" << response << "/dh with re-converged free surfaces: " << e.fdMoving << "\n";
      }
      m_entries[response][h.name] = e;
      log() << "fd check:   d" << response << "/dh: DDM " << e.ddm << ", FD " << e.fd << ", rel. difference "
            << relativeDifference(e.diff, e.ddm, e.fd) << (pr.unchangedSide == "both" ? "" : " (one-sided)") << "\n";
    }
    m_differences->getVectorNonConst(j)->update(1.0 / (2 * pr.delta), *plus.x, -1.0 / (2 * pr.delta), *minus.x, 0.0);
    if (!fields) {
      m_parameters.push_back(pr);
      continue;
    }
    const Vector ddmField = *sensitivity.solutionDerivatives().getVector(j);
    for (bool velocity : {true, false}) {
      double n[7];
      fieldNorms(dofMap, ddmField, *plus.x, *minus.x, *base.x, pr.delta, velocity, n);
      Entry e{n[0], n[1], n[2], n[3], n[4], n[5], n[6]};
      const std::string name = velocity ? "velocity_field" : "pressure_field";
      m_entries[name][h.name] = e;
      log() << "fd check:   " << name << ": |DDM| " << e.ddm << ", |FD| " << e.fd << ", |DDM - FD| / |FD| "
            << relativeDifference(e.diff, e.ddm, e.fd) << "\n";
    }
    m_parameters.push_back(pr);
  }
}

void FiniteDifferenceCheck::report(nlohmann::json& summary) const {
  nlohmann::json& check = summary["fd_check"];
  check = nlohmann::json::object();
  nlohmann::json runs = nlohmann::json::array();
  for (const ParameterRuns& pr : m_parameters) {
    nlohmann::json changed = nlohmann::json::array();
    for (const ChangedNode& c : pr.changed)
      changed.push_back({{"wall", c.wall}, {"node", c.node}, {"x", c.x}, {"y", c.y},
                         {"base", c.base.name()}, {"minus", c.minus.name()}, {"plus", c.plus.name()}});
    runs.push_back({{"parameter", pr.name}, {"value", pr.value}, {"delta", pr.delta}, {"converged", pr.converged},
                    {"message", pr.message}, {"newton_iterations", pr.newtonIterations},
                    {"contact_changes", pr.contactChanges}, {"changed_nodes", changed}});
    const bool oneSided = pr.unchangedSide != "both";
    for (const auto& [response, byParameter] : m_entries) {
      const auto it = byParameter.find(pr.name);
      if (it == byParameter.end()) continue;
      const Entry& e = it->second;
      nlohmann::json entry = {{"ddm", e.ddm},
                              {"fd", e.fd},
                              {"rel_diff", relativeDifference(e.diff, e.ddm, e.fd)},
                              {"abs_diff", e.diff},
                              {"fd_forward", e.forward},
                              {"fd_backward", e.backward},
                              {"delta", pr.delta},
                              {"one_sided", oneSided},
                              {"status", oneSided ? "one_sided" : "ok"},
                              {"changed_nodes", changed}};
      // At a kink the derivative is one-sided: compare with the side where nothing changed.
      if (pr.unchangedSide == "plus")
        entry["rel_diff_one_sided"] = relativeDifference(e.forwardDiff, e.ddm, e.forward);
      if (pr.unchangedSide == "minus")
        entry["rel_diff_one_sided"] = relativeDifference(e.backwardDiff, e.ddm, e.backward);
      if (oneSided) entry["consistent_side"] = pr.unchangedSide;
      if (e.hasMoving) {
        entry["fd_moving_shape"] = e.fdMoving;
        entry["shape_gap"] = relativeDifference(std::abs(e.fdMoving - e.fd), e.fdMoving, e.fd);
      }
      if (e.hasTotal) {
        entry["ddm_total_shape"] = e.ddmTotal;
        entry["rel_diff_total_shape"] = relativeDifference(std::abs(e.ddmTotal - e.fdMoving), e.ddmTotal, e.fdMoving);
        entry["abs_diff_total_shape"] = std::abs(e.ddmTotal - e.fdMoving);
      }
      check[response][pr.name] = entry;
    }
    if (!pr.converged)
      for (const std::string& response : m_names) {
        // The DDM value stands on its own; only the difference is missing.
        const auto byResponse = m_ddm.find(response);
        nlohmann::json ddmValue = nullptr;
        if (byResponse != m_ddm.end() && byResponse->second.count(pr.name)) ddmValue = byResponse->second.at(pr.name);
        check[response][pr.name] = {{"status", "not_converged"}, {"message", pr.message}, {"one_sided", false},
                                    {"ddm", ddmValue}, {"fd", nullptr}, {"rel_diff", nullptr}};
      }
  }
  summary["sensitivity"]["finite_difference"] = {{"runs", m_runs}, {"newton_iterations", m_newtonIterations},
                                                 {"all_converged", m_allConverged}, {"parameters", runs}};
}

}  // namespace flowform
