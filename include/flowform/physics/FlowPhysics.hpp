// What the bulk physics is: geometry, stabilization, body force and the material law. The
// solvers change it between solves (continuation in n and e0); the assembler reads it.
#pragma once

#include "flowform/physics/FlowResidual.hpp"
#include "flowform/physics/Material.hpp"

namespace flowform {

struct FlowPhysics {
  FlowKernelSettings kernel;
  MaterialParameters<double> material = powerLaw(0.0, 1.0, 1.0, 1e-3);
};

}  // namespace flowform
