#include "flowform/sensitivity/ShapeDerivative.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "flowform/core/Clock.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/freesurface/UpdateLinearization.hpp"
#include "flowform/problem/Problem.hpp"
#include "flowform/sensitivity/Sensitivity.hpp"

namespace flowform {

void ShapeDerivative::report(nlohmann::json& summary) const {
  summary["shape_derivative"] = {{"computed", computed}, {"surface_unknowns", unknowns},
                                 {"contraction", contraction}, {"seconds", seconds}};
  if (!failure.empty()) summary["shape_derivative"]["failure"] = failure;
  nlohmann::json& s = summary["sensitivities_total_shape"];
  s = nlohmann::json::object();
  for (const auto& [response, byParameter] : responses)
    for (const auto& [parameter, value] : byParameter) s[response][parameter] = value;
}

ShapeDerivative totalShapeDerivative(Problem& problem, const Sensitivity& sensitivity) {
  const auto start = std::chrono::steady_clock::now();
  ShapeDerivative out;
  if (!sensitivity.hasSolutionDerivatives()) {
    out.failure = "no DDM sensitivities to extend";
    return out;
  }
  const UpdateLinearization lin(problem.linearizationState(true), true);
  if (!lin.failure().empty()) {
    out.failure = lin.failure();
    return out;
  }
  const int nb = lin.size();
  out.unknowns = nb;
  out.contraction = lin.spectralRadius();

  // (I − G) db = U_q dq_frozen for every parameter, then dφ/dh = dφ/dh|frozen + Σ_j dφ/db_j db_j.
  const auto& parameters = sensitivity.parameters();
  const int np = static_cast<int>(parameters.size());
  Teuchos::SerialDenseMatrix<int, double> rhs(nb, np), db;
  // A Geo Parameter also moves the mesh under the held surfaces (X_h = V): + U_X V − V along the unknowns.
  for (int p = 0; p < np; ++p) {
    const std::vector<double> dU = lin.updateAlong(*sensitivity.solutionDerivatives().getVector(p));
    for (int i = 0; i < nb; ++i) rhs(i, p) = dU[i];
    const auto motion = sensitivity.geoMotions().find(parameters[p].name);
    if (motion == sensitivity.geoMotions().end()) continue;
    const std::vector<double> dr = lin.residualAlongMotion(motion->second);
    for (int i = 0; i < nb; ++i) rhs(i, p) += dr[i];
  }
  if (!lin.solve(rhs, db)) {
    out.failure = "I − G is singular: the surface's fixed point is not isolated";
    return out;
  }
  for (const auto& [name, byParameter] : sensitivity.responseDerivatives())
    for (int p = 0; p < np; ++p) {
      double total = byParameter.at(parameters[p].name);
      for (int j = 0; j < nb; ++j) total += lin.responseShape(j, name) * db(j, p);
      out.responses[name][parameters[p].name] = total;
    }
  out.computed = true;
  out.seconds = secondsSince(start);
  log() << "sensitivity: total derivatives through the free surfaces (" << nb << " surface unknowns, "
        << "spectral radius of the linearized update " << out.contraction << ", " << out.seconds << " s)\n";
  for (const auto& [name, byParameter] : out.responses)
    for (const auto& [parameter, value] : byParameter)
      log() << "sensitivity:   d" << name << "/d(" << parameter << ") total = " << value << "\n";
  return out;
}

}  // namespace flowform
