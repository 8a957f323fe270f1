#!/usr/bin/python3
"""Checks of tests/regression/uniformFluidizationPacksToGas.sh: tutorials/
validation/uniformFluidization with -packsToGas (coloringFunction with
conserveMomentum gas: the packs take the reactions, and those no support
holds hand them to the gas; PIMPLE balanceImplicitDrag true) at 3 parcels
per packed cell (2880 parcels of 382 particles), 2 s, read with the
tutorial's uniformFluidizationResults (summary over 1.2-2 s, monitor):
  - (deltaP - gas head)/(m g/A) within 2 % of 1,
        m g/A = 0.1 x 0.12 x 0.01 x 0.6 x 2500 x 9.81/0.001 = 1765.8 Pa;
  - the packs' reactions the gas took (packingMonitor's
    gasPackingMomentum, over the weight) at least 0.05 of the weight
    downward, <= -0.05 (measured -0.131: the falling parcels' landings on
    the packs; 0 if the packs' parcels took them);
  - what the packing step leaves to the supports, its force on the parcels
    plus the part the gas took, below 0.02 of the weight (measured 0.004);
  - 2880 parcels and the cloud mass 0.18 kg at every step (to 1e-9);
  - the largest cell solids fraction at most
        max(1.05 x 0.6, 0.6 + one parcel 0.6/3) = 0.8
    (measured 0.600), and the packing monitor's count of cells above close
    pack 0 at every step: its full cells hold 3 x 0.2 = 0.6 to round-off,
    which is not above it (counted as computed, all 960 full cells were,
    from the first step).

Usage: uniformFluidizationPacksToGas.py   (in the case)
"""
import sys

sys.path.insert(0, ".")
import uniformFluidizationResults as u  # noqa: E402 (the case's copy)
import checks  # noqa: E402
from checks import report as check  # noqa: E402


def check_weight_carried(res):
    check(abs(res["ratio"] - 1) <= 0.02,
          "(deltaP - gas head)/weight over 1.2-2 s %.4f within 2 %% of 1"
          % res["ratio"])
    check(res["toGas"] <= -0.05,
          "the gas took the packs' reactions: %.4f of the weight (<= -0.05)"
          % res["toGas"])
    supports = res["packing"] + res["toGas"]
    check(abs(supports) < 0.02,
          "the packing step leaves the supports %.4f of the weight (< 0.02)"
          % supports)


def check_parcels_mass_and_packing():
    mon = u.monitor(".")
    check(all(r[1] == 2880 for r in mon), "2880 parcels at every step")
    check(all(abs(r[2]/0.18 - 1) < 1e-9 for r in mon),
          "cloud mass 0.18 kg at every step")
    bound = max(1.05*0.6, 0.6 + 0.6/3)
    check(max(r[4] for r in mon) <= bound + 1e-12,
          "max cell solids fraction %.4f <= %.4f at every step"
          % (max(r[4] for r in mon), bound))
    check(all(r[5] == 0 for r in mon),
          "no cell above close pack by more than round-off at any step "
          "(largest count %d)" % max(r[5] for r in mon))


if __name__ == "__main__":
    check_weight_carried(u.summary(".", 1.2))
    check_parcels_mass_and_packing()
    sys.exit(checks.status())
