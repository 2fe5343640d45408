#include "flowform/sensitivity/BoundaryValuePartials.hpp"

#include "flowform/problem/Problem.hpp"

namespace flowform {

BoundaryValues givenBoundaryValues(const Teuchos::ParameterList& caseParams) {
  static const char* const kEntries[] = {"Velocity X",          "Velocity Y",          "Temperature",
                                         "Heat Transfer Coefficient", "Ambient Temperature", "Tool Temperature",
                                         "Friction Heat Fraction", "Strain"};
  BoundaryValues values;
  if (!caseParams.isSublist("Boundary Conditions")) return values;
  const Teuchos::ParameterList& bcList = caseParams.sublist("Boundary Conditions");
  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& group = bcList.name(it);
    if (!bcList.isSublist(group)) continue;
    const Teuchos::ParameterList& list = bcList.sublist(group);
    const bool rigid = list.isType<bool>("Rigid Inflow") && list.get<bool>("Rigid Inflow");
    for (const char* entry : kEntries) {
      if (!list.isType<double>(entry)) continue;
      if (rigid && std::string(entry).rfind("Velocity", 0) == 0) continue;
      values.emplace_back(group + "/" + entry, list.get<double>(entry));
    }
  }
  return values;
}

MeshPartials boundaryValuePartials(Problem& problem, const SensitivityParameter& h, const Vector& x) {
  MeshPartials out;
  Vector base(x.getMap()), shifted(x.getMap());
  const Assembler& assembler = problem.model().assembler();
  // The residual is affine in h, so any step gives ∂R/∂h exactly: one unit (a shifted condition is
  // not range-checked: a friction heat fraction of 1.7 is as good a second point as any).
  const double step = 1.0;
  // The responses too: a reaction sum reads the unconstrained residual, which a Friction Heat
  // Fraction enters (the other entries only the constrained one: there ∂φ/∂h = 0).
  assembler.residual(x, base);
  const auto phiBase = problem.evaluateResponses(x);
  problem.shiftBoundaryValue(h.group, h.entry, step);
  assembler.residual(x, shifted);
  const auto phiShifted = problem.evaluateResponses(x);
  problem.shiftBoundaryValue(h.group, h.entry, -step);
  out.dRdh = Teuchos::rcp(new Vector(x.getMap()));
  out.dRdh->update(1.0 / step, shifted, -1.0 / step, base, 0.0);
  for (const auto& [name, value] : phiShifted) out.dPhidh[name] = (value - phiBase.at(name)) / step;
  return out;
}

}  // namespace flowform
