#!/usr/bin/python3
"""Checks of tests/regression/kuipersJet.sh: tutorials/validation/kuipersJet as the case
runs it (coloringFunction, GidaspowDrag, 38 000 parcels, dt 5e-4 s) for
0.2 s, read with the tutorial's kuipersJetResults.summary(case, 0.1),
kuipersJetSlabs and kuipersJetGasBudget (the case's copies):
  - 38 000 parcels and the cloud mass 0.6 x 0.57 x 0.5 x 0.015 x 2660 =
    6.8229 kg at every step (to 1e-9; parcels are kept in at the outlet);
  - one parcel = 0.12 of a cell (to 1e-3), and the largest cell solids
    fraction at every step at most
        max(1.05 x 0.62, 0.62 + V_parcel/V_cell) = max(0.651, 0.74) = 0.74
    (the field is cell-based: it moves in steps of one parcel);
  - the bed pressure drop over 0.1-0.2 s, after the start-up jump of the
    packed bed, within 15 % of the bed weight per area,
    6.8229 x 9.81/(0.57 x 0.015) = 7828 Pa;
  - the field packingForce (packingMonitor writePackingForce, means over
    the written intervals 0.08-0.12-0.16-0.2 s: 3 of them) summed over the
    cells times the cell volume, over the weight, equals the monitor's
    packing momentum (packingMomentumY) summed over the steps of
    0.08-0.2 s, over 0.12 s, over the weight, to 1e-6;
  - the slab measure's samples (slabSamples, every 0.1 s from 0.1 s): two
    instants, 0.1 and 0.2 s, the one at 0.2 s equal to the written field to
    1e-12;
  - the slab measure on hand-made 76 x 100 grids (background 0.4): a row
    62/76 = 0.816 at 0.56 over a run of 39/76 = 0.513 at 0.1 is a slab
    (rows 60 over 30); 60/76 = 0.789 dense, or a void run of 38 (0.5, not
    wider than half), or the void above the dense row, is not;
  - the gas budget: the minimum fluidization of a resting full cell
    (eps_s 0.6) by the drag it reads equals Ergun's quadratic
        1.75/e^3 Re^2 + 150 (1-e)/e^3 Re = d^3 rho_g rho_p g/mu^2
                                         = 12080.8 at e = 0.4:
        Re 7.4977, U_mf 0.22493 m/s (1e-3);
    the superficial gas velocity it reads from phi.air across the row of
    cells at 0.9 m (152 cells above the bed, whose gas volume below stays
    put) at 0.2 s is the inflow over the cross-section,
        (0.25 x 0.555 + 10 x 0.015)/0.57 = 0.50658 m/s (1e-4).
(The log's capacity report and the push directions are checked in the
script.)

Usage: kuipersJet.py   (in the case)
"""
import sys

sys.path.insert(0, ".")
import numpy as np  # noqa: E402
import kuipersJetResults as k  # noqa: E402 (the case's copy)
import kuipersJetSlabs as s  # noqa: E402
import kuipersJetGasBudget as gb  # noqa: E402
import checks  # noqa: E402
from checks import report as check  # noqa: E402

MASS = 0.6*0.57*0.5*0.015*2660


def check_parcels_mass_and_packing(res):
    mon = res["monitor"]
    check(all(r[1] == 38000 for r in mon), "38000 parcels at every step")
    check(all(abs(r[2]/MASS - 1) < 1e-9 for r in mon),
          "cloud mass %.6g kg = %.6g kg at every step" % (mon[-1][2], MASS))
    check(abs(res["parcelFraction"] - 0.12) < 1e-3,
          "one parcel = %.4f of a cell" % res["parcelFraction"])
    check(res["maxCell"] <= 0.74 + 1e-9,
          "max cell solids fraction %.4f <= 0.74 at every step" % res["maxCell"])


def check_pressure_drop(res):
    check(abs(res["dpRatio"] - 1) <= 0.15,
          "mean deltaP over 0.1-0.2 s %.3f x bed weight within 15 %%"
          % res["dpRatio"])


def check_packing_force_field(res):
    mon = res["monitor"]
    force = res.get("forceSplit")
    rows = [r for r in mon if 0.08 + 1e-9 < r[0] <= 0.2 + 1e-9]
    fromMonitor = sum(r[9] for r in rows)/0.12/(MASS*9.81)
    fromField = None if force is None else \
        force["annulus"] + force["beside the jet"] + force["over the jet"]
    check(force is not None and res["forceGrid"][0] == 3
          and abs(fromField - fromMonitor) <= 1e-6,
          "packingForce over 3 written intervals %s x weight = monitor's %.6f"
          % (fromField, fromMonitor))


def check_slab_samples(res):
    samples = s.sample_grids(".", 0.1, (76, 100), 0.57, 1.0)
    check([t for t, _ in samples] == [0.1, 0.2],
          "slab samples at %s s" % [t for t, _ in samples])
    cells, xs, ys = res["grid"]
    written = k.to_grid(k.solids_field(".", "0.2"), cells, len(xs), len(ys))
    diff = max(abs(a - b) for ra, rb in zip(written, samples[-1][1])
               for a, b in zip(ra, rb))
    check(diff < 1e-12, "samples at 0.2 s = written field (largest difference %g)"
          % diff)


def hand_grid(dense_row, n_dense, void_row, n_void):
    """76 x 100 at 0.4; n_dense cells of dense_row at 0.56, n_void cells of
    void_row (from the 6th) at 0.1."""
    g = [[0.4]*76 for _ in range(100)]
    g[dense_row][:n_dense] = [0.56]*n_dense
    g[void_row][5:5 + n_void] = [0.1]*n_void
    return g


def check_slab_measure_on_hand_grids():
    check(s.slab_rows(hand_grid(60, 62, 30, 39)) == (60, 30), "slab 62/76 over void 39/76")
    check(s.slab_rows(hand_grid(60, 60, 30, 39)) is None, "no slab at 60/76 dense")
    check(s.slab_rows(hand_grid(60, 62, 30, 38)) is None, "no slab over a void of 38/76")
    check(s.slab_rows(hand_grid(30, 62, 60, 39)) is None, "no slab under a void")


def check_gas_budget(res):
    check(abs(gb.minimum_fluidization(0.6)/0.22493 - 1) < 1e-3,
          "minimum fluidization of a full cell %.5f m/s = Ergun's 0.22493"
          % gb.minimum_fluidization(0.6))
    cells, xs, ys = res["grid"]
    grid = np.array(cells)
    u_s, _ = gb.superficial_velocity(".", "0.2", gb.vertical_faces(".", grid), len(grid))
    top = np.abs(np.array(ys)[grid[:, 1]] - 0.905) < 1e-6
    check(top.sum() == 152 and abs(u_s[top].mean()/0.50658 - 1) < 1e-4,
          "superficial gas velocity across 0.9 m %.5f m/s = inflow 0.50658 (%d cells)"
          % (u_s[top].mean(), top.sum()))


if __name__ == "__main__":
    res = k.summary(".", 0.1)
    check_parcels_mass_and_packing(res)
    check_pressure_drop(res)
    check_packing_force_field(res)
    check_slab_samples(res)
    check_slab_measure_on_hand_grids()
    check_gas_budget(res)
    sys.exit(checks.status())
