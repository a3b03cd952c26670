"""Command-line entry point ``ldna`` of the ldnaFoam Python tooling."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import benchmark, meshing


def _mesh_levels(args: argparse.Namespace) -> int:
    for path in meshing.write_mesh_levels(Path(args.case)):
        print(path)
    return 0


def _bench_laser(args: argparse.Namespace) -> int:
    costs = benchmark.laser_cost(level=args.level, steps=args.steps)
    benchmark.print_costs(costs, args.level)
    return 0


def build_parser() -> argparse.ArgumentParser:
    """The ``ldna`` argument parser with one sub-command per task."""
    parser = argparse.ArgumentParser(prog="ldna", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)

    mesh_levels = commands.add_parser(
        "mesh-levels",
        help="write system/meshLevels/level0..3 of an LDNA case from its caseParameters",
    )
    mesh_levels.add_argument("case", nargs="?", default=".", help="case directory")
    mesh_levels.set_defaults(func=_mesh_levels)

    bench_laser = commands.add_parser(
        "bench-laser",
        help="time per step of the LDNA template without a laser and with each laser model",
    )
    bench_laser.add_argument("--level", type=int, default=1, help="mesh level (0..3)")
    bench_laser.add_argument("--steps", type=int, default=20, help="fixed time steps per run")
    bench_laser.set_defaults(func=_bench_laser)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Run the ``ldna`` command line."""
    args = build_parser().parse_args(argv)
    return int(args.func(args))


if __name__ == "__main__":
    sys.exit(main())
