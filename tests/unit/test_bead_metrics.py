"""Bead metrics that ``ldna post`` reads without a run: the wetting angle of
known caps, a run shorter than the bead's travel, a restarted run's rows
(the meltPoolMetrics function object on prescribed and solved fields is
tests/solver/test_post.py).
"""
from __future__ import annotations

import math
import os
import time
from pathlib import Path

import numpy as np
import pytest

from ldna.post import bead_not_yet_there, read_function_object_metrics, wetting_angle


#: Columns across the synthetic circular-cap bead (width 2 a) of the wetting-angle test
CAP_COLUMNS = 400
CAP_HALF_WIDTH = 7.5e-3


@pytest.mark.parametrize("contact_angle", [20.0, 45.0, 60.0, 90.0])
def test_wetting_angle_of_a_circular_cap(contact_angle: float) -> None:
    """The secant angle of a circular-cap bead against its closed form.

    A cap of half-width a and contact angle theta has radius R = a / sin(theta)
    and height H = a tan(theta / 2); its flank reaches H / 2 at
    |y| = sqrt(R^2 - (R - H / 2)^2), so the secant angle is
    atan(H / 2 / (a - |y|)).  Columns of width a / 200 give it within 0.5 deg.
    """
    a = CAP_HALF_WIDTH
    theta = math.radians(contact_angle)
    radius = a / math.sin(theta)
    height = a * math.tan(theta / 2)
    y = np.linspace(-a, a, CAP_COLUMNS + 1)
    y = 0.5 * (y[1:] + y[:-1])
    centre_height = height - radius
    profile = np.clip(np.sqrt(np.clip(radius**2 - y**2, 0, None)) + centre_height, 0, None)
    flank = math.sqrt(radius**2 - (radius - height / 2) ** 2)
    expected = math.degrees(math.atan2(height / 2, a - flank))
    measured = wetting_angle(y, profile, -a, a)
    print(f"contact angle {contact_angle:g}: secant {expected:.2f}, measured {measured:.2f}")
    assert measured == pytest.approx(expected, abs=0.5)
    assert 0 < measured < 90


def test_wetting_angle_of_flat_and_square_deposits() -> None:
    """No metal: angle 0; a rectangle of height H whose toes lie d outside its
    outermost columns: atan(H / 2 / d), near 90 degrees."""
    y = np.linspace(-1e-3, 1e-3, 201)
    assert wetting_angle(y, np.zeros_like(y), -1e-3, 1e-3) == 0.0
    height, toe_gap = 1e-3, 1e-5
    expected = math.degrees(math.atan2(height / 2, toe_gap))
    measured = wetting_angle(y, np.full_like(y, height), -1e-3 - toe_gap, 1e-3 + toe_gap)
    assert measured == pytest.approx(expected, rel=1e-9)


def test_a_run_shorter_than_the_bead_travel_says_so() -> None:
    section = 20.1e-3
    early = bead_not_yet_there(arrival=1.48, time=0.5, section=section)
    assert early is not None and "20.10 mm" in early and "t = 1.48 s" in early
    assert "--end-time 2" in early and "of the substrate" in early
    assert bead_not_yet_there(arrival=1.48, time=1.48, section=section) is None
    assert bead_not_yet_there(arrival=None, time=0.5, section=section) is None
    # Started at 10 s from another weld: the section holds that weld's bead
    changed = bead_not_yet_there(arrival=11.48, time=10.5, section=section, weld_start=10.0)
    assert changed is not None and "started from at t = 10 s" in changed
    assert "--end-time 12" in changed


def test_a_run_restarted_from_the_same_time_replaces_the_earlier_rows(tmp_path: Path) -> None:
    """OpenFOAM's writeFile names the table of a second run from the same
    start time meltPoolMetrics_<time>.dat: the metrics are that run's, not
    the first file's (a killed run resumed from its last written time)."""
    from ldna.post import read_function_object_metrics

    folder = tmp_path / "postProcessing" / "meltPoolMetrics" / "12.8"
    folder.mkdir(parents=True)
    header = "# Time\t" + "\t".join(f"c{i}" for i in range(15)) + "\n"

    def rows(times: list[float], value: float) -> str:
        return "".join(f"{t}" + f"\t{value}" * 15 + "\n" for t in times)

    (folder / "meltPoolMetrics.dat").write_text(header + rows([12.81, 12.82], 1.0))
    newer = folder / "meltPoolMetrics_12.8.dat"
    newer.write_text(header + rows([12.81, 12.82, 12.83, 12.84], 2.0))
    os.utime(newer, (time.time() + 10, time.time() + 10))
    table = read_function_object_metrics(tmp_path)
    np.testing.assert_array_equal(table[:, 0], [12.81, 12.82, 12.83, 12.84])
    assert (table[:, 1:] == 2.0).all()


def _cubes(cell: float, origin: tuple[float, float, float],
           size: tuple[float, float, float]) -> "object":
    """Cubic cells of edge ``cell`` filling the box at ``origin`` of ``size``
    [m], as the OpenFOAM reader gives a mesh (an unstructured grid)."""
    import pyvista as pv

    shape = tuple(round(length / cell) for length in size)
    return pv.ImageData(dimensions=tuple(n + 1 for n in shape), spacing=(cell,) * 3,
                        origin=origin).cast_to_unstructured_grid()


def _block(cell: float, alpha_of) -> "object":
    """A block of cubic cells (x 0-2 mm, y -3-3 mm, z -1-1 mm) as the
    OpenFOAM reader gives it, with alpha.metal from ``alpha_of(y, z)`` of
    each cell's centre."""
    grid = _cubes(cell, (0.0, -3e-3, -1e-3), (2e-3, 6e-3, 2e-3))
    centres = np.asarray(grid.cell_centers().points)
    grid.cell_data["alpha.metal"] = np.array([alpha_of(y, z) for _, y, z in centres])
    return grid


@pytest.mark.parametrize("cell", [0.25e-3, 0.125e-3])
def test_first_layer_of_a_bead_on_a_gas_film(cell: float) -> None:
    """A 4 mm wide bead whose first layer on the substrate holds a gas film
    0.1 mm thick under its middle 2 mm and none under the rest: the layer's
    metal fraction is the width-weighted mean of its cells, the film the
    gas's volume over the footprint: 0.1 x 2 / 4 = 0.05 mm on either mesh."""
    from ldna.post import first_layer

    film = 0.1e-3

    def alpha(y: float, z: float) -> float:
        if z < 0:
            return 1.0
        if abs(y) > 2e-3 or z > 1e-3:
            return 0.0
        if z < cell and abs(y) < 1e-3:
            return 1 - film / cell
        return 1.0

    fraction, gas = first_layer(_block(cell, alpha), 1e-3)
    assert gas == pytest.approx(0.5 * film, rel=1e-9)
    assert fraction == pytest.approx(1 - 0.5 * film / cell, rel=1e-9)


def test_first_layer_of_a_wetting_bead_and_of_none() -> None:
    """A bead that fills its first layer has no film; a section without metal
    above the surface has no first layer to measure."""
    from ldna.post import first_layer

    bead = _block(0.25e-3, lambda y, z: 1.0 if z < 0 or (abs(y) < 2e-3 and z < 1e-3) else 0.0)
    assert first_layer(bead, 1e-3) == (1.0, 0.0)
    bare = _block(0.25e-3, lambda y, z: 1.0 if z < 0 else 0.0)
    assert all(math.isnan(value) for value in first_layer(bare, 1e-3))



@pytest.mark.parametrize("cell", [0.25e-3, 0.125e-3])
def test_liquid_share_of_a_bead_section(cell: float) -> None:
    """A bead 4 mm wide and 1 mm high over a molten substrate: liquid in its
    upper half, the share is 1/2; mushy throughout at a liquid fraction of
    0.3, 0.3; frozen, 0 (the substrate's liquid is not the bead's); a
    section without metal above the surface has no share."""
    from ldna.post import bead_liquid_share

    def in_bead(y: float, z: float) -> bool:
        return abs(y) < 2e-3 and 0 <= z < 1e-3

    grid = _block(cell, lambda y, z: 1.0 if z < 0 or in_bead(y, z) else 0.0)
    _, y, z = np.asarray(grid.cell_centers().points).T
    for liquid, share in ((np.where(z > 0.5e-3, 1.0, 0.0), 0.5),
                          (np.full_like(z, 0.3), 0.3), (np.zeros_like(z), 0.0)):
        grid.cell_data["liquidFraction"] = np.where(z < 0, 1.0, liquid)
        assert bead_liquid_share(grid, 1e-3) == pytest.approx(share, rel=1e-12, abs=1e-15)
    bare = _block(cell, lambda y, z: 1.0 if z < 0 else 0.0)
    bare.cell_data["liquidFraction"] = np.ones(bare.n_cells)
    assert math.isnan(bead_liquid_share(bare, 1e-3))


def _layered_block(fine: float, coarse: float, band_top: float, alpha_of) -> "object":
    """Cells of ``fine`` size in a band on the substrate's surface (z from 0 to
    ``band_top``) between cells of ``coarse`` size, as the band meshes of the
    bead study are layered (one coarse cell long in x, y -3-3 mm, z -0.5 to
    2.5 mm); alpha.metal the share of each cell's section inside the metal,
    ``alpha_of(y, z)`` (vectorised) sampled on 16 x 16 points of it."""
    import pyvista as pv

    def block(size: float, z0: float, z1: float):
        shape = (round(coarse / size), round(6e-3 / size), round((z1 - z0) / size))
        return pv.ImageData(dimensions=tuple(n + 1 for n in shape), spacing=(size,) * 3,
                            origin=(0.0, -3e-3, z0)).cast_to_unstructured_grid()

    grid = block(coarse, -0.5e-3, 0.0).merge(block(fine, 0.0, band_top), merge_points=False)
    grid = grid.merge(block(coarse, band_top, 2.5e-3), merge_points=False)
    bounds = np.array([grid.get_cell(cell).bounds for cell in range(grid.n_cells)])
    share = (np.arange(16) + 0.5) / 16
    ys = bounds[:, 2, None, None] + share[None, :, None] * (bounds[:, 3] - bounds[:, 2])[:, None, None]
    zs = bounds[:, 4, None, None] + share[None, None, :] * (bounds[:, 5] - bounds[:, 4])[:, None, None]
    grid.cell_data["alpha.metal"] = alpha_of(*np.broadcast_arrays(ys, zs)).mean(axis=(1, 2))
    return grid


def test_wetting_angle_on_a_band_mesh_of_two_cell_sizes() -> None:
    """A circular cap of contact angle 60 deg (half-width 2 mm) on a mesh whose
    first 0.25 mm above the surface has cells half as wide as those above it:
    the cells of the two sizes are not columns, and the metal height across
    the weld must still add them all up.  The secant angle (closed form as
    in test_wetting_angle_of_a_circular_cap: 50.7 deg) is measured on the
    layered mesh as on a mesh of the fine cells throughout; the toes lie on
    the outer faces of the fine cells at the surface, up to a cell outside
    the cap's, which bounds the angle from below."""
    from ldna.post import bead_wetting_angle

    a, theta = 2e-3, math.radians(60.0)
    radius, height = a / math.sin(theta), a * math.tan(theta / 2)

    def cap(y: np.ndarray, z: np.ndarray) -> np.ndarray:
        top = np.sqrt(np.clip(radius**2 - y**2, 0.0, None)) + height - radius
        return ((z < 0) | (z <= top)).astype(float)

    fine, coarse = 0.0625e-3, 0.125e-3
    flank = math.sqrt(radius**2 - (radius - height / 2) ** 2)
    expected = math.degrees(math.atan2(height / 2, a - flank))
    toe_a_cell_out = math.degrees(math.atan2(height / 2, a - flank + fine))
    uniform = bead_wetting_angle(_layered_block(fine, fine, 0.25e-3, cap), 0.5 * coarse)
    layered = bead_wetting_angle(_layered_block(fine, coarse, 0.25e-3, cap), 0.5 * coarse)
    print(f"secant {expected:.2f} deg ({toe_a_cell_out:.2f} with the toes a cell out); "
          f"fine cells {uniform:.2f}, layered {layered:.2f}")
    for measured in (uniform, layered):
        assert toe_a_cell_out - 0.5 <= measured <= expected + 0.5
    assert layered == pytest.approx(uniform, abs=1.0)


def test_body_width_leaves_out_a_toe_film() -> None:
    """A rectangular bead 4 mm wide and 1 mm high whose toes run out into a
    film 0.0625 mm thick to 2.5 mm either side: the bead width (toe to toe,
    where the film's cells are metal) is the film's 5 mm, the body width
    (a quarter of the height thick) the rectangle's 4 mm, on the layered
    mesh as on the fine one."""
    from ldna.post import bead_body_width

    fine, coarse = 0.0625e-3, 0.125e-3

    def bead(y: np.ndarray, z: np.ndarray) -> np.ndarray:
        film = (np.abs(y) <= 2.5e-3) & (z <= fine)
        return ((z < 0) | ((np.abs(y) <= 2e-3) & (z <= 1e-3)) | film).astype(float)

    for cells in ((fine, fine), (fine, coarse)):
        width = bead_body_width(_layered_block(*cells, 0.25e-3, bead), 0.5 * coarse)
        assert width == pytest.approx(4e-3, abs=1e-9)
    bare = _layered_block(fine, coarse, 0.25e-3, lambda y, z: (z < 0).astype(float))
    assert bead_body_width(bare, 0.5 * coarse) == 0.0


@pytest.mark.parametrize("cell", [0.25e-3, 0.125e-3])
def test_substrate_gas_of_a_substrate_that_took_gas_in(cell: float) -> None:
    """A substrate 1 mm deep (2 x 6 mm) whose top 0.25 mm row holds 10 % gas
    in a strip 2 mm wide (|y| < 1 mm) under a bead: 0.1 x 0.25 x 2 x 2 =
    0.1 mm3 of gas, least metal fraction 0.9 where the row is a cell, and
    the bead's metal above the surface does not count; a full substrate
    holds none."""
    from ldna.post import substrate_gas

    def alpha(y: float, z: float) -> float:
        if z < 0:
            return 0.9 if z > -0.25e-3 and abs(y) < 1e-3 else 1.0
        return 1.0 if abs(y) < 2e-3 and z < 1e-3 else 0.0

    gas, least = substrate_gas(_block(cell, alpha))
    assert gas == pytest.approx(0.1 * 0.25e-3 * 2e-3 * 2e-3, rel=1e-9)
    assert least == pytest.approx(0.9)
    full = _block(cell, lambda y, z: 1.0 if z < 0 or (abs(y) < 2e-3 and z < 1e-3) else 0.0)
    assert substrate_gas(full) == (0.0, 1.0)


#: The synthetic section's meshes [m]: fine cells below the refined zone's
#: top, cells twice as large above it, one fine cell long along the weld
FINE_CELL = 0.45e-3
ZONE_TOP = 3.6e-3
SECTION_HALF_WIDTH = 5.4e-3
SECTION_TOP = 7.2e-3


def _two_size_section(blocks: list[tuple[float, float, float]]):
    """A transverse slice, cubes of FINE_CELL below ZONE_TOP and of twice
    that above (one fine cell long along the weld), holding a bead of
    rectangular blocks (y from, y to, height) side by side on the surface;
    each cell's metal fraction is its overlap with them."""
    fine = _cubes(FINE_CELL, (0.0, -SECTION_HALF_WIDTH, 0.0),
                  (FINE_CELL, 2 * SECTION_HALF_WIDTH, ZONE_TOP))
    coarse = _cubes(2 * FINE_CELL, (0.0, -SECTION_HALF_WIDTH, ZONE_TOP),
                    (2 * FINE_CELL, 2 * SECTION_HALF_WIDTH, SECTION_TOP - ZONE_TOP))
    grid = fine.merge(coarse, merge_points=False)
    bounds = np.array([grid.get_cell(i).bounds for i in range(grid.n_cells)])
    y0, y1, z0, z1 = bounds[:, 2], bounds[:, 3], bounds[:, 4], bounds[:, 5]
    overlap = sum((np.clip(np.minimum(y1, right) - np.maximum(y0, left), 0, None)
                   * np.clip(np.minimum(z1, height) - z0, 0, None)
                   for left, right, height in blocks), np.zeros(grid.n_cells))
    grid.cell_data["alpha.metal"] = overlap / ((y1 - y0) * (z1 - z0))
    return grid


def test_the_cells_that_top_a_bead_rising_out_of_the_refined_zone() -> None:
    """A stepped bead 5.4 mm wide (|y| < 2.7 mm, on cell edges of both
    sizes): 3 mm high, its top lies in the 0.45 mm cells across its whole
    width; raised to 4 mm for |y| < 0.9 mm, that 1.8 mm of its width is
    topped by the 0.9 mm cells above the zone (3.6 mm): a third of it.
    """
    from ldna.post import bead_surface_cells

    section = 0.2e-3
    low = [(-2.7e-3, 2.7e-3, 3.0e-3)]
    finest, coarsest, share = bead_surface_cells(_two_size_section(low), section)
    assert (finest, coarsest, share) == (pytest.approx(FINE_CELL), pytest.approx(FINE_CELL), 0.0)
    stepped = [(-2.7e-3, -0.9e-3, 3.0e-3), (-0.9e-3, 0.9e-3, 4.0e-3), (0.9e-3, 2.7e-3, 3.0e-3)]
    finest, coarsest, share = bead_surface_cells(_two_size_section(stepped), section)
    print(f"width topped by coarse cells: {share:.4f} (by hand {1 / 3:.4f})")
    assert finest == pytest.approx(FINE_CELL) and coarsest == pytest.approx(2 * FINE_CELL)
    assert share == pytest.approx(1 / 3, rel=1e-9)
    # No bead: nothing to read
    assert all(math.isnan(v) for v in bead_surface_cells(_two_size_section([]), section))
