// A frictional contact wall on a named boundary group (SPEC §2, paper §2.1): a tool fixed in
// space, acting on the wall's nodes with no extra unknowns.
//
// On an ACTIVE node k with outward normal n_k (material → tool), tangent t_k = (−n_y, n_x):
//   normal penalty (paper eq. 16):  R_k += α_n (u_k·n_k) n_k
//   friction (eq. 17–19):           R_k += g_k t_k,  g_k the tangential force opposing u_t = u_k·t_k
// with α_n = κ_n μ_k W_k, α_t = κ_t μ_k W_k (κ dimensionless input factors, μ_k the largest
// cell viscosity at the node, W_k = 2π r_k axisymmetric, 1 in plane strain): the penalties
// scale with the bulk stiffness, so one default works across scenes.
//
// Coulomb (consistent lumping of ν p⁺ on the active segments, 2π r included):
//   f̂_k = ν Σ_s ∫_s N_k p⁺_h W ds     (plane strain: ν L (p⁺_k/3 + p⁺_o/6) per segment)
//   g_k = 0 if f̂_k ≤ 0;  α_t u_t if α_t |u_t| ≤ f̂_k (stick);  f̂_k sign(u_t) otherwise (slip)
// Tresca: f̂_k = Σ_s ∫_s N_k m σ̄_h/√3 W ds; Orowan: f̂_k = min(Coulomb, Tresca); both with the
// same sticking bound. Norton (viscous): g_k = α_f K (u_t² + ε²)^((q−1)/2) u_t Σ_s ∫_s N_k W ds.
// A segment is active when both its nodes are. μ_k and σ̄ are taken from the solution at
// the start of each flow solve and held during its Newton iterations (setScales).
//
// The law is templated on the dof scalar (Scalar) and on the friction parameters ν, m
// (PScalar, FrictionParameters): the same code gives values, the AD tangent and ∂/∂ν, ∂/∂m
// (SPEC §4, paper eq. 28). The branch is decided by the compression measure, not by f̂:
// Coulomb P_k = Σ_s ∫_s N_k p⁺_h W ds > 0, so at ν = 0 a compressed node slips with g = 0
// and ∂g/∂ν = P_k sign(u_t), while a node in tension (P_k ≤ 0) has g = ∂g/∂ν = 0; in stick
// g = α_t u_t does not depend on ν or m, so ∂g/∂ν = ∂g/∂m = 0 exactly.
//
// Nodal normal: the curve's (bisector of the two segment normals inside one wall; the
// segment's own at a wall's end). Where two walls meet at a corner, the node gets each
// wall's penalty along that wall's normal, so both velocity components are held there.
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "flowform/BoundaryCurve.hpp"
#include "flowform/Mesh.hpp"
#include "flowform/Types.hpp"

namespace flowform {

enum class FrictionLaw { None, Coulomb, Tresca, Orowan, Norton };

/// The friction parameters that sensitivity analysis may seed as AD variables.
template <typename PScalar>
struct FrictionParameters {
  PScalar frictionCoefficient;  ///< ν (Coulomb, Orowan)
  PScalar shearFactor;          ///< m (Tresca, Orowan)
};

/// Which branch of the law a wall node is on (a kink of the law lies between branches):
/// Free (not in contact), NoFriction (active but not compressed, or law None), Stick,
/// Slip (Coulomb-limited, or Tresca/Norton), SlipTresca (Orowan limited by m σ̄/√3).
enum class FrictionBranch { Free, NoFriction, Stick, Slip, SlipTresca };
const char* frictionBranchName(FrictionBranch b);

struct ContactWallSettings {
  FrictionLaw law = FrictionLaw::Coulomb;
  double frictionCoefficient = 0.0;  ///< ν
  double shearFactor = 0.0;          ///< m
  double nortonCoefficient = 0.0;    ///< α_f K
  double nortonExponent = 1.0;       ///< q
  double nortonRegularization = 1e-6;
  double normalPenalty = 1e3;        ///< κ_n
  double tangentialPenalty = 10.0;   ///< κ_t
  double penaltyViscosity = 0.0;     ///< fixed μ of the penalties; 0: the local cell viscosity
  bool initiallyActive = true;
};

/// What a status update decided: the wall node to change, or none (index −1).
struct StatusChange {
  int node = -1;
  bool activate = false;
  double violation = 0.0;  ///< tension (−p) or penetration (u·n)
};

class ContactWall {
 public:
  /// Valid entries of a "Contact Wall" group sublist (besides Type).
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();

  /// `params` is the group's sublist (validated here; InputError naming the group).
  ContactWall(const std::string& group, const Teuchos::ParameterList& params, const Mesh& mesh, Geometry geometry);

  const std::string& name() const { return m_curve.name; }
  const BoundaryCurve& curve() const { return m_curve; }
  const ContactWallSettings& settings() const { return m_settings; }
  int numNodes() const { return static_cast<int>(m_curve.nodes.size()); }
  /// Consecutive wall nodes, which the friction law couples (for the DofMap).
  std::vector<std::array<GO, 2>> couplings() const;

  bool isActive(int k) const { return m_active[k] != 0; }
  /// Changes the status of node k and counts the change.
  void setActive(int k, bool active) {
    m_active[k] = active;
    ++m_changes[k];
  }
  int changes(int k) const { return m_changes[k]; }
  /// Forgets the change counts (a new solve from this state, e.g. a finite-difference run,
  /// gets its own Max Changes Per Node).
  void resetChangeCounts() { m_changes.assign(m_changes.size(), 0); }
  const std::array<double, 2>& nodeCoordinates(int k) const { return m_coords[k]; }
  /// Wall neighbours of node k (−1 where the wall ends).
  int previous(int k) const { return k > 0 ? k - 1 : (m_curve.closed ? numNodes() - 1 : -1); }
  int next(int k) const { return k + 1 < numNodes() ? k + 1 : (m_curve.closed ? 0 : -1); }

  /// At a node this wall shares with another wall at a convex tool corner (the material's
  /// angle there is reflex, like the die lip), material moving along the other wall is not
  /// entering the tool: a free node penetrates only if u·n > tolerance for this wall's normal
  /// AND for each normal added here (the tool is the intersection of the half-planes).
  void addCornerNormal(int k, const std::array<double, 2>& otherNormal) { m_cornerNormals[k].push_back(otherNormal); }

  /// Per wall node: viscosity μ and flow stress σ̄ (largest over the adjacent cells).
  void setScales(std::vector<double> viscosity, std::vector<double> flowStress);
  void setFrictionCoefficient(double nu) { m_settings.frictionCoefficient = nu; }
  void setShearFactor(double m) { m_settings.shearFactor = m; }
  /// ν and m as the case gives them.
  FrictionParameters<double> frictionParameters() const {
    return {m_settings.frictionCoefficient, m_settings.shearFactor};
  }
  /// Whether ν (Coulomb, Orowan) or m (Tresca, Orowan) enters this wall's law.
  bool usesFrictionCoefficient() const {
    return m_settings.law == FrictionLaw::Coulomb || m_settings.law == FrictionLaw::Orowan;
  }
  bool usesShearFactor() const { return m_settings.law == FrictionLaw::Tresca || m_settings.law == FrictionLaw::Orowan; }

  /// The two momentum rows of wall node k: dofs are u_k (2) and the pressures of
  /// previous(k), k, next(k) (an absent neighbour's is ignored). Adds into R[2]. The
  /// friction parameters are `fp` (PScalar: double, or an AD type when ∂/∂ν, ∂/∂m are
  /// wanted; Scalar must then be an AD type of the same kind).
  template <typename Scalar, typename PScalar>
  void addNodeResidual(int k, const FrictionParameters<PScalar>& fp, const Scalar* u, const Scalar* p, Scalar* R) const;
  template <typename Scalar>
  void addNodeResidual(int k, const Scalar* u, const Scalar* p, Scalar* R) const {
    addNodeResidual(k, frictionParameters(), u, p, R);
  }

  /// Tangential force g_k (positive along t_k) and the branch of the law it is on.
  template <typename Scalar, typename PScalar>
  Scalar tangentialForce(int k, const FrictionParameters<PScalar>& fp, const Scalar* u, const Scalar* p,
                         FrictionBranch* branch = nullptr) const;
  /// g_k with the case's ν, m, and whether the node sticks, for output.
  template <typename Scalar>
  Scalar tangentialForce(int k, const Scalar* u, const Scalar* p, bool* sticks = nullptr) const {
    FrictionBranch b;
    const Scalar g = tangentialForce(k, frictionParameters(), u, p, &b);
    if (sticks) *sticks = b == FrictionBranch::Stick;
    return g;
  }

  /// The next status change (SPEC §2): an active node in tension (p < −pressureTolerance)
  /// is released, a free node that penetrates (u·n > penetrationTolerance) is activated;
  /// among the candidates at the limit of the contact zone (a neighbour of the other
  /// status, or a wall end) the one with the largest violation. Candidates not at a limit
  /// are taken only when no limit node is one. `p`, `u` per wall node. A node that has
  /// already changed `maxChangesPerNode` times is not changed again (it would cycle);
  /// `unsettled` returns how many such nodes still violate their criterion.
  StatusChange nextChange(const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                          double pressureTolerance, double penetrationTolerance, int maxChangesPerNode,
                          int* unsettled = nullptr) const;

 private:
  /// f̂_k; `loaded` is false when the node carries no friction (Coulomb, Orowan: P_k ≤ 0);
  /// `trescaLimited` when Orowan takes the m σ̄/√3 bound.
  template <typename Scalar, typename PScalar>
  Scalar lumpedFrictionBound(int k, const FrictionParameters<PScalar>& fp, const Scalar* p, bool& loaded,
                             bool& trescaLimited) const;
  double weight(int k) const;  ///< W_k: 2π r_k or 1

  BoundaryCurve m_curve;
  ContactWallSettings m_settings;
  Geometry m_geometry;
  std::vector<char> m_active;
  std::vector<int> m_changes;
  std::vector<std::vector<std::array<double, 2>>> m_cornerNormals;
  std::vector<double> m_viscosity, m_flowStress;
  std::vector<std::array<double, 2>> m_coords;
};

// ---------------------------------------------------------------------------------------

inline double ContactWall::weight(int k) const {
  return m_geometry == Geometry::Axisymmetric ? 2.0 * M_PI * m_coords[k][0] : 1.0;
}

template <typename Scalar, typename PScalar>
Scalar ContactWall::lumpedFrictionBound(int k, const FrictionParameters<PScalar>& fp, const Scalar* p, bool& loaded,
                                        bool& trescaLimited) const {
  // P_k = Σ_s ∫_s N_k p⁺_h W ds and S_k = Σ_s ∫_s N_k σ̄_h W ds over active segments,
  // 2-point Gauss (exact: N, p_h, σ̄_h, W linear).
  const double gp[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  const bool coulomb = usesFrictionCoefficient();
  const bool tresca = usesShearFactor();
  Scalar pressureIntegral = 0.0;
  double stressIntegral = 0.0;
  const int neighbours[2] = {previous(k), next(k)};
  for (int side = 0; side < 2; ++side) {
    const int o = neighbours[side];
    if (o < 0 || !m_active[o]) continue;
    const double L = std::hypot(m_coords[o][0] - m_coords[k][0], m_coords[o][1] - m_coords[k][1]);
    const Scalar pk = p[1] > 0.0 ? p[1] : Scalar(0.0);                                  // p⁺_k
    const Scalar po = p[side == 0 ? 0 : 2] > 0.0 ? p[side == 0 ? 0 : 2] : Scalar(0.0);  // p⁺_o
    for (double s : gp) {
      const double Nk = 1.0 - s, No = s;
      double w = 0.5 * L;
      if (m_geometry == Geometry::Axisymmetric) w *= 2.0 * M_PI * (Nk * m_coords[k][0] + No * m_coords[o][0]);
      if (coulomb) pressureIntegral += w * Nk * (Nk * pk + No * po);
      if (tresca) stressIntegral += w * Nk * (Nk * m_flowStress[k] + No * m_flowStress[o]);
    }
  }
  trescaLimited = false;
  // Coulomb and Orowan act only under compression; Tresca wherever the segment is active.
  loaded = coulomb ? pressureIntegral > 0.0 : stressIntegral > 0.0;
  const Scalar fCoulomb = fp.frictionCoefficient * pressureIntegral;
  const Scalar fTresca = fp.shearFactor * (stressIntegral / std::sqrt(3.0));
  if (m_settings.law == FrictionLaw::Coulomb) return fCoulomb;
  if (m_settings.law == FrictionLaw::Tresca) return fTresca;
  trescaLimited = !(fCoulomb < fTresca);  // Orowan: min(ν P, m S/√3)
  return trescaLimited ? fTresca : fCoulomb;
}

template <typename Scalar, typename PScalar>
Scalar ContactWall::tangentialForce(int k, const FrictionParameters<PScalar>& fp, const Scalar* u, const Scalar* p,
                                    FrictionBranch* branch) const {
  FrictionBranch b = FrictionBranch::Free;
  Scalar g = 0.0;
  if (m_active[k]) {
    b = FrictionBranch::NoFriction;
    const auto& n = m_curve.normals[k];
    const Scalar ut = -n[1] * u[0] + n[0] * u[1];  // u·t, t = (−n_y, n_x)
    if (m_settings.law == FrictionLaw::Norton) {
      double tributary = 0.0;  // Σ_s ∫_s N_k W ds
      for (int o : {previous(k), next(k)}) {
        if (o < 0 || !m_active[o]) continue;
        const double L = std::hypot(m_coords[o][0] - m_coords[k][0], m_coords[o][1] - m_coords[k][1]);
        tributary += m_geometry == Geometry::Axisymmetric
                         ? 2.0 * M_PI * L * (m_coords[k][0] / 3.0 + m_coords[o][0] / 6.0)
                         : 0.5 * L;
      }
      using std::pow;
      const double eps = m_settings.nortonRegularization;  // u_t² + ε² > 0: pow is differentiable
      b = FrictionBranch::Slip;
      g = m_settings.nortonCoefficient * tributary * pow(ut * ut + eps * eps, 0.5 * (m_settings.nortonExponent - 1.0)) * ut;
    } else if (m_settings.law != FrictionLaw::None) {
      bool loaded = false, trescaLimited = false;
      const Scalar fHat = lumpedFrictionBound(k, fp, p, loaded, trescaLimited);
      if (loaded) {  // otherwise no compression: no friction, and ∂/∂ν = 0 (eq. 28)
        const double alphaT = m_settings.tangentialPenalty * m_viscosity[k] * weight(k);
        const Scalar stick = alphaT * ut;  // f* = α_t |u_t|, the sticking bound
        if ((stick >= 0.0 ? stick : Scalar(-stick)) <= fHat) {
          b = FrictionBranch::Stick;  // independent of ν and m: ∂/∂ν = ∂/∂m = 0 (eq. 28)
          g = stick;
        } else {
          b = trescaLimited ? FrictionBranch::SlipTresca : FrictionBranch::Slip;
          g = ut >= 0.0 ? fHat : Scalar(-fHat);  // slip: f̂ opposing u_t
        }
      }
    }
  }
  if (branch) *branch = b;
  return g;
}

template <typename Scalar, typename PScalar>
void ContactWall::addNodeResidual(int k, const FrictionParameters<PScalar>& fp, const Scalar* u, const Scalar* p,
                                  Scalar* R) const {
  if (!m_active[k]) return;
  const auto& n = m_curve.normals[k];
  const double alphaN = m_settings.normalPenalty * m_viscosity[k] * weight(k);
  const Scalar un = n[0] * u[0] + n[1] * u[1];
  R[0] += alphaN * un * n[0];
  R[1] += alphaN * un * n[1];
  const Scalar g = tangentialForce(k, fp, u, p);
  R[0] += g * (-n[1]);
  R[1] += g * n[0];
}

}  // namespace flowform
