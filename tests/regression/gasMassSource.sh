#!/bin/bash
# gasMassSource <runDir>: gas added inside the domain (libmppicModels'
# gasMassSources, MFiX's point sources) against the 1D solution.
#
# A channel of length L = 1 m along x, 200 cells, closed at x = 0 (wall),
# open at x = L (p = 0), no parcels, no gravity; one source spread over the
# whole channel adds S = Q/V = 1 /s of gas volume per unit volume with the
# velocity (u_s, 0, 0), u_s = 0 and 0.5 m/s, 5 steps of 1e-3 s; the same
# (u_s = 0.5 m/s) on 2 ranks, the channel cut at x = 0.5.
# checks: gasMassSource.py (the outflow, the face fluxes, the velocities and
# p against U = S x and p(x) - p(L) = S^2 (L^2 - x^2) - S u_s (L - x); the
# continuity error; the 2 ranks against serial).
# processes: 2
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
runDir="${1:?}"
mkdir -p "$runDir"

makeChannel()   # dir us
{
    local dir="$1" us="$2"
    copyTutorial verification/settlingColumn "$dir"
    rm -rf "$dir/0.orig" "$dir/column.geo" "$dir/system/changeDictionaryDict"
    mkdir -p "$dir/0"
    local header='FoamFile { version 2.0; format ascii; class'
    cat > "$dir/system/blockMeshDict" <<BLOCK
$header dictionary; object blockMeshDict; }
convertToMeters 1;
vertices ((0 0 0) (1 0 0) (1 0.01 0) (0 0.01 0)
          (0 0 0.01) (1 0 0.01) (1 0.01 0.01) (0 0.01 0.01));
blocks (hex (0 1 2 3 4 5 6 7) (200 1 1) simpleGrading (1 1 1));
boundary
(
    bottom { type wall; faces ((0 4 7 3)); }
    top { type patch; faces ((1 2 6 5)); }
    walls { type empty; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }
);
BLOCK
    cat > "$dir/0/U.air" <<FIELD
$header volVectorField; object U.air; }
dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField
{
    bottom { type noSlip; }
    top { type pressureInletOutletVelocity; phi phi.air; value uniform (0 0 0); }
    walls { type empty; }
}
FIELD
    cat > "$dir/0/p" <<FIELD
$header volScalarField; object p; }
dimensions [0 2 -2 0 0 0 0];
internalField uniform 0;
boundaryField
{
    bottom { type fixedFluxPressure; value uniform 0; }
    top { type fixedValue; value uniform 0; }
    walls { type empty; }
}
FIELD
    cat > "$dir/constant/gasMassSources" <<DICT
$header dictionary; object gasMassSources; }
sources
{
    channel
    {
        centre              (0.5 0.005 0.005);
        radius              1;
        volumetricFlowRate  1e-4;
        velocity            ($us 0 0);
    }
}
DICT
    echo "$header vectorField; object kinematicCloudPositions; } 0()" \
        > "$dir/constant/kinematicCloudPositions"
    setEntry "$dir" constant/g value "(0 0 0)"
    setEntry "$dir" system/controlDict endTime 0.005
    setEntry "$dir" system/controlDict deltaT 0.001
    setEntry "$dir" system/controlDict writeInterval 0.005
    setEntry "$dir" system/controlDict writePrecision 15
    foamDictionary "$dir/system/controlDict" -entry functions -set "{}" \
        > /dev/null
    tightGasSolvers "$dir"
    (cd "$dir" && runApplication blockMesh && runApplication mppicPimpleFoam)
    if grep -l -E 'FOAM FATAL|FOAM aborting' "$dir"/log.*
    then
        return 1
    fi
    (cd "$dir" && postProcess -func writeCellCentres -time 0.005 \
        > log.postProcess 2>&1)
}

status=0
for us in 0 0.5
do
    makeChannel "$runDir/us$us" $us || { status=1; continue; }
    /usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/gasMassSource.py" \
        channel "$runDir/us$us" "$us" || status=1
    errs=$(grep "continuity errors" "$runDir/us$us/log.mppicPimpleFoam" \
        | sed 's/.*sum local = \([^,]*\),.*/\1/' | sort -g | tail -1)
    /usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/gasMassSource.py" \
        continuity "$errs" "$us" || status=1
done

# The same source on 2 ranks against the serial run
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1
par="$runDir/us0.5-ranks2"
rm -rf "$par"
mkdir -p "$par"
cp -r "$runDir/us0.5/0" "$runDir/us0.5/constant" "$runDir/us0.5/system" "$par/"
setEntry "$par" system/decomposeParDict coeffs/n "(2 1 1)"
(
    cd "$par" &&
    decomposePar > log.decomposePar 2>&1 &&
    mpirun -np 2 mppicPimpleFoam -parallel > log.mppicPimpleFoam 2>&1 &&
    reconstructPar -latestTime > log.reconstructPar 2>&1 &&
    postProcess -func writeCellCentres -time 0.005 > log.postProcess 2>&1
) || { echo "gasMassSource: the 2-rank run failed ($par/log.*)"; exit 1; }
/usr/bin/python3 "$MPPIC_PROJECT_DIR/tests/regression/gasMassSource.py" \
    ranks "$runDir/us0.5/0.005" "$par/0.005" || status=1
exit $status
