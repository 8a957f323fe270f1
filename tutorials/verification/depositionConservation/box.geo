// Deposition conservation (Vaidheeswaran et al. 2020, section 2.2.2): the
// unit cube, n x n x n hexahedra, for gmsh -3 -format msh2. Every face is a patch of
// its own; createPatch pairs them into cyclics.
L = 1;
n = 32;

Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, L, 0};
Point(4) = {0, L, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1};
Recombine Surface{1};

out[] = Extrude {0, 0, L} { Surface{1}; Layers{n}; Recombine; };

Physical Surface("xmin") = {out[5]};
Physical Surface("xmax") = {out[3]};
Physical Surface("ymin") = {out[2]};
Physical Surface("ymax") = {out[4]};
Physical Surface("zmin") = {1};
Physical Surface("zmax") = {out[0]};
Physical Volume("box")   = {out[1]};
