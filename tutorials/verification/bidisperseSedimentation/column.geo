// Settling-shock column (Vaidheeswaran et al. 2020, section 2.3):
// 0.02 m (x) x 1.00 m (y) x 0.02 m (z), 5 x 100 x 5 hexahedra, for
// gmsh -3 -format msh2 and gmshToFoam; x and z become cyclic (createPatch).
width  = 0.02;
height = 1.00;
depth  = 0.02;
nx = 5;
ny = 100;
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
// out[0]: back face (z = depth), out[1]: volume,
// out[2..5]: bottom, right (x = width), top, left (x = 0)

Physical Surface("bottom") = {out[2]};
Physical Surface("top")    = {out[4]};
Physical Surface("left")   = {out[5]};
Physical Surface("right")  = {out[3]};
Physical Surface("front")  = {1};
Physical Surface("back")   = {out[0]};
Physical Volume("column")  = {out[1]};
