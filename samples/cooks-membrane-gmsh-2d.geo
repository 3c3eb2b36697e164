// Cook's membrane for Gmsh: the tapered panel with corners (0, 0), (48, 44), (48, 60), (0, 44) [mm], N x N linear
// quadrangles by transfinite interpolation (on straight edges the bilinear map, as scripts/make-cooks-membrane.py
// writes the .inp deck), and the physical groups the project names: panel (the elements), left (the clamped edge
// x = 0) and right (the loaded edge x = 48).
//   gmsh -2 -format msh41 samples/cooks-membrane-gmsh-2d.geo -o samples/cooks-membrane-gmsh-2d.msh
N = 16;
Point(1) = {0, 0, 0}; Point(2) = {48, 44, 0}; Point(3) = {48, 60, 0}; Point(4) = {0, 44, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = N + 1;
Transfinite Surface{1} = {1, 2, 3, 4};
Recombine Surface{1};
Physical Surface("panel") = {1};
Physical Curve("left") = {4};
Physical Curve("right") = {2};
