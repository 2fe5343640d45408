// The assembler's view of a physics kernel (physics/PhysicsKernel.hpp): CellKernel is the
// run-time interface the assembler loops over; CellKernelOf<Kernel> binds a kernel's field
// names to node components (FieldRegistry) and is the one cell loop — gather the read
// components, seed them for the evaluation type, evaluate, zero the constrained rows,
// scatter the owned rows (Albany's gather/scatter). The element vector's size is a
// compile-time constant, kNumComponents × the element's node count (withNodeCount), so the
// Jacobian's SFad stays fixed-size.
#pragma once

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "flowform/assembly/EvaluationTypes.hpp"
#include "flowform/bc/BoundaryConditions.hpp"
#include "flowform/discretization/CellGeometry.hpp"
#include "flowform/discretization/DofMap.hpp"
#include "flowform/discretization/ElementLayout.hpp"
#include "flowform/mesh/Mesh.hpp"
#include "flowform/physics/FlowPhysics.hpp"
#include "flowform/physics/PhysicsKernel.hpp"

namespace flowform {

/// What every kernel's cell loop reads from the assembler.
struct CellLoop {
  const Mesh& mesh;
  const DofMap& dofMap;
  const FlowPhysics& physics;                     ///< bulk settings and the case's material
  const std::vector<NodeConstraint>& constraints; ///< velocity constraints, per overlap node
  const std::vector<char>& prescribed;            ///< per overlap dof: a prescribed-value row (empty: none)
  const SensitivityParameter* h;                  ///< the seeded parameter (tangent), or null
  bool applyConstraints;
};

class CellKernel {
 public:
  virtual ~CellKernel() = default;
  virtual const char* name() const = 0;
  virtual const KernelFields& fields() const = 0;
  /// Node components this kernel owns (its rows).
  virtual std::vector<int> ownedComponents() const = 0;
  /// Adds this rank's cells' contributions for the evaluation type (tag dispatch).
  virtual void assemble(const CellLoop& loop, Workset& ws, ResidualEval) const = 0;
  virtual void assemble(const CellLoop& loop, Workset& ws, JacobianEval) const = 0;
  virtual void assemble(const CellLoop& loop, Workset& ws, TangentEval) const = 0;
};

template <class Kernel>
class CellKernelOf final : public CellKernel {
 public:
  static constexpr int C = Kernel::kNumComponents;

  /// Binds `kernel`'s fields to the components of `registry`; throws when a field is missing,
  /// the read components are not C, or an owned field is not read.
  CellKernelOf(Kernel kernel, const FieldRegistry& registry) : m_kernel(std::move(kernel)), m_fields(m_kernel.fields()) {
    const std::vector<int> read = registry.components(m_fields.read);
    if (static_cast<int>(read.size()) != C)
      throw std::invalid_argument(std::string("kernel '") + m_kernel.name() + "': its read fields have " +
                                  std::to_string(read.size()) + " components, its element vector " + std::to_string(C));
    std::copy(read.begin(), read.end(), m_components);
    for (int c : registry.components(m_fields.owned)) {
      const auto it = std::find(read.begin(), read.end(), c);
      if (it == read.end())
        throw std::invalid_argument(std::string("kernel '") + m_kernel.name() + "' owns a field it does not read");
      m_owned[it - read.begin()] = true;
    }
    m_ownsAll = std::all_of(m_owned, m_owned + C, [](bool o) { return o; });
    // The velocity constraints act on the rows (u_x, u_y) of whichever kernel owns them.
    for (int i = 0; i + 1 < C; ++i)
      if (m_components[i] == kUx && m_owned[i] && m_components[i + 1] == kUy && m_owned[i + 1]) m_velocityRow = i;
  }

  const char* name() const override { return m_kernel.name(); }
  const KernelFields& fields() const override { return m_fields; }
  std::vector<int> ownedComponents() const override {
    std::vector<int> owned;
    for (int i = 0; i < C; ++i)
      if (m_owned[i]) owned.push_back(m_components[i]);
    return owned;
  }
  const Kernel& kernel() const { return m_kernel; }

  void assemble(const CellLoop& loop, Workset& ws, ResidualEval) const override { dispatch<ResidualEval>(loop, ws); }
  void assemble(const CellLoop& loop, Workset& ws, JacobianEval) const override { dispatch<JacobianEval>(loop, ws); }
  void assemble(const CellLoop& loop, Workset& ws, TangentEval) const override { dispatch<TangentEval>(loop, ws); }

 private:
  template <typename EvalT>
  void dispatch(const CellLoop& loop, Workset& ws) const {
    withNodeCount(loop.mesh.cellType, [&](auto numNodes) { assembleCells<EvalT, decltype(numNodes)::value>(loop, ws); });
  }

  template <typename EvalT, int NumNodes>
  void assembleCells(const CellLoop& loop, Workset& ws) const {
    constexpr int N = C * NumNodes;
    using Scalar = typename EvalT::template Scalar<N>;
    using PScalar = typename EvalT::ParamScalar;
    const MaterialParameters<PScalar> material = materialFor<PScalar>(loop.physics.material, loop.h);
    const ThermalParameters<PScalar> thermal = thermalFor<PScalar>(loop.physics.thermal, loop.h);
    const DofMap& dofMap = loop.dofMap;
    const size_t numCells = dofMap.cells().size();
    CellGeometry g;
    LO dofs[N], rows[N];
    Scalar values[N], res[N], ownedRes[N];
    for (size_t k = 0; k < numCells; ++k) {
      computeCellGeometry(loop.mesh, dofMap.cells()[k], loop.physics.kernel.geometry, g);
      const LO* nodes = dofMap.cellNodes(k);
      dofMap.cellDofs(k, m_components, C, dofs);
      gather(ws, dofs, N, values);
      std::fill(res, res + N, Scalar(0.0));
      StressDualPoint* dual = Kernel::kUsesStressDual && ws.dual ? ws.dual->cells.cell(k, numCells) : nullptr;
      m_kernel.evaluate(
          CellContext<PScalar>{g, loop.physics.kernel, material, dual, &thermal, &loop.physics.strainField}, values,
          res);
      if (loop.applyConstraints) {
        if (m_velocityRow >= 0)
          for (int a = 0; a < NumNodes; ++a)
            applyConstraintRows(loop.constraints[nodes[a]], res + NodeMajorLayout<C>::index(a, m_velocityRow));
        if (!loop.prescribed.empty())
          for (int i = 0; i < N; ++i)
            if (loop.prescribed[dofs[i]]) res[i] = 0.0;  // the owner adds the row x − g
      }
      if (m_ownsAll) {
        scatter(ws, dofs, N, dofs, N, res);
      } else {
        int m = 0;
        for (int i = 0; i < N; ++i)
          if (m_owned[i % C]) {
            rows[m] = dofs[i];
            ownedRes[m++] = res[i];
          }
        scatter(ws, rows, m, dofs, N, ownedRes);
      }
    }
  }

  Kernel m_kernel;
  KernelFields m_fields;
  int m_components[C] = {};  ///< node component of each element-vector slot of a node
  bool m_owned[C] = {};
  bool m_ownsAll = false;
  int m_velocityRow = -1;  ///< slot of u_x when the kernel owns (u_x, u_y), else −1
};

/// The kernel as the assembler holds it, bound to the case's fields.
template <class Kernel>
std::shared_ptr<const CellKernel> makeCellKernel(Kernel kernel, const FieldRegistry& registry) {
  return std::make_shared<const CellKernelOf<Kernel>>(std::move(kernel), registry);
}

}  // namespace flowform
