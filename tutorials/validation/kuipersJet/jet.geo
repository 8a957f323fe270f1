// Kuipers (1990) central-jet bed, the MFiX-PIC KUIP_JET set-up (seed 1,
// section 6.1): 0.57 m wide (x), 1.00 m tall (y), 0.015 m deep (z),
// uniform hexahedra 0.75 cm x 1 cm x 0.75 cm (76 x 100 x 2); a jet
// nJet cells wide at the centre of the bottom face.
// gmsh -3 -format msh2 -o jet.msh jet.geo; gmshToFoam jet.msh
width  = 0.57;
height = 1.00;
depth  = 0.015;
nx     = 76;        // cells across (even: the jet sits on the centre line)
ny     = 100;       // cells up
nz     = 2;         // cells deep
nJet   = 2;         // jet width in cells (2 x 0.75 cm = 1.5 cm)

dx   = width/nx;
xJ0  = 0.5*width - 0.5*nJet*dx;    // jet edges
xJ1  = 0.5*width + 0.5*nJet*dx;
nSide = (nx - nJet)/2;

// Bottom and top rows of points: side | jet | side
xs[] = {0, xJ0, xJ1, width};
For i In {0:3}
    Point(1 + i) = {xs[i], 0,      0};
    Point(5 + i) = {xs[i], height, 0};
EndFor
For i In {0:2}
    Line(1 + i) = {1 + i, 2 + i};          // bottom segments
    Line(4 + i) = {5 + i, 6 + i};          // top segments
EndFor
For i In {0:3}
    Line(7 + i) = {1 + i, 5 + i};          // verticals
EndFor
cells[] = {nSide, nJet, nSide};
For i In {0:2}
    Curve Loop(1 + i) = {1 + i, 8 + i, -(4 + i), -(7 + i)};
    Plane Surface(1 + i) = {1 + i};
    Transfinite Curve{1 + i, 4 + i} = cells[i] + 1;
EndFor
Transfinite Curve{7:10} = ny + 1;
For i In {0:2}
    Transfinite Surface{1 + i};
    Recombine Surface{1 + i};
EndFor

// Extrusions in z: out[] lists, per surface, front face, volume, then the
// sides in the order of the curve loop (bottom, right, top, left)
For i In {0:2}
    e[] = Extrude {0, 0, depth} { Surface{1 + i}; Layers{nz}; Recombine; };
    front[i] = e[0]; vol[i] = e[1]; bot[i] = e[2]; right[i] = e[3];
    topS[i] = e[4]; left[i] = e[5];
EndFor

Physical Surface("inlet")        = {bot[0], bot[2]};
Physical Surface("jet")          = {bot[1]};
Physical Surface("outlet")       = {topS[0], topS[1], topS[2]};
Physical Surface("walls")        = {left[0], right[2]};
Physical Surface("frontAndBack") = {1, 2, 3, front[0], front[1], front[2]};
Physical Volume("bed")           = {vol[0], vol[1], vol[2]};
