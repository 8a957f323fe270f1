// Terminal velocity (Vaidheeswaran et al. 2020, section 2.1):
// 0.01 x 0.30 x 0.01 m, 5 x 60 x 5 hexahedra, for gmsh -3 -format msh2.
width  = 0.01;
height = 0.30;
depth  = 0.01;
nx = 5;
ny = 60;
nz = 5;

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

Physical Surface("inlet")  = {out[2]};
Physical Surface("outlet") = {out[4]};
Physical Surface("walls")  = {out[3], out[5], 1, out[0]};
Physical Volume("column")  = {out[1]};
