#!/usr/bin/python3
"""Deposition conservation: gas plus parcel volume against the box volume.

Vaidheeswaran, Musser & Clarke (2020), section 2.2.2, Table 2: at every
period t = k*T the volume of the gas, from the gas fraction the solver
writes, plus the volume of the parcels, from the parcels themselves,
must be the volume of the box:

    error = |sum_cells eps_g V + sum_parcels n pi/6 d^3 - V_total|/V_total

with eps_g = alpha.<gas> (= 1 - alpha.<cloud> below the alphaMax limit)
and V the cell volumes (0/V, postProcess -func writeCellVolumes),
V_total = sum V. Also printed: the solids volume the mesh holds,
sum (1 - eps_g) V, against the parcels' own, relative to the latter (a
stricter view: the parcels are 2.5e-4 of the box). Sums are exact
(math.fsum) of the values as written (17 digits).

Usage: depositionConservationResults.py [--case DIR] [--period T]
           [--label NAME] [--check] [--limit L] [--plot] [--record FILE]
--check exits 1 unless every period has all parcels and an error at most
--limit (default 1e-14); --plot writes depositionConservation_<label>.png;
--record FILE writes the validation matrix's record of the case
(tutorials/lib/validationRecord.py): the largest error against --limit and
MFiX-PIC's, the parcels present and the deposited solids' error.
"""
import argparse
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


GAS, CLOUD = "air", "kinematicCloud"
# MFiX-PIC, seed 2 Table 2: the largest absolute volume error (box 1 m3)
MFIX_ERROR = 1.67e-15


def field_values(path):
    """Values of a scalar field file: a volScalarField's internalField or
    a lagrangian field, uniform or listed."""
    text = post.read_text(path)
    text = re.sub(r"//.*", "", text[text.index("}", text.index("FoamFile")):])
    start = text.find("internalField")
    text = text[start:] if start >= 0 else text
    uniform = re.match(r"internalField\s+uniform\s+(\S+);", text)
    if uniform:
        return None, float(uniform.group(1))
    m = re.search(r"(\d+)\s*([({])", text)
    n = int(m.group(1))
    if m.group(2) == "{":
        value = float(text[m.end():text.index("}", m.end())])
        return [value]*n, None
    values = [float(v) for v in text[m.end():text.index(")", m.end())].split()]
    assert len(values) == n, path
    return values, None


def balance(case, time, volumes):
    gas, uniform = field_values(os.path.join(case, time, "alpha." + GAS))
    if gas is None:
        gas = [uniform]*len(volumes)
    base = os.path.join(case, time, "lagrangian", CLOUD)
    n, _ = field_values(os.path.join(base, "nParticle"))
    d, _ = field_values(os.path.join(base, "d"))
    parcels = math.fsum(ni*math.pi/6*di**3 for ni, di in zip(n, d))
    total = math.fsum(volumes)
    gas_volume = math.fsum(a*v for a, v in zip(gas, volumes))
    deposited = math.fsum((1 - a)*v for a, v in zip(gas, volumes))
    return dict(nParcels=len(n), solids=parcels/total, gas=gas_volume/total,
                error=abs(math.fsum([gas_volume, parcels, -total]))/total,
                solidsError=abs(deposited - parcels)/parcels)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--case", default=".")
    parser.add_argument("--period", type=float, default=0.25)
    parser.add_argument("--label", default="basic")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--limit", type=float, default=1e-14)
    parser.add_argument("--plot", action="store_true")
    record.add_record_argument(parser)
    args = parser.parse_args()

    volumes, _ = field_values(os.path.join(args.case, "0", "V"))
    rows = []
    for name in os.listdir(args.case):
        if not re.fullmatch(r"[0-9.e+-]+", name) or float(name) <= 0:
            continue
        k = round(float(name)/args.period)
        if abs(float(name) - k*args.period) < 1e-9 and os.path.isdir(
                os.path.join(args.case, name, "lagrangian", CLOUD)):
            rows.append((k, float(name), balance(args.case, name, volumes)))
    rows.sort(key=lambda r: r[0])
    nStart = sum(1 for line in post.read_text(os.path.join(
        args.case, "constant", "kinematicCloudPositions")).splitlines()
        if line.startswith("(") and line.strip() != "(")

    print("averaging %s: %d cells, %d parcels at the start"
          % (args.label, len(volumes), nStart))
    print("| period | t [s] | parcels | solids fraction | gas fraction | "
          "error (gas + parcels vs box) | deposited vs parcel solids |")
    print("|---|---|---|---|---|---|---|")
    for k, t, b in rows:
        print("| %d | %.2f | %d | %.6e | %.15f | %.2e | %.2e |"
              % (k, t, b["nParcels"], b["solids"], b["gas"], b["error"],
                 b["solidsError"]))

    if args.plot and rows:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.2))
        floor = 1e-18   # zero errors drawn at the bottom of the axis
        ax.semilogy([r[0] for r in rows],
                    [max(r[2]["error"], floor) for r in rows], "o-",
                    label="gas + parcels vs box, / V_total")
        ax.semilogy([r[0] for r in rows],
                    [max(r[2]["solidsError"], floor) for r in rows], "s--",
                    label="deposited vs parcel solids, / V_solids")
        ax.axhline(args.limit, color="r", ls=":", lw=1,
                   label="goal %.0e" % args.limit)
        ax.set_ylim(floor/2, 1e-10)
        ax.set_xlabel("period k (t = k T, T = %g s)" % args.period)
        ax.set_ylabel("relative volume error")
        ax.set_title("Deposition conservation, averaging %s (zero drawn at "
                     "1e-18)" % args.label, fontsize=10)
        ax.legend()
        ax.grid(True, which="both", lw=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(args.case, "depositionConservation_%s.png"
                                 % args.label), dpi=100)
    if args.record:
        write_record(args, rows, nStart)

    if args.check:
        worst = max((r[2]["error"] for r in rows), default=float("inf"))
        ok = bool(rows) and worst <= args.limit and all(
            r[2]["nParcels"] == nStart for r in rows)
        print("%s: largest error %.2e over %d periods, limit %.0e, all %d "
              "parcels at every period" % ("PASS" if ok else "FAIL", worst,
                                           len(rows), args.limit, nStart))
        return 0 if ok else 1
    return 0


def settings(case):
    """What the run used, from its constant/kinematicCloudProperties and
    system/controlDict."""
    path = os.path.join(case, "constant", "kinematicCloudProperties")
    text = post.read_text(path)
    method = post.dict_entry(path, "averagingMethod")
    coeffs = re.search(r"^\s*%sCoeffs\s*\{([^}]*)\}" % method, text, re.M)
    if coeffs:
        method += " (%s)" % "; ".join(
            " ".join(line.split("//")[0].split()).rstrip(";")
            for line in coeffs.group(1).splitlines()
            if line.split("//")[0].strip())
    forces = re.search(r"particleForces\s*\{\s*(\w+)", text)
    gas = os.path.join(case, "constant", "prescribedGasFlowProperties")
    return ("averagingMethod %s; solidsFractionFrom %s; packingModel %s; "
            "drag %s (C %s 1/s); gas prescribed (%s, period %s s), not "
            "solved; deltaT %s s, maxCo %s" % (
                method, post.dict_entry(path, "solidsFractionFrom") or "cell",
                post.dict_entry(path, "packingModel"),
                forces.group(1) if forces else "none",
                post.dict_entry(path, "C"), post.dict_entry(gas, "type"),
                post.dict_entry(gas, "period"),
                post.control_entry(case, "deltaT"),
                post.dict_entry(path, "maxCo")))


def write_record(args, rows, nStart):
    """The validation matrix's record (--record FILE)."""
    errors = [r[2]["error"] for r in rows]
    method = post.dict_entry(os.path.join(
        args.case, "constant", "kinematicCloudProperties"), "averagingMethod")
    label = "" if method == args.label else \
        "; run with averagingMethod %s, --label %s" % (method, args.label)
    out = [
        record.row("largest volume error |gas + parcels - box|/box over %d "
                   "periods" % len(rows), max(errors) if errors else None,
                   peer=MFIX_ERROR, goal=record.at_most(args.limit),
                   note="MFiX-PIC: seed 2 Table 2" + label),
        record.row("parcels present at every period (fewest)",
                   min((r[2]["nParcels"] for r in rows), default=None),
                   goal=record.at_least(nStart), note="%d seeded" % nStart),
        record.row("largest |deposited - parcel solids|/parcel solids",
                   max((r[2]["solidsError"] for r in rows), default=None),
                   note="for information"),
    ]
    record.write(args.record, "depositionConservation", out,
                 plots=["depositionConservation_%s.png" % args.label]
                 if args.plot and rows else [],
                 settings=settings(args.case))


if __name__ == "__main__":
    sys.exit(main())
