"""A start near the steady state (``ldna steady-start``).

From a flat substrate the template's bead takes seconds of welding to become
steady: the deposit must travel to the section and the substrate must warm
up.  This writes instead, into the time-0 fields of a meshed case, an
estimate of the steady weld in the moving frame:

- the deposit: the mass balance's section A = m_dot / (rho v) as a circular
  cap across the weld, laid from the wires on (half of it behind the first
  wire, all of it behind the second: each brings half the metal), as wide
  as the laser's sweep, 2 (oscillation amplitude + beam radius), where the
  laser wets the clad out to;
- its temperature: each transverse section of the moving substrate is a
  moment of one 2D transient, t = (x - x_wire) / v (heat conduction along
  the weld neglected: the Peclet number v L / alpha is about 15 over the
  pool's length).  The section's metal, substrate and deposit, conducts
  heat with the metal's k(T) and enthalpy h(T) (latent heat included), the
  deposit arrives at the droplets' temperature, the laser's absorbed power
  (absorptivity x power, its Gaussian profile averaged over the sinusoidal
  sweep) heats the top of the metal as the section passes under the beam,
  and the section's sides and bottom are adiabatic.  Gas stays at the
  ambient temperature; the metal moves at the welding speed.

The metal's properties are the solver's own table (metal.dat), written by a
run of the solver to time 0.  The estimate is a starting point, not a
result: the run from it computes the weld; ``ldna steady`` says when it is
steady.
"""
from __future__ import annotations

import math
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import post
from .case import Case
from .material import SUBSTRATE, Metal, two_metals

#: Grid spacing of the transverse 2D march [m]: a third of a level-0 cell
GRID = 0.15e-3
#: Stability share of the explicit step's limit h^2 rho cp / (4 k)
STEP_SAFETY = 0.8
#: Sub-points per cell and direction that sample the deposit's volume fraction
SAMPLES = 4
#: Metal fraction below which a cell is gas (at the ambient temperature)
GAS_ALPHA = 1e-3
PARAMETERS = "system/caseParameters"
OPTIONS = "constant/fvOptions"


@dataclass(frozen=True)
class Process:
    """What the estimate needs from the case [SI]."""

    speed: float
    ambient: float
    droplet_temperature: float
    first_wire: float
    second_wire: float
    laser_x: float
    absorbed_power: float
    beam_radius: float
    amplitude: float
    bead_area: float
    width: float
    substrate_depth: float
    length: float

    @classmethod
    def of(cls, case: Case) -> "Process":
        mm = 1e-3
        mid = mm * case.scalar(PARAMETERS, "processPosition")
        spacing = mm * case.scalar(PARAMETERS, "wireSpacing")
        absorptivity = case.value(OPTIONS, "laser/absorptivity").split()
        if absorptivity[0] != "constant":
            raise ValueError("ldna steady-start: the laser's absorptivity must be "
                             f"'constant a', not '{' '.join(absorptivity)}'")
        return cls(
            speed=case.scalar(PARAMETERS, "weldingSpeed"),
            ambient=case.scalar(PARAMETERS, "ambientTemperature"),
            droplet_temperature=case.scalar(PARAMETERS, "dropletTemperature"),
            first_wire=mid - spacing / 2, second_wire=mid + spacing / 2,
            laser_x=mm * (case.scalar(PARAMETERS, "processPosition")
                          + case.scalar(PARAMETERS, "laserOffset")),
            absorbed_power=float(absorptivity[1]) * case.scalar(PARAMETERS, "laserPower"),
            beam_radius=case.scalar(PARAMETERS, "laserBeamRadius"),
            amplitude=case.scalar(PARAMETERS, "oscillationAmplitude"),
            bead_area=post.expected_bead_area(case),
            width=mm * case.scalar(PARAMETERS, "width"),
            substrate_depth=mm * case.scalar(PARAMETERS, "substrateDepth"),
            length=mm * case.scalar(PARAMETERS, "length"),
        )


def cap_height(area: float, half_width: float) -> float:
    """Height of the circular cap of chord 2 b and area A (bisection on the
    cap's angle: the area grows with it from 0 to the half-disc's).  A cap
    beyond the half disc would overhang its chord: the deposit would be
    wider than the laser's sweep."""
    if not 0 < area <= 0.5 * math.pi * half_width**2:
        raise ValueError(f"ldna steady-start: a bead section of {1e6 * area:.3g} mm2 is no "
                         f"circular cap on a width of {2e3 * half_width:.3g} mm (at most the "
                         f"half disc, {0.5e6 * math.pi * half_width**2:.3g} mm2)")
    low, high = 1e-9, 0.5 * math.pi
    for _ in range(200):
        theta = 0.5 * (low + high)            # half the cap's central angle
        radius = half_width / math.sin(theta)
        if radius**2 * (theta - math.sin(theta) * math.cos(theta)) < area:
            low = theta
        else:
            high = theta
    return radius * (1 - math.cos(theta))


def cap_top(y: np.ndarray, area: float, half_width: float) -> np.ndarray:
    """Height of the cap's surface above the substrate at y (0 outside)."""
    height = cap_height(area, half_width)
    radius = (half_width**2 + height**2) / (2 * height)
    top = np.sqrt(np.clip(radius**2 - y**2, 0, None)) - (radius - height)
    return np.where(np.abs(y) < half_width, np.clip(top, 0, None), 0.0)


def deposit_share(x: np.ndarray, process: Process) -> np.ndarray:
    """Share of the mass balance's section laid at x: half behind each wire."""
    return 0.5 * (x >= process.first_wire) + 0.5 * (x >= process.second_wire)


def sweep_profile(y: np.ndarray, process: Process) -> np.ndarray:
    """The laser's absorbed power across the weld per unit width [1/m], averaged
    over the sinusoidal sweep: the beam's marginal profile exp(-3 y^2/R^2)
    (integral 1) at y_c = a sin(phase), phases uniform."""
    phases = np.linspace(0, 2 * np.pi, 721)[:-1]
    centres = process.amplitude * np.sin(phases)
    r = process.beam_radius
    profile = math.sqrt(3 / math.pi) / r * np.exp(-3 * (y[:, None] - centres[None, :])**2 / r**2)
    return profile.mean(axis=1)


def beam_profile_along(x: np.ndarray, process: Process) -> np.ndarray:
    """The beam's marginal profile along the weld [1/m] about its target."""
    r = process.beam_radius
    return math.sqrt(3 / math.pi) / r * np.exp(-3 * (x - process.laser_x)**2 / r**2)


class _Tables:
    """One metal's enthalpy and conductivity against T (the solver's table)."""

    def __init__(self, metal: Metal) -> None:
        table = metal.table
        self.T = np.asarray(table["T"], dtype=float)
        self.h = np.asarray(table["enthalpy"], dtype=float)
        self.k = np.asarray(table["kappa"], dtype=float)
        self.density = metal.reference_density

    def enthalpy(self, T: float) -> float:
        return float(np.interp(T, self.T, self.h))

    def temperature(self, h: np.ndarray) -> np.ndarray:
        return np.interp(h, self.h, self.T)

    def conductivity(self, T: np.ndarray) -> np.ndarray:
        return np.interp(T, self.T, self.k)

    def max_diffusivity(self, T_max: float) -> float:
        """Largest k / (rho Cp) up to ``T_max`` (the explicit step's limit)."""
        k_max = float(self.k[self.T <= T_max].max())
        cp_min = float(np.min(np.diff(self.h) / np.diff(self.T)))
        return k_max / (self.density * cp_min)


class TransverseMarch:
    """The 2D transient of one transverse section carried by the substrate."""

    def __init__(self, process: Process, metal: Metal, substrate: Metal | None = None) -> None:
        """``metal``: the filler (the deposit); ``substrate``: the
        substrate's own metal (two metals), else the filler's."""
        self.process = process
        self.metals = [_Tables(metal), _Tables(substrate or metal)]
        half = process.width / 2
        self.y = np.arange(-half + GRID / 2, half, GRID)
        top = cap_height(process.bead_area, process.amplitude + process.beam_radius)
        self.z = np.arange(-process.substrate_depth + GRID / 2, top + GRID, GRID)
        Z = np.meshgrid(self.y, self.z, indexing="ij")[1]
        self.cap = cap_top(self.y, process.bead_area, process.amplitude + process.beam_radius)
        self.in_cap = (Z >= 0) & (Z < self.cap[:, None])
        self.substrate = Z < 0
        # Per node: 0 filler, 1 substrate's metal
        self.material = self.substrate.astype(int)
        self.density = np.where(self.substrate, self.metals[1].density,
                                self.metals[0].density)

    def temperature(self, h: np.ndarray) -> np.ndarray:
        return np.where(self.substrate, self.metals[1].temperature(h),
                        self.metals[0].temperature(h))

    def conductivity(self, T: np.ndarray) -> np.ndarray:
        return np.where(self.substrate, self.metals[1].conductivity(T),
                        self.metals[0].conductivity(T))

    def run(self, x_end: float) -> tuple[np.ndarray, list[np.ndarray]]:
        """Positions along the weld [m] and the section's temperatures there,
        from the first wire to ``x_end``."""
        p = self.process
        filler, base = self.metals
        h = np.where(self.substrate, base.enthalpy(p.ambient), filler.enthalpy(p.ambient))
        h_droplet = filler.enthalpy(p.droplet_temperature)
        metal = self.substrate.copy()
        diffusivity = max(m.max_diffusivity(2 * p.droplet_temperature) for m in self.metals)
        dt = STEP_SAFETY * GRID**2 / (4 * diffusivity)
        across = sweep_profile(self.y, p)
        x = p.first_wire
        positions, fields = [], []
        share = 0.0
        next_snapshot = x
        while x <= x_end:
            # The deposit grows in two steps: its cap scaled in height
            new_share = float(deposit_share(np.array([x]), p)[0])
            if new_share > share:
                grown = (self.in_cap_at(new_share)) & ~metal
                h[grown] = h_droplet
                metal |= grown
                share = new_share
            T = self.temperature(h)
            top = metal.shape[1] - 1 - np.argmax(metal[:, ::-1], axis=1)
            if x >= next_snapshot:
                # A snapshot every grid spacing of travel; above the metal each
                # column continues at its surface temperature, so that a cell
                # the surface cuts gets the metal's
                snapshot = T.copy()
                above = np.arange(metal.shape[1])[None, :] > top[:, None]
                snapshot[above] = np.broadcast_to(T[np.arange(len(top)), top][:, None],
                                                  T.shape)[above]
                positions.append(x)
                fields.append(snapshot)
                next_snapshot = x + GRID
            # Conduction between metal neighbours, harmonic face conductivity
            k = self.conductivity(T)
            flux = np.zeros_like(h)
            for axis in (0, 1):
                both = np.logical_and(np.take(metal, range(1, metal.shape[axis]), axis=axis),
                                      np.take(metal, range(0, metal.shape[axis] - 1), axis=axis))
                k1 = np.take(k, range(1, k.shape[axis]), axis=axis)
                k0 = np.take(k, range(0, k.shape[axis] - 1), axis=axis)
                face_k = 2 * k1 * k0 / (k1 + k0)
                dT = np.diff(T, axis=axis)
                q = np.where(both, face_k * dT / GRID**2, 0.0)
                if axis == 0:
                    flux[:-1, :] += q
                    flux[1:, :] -= q
                else:
                    flux[:, :-1] += q
                    flux[:, 1:] -= q
            # The laser on the top metal node of each column
            power = p.absorbed_power * float(beam_profile_along(np.array([x]), p)[0])
            heating = np.zeros_like(h)
            heating[np.arange(len(self.y)), top] = power * across / GRID
            h = h + dt * (flux + heating * metal) / self.density
            x += p.speed * dt
        return np.array(positions), fields

    def in_cap_at(self, share: float) -> np.ndarray:
        """The deposit's nodes when ``share`` of the section is laid (the cap's
        height scaled)."""
        Z = self.z[None, :]
        return (Z >= 0) & (Z < share * self.cap[:, None])


def write_estimate(case: Case) -> dict[str, float]:
    """Write the estimate into the case's time-0 T, alpha.metal and U (the case
    must be meshed and set)."""
    case = Case(case)
    process = Process.of(case)
    metal, substrate = solver_metals(case)
    march = TransverseMarch(process, metal, substrate)
    positions, fields = march.run(process.length)

    case.run("postProcess -func writeCellCentres -time 0", log_name="writeCellCentres")
    centres = case.field("C", "0")
    x, y, z = centres.T
    substrate_alpha = case.field("alpha.metal", "0")
    deposit = deposit_fraction(case, process, centres)
    alpha = np.clip(np.maximum(substrate_alpha, deposit), 0.0, 1.0)
    # The section that passed x, in the march: bilinear in (y, z)
    index = np.clip(np.searchsorted(positions, x) - 1, 0, len(positions) - 1)
    T = np.full(len(x), process.ambient)
    behind = x >= process.first_wire
    for k in np.unique(index[behind]):
        cells = behind & (index == k)
        T[cells] = bilinear(march.y, march.z, fields[k], y[cells], z[cells])
    # Gas at the ambient temperature; cells the surface cuts, the metal's
    T = np.where(alpha > GAS_ALPHA, T, process.ambient)
    velocity = np.zeros_like(centres)
    velocity[:, 0] = process.speed * (alpha >= 0.5)
    case.write_field("T", values=T)
    case.write_field("alpha.metal", values=alpha)
    case.write_field("U", values=velocity)
    if substrate is not None:
        # The deposit is filler, the rest of the metal the substrate's
        filler = np.divide(alpha - substrate_alpha, alpha, out=np.zeros_like(alpha),
                           where=alpha > 0)
        case.write_field("fillerFraction", values=np.clip(filler, 0.0, 1.0))
    # The geometry fields were only for this
    for name in ("C", "Cx", "Cy", "Cz", "V"):
        (case / "0" / name).unlink(missing_ok=True)
    figures = {"bead_area_mm2": 1e6 * process.bead_area,
               "bead_width_mm": 2e3 * (process.amplitude + process.beam_radius),
               "bead_height_mm": 1e3 * cap_height(process.bead_area,
                                                  process.amplitude + process.beam_radius),
               "peak_substrate_temperature_K":
                   float(max(f[march.substrate].max() for f in fields))}
    write_record(case, figures)
    return figures


def write_record(case: Case, figures: dict[str, float]) -> None:
    """The estimate's figures as a table, so that the tools know what the
    time-0 fields hold (``post.started_from_estimate``)."""
    name, file = post.STEADY_START_RECORD
    directory = case / "postProcessing" / name / "0"
    directory.mkdir(parents=True, exist_ok=True)
    (directory / f"{file}.dat").write_text(
        "# Estimate of the steady weld written into the time-0 fields (ldna steady-start)\n"
        "# Time " + " ".join(figures) + "\n"
        "0 " + " ".join(f"{value:.9g}" for value in figures.values()) + "\n")


def bilinear(y: np.ndarray, z: np.ndarray, values: np.ndarray, yq: np.ndarray,
             zq: np.ndarray) -> np.ndarray:
    """Bilinear interpolation on the grid (y, z), clamped at its edges."""
    i = np.clip(np.searchsorted(y, yq) - 1, 0, len(y) - 2)
    j = np.clip(np.searchsorted(z, zq) - 1, 0, len(z) - 2)
    s = np.clip((yq - y[i]) / (y[i + 1] - y[i]), 0, 1)
    t = np.clip((zq - z[j]) / (z[j + 1] - z[j]), 0, 1)
    return ((1 - s) * (1 - t) * values[i, j] + s * (1 - t) * values[i + 1, j]
            + (1 - s) * t * values[i, j + 1] + s * t * values[i + 1, j + 1])


def deposit_fraction(case: Case, process: Process, centres: np.ndarray) -> np.ndarray:
    """The deposit's volume fraction in each cell, sampled on SAMPLES^3 points
    of a cube of the cell's volume about its centre (the template's cells are
    cubes and boxes)."""
    case.run("postProcess -func writeCellVolumes -time 0", log_name="writeCellVolumes")
    side = np.cbrt(case.field("V", "0"))[:, None]
    offsets = (np.arange(SAMPLES) + 0.5) / SAMPLES - 0.5
    fraction = np.zeros(len(centres))
    half_width = process.amplitude + process.beam_radius
    for ox in offsets:
        for oy in offsets:
            for oz in offsets:
                sample = centres + side * np.array([ox, oy, oz])
                top = (deposit_share(sample[:, 0], process)
                       * cap_top(sample[:, 1], process.bead_area, half_width))
                fraction += (sample[:, 2] >= 0) & (sample[:, 2] < top)
    return fraction / SAMPLES**3


def solver_metals(case: Case) -> tuple[Metal, Metal | None]:
    """The case's filler and, with two metals, the substrate's metal, with
    the solver's own property tables, from a run of the solver to time 0 in
    a scratch copy (the case's postProcessing stays as it was)."""
    with tempfile.TemporaryDirectory() as scratch:
        copy = Case.copy_of(case, Path(scratch) / "case")
        shutil.copytree(case / "constant" / "polyMesh", copy / "constant" / "polyMesh")
        copy.set("system/controlDict", "endTime", "0")
        copy.run("ldnaFoam", log_name="ldnaFoam")
        metal = Metal.from_case(copy.path)
        metal.table  # read before the scratch copy goes
        substrate = None
        if two_metals(copy.path):
            substrate = Metal.from_case(copy.path, SUBSTRATE)
            substrate.table
    return metal, substrate
