// The unknown fields of a case, in the order their components are numbered at a node
// (MOOSE's variables, Albany's DOF names). Each field has a name and a number of
// components; which nodes of an element carry it is the element layout's answer
// (discretization/ElementLayout.hpp), and where its dofs sit is the DofMap's.
//
// Component c of a node is the c-th component over the fields in registration order. The
// flow's fields come first — Velocity (u_x, u_y) then Pressure (p) — so their components
// are kUx, kUy, kP (core/Types.hpp) whatever else a case adds after them, and a flow-only
// case numbers its dofs exactly as before fields were registrable.
#pragma once

#include <string>
#include <vector>

namespace flowform {

struct FieldDescription {
  std::string name;       ///< unique, as kernels and outputs name it
  int numComponents = 1;  ///< 2 for the velocity, 1 for a scalar
};

/// The temperature field's name: a case with Material/Thermal registers it after the flow's
/// (docs/theory.md §10); kernels, responses and solvers look it up by this name.
inline constexpr const char* kTemperatureField = "Temperature";
/// The equivalent strain field's name: a case with Material/Strain Field registers it after the
/// flow's and the temperature's (docs/theory.md §1.1).
inline constexpr const char* kStrainField = "Strain";

class FieldRegistry {
 public:
  /// The flow's fields: Velocity (2 components) and Pressure (1).
  static FieldRegistry flow();

  /// Appends a field; its first component follows the last registered one. Throws on a
  /// repeated name or a component count below 1.
  int add(const FieldDescription& field);

  int numFields() const { return static_cast<int>(m_fields.size()); }
  const FieldDescription& field(int f) const { return m_fields[f]; }
  /// Index of the field called `name`; throws when the case has none.
  int find(const std::string& name) const;
  bool contains(const std::string& name) const;
  /// Node component of component `c` of field `f` (the field's first component + c).
  int component(int f, int c = 0) const { return m_first[f] + c; }
  int component(const std::string& name, int c = 0) const { return component(find(name), c); }
  /// The first component of the field called `name`, −1 when the case has none.
  int componentOf(const std::string& name) const { return contains(name) ? component(name) : -1; }
  /// Components of all fields together (at a node that carries every field).
  int numComponents() const { return m_first.empty() ? 0 : m_first.back() + m_fields.back().numComponents; }
  /// The node components of the named fields, in the order given (a kernel's element vector).
  std::vector<int> components(const std::vector<std::string>& names) const;

 private:
  std::vector<FieldDescription> m_fields;
  std::vector<int> m_first;  ///< first node component of each field
};

}  // namespace flowform
