#include "flowform/discretization/FieldRegistry.hpp"

#include <stdexcept>

#include "flowform/core/Types.hpp"

namespace flowform {

FieldRegistry FieldRegistry::flow() {
  FieldRegistry fields;
  fields.add({"Velocity", 2});
  fields.add({"Pressure", 1});
  static_assert(kUx == 0 && kUy == 1 && kP == 2, "the flow's components are registered first, in this order");
  return fields;
}

int FieldRegistry::add(const FieldDescription& field) {
  if (field.numComponents < 1) throw std::invalid_argument("field '" + field.name + "': no components");
  if (contains(field.name)) throw std::invalid_argument("field '" + field.name + "' is registered twice");
  m_first.push_back(numComponents());
  m_fields.push_back(field);
  return numFields() - 1;
}

bool FieldRegistry::contains(const std::string& name) const {
  for (const auto& f : m_fields)
    if (f.name == name) return true;
  return false;
}

int FieldRegistry::find(const std::string& name) const {
  for (int f = 0; f < numFields(); ++f)
    if (m_fields[f].name == name) return f;
  throw std::invalid_argument("no field '" + name + "' in this case");
}

std::vector<int> FieldRegistry::components(const std::vector<std::string>& names) const {
  std::vector<int> result;
  for (const auto& name : names) {
    const int f = find(name);
    for (int c = 0; c < m_fields[f].numComponents; ++c) result.push_back(component(f, c));
  }
  return result;
}

}  // namespace flowform
