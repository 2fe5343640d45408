// Point Value: one field of the solution at a point of the material (a thermocouple, a
// pressure tap, a velocity probe),
//   φ = Σ_a N_a(x) q_a,
// the finite-element interpolant of the field's nodal values q_a in the cell that holds x
// (PointLocator: P1 barycentric or Q1 bilinear values). The point is fixed in space: when a
// free surface or a Geo Parameter moves the mesh, the cell and the N_a(x) follow the nodes, so a
// total derivative through the moving surface counts the interpolant's motion too.
//
// `Field` is a component of the case's unknowns: Velocity X, Velocity Y, Pressure, Temperature
// (only with Material/Thermal), Strain (only with Material/Strain Field; fieldRead). A point outside the mesh is refused
// before the solve (checkMesh); one that a moving surface leaves outside is an input error at
// evaluation (exit 2, before any output is written).
#pragma once

#include <array>
#include <string>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/mesh/PointLocator.hpp"
#include "flowform/responses/ResponseContext.hpp"

namespace flowform {

struct PointValue {
  static constexpr const char* kName = "Point Value";
  static constexpr const char* kDescription =
      "the interpolated value of one Field (Velocity X, Velocity Y, Pressure, Temperature, Strain) at the point (X, "
      "Y): a thermocouple, a pressure tap";
  static constexpr bool kNeedsBoundary = false, kNeedsWall = false, kReactionBased = false, kAdaptivityTarget = false,
                        kDifferentiable = true;

  static void declareParameters(Teuchos::ParameterList& list) {
    list.set("Field", "Temperature",
             "Point Value: the component read (Temperature needs Material/Thermal, Strain Material/Strain Field)",
             Teuchos::rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>(
                 "Velocity X", "Velocity Y", "Pressure", kTemperatureField, kStrainField))));
    list.set("X", 0.0, "Point Value: x (r when axisymmetric) of the point, in the mesh's units", finiteNumber());
    list.set("Y", 0.0, "Point Value: y (z when axisymmetric) of the point, in the mesh's units", finiteNumber());
  }
  explicit PointValue(const Teuchos::ParameterList& p)
      : m_field(p.get<std::string>("Field")), m_point{p.get<double>("X"), p.get<double>("Y")} {}

  /// The field besides the flow's that the point reads ("" for the flow's own).
  std::string fieldRead() const { return m_field == kTemperatureField || m_field == kStrainField ? m_field : ""; }

  /// Refuses a point that no cell of the (initial) mesh holds.
  void checkMesh(const Mesh& mesh) const {
    if (!PointLocator(mesh).locate(m_point).inside)
      throw InputError("X, Y: the point (" + std::to_string(m_point[0]) + ", " + std::to_string(m_point[1]) +
                       ") lies outside mesh '" + mesh.source + "'");
  }

  template <typename Scalar>
  Scalar evaluate(const ResponseContext<Scalar>& c) const {
    const int component = m_field == "Velocity X"   ? kUx
                          : m_field == "Velocity Y" ? kUy
                          : m_field == "Pressure"   ? kP
                                                    : c.dofMap.fields().componentOf(m_field);
    if (component < 0) throw InputError("Responses: a Point Value of " + m_field + " needs its field");
    const CellPoint at = PointLocator(c.mesh).locate(m_point);
    if (!at.inside)
      throw InputError("Responses: a Point Value's point (" + std::to_string(m_point[0]) + ", " +
                       std::to_string(m_point[1]) + ") lies outside the mesh its free surfaces moved to: place it "
                       "inside the material");
    const GO* nodes = c.mesh.cell(at.cell);
    Scalar local = 0.0;
    for (int a = 0; a < nodesPerCell(c.mesh.cellType); ++a) {
      const LO n = c.dofMap.overlapIndex(nodes[a]);
      if (c.dofMap.ownsNode(n)) local += at.weights[a] * c.u(c.x, n, component);  // each node by its owner
    }
    return sumOverRanks(*c.dofMap.comm(), local);
  }

 private:
  std::string m_field;
  std::array<double, 2> m_point;
};

}  // namespace flowform
