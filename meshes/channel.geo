// Channel [0,4] x [-1,1] of docs/theory.md §6.1 (verification against the exact fully developed
// profile). Structured: N cells across the height 2 and 2N along the length 4, so the cells
// are squares of side 2/N (or those squares cut by one diagonal, alternating direction).
//
// The cell type is not set here: flowform's reader asks gmsh for quadrilaterals with
// Mesh.RecombineAll = 1 when "Element Type" is "Quadrilateral", which recombines each
// structured square exactly. Refine with "Uniform Refinements" or with N; "Size Factor" has
// no effect on a transfinite mesh.
//
// From the case XML:  <ParameterList name="Geo Parameters">
//                       <Parameter name="N" type="double" value="8"/>
//                     </ParameterList>
// From the command line:  gmsh -2 channel.geo -setnumber N 8 [-setnumber Mesh.RecombineAll 1]

DefineConstant[ N = {4, Min 1, Max 1024, Step 1,
                     Name "Parameters/N", Label "cells across the height (an integer)"} ];

Point(1) = {0, -1, 0};
Point(2) = {4, -1, 0};
Point(3) = {4, 1, 0};
Point(4) = {0, 1, 0};

Line(1) = {1, 2};  // bottom wall, y = -1
Line(2) = {2, 3};  // outlet, x = 4
Line(3) = {3, 4};  // top wall, y = 1
Line(4) = {4, 1};  // inlet, x = 0

// Counter-clockwise loop, so gmsh's cells come out counter-clockwise too.
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = 2 * N + 1;  // points, i.e. 2N segments
Transfinite Curve{2, 4} = N + 1;
// "Alternate": the diagonals alternate direction, so the triangle mesh has no preferred
// diagonal (it is symmetric about y = 0 for even N).
Transfinite Surface{1} = {1, 2, 3, 4} Alternate;

Physical Curve("inlet") = {4};
Physical Curve("outlet") = {2};
Physical Curve("bottom") = {1};
Physical Curve("top") = {3};
Physical Surface("channel") = {1};
