"""The circulating fluidized bed's constants, shared by cfbResults.py (the
measurements) and cfbPlots.py (its figures): cfbPlots imports them from
here, not from cfbResults, so that cfbResults --plot can import cfbPlots
without an import cycle."""

RHO_P = 860.0            # HDPE, kg/m3 (constant/kinematicCloudProperties)
CLOSE_PACK = 0.6
STANDPIPE_Y0 = 0.146     # top of the bend, bottom of the straight standpipe
STANDPIPE_LENGTH = 0.932 - 0.146
HEIGHT_THRESHOLD = 0.3   # solids fraction at the inventory's top
HEIGHT_AVERAGE = 0.02    # m, running mean along the axis
TAPS = {"riser005": 0, "riser119": 4, "standpipe016": 5, "standpipe090": 8}
