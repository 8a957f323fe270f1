#!/usr/bin/python3
"""Numeric checks of case results for the regression tests.

Reads OpenFOAM output directly (lagrangian fields, postProcessing tables,
logs) and compares with hand-derived references or between runs. Each
check prints one line per comparison and the script exits 1 on any failure.

Usage:
    checks.py parity <caseA> <caseB> <time> <t0> <t1> <relTol>
    checks.py serialParallel <serialCase> <parallelCase> <time>
    checks.py cloudMass <case> <time> <expectedMass> <relTol>
    checks.py fatal <log> <rc> <text> [<text> ...]
"""
import math
import os
import re
import sys

failures = 0


def report(ok, what):
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    if not ok:
        failures += 1


def read_list(path):
    """Values of a lagrangian scalar field file (ascii, N(...) or N{v})."""
    text = open(path).read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    body = re.sub(r"//.*", "", body)
    uniform = re.search(r"(\d+)\s*\{\s*([^}\s]+)\s*\}", body)
    listed = re.search(r"(\d+)\s*\(([^)]*)\)", body, re.S)
    if uniform and (not listed or uniform.start() < listed.start()):
        return [float(uniform.group(2))]*int(uniform.group(1))
    n = int(listed.group(1))
    values = [float(v) for v in listed.group(2).split()]
    assert len(values) == n, path
    return values


def parcel_masses(case, time, cloud="kinematicCloud"):
    d = os.path.join(case, time, "lagrangian", cloud)
    if not os.path.isdir(d):
        return []
    n = read_list(os.path.join(d, "nParticle"))
    dia = read_list(os.path.join(d, "d"))
    rho = read_list(os.path.join(d, "rho"))
    return sorted(ni*r*math.pi/6*di**3 for ni, di, r in zip(n, dia, rho))


def mean_delta_p(case, t0, t1, name="bedPressureDrop"):
    path = os.path.join(case, "postProcessing", name, "0", name + ".dat")
    values = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        cols = line.split()
        t = float(cols[0])
        if t0 - 1e-9 <= t <= t1 + 1e-9:
            values.append(float(cols[3]))
    return sum(values)/len(values), len(values)


def parity(a, b, time, t0, t1, tol):
    ma, mb = parcel_masses(a, time), parcel_masses(b, time)
    report(len(ma) > 0 and len(ma) == len(mb),
           "parcel count at t=%s: %d vs %d" % (time, len(ma), len(mb)))
    report(math.fsum(ma) == math.fsum(mb),
           "cloud mass at t=%s: %.15g vs %.15g kg" % (time, math.fsum(ma),
                                                     math.fsum(mb)))
    pa, na = mean_delta_p(a, float(t0), float(t1))
    pb, nb = mean_delta_p(b, float(t0), float(t1))
    rel = abs(pa - pb)/abs(pb)
    report(na == nb and rel <= float(tol),
           "mean bed pressure drop %s-%s s: %.6g vs %.6g Pa (%d/%d samples),"
           " relative difference %.3g <= %s" % (t0, t1, pa, pb, na, nb, rel, tol))


def serial_parallel(s, p, time):
    ms, mp = parcel_masses(s, time), parcel_masses(p, time)
    report(len(ms) > 0 and len(ms) == len(mp),
           "parcel count at t=%s: serial %d, parallel %d" % (time, len(ms), len(mp)))
    report(ms == mp and math.fsum(ms) == math.fsum(mp),
           "cloud mass at t=%s: serial %.17g, parallel %.17g kg"
           % (time, math.fsum(ms), math.fsum(mp)))


def cloud_mass(case, time, expected, tol):
    m = math.fsum(parcel_masses(case, time))
    expected = float(expected)
    report(abs(m - expected) <= float(tol)*expected,
           "cloud mass at t=%s: %.15g kg, expected %.15g" % (time, m, expected))


def fatal(log, rc, *texts):
    text = open(log, errors="replace").read()
    rc = int(rc)
    report(rc != 0, "exit status non-zero (%d)" % rc)
    report(rc < 128, "no crash by signal (exit status %d)" % rc)
    report("FOAM FATAL" in text, "FOAM FATAL (IO) ERROR reported")
    report("core dumped" not in text and "Segmentation" not in text,
           "no core dump, no segmentation fault")
    for t in texts:
        report(t in text, "message names '%s'" % t)


def main(argv):
    cmd, args = argv[1], argv[2:]
    {"parity": parity, "serialParallel": serial_parallel,
     "cloudMass": cloud_mass, "fatal": fatal}[cmd](*args)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
