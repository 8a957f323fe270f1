"""The validation matrix's record of a Kuipers jet run (kuipersJetResults.py
--record FILE; tutorials/lib/validationRecord.py), from the summary dict of
kuipersJetResults.summary():
  - deltaP over the statistics window / bed weight, at least 0.90, beside
    MFiX-PIC's mean of seed 1 Fig. 7 over 20-24 s (kuipersJetPressureDrop.csv);
  - the mean |difference| of the time-averaged profiles from Kuipers'
    measured points at 3.4 and 6.4 cm from the axis (kuipersJetProfiles.csv),
    at most 0.035 and 0.058, beside MFiX-PIC's own (its curve of seed 1
    Fig. 6 against the same points);
    (and, in its note, where the rest of the weight goes: the packing step,
    the walls);
  - the slab measure: the instants of the window at which a packed slab
    lies over a gas void, none (Kuipers saw none);
  - the largest cell solids fraction against the script's bound
    max(1.05 alpha_cp, alpha_cp + one parcel).
The settings are read from the case's files: the packing model and its
coefficients, the deposit, the drag, PIMPLE's switches, serial or ranks.
"""
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)

CASE = "kuipersJet"
# the goals (issue 63): deltaP/weight at least 0.90; the profiles' mean
# |difference| from Kuipers' points at most MFiX-PIC's, 0.035 and 0.058
DP_GOAL = 0.90
MAD_GOALS = {3.4: 0.035, 6.4: 0.058}


def mfix_pic_ratio():
    """MFiX-PIC's mean deltaP over the seed's bed weight: the mfix_pic rows
    of kuipersJetPressureDrop.csv (seed 1 Fig. 7, 20-24 s) over the weight
    per area its header gives ('= 7825 Pa'); None without them."""
    path = os.path.join(HERE, "kuipersJetPressureDrop.csv")
    text = open(path).read()
    weight = re.search(r"=\s*([0-9.]+)\s*Pa", text)
    dp = [float(line.split(",")[2]) for line in text.splitlines()
          if line.startswith("mfix_pic,")]
    if not weight or not dp:
        return None
    return 1e3*sum(dp)/len(dp)/float(weight.group(1))


def finite(value):
    """value, or None for a missing or nan figure (JSON has no nan)."""
    return value if value is not None and math.isfinite(value) else None


def weight_shares(res):
    """Where the bed's weight goes over the window (the goal's fallback when
    deltaP carries less than 0.90 of it): '' without the packing budget."""
    if res.get("packing") is None or res.get("walls") is None:
        return ""
    return ("; the weight carried by the gas (deltaP) %.3f, the packing step "
            "(held packs on the distributor and the walls) %.3f, the rest "
            "(walls; drag beyond the gas's pressure drop) %.3f"
            % (res["dpRatio"], res["packing"], res["walls"]))


def rows(res, case):
    """The record's rows from kuipersJetResults.summary() of the run in case."""
    mad = res.get("mad", {})
    # the profiles are fieldAverage's, from averageStart whatever --from says
    start = post.control_entry(case, "averageStart")
    out = [record.row(
        "deltaP / bed weight", finite(res.get("dpRatio")), reference=1.0,
        reference_source="the bed's weight (no measured deltaP is public)",
        peer=finite(mfix_pic_ratio()), goal=record.at_least(DP_GOAL),
        note="MFiX-PIC: seed 1 Fig. 7, 20-24 s (kuipersJetPressureDrop.csv); "
        "ours: std %s Pa, amplitude (half 5-95 %% range) %s Pa%s"
        % ("%.0f" % res["dpStd"] if "dpStd" in res else "-",
           "%.0f" % res["dpAmplitude"] if "dpAmplitude" in res else "-",
           weight_shares(res)))]
    for x_cm in (3.4, 6.4):
        out.append(record.row(
            "profile at %.1f cm: mean |difference| from Kuipers' points" % x_cm,
            finite(mad.get(("ours", x_cm))),
            reference_source="Kuipers (1990), measured, seed 1 Fig. 6 "
            "(kuipersJetProfiles.csv)",
            peer=finite(mad.get(("mfix_pic", x_cm))),
            goal=record.at_most(MAD_GOALS[x_cm]),
            note="solids fraction time-averaged from averageStart %s s, left "
            "and right averaged" % start))
    if res.get("slab") is not None:
        out.append(record.row(
            "instants with a packed slab over a gas void",
            int(round(res["slab"]*res["slabCount"])),
            goal=record.at_most(0),
            note="of %d instants (%s) in the window: %.1f %%"
            % (res["slabCount"], res["slabSource"], 100*res["slab"])))
    if "maxCell" in res:
        out.append(record.row(
            "largest cell solids fraction", res["maxCell"],
            reference=round(res["bound"], 4),
            reference_source="max(1.05 x alpha_cp, alpha_cp + one parcel %.4f)"
            % res["parcelFraction"],
            goal=record.at_most(res["bound"] + 1e-12),
            note="over every step; 99th percentile of the per-step largest "
            "%.4f" % res["p99Cell"]))
    return out


def write(path, res, case, plots=()):
    """Write the record of the run in case (nothing when path is None)."""
    if not path:
        return
    record.write(path, CASE, rows(res, case), plots=plots, settings=record.case_settings(case),
                 window="%g-%s s" % (res["t0"], "%g" % res["endTime"]
                                     if "endTime" in res else "?"))
