#!/usr/bin/python3
"""Where the background gas goes in the Kuipers jet's annulus, and what then
carries the annulus's packed cells.

Usage:
    kuipersJetGasBudget.py [--case DIR] [--from T0] [--to T1]

For a run that writes its fields often (./Allrun 31 -continue -write 0.02):
each written time t with T0 < t <= T1 and a written time before it is one
interval. On the annulus, |x - 0.285| > 0.10 m, in two height bands
(0.02-0.15 m, 0.15-0.45 m), it prints:
  - the mean superficial gas velocity U_s: for each cell the mean of the
    gas flux through its bottom and top faces over the face area; phi.air
    is the flux of the interstitial velocity (MPPICFoam's phic), so the
    gas's flux is alpha_g,f phi with alpha_g,f the mean of the two cells'
    alpha.air;
  - which cells carry that gas: the shares through full (eps_s >= 0.59),
    partial (0.3-0.59) and void (<= 0.3) cells, and their shares of the
    cells;
  - for the cells full at both ends of the interval: U_s; the relative
    superficial velocity U_s - alpha_g u_p (u_p the mean vertical velocity
    of the cell's parcels, from lagrangian/kinematicCloud/{coordinates,U});
    the drag the model's GidaspowDrag (OpenFOAM's Ergun form below a gas
    fraction of 0.8) gives the cell's parcels at that relative velocity
    over their weight; the packing step's force (the field packingForce,
    the interval's mean, packingMonitor writePackingForce) over the same
    weight; and their sum, which is 1 when drag and packing step carry the
    cells between them (the cells' own acceleration is left out).
The same for the partial cells. The minimum fluidization velocity of a
resting full cell (5 parcels, eps_s 0.60) by that drag is printed first:
0.225 m/s (Kuipers' beads: 0.25 m/s measured, the background gas).
"""
import argparse
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get(
    "MPPIC_PROJECT_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")),
    "tutorials", "lib"))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kuipersJetResults as jet  # noqa: E402 (beside this file)
from mppicPost import internal_field, lagrangian_field, time_dirs  # noqa: E402

RHO_P, RHO_G, MU, D = 2660.0, 1.2, 1.8e-5, 5e-4    # constant/*Properties
FACE_AREA = 0.0075*0.0075                           # a horizontal face [m2]
FULL, VOID = 0.59, 0.3
BANDS = (("0.02-0.15 m", 0.02, 0.15), ("0.15-0.45 m", 0.15, 0.45))


def drag_over_weight(u_rel, eps_s):
    """Drag on resting parcels at relative superficial velocity u_rel [m/s]
    in a cell at solids fraction eps_s, over their weight: OpenFOAM's
    ErgunWenYuDragForce below a gas fraction of 0.8 (GidaspowDrag there),
    F/V_p = mu/(alpha_g d^2) (150 eps_s/alpha_g + 1.75 Re) u_rel/alpha_g,
    Re = rho_g |u_rel/alpha_g| d/mu."""
    alpha_g = 1 - np.asarray(eps_s, dtype=float)
    slip = np.asarray(u_rel, dtype=float)/alpha_g
    re = RHO_G*np.abs(slip)*D/MU
    return MU/(alpha_g*D*D)*(150*(1 - alpha_g)/alpha_g + 1.75*re)*slip/(RHO_P*jet.G)


def minimum_fluidization(eps_s=0.6):
    """The superficial velocity at which drag_over_weight is 1 (bisection)."""
    lo, hi = 0.0, 5.0
    for _ in range(60):
        mid = 0.5*(lo + hi)
        lo, hi = (mid, hi) if drag_over_weight(mid, eps_s) < 1 else (lo, mid)
    return 0.5*(lo + hi)


def label_list(path):
    """An ascii labelList (owner, neighbour) as a numpy array."""
    text = open(path).read()
    start = text.index("(", text.index("}", text.index("FoamFile")))
    n = int(text[:start].split()[-1])
    return np.array(text[start + 1:].split(None, n)[:n], dtype=int)


def vertical_faces(case, grid):
    """The internal faces between vertically adjacent cells: (face index,
    lower cell, upper cell, +1 where the owner is the lower cell else -1)."""
    owner = label_list(os.path.join(case, "constant", "polyMesh", "owner"))
    neighbour = label_list(os.path.join(case, "constant", "polyMesh", "neighbour"))
    owner = owner[:len(neighbour)]
    col, row = grid[owner].T, grid[neighbour].T
    faces = np.nonzero((col[0] == row[0]) & (np.abs(col[1] - row[1]) == 1))[0]
    upward = grid[neighbour[faces], 1] > grid[owner[faces], 1]
    lower = np.where(upward, owner[faces], neighbour[faces])
    upper = np.where(upward, neighbour[faces], owner[faces])
    return faces, lower, upper, np.where(upward, 1.0, -1.0), owner, neighbour


def superficial_velocity(case, time, faces, n_cells):
    """Each cell's mean upward gas flux through its bottom and top faces
    over the face area [m/s], and alpha.air."""
    face, lower, upper, sign, owner, neighbour = faces
    alpha = np.array(internal_field(os.path.join(case, time, "alpha.air")))
    phi = np.array(internal_field(os.path.join(case, time, "phi.air")))
    flux = 0.5*(alpha[owner[face]] + alpha[neighbour[face]])*phi[face]*sign
    total = np.bincount(lower, flux, n_cells) + np.bincount(upper, flux, n_cells)
    return 0.5*total/FACE_AREA, alpha


def parcel_velocity(case, time, n_cells):
    """The mean vertical velocity of each cell's parcels (0 in empty cells)."""
    cloud = os.path.join(case, time, "lagrangian", "kinematicCloud")
    text = open(os.path.join(cloud, "coordinates")).read()
    cell = np.array(re.findall(r"\)\s+(\d+)\s+\d+\s+\d+", text), dtype=int)
    u = np.array(lagrangian_field(os.path.join(cloud, "U")))[:, 1]
    count = np.bincount(cell, minlength=n_cells)
    return np.bincount(cell, u, n_cells)/np.maximum(count, 1)


def budget(case, t0, t1):
    """The sums behind the printed table, by band."""
    cells, xs, ys = jet.cell_grid(case)
    grid = np.array(cells)
    n_cells = len(grid)
    faces = vertical_faces(case, grid)
    x, y = np.array(xs)[grid[:, 0]], np.array(ys)[grid[:, 1]]
    annulus = np.abs(x - jet.AXIS) > 0.10
    times = [d for _, d in time_dirs(case)
             if os.path.exists(os.path.join(case, d, "phi.air"))]
    out = {band: {"flow": np.zeros(3), "cells": np.zeros(3), "n": 0,
                  "full": np.zeros(5), "partial": np.zeros(5),
                  "fullWeight": 0.0, "partialWeight": 0.0} for band, _, _ in BANDS}
    eps = None
    for before, time in zip(times, times[1:]):
        if not t0 + 1e-9 < float(time) <= t1 + 1e-9:
            eps = None
            continue
        # the field at the interval's start is the previous interval's end
        eps0 = np.array(jet.solids_field(case, before)) if eps is None else eps
        eps = np.array(jet.solids_field(case, time))
        u_s, alpha = superficial_velocity(case, time, faces, n_cells)
        u_rel = u_s - alpha*parcel_velocity(case, time, n_cells)
        weight = np.maximum(eps, 1e-9)*RHO_P*jet.G
        packing = np.array(internal_field(os.path.join(case, time, "packingForce")))[:, 1]
        states = (eps >= FULL, (eps > VOID) & (eps < FULL), eps <= VOID)
        for band, lo, hi in BANDS:
            where = annulus & (y > lo) & (y < hi)
            b = out[band]
            b["n"] += np.count_nonzero(where)
            for k, state in enumerate(states):
                b["flow"][k] += u_s[where & state].sum()
                b["cells"][k] += np.count_nonzero(where & state)
            for key, cellset in (("full", where & states[0] & (eps0 >= FULL)),
                                 ("partial", where & states[1])):
                w = weight[cellset]
                b[key] += [w.size, (u_s[cellset]*w).sum(), (u_rel[cellset]*w).sum(),
                           (drag_over_weight(u_rel[cellset], eps[cellset])*w).sum(),
                           packing[cellset].sum()]
                b[key + "Weight"] += w.sum()
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", default=".")
    parser.add_argument("--from", dest="t0", type=float, default=0.0)
    parser.add_argument("--to", dest="t1", type=float, default=1e9)
    args = parser.parse_args()
    print("minimum fluidization of a resting full cell (eps_s 0.60) by GidaspowDrag: %.3f m/s"
          % minimum_fluidization(0.6))
    for band, b in budget(args.case, args.t0, args.t1).items():
        if not b["n"]:
            continue
        flow = b["flow"].sum()
        print("annulus %s: mean U_s %.3f m/s; the gas through full / partial / void cells "
              "%.2f / %.2f / %.2f of it; the cells %.2f / %.2f / %.2f"
              % (band, flow/b["n"], *(b["flow"]/max(flow, 1e-30)), *(b["cells"]/b["n"])))
        for key in ("full", "partial"):
            n, us, urel, drag, pack = b[key]
            w = b[key + "Weight"]
            if n:
                print("  %-7s cells (%d): U_s %.3f, relative %.3f m/s; drag %.3f + packing step"
                      " %.3f = %.3f of their weight" % (key, n, us/w, urel/w, drag/w, pack/w,
                                                        (drag + pack)/w))


if __name__ == "__main__":
    main()
