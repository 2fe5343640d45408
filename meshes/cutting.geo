// Orthogonal plane-strain cutting in the tool's frame (docs/cutting.md, paper §4.2). The
// workpiece enters from the left at speed 1; the layer of uncut thickness t above the cut line
// y = 0 is turned up by the tool's rake face into a chip; the rest passes under the tool tip
// (0, 0) and leaves on the right with the machined surface y = 0.
//
//          chip_outlet
//    y = H   +-------+  (rake top)
//            |       |
//  chip_back |  chip | rake   (rake face through the tip at rake angle alpha from the vertical)
//            |       |
//    y = t --+       |
//   far  |      (shear zone)
//        |           + tip (0, 0) ------ machined ------+
//        |                                              | far
//   y = -D +------------------- far --------------------+
//        x = -Lin                                     x = Lout
//
// "far": the inlet, the bottom and the outlet of the workpiece, where it moves rigidly at the
// cutting speed (one group, so that its force and power are summed once at its corners).
//
// The chip's shape here is only the start of the free-surface loop: its back is the line at
// the distance tc from the rake face (the starting chip thickness, chosen by the case), met by
// the workpiece's top surface y = t at a sharp corner, which the loop moves and rounds; the
// inner surface is the rake face itself until it separates. docs/cutting.md §3 measures how the
// converged chip depends on tc.
// Sizes: hc at the tip and along a shear plane, h elsewhere, graded over dc. The shear plane is
// the line from the tip to the starting chip's corner (phi = 0, the default), or at the angle
// phi (degrees) to the cut line, up to the workpiece's top surface: a guess of the converged
// shear angle (ν = 0.2 converges to 25.8, the ν sweep 0 ... 0.5 to 20 ... 31). phi = 26 halves
// the estimated error of t/t_c at h = 0.1 but the loop needs more updates (docs/cutting.md §6).
// A phi steeper than the start's corner ends the line at the corner.

DefineConstant[
  t = {1.0, Min 0.05, Max 10, Step 0.1, Name "Parameters/t", Label "uncut chip thickness"},
  tc = {1.0, Min 0.05, Max 20, Step 0.1, Name "Parameters/tc", Label "chip thickness of the starting shape"},
  alpha = {0, Min -30, Max 45, Step 1, Name "Parameters/alpha", Label "rake angle (degrees)"},
  Lin = {3.0, Min 0.5, Max 50, Step 0.5, Name "Parameters/Lin", Label "workpiece length before the tool"},
  Lout = {3.0, Min 0.5, Max 50, Step 0.5, Name "Parameters/Lout", Label "workpiece length after the tool"},
  D = {2.0, Min 0.2, Max 50, Step 0.5, Name "Parameters/D", Label "workpiece depth below the cut"},
  H = {3.5, Min 0.5, Max 50, Step 0.5, Name "Parameters/H", Label "height of the chip outlet"},
  h = {0.1, Min 1e-4, Max 1, Step 0.01, Name "Parameters/h", Label "mesh size in the bulk"}
];
DefineConstant[
  hc = {h / 4, Min 1e-5, Max 1, Step 0.005, Name "Parameters/hc", Label "mesh size at the tip and shear zone"},
  dc = {0.5, Min 0, Max 10, Step 0.05, Name "Parameters/dc", Label "distance over which hc grows to h"},
  phi = {0, Min 0, Max 80, Step 1, Name "Parameters/phi", Label "shear angle the mesh is refined along (degrees; 0: to the start's corner)"}
];

If (H <= t + 0.1)
  Error("cutting.geo: the chip outlet H = %g must lie above the workpiece top t = %g", H, t);
EndIf

a = alpha * Pi / 180;
// The rake face: from the tip (0, 0) up to y = H, leaning by alpha towards +x; the chip's back is
// parallel to it at the distance tc (measured normal to the face); the chip outlet runs from the
// rake top normal to the face (the straight chip leaves across it).
rx = H * Tan(a);
bx = -tc / Cos(a);                  // back line's x at y = 0
cy = t;                             // where the back meets the top surface y = t
cx = bx + cy * Tan(a);

Point(1) = {-Lin, -D, 0, h};
Point(2) = {Lout, -D, 0, h};
Point(3) = {Lout, 0, 0, h};
Point(4) = {0, 0, 0, hc};           // the tool tip
Point(5) = {rx, H, 0, h};           // the rake face's top
Point(6) = {rx - tc * Cos(a), H + tc * Sin(a), 0, h};  // the chip outlet is normal to the rake face
Point(7) = {cx, cy, 0, hc};         // the corner of the starting chip
Point(8) = {-Lin, t, 0, h};

Line(1) = {1, 2};  // bottom
Line(2) = {2, 3};  // outlet
Line(3) = {3, 4};  // machined surface
Line(4) = {4, 5};  // rake face
Line(5) = {5, 6};  // chip outlet
Line(6) = {6, 7};  // chip back
Line(8) = {8, 1};  // inlet

// The shear plane's end on the top surface y = t (point 9), when it lies upstream of the corner.
sx = cx;
If (phi > 0)
  sx = -t / Tan(phi * Pi / 180);
EndIf
If (sx < cx - 1e-3 * t && sx > -Lin + 1e-3 * t)
  Point(9) = {sx, t, 0, hc};
  Line(7) = {7, 9};   // top of the uncut workpiece (the same free surface as the chip back)
  Line(10) = {9, 8};
  Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 10, 8};
  Line(9) = {4, 9};   // the shear plane
  top[] = {7, 10};
Else
  Line(7) = {7, 8};
  Curve Loop(1) = {1, 2, 3, 4, 5, 6, 7, 8};
  Line(9) = {4, 7};
  top[] = {7};
EndIf
Plane Surface(1) = {1};

// hc along the shear plane and at the tip.
Line{9} In Surface{1};
Field[1] = Distance;
Field[1].CurvesList = {9};
Field[1].NumPointsPerCurve = 100;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = h;
Field[2].DistMin = 0;
Field[2].DistMax = dc;
Background Field = 2;

Physical Curve("far") = {8, 1, 2};
Physical Curve("machined") = {3};
Physical Curve("rake") = {4};
Physical Curve("chip_outlet") = {5};
Physical Curve("chip_back") = {6, top[]};
Physical Surface("workpiece") = {1};
