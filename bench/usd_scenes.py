#!/usr/bin/env python3
"""Whole-process benchmark of USD stages: `shenlong convert STAGE OUT.json` (read) and
`shenlong edit STAGE "move box_7 1 m to the left" -o OUT.usda` (read, edit, write).

For each size it writes a `.usda` of `Xform` prims on a square grid under `/World`, each
holding a 1 m `Cube`, runs both commands `--runs` times alternating, and reports the
median wall time and the median peak resident memory (from `wait4`'s `ru_maxrss`). Every
run must succeed. The files go to a temporary folder, removed afterwards.

    python3 bench/usd_scenes.py --bin target/release/shenlong --sizes 1000,10000,100000 --runs 3

With `--usd-core`, Pixar's own library does the same edit in the same loop, alternating —
open the stage, set the prim's translate op, export it — as a user would instead. It runs
in the benchmark's own virtual environment, `bench/.venv-usd` (made with `python3.11 -m
venv` and `bench/requirements-usd.txt` on first use); `--usd-python PY` names another
Python with `usd-core`. Both edits are then read back with usd-core: `Box_7` must be 1 m
to the left and `Box_8` where it was, in each output.

    python3 bench/usd_scenes.py --sizes 10000,100000 --runs 5 --usd-core
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


#: The same edit with usd-core: open, move /World/Box_7 1 m along -x, export.
USD_CORE_EDIT = """
import sys
from pxr import Gf, Usd, UsdGeom
stage = Usd.Stage.Open(sys.argv[1])
prim = stage.GetPrimAtPath("/World/Box_7")
op = UsdGeom.Xformable(prim).GetOrderedXformOps()[0]
op.Set(op.Get() + Gf.Vec3d(-1, 0, 0))
stage.GetRootLayer().Export(sys.argv[2])
"""


#: Reads an edited stage back: Box_7 moved 1 m along -x, Box_8 not (prints "ok").
USD_CORE_CHECK = """
import sys
from pxr import Usd, UsdGeom
for path in sys.argv[1:]:
    stage = Usd.Stage.Open(path)
    cache = UsdGeom.XformCache()
    def at(name):
        return cache.GetLocalToWorldTransform(stage.GetPrimAtPath("/World/" + name)).ExtractTranslation()
    assert abs(at("Box_7")[0] - (7 * 2.0 - 1)) < 1e-9 and abs(at("Box_8")[0] - 8 * 2.0) < 1e-9, path
print("ok")
"""

HERE = os.path.dirname(os.path.abspath(__file__))


def own_venv() -> str:
    """The Python of the benchmark's own virtual environment with usd-core, made on first use."""
    venv = os.path.join(HERE, ".venv-usd")
    python = os.path.join(venv, "bin", "python")
    if not os.path.exists(python):
        print(f"making {venv} (usd-core) …", file=sys.stderr, flush=True)
        subprocess.run(["python3.11", "-m", "venv", venv], check=True)
        subprocess.run(
            [python, "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
             "-r", os.path.join(HERE, "requirements-usd.txt")],
            check=True,
        )
    return python


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--bin", default="target/release/shenlong")
    p.add_argument("--sizes", default="1000,10000")
    p.add_argument("--runs", type=int, default=3)
    p.add_argument("--usd-core", action="store_true",
                   help="time the same edit with usd-core, in the benchmark's own virtual environment")
    p.add_argument("--usd-python", help="another Python with usd-core, to time the same edit with it")
    a = p.parse_args()
    if not os.path.exists(a.bin):
        sys.exit(f"no binary at {a.bin}: build it with `cargo build --release`")
    if a.usd_core and not a.usd_python:
        a.usd_python = own_venv()
    print(
        "| prims (objects) | file | convert (read) | edit (read, edit, write) | peak memory (edit) "
        "| usd-core edit | usd-core memory |"
    )
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for n in (int(s) for s in a.sizes.split(",")):
            src = os.path.join(tmp, f"grid{n}.usda")
            with open(src, "w") as f:
                f.write(stage(n))
            conv, edit, mem, pixar, pixar_mem = [], [], [], [], []
            for _ in range(a.runs):
                conv.append(timed([a.bin, "convert", src, os.path.join(tmp, "o.json")])[0])
                t, m = timed([a.bin, "edit", src, "move box_7 1 m to the left", "-o", os.path.join(tmp, "o.usda")])
                edit.append(t)
                mem.append(m)
                if a.usd_python:
                    t, m = timed([a.usd_python, "-c", USD_CORE_EDIT, src, os.path.join(tmp, "p.usda")])
                    pixar.append(t)
                    pixar_mem.append(m)
            if a.usd_python:
                check = subprocess.run(
                    [a.usd_python, "-c", USD_CORE_CHECK, os.path.join(tmp, "o.usda"), os.path.join(tmp, "p.usda")],
                    capture_output=True, text=True,
                )
                if check.stdout.strip() != "ok":
                    sys.exit(f"an edit of {n:,} objects did not read back right: {check.stderr.strip()}")
            size = os.path.getsize(src) / 1e6
            theirs = (
                f"{statistics.median(pixar):.2f} s | {statistics.median(pixar_mem):.0f} MiB"
                if pixar
                else "— | —"
            )
            print(
                f"| {2 * n:,} ({n:,}) | {size:.1f} MB | {statistics.median(conv):.2f} s "
                f"| {statistics.median(edit):.2f} s | {statistics.median(mem):.0f} MiB | {theirs} |",
                flush=True,
            )


if __name__ == "__main__":
    main()
