"""Command-line entry point ``ldna`` of the ldnaFoam Python tooling."""
from __future__ import annotations

import argparse
import copy
import json
import os
import sys
import textwrap
from collections.abc import Callable
from pathlib import Path

from . import meshing, state
from .dev import benchmark


def _mesh_levels(args: argparse.Namespace) -> int:
    for path in meshing.write_mesh_levels(Path(args.case)):
        print(path)
    return 0


def _bench_laser(args: argparse.Namespace) -> int:
    costs = benchmark.laser_cost(level=args.level, steps=args.steps)
    benchmark.print_costs(costs, args.level)
    return 0


def _bench(args: argparse.Namespace) -> int:
    costs = benchmark.solver_costs(level=args.level, steps=args.steps, n_procs=args.np,
                                   repeats=args.repeats, start_time=args.start_time,
                                   instruction_steps=args.instructions)
    if args.json:
        print(json.dumps(costs.summary()))
    else:
        benchmark.print_solver_costs(costs)
    return 0


def _scaling(args: argparse.Namespace) -> int:
    from .dev import scaling

    if not all(n >= 1 and n == int(n) for n in args.ranks):
        raise SystemExit("ldna scaling: --ranks must be whole numbers >= 1")
    serial, efficiency, projections = scaling.scaling(
        Path(args.serial_run), Path(args.serial_run), Path(args.parallel_run),
        [int(n) for n in args.ranks])
    if args.json:
        print(json.dumps(scaling.as_json(serial, efficiency, projections)))
    else:
        print(scaling.table(serial, efficiency, projections))
    return 0


def _gmsh_mesh(args: argparse.Namespace) -> int:
    from . import gmsh_mesh

    n_cells = gmsh_mesh.gmsh_mesh(Path(args.case), args.level)
    print(f"{args.case}: {n_cells} hexahedra, constant/polyMesh written by gmshToFoam")
    return 0


def _study(args: argparse.Namespace) -> int:
    from . import study

    parameters = [study.Parameter.parse(text) for text in args.set]
    if args.start_time is not None and args.start_from is None:
        print("ldna study: --start-time needs --start-from", file=sys.stderr)
        return 2
    start = None if args.start_from is None else study.StartFrom(Path(args.start_from),
                                                                 args.start_time)
    members, table = study.run_study(Path(args.template), Path(args.study_dir), parameters,
                                     end_time=args.end_time, n_procs=args.np,
                                     resume=args.resume, start=start, paired=args.paired,
                                     jobs=args.jobs)
    failed = [m.name for m in members if m.status != "done"]
    print(f"{len(members)} members, {len(failed)} failed; results: {table} "
          f"and {table.with_suffix('.json')}")
    if failed:
        print("failed: " + ", ".join(failed) + " (see their log.Allrun and log.*); "
              "to continue the members from their latest written time, run the same "
              "command with --resume")
    return 1 if failed else 0


def _accuracy(args: argparse.Namespace) -> int:
    from .dev import accuracy

    scene = None if args.scene == "auto" else accuracy.SCENES[args.scene]
    if args.band:
        scene = scene or accuracy.detect_scene(Path(args.case))
        if not isinstance(scene, accuracy.LdnaScene):
            print("ldna accuracy: --band needs --scene ldna or bead", file=sys.stderr)
            return 2
        if not args.start_from:
            print("ldna accuracy: --band refines where --start-from has its weld: give it",
                  file=sys.stderr)
            return 2
        scene = copy.copy(scene)
        scene.band = True
    start = None
    if args.start_from:
        if args.start_time is None:
            print("ldna accuracy: --start-from needs --start-time", file=sys.stderr)
            return 2
        start = accuracy.StartState(Path(args.start_from), args.start_time)
    if args.sequence and start is None:
        print("ldna accuracy: error: --sequence starts the first level from --start-from: give it",
              file=sys.stderr)
        return 2
    end_time = args.end_time
    if args.min_window is not None:
        if not isinstance(scene, accuracy.BeadScene):
            print("ldna accuracy: error: --min-window judges a bead study's steadiness: "
                  "give --scene bead", file=sys.stderr)
            return 2
        scene = copy.copy(scene)
        scene.min_window = args.min_window
    if isinstance(scene, accuracy.BeadScene):
        if end_time is None:
            end_time = (start.time if start else 0.0) + scene.MAX_SPAN
        limit = (f"at most {end_time - start.time:g} s from its start" if args.sequence
                 else f"at most to {end_time:g} s")
        print(f"ldna accuracy: each level runs until its bead is quasi-steady, {limit}, "
              f"writing every {scene.STRETCH:g} s; if it stops, run the same "
              f"command with --resume (on another checkout or machine: ldna pack "
              f"{args.output} ARCHIVE here, ldna unpack ARCHIVE {args.output} there)",
              flush=True)
        if args.resume and args.cost_window is None:
            print("ldna accuracy: a resumed study's runs may have run on other machines or "
                  "beside other work; --cost-window 0.04 measures every level's cost on this "
                  "machine after the runs", flush=True)
    from .study import Parameter

    settings = [Parameter.parse(text) for text in args.set]
    several = [p.name for p in settings if len(p.values) != 1]
    if several:
        print(f"ldna accuracy: error: --set gives one value per entry: {', '.join(several)}",
              file=sys.stderr)
        return 2
    study, paths = accuracy.run_study(Path(args.case), Path(args.output), scene,
                                      levels=args.levels, max_co=args.max_co,
                                      end_time=end_time, n_procs=args.np, start=start,
                                      resume=args.resume, cost_window=args.cost_window,
                                      sequence=args.sequence, settings=settings)
    print(accuracy.markdown(study))
    for path in paths:
        print(path)
    return 0


def _steady(args: argparse.Namespace) -> int:
    from . import steady

    times, table, arrival = steady.case_table(Path(args.case), args.section)
    balance = steady.DomainBalance.of(Path(args.case))
    min_window = args.min_window or steady.MIN_WINDOW
    verdict = steady.judge(times, table, arrival, min_window, balance=balance)
    first = steady.first_steady(times, table, arrival, min_window, balance=balance)
    if args.json:
        print(json.dumps({**verdict.as_dict(), "first_steady_s": first}))
    else:
        print(steady.format_steadiness(verdict))
        print("first judged quasi-steady at " + (f"t = {first:.4g} s" if first is not None
                                                 else "no time yet"))
    return 0


def _means(args: argparse.Namespace) -> int:
    from . import steady

    figures = steady.span_means(Path(args.case), args.start, args.end, args.section)
    print(json.dumps(figures) if args.json else
          "\n".join(f"{key:<36}{value:12.5g}" for key, value in figures.items()))
    return 0


def _steady_start(args: argparse.Namespace) -> int:
    from . import steady_start
    from .case import Case

    figures = steady_start.write_estimate(Case(Path(args.case)))
    print(json.dumps(figures) if args.json else
          "\n".join(f"{key:<32}{value:10.4g}" for key, value in figures.items()))
    return 0


def _bead_report(args: argparse.Namespace) -> int:
    from .dev import validation

    figures = validation.bead_report(Path(args.case), Path(args.output), args.section,
                                     args.cpu_seconds)
    print(json.dumps(figures, indent=2))
    return 0


def _float_list(text: str) -> list[float]:
    try:
        values = [float(value) for value in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"'{text}' is not a comma-separated list of numbers")
    if not all(value == value and abs(value) != float("inf") for value in values):
        raise argparse.ArgumentTypeError(f"'{text}' holds a value that is not finite")
    return values


def _case(text: str) -> str:
    """An OpenFOAM case directory: one with system/controlDict."""
    if not (Path(text) / "system" / "controlDict").is_file():
        raise argparse.ArgumentTypeError(f"'{text}' is not an OpenFOAM case "
                                         "(no system/controlDict)")
    return text


def _case_or_folder(text: str) -> str:
    """An existing folder (a case, or one holding cases)."""
    if not Path(text).is_dir():
        raise argparse.ArgumentTypeError(f"'{text}' is not a folder")
    return text


def _whole_number(low: int, high: int | None, what: str = "") -> Callable[[str], int]:
    """An argparse type: a whole number in [low, high] (no upper bound: None)."""
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not a whole number")
        if high is None and value < low:
            raise argparse.ArgumentTypeError(f"{value} must be at least {low}")
        if high is not None and not low <= value <= high:
            raise argparse.ArgumentTypeError(f"{what}{value} must lie in {low}..{high}")
        return value
    return parse


_positive_int = _whole_number(1, None)
_non_negative_int = _whole_number(0, None)
_level = _whole_number(0, 3, "level ")


def _real_number(positive: bool) -> Callable[[str], float]:
    """An argparse type: a finite number (positive: above zero as well)."""
    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"'{text}' is not a number")
        if not (abs(value) < float("inf")) or (positive and not value > 0):
            raise argparse.ArgumentTypeError(
                f"{text} must be a {'positive, ' if positive else ''}finite number")
        return value
    return parse


_positive_float = _real_number(positive=True)
_finite_float = _real_number(positive=False)


def _post(args: argparse.Namespace) -> int:
    from . import post

    case = Path(args.case)
    if not (case / "constant" / "polyMesh" / "faces").exists() and not any(
            (p / "constant" / "polyMesh").exists() for p in case.glob("processor*")):
        raise FileNotFoundError(f"{case} has no mesh: run its Allrun (or blockMesh) first")
    result, pictures, time = post.post_process(Path(args.case), args.output, args.time,
                                               surface_height=args.surface_height,
                                               bead_section=args.bead_section,
                                               fusion_temperature_=args.fusion_temperature)
    if args.json:
        print(json.dumps(post.summary(Path(args.case), result, time)))
        return 0
    print(post.format_metrics(result))
    note = post.bead_not_yet_there(post.bead_arrival_time(case, result.bead_section), time,
                                   result.bead_section, post.started_from_estimate(case),
                                   post.weld_start_time(case))
    if note:
        print(textwrap.fill(note, width=79))
    for picture in pictures:
        print(picture)
    return 0


def _pack(args: argparse.Namespace) -> int:
    archive = state.pack_run(Path(args.run), Path(args.archive))
    size = archive.stat().st_size / 2**20
    print(f"{archive}: {args.run} packed ({size:.1f} MiB); elsewhere: ldna unpack {archive} RUN, "
          "then continue RUN with its command's --resume (./Allrun -resume [-parallel], "
          "ldna study or ldna accuracy ... --resume)")
    return 0


def _unpack(args: argparse.Namespace) -> int:
    run = state.unpack_run(Path(args.archive), Path(args.run))
    print(f"{run}: unpacked; continue it with its command's --resume")
    return 0


def _set(args: argparse.Namespace) -> int:
    from .case import Case
    Case(args.case).set(args.file, args.entry, args.value, create=args.create)
    return 0


def _save_state(args: argparse.Namespace) -> int:
    target = state.save_state(Path(args.run), Path(args.target), args.time, args.history)
    print(f"{target}: the state of {args.run} at t = {state.state_time(target)} s; start a run "
          f"from it with ./Allrun -start-from {target}")
    return 0


def _case_argument(parser: argparse.ArgumentParser, optional: bool = True) -> None:
    """The case directory, the current one if ``optional`` and not given."""
    if optional:
        parser.add_argument("case", nargs="?", default=".", type=_case, help="case directory")
    else:
        parser.add_argument("case", type=_case, help="case directory")


def _json_flag(parser: argparse.ArgumentParser, what: str = "the figures as JSON") -> None:
    """--json: print ``what`` instead of the table."""
    parser.add_argument("--json", action="store_true", help=f"print {what}")


def _section_option(parser: argparse.ArgumentParser, role: str) -> None:
    """--section: the meltPoolMetrics function object that ``role``."""
    parser.add_argument("--section", default="meltPoolMetrics",
                        help=f"the meltPoolMetrics function object {role} "
                             "(default: meltPoolMetrics)")


def build_parser() -> argparse.ArgumentParser:
    """The ``ldna`` argument parser with one sub-command per task."""
    parser = argparse.ArgumentParser(prog="ldna", description=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)

    mesh_levels = commands.add_parser(
        "mesh-levels",
        help="write system/meshLevels/level0..3 of an LDNA case from its caseParameters",
    )
    _case_argument(mesh_levels)
    mesh_levels.set_defaults(func=_mesh_levels)

    bench_laser = commands.add_parser(
        "bench-laser",
        help="time per step of the LDNA template without a laser and with each laser model",
    )
    bench_laser.add_argument("--level", type=_level, default=1, help="mesh level (0..3)")
    bench_laser.add_argument("--steps", type=_positive_int, default=20, help="fixed time steps per run")
    bench_laser.set_defaults(func=_bench_laser)

    scale = commands.add_parser(
        "scaling",
        help="strong scaling projected to a cluster's ranks from a serial and a 2-rank run "
             "of the same window (the step's cost, the two ranks' efficiency), the case's "
             "decompositions (cells, processor faces, neighbours of the busiest rank) and "
             "the step's MPI traffic",
    )
    scale.add_argument("serial_run", type=_case, help="serial run of a few steps (its mesh counts)")
    scale.add_argument("parallel_run", type=_case, help="the same steps on 2 ranks")
    scale.add_argument("--ranks", type=_float_list, default=[1, 2, 4, 8, 16, 32, 64],
                       metavar="N1,N2,...", help="rank counts [1,2,4,8,16,32,64]")
    _json_flag(scale)
    scale.set_defaults(func=_scaling)

    bench = commands.add_parser(
        "bench",
        help="cost ratios: ldnaFoam without effects against compressibleInterFoam, each "
             "effect against none, throughput and projected core-hours at the paper's "
             "resolution, parallel efficiency",
    )
    bench.add_argument("--level", type=_level, default=0, help="mesh level (0..3)")
    bench.add_argument("--steps", type=_positive_int, default=140,
                       help="fixed time steps per run (140 at level 0: 25 ms, a droplet of each "
                            "wire inserted and landing)")
    bench.add_argument("--start-time", type=_positive_float, default=0.1,
                       help="process time [s] the template runs to first; every variant starts "
                            "from that state")
    bench.add_argument("--np", type=_positive_int, default=2, help="MPI ranks of the parallel run")
    bench.add_argument("--repeats", type=_positive_int, default=5,
                       help="rounds of every variant; the median of each round's ratios counts")
    bench.add_argument("--instructions", type=_non_negative_int, default=0, metavar="STEPS",
                       help="also count the instructions per step of every serial variant "
                            "under valgrind's callgrind over STEPS steps after the first, from "
                            "the state two steps before a droplet's insertion: ratios that do "
                            "not depend on the machine's load (0: off; about 3 min per variant "
                            "for 4 steps at level 0)")
    _json_flag(bench, "the figures as one JSON object instead of a table")
    bench.set_defaults(func=_bench)

    gmsh = commands.add_parser(
        "gmsh-mesh",
        help="mesh an LDNA case with gmsh (hexahedra, refined band at the surface) "
             "and gmshToFoam instead of blockMesh",
    )
    _case_argument(gmsh)
    gmsh.add_argument("--level", type=_level, help="resolution level 0..3 [caseParameters]")
    gmsh.set_defaults(func=_gmsh_mesh)

    study = commands.add_parser(
        "study",
        help="run a case template over a parameter grid and collect the bead metrics in a CSV",
        description="Copy TEMPLATE into STUDY_DIR once per member of the grid of --set "
                    "values, run each member's Allrun, collect STUDY_DIR/results.csv and "
                    "results.json (with ldna post's figures and ldna steady's verdict).",
    )
    study.add_argument("template", type=_case, help="case template, e.g. cases/ldna")
    study.add_argument("study_dir", help="folder of the study (members and results.csv)")
    study.add_argument("--set", action="append", required=True, metavar="NAME=V1,V2,...",
                       help="a grid axis: a caseParameters entry (laserPower, weldingSpeed, "
                            "wireFeedSpeed, oscillationAmplitude, level, ...) or FILE:ENTRY "
                            "(e.g. constant/fvOptions:laser/absorptionModel); repeat for more")
    study.add_argument("--end-time", type=_positive_float, help="simulated time of every member [s]")
    study.add_argument("--np", type=_positive_int, default=1, help="MPI ranks per member (1: serial)")
    study.add_argument("--jobs", type=_positive_int, default=1,
                       help="members run at a time (each on --np ranks)")
    study.add_argument("--paired", action="store_true",
                       help="pair the --set axes' values (member i takes the i-th value of "
                            "each; equally long lists) instead of spanning their grid")
    study.add_argument("--resume", action="store_true",
                       help="keep the members that exist and continue each from its latest "
                            "written time (--end-time may be raised); finished ones are only "
                            "collected")
    study.add_argument("--start-from", type=_case, metavar="RUN",
                       help="start every member from this run's state (a steady run of the "
                            "scene: the members relax from it instead of from the flat "
                            "substrate), mapped onto its mesh; --end-time past its time")
    study.add_argument("--start-time", type=_positive_float, metavar="T",
                       help="the reconstructed time of --start-from [its latest]")
    study.set_defaults(func=_study)

    accuracy = commands.add_parser(
        "accuracy",
        help="run a scene at several mesh levels: error of its key outputs against cost "
             "(CSV, Markdown table, log-log plot, observed order)",
        description="Copy CASE into OUTPUT/members once per level (and maxCo), run each, "
                    "compare the key outputs with the analytical answer (stefanMelting) or "
                    "the finest run (LDNA scene), and write OUTPUT/accuracy.{csv,md,png}.",
    )
    accuracy.add_argument("case", type=_case, help="case template: cases/ldna or cases/stefanMelting")
    accuracy.add_argument("output", help="folder of the study")
    accuracy.add_argument("--scene", choices=("auto", "ldna", "bead", "stefan"), default="auto",
                          help="kind of scene [from the case's caseParameters]; bead: the LDNA "
                               "template run at each level until ldna steady judges its bead "
                               "quasi-steady (at most to --end-time), best --start-from a "
                               "steady run")
    accuracy.add_argument("--levels", type=_float_list, metavar="L1,L2,...",
                          help="mesh levels; LDNA: 0..3, halves allowed (process-zone "
                               "cells of 0.45 mm/2^level) [0,0.5,1]; Stefan: 25*2^level cells "
                               "and time steps of 16 ms/2^level [0,1,2,3,4]")
    accuracy.add_argument("--max-co", type=_float_list, metavar="C1,C2,...",
                          help="also vary maxCo and maxAlphaCo (adjustable time step)")
    accuracy.add_argument("--end-time", type=_positive_float, help="simulated time of every run [s]")
    accuracy.add_argument("--start-from", metavar="RUN",
                          help="start every run from a developed state of this finished run "
                               "(mapped onto each level's mesh; with --start-time)")
    accuracy.add_argument("--start-time", type=_finite_float, metavar="T",
                          help="the reconstructed time of --start-from to start at [s]")
    accuracy.add_argument("--band", action="store_true",
                          help="LDNA: every level refines only the band where the "
                               "--start-from weld has its deposit (metal above the "
                               "substrate), its pool and its droplets, grown by a cell and "
                               "above the substrate by another (level L: level L-1 with "
                               "that band split once, bandLevel in caseParameters; levels "
                               "from 0)")
    accuracy.add_argument("--min-window", type=_positive_float, default=None, metavar="S",
                          help="bead scene: judge steadiness over windows of at least S "
                               "seconds (as ldna steady --min-window), for a weld that fills "
                               "and drains slower than the default's ripple periods; give "
                               "it to every leg of a study [ldna steady's default]")
    accuracy.add_argument("--sequence", action="store_true",
                          help="with --start-from: only the first level starts from it; each "
                               "later level starts from the latest time of the level before "
                               "(the bead scene: its quasi-steady weld) and may run as long "
                               "from there as the first from --start-time to --end-time")
    accuracy.add_argument("--np", type=_positive_int, default=1, help="MPI ranks per run (1: serial)")
    accuracy.add_argument("--cost-window", type=_positive_float, default=None, metavar="S",
                          help="after the runs, measure each level's cost by a serial run of S "
                               "simulated seconds from its latest time (in OUTPUT/cost), all "
                               "levels on this machine now: a study resumed over sessions ran "
                               "its legs on other machines, beside other work [off: the runs' "
                               "own CPU time]")
    accuracy.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                          help="set an entry in every member's copy of CASE before it is "
                               "meshed (NAME: a caseParameters entry or FILE:ENTRY; "
                               "repeatable), e.g. processZoneDownstream=21")
    accuracy.add_argument("--resume", action="store_true",
                          help="continue the members that ran before from their latest "
                               "written time (a study that outlasted a session: run the same "
                               "command with --resume)")
    accuracy.set_defaults(func=_accuracy)

    post = commands.add_parser(
        "post",
        help="bead metrics and PNG pictures (free surface, transverse and longitudinal "
             "sections) of a case",
    )
    _case_argument(post)
    post.add_argument("--output", help="folder of the pictures [CASE/pictures]")
    post.add_argument("--time", type=_finite_float, help="time to read [latest]")
    post.add_argument("--surface-height", type=_finite_float, default=0.0,
                      help="height of the substrate surface [m]")
    post.add_argument("--bead-section", type=_finite_float,
                      help="position along the weld of the bead section [m] "
                           "[slice of largest bead area]")
    post.add_argument("--fusion-temperature", type=_positive_float,
                      help="isotherm of the fusion line [K] [the solidus]")
    report = commands.add_parser(
        "bead-report",
        help="validation report of a long run: bead.json (figures, steadiness, mass "
             "balance, cost), bead area against time and the pictures",
    )
    _case_argument(report, optional=False)
    report.add_argument("output", help="folder of the report")
    _section_option(report, "whose section judges the bead")
    report.add_argument("--cpu-seconds", type=float, default=None,
                        help="the solver's CPU time on its master rank [s], for a run "
                             "without the timeInfo table (default: from postProcessing/timeInfo)")
    report.set_defaults(func=_bead_report)

    steady_command = commands.add_parser(
        "steady",
        help="is the bead quasi-steady? the drift of every section metric's means over the "
             "last four windows of whole ripple periods, against 1 %% or the means' noise "
             "(works on a running case)",
    )
    _case_argument(steady_command)
    _section_option(steady_command, "to judge")
    steady_command.add_argument("--min-window", type=_positive_float, default=None,
                                metavar="S",
                                help="shortest averaging window [s]: whole ripple periods of "
                                     "at least this (default 0.25); longer for a bead whose "
                                     "metrics swing more slowly than the windows")
    _json_flag(steady_command, "the verdict and every metric's figures as JSON (SI)")
    steady_command.set_defaults(func=_steady)

    means = commands.add_parser(
        "means",
        help="time-weighted means (and largest values) of the section's metrics and the "
             "laser's absorbed power over a span of a run (SI)",
    )
    _case_argument(means, optional=False)
    means.add_argument("start", type=float, help="the span's start [s]")
    means.add_argument("end", type=float, help="the span's end [s]")
    _section_option(means, "to read")
    _json_flag(means)
    means.set_defaults(func=_means)

    start = commands.add_parser(
        "steady-start",
        help="write an estimate of the steady weld (the mass balance's deposit, a moving-"
             "section temperature) into the time-0 fields of a meshed, set case",
    )
    _case_argument(start)
    _json_flag(start, "the estimate's figures as JSON")
    start.set_defaults(func=_steady_start)

    save = commands.add_parser(
        "save-state",
        help="keep a run's state (mesh, fields, the tables ldna steady judges) compressed, "
             "to start other runs from (./Allrun -start-from TARGET)",
    )
    save.add_argument("run", type=_case, help="the run (reconstructed)")
    save.add_argument("target", help="folder to write; must not exist")
    save.add_argument("--time", help="the reconstructed time to keep [the latest]")
    save.add_argument("--history", type=_positive_float, default=state.HISTORY_SECONDS,
                      help="seconds of tables before the time to keep "
                           f"[{state.HISTORY_SECONDS:g}]")
    save.set_defaults(func=_save_state)

    set_entry = commands.add_parser(
        "set",
        help="set a dictionary entry of a case in place (scoped as coeffs/n), keeping "
             "comments, #include and #eval (foamDictionary -set expands them); an entry "
             "the file does not have is an error unless --create",
    )
    _case_argument(set_entry, optional=False)
    set_entry.add_argument("file", help="dictionary, relative to the case (system/controlDict)")
    set_entry.add_argument("entry", help="entry, scoped with slashes (functions/x/writeControl)")
    set_entry.add_argument("value", help="its new value: 0.5, '(3 1 1)', '{ type wall; }'")
    set_entry.add_argument("--create", action="store_true", help="add the entry if missing")
    set_entry.set_defaults(func=_set)

    pack = commands.add_parser(
        "pack",
        help="pack a run or a study that outlasts a session (mesh, initial and latest "
             "time reconstructed, tables) into one .tar.xz, to continue it on another "
             "checkout or machine (ldna unpack, then --resume)",
    )
    pack.add_argument("run", type=_case_or_folder, help="a case or a folder of cases (a study)")
    pack.add_argument("archive", help="the .tar.xz to write")
    pack.set_defaults(func=_pack)

    unpack = commands.add_parser("unpack", help="unpack an archive of ldna pack")
    unpack.add_argument("archive", help="the .tar.xz of ldna pack")
    unpack.add_argument("run", help="folder to unpack into; must not exist")
    unpack.set_defaults(func=_unpack)

    _json_flag(post, "the bead figures as one JSON object (mm, mm2, K, deg) instead of the table")
    post.set_defaults(func=_post)
    return parser


#: Errors of the user's input or of a run, told in one line; anything else is
#: a bug and shows its traceback.  LDNA_DEBUG=1 shows the traceback of all.
USER_ERRORS = (OSError, ValueError, RuntimeError, KeyError)


def main(argv: list[str] | None = None) -> int:
    """Run the ``ldna`` command line."""
    args = build_parser().parse_args(argv)
    try:
        return int(args.func(args))
    except USER_ERRORS as error:
        if os.environ.get("LDNA_DEBUG"):
            raise
        message = str(error).strip().splitlines()
        print(f"ldna {args.command}: error: {message[0] if message else type(error).__name__}",
              file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
