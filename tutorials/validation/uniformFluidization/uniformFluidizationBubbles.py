"""The uniform bed's bubbles (tutorials/lib/mppicBubbles.py on the gas
fraction that the function object bubbleSlices samples on the front and
back walls every 0.02 s), for uniformFluidizationResults.py:

    summary(case, t0, t1, series)
                             the window's statistics (mppicBubbles.
                             bubble_statistics) with the standard deviation
                             and dominant frequency of the (t, deltaP/
                             weight) series the results script read, and
                             the references; None without samples in the
                             window
    DARTON, TWO_PHASE        the references: Darton's diameter at half the
                             settled height, two-phase theory's bubble
                             fraction with it
    lines(res)               what the results script prints
    record_rows(res)         the validation matrix's rows
    plots(res, case, label)  uniformFluidization_<label>_bubbles.png
                             (diameter against height beside Darton's
                             correlation) and _snapshots.png

References (no measured bubble data of this bed exist):
    - two-phase theory's bubble fraction (mppicBubbles.
      two_phase_bubble_fraction) with Darton et al.'s diameter at half the
      settled height: U = 0.5, U_mf = 0.213 m/s (Ergun at voidage 0.4, the
      README), eps_mf 0.4: D(0.06 m) = 21.9 mm, delta = 0.346;
    - the goal of a bubbling bed: a bubble fraction of at least 0.15;
    - MFiX-PIC 21.3.2 on this bed (reference/mfix_pic_uniform_bed.csv):
      its bed height over the settled 1.35 (std 0.007 m), deltaP/weight
      std 0.080 at 4.3 Hz, void cells 0.055 (below the bed height).
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicBubbles as bubbles  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402

U, UMF, EPS_MF = 0.5, 0.213, 0.4
SETTLED = 0.12
GOAL_FRACTION = 0.15
MFIX = {"expansion": 1.35, "heightStd": 0.007, "std": 0.080,
        "frequency": 4.3, "void": 0.055}


DARTON = float(bubbles.darton_diameter(U, UMF, 0.5*SETTLED))
TWO_PHASE = bubbles.two_phase_bubble_fraction(U, UMF, EPS_MF, DARTON)[0]


def summary(case, t0, t1, series):
    folder = os.path.join(case, "postProcessing", "bubbleSlices")
    if not os.path.isdir(folder):
        return None
    times, xs, ys, eps = bubbles.read_slices(case)
    if not any(t0 - 1e-9 <= t <= t1 + 1e-9 for t in times):
        return None
    res = bubbles.bubble_statistics(times, xs, ys, eps, t0, t1)
    window = [(t, r) for t, r in series if t0 - 1e-12 <= t <= t1 + 1e-12]
    res["std"], _, _, res["frequency"] = bubbles.pressure_signal(
        [t for t, _ in window], [r for _, r in window])
    res["darton"], res["twoPhase"] = DARTON, TWO_PHASE
    res["t0"], res["t1"] = t0, t1
    res["snapshots"] = (xs, ys, times, eps)
    return res


def lines(res, label):
    rise = [v for _, v in res["rise"]]
    return [
        "%s: bubbles over %g-%g s (gas fraction > 0.8 below %.3f m, each "
        "wall a picture): void cells %.3f; in bubbles of 3 cells or more "
        "%.3f (two-phase theory %.3f); %.2f bubbles a picture, mean "
        "diameter %.1f mm, largest %.1f mm; median rise %.3f m/s of %d "
        "tracked" % (label, res["t0"], res["t1"], res["top"],
                     res["voidFraction"], res["bubbleFraction"],
                     res["twoPhase"], res["bubblesPerFrame"],
                     1e3*res["meanDiameter"], 1e3*res["largest"],
                     float(np.median(rise)) if rise else float("nan"),
                     len(rise)),
        "%s: bed height %.4f m (std %.4f m) = %.3f x settled; deltaP/weight "
        "std %.3f, dominant frequency %.2f Hz"
        % (label, res["bedHeight"], res["bedHeightStd"],
           res["bedHeight"]/SETTLED, res["std"], res["frequency"])]


def record_rows(res):
    return [
        record.row("bubble fraction (bubbles of >= 3 cells)",
                   res["bubbleFraction"], reference=round(res["twoPhase"], 3),
                   reference_source="two-phase theory with Darton's D at "
                   "0.06 m (%.1f mm)" % (1e3*res["darton"]),
                   goal=record.at_least(GOAL_FRACTION),
                   note="gas fraction > 0.8 below 0.8 x the bed height; "
                   "%.2f bubbles a picture" % res["bubblesPerFrame"]),
        record.row("void cells (gas fraction > 0.8)", res["voidFraction"],
                   peer=MFIX["void"],
                   note="MFiX-PIC's below the bed height, ours below 0.8 x"),
        record.row("mean bubble diameter [mm]", 1e3*res["meanDiameter"],
                   reference=round(1e3*res["darton"], 1),
                   reference_source="Darton et al. (1977) at 0.06 m",
                   note="largest %.1f mm" % (1e3*res["largest"])),
        record.row("bed height / settled", res["bedHeight"]/SETTLED,
                   peer=MFIX["expansion"],
                   note="where the row-mean solids fraction falls through "
                   "0.1; std %.4f m (MFiX-PIC %g)"
                   % (res["bedHeightStd"], MFIX["heightStd"])),
        record.row("deltaP/weight std", res["std"], peer=MFIX["std"],
                   note="dominant frequency %.2f Hz (MFiX-PIC %g Hz)"
                   % (res["frequency"], MFIX["frequency"])),
    ]


def plots(res, case, label):
    names = ["uniformFluidization_%s_bubbles.png" % label,
             "uniformFluidization_%s_snapshots.png" % label]
    heights = np.linspace(0.005, res["bedHeight"], 30)
    edges = np.arange(0, res["top"] + 0.01, 0.02)
    bubbles.plot_diameters(
        os.path.join(case, names[0]), [(label, res["bubbles"], edges)],
        [("Darton et al. (1977), 3D beds",
          heights, bubbles.darton_diameter(U, UMF, heights))],
        title="uniform bed, 0.5 m/s, %s: bubbles over %g-%g s"
        % (label, res["t0"], res["t1"]), top=res["top"])
    xs, ys, times, eps = res["snapshots"]
    shown = np.linspace(res["t1"] - 0.5, res["t1"], 6)
    bubbles.plot_snapshots(os.path.join(case, names[1]),
                           [(label, xs, ys, times, eps)], shown,
                           top=min(ys[-1], 2*SETTLED),
                           title="uniform bed, %s: gas fraction at the "
                           "front wall" % label)
    for name in names:
        print("wrote", os.path.join(case, name))
    return names
