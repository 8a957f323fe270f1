// Settling column: 0.04 m wide (x), 0.40 m tall (y), 0.01 m deep (z),
// 5 mm hexahedra (8 x 80 x 2), for gmsh -3 -format msh2 and gmshToFoam.
width  = 0.04;
height = 0.40;
depth  = 0.01;
nx = 8;
ny = 80;
nz = 2;

Point(1) = {0,     0,      0};
Point(2) = {width, 0,      0};
Point(3) = {width, height, 0};
Point(4) = {0,     height, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};

out[] = Extrude {0, 0, depth} { Surface{1}; Layers{nz}; Recombine; };
// out[0]: back face at z = depth, out[1]: volume,
// out[2..5]: faces extruded from lines 1..4 (bottom, right, top, left)

Physical Surface("bottom") = {out[2]};
Physical Surface("top")    = {out[4]};
Physical Surface("walls")  = {out[3], out[5], 1, out[0]};
Physical Volume("column")  = {out[1]};
