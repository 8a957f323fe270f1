#!/usr/bin/python3
"""Settling and filling fronts of the settling-shock case at t = 1 s.

Usage:
    settlingShocksResults.py [--case DIR] [--time T] [--tolerance M]
                             [--check] [--plot] [--record FILE]

Reads <time>/alpha.kinematicCloud (cell solids fraction), 0/C (cell
centres) and system/mppicSeedParcelsDict (initial solids fraction, top of
the suspension) and averages the solids fraction over each horizontal layer
of cells. Fronts (linear interpolation between layer centres):
  - settling front: the highest height where the layer profile falls
    through eps_s0/2 (the top of the suspension);
  - filling front: the lowest height above the bottom where it falls
    through (eps_s* + eps_s0)/2 (the top of the packed bed).
References (Vaidheeswaran et al. 2020, eqs 6-8), with Stokes drag and the
voidage factor of eq 7,  u_r(eg) = g*(rho_p - rho_g)*d^2/(18*mu)*eg^3.65:
  settling  y = y0 - t*eg0*u_r(eg0)                                  (eq 6)
  filling   y = -t*(es*eg*u_r(eg*) - es0*eg0*u_r(eg0))/(es* - es0)    (eq 8)
            with es* = 0.6, the close-pack SOLIDS fraction of the case
            (eg* = 0.4): the seed's reference, in which the packed layer
            still carries the hindered-settling flux es*eg*u_r(eg*);
  filling, packed bed at rest (no solids flux through a bed on a wall):
            y = t*es0*eg0*u_r(eg0)/(es* - es0)
  settling from the parcels' start velocity v0 (U0 of the injection in
  constant/kinematicCloudProperties; 0, at rest, as the seed poses it): a
  parcel of the suspension (OpenFOAM's equation, no added mass:
  dv/dt = g' - v/tau with the return flow of the liquid, v = -eg0*u_r0 at
  equilibrium) relaxes from v0 with tau = rho_p*d^2/(18*mu)*eg0^3.65*eg0:
            y = y0 - eg0*u_r0*t + (v0 + eg0*u_r0)*tau*(1 - exp(-t/tau))
  From rest the front lags eq 6 by eg0*u_r0*tau*(1 - exp(-t/tau)); started
  at the hindered velocity (./Allrun ... moving), v0 = -eg0*u_r0, it is
  eq 6 itself, the state eq 6 assumes from t = 0;
and MFiX-PIC's fronts (the seed's tables 3 and 4).
--hindered-velocity ES0 prints eg0*u_r(eg0) [m/s] (Allrun's start velocity).
--tableHead, --row [--label L --wallTime S --failure TEXT]: bin/compareSolvers's
header and the run's two rows (settling, filling).
Prints the table row; --check: exit 1 unless both fronts are within the
tolerance of the reference: --reference exact (default: settling from the start,
filling with the bed at rest, tolerance 0.005 m by default) or seed (eqs 6
and 8, tolerance 0.010 m by default); --plot: settlingShocks_<es0>.png.
--record FILE: the validation matrix's record (tutorials/lib/
validationRecord.py, case settlingShocks-<es0>): both fronts against the
exact solutions, within 0.010 m, with MFiX-PIC's (at 1 s), and the largest
layer solids fraction.
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

G = post.G
RHO_P, RHO_G, D_P, MU = 2000.0, 1000.0, 1e-3, 1e-3
CLOSE_PACK = 0.6

# Vaidheeswaran et al. (2020), tables 3 and 4: MFiX-PIC fronts at 1 s [m]
MFIX_PIC = {0.10: (0.455, 0.067), 0.15: (0.521, 0.093), 0.20: (0.583, 0.107)}


def slip(eg):
    """Eq 7: Stokes slip with the voidage factor."""
    return G*(RHO_P - RHO_G)*D_P**2/(18*MU)*eg**3.65


def references(es0, y0, t, v0=0.0):
    eg0, egp = 1 - es0, 1 - CLOSE_PACK
    settling = y0 - t*eg0*slip(eg0)
    filling = -t*(CLOSE_PACK*egp*slip(egp) - es0*eg0*slip(eg0)) \
        / (CLOSE_PACK - es0)
    filling_at_rest = t*es0*eg0*slip(eg0)/(CLOSE_PACK - es0)
    tau = RHO_P*D_P**2/(18*MU)*eg0**3.65*eg0
    settling_from_start = \
        settling + (v0 + eg0*slip(eg0))*tau*(1 - math.exp(-t/tau))
    return settling, filling, filling_at_rest, settling_from_start


def start_velocity(case):
    """The vertical component of the injection's U0 (0 if absent)."""
    text = open(os.path.join(case, "constant",
                             "kinematicCloudProperties")).read()
    m = re.search(r"\n\s*U0\s+\(\s*(\S+)\s+(\S+)\s+(\S+)\s*\)", text)
    return float(m.group(2)) if m else 0.0


def seeding(case):
    text = open(os.path.join(case, "system", "mppicSeedParcelsDict")).read()
    es0 = float(re.search(r"\n\s*solidsFraction\s+([^;]+);", text).group(1))
    box = re.search(r"\n\s*box\s+\(([^)]*)\)\s*\(([^)]*)\)", text)
    return es0, float(box.group(2).split()[1])


def layer_profile(case, time):
    return post.layer_means(
        post.internal_field(os.path.join(case, time, "alpha.kinematicCloud")),
        post.internal_field(os.path.join(case, "0", "C")))


def summary(case, time):
    """The fronts of the run in case at time, with their references."""
    es0, y0 = seeding(case)
    ys, profile = layer_profile(case, time)
    v0 = start_velocity(case)
    return dict(es0=es0, ys=ys, profile=profile, v0=v0,
                settling=post.profile_crossing(ys, profile, es0/2,
                                               from_top=True),
                filling=post.profile_crossing(ys, profile,
                                              (CLOSE_PACK + es0)/2,
                                              from_top=False),
                refs=references(es0, y0, float(time), v0),
                mfix=MFIX_PIC.get(round(es0, 2), (float("nan"), float("nan"))))


TABLE_HEAD = ("| run | front | ours [m] | eq 6/8 [m] | ours - eq 6/8 | "
              "exact [m] | ours - exact | MFiX-PIC [m] | max layer eps_s | "
              "wall time [s] | failed |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|")


def table_rows(res, label, wall, failure):
    """Two rows (settling, filling) of TABLE_HEAD; exact: from the start for
    the settling front, the bed at rest for the filling front."""
    refs, mfix = res["refs"], res["mfix"]
    rows = []
    for name, ours, ref, exact, theirs in (
            ("settling", res["settling"], refs[0], refs[3], mfix[0]),
            ("filling", res["filling"], refs[1], refs[2], mfix[1])):
        rows.append("| %s | %s | %.4f | %.4f | %+.4f | %.4f | %+.4f | %.3f | "
                    "%.3f | %s | %s |" % (
                        label or "%.2f" % res["es0"], name, ours, ref,
                        ours - ref, exact, ours - exact, theirs,
                        max(res["profile"]), "%.0f" % wall if wall else "-",
                        failure or "no"))
    return "\n".join(rows)


def record_rows(res, time):
    """The record's rows: the fronts against the exact solutions (settling
    from the parcels' start, filling with the bed at rest), MFiX-PIC's at
    1 s, and the largest layer solids fraction."""
    refs = res["refs"]
    at_one = abs(float(time) - 1) < 1e-9

    def value(x):
        return None if x is None or math.isnan(x) else x
    rows = []
    for i, (name, ours, exact, seed, what) in enumerate((
            ("settling", res["settling"], refs[3], refs[0],
             "settling from the parcels' start, %s"
             % ("at %+.4f m/s" % res["v0"] if res["v0"] else "at rest")),
            ("filling", res["filling"], refs[2], refs[1],
             "filling with the bed at rest"))):
        rows.append(record.row(
            "%s front at %s s [m]" % (name, time), value(ours),
            reference=exact,
            reference_source="exact: %s (settlingShocksResults.py)" % what,
            peer=value(res["mfix"][i]) if at_one else None,
            goal=record.within(0.010, absolute=True),
            note="seed 2 eq %s: %.4f m; MFiX-PIC: seed 2 Tables 3-4%s"
            % ("6" if i == 0 else "8", seed,
               "" if at_one else ", at 1 s only")))
    rows.append(record.row(
        "largest layer solids fraction", max(res["profile"]),
        reference=CLOSE_PACK, reference_source="close pack",
        note="informational (layer means of alpha.kinematicCloud)"))
    return rows


def plot(ys, profile, es0, fronts, refs, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(5, 6))
    ax.plot(profile, ys, "k.-", ms=3, label="mppicPimpleFoam, layer mean")
    colours = ("tab:blue", "tab:red")
    for (name, ours, ref), c in zip(
            (("settling", fronts[0], refs[0]),
             ("filling", fronts[1], refs[1])), colours):
        ax.axhline(ours, color=c, ls="-", lw=1,
                   label="%s front, ours %.4f m" % (name, ours))
        ax.axhline(ref, color=c, ls="--", lw=1,
                   label="%s front, eq %s %.4f m"
                   % (name, "6" if name == "settling" else "8", ref))
    ax.axhline(refs[2], color="tab:green", ls=":", lw=1,
               label="filling, bed at rest %.4f m" % refs[2])
    ax.axhline(refs[3], color="tab:purple", ls=":", lw=1,
               label="settling from the start %.4f m" % refs[3])
    if es0 in MFIX_PIC:
        for v in MFIX_PIC[es0]:
            ax.plot([0.02], [v], "o", mfc="none", color="gray")
        ax.plot([], [], "o", mfc="none", color="gray", label="MFiX-PIC fronts")
    ax.set_xlabel("solids fraction (layer mean)")
    ax.set_ylabel("height y [m]")
    ax.set_xlim(0, 0.7)
    ax.set_ylim(0, 1)
    ax.set_title("Settling shocks, eps_s0 = %.2f, t = 1 s" % es0)
    ax.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = post.results_parser(None, __doc__.split("\n")[0])
    parser.add_argument("--time", default="1")
    parser.add_argument("--reference", choices=("exact", "seed"),
                        default="exact")
    parser.add_argument("--tolerance", type=float)
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--plot", action="store_true")
    parser.add_argument("--hindered-velocity", type=float, metavar="ES0")
    record.add_record_argument(parser)
    args = post.parse_results_args(parser, TABLE_HEAD)
    if args.hindered_velocity is not None:
        es0 = args.hindered_velocity
        if not 0 < es0 < CLOSE_PACK:
            print("--hindered-velocity %g: not in (0, %g)"
                  % (es0, CLOSE_PACK), file=sys.stderr)
            return 2
        print("%.6g" % ((1 - es0)*slip(1 - es0)))
        return 0

    res = summary(args.case, args.time)
    if args.row:
        print(table_rows(res, args.label, args.wallTime, args.failure))
        return 0
    es0, ys, profile = res["es0"], res["ys"], res["profile"]
    settling, filling, refs = res["settling"], res["filling"], res["refs"]
    mfix = res["mfix"]

    print("start velocity of the parcels %+.4f m/s" % res["v0"])
    print("eps_s0 | front | ours [m] | eqs 6/8 [m] | ours - ref [m] | "
          "from the start / bed at rest [m] | ours - that [m] | "
          "MFiX-PIC [m]")
    print("%.2f | settling | %.4f | %.4f | %+.4f | %.4f | %+.4f | %.3f"
          % (es0, settling, refs[0], settling - refs[0], refs[3],
             settling - refs[3], mfix[0]))
    print("%.2f | filling | %.4f | %.4f | %+.4f | %.4f | %+.4f | %.3f"
          % (es0, filling, refs[1], filling - refs[1], refs[2],
             filling - refs[2], mfix[1]))
    print("max layer solids fraction %.4f (close pack %.2f)"
          % (max(profile), CLOSE_PACK))

    png = "settlingShocks_%.2f.png" % es0
    if args.plot:
        path = os.path.join(args.case, png)
        plot(ys, profile, round(es0, 2), (settling, filling), refs, path)
        print("wrote " + path)
    if args.record:
        record.write(args.record, "settlingShocks-%.2f" % es0,
                     record_rows(res, args.time),
                     plots=[png] if args.plot else [],
                     settings="%s; parcels start %s" % (
                         record.case_settings(args.case), "at %+.4f m/s" % res["v0"]
                         if res["v0"] else "at rest"))

    ok = True
    if args.check:
        seed = args.reference == "seed"
        tol = args.tolerance or (0.010 if seed else 0.005)
        targets = ((refs[0], "eq 6"), (refs[1], "eq 8")) if seed else \
            ((refs[3], "from the start"), (refs[2], "bed at rest"))
        for (name, ours), (ref, what) in zip(
                (("settling", settling), ("filling", filling)), targets):
            good = abs(ours - ref) <= tol
            print("%s %s front %.4f m within %.3f m of %.4f m (%s)"
                  % ("PASS" if good else "FAIL", name, ours, tol, ref, what))
            ok = ok and good
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
