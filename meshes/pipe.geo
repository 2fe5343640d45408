// Pipe section for the axisymmetric verification (docs/verification.md): x = r ∈ [0,1],
// y = z ∈ [0,4]. Structured: N cells across the radius, 4N along the axis (square cells).
DefineConstant[ N = {4, Min 1, Max 1024, Step 1,
                     Name "Parameters/N", Label "cells across the radius (an integer)"} ];

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 4, 0};
Point(4) = {0, 4, 0};

Line(1) = {1, 2};  // inlet, z = 0
Line(2) = {2, 3};  // wall, r = 1
Line(3) = {3, 4};  // outlet, z = 4
Line(4) = {4, 1};  // axis, r = 0

Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

Transfinite Curve{1, 3} = N + 1;
Transfinite Curve{2, 4} = 4 * N + 1;
Transfinite Surface{1} = {1, 2, 3, 4} Alternate;

Physical Curve("inlet") = {1};
Physical Curve("wall") = {2};
Physical Curve("outlet") = {3};
Physical Curve("axis") = {4};
Physical Surface("pipe") = {1};
