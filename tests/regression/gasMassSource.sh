#!/bin/bash
# gasMassSource <runDir>: gas added inside the domain (libmppicModels'
# gasMassSources, MFiX's point sources) against the 1D solution.
#
# A channel of length L = 1 m along x, 200 cells, closed at x = 0 (wall),
# open at x = L (p = 0), no parcels, no gravity; one source spread over the
# whole channel adds S = Q/V = 1 /s of gas volume per unit volume with the
# velocity (u_s, 0, 0). Continuity gives U(x) = S x, whatever the time, so
# the steady momentum balance U dU/dx = S (u_s - U) - dp/dx holds from the
# first step and
#     p(x) - p(L) = S^2 (L^2 - x^2) - S u_s (L - x)        (kinematic p)
# Checks, for u_s = 0 and u_s = 0.5 m/s after 5 steps of 1e-3 s:
#   - the outlet's gas flux equals Q to 1e-8 (the continuity's source);
#   - the face fluxes equal S x A to 1e-8 relative (A the section, 1e-4 m2),
#     the cell velocities S x within 0.5 % of the outflow's S L;
#   - p at the first cell (x = 0.0025 m) within 1 % of the formula
#     (0.99999 and 0.49874 m2/s2): a missing momentum source
#     (the gas arriving with the cell's velocity) would give 0.5 x and
#     1.0 x of these, a double-counted one 1.5 x.
# The continuity error printed by the solver, with the source taken off,
# stays below 1e-10.
# On 2 ranks (u_s = 0.5 m/s, the channel cut at x = 0.5, the sphere spread
# over both), p and the face fluxes equal the serial run's to 1e-9 relative:
# the source's cell volume is summed over the ranks.
# processes: 2
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
runDir="${1:?}"
mkdir -p "$runDir"

makeChannel()   # dir us
{
    local dir="$1" us="$2"
    copyTutorial settlingColumn "$dir"
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
    /usr/bin/python3 - "$runDir/us$us" "$us" <<'PY' || status=1
import re, sys
from checks import report, status
case, us = sys.argv[1], float(sys.argv[2])
t = case + "/0.005/"

def internal(name, vector=False):
    text = open(t + name).read()
    body = text.split("internalField", 1)[1]
    body = body[body.index("(", body.index("\n")) + 1:]
    if vector:
        return [tuple(map(float, v.split()))
                for v in re.findall(r"\(([^()]*)\)", body.split("\n)\n")[0])]
    return [float(v) for v in body.split(")")[0].split()]

x = [c[0] for c in internal("C", vector=True)]
U = [u[0] for u in internal("U.air", vector=True)]
p = internal("p")
S, L, Q = 1.0, 1.0, 1e-4

phi = open(t + "phi.air").read()
top = phi.split("top", 1)[1]
m = re.search(r"value\s+uniform\s+([-0-9.eE+]+)", top) or \
    re.search(r"value\s+nonuniform\s+List<scalar>\s+1\(([-0-9.eE+]+)\)", top)
outflow = float(m.group(1))
report(abs(outflow - Q) <= 1e-8*Q,
       "outlet flux %.12g m3/s, Q %g (1e-8)" % (outflow, Q))

A, n = 1e-4, len(x)
faceFlux = internal("phi.air")
worst = max(abs(f - S*(i + 1)/n*L*A)/(S*(i + 1)/n*L*A)
            for i, f in enumerate(faceFlux))
report(len(faceFlux) == n - 1 and worst <= 1e-8,
       "%d face fluxes, largest |phi - S x A|/(S x A) %.3g (1e-8)"
       % (len(faceFlux), worst))
worst = max(abs(u - S*xi) for u, xi in zip(U, x))/(S*L)
report(worst <= 0.005,
       "largest |U - S x|/(S L) at the cells: %.3g (0.5 %%)" % worst)

x1 = x[0]
exact = S**2*(L**2 - x1**2) - S*us*(L - x1)
report(abs(p[0] - exact) <= 0.01*exact,
       "p at x = %.4f m: %.6g m2/s2, formula %.6g (1 %%)" % (x1, p[0], exact))
sys.exit(status())
PY
    errs=$(grep "continuity errors" "$runDir/us$us/log.mppicPimpleFoam" \
        | sed 's/.*sum local = \([^,]*\),.*/\1/' | sort -g | tail -1)
    /usr/bin/python3 -c "
from checks import report, status
import sys
report($errs <= 1e-10,
       'largest continuity error (sum local), u_s $us: $errs (1e-10)')
sys.exit(status())" || status=1
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
/usr/bin/python3 - "$runDir/us0.5/0.005" "$par/0.005" <<'PY' || status=1
import re, sys
from checks import report, status
def internal(t, name):
    text = open(t + "/" + name).read()
    body = text.split("internalField", 1)[1]
    body = body[body.index("(", body.index("\n")) + 1:]
    return [float(v) for v in body.split(")")[0].split()]
for name in ("p", "phi.air"):
    serial, ranks2 = internal(sys.argv[1], name), internal(sys.argv[2], name)
    scale = max(abs(v) for v in serial)
    worst = max(abs(a - b) for a, b in zip(serial, ranks2))/scale
    report(len(serial) == len(ranks2) and worst <= 1e-9,
           "%s on 2 ranks against serial: largest difference %.3g of the "
           "largest value (1e-9)" % (name, worst))
sys.exit(status())
PY
exit $status
