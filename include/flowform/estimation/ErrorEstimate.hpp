// What an error estimate of a run's responses found (EstimationMethods.hpp lists how it can be
// made: NewtonStepEstimate.hpp, TwoLevelEstimate.hpp).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "flowform/core/Types.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

struct ErrorEstimate;
/// Whether the indicators are wanted, given the estimate without them (the adaptive loop: not
/// when the estimate meets the target). Empty: always.
using IndicatorsWanted = std::function<bool(const ErrorEstimate&)>;

struct ErrorEstimate {
  bool estimated = false;
  std::string method;  ///< the Error Estimation/Method that made it
  /// Why there is no estimate although one was asked for (the refined solve did not converge).
  std::string failure;
  double order = 1.0;  ///< p
  /// η_φ ≈ φ(u) − φ(u_h), by response name.
  std::map<std::string, double> functionals;
  /// η of dφ/dh: response → parameter → value (when the case asks for sensitivities).
  std::map<std::string, std::map<std::string, double>> sensitivities;
  /// η of the total dφ/dh through the moving free surfaces (ShapeDerivative), when computed.
  std::map<std::string, std::map<std::string, double>> sensitivitiesTotalShape;
  /// The level the estimate compared with: "refined" (the mesh refined once more) or "coarser"
  /// (the mesh one uniform refinement coarser); the summary's keys say it.
  std::string otherLevel = "refined";
  /// φ and dφ/dh (frozen shape and total) on that level (named refined* for the refined one).
  std::map<std::string, double> refinedFunctionals;
  std::map<std::string, std::map<std::string, double>> refinedSensitivities;
  std::map<std::string, std::map<std::string, double>> refinedSensitivitiesTotalShape;
  /// Free-surface updates the other level's solve took (the refined one from the carried shape;
  /// the coarser one from the run's shape, or, nested, from the mesh as made); −1: no free
  /// surfaces. summary.json: error_estimation.<otherLevel>_free_surface_iterations.
  int refinedSurfaceUpdates = -1;
  /// Per node of the coarse mesh and per indicator response: |share of η| (replicated).
  std::map<std::string, std::vector<double>> indicators;
  /// The mesh (as made) whose nodes the indicators are on when it is not the run's: the coarser
  /// level's, whose sizes are twice the run's.
  std::shared_ptr<const Mesh> indicatorMesh;
  GO refinedDofs = 0;
  double seconds = 0.0;
  /// Where the seconds went (refined setup, transfer, assembly, factorization, solves, ...).
  std::map<std::string, double> timings;
  /// What the method measured of itself (e.g. the refined residual norms before and after the step).
  std::map<std::string, double> details;

  /// "functionals_error_estimate", "sensitivities_error_estimate",
  /// "sensitivities_total_shape_error_estimate" and "error_estimation"
  /// (method, order, refined dofs and responses, seconds, timings, details) into the summary.
  void report(nlohmann::json& summary) const;
};

}  // namespace flowform
