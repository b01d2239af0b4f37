"""Broken and hostile binary stages: valid `.usdc` files authored by Pixar's own library
(`usd-core`), then corrupted byte by byte and in their counts. `shenlong` must answer
each with an edit or a one-line refusal, in bounded time, and never be killed by a
signal (a crash, an abort, memory exhausted).

    SHENLONG_BIN=target/debug/shenlong /tmp/usd/bin/python -m unittest integrations/usd/tests/test_usd_hostile.py -v
"""

from __future__ import annotations

import os
import random
import struct
import subprocess
import tempfile
import time
import unittest

try:
    from pxr import Gf, Sdf, Usd, UsdGeom
except ImportError:  # pragma: no cover - reported by the runner
    raise unittest.SkipTest("usd-core is not installed (pip install usd-core)")


from test_usd_e2e import binary  # the one way these tests find the shenlong binary


def run(*args: str) -> tuple[subprocess.CompletedProcess, float]:
    env = dict(os.environ, SHENLONG_USD_SECONDS="5")
    start = time.monotonic()
    r = subprocess.run([binary(), *args], capture_output=True, text=True, timeout=60, env=env)
    return r, time.monotonic() - start


def author(path: str) -> None:
    """A small valid stage: a turned table with a mesh, a cube, a non-ASCII op name."""
    stage = Usd.Stage.CreateNew(path)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    table = UsdGeom.Xform.Define(stage, "/World/Table")
    table.AddTranslateOp().Set(Gf.Vec3d(1, 0, 0))
    table.AddRotateYOp().Set(30.0)
    mesh = UsdGeom.Mesh.Define(stage, "/World/Table/Top")
    pts = [Gf.Vec3f(x, y, z) for x in (-0.6, 0.6) for y in (0.7, 0.75) for z in (-0.4, 0.4)]
    mesh.GetPointsAttr().Set(pts)
    mesh.GetFaceVertexCountsAttr().Set([4, 4])
    mesh.GetFaceVertexIndicesAttr().Set([0, 1, 3, 2, 4, 5, 7, 6])
    cube = UsdGeom.Cube.Define(stage, "/World/A")
    cube.GetSizeAttr().Set(0.5)
    cube.AddTranslateOp().Set(Gf.Vec3d(-1, 0.25, 0))
    # An op whose name is not ASCII, as a stage from elsewhere may have.
    prim = stage.GetPrimAtPath("/World/A")
    attr = prim.CreateAttribute("xformOp:rotateÅY", Sdf.ValueTypeNames.Float)
    attr.Set(10.0)
    # … named in the op order, where Shenlong reads it (it once sliced the name by bytes).
    UsdGeom.Xformable(prim).GetXformOpOrderAttr().Set(["xformOp:translate", "xformOp:rotateÅY"])
    stage.GetRootLayer().Save()


class HostileCrates(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="shenlong-usdc-")
        self.dir = self._tmp.name
        self.valid = os.path.join(self.dir, "valid.usdc")
        author(self.valid)
        with open(self.valid, "rb") as f:
            self.bytes = f.read()

    def tearDown(self):
        self._tmp.cleanup()

    def check(self, data: bytes, name: str) -> str:
        path = os.path.join(self.dir, name)
        with open(path, "wb") as f:
            f.write(data)
        out = os.path.join(self.dir, "out.usda")
        if os.path.exists(out):
            os.remove(out)
        r, took = run("edit", path, "move the 'A' 1 m to the left", "-o", out)
        self.assertGreaterEqual(r.returncode, 0, f"{name}: killed by signal {-r.returncode}: {r.stderr[-300:]}")
        self.assertIn(r.returncode, (0, 1), f"{name}: exit {r.returncode}: {r.stderr[-300:]}")
        self.assertLess(took, 30, f"{name}: took {took:.1f} s")
        if r.returncode == 1:
            self.assertEqual(len(r.stderr.strip().splitlines()), 1, f"{name}: {r.stderr!r}")
            self.assertFalse(os.path.exists(out), f"{name}: a refusal wrote {out}")
        return "edited" if r.returncode == 0 else "refused"

    def test_the_valid_stage_is_edited(self):
        self.assertEqual(self.check(self.bytes, "ok.usdc"), "edited")

    def test_single_byte_mutants_never_crash_or_hang(self):
        rng = random.Random(7)
        outcomes = {"edited": 0, "refused": 0}
        for k in range(120):
            data = bytearray(self.bytes)
            at = rng.randrange(len(data))
            data[at] = (data[at] + rng.randrange(1, 256)) % 256
            outcomes[self.check(bytes(data), f"m{k}.usdc")] += 1
        print(f"\n120 single-byte mutants: {outcomes}")

    def test_huge_counts_are_refused(self):
        # Every 8-byte little-endian number in the file that looks like a count or an
        # offset (1..2^20), set to 2^50: the crate must not trust it.
        positions = [
            i for i in range(0, len(self.bytes) - 8, 8)
            if 0 < struct.unpack_from("<Q", self.bytes, i)[0] < (1 << 20)
        ]
        self.assertTrue(positions)
        for k, i in enumerate(positions[:60]):
            data = bytearray(self.bytes)
            struct.pack_into("<Q", data, i, 1 << 50)
            self.check(bytes(data), f"count{k}.usdc")


if __name__ == "__main__":
    unittest.main()
