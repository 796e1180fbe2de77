"""The ``charts`` command line.

    charts run SCENE -o DIR [--resume|--force] [--quiet]   run a scene (a .toml file or a bundled name)
    charts scenes [NAME]                          list the bundled scenes, or print one
    charts reproduce ...                          the paper's figures and table
    charts generate [--check]                     regenerate generated/ (code generator)
    charts bench accuracy | integrators | performance | compare | coldstart | ensemble | first_use | gpu
    charts sweep SWEEP -o DIR [--scheduler ADDR]   a parameter sweep on Dask
    charts warmup [--n N ...]                     compile the kernels once after an install

Every subcommand has ``--help``.  No command prints a traceback for anything a user can
do: errors in the input (arguments, scene or sweep files, output folders, a folder another
process is writing) are reported in one line on stderr, ``charts: error: …``, with exit
status 2; a run that started and failed (e.g. a trajectory through a singular point, or
an unexpected error) exits with 1 and keeps its finished part; an interrupted run exits
with 130 (Ctrl-C) or 143 (SIGTERM, taken as Ctrl-C) and says what was kept and how to
resume it.  ``charts --debug …`` or
``CHARTS_DEBUG=1`` shows the traceback of a failure (for developers).
"""
from __future__ import annotations

import argparse
import importlib.util
import os
import shlex
import sys
import traceback
from pathlib import Path

from ..runs import interrupts
from ..runs.bundled import bundled_files
from ..runs.cli_parser import OneLineParser

__all__ = ["main", "bundled_scenes", "resolve_scene"]

EXIT_USAGE = 2
EXIT_FAILED = 1
EXIT_INTERRUPTED = 130


def _checkout_root() -> Path | None:
    """The source checkout holding this package (None for a plain installation)."""
    root = Path(__file__).resolve().parents[2]
    return root if (root / "scripts" / "generate.py").exists() else None


def bundled_scenes() -> dict[str, Path]:
    """Name -> path of every scene shipped in ``charts/data/scenes``."""
    return bundled_files("charts.data.scenes")


def resolve_scene(arg: str) -> Path:
    """A scene argument is a path to a .toml file or the name of a bundled scene."""
    p = Path(arg)
    if p.exists() or p.suffix == ".toml":
        return p
    scenes = bundled_scenes()
    if arg in scenes:
        return scenes[arg]
    import difflib
    hint = difflib.get_close_matches(arg, list(scenes), n=1)
    did = f" — did you mean {hint[0]!r}?" if hint else ""
    raise SystemExit(_fail(f"{arg!r} is neither a scene file nor a bundled scene{did} "
                           "(list them with `charts scenes`)"))


def _fail(msg: str) -> int:
    print(f"charts: error: {msg}", file=sys.stderr)
    return EXIT_USAGE


# ------------------------------------------------------------------------------- run
def _cmd_run(args) -> int:
    from ..runs.outdir import LOCK, check_output
    from ..runs.runner import RunError, run_scene
    from ..runs.scene import SceneError, load_scene

    path = resolve_scene(args.scene)
    out = Path(args.output)
    if args.force and args.resume:
        return _fail("--force and --resume exclude each other (--force starts over)")
    check_output(out)                    # a file, under a file, too long: refused, nothing made
    if not args.resume and not args.force and out.is_dir() and any(
            p.name != LOCK for p in out.iterdir()):
        return _fail(f"{out} is not empty: use --force to overwrite its results, --resume to "
                     "continue an interrupted run there, or choose another output folder")
    try:
        scene = load_scene(path)
        # --force: the old outputs are removed by run_scene once it holds the folder's lock
        result = run_scene(scene, args.output, resume=args.resume, quiet=args.quiet,
                           force=args.force)
    except SceneError as exc:
        return _fail(str(exc))
    except RunError as exc:
        _fail(str(exc))
        # a run that started and failed (status "failed" in result.json) exits with 1
        return 1 if _status(args.output) == "failed" else EXIT_USAGE
    except KeyboardInterrupt as exc:
        res = exc.args[0] if exc.args and isinstance(exc.args[0], dict) else None
        if res is not None:
            p = res["progress"]
            print(f"\ninterrupted at t = {p['t_done']:g} of {p['t_final']:g} "
                  f"({p['chunks_done']}/{p['chunks']} chunks kept in {args.output}); "
                  f"continue with:\n  charts run {shlex.quote(str(args.scene))} -o "
                  f"{shlex.quote(str(args.output))} --resume",
                  file=sys.stderr)
        return EXIT_INTERRUPTED
    if not args.quiet:
        _summary(result, args.output)
    return 0


def _status(outdir) -> str | None:
    import json
    try:
        return json.loads((Path(outdir) / "result.json").read_text()).get("status")
    except (OSError, ValueError):
        return None


def _summary(result: dict, outdir) -> None:
    comp, res = result["computation"], result["results"]
    times = result["timings"]
    compiled = (f" and {times['compile_wall_s']:.1f} s compiling kernels"
                if times["compile_wall_s"] >= 0.05 else "")
    print(f"{result['scene']['name']}: done in {times['integration_wall_s']:.2f} s of wall time "
          f"integrating{compiled} (files and figures not counted) -> {outdir}")
    print(f"  integrated: {comp['state_dimension']} state variables, "
          f"{comp['tangent_vectors']} tangent vectors, {comp['rhs_evaluations']} rhs evaluations")
    d = result["drift"]
    print(f"  final drift: constraint {d['constraint']:.1e}, tangency {d['tangency']:.1e}, "
          f"energy {d['energy_relative']:.1e}")
    if "lyapunov" in res and "exponents" in res["lyapunov"]:
        ly = res["lyapunov"]
        se = ly.get("stderr", [float("nan")] * len(ly["exponents"]))
        txt = ", ".join(f"{e:.4f} ± {s:.4f}" for e, s in zip(ly["exponents"], se))
        print(f"  Lyapunov exponents: {txt}" + (f"  (paper: {ly['paper']})" if "paper" in ly else ""))
    if "curvature" in res:
        for route in ("numerical", "exact"):
            if route in res["curvature"]:
                fp = res["curvature"][route]["fraction_positive"]
                print(f"  curvature ({route}): fraction of K_ii > 0: "
                      + ", ".join(f"{x:.3f}" for x in fp))
    if "switches" in res:
        print(f"  chart switches: {res['switches']['count']}")
    print(f"  files: {', '.join(result['files'])}")


# ------------------------------------------------------------------------------- scenes
def _cmd_scenes(args) -> int:
    scenes = bundled_scenes()
    if args.name:
        if args.name not in scenes:
            return _fail(f"no bundled scene {args.name!r} (one of: {', '.join(scenes)})")
        print(scenes[args.name].read_text(), end="")
        return 0
    from ..runs.scene import SceneError, load_scene
    width = max(len(n) for n in scenes) if scenes else 0
    for name, path in scenes.items():
        try:
            desc = load_scene(path).description.strip().splitlines()[0]
        except (SceneError, IndexError) as exc:
            desc = f"(invalid: {exc})" if isinstance(exc, SceneError) else ""
        print(f"{name:<{width}}  {desc}")
    print("\nrun one with: charts run NAME -o DIR   (print it: charts scenes NAME)")
    return 0


# ------------------------------------------------------------------------------- delegation
def _load_script(name: str):
    root = _checkout_root()
    path = root / "scripts" / f"{name}.py" if root else None
    if path is None or not path.exists():
        return None
    spec = importlib.util.spec_from_file_location(f"charts_script_{name}", path)
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod  # so that its functions pickle for worker processes
    spec.loader.exec_module(mod)
    return mod


def _cmd_reproduce(args) -> int:
    try:
        from ..runs.reproduce import main as reproduce_main
    except ImportError:
        return _fail("`charts reproduce` needs charts.runs.reproduce, which this "
                     "installation does not have yet")
    try:
        return int(reproduce_main(args.rest) or 0)
    except SystemExit as exc:            # its argparse: --help, usage errors
        return exc.code if isinstance(exc.code, int) else EXIT_USAGE


def _cmd_generate(args) -> int:
    script = _load_script("generate")
    argv = ["--check"] if args.check else []
    if script is not None:
        return int(script.main(argv) or 0)
    return _generate_installed(args.check)


def _generate_installed(check: bool) -> int:
    """Without a checkout: compare (or rewrite) the installed ``charts.generated``."""
    from importlib.util import find_spec

    from ..codegen.regenerate import stale_files, write_all

    folder = Path(find_spec("charts.generated").origin).resolve().parent
    if not check:
        write_all(folder, verbose=False)
        print(f"wrote {folder}")
        return 0
    stale, _ = stale_files(folder)
    if stale:
        print(f"{folder}: stale: {', '.join(stale)}; run `charts generate` to rewrite")
        return 1
    print(f"{folder} is up to date")
    return 0


def _cmd_warmup(args) -> int:
    """`charts warmup`: compile every analysis's kernels for the given N (or load them)."""
    from ..runs.warmup import TASKS, warmup

    bad = [n for n in args.n if n < 3]
    if bad:
        return _fail(f"--n: N must be at least 3, got {bad[0]}")
    unknown = [a for a in args.analysis or () if a not in TASKS]
    if unknown:
        return _fail(f"--analysis: unknown {unknown[0]!r}; choose from {', '.join(TASKS)}")

    def report(row):
        if not args.quiet:
            print(f"{row['analysis']:>10}  N = {row['n']}: {row['compile']:6.1f} s compiling "
                  f"({row['cpu']:.1f} s CPU in all)", flush=True)

    if args.workers is not None and args.workers < 1:
        return _fail(f"--workers must be at least 1, got {args.workers}")
    rows = warmup(args.n, args.analysis, report=report, workers=args.workers)
    if not args.quiet:
        print(f"charts: kernels ready ({sum(r['compile'] for r in rows):.1f} s); later processes "
              "load them from numba's cache")
    return 0


def _cmd_bench(args) -> int:
    """`charts bench NAME`: module NAME of ``charts.runs.benchmarks`` (accuracy: runs.accuracy)."""
    if args.what == "accuracy":
        from ..runs.accuracy import main as accuracy_main
        return int(accuracy_main(args.rest, quiet=args.quiet) or 0)
    module = importlib.import_module(f"charts.runs.benchmarks.{args.what}")
    return int(module.main(args.rest) or 0)


# ------------------------------------------------------------------------------- parser
class _SourceVersion(argparse.Action):
    """``--version``: the release and the code it runs (``charts.version.source_version``),
    read only when asked."""

    def __call__(self, parser, namespace, values, option_string=None):
        from ..version import source_version

        parser.exit(message=f"charts {source_version()}\n")


def build_parser() -> argparse.ArgumentParser:
    ap = OneLineParser(
        prog="charts", description="Geodesic flows of coupled rotators (Kuznetsov): run scenes, "
        "reproduce the paper, regenerate code, benchmark.",
        epilog="`charts COMMAND --help` describes each command.")
    ap.add_argument("--version", action=_SourceVersion, nargs=0,
                    help="show the release and the commit (or source digest) it runs, and exit")
    ap.add_argument("--debug", action="store_true",
                    help="show the traceback of a failure (also CHARTS_DEBUG=1)")
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")

    p = sub.add_parser("run", help="run a scene (TOML file or bundled name) into a folder",
                       description="Run a scene: validate it, integrate only what its effects "
                       "need, write result.json, arrays.npz and PNG figures into DIR. Ctrl-C "
                       "keeps the finished chunks; --resume continues.")
    p.add_argument("scene", metavar="SCENE", help="path to a .toml scene, or a bundled scene "
                   "name (see `charts scenes`)")
    p.add_argument("-o", "--output", required=True, type=Path, metavar="DIR",
                   help="output folder (created if missing)")
    p.add_argument("--resume", action="store_true",
                   help="continue an interrupted run from DIR/checkpoint.npz")
    p.add_argument("--force", action="store_true",
                   help="start over in DIR even if it is not empty: once DIR's lock is held, the "
                   "files of the earlier run there (results, checkpoint, figures) are removed; "
                   "other files are kept")
    p.add_argument("--quiet", "-q", action="store_true", help="no progress bar, no summary")
    p.set_defaults(func=_cmd_run)

    p = sub.add_parser("scenes", help="list the bundled scenes, or print one",
                       description="List the scenes shipped with charts (one per figure of "
                       "the paper, the table of exponents, the integrators' hard cases).")
    p.add_argument("name", nargs="?", help="print this scene's TOML")
    p.set_defaults(func=_cmd_scenes)

    p = sub.add_parser("reproduce", help="reproduce the paper's figures and table",
                       description="Dispatch to charts.runs.reproduce; the options after "
                       "`reproduce` are passed through (try `charts reproduce --help`).",
                       add_help=False)
    p.add_argument("rest", nargs=argparse.REMAINDER)
    p.set_defaults(func=_cmd_reproduce)

    p = sub.add_parser("generate", help="regenerate the chart kernels in generated/",
                       description="Run the code generator (scripts/generate.py in a checkout) "
                       "for N = 3..6.")
    p.add_argument("--check", action="store_true",
                   help="regenerate into a temporary place and exit 1 if generated/ is stale")
    p.set_defaults(func=_cmd_generate)

    p = sub.add_parser("warmup", help="compile the kernels once after an install",
                       description="Call each analysis once for each N so that numba compiles "
                       "and caches its kernels, in parallel processes, each kernel compiled by "
                       "one of them; the first real call then loads them in ~0.05 s instead of "
                       "compiling (docs/performance.md, Cold start). Run it after every install "
                       "or upgrade.")
    p.add_argument("--n", type=int, nargs="+", default=[3, 4, 5, 6], metavar="N",
                   help="rotor counts (default 3 4 5 6)")
    p.add_argument("--analysis", nargs="+", metavar="NAME",
                   help="lyapunov, lanes, integrate, integrate_ambient, curvature, angles, "
                   "clv (default all but lanes: an ensemble takes the lanes only where they "
                   "are compiled or where it runs long enough to pay for compiling them)")
    p.add_argument("--workers", type=int, default=None, metavar="W",
                   help="parallel processes (default: one per core)")
    p.add_argument("--quiet", "-q", action="store_true", help="print nothing")
    p.set_defaults(func=_cmd_warmup)

    p = sub.add_parser("bench", help="benchmarks: `accuracy` (work–precision), `integrators` "
                       "(against solve_ivp), `performance` (against JiTCODE and SciPy), "
                       "`compare` (installations against each other), `coldstart` (the first-ever call), "
                       "`ensemble` (lanes against the one-trajectory kernel), `first_use` (each "
                       "analysis's first call on an empty cache, warmup, reproduce --quick), `gpu` (ensembles on a GPU)",
                       description="`charts bench accuracy [--quick] [-o DIR]`: work–precision "
                       "diagrams and table (docs/accuracy.md). `charts bench integrators`: cost "
                       "per unit time against solve_ivp (docs/integrators.md). `charts bench "
                       "performance [--quick]`: the Lyapunov task against JiTCODE and SciPy, cold "
                       "start, all cores (docs/performance.md). `charts bench compare --engine "
                       "LABEL=PYTHON ...`: Lyapunov throughput of several installations, e.g. two "
                       "checkouts, interleaved in one run. `charts bench coldstart`: where the "
                       "seconds of a fresh install's first call go (docs/performance.md). `charts "
                       "bench ensemble [--quick]`: ensembles in vector lanes against the "
                       "one-trajectory kernel and JiTCODE. `charts bench first_use`: CPU seconds "
                       "of each public analysis's first call per N on an empty cache. `charts bench "
                       "gpu [--quick] [--flops]`: Lyapunov ensembles on an NVIDIA GPU against the "
                       "CPU lanes on every core (docs/gpu.md). Each is a "
                       "module of "
                       "charts.runs.benchmarks: no source checkout needed.")
    p.add_argument("what", choices=("accuracy", "integrators", "performance", "compare",
                                    "coldstart", "ensemble", "first_use", "gpu"))
    p.add_argument("--quiet", "-q", action="store_true", help="no progress bars (accuracy)")
    p.add_argument("rest", nargs=argparse.REMAINDER,
                   help="options of the benchmark (e.g. `charts bench performance --help`)")
    p.set_defaults(func=_cmd_bench)

    from .sweep import add_parser as add_sweep_parser   # `charts sweep`
    add_sweep_parser(sub)
    from .verdict import add_parser as add_verdict_parser   # `charts verdict`
    add_verdict_parser(sub)
    return ap


def main(argv=None) -> int:
    """Run ``charts ARGV``; return the exit status (0, 1 failed, 2 usage, 130 interrupted,
    143 stopped by SIGTERM)."""
    argv = list(sys.argv[1:] if argv is None else argv)
    debug = os.environ.get("CHARTS_DEBUG", "") not in ("", "0")
    if argv[:1] == ["--debug"]:
        debug, argv = True, argv[1:]
    # SIGTERM as Ctrl-C (exit 143), pool workers quiet and stopped (charts.runs.interrupts)
    with interrupts.handled():
        return interrupts.exit_status(_main(argv, debug))


def console(argv=None) -> int:
    """The ``charts`` command (and ``python -m charts``): `main`, then, for a command that an
    interrupt stopped (130, 143) or whose pool workers an interrupt killed, the process ends
    at once with its status, its output flushed, everything it keeps written already:
    Python's exit would join the pools' manager threads, which a killed worker can leave
    waiting forever for the rest of a result, or writing to a pipe already closed (a
    traceback after the interrupted message)."""
    status = main(argv)
    if status in (interrupts.EXIT_INTERRUPTED, interrupts.EXIT_TERMINATED) or \
            interrupts.workers_stopped():
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(status)
    return status


def _main(argv, debug) -> int:
    try:
        return _dispatch(argv)
    except KeyboardInterrupt:            # outside the run and sweep handlers (which resume)
        print("\ncharts: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except BrokenPipeError:              # `charts scenes | head`
        return 0
    except Exception as exc:             # noqa: BLE001 - the one place that reports them all
        if interrupts.interrupt_for(exc) is not None:   # a pool broken by the interrupt
            print("\ncharts: interrupted", file=sys.stderr)
            return EXIT_INTERRUPTED
        return _report_exception(exc, debug)


def _report_exception(exc: BaseException, debug: bool) -> int:
    """One line ``charts: error: …`` (the traceback with ``debug``); the exit status: 2 for
    input refused by a check (ValueError, TypeError, charts' own input errors), 1 otherwise."""
    if debug:
        traceback.print_exception(exc)
    usage = isinstance(exc, (ValueError, TypeError))
    text = " ".join(str(exc).split()) or type(exc).__name__
    if len(text) > 400:
        text = f"{text[:200]} … {text[-150:]}"
    if not usage:
        text = f"{type(exc).__name__}: {text}"
    hint = "" if debug else " (run with --debug or CHARTS_DEBUG=1 for the traceback)"
    print(f"charts: error: {text}" + ("" if usage else hint), file=sys.stderr)
    return EXIT_USAGE if usage else EXIT_FAILED


def _dispatch(argv) -> int:
    ap = build_parser()
    if argv[:1] == ["reproduce"]:        # pass everything through, --help included
        return _cmd_reproduce(argparse.Namespace(rest=argv[1:]))
    try:
        args = ap.parse_args(argv)
    except SystemExit as exc:            # --help, --version (0) or a usage error (2)
        return exc.code if isinstance(exc.code, int) else EXIT_USAGE
    if args.command is None:
        ap.print_help()
        return EXIT_USAGE
    try:
        return int(args.func(args) or 0)
    except SystemExit as exc:            # resolve_scene and delegated parsers
        return exc.code if isinstance(exc.code, int) else EXIT_USAGE


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
