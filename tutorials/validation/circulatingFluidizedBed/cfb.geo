// NETL small-scale circulating fluidized bed, full loop (Xu et al. 2017;
// seed 2, section 3.3). Dimensions of record: shared/reference/cfb_geometry.md
// (measured from MFiX's MINI-CFB STL); departures are marked "departs".
// Coordinates in m, y up; every part is a circular pipe or cone.
//
//     gmsh -3 -format msh2 [-setnumber cellSize 0.010] -o cfb.msh cfb.geo
//     gmshToFoam cfb.msh
//
// Fluid volumes (OpenCASCADE solids) fused with BooleanUnion; the two
// aeration ports are flush patches on the pipe walls, cut out of the wall
// by BooleanFragments with a short cylinder. Tetrahedra of one size.
SetFactory("OpenCASCADE");

// ---- mesh: the one size parameter (tetrahedron edge length) ----------------
// 0.010 (default): one parcel of 4 particles of 0.87 mm (seed 2's
// statistical weight) is at most 5 % of a cell, see README.md.
DefineConstant[ cellSize = {0.010, Name "Parameters/cellSize"} ];

// ---- equal-area pipes (departs, optional) ----------------------------------
// A pipe a few cells across is meshed as a polygon inscribed in its circle,
// with less cross-section: the 1" pipes (a 1" circle in 6 edges of 14 mm)
// have 17 % less area on the coarse mesh, 8 % on the fine one, the 2"
// riser 4 % and 2 %; the gas in them runs faster (20 % in the coarse 1" pipes; README,
// "Equal-area pipes"). Allrun -equalArea scales the diameters so that the
// meshed cross-sections have the pipes' areas (to 0.5 %, test
// cfbEqualArea): 1" by diameterScale1in, the 2" riser by diameterScale2in.
DefineConstant[ diameterScale1in = {1, Name "Parameters/diameterScale1in"} ];
DefineConstant[ diameterScale2in = {1, Name "Parameters/diameterScale2in"} ];

// ---- riser ----------------------------------------------------------------
riserD    = 0.0508*diameterScale2in;    // inner diameter (2")
riserX    = 0.282;      // axis x
axisZ     = 0.075;      // z of every axis (the loop lies in the plane z = axisZ)
riserTop  = 1.2686;     // closed top (riser from y = 0)

// ---- cyclone --------------------------------------------------------------
// departs: the record gives the cyclone axis at x = 0.0725 and the
// standpipe axis at x = 0.0729; one axis here (0.0727), so that the cone
// and the standpipe meet on a common circle.
cycX      = 0.0727;     // axis x of cyclone and standpipe
barrelD   = 0.127;      // barrel diameter (5")
barrelY0  = 1.073;      // barrel bottom (top of the cone)
roofY     = 1.2749;     // roof
coneY0    = 0.932;      // cone bottom = standpipe top

// ---- crossover (riser -> cyclone), tangential entry ------------------------
crossD    = 0.0254*diameterScale1in;     // 1"
crossY    = 1.218;      // axis height
// distance of the crossover axis from the cyclone axis: the record's STL
// has ~0.052, where the pipe would stand 1.2 mm outside the barrel wall
// (a sliver no cell of this size resolves); departs: 0.048, the pipe's
// outer wall 2.8 mm inside the barrel wall.
crossOffset = 0.048;

// ---- vortex finder and gas outlet -------------------------------------------
vfD       = 0.0254*diameterScale1in;     // exit tube bore (1")
sleeveD   = 0.0476;     // outer diameter of the vortex-finder sleeve
vfY0      = 1.1225;     // open bottom of the vortex finder (inside the cyclone)
outletY   = 1.32;       // gas outlet (top of the exit tube)

// ---- standpipe and L-valve ----------------------------------------------------
standD    = 0.0254*diameterScale1in;     // 1"
standY0   = 0.146;      // bottom of the straight standpipe (start of the bend)
legY      = 0.0176;     // axis height of the horizontal leg
legD      = 0.0254*diameterScale1in;     // 1"
bendR     = standY0 - legY;   // bend centre-line radius (0.1284)
bendX     = cycX + bendR;     // arc centre x (0.2011)

// ---- aeration ports: flush circular patches on the pipe wall -----------------
portD     = 0.0127;     // port diameter (1/2")
// aerationBend (FTC135, L-valve aeration): on the outer wall of the bend,
// portBendAngle from the start of the bend (0 = standpipe end, 90 = leg)
portBendAngle = 45;
// aerationStandpipe (FTC115, standpipe aeration): on the standpipe wall
// facing away from the riser (-x), at height portStandY
portStandY = 0.30;

// =============================================================================
// Volumes
riser   = newv; Cylinder(riser) = {riserX, 0, axisZ, 0, riserTop, 0, riserD/2};

barrel  = newv; Cylinder(barrel) = {cycX, barrelY0, axisZ, 0, roofY - barrelY0, 0, barrelD/2};
cone    = newv; Cone(cone) = {cycX, coneY0, axisZ, 0, barrelY0 - coneY0, 0, standD/2, barrelD/2};
sleeve  = newv; Cylinder(sleeve) = {cycX, vfY0, axisZ, 0, roofY - vfY0, 0, sleeveD/2};
cyclone() = BooleanDifference{ Volume{barrel}; Delete; }{ Volume{sleeve}; Delete; };
exitTube = newv; Cylinder(exitTube) = {cycX, vfY0, axisZ, 0, outletY - vfY0, 0, vfD/2};

// crossover: from the riser axis towards -x, tilted in the x-z plane so
// that its axis passes crossOffset from the cyclone axis; it ends at the
// point of closest approach, inside the barrel
span    = riserX - cycX;
theta   = Asin(crossOffset/span);
crossL  = span*Cos(theta);
cross   = newv; Cylinder(cross) = {riserX, crossY, axisZ, -crossL*Cos(theta), 0, crossL*Sin(theta), crossD/2};

standpipe = newv; Cylinder(standpipe) = {cycX, standY0, axisZ, 0, coneY0 - standY0, 0, standD/2};

// bend: a horizontal disk at the standpipe bottom swept a quarter turn
// about the z axis through the arc centre, down to the leg
bendDisk = news; Disk(bendDisk) = {cycX, standY0, axisZ, standD/2};
Rotate { {1, 0, 0}, {cycX, standY0, axisZ}, Pi/2 } { Surface{bendDisk}; }
bendOut[] = Extrude { {0, 0, 1}, {bendX, standY0, axisZ}, Pi/2 } { Surface{bendDisk}; };
bend = bendOut[1];

// horizontal leg: from the end of the bend into the riser, up to its axis
leg = newv; Cylinder(leg) = {bendX, legY, axisZ, riserX - bendX, 0, 0, legD/2};

fluid() = BooleanUnion{ Volume{riser}; Delete; }
    { Volume{cyclone(), cone, exitTube, cross, standpipe, bend, leg}; Delete; };

// Aeration ports: flush circular patches imprinted on the pipe wall. A
// short cylinder of diameter portD across the wall cuts the port patch out
// of the wall face (BooleanIntersection of the face with the cylinder);
// BooleanFragments then imprints the patch on the fluid's boundary, which
// splits the wall face into the port and the rest. No volume is added or
// split, so no small cells are made at the port.
portDepth = standD/4;
eps       = 1e-6;

// The wall face through a point: the one boundary surface of the fluid
// whose bounding box holds the point (to 0.1 mm)
Macro WallFaceAt
    faces() = Abs(Boundary{ Volume{fluid()}; });
    found = -1;
    nFound = 0;
    tol = 1e-4;
    For k In {0:#faces()-1}
        bb() = BoundingBox Surface{faces(k)};
        If (bb(0) <= at(0) + tol && bb(3) >= at(0) - tol && bb(1) <= at(1) + tol && bb(4) >= at(1) - tol &&
            bb(2) <= at(2) + tol && bb(5) >= at(2) - tol)
            found = faces(k);
            nFound += 1;
        EndIf
    EndFor
    If (nFound != 1)
        found = -1;
    EndIf
Return

// standpipe port: outward normal -x
pS[] = {cycX - standD/2, portStandY, axisZ};
portS = newv; Cylinder(portS) = {pS[0] - portDepth, pS[1], pS[2], 2*portDepth, 0, 0, portD/2};
at() = pS[];
Call WallFaceAt;
wallS = found;
patchS() = BooleanIntersection{ Surface{wallS}; }{ Volume{portS}; Delete; };

// bend port: on the outer wall at angle a from the standpipe end; the
// outward normal there is (-cos a, -sin a, 0)
a    = portBendAngle*Pi/180;
nB[] = {-Cos(a), -Sin(a), 0};
pB[] = {bendX + (bendR + standD/2)*nB[0], standY0 + (bendR + standD/2)*nB[1], axisZ};
portB = newv; Cylinder(portB) = {pB[0] + portDepth*nB[0], pB[1] + portDepth*nB[1], pB[2],
                                 -2*portDepth*nB[0], -2*portDepth*nB[1], 0, portD/2};
at() = pB[];
Call WallFaceAt;
wallB = found;
patchB() = BooleanIntersection{ Surface{wallB}; }{ Volume{portB}; Delete; };

If (wallS < 0 || wallB < 0 || #patchS() != 1 || #patchB() != 1)
    Error("cfb.geo: aeration port faces not found (wall faces %g %g, patches %g %g)",
          wallS, wallB, #patchS(), #patchB());
EndIf

BooleanFragments{ Volume{fluid()}; Delete; }{ Surface{patchS(), patchB()}; Delete; }
pieces() = Volume{:};

// =============================================================================
// Patches: the outer boundary of the fluid, sorted by bounding boxes
boundary() = Abs(CombinedBoundary{ Volume{pieces()}; });

// surfaces of boundary() that lie in a box: inBox() = boundary() /\ box
Macro SurfacesInBox
    notIn() = boundary();
    notIn() -= Surface In BoundingBox{box[0], box[1], box[2], box[3], box[4], box[5]};
    inBox() = boundary();
    inBox() -= notIn();
Return

r = riserD/2 + 1e-4;
box[] = {riserX - r, -eps, axisZ - r, riserX + r, eps, axisZ + r};
Call SurfacesInBox;
riserInlet() = inBox();

r = vfD/2 + 1e-4;
box[] = {cycX - r, outletY - eps, axisZ - r, cycX + r, outletY + eps, axisZ + r};
Call SurfacesInBox;
outlet() = inBox();

r = portD/2 + 0.002;
box[] = {pS[0] - r, pS[1] - r, pS[2] - r, pS[0] + r, pS[1] + r, pS[2] + r};
Call SurfacesInBox;
aerationStandpipe() = inBox();

box[] = {pB[0] - r, pB[1] - r, pB[2] - r, pB[0] + r, pB[1] + r, pB[2] + r};
Call SurfacesInBox;
aerationBend() = inBox();

walls() = boundary();
walls() -= riserInlet();
walls() -= outlet();
walls() -= aerationStandpipe();
walls() -= aerationBend();

If (#riserInlet() != 1 || #outlet() != 1 || #aerationStandpipe() != 1 || #aerationBend() != 1)
    Error("cfb.geo: patch search found %g riserInlet, %g outlet, %g aerationStandpipe, %g aerationBend surfaces (1 each expected)",
          #riserInlet(), #outlet(), #aerationStandpipe(), #aerationBend());
EndIf

Physical Surface("riserInlet")        = {riserInlet()};
Physical Surface("outlet")            = {outlet()};
Physical Surface("aerationStandpipe") = {aerationStandpipe()};
Physical Surface("aerationBend")      = {aerationBend()};
Physical Surface("walls")             = {walls()};
Physical Volume("fluid")              = {pieces()};

// =============================================================================
// Mesh: tetrahedra of edge cellSize everywhere (no growth: the parcels'
// share of a cell's volume is set by the smallest cells). HXT with the
// optimizer working on every tetrahedron of quality below 0.5 leaves the
// fewest flat (sliver) cells: at cellSize 0.016 the smallest eigenvalue of
// a cell's sum n_f S_f is at least 0.02 of its largest (Delaunay with the
// default threshold 0.3: 0.009), non-orthogonality at most 65 degrees
// (73). HXT is not deterministic, even on one thread: two runs differ by a
// few cells in 10 000 (Delaunay is, but leaves cells 20 times flatter and
// non-orthogonality near 70 degrees at cellSize 0.014).
Mesh.CharacteristicLengthMin = 0.5*cellSize;
Mesh.CharacteristicLengthMax = cellSize;
Mesh.CharacteristicLengthFromCurvature = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
MeshSize{ PointsOf{ Volume{pieces()}; } } = cellSize;
Mesh.Algorithm3D = 10;          // HXT
Mesh.Optimize = 1;
Mesh.OptimizeThreshold = 0.5;
