// The functionals of a converged solution: the case's "Responses" sublist, one sublist per
// response naming its Type (the registered types: ResponseRegistry.hpp, one file each in this
// folder). Every response is evaluated by the same templated code for its value and for its total
// derivative dφ/dh = ∂φ/∂h + ∂φ/∂q dq/dh (docs/theory.md §4, paper eq. 21): a directional-
// derivative Fad with x seeded along dq/dh and h seeded (the reactions' part from
// Assembler::tangent). Forces are per unit depth in plane strain (for the modelled half when
// symmetric), total in axisymmetric models.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/assembly/Assembler.hpp"
#include "flowform/contact/ContactWall.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/mesh/Mesh.hpp"

namespace flowform {

struct SensitivityParameter;
class ResponseFunction;

class Responses {
 public:
  /// One response sublist's entries (validResponseParameters()).
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// `list` is the "Responses" sublist; InputError for a bad type or a missing group.
  Responses(const Teuchos::ParameterList& list, const Mesh& mesh);

  /// InputError for a response that measures a contact wall (Wall Gap, Contact Length, Wall
  /// Force) on a group that is not one.
  void checkWalls(const std::vector<ContactWall>& walls) const;
  /// InputError naming the first response that reads a field (Temperature, Strain) the case does
  /// not have (`fields`: the case's).
  void checkFields(const FieldRegistry& fields) const;

  /// Every response at x, the same on every rank.
  /// `reactions`: the unconstrained residual at x when the caller has it (else assembled here).
  std::map<std::string, double> evaluate(const Vector& xOwned, const Mesh& mesh, const DofMap& dofMap,
                                         const Assembler& assembler, const std::vector<ContactWall>& walls,
                                         const Vector* reactions = nullptr) const;

  /// dφ/dh of every differentiable response, with dxOwned = dq/dh: the total derivative
  /// along (dq/dh, h), the same on every rank.
  std::map<std::string, double> derivatives(const Vector& xOwned, const Vector& dxOwned, const SensitivityParameter& h,
                                            const Mesh& mesh, const DofMap& dofMap, const Assembler& assembler,
                                            const std::vector<ContactWall>& walls) const;

  /// ∂φ/∂h at fixed q of every differentiable response: the derivative along (0, h), the same on
  /// every rank (the explicit part of the adjoint's dφ/dh).
  std::map<std::string, double> partials(const Vector& xOwned, const SensitivityParameter& h, const Mesh& mesh,
                                         const DofMap& dofMap, const Assembler& assembler,
                                         const std::vector<ContactWall>& walls) const;

  /// The gradient ∂φ/∂q at x of each response in `names` (differentiable ones: differentiableNames()),
  /// column i of `gradient` (owned map) for names[i]. Each response is evaluated once on GradientFad,
  /// every dof of x and of the reactions R_unc(x) its own variable; the reactions' part is carried to
  /// q by the unconstrained Jacobian: ∂φ/∂q = ∂φ/∂x + J_uncᵀ ∂φ/∂R (docs/sensitivity.md "Adjoint").
  void gradients(const Vector& xOwned, const std::vector<std::string>& names, const Mesh& mesh, const DofMap& dofMap,
                 const Assembler& assembler, const std::vector<ContactWall>& walls, MultiVector& gradient) const;
  /// The names of the responses that have a derivative, in the case's order.
  std::vector<std::string> differentiableNames() const;

  /// For a response linear in the reactions (an adaptivity target), φ = c·R_unc(x) (Boundary
  /// Force: c = e_X or e_Y on the group's nodes; Mean Pressure: c = −n/A), c on the owned map;
  /// false (c untouched) for the other types. The adjoint of the error estimates starts from it.
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
                                           const std::vector<ContactWall>& walls,
                                           const Vector* givenReactions = nullptr) const;
  struct Response {
    std::string name, boundary;
    int type;  ///< index of responseTypes()
    std::shared_ptr<const ResponseFunction> function;
  };
  std::vector<Response> m_responses;
};

}  // namespace flowform
