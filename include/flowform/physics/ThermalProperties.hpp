// The thermal properties of the workpiece (Material/Thermal): a case that gives this sublist
// gets a Temperature field, coupled to the flow in one Newton (physics/kernels/CoupledFlowKernel.hpp,
// docs/theory.md §10); a case without it has no temperature unknowns at all.
//
//   k   Conductivity     [power / (length · temperature)]   mW/(mm K) = N/(s K) with mm, s, MPa
//   ρ   Density          [mass / volume]
//   c   Specific Heat    [energy / (mass · temperature)]
//   η   Heat Fraction    the share of the plastic power σ:D that heats the metal (0.9–1)
//
// Units are the case's: with lengths in mm, time in s and stresses in MPa a power density is
// MPa/s = mW/mm³, so ρc is in MPa/K (= mJ/(mm³ K); aluminium 2.4e-3 J/(mm³ K) = 2.4 MPa/K)
// and k in mW/(mm K) = N/(s K) (aluminium 0.2 W/(mm K) = 200 N/(s K)).
#pragma once

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace flowform {

/// The properties by index (the sensitivity parameters "Thermal:<name>").
enum ThermalParameter { kConductivity, kDensity, kSpecificHeat, kHeatFraction, kNumThermalParameters };
inline constexpr const char* kThermalParameterNames[kNumThermalParameters] = {"Conductivity", "Density",
                                                                              "Specific Heat", "Heat Fraction"};
inline constexpr const char* kThermalParameterSymbols[kNumThermalParameters] = {"k", "rho", "c", "eta"};

struct ThermalProperties {
  double conductivity = 1.0;   ///< k > 0
  double density = 1.0;        ///< ρ > 0
  double specificHeat = 1.0;   ///< c > 0
  double heatFraction = 0.9;   ///< η in [0, 1]
  /// ρ c, the volumetric heat capacity.
  double capacity() const { return density * specificHeat; }
  /// The property of index i (ThermalParameter).
  double& value(int i) { return i == kConductivity ? conductivity : i == kDensity ? density : i == kSpecificHeat ? specificHeat : heatFraction; }
  double value(int i) const { return const_cast<ThermalProperties*>(this)->value(i); }

  /// The entries of Material/Thermal, with their ranges.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// From a validated Material/Thermal sublist.
  static ThermalProperties fromParameters(const Teuchos::ParameterList& thermal);
};

/// What the temperature rows (CoupledFlowKernel) read, on the parameter scalar (PScalar: an AD type with the property a
/// sensitivity parameter seeds; assembly/EvaluationTypes.hpp thermalFor).
template <typename PScalar>
struct ThermalParameters {
  PScalar conductivity, capacity, heatFraction;  ///< k, ρc, η
};

}  // namespace flowform
