#include "flowform/contact/friction/FrictionLaws.hpp"

namespace flowform {

namespace {

template <typename... Laws>
std::vector<FrictionLawInfo> collect(FrictionLawList<Laws...>) {
  return {FrictionLawInfo{Laws::kName, Laws::kDescription, Laws::kUsesFrictionCoefficient, Laws::kUsesShearFactor,
                          Laws::kNeedsTributary}...};
}

}  // namespace

const char* frictionBranchName(FrictionBranch b) {
  switch (b) {
    case FrictionBranch::Free: return "free";
    case FrictionBranch::NoFriction: return "no_friction";
    case FrictionBranch::Stick: return "stick";
    case FrictionBranch::Slip: return "slip";
    case FrictionBranch::SlipTresca: return "slip_tresca";
  }
  return "?";
}

const std::vector<FrictionLawInfo>& frictionLaws() {
  static const std::vector<FrictionLawInfo> laws = collect(RegisteredFrictionLaws{});
  return laws;
}

int frictionLawIndex(const std::string& name) { return indexByName(frictionLaws(), name); }

}  // namespace flowform
