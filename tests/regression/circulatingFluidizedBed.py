#!/usr/bin/python3
"""The test's additions to tutorials/validation/circulatingFluidizedBed and its checks
(tests/regression/circulatingFluidizedBed.sh): 120 tracer parcels (a second
manualInjection, 4 particles each) on and around the axes of the exit tube
and the crossover pipe, so that parcels leave through the outlet within the
0.15 s run; then, in the case:
  - at every step: parcels in the cloud (packingMonitor) + parcels escaped
    through the outlet (localInteraction, cfbResults.outlet_escapes) =
    parcels injected, nParcels of constant/seededParcels + 120 tracers: no
    parcel lost by the tracking; and some parcels did leave by the end;
  - at every step: cloud mass + mass escaped through the outlet = the
    injected mass, to 1e-10 relative:
        m_injected = solidsVolume x 860 + 120 x 4 x pi/6 d^3 x 860,
        d = 8.7e-4 m (solidsVolume = 0.6 x the seeded region's volume,
        constant/seededParcels);
    the same at every write time from the parcels' own fields (sum of
    nParticle rho pi/6 d^3, checks.lagrangian_masses) plus the escaped mass
    at the nearest step;
  - at every write time (at least 10), in every cell: solids fraction
    (alpha.kinematicCloud, the cell values the packing model uses:
    averagingMethod basic) at most max(1.05 x 0.6, 0.6 + V_parcel/V_cell),
    V_parcel = nParticle pi/6 d^3 that of a seeded parcel (one parcel's
    step in a cell-based value); at every step the monitor's largest cell
    value at most 0.6 + V_parcel/(smallest cell);
  - no parcel crossed more than one cell in a step (nFastParcels 0);
  - cfbResults.summary gives finite pressure drops and packed height.

Usage:
    circulatingFluidizedBed.py tracerPositions <case>   (constant/tracerPositions)
    circulatingFluidizedBed.py tracerInjector <case>    (the injector, next to the seeded one)
    circulatingFluidizedBed.py results                  (the checks, in the case)
"""
import glob
import math
import os
import re
import sys

import checks
from checks import lagrangian_masses, report as check

RHO, D = 860.0, 8.7e-4
VP1 = math.pi/6*D**3      # one particle's volume
N_TRACERS = 120


def write_tracer_positions(case):
    """The tracers on the case's geometry of record (cfb.geo): the exit tube
    axis x = 0.0727, z = 0.075 and four points 5 mm around it, y 1.15 to
    1.30; the crossover axis from the riser axis (0.282 1.218 0.075) along
    (-0.97335 0 0.22934), 0.05 to 0.18 m, with points 5 mm above and below;
    filled up to 120 on the exit tube axis itself."""
    pts = []
    for k in range(16):
        y = 1.15 + 0.01*k
        for dx, dz in ((0.005, 0), (-0.005, 0), (0, 0.005), (0, -0.005)):
            pts.append((0.0727 + dx, y, 0.075 + dz))
    for k in range(14):
        t = 0.05 + 0.01*k
        x, z = 0.282 - 0.97335*t, 0.075 + 0.22934*t
        for dy in (-0.005, 0.0, 0.005):
            pts.append((x, 1.218 + dy, z))
    assert len(pts) == 106, len(pts)
    # fill up to 120 on the exit tube axis itself
    for k in range(14):
        pts.append((0.0727, 1.16 + 0.01*k, 0.075))
    with open(case + "/constant/tracerPositions", "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class vectorField; "
                "object tracerPositions; }\n%d\n(\n" % len(pts))
        for p in pts:
            f.write("(%.10g %.10g %.10g)\n" % p)
        f.write(")\n")


def add_tracer_injector(case):
    """The tracer manualInjection (4 particles a parcel, d 8.7e-4 m, at
    rest) first in the cloud's injectionModels."""
    path = case + "/constant/kinematicCloudProperties"
    s = open(path).read()
    anchor = "    injectionModels\n    {\n"
    assert anchor in s
    tracers = """        tracers
        {
            type            manualInjection;
            massTotal       0;
            parcelBasisType fixed;
            nParticle       4;
            SOI             0;
            positionsFile   "tracerPositions";
            U0              (0 0 0);
            sizeDistribution
            {
                type        fixedValue;
                fixedValueDistribution
                {
                    value   8.7e-4;
                }
            }
        }
"""
    s = s.replace(anchor, anchor + tracers)
    open(path, "w").write(s)


def injected():
    """(parcels, mass) injected, from constant/seededParcels and the
    tracers; and the seeded parcels' nParticle."""
    seeded = open("constant/seededParcels").read()
    nSeeded = int(float(re.search(r"nParcels\s+([^;]+);", seeded).group(1)))
    nParticle = float(re.search(r"nParticle\s+([^;]+);", seeded).group(1))
    solidsVolume = float(re.search(r"solidsVolume\s+([^;]+);", seeded).group(1))
    nInjected = nSeeded + N_TRACERS
    mInjected = solidsVolume*RHO + N_TRACERS*4*VP1*RHO
    print("injected: %d seeded parcels (%.12g kg) + %d tracers = %d parcels, %.15g kg"
          % (nSeeded, solidsVolume*RHO, N_TRACERS, nInjected, mInjected))
    return nInjected, mInjected, nParticle


def check_every_step(mon, esc, nInjected, mInjected):
    """Parcels and mass in the cloud + escaped = injected at every step;
    some parcels left."""
    check(len(mon) > 100 and len(esc) >= len(mon),
          "per-step tables: %d monitor rows, %d escape rows" % (len(mon), len(esc)))
    missing = [r[0] for r in mon if round(r[0], 9) not in esc]
    check(not missing, "an escape row for every monitor row (%d missing)" % len(missing))
    badCount = [(r[0], int(r[1]), esc[round(r[0], 9)][0]) for r in mon
                if round(r[0], 9) in esc and int(r[1]) + int(esc[round(r[0], 9)][0]) != nInjected]
    check(not badCount, "in cloud + escaped = %d parcels at every step (%d steps differ%s)"
          % (nInjected, len(badCount), ", first %s" % (badCount[0],) if badCount else ""))
    worst = max(abs((r[2] + esc[round(r[0], 9)][1])/mInjected - 1) for r in mon
                if round(r[0], 9) in esc)
    check(worst <= 1e-10, "cloud mass + escaped mass = injected mass at every step "
          "(largest relative difference %.2e <= 1e-10)" % worst)
    nLost = int(esc[round(mon[-1][0], 9)][0])
    check(nLost > 0, "%d parcels left through the outlet by %.4g s" % (nLost, mon[-1][0]))


def is_time(name):
    try:
        return float(name) > 0
    except ValueError:
        return False


def check_write_times(c, mon, esc, mInjected, nParticle):
    """At the write times, from the parcels' own fields: the mass balance
    and every cell's solids fraction; over the steps the monitor's largest
    cell value and nFastParcels."""
    V = c.post.internal_field("0/V")
    vParcel = nParticle*VP1
    times = sorted((d for d in glob.glob("[0-9]*") if is_time(d) and os.path.isdir(d)),
                   key=float)
    worstField = 0.0
    worstCell = (-1.0, None)
    largestField = 0.0
    for t in times:
        lag = os.path.join(t, "lagrangian", "kinematicCloud")
        mass = math.fsum(lagrangian_masses(lag))
        tEsc = min(esc, key=lambda k: abs(k - float(t)))
        worstField = max(worstField, abs((mass + esc[tEsc][1])/mInjected - 1))
        alpha = c.post.internal_field(os.path.join(t, "alpha.kinematicCloud"))
        largestField = max(largestField, max(alpha))
        for a, v in zip(alpha, V):
            excess = a - max(1.05*0.6, 0.6 + vParcel/v)
            if excess > worstCell[0]:
                worstCell = (excess, "t %s: solids fraction %.4f in a cell of %.3g m3"
                             % (t, a, v))
    check(len(times) >= 10, "%d write times" % len(times))
    check(worstField <= 1e-10, "parcel fields + escaped = injected mass at the write times "
          "(largest relative difference %.2e <= 1e-10)" % worstField)
    check(worstCell[0] <= 1e-12, "every cell at every write time within "
          "max(1.05*0.6, 0.6 + V_parcel/V_cell) (closest: %.3g above the bound, %s)"
          % (worstCell[0], worstCell[1]))
    # the record's count (mppicPost.cells_above_bound: each cell's solids
    # fraction from the parcels' coordinates, nParticle and d) against the
    # written field's
    b = c.post.cells_above_bound(".", 0.6)
    check(b["cellsAbove"] == 0 and b["times"] >= len(times)
          and abs(b["largest"] - largestField) <= 1e-9*largestField,
          "cells_above_bound: %d cells above at %d times, largest "
          "%.10f from the parcels, %.10f in alpha.kinematicCloud"
          % (b["cellsAbove"], b["times"], b["largest"], largestField))
    bound = 0.6 + vParcel/min(V)
    maxCell = max(r[4] for r in mon)
    check(maxCell <= bound, "largest cell solids fraction over the steps %.4f <= "
          "0.6 + V_parcel/V_min = %.4f" % (maxCell, bound))
    fast = max(r[7] for r in mon)
    check(fast == 0, "no parcel crossed more than one cell in a step (max %d)" % fast)


def check_results_script(c):
    r = c.summary(".", 0.05)
    check(all(math.isfinite(r[k]) for k in ("riserDp", "standpipeDp", "packedHeight")),
          "results: riser dP %.1f Pa, standpipe dP %.1f Pa, packed height %.3f m"
          % (r["riserDp"], r["standpipeDp"], r["packedHeight"]))


def results():
    sys.path.insert(0, ".")
    import cfbResults as c  # the tutorial's copy in the case
    nInjected, mInjected, nParticle = injected()
    mon = c.series("postProcessing/packingMonitor", "packingMonitor.dat")
    esc = {round(t, 9): (n, m) for t, n, m in c.outlet_escapes(".")}
    check_every_step(mon, esc, nInjected, mInjected)
    check_write_times(c, mon, esc, mInjected, nParticle)
    check_results_script(c)
    return checks.status()


def main(argv):
    return checks.run_command(argv, {
        "tracerPositions": write_tracer_positions,
        "tracerInjector": add_tracer_injector,
        "results": results})


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
