// Sedimentation column: 0.05 m wide (x), 0.20 m tall (y), 0.005 m deep (z),
// 5 mm hexahedra (10 x 40 x 1), for gmsh -3 -format msh2 and gmshToFoam.
width  = 0.05;
height = 0.20;
depth  = 0.005;
nx = 10;
ny = 40;
nz = 1;

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
// out[0]: back face, out[1]: volume, out[2..5]: bottom, right, top, left

Physical Surface("bottom") = {out[2]};
Physical Surface("top")    = {out[4]};
Physical Surface("walls")  = {out[3], out[5], 1, out[0]};
Physical Volume("column")  = {out[1]};
