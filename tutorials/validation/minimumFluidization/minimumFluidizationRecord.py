"""The validation matrix's record of a minimumFluidization run
(tutorials/lib/validationRecord.py): minimumFluidizationResults.py --record
FILE passes its summary() here. The rows: Umf of the fits' crossing against
NETL's measured 0.182 m/s (within 10 %), the plateau dP* against 1 (within
0.03) and the fixed-bed branch against Ergun (informational). MFiX-PIC has
no figure: it showed no transition (seed 2 Fig. 10).
"""

import validationRecord as record


def settings(case, res):
    """The case's settings (validationRecord) and the inlet's ramp."""
    b = res["bed"]
    return "%s; inlet ramp 0-%g m/s over %g s" % (
        record.case_settings(case), b["rampVelocity"], b["rampTime"])


def rows(res, measured_umf):
    """The record's rows from minimumFluidizationResults.summary()."""
    b = res["bed"]
    found = "umf" in res
    return [
        record.row(
            "Umf, fits crossing [m/s]", res.get("umf"),
            reference=measured_umf,
            reference_source="NETL, measured (HDPE; seed 2 §3.2, Fig. 9)",
            goal=record.within(0.10),
            note="%sMFiX-PIC showed no transition (seed 2 Fig. 10): no "
            "figure; Umf of Ergun for this voidage %.4f m/s, of Wen-Yu "
            "%.4f m/s%s" % (
                "" if found else "no transition found; ",
                res["ergunUmf"], res["wenYuUmf"],
                "; the bed unlocks at %.4f m/s" % res["departure"]
                if res.get("departure") else "")),
        record.row(
            "plateau (deltaP - gas head)/weight", res.get("plateau"),
            reference=1.0, reference_source="the bed's weight",
            goal=record.within(0.03, absolute=True),
            note="mean of dP* above 1.5 Umf (smoothed over 0.05 m/s)"),
        record.row(
            "fixed-bed branch vs Ergun, mean |error|", res.get("fixedError"),
            reference_source="Ergun, voidage %g" % (1 - b["alpha"]),
            note="informational: mean |dP*/dP*_Ergun - 1| over 0.3-0.8 "
            "Umf, a fraction"),
    ]
