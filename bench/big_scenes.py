#!/usr/bin/env python3
"""Whole-process benchmark of `shenlong edit` on big scenes (issue: big scenes).

For each size it writes a scene JSON of unit boxes on a square grid (1.5 m apart, so
neighbours leave 0.5 m gaps), then runs, in the same loop and alternating so that the
shared machine's noise falls on both alike:

* `shenlong edit SCENE "move the 'box-K' 1.5 m to the right" -o OUT --json REPORT`: the
  box lands on its neighbour, so the edit collides once and is resolved;
* `python3 -c 'import json; json.load(open(SCENE))'`, the baseline the targets are
  stated against.

It reports, per size, the median wall time of each, their ratio, and the median peak
resident memory of the edit (from `wait4`'s `ru_maxrss`), and checks that every edit
succeeded and moved the box. The files go to a temporary folder, removed afterwards.

    python3 bench/big_scenes.py --bin target/release/shenlong --sizes 1000,10000,100000 --runs 5

With `--group`, each scene is `N` chairs 1 m apart and the edit is a group edit, "move all
the chairs 1 m up" (nothing collides: the cost of collision checks for N moved objects),
timed beside the same edit with `--no-collide` and `json.load`. With `--compare BIN`,
another build of `shenlong` (an earlier commit's) runs the same edit in the same loop,
alternating, so that two builds are compared on a machine loaded alike.

    python3 bench/big_scenes.py --group --sizes 1000,10000 --runs 5
    python3 bench/big_scenes.py --sizes 100000 --runs 9 --compare /tmp/old/shenlong
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time


def write_objects(path: str, name: str, count: int, spacing: float, entry) -> int:
    """Writes scene `name` of `count` objects on a square grid `spacing` m apart,
    `entry(i, x, z)` giving each one's JSON; returns the grid's side."""
    side = math.ceil(math.sqrt(count))
    with open(path, "w", encoding="utf-8") as f:
        f.write(f'{{"name": "{name}", "objects": [\n')
        for i in range(count):
            x, z = (i % side) * spacing, (i // side) * spacing
            f.write((",\n" if i else "") + entry(i, x, z))
        f.write("\n]}\n")
    return side


def write_grid(path: str, count: int) -> str:
    """Writes `count` unit boxes 1.5 m apart and returns the name of one in the middle."""
    side = write_objects(
        path, "grid", count, 1.5,
        lambda i, x, z: f'{{"name": "box-{i}", "size": [1, 1, 1], "position": [{x}, 0, {z}]}}',
    )
    middle = (side // 2) * side + side // 2
    return f"box-{min(middle, count - 1)}"


def write_chairs(path: str, count: int) -> None:
    """Writes `count` chairs on a grid 1 m apart (0.5 m gaps), for a group edit."""
    write_objects(
        path, "hall", count, 1.0,
        lambda i, x, z: f'{{"name": "chair {i + 1}", "category": "chair", '
        f'"size": [0.5, 0.9, 0.5], "position": [{x}, 0, {z}]}}',
    )


def group_rows(args, sizes, tmp) -> int:
    """The group-edit figures (`--group`)."""
    for n in sizes:
        scene = os.path.join(tmp, f"hall-{n}.json")
        write_chairs(scene, n)
        out = os.path.join(tmp, f"hall-out-{n}.json")
        edit = [args.bin, "edit", scene, "move all the chairs 1 m up", "-o", out]
        python = [sys.executable, "-c", f"import json; json.load(open({scene!r}))"]
        with_c, without_c, peaks, baselines = [], [], [], []
        for _ in range(args.runs):
            t, rss, code, stderr = run_measured(edit)
            if code != 0:
                print(f"{n} chairs: the edit failed: {stderr.strip()}", file=sys.stderr)
                return 1
            with_c.append(t)
            peaks.append(rss)
            t2, _, code, stderr = run_measured(edit + ["--no-collide"])
            if code != 0:
                print(f"{n} chairs: the edit failed: {stderr.strip()}", file=sys.stderr)
                return 1
            without_c.append(t2)
            baselines.append(run_measured(python)[0])
        print(
            f"{n:>9} chairs  group edit {statistics.median(with_c) * 1000:9.1f} ms  "
            f"--no-collide {statistics.median(without_c) * 1000:9.1f} ms  "
            f"json.load {statistics.median(baselines) * 1000:8.1f} ms  "
            f"peak {statistics.median(peaks) / 1024:7.1f} MiB",
            flush=True,
        )
    return 0


def run_measured(argv: list[str]) -> tuple[float, int, int, str]:
    """Runs a command; returns (seconds, peak RSS in KiB, exit code, stderr)."""
    err = tempfile.TemporaryFile()
    start = time.perf_counter()
    pid = os.fork()
    if pid == 0:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        os.dup2(err.fileno(), 2)
        try:
            os.execvp(argv[0], argv)
        finally:
            os._exit(127)
    _, status, usage = os.wait4(pid, 0)
    elapsed = time.perf_counter() - start
    err.seek(0)
    code = os.waitstatus_to_exitcode(status)
    return elapsed, usage.ru_maxrss, code, err.read().decode("utf-8", "replace")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", default="target/release/shenlong", help="the shenlong binary")
    parser.add_argument(
        "--sizes", default="1000,10000,100000", help="object counts, comma-separated"
    )
    parser.add_argument("--runs", type=int, default=5, help="runs per size (median quoted)")
    parser.add_argument("--json", help="also write the figures as JSON to this file")
    parser.add_argument("--group", action="store_true", help="time a group edit of N chairs")
    parser.add_argument("--compare", metavar="BIN", help="another shenlong build, timed alike")
    args = parser.parse_args()
    sizes = [int(s) for s in args.sizes.split(",") if s.strip()]
    rows = []
    if args.group:
        with tempfile.TemporaryDirectory(prefix="shenlong-group-") as tmp:
            return group_rows(args, sizes, tmp)
    with tempfile.TemporaryDirectory(prefix="shenlong-big-") as tmp:
        for n in sizes:
            scene = os.path.join(tmp, f"grid-{n}.json")
            name = write_grid(scene, n)
            out = os.path.join(tmp, f"out-{n}.json")
            report = os.path.join(tmp, f"report-{n}.json")
            edit = [
                args.bin, "edit", scene, f"move the '{name}' 1.5 m to the right",
                "-o", out, "--json", report,
            ]
            python = [sys.executable, "-c", f"import json; json.load(open({scene!r}))"]
            times, peaks, baselines, phases = [], [], [], []
            other_times, other_peaks = [], []
            for _ in range(args.runs):
                if args.compare:
                    t, rss, code, stderr = run_measured([args.compare] + edit[1:])
                    if code != 0:
                        print(f"{n} objects: --compare's edit failed: {stderr.strip()}", file=sys.stderr)
                        return 1
                    other_times.append(t)
                    other_peaks.append(rss)
                t, rss, code, stderr = run_measured(edit)
                if code != 0:
                    print(f"{n} objects: the edit failed: {stderr.strip()}", file=sys.stderr)
                    return 1
                with open(report, encoding="utf-8") as f:
                    # `--json` writes the edit's outcome; the whole report is in it.
                    r = json.load(f)["report"]
                if not r.get("collisions_resolved"):
                    print(f"{n} objects: the edit resolved no collision", file=sys.stderr)
                    return 1
                phases.append(r.get("timings_ms", {}))
                times.append(t)
                peaks.append(rss)
                baselines.append(run_measured(python)[0])
            size_mb = os.path.getsize(scene) / 1e6
            row = {
                "objects": n,
                "file_mb": round(size_mb, 2),
                "edit_s": statistics.median(times),
                "python_json_load_s": statistics.median(baselines),
                "ratio": statistics.median(times) / statistics.median(baselines),
                "peak_mib": statistics.median(peaks) / 1024,
                "bytes_per_object": statistics.median(peaks) * 1024 / n,
                "phases_ms": {
                    k: statistics.median(p.get(k, 0.0) for p in phases)
                    for k in sorted({k for p in phases for k in p})
                },
            }
            if other_times:
                row["compare_edit_s"] = statistics.median(other_times)
                row["compare_peak_mib"] = statistics.median(other_peaks) / 1024
                row["vs_compare"] = row["edit_s"] / row["compare_edit_s"]
            rows.append(row)
            print(
                f"{n:>9} objects  {size_mb:7.2f} MB  edit {row['edit_s'] * 1000:9.1f} ms  "
                f"json.load {row['python_json_load_s'] * 1000:8.1f} ms  "
                f"ratio {row['ratio']:5.2f}  peak {row['peak_mib']:7.1f} MiB "
                f"({row['bytes_per_object']:.0f} B/object)",
                flush=True,
            )
            print(f"{'':>11}phases (ms): {row['phases_ms']}", flush=True)
            if other_times:
                print(
                    f"{'':>11}--compare: edit {row['compare_edit_s'] * 1000:9.1f} ms, "
                    f"peak {row['compare_peak_mib']:7.1f} MiB; this build / that one: "
                    f"time {row['vs_compare']:.3f}, memory {row['peak_mib'] / row['compare_peak_mib']:.3f}",
                    flush=True,
                )
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(rows, f, indent=2)
    return 0


if __name__ == "__main__":
    sys.exit(main())
