#include "flowform/contact/ContactWall.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <limits>

#include <Teuchos_SerialDenseMatrix.hpp>
#include <Teuchos_SerialDenseSolver.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/bc/FieldBoundaryValues.hpp"
#include "flowform/contact/ToolCorners.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/core/NumberRange.hpp"
#include "flowform/core/Log.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

static void buildValidParameters(const ValidList& valid) {
  valid->set("Type", "Contact Wall", "a frictional contact wall (docs/theory.md §2)");
  // The choices are the registered laws (contact/friction/FrictionLaws.hpp), the first the default.
  Teuchos::Array<std::string> names;
  std::string doc;
  for (const FrictionLawInfo& law : frictionLaws()) {
    names.push_back(law.name);
    doc += (doc.empty() ? "" : ", ") + law.description;
  }
  Teuchos::setStringToIntegralParameter<int>("Friction Law", names[0], doc, names(), valid.get());
  valid->set("Friction Coefficient", 0.0, "ν >= 0 (Coulomb, Orowan)", nonNegative());
  valid->set("Friction Field", Teuchos::Array<double>(),
             "ν along the wall instead of one Friction Coefficient (Coulomb, Orowan): its values ν_0 ... ν_N >= 0 at "
             "N + 1 >= 2 equally spaced stations from the wall's first node to its last (the boundary curve runs "
             "with the material on its left), linear between them (a Friction Coefficient given too is not used); each value is a sensitivity and "
             "design parameter 'Friction Field:<wall>/<j>' (docs/contact.md \"Friction fields\")");
  valid->set("Shear Factor", 0.0, "m in [0, 1] (Tresca, Orowan)", inRange(0.0, 1.0));
  valid->set("Norton Coefficient", 0.0, "α_f K >= 0 (Norton) [stress·(time/length)^q]", nonNegative());
  valid->set("Norton Exponent", 1.0, "q > 0 (Norton)", positive());
  valid->set("Norton Regularization", 1e-6, "ε > 0 in (u_t² + ε²)^((q-1)/2) [velocity]", positive());
  valid->set("Normal Penalty Factor", 1e3, "κ_n > 0: α_n = κ_n μ (× 2π r)", positive());
  valid->set("Tangential Penalty Factor", 10.0,
             "κ_t > 0: sticking stiffness α_t = κ_t μ (× 2π r); the extrusion's ram force changes by < 3e-4 "
             "for κ_t in [1, 1000], and Newton needs more iterations as κ_t grows "
             "(docs/extrusion_verification.md §4)",
             positive());
  valid->set("Penalty Viscosity", 0.0,
             "μ in the penalties: 0 (default) = the largest adjacent cell viscosity, refreshed before every "
             "flow solve; > 0 = this fixed value at every node, so the penalties do not depend on the "
             "solution (docs/sensitivity.md: an external finite-difference check needs that)",
             nonNegative());
  Teuchos::setStringToIntegralParameter<int>("Initial Status", "Active", "status of every wall node at the start",
                                             Teuchos::tuple<std::string>("Active", "Free"), valid.get());
  Teuchos::setStringToIntegralParameter<int>(
      "Released Nodes", "Fixed",
      "Fixed: released nodes stay on the tool, traction-free (the paper's contact element); Free Surface: every run "
      "of released nodes is a free surface from the node before it (the separation point) that leaves the tool and "
      "becomes a streamline (docs/theory.md §3; needs Start Group); Never: a bilateral wall, no node is released",
      Teuchos::tuple<std::string>("Fixed", "Free Surface", "Never"), valid.get());
  Teuchos::setStringToIntegralParameter<int>(
      "Convex Corners", "Open",
      "at a convex tool corner shared with another wall (the die lip): Open: the corner node is held by this wall "
      "only while it is active here, and it is released when it slides along the other wall (then the interpolated "
      "velocity crosses this wall's first segment: a leak of O(h) of the throughput, docs/contact.md); Closed: the "
      "corner node is always held by this wall (active, never released): no leak, the corner velocity is then "
      "limited to the other wall's tangent, or zero if that wall holds it too",
      Teuchos::tuple<std::string>("Open", "Closed"), valid.get());
  Teuchos::setStringToIntegralParameter<int>(
      "Coulomb Normal Force", "Pressure",
      "what the Coulomb (and Orowan) bound ν N multiplies: Pressure: N = ∫ N_k p⁺ ds, the pressure lumped over the "
      "node's active segments (the paper's eq. 17-18); Contact Force: N = max(α_n u·n, 0), the normal force the "
      "penalty puts on the node, the normal traction ∫ N_k σ_n ds at convergence (so that under full sliding the "
      "friction force is exactly ν times the normal force; the two differ by the deviatoric normal stress s_nn, "
      "which is ±k on a yielding rake face; docs/cutting.md)",
      Teuchos::tuple<std::string>("Pressure", "Contact Force"), valid.get());
  Teuchos::setStringToIntegralParameter<int>(
      "Tool Motion", "Fixed",
      "how the tool moves, tangentially to its own surface (a steady state; docs/contact.md \"Moving tools\"): Fixed: "
      "at rest; Translation: with the velocity (Tool Velocity X, Tool Velocity Y), e.g. a container moving with the "
      "billet (axisymmetric: along the axis only); Rotation: about (Rotation Centre X, Rotation Centre Y) at Angular "
      "Velocity ω, counter-clockwise positive, v_w = ω e_z × (x − c), e.g. a roll (plane strain only). The normal "
      "condition acts on (u − v_w)·n and the friction law on the relative slip (u − v_w)·t",
      Teuchos::tuple<std::string>("Fixed", "Translation", "Rotation"), valid.get());
  valid->set("Tool Velocity X", 0.0, "Tool Motion = Translation: the tool's velocity, x component [velocity]", finiteNumber());
  valid->set("Tool Velocity Y", 0.0, "Tool Motion = Translation: the tool's velocity, y component [velocity]", finiteNumber());
  valid->set("Rotation Centre X", 0.0,
             "Tool Motion = Rotation: the centre c the tool turns about, x [length]; also the point the Tool Torque "
             "response is taken about. Neither X nor Y given: the centre of the circle fitted to the wall's nodes "
             "(a roll's axis then follows the mesh's radius and gap)", finiteNumber());
  valid->set("Rotation Centre Y", 0.0, "Tool Motion = Rotation: the centre c, y [length]; see Rotation Centre X", finiteNumber());
  valid->set("Angular Velocity", 0.0, "Tool Motion = Rotation: ω [1/time], counter-clockwise positive", finiteNumber());
  valid->set("Tangency Tolerance", 1e-3,
             "a moving tool: the largest |v_w·n|/|v_w| accepted at the midpoints of the wall's segments (n the "
             "segment's normal). 0 to round-off for a straight wall along the velocity or a polyline inscribed in "
             "a circle about the rotation centre; the default allows rounded coordinates",
             positive());
  valid->set("Start Group", "",
             "a Contact Wall with Released Nodes = Free Surface: the boundary group at the wall's upstream end; a Free "
             "Surface group: the boundary group that shares its fixed start (docs/theory.md §3.1)");
  declareFieldBoundaryEntries(*valid);
}

Teuchos::RCP<const Teuchos::ParameterList> ContactWall::validParameters() {
  return validListOnce<buildValidParameters>("Contact Wall");
}

ContactWall::ContactWall(const std::string& group, const Teuchos::ParameterList& params, const Mesh& mesh,
                         Geometry geometry)
    : m_geometry(geometry) {
  Teuchos::ParameterList list = params;
  try {
    list.validateParametersAndSetDefaults(*validParameters());
  } catch (const std::exception& e) {
    throw InputError("Boundary Conditions/" + group + " (Contact Wall): " + e.what());
  }
  auto positive = [&](const char* name) {
    const double v = list.get<double>(name);
    if (!(v > 0.0))
      throw InputError("Boundary Conditions/" + group + "/" + name + " must be > 0 (got " + Teuchos::toString(v) + ")");
    return v;
  };
  m_settings.law = frictionLawIndex(list.get<std::string>("Friction Law"));  // validated: one of them
  m_settings.frictionCoefficient = list.get<double>("Friction Coefficient");
  for (double nu : list.get<Teuchos::Array<double>>("Friction Field")) m_settings.frictionField.push_back(nu);
  m_settings.shearFactor = list.get<double>("Shear Factor");
  m_settings.friction.nortonCoefficient = list.get<double>("Norton Coefficient");
  m_settings.friction.nortonExponent = positive("Norton Exponent");
  m_settings.friction.nortonRegularization = positive("Norton Regularization");
  m_settings.normalPenalty = positive("Normal Penalty Factor");
  m_settings.tangentialPenalty = positive("Tangential Penalty Factor");
  m_settings.penaltyViscosity = list.get<double>("Penalty Viscosity");
  m_settings.initiallyActive = list.get<std::string>("Initial Status") == "Active";
  m_settings.releasedFreeSurface = list.get<std::string>("Released Nodes") == "Free Surface";
  m_settings.neverReleased = list.get<std::string>("Released Nodes") == "Never";
  m_settings.closedCorners = list.get<std::string>("Convex Corners") == "Closed";
  m_settings.coulombOnContactForce = list.get<std::string>("Coulomb Normal Force") == "Contact Force";
  m_settings.upstreamGroup = list.get<std::string>("Start Group");
  readToolMotion(group, params, list);
  // Entries the law does not read: said, not silently dropped (a law switched by --set keeps the
  // old law's entries in the file, so a warning, not an error).
  {
    const FrictionLawInfo& info = frictionLaws()[m_settings.law];
    const std::string where = "Boundary Conditions/" + group + ": Friction Law = " + info.name;
    for (const char* entry : {"Friction Coefficient", "Coulomb Normal Force"})
      if (!info.usesFrictionCoefficient && params.isParameter(entry))
        warn() << where << " does not use '" << entry << "' (ignored)\n";
    if (!info.usesShearFactor && params.isParameter("Shear Factor"))
      warn() << where << " does not use 'Shear Factor' (ignored)\n";
    if (info.usesShearFactor && !params.isParameter("Shear Factor"))
      warn() << where << " uses 'Shear Factor', which is not given: m = 0, no friction from it\n";
    if (info.usesFrictionCoefficient && !params.isParameter("Friction Coefficient") && m_settings.frictionField.empty())
      warn() << where << " uses 'Friction Coefficient', which is not given: ν = 0, no friction from it\n";
    if (!m_settings.frictionField.empty()) {
      const std::string field = "Boundary Conditions/" + group + "/Friction Field";
      if (!info.usesFrictionCoefficient)
        throw InputError(field + ": Friction Law = " + info.name + " has no friction coefficient (Coulomb, Orowan do)");
      // A field given over a case that sets ν (by --set, or over a Base Case): the field wins, said.
      if (params.isParameter("Friction Coefficient"))
        warn() << field << " gives ν along the wall: its Friction Coefficient is not used\n";
      if (m_settings.frictionField.size() < 2)
        throw InputError(field + ": needs at least 2 values (the wall's two ends), got " +
                         std::to_string(m_settings.frictionField.size()));
      for (double nu : m_settings.frictionField)
        if (!(nu >= 0.0) || !std::isfinite(nu))
          throw InputError(field + ": every value must be a finite number >= 0 (got " + Teuchos::toString(nu) + ")");
    }
  }
  if (m_settings.releasedFreeSurface && m_settings.upstreamGroup.empty())
    throw InputError("Boundary Conditions/" + group + "/Start Group: Released Nodes = Free Surface needs the "
                     "boundary group at the wall's upstream end");

  // InputError for a missing group, a zero-length segment, a branched group.
  m_curve = buildBoundaryCurve(mesh, mesh.boundary(group));
  fitRotationCentre(group, params, mesh);
  m_active.assign(m_curve.nodes.size(), m_settings.initiallyActive);
  m_inContact.assign(m_curve.nodes.size(), m_settings.initiallyActive);
  m_changes.assign(m_curve.nodes.size(), 0);
  m_viscosity.assign(m_curve.nodes.size(), 1.0);
  m_flowStress.assign(m_curve.nodes.size(), 1.0);
  refreshGeometry(mesh);
  setTool(mesh);  // the tool where the mesh was made
  checkTangency(group);
  if (m_settings.releasedFreeSurface && !mesh.hasBoundary(m_settings.upstreamGroup))
    throw InputError("Boundary Conditions/" + group + "/Start Group: mesh '" + mesh.source +
                     "' has no boundary group '" + m_settings.upstreamGroup + "'; it has: " + mesh.boundaryNames());
  if (!m_settings.upstreamGroup.empty() && mesh.hasBoundary(m_settings.upstreamGroup)) {
    const CurveEnds ends = endsOn(m_curve, mesh.boundary(m_settings.upstreamGroup));
    m_firstIsUpstream = ends.first;
    // A free surface shares exactly one end with its Start Group (FreeSurface says so otherwise).
    if (m_settings.releasedFreeSurface && ends.first) m_upstreamEnd = 0;
    if (m_settings.releasedFreeSurface && ends.last && !m_curve.closed) m_upstreamEnd = numNodes() - 1;
  }
}

void ContactWall::readToolMotion(const std::string& group, const Teuchos::ParameterList& given,
                                 const Teuchos::ParameterList& list) {
  const std::string where = "Boundary Conditions/" + group + "/Tool Motion";
  const std::string kind = list.get<std::string>("Tool Motion");  // validated: one of the three
  ToolMotion& m = m_settings.motion;
  m.kind = kind == "Translation" ? ToolMotion::Kind::Translation
           : kind == "Rotation"  ? ToolMotion::Kind::Rotation
                                 : ToolMotion::Kind::Fixed;
  m.velocity = {list.get<double>("Tool Velocity X"), list.get<double>("Tool Velocity Y")};
  m.centre = {list.get<double>("Rotation Centre X"), list.get<double>("Rotation Centre Y")};
  m.angularVelocity = list.get<double>("Angular Velocity");
  m_settings.tangencyTolerance = list.get<double>("Tangency Tolerance");
  // Entries the motion does not read: said (Rotation Centre is also where Tool Torque is taken).
  const char* translationOnly[] = {"Tool Velocity X", "Tool Velocity Y"};
  if (m.kind != ToolMotion::Kind::Translation)
    for (const char* entry : translationOnly)
      if (given.isParameter(entry)) warn() << where << " = " << kind << " does not use '" << entry << "' (ignored)\n";
  if (m.kind != ToolMotion::Kind::Rotation && given.isParameter("Angular Velocity"))
    warn() << where << " = " << kind << " does not use 'Angular Velocity' (ignored)\n";
  if (m_geometry == Geometry::Axisymmetric) {
    if (m.kind == ToolMotion::Kind::Rotation)
      throw InputError(where + " = Rotation: an axisymmetric tool cannot turn in the r-z plane (the rotation "
                       "would not be axisymmetric); allowed here: Fixed, or Translation along the axis (Tool "
                       "Velocity Y)");
    if (m.kind == ToolMotion::Kind::Translation && m.velocity[0] != 0.0)
      throw InputError(where + " = Translation: an axisymmetric tool moves along the axis only: Tool Velocity X "
                       "(radial) must be 0 (got " + Teuchos::toString(m.velocity[0]) + ")");
  }
}

namespace {

/// Kåsa's algebraic fit: the circle x² + y² + D x + E y + F = 0 that minimizes the sum of its
/// squared residuals at the points, in coordinates relative to their mean (so that the 3×3
/// normal equations stay well conditioned for a short arc of a large roll); centre (−D/2, −E/2).
/// Exact for points on a circle. False for points on a straight line (the normal equations
/// singular, or a "circle" far larger than the points' extent: its sagitta below round-off).
bool fitCircleCentre(const std::vector<std::array<double, 2>>& points, std::array<double, 2>& centre, double& radius) {
  const size_t n = points.size();
  double mx = 0.0, my = 0.0;
  for (const auto& p : points) {
    mx += p[0] / n;
    my += p[1] / n;
  }
  Teuchos::SerialDenseMatrix<int, double> A(3, 3), b(3, 1), sol(3, 1);
  double extent = 0.0;
  for (const auto& p : points) {
    const double x = p[0] - mx, y = p[1] - my;
    const double row[3] = {x, y, 1.0}, rhs = -(x * x + y * y);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) A(i, j) += row[i] * row[j];
      b(i, 0) += row[i] * rhs;
    }
    extent = std::max(extent, std::hypot(x, y));
  }
  Teuchos::SerialDenseSolver<int, double> solver;
  solver.setMatrix(Teuchos::rcpFromRef(A));
  solver.setVectors(Teuchos::rcpFromRef(sol), Teuchos::rcpFromRef(b));
  solver.factorWithEquilibration(true);  // x, y ~ the arc's extent, 1: rows of very different sizes
  const bool solved = solver.factor() == 0 && solver.solve() == 0;
  centre = {mx - 0.5 * sol(0, 0), my - 0.5 * sol(1, 0)};
  radius = std::hypot(centre[0] - mx, centre[1] - my);
  return solved && std::isfinite(centre[0]) && std::isfinite(centre[1]) && radius < 1e6 * extent;
}

}  // namespace

void ContactWall::fitRotationCentre(const std::string& group, const Teuchos::ParameterList& given,
                                    const Mesh& mesh) {
  if (m_settings.motion.kind != ToolMotion::Kind::Rotation || given.isParameter("Rotation Centre X") ||
      given.isParameter("Rotation Centre Y"))
    return;
  // checkTangency then measures how well the segments fit the circle.
  const std::string where = "Boundary Conditions/" + group + "/Tool Motion = Rotation";
  const size_t n = m_curve.nodes.size();
  if (n < 3)
    throw InputError(where + ": the Rotation Centre is not given and " + std::to_string(n) +
                     " wall node(s) define no circle; give Rotation Centre X and Y");
  std::vector<std::array<double, 2>> points;
  for (GO node : m_curve.nodes) points.push_back(mesh.coords[node]);
  std::array<double, 2> centre;
  double radius = 0.0;
  if (!fitCircleCentre(points, centre, radius))
    throw InputError(where + ": the Rotation Centre is not given and the wall's nodes lie on a straight line, "
                     "not on a circle; give Rotation Centre X and Y");
  m_settings.motion.centre = centre;
  m_centreFitted = true;
  log() << "contact: wall '" << group << "' turns about the centre of its nodes' circle (" << centre[0] << ", "
        << centre[1] << "), radius " << radius << "\n";
}

void ContactWall::checkTangency(const std::string& group) const {
  if (!m_settings.motion.moving()) return;
  // At each segment's midpoint m against its own normal n_s: v_w(m)·n_s = 0 exactly for a
  // straight wall along V and for a chord of a circle about c (m − c is along n_s).
  double worst = 0.0;
  int worstSegment = -1;
  for (int k = 0; k < numNodes(); ++k) {
    const int o = next(k);
    if (o < 0) continue;
    const auto& a = m_coords[k];
    const auto& b = m_coords[o];
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::hypot(dx, dy);
    // The segment normal with the curve's orientation: the nodal normals' side (t = (−n_y, n_x)).
    const std::array<double, 2> mid{0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
    const std::array<double, 2> v = m_settings.motion.velocityAt(mid);
    const double speed = std::hypot(v[0], v[1]);
    if (!(speed > 0.0) || !(len > 0.0)) continue;
    const double ratio = std::abs(v[0] * dy - v[1] * dx) / (len * speed);  // |v·n_s| / |v|
    if (ratio > worst) {
      worst = ratio;
      worstSegment = k;
    }
  }
  if (worst > m_settings.tangencyTolerance) {
    auto num = [](double v) {
      std::ostringstream o;
      o << std::setprecision(6) << v;
      return o.str();
    };
    const auto& a = m_coords[worstSegment];
    const auto& b = m_coords[next(worstSegment)];
    throw InputError("Boundary Conditions/" + group + "/Tool Motion: the tool must move tangentially to its own "
                     "surface (a steady state), but on the segment (" + num(a[0]) + ", " +
                     num(a[1]) + ")–(" + num(b[0]) + ", " + num(b[1]) +
                     ") |v_w·n|/|v_w| = " + num(worst) + " > Tangency Tolerance " +
                     num(m_settings.tangencyTolerance) +
                     " (a Translation must be parallel to a straight wall, a Rotation centred on the wall's circle)");
  }
}

std::array<double, 2> ContactWall::stationPoint(int station) const {
  const double s = length() * station / (numFieldStations() - 1);
  size_t k = 0;
  while (k + 2 < m_curve.arcLength.size() && m_curve.arcLength[k + 1] < s) ++k;
  const size_t o = (k + 1) % m_toolCoords.size();
  const double w = std::clamp((s - m_curve.arcLength[k]) / m_curve.segmentLength[k], 0.0, 1.0);
  return {(1.0 - w) * m_toolCoords[k][0] + w * m_toolCoords[o][0], (1.0 - w) * m_toolCoords[k][1] + w * m_toolCoords[o][1]};
}

void ContactWall::refreshGeometry(const Mesh& mesh) {
  // The same nodes in the same order (the mesh's topology does not change), new positions.
  const std::vector<GO> nodes = m_curve.nodes;
  m_curve = buildBoundaryCurve(mesh, mesh.boundary(m_curve.name));
  if (m_curve.nodes != nodes)
    throw std::logic_error("contact wall '" + m_curve.name + "': moving the nodes changed the order of the curve");
  m_coords.clear();
  for (GO node : m_curve.nodes) m_coords.push_back(mesh.coords[node]);
  if (hasFrictionField()) {
    // Node k at s_k/L of the wall: between stations floor(N s_k/L) and the next.
    const int intervals = numFieldStations() - 1;
    const double L = length();
    m_fieldStation.resize(m_curve.nodes.size());
    m_fieldFraction.resize(m_curve.nodes.size());
    for (size_t k = 0; k < m_curve.nodes.size(); ++k) {
      const double t = intervals * m_curve.arcLength[k] / L;
      m_fieldStation[k] = std::min(static_cast<int>(std::floor(t)), intervals - 1);
      m_fieldFraction[k] = t - m_fieldStation[k];
    }
  }
  if (m_settings.releasedFreeSurface && !m_toolNormals.empty()) m_curve.normals = m_toolNormals;
  m_cornerNormals.assign(m_curve.nodes.size(), {});
  m_normalHeld.assign(m_curve.nodes.size(), 0);
  m_cornerSpeeds.assign(m_curve.nodes.size(), {});
  // The tool's surface velocity at each node, split along the node's normal and tangent (all 0
  // for a fixed tool, so that its relative velocities are the material's, bit for bit).
  m_wallVelocity.assign(m_curve.nodes.size(), {0.0, 0.0});
  m_wallNormalSpeed.assign(m_curve.nodes.size(), 0.0);
  m_wallTangentialSpeed.assign(m_curve.nodes.size(), 0.0);
  if (!m_settings.motion.moving()) return;
  // A fitted centre follows the wall's nodes (a shape parameter moving the roll: GeoParameterMotion).
  std::array<double, 2> centre;
  double radius = 0.0;
  if (m_centreFitted && fitCircleCentre(m_coords, centre, radius)) m_settings.motion.centre = centre;
  for (size_t k = 0; k < m_curve.nodes.size(); ++k) {
    const auto v = m_settings.motion.velocityAt(m_coords[k]);
    const auto& n = m_curve.normals[k];
    m_wallVelocity[k] = v;
    m_wallNormalSpeed[k] = v[0] * n[0] + v[1] * n[1];
    m_wallTangentialSpeed[k] = -n[1] * v[0] + n[0] * v[1];
  }
}

void ContactWall::setTool(const Mesh& made) {
  const BoundaryCurve tool = buildBoundaryCurve(made, made.boundary(m_curve.name));
  if (tool.nodes != m_curve.nodes)
    throw std::logic_error("contact wall '" + m_curve.name + "': the tool's mesh has other nodes than the wall");
  m_toolCoords.clear();
  for (GO node : tool.nodes) m_toolCoords.push_back(made.coords[node]);
  m_toolNormals = tool.normals;
}

std::vector<std::array<GO, 2>> ContactWall::couplings() const {
  std::vector<std::array<GO, 2>> pairs;
  for (int k = 0; k < numNodes(); ++k)
    if (next(k) >= 0) pairs.push_back({m_curve.nodes[k], m_curve.nodes[next(k)]});
  return pairs;
}

void ContactWall::setScales(std::vector<double> viscosity, std::vector<double> flowStress) {
  m_viscosity = std::move(viscosity);
  m_flowStress = std::move(flowStress);
}

double ContactWall::compression(int k, const std::vector<double>& p, const std::vector<std::array<double, 2>>& u) const {
  // Not on a wall whose released nodes become a free surface (the cutting rake): there the
  // traction criterion moved the chip's separation point between nearby runs (the total
  // dF_c/dν by DDM and by re-converged differences disagreed), the mean pressure does not.
  if (!m_settings.coulombOnContactForce || m_settings.releasedFreeSurface) return p[k];
  // The penalty's normal force α_n (u − v_w)·n over the node's lumped area W_k ℓ_k (ℓ_k half its
  // segments' lengths): the normal traction the wall carries there, compression positive.
  double lumped = 0.0;
  for (int o : {previous(k), next(k)})
    if (o >= 0) lumped += 0.5 * std::hypot(m_coords[o][0] - m_coords[k][0], m_coords[o][1] - m_coords[k][1]);
  if (!(lumped > 0.0)) return p[k];
  return m_settings.normalPenalty * m_viscosity[k] * relativeNormalVelocity(k, u[k]) / lumped;
}

double ContactWall::violation(int k, const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                              double pressureTolerance, double penetrationTolerance) const {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  if (held(k) || (m_active[k] != kFree && m_settings.neverReleased)) return kNone;  // no status change
  if (m_active[k] == kComplementary) return kNone;  // decided inside Newton
  const double un = relativeNormalVelocity(k, u[k]);  // (u − v_w)·n
  if (m_active[k] == kSelfDeciding) return -un - penetrationTolerance;  // it leaves the tool: free
  if (m_active[k] == kActive) return -compression(k, p, u) - pressureTolerance;  // tension beyond the tolerance
  if (gap(k) > 1e-9 * m_curve.arcLength.back()) return kNone;  // off the tool: the surface update brings it back
  double v = un - penetrationTolerance;                        // moving into the tool
  for (size_t c = 0; c < m_cornerNormals[k].size(); ++c) {  // convex tool corner: into every half-plane
    const auto& other = m_cornerNormals[k][c];
    v = std::min(v, u[k][0] * other[0] + u[k][1] * other[1] - m_cornerSpeeds[k][c] - penetrationTolerance);
  }
  return v;
}

int ContactWall::letCyclingNodesDecide(const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                                      double pressureTolerance, double penetrationTolerance, int maxChangesPerNode) {
  int count = 0;
  for (int k = 0; k < numNodes(); ++k)
    if (m_changes[k] >= maxChangesPerNode && m_active[k] != kSelfDeciding &&
        violation(k, p, u, pressureTolerance, penetrationTolerance) > 0.0) {
      m_active[k] = kSelfDeciding;
      m_changes[k] = 0;  // it may still leave the tool for good (released as any node)
      ++count;
    }
  return count;
}

StatusChange ContactWall::nextChange(const std::vector<double>& p, const std::vector<std::array<double, 2>>& u,
                                     double pressureTolerance, double penetrationTolerance,
                                     int maxChangesPerNode, int* unsettled, double* runnerUp,
                                     double* unsettledRatio) const {
  StatusChange atLimit, anywhere;
  double secondAtLimit = 0.0, secondAnywhere = 0.0;
  if (unsettled) *unsettled = 0;
  if (unsettledRatio) *unsettledRatio = 0.0;
  for (int k = 0; k < numNodes(); ++k) {
    const double violation = this->violation(k, p, u, pressureTolerance, penetrationTolerance);
    if (!(violation > 0.0)) continue;
    if (m_changes[k] >= maxChangesPerNode) {
      if (unsettled) ++*unsettled;
      // The tension or penetration over its tolerance (∞ for a zero tolerance).
      const double tolerance = m_active[k] == kActive ? pressureTolerance : penetrationTolerance;
      const double ratio = tolerance > 0.0 ? (violation + tolerance) / tolerance : std::numeric_limits<double>::infinity();
      if (unsettledRatio) *unsettledRatio = std::max(*unsettledRatio, ratio);
      continue;
    }
    const int a = previous(k), b = next(k);
    const bool limit = a < 0 || b < 0 || m_active[a] != m_active[k] || m_active[b] != m_active[k];
    StatusChange& best = limit ? atLimit : anywhere;
    double& second = limit ? secondAtLimit : secondAnywhere;
    if (violation > best.violation) {
      if (best.node >= 0) second = best.violation;
      best = {k, m_active[k] == kFree, violation};
    } else {
      second = std::max(second, violation);
    }
  }
  if (runnerUp) *runnerUp = atLimit.node >= 0 ? secondAtLimit : secondAnywhere;
  return atLimit.node >= 0 ? atLimit : anywhere;
}

std::vector<ContactWall> contactWallsFromCase(const Teuchos::ParameterList& bcList, const Mesh& mesh,
                                              Geometry geometry) {
  std::vector<ContactWall> walls;
  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (!bcList.isSublist(name)) continue;  // BoundaryConditions reports it
    const Teuchos::ParameterList& group = bcList.sublist(name);
    if (!group.isType<std::string>("Type") || group.get<std::string>("Type") != "Contact Wall") continue;
    if (!mesh.hasBoundary(name))
      throw InputError("Boundary Conditions/" + name + ": mesh '" + mesh.source +
                       "' has no boundary group of that name; it has: " + mesh.boundaryNames());
    walls.emplace_back(name, group, mesh, geometry);
  }
  markConvexToolCorners(walls);
  return walls;
}

void ContactWall::takeStatusesFrom(const ContactWall& other, const std::vector<std::array<double, 2>>* u,
                                   double penetrationTolerance) {
  for (int k = 0; k < numNodes(); ++k) {
    const auto& x = m_coords[k];
    double bestDistance = std::numeric_limits<double>::max();
    bool active = other.isActive(0), zoneLimit = false;
    for (int a = 0; a < other.numNodes(); ++a) {
      const int b = other.next(a);
      if (b < 0) continue;
      // Nearest point of segment a–b: parameter t of the projection, clamped to [0, 1].
      const auto& xa = other.nodeCoordinates(a);
      const auto& xb = other.nodeCoordinates(b);
      const double dx = xb[0] - xa[0], dy = xb[1] - xa[1];
      const double len2 = dx * dx + dy * dy;
      const double t = len2 > 0.0 ? std::clamp(((x[0] - xa[0]) * dx + (x[1] - xa[1]) * dy) / len2, 0.0, 1.0) : 0.0;
      const double px = xa[0] + t * dx - x[0], py = xa[1] + t * dy - x[1];
      const double d = px * px + py * py;
      if (d < bestDistance) {
        bestDistance = d;
        if (std::abs(t - 0.5) < 1e-6)
          active = other.isActive(a) && other.isActive(b);
        else
          active = t < 0.5 ? other.isActive(a) : other.isActive(b);
        zoneLimit = other.isActive(a) != other.isActive(b) && t > 1e-6 && t < 1.0 - 1e-6;
      }
    }
    if (zoneLimit && u) {
      const auto& v = (*u)[k];
      active = relativeNormalVelocity(k, v) > penetrationTolerance;
      for (size_t c = 0; c < m_cornerNormals[k].size(); ++c) {
        const auto& corner = m_cornerNormals[k][c];
        active = active && v[0] * corner[0] + v[1] * corner[1] - m_cornerSpeeds[k][c] > penetrationTolerance;
      }
    }
    if (m_active[k] == kComplementary)
      m_inContact[k] = active;  // its own complementarity decides from here
    else
      m_active[k] = active || held(k) ? kActive : kFree;
  }
  resetChangeCounts();
  // A solve from here: the same model as the state it starts from. Without u (the adaptive
  // indicators' linearization at the carried state) the statuses stay as carried: measured, the
  // indicators of the complementarity walls coarsened the extrusion's mesh cycle after cycle.
  if (other.m_complementarity && u) enterComplementarity();
}

int ContactWall::enterComplementarity() {
  m_complementarity = true;
  if (m_settings.releasedFreeSurface || m_settings.neverReleased) return 0;
  int count = 0;
  for (int k = 0; k < numNodes(); ++k) {
    if (held(k) || !m_cornerNormals[k].empty() || m_active[k] == kComplementary) continue;
    m_inContact[k] = isActive(k);
    m_active[k] = kComplementary;
    ++count;
  }
  return count;
}

int ContactWall::releaseCornersInTension(const std::vector<double>& p, double pressureTolerance) {
  int count = 0;
  for (int k = 0; k < numNodes(); ++k)
    if (!m_cornerNormals[k].empty() && m_active[k] == kActive && !held(k) && !m_settings.neverReleased &&
        !m_settings.releasedFreeSurface && p[k] < -pressureTolerance) {
      setActive(k, false);
      ++count;
    }
  return count;
}

int ContactWall::readContact(const std::vector<std::array<double, 2>>& u) {
  int changed = 0;
  for (int k = 0; k < numNodes(); ++k) {
    if (m_active[k] != kComplementary) continue;
    const char pressing = relativeNormalVelocity(k, u[k]) > 0.0;  // (u − v_w)·n
    changed += pressing != m_inContact[k];
    m_inContact[k] = pressing;
  }
  return changed;
}

std::array<double, ContactWall::kNodeStencilSize> ContactWall::stencilValues(
    int k, const std::vector<double>& p, const std::vector<std::array<double, 2>>& u) const {
  std::array<double, kNodeStencilSize> v{};
  const auto stencil = nodeStencil(k);
  for (int i = 0; i < kNodeStencilSize; ++i) {
    const int j = stencil[i].node;
    if (j < 0) continue;
    v[i] = stencil[i].component == kP ? p[j] : u[j][stencil[i].component == kUx ? 0 : 1];
  }
  return v;
}

}  // namespace flowform
