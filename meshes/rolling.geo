// Steady flat rolling in plane strain, docs/rolling.md: the upper half of the strip, cut by the
// symmetry line y = 0, under one roll of radius R whose centre (0, h1/2 + R) stands above the gap.
//
//          y                    roll centre (0, h1/2 + R)
//                                      .
//   h0/2 +--- entry_surface ---+  roll  .
//        |                      `-.__   .
//  inlet |        strip              `--+---- exit_surface ----+ h1/2
//        |                                                     | outlet
//      0 +------------------------- axis ----------------------+
//     x = xe − Lin                 x = xe      x = 0        x = Lout
//
// h0 and h1 are the thicknesses of the whole strip (entry and exit = roll gap); the model holds
// half of it. The arc `roll` runs from the geometric entry point (xe, h0/2) at the bite angle α,
//   cos α = 1 − (h0 − h1)/(2R),   xe = −R sin α,
// to the exit point (0, h1/2), the roll's lowest point. The strip lengths Lin (before the entry
// point) and Lout (after the exit plane) are absolute lengths. Where the strip touches the roll is
// decided by the solver's contact statuses on this arc.
//
// Sizes: h in the bulk, hc on the arc, graded from hc to h over the distance dc from it; the
// entry and exit points of the arc get hc too.
// The cell type is not set here (flowform asks gmsh for quadrilaterals with "Element Type"
// Quadrilateral); quads = 1 makes every cell a quadrilateral by subdivision (meshes/extrusion.geo).
//
// From the case XML:  <ParameterList name="Geo Parameters"> <Parameter name="R" type="double" value="10"/> ...
// From flowform:      --set "Mesh/Geo Parameters/R=20"
// From the command line:  gmsh -2 rolling.geo -setnumber R 20 -setnumber h1 0.8

DefineConstant[
  R = {10, Min 0.5, Max 1000, Step 1, Name "Parameters/R", Label "roll radius"},
  h0 = {1, Min 1e-3, Max 100, Step 0.1, Name "Parameters/h0", Label "entry thickness of the whole strip"},
  h1 = {0.75, Min 1e-3, Max 100, Step 0.05, Name "Parameters/h1", Label "roll gap = exit thickness of the whole strip"},
  Lin = {1.5, Min 0.01, Max 100, Step 0.1, Name "Parameters/Lin", Label "strip length before the entry point"},
  Lout = {1.5, Min 0.01, Max 100, Step 0.1, Name "Parameters/Lout", Label "strip length after the exit plane"},
  h = {0.05, Min 1e-4, Max 10, Step 0.01, Name "Parameters/h", Label "mesh size in the bulk"}
];
DefineConstant[
  hc = {h / 2.5, Min 1e-5, Max 10, Step 0.005, Name "Parameters/hc", Label "mesh size on the arc"},
  dc = {0.25, Min 0, Max 100, Step 0.05,
        Name "Parameters/dc", Label "distance over which the size grows from hc to h"},
  quads = {0, Choices {0, 1}, Name "Parameters/quads", Label "1: all-quadrilateral mesh by subdivision"}
];

If (h1 >= h0)
  Error("rolling.geo: the roll gap h1 = %g must be smaller than the entry thickness h0 = %g", h1, h0);
EndIf
If ((h0 - h1) / 2 >= R)
  Error("rolling.geo: the reduction per roll (h0 - h1)/2 = %g must be smaller than the roll radius R = %g",
        (h0 - h1) / 2, R);
EndIf

cy = h1 / 2 + R;                                 // roll centre (0, cy)
xe = -Sqrt(R * R - (R - (h0 - h1) / 2) ^ 2);     // entry point (xe, h0/2): −R sin α
xin = xe - Lin;

Point(1) = {xin, 0, 0, h};
Point(2) = {Lout, 0, 0, h};
Point(3) = {Lout, h1 / 2, 0, h};
Point(4) = {0, h1 / 2, 0, hc};       // exit point: the roll's lowest point
Point(5) = {xe, h0 / 2, 0, hc};      // entry point at the bite angle
Point(6) = {xin, h0 / 2, 0, h};
Point(7) = {0, cy, 0, h};            // roll centre (not meshed)

Line(1) = {1, 2};        // axis: y = 0
Line(2) = {2, 3};        // outlet: x = Lout
Line(3) = {3, 4};        // exit_surface: y = h1/2, x from Lout to 0
Circle(4) = {4, 7, 5};   // roll: the arc from the exit point to the entry point
Line(5) = {5, 6};        // entry_surface: y = h0/2, x from xe to xin
Line(6) = {6, 1};        // inlet: x = xin

Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};

// Grade the size from hc on the arc to h at distance dc from it.
Field[1] = Distance;
Field[1].CurvesList = {4};
Field[1].NumPointsPerCurve = 200;
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hc;
Field[2].SizeMax = h;
Field[2].DistMin = 0;
Field[2].DistMax = dc;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;

If (quads == 1)
  Mesh.SubdivisionAlgorithm = 1;
EndIf

Physical Curve("axis") = {1};
Physical Curve("outlet") = {2};
Physical Curve("exit_surface") = {3};
Physical Curve("roll") = {4};
Physical Curve("entry_surface") = {5};
Physical Curve("inlet") = {6};
Physical Surface("strip") = {1};
