// Binary bubbling bed: a pseudo-2D box of hexahedra (gmsh, structured).
// Every dimension a named parameter; cellSize the one mesh parameter.
//     gmsh -3 -format msh2 -o bed.msh bed.geo
width    = 0.15;    // x [m]
height   = 0.45;    // y [m]
depth    = 0.015;   // z [m]
cellSize = 0.005;   // edge of the cubic cells [m]

nx = Round(width/cellSize);
ny = Round(height/cellSize);
nz = Round(depth/cellSize);

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

e[] = Extrude {0, 0, depth} { Surface{1}; Layers{nz}; Recombine; };
// e[0] front, e[1] volume, e[2..5] the sides from lines 1..4

Physical Surface("inlet")        = {e[2]};
Physical Surface("outlet")       = {e[4]};
Physical Surface("walls")        = {e[3], e[5]};
Physical Surface("frontAndBack") = {1, e[0]};
Physical Volume("bed")           = {e[1]};
