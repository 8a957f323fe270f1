// Wet-bulb evaporation (seed 2, section 2.4): one 0.01 m cube, one
// hexahedron, for gmsh -3 -format msh2. Air flows in x.
side = 0.01;

Point(1) = {0,    0,    0};
Point(2) = {side, 0,    0};
Point(3) = {side, side, 0};
Point(4) = {0,    side, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};

out[] = Extrude {0, 0, side} { Surface{1}; Layers{1}; Recombine; };

// out[2..5]: the sides from lines 1..4 (y = 0, x = side, y = side, x = 0)
Physical Surface("inlet")  = {out[5]};
Physical Surface("outlet") = {out[3]};
Physical Surface("walls")  = {out[2], out[4], 1, out[0]};
Physical Volume("cube")    = {out[1]};
