// The registry of responses: the one list a new response type is added to. Adding one is one
// file beside this one (a struct like BoundaryForce: its name, description, traits, the
// parameters it reads with their validators and doc strings, and its evaluation templated on
// the scalar type) and one entry in RegisteredResponses below. The response sublist's valid
// parameters, the "Type" choices and their --help text, the wall and boundary checks, the
// adaptivity targets and which responses get a derivative all follow from the list.
//
// Traits of a type:
//   kNeedsBoundary    its "Boundary" must be a boundary group of the mesh
//   kNeedsWall        its "Boundary" must be a Contact Wall
//   kReactionBased    it sums the reactions R_unc(x) (the unconstrained momentum residual)
//   kAdaptivityTarget it is linear in the reactions, φ = c·R_unc(x), and gives c
//                     (reactionWeights): its adjoint gives the adaptive loop's indicators
//   kDifferentiable   it has a derivative (evaluate<TangentFad>, and its gradient evaluate<GradientFad>); false for the piecewise
//                     constant ones (Dead Zone, Contact Length), which have evaluate(double) only
//   kField            (optional, "" when absent) the field besides the flow's it reads
//                     (kTemperatureField, kStrainField): a case without it is refused
// and, optionally, members of an instance:
//   std::string fieldRead() const      the same, when the parameters decide (Point Value's Field)
//   void checkMesh(const Mesh&) const  refuses, before the solve, parameters the mesh cannot
//                                      serve (InputError naming the entry; Responses prefixes
//                                      "Responses/<name>/")
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "flowform/core/TypeList.hpp"
#include "flowform/responses/BoundaryExtent.hpp"
#include "flowform/responses/BoundaryForce.hpp"
#include "flowform/responses/BoundaryPower.hpp"
#include "flowform/responses/CellPowers.hpp"
#include "flowform/responses/ContactLength.hpp"
#include "flowform/responses/FlowRate.hpp"
#include "flowform/responses/FluxWeightedMean.hpp"
#include "flowform/responses/ForwardSlip.hpp"
#include "flowform/responses/HeatFlow.hpp"
#include "flowform/responses/MeanPressure.hpp"
#include "flowform/responses/NeutralAngle.hpp"
#include "flowform/responses/PointValue.hpp"
#include "flowform/responses/RedundantWorkFactor.hpp"
#include "flowform/responses/ShearAngle.hpp"
#include "flowform/responses/TemperatureResponses.hpp"
#include "flowform/responses/ThicknessRatio.hpp"
#include "flowform/responses/ToolPower.hpp"
#include "flowform/responses/ToolTorque.hpp"
#include "flowform/responses/WallGap.hpp"
#include "flowform/responses/WallPowers.hpp"

namespace flowform {

template <typename... Types>
using ResponseList = TypeList<Types...>;

/// The first is the default of "Type".
using RegisteredResponses =
    ResponseList<BoundaryForce, MeanPressure, BoundaryPower, FlowRate, PlasticPower, FrictionPower, PenaltyPower,
                 StabilizationPower, DeadZone, BoundaryExtent, WallGap, ContactLength, WallForce, ThicknessRatio,
                 ShearAngle, ToolPower, ToolTorque, NeutralAngle, ForwardSlip, HeatFlow,
                 MeanTemperature, MaximumTemperature, PointValue, WallPressure, RedundantWorkFactor, MeanStrain>;

/// A type's static facts, by its index in RegisteredResponses.
struct ResponseTypeInfo {
  std::string name, description;
  bool needsBoundary, needsWall, reactionBased, adaptivityTarget, differentiable;
  std::string field;  ///< the field besides the flow's it reads (a type's optional kField), "" none
};
const std::vector<ResponseTypeInfo>& responseTypes();
/// Index of the type called `name`, −1 when there is none.
int responseTypeIndex(const std::string& name);
/// The names of the types with `trait` (a member of ResponseTypeInfo), joined by `separator`.
std::string responseTypeNames(bool ResponseTypeInfo::*trait, const std::string& separator);

/// The entries of one response sublist: "Type" (the registered names, each with its description)
/// and the union of the types' parameters (an entry several types read documents each one's use).
Teuchos::RCP<const Teuchos::ParameterList> validResponseParameters();

/// One response of a case: a registered type with its parameters read.
class ResponseFunction {
 public:
  virtual ~ResponseFunction() = default;
  virtual double value(const ResponseContext<double>& c) const = 0;
  /// The value and directional derivative; only for a differentiable type.
  virtual TangentFad derivative(const ResponseContext<TangentFad>& c) const = 0;
  /// The value and the gradient by every dof of the context's worksets; only for a differentiable type.
  virtual GradientFad gradient(const ResponseContext<GradientFad>& c) const = 0;
  /// φ = c·R_unc(x): writes c (owned map, zeroed first) and returns true for an adaptivity
  /// target; false (c untouched) for the others.
  virtual bool reactionWeights(const Mesh& mesh, const DofMap& dofMap, Geometry geometry, Vector& c) const = 0;
  /// The field besides the flow's this response reads ("" none).
  virtual std::string fieldRead() const = 0;
  /// The type's checkMesh where it has one.
  virtual void checkMesh(const Mesh& mesh) const = 0;
};

/// Declares the entries of response type `type` (an index of responseTypes()) into `list`:
/// the type's own declareParameters (std::out_of_range for an index that is no type).
void declareResponseParameters(int type, Teuchos::ParameterList& list);

/// The response of type `type` (an index of responseTypes()) from its validated sublist.
std::shared_ptr<const ResponseFunction> makeResponse(int type, const Teuchos::ParameterList& validated);

}  // namespace flowform
