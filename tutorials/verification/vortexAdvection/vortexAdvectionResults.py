#!/usr/bin/python3
"""Vortex advection: largest L1 displacement of the parcels per period.

Vaidheeswaran, Musser & Clarke (2020), section 2.2.1: in the vortex of
eq 3, which reverses at T/2, a tracer is back where it started at every
multiple of T. For each output time t = k*T this prints the largest over
the parcels of |dx| + |dy| + |dz|, the displacement from the parcel's
start, next to MFiX-PIC's Table 1 (copied below from the shared reference
vortex_advection_mfix.csv).

Usage: vortexAdvectionResults.py [--case DIR] [--period T] [--check]
                                 [--limit L] [--plot] [--record FILE]
Start positions: constant/kinematicCloudPositions, parcel i there is the
parcel with origId i (manualInjection injects them in that order).
Positions at time t: <t>/lagrangian/kinematicCloud/positions (ascii,
optionally .gz: cartesian "(x y z) celli" lines, which v1912 writes beside
the barycentric 'coordinates') and origId. A displacement across a cyclic
face is unwrapped to the nearest image in the unit cube; the number of
parcels that needed it is printed.
With --check it exits 1 unless every parcel is present at every period
and the largest L1 at the last period is below --limit (default 5e-3 m);
with --plot it writes vortexAdvection.png (L1 against period, ours and
MFiX-PIC; the parcels at 0, T/2 and T of the last period when written);
with --record FILE it writes the validation matrix's record of the case
(tutorials/lib/validationRecord.py): the largest L1 at period 16 (goal
5e-3 m) and 8 against MFiX-PIC's, and the parcels present.
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)
import validationRecord as record  # noqa: E402 (tutorials/lib)


# MFiX-PIC, Table 1 of seed 2 (= /work/shared/reference/vortex_advection_mfix.csv)
MFIX_L1 = [2.11e-03, 1.22e-03, 2.59e-03, 2.44e-03, 3.46e-03, 3.65e-03,
           4.49e-03, 4.87e-03, 5.60e-03, 6.08e-03, 6.74e-03, 7.29e-03,
           7.90e-03, 8.51e-03, 9.08e-03, 9.72e-03]
CLOUD = "kinematicCloud"


def list_body(text):
    """The entries of the first N ( ... ) list after the header."""
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    body = re.sub(r"//.*", "", body)
    m = re.search(r"(\d+)\s*\(", body)
    n = int(m.group(1))
    inner = body[m.end():body.rindex(")")]
    return n, inner


def read_points(text):
    n, inner = list_body(text)
    points = [tuple(float(v) for v in m.split())
              for m in re.findall(r"\(([^()]*)\)", inner)]
    assert len(points) == n, "expected %d points, read %d" % (n, len(points))
    return points


def read_labels(text):
    n, inner = list_body(text)
    labels = [int(v) for v in inner.split()]
    assert len(labels) == n
    return labels


def parcels(case, time):
    """{origId: (x, y, z)} at the time directory `time`."""
    base = os.path.join(case, time, "lagrangian", CLOUD)
    if not os.path.exists(os.path.join(base, "origId")) \
            and not os.path.exists(os.path.join(base, "origId.gz")):
        return {}
    pos = read_points(post.read_text(os.path.join(base, "positions")))
    ids = read_labels(post.read_text(os.path.join(base, "origId")))
    return dict(zip(ids, pos))


def times(case):
    out = []
    for name in os.listdir(case):
        if re.fullmatch(r"[0-9.e+-]+", name) and float(name) > 0 \
                and os.path.isdir(os.path.join(case, name, "lagrangian")):
            out.append((float(name), name))
    return sorted(out)


def max_l1(start, now, length=1.0):
    """Largest L1 displacement and the number of unwrapped parcels."""
    worst, unwrapped = 0.0, 0
    for i, p0 in enumerate(start):
        d = [b - a for a, b in zip(p0, now[i])]
        wrapped = [x - length*round(x/length) for x in d]
        unwrapped += wrapped != d
        worst = max(worst, sum(abs(x) for x in wrapped))
    return worst, unwrapped


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--case", default=".")
    parser.add_argument("--period", type=float, default=0.25)
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--limit", type=float, default=5e-3)
    parser.add_argument("--plot", action="store_true")
    record.add_record_argument(parser)
    args = parser.parse_args()

    start = read_points(post.read_text(os.path.join(
        args.case, "constant", "kinematicCloudPositions")))
    rows, complete, fewest = [], True, len(start)
    for t, name in times(args.case):
        k = round(t/args.period)
        if abs(t - k*args.period) > 1e-9 or k < 1:
            continue
        now = parcels(args.case, name)
        fewest = min(fewest, len(now))
        complete &= len(now) == len(start)
        if len(now) != len(start):
            print("t = %s: %d parcels of %d" % (name, len(now), len(start)))
            continue
        l1, unwrapped = max_l1(start, now)
        rows.append((k, t, l1, unwrapped))

    print("| period | t [s] | max L1, ours [m] | MFiX-PIC [m] | ours/MFiX |")
    print("|---|---|---|---|---|")
    for k, t, l1, _ in rows:
        ref = MFIX_L1[k - 1] if k <= len(MFIX_L1) else float("nan")
        print("| %d | %.2f | %.3e | %.2e | %.3f |" % (k, t, l1, ref, l1/ref))
    print("parcels unwrapped across a cyclic face: %s"
          % ", ".join(str(r[3]) for r in rows))

    if args.plot and rows:
        plot(args, start, rows)
    if args.record:
        write_record(args, start, rows, fewest)

    if args.check:
        ok = complete and rows and rows[-1][2] < args.limit
        print("%s: max L1 at period %d = %.3e m, limit %.1e m, all %d parcels"
              " at every period: %s" % ("PASS" if ok else "FAIL",
                                       rows[-1][0] if rows else 0,
                                       rows[-1][2] if rows else float("nan"),
                                       args.limit, len(start), complete))
        return 0 if ok else 1
    return 0


def settings(case):
    """What the run used, from its constant/ and system/ dictionaries."""
    gas = os.path.join(case, "constant", "prescribedGasFlowProperties")
    return record.parcel_settings(
        case, ("C",), "gas prescribed (%s, period %s s), not solved"
        % (post.dict_entry(gas, "type"), post.dict_entry(gas, "period")))


def write_record(args, start, rows, fewest):
    """The validation matrix's record (--record FILE): the largest L1 at
    Table 1's last period (16) with the goal --limit, at its middle (8)
    for information, and the fewest parcels at a period."""
    l1 = {r[0]: r[2] for r in rows}
    last = len(MFIX_L1)
    out = []
    for k, goal in ((last, record.at_most(args.limit)), (last//2, None)):
        out.append(record.row(
            "largest L1 displacement at period %d (t = %g s) [m]"
            % (k, k*args.period), l1.get(k), peer=MFIX_L1[k - 1], goal=goal,
            note="MFiX-PIC: seed 2 Table 1" + (
                "" if k in l1 else "; period not written or parcels "
                "missing")))
    out.append(record.row("parcels present at every period (fewest)",
                          fewest, goal=record.at_least(len(start)),
                          note="%d seeded" % len(start)))
    record.write(args.record, "vortexAdvection", out,
                 plots=["vortexAdvection.png"] if args.plot and rows else [],
                 settings=settings(args.case))


def plot(args, start, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig = plt.figure(figsize=(12, 4.2))
    ax = fig.add_subplot(1, 2, 1)
    ax.semilogy(range(1, len(MFIX_L1) + 1), MFIX_L1, "s--", color="gray",
                label="MFiX-PIC (Table 1)")
    ax.semilogy([r[0] for r in rows], [r[2] for r in rows], "o-",
                label="mppicPimpleFoam")
    ax.axhline(args.limit, color="r", ls=":", lw=1,
               label="goal %.0e m" % args.limit)
    ax.set_xlabel("period k (t = k T, T = %g s)" % args.period)
    ax.set_ylabel("max over parcels of L1 displacement [m]")
    ax.legend()
    ax.grid(True, which="both", lw=0.3)

    last = rows[-1][0]
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    for t, label, style in ((last - 1, "t = %g s" % ((last - 1)*args.period),
                             "o"),
                            (last - 0.5, "t = %g s (T/2 later)"
                             % ((last - 0.5)*args.period), "."),
                            (last, "t = %g s (back on the first)"
                             % (last*args.period), "x")):
        name = "%g" % (t*args.period)
        pts = list(parcels(args.case, name).values()) if t > 0 else start
        if pts:
            ax3.scatter(*zip(*pts), marker=style, s=6, label=label)
    ax3.set_xlabel("x [m]")
    ax3.set_ylabel("y [m]")
    ax3.set_zlabel("z [m]")
    ax3.legend(loc="upper left", fontsize=8)
    fig.suptitle("Vortex advection, 512 parcels, 32^3 cells")
    fig.tight_layout()
    fig.savefig(os.path.join(args.case, "vortexAdvection.png"), dpi=100)


if __name__ == "__main__":
    sys.exit(main())
