#include "flowform/sensitivity/BoundaryValuePartials.hpp"

#include "flowform/problem/Problem.hpp"

namespace flowform {

BoundaryValues givenBoundaryValues(const Teuchos::ParameterList& caseParams) {
  static const char* const kEntries[] = {"Velocity X",          "Velocity Y",          "Temperature",
                                         "Heat Transfer Coefficient", "Ambient Temperature", "Tool Temperature"};
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
  assembler.residual(x, base);
  problem.shiftBoundaryValue(h.group, h.entry, 1.0);
  assembler.residual(x, shifted);
  problem.shiftBoundaryValue(h.group, h.entry, -1.0);
  out.dRdh = Teuchos::rcp(new Vector(x.getMap()));
  out.dRdh->update(1.0, shifted, -1.0, base, 0.0);
  for (const std::string& name : problem.responses().names()) out.dPhidh[name] = 0.0;
  return out;
}

}  // namespace flowform
