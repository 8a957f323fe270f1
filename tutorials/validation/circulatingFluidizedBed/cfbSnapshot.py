#!/usr/bin/python3
"""Snapshot of the solids in the loop: the parcels of one written time
projected on the x-y plane (the loop's plane), coloured by their speed.

Reads <case>/<time>/lagrangian/kinematicCloud/positions (OpenFOAM v1912
ASCII: one "(x y z) celli" per parcel) and U.

Usage:
    cfbSnapshot.py [--case DIR] --time T [--out PNG]
"""
import argparse
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR")
                                or os.path.join(HERE, "..", "..", ".."),
                                "tutorials", "lib"))
import mppicPost as post  # noqa: E402 (tutorials/lib)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--case", default=".")
    parser.add_argument("--time", required=True)
    parser.add_argument("--out", default=None)
    args = parser.parse_args()
    cloud = os.path.join(args.case, args.time, "lagrangian", "kinematicCloud")
    positions = [tuple(r[:3]) for r in
                 post.lagrangian_field(os.path.join(cloud, "positions"))]
    velocities = [tuple(r) for r in post.lagrangian_field(os.path.join(cloud, "U"))]
    if len(positions) != len(velocities) or not positions:
        print("cfbSnapshot: %d positions, %d velocities in %s"
              % (len(positions), len(velocities), cloud))
        return 1
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    speed = [math.sqrt(u*u + v*v + w*w) for u, v, w in velocities]
    fig, ax = plt.subplots(figsize=(4.2, 8))
    dots = ax.scatter([p[0] for p in positions], [p[1] for p in positions],
                      c=speed, s=0.4, cmap="viridis", vmin=0, vmax=2)
    fig.colorbar(dots, ax=ax, label="parcel speed [m/s]", shrink=0.6)
    ax.set_aspect("equal")
    ax.set_xlim(-0.02, 0.33)
    ax.set_ylim(0, 1.33)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("%d parcels at t = %s s" % (len(positions), args.time), fontsize=9)
    fig.tight_layout()
    out = args.out or os.path.join(args.case, "cfb_snapshot_%s.png" % args.time)
    fig.savefig(out, dpi=110)
    print("wrote " + out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
