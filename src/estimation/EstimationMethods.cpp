#include "flowform/estimation/EstimationMethods.hpp"

#include <stdexcept>

namespace flowform {

namespace {

template <typename... Methods>
std::vector<EstimationMethodInfo> collect(TypeList<Methods...>) {
  return {EstimationMethodInfo{Methods::kName, Methods::kDescription}...};
}

}  // namespace

const std::vector<EstimationMethodInfo>& estimationMethods() {
  static const std::vector<EstimationMethodInfo> methods = collect(RegisteredEstimationMethods{});
  return methods;
}

int estimationMethodIndex(const std::string& name) { return indexByName(estimationMethods(), name); }

std::string adaptiveEstimationMethod(const std::string& method) {
  return method == "None" ? estimationMethods().front().name : method;
}

ErrorEstimate estimateErrors(int method, CaseRun& coarse, const CaseRunFactory& makeRun,
                             const std::vector<std::string>& indicatorResponses, const IndicatorsWanted& wanted) {
  ErrorEstimate estimate;
  if (!visitByIndex(RegisteredEstimationMethods{}, method, [&](auto tag) {
        estimate = decltype(tag)::type::estimate(coarse, makeRun, indicatorResponses, wanted);
      }))
    throw std::logic_error("no error-estimate method of index " + std::to_string(method));
  return estimate;
}

}  // namespace flowform
