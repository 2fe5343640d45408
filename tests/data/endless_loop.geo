// A .geo whose loop does not end in any reasonable time: Mesh/Time Limit stops gmsh.
For k In {1:1e15}
  x = k;
EndFor
