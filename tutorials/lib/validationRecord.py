"""The validation matrix's record of one case: its figures against their
references and goals, written by the case's results script as JSON for
bin/validate, which collects the records into docs/validation/ and writes
docs/VALIDATION.md from them (tutorials/lib/validationReport.py).

A results script builds its rows and writes them:

    import validationRecord as record
    rows = [record.row("upper front at 1 s [m]", ours=0.468,
                       reference=0.4661, reference_source="eqs 6-8",
                       peer=0.466, goal=record.within(0.010, absolute=True))]
    record.write(args.record, "settlingShocks-0.10", rows,
                 plots=["settlingShocks.png"], settings="...")

A goal is a (text, test) pair; a row's "met" is test(ours, reference); a
figure with a goal but no value (not found, nan) is recorded as not met.
case_settings(case) gives the settings line of a cloud case from its files
(the packing model and its coefficients, the deposit, the drag, the PIMPLE
switches that are on, the seeding, the solver and the ranks).
The run's commit, date (when the run ended), command and wall time come
from bin/validate's environment (MPPIC_VALIDATE_COMMIT, _DIRTY, _DATE,
_COMMAND, _WALLTIME); a script run by hand records its own working tree's
commit, the present date and "by hand".
"""
import datetime
import json
import math
import os
import re
import subprocess

import mppicPost as post


def within(tolerance, absolute=False):
    """|ours - reference| <= tolerance (absolute) or <= tolerance*|reference|
    (relative, tolerance a fraction)."""
    if absolute:
        text = "within +-%g" % tolerance
        return text, lambda ours, ref: abs(ours - ref) <= tolerance
    text = "within %g %%" % (100*tolerance)
    return text, lambda ours, ref: abs(ours - ref) <= tolerance*abs(ref)


def between(lower, upper):
    """lower <= ours <= upper (None: unbounded)."""
    lo = "-inf" if lower is None else "%g" % lower
    hi = "inf" if upper is None else "%g" % upper
    return ("in [%s, %s]" % (lo, hi),
            lambda ours, ref: (lower is None or ours >= lower)
            and (upper is None or ours <= upper))


def at_most(upper):
    """ours <= upper."""
    return "<= %g" % upper, lambda ours, ref: ours <= upper


def at_least(lower):
    """ours >= lower."""
    return ">= %g" % lower, lambda ours, ref: ours >= lower


def row(figure, ours, reference=None, reference_source="", peer=None,
        goal=None, note=""):
    """One figure: ours against the reference (and the peer's, MFiX-PIC's,
    where it has one) and the goal (within, between, at_most, at_least)."""
    text, test = goal if goal else ("-", None)
    if ours is not None and isinstance(ours, float) and not math.isfinite(ours):
        ours = None
    if reference is not None and isinstance(reference, float) \
            and not math.isfinite(reference):
        reference = None
    if ours is None and test is not None:
        note = "; ".join(n for n in ("no value", note) if n)
    return {
        "figure": figure,
        "reference": reference,
        "referenceSource": reference_source,
        "peer": peer,
        "ours": ours,
        "goal": text,
        "met": None if test is None
        else False if ours is None else bool(test(ours, reference)),
        "note": note,
    }


def coeffs_text(path, block):
    """The entries of a dictionary's sub-dictionary block (the first of that
    name, nested braces kept), comments dropped, on one line ("" without
    it)."""
    text = re.sub(r"//.*", "", post.read_text(path))
    m = re.search(r"\b%s\s*\{" % re.escape(block), text)
    if not m:
        return ""
    depth, i = 1, m.end()
    while depth and i < len(text):
        depth += {"{": 1, "}": -1}.get(text[i], 0)
        i += 1
    return " ".join(text[m.end():i - 1].split()).rstrip(";")


# mppicPimpleFoam's PIMPLE keywords and their defaults (mppicPimpleFoam.C)
PIMPLE_SWITCHES = (("faceInterpolatedDrag", False),
                   ("superficialFluxCoupling", False),
                   ("balanceImplicitDrag", False))


def add_record_argument(parser):
    """A results script's option --record FILE: write the validation
    matrix's record of the run (write) to FILE."""
    parser.add_argument("--record", metavar="FILE",
                        help="write the validation matrix's record of the "
                        "run (tutorials/lib/validationRecord.py) to FILE")


def parcel_settings(case, drag_detail, gas=""):
    """One line of what a single-parcel or tracer case ran with: the
    packing model, the drag (its name and drag_detail, the keywords of its
    coefficients to show), gas (a note on the gas), the averaging, the gas
    velocity interpolation, deltaT and maxCo."""
    path = os.path.join(case, "constant", "kinematicCloudProperties")
    forces = re.search(r"particleForces\s*\{\s*(\w+)", post.read_text(path))
    detail = ", ".join("%s %s" % (key, post.dict_entry(path, key))
                       for key in drag_detail)
    return "; ".join(part for part in (
        "packingModel %s" % post.dict_entry(path, "packingModel"),
        "drag %s (%s)" % (forces.group(1) if forces else "none", detail),
        gas,
        "averagingMethod %s" % post.dict_entry(path, "averagingMethod"),
        "gas velocity interpolation %s" % post.dict_entry(path, "U.air"),
        "deltaT %s s, maxCo %s" % (post.control_entry(case, "deltaT"),
                                   post.dict_entry(path, "maxCo"))) if part)


def case_settings(case, cloud_file="kinematicCloudProperties"):
    """One line of what a cloud case ran with, read from its files."""
    cloud = os.path.join(case, "constant", cloud_file)
    seeds = os.path.join(case, "system", "mppicSeedParcelsDict")
    fv_solution = os.path.join(case, "system", "fvSolution")
    model = post.dict_entry(cloud, "packingModel")
    averaging = post.dict_entry(cloud, "averagingMethod")
    drag = re.search(r"particleForces\s*\{\s*(\w+)",
                     re.sub(r"//.*", "", post.read_text(cloud)))

    def with_coeffs(name, block):
        inner = coeffs_text(cloud, block)
        return "%s {%s}" % (name, inner) if inner else name

    parts = [
        with_coeffs(model, model + "Coeffs"),
        "solidsFractionFrom %s" % (post.dict_entry(cloud, "solidsFractionFrom")
                                   or "cell"),
        "averagingMethod " + with_coeffs(averaging, averaging + "Coeffs"),
        with_coeffs(drag.group(1), drag.group(1)) if drag else "no drag",
    ]
    changed = []
    for key, default in PIMPLE_SWITCHES:
        value = post.dict_entry(fv_solution, key)
        if value is not None and (value in ("true", "on", "yes")) != default:
            changed.append("%s %s" % (key, value))
    parts.append("PIMPLE " + (", ".join(changed) if changed
                              else "defaults"))
    if os.path.exists(seeds):
        parts.append("seeded at solids fraction %s, %s parcels per cell"
                     % (post.dict_entry(seeds, "solidsFraction"),
                        post.dict_entry(seeds, "parcelsPerCell")))
    ranks = len([d for d in os.listdir(case) if d.startswith("processor")])
    parts.append("%s, %s" % (post.control_entry(case, "application"),
                             "%d ranks" % ranks if ranks else "serial"))
    return "; ".join(parts)


def git(where, *args):
    """git's output of args run in the folder where ("" on failure)."""
    try:
        return subprocess.run(["git", "-C", where] + list(args),
                              capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def _git(*args):
    return git(os.path.dirname(os.path.abspath(__file__)), *args)


def write(path, case, rows, plots=(), settings="", window=""):
    """Write the record of a case to path (nothing when path is None)."""
    if not path:
        return
    env = os.environ
    wall = env.get("MPPIC_VALIDATE_WALLTIME")
    record = {
        "case": case,
        "commit": env.get("MPPIC_VALIDATE_COMMIT")
        or _git("rev-parse", "--short=10", "HEAD"),
        "dirty": env.get("MPPIC_VALIDATE_DIRTY",
                         "true" if _git("status", "--porcelain", "--",
                                        ":/src", ":/applications",
                                        ":/tutorials")
                         else "false") == "true",
        "date": env.get("MPPIC_VALIDATE_DATE")
        or datetime.datetime.now(datetime.timezone.utc)
        .strftime("%Y-%m-%d %H:%M UTC"),
        "command": env.get("MPPIC_VALIDATE_COMMAND", "by hand"),
        "wallTime": int(float(wall)) if wall else None,
        "settings": settings,
        "window": window,
        "rows": rows,
        "plots": list(plots),
    }
    with open(path, "w") as f:
        json.dump(record, f, indent=1)
        f.write("\n")
