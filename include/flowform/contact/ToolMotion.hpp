// The motion of a contact wall's tool (docs/theory.md §2 "Moving tools"): its rigid surface
// velocity v_w(x), which the normal condition and the friction laws act relative to.
//   Fixed        v_w = 0 (every wall before tools could move; the default)
//   Translation  v_w = (V_x, V_y), the same at every point (a container moving with the billet)
//   Rotation     v_w = ω e_z × (x − c) = ω (−(y − c_y), x − c_x), ω counter-clockwise positive
//                (a roll turning about its centre c)
// In a steady state the tool's surface must not move in space: the motion is tangential to
// it (v_w·n = 0), which ContactWall checks on its segments (a straight wall along V, or a
// polyline inscribed in a circle about c, satisfy it to round-off at the segment midpoints).
#pragma once

#include <array>
#include <cmath>

namespace flowform {

struct ToolMotion {
  enum class Kind { Fixed, Translation, Rotation };
  Kind kind = Kind::Fixed;
  std::array<double, 2> velocity{0.0, 0.0};  ///< V (Translation)
  std::array<double, 2> centre{0.0, 0.0};    ///< c (Rotation; also the point Tool Torque is taken about)
  double angularVelocity = 0.0;              ///< ω (Rotation), counter-clockwise positive

  bool moving() const { return kind != Kind::Fixed; }
  /// v_w at the point x.
  std::array<double, 2> velocityAt(const std::array<double, 2>& x) const {
    switch (kind) {
      case Kind::Translation: return velocity;
      case Kind::Rotation: return {-angularVelocity * (x[1] - centre[1]), angularVelocity * (x[0] - centre[0])};
      case Kind::Fixed: break;
    }
    return {0.0, 0.0};
  }
};

}  // namespace flowform
