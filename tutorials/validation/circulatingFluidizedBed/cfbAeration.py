#!/usr/bin/python3
"""The L-valve's response to its aeration (tutorials/validation/circulatingFluidizedBed,
issue 22): where the aeration gas goes and what solids it moves.

Usage:
    cfbAeration.py RUN [RUN ...] [--standpipe SLPM] [--plot FILE]
    RUN = SLPM:DIR:T0:T1[:LABEL], e.g. 12:../runs/f12:2.3:3 (the bend
          aeration FTC135 of the run, its directory, the window in
          simulated s; runs of one LABEL are one line of the plot)

For each run, over the window:
  - the gas up the standpipe and along the leg into the riser, m3/s, from
    the written fields (every write time in the window): the mean of
    alpha_g U_g (y component in the standpipe, x in the leg) over the cells
    within one pipe radius (0.0127 m) of the pipe's axis, in the standpipe
    at y 0.80-0.88 m (above its inventory) and in the leg at x 0.13-0.19 m,
    times the nominal 1" area; needs 0/C and 0/V (Allrun writes them);
  - the solids fed: cfbResults' net parcel mass down through the standpipe
    plane y = 0.20 (kg/s), and the riser and standpipe pressure drops.
The aerations of the run are given, not read (a run forked from another
with new flows does not record them): FTC135 in RUN, the standpipe's FTC115
by --standpipe (default 1.5 SLPM, Cases 1 and 3); the shares are of the two.
--plot draws the fed solids against FTC135 (a line per label) and the gas
shares of the label with the most runs.
"""
import argparse
import math
import os

import numpy as np

import cfbResults
from cfbResults import post

PIPE_R = 0.0127                   # 1" pipes
PIPE_AREA = math.pi*(2*PIPE_R)**2/4
STANDPIPE_AXIS = (0.0727, 0.075)  # x, z
LEG_AXIS = (0.0176, 0.075)        # y, z


def gas_split(case, t0, t1):
    """Mean gas flow up the standpipe and along the leg [m3/s] over the
    fields written in [t0, t1], and the number of fields."""
    C = np.array(post.internal_field(os.path.join(case, "0", "C")))
    V = np.array(post.internal_field(os.path.join(case, "0", "V")))
    stand = ((np.hypot(C[:, 0] - STANDPIPE_AXIS[0], C[:, 2] - STANDPIPE_AXIS[1]) < PIPE_R)
             & (C[:, 1] > 0.80) & (C[:, 1] < 0.88))
    leg = ((np.hypot(C[:, 1] - LEG_AXIS[0], C[:, 2] - LEG_AXIS[1]) < PIPE_R)
           & (C[:, 0] > 0.13) & (C[:, 0] < 0.19))
    up, along = [], []
    for t, name in post.time_dirs(case):
        d = os.path.join(case, name)
        if not (t0 - 1e-9 <= t <= t1 + 1e-9 and t > 0
                and os.path.isfile(os.path.join(d, "U.air"))
                and os.path.isfile(os.path.join(d, "alpha.air"))):
            continue
        U = np.array(post.internal_field(os.path.join(d, "U.air")))
        a = np.array(post.internal_field(os.path.join(d, "alpha.air")))
        up.append(np.sum(a[stand]*U[stand, 1]*V[stand])/np.sum(V[stand])*PIPE_AREA)
        along.append(np.sum(a[leg]*U[leg, 0]*V[leg])/np.sum(V[leg])*PIPE_AREA)
    n = len(up)
    return (float(np.mean(up)) if n else math.nan,
            float(np.mean(along)) if n else math.nan, n)


def measure(spec, standpipeSlpm):
    slpm, case, t0, t1, label = (spec.split(":") + ["runs"])[:5]
    t0, t1 = float(t0), float(t1)
    r = cfbResults.summary(case, t0, t1)
    up, along, n = gas_split(case, t0, t1)
    q = (float(slpm) + standpipeSlpm)*1e-3/60
    return {"slpm": float(slpm), "case": case, "label": label, "t0": t0, "t1": t1,
            "up": up, "along": along, "nFields": n, "aeration": q,
            "fed": r["circulationStandpipe"], "riserDp": r["riserDp"],
            "standpipeDp": r["standpipeDp"], "level": r["heightAboveBend"]}


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = sorted(rows, key=lambda r: r["slpm"])
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(9, 3.6))
    labels = list(dict.fromkeys(r["label"] for r in rows))
    for label, marker in zip(labels, "osdv^"):
        own = [r for r in rows if r["label"] == label]
        a1.plot([r["slpm"] for r in own], [1e3*r["fed"] for r in own],
                marker + "-", label=label)
    a1.legend(fontsize=8)
    a1.set_xlabel("bend aeration FTC135 [SLPM]")
    a1.set_ylabel("solids down the standpipe [g/s]")
    a1.set_xlim(left=0)
    a1.set_ylim(bottom=0)
    most = max(labels, key=lambda l: sum(r["label"] == l for r in rows))
    own = [r for r in rows if r["label"] == most]
    x = [r["slpm"] for r in own]
    a2.plot(x, [1e6*r["up"] for r in own], "o-", label="up the standpipe")
    a2.plot(x, [1e6*r["along"] for r in own], "s-", label="along the leg")
    a2.plot(x, [1e6*r["aeration"] for r in own], "k--", label="both aerations")
    a2.set_title(most, fontsize=9)
    a2.set_xlabel("bend aeration FTC135 [SLPM]")
    a2.set_ylabel("gas [cm$^3$/s]")
    a2.set_xlim(left=0)
    a2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("runs", nargs="+")
    p.add_argument("--standpipe", type=float, default=1.5)
    p.add_argument("--plot")
    a = p.parse_args()
    rows = [measure(s, a.standpipe) for s in a.runs]
    print("| run | FTC135 [SLPM] | window [s] | solids fed [g/s] | gas up the standpipe [cm3/s]"
          " | gas along the leg [cm3/s] | riser dP [Pa] | standpipe dP [Pa] | level above the bend [m] |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in sorted(rows, key=lambda r: r["slpm"]):
        print("| %s | %g | %g-%g | %.1f | %.0f (%.0f %% of the aerations) | %.0f | %.0f | %.0f | %.3f |"
              % (r["label"], r["slpm"], r["t0"], r["t1"], 1e3*r["fed"], 1e6*r["up"],
                 100*r["up"]/r["aeration"] if r["aeration"] else math.nan,
                 1e6*r["along"], r["riserDp"], r["standpipeDp"], r["level"]))
    if a.plot:
        plot(rows, a.plot)


if __name__ == "__main__":
    main()
