#!/usr/bin/python3
"""Numeric checks of case results for the regression tests.

Reads OpenFOAM output directly (lagrangian fields, postProcessing tables,
logs) and compares with hand-derived references or between runs. Each
check prints one line per comparison and the script exits 1 on any failure.

A test's own Python (tests/regression/<name>.py beside <name>.sh) imports
it for the same lines (report) and its exit status (status()): one
pass/fail helper for every test; and for the readers they share
(read_list, read_rows, read_dat, lagrangian_masses, seeded_parcels).

Usage:
    checks.py parity <caseA> <caseB> <time> <t0> <t1> <relTol>
    checks.py serialParallel <serialCase> <parallelCase> <time>
    checks.py cloudMass <case> <time> <expectedMass> <relTol>
    checks.py fatal <log> <rc> <text> [<text> ...]
    checks.py subCycles <log> <responseTime> <factor>
    checks.py subCyclesCFL <case> <log> <CFL> <cellHeight>
    checks.py balance <case> <specie> <relTol> <minTransferred>
    checks.py sameState <caseA> <caseB> <time> <relTol> <field> [<field> ...]
    checks.py differs <caseA> <caseB> <time> <relTol> <field> [<field> ...]
"""
import math
import os
import re
import sys

failures = 0


def report(ok, what):
    """One PASS or FAIL line; a failure counts towards status()."""
    global failures
    print(("PASS " if ok else "FAIL ") + what)
    if not ok:
        failures += 1


def status():
    """Exit status of a test script: 1 if any check failed, else 0."""
    return 1 if failures else 0


def run_command(argv, commands):
    """A test script's command line: run commands[argv[0]] (a function of
    the remaining arguments, as strings); its return value, or status()
    when it returns None. An unknown command stops the script."""
    if not argv or argv[0] not in commands:
        sys.exit("unknown command %s (allowed: %s)"
                 % (argv[0] if argv else "", ", ".join(commands)))
    rc = commands[argv[0]](*argv[1:])
    return status() if rc is None else rc


def read_list(path):
    """Values of a lagrangian scalar field file (ascii, N(...) or N{v})."""
    return [row[0] for row in read_rows(path)]


def seeded_parcels(case):
    """The positions mppicSeedParcels wrote (constant/kinematicCloudPositions)
    and the nParticle it reports (constant/seededParcels)."""
    text = open(os.path.join(case, "constant", "kinematicCloudPositions")).read()
    pts = [tuple(map(float, t)) for t in
           re.findall(r"\(([-\d.e+]+) ([-\d.e+]+) ([-\d.e+]+)\)", text)]
    seeded = open(os.path.join(case, "constant", "seededParcels")).read()
    return pts, float(re.search(r"nParticle\s+([^;]+);", seeded).group(1))


def lagrangian_masses(cloud_dir):
    """Each parcel's mass nParticle*rho*pi/6*d^3, in the order of the files,
    from a lagrangian cloud folder's nParticle, d and rho."""
    n = read_list(os.path.join(cloud_dir, "nParticle"))
    dia = read_list(os.path.join(cloud_dir, "d"))
    rho = read_list(os.path.join(cloud_dir, "rho"))
    return [ni*r*math.pi/6*di**3 for ni, di, r in zip(n, dia, rho)]


def parcel_masses(case, time, cloud="kinematicCloud"):
    d = os.path.join(case, time, "lagrangian", cloud)
    if not os.path.isdir(d):
        return []
    return sorted(lagrangian_masses(d))


def read_dat(path):
    """Rows of numbers of a postProcessing .dat table (comment lines, which
    start with #, and blank lines skipped)."""
    return [[float(v) for v in line.split()] for line in open(path)
            if not line.startswith("#") and line.strip()]


def mean_delta_p(case, t0, t1, name="bedPressureDrop"):
    path = os.path.join(case, "postProcessing", name, "0", name + ".dat")
    values = [cols[3] for cols in read_dat(path)
              if t0 - 1e-9 <= cols[0] <= t1 + 1e-9]
    return sum(values)/len(values), len(values)


# Two runs of the same parcels write the same masses (no parcel changes
# mass in these cases); the relative tolerance only absorbs the order of
# the summation, far below the written precision (10-17 digits)
MASS_RTOL = 1e-12


def same_mass(ma, mb):
    """Total and sorted per-parcel masses equal to MASS_RTOL relative."""
    ta, tb = math.fsum(ma), math.fsum(mb)
    return len(ma) == len(mb) and abs(ta - tb) <= MASS_RTOL*abs(tb) \
        and all(abs(x - y) <= MASS_RTOL*abs(y) for x, y in zip(ma, mb))


def same_cloud(a, b, time, names):
    """Two runs hold the same parcels at a time: their count and their
    masses (sorted) to MASS_RTOL; names label the runs in the lines."""
    ma, mb = parcel_masses(a, time), parcel_masses(b, time)
    report(len(ma) > 0 and len(ma) == len(mb),
           "parcel count at t=%s: %s %d, %s %d"
           % (time, names[0], len(ma), names[1], len(mb)))
    report(same_mass(ma, mb),
           "cloud mass at t=%s: %s %.17g, %s %.17g kg (relative %g)"
           % (time, names[0], math.fsum(ma), names[1], math.fsum(mb),
              MASS_RTOL))


def parity(a, b, time, t0, t1, tol):
    same_cloud(a, b, time, ("first", "second"))
    pa, na = mean_delta_p(a, float(t0), float(t1))
    pb, nb = mean_delta_p(b, float(t0), float(t1))
    rel = abs(pa - pb)/abs(pb)
    report(na == nb and rel <= float(tol),
           "mean bed pressure drop %s-%s s: %.6g vs %.6g Pa (%d/%d samples),"
           " relative difference %.3g <= %s" % (t0, t1, pa, pb, na, nb, rel, tol))


def serial_parallel(s, p, time):
    same_cloud(s, p, time, ("serial", "parallel"))


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


def sub_cycles(log, response_time, factor):
    """Each gas step's sub-step count against eq 24 by hand: when the
    response time limits, n = ceil(dt_gas/(factor*tau_p))."""
    dt_sol = float(factor)*float(response_time)
    text = open(log).read()
    steps = re.findall(r"\ndeltaT = (\S+)\nTime = \S+.*?"
                       r"Solids sub-cycling: (\d+) sub-step\(s\) of \S+ s, "
                       r"limited by ([a-z ]+) \(", text, re.S)
    limited = [(float(dt), int(n)) for dt, n, why in steps
               if why == "response time"]
    report(len(limited) >= 5, "%d of %d gas steps limited by the response "
           "time (at least 5)" % (len(limited), len(steps)))
    wrong = [(dt, n) for dt, n in limited
             if n != math.ceil(dt/dt_sol*(1 - 1e-12))]
    report(not wrong, "sub-steps = ceil(dt_gas/(%g*%g)) on every such step "
           "(wrong: %s)" % (float(factor), float(response_time), wrong[:3]))
    full = [n for dt, n in limited if abs(dt - 0.01) < 1e-12]
    if full:
        report(all(n == math.ceil(0.01/dt_sol) for n in full),
               "%d steps of 0.01 s: %s sub-steps (hand: %d)"
               % (len(full), sorted(set(full)), math.ceil(0.01/dt_sol)))


def sub_cycles_cfl(case, log, cfl, height):
    """The solids step of the gas step that follows each write time,
    against CFL*dy/|V_y| with the parcel's velocity as written (one parcel
    moving along y in cells of height dy)."""
    text = open(log).read()
    steps = re.findall(r"\nTime = (\S+)\n.*?Solids sub-cycling: \d+ "
                       r"sub-step\(s\) of \S+ s, limited by ([a-zA-Z ]+) "
                       r"\(dt_sol = (\S+) s\)", text, re.S)
    times = sorted((float(t), t) for t in os.listdir(case)
                   if re.fullmatch(r"[0-9.e+-]+", t) and float(t) > 0)
    checked = 0
    start = {float(t): (why, float(s)) for t, why, s in steps}
    for k, (t, name) in enumerate(times[:-1]):
        path = os.path.join(case, name, "lagrangian", "kinematicCloud", "U")
        if not os.path.exists(path):
            continue
        vy = float(re.search(r"1\s*\(\s*\(([^)]*)\)",
                             open(path).read()).group(1).split()[1])
        # the step that starts at t ends at the first logged time above t
        after = [s for s in start if s > t + 1e-12]
        if not after:
            continue
        why, dt_sol = start[min(after)]
        if why != "CFL":
            continue
        expected = float(cfl)*float(height)/abs(vy)
        report(abs(dt_sol - expected) <= 1e-6*expected,
               "t = %s: dt_sol %.9g = CFL*dy/|V_y| %.9g" % (name, dt_sol,
                                                           expected))
        checked += 1
    report(checked >= 5, "%d write times checked (at least 5)" % checked)


def balance(case, specie, rel_tol, min_transferred):
    """reactingCloudBalance of a closed case: the total mass of the specie
    (gas + cloud) and the total enthalpy stay at their first values to
    rel_tol relative, while the gas gained at least min_transferred of the
    specie's total (so that something was exchanged)."""
    path = os.path.join(case, "postProcessing", "balance", "0",
                        "reactingCloudBalance.dat")
    header, rows = None, []
    for line in open(path):
        if line.startswith("#"):
            header = line[1:].split()
        elif line.strip():
            rows.append([float(v) for v in line.split()])
    col = {name: i for i, name in enumerate(header)}
    rel_tol, min_transferred = float(rel_tol), float(min_transferred)
    for name in ("total:" + specie, "totalEnthalpy"):
        first = rows[0][col[name]]
        worst = max(abs(r[col[name]] - first) for r in rows)/abs(first)
        report(worst <= rel_tol, "%s constant to %.3g relative over %d steps "
               "(t %g to %g; tolerance %g)"
               % (name, worst, len(rows), rows[0][0], rows[-1][0], rel_tol))
    gas = "gas:" + specie
    gained = (rows[-1][col[gas]] - rows[0][col[gas]])/rows[0][col["total:" + specie]]
    report(gained >= min_transferred, "the gas gained %.4g of the %s "
           "(at least %g)" % (gained, specie, min_transferred))


def read_rows(path):
    """Rows of numbers of an ascii field file's list: one row per entry,
    e.g. (a b c d) i j k of a lagrangian positions file, (x y z) of a
    vector field, one number of a scalar field; the internal field only of
    a volume field, one row if it is uniform."""
    text = open(path).read()
    body = text[text.index("}", text.index("FoamFile")) + 1:]
    body = re.sub(r"//.*", "", body)
    start = body.find("internalField")
    if start >= 0:
        body = body[start:body.find("boundaryField")]
        uniform = re.match(r"internalField\s+uniform\s+\(?([^;)]*)", body)
        if uniform:
            return [[float(v) for v in uniform.group(1).split()]]
    same = re.search(r"(\d+)\s*\{\s*([^}\s]+)\s*\}", body)
    head = re.search(r"(\d+)\s*\(", body)
    if same and (not head or same.start() < head.start()):
        return [[float(same.group(2))]]*int(same.group(1))
    n = int(head.group(1))
    lines = body[head.end():].strip().splitlines()
    number = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
    if lines and lines[0].lstrip().startswith("("):
        rows = [[float(v) for v in re.findall(number, l)] for l in lines[:n]]
    else:
        values = re.findall(number, " ".join(lines).split(")")[0])
        rows = [[float(v)] for v in values]
    assert len(rows) == n, path
    return rows


def largest_difference(a, b, time, field):
    """Largest |x_a - x_b| of a field at a time over the largest magnitude
    of its column (each column scaled by its own); None when the two have
    different sizes or are empty."""
    ra = read_rows(os.path.join(a, time, field))
    rb = read_rows(os.path.join(b, time, field))
    if len(ra) == 0 or len(ra) != len(rb) \
            or any(len(x) != len(y) for x, y in zip(ra, rb)):
        return None
    worst = 0.0
    for c in range(len(ra[0])):
        scale = max(max(abs(r[c]) for r in ra), max(abs(r[c]) for r in rb))
        if scale > 0:
            worst = max(worst, max(abs(x[c] - y[c]) for x, y in zip(ra, rb))
                        / scale)
    return worst


def same_state(a, b, time, tol, *fields):
    """Field by field, entry by entry: |x_a - x_b| <= relTol*max|column|
    (each column of a field scaled by its own largest magnitude)."""
    tol = float(tol)
    for field in fields:
        worst = largest_difference(a, b, time, field)
        if worst is None:
            report(False, "%s at t=%s: sizes differ or empty" % (field, time))
            continue
        report(worst <= tol, "%s at t=%s: %d entries, largest difference %.3g"
               " of the column's scale <= %g%s" % (
                   field, time, len(read_rows(os.path.join(a, time, field))),
                   worst, tol, " (bitwise)" if worst == 0 else ""))


def differs(a, b, time, tol, *fields):
    """The largest difference of at least one of the fields exceeds relTol:
    a comparison that can fail."""
    tol = float(tol)
    worst = max(largest_difference(a, b, time, f) or 0.0 for f in fields)
    report(worst > tol, "%s and %s differ at t=%s: largest difference %.3g"
           " > %g" % (a, b, time, worst, tol))


def main(argv):
    cmd, args = argv[1], argv[2:]
    {"parity": parity, "serialParallel": serial_parallel,
     "cloudMass": cloud_mass, "fatal": fatal,
     "subCycles": sub_cycles, "subCyclesCFL": sub_cycles_cfl,
     "balance": balance, "sameState": same_state, "differs": differs}[cmd](*args)
    return status()


if __name__ == "__main__":
    sys.exit(main(sys.argv))
