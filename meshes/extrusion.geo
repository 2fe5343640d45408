// Plane-strain extrusion through a flat (90°) die, docs/theory.md §6.2 (paper §4.1): the upper half of
// the section, cut by the symmetry line y = 0. One L-shaped surface:
//
//        y
//        1 +----------- container ----------+
//          |                                 | die_face
//      ram |            billet               +------- die_land -------+ exit
//          |                                                          | outlet
//        0 +------------------------- axis ---------------------------+
//        x = -Lc                        x = 0                       x = Le
//
// Container x ∈ [-Lc, 0], y ∈ [0, 1]; die face x = 0, y ∈ [exit, 1]; exit channel
// x ∈ [0, Le], y ∈ [0, exit]. Reduction R = 1/exit (container height over exit height).
//
// transpose = 1 places every point (x, y) at (y, x), for the axisymmetric variant
// (flowform: x = r, y = z): the symmetry line becomes the axis r = 0, the ram the bottom
// z = -Lc, the flow runs along +z. The physical names stay the same. The loop is reversed
// when transposed (a reflection), so the surface is counter-clockwise either way.
//
// Lengths and sizes are in container half-heights, times scale: scale = 50 with lengths in mm
// is a 100 mm billet (xml/hot_extrusion.xml); scale = 1 (the default) leaves every point as it was.
//
// Sizes: h in the bulk, hc at the two die corners (0, exit) and (0, 1), where the velocity
// field is singular; a Distance + Threshold field grades hc -> h over the distance dc.
// The cell type is not set here: flowform asks gmsh for quadrilaterals (Mesh.RecombineAll,
// Blossom) when "Element Type" is "Quadrilateral". Blossom can leave a few triangles on this
// unstructured mesh; quads = 1 makes every cell a quadrilateral by gmsh's subdivision
// (Mesh.SubdivisionAlgorithm = 1: each triangle becomes 3 quads, each quad 4, so the cells
// are about half the size asked). quads = 1 with "Element Type" Triangle is an error.
//
// From the case XML:  <ParameterList name="Geo Parameters">
//                       <Parameter name="h" type="double" value="0.05"/>
//                     </ParameterList>
// From flowform:      --set "Mesh/Geo Parameters/h=0.05"
// From the command line:  gmsh -2 extrusion.geo -setnumber h 0.05 -setnumber transpose 1

DefineConstant[
  exit = {0.5, Min 0.05, Max 0.95, Step 0.05,
          Name "Parameters/exit", Label "exit half-height (container half-height 1), R = 1/exit"},
  Lc = {1.5, Min 0.1, Max 20, Step 0.1, Name "Parameters/Lc", Label "container length"},
  Le = {1.5, Min 0.1, Max 20, Step 0.1, Name "Parameters/Le", Label "exit channel length"},
  h = {0.1, Min 1e-4, Max 1, Step 0.01, Name "Parameters/h", Label "mesh size in the bulk"},
  scale = {1, Min 1e-6, Max 1e6, Step 1, Name "Parameters/scale",
           Label "the container half-height in the case's length unit (1: nondimensional; 50 for a 100 mm billet in mm)"}
];
DefineConstant[
  hc = {h / 4, Min 1e-5, Max 1, Step 0.005,
        Name "Parameters/hc", Label "mesh size at the die corners"},
  dc = {0.5, Min 0, Max 10, Step 0.05,
        Name "Parameters/dc", Label "distance over which the size grows from hc to h"},
  transpose = {0, Choices {0, 1}, Name "Parameters/transpose",
               Label "1: place (x, y) at (y, x) (axisymmetric, x = r)"},
  quads = {0, Choices {0, 1}, Name "Parameters/quads",
           Label "1: all-quadrilateral mesh by subdivision"}
];

If (exit <= 0 || exit >= 1)
  Error("extrusion.geo: exit = %g must lie in (0, 1)", exit);
EndIf
If (transpose != 0 && transpose != 1)
  Error("extrusion.geo: transpose = %g must be 0 or 1", transpose);
EndIf

// Point (x, y) of the untransposed section, placed at (y, x) when transpose = 1.
xs[] = {-Lc, Le, Le,   0,    0, -Lc};
ys[] = {  0,  0, exit, exit, 1,   1};
// Bulk size at the outer corners, hc at the die corners (points 4 and 5).
ls[] = {  h,  h, h,    hc,   hc,  h};
For i In {0 : 5}
  If (transpose == 1)
    Point(i + 1) = {scale * ys[i], scale * xs[i], 0, scale * ls[i]};
  Else
    Point(i + 1) = {scale * xs[i], scale * ys[i], 0, scale * ls[i]};
  EndIf
EndFor

Line(1) = {1, 2};  // axis: symmetry line y = 0, x ∈ [-Lc, Le]
Line(2) = {2, 3};  // outlet: x = Le, y ∈ [0, exit]
Line(3) = {3, 4};  // die_land: y = exit, x from Le to 0
Line(4) = {4, 5};  // die_face: x = 0, y from exit to 1
Line(5) = {5, 6};  // container: y = 1, x from 0 to -Lc
Line(6) = {6, 1};  // ram: x = -Lc, y from 1 to 0

// Counter-clockwise in the plotted plane (the transposed loop runs the other way round).
If (transpose == 1)
  Curve Loop(1) = {-6, -5, -4, -3, -2, -1};
Else
  Curve Loop(1) = {1, 2, 3, 4, 5, 6};
EndIf
Plane Surface(1) = {1};

// Grade the size from hc at the die corners to h at distance dc from them.
Field[1] = Distance;
Field[1].PointsList = {4, 5};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = scale * hc;
Field[2].SizeMax = scale * h;
Field[2].DistMin = 0;
Field[2].DistMax = scale * dc;
Background Field = 2;

If (quads == 1)
  Mesh.SubdivisionAlgorithm = 1;
EndIf

Physical Curve("axis") = {1};
Physical Curve("outlet") = {2};
Physical Curve("die_land") = {3};
Physical Curve("die_face") = {4};
Physical Curve("container") = {5};
Physical Curve("ram") = {6};
Physical Surface("billet") = {1};
