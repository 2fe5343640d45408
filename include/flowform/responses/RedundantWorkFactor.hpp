// Redundant Work Factor: Φ = P / (Y Q ln(A_in/A_out)), the plastic power P = ∫ s:D dΩ over the
// work of homogeneous deformation at the flow stress Y (parameter Flow Stress) for the volume
// flux Q through the group (the outlet) and the area ratio of the Entry Boundary to it (A the
// group's length in plane strain, its area ∫ 2πr ds when axisymmetric: for a wire drawn from
// radius R0 to R1, ln(A_in/A_out) = 2 ln(R0/R1), the homogeneous strain). Φ = 1 for homogeneous
// deformation of a rigid-perfectly plastic material; Φ − 1 is the share of the plastic work
// spent in shearing the section (docs/drawing.md §2). Friction power is not in P.
#pragma once

#include <cmath>

#include "flowform/core/NumberRange.hpp"
#include "flowform/responses/CellPowers.hpp"
#include "flowform/responses/FlowRate.hpp"

namespace flowform {

struct RedundantWorkFactor {
  static constexpr const char* kName = "Redundant Work Factor";
  static constexpr const char* kDescription =
      "plastic power / (Flow Stress x flux through the group x ln(A of Entry Boundary / A of the group)): 1 for "
      "homogeneous deformation";
  static constexpr bool kNeedsBoundary = true, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) {
    declareBoundary(list, "the exit group the flux crosses");
    list.set("Entry Boundary", "", "Redundant Work Factor: the group the material enters through");
    list.set("Flow Stress", 1.0, "Redundant Work Factor: the flow stress Y of the homogeneous work (> 0)", positive());
  }
  explicit RedundantWorkFactor(const Teuchos::ParameterList& p)
      : m_exit(p.get<std::string>("Boundary")), m_entry(p.get<std::string>("Entry Boundary")),
        m_flowStress(p.get<double>("Flow Stress")) {
    if (m_entry.empty()) throw InputError("Redundant Work Factor: 'Entry Boundary' is required");
  }

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const BoundaryCurve exit = buildBoundaryCurve(c.mesh, c.mesh.boundary(m_exit));
    const BoundaryCurve entry = buildBoundaryCurve(c.mesh, c.mesh.boundary(m_entry));
    const double strain = std::log(curveArea(c.mesh, entry, c.geometry()) / curveArea(c.mesh, exit, c.geometry()));
    const Scalar flux = FlowRate::through(c, exit);
    return cellPower(c, true) / (m_flowStress * flux * strain);
  }

  /// The Entry Boundary must exist (the registry checks Boundary) and be the wider section: a
  /// section across the flow sweeps a larger area exactly when it is longer (r from the axis).
  void checkMesh(const Mesh& mesh) const {
    if (!mesh.hasBoundary(m_entry))
      throw InputError("Redundant Work Factor: the mesh has no boundary group '" + m_entry + "' (Entry Boundary)");
    const double in = curveArea(mesh, buildBoundaryCurve(mesh, mesh.boundary(m_entry)), Geometry::PlaneStrain);
    const double out = curveArea(mesh, buildBoundaryCurve(mesh, mesh.boundary(m_exit)), Geometry::PlaneStrain);
    if (!(in > out))
      throw InputError("Redundant Work Factor: the Entry Boundary '" + m_entry + "' (length " + std::to_string(in) +
                       ") is not wider than '" + m_exit + "' (" + std::to_string(out) +
                       "): no homogeneous strain to compare with");
  }

 private:
  std::string m_exit, m_entry;
  double m_flowStress;
};

}  // namespace flowform
