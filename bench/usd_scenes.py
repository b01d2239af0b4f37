#!/usr/bin/env python3
"""Whole-process benchmark of USD stages: `shenlong convert STAGE OUT.json` (read) and
`shenlong edit STAGE "move box_7 1 m to the left" -o OUT.usda` (read, edit, write).

For each size it writes a `.usda` of `Xform` prims on a square grid under `/World`, each
holding a 1 m `Cube`, runs both commands `--runs` times alternating, and reports the
median wall time and the median peak resident memory (from `wait4`'s `ru_maxrss`). Every
run must succeed. The files go to a temporary folder, removed afterwards.

    python3 bench/usd_scenes.py --bin target/release/shenlong --sizes 1000,10000,100000 --runs 3
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time


def stage(n: int) -> str:
    side = int(n**0.5) + 1
    parts = ['#usda 1.0\n(\n    defaultPrim = "World"\n    metersPerUnit = 1\n    upAxis = "Y"\n)\n\ndef Xform "World"\n{\n']
    for i in range(n):
        x, z = (i % side) * 2.0, (i // side) * 2.0
        parts.append(
            f'    def Xform "Box_{i}"\n    {{\n        double3 xformOp:translate = ({x}, 0, {z})\n'
            '        uniform token[] xformOpOrder = ["xformOp:translate"]\n'
            '        def Cube "Geo"\n        {\n            double size = 1\n'
            '            double3 xformOp:translate = (0, 0.5, 0)\n'
            '            uniform token[] xformOpOrder = ["xformOp:translate"]\n        }\n    }\n'
        )
    parts.append("}\n")
    return "".join(parts)


def timed(args: list[str]) -> tuple[float, float]:
    start = time.perf_counter()
    proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(proc.pid, 0)
    elapsed = time.perf_counter() - start
    if status != 0:
        sys.exit(f"failed: {' '.join(args)}: {proc.stderr.read().decode().strip()}")
    return elapsed, usage.ru_maxrss / 1024.0


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--bin", default="target/release/shenlong")
    p.add_argument("--sizes", default="1000,10000")
    p.add_argument("--runs", type=int, default=3)
    a = p.parse_args()
    print("| prims (objects) | file | convert (read) | edit (read, edit, write) | peak memory (edit) |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for n in (int(s) for s in a.sizes.split(",")):
            src = os.path.join(tmp, f"grid{n}.usda")
            with open(src, "w") as f:
                f.write(stage(n))
            conv, edit, mem = [], [], []
            for _ in range(a.runs):
                conv.append(timed([a.bin, "convert", src, os.path.join(tmp, "o.json")])[0])
                t, m = timed([a.bin, "edit", src, "move box_7 1 m to the left", "-o", os.path.join(tmp, "o.usda")])
                edit.append(t)
                mem.append(m)
            size = os.path.getsize(src) / 1e6
            print(
                f"| {2 * n:,} ({n:,}) | {size:.1f} MB | {statistics.median(conv):.2f} s "
                f"| {statistics.median(edit):.2f} s | {statistics.median(mem):.0f} MiB |"
            )


if __name__ == "__main__":
    main()
