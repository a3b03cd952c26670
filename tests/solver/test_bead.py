"""Droplets that arrive as bodies of metal (dropletSource mode insertion).

- insertion: a droplet enters as a sphere of metal fraction 1 whose volume
  on the mesh is exactly 4/3 pi R^3 (1 %), the metal fraction stays bounded
  and the solver's metal mass equals the mass the source reports;
- a droplet radius of fewer than 1.5 cells stops insertion with an error
  naming the cell size and the level that would do;
- with three cells per droplet radius (the template's level 1) a droplet
  flies as a body: metal fraction >= 0.99 in its cells 2 ms after it left
  the wire tip;
- the LDNA template at level 0, briefly, on a substrate preheated under the
  process: droplets fly as bodies of metal (cells more than half metal) and
  a pool melts into the substrate.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from foamlib import FoamFile

from solver_cases import prepare_test_case
from ldna.balance import WIRE_COLUMNS, wire_table
from ldna.case import Case

VOLUME_TOLERANCE = 0.01
ALPHA_BOUND = 1e-6
#: A droplet body: cells this full between the wire tips and the surface
BODY_FRACTION = 0.99
#: The first pulse of the default switch (eq. 18) at 100 Hz starts at
#: (asin 0.8 - asin 0.9 + 2 pi)/(2 pi 100) = 9.69 ms; the box stops in the
#: step after it, with the droplets just inserted
END_OF_FIRST_DROPLET = "0.0098"


def droplet_radius(log_text: str) -> float:
    """The regular droplet radius [m] the source reports for its first wire."""
    return float(re.search(r"droplet radius (\S+) m", log_text).group(1))


@pytest.fixture
def insertion_box(tmp_path: Path) -> Case:
    """The closed argon box of the droplet tests, 1/3 mm cells, droplets inserted."""
    case = prepare_test_case("dropletBox", tmp_path, material_from_template=True)
    case.set("constant/fvOptions", "wireDroplets/mode", "insertion", create=True)
    block_mesh = case / "system" / "blockMeshDict"
    block_mesh.write_text(block_mesh.read_text().replace("(20 16 32)", "(30 24 48)"))
    case.run("blockMesh")
    return case


def test_inserted_droplet_is_a_sphere_of_exact_volume(insertion_box: Case) -> None:
    case = insertion_box
    for entry in ("endTime", "writeInterval"):
        case.set("system/controlDict", entry, END_OF_FIRST_DROPLET)
    case.set("system/controlDict", "writeFormat", "ascii")
    result = case.run("ldnaFoam")
    log = result.output

    radius = droplet_radius(log)
    last = case.times[-1]
    alpha = case.field("alpha.metal", last)
    case.run("postProcess -func writeCellVolumes -latestTime", log_name="postProcess")
    volumes = case.field("V", last)
    n_droplets = sum(len(np.unique(values[:, 0])) - 1 for values in wire_table(case).values())
    assert n_droplets == 2, "one droplet per wire by the end of the first pulse"
    expected = n_droplets * 4 / 3 * math.pi * radius**3
    assert abs(np.sum(alpha * volumes) / expected - 1) < VOLUME_TOLERANCE
    assert alpha.max() >= BODY_FRACTION, "the droplet is a body of metal, not a smear"
    low, high = case.alpha_bounds()
    assert low > -ALPHA_BOUND and high < 1 + ALPHA_BOUND

    # The solver's metal mass is the mass the source reports it inserted
    balances = case.balances()
    added = sum(values[-1, WIRE_COLUMNS.index("addedMass")]
                for values in wire_table(case).values())
    assert balances["metal_mass"][-1] - balances["metal_mass"][0] == pytest.approx(added, rel=1e-6)


#: Sub-samples per cell edge of the independent sphere/cell overlap: its
#: error in a cut cell is below 1/SAMPLES of the cell (a plane through the
#: cell moves by at most half a sample spacing)
SAMPLES = 24


def planar_cut_bound(spacing: float, radius: float) -> float:
    """Bound on sum |metal fraction - overlap| V over a sphere's cells, as a
    share of its volume, for a cut that is planar within each cell: a facet
    h wide misses the sphere by its sagitta h^2/(8 R), a lens of at most a
    third of (sagitta x area) over the sphere's area 4 pi R^2, against the
    volume 4/3 pi R^3: (h / R)^2 / 8."""
    return (spacing / radius) ** 2 / 8


def droplet_radius_of_eq16(case: Case, wire: str) -> float:
    """The droplet radius [m] of a wire from its feed (eq. 16): one droplet
    per detachment period takes the wire volume fed in it."""
    source = "constant/fvOptions"
    key = f"wireDroplets/wires/{wire}"
    volume = (math.pi * case.scalar(source, f"{key}/wireRadius") ** 2
              * case.scalar(source, f"{key}/feedSpeed")
              / case.scalar(source, f"{key}/detachmentFrequency"))
    return (3 * volume / (4 * math.pi)) ** (1 / 3)


def sphere_overlap(centres: np.ndarray, spacing: np.ndarray, centre: np.ndarray,
                   radius: float) -> np.ndarray:
    """Volume share of each box-shaped cell (centres, edge lengths) inside a
    sphere, from SAMPLES^3 points per cell."""
    offsets = (np.arange(SAMPLES) + 0.5) / SAMPLES - 0.5
    grid = np.stack(np.meshgrid(offsets, offsets, offsets, indexing="ij"), -1).reshape(-1, 3)
    overlap = np.zeros(len(centres))
    near = np.linalg.norm(centres - centre, axis=1) < radius + np.linalg.norm(spacing)
    for i in np.nonzero(near)[0]:
        points = centres[i] + grid * spacing
        overlap[i] = np.mean(np.linalg.norm(points - centre, axis=1) < radius)
    return overlap


def test_inserted_droplet_holds_the_sphere_cell_by_cell(insertion_box: Case) -> None:
    """Each droplet, as the insertions table states its centre: its radius is
    eq. 16's, its cells hold the sphere's overlap computed here (not the
    code's cut); the table reports how far the planar cut at the radius falls
    short of the sphere and the cut radius that makes it whole."""
    case = insertion_box
    for entry in ("endTime", "writeInterval"):
        case.set("system/controlDict", entry, END_OF_FIRST_DROPLET)
    case.set("system/controlDict", "writeFormat", "ascii")
    case.run("ldnaFoam")
    last = case.times[-1]
    alpha = case.field("alpha.metal", last)
    centres = case.field("C", "0") if (case / "0" / "C").exists() else None
    if centres is None:
        case.run("postProcess -func writeCellCentres -latestTime", log_name="writeCellCentres")
        centres = case.field("C", last)
    points = np.asarray(FoamFile(case / "constant" / "polyMesh" / "points")[None])
    spacing = np.array([np.diff(np.unique(np.round(points[:, k], 12))).max() for k in range(3)])
    volume = float(np.prod(spacing))

    insertions = case.table("wireDroplets", "insertions")
    wires = re.findall(r"^\s*(\w+)\s*$", case.value("constant/fvOptions", "wireDroplets/wires"), re.M)
    assert len(insertions) == 2, "one droplet per wire by the end of the first pulse"
    overlap = np.zeros_like(alpha)
    for row in insertions:
        radius = droplet_radius_of_eq16(case, wires[int(row["wire"]) - 1])
        exact = 4 / 3 * math.pi * radius**3
        print(f"wire {int(row['wire'])}: radius {1e3 * row['radius']:.5f} mm (eq. 16: "
              f"{1e3 * radius:.5f}), {int(row['cells'])} cells; cut at the radius "
              f"{row['cutVolume']:.6e} m3 ({100 * (row['cutVolume'] / exact - 1):+.2f} % of "
              f"4/3 pi R^3), cut radius {row['cutRadius'] / radius:.5f} R, volume put in "
              f"{row['volume'] / exact:.9f} of 4/3 pi R^3")
        assert row["radius"] == pytest.approx(radius, rel=1e-9)
        # A planar cut inside each cell lies inside a sphere: short of its volume
        assert row["cutVolume"] < exact and row["cutRadius"] > radius
        assert row["volume"] == pytest.approx(exact, rel=1e-9)
        centre = np.array([row["centreX"], row["centreY"], row["centreZ"]])
        overlap += sphere_overlap(centres, spacing, centre, radius)
    exact_total = sum(4 / 3 * math.pi * droplet_radius_of_eq16(case, w) ** 3 for w in wires)
    sampled = overlap.sum() * volume
    shape_error = np.abs(alpha - overlap).sum() * volume / exact_total
    bound = planar_cut_bound(spacing.max(), droplet_radius_of_eq16(case, wires[0]))
    print(f"metal {alpha.sum() * volume:.6e} m3, sampled overlap {sampled:.6e} m3, "
          f"4/3 pi R^3 {exact_total:.6e} m3; sum |alpha - overlap| V / volume {100 * shape_error:.2f} %, "
          f"(bound {100 * bound:.2f} %), largest cell difference {np.abs(alpha - overlap).max():.3f}")
    assert abs(sampled / exact_total - 1) < 1 / SAMPLES, "the independent overlap is the sphere"
    assert abs(alpha.sum() * volume / exact_total - 1) < VOLUME_TOLERANCE
    assert shape_error < bound


def test_insertion_stops_on_unresolved_droplets(tmp_path: Path) -> None:
    case = prepare_test_case("dropletBox", tmp_path, material_from_template=True)
    case.set("constant/fvOptions", "wireDroplets/mode", "insertion", create=True)
    case.run("blockMesh")
    result = case.run("ldnaFoam", check=False)
    assert result.returncode != 0
    text = result.output
    assert "FOAM FATAL IO ERROR" in text and "Segmentation" not in text
    assert "at least 1.5 cells per radius" in text
    # The largest cell that inserts them: 1.5 cells on the radius of eq. 16,
    # V_d = v_w pi R_w^2 / nu_d (the case's wires: 0.6 mm, 0.11583 m/s, 100 Hz)
    radius = (3 * 0.11583 * 0.6e-3**2 / (4 * 100)) ** (1 / 3)
    largest = float(text.split("cells of at most ")[1].split()[0])
    assert abs(largest / (radius / 1.5) - 1) < 1e-5
    assert "wireDroplets" in text



#: The switch phase [deg] that starts the first pulse at 0.1 ms (eq. 18:
#: pulses start where 360 nu t + phase passes asin 0.8 = 53.13 deg)
EARLY_PULSE_PHASE = 53.1301 - 360 * 100 * 1e-4
#: Flight time before the droplet is looked at [s]
FLIGHT_TIME = "0.0021"


def test_resolved_droplet_flies_as_a_body(tmp_path: Path) -> None:
    case = prepare_test_case("dropletBox", tmp_path, material_from_template=True)
    options = "constant/fvOptions"
    for entry, value in (("mode", "insertion"), ("switchPhase", f"{EARLY_PULSE_PHASE:.4f}")):
        case.set(options, f"wireDroplets/{entry}", value, create=True)
    # 0.222 mm cells: three per droplet radius
    block_mesh = case / "system" / "blockMeshDict"
    block_mesh.write_text(block_mesh.read_text().replace("(20 16 32)", "(45 36 72)"))
    case.run("blockMesh")
    for entry in ("endTime", "writeInterval"):
        case.set("system/controlDict", entry, FLIGHT_TIME)
    case.set("system/controlDict", "writeFormat", "ascii")
    result = case.run("ldnaFoam")
    assert "under-resolved" not in result.output

    alpha = case.field("alpha.metal")
    print(f"after {FLIGHT_TIME} s of flight: largest metal fraction {alpha.max():.4f}")
    assert alpha.max() >= BODY_FRACTION, "a resolved droplet flies as a body of metal"

#: The template's short run: written when the first droplets are in flight
#: (they detach at 9.7 ms) and when they have landed
IN_FLIGHT_TIME = "0.012"
LANDED_TIME = "0.03"
#: A substrate preheated under the process so that a pool melts into it
#: within the short run: this far below the substrate's solidus [K] (the
#: contact temperature of 2100 K droplets on it, about the two bodies' mean
#: for steels of alike effusivity, then lies above its liquidus).  The test
#: was written with a 316L substrate at 1600 K, 75 K below its solidus; at
#: 1600 K the AISI 1024 substrate (solidus 1760 K) reached a liquid fraction
#: of at most 0.47
PREHEATED_BOX = "(5e-3 -6e-3 -2e-3) (15e-3 6e-3 0)"
PREHEAT_BELOW_SOLIDUS = 75.0


def test_template_droplets_arrive_as_bodies_into_a_pool(ldna_case: Case) -> None:
    case = ldna_case
    case.set("system/controlDict", "endTime", LANDED_TIME)
    case.set("system/controlDict", "writeControl", "adjustableRunTime")
    case.set("system/controlDict", "writeInterval", IN_FLIGHT_TIME)
    preheat_temperature = (case.scalar("constant/thermophysicalProperties", "substrate/solidus")
                           - PREHEAT_BELOW_SOLIDUS)
    set_fields = case / "system" / "setFieldsDict"
    text = set_fields.read_text()
    preheat = f"""
    boxToCell
    {{
        box {PREHEATED_BOX};
        fieldValues (volScalarFieldValue T {preheat_temperature:g});
    }}
);"""
    set_fields.write_text(text[:text.rindex(");")] + preheat + text[text.rindex(");") + 2:])
    case.mesh()
    case.run("setFields")
    case.run("ldnaFoam")
    case.run("postProcess -func writeCellCentres -time 0", log_name="postProcess")
    z = case.field("C", "0")[:, 2]
    wire_height = 1e-3 * case.scalar("system/caseParameters", "wireHeight")

    # At level 0 (1.5 cells per radius) a droplet in flight straddles cells:
    # it stays a body (cells mostly metal), where the paper's Gaussian source
    # put 0.11 at most into any cell at the coarsest level
    in_flight = case.field("alpha.metal", IN_FLIGHT_TIME)
    between = (z > 0.1 * wire_height) & (z < 0.9 * wire_height)
    print(f"in flight: largest metal fraction {in_flight[between].max():.4f}")
    assert in_flight[between].max() > 0.5, "droplets fly as bodies of metal"

    last = case.times[-1]
    alpha = case.field("alpha.metal", last)
    liquid = case.field("liquidFraction", last)
    molten_substrate = (z < 0) & (alpha > 0.5) & (liquid > 0.5)
    print(f"landed: {molten_substrate.sum()} molten substrate cells")
    assert molten_substrate.sum() > 0, "a pool melts into the substrate"
    low, high = case.alpha_bounds()
    assert low > -ALPHA_BOUND and high < 1 + ALPHA_BOUND
