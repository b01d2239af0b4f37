"""Run a benchmark suite over a Ray cluster: one Ray task per shard, merged as the CLI merges.

    python -m shenlong.ray_bench SUITE --shards N --out DIR [--llm L] [--system S]
                                 [--collide] [--limit N] [--jobs N] [--address ADDR]

Each shard K/N runs ``shenlong.bench(SUITE, shard=(K, N))`` in a task on whichever node
Ray picks, in a scratch folder of that node; the task returns the shard's results and run
description, which are kept in DIR/shards/shard-K (so a second run of the same command
resumes each shard where it stopped), and DIR gets the report ``shenlong.bench_merge``
builds from them: the same figures as ``shenlong bench SUITE --out DIR`` on one machine.

A task that fails is retried once by Ray; a shard that fails twice is named on stderr and
in the report (``missing_shards``), and the command exits with status 1. Without
``--address``, ``ray.init()`` starts a local Ray; with one (``auto``, ``HOST:PORT`` or
``ray://HOST:10001``) it joins a running cluster. Every node must read the suite and its
scenes at the same path (a shared filesystem), or pass ``--working-dir`` to have Ray ship
a folder to the nodes (SUITE is then relative to it). See docs/python.md.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import shenlong


def _write_atomic(path: Path, text: str) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def run_shard(
    suite: str,
    shard: Tuple[int, int],
    options: Dict[str, Any],
    prior_results: Optional[str],
) -> Dict[str, str]:
    """One shard in a scratch folder: its results.jsonl and run.json as text.

    ``prior_results`` (an earlier attempt's results) are put back first, so the run
    resumes where that one stopped.
    """
    with tempfile.TemporaryDirectory(prefix="shenlong-shard-") as scratch:
        if prior_results:
            Path(scratch, "results.jsonl").write_text(prior_results, encoding="utf-8")
        shenlong.bench(suite, scratch, shard=shard, **options)
        return {
            "results": Path(scratch, "results.jsonl").read_text(encoding="utf-8"),
            "run": Path(scratch, "run.json").read_text(encoding="utf-8"),
        }


def _parse(argv: Optional[Sequence[str]]) -> argparse.Namespace:
    p = argparse.ArgumentParser(
        prog="python -m shenlong.ray_bench",
        description="Run a Shenlong benchmark suite as Ray tasks, one per shard, and merge "
        "the shards into one report (the same figures as `shenlong bench` on one machine).",
        epilog="Example: python -m shenlong.ray_bench bench/dev.suite.json --shards 8 "
        "--out results/gpt-4o --llm openai:gpt-4o --system cga,euclidean,omniverse "
        "--address auto",
    )
    p.add_argument("suite", help="the suite file (*.suite.json)")
    p.add_argument("--shards", type=int, required=True, metavar="N", help="number of shards (Ray tasks)")
    p.add_argument("--out", required=True, metavar="DIR", help="where the shards and the merged report go")
    p.add_argument("--llm", default="offline", help="the translator (default: offline)")
    p.add_argument("--system", default="cga", help="prompt systems, separated by commas (default: cga)")
    p.add_argument("--collide", action="store_true", help="resolve collisions as `edit` does")
    p.add_argument("--limit", type=int, metavar="N", help="run at most N instances per system")
    p.add_argument("--jobs", type=int, default=1, metavar="N", help="instances at once within a shard")
    p.add_argument("--address", help="a running Ray cluster (auto, HOST:PORT, ray://HOST:10001); "
                   "default: start a local Ray")
    p.add_argument("--working-dir", metavar="DIR", help="a folder Ray ships to every node "
                   "(runtime_env working_dir); SUITE is relative to it")
    p.add_argument("--num-cpus", type=int, metavar="N", help="CPUs of a local Ray (default: all)")
    args = p.parse_args(argv)
    if args.shards < 1:
        p.error("--shards must be at least 1")
    if args.jobs < 1:
        p.error("--jobs must be at least 1")
    if args.limit is not None and args.limit < 0:
        p.error("--limit must be at least 0")
    return args


def main(argv: Optional[Sequence[str]] = None) -> int:
    args = _parse(argv)
    try:
        import ray
    except ImportError:
        print("shenlong.ray_bench: Ray is not installed: pip install 'ray>=2.9'", file=sys.stderr)
        return 2

    out = Path(args.out)
    # The output is checked before any shard runs: a run's results are never lost to it.
    if out.exists() and not out.is_dir():
        print(f"shenlong.ray_bench: --out {out}: not a folder (a file is there)", file=sys.stderr)
        return 2
    try:
        out.mkdir(parents=True, exist_ok=True)
        probe = out / f".shenlong-write-check-{os.getpid()}"
        probe.write_bytes(b"")
        probe.unlink()
    except OSError as exc:
        print(f"shenlong.ray_bench: --out {out}: cannot write there: {exc.strerror or exc}", file=sys.stderr)
        return 2
    local_suite = Path(args.working_dir, args.suite) if args.working_dir else Path(args.suite)
    if not local_suite.is_file():
        print(f"shenlong.ray_bench: {local_suite}: no such suite file", file=sys.stderr)
        return 2
    options = {
        "llm": args.llm,
        "system": args.system,
        "collide": args.collide,
        "limit": args.limit,
        "jobs": args.jobs,
    }
    init: Dict[str, Any] = {"include_dashboard": False, "log_to_driver": False}
    if args.address:
        init["address"] = args.address
    elif args.num_cpus:
        init["num_cpus"] = args.num_cpus
    if args.working_dir:
        init["runtime_env"] = {"working_dir": args.working_dir}
    # Shards on a shared filesystem read the suite by its absolute path; with a working
    # dir, by its path inside the shipped folder.
    suite = args.suite if args.working_dir else str(local_suite.resolve())
    ray.init(**init)
    try:
        return _run(ray, suite, args.shards, options, out)
    finally:
        ray.shutdown()


def _run(
    ray: Any,
    suite: str,
    n: int,
    options: Dict[str, Any],
    out: Path,
    shard_fn: Callable[..., Dict[str, str]] = run_shard,
) -> int:
    """Runs the shards as Ray tasks (``shard_fn`` is :func:`run_shard`; tests pass one that
    fails), keeps their folders and merges them; the exit status."""
    task = ray.remote(max_retries=1, retry_exceptions=True)(shard_fn)
    pending = {}
    for k in range(1, n + 1):
        prior = out / "shards" / f"shard-{k}" / "results.jsonl"
        prior_text = prior.read_text(encoding="utf-8") if prior.is_file() else None
        pending[task.remote(suite, (k, n), options, prior_text)] = k
    done: List[Path] = []
    failed: List[Tuple[int, str]] = []
    print(f"shards done 0/{n}", file=sys.stderr, flush=True)
    while pending:
        ready, _ = ray.wait(list(pending), num_returns=1)
        for ref in ready:
            k = pending.pop(ref)
            folder = out / "shards" / f"shard-{k}"
            try:
                got = ray.get(ref)
            except Exception as e:  # a shard that failed twice: named, never dropped
                cause = getattr(e, "cause", None) or e
                failed.append((k, str(cause).strip().splitlines()[-1] if str(cause).strip() else type(cause).__name__))
                print(f"shenlong.ray_bench: shard {k}/{n} failed twice: {failed[-1][1]}", file=sys.stderr)
            else:
                _write_atomic(folder / "results.jsonl", got["results"])
                _write_atomic(folder / "run.json", got["run"])
                done.append(folder)
            print(f"shards done {len(done) + len(failed)}/{n}", file=sys.stderr, flush=True)
    if not done:
        print("shenlong.ray_bench: every shard failed: no report", file=sys.stderr)
        return 1
    done.sort(key=lambda p: int(p.name.split("-")[1]))
    report = shenlong.bench_merge(done, out)
    print(f"report: {out / 'report.md'}", file=sys.stderr)
    if failed:
        names = ", ".join(f"{k}/{n}" for k, _ in sorted(failed))
        print(f"shenlong.ray_bench: the report covers part of the run: shard(s) {names} failed",
              file=sys.stderr)
        return 1
    print(json.dumps({name: s["overall"]["success_rate"] for name, s in report["systems"].items()}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
