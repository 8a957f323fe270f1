#!/usr/bin/python3
"""Helpers and checks of tests/regression/splitParcels.sh: bin/splitParcels
on tutorials/validation/uniformFluidization (hexahedra, a prescribed uniform
gas flow), ascii at 17 digits, run to 0.01 s and its cloud split into
K = 4 (case/0.01, against the 0.01 s cloud kept aside in before/).

split, on the written split:
  - 4 N parcels (positions and U); copy k of parcel i (entry K i + k) has
    parcel i's U, d and rho as written, nParticle/4 to 1e-15
    (|K n_copy/n_i - 1|), and origId 4 origId_i + k, all 4 N unique;
  - every cell (the positions' cell label) holds the solids volume
    sum nParticle pi/6 d^3 it held, to 1e-12 relative;
  - every copy lies between the parcel and its cell's centre (0.01/C, else
    0/C), 1-50 % of the way: with f the copy's displacement projected on
    the segment to the centre, over its length, and off its distance from
    the segment, every f >= 0.01 and f + off/length <= 0.5 (the geometry
    that keeps it in a convex cell);
solver, after the solver read it and ran one step (case/log.split):
  - no parcel initialised outside the mesh, no FOAM FATAL;
  - 4 N parcels at the new time, and the cloud's mass (sum nParticle rho
    pi/6 d^3, checks.lagrangian_masses) that of the 0.01 s cloud to 1e-12.
And two helpers of the bad inputs: badNParticle prints 1.01 nParticle/4
(--nParticle 1 % off nParticle/K), oneShort makes a uniform list N{v}
(N - 1){v}.

Usage (split, solver: in the run folder that holds case/ and before/):
    splitParcels.py badNParticle <nParticle>
    splitParcels.py oneShort <field file>
    splitParcels.py split
    splitParcels.py solver
"""
import glob
import math
import os
import re
import sys

import checks
from checks import lagrangian_masses, report as check

K = 4


def bad_nparticle(nP):
    """--nParticle 1 % off nParticle/K, as bash reads it."""
    print(repr(1.01*float(nP)/4))


def one_short(path):
    """A uniform list N{v} becomes (N - 1){v}."""
    s = open(path).read()
    open(path, "w").write(re.sub(r"(?m)^(\d+)\{", lambda m: "%d{" % (int(m.group(1)) - 1), s))


def items(path):
    """The entries of a field file's list as written (strings): a uniform
    N{v} expanded, a lagrangian positions entry "(a b c d) celli"."""
    text = open(path).read()
    body = re.sub(r"//[^\n]*", "", text[text.index("}", text.index("FoamFile")) + 1:])
    if "internalField" in body:
        body = body[body.index("internalField"):body.index("boundaryField")]
        body = body[body.index(">") + 1:body.rindex(";")]
    m = re.match(r"\s*(\d+)\s*\{(.*?)\}", body, re.S)
    if m:
        return [m.group(2).strip()]*int(m.group(1))
    inner = body[body.index("(") + 1:body.rindex(")")]
    return re.findall(r"\([^()]*\)(?:[ \t]+\d+)?", inner) if "(" in inner else inner.split()


def vec(s):
    return [float(v) for v in s[s.index("(") + 1:s.index(")")].split()]


def cell_volumes(pos, nP, d):
    """Solids volume of each cell, from the positions' cell labels."""
    out = {}
    for p, a, b in zip(pos, nP, d):
        c = int(p.split(")")[1])
        out[c] = out.get(c, 0.0) + a*math.pi/6*b**3
    return out


def check_split():
    old, new = "before/lagrangian/kinematicCloud", "case/0.01/lagrangian/kinematicCloud"
    n = len(items(old + "/U"))
    pos0 = items(old + "/positions")
    pos1 = items(new + "/positions")
    check(len(pos1) == K*n and len(items(new + "/U")) == K*n,
          "%d parcels split into %d (K = %d)" % (n, len(pos1), K))
    same = True
    for f in ("U", "d", "rho"):
        a, b = items(old + "/" + f), items(new + "/" + f)
        same = same and all(b[K*i + k] == a[i] for i in range(n) for k in range(K))
    check(same, "every copy has its parcel's U, d and rho as written")
    n0 = [float(v) for v in items(old + "/nParticle")]
    n1 = [float(v) for v in items(new + "/nParticle")]
    worst = max(abs(K*n1[K*i + k]/n0[i] - 1) for i in range(n) for k in range(K))
    check(worst <= 1e-15, "nParticle of a copy = the parcel's / %d (largest difference %.2e <= 1e-15)"
          % (K, worst))
    ids0 = [int(v) for v in items(old + "/origId")]
    ids1 = [int(v) for v in items(new + "/origId")]
    check(ids1 == [K*v + k for v in ids0 for k in range(K)] and len(set(ids1)) == K*n,
          "origId of copy k = %d origId + k, all %d unique" % (K, len(set(ids1))))

    d0 = [float(v) for v in items(old + "/d")]
    d1 = [float(v) for v in items(new + "/d")]
    v0, v1 = cell_volumes(pos0, n0, d0), cell_volumes(pos1, n1, d1)
    worst = max(abs(v1.get(c, 0.0)/v - 1) for c, v in v0.items())
    check(set(v0) == set(v1) and worst <= 1e-12,
          "%d cells hold the solids volume they held (largest difference %.2e <= 1e-12)"
          % (len(v0), worst))

    C = [vec(c) for c in items("case/0.01/C" if os.path.isfile("case/0.01/C") else "case/0/C")]
    worstF = (1.0, 0.0)
    for i, p in enumerate(pos0):
        x, c = vec(p), int(p.split(")")[1])
        for k in range(K):
            q = vec(pos1[K*i + k])
            to = [C[c][j] - x[j] for j in range(3)]
            f = sum((q[j] - x[j])*to[j] for j in range(3))/max(sum(t*t for t in to), 1e-300)
            off = math.sqrt(sum((q[j] - x[j] - f*to[j])**2 for j in range(3)))
            worstF = (min(worstF[0], f), max(worstF[1], f + off/math.sqrt(sum(t*t for t in to))))
    check(0.01 - 1e-9 <= worstF[0] and worstF[1] <= 0.5 + 1e-9,
          "every copy on the segment to its cell's centre, fraction %.4f to %.4f (within 0.01-0.5)"
          % worstF)


def mass(lag):
    """Parcels and cloud mass of a lagrangian cloud folder."""
    masses = lagrangian_masses(lag)
    return len(masses), math.fsum(masses)


def check_solver_read_split():
    log = open("case/log.split").read()
    check("outside of the mesh" not in log and "FOAM FATAL" not in log,
          "the solver read the split cloud: no parcel outside the mesh")
    t = max((x for x in glob.glob("case/0.01*") if x != "case/0.01"),
            key=lambda x: float(os.path.basename(x)))
    n0, m0 = mass("before/lagrangian/kinematicCloud")
    n1, m1 = mass(os.path.join(t, "lagrangian", "kinematicCloud"))
    check(n1 == 4*n0, "after one step at %s s: %d parcels (4 x %d)" % (os.path.basename(t), n1, n0))
    check(abs(m1/m0 - 1) <= 1e-12, "cloud mass %.15g kg = before the split %.15g (%.2e <= 1e-12)"
          % (m1, m0, abs(m1/m0 - 1)))


def main(argv):
    return checks.run_command(argv, {
        "badNParticle": bad_nparticle, "oneShort": one_short,
        "split": check_split, "solver": check_solver_read_split})


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
