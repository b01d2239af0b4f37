"""End to end on real-looking files: scenes authored with the formats' own libraries the way
Blender, Omniverse, a USD pipeline, a glTF exporter and a CAD exporter write them
(`../author.py`), edited with `shenlong edit FILE "INSTRUCTION" -o OUT`, and read back
with the format's own library (usd-core's bounding boxes and transforms; pygltflib and
numpy for glTF; json for scene JSON). Every assertion is about where things end up, never
about Shenlong's report.

    python3.11 -m venv /tmp/shenlong-real-venv
    /tmp/shenlong-real-venv/bin/pip install usd-core pygltflib numpy
    SHENLONG_BIN=target/debug/shenlong /tmp/shenlong-real-venv/bin/python \
        -m unittest discover -s integrations/realfiles/tests -v

Frame: Shenlong is Y-up metres; right = +X, left = -X, forward = +Z, back = -Z. A Z-up
stage maps as Shenlong (x, y, z) = stage (x, z, -y): right is stage +X, forward is stage
-Y, up is stage +Z. The Blender room is in centimetres (1 unit = 1 cm).
"""

from __future__ import annotations

import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

try:
    import numpy as np
    import pygltflib
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdShade
except ImportError as exc:  # pragma: no cover - reported by the runner
    raise unittest.SkipTest(
        f"needs usd-core, pygltflib and numpy ({exc}); "
        "pip install usd-core pygltflib numpy"
    )

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
import author  # noqa: E402

REPO = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SRC = None  # the folder the files are authored into, once per run
_TMP = None


def setUpModule():
    global SRC, _TMP
    _TMP = tempfile.TemporaryDirectory(prefix="shenlong-realfiles-")
    SRC = os.path.join(_TMP.name, "src")
    author.author_all(SRC)


def tearDownModule():
    _TMP.cleanup()


# ---------------------------------------------------------------------------------------
# Running shenlong
# ---------------------------------------------------------------------------------------


def binary() -> str:
    path = os.environ.get("SHENLONG_BIN") or os.path.join(REPO, "target", "debug", "shenlong")
    return os.path.abspath(path)


def shenlong(*args: str) -> subprocess.CompletedProcess:
    """Runs the binary; a missing binary fails the test (build it first)."""
    path = binary()
    if not os.path.exists(path):
        raise AssertionError(f"no shenlong binary at {path}: build it first (cargo build)")
    return subprocess.run([path, *args], capture_output=True, text=True, timeout=120)


def src(*parts):
    return os.path.join(SRC, *parts)


# ---------------------------------------------------------------------------------------
# USD read-back
# ---------------------------------------------------------------------------------------


def open_stage(path):
    """Opens a stage with usd-core; a file usd-core cannot read fails the test (not an error)."""
    try:
        stage = Usd.Stage.Open(path)
    except Exception as exc:  # pxr.Tf.ErrorException
        first = " ".join(str(exc).split())[:400]
        raise AssertionError(f"usd-core cannot open {os.path.basename(path)}: {first}") from None
    if stage is None:
        raise AssertionError(f"usd-core cannot open {os.path.basename(path)}")
    return stage


def wbox(stage, path):
    """The world axis-aligned box of a prim, by usd-core; None when the prim is missing."""
    prim = stage.GetPrimAtPath(path)
    if not prim or not prim.IsValid():
        return None
    cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [UsdGeom.Tokens.default_])
    r = cache.ComputeWorldBound(prim).ComputeAlignedRange()
    if r.IsEmpty():
        return None
    return np.array(r.GetMin(), float), np.array(r.GetMax(), float)


def world_matrix(stage, path):
    prim = stage.GetPrimAtPath(path)
    return UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(Usd.TimeCode.Default())


def world_dir(stage, path, local):
    d = world_matrix(stage, path).TransformDir(Gf.Vec3d(*local))
    return np.array(d, float)


def centre(box):
    return (box[0] + box[1]) / 2


def fmt(v):
    return "(" + ", ".join(f"{x:.3f}" for x in v) + ")"


def box_gap(a, b, axes):
    """Distance between two boxes over the given axes (0 when they touch or overlap)."""
    g = [max(b[0][k] - a[1][k], a[0][k] - b[1][k], 0.0) for k in axes]
    return math.sqrt(sum(x * x for x in g))


def penetration(a, b):
    """How deep two boxes interpenetrate (the smallest overlap over the three axes); <= 0
    when they do not."""
    return min(min(a[1][k], b[1][k]) - max(a[0][k], b[0][k]) for k in range(3))


def angle_deg(u, v):
    u, v = np.asarray(u, float), np.asarray(v, float)
    c = float(np.dot(u, v) / (np.linalg.norm(u) * np.linalg.norm(v)))
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def wrap180(a):
    return (a + 180.0) % 360.0 - 180.0


BLENDER_OBJECTS = ["/root/Floor"] + [f"/root/{w}" for w in author.BLENDER_WALLS] + [
    f"/root/{n}" for n in author.BLENDER
]
OMNI_OBJECTS = [
    "/World/Furniture/Table",
    "/World/Furniture/Table/Top",
    "/World/Furniture/Table/Leg_FL",
    "/World/Furniture/Table/Leg_FR",
    "/World/Furniture/Table/Leg_BL",
    "/World/Furniture/Table/Leg_BR",
    "/World/Furniture/Chair",
    "/World/Furniture/Shelf",
    "/World/Props/Mug",
    "/World/Props/Vase",
    "/World/Props/Book",
]
LAYERED_OBJECTS = ["/World/Table", "/World/Lamp", "/World/Chair"]
DUP_OBJECTS = ["/World/GroupA/Chair", "/World/GroupB/Chair", "/World/Table"]


class Base(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="shenlong-case-")
        self.dir = self._tmp.name

    def tearDown(self):
        self._tmp.cleanup()

    def out(self, name, sub=None):
        folder = os.path.join(self.dir, sub) if sub else self.dir
        os.makedirs(folder, exist_ok=True)
        return os.path.join(folder, name)

    def edit(self, scene, instruction, out, *extra):
        r = shenlong("edit", scene, instruction, "-o", out, *extra)
        self.assertEqual(
            r.returncode, 0,
            f"{instruction!r}: expected an edit, shenlong exited {r.returncode}: {r.stderr.strip()}",
        )
        self.assertTrue(os.path.exists(out), f"{instruction!r}: no output file {out}")
        return r

    def refuse(self, scene, instruction, *extra, mentions=None, describe=None):
        """The edit must fail in one line and write nothing. `describe(out)` says what an
        edit that went through did, for the failure message."""
        out = self.out("never" + os.path.splitext(scene)[1])
        r = shenlong("edit", scene, instruction, "-o", out, *extra)
        if r.returncode == 0:
            what = ""
            if describe and os.path.exists(out):
                try:
                    what = ": " + describe(out)
                except AssertionError as exc:
                    what = f": (output unreadable: {exc})"
            self.fail(f"{instruction!r} should be refused; it was edited{what}")
        self.assertFalse(os.path.exists(out), f"{instruction!r}: a refusal wrote {out}")
        lines = r.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, f"{instruction!r}: refusal is not one line: {r.stderr!r}")
        if mentions:
            self.assertIn(mentions, r.stderr, f"{instruction!r}: refusal should mention {mentions}")
        self.assertEqual(os.listdir(os.path.dirname(out)), [], "a refusal leaves no temporary file")
        return r

    # --- USD assertions ----------------------------------------------------------------

    def usd_moved_by(self, before, after, path, delta, tol, what=""):
        b, a = wbox(before, path), wbox(after, path)
        self.assertIsNotNone(a, f"{path} is missing from the edited stage")
        d = a[0] - b[0]
        self.assertTrue(
            np.allclose(d, delta, atol=tol) and np.allclose(a[1] - b[1], delta, atol=tol),
            f"{what}{path}: expected to move by {fmt(delta)}, moved by min {fmt(d)} max {fmt(a[1] - b[1])}",
        )

    def usd_unchanged(self, before, after, paths, except_=(), tol=1e-6):
        for p in paths:
            if p in except_:
                continue
            b, a = wbox(before, p), wbox(after, p)
            self.assertIsNotNone(a, f"{p} is missing from the edited stage")
            self.assertTrue(
                np.allclose(a[0], b[0], atol=tol) and np.allclose(a[1], b[1], atol=tol),
                f"{p} should not move: box {fmt(b[0])}-{fmt(b[1])} became {fmt(a[0])}-{fmt(a[1])}",
            )


# ---------------------------------------------------------------------------------------
# a. The Blender room (Z-up, centimetres)
# ---------------------------------------------------------------------------------------


class BlenderRoom(Base):
    CM = 0.1  # tolerance in stage units (cm): 1 mm

    def setUp(self):
        super().setUp()
        self.scene = src("blender_room.usda")
        self.before = open_stage(self.scene)

    def run_edit(self, instruction, name="edited.usda", sub=None):
        out = self.out(name, sub)
        self.edit(self.scene, instruction, out)
        after = open_stage(out)
        self.assertEqual(UsdGeom.GetStageUpAxis(after), UsdGeom.Tokens.z)
        self.assertAlmostEqual(UsdGeom.GetStageMetersPerUnit(after), 0.01)
        return after

    def test_move_sofa_50cm_right(self):
        after = self.run_edit("move the sofa 50 cm to the right")
        self.usd_moved_by(self.before, after, "/root/Sofa", (50, 0, 0), self.CM)
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Sofa"})

    def test_usdc_output_is_refused_and_writes_nothing(self):
        # Shenlong writes USD edits as .usda text (the only writer that keeps every stage
        # openable in usd-core); a .usdc output is refused in one line naming .usda.
        out = self.out("edited.usdc")
        r = shenlong("edit", self.scene, "move the couch half a metre to the right", "-o", out)
        self.assertNotEqual(r.returncode, 0)
        self.assertFalse(os.path.exists(out), "a refusal writes nothing")
        self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
        self.assertIn(".usda", r.stderr)

    def test_output_in_another_folder_keeps_materials_bound(self):
        after = self.run_edit("move the sofa 50 cm to the right", sub="elsewhere/deeper")
        self.usd_moved_by(self.before, after, "/root/Sofa", (50, 0, 0), self.CM)
        for name in ["Floor/Plane", "Sofa/Sofa_Mesh", "Vase/Vase_Mesh", "Armchair/Armchair_Mesh"]:
            prim = after.GetPrimAtPath(f"/root/{name}")
            self.assertTrue(prim.HasAPI(UsdShade.MaterialBindingAPI), f"{name} keeps MaterialBindingAPI")
            mat, _ = UsdShade.MaterialBindingAPI(prim).ComputeBoundMaterial()
            self.assertTrue(mat and mat.GetPrim().IsValid(), f"{name}'s material still resolves")
            self.assertTrue(str(mat.GetPath()).startswith("/root/_materials/"))

    def test_move_bed_1m_left(self):
        after = self.run_edit("move the bed 1 m to the left")
        self.usd_moved_by(self.before, after, "/root/Bed", (-100, 0, 0), self.CM)
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Bed"})

    def test_move_coffee_table_forward_carries_the_vase(self):
        after = self.run_edit("move the coffee table 30 cm forward")
        # Forward is Shenlong +Z: stage -Y in a Z-up stage.
        self.usd_moved_by(self.before, after, "/root/Coffee_Table", (0, -30, 0), self.CM)
        self.usd_moved_by(self.before, after, "/root/Vase", (0, -30, 0), self.CM, "carried: ")
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Coffee_Table", "/root/Vase"})

    def test_move_coffee_table_left_vase_stays_on_top(self):
        after = self.run_edit("slide the coffee table 40cm to the left")
        self.usd_moved_by(self.before, after, "/root/Coffee_Table", (-40, 0, 0), self.CM)
        self.usd_moved_by(self.before, after, "/root/Vase", (-40, 0, 0), self.CM, "carried: ")
        vase, table = wbox(after, "/root/Vase"), wbox(after, "/root/Coffee_Table")
        self.assertAlmostEqual(vase[0][2], table[1][2], delta=self.CM, msg="the vase still stands on the top")

    def test_raise_the_lamp_10cm(self):
        after = self.run_edit("raise the lamp by 10 cm")
        self.usd_moved_by(self.before, after, "/root/Floor_Lamp", (0, 0, 10), self.CM)
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Floor_Lamp"})

    def test_move_the_floor_lamp_left_not_the_floor(self):
        after = self.run_edit("move the floor lamp 30 cm to the left")
        self.usd_moved_by(self.before, after, "/root/Floor_Lamp", (-30, 0, 0), self.CM)
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Floor_Lamp"})

    def test_turn_armchair_to_face_coffee_table(self):
        after = self.run_edit("turn the armchair to face the coffee table")
        # Blender models face -Y: the armchair's front is its local -Y.
        front = world_dir(after, "/root/Armchair", (0, -1, 0))
        chair_c, table_c = centre(wbox(after, "/root/Armchair")), centre(wbox(after, "/root/Coffee_Table"))
        want = (table_c - chair_c)[:2]
        err = angle_deg(front[:2], want)
        self.assertLess(
            err, 10.0,
            f"armchair front {fmt(front)} should point at the coffee table (direction {fmt(want)}); off by {err:.1f} deg",
        )
        self.assertLess(abs(front[2]), 1e-6, "the armchair stays upright")
        b = centre(wbox(self.before, "/root/Armchair"))
        self.assertLess(np.linalg.norm((chair_c - b)[:2]), 1.0, "it turns where it stands")
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Armchair"})

    def test_rotate_side_table_90_degrees(self):
        after = self.run_edit("rotate the side table 90 degrees")
        yb = world_dir(self.before, "/root/Side_Table", (1, 0, 0))
        ya = world_dir(after, "/root/Side_Table", (1, 0, 0))
        change = wrap180(math.degrees(math.atan2(ya[1], ya[0]) - math.atan2(yb[1], yb[0])))
        self.assertAlmostEqual(
            change, 90.0, delta=0.01,
            msg=f"yaw should change by +90 (counter-clockwise seen from above); changed by {change:.3f}",
        )
        up = world_dir(after, "/root/Side_Table", (0, 0, 1))
        self.assertLess(angle_deg(up, (0, 0, 1)), 0.01, "it stays upright")
        cb, ca = centre(wbox(self.before, "/root/Side_Table")), centre(wbox(after, "/root/Side_Table"))
        self.assertLess(np.linalg.norm(ca - cb), self.CM, f"it turns in place: centre {fmt(cb)} -> {fmt(ca)}")
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Side_Table"})

    def test_turn_armchair_90_clockwise(self):
        after = self.run_edit("turn the armchair 90 degrees clockwise")
        fb = world_dir(self.before, "/root/Armchair", (0, -1, 0))
        fa = world_dir(after, "/root/Armchair", (0, -1, 0))
        change = wrap180(math.degrees(math.atan2(fa[1], fa[0]) - math.atan2(fb[1], fb[0])))
        self.assertAlmostEqual(change, -90.0, delta=0.01, msg=f"front turned by {change:.3f} deg")
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Armchair"})

    def test_move_turned_armchair_right(self):
        after = self.run_edit("move the armchair half a meter to the right")
        self.usd_moved_by(self.before, after, "/root/Armchair", (50, 0, 0), self.CM)
        fb = world_dir(self.before, "/root/Armchair", (0, -1, 0))
        fa = world_dir(after, "/root/Armchair", (0, -1, 0))
        self.assertLess(angle_deg(fa, fb), 0.01, "a move does not turn it")
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Armchair"})

    def test_move_sofa_back_50cm(self):
        after = self.run_edit("push the sofa back 50 cm")
        self.usd_moved_by(self.before, after, "/root/Sofa", (0, 50, 0), self.CM)
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Sofa"})

    def test_move_vase_10cm_right_stays_on_table(self):
        after = self.run_edit("move the vase 10cm to the right")
        self.usd_moved_by(self.before, after, "/root/Vase", (10, 0, 0), self.CM)
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Vase"})

    def test_move_sofa_and_armchair_forward(self):
        after = self.run_edit("move the sofa and the armchair 20 cm forward")
        self.usd_moved_by(self.before, after, "/root/Sofa", (0, -20, 0), self.CM)
        self.usd_moved_by(self.before, after, "/root/Armchair", (0, -20, 0), self.CM)
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Sofa", "/root/Armchair"})

    def test_vase_on_the_floor_next_to_the_lamp(self):
        after = self.run_edit("put the vase on the floor next to the lamp")
        vase, lamp, floor = wbox(after, "/root/Vase"), wbox(after, "/root/Floor_Lamp"), wbox(after, "/root/Floor")
        self.assertAlmostEqual(
            vase[0][2], floor[1][2], delta=1.0,
            msg=f"the vase's bottom should be on the floor (z {floor[1][2]:.2f}); it is at z {vase[0][2]:.2f}",
        )
        gap = box_gap(vase, lamp, (0, 1))
        self.assertLessEqual(gap, 100.0, f"the vase should be next to the lamp (within 1 m); it is {gap:.1f} cm away")
        self.assertLessEqual(penetration(vase, lamp), 0.1, "the vase is not inside the lamp")
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Vase"})

    def test_push_bed_against_the_wall(self):
        after = self.run_edit("push the bed against the wall")
        bed = wbox(after, "/root/Bed")
        gaps = {w: box_gap(bed, wbox(after, f"/root/{w}"), (0, 1)) for w in author.BLENDER_WALLS}
        nearest = min(gaps, key=gaps.get)
        self.assertLessEqual(
            gaps[nearest], 5.0,
            f"the bed should end within 5 cm of a wall; nearest is {nearest} at {gaps[nearest]:.1f} cm "
            f"(bed {fmt(bed[0])}-{fmt(bed[1])})",
        )
        for w in author.BLENDER_WALLS:
            self.assertLessEqual(penetration(bed, wbox(after, f"/root/{w}")), 0.1, f"the bed is not inside {w}")
        self.assertAlmostEqual(bed[0][2], 0.0, delta=self.CM, msg="the bed stays on the floor")
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Bed"})

    def test_coffee_table_to_the_middle_of_the_room(self):
        after = self.run_edit("move the coffee table to the middle of the room")
        c = centre(wbox(after, "/root/Coffee_Table"))
        # The room is what the walls enclose: x in [-300, 300], y in [-250, 250].
        self.assertLess(
            np.linalg.norm(c[:2]), 5.0,
            f"the coffee table's centre should be at the room's middle (0, 0); it is at {fmt(c)}",
        )
        tb, ta = wbox(self.before, "/root/Coffee_Table"), wbox(after, "/root/Coffee_Table")
        self.usd_moved_by(self.before, after, "/root/Vase", ta[0] - tb[0], self.CM, "carried: ")
        self.usd_unchanged(self.before, after, BLENDER_OBJECTS, except_={"/root/Coffee_Table", "/root/Vase"})

    def test_piano_is_refused(self):
        self.refuse(self.scene, "move the piano 1 m left")


# ---------------------------------------------------------------------------------------
# b. The Omniverse props stage (Y-up, metres, plain groups, no kinds)
# ---------------------------------------------------------------------------------------


class OmniverseProps(Base):
    M = 1e-3

    def setUp(self):
        super().setUp()
        self.scene = src("omniverse_props.usda")
        self.before = open_stage(self.scene)

    def run_edit(self, instruction, name="edited.usda", sub=None):
        out = self.out(name, sub)
        self.edit(self.scene, instruction, out)
        return open_stage(out)

    def test_move_chair_30cm_forward_moves_only_the_chair(self):
        after = self.run_edit("move the chair 30 cm forward")
        self.usd_moved_by(self.before, after, "/World/Furniture/Chair", (0, 0, 0.3), self.M)
        self.usd_unchanged(self.before, after, OMNI_OBJECTS, except_={"/World/Furniture/Chair"})

    def test_the_table_is_the_whole_five_mesh_table_and_carries_mug_and_vase(self):
        after = self.run_edit("move the table 50 cm to the left")
        for p in ["/World/Furniture/Table"] + [f"/World/Furniture/Table/{m}" for m in
                                               ("Top", "Leg_FL", "Leg_FR", "Leg_BL", "Leg_BR")]:
            self.usd_moved_by(self.before, after, p, (-0.5, 0, 0), self.M)
        self.usd_moved_by(self.before, after, "/World/Props/Mug", (-0.5, 0, 0), self.M, "carried: ")
        self.usd_moved_by(self.before, after, "/World/Props/Vase", (-0.5, 0, 0), self.M, "carried: ")
        self.usd_unchanged(self.before, after, ["/World/Furniture/Chair", "/World/Furniture/Shelf", "/World/Props/Book"])

    def test_put_the_book_on_the_table(self):
        after = self.run_edit("put the book on the table")
        book, table = wbox(after, "/World/Props/Book"), wbox(after, "/World/Furniture/Table")
        self.assertAlmostEqual(book[0][1], author.OMNI_TABLE_TOP, delta=self.M,
                               msg=f"book bottom at y {book[0][1]:.4f}, table top {author.OMNI_TABLE_TOP}")
        c = centre(book)
        self.assertTrue(table[0][0] <= c[0] <= table[1][0] and table[0][2] <= c[2] <= table[1][2],
                        f"the book's centre {fmt(c)} is over the table")
        for p in ("/World/Props/Mug", "/World/Props/Vase"):
            self.assertLessEqual(penetration(book, wbox(after, p)), 1e-3, f"the book does not go into {p}")
        self.usd_unchanged(self.before, after, OMNI_OBJECTS, except_={"/World/Props/Book"})

    def test_move_mug_20cm_right(self):
        after = self.run_edit("move the mug 20 cm to the right")
        self.usd_moved_by(self.before, after, "/World/Props/Mug", (0.2, 0, 0), self.M)
        self.usd_unchanged(self.before, after, OMNI_OBJECTS, except_={"/World/Props/Mug"})

    def test_move_shelf_carries_the_book(self):
        after = self.run_edit("move the shelf 1 m to the right")
        self.usd_moved_by(self.before, after, "/World/Furniture/Shelf", (1, 0, 0), self.M)
        self.usd_moved_by(self.before, after, "/World/Props/Book", (1, 0, 0), self.M, "carried: ")
        self.usd_unchanged(self.before, after, OMNI_OBJECTS, except_={"/World/Furniture/Shelf", "/World/Props/Book"})

    def test_put_the_vase_on_the_shelf(self):
        after = self.run_edit("put the vase on the shelf")
        vase, shelf = wbox(after, "/World/Props/Vase"), wbox(after, "/World/Furniture/Shelf")
        self.assertAlmostEqual(vase[0][1], shelf[1][1], delta=self.M,
                               msg=f"vase bottom y {vase[0][1]:.4f}, shelf top {shelf[1][1]:.4f}")
        c = centre(vase)
        self.assertTrue(shelf[0][0] <= c[0] <= shelf[1][0] and shelf[0][2] <= c[2] <= shelf[1][2],
                        f"the vase's centre {fmt(c)} is over the shelf")
        self.assertLessEqual(penetration(vase, wbox(after, "/World/Props/Book")), 1e-3, "not into the book")
        self.usd_unchanged(self.before, after, OMNI_OBJECTS, except_={"/World/Props/Vase"})

    def test_usda_to_another_folder(self):
        after = self.run_edit("move the chair 20 cm to the right", name="props_edit.usda", sub="out/usda")
        self.assertEqual(UsdGeom.GetStageUpAxis(after), UsdGeom.Tokens.y)
        self.assertEqual(after.GetDefaultPrim().GetPath(), Sdf.Path("/World"))
        self.usd_moved_by(self.before, after, "/World/Furniture/Chair", (0.2, 0, 0), self.M)
        self.usd_unchanged(self.before, after, OMNI_OBJECTS, except_={"/World/Furniture/Chair"})

    def test_turn_chair_to_face_the_shelf(self):
        after = self.run_edit("turn the chair so it faces the shelf")
        front = world_dir(after, "/World/Furniture/Chair", (0, 0, 1))
        want = centre(wbox(after, "/World/Furniture/Shelf")) - centre(wbox(after, "/World/Furniture/Chair"))
        err = angle_deg(front[[0, 2]], want[[0, 2]])
        self.assertLess(err, 10.0, f"chair front {fmt(front)} vs direction to shelf {fmt(want)}: {err:.1f} deg")
        self.usd_unchanged(self.before, after, OMNI_OBJECTS, except_={"/World/Furniture/Chair"})

    def test_piano_is_refused(self):
        self.refuse(self.scene, "move the piano 1 m to the left")


# ---------------------------------------------------------------------------------------
# c. A layered shot: sublayer + reference, written to another folder
# ---------------------------------------------------------------------------------------


def _read_tree(folder):
    out = {}
    for root, _, files in os.walk(folder):
        for f in files:
            p = os.path.join(root, f)
            with open(p, "rb") as fh:
                out[os.path.relpath(p, folder)] = fh.read()
    return out


class LayeredShot(Base):
    M = 1e-3

    def setUp(self):
        super().setUp()
        self.scene = src("layered", "shot.usda")
        self.before = open_stage(self.scene)
        self.inputs = _read_tree(src("layered"))

    def check_composes(self, after, moved, delta):
        for p in LAYERED_OBJECTS:
            self.assertIsNotNone(wbox(after, p), f"{p} no longer composes in the edited shot")
        self.usd_moved_by(self.before, after, moved, delta, self.M)
        self.usd_unchanged(self.before, after, LAYERED_OBJECTS, except_={moved})
        self.assertEqual(_read_tree(src("layered")), self.inputs, "the input files are never written")

    def test_move_referenced_chair_output_elsewhere(self):
        out = self.out("shot_edit.usda", "renders/v002")
        self.edit(self.scene, "move the chair 40 cm to the right", out)
        self.check_composes(open_stage(out), "/World/Chair", (0.4, 0, 0))

    def test_move_sublayer_table_output_elsewhere(self):
        out = self.out("shot_table.usda", "elsewhere")
        self.edit(self.scene, "move the table 30 cm back", out)
        self.check_composes(open_stage(out), "/World/Table", (0, 0, -0.3))

    def test_layer_beside_the_shot(self):
        # --usd-layer: a layer of overs over the shot, written beside it.
        work = os.path.join(self.dir, "layered")
        shutil.copytree(src("layered"), work)
        out = os.path.join(work, "shot_lamp.usda")
        self.edit(os.path.join(work, "shot.usda"), "move the lamp 1 m to the right", out, "--usd-layer")
        self.check_composes(open_stage(out), "/World/Lamp", (1, 0, 0))


# ---------------------------------------------------------------------------------------
# d. Two prims named Chair
# ---------------------------------------------------------------------------------------


class Duplicates(Base):
    M = 1e-3

    def setUp(self):
        super().setUp()
        self.scene = src("duplicates.usda")
        self.before = open_stage(self.scene)

    def moved(self, out):
        after = open_stage(out)
        return ", ".join(f"{p} moved by {fmt(wbox(after, p)[0] - wbox(self.before, p)[0])}" for p in DUP_OBJECTS)

    def test_the_chair_is_ambiguous_and_refused(self):
        self.refuse(self.scene, "move the chair 20 cm to the left", describe=self.moved)

    def test_the_chair_in_group_a(self):
        out = self.out("a.usda")
        self.edit(self.scene, "move the chair in GroupA 20 cm to the left", out)
        after = open_stage(out)
        self.usd_moved_by(self.before, after, "/World/GroupA/Chair", (-0.2, 0, 0), self.M)
        self.usd_unchanged(self.before, after, DUP_OBJECTS, except_={"/World/GroupA/Chair"})

    def test_the_group_b_chair(self):
        out = self.out("b.usda")
        self.edit(self.scene, "move the GroupB chair 20 cm to the right", out)
        after = open_stage(out)
        self.usd_moved_by(self.before, after, "/World/GroupB/Chair", (0.2, 0, 0), self.M)
        self.usd_unchanged(self.before, after, DUP_OBJECTS, except_={"/World/GroupB/Chair"})

    def test_the_table_moves_alone(self):
        out = self.out("t.usda")
        self.edit(self.scene, "move the table 20 cm forward", out)
        after = open_stage(out)
        self.usd_moved_by(self.before, after, "/World/Table", (0, 0, 0.2), self.M)
        self.usd_unchanged(self.before, after, DUP_OBJECTS, except_={"/World/Table"})


# ---------------------------------------------------------------------------------------
# glTF read-back with pygltflib + numpy
# ---------------------------------------------------------------------------------------


def _quat_matrix(q):
    x, y, z, w = q
    return np.array([
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ])


def _node_local(n):
    if n.matrix is not None and list(n.matrix) != [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]:
        return np.array(n.matrix, float).reshape(4, 4).T  # column-major
    m = np.eye(4)
    r = _quat_matrix(n.rotation or [0, 0, 0, 1])
    s = np.diag(n.scale or [1, 1, 1])
    m[:3, :3] = r @ s
    m[:3, 3] = n.translation or [0, 0, 0]
    return m


class Gltf:
    """World matrices and world boxes of a glTF file's nodes, by node name."""

    def __init__(self, path):
        self.path = path
        self.doc = pygltflib.GLTF2().load(path)
        d = self.doc
        self.world = {}
        self.box = {}
        scene = d.scenes[d.scene or 0]
        order = []
        stack = [(i, np.eye(4)) for i in scene.nodes]
        while stack:
            i, parent = stack.pop()
            w = parent @ _node_local(d.nodes[i])
            self.world[i] = w
            order.append(i)
            for c in d.nodes[i].children or []:
                stack.append((c, w))
        for i in reversed(order):  # children before parents
            n = d.nodes[i]
            boxes = []
            if n.mesh is not None:
                for prim in d.meshes[n.mesh].primitives:
                    acc = d.accessors[prim.attributes.POSITION]
                    lo, hi = acc.min, acc.max
                    pts = np.array([[x, y, z, 1] for x in (lo[0], hi[0]) for y in (lo[1], hi[1])
                                    for z in (lo[2], hi[2])])
                    wp = (self.world[i] @ pts.T).T[:, :3]
                    boxes.append((wp.min(0), wp.max(0)))
            for c in n.children or []:
                if c in self.box:
                    boxes.append(self.box[c])
            if boxes:
                self.box[i] = (np.min([b[0] for b in boxes], 0), np.max([b[1] for b in boxes], 0))
        self.by_name = {n.name: i for i, n in enumerate(d.nodes)}

    def b(self, name):
        return self.box[self.by_name[name]]

    def w(self, name):
        return self.world[self.by_name[name]]


def gltf_validator():
    """The Khronos validator's validate.mjs with its node_modules, when installed."""
    for d in (os.environ.get("GLTF_VALIDATOR_DIR"), os.path.join(REPO, "tools", "gltf-validator")):
        if d and os.path.isdir(os.path.join(d, "node_modules", "gltf-validator")) and shutil.which("node"):
            return os.path.join(d, "validate.mjs")
    return None


class GltfBase(Base):
    M = 1e-3

    def gltf_moved_by(self, before, after, name, delta, tol=None, what=""):
        tol = tol or self.M
        b, a = before.b(name), after.b(name)
        self.assertTrue(
            np.allclose(a[0] - b[0], delta, atol=tol) and np.allclose(a[1] - b[1], delta, atol=tol),
            f"{what}{name}: expected to move by {fmt(delta)}, moved by min {fmt(a[0] - b[0])} max {fmt(a[1] - b[1])}",
        )

    def gltf_unchanged(self, before, after, names, except_=(), tol=1e-6):
        for n in names:
            if n in except_:
                continue
            b, a = before.b(n), after.b(n)
            self.assertTrue(
                np.allclose(a[0], b[0], atol=tol) and np.allclose(a[1], b[1], atol=tol),
                f"{n} should not move: {fmt(b[0])}-{fmt(b[1])} became {fmt(a[0])}-{fmt(a[1])}",
            )

    def validate(self, path):
        v = gltf_validator()
        if not v:
            return
        r = subprocess.run(["node", v, path], capture_output=True, text=True, timeout=120)
        self.assertEqual(r.returncode, 0, f"{path} fails the Khronos validator: {r.stdout}")


GLTF_PARTS = ["Seat", "Back", "Leg_L", "Leg_R"]
GLTF_ALL = ["Floor", "Table", "Cup"] + GLTF_PARTS


# ---------------------------------------------------------------------------------------
# e. hierarchy.gltf
# ---------------------------------------------------------------------------------------


class HierarchyGltf(GltfBase):
    def setUp(self):
        super().setUp()
        self.scene = src("hierarchy.gltf")
        self.before = Gltf(self.scene)

    def run_edit(self, instruction, name="edited.gltf", sub=None):
        out = self.out(name, sub)
        self.edit(self.scene, instruction, out)
        return Gltf(out)

    def test_the_four_part_chair_moves_as_one_output_elsewhere(self):
        out = self.out("chair_right.gltf", "export/v2")
        self.edit(self.scene, "move the chair 50 cm to the right", out)
        after = Gltf(out)
        for part in GLTF_PARTS:
            self.gltf_moved_by(self.before, after, part, (0.5, 0, 0), what="chair part ")
        self.gltf_unchanged(self.before, after, GLTF_ALL, except_=set(GLTF_PARTS))
        for buf in after.doc.buffers:
            self.assertTrue(buf.uri and os.path.exists(os.path.join(os.path.dirname(out), buf.uri)),
                            f"buffer {buf.uri} resolves beside the output")
        self.validate(out)

    def test_move_table_carries_the_cup(self):
        after = self.run_edit("move the table 40 cm to the left")
        self.gltf_moved_by(self.before, after, "Table", (-0.4, 0, 0))
        self.gltf_moved_by(self.before, after, "Cup", (-0.4, 0, 0), what="carried: ")
        self.gltf_unchanged(self.before, after, GLTF_ALL, except_={"Table", "Cup"})
        self.validate(after.path)

    def test_rotate_turned_table_90_carries_the_cup(self):
        after = self.run_edit("rotate the table 90 degrees")

        def yaw(w):
            d = w[:3, :3] @ np.array([1.0, 0, 0])
            return math.degrees(math.atan2(-d[2], d[0]))

        change = wrap180(yaw(after.w("Table")) - yaw(self.before.w("Table")))
        self.assertAlmostEqual(change, 90.0, delta=0.01, msg=f"the table's yaw changed by {change:.3f}")
        cup, table = after.b("Cup"), after.b("Table")
        self.assertAlmostEqual(cup[0][1], author.GLTF_TABLE_TOP, delta=self.M, msg="the cup is still on the top")
        # Carried round the table's centre (the origin): (0.1, 0.05) -> (0.05, -0.1).
        c = centre(cup)
        self.assertLess(np.linalg.norm(c[[0, 2]] - np.array([0.05, -0.1])), 0.01,
                        f"the cup turns with the table: centre {fmt(c)}, expected (0.05, _, -0.1)")
        self.gltf_unchanged(self.before, after, GLTF_ALL, except_={"Table", "Cup"})

    def test_move_cup_10cm_left(self):
        after = self.run_edit("move the cup 10 cm to the left")
        self.gltf_moved_by(self.before, after, "Cup", (-0.1, 0, 0))
        self.gltf_unchanged(self.before, after, GLTF_ALL, except_={"Cup"})

    def test_move_chair_30cm_forward(self):
        after = self.run_edit("move the chair 30cm forward")
        for part in GLTF_PARTS:
            self.gltf_moved_by(self.before, after, part, (0, 0, 0.3), what="chair part ")
        self.gltf_unchanged(self.before, after, GLTF_ALL, except_=set(GLTF_PARTS))

    def test_turn_the_chair_90_degrees_as_one(self):
        after = self.run_edit("turn the chair 90 degrees")
        pivot = np.array([0.0, 1.0])  # the chair's footprint centre (x, z)
        a = math.radians(90)
        for part in GLTF_PARTS:
            cb = centre(self.before.b(part))[[0, 2]] - pivot
            want = pivot + np.array([cb[0] * math.cos(a) + cb[1] * math.sin(a),
                                     -cb[0] * math.sin(a) + cb[1] * math.cos(a)])
            got = centre(after.b(part))[[0, 2]]
            self.assertLess(np.linalg.norm(got - want), 0.01,
                            f"{part} should turn with the chair about its centre: at {fmt(got)}, expected {fmt(want)}")
        self.gltf_unchanged(self.before, after, GLTF_ALL, except_=set(GLTF_PARTS))

    def test_sofa_is_refused(self):
        self.refuse(self.scene, "move the sofa 1 m to the left")


# ---------------------------------------------------------------------------------------
# f. cad_mm.glb
# ---------------------------------------------------------------------------------------


class CadMillimetres(GltfBase):
    def setUp(self):
        super().setUp()
        self.scene = src("cad_mm.glb")
        self.before = Gltf(self.scene)

    def test_implausible_scale_is_refused_mentioning_units(self):
        def moved(out):
            after = Gltf(out)
            return ", ".join(f"{n} moved by {fmt(after.b(n)[0] - self.before.b(n)[0])} mm"
                             for n in ("Desk", "Monitor"))

        self.refuse(self.scene, "move the desk 10 cm to the right", mentions="--units", describe=moved)

    def test_units_mm_move_desk_10cm_right_carries_monitor(self):
        out = self.out("desk.glb")
        self.edit(self.scene, "move the desk 10 cm to the right", out, "--units", "mm")
        with open(out, "rb") as f:
            self.assertEqual(f.read(4), b"glTF", "a .glb stays binary")
        after = Gltf(out)
        self.gltf_moved_by(self.before, after, "Desk", (100, 0, 0), tol=0.1)
        self.gltf_moved_by(self.before, after, "Monitor", (100, 0, 0), tol=0.1, what="carried: ")
        self.gltf_unchanged(self.before, after, ["Floor", "Chair"])
        self.validate(out)

    def test_units_mm_move_monitor_5cm_left(self):
        out = self.out("monitor.glb")
        self.edit(self.scene, "move the monitor 5 cm to the left", out, "--units", "mm")
        after = Gltf(out)
        self.gltf_moved_by(self.before, after, "Monitor", (-50, 0, 0), tol=0.1)
        self.assertAlmostEqual(after.b("Monitor")[0][1], author.CAD_DESK_TOP, delta=0.1)
        self.gltf_unchanged(self.before, after, ["Floor", "Desk", "Chair"])


class AuthoredFilesAreValid(GltfBase):
    def test_authored_gltf_files_pass_the_khronos_validator(self):
        if not gltf_validator():
            self.skipTest("Khronos validator not installed (npm ci in a copy of tools/gltf-validator; "
                          "set GLTF_VALIDATOR_DIR)")
        for f in ("hierarchy.gltf", "cad_mm.glb"):
            self.validate(src(f))

    def test_authored_usd_files_open(self):
        for f in ("blender_room.usda", "omniverse_props.usda", "duplicates.usda", "layered/shot.usda"):
            stage = open_stage(src(f))
            self.assertTrue(stage.GetDefaultPrim().IsValid(), f)


# ---------------------------------------------------------------------------------------
# 4. One small scene as scene JSON, USD and glTF: the same objects, the same edits
# ---------------------------------------------------------------------------------------

SMALL_SCENE = {
    "name": "dining corner",
    "bounds": {"min": [-3, 0, -3], "max": [3, 3, 3]},
    "objects": [
        {"name": "table", "position": [0, 0, 0], "size": [1.2, 0.75, 0.8]},
        {"name": "cup", "position": [0.2, 0.75, 0.1], "size": [0.08, 0.1, 0.08]},
        {"name": "chair", "position": [0, 0, 0.9], "size": [0.45, 0.9, 0.5], "rotation": [0, 1, 0, 0]},
    ],
}
SMALL_NAMES = ["table", "cup", "chair"]
CROSS_INSTRUCTIONS = {
    "table_left": "move the table 50 cm to the left",
    "turn_chair": "turn the chair 90 degrees",
    "cup_forward": "move the cup 10 cm forward",
}


def json_boxes(path):
    with open(path) as f:
        scene = json.load(f)
    out = {}
    for o in scene["objects"]:
        w, h, d = o["size"]
        s = o.get("scale", 1.0)
        r = _quat_matrix(o.get("rotation", [0, 0, 0, 1]))
        p = np.array(o["position"], float)
        corners = np.array([[x, y, z] for x in (-w / 2, w / 2) for y in (0, h) for z in (-d / 2, d / 2)]) * s
        wc = (r @ corners.T).T + p
        out[o["name"]] = (wc.min(0), wc.max(0))
    return out


def usd_boxes(path):
    stage = open_stage(path)
    out = {}
    for prim in stage.GetDefaultPrim().GetChildren():
        attr = prim.GetAttribute("shenlong:name")
        name = attr.Get() if attr and attr.HasAuthoredValue() else prim.GetName()
        b = wbox(stage, prim.GetPath())
        if b is not None:
            # Into Shenlong's frame (Y-up metres) whatever the stage's axes.
            mpu = UsdGeom.GetStageMetersPerUnit(stage)
            lo, hi = b[0] * mpu, b[1] * mpu
            if UsdGeom.GetStageUpAxis(stage) == UsdGeom.Tokens.z:
                lo, hi = np.array([lo[0], lo[2], -hi[1]]), np.array([hi[0], hi[2], -lo[1]])
            out[name] = (lo, hi)
    return out


def gltf_boxes(path):
    g = Gltf(path)
    return {g.doc.nodes[i].name: g.box[i] for i in g.box if g.doc.nodes[i].mesh is not None}


def without_room(boxes):
    """A converted file's objects without the slabs that carry the room (`Room_Floor`,
    `Room_Wall_…`, `Room_Ceiling`)."""
    return {n: b for n, b in boxes.items() if not n.startswith("Room_")}


def room_of(boxes):
    """The room the slabs of a converted file enclose: (min, max) inside them."""
    lo = np.array([boxes["Room_Wall_West"][1][0], boxes["Room_Floor"][1][1], boxes["Room_Wall_Back"][1][2]])
    hi = np.array([boxes["Room_Wall_East"][0][0], boxes["Room_Ceiling"][0][1], boxes["Room_Wall_Front"][0][2]])
    return lo, hi


class SameSceneThreeFormats(Base):
    TOL = 1e-3

    @classmethod
    def setUpClass(cls):
        cls._ctmp = tempfile.TemporaryDirectory(prefix="shenlong-cross-")
        d = cls._ctmp.name
        cls.json_path = os.path.join(d, "scene.json")
        with open(cls.json_path, "w") as f:
            json.dump(SMALL_SCENE, f, indent=2)
        cls.conv = {}
        for ext in ("usda", "gltf"):
            p = os.path.join(d, f"scene.{ext}")
            r = shenlong("convert", cls.json_path, p)
            cls.conv[ext] = (p if r.returncode == 0 and os.path.exists(p) else None, r.stderr.strip())
        cls.edited = {}

    @classmethod
    def tearDownClass(cls):
        cls._ctmp.cleanup()

    def converted(self, ext):
        path, err = self.conv[ext]
        self.assertIsNotNone(path, f"shenlong convert scene.json scene.{ext} failed: {err}")
        return path

    def edited_boxes(self, ext, key):
        """The edit of one instruction on one format, read back with its own library."""
        cache = (ext, key)
        if cache not in self.edited:
            scene = self.json_path if ext == "json" else self.converted(ext)
            out = os.path.join(self._ctmp.name, f"{key}.{ext}")
            r = shenlong("edit", scene, CROSS_INSTRUCTIONS[key], "-o", out)
            self.edited[cache] = (r, out)
        r, out = self.edited[cache]
        self.assertEqual(r.returncode, 0, f"{ext}: {CROSS_INSTRUCTIONS[key]!r} failed: {r.stderr.strip()}")
        return without_room({"json": json_boxes, "usda": usd_boxes, "gltf": gltf_boxes}[ext](out))

    def same(self, got, want, what):
        self.assertEqual(sorted(got), sorted(want), f"{what}: objects {sorted(got)} vs {sorted(want)}")
        for n in want:
            self.assertTrue(
                np.allclose(got[n][0], want[n][0], atol=self.TOL) and np.allclose(got[n][1], want[n][1], atol=self.TOL),
                f"{what}: {n} is {fmt(got[n][0])}-{fmt(got[n][1])}, in scene JSON {fmt(want[n][0])}-{fmt(want[n][1])}",
            )

    def test_convert_to_usd(self):
        self.converted("usda")

    def test_convert_to_gltf(self):
        self.converted("gltf")

    def test_same_objects_before_usd(self):
        self.same(without_room(usd_boxes(self.converted("usda"))), json_boxes(self.json_path), "USD before any edit")

    def test_same_objects_before_gltf(self):
        self.same(without_room(gltf_boxes(self.converted("gltf"))), json_boxes(self.json_path), "glTF before any edit")

    def test_the_room_survives_conversion(self):
        want = (np.array(SMALL_SCENE["bounds"]["min"], float), np.array(SMALL_SCENE["bounds"]["max"], float))
        for ext, boxes in (("usda", usd_boxes), ("gltf", gltf_boxes)):
            lo, hi = room_of(boxes(self.converted(ext)))
            self.assertTrue(np.allclose(lo, want[0], atol=1e-5) and np.allclose(hi, want[1], atol=1e-5),
                            f"{ext}: room {fmt(lo)}-{fmt(hi)}, in scene JSON {fmt(want[0])}-{fmt(want[1])}")

    def test_json_table_left(self):
        before, after = json_boxes(self.json_path), self.edited_boxes("json", "table_left")
        for n in ("table", "cup"):
            self.assertTrue(np.allclose(after[n][0] - before[n][0], (-0.5, 0, 0), atol=self.TOL), n)
        self.assertTrue(np.allclose(after["chair"][0], before["chair"][0], atol=1e-9))

    def test_json_turn_chair(self):
        before, after = json_boxes(self.json_path), self.edited_boxes("json", "turn_chair")
        ext_b, ext_a = before["chair"][1] - before["chair"][0], after["chair"][1] - after["chair"][0]
        self.assertTrue(np.allclose(ext_a, ext_b[[2, 1, 0]], atol=self.TOL), "a quarter turn swaps width and depth")
        self.assertTrue(np.allclose(centre(after["chair"]), centre(before["chair"]), atol=self.TOL))

    def test_json_cup_forward(self):
        before, after = json_boxes(self.json_path), self.edited_boxes("json", "cup_forward")
        self.assertTrue(np.allclose(after["cup"][0] - before["cup"][0], (0, 0, 0.1), atol=self.TOL))
        self.assertTrue(np.allclose(after["table"][0], before["table"][0], atol=1e-9))

    def _cross(self, ext, key):
        self.same(self.edited_boxes(ext, key), self.edited_boxes("json", key), f"{ext} after {CROSS_INSTRUCTIONS[key]!r}")

    def test_usd_table_left_matches_json(self):
        self._cross("usda", "table_left")

    def test_usd_turn_chair_matches_json(self):
        self._cross("usda", "turn_chair")

    def test_usd_cup_forward_matches_json(self):
        self._cross("usda", "cup_forward")

    def test_gltf_table_left_matches_json(self):
        self._cross("gltf", "table_left")

    def test_gltf_turn_chair_matches_json(self):
        self._cross("gltf", "turn_chair")

    def test_gltf_cup_forward_matches_json(self):
        self._cross("gltf", "cup_forward")


if __name__ == "__main__":
    unittest.main()
