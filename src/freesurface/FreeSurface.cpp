#include "flowform/freesurface/FreeSurface.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "flowform/bc/FieldBoundaryValues.hpp"
#include "flowform/core/InputError.hpp"
#include "flowform/mesh/BoundaryCurve.hpp"
#include "flowform/core/ValidList.hpp"

namespace flowform {

namespace {

using Point = std::array<double, 2>;

double dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1]; }
Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1]}; }

/// `curve`'s nodes from the end it shares with group `start` (InputError if it shares none).
std::vector<GO> orderedFrom(const Mesh& mesh, const BoundaryCurve& curve, const std::string& start,
                            const std::string& where) {
  if (!mesh.hasBoundary(start))
    throw InputError(where + "/Start Group: mesh '" + mesh.source + "' has no boundary group '" + start +
                     "'; it has: " + mesh.boundaryNames());
  if (curve.closed) throw InputError(where + ": a free surface must be an open curve, and this one is closed");
  const CurveEnds ends = endsOn(curve, mesh.boundary(start));
  if (ends.first == ends.last)
    throw InputError(where + "/Start Group: group '" + start + "' must share exactly one end of the surface " +
                     (ends.first ? "(it shares both)" : "(it shares neither)"));
  std::vector<GO> nodes = curve.nodes;
  if (ends.last) std::reverse(nodes.begin(), nodes.end());
  return nodes;
}

/// The segment's flux-weighted mean velocity: the plain mean in plane strain; in axisymmetry
/// (u_a(2r_a + r_b) + u_b(r_a + 2r_b)) / (3(r_a + r_b)), so that L ū·n is the flux ∫ u·n 2πr ds / 2π r̄.
Point segmentVelocity(const Point& xa, const Point& xb, const Point& ua, const Point& ub, Geometry geometry) {
  double wa = 0.5;
  if (geometry == Geometry::Axisymmetric && xa[0] + xb[0] > 0.0) wa = (2.0 * xa[0] + xb[0]) / (3.0 * (xa[0] + xb[0]));
  const double wb = 1.0 - wa;
  return {wa * ua[0] + wb * ub[0], wa * ua[1] + wb * ub[1]};
}

/// The unit tangent at x of the circle about `centre` through x, pointing along `towards`.
Point circleTangent(const Point& x, const Point& centre, const Point& towards) {
  const Point r = minus(x, centre);
  const double length = std::hypot(r[0], r[1]), sign = dot({-r[1], r[0]}, towards) >= 0.0 ? 1.0 : -1.0;
  return {-sign * r[1] / length, sign * r[0] / length};
}

/// +1 where moving along `tangent` at x turns counter-clockwise about `centre`, −1 clockwise.
double turnSign(const Point& x, const Point& centre, const Point& tangent) {
  const Point r = minus(x, centre);
  return r[0] * tangent[1] - r[1] * tangent[0] >= 0.0 ? 1.0 : -1.0;
}

/// |ū·n|/|ū| of segment a–b: the sine of the angle between the flow and the segment.
double flowAngle(const Point& xa, const Point& xb, const Point& mean) {
  const Point d = minus(xb, xa);
  const double len = std::hypot(d[0], d[1]);
  return std::abs(mean[0] * d[1] - mean[1] * d[0]) / (len * std::hypot(mean[0], mean[1]));
}

}  // namespace

static void buildValidFreeSurfaceParameters(const ValidList& valid) {
  valid->set("Type", "Free Surface", "a traction-free boundary that becomes a streamline (docs/theory.md §3)");
  valid->set("Start Group", "",
             "the boundary group that shares the surface's fixed start (the die wall at a die exit)");
  Teuchos::setStringToIntegralParameter<int>(
      "Update", "Spines",
      "Spines: every node moves along the normal of the surface's chord (a surface that advances along its chord: "
      "a jet, a die land); Arc Length: every segment keeps its length and turns with the flow (a surface that "
      "turns, e.g. a chip's back); docs/theory.md §3.2",
      Teuchos::tuple<std::string>("Spines", "Arc Length"), valid.get());
  declareFieldBoundaryEntries(*valid);
}

Teuchos::RCP<const Teuchos::ParameterList> validFreeSurfaceParameters() {
  return validListOnce<buildValidFreeSurfaceParameters>("Free Surface");
}

FreeSurfaces::FreeSurfaces(const Teuchos::ParameterList& bcList, const Mesh& mesh,
                           const std::vector<ContactWall>& walls) {
  auto make = [&](const std::string& name, std::vector<GO> nodes, const std::string& where, bool arcLength) {
    Surface s;
    s.name = name;
    s.nodes = std::move(nodes);
    s.arcLength = arcLength;
    for (size_t k = 0; k + 1 < s.nodes.size(); ++k) {
      const Point d = minus(mesh.coords[s.nodes[k + 1]], mesh.coords[s.nodes[k]]);
      s.segmentLength.push_back(std::hypot(d[0], d[1]));
    }
    // Spine frame: c along the chord start → end, m ⊥ c on the outward side of the curve.
    const Point x0 = mesh.coords[s.nodes.front()], x1 = mesh.coords[s.nodes.back()];
    const double length = std::hypot(x1[0] - x0[0], x1[1] - x0[1]);
    if (!(length > 0.0)) throw InputError(where + ": the surface's ends coincide");
    s.origin = x0;
    s.chord = {(x1[0] - x0[0]) / length, (x1[1] - x0[1]) / length};
    const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(name));
    Point outward{0.0, 0.0};
    for (const auto& n : curve.segmentNormals) outward = {outward[0] + n[0], outward[1] + n[1]};
    s.normal = {-s.chord[1], s.chord[0]};
    if (dot(s.normal, outward) < 0.0) s.normal = {-s.normal[0], -s.normal[1]};
    for (GO node : s.nodes) {
      const Point d = minus(mesh.coords[node], x0);
      s.along.push_back(dot(d, s.chord));
      s.tool.push_back(dot(d, s.normal));
    }
    for (size_t k = 1; k < s.along.size() && !arcLength; ++k)
      if (!(s.along[k] > s.along[k - 1]))
        throw InputError(where + ": the surface turns back on its chord (node " + std::to_string(s.nodes[k]) +
                         "); the spine update needs a surface that advances along it");
    // The straight group at the downstream end, dragged along (or a contact wall, along whose
    // tool the end slides).
    const GO end = s.nodes.back();
    for (const BoundaryGroup& g : mesh.boundaries) {
      if (g.name == name) continue;
      bool has = false;
      for (const auto& e : g.edges) has = has || e[0] == end || e[1] == end;
      if (!has) continue;
      const BoundaryCurve other = buildBoundaryCurve(mesh, g);
      const auto wall = std::find_if(walls.begin(), walls.end(), [&](const ContactWall& w) { return w.name() == g.name; });
      if (wall != walls.end() && !arcLength) {
        if (wall->motion().kind != ToolMotion::Kind::Rotation && !other.isStraight(1e-8))
          throw InputError(where + ": the surface lands on contact wall '" + g.name + "', whose tool must be straight "
                           "or a circle turning about its Rotation Centre (a roll): the end node slides along it");
        if (other.closed || (other.nodes.front() != end && other.nodes.back() != end))
          throw InputError(where + ": the surface must land on an end of contact wall '" + g.name + "'");
        s.endWall = static_cast<int>(wall - walls.begin());
        // The wall's other nodes slide with the end by their arc-length fraction from its far end.
        const bool endFirst = other.nodes.front() == end;
        const double total = other.arcLength.back();
        for (size_t k = 1; k + 1 < other.nodes.size(); ++k) {
          const size_t i = endFirst ? k : other.nodes.size() - 1 - k;
          s.dragged.push_back(other.nodes[i]);
          s.dragFraction.push_back(endFirst ? 1.0 - other.arcLength[i] / total : other.arcLength[i] / total);
        }
        continue;
      }
      if (!other.isStraight(1e-8))
        throw InputError(where + ": group '" + g.name + "' at the surface's downstream end must be straight");
      const auto& n = other.segmentNormals.front();
      if (arcLength) {
        s.endOnLine = true;
        s.endLinePoint = mesh.coords[end];
        s.endLineNormal = n;
      }
      if (!arcLength && std::abs(dot(n, s.normal)) > 1e-8)
        throw InputError(where + ": group '" + g.name + "' at the surface's downstream end must run along the "
                         "surface's normal (its end node moves along it)");
      // Fraction of the arc length from the group's other end (fixed, or the end of another
      // surface, whose drag adds the complementary fraction: the group stays straight).
      const double total = other.arcLength.back();
      const bool endFirst = other.nodes.front() == end;
      for (size_t k = 0; k < other.nodes.size(); ++k) {
        if (other.nodes[k] == end) continue;
        s.dragged.push_back(other.nodes[k]);
        s.dragFraction.push_back(endFirst ? 1.0 - other.arcLength[k] / total : other.arcLength[k] / total);
      }
    }
    m_lengthScale = std::max(m_lengthScale, length);
    return s;
  };
  m_lengthScale = 0.0;
  for (auto it = bcList.begin(); it != bcList.end(); ++it) {
    const std::string& name = bcList.name(it);
    if (!bcList.isSublist(name)) continue;
    const Teuchos::ParameterList& group = bcList.sublist(name);
    if (!group.isType<std::string>("Type") || group.get<std::string>("Type") != "Free Surface") continue;
    const std::string where = "Boundary Conditions/" + name + " (Free Surface)";
    Teuchos::ParameterList list = group;
    try {
      list.validateParametersAndSetDefaults(*validFreeSurfaceParameters());
    } catch (const std::exception& e) {
      throw InputError(where + ": " + e.what());
    }
    const BoundaryCurve curve = buildBoundaryCurve(mesh, mesh.boundary(name));
    m_surfaces.push_back(make(name, orderedFrom(mesh, curve, list.get<std::string>("Start Group"), where), where,
                              list.get<std::string>("Update") == "Arc Length"));
  }
  for (size_t w = 0; w < walls.size(); ++w) {
    const ContactWall& wall = walls[w];
    if (!wall.releasedFreeSurface()) continue;
    const std::string where = "Boundary Conditions/" + wall.name() + " (Contact Wall, Released Nodes = Free Surface)";
    std::vector<GO> nodes = orderedFrom(mesh, wall.curve(), wall.upstreamGroup(), where);
    Surface s = make(wall.name(), nodes, where, false);
    s.wall = static_cast<int>(w);
    const bool reversed = !wall.firstNodeIsUpstream();  // orderedFrom ran from the same end
    for (int k = 0; k < wall.numNodes(); ++k) s.wallIndex.push_back(reversed ? wall.numNodes() - 1 - k : k);
    m_surfaces.push_back(std::move(s));
  }
  if (m_lengthScale <= 0.0) m_lengthScale = 1.0;
}

std::array<double, 2> FreeSurfaceStep::Slide::displacement(double amount) const {
  if (!circle) return {amount * tangent[0], amount * tangent[1]};
  // x = c + Rot(θ)(at − c), θ = amount/r turned from at − c towards the tangent.
  const Point r = minus(at, centre);
  const double theta = turnSign(at, centre, tangent) * amount / std::hypot(r[0], r[1]);
  const double c = std::cos(theta), sn = std::sin(theta);
  const Point x{centre[0] + c * r[0] - sn * r[1], centre[1] + sn * r[0] + c * r[1]};
  return minus(x, at);
}

void FreeSurfaceStep::relax(double omega) {
  std::vector<std::array<double, 2>> scaled(moves.size());
  for (size_t i = 0; i < moves.size(); ++i) scaled[i] = {omega * moves[i].residual[0], omega * moves[i].residual[1]};
  setMoves(scaled);
}

void FreeSurfaceStep::setMoves(const std::vector<std::array<double, 2>>& perMove) {
  std::vector<std::array<double, 2>> moved(moves.size());
  for (size_t i = 0; i < moves.size(); ++i) {
    const Move& m = moves[i];
    std::array<double, 2> d = perMove[i];
    if (!m.arcLength && dot(d, m.normal) > m.room) d = {m.room * m.normal[0], m.room * m.normal[1]};  // not into the tool
    if (m.slide.on) d = m.slide.displacement(dot(d, m.normal));  // along the tool, on it
    moved[i] = d;
    displacement[m.node] = d;
    prescribed[m.node] = 1;
  }
  // A dragged group between two surfaces' ends (a chip's outlet) holds each end in the other's
  // drag list (fraction 0): an end is moved by its own surface, never dragged.
  std::vector<char> isMove(displacement.size(), 0);
  for (const Move& m : moves) isMove[m.node] = 1;
  for (const Drag& d : drags)
    if (!isMove[d.node]) displacement[d.node] = {0.0, 0.0};
  for (const Drag& d : drags) {
    if (isMove[d.node]) continue;
    if (d.slide.on) {  // its fraction of the attachment's slide, along the tool
      const Move& end = moves[d.end];
      displacement[d.node] = d.slide.displacement(d.fraction * dot(perMove[d.end], end.normal));
      prescribed[d.node] = 1;
      continue;
    }
    displacement[d.node][0] += d.fraction * moved[d.end][0];
    displacement[d.node][1] += d.fraction * moved[d.end][1];
    prescribed[d.node] = 1;
  }
}

bool FreeSurfaces::arcLengthStep(const Surface& s, const Mesh& mesh,
                                 const std::function<std::array<double, 2>(GO)>& velocity, Geometry geometry,
                                 FreeSurfaceStep& out) const {
  // Arc length: x_{k+1} = x_k + L_k ū/|ū| from the fixed start, L_k the segment's length as made
  // (the streamline's polyline, with the directions of the current segments' mean velocities) ...
  const size_t n = s.nodes.size();
  std::vector<Point> x(n), xNew(n), direction(n - 1);
  for (size_t k = 0; k < n; ++k) x[k] = mesh.coords[s.nodes[k]];
  for (size_t k = 0; k + 1 < n; ++k) {
    const Point mean = segmentVelocity(x[k], x[k + 1], velocity(s.nodes[k]), velocity(s.nodes[k + 1]), geometry);
    const double speed = std::hypot(mean[0], mean[1]);
    if (!(speed > 0.0)) {
      out.failure = "the flow stands still on free surface '" + s.name + "' near (" + std::to_string(x[k][0]) + ", " +
                    std::to_string(x[k][1]) + ")";
      return false;
    }
    out.noteFlowAngle(flowAngle(x[k], x[k + 1], mean), x[k], x[k + 1]);
    direction[k] = {mean[0] / speed, mean[1] / speed};
  }
  // ... then, with a straight group at the end, every length scaled by the one λ that puts the
  // last node on that group's line g(x) = (x − p)·ν = 0 (as made): x_{n−1} = x_0 + λ Σ L_k d_k,
  // so λ = −g(x_0) / (Σ L_k d_k · ν), which must be positive (λ = 1 without such a group).
  double scale = 1.0;
  if (s.endOnLine) {
    Point reach{0.0, 0.0};
    for (size_t k = 0; k + 1 < n; ++k)
      reach = {reach[0] + s.segmentLength[k] * direction[k][0], reach[1] + s.segmentLength[k] * direction[k][1]};
    const double towards = dot(reach, s.endLineNormal), start = dot(minus(x[0], s.endLinePoint), s.endLineNormal);
    scale = towards > 0.0 ? -start / towards : -1.0;
    if (!(scale > 0.0)) {
      out.failure = "free surface '" + s.name + "' does not reach the line of the group at its end: the flow along it "
                    "runs along or away from that line";
      return false;
    }
  }
  xNew[0] = x[0];
  for (size_t k = 0; k + 1 < n; ++k)
    xNew[k + 1] = {xNew[k][0] + scale * s.segmentLength[k] * direction[k][0],
                   xNew[k][1] + scale * s.segmentLength[k] * direction[k][1]};
  const size_t first = out.moves.size();
  for (size_t k = 0; k < n; ++k) {
    const Point r = minus(xNew[k], x[k]);
    out.residual.push_back(r[0]);
    out.residual.push_back(r[1]);
    out.noteMove(std::hypot(r[0], r[1]), x[k]);
    out.moves.push_back({s.nodes[k], s.normal, r, std::numeric_limits<double>::infinity(), k > 0, true});
  }
  for (size_t k = 0; k < s.dragged.size(); ++k) out.drags.push_back({s.dragged[k], s.dragFraction[k], first + n - 1});
  return true;
}

bool FreeSurfaces::attachmentStep(const Surface& s, const Mesh& mesh, const std::vector<ContactWall>& walls,
                                  const Point& before, const Point& flow, FreeSurfaceStep& out) const {
  const ContactWall& wall = walls[s.endWall];
  const GO end = s.nodes.back();
  const Point x = mesh.coords[end];
  // The tool at the end node: a circle about the roll's centre, or the wall's line; its tangent
  // there points into the wall (the flow's direction along it).
  const BoundaryCurve& curve = wall.curve();
  const bool endFirst = curve.nodes.front() == end;
  const Point next = mesh.coords[endFirst ? curve.nodes[1] : curve.nodes[curve.nodes.size() - 2]];
  FreeSurfaceStep::Slide slide;
  slide.on = true;
  slide.at = x;
  slide.circle = wall.motion().kind == ToolMotion::Kind::Rotation;
  slide.centre = wall.motion().centre;
  const Point chord = minus(next, x);
  const double radius = std::hypot(x[0] - slide.centre[0], x[1] - slide.centre[1]);
  const double chordLength = std::hypot(chord[0], chord[1]);
  slide.tangent = slide.circle ? circleTangent(x, slide.centre, chord)
                               : Point{chord[0] / chordLength, chord[1] / chordLength};
  // Where the line before + λ·flow first meets the tool (λ > 0).
  const double speed = std::hypot(flow[0], flow[1]);
  const Point d{flow[0] / speed, flow[1] / speed};
  double lambda = -1.0;
  if (slide.circle) {
    // |before + λ d − c|² = r²: λ² + 2 λ d·e + |e|² − r² = 0, e = before − c; the first root.
    const Point e = minus(before, slide.centre);
    const double half = dot(d, e), c = dot(e, e) - radius * radius, disc = half * half - c;
    if (c > 0.0 && disc >= 0.0) lambda = -half - std::sqrt(disc);
  } else {
    const Point n{-slide.tangent[1], slide.tangent[0]};  // the line (y − x)·n = 0
    const double towards = dot(d, n);
    if (towards != 0.0) lambda = dot(minus(x, before), n) / towards;
  }
  if (!(lambda > 0.0)) {
    out.failure = "free surface '" + s.name + "' does not meet contact wall '" + wall.name() +
                  "' downstream of its last free node (" + std::to_string(before[0]) + ", " +
                  std::to_string(before[1]) + "): the flow there runs along or away from the tool";
    return false;
  }
  const Point meet{before[0] + lambda * d[0], before[1] + lambda * d[1]};
  // The slide from x to meet along the tool (an arc length on a circle).
  double amount = dot(minus(meet, x), slide.tangent);
  if (slide.circle) {
    const Point a = minus(x, slide.centre), b = minus(meet, slide.centre);
    amount = turnSign(x, slide.centre, slide.tangent) * radius * std::atan2(a[0] * b[1] - a[1] * b[0], dot(a, b));
  }
  const Point& last = mesh.coords[s.nodes[s.nodes.size() - 2]];  // the last segment, as it is
  out.noteFlowAngle(flowAngle(last, x, flow), last, x);
  out.residual.push_back(amount);
  out.noteMove(std::abs(amount), x);
  const size_t move = out.moves.size();
  out.moves.push_back({end, slide.tangent, {amount * slide.tangent[0], amount * slide.tangent[1]},
                       std::numeric_limits<double>::infinity(), true, false, slide});
  // The wall's other nodes (but its far end) slide by their fraction; each with its own tangent.
  for (size_t k = 0; k < s.dragged.size(); ++k) {
    FreeSurfaceStep::Slide own = slide;
    own.at = mesh.coords[s.dragged[k]];
    if (slide.circle) own.tangent = circleTangent(own.at, slide.centre, slide.tangent);
    out.drags.push_back({s.dragged[k], s.dragFraction[k], move, own});
  }
  return true;
}

FreeSurfaceStep FreeSurfaces::step(const Mesh& mesh, const DofMap& dofMap, const std::vector<double>& u,
                                   const std::vector<ContactWall>& walls, Geometry geometry,
                                   double gapTolerance) const {
  FreeSurfaceStep out;
  out.displacement.assign(mesh.numNodes(), {0.0, 0.0});
  out.prescribed.assign(mesh.numNodes(), 0);
  const std::function<Point(GO)> velocity = [&](GO node) -> Point {
    return {u[dofMap.globalDof(node, kUx)], u[dofMap.globalDof(node, kUy)]};
  };
  for (const Surface& s : m_surfaces) {
    const size_t n = s.nodes.size();
    if (s.arcLength) {
      if (!arcLengthStep(s, mesh, velocity, geometry, out)) return out;
      continue;
    }
    std::vector<double> b(n);
    for (size_t k = 0; k < n; ++k) b[k] = dot(minus(mesh.coords[s.nodes[k]], s.origin), s.normal);
    // A Free Surface group: every node but the first follows the streamline from it. A wall:
    // active nodes stay on the tool; each run of free nodes follows the streamline from the node
    // before it (an active node: the separation point, or the wall's upstream end).
    // An active node that a separated run's streamline passes below the tool (by more than
    // gapTolerance) is not touched by the material: it is released and the run goes on through it.
    const ContactWall* wall = s.wall >= 0 ? &walls[s.wall] : nullptr;
    std::vector<double> bNew = b;
    std::vector<char> free(n, 1);        // per surface node
    std::vector<char> integrated(n, 0);  // placed by the streamline (not a start, not on the tool)
    if (wall)
      for (size_t k = 0; k < n; ++k) free[k] = !wall->isActive(s.wallIndex[k]);
    for (size_t k = 0; k + 1 < n; ++k) {
      if (!free[k + 1] && !free[k]) {  // inside a contact zone: on the tool
        bNew[k + 1] = s.tool[k + 1];
        continue;
      }
      const GO na = s.nodes[k], nb = s.nodes[k + 1];
      const Point mean = segmentVelocity(mesh.coords[na], mesh.coords[nb], velocity(na), velocity(nb), geometry);
      const double speed = std::hypot(mean[0], mean[1]);
      const double uc = dot(mean, s.chord), um = dot(mean, s.normal);
      if (!(uc > 1e-3 * speed) || !(speed > 0.0)) {
        out.failure = "the flow on free surface '" + s.name + "' does not advance along it near (" +
                      std::to_string(mesh.coords[na][0]) + ", " + std::to_string(mesh.coords[na][1]) +
                      "): the spine update needs u·c > 0";
        return out;
      }
      const double angle = flowAngle(mesh.coords[na], mesh.coords[nb], mean);  // at the current positions
      bNew[k + 1] = bNew[k] + dot(minus(mesh.coords[nb], mesh.coords[na]), s.chord) * um / uc;
      if (!free[k + 1]) {  // the end of a separated run: reattached, or passing below the node
        if (bNew[k + 1] < s.tool[k + 1] - gapTolerance && !wall->held(s.wallIndex[k + 1])) {
          free[k + 1] = 1;
          integrated[k + 1] = 1;
          out.released.push_back({s.wall, s.wallIndex[k + 1]});
          out.noteFlowAngle(angle, mesh.coords[na], mesh.coords[nb]);
        } else {
          bNew[k + 1] = s.tool[k + 1];
        }
        continue;
      }
      if (wall && bNew[k + 1] >= s.tool[k + 1]) {
        // The streamline reaches the tool: the node goes back on it (where the status loop may
        // activate it); the segment is where the surface meets the tool, not a streamline.
        bNew[k + 1] = s.tool[k + 1];
        ++out.clampedToTool;
      } else {
        out.noteFlowAngle(angle, mesh.coords[na], mesh.coords[nb]);
        integrated[k + 1] = 1;
      }
    }
    // The update's residual is bNew − b along m; relax() moves the nodes by ω times it.
    const size_t first = out.moves.size();
    const size_t spines = s.endWall >= 0 ? n - 1 : n;  // an attachment point slides instead
    for (size_t k = 0; k < spines; ++k) {
      const double r = bNew[k] - b[k];
      out.residual.push_back(r);
      out.noteMove(std::abs(r), mesh.coords[s.nodes[k]]);
      const double room = wall ? s.tool[k] - b[k] : std::numeric_limits<double>::infinity();
      out.moves.push_back({s.nodes[k], s.normal, {r * s.normal[0], r * s.normal[1]}, room, integrated[k] != 0, false});
    }
    if (s.endWall >= 0) {
      // The node before it where the update puts it: moved along its spine from where it is (a
      // refined run started from a coarse one's surface has it off its as-made abscissa).
      const GO na = s.nodes[n - 2], nb = s.nodes[n - 1];
      const double rb = bNew[n - 2] - b[n - 2];
      const Point before{mesh.coords[na][0] + rb * s.normal[0], mesh.coords[na][1] + rb * s.normal[1]};
      const Point flow = segmentVelocity(mesh.coords[na], mesh.coords[nb], velocity(na), velocity(nb), geometry);
      if (!attachmentStep(s, mesh, walls, before, flow, out)) return out;
      continue;
    }
    for (size_t k = 0; k < s.dragged.size(); ++k) out.drags.push_back({s.dragged[k], s.dragFraction[k], first + n - 1});
  }
  out.relax(1.0);
  return out;
}

}  // namespace flowform
