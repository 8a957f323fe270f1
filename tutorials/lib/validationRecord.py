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

A goal is a (text, test) pair; a row's "met" is test(ours, reference).
The run's commit, date, command and wall time come from bin/validate's
environment (MPPIC_VALIDATE_COMMIT, _DIRTY, _COMMAND, _WALLTIME); a script
run by hand records its own working tree's commit and "by hand".
"""
import datetime
import json
import os
import subprocess


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
    return {
        "figure": figure,
        "reference": reference,
        "referenceSource": reference_source,
        "peer": peer,
        "ours": ours,
        "goal": text,
        "met": None if test is None or ours is None
        else bool(test(ours, reference)),
        "note": note,
    }


def _git(*args):
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        return subprocess.run(["git", "-C", here] + list(args),
                              capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


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
        "date": datetime.datetime.now(datetime.timezone.utc)
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
