// The contact wall's nodal law (docs/theory.md §2) against hand values, its AD tangent against
// finite differences, and the status decisions.
#include <Sacado.hpp>
#include <Teuchos_UnitTestHarness.hpp>

#include "flowform/core/InputError.hpp"
#include "flowform/contact/ContactWall.hpp"

#include "BottomMesh.hpp"

namespace {

using namespace flowform;


ContactWall makeWall(const std::string& law, double nu, double m = 0.0, Geometry g = Geometry::PlaneStrain) {
  Teuchos::ParameterList p;
  p.set("Type", "Contact Wall");
  p.set("Friction Law", law);
  p.set("Friction Coefficient", nu);
  p.set("Shear Factor", m);
  p.set("Norton Coefficient", 0.7);
  p.set("Norton Exponent", 0.3);
  p.set("Normal Penalty Factor", 100.0);
  p.set("Tangential Penalty Factor", 10.0);
  ContactWall wall("bottom", p, bottomMesh(), g);
  wall.setScales({2.0, 2.0, 2.0}, {1.5, 1.5, 1.5});  // μ = 2, σ̄ = 1.5 at every node
  return wall;
}

const double kL = 0.5;

/// A wall node's stencil values (ContactWall::nodeStencil) from its velocity u[2] and the
/// pressures p[3] of its previous neighbour, itself and its next one; the neighbours'
/// velocities 0 (a wall with statuses does not read them).
template <typename T>
std::array<T, ContactWall::kNodeStencilSize> V(const T* u, const T* p) {
  return {u[0], u[1], p[0], p[1], p[2], T(0.0), T(0.0), T(0.0), T(0.0)};
}

TEUCHOS_UNIT_TEST(ContactWall, CoulombSlipIsConsistentlyLumpedPressure) {
  const ContactWall wall = makeWall("Coulomb", 0.2);
  // Middle node: two segments of length L; f̂ = ν [L(p1/3 + p0/6) + L(p1/3 + p2/6)].
  const double p[3] = {1.0, 2.0, 4.0};
  const double fHat = 0.2 * (kL * (2.0 / 3 + 1.0 / 6) + kL * (2.0 / 3 + 4.0 / 6));
  const double u[2] = {0.5, 0.0};  // slides along +t: α_t |u_t| = 10·2·0.5 = 10 > f̂
  bool sticks = true;
  TEST_FLOATING_EQUALITY(wall.tangentialForce(1, V(u, p).data(), &sticks), fHat, 1e-14);
  TEST_ASSERT(!sticks);
  // Residual: R += α_n (u·n) n + g t with α_n = 100·2, u·n = 0 here, t = (1, 0).
  double R[2] = {0.0, 0.0};
  wall.addNodeResidual(1, V(u, p).data(), R);
  TEST_FLOATING_EQUALITY(R[0], fHat, 1e-14);
  TEST_EQUALITY_CONST(R[1], 0.0);
  // Reversed sliding reverses the force.
  const double uBack[2] = {-0.5, 0.0};
  TEST_FLOATING_EQUALITY(wall.tangentialForce(1, V(uBack, p).data()), -fHat, 1e-14);
  // End node 0 has one segment: f̂ = ν L (p0/3 + p1/6) (its p[0] is ignored: no neighbour).
  const double pEnd[3] = {99.0, 1.0, 2.0};
  TEST_FLOATING_EQUALITY(wall.tangentialForce(0, V(u, pEnd).data()), 0.2 * kL * (1.0 / 3 + 2.0 / 6), 1e-14);
}

TEUCHOS_UNIT_TEST(ContactWall, StickBelowTheBoundAndNothingInTension) {
  const ContactWall wall = makeWall("Coulomb", 0.2);
  const double p[3] = {1.0, 2.0, 4.0};
  const double u[2] = {1e-4, 0.0};  // α_t |u_t| = 2e-3 < f̂ = 0.25: stick
  bool sticks = false;
  TEST_FLOATING_EQUALITY(wall.tangentialForce(1, V(u, p).data(), &sticks), 10.0 * 2.0 * 1e-4, 1e-14);
  TEST_ASSERT(sticks);
  const double tension[3] = {-1.0, -2.0, -4.0};  // p⁺ = 0: no friction
  TEST_EQUALITY_CONST(wall.tangentialForce(1, V(u, tension).data()), 0.0);
  // Normal penalty: u·n with n = (0,−1); u_y = −0.01 means u·n = 0.01 (moving into the tool).
  const double uIn[2] = {0.0, -0.01};
  double R[2] = {0.0, 0.0};
  wall.addNodeResidual(1, V(uIn, tension).data(), R);
  TEST_FLOATING_EQUALITY(R[1], 100.0 * 2.0 * 0.01 * (-1.0), 1e-14);
}

TEUCHOS_UNIT_TEST(ContactWall, TrescaOrowanNortonByHand) {
  const double p[3] = {1.0, 2.0, 4.0};
  const double u[2] = {0.5, 0.0};
  // Tresca, m = 0.5, σ̄ = 1.5: f̂ = m σ̄/√3 × 2 L (1/3 + 1/6) = m σ̄/√3 × L.
  const double tresca = 0.5 * 1.5 / std::sqrt(3.0) * kL;
  TEST_FLOATING_EQUALITY(makeWall("Tresca", 0.0, 0.5).tangentialForce(1, V(u, p).data()), tresca, 1e-14);
  // Orowan: the smaller of the Coulomb and Tresca bounds.
  const double coulomb = 0.2 * (kL * (2.0 / 3 + 1.0 / 6) + kL * (2.0 / 3 + 4.0 / 6));
  TEST_FLOATING_EQUALITY(makeWall("Orowan", 0.2, 0.5).tangentialForce(1, V(u, p).data()), std::min(coulomb, tresca), 1e-14);
  TEST_FLOATING_EQUALITY(makeWall("Orowan", 0.01, 0.5).tangentialForce(1, V(u, p).data()), 0.05 * coulomb, 1e-14);
  // Norton: α_f K (u_t² + ε²)^((q−1)/2) u_t × tributary length (two halves of L = L).
  const double norton = 0.7 * std::pow(0.25 + 1e-12, 0.5 * (0.3 - 1.0)) * 0.5 * kL;
  TEST_FLOATING_EQUALITY(makeWall("Norton", 0.0).tangentialForce(1, V(u, p).data()), norton, 1e-12);
  TEST_EQUALITY_CONST(makeWall("None", 0.2).tangentialForce(1, V(u, p).data()), 0.0);
}

TEUCHOS_UNIT_TEST(ContactWall, FreeNodesAndSegmentsCarryNothing) {
  ContactWall wall = makeWall("Coulomb", 0.2);
  const double p[3] = {1.0, 2.0, 4.0};
  const double u[2] = {0.5, 0.3};
  wall.setActive(2, false);  // segment (1,2) inactive: only (0,1) loads node 1
  TEST_FLOATING_EQUALITY(wall.tangentialForce(1, V(u, p).data()), 0.2 * kL * (2.0 / 3 + 1.0 / 6), 1e-14);
  double R[2] = {0.0, 0.0};
  wall.addNodeResidual(2, V(u, p).data(), R);  // a free node: no term at all
  TEST_EQUALITY_CONST(R[0], 0.0);
  TEST_EQUALITY_CONST(R[1], 0.0);
}

TEUCHOS_UNIT_TEST(ContactWall, SelfDecidingNodePushesButNeverPulls) {
  // Node 1 has cycled (4 changes, active now) and still pulls (p = −1): it decides by itself.
  ContactWall wall = makeWall("Coulomb", 0.2);
  for (bool active : {false, true, false, true}) wall.setActive(1, active);
  const std::vector<double> pull = {1.0, -1.0, 1.0};
  const std::vector<std::array<double, 2>> resting = {{0.5, 0.0}, {0.5, 0.0}, {0.5, 0.0}};
  const int deciding = wall.letCyclingNodesDecide(pull, resting, 1e-3, 1e-4, 4);
  TEST_EQUALITY(deciding, 1);
  TEST_ASSERT(wall.isSelfDeciding(1) && wall.isActive(1));
  TEST_EQUALITY(wall.selfDecidingNodes(), 1);
  // Pressing (u·n = 0.01 with n = (0, −1)): the normal force α_n u·n = 100·2·0.01 = 2, and the
  // friction is bounded by ν times it (not by the lumped pressure): sliding, g = 0.4 along t = (1, 0).
  const double p[3] = {1.0, 2.0, 4.0};
  const double pressing[2] = {0.5, -0.01};
  double R[2] = {0.0, 0.0};
  wall.addNodeResidual(1, V(pressing, p).data(), R);
  TEST_FLOATING_EQUALITY(R[0], 0.2 * 2.0, 1e-14);
  TEST_FLOATING_EQUALITY(R[1], -2.0, 1e-14);
  // Separating (u·n = −0.01): nothing, neither the penalty's pull nor friction.
  const double separating[2] = {0.5, 0.01};
  double S[2] = {0.0, 0.0};
  wall.addNodeResidual(1, V(separating, p).data(), S);
  TEST_EQUALITY_CONST(S[0], 0.0);
  TEST_EQUALITY_CONST(S[1], 0.0);
  // Leaving the tool beyond the penetration tolerance, it is released like any node.
  const std::vector<std::array<double, 2>> leaving = {{0.5, 0.0}, {0.5, 0.01}, {0.5, 0.0}};
  const StatusChange change = wall.nextChange(pull, leaving, 1e-3, 1e-4, 4);
  TEST_EQUALITY(change.node, 1);
  TEST_ASSERT(!change.activate);
}

TEUCHOS_UNIT_TEST(ContactWall, AxisymmetricWeightIsTwoPiR) {
  // Same wall, axisymmetric: f̂ = ν Σ ∫ N_k p W ds with W = 2π r; r = x here.
  const ContactWall wall = makeWall("Coulomb", 0.2, 0.0, Geometry::Axisymmetric);
  const double p[3] = {1.0, 1.0, 1.0};  // p = 1: f̂ = ν 2π ∫ N_1 r ds over both segments
  // ∫_0^0.5 N_1 r ds with N_1 = r/0.5: = 0.5²/3 ... computed exactly: ∫_0^L (s/L) s ds = L²/3;
  // right segment r = 0.5 + s, N_1 = 1 − s/L: ∫ (1 − s/L)(0.5 + s) ds = 0.5 L/2 + L²/6.
  const double integral = kL * kL / 3 + 0.5 * kL / 2 + kL * kL / 6;
  const double u[2] = {5.0, 0.0};
  TEST_FLOATING_EQUALITY(wall.tangentialForce(1, V(u, p).data()), 0.2 * 2 * M_PI * integral, 1e-13);
}

/// AD tangent of the node residual against central differences, in slip and in stick.
void checkTangent(const ContactWall& wall, int k, const double* u0, const double* p0, Teuchos::FancyOStream& out,
                  bool& success) {
  using Fad = Sacado::Fad::SFad<double, 5>;
  Fad u[2] = {Fad(5, 0, u0[0]), Fad(5, 1, u0[1])};
  Fad p[3] = {Fad(5, 2, p0[0]), Fad(5, 3, p0[1]), Fad(5, 4, p0[2])};
  Fad R[2] = {0.0, 0.0};
  wall.addNodeResidual(k, V(u, p).data(), R);
  const double delta = 1e-7;  // central FD: truncation O(δ²) on the smooth branch, round-off ~1e-16/δ
  for (int j = 0; j < 5; ++j) {
    double up[2] = {u0[0], u0[1]}, pp[3] = {p0[0], p0[1], p0[2]};
    double um[2] = {u0[0], u0[1]}, pm[3] = {p0[0], p0[1], p0[2]};
    (j < 2 ? up[j] : pp[j - 2]) += delta;
    (j < 2 ? um[j] : pm[j - 2]) -= delta;
    double Rp[2] = {0, 0}, Rm[2] = {0, 0};
    wall.addNodeResidual(k, V(up, pp).data(), Rp);
    wall.addNodeResidual(k, V(um, pm).data(), Rm);
    for (int c = 0; c < 2; ++c) {
      const double fd = (Rp[c] - Rm[c]) / (2 * delta);
      TEST_FLOATING_EQUALITY(R[c].dx(j) + 1.0, fd + 1.0, 1e-6);
    }
  }
}

TEUCHOS_UNIT_TEST(ContactWall, TangentMatchesFiniteDifferences) {
  const double p[3] = {1.0, 2.0, 4.0};
  const double slip[2] = {0.5, 0.02}, stick[2] = {1e-4, 0.003};
  for (const char* law : {"Coulomb", "Tresca", "Orowan", "Norton"}) {
    out << law << "\n";
    const ContactWall wall = makeWall(law, 0.2, 0.5);
    checkTangent(wall, 1, slip, p, out, success);
    checkTangent(wall, 1, stick, p, out, success);
  }
}

// ---------------------------------------------------------------------------------------
// Parameter derivatives ∂R/∂ν, ∂R/∂m (docs/theory.md §4, paper eq. 28): the same law with the friction
// parameters as PScalar = SFad<double, 1> (dofs constant Fads), against central differences.
// ---------------------------------------------------------------------------------------

using PFad = Sacado::Fad::SFad<double, 1>;

/// ∂R/∂h of node k's residual by AD; h = ν (which = 0) or m (which = 1).
std::array<double, 2> parameterDerivative(const ContactWall& wall, int k, int which, const double* u0, const double* p0,
                                          FrictionBranch* branch = nullptr) {
  const FrictionParameters<double> fp0 = wall.frictionParameters();
  const FrictionParameters<PFad> fp{which == 0 ? PFad(1, 0, fp0.frictionCoefficient) : PFad(fp0.frictionCoefficient),
                                    which == 1 ? PFad(1, 0, fp0.shearFactor) : PFad(fp0.shearFactor)};
  PFad u[2] = {u0[0], u0[1]}, p[3] = {p0[0], p0[1], p0[2]}, R[2] = {0.0, 0.0};
  wall.addNodeResidual(k, fp, V(u, p).data(), R);
  if (branch) wall.tangentialForce(k, fp, V(u, p).data(), branch);
  return {R[0].dx(0), R[1].dx(0)};
}

/// The same by central differences of the double residual, step δ on h.
std::array<double, 2> parameterDifference(const ContactWall& wall, int k, int which, const double* u0, const double* p0,
                                          double delta) {
  std::array<double, 2> d{};
  for (double sign : {1.0, -1.0}) {
    FrictionParameters<double> fp = wall.frictionParameters();
    (which == 0 ? fp.frictionCoefficient : fp.shearFactor) += sign * delta;
    double R[2] = {0.0, 0.0};
    wall.addNodeResidual(k, fp, V(u0, p0).data(), R);
    for (int c = 0; c < 2; ++c) d[c] += sign * R[c] / (2 * delta);
  }
  return d;
}

TEUCHOS_UNIT_TEST(ContactWall, FrictionParameterDerivativesMatchFiniteDifferences) {
  // Inside a branch the residual is linear in ν and m (slip: ±ν P or ±m S/√3; stick and
  // tension: independent), so central differences are exact up to round-off ~eps |R|/δ
  // = 1e-16 · O(1) / 1e-6 = 1e-10; the tolerance 1e-8 (absolute, |∂R/∂h| = O(0.1..1))
  // leaves 100×. δ = 1e-6 keeps every case at least 1e-3 away from a branch change.
  const double delta = 1e-6;
  const double p[3] = {1.0, 2.0, 4.0}, tension[3] = {-1.0, -2.0, -4.0};
  const double slip[2] = {0.5, 0.02}, stick[2] = {1e-4, 0.003};
  struct Case {
    const char* law;
    double nu, m;
    const double* u;
    const double* p;
    FrictionBranch branch;
  };
  const Case cases[] = {{"Coulomb", 0.2, 0.0, slip, p, FrictionBranch::Slip},
                        {"Coulomb", 0.2, 0.0, stick, p, FrictionBranch::Stick},
                        {"Coulomb", 0.2, 0.0, slip, tension, FrictionBranch::NoFriction},
                        {"Coulomb", 0.0, 0.0, slip, p, FrictionBranch::Slip},  // ν = 0 under compression: slip
                        {"Tresca", 0.0, 0.5, slip, p, FrictionBranch::Slip},
                        {"Tresca", 0.0, 0.5, stick, p, FrictionBranch::Stick},
                        {"Orowan", 0.1, 0.5, slip, p, FrictionBranch::Slip},         // ν P < m S/√3
                        {"Orowan", 0.5, 0.2, slip, p, FrictionBranch::SlipTresca},   // m S/√3 < ν P
                        {"Orowan", 0.2, 0.5, stick, p, FrictionBranch::Stick}};
  for (const Case& c : cases) {
    const ContactWall wall = makeWall(c.law, c.nu, c.m);
    for (int which : {0, 1}) {
      FrictionBranch branch;
      const auto ad = parameterDerivative(wall, 1, which, c.u, c.p, &branch);
      const auto fd = parameterDifference(wall, 1, which, c.u, c.p, delta);
      out << c.law << " ν = " << c.nu << " m = " << c.m << " " << frictionBranchName(branch) << " ∂R/∂"
          << (which == 0 ? "ν" : "m") << " = (" << ad[0] << ", " << ad[1] << "), FD (" << fd[0] << ", " << fd[1]
          << ")\n";
      TEST_ASSERT(branch == c.branch);
      for (int k = 0; k < 2; ++k) TEST_FLOATING_EQUALITY(ad[k] + 1.0, fd[k] + 1.0, 1e-8);
    }
  }
}

TEUCHOS_UNIT_TEST(ContactWall, FrictionCoefficientSensitivityIsExactlyZeroInStickAndTension) {
  // Paper eq. 28: in stick and without compression ∂f/∂ν = 0 exactly (not to round-off).
  const double p[3] = {1.0, 2.0, 4.0}, tension[3] = {-1.0, -2.0, -4.0};
  const double slip[2] = {0.5, 0.0}, stick[2] = {1e-4, 0.0};
  for (double nu : {0.0, 0.2}) {
    const ContactWall wall = makeWall("Coulomb", nu);
    FrictionBranch branch;
    // In tension (also at ν = 0): no friction, no sensitivity.
    auto d = parameterDerivative(wall, 1, 0, slip, tension, &branch);
    TEST_ASSERT(branch == FrictionBranch::NoFriction);
    TEST_EQUALITY_CONST(d[0], 0.0);
    TEST_EQUALITY_CONST(d[1], 0.0);
    // Slip under compression: ∂g/∂ν = P sign(u_t) = f̂/ν, P = Σ_s L(p_k/3 + p_o/6).
    const double P = kL * (2.0 / 3 + 1.0 / 6) + kL * (2.0 / 3 + 4.0 / 6);
    d = parameterDerivative(wall, 1, 0, slip, p, &branch);
    TEST_ASSERT(branch == FrictionBranch::Slip);
    TEST_FLOATING_EQUALITY(d[0], P, 1e-14);  // t = (1, 0)
    TEST_EQUALITY_CONST(d[1], 0.0);
  }
  const ContactWall wall = makeWall("Coulomb", 0.2);
  FrictionBranch branch;
  const auto d = parameterDerivative(wall, 1, 0, stick, p, &branch);
  TEST_ASSERT(branch == FrictionBranch::Stick);
  TEST_EQUALITY_CONST(d[0], 0.0);
  TEST_EQUALITY_CONST(d[1], 0.0);
  // A free node has no contact term at all.
  ContactWall released = makeWall("Coulomb", 0.2);
  released.setActive(1, false);
  const auto f = parameterDerivative(released, 1, 0, slip, p, &branch);
  TEST_ASSERT(branch == FrictionBranch::Free);
  TEST_EQUALITY_CONST(f[0], 0.0);
}

TEUCHOS_UNIT_TEST(ContactWall, StatusChangesAtTheZoneLimitOneAtATime) {
  ContactWall wall = makeWall("Coulomb", 0.2);
  const std::vector<std::array<double, 2>> u(3, {0.0, 0.0});
  // All active; node 1 (interior) in strong tension, node 2 (a wall end, so a limit) in mild tension.
  StatusChange c = wall.nextChange({1.0, -5.0, -0.5}, u, 1e-3, 1e-4, 4);
  TEST_EQUALITY_CONST(c.node, 2);
  TEST_ASSERT(!c.activate);
  wall.setActive(2, false);
  // Now node 1 borders a free node: it is at the limit and goes next.
  c = wall.nextChange({1.0, -5.0, -0.5}, u, 1e-3, 1e-4, 4);
  TEST_EQUALITY_CONST(c.node, 1);
  // A free node moving into the tool (u·n > 0, n = (0,−1): u_y < 0) is activated.
  wall.setActive(1, false);
  c = wall.nextChange({1.0, 0.0, 0.0}, {{0.0, 0.0}, {0.0, -0.1}, {0.0, 0.0}}, 1e-3, 1e-4, 4);
  TEST_EQUALITY_CONST(c.node, 1);
  TEST_ASSERT(c.activate);
  // Within the tolerances nothing changes.
  c = wall.nextChange({1.0, -1e-4, 0.0}, {{0.0, 0.0}, {0.0, -1e-5}, {0.0, 0.0}}, 1e-3, 1e-4, 4);
  TEST_EQUALITY_CONST(c.node, -1);
  // A node that has used up its changes is not changed again but is reported unsettled.
  wall.setActive(1, true);
  wall.setActive(1, false);  // node 1 has now changed 3 times
  int unsettled = 0;
  c = wall.nextChange({1.0, 0.0, 0.0}, {{0.0, 0.0}, {0.0, -0.1}, {0.0, 0.0}}, 1e-3, 1e-4, 2, &unsettled);
  TEST_EQUALITY_CONST(c.node, -1);
  TEST_EQUALITY_CONST(unsettled, 1);
}

TEUCHOS_UNIT_TEST(ContactWall, BadInputNamesTheGroup) {
  Teuchos::ParameterList p;
  p.set("Type", "Contact Wall");
  p.set("Friction Coefficient", -0.1);
  TEST_THROW(ContactWall("bottom", p, bottomMesh(), Geometry::PlaneStrain), InputError);
  Teuchos::ParameterList ok;
  ok.set("Type", "Contact Wall");
  try {
    ContactWall("nosuch", ok, bottomMesh(), Geometry::PlaneStrain);
    success = false;
  } catch (const InputError& e) {
    TEST_ASSERT(std::string(e.what()).find("nosuch") != std::string::npos);
  }
}


// ---------------------------------------------------------------------------------------
// Complementarity walls (docs/contact.md, "Complementarity"): the normal force α_n max(u·n, 0)
// and the friction integrated up to the interpolated zero of φ inside the segment that holds
// the zone limit, by hand; its continuity as the limit reaches a node; its AD tangent in all
// nine stencil values against central differences.
// ---------------------------------------------------------------------------------------

/// Stencil values of the middle node 1 of the bottom wall (n = (0, −1)): u_y = −g, so u·n = g.
std::array<double, ContactWall::kNodeStencilSize> middle(double g0, double g1, double g2, const double* p) {
  return {0.5, -g1, p[0], p[1], p[2], 0.5, -g0, 0.5, -g2};
}

/// ∫_0^a N_1 (N_1 p1 + N_2 p2) L ds on the segment 1→2 (N_1 = 1 − s, N_2 = s).
double partIntegral(double a, double p1, double p2) {
  return kL * (p1 * (1.0 - std::pow(1.0 - a, 3)) / 3.0 + p2 * (a * a / 2.0 - a * a * a / 3.0));
}

TEUCHOS_UNIT_TEST(ContactWall, ComplementarityPushesAndIntegratesFrictionToTheZoneLimit) {
  ContactWall wall = makeWall("Coulomb", 0.2);
  const int entered = wall.enterComplementarity();  // (the macro evaluates its arguments twice)
  TEST_EQUALITY_CONST(entered, 3);
  const double p[3] = {1.0, 2.0, 4.0};
  // Node 0 and 1 press (u·n = 0.01: φ = κ_n u·n = 1), node 2 separates (u·n = −0.02 = φ): the
  // segment 1–2 is in contact up to s* = 1/1.02.
  const auto v = middle(0.01, 0.01, -0.02, p);
  const double sStar = 1.0 / 1.02;
  const double fHat = 0.2 * (kL * (2.0 / 3 + 1.0 / 6) + partIntegral(sStar, 2.0, 4.0));
  double R[2] = {0.0, 0.0};
  wall.addNodeResidual(1, v.data(), R);
  TEST_FLOATING_EQUALITY(R[0], fHat, 1e-13);                        // slip: α_t |u_t| = 10 > f̂
  TEST_FLOATING_EQUALITY(R[1], 100.0 * 2.0 * 0.01 * (-1.0), 1e-14);  // α_n u·n along n
  // Separating, node 1 gets no normal force, but its share of the friction on the part of
  // segment 0–1 in contact (φ_0 = 1, φ_1 = −0.01: up to s* = 1/1.01 from node 0).
  const auto separated = middle(0.01, -0.01, -0.02, p);
  double S[2] = {0.0, 0.0};
  wall.addNodeResidual(1, separated.data(), S);
  TEST_EQUALITY_CONST(S[1], 0.0);
  const double a = 1.0 / 1.01;  // from node 0: ∫_0^a N_1 (N_0 p0 + N_1 p1) L ds with N_1 = s
  const double share = kL * (p[0] * (a * a / 2.0 - a * a * a / 3.0) + p[1] * a * a * a / 3.0);
  TEST_FLOATING_EQUALITY(S[0], 0.2 * share, 1e-13);
  // Nothing in contact anywhere: nothing at all.
  const auto away = middle(-0.01, -0.01, -0.02, p);
  double Z[2] = {0.0, 0.0};
  wall.addNodeResidual(1, away.data(), Z);
  TEST_EQUALITY_CONST(Z[0], 0.0);
  TEST_EQUALITY_CONST(Z[1], 0.0);
}

TEUCHOS_UNIT_TEST(ContactWall, ComplementarityFrictionIsContinuousAsTheLimitReachesANode) {
  ContactWall wall = makeWall("Coulomb", 0.2);
  wall.enterComplementarity();
  const double p[3] = {1.0, 2.0, 4.0};
  auto friction = [&](double g2) {
    const auto v = middle(0.01, 0.01, g2, p);
    double R[2] = {0.0, 0.0};
    wall.addNodeResidual(1, v.data(), R);
    return R[0];
  };
  // Node 2 from separating to pressing: the friction at node 1 goes to the full segment's value
  // continuously (a change of 1e-12 in u·n changes it by O(1e-12 / φ_1), not by a segment's worth).
  const double full = 0.2 * (kL * (2.0 / 3 + 1.0 / 6) + kL * (2.0 / 3 + 4.0 / 6));
  TEST_FLOATING_EQUALITY(friction(1e-12), full, 1e-14);
  TEST_FLOATING_EQUALITY(friction(-1e-12), full, 1e-10);
}

TEUCHOS_UNIT_TEST(ContactWall, ComplementarityTangentMatchesFiniteDifferences) {
  using Fad = Sacado::Fad::SFad<double, ContactWall::kNodeStencilSize>;
  constexpr int N = ContactWall::kNodeStencilSize;
  const double p[3] = {1.0, 2.0, 4.0};
  for (const char* law : {"Coulomb", "Tresca", "Norton"}) {
    out << law << "\n";
    ContactWall wall = makeWall(law, 0.2, 0.5);
    wall.enterComplementarity();
    // Node 1 presses, node 2 separates (the limit inside segment 1–2), in slip.
    const auto v0 = middle(0.01, 0.012, -0.02, p);
    Fad v[N], R[2] = {0.0, 0.0};
    for (int i = 0; i < N; ++i) v[i] = Fad(N, i, v0[i]);
    wall.addNodeResidual(1, v, R);
    const double delta = 1e-8;  // central FD: truncation O(δ²) inside the branch, round-off ~1e-16/δ
    for (int j = 0; j < N; ++j) {
      auto vp = v0, vm = v0;
      vp[j] += delta;
      vm[j] -= delta;
      double Rp[2] = {0, 0}, Rm[2] = {0, 0};
      wall.addNodeResidual(1, vp.data(), Rp);
      wall.addNodeResidual(1, vm.data(), Rm);
      for (int c = 0; c < 2; ++c) TEST_FLOATING_EQUALITY(R[c].dx(j) + 1.0, (Rp[c] - Rm[c]) / (2 * delta) + 1.0, 1e-6);
    }
  }
}

// ---------------------------------------------------------------------------------------
// Moving tools (docs/theory.md §2 "Moving tools"): the normal penalty on (u − v_w)·n and the laws
// on the relative slip (u − v_w)·t. The bottom wall: n = (0, −1), t = (1, 0).
// ---------------------------------------------------------------------------------------

/// makeWall's wall with Tool Motion set by `motion` (its entries added to the list).
ContactWall makeMovingWall(const std::string& law, double nu, double m, const Teuchos::ParameterList& motion) {
  Teuchos::ParameterList p;
  p.set("Type", "Contact Wall");
  p.set("Friction Law", law);
  p.set("Friction Coefficient", nu);
  p.set("Shear Factor", m);
  p.set("Norton Coefficient", 0.7);
  p.set("Norton Exponent", 0.3);
  p.set("Normal Penalty Factor", 100.0);
  p.set("Tangential Penalty Factor", 10.0);
  p.setParameters(motion);
  ContactWall wall("bottom", p, bottomMesh(), Geometry::PlaneStrain);
  wall.setScales({2.0, 2.0, 2.0}, {1.5, 1.5, 1.5});
  return wall;
}

Teuchos::ParameterList translation(double vx) {
  Teuchos::ParameterList m;
  m.set("Tool Motion", "Translation");
  m.set("Tool Velocity X", vx);
  return m;
}

TEUCHOS_UNIT_TEST(ContactWall, MovingToolSlipIsRelativeToTheTool) {
  const ContactWall wall = makeMovingWall("Coulomb", 0.2, 0.0, translation(0.8));
  TEST_FLOATING_EQUALITY(wall.wallTangentialSpeed(1), 0.8, 1e-15);
  TEST_EQUALITY_CONST(wall.wallNormalSpeed(1), 0.0);
  const double p[3] = {1.0, 2.0, 4.0};
  const double fHat = 0.2 * (kL * (2.0 / 3 + 1.0 / 6) + kL * (2.0 / 3 + 4.0 / 6));
  // The material moves along +t at 0.3, the tool faster at 0.8: the relative slip is −0.5, so the
  // tool drags the material forward: g = −f̂ (a fixed tool gives +f̂ at the same u, test above).
  const double u[2] = {0.3, -0.01};
  bool sticks = true;
  TEST_FLOATING_EQUALITY(wall.tangentialForce(1, V(u, p).data(), &sticks), -fHat, 1e-14);
  TEST_ASSERT(!sticks);
  TEST_FLOATING_EQUALITY(makeWall("Coulomb", 0.2).tangentialForce(1, V(u, p).data()), fHat, 1e-14);
  // Residual: R = α_n ((u − v_w)·n) n + g t, α_n = 100·2, (u − v_w)·n = 0.01.
  double R[2] = {0.0, 0.0};
  wall.addNodeResidual(1, V(u, p).data(), R);
  TEST_FLOATING_EQUALITY(R[0], -fHat, 1e-14);
  TEST_FLOATING_EQUALITY(R[1], 200.0 * 0.01 * (-1.0), 1e-14);
  // Moving with the tool up to 1e-4: stick, g = α_t (u_t − v_t) = 10·2·1e-4.
  const double withTool[2] = {0.8 + 1e-4, -0.01};
  TEST_FLOATING_EQUALITY(wall.tangentialForce(1, V(withTool, p).data(), &sticks), 20.0 * 1e-4, 1e-9);
  TEST_ASSERT(sticks);
  // The other laws on the same relative slip −0.5: Tresca −m S/√3, Norton α_f K A (s²+ε²)^((q−1)/2) s.
  const double S = 1.5 * 2.0 * kL / 2.0;  // Σ ∫ N_1 σ̄ ds over both segments, σ̄ = 1.5
  TEST_FLOATING_EQUALITY(makeMovingWall("Tresca", 0.0, 0.5, translation(0.8)).tangentialForce(1, V(u, p).data()),
                         -0.5 * S / std::sqrt(3.0), 1e-14);
  const double norton = 0.7 * kL * std::pow(0.25 + 1e-12, 0.5 * (0.3 - 1.0)) * (-0.5);
  TEST_FLOATING_EQUALITY(makeMovingWall("Norton", 0.0, 0.0, translation(0.8)).tangentialForce(1, V(u, p).data()),
                         norton, 1e-12);
  TEST_EQUALITY_CONST(makeMovingWall("None", 0.2, 0.0, translation(0.8)).tangentialForce(1, V(u, p).data()), 0.0);
}

TEUCHOS_UNIT_TEST(ContactWall, RotatingToolNormalAndSlipAtAnEndNode) {
  // ω = 0.5 about c = (0.5, −2): v_w = ω (−(y − c_y), x − c_x); at node 0 (0, 0) v_w = (−1, −0.25)
  // (counter-clockwise: above the centre the tool moves to −x), so v_w·n = 0.25 and v_w·t = −1. The straight wall is no circle about c: the tolerance is opened
  // to let the test see a tool velocity with a normal part (the segments' worst is 0.124).
  Teuchos::ParameterList m;
  m.set("Tool Motion", "Rotation");
  m.set("Angular Velocity", 0.5);
  m.set("Rotation Centre X", 0.5);
  m.set("Rotation Centre Y", -2.0);
  m.set("Tangency Tolerance", 0.2);
  const ContactWall wall = makeMovingWall("Coulomb", 0.2, 0.0, m);
  TEST_FLOATING_EQUALITY(wall.wallVelocity(0)[0], -1.0, 1e-15);
  TEST_FLOATING_EQUALITY(wall.wallVelocity(0)[1], -0.25, 1e-15);
  TEST_FLOATING_EQUALITY(wall.wallNormalSpeed(0), 0.25, 1e-15);
  const double pEnd[3] = {99.0, 1.0, 2.0};
  const double u[2] = {0.2, -0.3};  // (u − v_w)·n = 0.3 − 0.25 = 0.05; slip 0.2 − (−1) = 1.2: g = +f̂
  double R[2] = {0.0, 0.0};
  wall.addNodeResidual(0, V(u, pEnd).data(), R);
  const double fHat = 0.2 * kL * (1.0 / 3 + 2.0 / 6);
  TEST_FLOATING_EQUALITY(R[0], fHat, 1e-14);
  TEST_FLOATING_EQUALITY(R[1], 200.0 * 0.05 * (-1.0), 1e-13);
  // Against the tool's motion from the other side: u_t = −1.5 is a slip of −0.5: g = −f̂.
  const double uBack[2] = {-1.5, -0.3};
  TEST_FLOATING_EQUALITY(wall.tangentialForce(0, V(uBack, pEnd).data()), -fHat, 1e-14);
  // Too tight a tolerance for this wall: an input error naming the group.
  m.set("Tangency Tolerance", 1e-3);
  TEST_THROW(makeMovingWall("Coulomb", 0.2, 0.0, m), InputError);
  try {
    makeMovingWall("Coulomb", 0.2, 0.0, m);
  } catch (const InputError& e) {
    TEST_ASSERT(std::string(e.what()).find("Boundary Conditions/bottom/Tool Motion") != std::string::npos);
  }
}

TEUCHOS_UNIT_TEST(ContactWall, MovingToolStatusesReadTheRelativeNormalVelocity) {
  // A free node moving along with a tool whose velocity has a normal part does not penetrate it:
  // u = v_w at node 0 (u·n = 0.25 > tolerance for a fixed tool, (u − v_w)·n = 0 for this one).
  Teuchos::ParameterList m;
  m.set("Tool Motion", "Rotation");
  m.set("Angular Velocity", 0.5);
  m.set("Rotation Centre X", 0.5);
  m.set("Rotation Centre Y", -2.0);
  m.set("Tangency Tolerance", 0.2);
  ContactWall moving = makeMovingWall("Coulomb", 0.2, 0.0, m);
  ContactWall fixed = makeWall("Coulomb", 0.2);
  const std::vector<double> p = {0.0, 0.0, 0.0};
  const std::vector<std::array<double, 2>> u = {moving.wallVelocity(0), moving.wallVelocity(1), moving.wallVelocity(2)};
  for (ContactWall* w : {&moving, &fixed})
    for (int k = 0; k < 3; ++k) w->setActive(k, false);
  TEST_EQUALITY(moving.nextChange(p, u, 1e-6, 1e-6, 10).node, -1);
  TEST_EQUALITY(fixed.nextChange(p, u, 1e-6, 1e-6, 10).node, 0);  // u·n = 0.25 at node 0
  // Complementarity reads the same: nobody presses on the moving tool.
  moving.enterComplementarity();
  moving.readContact(u);
  for (int k = 0; k < 3; ++k) TEST_ASSERT(!moving.isActive(k));
}

TEUCHOS_UNIT_TEST(ContactWall, MovingToolTangentMatchesFiniteDifferences) {
  // checkTangent's states, read relative to a tool moving at 0.3 along t: slip 0.2 and 1e-4 − 0.3
  // (slip), and 0.3 + 1e-4 (stick).
  const double p[3] = {1.0, 2.0, 4.0};
  const double slip[2] = {0.5, 0.02}, slipBack[2] = {1e-4, 0.003}, stick[2] = {0.3 + 1e-4, 0.003};
  for (const char* law : {"Coulomb", "Tresca", "Orowan", "Norton"}) {
    out << law << "\n";
    const ContactWall wall = makeMovingWall(law, 0.2, 0.5, translation(0.3));
    checkTangent(wall, 1, slip, p, out, success);
    checkTangent(wall, 1, slipBack, p, out, success);
    checkTangent(wall, 1, stick, p, out, success);
    FrictionBranch branch;
    wall.tangentialForce(1, wall.frictionParameters(), V(stick, p).data(), &branch);
    if (std::string(law) != "Norton") TEST_ASSERT(branch == FrictionBranch::Stick);
  }
}

}  // namespace
