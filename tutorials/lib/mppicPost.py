"""What the tutorials' results scripts share: reading a case's output and
the statistics and bookkeeping of a bed.

Readers (OpenFOAM ascii output of a case folder):
    read_text(path)                    a file's text, or its .gz's
    function_object_table(case, name)  postProcessing/<name>/<t>/<name>.dat,
                                       the pieces of a continued run joined
    dict_entry(path, key)              the first 'key value;' of a file, text
    dict_number(path, key)             the first 'key <number>;', a float
    control_entry(case, key)           a top-level entry of system/controlDict
    time_dirs(case), latest_time(case) the written times
    internal_field(path)               a volField's internalField
    lagrangian_field(path)             a written cloud field, one row a parcel
    parcel_cells_volumes(case, time)   each parcel's cell, solids volume and
                                       typeId (its solids phase)
    cell_solids_fractions(case, time, volumes)
                                       each cell's solids fraction from the
                                       parcels; phase_solids_fractions: per
                                       phase
    cells_above_bound(case, close_pack) cells above close pack + one parcel
                                       at every written time
    time_mean_field(case, name, t0, t1[, component, transform])
                                       a volField's mean over the written
                                       times in (t0, t1] that hold it
    layer_means(values, centres)       means over layers of cells (by height)
    profile_crossing(ys, profile, level, from_top)
                                       where a profile falls through a level

Statistics: mppicStatistics.py (percentile, mean_and_error, block_means,
interpolate, window_mean, fit_line, fit_through_origin), re-exported here.

A bed's vertical momentum budget over a window (packingMonitor's columns):
    packing_force(rows, mass)          the packing step's mean upward force
                                       over the cloud's weight
    gas_packing_force(rows, mass)      the part of the packs' reactions
                                       handed to the gas instead
                                       (freePackReactionsToGas): inside the
                                       gas's share, not on the parcels
    cloud_momentum(case, time)         the cloud's vertical momentum written
                                       at a time
    weight_rest(case, t0, t1, carried, mass)
                                       what neither the gas nor the packing
                                       step carries: the walls' rebounds
                                       and the drag the gas did not give
                                       (without balanceImplicitDrag)

Scripts find this module through $MPPIC_PROJECT_DIR (etc/bashrc), else
through the tutorials folder they sit in:
    sys.path.insert(0, os.path.join(os.environ.get("MPPIC_PROJECT_DIR",
                                    <the project>), "tutorials", "lib"))
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np

# packingMonitor.dat columns (src/mppicModels/functionObjects/packingMonitor)
MONITOR_MASS, MONITOR_PACKING_Y, MONITOR_GAS_PACKING_Y = 2, 9, 15

# Gravity [m/s2], as the tutorials' constant/g
G = 9.81


# * * * * * * * * * * * * * * * * Readers  * * * * * * * * * * * * * * * * * #

def read_text(path):
    """A file's text, or that of path.gz (writeCompression on)."""
    if os.path.exists(path) or not os.path.exists(path + ".gz"):
        return open(path).read()
    import gzip
    with gzip.open(path + ".gz", "rt") as f:
        return f.read()


def read_table(path):
    """Rows of a function object's .dat file (comment lines and lines that
    are not numbers skipped), as a list of float lists."""
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        try:
            rows.append([float(v) for v in line.split()])
        except ValueError:
            pass
    return rows


def function_object_table(case, name, file=None):
    """Rows of postProcessing/<name>/<start>/<file>.dat (file: the
    function object's name unless given, e.g. phases); a continued run
    writes a folder per start time, and its rows replace the earlier
    pieces' rows from its first time on. A piece that starts where an
    earlier one did finds the file there and writes <name>_<start>.dat
    beside it (OpenFOAM's functionObjectFile): it comes after the file."""
    rows = []
    file = file or name
    paths = [p for pattern in (file + ".dat", file + "_*.dat")
             for p in glob.glob(os.path.join(case, "postProcessing", name, "*", pattern))]
    for path in sorted(paths, key=lambda p: (float(p.split(os.sep)[-2]), len(p), p)):
        new = read_table(path)
        if new:
            rows = [r for r in rows if r[0] < new[0][0]] + new
    return rows


def add_table_arguments(parser, label):
    """The options by which bin/compareSolvers asks a results script for its
    table: --tableHead (print the head), --row (print the run's row) with
    --label (default label), --wallTime S and --failure TEXT."""
    parser.add_argument("--label", default=label)
    parser.add_argument("--tableHead", action="store_true")
    parser.add_argument("--row", action="store_true")
    parser.add_argument("--wallTime", type=float, default=None)
    parser.add_argument("--failure", default="")


def results_parser(label, description=None):
    """The command line a results script starts from: --case DIR (default
    the current folder) and the table options of add_table_arguments."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--case", default=".")
    add_table_arguments(parser, label)
    return parser


def parse_results_args(parser, table_head):
    """The script's parsed options; with --tableHead, prints table_head and
    exits with status 0 (bin/compareSolvers asks for the head alone)."""
    args = parser.parse_args()
    if args.tableHead:
        print(table_head)
        sys.exit(0)
    return args


def control_entry(case, key):
    """A top-level entry of system/controlDict, as text (None if absent)."""
    text = open(os.path.join(case, "system", "controlDict")).read()
    m = re.search(r"^%s\s+([^;]+);" % key, text, re.M)
    return m.group(1).strip() if m else None


def dict_entry(path, key):
    """The value of the first 'key value;' line of a dictionary file (at
    any depth), as text; None if absent."""
    m = re.search(r"^\s*" + re.escape(key) + r"\s+([^;]+);",
                  read_text(path), re.M)
    return m.group(1).strip() if m else None


def dict_number(path, key):
    """The first 'key <number>;' of a dictionary file, as a float; stops
    with a message naming the key and the file if there is none."""
    m = re.search(r"^\s*%s\s+([-0-9.eE+]+)\s*;" % re.escape(key),
                  read_text(path), re.M)
    if not m:
        raise SystemExit("no %s in %s" % (key, path))
    return float(m.group(1))


def time_dirs(case):
    """[(t, folder name)] of the case's time folders, by time."""
    out = []
    for d in os.listdir(case):
        try:
            out.append((float(d), d))
        except ValueError:
            pass
    return sorted(out)


def latest_time(case):
    """The folder name of the case's latest written time."""
    return time_dirs(case)[-1][1]


def internal_field(path):
    """A volField's internalField: a float (a vector tuple) if uniform,
    else a list of floats or of vector tuples."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<(\w+)>\s*(\d+)\s*"
                  r"\((.*?)\)\s*;", text, re.S)
    if m is None:
        m = re.search(r"internalField\s+uniform\s+([^;]+);", text)
        value = m.group(1).strip()
        if value.startswith("("):
            return tuple(float(v) for v in value.strip("()").split())
        return float(value)
    if m.group(1) == "vector":
        return [tuple(map(float, v.split()))
                for v in re.findall(r"\(([^()]*)\)", m.group(3))]
    return [float(v) for v in m.group(3).split()]


def time_mean_field(case, name, t0, t1, component=None, transform=None):
    """Mean of a volField's internal field over the written times t with
    t0 < t <= t1 that hold it, as a numpy array (one component of a vector
    field with component 0, 1 or 2; each time's values passed through
    transform first if given, e.g. an indicator), and the number of times;
    (None, 0) if none. A time written uniform adds its value to every cell
    (a scalar if every time is uniform)."""
    total, count = None, 0
    for t, d in time_dirs(case):
        path = os.path.join(case, d, name)
        if not (t0 + 1e-9 < t <= t1 + 1e-9) or not os.path.exists(path):
            continue
        values = internal_field(path)
        if component is not None:
            values = values[component] if isinstance(values, tuple) \
                else np.array(values, dtype=float)[:, component]
        values = np.asarray(values, dtype=float)
        if transform is not None:
            values = np.asarray(transform(values), dtype=float)
        total = values if total is None else total + values
        count += 1
    return (total/count, count) if count else (None, 0)


def lagrangian_field(path):
    """A written cloud field, one list of floats per parcel (a uniform
    N{value} expanded)."""
    text = open(path).read()
    text = text[text.index("}", text.index("FoamFile")) + 1:]
    m = re.search(r"(\d+)\s*\{([^}]*)\}", text)
    if m and (text.find("(") < 0 or text.find("(") > m.start()):
        value = [float(v) for v in m.group(2).strip("() \n").split()]
        return [value]*int(m.group(1))
    body = text[text.index("(") + 1:text.rindex(")")]
    if "(" in body:
        return [[float(v) for v in t.split()]
                for t in re.findall(r"\(([^()]*)\)", body)]
    return [[float(v)] for v in body.split()]


def parcel_cells_volumes(case, time, cloud="kinematicCloud"):
    """The parcels of a written time: each one's cell (from its
    coordinates), its solids volume nParticle*pi/6*d^3 and its typeId (its
    solids phase; -1 when not written): numpy arrays, or Nones when the
    time holds no cloud."""
    folder = os.path.join(case, time, "lagrangian", cloud)
    if not os.path.exists(os.path.join(folder, "coordinates")):
        return None, None, None
    text = open(os.path.join(folder, "coordinates")).read()
    cells = np.array(re.findall(r"\)\s+(-?\d+)\s+-?\d+\s+-?\d+", text),
                     dtype=int)
    n = np.array(lagrangian_field(os.path.join(folder, "nParticle")))[:, 0]
    d = np.array(lagrangian_field(os.path.join(folder, "d")))[:, 0]
    phase = np.full(len(cells), -1, dtype=int)
    if os.path.exists(os.path.join(folder, "typeId")):
        phase = np.array(lagrangian_field(os.path.join(folder, "typeId")),
                         dtype=float)[:, 0].astype(int)
    return cells, n*math.pi/6*d**3, phase


def cell_solids_fractions(case, time, volumes, cloud="kinematicCloud"):
    """Each cell's solids fraction at a written time, from the parcels
    themselves: sum of nParticle*pi/6*d^3 over the parcels whose
    coordinates name the cell, over the cell volumes (a numpy array); and
    the parcel volumes. None when the time holds no cloud."""
    cells, parcel, _ = parcel_cells_volumes(case, time, cloud)
    if cells is None:
        return None, None
    return np.bincount(cells, weights=parcel,
                       minlength=len(volumes))/volumes, parcel


def phase_solids_fractions(case, time, volumes, cloud="kinematicCloud"):
    """Each solids phase's cell solids fractions at a written time (as
    cell_solids_fractions, over the parcels of that typeId): a dict typeId
    -> numpy array, or None when the time holds no cloud."""
    cells, parcel, phase = parcel_cells_volumes(case, time, cloud)
    if cells is None:
        return None
    return {int(k): np.bincount(cells[phase == k], weights=parcel[phase == k],
                                minlength=len(volumes))/volumes
            for k in np.unique(phase)}


def cells_above_bound(case, close_pack, cloud="kinematicCloud"):
    """The cells' solids fractions (cell_solids_fractions) at every written
    time against each cell's bound max(1.05 alpha_cp, alpha_cp +
    V_parcel/V_cell): a cell may hold the parcel count nearest close pack,
    so one parcel more than close pack at most. Needs the cell volumes
    written at time 0 (postProcess -func writeCellVolumes). A dict: times
    read, the most cells above their bound at one time, the largest
    solids fraction, its cell's bound and volume, and the largest parcel
    volume."""
    volumes = np.asarray(internal_field(os.path.join(case, "0", "V")),
                         dtype=float)
    out = {"times": 0, "cellsAbove": 0, "largest": 0.0, "largestBound": 0.0,
           "largestVolume": 0.0, "parcelVolume": 0.0}
    for t, d in time_dirs(case):
        alpha, parcel = cell_solids_fractions(case, d, volumes, cloud)
        if alpha is None:
            continue
        bound = np.maximum(1.05*close_pack, close_pack + parcel.max()/volumes)
        out["times"] += 1
        out["cellsAbove"] = max(out["cellsAbove"],
                                int((alpha > bound*(1 + 1e-9)).sum()))
        i = int(np.argmax(alpha))
        if alpha[i] > out["largest"]:
            out.update(largest=float(alpha[i]), largestBound=float(bound[i]),
                       largestVolume=float(volumes[i]))
        out["parcelVolume"] = max(out["parcelVolume"], float(parcel.max()))
    return out


def layer_means(values, centres, axis=1, digits=9):
    """Means of a cell field over the layers of cells at one height (the
    centres' coordinate along axis, rounded to digits): (heights, means),
    by height."""
    layers = {}
    for v, c in zip(values, centres):
        layers.setdefault(round(c[axis], digits), []).append(v)
    heights = sorted(layers)
    return heights, [sum(layers[h])/len(layers[h]) for h in heights]


def profile_crossing(ys, profile, level, from_top):
    """Height where a profile over ascending heights ys falls through level
    going up (linear between points): the highest such crossing (from_top)
    or the lowest; nan if none."""
    order = range(len(ys) - 2, -1, -1) if from_top else range(len(ys) - 1)
    for j in order:
        if profile[j] >= level > profile[j + 1]:
            f = (profile[j] - level)/(profile[j] - profile[j + 1])
            return ys[j] + f*(ys[j + 1] - ys[j])
    return float("nan")


# * * * * * * * * * * * * * * * * Statistics * * * * * * * * * * * * * * * * #

from mppicStatistics import percentile, mean_and_error, block_means, \
    interpolate, window_mean, fit_line, fit_through_origin  # noqa: E402,F401


# * * * * * * * * * * * * * A bed's momentum budget * * * * * * * * * * * * * #

def packing_force(rows, mass=None, g=9.81, column=MONITOR_PACKING_Y):
    """The packing step's mean upward force over the cloud's weight: the
    vertical momentum it added (packingMonitor, every step) over the
    window's duration, over M g (M: the given mass, else the last row's).
    column: the monitor's column summed (rows without it count 0)."""
    if len(rows) < 2:
        return float("nan")
    duration = rows[-1][0] - rows[0][0] + (rows[1][0] - rows[0][0])
    if mass is None:
        mass = rows[-1][MONITOR_MASS]
    return sum(r[column] if len(r) > column else 0.0
               for r in rows)/duration/(mass*g)


def gas_packing_force(rows, mass=None, g=9.81):
    """The packs' reactions handed to the gas (packingMonitor's
    gasPackingMomentum, freePackReactionsToGas) as a mean upward force over
    the weight; 0 for monitors written before that column. It pushes the
    gas as the drag's reaction does: the drag on the parcels is the
    pressure drop's share plus this (pass both, with the packing force, to
    weight_rest)."""
    return packing_force(rows, mass, g, MONITOR_GAS_PACKING_Y)


def cloud_momentum(case, time, cloud="kinematicCloud"):
    """The cloud's vertical momentum written at a time folder, kg m/s
    (None if the folder holds no cloud)."""
    d = os.path.join(case, time, "lagrangian", cloud)
    if not os.path.isdir(d):
        return None
    fields = [lagrangian_field(os.path.join(d, f))
              for f in ("nParticle", "rho", "d", "U")]
    return sum(n[0]*rho[0]*math.pi/6*dia[0]**3*u[1]
               for n, rho, dia, u in zip(*fields))


def weight_rest(case, t0, t1, carried, mass, g=9.81, cloud="kinematicCloud"):
    """What the gas and the packing step do not carry, over the weight:
    d(P_y)/dt/(M g) + 1 - carried, with P_y the cloud's vertical momentum
    at the written times nearest t0 and t1 and carried the gas's and the
    packing step's shares together. Without wall friction it is the walls'
    rebounds (a distributor's). None without two written clouds. (A
    solids-sub-cycled run also leaves time folders holding only uniform/:
    only those with the cloud count.)"""
    times = [name for _, name in time_dirs(case)
             if os.path.isdir(os.path.join(case, name, "lagrangian", cloud))]
    if not times:
        return None
    a = min(times, key=lambda d: abs(float(d) - t0))
    b = min(times, key=lambda d: abs(float(d) - t1))
    if a == b:
        return None
    pa, pb = cloud_momentum(case, a, cloud), cloud_momentum(case, b, cloud)
    if pa is None or pb is None:
        return None
    return (pb - pa)/(float(b) - float(a))/(mass*g) + 1 - carried
