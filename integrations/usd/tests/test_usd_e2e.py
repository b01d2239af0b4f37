"""End to end: stages authored by Pixar's own USD library (`usd-core` on PyPI), edited with
`shenlong edit`, and read back with `usd-core` — its bounding boxes, its values.

    python3.11 -m venv /tmp/usd && /tmp/usd/bin/pip install "usd-core>=24"
    SHENLONG_BIN=target/debug/shenlong /tmp/usd/bin/python -m unittest discover -s integrations/usd/tests -v
"""

from __future__ import annotations

import os
import subprocess
import tempfile
import unittest

try:
    from pxr import Gf, Sdf, Usd, UsdGeom
except ImportError:  # pragma: no cover - reported by the runner
    raise unittest.SkipTest("usd-core is not installed (pip install usd-core)")

TOL_M = 1e-3


def binary() -> str:
    path = os.environ.get("SHENLONG_BIN")
    if not path:
        raise unittest.SkipTest("SHENLONG_BIN is not set to the shenlong binary")
    return os.path.abspath(path)


def shenlong(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([binary(), *args], capture_output=True, text=True, timeout=120)


def box_points(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [Gf.Vec3f(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]


def add_box_mesh(stage, path, lo, hi):
    """A closed box as a Mesh, in the prim's own space."""
    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr(box_points(lo, hi))
    mesh.CreateFaceVertexCountsAttr([4] * 6)
    mesh.CreateFaceVertexIndicesAttr(
        [0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1, 2, 3, 7, 6, 0, 2, 6, 4, 1, 5, 7, 3]
    )
    mesh.CreateExtentAttr([Gf.Vec3f(*lo), Gf.Vec3f(*hi)])
    return mesh


def living_room_z_up_cm(path: str) -> None:
    """Z-up, centimetres: a table (a mesh top on a nested xform), a vase (a cube gprim), a
    bookshelf under a parent turned 90 degrees, a lamp with a cylinder, and a material."""
    stage = Usd.Stage.CreateNew(path)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 0.01)
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    stage.SetMetadata("comment", "authored by usd-core for shenlong's tests")

    table = UsdGeom.Xform.Define(stage, "/World/Table")
    table.AddTranslateOp().Set(Gf.Vec3d(0, 0, 0))
    legs = UsdGeom.Xform.Define(stage, "/World/Table/Frame")
    legs.AddTranslateOp().Set(Gf.Vec3d(0, 0, 35))
    add_box_mesh(stage, "/World/Table/Frame/Top", (-60, -40, 35), (60, 40, 40))
    add_box_mesh(stage, "/World/Table/Leg", (-5, -5, 0), (5, 5, 70))

    vase = UsdGeom.Cube.Define(stage, "/World/Vase")
    vase.CreateSizeAttr(20.0)
    vase.AddTranslateOp().Set(Gf.Vec3d(200, 100, 10))
    vase.GetPrim().CreateAttribute("userProperties:glaze", Sdf.ValueTypeNames.String).Set("celadon")

    shelf = UsdGeom.Xform.Define(stage, "/World/Shelf")
    shelf.AddTranslateOp().Set(Gf.Vec3d(-250, 0, 0))
    shelf.AddRotateZOp().Set(90.0)
    add_box_mesh(stage, "/World/Shelf/Body", (-50, -15, 0), (50, 15, 180))

    lamp = UsdGeom.Xform.Define(stage, "/World/Lamp")
    lamp.AddTranslateOp().Set(Gf.Vec3d(150, -150, 0))
    lamp.AddScaleOp().Set(Gf.Vec3f(2, 2, 2))
    cyl = UsdGeom.Cylinder.Define(stage, "/World/Lamp/Stem")
    cyl.CreateRadiusAttr(5.0)
    cyl.CreateHeightAttr(60.0)
    cyl.CreateAxisAttr("Z")
    cyl.AddTranslateOp().Set(Gf.Vec3d(0, 0, 30))
    stage.GetRootLayer().Save()


def study_y_up_m(path: str) -> None:
    """Y-up, metres (written as .usdc when the path says so): a desk and a mug, nested
    xforms with an orient op, no default prim (the root's children are the objects)."""
    stage = Usd.Stage.CreateNew(path)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    desk = UsdGeom.Xform.Define(stage, "/Desk")
    desk.AddTranslateOp().Set(Gf.Vec3d(1.0, 0, -1.0))
    desk.AddOrientOp().Set(Gf.Quatf(1, 0, 0, 0))
    add_box_mesh(stage, "/Desk/Top", (-0.7, 0.72, -0.4), (0.7, 0.75, 0.4))
    add_box_mesh(stage, "/Desk/Base", (-0.6, 0.0, -0.3), (0.6, 0.72, 0.3))
    mug = UsdGeom.Xform.Define(stage, "/Mug")
    mug.AddTranslateOp().Set(Gf.Vec3d(-1.0, 0, 1.0))
    body = UsdGeom.Cylinder.Define(stage, "/Mug/Body")
    body.CreateRadiusAttr(0.05)
    body.CreateHeightAttr(0.1)
    body.CreateAxisAttr("Y")
    body.AddTranslateOp().Set(Gf.Vec3d(0, 0.05, 0))
    chair = UsdGeom.Xform.Define(stage, "/Chair")
    chair.AddTranslateOp().Set(Gf.Vec3d(2.5, 0, 1.0))
    add_box_mesh(stage, "/Chair/Seat", (-0.25, 0.0, -0.25), (0.25, 0.9, 0.25))
    stage.GetRootLayer().Save()


def world_box(stage, path):
    cache = UsdGeom.BBoxCache(Usd.TimeCode.Default(), [UsdGeom.Tokens.default_])
    r = cache.ComputeWorldBound(stage.GetPrimAtPath(path)).ComputeAlignedRange()
    return r.GetMin(), r.GetMax()


def values(stage, skip_xform_of=()):
    """Every attribute value of every prim, by path: what must be kept exactly."""
    out = {}
    for prim in stage.Traverse():
        for attr in prim.GetAttributes():
            name = attr.GetName()
            if str(prim.GetPath()) in skip_xform_of and (
                name.startswith("xformOp") or name == "xformOpOrder"
            ):
                continue
            out[(str(prim.GetPath()), name)] = attr.Get()
    return out


class UsdEndToEnd(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name

    def tearDown(self):
        self.tmp.cleanup()

    def test_z_up_centimetres_put_the_vase_on_the_table(self):
        src = os.path.join(self.dir, "room.usda")
        out = os.path.join(self.dir, "edited.usda")
        living_room_z_up_cm(src)
        before = Usd.Stage.Open(src)
        r = shenlong("edit", src, "put the vase on the table", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        after = Usd.Stage.Open(out)
        self.assertEqual(UsdGeom.GetStageUpAxis(after), UsdGeom.Tokens.z)
        self.assertAlmostEqual(UsdGeom.GetStageMetersPerUnit(after), 0.01)
        vlo, vhi = world_box(after, "/World/Vase")
        tlo, thi = world_box(after, "/World/Table")
        cm = TOL_M * 100
        # Its bottom on the table's top (z up), its centre over the table's footprint.
        self.assertLess(abs(vlo[2] - thi[2]), cm, (vlo, thi))
        cx, cy = (vlo[0] + vhi[0]) / 2, (vlo[1] + vhi[1]) / 2
        self.assertTrue(tlo[0] - cm <= cx <= thi[0] + cm and tlo[1] - cm <= cy <= thi[1] + cm)
        # Its size is its size.
        blo, bhi = world_box(before, "/World/Vase")
        for k in range(3):
            self.assertLess(abs((vhi[k] - vlo[k]) - (bhi[k] - blo[k])), cm)
        # Everything but the vase's transform is kept exactly.
        self.assertEqual(values(before, {"/World/Vase"}), values(after, {"/World/Vase"}))
        self.assertEqual(after.GetMetadata("comment"), before.GetMetadata("comment"))

    def test_z_up_centimetres_a_move_by_a_distance_under_a_turned_parent(self):
        src = os.path.join(self.dir, "room.usda")
        out = os.path.join(self.dir, "edited.usda")
        living_room_z_up_cm(src)
        before = Usd.Stage.Open(src)
        r = shenlong("edit", src, "move the shelf 50 cm to the right", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        after = Usd.Stage.Open(out)
        blo, bhi = world_box(before, "/World/Shelf")
        alo, ahi = world_box(after, "/World/Shelf")
        # Right is +x in both frames; 50 cm is 50 units of a centimetre stage.
        self.assertLess(abs((alo[0] - blo[0]) - 50.0), TOL_M * 100)
        self.assertLess(abs(alo[1] - blo[1]), TOL_M * 100)
        self.assertLess(abs(alo[2] - blo[2]), TOL_M * 100)
        self.assertEqual(values(before, {"/World/Shelf"}), values(after, {"/World/Shelf"}))

    def test_y_up_metres_usdc_in_usda_out(self):
        src = os.path.join(self.dir, "study.usdc")
        out = os.path.join(self.dir, "study_edited.usda")
        study_y_up_m(src)
        before = Usd.Stage.Open(src)
        r = shenlong("edit", src, "put the mug on the desk", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        after = Usd.Stage.Open(out)
        mlo, mhi = world_box(after, "/Mug")
        dlo, dhi = world_box(after, "/Desk")
        self.assertLess(abs(mlo[1] - dhi[1]), TOL_M, (mlo, dhi))
        self.assertEqual(values(before, {"/Mug"}), values(after, {"/Mug"}))
        # (Another file: usd-core keeps a layer it has opened, and would not see it change.)
        out2 = os.path.join(self.dir, "study_chair.usda")
        r = shenlong("edit", src, "move the chair 0.5 m forward", "-o", out2)
        self.assertEqual(r.returncode, 0, r.stderr)
        after = Usd.Stage.Open(out2)
        clo, _ = world_box(after, "/Chair")
        blo, _ = world_box(before, "/Chair")
        self.assertLess(abs((clo[2] - blo[2]) - 0.5), TOL_M)

    def test_the_edit_as_a_layer_over_the_input(self):
        src = os.path.join(self.dir, "room.usda")
        out = os.path.join(self.dir, "edit_layer.usda")
        living_room_z_up_cm(src)
        with open(src, "rb") as f:
            original = f.read()
        r = shenlong("edit", src, "move the lamp 1 m to the left", "-o", out, "--usd-layer")
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(src, "rb") as f:
            self.assertEqual(f.read(), original, "the input is never written")
        layer = Sdf.Layer.FindOrOpen(out)
        self.assertEqual(len(layer.subLayerPaths), 1)
        spec = layer.GetPrimAtPath("/World/Lamp")
        self.assertEqual(spec.specifier, Sdf.SpecifierOver)
        self.assertIsNone(layer.GetPrimAtPath("/World/Vase"), "only what moved is in the layer")
        before, after = Usd.Stage.Open(src), Usd.Stage.Open(out)
        blo, _ = world_box(before, "/World/Lamp")
        alo, _ = world_box(after, "/World/Lamp")
        self.assertLess(abs((alo[0] - blo[0]) + 100.0), TOL_M * 100)

    def test_a_refusal_writes_nothing(self):
        src = os.path.join(self.dir, "room.usda")
        out = os.path.join(self.dir, "never.usda")
        living_room_z_up_cm(src)
        r = shenlong("edit", src, "move the piano 1 m to the left", "-o", out)
        self.assertNotEqual(r.returncode, 0)
        self.assertEqual(len(r.stderr.strip().splitlines()), 1, r.stderr)
        self.assertFalse(os.path.exists(out))

    def test_convert_lists_the_objects_with_their_boxes_in_metres_y_up(self):
        src = os.path.join(self.dir, "room.usda")
        out = os.path.join(self.dir, "room.json")
        living_room_z_up_cm(src)
        r = shenlong("convert", src, out)
        self.assertEqual(r.returncode, 0, r.stderr)
        import json

        with open(out) as f:
            scene = json.load(f)
        names = sorted(o["name"] for o in scene["objects"])
        self.assertEqual(names, ["Lamp", "Shelf", "Table", "Vase"])
        vase = next(o for o in scene["objects"] if o["name"] == "Vase")
        # 20 cm cube centred at (200, 100, 10) cm, Z-up: Y-up metres (2, 0.1, -1).
        self.assertAlmostEqual(vase["size"][0], 0.2, places=6)
        self.assertAlmostEqual(vase["size"][1], 0.2, places=6)
        self.assertAlmostEqual(vase["position"][0], 2.0, places=6)
        self.assertAlmostEqual(vase["position"][2], -1.0, places=6)

    def test_component_models_are_the_objects(self):
        src = os.path.join(self.dir, "office.usda")
        out = os.path.join(self.dir, "office_edited.usda")
        stage = Usd.Stage.CreateNew(src)
        UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
        UsdGeom.SetStageMetersPerUnit(stage, 1.0)
        world = UsdGeom.Xform.Define(stage, "/World")
        stage.SetDefaultPrim(world.GetPrim())
        Usd.ModelAPI(world.GetPrim()).SetKind("assembly")
        group = UsdGeom.Xform.Define(stage, "/World/Furniture")
        Usd.ModelAPI(group.GetPrim()).SetKind("group")
        group.AddTranslateOp().Set(Gf.Vec3d(1.0, 0, 0))
        for name, x in (("Chair", -1.0), ("Desk", 1.0)):
            x_form = UsdGeom.Xform.Define(stage, f"/World/Furniture/{name}")
            Usd.ModelAPI(x_form.GetPrim()).SetKind("component")
            x_form.AddTranslateOp().Set(Gf.Vec3d(x, 0, 0))
            add_box_mesh(stage, f"/World/Furniture/{name}/Geo", (-0.3, 0, -0.3), (0.3, 0.8, 0.3))
        stage.GetRootLayer().Save()
        before = Usd.Stage.Open(src)
        r = shenlong("edit", src, "move the chair 0.5 m to the left", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        after = Usd.Stage.Open(out)
        blo, _ = world_box(before, "/World/Furniture/Chair")
        alo, _ = world_box(after, "/World/Furniture/Chair")
        self.assertLess(abs((alo[0] - blo[0]) + 0.5), TOL_M)
        self.assertEqual(
            values(before, {"/World/Furniture/Chair"}), values(after, {"/World/Furniture/Chair"})
        )

    def test_a_usdz_package_is_read_and_its_edit_written_as_usda(self):
        from pxr import UsdUtils

        src = os.path.join(self.dir, "room.usda")
        living_room_z_up_cm(src)
        pkg = os.path.join(self.dir, "room.usdz")
        self.assertTrue(UsdUtils.CreateNewUsdzPackage(Sdf.AssetPath(src), pkg))
        out = os.path.join(self.dir, "from_usdz.usda")
        r = shenlong("edit", pkg, "move the vase 30 cm to the right", "-o", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        before, after = Usd.Stage.Open(pkg), Usd.Stage.Open(out)
        blo, _ = world_box(before, "/World/Vase")
        alo, _ = world_box(after, "/World/Vase")
        self.assertLess(abs((alo[0] - blo[0]) - 30.0), TOL_M * 100)

    def test_a_scene_json_converts_to_a_stage_usd_core_reads(self):
        out = os.path.join(self.dir, "living_room.usda")
        r = shenlong("convert", "example:living_room", out)
        self.assertEqual(r.returncode, 0, r.stderr)
        stage = Usd.Stage.Open(out)
        self.assertEqual(UsdGeom.GetStageUpAxis(stage), UsdGeom.Tokens.y)
        lo, hi = world_box(stage, "/World/sofa")
        self.assertLess(abs((hi[0] - lo[0]) - 2.2), TOL_M)
        self.assertLess(abs(lo[1]), TOL_M)


if __name__ == "__main__":
    unittest.main()
