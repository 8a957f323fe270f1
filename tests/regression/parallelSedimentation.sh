#!/bin/bash
#------------------------------------------------------------------------------
# parallelSedimentation <runDir>
# processes: 4 (MPI ranks at most; tests/Alltest runs it alone)
# tutorials/verification/sedimentation with coloringFunction decomposed with
# simple into 2 halves side by side (2 1 1), so that the processor boundary
# runs vertically through the settled bed (1 s, the full case), and into 4
# quarters (2 2 1), a second boundary across the column at mid-height (0.5 s:
# the bed has formed; 4 processes on the 2 cores: oversubscribed, for
# correctness only).
# The serial run keeps every cell at 0.6 = close pack (tests/regression/
# sedimentation.sh); before the parcel records were exchanged between
# processors the 2-way split reached 2.36 (issue 20). Checks of each:
#   - the largest cell solids fraction of the whole domain (the solver's
#     log, every step) <= 0.6 + 1e-9, the serial run's bound;
#   - 2400 parcels at every step; the cloud mass at the end equals the
#     seeded solids volume * 2500 to 1e-9;
#   - (2 processes, 1 s) the bed height within 3 % of 0.0375 m, as serial.
#------------------------------------------------------------------------------
runDir="${1:?usage: parallelSedimentation.sh <runDir>}"
. "$MPPIC_PROJECT_DIR/tests/lib/caseFunctions"
# (ranks yield the core when they wait: without it, oversubscribed ranks
# spin against each other and against any other load)
export OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1

status=0
for split in "2 1 (2 1 1)" "4 0.5 (2 2 1)"
do
    n="${split%% *}"
    endTime=$(echo "$split" | cut -d' ' -f2)
    case="$runDir/ranks$n"
    copyTutorial verification/sedimentation "$case"
    setEntry "$case" system/controlDict endTime "$endTime"
    setEntry "$case" system/decomposeParDict numberOfSubdomains "$n"
    setEntry "$case" system/decomposeParDict coeffs/n "${split#* * }"
    runAllrun "$case" coloringFunction -parallel || exit 1

    (cd "$case" && /usr/bin/python3 - "$n" "$endTime") <<'PY' || status=1
import re, sys
sys.path.insert(0, ".")
from sedimentationResults import read_monitor, bed_profile, post, \
    surface_height, seeded_solids_volume
n, end = sys.argv[1], float(sys.argv[2])
import checks
def check(ok, what):
    checks.report(ok, "%s ranks: " % n + what)
steps = [(int(m.group(1)), float(m.group(2))) for m in re.finditer(
    r"^Cloud: parcels = (\d+), max solids fraction = (\S+)$",
    open("log.mppicPimpleFoam").read(), re.M)]
check(len(steps) > 4000*end, "%d steps logged" % len(steps))
check(all(p == 2400 for p, _ in steps), "2400 parcels at every step")
largest = max(a for _, a in steps)
check(largest <= 0.6 + 1e-9,
      "largest cell solids fraction %.9g <= 0.6 (serial) at every step" % largest)
cp, rows = read_monitor(".")
mass = rows[-1][2]
check(abs(mass/(seeded_solids_volume(".")*2500) - 1) < 1e-9,
      "cloud mass %.10g kg = seeded volume * 2500" % mass)
if end >= 1:
    ys, prof, dy, _, _ = bed_profile(".", post.latest_time("."))
    h = surface_height(ys, prof, 0.5*cp, dy)
    check(abs(h/0.0375 - 1) <= 0.03, "bed height %.4f m within 3 %% of 0.0375 m" % h)
sys.exit(checks.status())
PY
done
exit $status
