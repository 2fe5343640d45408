// Shape parameters (docs/sensitivity.md "Shape parameters"): a constant of the case's .geo (a die
// angle, a roll radius, a land length), named "Geo Parameter:<name>" in Sensitivity/Parameters.
//
// The parameter moves the mesh, not a coefficient. Its mesh velocity V = dX/dh is measured by
// meshing the .geo at h ± δ (δ = kGeoMotionStep |h|) with the run's own options: each boundary
// group's nodes are followed along the group (the k-th node of the group in the other mesh is
// the k-th here: gmsh's 1-D meshing of a curve keeps its node count under a small change), and
// the interior follows the boundary by the harmonic extension of the free-surface loop
// (freesurface/MeshMotion) — gmsh's unstructured interior is not followed, since a change of
// 10⁻⁴ of the roll radius re-triangulates most of it. V = (X(h + δ) − X(h − δ)) / 2δ on this
// mesh's topology. Free-surface displacements are held (the converged mesh is X(h) + D; D does
// not move with h): the surfaces' own response is the total derivative's
// (sensitivity/ShapeDerivative).
//
// With V, the parameter enters the DDM like any other (docs/theory.md §4): K_t dq/dh = −∂R/∂h with
//     ∂R/∂h = ∂R/∂X V,      ∂φ/∂h = ∂φ/∂X V,
// both central differences of the residual and the responses at X ± εV with q held (ε V at most
// kMeshPartialMove of the mesh's size), the tools moved too (Problem::moveShape: the mesh as made
// moved along V), and whatever the mesh moves carries along: the wall normals, a rolling
// wall's fitted centre, the symmetry directions, the Dirichlet rows' prescribed values. A moving
// tool's nodes keep their velocity relative to the tool instead (q + Q_h ε at X + εV, Q_h the tool
// velocities' change per unit h, contact/ToolVelocities.hpp): the partials are then along (V, Q_h)
// and the DDM adds Q_h to the dq/dh it solves for, so dφ/dh is unchanged in exact arithmetic.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "flowform/assembly/SensitivityParameter.hpp"
#include "flowform/core/TpetraTypes.hpp"

namespace flowform {

class Problem;

/// The relative step of the meshings that measure V. Measured: on xml/rolling.xml the derivatives
/// by R and h1 from steps 10⁻³ and 10⁻⁴ agree to 2.3·10⁻⁶ (force, torque; the small forward slip's
/// by h1 to 5·10⁻⁵); on xml/extrusion.xml a step of 10⁻³ of the die opening changes the node count
/// of group die_face (22 against 21), which 10⁻⁴ does not.
constexpr double kGeoMotionStep = 1e-4;

/// The Mesh/Geo Parameters of a validated case (numbers), what "Geo Parameter:<name>" may name.
GeoParameterValues givenGeoParameters(const Teuchos::ParameterList& caseParams);

/// The problem's mesh as made, moved to the case's .geo meshed with Geo Parameter `name` = `value`
/// and every other option of its own (the sizes, the refinements, the size field): its boundary
/// nodes where that mesh puts them, its interior by the harmonic extension. InputError when a
/// boundary group's node count differs or a group is closed.
std::vector<std::array<double, 2>> meshedAt(const Problem& problem, const std::string& name, double value);

/// V = dX/dh at every node (as made, before free-surface moves).
std::vector<std::array<double, 2>> geoParameterMotion(const Problem& problem, const SensitivityParameter& h);

/// The largest node move of the central differences in the node positions, relative to the mesh's
/// size (GeoParameterMotion.cpp says why it is this small).
constexpr double kMeshPartialMove = 1e-9;

/// What h changes at a fixed flow x when the mesh moves along V.
struct MeshPartials {
  Teuchos::RCP<Vector> dRdh;            ///< ∂R/∂h|_q (the constrained residual's)
  std::map<std::string, double> dPhidh;  ///< ∂φ/∂h|_q of every response
  double dInflowForce = 0.0;             ///< ∂F/∂h|_q of a Rigid Inflow's balance (0 without)
  std::vector<std::array<double, 2>> motion;  ///< V, the mesh velocity they were made along
  /// Q_h, the flow held relative to the moving tools along V (null without a moving tool): the
  /// partials above are along (V, Q_h), dq/dh = Q_h − K_t⁻¹ ∂R/∂h (the DDM adds it).
  Teuchos::RCP<Vector> velocityShift;
};

/// A problem's partials of a Geo Parameter at its converged flow x (V measured, then meshPartials),
/// or of a Boundary Value (sensitivity/BoundaryValuePartials.hpp).
using GeoPartialsSource = std::function<MeshPartials(const SensitivityParameter& h, const Vector& x)>;
/// That source for `problem` (which must outlive it).
GeoPartialsSource geoPartialsOf(Problem& problem);

/// ∂R/∂h, ∂φ/∂h (and a Rigid Inflow's ∂F/∂h) at x by central differences at X ± εV; the mesh is
/// put back (collective).
MeshPartials meshPartials(Problem& problem, const Vector& x, const std::vector<std::array<double, 2>>& V);

/// `coords` moved by `amount` V (the problem's mesh with its free-surface displacements, or the
/// mesh as made that sets the tools).
std::vector<std::array<double, 2>> movedAlong(const std::vector<std::array<double, 2>>& coords,
                                              const std::vector<std::array<double, 2>>& V, double amount);

}  // namespace flowform
