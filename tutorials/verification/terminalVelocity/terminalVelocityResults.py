#!/usr/bin/python3
"""Terminal velocity: the parcel against an RK4 solution of eq 1.

Vaidheeswaran, Musser & Clarke (2020), section 2.1, eq 1, with y up and the
gas moving up at v_g:
    dv/dt = -g*(rho_p - rho_g)/rho_p + 3/4*rho_g/(d*rho_p)*Cd*|v_g - v|*(v_g - v)
    dy/dt = v,        y(0) = h0, v(0) = 0
RK4 with a step of 1e-5 s. The terminal velocity is
    v_t = v_g - sqrt(4/3*g*d*(rho_p - rho_g)/(rho_g*Cd)).

Usage: terminalVelocityResults.py [--case DIR] [--check] [--plot]
                                  [--record FILE]
Reads the parcel's position and velocity from every time directory
(lagrangian/kinematicCloud/positions and U) and prints, against RK4:
  - the error in the terminal velocity: v at the last time (t = 0.3 s),
    relative to RK4's;
  - the error in y(t): the largest |y - y_RK4|/y_RK4 over the times;
  - for information, the largest |v - v_RK4| over the times relative to
    |v_t|, and the largest error in the fallen distance h0 - y relative
    to itself (large at the first times: the parcel is injected during
    the first step and so lags by about one step, 1e-4 s).
With --check it exits 1 when either of the first two exceeds 0.5 %; with
--plot it writes terminalVelocity.png. With --record FILE it writes the
validation matrix's record of the case (tutorials/lib/validationRecord.py):
the terminal velocity against RK4's and the y(t) error, each goal 0.5 %.
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

g, rhop, rhog, d, Cd, vg = 9.81, 2000.0, 1.2, 1e-4, 1.0, 0.4


def rhs(v):
    rel = vg - v
    return -g*(rhop - rhog)/rhop + 0.75*rhog/(d*rhop)*Cd*abs(rel)*rel


def rk4(h0, times, h=1e-5):
    """y and v at the given (sorted) times."""
    t, y, v = 0.0, h0, 0.0
    out = []
    for target in times:
        while t < target - 1e-12:
            dt = min(h, target - t)
            k1v, k1y = rhs(v), v
            k2v, k2y = rhs(v + 0.5*dt*k1v), v + 0.5*dt*k1v
            k3v, k3y = rhs(v + 0.5*dt*k2v), v + 0.5*dt*k2v
            k4v, k4y = rhs(v + dt*k3v), v + dt*k3v
            v += dt/6*(k1v + 2*k2v + 2*k3v + k4v)
            y += dt/6*(k1y + 2*k2y + 2*k3y + k4y)
            t += dt
        out.append((y, v))
    return out


def parcel(case, time):
    """Height and vertical velocity of the (one) parcel at a time."""
    base = os.path.join(case, time, "lagrangian", "kinematicCloud")
    y = post.lagrangian_field(os.path.join(base, "positions"))[0][1]
    v = post.lagrangian_field(os.path.join(base, "U"))[0][1]
    return y, v


def settings(case):
    """What the run used, from its constant/kinematicCloudProperties and
    system/controlDict."""
    return record.parcel_settings(case, ("Cd", "feedback"))


def write_record(args, times, sim, ref, vt, y_err):
    """The validation matrix's record (--record FILE)."""
    rows = [
        record.row("terminal velocity at t = %g s [m/s]" % times[-1][0],
                   sim[-1][1], reference=ref[-1][1],
                   reference_source="RK4 of eq 1",
                   goal=record.within(0.005),
                   note="analytical v_t %.4f m/s, RK4 at %.1f %% of it"
                   % (vt, 100*ref[-1][1]/vt)),
        record.row("largest relative y(t) error over %d output times"
                   % len(times), y_err, goal=record.at_most(0.005),
                   note="|y - y_RK4|/y_RK4 as a fraction"),
    ]
    record.write(args.record, "terminalVelocity", rows,
                 plots=["terminalVelocity.png"] if args.plot else [],
                 settings=settings(args.case))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--case", default=".")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--plot", action="store_true")
    record.add_record_argument(parser)
    args = parser.parse_args()

    h0 = float(re.search(r"\(\s*\(\s*\S+\s+(\S+)\s+\S+\s*\)",
                         open(os.path.join(args.case, "constant",
                                           "kinematicCloudPositions")).read()
                         .split("//")[-1]).group(1))
    times = sorted((float(t), t) for t in os.listdir(args.case)
                   if re.fullmatch(r"[0-9.e+-]+", t) and float(t) > 0
                   and os.path.isdir(os.path.join(args.case, t, "lagrangian")))
    sim = [parcel(args.case, name) for _, name in times]
    ref = rk4(h0, [t for t, _ in times])

    vt = vg - math.sqrt(4/3*g*d*(rhop - rhog)/(rhog*Cd))
    end_err = abs(sim[-1][1] - ref[-1][1])/abs(ref[-1][1])
    y_err = max(abs(s[0] - r[0])/r[0] for s, r in zip(sim, ref))
    v_err = max(abs(s[1] - r[1]) for s, r in zip(sim, ref))/abs(vt)
    fall_err = max(abs(s[0] - r[0])/abs(h0 - r[0]) for s, r in zip(sim, ref))

    print("terminal velocity v_t = %.6f m/s (analytical); at t = %g s: parcel "
          "%.6f, RK4 %.6f (%.3f %% of v_t)" % (vt, times[-1][0], sim[-1][1],
                                              ref[-1][1], 100*ref[-1][1]/vt))
    print("terminal velocity error %.4f %%, largest y(t) error %.4f %% "
          "(%d times); largest velocity error %.3f %% of v_t, fallen distance "
          "%.3f %%" % (100*end_err, 100*y_err, len(times), 100*v_err,
                       100*fall_err))

    if args.plot:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        t = [x for x, _ in times]
        fine = [i*0.002 for i in range(int(t[-1]/0.002) + 1)]
        ref_fine = rk4(h0, fine)
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
        ax1.plot(fine, [r[1] for r in ref_fine], "k-", label="RK4, eq 1")
        ax1.plot(t, [s[1] for s in sim], "o", ms=4, label="mppicPimpleFoam")
        ax1.axhline(vt, color="gray", ls="--", lw=0.8, label="terminal velocity")
        ax1.set_xlabel("t [s]")
        ax1.set_ylabel("parcel velocity v [m/s]")
        ax1.legend()
        ax2.plot(fine, [r[0] for r in ref_fine], "k-", label="RK4, eq 1")
        ax2.plot(t, [s[0] for s in sim], "o", ms=4, label="mppicPimpleFoam")
        ax2.set_xlabel("t [s]")
        ax2.set_ylabel("parcel height y [m]")
        ax2.legend()
        fig.suptitle("Terminal velocity, Cd = 1, gas 0.4 m/s up")
        fig.tight_layout()
        fig.savefig(os.path.join(args.case, "terminalVelocity.png"), dpi=100)

    if args.record:
        write_record(args, times, sim, ref, vt, y_err)

    if args.check and max(end_err, y_err) > 0.005:
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
