// The energy balance of a case with a Temperature field (docs/theory.md §10), written to
// summary.json as "energy_balance" after the solve: where the heat the metal makes goes.
//
// Testing the energy equation with Σ_a N_a = 1 (the SUPG term vanishes: a·∇1 = 0, and so does the
// diffusion) gives, at any state, with R_T the unconstrained temperature rows (the reactions):
//   Σ_a R_T,a = ∫ ρc u·∇T dΩ − η ∫ s:D dΩ − Σ_walls β P_f,
// and at convergence R_T vanishes except at the groups that hold or transfer their temperature,
// where −Σ R_T is the heat that leaves there (the Heat Flow response). So
//   η P + Σ β P_f  =  Q_out  +  C,     C = ∫ ρc u·∇T dΩ (the heat the flow carries out),
// Q_out = −Σ R_T over the nodes of those groups (each node once). The "imbalance" η P + Σ β P_f −
// Q_out − C is Σ R_T over every other node: what Newton left, zero at convergence (a check of the
// solve and of the Heat Flow's consistency with the assembly, not of the discretization).
// The carried heat is also the enthalpy that crosses the boundary,
//   C = Σ_groups E_g − ρc ∫ (T − T_ref) div u_h dΩ,   E_g = ρc ∫_g (T − T_ref) u·n dΓ,
// T_ref the mixing-cup temperature of what enters: the last term ("mass_loss_term") is what the
// discrete flow's mass loss (div u_h ≠ 0 near a die corner) and the boundary's lumped quadrature
// take from the physical balance, and "enthalpy_closure" = (η P + Σ β P_f − Q_out − Σ E_g) / scale
// says how closely that physical balance closes ("scale" the largest of the heat made, the heat
// out and Σ |E_g|: a case that only cools makes no heat; "relative_imbalance" is over it too).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace flowform {

class Problem;

struct EnergyBalance {
  double referenceTemperature = 0.0;           ///< T_ref: the mixing-cup temperature entering
  double plasticHeat = 0.0;                    ///< η ∫ s:D dΩ
  std::map<std::string, double> frictionPower; ///< per contact wall: P_f = Σ_k g_k (u_k − v_w)·t_k
  std::map<std::string, double> frictionHeat;  ///< per contact wall: β P_f, the share the metal keeps
  double heatMade = 0.0;                       ///< η P + Σ β P_f
  std::map<std::string, double> heatOut;       ///< per group that holds or transfers T: its Heat Flow
  double heatOutTotal = 0.0;                   ///< Q_out: −Σ R_T over those groups' nodes (each once)
  std::map<std::string, double> enthalpyFlow;  ///< per boundary group through which material flows: E_g
  double convected = 0.0;                      ///< C = ∫ ρc u·∇T dΩ
  double imbalance = 0.0;                      ///< η P + Σ β P_f − Q_out − C: Σ R_T at the other nodes
  double massLossTerm = 0.0;                   ///< C − Σ E_g
  /// Groups that are not one simple curve: no per-group heat (Heat Flow) or enthalpy flow for them
  /// (their nodes still count in Q_out; their enthalpy is then in mass_loss_term).
  std::vector<std::string> groupsLeftOut;
  double scale = 0.0;                          ///< the largest of |η P + Σ β P_f|, |Q_out|, Σ |E_g|
  double enthalpyClosure = 0.0;                ///< (η P + Σ β P_f − Q_out − Σ E_g) / scale

  /// The "energy_balance" block.
  void report(nlohmann::json& summary) const;
};

/// The balance at the problem's solution (a case with Material/Thermal), the same on every rank.
EnergyBalance energyBalance(const Problem& problem);

}  // namespace flowform
