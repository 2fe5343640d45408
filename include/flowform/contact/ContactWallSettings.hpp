// What a contact wall's parameter list sets (ContactWall reads it from the case's Contact Wall
// sublist: its friction law and constants, penalty factors, which nodes may be released, and
// how its corners and Coulomb bound are treated, and how its tool moves; docs/theory.md §2, docs/contact.md).
#pragma once

#include <string>
#include <vector>

#include "flowform/contact/ToolMotion.hpp"
#include "flowform/contact/friction/FrictionLaw.hpp"

namespace flowform {

struct ContactWallSettings {
  int law = 0;                       ///< index in frictionLaws()
  double frictionCoefficient = 0.0;  ///< ν
  /// Friction Field: ν at N + 1 equally spaced stations along the wall (empty: ν everywhere).
  std::vector<double> frictionField;
  double shearFactor = 0.0;          ///< m
  FrictionSettings friction;         ///< the law's own constants
  double normalPenalty = 1e3;        ///< κ_n
  double tangentialPenalty = 10.0;   ///< κ_t
  double penaltyViscosity = 0.0;     ///< fixed μ of the penalties; 0: the local cell viscosity
  bool initiallyActive = true;
  /// Released Nodes = Free Surface: the wall's released tail is a free surface that leaves the
  /// tool (freesurface/FreeSurface.hpp); upstreamGroup names the group at its upstream end.
  bool releasedFreeSurface = false;
  bool neverReleased = false;  ///< Released Nodes = Never: bilateral, the status loop releases no node
  std::string upstreamGroup;
  /// Convex Corners = Closed: the wall's nodes at convex tool corners are held (active, never
  /// released), so no material crosses the wall's segment there (docs/contact.md).
  bool closedCorners = false;
  /// Coulomb Normal Force = Contact Force: the Coulomb bound is ν max(α_n u·n, 0) (the penalty's
  /// normal force) instead of ν ∫ N_k p⁺ ds.
  bool coulombOnContactForce = false;
  /// Tool Motion: the tool's surface velocity v_w (Fixed: 0).
  ToolMotion motion;
  /// Tangency Tolerance: the largest |v_w·n|/|v_w| accepted on the wall's segments.
  double tangencyTolerance = 1e-3;
};

}  // namespace flowform
