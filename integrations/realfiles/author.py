"""Author real-looking scene files the way real tools write them, with the formats' own
libraries only: Pixar's `usd-core` (pxr) for USD and `pygltflib` for glTF. Nothing here
writes a scene file's text by hand.

    python author.py OUT_DIR        # writes every file into OUT_DIR

Files (see README.md for what each imitates):

    blender_room.usda       Z-up centimetres, Blender-style Xform + Mesh pairs, materials
    omniverse_props.usda    Y-up metres, /World/Furniture and /World/Props groups, no kinds
    layered/shot.usda       sublayers ./set.usda, references ./props/chair.usda
    duplicates.usda         /World/GroupA/Chair and /World/GroupB/Chair, a table
    hierarchy.gltf (+.bin)  a Chair node with four mesh parts, a turned Table, a Cup on it
    cad_mm.glb              a CAD export in millimetres: floor, desk, monitor, chair

Every number that a test relies on is a module constant below, so the tests and the
files agree by construction.
"""

from __future__ import annotations

import math
import os
import struct
import sys

# ---------------------------------------------------------------------------------------
# Layout constants shared with the tests.
# ---------------------------------------------------------------------------------------

# blender_room.usda: Z-up, 1 unit = 1 cm. The room spans x in [-300, 300], y in [-250, 250].
ROOM_HALF_X = 300.0
ROOM_HALF_Y = 250.0
WALL_T = 10.0
WALL_H = 270.0
FLOOR_T = 2.0  # the Floor slab spans z in [-2, 0]: its top is the floor level, z = 0
BLENDER = {
    # name: (translate, rotate op, local boxes [(lo, hi)], material)
    "Sofa": ((0.0, 150.0, 0.0), ("xyz", (0, 0, 0)), "sofa", "Fabric_Grey"),
    "Coffee_Table": ((0.0, 40.0, 0.0), ("xyz", (0, 0, 0)), "coffee_table", "Oak"),
    "Vase": ((20.0, 40.0, 45.0), ("xyz", (0, 0, 0)), "vase", "Ceramic_White"),
    "Armchair": ((-180.0, -60.0, 0.0), ("z", -90.0), "armchair", "Fabric_Green"),
    "Side_Table": ((-180.0, 60.0, 0.0), ("xyz", (0, 0, 45)), "side_table", "Oak"),
    "Floor_Lamp": ((170.0, 195.0, 0.0), ("xyz", (0, 0, 0)), "floor_lamp", "Brass"),
    "Bed": ((150.0, -120.0, 0.0), ("xyz", (0, 0, 0)), "bed", "Linen"),
}
COFFEE_TABLE_TOP = 45.0
BLENDER_WALLS = ["Wall_North", "Wall_South", "Wall_East", "Wall_West"]

# omniverse_props.usda: Y-up metres.
OMNI_TABLE_TOP = 0.76
OMNI_SHELF_TOP = 1.2

# hierarchy.gltf: Y-up metres.
GLTF_TABLE_TOP = 0.75
GLTF_TABLE_YAW_DEG = 30.0

# cad_mm.glb: millimetres.
CAD_DESK_TOP = 750.0


def _box_points(lo, hi):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return [(x, y, z) for x in (x0, x1) for y in (y0, y1) for z in (z0, z1)]


# Quads of a box whose 8 points are ordered x-major (index = 4*ix + 2*iy + iz), outward
# and counter-clockwise (USD's default rightHanded orientation).
_BOX_QUADS = [
    (0, 1, 3, 2),  # -x
    (4, 6, 7, 5),  # +x
    (0, 4, 5, 1),  # -y
    (2, 3, 7, 6),  # +y
    (0, 2, 6, 4),  # -z
    (1, 5, 7, 3),  # +z
]


def _prism(cx, cy, r, z0, z1, sides, up="z"):
    """A closed n-sided prism (a mug, a vase, a lamp pole) as (points, quads/ngons)."""
    pts = []
    for k in range(sides):
        a = 2 * math.pi * k / sides
        u, v = cx + r * math.cos(a), cy + r * math.sin(a)
        for h in (z0, z1):
            pts.append((u, v, h) if up == "z" else (u, h, -v))
    faces = []
    for k in range(sides):
        a0, a1 = 2 * k, 2 * ((k + 1) % sides)
        faces.append((a0, a1, a1 + 1, a0 + 1))
    faces.append(tuple(2 * k for k in reversed(range(sides))))  # bottom
    faces.append(tuple(2 * k + 1 for k in range(sides)))  # top
    return pts, faces


# ---------------------------------------------------------------------------------------
# Geometry of the Blender room's objects, in each object's local space (Z-up, cm). Blender
# models face -Y: a sofa's or an armchair's back is at +Y, its seat front at -Y.
# ---------------------------------------------------------------------------------------


def _blender_parts(kind):
    """A list of parts; each is ('box', lo, hi) or ('prism', cx, cy, r, z0, z1, n)."""
    if kind == "sofa":
        return [
            ("box", (-100, -45, 0), (100, 45, 42)),  # base and seat
            ("box", (-100, 25, 42), (100, 45, 85)),  # back (at +Y: faces -Y)
            ("box", (-100, -45, 42), (-85, 25, 62)),  # arm
            ("box", (85, -45, 42), (100, 25, 62)),  # arm
        ]
    if kind == "coffee_table":
        parts = [("box", (-60, -35, 40), (60, 35, COFFEE_TABLE_TOP))]
        for sx in (-1, 1):
            for sy in (-1, 1):
                x, y = sx * 55, sy * 30
                parts.append(("box", (x - 3, y - 3, 0), (x + 3, y + 3, 40)))
        return parts
    if kind == "vase":
        return [("prism", 0, 0, 6, 0, 30, 8)]
    if kind == "armchair":
        return [
            ("box", (-40, -40, 0), (40, 40, 42)),
            ("box", (-40, 28, 42), (40, 40, 95)),  # back at local +Y: faces local -Y
            ("box", (-40, -40, 42), (-30, 28, 62)),
            ("box", (30, -40, 42), (40, 28, 62)),
        ]
    if kind == "side_table":
        return [
            ("box", (-25, -25, 52), (25, 25, 55)),
            ("prism", 0, 0, 4, 0, 52, 8),
        ]
    if kind == "floor_lamp":
        return [
            ("prism", 0, 0, 14, 0, 3, 12),  # base
            ("prism", 0, 0, 1.5, 3, 140, 8),  # pole
            ("prism", 0, 0, 20, 140, 170, 12),  # shade
        ]
    if kind == "bed":
        return [
            ("box", (-80, -100, 0), (80, 100, 50)),  # frame and mattress
            ("box", (-80, 92, 50), (80, 100, 110)),  # headboard at +Y
        ]
    raise ValueError(kind)


def _mesh_from_parts(parts):
    points, counts, indices = [], [], []
    for part in parts:
        base = len(points)
        if part[0] == "box":
            points += _box_points(part[1], part[2])
            faces = _BOX_QUADS
        else:
            pts, faces = _prism(*part[1:])
            points += pts
        for f in faces:
            counts.append(len(f))
            indices += [base + i for i in f]
    return points, counts, indices


def _define_mesh(stage, path, points, counts, indices, material=None):
    from pxr import Gf, UsdGeom, UsdShade, Vt

    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr(Vt.Vec3fArray([Gf.Vec3f(*p) for p in points]))
    mesh.CreateFaceVertexCountsAttr(Vt.IntArray(counts))
    mesh.CreateFaceVertexIndicesAttr(Vt.IntArray(indices))
    mesh.CreateExtentAttr(UsdGeom.PointBased.ComputeExtent(mesh.GetPointsAttr().Get()))
    mesh.CreateSubdivisionSchemeAttr(UsdGeom.Tokens.none)
    mesh.CreateDoubleSidedAttr(False)
    if material is not None:
        UsdShade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(material)
    return mesh


def _preview_material(stage, path, rgb, roughness=0.5, metallic=0.0, shader_name="Principled_BSDF"):
    from pxr import Gf, Sdf, UsdShade

    mat = UsdShade.Material.Define(stage, path)
    shader = UsdShade.Shader.Define(stage, f"{path}/{shader_name}")
    shader.CreateIdAttr("UsdPreviewSurface")
    shader.CreateInput("diffuseColor", Sdf.ValueTypeNames.Color3f).Set(Gf.Vec3f(*rgb))
    shader.CreateInput("roughness", Sdf.ValueTypeNames.Float).Set(roughness)
    shader.CreateInput("metallic", Sdf.ValueTypeNames.Float).Set(metallic)
    shader.CreateInput("ior", Sdf.ValueTypeNames.Float).Set(1.45)
    mat.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
    return mat


# ---------------------------------------------------------------------------------------
# a. blender_room.usda
# ---------------------------------------------------------------------------------------


def blender_room(folder: str) -> str:
    """Like Blender 4.x's USD export of a living room modelled in centimetres (scene unit
    scale 0.01): /root holds one Xform per object with its mesh data as a Mesh child, the
    Xform carrying translate / rotateXYZ / scale (the armchair was rotated -90 about Z in a
    tool that writes rotateZ), materials under /root/_materials bound to the meshes."""
    from pxr import Gf, Sdf, Usd, UsdGeom, Vt

    path = os.path.join(folder, "blender_room.usda")
    stage = Usd.Stage.CreateNew(path)
    stage.GetRootLayer().documentation = "Blender v4.2.3"
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 0.01)
    stage.SetStartTimeCode(1)
    stage.SetEndTimeCode(250)
    root = UsdGeom.Xform.Define(stage, "/root")
    root.GetPrim().SetCustomDataByKey("Blender:generated", True)
    stage.SetDefaultPrim(root.GetPrim())

    UsdGeom.Scope.Define(stage, "/root/_materials")
    mats = {}
    for name, rgb, rough, metal in [
        ("Fabric_Grey", (0.35, 0.35, 0.37), 0.9, 0.0),
        ("Fabric_Green", (0.18, 0.32, 0.2), 0.9, 0.0),
        ("Oak", (0.55, 0.38, 0.22), 0.6, 0.0),
        ("Ceramic_White", (0.92, 0.92, 0.9), 0.2, 0.0),
        ("Brass", (0.8, 0.6, 0.3), 0.3, 1.0),
        ("Linen", (0.85, 0.82, 0.75), 0.8, 0.0),
        ("Plaster", (0.9, 0.9, 0.88), 0.95, 0.0),
        ("Floorboards", (0.45, 0.3, 0.18), 0.5, 0.0),
    ]:
        mats[name] = _preview_material(stage, f"/root/_materials/{name}", rgb, rough, metal)

    def blender_xform(name, translate, rot):
        xf = UsdGeom.Xform.Define(stage, f"/root/{name}")
        xf.GetPrim().CreateAttribute(
            "userProperties:blender:object_name", Sdf.ValueTypeNames.String
        ).Set(name)
        xf.AddTranslateOp().Set(Gf.Vec3d(*translate))
        if rot[0] == "z":
            xf.AddRotateZOp().Set(float(rot[1]))
        else:
            xf.AddRotateXYZOp().Set(Gf.Vec3f(*rot[1]))
        xf.AddScaleOp().Set(Gf.Vec3f(1, 1, 1))
        return xf

    # The room: a floor slab with its top at z = 0, four walls standing on it.
    hx, hy, t = ROOM_HALF_X, ROOM_HALF_Y, WALL_T
    blender_xform("Floor", (0, 0, 0), ("xyz", (0, 0, 0)))
    pts, counts, idx = _mesh_from_parts([("box", (-hx - t, -hy - t, -FLOOR_T), (hx + t, hy + t, 0))])
    _define_mesh(stage, "/root/Floor/Plane", pts, counts, idx, mats["Floorboards"])
    walls = {
        # name: (centre, half extents): thin tall slabs just outside the room's boundary
        "Wall_North": ((0, hy + t / 2), (hx + t, t / 2)),
        "Wall_South": ((0, -hy - t / 2), (hx + t, t / 2)),
        "Wall_East": ((hx + t / 2, 0), (t / 2, hy)),
        "Wall_West": ((-hx - t / 2, 0), (t / 2, hy)),
    }
    for i, name in enumerate(BLENDER_WALLS):
        (cx, cy), (ex, ey) = walls[name]
        blender_xform(name, (cx, cy, 0), ("xyz", (0, 0, 0)))
        pts, counts, idx = _mesh_from_parts([("box", (-ex, -ey, 0), (ex, ey, WALL_H))])
        _define_mesh(stage, f"/root/{name}/Cube_{i + 1:03d}", pts, counts, idx, mats["Plaster"])

    for name, (translate, rot, kind, mat) in BLENDER.items():
        blender_xform(name, translate, rot)
        pts, counts, idx = _mesh_from_parts(_blender_parts(kind))
        # Blender names the Mesh prim after the mesh data block.
        _define_mesh(stage, f"/root/{name}/{name}_Mesh", pts, counts, idx, mats[mat])

    # Blender also exports its camera and the default light (no geometry: no objects).
    cam = UsdGeom.Camera.Define(stage, "/root/Camera")
    cam.AddTranslateOp().Set(Gf.Vec3d(0, -600, 160))
    cam.AddRotateXYZOp().Set(Gf.Vec3f(80, 0, 0))
    cam.AddScaleOp().Set(Gf.Vec3f(1, 1, 1))
    cam.CreateFocalLengthAttr(50.0)
    from pxr import UsdLux

    light = UsdLux.SphereLight.Define(stage, "/root/Light")
    light.AddTranslateOp().Set(Gf.Vec3d(0, 0, 250))
    light.CreateIntensityAttr(318.3)
    light.CreateRadiusAttr(10.0)
    stage.GetRootLayer().Save()
    return path


# ---------------------------------------------------------------------------------------
# b. omniverse_props.usda
# ---------------------------------------------------------------------------------------


def omniverse_props(folder: str) -> str:
    """Like a stage laid out in Omniverse Kit / USD Composer: Y-up metres, /World the default
    prim, furniture and props in plain Xform groups (no model kinds), double-precision
    translate / orient / scale ops, materials in /World/Looks, a distant light."""
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdLux

    path = os.path.join(folder, "omniverse_props.usda")
    stage = Usd.Stage.CreateNew(path)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    stage.SetTimeCodesPerSecond(60)
    stage.GetRootLayer().customLayerData = {
        "cameraSettings": {"boundCamera": "/OmniverseKit_Persp"},
        "renderSettings": {"rtx:directLighting:sampledLighting:enabled": True},
    }
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())

    UsdGeom.Scope.Define(stage, "/World/Looks")
    looks = {
        "Walnut": _preview_material(stage, "/World/Looks/Walnut", (0.3, 0.18, 0.1), shader_name="Shader"),
        "Ceramic": _preview_material(stage, "/World/Looks/Ceramic", (0.9, 0.9, 0.92), 0.2, shader_name="Shader"),
        "Paper": _preview_material(stage, "/World/Looks/Paper", (0.8, 0.1, 0.1), 0.8, shader_name="Shader"),
    }

    def kit_xform(path, t, orient=(1, 0, 0, 0)):
        xf = UsdGeom.Xform.Define(stage, path)
        xf.AddTranslateOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(*t))
        xf.AddOrientOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Quatd(*orient))
        xf.AddScaleOp(UsdGeom.XformOp.PrecisionDouble).Set(Gf.Vec3d(1, 1, 1))
        return xf

    def box(path, lo, hi, mat):
        pts, counts, idx = _mesh_from_parts([("box", lo, hi)])
        return _define_mesh(stage, path, pts, counts, idx, looks[mat])

    UsdGeom.Xform.Define(stage, "/World/Furniture")
    UsdGeom.Xform.Define(stage, "/World/Props")

    # The table: one Xform holding five meshes (top and four legs).
    top = OMNI_TABLE_TOP
    kit_xform("/World/Furniture/Table", (0, 0, 0))
    box("/World/Furniture/Table/Top", (-0.7, top - 0.04, -0.4), (0.7, top, 0.4), "Walnut")
    for name, (x, z) in {
        "Leg_FL": (-0.64, 0.34),
        "Leg_FR": (0.64, 0.34),
        "Leg_BL": (-0.64, -0.34),
        "Leg_BR": (0.64, -0.34),
    }.items():
        box(f"/World/Furniture/Table/{name}", (x - 0.03, 0, z - 0.03), (x + 0.03, top - 0.04, z + 0.03), "Walnut")

    # The chair, drawn up to the table's front (+Z), facing it would be -Z; it faces +Z
    # here (pulled out, as a model faces by default).
    kit_xform("/World/Furniture/Chair", (0, 0, 0.75))
    box("/World/Furniture/Chair/Seat", (-0.22, 0.42, -0.22), (0.22, 0.46, 0.22), "Walnut")
    box("/World/Furniture/Chair/Back", (-0.22, 0.46, -0.22), (0.22, 0.9, -0.19), "Walnut")
    box("/World/Furniture/Chair/Legs", (-0.2, 0, -0.2), (0.2, 0.42, 0.2), "Walnut")

    # A low shelf against the back-left, 1.2 m tall: sides and three boards.
    kit_xform("/World/Furniture/Shelf", (-2.0, 0, -1.5))
    box("/World/Furniture/Shelf/Side_L", (-0.4, 0, -0.175), (-0.38, OMNI_SHELF_TOP, 0.175), "Walnut")
    box("/World/Furniture/Shelf/Side_R", (0.38, 0, -0.175), (0.4, OMNI_SHELF_TOP, 0.175), "Walnut")
    for i, y in enumerate((0.0, 0.58, OMNI_SHELF_TOP - 0.02)):
        box(f"/World/Furniture/Shelf/Board_{i}", (-0.38, y, -0.175), (0.38, y + 0.02, 0.175), "Walnut")

    # Props: the mug and the vase stand on the table top, the book lies on the shelf's top.
    kit_xform("/World/Props/Mug", (0.25, top, 0.1))
    pts, faces = _prism(0, 0, 0.045, 0.0, 0.1, 12, up="y")
    counts, idx = [len(f) for f in faces], [i for f in faces for i in f]
    _define_mesh(stage, "/World/Props/Mug/Body", pts, counts, idx, looks["Ceramic"])
    box("/World/Props/Mug/Handle", (0.045, 0.02, -0.008), (0.075, 0.08, 0.008), "Ceramic")

    kit_xform("/World/Props/Vase", (-0.3, top, -0.1))
    pts, faces = _prism(0, 0, 0.07, 0.0, 0.32, 16, up="y")
    counts, idx = [len(f) for f in faces], [i for f in faces for i in f]
    _define_mesh(stage, "/World/Props/Vase/Vase_geo", pts, counts, idx, looks["Ceramic"])

    # The book lies on the shelf's top, turned 20 degrees about Y (orient quaternion).
    a = math.radians(20) / 2
    kit_xform("/World/Props/Book", (-2.05, OMNI_SHELF_TOP, -1.5), (math.cos(a), 0, math.sin(a), 0))
    box("/World/Props/Book/Cover", (-0.11, 0, -0.15), (0.11, 0.035, 0.15), "Paper")

    light = UsdLux.DistantLight.Define(stage, "/World/DistantLight")
    light.CreateIntensityAttr(3000.0)
    light.CreateAngleAttr(1.0)
    xf = UsdGeom.Xformable(light.GetPrim())
    xf.AddRotateXYZOp().Set(Gf.Vec3f(-45, 30, 0))
    stage.GetRootLayer().Save()
    return path


# ---------------------------------------------------------------------------------------
# c. layered/: shot.usda sublayers set.usda and references props/chair.usda
# ---------------------------------------------------------------------------------------


def layered(folder: str) -> str:
    """A shot as a pipeline composes it: the shot's root layer sublayers the set and places
    an asset (the chair) by reference, with the asset in its own file in props/."""
    from pxr import Gf, Kind, Sdf, Usd, UsdGeom

    base = os.path.join(folder, "layered")
    os.makedirs(os.path.join(base, "props"), exist_ok=True)

    def box(stage, path, lo, hi):
        pts, counts, idx = _mesh_from_parts([("box", lo, hi)])
        return _define_mesh(stage, path, pts, counts, idx)

    # The asset: its own default prim, in its own space.
    chair_path = os.path.join(base, "props", "chair.usda")
    chair = Usd.Stage.CreateNew(chair_path)
    UsdGeom.SetStageUpAxis(chair, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(chair, 1.0)
    c = UsdGeom.Xform.Define(chair, "/Chair")
    chair.SetDefaultPrim(c.GetPrim())
    UsdGeom.Scope.Define(chair, "/Chair/Geom")
    box(chair, "/Chair/Geom/Seat", (-0.23, 0.42, -0.23), (0.23, 0.46, 0.23))
    box(chair, "/Chair/Geom/Back", (-0.23, 0.46, -0.23), (0.23, 0.92, -0.2))
    box(chair, "/Chair/Geom/Frame", (-0.21, 0, -0.21), (0.21, 0.42, 0.21))
    chair.GetRootLayer().Save()

    # The set: the room's furniture.
    set_path = os.path.join(base, "set.usda")
    st = Usd.Stage.CreateNew(set_path)
    UsdGeom.SetStageUpAxis(st, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(st, 1.0)
    w = UsdGeom.Xform.Define(st, "/World")
    st.SetDefaultPrim(w.GetPrim())
    t = UsdGeom.Xform.Define(st, "/World/Table")
    t.AddTranslateOp().Set(Gf.Vec3d(0, 0, 0))
    box(st, "/World/Table/Top", (-0.8, 0.72, -0.45), (0.8, 0.76, 0.45))
    box(st, "/World/Table/Base", (-0.7, 0, -0.35), (0.7, 0.72, 0.35))
    lamp = UsdGeom.Xform.Define(st, "/World/Lamp")
    lamp.AddTranslateOp().Set(Gf.Vec3d(-2.0, 0, -1.0))
    pts, faces = _prism(0, 0, 0.15, 0.0, 1.6, 12, up="y")
    _define_mesh(st, "/World/Lamp/Body", pts, [len(f) for f in faces], [i for f in faces for i in f])
    st.GetRootLayer().Save()

    # The shot: sublayers the set, places the chair by reference.
    shot_path = os.path.join(base, "shot.usda")
    shot = Usd.Stage.CreateNew(shot_path)
    shot.GetRootLayer().subLayerPaths.append("./set.usda")
    UsdGeom.SetStageUpAxis(shot, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(shot, 1.0)
    shot.GetRootLayer().defaultPrim = "World"
    ch = UsdGeom.Xform.Define(shot, "/World/Chair")
    ch.GetPrim().GetReferences().AddReference("./props/chair.usda")
    ch.AddTranslateOp().Set(Gf.Vec3d(1.3, 0, 0.2))
    ch.AddRotateYOp().Set(-90.0)
    shot.GetRootLayer().Save()
    return shot_path


# ---------------------------------------------------------------------------------------
# d. duplicates.usda
# ---------------------------------------------------------------------------------------


def duplicates(folder: str) -> str:
    """An assembly with two groups that each hold a 'Chair' (the same asset placed twice,
    as layout tools name it), plus a table; models are marked with kinds, as in a Pixar-
    style pipeline (assembly / group / component)."""
    from pxr import Gf, Kind, Usd, UsdGeom

    path = os.path.join(folder, "duplicates.usda")
    stage = Usd.Stage.CreateNew(path)
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.y)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    world = UsdGeom.Xform.Define(stage, "/World")
    stage.SetDefaultPrim(world.GetPrim())
    Usd.ModelAPI(world.GetPrim()).SetKind(Kind.Tokens.assembly)

    def box(p, lo, hi):
        pts, counts, idx = _mesh_from_parts([("box", lo, hi)])
        return _define_mesh(stage, p, pts, counts, idx)

    for group, x in (("GroupA", -1.5), ("GroupB", 1.5)):
        g = UsdGeom.Xform.Define(stage, f"/World/{group}")
        Usd.ModelAPI(g.GetPrim()).SetKind(Kind.Tokens.group)
        g.AddTranslateOp().Set(Gf.Vec3d(x, 0, 0))
        c = UsdGeom.Xform.Define(stage, f"/World/{group}/Chair")
        Usd.ModelAPI(c.GetPrim()).SetKind(Kind.Tokens.component)
        c.AddTranslateOp().Set(Gf.Vec3d(0, 0, 0.5))
        box(f"/World/{group}/Chair/Seat", (-0.22, 0.42, -0.22), (0.22, 0.46, 0.22))
        box(f"/World/{group}/Chair/Back", (-0.22, 0.46, -0.22), (0.22, 0.9, -0.19))
        box(f"/World/{group}/Chair/Frame", (-0.2, 0, -0.2), (0.2, 0.42, 0.2))
    t = UsdGeom.Xform.Define(stage, "/World/Table")
    Usd.ModelAPI(t.GetPrim()).SetKind(Kind.Tokens.component)
    t.AddTranslateOp().Set(Gf.Vec3d(0, 0, -1.0))
    box("/World/Table/Top", (-0.6, 0.71, -0.4), (0.6, 0.75, 0.4))
    box("/World/Table/Base", (-0.5, 0, -0.3), (0.5, 0.71, 0.3))
    stage.GetRootLayer().Save()
    return path


# ---------------------------------------------------------------------------------------
# glTF with pygltflib
# ---------------------------------------------------------------------------------------


def _tri_box(lo, hi):
    """12 outward counter-clockwise triangles of a box."""
    p = _box_points(lo, hi)
    tris = []
    for a, b, c, d in _BOX_QUADS:
        tris += [(p[a], p[b], p[c]), (p[a], p[c], p[d])]
    return tris


def _tri_prism_y(r, y0, y1, sides, cx=0.0, cz=0.0):
    tris = []
    for k in range(sides):
        a0 = 2 * math.pi * k / sides
        a1 = 2 * math.pi * (k + 1) / sides
        p0 = (cx + r * math.cos(a0), cz - r * math.sin(a0))
        p1 = (cx + r * math.cos(a1), cz - r * math.sin(a1))
        b0, b1 = (p0[0], y0, p0[1]), (p1[0], y0, p1[1])
        t0, t1 = (p0[0], y1, p0[1]), (p1[0], y1, p1[1])
        tris += [(b0, b1, t1), (b0, t1, t0)]
        tris.append(((cx, y1, cz), t0, t1))
        tris.append(((cx, y0, cz), b1, b0))
    return tris


class _GltfBuilder:
    def __init__(self, generator):
        import pygltflib as g

        self.g = g
        self.gltf = g.GLTF2(asset=g.Asset(version="2.0", generator=generator))
        self.blob = bytearray()

    def _view(self, data: bytes, target):
        while len(self.blob) % 4:
            self.blob.append(0)
        view = self.g.BufferView(buffer=0, byteOffset=len(self.blob), byteLength=len(data), target=target)
        self.blob += data
        self.gltf.bufferViews.append(view)
        return len(self.gltf.bufferViews) - 1

    def material(self, name, rgb, metallic=0.0, roughness=0.6):
        g = self.g
        self.gltf.materials.append(
            g.Material(
                name=name,
                pbrMetallicRoughness=g.PbrMetallicRoughness(
                    baseColorFactor=[*rgb, 1.0], metallicFactor=metallic, roughnessFactor=roughness
                ),
            )
        )
        return len(self.gltf.materials) - 1

    def mesh(self, name, tris, material):
        g = self.g
        pos, nrm = [], []
        for a, b, c in tris:
            u = [b[i] - a[i] for i in range(3)]
            v = [c[i] - a[i] for i in range(3)]
            n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
            ln = math.sqrt(sum(x * x for x in n)) or 1.0
            n = [x / ln for x in n]
            for p in (a, b, c):
                pos.append(p)
                nrm.append(n)
        count = len(pos)
        pbytes = b"".join(struct.pack("<3f", *p) for p in pos)
        nbytes = b"".join(struct.pack("<3f", *n) for n in nrm)
        ibytes = b"".join(struct.pack("<H", i) for i in range(count))
        f32 = [struct.unpack("<f", struct.pack("<f", x))[0] for p in pos for x in p]
        xs, ys, zs = f32[0::3], f32[1::3], f32[2::3]
        pv = self._view(pbytes, g.ARRAY_BUFFER)
        self.gltf.accessors.append(
            g.Accessor(
                bufferView=pv, componentType=g.FLOAT, count=count, type=g.VEC3,
                min=[min(xs), min(ys), min(zs)], max=[max(xs), max(ys), max(zs)],
            )
        )
        pa = len(self.gltf.accessors) - 1
        nv = self._view(nbytes, g.ARRAY_BUFFER)
        self.gltf.accessors.append(g.Accessor(bufferView=nv, componentType=g.FLOAT, count=count, type=g.VEC3))
        na = len(self.gltf.accessors) - 1
        iv = self._view(ibytes, g.ELEMENT_ARRAY_BUFFER)
        self.gltf.accessors.append(
            g.Accessor(bufferView=iv, componentType=g.UNSIGNED_SHORT, count=count, type=g.SCALAR)
        )
        ia = len(self.gltf.accessors) - 1
        self.gltf.meshes.append(
            g.Mesh(
                name=name,
                primitives=[
                    g.Primitive(attributes=g.Attributes(POSITION=pa, NORMAL=na), indices=ia, material=material)
                ],
            )
        )
        return len(self.gltf.meshes) - 1

    def node(self, name, mesh=None, translation=None, rotation=None, scale=None, children=None):
        n = self.g.Node(name=name)
        if mesh is not None:
            n.mesh = mesh
        if translation is not None:
            n.translation = list(translation)
        if rotation is not None:
            n.rotation = list(rotation)
        if scale is not None:
            n.scale = list(scale)
        if children:
            n.children = list(children)
        self.gltf.nodes.append(n)
        return len(self.gltf.nodes) - 1

    def finish(self, roots, scene_name="Scene"):
        g = self.g
        while len(self.blob) % 4:
            self.blob.append(0)
        self.gltf.scenes.append(g.Scene(name=scene_name, nodes=list(roots)))
        self.gltf.scene = 0
        return bytes(self.blob)


def hierarchy_gltf(folder: str) -> str:
    """A glTF with a node hierarchy as exporters write one: a 'Chair' empty with four mesh
    parts that together are one chair (turned to face the table), a 'Table' turned 30
    degrees about +Y by a quaternion, a 'Cup' resting on the table's top (a root node of
    its own), and a 'Floor'. Y-up metres; models face +Z. External buffer hierarchy.bin."""
    b = _GltfBuilder("Khronos glTF Blender I/O v4.2.70 (imitated with pygltflib)")
    wood = b.material("Wood_Oak", (0.55, 0.38, 0.22))
    ceramic = b.material("Ceramic_Blue", (0.2, 0.3, 0.8), roughness=0.2)
    floorm = b.material("Floor_Tiles", (0.7, 0.7, 0.7))

    floor = b.node("Floor", b.mesh("Floor", _tri_box((-3, -0.02, -2.5), (3, 0, 2.5)), floorm))

    top = GLTF_TABLE_TOP
    table_tris = _tri_box((-0.6, top - 0.04, -0.4), (0.6, top, 0.4))
    for x in (-0.55, 0.55):
        for z in (-0.35, 0.35):
            table_tris += _tri_box((x - 0.025, 0, z - 0.025), (x + 0.025, top - 0.04, z + 0.025))
    h = math.radians(GLTF_TABLE_YAW_DEG) / 2
    table = b.node("Table", b.mesh("DiningTable", table_tris, wood), rotation=(0, math.sin(h), 0, math.cos(h)))

    cup = b.node("Cup", b.mesh("Cup", _tri_prism_y(0.04, 0.0, 0.09, 12), ceramic), translation=(0.1, top, 0.05))

    seat = b.node("Seat", b.mesh("Chair_Seat", _tri_box((-0.22, -0.025, -0.22), (0.22, 0.025, 0.22)), wood),
                  translation=(0, 0.445, 0))
    back = b.node("Back", b.mesh("Chair_Back", _tri_box((-0.22, -0.24, -0.02), (0.22, 0.24, 0.02)), wood),
                  translation=(0, 0.71, -0.2))
    leg_l = b.node("Leg_L", b.mesh("Chair_Leg", _tri_box((-0.02, -0.21, -0.22), (0.02, 0.21, 0.22)), wood),
                   translation=(-0.2, 0.21, 0))
    # Both legs share one mesh, as exporters write instanced data.
    leg_r = b.node("Leg_R", b.gltf.nodes[leg_l].mesh, translation=(0.2, 0.21, 0))
    chair = b.node("Chair", translation=(0, 0, 1.0), rotation=(0, 1, 0, 0), children=[seat, back, leg_l, leg_r])

    blob = b.finish([floor, table, cup, chair])
    g = b.g
    b.gltf.buffers.append(g.Buffer(byteLength=len(blob), uri="hierarchy.bin"))
    path = os.path.join(folder, "hierarchy.gltf")
    with open(os.path.join(folder, "hierarchy.bin"), "wb") as f:
        f.write(blob)
    b.gltf.save_json(path)
    return path


def cad_mm_glb(folder: str) -> str:
    """A CAD export in millimetres (no unit scale on any node, as many CAD exporters write):
    a room 4000 units wide with a desk 1200 units wide, a monitor standing on it, a chair."""
    b = _GltfBuilder("CAD glTF exporter (imitated with pygltflib)")
    grey = b.material("Concrete", (0.6, 0.6, 0.6))
    lam = b.material("Laminate_White", (0.95, 0.95, 0.95))
    black = b.material("Plastic_Black", (0.05, 0.05, 0.05), roughness=0.3)

    floor = b.node("Floor", b.mesh("Floor", _tri_box((-2000, -20, -1500), (2000, 0, 1500)), grey))
    top = CAD_DESK_TOP
    desk_tris = _tri_box((-600, top - 30, -350), (600, top, 350))
    desk_tris += _tri_box((-600, 0, -350), (-570, top - 30, 350))
    desk_tris += _tri_box((570, 0, -350), (600, top - 30, 350))
    desk = b.node("Desk", b.mesh("Desk", desk_tris, lam), translation=(0, 0, -1000))
    mon_tris = _tri_box((-120, 0, -100), (120, 15, 100))
    mon_tris += _tri_box((-20, 15, -20), (20, 120, 20))
    mon_tris += _tri_box((-310, 120, -10), (310, 480, 20))
    monitor = b.node("Monitor", b.mesh("Monitor", mon_tris, black), translation=(0, top, -1100))
    chair_tris = _tri_box((-250, 0, -250), (250, 480, 250)) + _tri_box((-250, 480, 200), (250, 1000, 250))
    chair = b.node("Chair", b.mesh("OfficeChair", chair_tris, black), translation=(0, 0, -200),
                   rotation=(0, 1, 0, 0))
    blob = b.finish([floor, desk, monitor, chair])
    g = b.g
    b.gltf.buffers.append(g.Buffer(byteLength=len(blob)))
    b.gltf.set_binary_blob(blob)
    path = os.path.join(folder, "cad_mm.glb")
    b.gltf.save_binary(path)
    return path


def author_all(folder: str) -> dict:
    os.makedirs(folder, exist_ok=True)
    return {
        "blender_room": blender_room(folder),
        "omniverse_props": omniverse_props(folder),
        "layered": layered(folder),
        "duplicates": duplicates(folder),
        "hierarchy": hierarchy_gltf(folder),
        "cad_mm": cad_mm_glb(folder),
    }


if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else "realfiles_out"
    for k, v in author_all(out).items():
        print(f"{k}: {v}")
