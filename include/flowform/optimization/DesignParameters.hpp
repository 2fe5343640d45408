// The design of an optimization (docs/optimization.md): sensitivity parameters (the names of
// Sensitivity/Parameters, docs/sensitivity.md) that the optimizer moves, each tied to the case
// entries that hold its value:
//   Geo Parameter:<name>            Mesh/Geo Parameters/<name>
//   Boundary Value:<group>/<entry>  Boundary Conditions/<group>/<entry>
//   Friction Coefficient[:<wall>]   Boundary Conditions/<wall>/Friction Coefficient (every wall that
//   Shear Factor[:<wall>]           gives it, moved together, without a wall name), the same for m
//   Friction Field:<wall>/<j>       Boundary Conditions/<wall>/Friction Field, its value j
//   Thermal:<property>              Material/Thermal/<property>
//   <a law's constant>              Material/<name>
// Each starts from the case's value, which must lie within its bounds.
#pragma once

#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace flowform {

class DesignParameters {
 public:
  /// `names` from Optimization/Design Parameters; the case's entries that hold each (InputError
  /// naming the parameter when the case gives none, or gives a "moved together" value unequal
  /// on its walls).
  DesignParameters(const std::vector<std::string>& names, const Teuchos::ParameterList& caseParams);

  const std::vector<std::string>& names() const { return m_names; }
  std::size_t size() const { return m_names.size(); }
  /// Whether a design parameter is a Geo Parameter (the domain changes from design to design).
  bool movesShape() const;
  /// `params` with the design's Geo Parameters at `values` as its reference topology
  /// (Mesh/Reference Geo Parameters, freesurface/ReferenceTopology); unchanged without any.
  Teuchos::ParameterList onReferenceTopology(Teuchos::ParameterList params, const std::vector<double>& values) const;
  /// The case's own values (the start).
  const std::vector<double>& initial() const { return m_initial; }
  /// A copy of the case's parameters with the design `values` written into their entries.
  Teuchos::ParameterList applied(const Teuchos::ParameterList& caseParams, const std::vector<double>& values) const;

 private:
  /// Every entry of one parameter: the path of sublists, then the entry's name.
  using Path = std::vector<std::string>;
  std::vector<std::string> m_names;
  std::vector<std::vector<Path>> m_paths;
  std::vector<int> m_elements;  ///< per parameter: the index in an array entry, −1 for a number
  std::vector<double> m_initial;
};

}  // namespace flowform
