// Extrudate (die) swell, docs/theory.md §3.3: fully developed flow in a die leaves it into a
// traction-free jet whose surface is a free surface. Half of the section, cut by the
// symmetry line y = 0 (plane) or the axis (transpose = 1, x = r):
//
//        y
//        1 +------ die_wall ------+~~~~~~~~~~~~ free_surface ~~~~~~~~~~~~~+
//          |                      (die exit x = 0)                        | outlet
//    inlet |               die                    jet                    |
//        0 +------------------------------ axis -------------------------+
//        x = -Ld                  0                                     x = Lf
//
// Die half-height (radius) 1, die length Ld, jet length Lf. The free surface starts at the
// die exit (0, 1), where the velocity field is singular (no-slip meets traction-free): the
// mesh is hc there and grows to h over the distance dc.
// transpose = 1 places every point (x, y) at (y, x) (axisymmetric: x = r, y = z, flow along +z).

DefineConstant[
  Ld = {4, Min 0.5, Max 50, Step 0.5, Name "Parameters/Ld", Label "die length"},
  Lf = {8, Min 1, Max 100, Step 0.5, Name "Parameters/Lf", Label "jet length"},
  h = {0.1, Min 1e-4, Max 1, Step 0.01, Name "Parameters/h", Label "mesh size in the bulk"}
];
DefineConstant[
  hc = {h / 5, Min 1e-5, Max 1, Step 0.005, Name "Parameters/hc", Label "mesh size at the die exit"},
  dc = {1.0, Min 0, Max 10, Step 0.05, Name "Parameters/dc", Label "distance over which hc grows to h"},
  transpose = {0, Choices {0, 1}, Name "Parameters/transpose",
               Label "1: place (x, y) at (y, x) (axisymmetric, x = r)"}
];

xs[] = {-Ld, Lf, Lf, 0, -Ld};
ys[] = {  0,  0,  1, 1,   1};
For i In {0 : 4}
  If (transpose == 1)
    Point(i + 1) = {ys[i], xs[i], 0, h};
  Else
    Point(i + 1) = {xs[i], ys[i], 0, h};
  EndIf
EndFor

Line(1) = {1, 2};  // axis
Line(2) = {2, 3};  // outlet
Line(3) = {3, 4};  // free_surface: from the jet's end back to the die exit
Line(4) = {4, 5};  // die_wall
Line(5) = {5, 1};  // inlet

If (transpose == 1)
  Curve Loop(1) = {-5, -4, -3, -2, -1};
Else
  Curve Loop(1) = {1, 2, 3, 4, 5};
EndIf
Plane Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {4};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = h;
Field[2].DistMin = 0;
Field[2].DistMax = dc;
Background Field = 2;

Physical Curve("axis") = {1};
Physical Curve("outlet") = {2};
Physical Curve("free_surface") = {3};
Physical Curve("die_wall") = {4};
Physical Curve("inlet") = {5};
Physical Surface("fluid") = {1};
