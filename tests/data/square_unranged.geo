// A unit square whose mesh size h has no declared range: h = 0 reaches gmsh.
DefineConstant[ h = {0.25, Name "Parameters/h"}, N = {2, Name "Parameters/N"} ];
Point(1) = {0, 0, 0, h}; Point(2) = {1, 0, 0, h}; Point(3) = {1, 1, 0, h}; Point(4) = {0, 1, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("flow") = {1}; Physical Curve("wall") = {1, 2, 3, 4};
