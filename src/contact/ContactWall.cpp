#include "flowform/contact/ContactWall.hpp"

#include <algorithm>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/InputError.hpp"

namespace flowform {

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

Teuchos::RCP<const Teuchos::ParameterList> ContactWall::validParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Contact Wall"));
  using Teuchos::EnhancedNumberValidator;
  auto nonNegative = Teuchos::rcp(new EnhancedNumberValidator<double>(0.0, 1e300));
  valid->set("Type", "Contact Wall", "a frictional contact wall (SPEC §2)");
  Teuchos::setStringToIntegralParameter<int>(
      "Friction Law", "Coulomb",
      "Coulomb (ν p, capped by sticking), Tresca (m σ̄/√3), Orowan (min of both), Norton (α_f K |u_t|^(q-1) u_t), None",
      Teuchos::tuple<std::string>("Coulomb", "Tresca", "Orowan", "Norton", "None"), valid.get());
  valid->set("Friction Coefficient", 0.0, "ν >= 0 (Coulomb, Orowan)", nonNegative);
  valid->set("Shear Factor", 0.0, "m in [0, 1] (Tresca, Orowan)", Teuchos::rcp(new EnhancedNumberValidator<double>(0.0, 1.0)));
  valid->set("Norton Coefficient", 0.0, "α_f K >= 0 (Norton) [stress·(time/length)^q]", nonNegative);
  valid->set("Norton Exponent", 1.0, "q > 0 (Norton)");
  valid->set("Norton Regularization", 1e-6, "ε > 0 in (u_t² + ε²)^((q-1)/2) [velocity]");
  valid->set("Normal Penalty Factor", 1e3, "κ_n > 0: α_n = κ_n μ (× 2π r)");
  valid->set("Tangential Penalty Factor", 10.0,
             "κ_t > 0: sticking stiffness α_t = κ_t μ (× 2π r); the extrusion's ram force changes by < 3e-4 "
             "for κ_t in [1, 1000], and Newton needs more iterations as κ_t grows "
             "(docs/extrusion_verification.md §4)");
  valid->set("Penalty Viscosity", 0.0,
             "μ in the penalties: 0 (default) = the largest adjacent cell viscosity, refreshed before every "
             "flow solve; > 0 = this fixed value at every node, so the penalties do not depend on the "
             "solution (docs/sensitivity.md: an external finite-difference check needs that)",
             nonNegative);
  Teuchos::setStringToIntegralParameter<int>("Initial Status", "Active", "status of every wall node at the start",
                                             Teuchos::tuple<std::string>("Active", "Free"), valid.get());
  return valid;
}

ContactWall::ContactWall(const std::string& group, const Teuchos::ParameterList& params, const Mesh& mesh,
                         Geometry geometry)
    : m_geometry(geometry) {
  Teuchos::ParameterList list = params;
  try {
    list.validateParametersAndSetDefaults(*validParameters());
  } catch (const std::exception& e) {
    throw InputError("Boundary Conditions/" + group + " (Contact Wall): " + e.what());
  }
  auto positive = [&](const char* name) {
    const double v = list.get<double>(name);
    if (!(v > 0.0))
      throw InputError("Boundary Conditions/" + group + "/" + name + " must be > 0 (got " + Teuchos::toString(v) + ")");
    return v;
  };
  const std::string law = list.get<std::string>("Friction Law");
  m_settings.law = law == "Coulomb" ? FrictionLaw::Coulomb
                   : law == "Tresca" ? FrictionLaw::Tresca
                   : law == "Orowan" ? FrictionLaw::Orowan
                   : law == "Norton" ? FrictionLaw::Norton
                                     : FrictionLaw::None;
  m_settings.frictionCoefficient = list.get<double>("Friction Coefficient");
  m_settings.shearFactor = list.get<double>("Shear Factor");
  m_settings.nortonCoefficient = list.get<double>("Norton Coefficient");
  m_settings.nortonExponent = positive("Norton Exponent");
  m_settings.nortonRegularization = positive("Norton Regularization");
  m_settings.normalPenalty = positive("Normal Penalty Factor");
  m_settings.tangentialPenalty = positive("Tangential Penalty Factor");
  m_settings.penaltyViscosity = list.get<double>("Penalty Viscosity");
  m_settings.initiallyActive = list.get<std::string>("Initial Status") == "Active";

  // InputError for a missing group, a zero-length segment, a branched group.
  m_curve = buildBoundaryCurve(mesh, mesh.boundary(group));
  m_active.assign(m_curve.nodes.size(), m_settings.initiallyActive);
  m_changes.assign(m_curve.nodes.size(), 0);
  m_cornerNormals.resize(m_curve.nodes.size());
  m_viscosity.assign(m_curve.nodes.size(), 1.0);
  m_flowStress.assign(m_curve.nodes.size(), 1.0);
  for (GO node : m_curve.nodes) m_coords.push_back(mesh.coords[node]);
}

std::vector<std::array<GO, 2>> ContactWall::couplings() const {
  std::vector<std::array<GO, 2>> pairs;
  for (int k = 0; k < numNodes(); ++k)
    if (next(k) >= 0) pairs.push_back({m_curve.nodes[k], m_curve.nodes[next(k)]});
  return pairs;
}

void ContactWall::setScales(std::vector<double> viscosity, std::vector<double> flowStress) {
  m_viscosity = std::move(viscosity);
  m_flowStress = std::move(flowStress);
}

StatusChange ContactWall::nextChange(const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                                     double pressureTolerance, double penetrationTolerance,
                                     int maxChangesPerNode, int* unsettled) const {
  StatusChange atLimit, anywhere;
  if (unsettled) *unsettled = 0;
  for (int k = 0; k < numNodes(); ++k) {
    double violation = 0.0;
    if (m_active[k]) {
      violation = -p[k] - pressureTolerance;  // tension beyond the tolerance
    } else {
      const auto& n = m_curve.normals[k];
      violation = u[k][0] * n[0] + u[k][1] * n[1] - penetrationTolerance;  // moving into the tool
      for (const auto& other : m_cornerNormals[k])  // convex tool corner: into every half-plane
        violation = std::min(violation, u[k][0] * other[0] + u[k][1] * other[1] - penetrationTolerance);
    }
    if (!(violation > 0.0)) continue;
    if (m_changes[k] >= maxChangesPerNode) {
      if (unsettled) ++*unsettled;
      continue;
    }
    const int a = previous(k), b = next(k);
    const bool limit = a < 0 || b < 0 || m_active[a] != m_active[k] || m_active[b] != m_active[k];
    StatusChange& best = limit ? atLimit : anywhere;
    if (violation > best.violation) best = {k, !m_active[k], violation};
  }
  return atLimit.node >= 0 ? atLimit : anywhere;
}

}  // namespace flowform
