"""How a run scales past this machine (``ldna scaling``).

This machine has two cores, so strong scaling to a cluster's 8-64 ranks is
projected from what is measured here:

- the step's cost on one and on two ranks (``timeInfo`` of a serial and a
  2-rank run of the same window): the serial step, and the two ranks'
  efficiency, which is taken for a node's share of memory bandwidth;
- per rank count the decomposition the case gets (``decomposePar -dry-run
  -cellDist``, the template's ``hierarchical`` split): the busiest rank's
  cells, its processor faces and its neighbour ranks;
- the traffic of a step: point-to-point messages per neighbour, bytes per
  processor face, and collectives (reductions, the rays' and droplets'
  all-to-all hand-overs), counted with ``bin/tools/mpiCounts.c``;
- an interconnect's latency and bandwidth.

A step on n ranks then takes the busiest rank's share of the serial step
over the node efficiency, plus its halo exchanges (a latency per message
and neighbour, its faces' bytes over the bandwidth), plus the collectives
(recursive doubling: log2 n latencies each).
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from pathlib import Path

import numpy as np

from ..case import Case

#: An InfiniBand interconnect: the one-way MPI latency of a zero-byte
#: message and the bandwidth between 8 and 16 kB messages, from the
#: ``osu_latency`` example output in QLogic's InfiniPath user guide
#: (IB0054606-02 A, Benchmark 1: 1.06 us at 0 B; 7.28 and 11.75 us at 8 and
#: 16 kB).  Newer fabrics have a similar latency and several times the
#: bandwidth: the projection is on the safe side.
INTERCONNECT_LATENCY = 1.06e-6
INTERCONNECT_BANDWIDTH = 8192 / (11.75e-6 - 7.28e-6)


@dataclass(frozen=True)
class StepTraffic:
    """MPI traffic of one time step."""

    #: Point-to-point messages to each neighbour rank
    messages: float
    #: Bytes sent per processor face
    bytes_per_face: float
    #: Reductions and all-to-all exchanges
    collectives: float


#: The level-1 band (81 108 cells) from the saved weld at 12 s on 2 ranks,
#: 31 steps, counted with bin/tools/mpiCounts.c (2026-11-27): 197 MPI_Isend
#: and 47 MPI_Send a step to the one neighbour, 3.89 MB a step over 1 846
#: processor faces, 269 MPI_Allreduce and 17 MPI_Alltoall a step
LEVEL1_BAND_TRAFFIC = StepTraffic(messages=244, bytes_per_face=2107, collectives=286)


@dataclass(frozen=True)
class Decomposition:
    """What the busiest rank of a decomposition holds."""

    split: tuple[int, int, int]
    cells: int
    max_cells: int
    max_processor_faces: int
    max_neighbours: int

    @property
    def ranks(self) -> int:
        return math.prod(self.split)


def decomposition(case: Case, split: tuple[int, int, int]) -> Decomposition:
    """The case's hierarchical decomposition into ``split`` parts (a dry run:
    nothing is written but the ranks' cell field, removed again)."""
    ranks = math.prod(split)
    dictionary = case / "system" / "decomposeParDict.scaling"
    dictionary.write_text(
        "FoamFile { version 2.0; format ascii; class dictionary; "
        "object decomposeParDict; }\n"
        f"numberOfSubdomains {ranks};\nmethod hierarchical;\n"
        f"coeffs {{ n ({split[0]} {split[1]} {split[2]}); order xyz; }}\n")
    try:
        case.run(f"decomposePar -dry-run -cellDist -decomposeParDict {dictionary}",
                 log_name=f"decomposePar.scaling{ranks}")
        written = sorted(case.path.glob("*/cellDist"), key=lambda p: p.stat().st_mtime)
        # One rank: written as a uniform field
        rank = np.broadcast_to(case.field("cellDist", written[-1].parent).astype(int),
                               case.cells)
        written[-1].unlink()
    finally:
        dictionary.unlink()
    from foamlib import FoamFile

    mesh = case / "constant" / "polyMesh"
    owner = np.asarray(FoamFile(mesh / "owner")[None], dtype=int)
    neighbour = np.asarray(FoamFile(mesh / "neighbour")[None], dtype=int)
    sides = rank[owner[:len(neighbour)]], rank[neighbour]
    cut = sides[0] != sides[1]
    faces = np.bincount(sides[0][cut], minlength=ranks) + np.bincount(sides[1][cut],
                                                                       minlength=ranks)
    pairs = {(a, b) for a, b in zip(sides[0][cut].tolist(), sides[1][cut].tolist())}
    neighbours = np.zeros(ranks, dtype=int)
    for a, b in {(min(p), max(p)) for p in pairs}:
        neighbours[a] += 1
        neighbours[b] += 1
    return Decomposition(split, len(rank), int(np.bincount(rank, minlength=ranks).max()),
                         int(faces.max()), int(neighbours.max()))


@dataclass(frozen=True)
class Projection:
    """A rank count's projected step and its parts [s]."""

    ranks: int
    split: tuple[int, int, int]
    cells_per_rank: int
    processor_faces: int
    neighbours: int
    compute_s: float
    halo_s: float
    collectives_s: float
    step_s: float
    speed_up: float
    efficiency: float


def project(decomp: Decomposition, serial_step: float, node_efficiency: float,
            traffic: StepTraffic = LEVEL1_BAND_TRAFFIC,
            latency: float = INTERCONNECT_LATENCY,
            bandwidth: float = INTERCONNECT_BANDWIDTH) -> Projection:
    """The step on ``decomp``'s ranks (see the module's description)."""
    n = decomp.ranks
    if n == 1:
        compute, halo, collectives = serial_step, 0.0, 0.0
    else:
        compute = serial_step * decomp.max_cells / decomp.cells / node_efficiency
        halo = (traffic.messages * decomp.max_neighbours * latency
                + traffic.bytes_per_face * decomp.max_processor_faces / bandwidth)
        collectives = traffic.collectives * math.ceil(math.log2(n)) * latency
    step = compute + halo + collectives
    return Projection(n, decomp.split, decomp.max_cells, decomp.max_processor_faces,
                      decomp.max_neighbours, compute, halo, collectives, step,
                      serial_step / step, serial_step / step / n)


def scaling(case: Path, serial_run: Path, parallel_run: Path,
            ranks: list[int]) -> tuple[float, float, list[Projection]]:
    """Serial step, two-rank efficiency and the projections along the weld
    (``(n 1 1)``, the template's split) for ``ranks``."""
    serial = Case(serial_run).seconds_per_step()
    two = Case(parallel_run).seconds_per_step()
    node_efficiency = serial / (2 * two)
    case = Case(case)
    projections = [project(decomposition(case, (n, 1, 1)), serial, node_efficiency)
                   for n in ranks]
    return serial, node_efficiency, projections


def table(serial: float, node_efficiency: float, projections: list[Projection]) -> str:
    lines = [f"serial step {serial:.3f} s, two ranks' efficiency {node_efficiency:.2f} "
             "(taken for a node)",
             "| ranks | cells per rank | processor faces | neighbours | compute [ms] "
             "| halo [ms] | collectives [ms] | step [ms] | speed-up | efficiency |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for p in projections:
        lines.append(f"| {p.ranks} | {p.cells_per_rank} | {p.processor_faces} | "
                     f"{p.neighbours} | {1e3 * p.compute_s:.1f} | {1e3 * p.halo_s:.2f} | "
                     f"{1e3 * p.collectives_s:.2f} | {1e3 * p.step_s:.1f} | "
                     f"{p.speed_up:.1f} | {p.efficiency:.2f} |")
    return "\n".join(lines)


def as_json(serial: float, node_efficiency: float, projections: list[Projection]) -> dict:
    return {"serial_step_s": serial, "node_efficiency": node_efficiency,
            "traffic": asdict(LEVEL1_BAND_TRAFFIC),
            "interconnect": {"latency_s": INTERCONNECT_LATENCY,
                             "bandwidth_B_per_s": INTERCONNECT_BANDWIDTH},
            "projections": [asdict(p) for p in projections]}
