#include "flowform/estimation/ResponseAdjoint.hpp"

namespace flowform {

bool responseAdjoint(FlowModel& model, const Vector& x, const Responses& responses, const std::string& name,
                     const Mesh& mesh, Vector& z, bool factor) {
  const Assembler& assembler = model.assembler();
  const DofMap& dofMap = assembler.dofMap();
  Vector c(dofMap.ownedMap()), gradient(dofMap.ownedMap());
  if (!responses.reactionWeights(name, mesh, dofMap, assembler.physics().kernel.geometry, c)) return false;
  auto unconstrained = assembler.createJacobian();
  assembler.unconstrainedJacobian(x, *unconstrained);
  if (factor) {
    model.restartLinearization();  // the exact K_t at x
    model.computeJacobian(x);
  }
  // ∂φ/∂q = J_uncᵀ c, then K_tᵀ z = ∂φ/∂q.
  unconstrained->apply(c, gradient, Teuchos::TRANS);
  model.solveTranspose(gradient, z);
  // K_tᵀ's constraint columns leave junk at the held velocity components; z lives in the
  // test space, which vanishes there.
  assembler.boundaryConditions().imposeOnSolution(z, true);
  // ζ = c − z: z carries c's one-element layer next to the response's group (z = 0 on the held
  // components there, z ≈ c one node in); ζ, the adjoint with the response's Dirichlet data,
  // is smooth there, so its interpolation error measures the solution's, not the layer's.
  z.update(1.0, c, -1.0);
  return true;
}

}  // namespace flowform
