"""Pictures and bead metrics of an ldnaFoam case (``ldna post``).

Reads a case (reconstructed or decomposed) with pyvista and

- takes the bead and melt-pool metrics from the ``meltPoolMetrics``
  function object (src/ldnaFunctionObjects), which it runs at the time it
  reads with OpenFOAM's ``postProcess``: pool length and width,
  penetration, pool volume, bead width and height, bead and fused areas,
  bonded and unbonded width, dilution, peak metal temperature; and adds the
  bead's wetting angle;
- renders, without a display, the pictures a welding engineer looks at:
  the free surface (alpha = 0.5) coloured by temperature, a transverse
  section through the deepest fusion (without fusion: the bead section)
  with the fusion line the function object located (the pool's projection,
  between cell centres), and a longitudinal section along the weld's
  centre line with the fusion isotherm.

The weld frame is the template's: x along the weld (the substrate moves to
+x), y across it, z up, the substrate surface at z = surface_height.
"""
from __future__ import annotations

import math
import os
import re
import shutil
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from .case import Case
from .material import Metal, two_metals

#: Metal fraction from which a cell counts as metal (meltPoolMetrics default)
METAL_THRESHOLD = 0.5
#: Relative difference of two slice areas taken as round-off (meltPoolMetrics)
SLICE_AREA_TOLERANCE = 1e-6
#: Cell edges across the weld are compared to this many decimals of a metre
EDGE_DECIMALS = 12
#: Share of the bead's height from which its section counts as the bead's
#: body (bead_body_width): above the toe films of one cell, 0.1-0.5 mm, that
#: the bead study's meshes lay beside a bead 3.5-4.5 mm high
#: (docs/accuracy-cost.md)
BODY_HEIGHT_SHARE = 0.25
#: Picture size [pixels]
WINDOW_SIZE = (1200, 800)
#: Contour lines drawn this share of the domain size in front of their section
LINE_LIFT = 1e-3


@dataclass
class BeadMetrics:
    """Bead and melt-pool metrics of one time, SI units (m, m2, m3, K)."""

    pool_length: float = 0.0
    pool_width: float = 0.0
    penetration: float = 0.0
    pool_volume: float = 0.0
    bead_width: float = 0.0
    bead_height: float = 0.0
    bead_area: float = 0.0
    fused_area: float = 0.0
    dilution: float = 0.0
    peak_temperature: float = 0.0
    bead_section: float = 0.0
    fused_section: float = 0.0
    bonded_width: float = 0.0
    unbonded_width: float = 0.0
    #: Highest temperature of the substrate surface [K]: how near the bond came
    peak_surface_temperature: float = 0.0
    #: Base metal's share of the bead section's metal (two metals; NaN with one)
    chemical_dilution: float = math.nan
    #: Secant angle of the bead's flanks at the toes [deg] (post only)
    wetting_angle: float = 0.0
    #: Metal fraction of the first cell layer on the surface under the bead
    #: [-] and its gas as a film [m] (post only; 1 and 0 where the clad wets
    #: the substrate)
    first_layer_metal_fraction: float = math.nan
    first_layer_gas: float = math.nan
    #: Width over which the bead is at least a quarter of its height thick
    #: [m] (post only): the bead width without thin toe films
    body_width: float = 0.0
    #: Gas in the cells below the substrate's surface [m3] and their least
    #: metal fraction [-] (post only): 0 and 1 for a substrate that stays
    #: solid; a mesh whose faces trade the substrate's metal for the gas
    #: above shows it here (CHANGELOG: the band's substrate cells)
    substrate_gas: float = math.nan
    substrate_least_metal_fraction: float = math.nan
    #: Share of the section's bead metal still liquid [-] (post only): 0
    #: where the section shows the bead's final shape
    section_liquid: float = math.nan
    #: The cells that hold the section's bead top across its width
    #: (bead_surface_cells): the finest and coarsest one's height [m] and
    #: the share of its width topped in cells coarser than the finest [-]
    #: (post only): 0 where the refined cells enclose the bead
    surface_cell: float = math.nan
    coarsest_surface_cell: float = math.nan
    coarse_surface: float = math.nan

    #: What ``ldna post`` reads from the fields, not from the function object
    POST_ONLY = ("wetting_angle", "first_layer_metal_fraction", "first_layer_gas",
                 "body_width", "substrate_gas", "substrate_least_metal_fraction",
                 "section_liquid", "surface_cell", "coarsest_surface_cell",
                 "coarse_surface")

    #: Column order of meltPoolMetrics.dat after the time
    FUNCTION_OBJECT_COLUMNS = (
        "pool_length", "pool_width", "penetration", "pool_volume", "bead_width",
        "bead_height", "bead_area", "fused_area", "dilution", "peak_temperature",
        "bead_section", "fused_section", "bonded_width", "unbonded_width",
        "peak_surface_temperature", "chemical_dilution",
    )

    def as_dict(self) -> dict[str, float]:
        """The metrics by name."""
        return asdict(self)


def fusion_temperature(case: Case | Path) -> float:
    """The solidus of the substrate's metal [K] (its own with two metals):
    meltPoolMetrics' default fusion line."""
    return Metal.substrate_of(Path(case)).solidus


#: meltPoolMetrics' table of the fusion line (postProcessing/<name>/<time>/<file>)
FUSION_LINE_TABLE = "fusionLine.dat"


def read_fusion_line(case: Case | Path, name: str, time: float) -> np.ndarray:
    """The fusion line written by the meltPoolMetrics function object ``name``
    at the time nearest ``time``: rows (transverse position, depth below the
    surface) [m] ascending across the weld; the depth is negative where the
    isotherm runs above the surface."""
    rows = []
    for table in (Path(case) / "postProcessing" / name).glob(f"*/{FUSION_LINE_TABLE}"):
        # A time without any isotherm crossing writes no row
        data = [line for line in table.read_text().splitlines()
                if line.strip() and not line.startswith("#")]
        if data:
            rows.append(np.loadtxt(data, ndmin=2))
    if not rows:
        return np.empty((0, 2))
    table = np.vstack(rows)
    nearest = table[np.argmin(np.abs(table[:, 0] - time)), 0]
    line = table[table[:, 0] == nearest, 1:]
    return line[np.argsort(line[:, 0], kind="stable")]


def fused_outline(line: np.ndarray, surface_height: float = 0.0) -> np.ndarray:
    """The fused zone's outline in the transverse plane, (y, z) points, from
    the function object's fusion line: the surface where the depth passes
    zero, the fusion line between.  The outline of each fused interval is
    one run of points; runs are separated by a row of NaN."""
    y, depth = line[:, 0], line[:, 1]
    points: list[tuple[float, float]] = []
    for k in range(len(y)):
        if depth[k] <= 0:
            continue
        if k == 0 or depth[k - 1] <= 0:
            if points:
                points.append((np.nan, np.nan))
            if k > 0:
                edge = y[k - 1] + (y[k] - y[k - 1]) * depth[k - 1] / (depth[k - 1] - depth[k])
                points.append((edge, surface_height))
        points.append((y[k], surface_height - depth[k]))
        if k + 1 < len(y) and depth[k + 1] <= 0:
            edge = y[k] + (y[k + 1] - y[k]) * depth[k] / (depth[k] - depth[k + 1])
            points.append((edge, surface_height))
    return np.array(points).reshape(-1, 2)


def read_case(case: Case | Path, time: float | None = None, decomposed: bool | None = None):
    """The internal mesh of ``case`` at ``time`` (default: latest) as a pyvista grid.

    Cell data holds the fields, point data their interpolation (for contours).
    ``decomposed``: read the ranks' folders (True) or the reconstructed
    times (False); by default a decomposed case without reconstructed
    times is read from its ranks.
    """
    import pyvista as pv

    case = Path(case)
    foam_file = case / f"{case.name}.foam"
    foam_file.touch()
    reader = pv.POpenFOAMReader(str(foam_file))
    reader.skip_zero_time = False
    if decomposed is None:
        decomposed = len(reader.time_values) <= 1 and (case / "processor0").is_dir()
    if decomposed:
        reader.case_type = "decomposed"
    times = reader.time_values
    reader.set_active_time_value(times[-1] if time is None else
                                 min(times, key=lambda t: abs(t - time)))
    reader.cell_to_point_creation = True
    reader.disable_all_patch_arrays()
    reader.enable_patch_array("internalMesh")
    grid = reader.read()["internalMesh"]
    grid.field_data["time"] = np.array([reader.active_time_value])
    return grid


def _cell_bounds(grid) -> tuple[np.ndarray, np.ndarray]:
    """Per-cell minimum and maximum of the point coordinates (the weld frame is x, y, z)."""
    frame_points = np.asarray(grid.points, dtype=float)
    connectivity = np.asarray(grid.cell_connectivity)
    offsets = np.asarray(grid.cell_offsets)
    starts = offsets[:-1]
    lows = np.minimum.reduceat(frame_points[connectivity], starts, axis=0)
    highs = np.maximum.reduceat(frame_points[connectivity], starts, axis=0)
    return lows, highs


def _largest_slice(areas: np.ndarray) -> int:
    """The slice of largest area; of slices equal to round-off, the most downstream."""
    return int(np.nonzero(areas >= (1 - SLICE_AREA_TOLERANCE) * areas.max())[0][-1])


@dataclass(frozen=True)
class _Section:
    """The cells of a transverse slice of the bead above the surface, as the
    meltPoolMetrics function object takes them: the slices are one shortest
    cell long along the weld, from the mesh's upstream end; the section is
    the plane through the slice's centre and holds every cell it cuts (a
    longer cell beside a refined bead zone too)."""

    low: np.ndarray
    high: np.ndarray
    alpha: np.ndarray
    #: Cells of the slice above the surface, and those of them that are metal
    in_slice: np.ndarray
    in_bead: np.ndarray

    @classmethod
    def of(cls, grid, bead_section: float, surface_height: float,
           metal_threshold: float) -> "_Section":
        low, high = _cell_bounds(grid)
        centre = 0.5 * (low + high)
        alpha = np.asarray(grid.cell_data["alpha.metal"])
        slice_length = (high - low)[:, 0].min()
        origin = low[:, 0].min()
        n_slices = max(1, int(np.ceil((high[:, 0].max() - origin) / slice_length - 1e-12)))
        index = int(np.clip(np.floor((bead_section - origin) / slice_length), 0, n_slices - 1))
        plane = origin + (index + 0.5) * slice_length
        in_slice = (centre[:, 2] >= surface_height) & (low[:, 0] <= plane) & (high[:, 0] > plane)
        return cls(low, high, alpha, in_slice, in_slice & (alpha >= metal_threshold))

    def metal_height_profile(self) -> tuple[np.ndarray, np.ndarray]:
        """The metal height h(y) across the weld (sum of alpha dz over the
        slice's cells above the surface), exact on the intervals between the
        cells' edges across the weld: the edges, and h on each interval.  Cells of
        different widths (a refined band at the surface under coarser cells)
        add to every interval they span, so no column is split by them."""
        # Edges of neighbouring cells equal to round-off are one edge
        low = np.round(self.low[self.in_slice, 1], EDGE_DECIMALS)
        high = np.round(self.high[self.in_slice, 1], EDGE_DECIMALS)
        metal = self.alpha[self.in_slice] * (self.high - self.low)[self.in_slice, 2]
        edges = np.unique(np.concatenate([low, high]))
        change = np.zeros(len(edges))
        np.add.at(change, np.searchsorted(edges, low), metal)
        np.subtract.at(change, np.searchsorted(edges, high), metal)
        return edges, np.cumsum(change)[:-1]

    @property
    def toes(self) -> tuple[float, float]:
        """The outer edges across the weld of the bead's metal cells."""
        return float(self.low[self.in_bead, 1].min()), float(self.high[self.in_bead, 1].max())


def bead_wetting_angle(grid, bead_section: float, surface_height: float = 0.0,
                       metal_threshold: float = METAL_THRESHOLD) -> float:
    """Secant angle [deg] of the bead's flanks at its toes, in the transverse
    slice at ``bead_section`` [m] (0 without bead there; the section as
    :class:`_Section` takes it)."""
    section = _Section.of(grid, bead_section, surface_height, metal_threshold)
    if not section.in_bead.any():
        return 0.0
    edges, height = section.metal_height_profile()
    return wetting_angle(0.5 * (edges[1:] + edges[:-1]), height, *section.toes)


def bead_body_width(grid, bead_section: float, surface_height: float = 0.0,
                    metal_threshold: float = METAL_THRESHOLD) -> float:
    """Width [m] across the weld over which the bead in the slice at
    ``bead_section`` is at least ``BODY_HEIGHT_SHARE`` of its height thick
    (its metal height profile), outermost to outermost: the bead without
    the thin films its toes may run out into (0 without a bead there)."""
    section = _Section.of(grid, bead_section, surface_height, metal_threshold)
    if not section.in_bead.any():
        return 0.0
    edges, height = section.metal_height_profile()
    if not height.max() > 0:
        return 0.0
    body = np.nonzero(height >= BODY_HEIGHT_SHARE * height.max())[0]
    return float(edges[body[-1] + 1] - edges[body[0]])


def bead_liquid_share(grid, bead_section: float, surface_height: float = 0.0) -> float:
    """Share of the bead's metal in the slice at ``bead_section`` that is
    liquid (liquidFraction, mushy cells by their fraction), each cell by its
    area in the section: 0 for a solidified bead, NaN without metal there.

    A bead section still partly liquid is not the bead's final shape: its
    metal still flows along the weld, and the section grows behind it as
    it freezes (the bead study's level 1 at 11 mm behind the wires: 29 mm2
    with a quarter liquid, 35 mm2 near the outlet with 3 %)."""
    # A case written without the liquid fraction does not say
    if "liquidFraction" not in grid.cell_data.keys():
        return math.nan
    section = _Section.of(grid, bead_section, surface_height, METAL_THRESHOLD)
    size = section.high - section.low
    metal = (np.clip(section.alpha, 0.0, 1.0) * size[:, 1] * size[:, 2])[section.in_slice]
    liquid = np.clip(np.asarray(grid.cell_data["liquidFraction"]), 0.0, 1.0)[section.in_slice]
    if not metal.sum() > 0:
        return math.nan
    return float((metal * liquid).sum() / metal.sum())


#: Cell heights within this share of each other are one cell size
CELL_SIZE_TOLERANCE = 0.01


def bead_surface_cells(grid, bead_section: float,
                       surface_height: float = 0.0) -> tuple[float, float, float]:
    """The cells that hold the bead's top in the slice at ``bead_section``:
    across the weld between its toes, the cell in which its metal height
    profile (what its height, area, body width and wetting angle are read
    from) ends.  Returns the finest such cell's height [m], the coarsest's
    [m], and the share of the bead's width whose top lies in cells coarser
    than the finest; NaN without a bead there.

    The refined zone must enclose the bead: where the bead rises or
    spreads out of it, its shape is read on the base mesh's cells, twice to
    four times coarser (the bead study's levels before its zone was raised:
    docs/accuracy-cost.md).  Pores inside the bead and films beyond its
    toes do not count: they are not its outline."""
    section = _Section.of(grid, bead_section, surface_height, METAL_THRESHOLD)
    if not section.in_bead.any():
        return math.nan, math.nan, math.nan
    edges, height = section.metal_height_profile()
    left, right = section.toes
    middle, width = 0.5 * (edges[1:] + edges[:-1]), np.diff(edges)
    # Intervals far narrower than a cell lie between edges that are one but
    # for the mesh's written round-off
    cells_across = (section.high - section.low)[section.in_slice, 1]
    columns = ((middle > left) & (middle < right) & (height > 0)
               & (width > CELL_SIZE_TOLERANCE * cells_across.min()))
    cells = np.nonzero(section.in_slice)[0]
    low, high = section.low[cells], section.high[cells]
    sizes, widths = [], []
    for y, top, share in zip(middle[columns], surface_height + height[columns],
                             width[columns]):
        holding = (low[:, 1] <= y) & (high[:, 1] > y) & (low[:, 2] < top) & (high[:, 2] >= top)
        if holding.any():
            sizes.append(float((high - low)[holding, 2].max()))
            widths.append(float(share))
    if not sizes:
        return math.nan, math.nan, math.nan
    size, across = np.array(sizes), np.array(widths)
    finest = float(size.min())
    coarse = size > (1 + CELL_SIZE_TOLERANCE) * finest
    return finest, float(size.max()), float(across[coarse].sum() / across.sum())


#: Cells whose lower face lies this share of their height from the surface
#: stand on it
SURFACE_ROW_TOLERANCE = 1e-3


def first_layer(grid, bead_section: float, surface_height: float = 0.0,
                metal_threshold: float = METAL_THRESHOLD) -> tuple[float, float]:
    """Metal fraction of the first layer of cells on the substrate's surface
    under the bead, between its toes, in the slice at ``bead_section``
    (each cell by its width across the weld), and the gas in it as a film
    thickness [m] (the gas's volume over the footprint's area: comparable
    between meshes whose first layers differ in height); NaN without a bead
    there.

    A clad that wets its substrate fills that layer (1, no film); gas the
    pool's front rolled over and froze in lowers it, and that gas separates
    the bead from the base metal (lack of fusion, docs/limitations.md)."""
    section = _Section.of(grid, bead_section, surface_height, metal_threshold)
    if not section.in_bead.any():
        return math.nan, math.nan
    left, right = section.toes
    height = (section.high - section.low)[:, 2]
    on_surface = section.in_slice & (
        np.abs(section.low[:, 2] - surface_height) <= SURFACE_ROW_TOLERANCE * height)
    width = np.clip(np.minimum(section.high[:, 1], right) - np.maximum(section.low[:, 1], left),
                    0.0, None) * on_surface
    if not width.sum() > 0:
        return math.nan, math.nan
    metal = np.clip(section.alpha, 0.0, 1.0)
    return (float((width * metal).sum() / width.sum()),
            float((width * (1 - metal) * height).sum() / width.sum()))


def substrate_gas(grid, surface_height: float = 0.0) -> tuple[float, float]:
    """Gas volume [m3] in the cells that lie below the substrate's surface
    (their highest point at or below ``surface_height``), and their least
    metal fraction; NaN where no cell does."""
    low, high = _cell_bounds(grid)
    below = high[:, 2] <= surface_height + SURFACE_ROW_TOLERANCE * (high - low)[:, 2]
    if not below.any():
        return math.nan, math.nan
    alpha = np.clip(np.asarray(grid.cell_data["alpha.metal"], dtype=float), 0.0, 1.0)
    volume = np.prod(high - low, axis=1)
    return float(((1 - alpha) * volume)[below].sum()), float(alpha[below].min())


#: The function object ``ldna post`` runs at the time it reads (its table:
#: postProcessing/<name>/<time>/meltPoolMetrics.dat)
POST_FUNCTION = "postMeltPoolMetrics"


def _time_name(case: Case, time: float) -> tuple[str, int]:
    """The written time directory nearest ``time`` and the ranks to read it
    with (1: reconstructed; else the processor directories)."""
    processors = sorted(case.path.glob("processor[0-9]*"))
    reconstructed = [t for t in case.times if (t / "alpha.metal").exists()]
    directories = reconstructed or (Case(processors[0]).times if processors else [])
    if not directories:
        raise FileNotFoundError(f"no written time in {case}")
    nearest = min(directories, key=lambda t: abs(float(t.name) - time))
    return nearest.name, 1 if reconstructed else len(processors)


def function_object_metrics(case: Case | Path, time: float, surface_height: float = 0.0,
                            bead_section: float | None = None,
                            fusion_temperature_: float | None = None) -> BeadMetrics:
    """The meltPoolMetrics function object's metrics of ``case`` at the written
    time nearest ``time``, run there with OpenFOAM's postProcess (in
    parallel on a case that is only decomposed)."""
    case = Case(case)
    time_name, n_procs = _time_name(case, time)
    entries = {"surfaceHeight": f"{surface_height:.12g}"}
    if bead_section is not None:
        entries["beadSection"] = f"{bead_section:.12g}"
    if fusion_temperature_ is not None:
        entries["fusionTemperature"] = f"{fusion_temperature_:.12g}"
    settings = "\n".join(f"        {key:<18}{value};" for key, value in entries.items())
    (case / "system" / POST_FUNCTION).write_text(f"""FoamFile
{{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      {POST_FUNCTION};
}}

functions
{{
    {POST_FUNCTION}
    {{
        type              meltPoolMetrics;
        libs              ("libldnaFunctionObjects.so");
{settings}
    }}
}}
""")
    # Its tables go to a folder named by the case's start time, which with
    # startFrom latestTime is not the time read: clear them all, so that
    # the one table written (and its fusion line) is this time's
    output = case / "postProcessing" / POST_FUNCTION
    shutil.rmtree(output, ignore_errors=True)
    fields = "T alpha.metal" + (" fillerFraction" if two_metals(case) else "")
    command = (f"postProcess -dict system/{POST_FUNCTION} -fields '({fields})' "
               f"-time {time_name}")
    case.run(command, n_procs=n_procs, log_name=POST_FUNCTION)
    (table,) = output.glob("*/meltPoolMetrics.dat")
    row = np.loadtxt(table, comments="#", ndmin=2)[-1]
    return BeadMetrics(**dict(zip(BeadMetrics.FUNCTION_OBJECT_COLUMNS, map(float, row[1:]))))


def wetting_angle(y: np.ndarray, metal_height: np.ndarray, toe_left: float,
                  toe_right: float) -> float:
    """Secant angle [deg] of the bead's flanks, the mean of both sides.

    The section's profile is the metal height h(y) at positions ``y``
    across the weld (values at equal positions are added):
    :meth:`_Section.metal_height_profile` gives it on the intervals between
    the cells' edges.  On each side the flank runs from the toe (the edge
    of the bead width, h = 0) to where h first reaches half the bead's
    height; the angle is atan(H/2 / that distance): on the mesh, the contact
    angle cannot be resolved more finely than a cell.
    """
    columns = np.round(y, 9)
    positions = np.unique(columns)
    profile = np.array([metal_height[columns == c].sum() for c in positions])
    if profile.max() <= 0:
        return 0.0
    half = 0.5 * profile.max()
    reaches = positions[profile >= half]
    run_left, run_right = reaches.min() - toe_left, toe_right - reaches.max()
    angles = [np.degrees(np.arctan2(half, run)) for run in (run_left, run_right) if run > 0]
    return float(np.mean(angles)) if angles else 90.0


def expected_bead_area(case: Case | Path) -> float:
    """The steady bead's section [m2]: wire mass rate / (metal density x welding speed).

    The mass balance no model escapes: what the wires feed leaves in the bead.
    Read from the case's dropletSource (wires' density, feed speed and radius),
    enthalpy-porosity welding speed and the metal's reference density.
    """
    case = Case(case)
    source = "constant/fvOptions"
    wires = re.findall(r"^\s*(\w+)\s*$", case.value(source, "wireDroplets/wires"), re.M)
    common_density = case.scalar(source, "wireDroplets/wireDensity")
    mass_rate = 0.0
    for wire in wires:
        key = f"wireDroplets/wires/{wire}"
        mass_rate += (common_density * case.scalar(source, f"{key}/feedSpeed")
                      * np.pi * case.scalar(source, f"{key}/wireRadius") ** 2)
    return mass_rate / (Metal.from_case(case).reference_density * welding_speed(case))


def welding_speed(case: Case | Path) -> float:
    """The substrate's speed [m/s] (the enthalpy-porosity source's ``weldingSpeed``)."""
    return Case(case).scalar("constant/fvOptions", "enthalpyPorosity/weldingSpeed")


def bead_arrival_time(case: Case | Path, section: float) -> float | None:
    """When the start of the bead reaches the transverse section at x = ``section`` [s].

    Deposition starts under the wires at t = 0 and the deposit travels with
    the substrate: (section - wires' midpoint) / welding speed, read from the
    case's dropletSource (``wireDroplets``) and enthalpy-porosity entries.
    Before then the section holds no bead, whatever the models.  None for a
    case without wires or without a moving substrate.
    """
    try:
        return _bead_arrival_time(Case(case), section)
    except KeyError:
        return None


def _bead_arrival_time(case: Case, section: float) -> float:
    source = "constant/fvOptions"
    first_wire_x = float(case.value(source, "wireDroplets/position").strip("()").split()[0])
    wires = re.findall(r"^\s*(\w+)\s*$", case.value(source, "wireDroplets/wires"), re.M)
    spacing = case.scalar(source, "wireDroplets/wireSpacing")
    midpoint = first_wire_x + 0.5 * (len(wires) - 1) * spacing
    return weld_start_time(case.path) + (section - midpoint) / welding_speed(case)


#: The record of ``Allrun -start-from`` that the case's weld started at T
#: from another weld's state (other parameters or mesh):
#: postProcessing/<name>/<T>/<file>.dat (bin/tools/RunFunctions)
WELD_START_RECORD = ("weldStart", "start")


def weld_start_time(case: Path) -> float:
    """When the case's own weld started [s]: 0, or the time at which it
    started from another weld's state, whose bead the sections hold until
    the case's own arrives (the latest such start)."""
    state = weld_start_state(case)
    return 0.0 if state is None else state[1]


def weld_start_state(case: Path) -> tuple[str, float] | None:
    """The folder name of the run whose state the case's weld started from
    and that start's time (the latest such start), or None for a weld that
    started on the case's own fields."""
    name, file = WELD_START_RECORD
    starts = []
    for record in (Path(case) / "postProcessing" / name).glob(f"*/{file}.dat"):
        lines = record.read_text().splitlines()
        source = next((line.rsplit(" ", 1)[-1] for line in lines if line.startswith("#")), "")
        starts += [(float(line), Path(source).name) for line in lines
                   if line.strip() and not line.startswith("#")]
    if not starts:
        return None
    time, source = max(starts)
    return source, time


#: The record of ``ldna steady-start`` that a case's time-0 fields are its
#: estimate: postProcessing/<name>/0/<file>.dat
STEADY_START_RECORD = ("steadyStart", "estimate")


def started_from_estimate(case: Case | Path) -> bool:
    """Whether the case's time-0 fields are the estimate of ``ldna steady-start``."""
    name, file = STEADY_START_RECORD
    return (Path(case) / "postProcessing" / name / "0" / f"{file}.dat").exists()


def bead_not_yet_there(arrival: float | None, time: float, section: float,
                       estimate: bool = False, weld_start: float = 0.0) -> str | None:
    """What to tell a user whose run ended before the bead reached its section, else None.

    ``estimate``: the run started from ``ldna steady-start``'s estimate, whose
    deposit the section holds until the computed one arrives; ``weld_start``
    (> 0): the run started then from another weld's state, whose bead the
    section holds until this weld's arrives.
    """
    if arrival is None or time >= arrival:
        return None
    holds = (f"the weld this run started from at t = {weld_start:.4g} s, not of its own"
             if weld_start > 0 else
             "the estimate of the start (ldna steady-start), not a computed bead"
             if estimate else "the substrate")
    return (f"The bead has not reached the section x = {1e3 * section:.2f} mm yet: its start "
            f"arrives there at about t = {arrival:.3g} s and this run ends at "
            f"{time:.3g} s.  The section metrics above are of {holds}; for the bead run "
            f"longer (bin/ldna-scene --end-time {max(2.0, round(arrival + 1.0)):g}, or endTime "
            "in system/controlDict).")


def configured_bead_section(case: Case | Path, name: str = "meltPoolMetrics") -> float | None:
    """The bead section [m] of the case's meltPoolMetrics function object ``name``, if any."""
    try:
        return Case(case).scalar("system/controlDict", f"functions/{name}/beadSection")
    except KeyError:
        return None


def summary(case: Case | Path, result: BeadMetrics, time: float) -> dict[str, float]:
    """The figures a welding engineer compares, in mm, mm2, K and degrees (``--json``)."""
    return {
        "time_s": time,
        "bead_area_mm2": 1e6 * result.bead_area,
        "expected_bead_area_mm2": 1e6 * expected_bead_area(case),
        "bead_width_mm": 1e3 * result.bead_width,
        "bead_height_mm": 1e3 * result.bead_height,
        "body_width_mm": 1e3 * result.body_width,
        "penetration_mm": 1e3 * result.penetration,
        "dilution": result.dilution,
        # None (JSON null) with one metal: no composition to measure
        "chemical_dilution": (None if math.isnan(result.chemical_dilution)
                              else result.chemical_dilution),
        "wetting_angle_deg": result.wetting_angle,
        # None (JSON null) without metal in the section or a liquid fraction
        "section_liquid_share": (None if math.isnan(result.section_liquid)
                                 else result.section_liquid),
        # None (JSON null) without a bead in the section
        "first_layer_metal_fraction": (None if math.isnan(result.first_layer_metal_fraction)
                                       else result.first_layer_metal_fraction),
        "first_layer_gas_mm": (None if math.isnan(result.first_layer_gas)
                               else 1e3 * result.first_layer_gas),
        "substrate_gas_mm3": (None if math.isnan(result.substrate_gas)
                              else 1e9 * result.substrate_gas),
        "substrate_least_metal_fraction": (None if math.isnan(
            result.substrate_least_metal_fraction) else result.substrate_least_metal_fraction),
        # None (JSON null) without a bead in the section
        "surface_cell_mm": (None if math.isnan(result.surface_cell)
                            else 1e3 * result.surface_cell),
        "coarsest_surface_cell_mm": (None if math.isnan(result.coarsest_surface_cell)
                                     else 1e3 * result.coarsest_surface_cell),
        "coarse_surface_share": (None if math.isnan(result.coarse_surface)
                                 else result.coarse_surface),
        "pool_length_mm": 1e3 * result.pool_length,
        "pool_width_mm": 1e3 * result.pool_width,
        "fused_area_mm2": 1e6 * result.fused_area,
        "bonded_width_mm": 1e3 * result.bonded_width,
        "unbonded_width_mm": 1e3 * result.unbonded_width,
        "bead_section_mm": 1e3 * result.bead_section,
        "peak_metal_temperature_K": result.peak_temperature,
        "peak_surface_temperature_K": result.peak_surface_temperature,
        "bead_arrival_s": bead_arrival_time(case, result.bead_section),
        "steady_start": started_from_estimate(case),
    }


def _plotter():
    """An off-screen plotter that needs no display."""
    if not os.environ.get("DISPLAY"):
        os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    import pyvista as pv

    plotter = pv.Plotter(off_screen=True, window_size=WINDOW_SIZE)
    plotter.set_background("white")
    return plotter


def _temperature_bar(title: str = "T [K]") -> dict:
    return {"title": title, "color": "black", "vertical": True}


def render_surface(grid, path: Path, temperature_range: tuple[float, float]) -> Path:
    """The free surface alpha.metal = 0.5 in 3D, coloured by temperature."""
    surface = grid.contour([0.5], scalars="alpha.metal", preference="point")
    plotter = _plotter()
    plotter.add_mesh(grid.outline(), color="grey")
    if surface.n_points:
        plotter.add_mesh(surface, scalars="T", cmap="inferno", clim=temperature_range,
                         scalar_bar_args=_temperature_bar())
    plotter.add_text(f"Free surface, t = {grid.field_data['time'][0]:.4g} s",
                     color="black", font_size=12)
    plotter.view_isometric()
    plotter.camera.azimuth = -30
    plotter.screenshot(str(path))
    plotter.close()
    return path


#: How ``render_section`` colours a section: the field, its colour map and
#: its bar's title
TEMPERATURE_COLOURS = ("T", "inferno", "T [K]")
#: The metal fraction, to show gas in the deposit (the first layer's film)
METAL_COLOURS = ("alpha.metal", "cividis", "metal fraction")


def render_section(grid, path: Path, normal: str, origin: tuple[float, float, float],
                   fusion_temperature_: float, temperature_range: tuple[float, float],
                   title: str, outline: np.ndarray | None = None,
                   surface_height: float = 0.0,
                   colours: tuple[str, str, str] = TEMPERATURE_COLOURS) -> Path:
    """A plane section coloured by temperature (or ``colours``: the metal
    fraction from 0 to 1), with the fusion line and free surface.

    ``outline``: (y, z) points of the fused zone in a transverse section
    (``fused_outline``), drawn as the fusion line; without it the fusion
    isotherm is contoured in the section's plane below the substrate's
    surface (``surface_height``).
    """
    section = grid.slice(normal=normal, origin=origin)
    plotter = _plotter()
    field, cmap, bar_title = colours
    plotter.add_mesh(section, scalars=field, cmap=cmap,
                     clim=temperature_range if field == "T" else (0.0, 1.0),
                     preference="cell", scalar_bar_args=_temperature_bar(bar_title))
    if outline is not None:
        fusion_lines = [_polyline(run, origin[0]) for run in _runs(outline)]
        fusion_label = "fusion line (pool's projection)"
    else:
        # The fusion isotherm bounds the substrate's molten metal: below its
        # surface (the deposit above, however hot, is the pool's, whose own
        # melting range differs), and gas is left out
        substrate = section.clip(normal="z", origin=(0.0, 0.0, surface_height), invert=True)
        metal_temperature = np.where(
            np.asarray(substrate.point_data["alpha.metal"]) >= METAL_THRESHOLD,
            np.asarray(substrate.point_data["T"]), temperature_range[0])
        substrate.point_data["metalT"] = metal_temperature
        fusion_lines = [substrate.contour([fusion_temperature_], scalars="metalT",
                                          preference="point")]
        fusion_label = "fusion isotherm (substrate)"
    fusion_lines = [line for line in fusion_lines if line.n_points]
    free_surface = section.contour([0.5], scalars="alpha.metal", preference="point")
    if normal == "x":
        plotter.view_yz()
    else:
        plotter.view_xz()
    # The lines lie in the section's plane: lift them towards the camera,
    # or the section hides them from one side
    camera = plotter.camera
    towards_camera = np.subtract(camera.position, camera.focal_point)
    lift = LINE_LIFT * grid.length * towards_camera / np.linalg.norm(towards_camera)
    for k, line in enumerate(fusion_lines):
        plotter.add_mesh(line.translate(lift, inplace=False), color="cyan", line_width=4,
                         label=fusion_label if k == 0 else None)
    if free_surface.n_points:
        plotter.add_mesh(free_surface.translate(lift, inplace=False), color="white",
                         line_width=3, label="free surface")
    if fusion_lines or free_surface.n_points:
        plotter.add_legend(bcolor="grey", size=(0.25, 0.1), loc="lower left")
    if outline is not None and not fusion_lines:
        plotter.add_text("no fusion line: the substrate stayed below its solidus "
                         "(lack of fusion)", position="lower_edge", color="black", font_size=10)
    plotter.add_text(title, color="black", font_size=12)
    plotter.screenshot(str(path))
    plotter.close()
    return path


def _runs(outline: np.ndarray) -> list[np.ndarray]:
    """The runs of an outline, split at its rows of NaN."""
    breaks = np.nonzero(np.isnan(outline[:, 0]))[0]
    runs = [chunk[~np.isnan(chunk[:, 0])] for chunk in np.split(outline, breaks)]
    return [run for run in runs if len(run) > 1]


def _polyline(yz: np.ndarray, x: float):
    """A pyvista line through the (y, z) points in the plane at ``x``."""
    import pyvista as pv

    points = np.column_stack([np.full(len(yz), x), yz])
    return pv.lines_from_points(points)


def post_process(case: Case | Path, output: Path | None = None, time: float | None = None,
                 surface_height: float = 0.0, bead_section: float | None = None,
                 fusion_temperature_: float | None = None,
                 temperature_range: tuple[float, float] | None = None
                 ) -> tuple[BeadMetrics, list[Path], float]:
    """Metrics, pictures and the time read of ``case`` at ``time`` (default: latest).

    PNGs and metrics.csv go to ``output``; the bead is measured at
    ``bead_section``, by default where the case's meltPoolMetrics measures it.
    The pictures' temperature scale is ``temperature_range`` (several cases
    drawn alike), by default the case's own range.
    """
    case = Path(case)
    output = Path(output or case / "pictures")
    output.mkdir(parents=True, exist_ok=True)
    grid = read_case(case, time)
    t_fusion = fusion_temperature_ or fusion_temperature(case)
    if bead_section is None:
        bead_section = configured_bead_section(case)
    time_read = float(grid.field_data["time"][0])
    result = function_object_metrics(case, time_read, surface_height, bead_section,
                                     fusion_temperature_)
    outline = fused_outline(read_fusion_line(case, POST_FUNCTION, time_read), surface_height)
    result.wetting_angle = bead_wetting_angle(grid, result.bead_section, surface_height)
    result.first_layer_metal_fraction, result.first_layer_gas = first_layer(
        grid, result.bead_section, surface_height)
    result.body_width = bead_body_width(grid, result.bead_section, surface_height)
    result.section_liquid = bead_liquid_share(grid, result.bead_section, surface_height)
    result.surface_cell, result.coarsest_surface_cell, result.coarse_surface = (
        bead_surface_cells(grid, result.bead_section, surface_height))
    result.substrate_gas, result.substrate_least_metal_fraction = substrate_gas(
        grid, surface_height)

    temperature = np.asarray(grid.cell_data["T"])
    if temperature_range is None:
        temperature_range = (float(temperature.min()), float(max(temperature.max(), t_fusion)))
    x_section = result.fused_section if result.penetration > 0 else result.bead_section
    centre = grid.center
    time_label = f"t = {grid.field_data['time'][0]:.4g} s"
    pictures = [
        render_surface(grid, output / "surface.png", temperature_range),
        render_section(grid, output / "transverse.png", "x", (x_section, centre[1], centre[2]),
                       t_fusion, temperature_range,
                       f"Transverse section x = {1e3 * x_section:.2f} mm, {time_label}",
                       outline, surface_height),
        render_section(grid, output / "longitudinal.png", "y", (centre[0], 0.0, centre[2]),
                       t_fusion, temperature_range,
                       f"Longitudinal section y = 0, {time_label}",
                       surface_height=surface_height),
        # The bead's section by metal fraction: gas under or in the bead
        render_section(grid, output / "transverse-metal.png", "x",
                       (result.bead_section, centre[1], centre[2]), t_fusion, temperature_range,
                       f"Bead section x = {1e3 * result.bead_section:.2f} mm, metal fraction, "
                       f"{time_label}", outline, surface_height, METAL_COLOURS),
    ]
    with open(output / "metrics.csv", "w", encoding="utf-8") as stream:
        values = result.as_dict()
        stream.write("time," + ",".join(values) + "\n")
        stream.write(f"{grid.field_data['time'][0]:.9g}," +
                     ",".join(f"{v:.9g}" for v in values.values()) + "\n")
    return result, pictures, float(grid.field_data['time'][0])


def read_function_object_metrics(case: Case | Path, name: str = "meltPoolMetrics") -> np.ndarray:
    """Rows (time, metrics...) of postProcessing/<name>/*/meltPoolMetrics.dat
    by time, of every run (a run restarted from the same time as an earlier
    one writes ``meltPoolMetrics_<time>.dat``: its rows replace the earlier)."""
    table = Case(case).function_object(name, "meltPoolMetrics.dat")
    if table.size == 0:
        raise FileNotFoundError(f"no postProcessing/{name}/*/meltPoolMetrics.dat in {case}")
    return table[np.argsort(table[:, 0], kind="stable")]


def format_metrics(result: BeadMetrics) -> str:
    """The metrics as a welding engineer reads them (mm, mm2, %)."""
    return "\n".join([
        f"pool length      {1e3 * result.pool_length:8.2f} mm",
        f"pool width       {1e3 * result.pool_width:8.2f} mm",
        f"penetration      {1e3 * result.penetration:8.2f} mm",
        f"pool volume      {1e9 * result.pool_volume:8.2f} mm3",
        f"bead width       {1e3 * result.bead_width:8.2f} mm",
        f"bead height      {1e3 * result.bead_height:8.2f} mm",
        f"bead body width  {1e3 * result.body_width:8.2f} mm (where a quarter of its height thick)",
        f"bead area        {1e6 * result.bead_area:8.2f} mm2",
        f"fused area       {1e6 * result.fused_area:8.2f} mm2",
        f"bonded width     {1e3 * result.bonded_width:8.2f} mm",
        f"unbonded width   {1e3 * result.unbonded_width:8.2f} mm",
        f"dilution         {100 * result.dilution:8.2f} %",
        (f"chemical dilut.  {100 * result.chemical_dilution:8.2f} %"
         if not math.isnan(result.chemical_dilution) else "chemical dilut.       n/a (one metal)"),
        f"peak metal T     {result.peak_temperature:8.1f} K",
        f"peak surface T   {result.peak_surface_temperature:8.1f} K",
        f"bead section x   {1e3 * result.bead_section:8.2f} mm",
        f"deepest fusion x {1e3 * result.fused_section:8.2f} mm",
        f"wetting angle    {result.wetting_angle:8.1f} deg",
        (f"section liquid   {100 * result.section_liquid:8.1f} % of its bead's metal "
         "(0: the bead's final shape)" if not math.isnan(result.section_liquid)
         else "section liquid        n/a (no metal there or no liquidFraction written)"),
        f"first layer      {100 * result.first_layer_metal_fraction:8.1f} % metal "
        f"(gas film {1e3 * result.first_layer_gas:.3f} mm)",
        f"substrate gas    {1e9 * result.substrate_gas:8.3f} mm3 (least metal fraction "
        f"{result.substrate_least_metal_fraction:.4f}; a solid substrate holds none)",
        surface_cells_text(result),
    ])


def surface_cells_text(result: BeadMetrics) -> str:
    """The cells that top the section's bead, and whether the refined cells
    enclose it."""
    if math.isnan(result.coarse_surface):
        return "bead top cells        n/a (no bead in the section)"
    finest = 1e3 * result.surface_cell
    if not result.coarse_surface > 0:
        return f"bead top cells   {finest:8.3f} mm (the refined cells enclose the bead)"
    return (f"bead top cells   {finest:8.3f} to {1e3 * result.coarsest_surface_cell:.3f} mm: "
            f"{100 * result.coarse_surface:.1f} % of the bead's width is topped by cells "
            f"coarser than {finest:.3f} mm: out of the refined cells (a process zone below the "
            "bead's top, or a band split from another bead; docs/limitations.md)")
