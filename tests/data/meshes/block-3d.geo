// A 2 x 1 x 1 block of 4 x 2 x 2 linear hexahedra (transfinite, recombined) with physical groups: block (the
// volume), fixed (the face x = 0) and loaded (the face x = 2). Written binary, to read the binary format:
//   gmsh -3 -format msh41 -bin tests/data/meshes/block-3d.geo -o tests/data/meshes/block-3d.msh
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 5; Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Recombine Surface{1};
out[] = Extrude {0, 0, 1} { Surface{1}; Layers{2}; Recombine; };
Physical Volume("block") = {out[1]};
Physical Surface("fixed") = {out[5]};
Physical Surface("loaded") = {out[3]};
