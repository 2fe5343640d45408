// The registry of error-estimate methods (Error Estimation/Method): the one list a new method is
// added to. A method is one file in estimation/ (a struct like NewtonStepEstimate: kName,
// kDescription and a static estimate(run, run factory, indicator responses, whether they are wanted)) and one entry
// in RegisteredEstimationMethods below; the Method choices, their description and the dispatch
// follow from the list.
#pragma once

#include <string>
#include <vector>

#include "flowform/core/TypeList.hpp"
#include "flowform/estimation/CoarserMeshEstimate.hpp"
#include "flowform/estimation/NewtonStepEstimate.hpp"
#include "flowform/estimation/TwoLevelEstimate.hpp"

namespace flowform {

/// The first is the default: the method the adaptive loop uses when the case's Method is None.
using RegisteredEstimationMethods = TypeList<CoarserMeshEstimate, NewtonStepEstimate, TwoLevelEstimate>;

/// A method's static facts, by its index in RegisteredEstimationMethods.
struct EstimationMethodInfo {
  std::string name, description;
};
const std::vector<EstimationMethodInfo>& estimationMethods();
/// Index of the method called `name`, −1 when there is none.
int estimationMethodIndex(const std::string& name);
/// The method the adaptive loop estimates with for a case's Error Estimation/Method `method`: that
/// one, the registry's first when None.
std::string adaptiveEstimationMethod(const std::string& method);

/// The estimate of `coarse`'s responses by method `method` (an index of estimationMethods()); a
/// method may refactor `coarse`'s model (CoarserMeshEstimate), its solution stays.
ErrorEstimate estimateErrors(int method, CaseRun& coarse, const CaseRunFactory& makeRun,
                             const std::vector<std::string>& indicatorResponses, const IndicatorsWanted& wanted = {});

}  // namespace flowform
