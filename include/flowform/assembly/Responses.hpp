// Functionals of a converged solution (the case's "Responses" sublist), by name:
//   Boundary Force  — Σ over the group's nodes of the reaction (the unconstrained momentum
//                     residual: the force the tool applies to the material), component X or Y
//   Mean Pressure   — −Σ R_i·n_i / A over the group: the mean normal pressure the tool applies
//                     (A its length, or area 2πr ds when axisymmetric)
//   Boundary Power  — Σ R_i·u_i over the group: the power the tool puts in
//   Flow Rate       — ∫ u·n dΓ over the group (n outward; 2πr dΓ axisymmetric): the volume
//                     flux leaving through it (negative where material enters)
//   Plastic Power   — ∫ s:D dΩ = ∫ 2μ D:D dΩ, the viscoplastic dissipation (≈ ∫ σ̄ e dΩ)
//   Friction Power  — Σ over active wall nodes of g_k u_t,k, the friction dissipation
//   Penalty Power   — Σ over active wall nodes of α_n (u·n)², the work of the normal penalty
//   Stabilization Power — Σ_K τ_K ∫_K ∇p·(∇p − f) dΩ = −∫ p div u: the work of the pressure
//                     stabilization. With the two above, the discrete power balance
//                     Σ_tools Boundary Power = Plastic + Friction + Penalty + Stabilization
//                     holds to solver tolerance; the last two vanish as h → 0.
//   Dead Zone       — area (volume) of the cells where |u| < Fraction × Reference Speed
//   Boundary Extent — the largest coordinate (Component X or Y) of the group's nodes: where a free
//                     surface ends (the extrudate's half-thickness at the outlet: the swell)
//   Wall Gap        — the distance from its tool of a contact wall's downstream end (away from its
//                     Start Group) when its released runs are free surfaces: the gap of the
//                     separated product; 0 for other walls (their nodes never leave the tool)
//   Contact Length  — the arc length along a contact wall from its upstream end (Start Group) to its
//                     farthest active node: the tool–chip contact length (to within a segment; no
//                     derivative, like Dead Zone)
//   Wall Force      — the force the material exerts on a contact wall (Component X or Y): the sum of
//                     the wall's part of the momentum residual (normal penalty and friction); a
//                     tool's cutting and thrust forces
//   Thickness Ratio — t / w: t the Reference Thickness, w the thickness of the stream leaving through
//                     the group, normal to its mean velocity ū (w = |Δx × ū|/|ū|, Δx the group's
//                     chord): cutting's chip ratio t/t_c at the chip's outlet
//   Shear Angle     — φ from the chip ratio r and the Rake Angle α by the thin shear plane's
//                     kinematics, tan φ = r cos α / (1 − r sin α), in degrees
// Boundary Extent and Wall Gap are positions: on a frozen shape their derivative is zero; the
// finite-difference check with re-converged free surfaces gives the derivative through the shape.
// Derivatives (docs/theory.md §4, paper eq. 21): dφ/dh = ∂φ/∂h + ∂φ/∂q dq/dh is the same evaluation
// on a directional-derivative Fad, x seeded along dq/dh and h seeded (the reactions' part
// from Assembler::tangent). Dead Zone is piecewise constant in q and has none.
// Forces are per unit depth in plane strain (for the modelled half when symmetric), total
// in axisymmetric models.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/assembly/Assembler.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/contact/ContactWall.hpp"

namespace flowform {

struct SensitivityParameter;

class Responses {
 public:
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// `list` is the "Responses" sublist; InputError for a bad type or a missing group.
  Responses(const Teuchos::ParameterList& list, const Mesh& mesh);

  /// InputError for a Wall Gap or Contact Length on a group that is not a contact wall.
  void checkWalls(const std::vector<ContactWall>& walls) const;

  /// Every response at x, the same on every rank.
  std::map<std::string, double> evaluate(const Vector& xOwned, const Mesh& mesh, const DofMap& dofMap,
                                         const Assembler& assembler, const std::vector<ContactWall>& walls) const;

  /// dφ/dh of every response but Dead Zone, with dxOwned = dq/dh: the total derivative
  /// along (dq/dh, h), the same on every rank.
  std::map<std::string, double> derivatives(const Vector& xOwned, const Vector& dxOwned, const SensitivityParameter& h,
                                            const Mesh& mesh, const DofMap& dofMap, const Assembler& assembler,
                                            const std::vector<ContactWall>& walls) const;

  /// For a response linear in the reactions, φ = c·R_unc(x) (Boundary Force: c = e_X or e_Y
  /// on the group's nodes; Mean Pressure: c = −n/A), c on the owned map; false (c untouched)
  /// for the other types. The adjoint of the error estimates starts from it.
  bool reactionWeights(const std::string& name, const Mesh& mesh, const DofMap& dofMap, Geometry geometry,
                       Vector& c) const;

  /// Response names, in the case's order.
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const Response& r : m_responses) n.push_back(r.name);
    return n;
  }

 private:
  /// Values (Scalar double), or values and derivatives along (dx, h) (an AD Scalar).
  template <typename Scalar>
  std::map<std::string, Scalar> evaluateAs(const Vector& xOwned, const Vector* dxOwned, const SensitivityParameter* h,
                                           const Mesh& mesh, const DofMap& dofMap, const Assembler& assembler,
                                           const std::vector<ContactWall>& walls) const;
  struct Response {
    std::string name, type, boundary, component;
    double fraction = 0.01, referenceSpeed = 1.0;
    double referenceThickness = 1.0, rakeAngle = 0.0;  ///< Thickness Ratio, Shear Angle (degrees)
  };
  std::vector<Response> m_responses;
};

}  // namespace flowform
