#!/usr/bin/python3
"""Momentum budget of the packing step (tutorials/verification/packingMomentum).

Reads the cloud's linear momentum and kinetic energy after every step from
log.mppicPimpleFoam and the packing monitor's per-step packing momentum,
writes packingMomentum.txt and prints it.

Hand value: the layer alone moves at first, so the cloud's momentum is
    P0 = m_layer*U0,  m_layer = 0.15*(0.04*0.01*0.005 m3)*2500 kg/m3
       = 7.5e-4 kg,   U0 = (0.1, -0.5, 0) m/s  ->  P0 = (7.5e-5, -3.75e-4, 0).
With no forces, only the packing model changes it: with conserveMomentum
packs the pack takes the opposite impulse and P stays P0 to round-off while the
collisions (e1 = 0.5) remove kinetic energy; with none, P changes by the
monitor's packing momentum summed over the steps.

With conserveMomentum gas (./Allrun gas) the packs, which no support
holds here, hand their share to the gas: P + G stays P0, G the monitor's
gasPackingMomentum summed over the steps. Hand bounds for G_y: each layer
parcel is turned once by the pack at rest, dU_y = (1 + e1)*0.5 = 0.75 m/s,
and keeps f = M/(M + m_in) of it, where M is the pack cell's mass (0.6 of
the cell, 1.875e-4 kg) and m_in the mass turned into it in the step, at
most the layer's column over the cell (0.15 of two cells, 9.375e-5 kg): f
lies in [2/3, 1], the pack's share f*m*dU goes to the gas, so
    G_y = -f*m_layer*0.75  lies in  [-5.625e-4, -3.75e-4] kg m/s.

The monitor's field packingForce (writePackingForce, written at 0.02 and
0.04 s) times the cell volume (blockMeshDict: 0.04*0.04*0.005 m3 in 8*8*1
cells, 1.25e-7 m3) and the 0.02 s since the previous written time, summed
over the cells, is the monitor's packing momentum summed over the steps of
that interval.

    ./packingMomentumResults.py [--check]
--check exits 1 when the run's form (conserveMomentum from the cloud
properties) does not meet these statements.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)


P0 = (0.15*0.04*0.01*0.005*2500*0.1, -0.15*0.04*0.01*0.005*2500*0.5, 0.0)
CLOSE_PACK = 0.6
CELL_VOLUME = 0.04*0.04*0.005/(8*8*1)
FIELD_TIMES = ("0.02", "0.04")


def vector(text):
    return [float(v) for v in text.strip("()").split()]


def read_log(path="log.mppicPimpleFoam"):
    momentum, energy = [], []
    for line in open(path):
        m = re.match(r"\s+Linear momentum\s+= (\(.*\))", line)
        if m:
            momentum.append(vector(m.group(1)))
        m = re.match(r"\s+Linear kinetic energy\s+= (\S+)", line)
        if m:
            energy.append(float(m.group(1)))
    return momentum, energy


def read_monitor(path="postProcessing/packingMonitor/0/packingMonitor.dat"):
    rows = post.read_table(path)
    packing = [r[8:11] for r in rows]
    return packing, max(r[4] for r in rows), rows


def field_momentum(rows):
    """For each written time of packingForce: (sum over cells of the field
    times the cell volume and the interval, the monitor's rows summed over
    the interval's steps), x, y and z."""
    out = []
    start = 0.0
    for name in FIELD_TIMES:
        end = float(name)
        force = post.internal_field(os.path.join(name, "packingForce"))
        if not isinstance(force, list):
            force = [force]*64  # written uniform: one vector for all cells
        field = [sum(f[i] for f in force)*CELL_VOLUME*(end - start)
                 for i in range(3)]
        steps = [r for r in rows if start + 1e-9 < r[0] <= end + 1e-9]
        monitor = [sum(r[8 + i] for r in steps) for i in range(3)]
        out.append((name, field, monitor))
        start = end
    return out


def conserve_setting(path="constant/kinematicCloudProperties"):
    return post.dict_entry(path, "conserveMomentum") in ("packs", "gas")


def to_gas_setting(path="constant/kinematicCloudProperties"):
    return post.dict_entry(path, "conserveMomentum") == "gas"


def norm(v):
    return sum(x*x for x in v)**0.5


def main(argv):
    conserve = conserve_setting()
    to_gas = to_gas_setting()
    momentum, energy = read_log()
    packing, max_alpha, rows = read_monitor()
    scale = norm(P0)

    # The first step injects; the packing of step k changes P(k-1) to P(k)
    drift = max(norm([a - b for a, b in zip(p, momentum[0])])
                for p in momentum)/scale
    # The packs' reactions handed to the gas (monitor columns 14-16)
    handed = [sum(r[14 + i] for r in rows[1:]) for i in range(3)]
    total_drift = norm([a + b - c for a, b, c
                        in zip(momentum[-1], handed, momentum[0])])/scale
    summed = [sum(r[i] for r in packing[1:]) for i in range(3)]
    change = [a - b for a, b in zip(momentum[-1], momentum[0])]
    mismatch = norm([a - b for a, b in zip(change, summed)])/scale
    initial_error = norm([a - b for a, b in zip(momentum[0], P0)])/scale
    energy_ratio = energy[-1]/energy[0]
    fields = field_momentum(rows)
    field_mismatch = max(norm([a - b for a, b in zip(f, m)])
                         for _, f, m in fields)/scale

    lines = [
        "conserveMomentum               %s"
        % ("gas" if to_gas else "packs" if conserve else "none"),
        "steps                          %d" % len(momentum),
        "initial momentum [kg m/s]      (%.6e %.6e %.6e)" % tuple(momentum[0]),
        "hand value P0                  (%.6e %.6e %.6e)" % P0,
        "final momentum [kg m/s]        (%.6e %.6e %.6e)" % tuple(momentum[-1]),
        "max |P - P(0)|/|P0|            %.3e" % drift,
        "summed packing momentum        (%.6e %.6e %.6e)" % tuple(summed),
        "|dP - summed|/|P0|             %.3e" % mismatch,
        "summed to the gas              (%.15e %.15e %.15e)" % tuple(handed),
        "|P + to gas - P(0)|/|P0|       %.3e" % total_drift,
        "final/initial kinetic energy   %.4f" % energy_ratio,
        "max cell solids fraction       %.15g" % max_alpha,
    ] + [
        "packingForce*V*dt at %s s     (%.6e %.6e %.6e)" % ((n,) + tuple(f))
        + "; monitor (%.6e %.6e %.6e)" % tuple(m) for n, f, m in fields
    ] + [
        "max |field - monitor|/|P0|     %.3e" % field_mismatch,
    ]
    open("packingMomentum.txt", "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))

    if "--check" not in argv:
        return 0

    checks = [
        (initial_error < 1e-12, "initial momentum equals m_layer*U0"),
        (mismatch < 1e-10, "momentum change equals the monitor's sum"),
        (max_alpha <= CLOSE_PACK*(1 + 1e-12), "cells stay at close pack"),
        (field_mismatch < 1e-10, "packingForce field equals the monitor's"
         " sum over each written interval"),
    ]
    if to_gas:
        checks += [
            (total_drift < 1e-12, "cloud + reactions handed to the gas"
             " constant to round-off"),
            (-5.625e-4 <= handed[1] <= -3.75e-4, "the gas took the packs'"
             " share, within the hand bounds [-5.625e-4, -3.75e-4]"),
        ]
    elif conserve:
        checks += [
            (drift < 1e-12, "momentum constant to round-off"),
            (energy_ratio < 0.9, "collisions took kinetic energy"),
        ]
    else:
        checks += [(drift > 0.5, "the reflections changed the momentum")]
    failed = 0
    for ok, what in checks:
        print(("PASS " if ok else "FAIL ") + what)
        failed += not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
