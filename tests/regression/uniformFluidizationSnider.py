#!/usr/bin/python3
"""Checks of tests/regression/uniformFluidizationSnider.sh: tutorials/
validation/uniformFluidization with mfixSnider (-packing mfixSnider: the
Snider stress, and the gas, on the solids fraction deposited with its linear
hat, slip to the previous step's mean solids velocity, slip factor 0.9,
MFiX's collision damping, our capacity limit and held packs) for 2 s, read
with the tutorial's uniformFluidizationResults (summary over 1.2-2 s,
monitor):
  - the time-mean of (deltaP - gas head)/(m g/A) over 1.2-2 s in
    [0.90, 1.10] (0.90: issue 18's figure), m g/A = 1765.8 Pa (measured
    1.0687 on 2026-11-27 with fixedFluxExtrapolatedPressure on the inlet;
    when written, with fixedFluxPressure: 1.0290; the case as it runs, 10 s,
    0.9965 over 4-10 s; the collapsed bed gave 0.049, the stress on the cell
    counts 0.966, a softer stress (Ps 10) whose refusals push the bed down
    1.26: README);
  - 7680 parcels and the cloud mass 0.18 kg (to 1e-9) at every step;
  - the largest cell solids fraction at every step at most close pack plus
    half a parcel, 0.6 + 0.075/2 = 0.6375 (to 1e-9 relative), inside the
    issue's bound max(1.15 x 0.6, 0.6 + one parcel 0.075) = 0.69
    (capacityLimit false gives 1.73 within 2 s on this deposit: the check
    can fail);
  - the linear-hat field the stress and the gas read (the monitor's
    maxAlphaAveraged) at every step at most 1.15 x 0.6 = 0.69 (measured when
    written: 0.652; without releaseAbove, and seeded at random places
    (jitter 0.9) as before, 0.772 at the first step and up to 0.75-0.84 in
    the bed: the check can fail).

Usage: uniformFluidizationSnider.py   (in the case)
"""
import sys

sys.path.insert(0, ".")
import uniformFluidizationResults as u  # noqa: E402 (the case's copy)
import checks  # noqa: E402
from checks import report as check  # noqa: E402


def check_weight_carried():
    res = u.summary(".", 1.2)
    check(0.90 <= res["ratio"] <= 1.10,
          "(deltaP - gas head)/weight over 1.2-2 s %.4f in [0.90, 1.10]"
          % res["ratio"])


def check_parcels_mass_and_packing():
    mon = u.monitor(".")
    check(all(r[1] == 7680 for r in mon), "7680 parcels at every step")
    check(all(abs(r[2]/0.18 - 1) < 1e-9 for r in mon), "cloud mass 0.18 kg at every step")
    largest = max(r[4] for r in mon)
    check(largest <= 0.6375*(1 + 1e-9),
          "max cell solids fraction at every step %.4f <= 0.6375" % largest)
    hat = max(r[3] for r in mon)
    check(hat <= 0.69, "max linear-hat solids fraction at every step %.4f <= 0.69" % hat)


if __name__ == "__main__":
    check_weight_carried()
    check_parcels_mass_and_packing()
    sys.exit(checks.status())
