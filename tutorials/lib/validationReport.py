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
marked with its own commit, and says so when what changed since are
comments and layout only; a case with no record says so.
"""
import argparse
import json
import os
import subprocess
import sys

from validationRecord import git


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


def without_comments(text):
    """C++ or OpenFOAM-dictionary text without its comments (// and /* */,
    outside string and character literals), every run of white space one
    blank: two texts that differ in comments and layout only give the
    same."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1])
            i = j + 1
        elif text.startswith("//", i):
            j = text.find("\n", i)
            i = n if j < 0 else j
            out.append(" ")
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            i = n if j < 0 else j + 2
            out.append(" ")
        else:
            out.append(c)
            i += 1
    return " ".join("".join(out).split())


def comment_style(path, text):
    """True for a file whose comments are C++'s: sources, gmsh geometry and
    OpenFOAM dictionaries (a FoamFile header)."""
    return path.endswith((".C", ".H", ".c", ".h", ".geo")) \
        or "FoamFile" in text[:2000]


def changed_in_comments_only(project, commit, paths):
    """True when every file under paths that changed from commit to HEAD is
    a C++-style file changed in its comments or layout only."""
    diff = git(project, "diff", "--name-status", commit, "HEAD", "--", *paths)
    for line in diff.splitlines():
        status, name = line.split("\t", 1)
        if status != "M":
            return False
        old = git(project, "show", "%s:%s" % (commit, name))
        new = git(project, "show", "HEAD:%s" % name)
        if not comment_style(name, new) \
                or without_comments(old) != without_comments(new):
            return False
    return True


def code_state(project, record, tutorial):
    """"current" when no commit after the record's changed the code or the
    case (its results scripts and README aside: -resultsOnly re-reads a
    run), "comments" when what changed since are comments and layout only,
    else "older"."""
    if record.get("dirty"):
        return "older"
    paths = ["src", "applications", os.path.join("tutorials", tutorial),
             ":(exclude)*.py", ":(exclude)*.md"]
    changed = git(project, "log", "-1", "--format=%H", "--", *paths)
    if not changed:
        return "older"
    if subprocess.run(["git", "-C", project, "merge-base", "--is-ancestor",
                       changed, record["commit"]],
                      capture_output=True).returncode == 0:
        return "current"
    if changed_in_comments_only(project, record["commit"], paths):
        return "comments"
    return "older"


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
        lines += ["Not yet run by the matrix: `bin/validate %s`%s."
                  % (case["name"], " (a long case: hours)"
                     if case["length"] == "long" else ""), ""]
        return lines
    commit = record["commit"] + (" (with uncommitted changes)"
                                 if record.get("dirty") else "")
    state = code_state(project, record, case["tutorial"])
    lines.append("Run %s on commit `%s`%s by `%s`%s." % (
        record["date"], commit, {
            "current": "",
            "comments": " (the code since differs in comments only)",
            "older": " (**older than the current code**)"}[state],
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
        "tutorial (its results scripts and README aside) says so: "
        "\"comments since\" where the code since differs from it in "
        "comments and layout only (C++ sources, dictionaries and gmsh "
        "files compared without their comments), \"older\" otherwise."
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
        state = code_state(project, record, case["tutorial"])
        out.append("| [%s](#%s) | %d of %d | `%s`%s | %s |" % (
            case["title"], anchor(case["title"]), sum(rated), len(rated),
            record["commit"], {"current": "", "comments": " (comments since)",
                               "older": " (older)"}[state],
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
