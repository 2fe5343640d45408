// Wire drawing through a conical die, axisymmetric (docs/drawing.md): the half-section
// r ≥ 0 of the wire, flowform's x = r, y = z, the wire drawn along +z.
//
//          r
//     R0   +-- wire_surface --+
//          |                   `-._  die_cone (semi-angle alpha)
//    entry |         wire          `-._
//          |                           +--- die_land ---+ R1
//          |                                            | outlet (the wire pulled here)
//      0   +------------------- axis -------------------+
//        z = -Lc - Lin        z = -Lc                z = 0       z = Ld
//
// The cone runs from (R0, -Lc) to the die throat (R1, 0), Lc = (R0 - R1) / tan(alpha); the land
// r = R1, z ∈ [0, Ld]; the wire enters at z = -Lc - Lin (the entry, traction-free) with its
// surface r = R0 before the die, and leaves through the outlet z = Ld. The area reduction is
// 1 - (R1/R0)².
//
// Sizes: h in the bulk, hc at the cone's two ends (the entry corner (R0, -Lc) and the throat
// (R1, 0)), where the velocity field is singular; graded from hc to h over the distance dc.
// The cell type is not set here (flowform asks gmsh for quadrilaterals with "Element Type"
// Quadrilateral).
//
// Every constant below is a Geo Parameter (Mesh/Geo Parameters in the case, or
// `gmsh -2 drawing.geo -setnumber alpha 12`), and a shape parameter for the sensitivities
// (`Geo Parameter:alpha`, docs/sensitivity.md): the mesh's topology does not change with them.

DefineConstant[
  alpha = {8, Min 1, Max 60, Step 1, Name "Parameters/alpha", Label "die semi-angle [degrees]"},
  R0 = {1, Min 1e-3, Max 1000, Step 0.1, Name "Parameters/R0", Label "entry radius of the wire"},
  R1 = {0.894427191, Min 1e-3, Max 1000, Step 0.05, Name "Parameters/R1",
        Label "exit radius = the die's throat radius (default: 20 % area reduction)"},
  Ld = {0.3, Min 0.01, Max 100, Step 0.05, Name "Parameters/Ld", Label "land length"},
  Lin = {0.75, Min 0.01, Max 100, Step 0.05, Name "Parameters/Lin", Label "wire length before the die"},
  h = {0.05, Min 1e-4, Max 10, Step 0.01, Name "Parameters/h", Label "mesh size in the bulk"}
];
DefineConstant[
  hc = {h / 3, Min 1e-5, Max 10, Step 0.005, Name "Parameters/hc", Label "mesh size at the cone's ends"},
  dc = {0.3, Min 0, Max 100, Step 0.05,
        Name "Parameters/dc", Label "distance over which the size grows from hc to h"}
];

If (R1 >= R0)
  Error("drawing.geo: the exit radius R1 = %g must be smaller than the entry radius R0 = %g", R1, R0);
EndIf
If (alpha <= 0 || alpha >= 90)
  Error("drawing.geo: alpha = %g degrees must lie in (0, 90)", alpha);
EndIf

Lc = (R0 - R1) / Tan(alpha * Pi / 180);
zIn = -Lc - Lin;

// Counter-clockwise in the (r, z) plane.
Point(1) = {0, zIn, 0, h};     // axis at the entry
Point(2) = {R0, zIn, 0, h};    // the entry's outer corner
Point(3) = {R0, -Lc, 0, hc};   // where the wire meets the cone
Point(4) = {R1, 0, 0, hc};     // the die throat
Point(5) = {R1, Ld, 0, h};     // the land's end
Point(6) = {0, Ld, 0, h};      // axis at the outlet

Line(1) = {1, 2};  // entry: z = zIn
Line(2) = {2, 3};  // wire_surface: r = R0 before the die
Line(3) = {3, 4};  // die_cone
Line(4) = {4, 5};  // die_land: r = R1
Line(5) = {5, 6};  // outlet: z = Ld
Line(6) = {6, 1};  // axis: r = 0
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};

Field[1] = Distance;
Field[1].PointsList = {3, 4};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = h;
Field[2].DistMin = 0;
Field[2].DistMax = dc;
Background Field = 2;

Physical Curve("entry") = {1};
Physical Curve("wire_surface") = {2};
Physical Curve("die_cone") = {3};
Physical Curve("die_land") = {4};
Physical Curve("outlet") = {5};
Physical Curve("axis") = {6};
Physical Surface("wire") = {1};
