#!/usr/bin/python3
"""Write docs/VALIDATION.md from the validation matrix's records.

Usage: validationReport.py [--project DIR] [--records DIR]

--records DIR: the records' folder (default <project>/docs/validation); the
page is written beside it, as DIR/../VALIDATION.md.

Reads the case list tutorials/validationCases (bin/validate's) and each
case's record docs/validation/<case>.json (validationRecord.py), and writes
docs/VALIDATION.md: a summary table of every case (figures met, commit),
the options the defaults leave off with what they change
(tutorials/validationTradeOffs, measured by hand), then per case its table (figure, reference, MFiX-PIC, ours, goal, met),
the command, the settings, and its plots (docs/validation/<png>). A case
whose record was made on code older than the last change to src/,
applications/ or its tutorial (results scripts and READMEs aside) is
marked with its own commit; a case with no record says so.
"""
import argparse
import json
import os
import subprocess
import sys


def read_rows(path, n_fields):
    """The lines of a |-separated list (comments and blank lines aside),
    each as its n_fields stripped fields; stops naming the file and the
    line when a line has another count."""
    rows = []
    for line in open(path):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        fields = [f.strip() for f in line.split("|")]
        if len(fields) != n_fields:
            sys.exit("%s: expected %d fields separated by |: %s"
                     % (path, n_fields, line))
        rows.append(fields)
    return rows


def read_cases(project):
    """(name, tutorial, allrun args, results, title, long) per line of
    tutorials/validationCases."""
    path = os.path.join(project, "tutorials", "validationCases")
    return [dict(zip(("name", "tutorial", "allrun", "results", "title",
                      "length"), fields)) for fields in read_rows(path, 6)]


def read_trade_offs(project):
    """(option, case, with it, on the defaults, commit) per line of
    tutorials/validationTradeOffs; none without the file."""
    path = os.path.join(project, "tutorials", "validationTradeOffs")
    return read_rows(path, 5) if os.path.exists(path) else []


def git(project, *args):
    try:
        return subprocess.run(["git", "-C", project] + list(args),
                              capture_output=True, text=True,
                              check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return ""


def is_current(project, record, tutorial):
    """True when no commit after the record's changed the code or the case
    (its results scripts and README aside: -resultsOnly re-reads a run)."""
    if record.get("dirty"):
        return False
    changed = git(project, "log", "-1", "--format=%H", "--", "src",
                  "applications", os.path.join("tutorials", tutorial),
                  ":(exclude)*.py", ":(exclude)*.md")
    if not changed:
        return False
    return subprocess.run(["git", "-C", project, "merge-base",
                           "--is-ancestor", changed, record["commit"]],
                          capture_output=True).returncode == 0


def number(value):
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    if value == 0 or 1e-3 <= abs(value) < 1e5:
        return "%.4g" % value
    return "%.3e" % value


def cell(text):
    """Text for a Markdown table cell (a | would end the cell)."""
    return str(text).replace("|", "\\|")


def met_text(met):
    return {True: "yes", False: "**no**", None: "-"}[met]


def case_section(project, case, record, folder):
    lines = ["## %s" % case["title"], ""]
    if record is None:
        lines += ["Not yet run by the matrix: `bin/validate %s`%s. Earlier "
                  "figures of this case, from set-ups the shipped commands do "
                  "not all reproduce, are in this file's history (git log)."
                  % (case["name"], " (hours: in pieces)"
                     if case["length"] == "long" else ""), ""]
        return lines
    commit = record["commit"] + (" (with uncommitted changes)"
                                 if record.get("dirty") else "")
    current = is_current(project, record, case["tutorial"])
    lines.append("Run %s on commit `%s`%s by `%s`%s." % (
        record["date"], commit,
        "" if current else " (**older than the current code**)",
        record["command"],
        ", %d s of wall time" % record["wallTime"]
        if record.get("wallTime") else ""))
    if record.get("window"):
        lines.append("Window: %s." % record["window"])
    if record.get("settings"):
        lines.append("Settings: %s." % record["settings"])
    lines += ["", "| figure | reference | MFiX-PIC | ours | goal | met |",
              "|---|---|---|---|---|---|"]
    for r in record["rows"]:
        ref = number(r["reference"])
        if r.get("referenceSource"):
            ref += " (%s)" % r["referenceSource"]
        fig = r["figure"] + (" — %s" % r["note"] if r.get("note") else "")
        lines.append("| %s | %s | %s | %s | %s | %s |" % tuple(cell(c) for c in (
            fig, ref, number(r["peer"]), number(r["ours"]), r["goal"],
            met_text(r["met"]))))
    lines.append("")
    for png in record.get("plots", []):
        png = os.path.basename(png)
        lines += ["![%s](%s/%s)" % (png, folder, png), ""]
    return lines


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--project", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    parser.add_argument("--records", default=None)
    args = parser.parse_args()
    project = os.path.abspath(args.project)
    records_dir = os.path.abspath(args.records or os.path.join(
        project, "docs", "validation"))

    cases = read_cases(project)
    records = {}
    for case in cases:
        path = os.path.join(records_dir, case["name"] + ".json")
        records[case["name"]] = json.load(open(path)) \
            if os.path.exists(path) else None

    out = [
        "# Validation matrix",
        "",
        "Generated by `bin/validate -report` from the records in "
        "`%s/`; do not edit by hand. Each case runs from its "
        "tutorial's shipped `Allrun` on the shipped defaults "
        "(`bin/validate <case>`, list: `tutorials/validationCases`); its "
        "results script writes the record. A record made on code older "
        "than the last change to `src/`, `applications/` or the case's "
        "tutorial (its results scripts and README aside) says so."
        % os.path.relpath(records_dir, project),
        "",
        "| case | figures met | commit | date |",
        "|---|---|---|---|",
    ]
    for case in cases:
        record = records[case["name"]]
        if record is None:
            out.append("| [%s](#%s) | not run | - | - |" % (
                case["title"], anchor(case["title"])))
            continue
        rated = [r["met"] for r in record["rows"] if r["met"] is not None]
        current = is_current(project, record, case["tutorial"])
        out.append("| [%s](#%s) | %d of %d | `%s`%s | %s |" % (
            case["title"], anchor(case["title"]), sum(rated), len(rated),
            record["commit"], "" if current else " (older)",
            record["date"]))
    out.append("")
    trade_offs = read_trade_offs(project)
    if trade_offs:
        out += [
            "## Options the defaults leave off",
            "",
            "Each option below helps some case and harms another; the "
            "defaults are the setting the matrix as a whole is best served "
            "by. Measured by hand with the option set; the commit column "
            "names the code and what else was set (tutorials/"
            "validationTradeOffs).",
            "",
            "| option | case | with the option | on the defaults | commit |",
            "|---|---|---|---|---|",
        ]
        out += ["| %s |" % " | ".join(cell(f) for f in row)
                for row in trade_offs]
        out.append("")
    for case in cases:
        out += case_section(project, case, records[case["name"]],
                            os.path.basename(records_dir))

    path = os.path.join(os.path.dirname(records_dir), "VALIDATION.md")
    with open(path, "w") as f:
        f.write("\n".join(out).rstrip() + "\n")
    print("wrote %s (%d cases, %d with a record)" % (
        path, len(cases), sum(r is not None for r in records.values())))
    return 0


def anchor(title):
    """GitHub's anchor of a heading."""
    keep = [c for c in title.lower() if c.isalnum() or c in " -_"]
    return "".join(keep).replace(" ", "-")


if __name__ == "__main__":
    sys.exit(main())
