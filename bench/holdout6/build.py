#!/usr/bin/env python3
"""Generate the holdout6 scenes, suite and hand-worked answers (stdlib only).

Writes exam_hall.json, tavern.json, blender_export.json, clinic_ward.json (scenes),
holdout6.suite.json (the suite) and holdout6.answers.json (per non-refusal query, the
hand-worked edit per object: translation "t" in metres, "yaw" in degrees, scale factor "s";
used only by validate.py).

Conventions (SPEC sections 1-2): metres, +Y up, pivot at the bottom centre of each box,
yaw-only rotations as [x, y, z, w] quaternions, `bounds` = the room; right = +X,
forward = +Z, "clockwise" = negative yaw seen from above.

Run: python3 build.py && python3 validate.py
"""
import json
import math
import os


def yawq(deg):
    """Quaternion [x, y, z, w] for a rotation of `deg` degrees about +Y."""
    h = math.radians(deg) / 2.0
    return [0.0, round(math.sin(h), 9), 0.0, round(math.cos(h), 9)]


def obj(name, size, pos, yaw=0.0):
    o = {"name": name, "position": [round(v, 6) for v in pos], "size": list(size),
         "rotation": yawq(yaw) if yaw else [0, 0, 0, 1], "scale": 1.0}
    return o


# ---------------------------------------------------------------- exam hall
def exam_hall():
    objs = []
    cols = [-4.4, -2.2, 0.0, 2.2, 4.4]
    rows = [3.0, 1.2, -0.6, -2.4]          # row 1 (front, nearest the board) .. row 4 (back)
    for n in range(1, 21):
        r, c = (n - 1) // 5, (n - 1) % 5
        x, z = cols[c], rows[r]
        objs.append(obj(f"Desk {n}", [0.9, 0.75, 0.6], [x, 0, z]))
        objs.append(obj(f"Chair {n}", [0.45, 0.85, 0.45], [x, 0, z - 0.645]))
    objs += [
        obj("Invigilator Desk", [1.6, 0.75, 0.8], [0, 0, 4.6]),
        obj("Invigilator Chair", [0.55, 0.95, 0.55], [0, 0, 5.4], 180),
        obj("Whiteboard", [3.0, 1.2, 0.04], [0, 0.9, 5.98]),
        obj("Wall Clock", [0.35, 0.35, 0.04], [3.2, 2.4, 5.98]),
        obj("Desk Lamp", [0.2, 0.45, 0.2], [-0.6, 0.75, 4.75]),
        obj("Exam Papers", [0.3, 0.08, 0.22], [0.05, 0.75, 4.5]),
        obj("Hand Bell", [0.1, 0.12, 0.1], [0.55, 0.75, 4.35]),
        obj("Water Bottle", [0.07, 0.22, 0.07], [0.3, 0.75, 3.1]),
        obj("Calculator", [0.08, 0.02, 0.15], [-2.45, 0.75, 1.2]),
        obj("Pencil Case", [0.2, 0.06, 0.08], [-2.0, 0.75, 1.25]),
        obj("Dictionary", [0.16, 0.05, 0.23], [-2.2, 0.75, -0.55]),
        obj("Glasses Case", [0.16, 0.04, 0.06], [2.1, 0.75, -0.6]),
        obj("Coffee Cup", [0.09, 0.11, 0.09], [4.6, 0.75, -2.3]),
        obj("Backpack", [0.32, 0.45, 0.22], [3.0, 0, -0.25]),
        obj("Waste Bin", [0.35, 0.5, 0.35], [-6.5, 0, 5.5]),
        obj("Recycling Bin", [0.4, 0.6, 0.4], [-5.9, 0, 5.5]),
        obj("Coat Rack", [0.5, 1.8, 0.5], [-6.5, 0, -5.5]),
        obj("Notice Board", [0.03, 1.0, 1.6], [-6.985, 1.1, 0.0]),
        obj("Radiator", [0.1, 0.6, 1.4], [6.95, 0.15, 0.5]),
        obj("Door", [1.0, 2.1, 0.06], [5.5, 0, -5.97]),
        obj("Exit Sign", [0.4, 0.15, 0.03], [5.5, 2.4, -5.985]),
        obj("Supply Cart", [0.8, 0.9, 0.5], [-6.2, 0, 2.8]),
        obj("Box of Pencils", [0.25, 0.08, 0.15], [-6.4, 0.9, 2.8]),
        obj("Tissue Box", [0.24, 0.1, 0.12], [-6.0, 0.9, 2.8]),
        obj("Stack of Chairs", [0.5, 1.4, 0.5], [6.3, 0, -4.8]),
    ]
    return {"name": "exam_hall",
            "bounds": {"min": [-7, 0, -6], "max": [7, 3.5, 6]},
            "objects": objs}


# ---------------------------------------------------------------- tavern (game engine names)
def tavern():
    objs = [
        obj("SM_Bar_Counter", [4.0, 1.1, 0.7], [-1.0, 0, -4.0]),
        obj("SM_Shelf_Wall_01", [2.4, 0.04, 0.3], [-1.0, 1.6, -4.85]),
        obj("Prop_Bottle_01", [0.08, 0.3, 0.08], [-2.0, 1.64, -4.85]),
        obj("Prop_Bottle_02", [0.08, 0.3, 0.08], [-1.0 + 0.25, 1.64, -4.85]),
        obj("Prop_Bottle_03", [0.08, 0.3, 0.08], [0.0, 1.64, -4.85]),
        obj("BP_Tap_Beer", [0.3, 0.45, 0.15], [-1.0, 1.1, -4.15]),
        obj("Prop_Mug_A", [0.1, 0.12, 0.1], [-2.4, 1.1, -3.9]),
        obj("Prop_Mug_B", [0.1, 0.12, 0.1], [0.4, 1.1, -3.85]),
    ]
    for i, x in enumerate([-2.6, -1.8, -1.0, -0.2, 0.6], 1):
        objs.append(obj(f"SM_Stool_0{i}", [0.4, 0.75, 0.4], [x, 0, -3.2]))
    objs += [
        obj("SM_Barrel_01", [0.6, 0.9, 0.6], [5.3, 0, -4.3]),
        obj("SM_Barrel_02", [0.6, 0.9, 0.6], [4.6, 0, -4.3]),
        obj("SM_Barrel_03", [0.6, 0.9, 0.6], [5.3, 0, -3.6]),
        obj("Prop_Candle_01", [0.08, 0.2, 0.08], [5.3, 0.9, -4.3]),
        obj("SM_Crate_01", [0.5, 0.5, 0.5], [5.4, 0, -2.5]),
        obj("SM_Crate_02", [0.4, 0.4, 0.4], [5.4, 0.5, -2.5]),
    ]
    # two round tables, four chairs each, every chair facing its table
    k = 1
    for t, (tx, tz) in enumerate([(-3.0, 0.0), (0.5, 0.0)], 1):
        objs.append(obj(f"Table_Round_0{t}", [0.9, 0.75, 0.9], [tx, 0, tz]))
        for dx, dz, yaw in [(0, -0.775, 0), (0, 0.775, 180), (-0.775, 0, 90), (0.775, 0, -90)]:
            objs.append(obj(f"SM_Chair_0{k}", [0.45, 0.9, 0.45], [tx + dx, 0, tz + dz], yaw))
            k += 1
    objs += [
        obj("Prop_Candle_03", [0.08, 0.2, 0.08], [-3.0, 0.75, 0.0]),
        obj("Prop_Mug_D", [0.1, 0.12, 0.1], [-2.75, 0.75, 0.2]),
        obj("Prop_Cards_Deck", [0.07, 0.02, 0.1], [0.35, 0.75, -0.1]),
        obj("Prop_Goblet_01", [0.12, 0.18, 0.12], [0.7, 0.75, 0.2]),
        obj("Table_Long_Oak", [2.4, 0.75, 0.9], [3.8, 0, 1.0]),
        obj("SM_Bench_01", [2.0, 0.45, 0.35], [3.8, 0, 0.2]),
        obj("SM_Bench_02", [2.0, 0.45, 0.35], [3.8, 0, 1.8]),
        obj("Prop_Plate_01", [0.25, 0.02, 0.25], [3.2, 0.75, 1.0]),
        obj("Prop_Plate_02", [0.25, 0.02, 0.25], [4.4, 0.75, 1.0]),
        obj("Prop_Candle_02", [0.08, 0.2, 0.08], [3.8, 0.75, 1.0]),
        obj("Prop_Mug_C", [0.1, 0.12, 0.1], [4.7, 0.75, 1.25]),
        obj("BP_Lamp_Wall_01", [0.15, 0.3, 0.2], [5.925, 1.8, -0.5]),
        obj("BP_Lamp_Wall_02", [0.15, 0.3, 0.2], [5.925, 1.8, 2.5]),
        obj("SM_Fireplace", [2.0, 1.2, 0.6], [-5.7, 0, 2.5], 90),
        obj("Prop_Pelt_Bear", [0.03, 1.0, 1.4], [-5.985, 1.4, -1.5]),
        obj("BP_Lamp_Floor", [0.4, 1.7, 0.4], [-5.6, 0, 4.5]),
        obj("SM_Armchair_01", [0.9, 1.0, 0.85], [-3.2, 0, 3.1], -90),
        obj("SM_Armchair_02", [0.9, 1.0, 0.85], [-3.2, 0, 1.9]),
        obj("SM_Table_Side_01", [0.5, 0.6, 0.5], [-2.3, 0, 2.5]),
        obj("Prop_Book_Old", [0.15, 0.05, 0.22], [-2.3, 0.6, 2.5]),
        obj("Prop_Painting_Stag", [0.03, 0.8, 1.1], [5.985, 1.4, -1.5]),
        obj("SM_Door_Main", [1.2, 2.2, 0.08], [3.5, 0, 4.96]),
        obj("SM_Dartboard", [0.45, 0.45, 0.04], [0.5, 1.5, 4.98]),
        obj("SM_Piano_Upright", [1.5, 1.3, 0.6], [-1.5, 0, 4.68], 180),
        obj("SM_Bench_Piano", [0.8, 0.5, 0.35], [-1.5, 0, 3.9]),
        obj("Prop_Sheet_Music", [0.3, 0.01, 0.22], [-1.5, 1.3, 4.7]),
        obj("Prop_Candelabra", [0.2, 0.35, 0.1], [-2.0, 1.3, 4.68]),
    ]
    return {"name": "tavern",
            "bounds": {"min": [-6, 0, -5], "max": [6, 3.2, 5]},
            "objects": objs}


# ---------------------------------------------------------------- DCC export, meaningless names
def blender_export():
    objs = [
        obj("Plane.001", [0.04, 2.05, 0.9], [3.98, 0, 2.4]),          # door slab, right wall
        obj("Cube", [2.4, 1.8, 0.5], [-1.5, 0, -3.25]),               # shelving unit, back wall
        obj("Cube.001", [0.3, 0.25, 0.3], [-2.3, 1.8, -3.25]),        # small box, left end of shelf top
        obj("Cube.002", [0.3, 0.25, 0.3], [-0.7, 1.8, -3.25]),        # small box, right end
        obj("Cube.003", [2.0, 0.9, 0.8], [0.5, 0, 0.0]),              # workbench, middle
        obj("mesh_17", [0.5, 0.35, 0.35], [0.0, 0.9, 0.0]),           # box on the workbench
        obj("Object_3", [0.12, 0.3, 0.12], [1.1, 0.9, 0.1]),          # tall skinny thing on workbench
        obj("mesh_22", [0.45, 0.9, 0.45], [0.5, 0, 0.9], 180),        # chair-sized box facing the bench
        obj("Cube.004", [0.5, 2.1, 0.45], [3.55, 0, 1.3]),            # tall narrow cabinet by the door
        obj("Cube.005", [1.2, 0.4, 0.8], [-2.8, 0, 1.8]),             # low wide crate
        obj("mesh_31", [0.25, 0.2, 0.25], [-3.1, 0.4, 1.8]),          # little box on the crate
        obj("Plane.002", [1.0, 0.7, 0.02], [1.8, 1.3, -3.49]),        # panel on the back wall
        obj("Plane.003", [1.6, 0.01, 1.0], [-1.6, 0, -1.5]),          # mat on the floor
        obj("Object_7", [0.6, 1.9, 0.6], [-3.6, 0, 3.1]),             # tall box, front-left corner
        obj("Object_9", [0.55, 0.85, 0.55], [3.5, 0, -3.0]),          # knee-high drum, back-right corner
        obj("Cube.006", [0.6, 0.6, 0.6], [-3.4, 0, -0.6]),            # 60 cm cube by the left wall
        obj("Cube.007", [0.4, 0.4, 0.4], [-3.4, 0.6, -0.6]),          # smaller box stacked on it
        obj("Object_12", [0.3, 1.6, 0.3], [2.9, 0, -0.9]),            # tall thin pole-like thing
        obj("Cube.008", [0.35, 0.6, 1.0], [-3.825, 1.4, -0.6]),       # box hung on the left wall
        obj("mesh_40", [1.8, 0.45, 0.4], [0.5, 0, 3.2]),              # long low bench, front wall
        obj("Object_15", [0.3, 0.05, 0.2], [0.0, 0.45, 3.2]),         # flat thing on the low bench
        obj("Cube.009", [0.6, 0.6, 0.6], [1.6, 0, -2.0]),             # 60 cm cube near the back
        obj("mesh_5", [0.2, 0.15, 0.2], [1.6, 0.6, -2.0]),            # small thing on that cube
        obj("Plane.004", [0.02, 0.9, 1.4], [-3.99, 1.1, 1.6]),        # panel on the left wall
    ]
    return {"name": "blender_export",
            "bounds": {"min": [-4, 0, -3.5], "max": [4, 3, 3.5]},
            "objects": objs}


# ---------------------------------------------------------------- clinic ward
def clinic_ward():
    objs = []
    for i, z in enumerate([-3.5, 0.0, 3.5], 1):
        objs.append(obj(f"Bed {i}", [1.0, 0.6, 2.1], [-3.9, 0, z], 90))        # head at the left wall
        objs.append(obj(f"Bedside Table {i}", [0.45, 0.7, 0.45], [-4.7, 0, z - 0.8]))
    for i, z in enumerate([-3.5, 0.0, 3.5], 4):
        objs.append(obj(f"Bed {i}", [1.0, 0.6, 2.1], [3.9, 0, z], -90))        # head at the right wall
        objs.append(obj(f"Bedside Table {i}", [0.45, 0.7, 0.45], [4.7, 0, z - 0.8]))
    objs += [
        obj("Water Jug", [0.12, 0.25, 0.12], [-4.75, 0.7, -4.25]),
        obj("Plastic Cup", [0.07, 0.1, 0.07], [-4.6, 0.7, -4.4]),
        obj("Vase of Flowers", [0.15, 0.35, 0.15], [-4.75, 0.7, 2.7]),
        obj("Get Well Card", [0.12, 0.15, 0.03], [-4.55, 0.7, 2.6]),
        obj("Reading Glasses", [0.14, 0.04, 0.05], [4.7, 0.7, -0.8]),
        obj("Tissue Box", [0.24, 0.1, 0.12], [4.7, 0.7, 2.7]),
        obj("Tablet", [0.25, 0.01, 0.18], [-3.5, 0.6, 0.0]),
        obj("Folded Blanket", [0.5, 0.1, 0.4], [3.2, 0.6, 3.5]),
        obj("Visitor Chair 1", [0.5, 0.9, 0.5], [-3.3, 0, -2.6], 180),
        obj("Visitor Chair 2", [0.5, 0.9, 0.5], [3.3, 0, 0.9], 180),
        obj("Visitor Chair 3", [0.5, 0.9, 0.5], [-3.3, 0, 4.55], 180),
        obj("IV Stand 1", [0.5, 1.9, 0.5], [-3.6, 0, -4.4]),
        obj("IV Stand 2", [0.5, 1.9, 0.5], [3.6, 0, -4.4]),
        obj("IV Stand 3", [0.5, 1.9, 0.5], [2.4, 0, 3.1]),
        obj("Nurses Station", [2.4, 1.0, 0.8], [0, 0, 4.9]),
        obj("Monitor", [0.5, 0.4, 0.2], [-0.6, 1.0, 5.1]),
        obj("Phone", [0.2, 0.1, 0.2], [-0.9, 1.0, 4.7]),
        obj("Clipboard", [0.23, 0.02, 0.32], [0.85, 1.0, 4.85]),
        obj("Office Chair", [0.6, 1.0, 0.6], [0, 0, 5.65], 180),
        obj("Wall Clock", [0.35, 0.35, 0.04], [2.5, 2.2, 5.98]),
        obj("TV", [1.2, 0.7, 0.08], [0, 1.8, -5.96]),
        obj("Window", [0.04, 1.2, 1.2], [-4.98, 1.0, -1.75]),
        obj("Medicine Cart", [0.6, 1.0, 0.45], [-1.2, 0, -5.3]),
        obj("Pill Organizer", [0.2, 0.06, 0.12], [-1.3, 1.0, -5.3]),
        obj("Thermometer", [0.04, 0.02, 0.15], [-1.0, 1.0, -5.3]),
        obj("Wheelchair", [0.65, 0.95, 1.05], [1.2, 0, -5.3]),
        obj("Linen Hamper", [0.6, 0.9, 0.5], [-4.6, 0, -1.8]),
        obj("Waste Bin", [0.35, 0.5, 0.35], [2.6, 0, -5.6]),
        obj("Hand Sanitizer", [0.1, 0.25, 0.1], [4.95, 1.2, -1.8]),
    ]
    return {"name": "clinic_ward",
            "bounds": {"min": [-5, 0, -6], "max": [5, 3, 6]},
            "objects": objs}


SCENES = {"exam_hall": exam_hall, "tavern": tavern,
          "blender_export": blender_export, "clinic_ward": clinic_ward}

# ====================================================================== query helpers
FT = 0.3048
IN = 0.0254

QUERIES = []      # (scene, category, text, checks, answer)
_SC = {}          # scene name -> {object name: object}


def scene_objs(s):
    if s not in _SC:
        _SC[s] = {o["name"]: o for o in SCENES[s]()["objects"]}
    return _SC[s]


def mv(o, d, tol=0.03):
    return {"check": "moved", "object": o, "delta": [round(v, 4) for v in d], "tol": tol}


def dr(o, axis, mn=0.05):
    return {"check": "direction", "object": o, "axis": axis, "min": mn}


def rot(o, deg, either=False):
    c = {"check": "rotated", "object": o, "axis": "y", "degrees": deg, "tol": 3}
    if either:
        c["either_sign"] = True
    return c


def sc(o, f):
    return {"check": "scaled", "object": o, "factor": f}


def ontop(o, s):
    return {"check": "on_top", "object": o, "support": s}


def nextto(o, other, gap=0.4):
    return {"check": "next_to", "object": o, "other": other, "max_gap": gap}


def side(o, other, sd, gap=0.5):
    return {"check": "side", "object": o, "other": other, "side": sd, "max_gap": gap}


def above(o, other):
    return {"check": "above", "object": o, "other": other}


def between(o, a, b, tol=0.2):
    return {"check": "between", "object": o, "a": a, "b": b, "tol": tol}


def aligned(o, other, axis, tol=0.05):
    return {"check": "aligned", "object": o, "other": other, "axis": axis, "tol": tol}


def faces(o, t):
    return {"check": "faces", "object": o, "target": t}


def swapped(o, other):
    return {"check": "swapped", "object": o, "other": other}


def refused(mentions=()):
    return {"check": "refused", "mentions": list(mentions)}


def _centre(s, n):
    o = scene_objs(s)[n]
    # works for the yaw-symmetric boxes used here: centre is above the pivot
    p = o["position"]
    return [p[0], p[1] + o["size"][1] * o.get("scale", 1) / 2, p[2]]


def dist0(s, a, b):
    ca, cb = _centre(s, a), _centre(s, b)
    return math.dist(ca, cb), math.hypot(ca[0] - cb[0], ca[2] - cb[2])


def closer(s, o, other, by=0.05):
    """distance check: closer than now by at least `by` (both 3-D and floor plan)."""
    d3, _ = dist0(s, o, other)
    return {"check": "distance", "object": o, "other": other, "max": round(d3 - by, 3)}


def further(s, o, other, by=0.05):
    d3, _ = dist0(s, o, other)
    return {"check": "distance", "object": o, "other": other, "min": round(d3 + by, 3)}


def T(dx=0.0, dy=0.0, dz=0.0, yaw=0.0, s=None):
    a = {"t": [round(dx, 6), round(dy, 6), round(dz, 6)]}
    if yaw:
        a["yaw"] = round(yaw, 4)
    if s:
        a["s"] = s
    return a


def R(yaw):
    return T(yaw=yaw)


def onto(s, o, sup, x=None, z=None):
    """translation putting o's pivot on sup's top at (x, z) (default: sup's centre)."""
    ob, sp = scene_objs(s)[o], scene_objs(s)[sup]
    top = sp["position"][1] + sp["size"][1] * sp.get("scale", 1)
    x = sp["position"][0] if x is None else x
    z = sp["position"][2] if z is None else z
    p = ob["position"]
    return [x - p[0], top - p[1], z - p[2]]


def to(s, o, x, y, z):
    p = scene_objs(s)[o]["position"]
    return [x - p[0], y - p[1], z - p[2]]


def face_yaw(s, o, target, new_xz=None):
    """yaw delta (degrees) that turns o's front (+Z) toward target's centre."""
    ob = scene_objs(s)[o]
    p = ob["position"] if new_xz is None else [new_xz[0], 0, new_xz[1]]
    c = _centre(s, target)
    want = math.degrees(math.atan2(c[0] - p[0], c[2] - p[2]))
    q = ob["rotation"]
    cur = math.degrees(2 * math.atan2(q[1], q[3]))
    return (want - cur + 180) % 360 - 180


def Q(scene, cat, text, checks, ans=None):
    QUERIES.append((scene, cat, text, checks, ans))


def group(names, t):
    return {n: T(*t) for n in names}


# ====================================================================== exam hall
def exam_queries():
    S = "exam_hall"
    D = lambda n: f"Desk {n}"
    C = lambda n: f"Chair {n}"
    # ---- simple
    Q(S, "simple", "mvoe desk 5 one metre to the right",
      [mv("Desk 5", [1, 0, 0])], {"Desk 5": T(1)})
    Q(S, "simple", "chair 11: 40cm back",
      [mv("Chair 11", [0, 0, -0.4])], {"Chair 11": T(dz=-0.4)})
    Q(S, "simple", "Rotate the stack of chairs by 45 degrees",
      [rot("Stack of Chairs", 45, True)], {"Stack of Chairs": R(45)})
    Q(S, "simple", "raise the wall clock by 20 cm",
      [mv("Wall Clock", [0, 0.2, 0])], {"Wall Clock": T(dy=0.2)})
    Q(S, "simple", "can you shift the coat rack 2 feet to the right?",
      [mv("Coat Rack", [2 * FT, 0, 0])], {"Coat Rack": T(2 * FT)})
    Q(S, "simple", "push the supply cart 1.5 m forward",
      [mv("Supply Cart", [0, 0, 1.5]), mv("Box of Pencils", [0, 0, 1.5]), mv("Tissue Box", [0, 0, 1.5])],
      group(["Supply Cart", "Box of Pencils", "Tissue Box"], (0, 0, 1.5)))
    Q(S, "simple", "scale the desk lamp up by 50%",
      [sc("Desk Lamp", 1.5)], {"Desk Lamp": T(s=1.5)})
    Q(S, "simple", "turn the backpack 90° clockwise",
      [rot("Backpack", -90)], {"Backpack": R(-90)})
    Q(S, "simple", "lower the noticeboard 10cm",
      [mv("Notice Board", [0, -0.1, 0])], {"Notice Board": T(dy=-0.1)})
    Q(S, "simple", "Desk 18 left 50 cm",
      [mv("Desk 18", [-0.5, 0, 0])], {"Desk 18": T(-0.5)})
    Q(S, "simple", "make the hand bell twice as big",
      [sc("Hand Bell", 2)], {"Hand Bell": T(s=2)})
    Q(S, "simple", "put the coffee cup 10 cm to the left",
      [mv("Coffee Cup", [-0.1, 0, 0])], {"Coffee Cup": T(-0.1)})
    Q(S, "simple", "move the recycling bin 2'6\" to the right",
      [mv("Recycling Bin", [30 * IN, 0, 0])], {"Recycling Bin": T(30 * IN)})
    Q(S, "simple", "move chair 21 back a bit", [refused([])])
    Q(S, "simple", "put the stapler on desk 4", [refused([])])
    # ---- compositional
    Q(S, "compositional", "move desk 9 and chair 9 half a metre forward",
      [mv("Desk 9", [0, 0, 0.5]), mv("Chair 9", [0, 0, 0.5])],
      group(["Desk 9", "Chair 9"], (0, 0, 0.5)))
    Q(S, "compositional", "swap the calculator and the water bottle",
      [swapped("Calculator", "Water Bottle")],
      {"Calculator": T(*to(S, "Calculator", 0.3, 0.75, 3.1)),
       "Water Bottle": T(*to(S, "Water Bottle", -2.45, 0.75, 1.2))})
    front = [D(n) for n in range(1, 6)] + [C(n) for n in range(1, 6)] + ["Water Bottle"]
    Q(S, "compositional", "move the whole front row, desks and chairs, 40 cm forward",
      [mv(n, [0, 0, 0.4]) for n in front], group(front, (0, 0, 0.4)))
    Q(S, "compositional", "move desk 12 and everything on it 1 m to the left",
      [mv("Desk 12", [-1, 0, 0]), mv("Dictionary", [-1, 0, 0])],
      group(["Desk 12", "Dictionary"], (-1, 0, 0)))
    Q(S, "compositional", "rotate chairs 16-20 to face the back wall",
      [rot(C(n), 180, True) for n in range(16, 21)], {C(n): R(180) for n in range(16, 21)})
    Q(S, "compositional", "Put the tissue box on desk 6 and the box of pencils on desk 10",
      [ontop("Tissue Box", "Desk 6"), ontop("Box of Pencils", "Desk 10")],
      {"Tissue Box": T(*onto(S, "Tissue Box", "Desk 6")),
       "Box of Pencils": T(*onto(S, "Box of Pencils", "Desk 10"))})
    Q(S, "compositional", "move chair 2 30cm left and turn it 90 degrees clockwise",
      [mv("Chair 2", [-0.3, 0, 0]), rot("Chair 2", -90)], {"Chair 2": T(-0.3, yaw=-90)})
    g = [D(3), D(4), D(5), D(6), "Water Bottle"]
    Q(S, "compositional", "desks 3 to 6: 6 inches forward",
      [mv(n, [0, 0, 6 * IN]) for n in g], group(g, (0, 0, 6 * IN)))
    Q(S, "compositional", "raise the whiteboard 15 cm and move it 1 m to the left",
      [mv("Whiteboard", [-1, 0.15, 0])], {"Whiteboard": T(-1, 0.15)})
    Q(S, "compositional", "Move desk 1 and desk 4 20 cm to the right each",
      [mv(D(1), [0.2, 0, 0]), mv(D(4), [0.2, 0, 0])], group([D(1), D(4)], (0.2, 0, 0)))
    Q(S, "compositional", "Put the coffee cup on the invigilator's desk and the hand bell on desk 20",
      [ontop("Coffee Cup", "Invigilator Desk"), ontop("Hand Bell", "Desk 20")],
      {"Coffee Cup": T(*onto(S, "Coffee Cup", "Invigilator Desk", 0.2, 4.85)),
       "Hand Bell": T(*onto(S, "Hand Bell", "Desk 20"))})
    Q(S, "compositional", "lift the exit sign 10cm and slide it 50cm left",
      [mv("Exit Sign", [-0.5, 0.1, 0])], {"Exit Sign": T(-0.5, 0.1)})
    Q(S, "compositional", "shrink the water bottle by 20% and move it 30 cm to the left",
      [sc("Water Bottle", 0.8), mv("Water Bottle", [-0.3, 0, 0])], {"Water Bottle": T(-0.3, s=0.8)})
    Q(S, "compositional", "move the box and the bell to desk 2",
      [refused(["Box of Pencils", "Tissue Box"])])
    # ---- fuzzy
    Q(S, "fuzzy", "nudge the coat rack a little to the right",
      [dr("Coat Rack", "+x")], {"Coat Rack": T(0.2)})
    Q(S, "fuzzy", "could the notice board go a bit lower?",
      [dr("Notice Board", "-y", 0.03)], {"Notice Board": T(dy=-0.15)})
    Q(S, "fuzzy", "put the backpack next to the door",
      [nextto("Backpack", "Door", 0.5)], {"Backpack": T(*to(S, "Backpack", 4.7, 0, -5.7))})
    Q(S, "fuzzy", "move the waste bin closer to the invigilator desk",
      [closer(S, "Waste Bin", "Invigilator Desk", 0.3)], {"Waste Bin": T(5.0)})
    Q(S, "fuzzy", "centre the wall clock above the whiteboard",
      [aligned("Wall Clock", "Whiteboard", "x"), above("Wall Clock", "Whiteboard")],
      {"Wall Clock": T(-3.2)})
    Q(S, "fuzzy", "turn the invigilator's chair round so it faces the whiteboard",
      [faces("Invigilator Chair", "Whiteboard")], {"Invigilator Chair": R(180)})
    Q(S, "fuzzy", "slide desk 15 a touch toward the radiator",
      [closer(S, "Desk 15", "Radiator", 0.03)], {"Desk 15": T(0.15)})
    Q(S, "fuzzy", "move the pencil case a bit further from the calculator",
      [further(S, "Pencil Case", "Calculator", 0.05), ontop("Pencil Case", "Desk 7")],
      {"Pencil Case": T(0.12)})
    Q(S, "fuzzy", "the coffee cup should be on the desk in front of the one it's on now",
      [ontop("Coffee Cup", "Desk 15")], {"Coffee Cup": T(*onto(S, "Coffee Cup", "Desk 15"))})
    Q(S, "fuzzy", "put the dictionary on the desk behind it",
      [ontop("Dictionary", "Desk 17")], {"Dictionary": T(*onto(S, "Dictionary", "Desk 17", -2.2, -2.4))})
    Q(S, "fuzzy", "can the recycling bin go by the door?",
      [nextto("Recycling Bin", "Door", 0.5)],
      {"Recycling Bin": T(*to(S, "Recycling Bin", 4.65, 0, -5.65))})
    Q(S, "fuzzy", "move the lamp to the other end of the invigilator desk",
      [ontop("Desk Lamp", "Invigilator Desk"), dr("Desk Lamp", "+x", 0.8)], {"Desk Lamp": T(1.2)})
    Q(S, "fuzzy", "the backpack should sit right behind chair 14",
      [side("Backpack", "Chair 14", "behind", 0.4)],
      {"Backpack": T(*to(S, "Backpack", 2.2, 0, -1.65))})
    Q(S, "fuzzy", "glasses case onto desk 9 pls",
      [ontop("Glasses Case", "Desk 9")], {"Glasses Case": T(*onto(S, "Glasses Case", "Desk 9"))})
    Q(S, "fuzzy", "the backpack goes in front of desk 1",
      [side("Backpack", "Desk 1", "front", 0.5)], {"Backpack": T(*to(S, "Backpack", -4.4, 0, 3.48))})
    Q(S, "fuzzy", "move the bin a bit closer to the whiteboard",
      [refused(["Waste Bin", "Recycling Bin"])])
    Q(S, "fuzzy", "could the projector screen come down a bit?", [refused([])])
    # ---- compositional_fuzzy
    back = [D(n) for n in range(16, 21)] + [C(n) for n in range(16, 21)] + ["Coffee Cup"]
    Q(S, "compositional_fuzzy", "scoot the back row of desks and chairs forward a little",
      [dr(n, "+z") for n in back], group(back, (0, 0, 0.2)))
    Q(S, "compositional_fuzzy", "move chair 7 a bit to the left and spin it round to face the back",
      [dr("Chair 7", "-x"), rot("Chair 7", 180, True)], {"Chair 7": T(-0.25, yaw=180)})
    Q(S, "compositional_fuzzy", "I want desk 2 a bit more to the left and desk 4 a bit more to the right",
      [dr(D(2), "-x"), dr(D(4), "+x")], {D(2): T(-0.25), D(4): T(0.25)})
    Q(S, "compositional_fuzzy", "take the water bottle and the coffee cup over to the invigilator desk",
      [ontop("Water Bottle", "Invigilator Desk"), ontop("Coffee Cup", "Invigilator Desk")],
      {"Water Bottle": T(*onto(S, "Water Bottle", "Invigilator Desk", 0.35, 4.75)),
       "Coffee Cup": T(*onto(S, "Coffee Cup", "Invigilator Desk", -0.2, 4.85))})
    cart = ["Supply Cart", "Box of Pencils", "Tissue Box"]
    Q(S, "compositional_fuzzy", "shift the supply cart a little toward the front, with its stuff still on it",
      [dr(n, "+z") for n in cart], group(cart, (0, 0, 0.3)))
    bt = onto(S, "Hand Bell", "Desk 3", 0.15, 3.1)
    Q(S, "compositional_fuzzy", "put the hand bell next to the water bottle, then nudge desk 3 a bit to the right",
      [dr("Desk 3", "+x"), dr("Water Bottle", "+x"), ontop("Hand Bell", "Desk 3"),
       nextto("Hand Bell", "Water Bottle", 0.2)],
      {"Desk 3": T(0.2), "Water Bottle": T(0.2), "Hand Bell": T(bt[0] + 0.2, bt[1], bt[2])})
    Q(S, "compositional_fuzzy", "move desk 10 a bit to the right, then put the pencil case on it",
      [dr("Desk 10", "+x"), ontop("Pencil Case", "Desk 10")],
      {"Desk 10": T(0.3), "Pencil Case": T(*to(S, "Pencil Case", 4.7, 0.75, 1.2))})
    Q(S, "compositional_fuzzy", "lower the whiteboard a little and centre the clock above it",
      [dr("Whiteboard", "-y", 0.03), aligned("Wall Clock", "Whiteboard", "x"), above("Wall Clock", "Whiteboard")],
      {"Whiteboard": T(dy=-0.1), "Wall Clock": T(-3.2)})
    Q(S, "compositional_fuzzy", "push chair 13 in closer to its desk and give it a quarter turn counterclockwise",
      [dr("Chair 13", "+z", 0.03), rot("Chair 13", 90)], {"Chair 13": T(dz=0.08, yaw=90)})
    Q(S, "compositional_fuzzy", "could the exam papers go on desk 8 and the desk lamp a bit to the right?",
      [ontop("Exam Papers", "Desk 8"), dr("Desk Lamp", "+x"), ontop("Desk Lamp", "Invigilator Desk")],
      {"Exam Papers": T(*onto(S, "Exam Papers", "Desk 8")), "Desk Lamp": T(0.3)})
    g = [D(11), C(11)]
    Q(S, "compositional_fuzzy", "move desk 11 and its chair a bit to the left, and put the dictionary on desk 11",
      [dr(n, "-x") for n in g] + [ontop("Dictionary", D(11))],
      dict(group(g, (-0.3, 0, 0)), Dictionary=T(*onto(S, "Dictionary", D(11), -4.7, -0.6))))
    Q(S, "compositional_fuzzy", "turn the backpack a quarter turn clockwise and scoot it a little closer to desk 14",
      [rot("Backpack", -90), closer(S, "Backpack", D(14), 0.05)], {"Backpack": T(-0.15, yaw=-90)})
    g = [D(20), C(20), "Coffee Cup"]
    Q(S, "compositional_fuzzy", "push desk 20 a bit closer to desk 19, and take its chair and the cup with it",
      [dr(n, "-x") for n in g], group(g, (-0.4, 0, 0)))
    Q(S, "compositional_fuzzy", "move the front-row desk a bit back and its chair too",
      [refused([D(n) for n in range(1, 6)])])
    # ---- hard
    g = [C(6), C(7), C(9), C(10)]
    Q(S, "hard", "move every chair in the second row except chair 8 back 20 cm",
      [mv(n, [0, 0, -0.2]) for n in g], group(g, (0, 0, -0.2)))
    g = [D(7), "Calculator", "Pencil Case"]
    Q(S, "hard", "the desk with the calculator on it - move it 25 cm forward with its stuff",
      [mv(n, [0, 0, 0.25]) for n in g], group(g, (0, 0, 0.25)))
    g = [D(n) for n in range(16, 21)] + [C(n) for n in range(16, 21)] + ["Coffee Cup"]
    Q(S, "hard", "desks 16-20 and their chairs: 1 ft back",
      [mv(n, [0, 0, -FT]) for n in g], group(g, (0, 0, -FT)))
    Q(S, "hard", "put the hand bell on the desk at the front right corner of the rows",
      [ontop("Hand Bell", "Desk 5")], {"Hand Bell": T(*onto(S, "Hand Bell", "Desk 5"))})
    Q(S, "hard", "rotate the second chair in the front row 90° counterclockwise",
      [rot("Chair 2", 90)], {"Chair 2": R(90)})
    Q(S, "hard", "the last desk in the third row: move it 40 cm to the right",
      [mv("Desk 15", [0.4, 0, 0])], {"Desk 15": T(0.4)})
    Q(S, "hard", "move the desk thats directly behind desk 8 half a metre left",
      [mv("Desk 13", [-0.5, 0, 0])], {"Desk 13": T(-0.5)})
    Q(S, "hard", "put the dictionary between the calculator and the pencil case",
      [between("Dictionary", "Calculator", "Pencil Case", 0.1), ontop("Dictionary", "Desk 7")],
      {"Dictionary": T(*onto(S, "Dictionary", "Desk 7", -2.255, 1.2))})
    g = [D(1), D(2), D(4), D(5)]
    Q(S, "hard", "move all the front-row desks apart from desk 3 20 cm forward",
      [mv(n, [0, 0, 0.2]) for n in g], group(g, (0, 0, 0.2)))
    Q(S, "hard", "the chair at the back-left corner of the seating block, move it 1m left",
      [mv("Chair 16", [-1, 0, 0])], {"Chair 16": T(-1)})
    Q(S, "hard", "take chairs 9-12 and turn each one to face the notice board",
      [faces(C(n), "Notice Board") for n in range(9, 13)],
      {C(n): R(face_yaw(S, C(n), "Notice Board")) for n in range(9, 13)})
    g = [D(2), D(7), D(12), C(2), C(7), C(12), "Calculator", "Pencil Case", "Dictionary"]
    Q(S, "hard", "Desks 2, 7 and 12 with their chairs and everything on them: 50cm to the right",
      [mv(n, [0.5, 0, 0]) for n in g], group(g, (0.5, 0, 0)))
    Q(S, "hard", "put the glasses case on the dictionary's desk, right next to the dictionary",
      [ontop("Glasses Case", "Desk 12"), nextto("Glasses Case", "Dictionary", 0.2)],
      {"Glasses Case": T(*onto(S, "Glasses Case", "Desk 12", -2.0, -0.55))})
    Q(S, "hard", "move the coat rack to the other side of the room",
      [dr("Coat Rack", "+x", 10)], {"Coat Rack": T(13.0)})
    Q(S, "hard", "move the desk next to desk 3 half a metre back", [refused(["Desk 2", "Desk 4"])])
    Q(S, "hard", "put the laptop on the invigilator desk", [refused([])])
    Q(S, "hard", "move the case 20 cm left", [refused(["Pencil Case", "Glasses Case"])])
    Q(S, "hard", "rotate the exam papers and the clipboard 90 degrees", [refused([])])


# ====================================================================== tavern
def tavern_queries():
    S = "tavern"
    t1 = ["Table_Round_01", "SM_Chair_01", "SM_Chair_02", "SM_Chair_03", "SM_Chair_04",
          "Prop_Candle_03", "Prop_Mug_D"]
    t2 = ["Table_Round_02", "SM_Chair_05", "SM_Chair_06", "SM_Chair_07", "SM_Chair_08",
          "Prop_Cards_Deck", "Prop_Goblet_01"]
    lt = ["Table_Long_Oak", "SM_Bench_01", "SM_Bench_02", "Prop_Plate_01", "Prop_Plate_02",
          "Prop_Candle_02", "Prop_Mug_C"]
    piano = ["SM_Piano_Upright", "Prop_Sheet_Music", "Prop_Candelabra"]
    shelf = ["SM_Shelf_Wall_01", "Prop_Bottle_01", "Prop_Bottle_02", "Prop_Bottle_03"]
    # ---- simple
    Q(S, "simple", "move stool 5 half a metre right",
      [mv("SM_Stool_05", [0.5, 0, 0])], {"SM_Stool_05": T(0.5)})
    Q(S, "simple", "raise the stag painting 20cm",
      [mv("Prop_Painting_Stag", [0, 0.2, 0])], {"Prop_Painting_Stag": T(dy=0.2)})
    Q(S, "simple", "move the floor lamp 1 m to the right",
      [mv("BP_Lamp_Floor", [1, 0, 0])], {"BP_Lamp_Floor": T(1)})
    Q(S, "simple", "turn the piano bench 90 degrees",
      [rot("SM_Bench_Piano", 90, True)], {"SM_Bench_Piano": R(90)})
    Q(S, "simple", "scale the candelabra down to half size",
      [sc("Prop_Candelabra", 0.5)], {"Prop_Candelabra": T(s=0.5)})
    Q(S, "simple", "Prop_Mug_A: 20cm to the right",
      [mv("Prop_Mug_A", [0.2, 0, 0])], {"Prop_Mug_A": T(0.2)})
    Q(S, "simple", "can you move the dartboard 40 cm left?",
      [mv("SM_Dartboard", [-0.4, 0, 0])], {"SM_Dartboard": T(-0.4)})
    Q(S, "simple", "lower the wall shelf by 10 cm",
      [mv(n, [0, -0.1, 0]) for n in shelf], group(shelf, (0, -0.1, 0)))
    Q(S, "simple", "push the side table 2 feet back",
      [mv("SM_Table_Side_01", [0, 0, -2 * FT]), mv("Prop_Book_Old", [0, 0, -2 * FT])],
      group(["SM_Table_Side_01", "Prop_Book_Old"], (0, 0, -2 * FT)))
    Q(S, "simple", "turn SM_Armchair_01 around",
      [rot("SM_Armchair_01", 180, True)], {"SM_Armchair_01": R(180)})
    Q(S, "simple", "make the candle on the long table twice as big",
      [sc("Prop_Candle_02", 2)], {"Prop_Candle_02": T(s=2)})
    Q(S, "simple", "Prop_Book_Old - rotate 90 deg ccw",
      [rot("Prop_Book_Old", 90)], {"Prop_Book_Old": R(90)})
    Q(S, "simple", "move the door 50cm to the left",
      [mv("SM_Door_Main", [-0.5, 0, 0])], {"SM_Door_Main": T(-0.5)})
    Q(S, "simple", "move the jukebox into the corner", [refused([])])
    Q(S, "simple", "move stool 6 to the left", [refused([])])
    # ---- compositional
    g = t1
    Q(S, "compositional", "move table 1 and its four chairs 1 m back",
      [mv(n, [0, 0, -1]) for n in g], group(g, (0, 0, -1)))
    Q(S, "compositional", "swap stool 1 and stool 5 plz",
      [swapped("SM_Stool_01", "SM_Stool_05")],
      {"SM_Stool_01": T(3.2), "SM_Stool_05": T(-3.2)})
    Q(S, "compositional", "put Prop_Mug_B on the long table and Prop_Mug_A on round table 2",
      [ontop("Prop_Mug_B", "Table_Long_Oak"), ontop("Prop_Mug_A", "Table_Round_02")],
      {"Prop_Mug_B": T(*onto(S, "Prop_Mug_B", "Table_Long_Oak", 3.5, 1.3)),
       "Prop_Mug_A": T(*onto(S, "Prop_Mug_A", "Table_Round_02", 0.4, 0.25))})
    Q(S, "compositional", "move the candle off barrel 1 onto barrel 2 and turn barrel 3 by 90 degrees",
      [ontop("Prop_Candle_01", "SM_Barrel_02"), rot("SM_Barrel_03", 90, True)],
      {"Prop_Candle_01": T(*onto(S, "Prop_Candle_01", "SM_Barrel_02")), "SM_Barrel_03": R(90)})
    Q(S, "compositional", "raise both wall lamps 30 cm",
      [mv("BP_Lamp_Wall_01", [0, 0.3, 0]), mv("BP_Lamp_Wall_02", [0, 0.3, 0])],
      group(["BP_Lamp_Wall_01", "BP_Lamp_Wall_02"], (0, 0.3, 0)))
    Q(S, "compositional", "move the long table with its benches and all the stuff on it 50 cm to the left",
      [mv(n, [-0.5, 0, 0]) for n in lt], group(lt, (-0.5, 0, 0)))
    g = piano + ["SM_Bench_Piano"]
    Q(S, "compositional", "move the piano 1 m right and take its bench with it",
      [mv(n, [1, 0, 0]) for n in g], group(g, (1, 0, 0)))
    Q(S, "compositional", "put the book on the piano and the sheet music on the side table",
      [ontop("Prop_Book_Old", "SM_Piano_Upright"), ontop("Prop_Sheet_Music", "SM_Table_Side_01")],
      {"Prop_Book_Old": T(*onto(S, "Prop_Book_Old", "SM_Piano_Upright", -1.0, 4.68)),
       "Prop_Sheet_Music": T(*onto(S, "Prop_Sheet_Music", "SM_Table_Side_01"))})
    Q(S, "compositional", "Stool 2 and stool 4: 30 cm forward each",
      [mv("SM_Stool_02", [0, 0, 0.3]), mv("SM_Stool_04", [0, 0, 0.3])],
      group(["SM_Stool_02", "SM_Stool_04"], (0, 0, 0.3)))
    Q(S, "compositional", "drop the painting 15cm and slide it 1 m toward the back wall",
      [mv("Prop_Painting_Stag", [0, -0.15, -1])], {"Prop_Painting_Stag": T(0, -0.15, -1)})
    Q(S, "compositional", "put mugs C and D both on the bar",
      [ontop("Prop_Mug_C", "SM_Bar_Counter"), ontop("Prop_Mug_D", "SM_Bar_Counter")],
      {"Prop_Mug_C": T(*onto(S, "Prop_Mug_C", "SM_Bar_Counter", -2.0, -3.85)),
       "Prop_Mug_D": T(*onto(S, "Prop_Mug_D", "SM_Bar_Counter", -1.6, -3.85))})
    Q(S, "compositional", "move Table_Round_01 with its chairs 50 cm left and then 50 cm back",
      [mv(n, [-0.5, 0, -0.5]) for n in t1], group(t1, (-0.5, 0, -0.5)))
    Q(S, "compositional", "move the bench 40cm forward and the floor lamp 20cm left",
      [refused(["SM_Bench_01", "SM_Bench_02", "SM_Bench_Piano"])])
    # ---- fuzzy
    Q(S, "fuzzy", "nudge the piano bench a little closer to the piano",
      [dr("SM_Bench_Piano", "+z", 0.03)], {"SM_Bench_Piano": T(dz=0.15)})
    Q(S, "fuzzy", "the floor lamp should be a bit further from the fireplace",
      [further(S, "BP_Lamp_Floor", "SM_Fireplace", 0.1)], {"BP_Lamp_Floor": T(0.8)})
    Q(S, "fuzzy", "can stool 5 go a bit more to the right?",
      [dr("SM_Stool_05", "+x")], {"SM_Stool_05": T(0.3)})
    Q(S, "fuzzy", "put the goblet nxt to the beer tap",
      [nextto("Prop_Goblet_01", "BP_Tap_Beer", 0.3), ontop("Prop_Goblet_01", "SM_Bar_Counter")],
      {"Prop_Goblet_01": T(*onto(S, "Prop_Goblet_01", "SM_Bar_Counter", -0.7, -4.15))})
    Q(S, "fuzzy", "slide the front door a little to the right",
      [dr("SM_Door_Main", "+x")], {"SM_Door_Main": T(0.3)})
    Q(S, "fuzzy", "slide the dartboard up a touch",
      [dr("SM_Dartboard", "+y", 0.03)], {"SM_Dartboard": T(dy=0.1)})
    Q(S, "fuzzy", "I want the armchairs closer to the fire",
      [closer(S, "SM_Armchair_01", "SM_Fireplace", 0.1), closer(S, "SM_Armchair_02", "SM_Fireplace", 0.1)],
      {"SM_Armchair_01": T(-0.5), "SM_Armchair_02": T(-0.5)})
    Q(S, "fuzzy", "move the goblet closer to the cards",
      [closer(S, "Prop_Goblet_01", "Prop_Cards_Deck", 0.05), ontop("Prop_Goblet_01", "Table_Round_02")],
      {"Prop_Goblet_01": T(*onto(S, "Prop_Goblet_01", "Table_Round_02", 0.55, 0.05))})
    Q(S, "fuzzy", "could the painting go a bit higher",
      [dr("Prop_Painting_Stag", "+y", 0.03)], {"Prop_Painting_Stag": T(dy=0.15)})
    Q(S, "fuzzy", "move mug D away from the candle a bit",
      [further(S, "Prop_Mug_D", "Prop_Candle_03", 0.05), ontop("Prop_Mug_D", "Table_Round_01")],
      {"Prop_Mug_D": T(*onto(S, "Prop_Mug_D", "Table_Round_01", -2.7, 0.3))})
    Q(S, "fuzzy", "put the floor lamp by the fireplace",
      [nextto("BP_Lamp_Floor", "SM_Fireplace", 0.5)],
      {"BP_Lamp_Floor": T(*to(S, "BP_Lamp_Floor", -5.6, 0, 3.85))})
    Q(S, "fuzzy", "could the tap go a bit more to the right on the counter",
      [dr("BP_Tap_Beer", "+x"), ontop("BP_Tap_Beer", "SM_Bar_Counter")], {"BP_Tap_Beer": T(0.3)})
    Q(S, "fuzzy", "the dartboard should be centred over the piano",
      [aligned("SM_Dartboard", "SM_Piano_Upright", "x"), above("SM_Dartboard", "SM_Piano_Upright")],
      {"SM_Dartboard": T(-2.0)})
    Q(S, "fuzzy", "can the mug go on the piano?",
      [refused(["Prop_Mug_A", "Prop_Mug_B", "Prop_Mug_C", "Prop_Mug_D"])])
    Q(S, "fuzzy", "rotate the barrel against the right wall 45 degrees",
      [refused(["SM_Barrel_01", "SM_Barrel_03"])])
    # ---- compositional_fuzzy
    Q(S, "compositional_fuzzy", "pull round table 2 and its chairs a bit to the right, toward the long table",
      [dr(n, "+x") for n in t2], group(t2, (0.3, 0, 0)))
    Q(S, "compositional_fuzzy", "move the piano a little to the right and the dartboard a bit higher",
      [dr(n, "+x") for n in piano] + [dr("SM_Dartboard", "+y", 0.03)],
      dict(group(piano, (0.3, 0, 0)), SM_Dartboard=T(dy=0.1)))
    Q(S, "compositional_fuzzy", "turn stool 1 a quarter turn and slide it a bit to the left",
      [rot("SM_Stool_01", 90, True), dr("SM_Stool_01", "-x")], {"SM_Stool_01": T(-0.3, yaw=90)})
    Q(S, "compositional_fuzzy", "take the small crate off the big one and put it on the floor to the left of it",
      [side("SM_Crate_02", "SM_Crate_01", "left", 0.5)],
      {"SM_Crate_02": T(*to(S, "SM_Crate_02", 4.8, 0, -2.5))})
    Q(S, "compositional_fuzzy", "move the tap a bit left and put mug A right next to it",
      [dr("BP_Tap_Beer", "-x"), nextto("Prop_Mug_A", "BP_Tap_Beer", 0.2), ontop("Prop_Mug_A", "SM_Bar_Counter")],
      {"BP_Tap_Beer": T(-0.3), "Prop_Mug_A": T(*onto(S, "Prop_Mug_A", "SM_Bar_Counter", -1.55, -4.15))})
    Q(S, "compositional_fuzzy", "shift the long table and both benches a bit toward the door",
      [dr(n, "+z") for n in lt], group(lt, (0, 0, 0.3)))
    yaw = face_yaw(S, "SM_Armchair_02", "SM_Fireplace", (-3.6, 1.9))
    Q(S, "compositional_fuzzy", "turn armchair 2 toward the fireplace and push it a bit closer to it",
      [faces("SM_Armchair_02", "SM_Fireplace"), closer(S, "SM_Armchair_02", "SM_Fireplace", 0.05)],
      {"SM_Armchair_02": T(-0.4, yaw=yaw)})
    Q(S, "compositional_fuzzy", "lower the shelf a bit and move bottle 2 down to the counter",
      [dr("SM_Shelf_Wall_01", "-y", 0.03), dr("Prop_Bottle_01", "-y", 0.03), dr("Prop_Bottle_03", "-y", 0.03),
       ontop("Prop_Bottle_02", "SM_Bar_Counter")],
      dict(group(["SM_Shelf_Wall_01", "Prop_Bottle_01", "Prop_Bottle_03"], (0, -0.1, 0)),
           Prop_Bottle_02=T(*onto(S, "Prop_Bottle_02", "SM_Bar_Counter", -0.3, -4.1))))
    Q(S, "compositional_fuzzy", "move the last stool a bit to the right and put the deck of cards on it",
      [dr("SM_Stool_05", "+x"), ontop("Prop_Cards_Deck", "SM_Stool_05")],
      {"SM_Stool_05": T(0.3), "Prop_Cards_Deck": T(*to(S, "Prop_Cards_Deck", 0.9, 0.75, -3.2))})
    Q(S, "compositional_fuzzy", "could you move the side table a bit forward and spin the book on it 180?",
      [dr("SM_Table_Side_01", "+z"), dr("Prop_Book_Old", "+z"), rot("Prop_Book_Old", 180, True)],
      {"SM_Table_Side_01": T(dz=0.3), "Prop_Book_Old": T(dz=0.3, yaw=180)})
    ay = face_yaw(S, "SM_Armchair_01", "SM_Piano_Upright")
    Q(S, "compositional_fuzzy", "slide the floor lamp a bit closer to the armchairs and turn armchair 1 to face the piano",
      [closer(S, "BP_Lamp_Floor", "SM_Armchair_01", 0.05), closer(S, "BP_Lamp_Floor", "SM_Armchair_02", 0.05),
       faces("SM_Armchair_01", "SM_Piano_Upright")],
      {"BP_Lamp_Floor": T(0.6), "SM_Armchair_01": R(ay)})
    g = ["BP_Lamp_Wall_01", "BP_Lamp_Wall_02", "Prop_Painting_Stag"]
    Q(S, "compositional_fuzzy", "bring both wall lamps down a little, and the stag painting a bit lower too",
      [dr(n, "-y", 0.03) for n in g], group(g, (0, -0.1, 0)))
    Q(S, "compositional_fuzzy", "shift stool 3 a bit forward and put mug B on it",
      [dr("SM_Stool_03", "+z"), ontop("Prop_Mug_B", "SM_Stool_03")],
      {"SM_Stool_03": T(dz=0.3), "Prop_Mug_B": T(*to(S, "Prop_Mug_B", -1.0, 0.75, -2.9))})
    Q(S, "compositional_fuzzy", "move the chair at round table 2 a bit left and turn it",
      [refused(["SM_Chair_05", "SM_Chair_06", "SM_Chair_07", "SM_Chair_08"])])
    # ---- hard
    g = ["SM_Stool_01", "SM_Stool_02", "SM_Stool_04", "SM_Stool_05"]
    Q(S, "hard", "move every stool except the middle one 20 cm forward",
      [mv(n, [0, 0, 0.2]) for n in g], group(g, (0, 0, 0.2)))
    Q(S, "hard", "the table with the goblet on it: move it and its chairs 1 m toward the front",
      [mv(n, [0, 0, 1]) for n in t2], group(t2, (0, 0, 1)))
    Q(S, "hard", "put the mug which is on the same table as the plates onto the table the cards are on",
      [ontop("Prop_Mug_C", "Table_Round_02")],
      {"Prop_Mug_C": T(*onto(S, "Prop_Mug_C", "Table_Round_02", 0.35, 0.25))})
    Q(S, "hard", "swap the candle on the long table with the candelabra",
      [swapped("Prop_Candle_02", "Prop_Candelabra")],
      {"Prop_Candle_02": T(*to(S, "Prop_Candle_02", -2.0, 1.3, 4.68)),
       "Prop_Candelabra": T(*to(S, "Prop_Candelabra", 3.8, 0.75, 1.0))})
    Q(S, "hard", "rotate the chair across the table from SM_Chair_05 by 180°",
      [rot("SM_Chair_06", 180, True)], {"SM_Chair_06": R(180)})
    Q(S, "hard", "the wall lamp nearer the bar: 40cm down",
      [mv("BP_Lamp_Wall_01", [0, -0.4, 0])], {"BP_Lamp_Wall_01": T(dy=-0.4)})
    Q(S, "hard", "the barrel in front of the one with the candle on it, roll it 1 m to the left",
      [mv("SM_Barrel_03", [-1, 0, 0])], {"SM_Barrel_03": T(-1)})
    Q(S, "hard", "put the cards between the two plates",
      [between("Prop_Cards_Deck", "Prop_Plate_01", "Prop_Plate_02", 0.15), ontop("Prop_Cards_Deck", "Table_Long_Oak")],
      {"Prop_Cards_Deck": T(*onto(S, "Prop_Cards_Deck", "Table_Long_Oak", 3.55, 1.0))})
    g = ["SM_Chair_01", "SM_Chair_02", "SM_Chair_04"]
    Q(S, "hard", "all the chairs round table 1 except the one on the left: turn them 90° clockwise",
      [rot(n, -90) for n in g], {n: R(-90) for n in g})
    Q(S, "hard", "push the second stool from the left 6 inches toward the bar",
      [mv("SM_Stool_02", [0, 0, -6 * IN])], {"SM_Stool_02": T(dz=-6 * IN)})
    Q(S, "hard", "the chair at table 1 that faces right, move it back 30 cm",
      [mv("SM_Chair_03", [0, 0, -0.3])], {"SM_Chair_03": T(dz=-0.3)})
    Q(S, "hard", "put the floor lamp just right of the piano bench",
      [side("BP_Lamp_Floor", "SM_Bench_Piano", "right", 0.5)],
      {"BP_Lamp_Floor": T(*to(S, "BP_Lamp_Floor", -0.75, 0, 3.9))})
    Q(S, "hard", "put the goblet where the cards are and the cards where the goblet is",
      [swapped("Prop_Goblet_01", "Prop_Cards_Deck")],
      {"Prop_Goblet_01": T(*to(S, "Prop_Goblet_01", 0.35, 0.75, -0.1)),
       "Prop_Cards_Deck": T(*to(S, "Prop_Cards_Deck", 0.7, 0.75, 0.2))})
    Q(S, "hard", "rotate the bottle on the shelf 90°",
      [refused(["Prop_Bottle_01", "Prop_Bottle_02", "Prop_Bottle_03"])])
    Q(S, "hard", "move the table 1m to the right",
      [refused(["Table_Round_01", "Table_Round_02", "Table_Long_Oak", "SM_Table_Side_01"])])
    Q(S, "hard", "put Prop_Mug_E on the bar", [refused([])])


# ====================================================================== blender export
def blender_queries():
    S = "blender_export"
    bench = ["Cube.003", "mesh_17", "Object_3"]
    # ---- simple
    Q(S, "simple", "move Cube.004 50cm to the left",
      [mv("Cube.004", [-0.5, 0, 0])], {"Cube.004": T(-0.5)})
    Q(S, "simple", "rotate mesh_22 90 degrees clockwise",
      [rot("mesh_22", -90)], {"mesh_22": R(-90)})
    Q(S, "simple", "the mat on the floor: 1 m to the right",
      [mv("Plane.003", [1, 0, 0])], {"Plane.003": T(1)})
    Q(S, "simple", "raise the panel on the back wall by 25cm",
      [mv("Plane.002", [0, 0.25, 0])], {"Plane.002": T(dy=0.25)})
    Q(S, "simple", "scale Object_3 by 1.5",
      [sc("Object_3", 1.5)], {"Object_3": T(s=1.5)})
    Q(S, "simple", "push the tall thing in the front left corner 40 cm to the right",
      [mv("Object_7", [0.4, 0, 0])], {"Object_7": T(0.4)})
    Q(S, "simple", "could you lower the box on the left wall by 30 cm?",
      [mv("Cube.008", [0, -0.3, 0])], {"Cube.008": T(dy=-0.3)})
    Q(S, "simple", "turn the knee-high box in the back right corner 45°",
      [rot("Object_9", 45, True)], {"Object_9": R(45)})
    g = ["mesh_40", "Object_15"]
    Q(S, "simple", "move the long low bench along the front wall 2 ft back",
      [mv(n, [0, 0, -2 * FT]) for n in g], group(g, (0, 0, -2 * FT)))
    Q(S, "simple", "shrink the tall narrow cabinet by the door to 80%",
      [sc("Cube.004", 0.8)], {"Cube.004": T(s=0.8)})
    Q(S, "simple", "mesh_17 -> 20cm left",
      [mv("mesh_17", [-0.2, 0, 0])], {"mesh_17": T(-0.2)})
    Q(S, "simple", "move Object_12 one metre forward",
      [mv("Object_12", [0, 0, 1])], {"Object_12": T(dz=1)})
    g = ["Cube.005", "mesh_31"]
    Q(S, "simple", "Cube.005 30cm right",
      [mv(n, [0.3, 0, 0]) for n in g], group(g, (0.3, 0, 0)))
    Q(S, "simple", "turn Object_12 45 degrees counterclockwise",
      [rot("Object_12", 45)], {"Object_12": R(45)})
    Q(S, "simple", "move Cube.011 up 10 cm", [refused([])])
    Q(S, "simple", "move the sofa next to the door", [refused([])])
    # ---- compositional
    Q(S, "compositional", "move the table in the middle and everything on it 50cm right",
      [mv(n, [0.5, 0, 0]) for n in bench], group(bench, (0.5, 0, 0)))
    Q(S, "compositional", "put the little box from the low crate on top of the middle table, and move the crate 50 cm forward",
      [ontop("mesh_31", "Cube.003"), mv("Cube.005", [0, 0, 0.5])],
      {"mesh_31": T(*onto(S, "mesh_31", "Cube.003", 0.55, 0.0)), "Cube.005": T(dz=0.5)})
    Q(S, "compositional", "swap Cube.001 and Cube.002",
      [swapped("Cube.001", "Cube.002")], {"Cube.001": T(1.6), "Cube.002": T(-1.6)})
    Q(S, "compositional", "rotate the stack by the left wall 90 degrees and move it 1 m right",
      [rot("Cube.006", 90, True), mv("Cube.006", [1, 0, 0]), mv("Cube.007", [1, 0, 0])],
      {"Cube.006": T(1, yaw=90), "Cube.007": T(1, yaw=90)})
    Q(S, "compositional", "lift the panel on the left wall 20 cm and slide it 50 cm toward the back",
      [mv("Plane.004", [0, 0.2, -0.5])], {"Plane.004": T(0, 0.2, -0.5)})
    Q(S, "compositional", "move the tall skinny thing off the table onto the long low bench, and turn mesh_22 around",
      [ontop("Object_3", "mesh_40"), rot("mesh_22", 180, True)],
      {"Object_3": T(*onto(S, "Object_3", "mesh_40", 0.8, 3.2)), "mesh_22": R(180)})
    g = ["Cube.009", "mesh_5"]
    Q(S, "compositional", "Cube.009 plus whatever's on it: 1.5 m left",
      [mv(n, [-1.5, 0, 0]) for n in g], group(g, (-1.5, 0, 0)))
    Q(S, "compositional", "put the two small boxes from the top of the shelf onto the long low bench",
      [ontop("Cube.001", "mesh_40"), ontop("Cube.002", "mesh_40")],
      {"Cube.001": T(*onto(S, "Cube.001", "mesh_40", 0.5, 3.2)),
       "Cube.002": T(*onto(S, "Cube.002", "mesh_40", 1.0, 3.2))})
    Q(S, "compositional", "the panels on the back wall and on the left wall, both up 10 cm",
      [mv("Plane.002", [0, 0.1, 0]), mv("Plane.004", [0, 0.1, 0])],
      group(["Plane.002", "Plane.004"], (0, 0.1, 0)))
    Q(S, "compositional", "move the door 30 cm forward and the tall narrow cabinet next to it 30 cm forward too",
      [mv("Plane.001", [0, 0, 0.3]), mv("Cube.004", [0, 0, 0.3])],
      group(["Plane.001", "Cube.004"], (0, 0, 0.3)))
    Q(S, "compositional", "rotate every box on top of the shelf by 90 degrees",
      [rot("Cube.001", 90, True), rot("Cube.002", 90, True)], {"Cube.001": R(90), "Cube.002": R(90)})
    Q(S, "compositional", "move the small box on the shelf and the mat 1m to the left",
      [refused(["Cube.001", "Cube.002"])])
    # ---- fuzzy
    Q(S, "fuzzy", "nudge the tall narrow thing by the door a bit further away from the door",
      [further(S, "Cube.004", "Plane.001", 0.05)], {"Cube.004": T(dz=-0.4)})
    Q(S, "fuzzy", "shove the box in the back-right corner a bit forward",
      [dr("Object_9", "+z")], {"Object_9": T(dz=0.3)})
    Q(S, "fuzzy", "put the small thing that's sitting on the 60cm cube near the back onto the middle table",
      [ontop("mesh_5", "Cube.003")], {"mesh_5": T(*onto(S, "mesh_5", "Cube.003", 0.5, -0.2))})
    Q(S, "fuzzy", "move the chair-sized box a little closer to the table",
      [dr("mesh_22", "-z", 0.03)], {"mesh_22": T(dz=-0.1)})
    Q(S, "fuzzy", "the panel on the back wall should be centred above the knee-high box in the corner",
      [aligned("Plane.002", "Object_9", "x"), above("Plane.002", "Object_9")], {"Plane.002": T(1.7)})
    Q(S, "fuzzy", "move the low crate closer to the door",
      [closer(S, "Cube.005", "Plane.001", 0.3), ontop("mesh_31", "Cube.005")],
      group(["Cube.005", "mesh_31"], (3.0, 0, 0)))
    Q(S, "fuzzy", "put the little box from the crate next to the tall skinny thing",
      [nextto("mesh_31", "Object_3", 0.3)], {"mesh_31": T(*onto(S, "mesh_31", "Cube.003", 0.85, 0.1))})
    Q(S, "fuzzy", "push the mat a bit towrds the back wall",
      [dr("Plane.003", "-z")], {"Plane.003": T(dz=-0.3)})
    Q(S, "fuzzy", "Could the tall thing in the corner be turned to face the door?",
      [faces("Object_7", "Plane.001")], {"Object_7": R(face_yaw(S, "Object_7", "Plane.001"))})
    Q(S, "fuzzy", "I'd like the small box at the right end of the shelf moved a bit toward the middle of the shelf",
      [dr("Cube.002", "-x"), ontop("Cube.002", "Cube")], {"Cube.002": T(-0.4)})
    Q(S, "fuzzy", "put the flat thing that's on the low bench on top of the stack by the left wall",
      [ontop("Object_15", "Cube.007")], {"Object_15": T(*onto(S, "Object_15", "Cube.007"))})
    Q(S, "fuzzy", "bring the tall pole-like thing a bit closer to the corner box at the back right",
      [closer(S, "Object_12", "Object_9", 0.05)], {"Object_12": T(dz=-0.8)})
    Q(S, "fuzzy", "the little box on the low crate should go on the floor right beside the crate",
      [nextto("mesh_31", "Cube.005", 0.3)], {"mesh_31": T(*to(S, "mesh_31", -1.95, 0, 1.8))})
    Q(S, "fuzzy", "lower the flat panel on the wall a bit", [refused(["Plane.002", "Plane.004"])])
    Q(S, "fuzzy", "could the 60cm cube move a bit left?", [refused(["Cube.006", "Cube.009"])])
    # ---- compositional_fuzzy
    Q(S, "compositional_fuzzy", "slide the middle table a little toward the back along with whatever's on it, and turn the chair-looking box to face the door",
      [dr(n, "-z") for n in bench] + [faces("mesh_22", "Plane.001")],
      dict(group(bench, (0, 0, -0.3)), mesh_22=R(face_yaw(S, "mesh_22", "Plane.001"))))
    Q(S, "compositional_fuzzy", "give the knee-high box in the back corner a quarter turn and move it a bit toward the middle table",
      [rot("Object_9", 90, True), closer(S, "Object_9", "Cube.003", 0.05)],
      {"Object_9": T(-0.3, 0, 0.4, yaw=90)})
    st = ["Cube.006", "Cube.007"]
    Q(S, "compositional_fuzzy", "move the box on the left wall a bit higher and the stack under it a bit forward",
      [dr("Cube.008", "+y", 0.03)] + [dr(n, "+z") for n in st],
      dict(group(st, (0, 0, 0.3)), **{"Cube.008": T(dy=0.15)}))
    Q(S, "compositional_fuzzy", "put Object_15 on the squat box in the back-right corner and nudge the long low bench a bit to the left",
      [ontop("Object_15", "Object_9"), dr("mesh_40", "-x")],
      {"Object_15": T(*onto(S, "Object_15", "Object_9")), "mesh_40": T(-0.3)})
    Q(S, "compositional_fuzzy", "shift the tall narrow thing by the door a bit to the left and make it 10% smaller",
      [dr("Cube.004", "-x"), sc("Cube.004", 0.9)], {"Cube.004": T(-0.3, s=0.9)})
    Q(S, "compositional_fuzzy", "move both small boxes on the shelf a bit closer to each other",
      [dr("Cube.001", "+x"), dr("Cube.002", "-x"), ontop("Cube.001", "Cube"), ontop("Cube.002", "Cube")],
      {"Cube.001": T(0.3), "Cube.002": T(-0.3)})
    Q(S, "compositional_fuzzy", "turn the chair-ish box to face the long low bench and slide it a bit closer to it",
      [faces("mesh_22", "mesh_40"), closer(S, "mesh_22", "mesh_40", 0.05)],
      {"mesh_22": T(dz=0.5, yaw=180)})
    Q(S, "compositional_fuzzy", "move the crate a little to the right and put the pole thing right behind it",
      [dr("Cube.005", "+x"), dr("mesh_31", "+x"), side("Object_12", "Cube.005", "behind", 0.4)],
      dict(group(["Cube.005", "mesh_31"], (0.3, 0, 0)),
           Object_12=T(*to(S, "Object_12", -2.5, 0, 1.2))))
    Q(S, "compositional_fuzzy", "raise the panel on the left wall a little and slide the low crate a bit toward the back",
      [dr("Plane.004", "+y", 0.03), dr("Cube.005", "-z"), dr("mesh_31", "-z")],
      dict(group(["Cube.005", "mesh_31"], (0, 0, -0.3)), **{"Plane.004": T(dy=0.1)}))
    Q(S, "compositional_fuzzy", "move the pole-like thing a bit to the left and turn it 45 degrees",
      [dr("Object_12", "-x"), rot("Object_12", 45, True)], {"Object_12": T(-0.3, yaw=45)})
    Q(S, "compositional_fuzzy", "slide the 60cm cube near the back a bit to the right, keeping the little thing on it, and make that little thing twice as big",
      [dr("Cube.009", "+x"), dr("mesh_5", "+x"), sc("mesh_5", 2)],
      {"Cube.009": T(0.3), "mesh_5": T(0.3, s=2)})
    Q(S, "compositional_fuzzy", "move the tall box a bit right and put the knee-high one next to it",
      [refused(["Cube.004", "Object_7"])])
    # ---- hard
    Q(S, "hard", "move the tallest object 1 m toward the back wall",
      [mv("Cube.004", [0, 0, -1])], {"Cube.004": T(dz=-1)})
    Q(S, "hard", "the box that's on top of the other box by the left wall: move it onto the long low bench",
      [ontop("Cube.007", "mesh_40")], {"Cube.007": T(*onto(S, "Cube.007", "mesh_40", 0.9, 3.2))})
    Q(S, "hard", "move everything on the middle table to the long low bench",
      [ontop("mesh_17", "mesh_40"), ontop("Object_3", "mesh_40")],
      {"mesh_17": T(*onto(S, "mesh_17", "mesh_40", 0.6, 3.2)),
       "Object_3": T(*onto(S, "Object_3", "mesh_40", 1.1, 3.2))})
    Q(S, "hard", "put the knee-high box from the back-right corner between the middle table and the door",
      [between("Object_9", "Cube.003", "Plane.001", 0.3)], {"Object_9": T(*to(S, "Object_9", 2.24, 0, 1.2))})
    Q(S, "hard", "put the pole-looking thing directly behind the tall narrow cabinet",
      [side("Object_12", "Cube.004", "behind", 0.5)], {"Object_12": T(*to(S, "Object_12", 3.55, 0, 0.8))})
    Q(S, "hard", "put the thing standing on the table (not the box) onto the 60cm cube nearest the back wall",
      [ontop("Object_3", "Cube.009")], {"Object_3": T(*onto(S, "Object_3", "Cube.009", 1.78, -1.82))})
    Q(S, "hard", "the flat thing lying on the floor, rotate it 90° and move it 50 cm left",
      [rot("Plane.003", 90, True), mv("Plane.003", [-0.5, 0, 0])], {"Plane.003": T(-0.5, yaw=90)})
    Q(S, "hard", "swap the positions of the tall thing in the corner and the tall narrow cabinet by the door",
      [swapped("Object_7", "Cube.004")],
      {"Object_7": T(*to(S, "Object_7", 3.55, 0, 1.3)), "Cube.004": T(*to(S, "Cube.004", -3.6, 0, 3.1))})
    Q(S, "hard", "put mesh_5 on the left-hand small box on top of the shelf",
      [ontop("mesh_5", "Cube.001")], {"mesh_5": T(*onto(S, "mesh_5", "Cube.001"))})
    st = ["Cube.006", "Cube.007"]
    Q(S, "hard", "move the stack, both boxes, so it stands just to the right of the low crate",
      [side("Cube.006", "Cube.005", "right", 0.5), ontop("Cube.007", "Cube.006")],
      group(st, to(S, "Cube.006", -1.75, 0, 1.8)))
    Q(S, "hard", "whatever is hanging on the left wall above the stack - 15cm up",
      [mv("Cube.008", [0, 0.15, 0])], {"Cube.008": T(dy=0.15)})
    Q(S, "hard", "put the knee-high box from the back-right corner under the panel on the left wall",
      [{"check": "below", "object": "Object_9", "other": "Plane.004"},
       aligned("Object_9", "Plane.004", "z", 0.35),
       {"check": "distance", "object": "Object_9", "other": "Plane.004", "max": 1.4}],
      {"Object_9": T(*to(S, "Object_9", -3.7, 0, 1.6))})
    Q(S, "hard", "rotate the plant by the door", [refused([])])
    Q(S, "hard", "move Object_5 to the left", [refused([])])
    Q(S, "hard", "grab the little cube off the top of the shelving and set it on the middle table",
      [refused(["Cube.001", "Cube.002"])])


# ====================================================================== clinic ward
def ward_queries():
    S = "clinic_ward"
    BT = lambda n: f"Bedside Table {n}"
    station = ["Nurses Station", "Monitor", "Phone", "Clipboard"]
    cart = ["Medicine Cart", "Pill Organizer", "Thermometer"]
    # ---- simple
    Q(S, "simple", "move bed 2 forward 30 cm",
      [mv("Bed 2", [0, 0, 0.3]), mv("Tablet", [0, 0, 0.3])], group(["Bed 2", "Tablet"], (0, 0, 0.3)))
    Q(S, "simple", "rotate visitor chair 2 by 90 degrees counter-clockwise",
      [rot("Visitor Chair 2", 90)], {"Visitor Chair 2": R(90)})
    Q(S, "simple", "raise teh TV 20cm",
      [mv("TV", [0, 0.2, 0])], {"TV": T(dy=0.2)})
    Q(S, "simple", "IV stand 3 -> 50cm left",
      [mv("IV Stand 3", [-0.5, 0, 0])], {"IV Stand 3": T(-0.5)})
    Q(S, "simple", "push the wheelchair 1 m forward",
      [mv("Wheelchair", [0, 0, 1])], {"Wheelchair": T(dz=1)})
    Q(S, "simple", "make the vase of flowers 25% bigger",
      [sc("Vase of Flowers", 1.25)], {"Vase of Flowers": T(s=1.25)})
    Q(S, "simple", "move the linen hamper 18 inches back",
      [mv("Linen Hamper", [0, 0, -18 * IN])], {"Linen Hamper": T(dz=-18 * IN)})
    Q(S, "simple", "lower the wall clock by 15cm",
      [mv("Wall Clock", [0, -0.15, 0])], {"Wall Clock": T(dy=-0.15)})
    Q(S, "simple", "turn the office chair 180°",
      [rot("Office Chair", 180, True)], {"Office Chair": R(180)})
    Q(S, "simple", "shift the waste bin 40cm to the right",
      [mv("Waste Bin", [0.4, 0, 0])], {"Waste Bin": T(0.4)})
    Q(S, "simple", "Scale the pill organizer by 0.5",
      [sc("Pill Organizer", 0.5)], {"Pill Organizer": T(s=0.5)})
    Q(S, "simple", "move the visitor chair by bed 3 one metre to the right",
      [mv("Visitor Chair 3", [1, 0, 0])], {"Visitor Chair 3": T(1)})
    Q(S, "simple", "move the defibrillator to the left", [refused([])])
    Q(S, "simple", "raise bed 7 a bit", [refused([])])
    # ---- compositional
    g = ["Bed 3", BT(3), "Vase of Flowers", "Get Well Card"]
    Q(S, "compositional", "move bed 3 and its bedside table 40cm back",
      [mv(n, [0, 0, -0.4]) for n in g], group(g, (0, 0, -0.4)))
    Q(S, "compositional", "swap visitor chairs 1 and 3",
      [swapped("Visitor Chair 1", "Visitor Chair 3")],
      {"Visitor Chair 1": T(dz=7.15), "Visitor Chair 3": T(dz=-7.15)})
    Q(S, "compositional", "put the water jug on bedside table 2 and the plastic cup on bedside table 4",
      [ontop("Water Jug", BT(2)), ontop("Plastic Cup", BT(4))],
      {"Water Jug": T(*onto(S, "Water Jug", BT(2))), "Plastic Cup": T(*onto(S, "Plastic Cup", BT(4)))})
    Q(S, "compositional", "move the medicine cart 1 m to the right with everything on it, and the wheelchair 1 m forward",
      [mv(n, [1, 0, 0]) for n in cart] + [mv("Wheelchair", [0, 0, 1])],
      dict(group(cart, (1, 0, 0)), Wheelchair=T(dz=1)))
    Q(S, "compositional", "spin bed 4 round 180 degrees and push IV stand 2 30 cm to the left",
      [rot("Bed 4", 180, True), mv("IV Stand 2", [-0.3, 0, 0])], {"Bed 4": R(180), "IV Stand 2": T(-0.3)})
    Q(S, "compositional", "raise the window 10 cm and the TV 10 cm",
      [mv("Window", [0, 0.1, 0]), mv("TV", [0, 0.1, 0])], group(["Window", "TV"], (0, 0.1, 0)))
    g = station + ["Office Chair"]
    Q(S, "compositional", "move the nurses station (with its stuff) and the office chair 50 cm back",
      [mv(n, [0, 0, -0.5]) for n in g], group(g, (0, 0, -0.5)))
    Q(S, "compositional", "put the tablet on the nurses station and the clipboard on bed 2",
      [ontop("Tablet", "Nurses Station"), ontop("Clipboard", "Bed 2")],
      {"Tablet": T(*onto(S, "Tablet", "Nurses Station", 0.0, 4.75)),
       "Clipboard": T(*onto(S, "Clipboard", "Bed 2", -3.5, 0.0))})
    Q(S, "compositional", "move visitor chair 2 60 cm left and rotate it 90° clockwise",
      [mv("Visitor Chair 2", [-0.6, 0, 0]), rot("Visitor Chair 2", -90)], {"Visitor Chair 2": T(-0.6, yaw=-90)})
    Q(S, "compositional", "Bed 1: 15 cm right, 10 cm forward",
      [mv("Bed 1", [0.15, 0, 0.1])], {"Bed 1": T(0.15, 0, 0.1)})
    Q(S, "compositional", "put the thermometer on bedside table 6 and rotate the tissue box 90°",
      [ontop("Thermometer", BT(6)), rot("Tissue Box", 90, True)],
      {"Thermometer": T(*onto(S, "Thermometer", BT(6), 4.55, 2.7)), "Tissue Box": R(90)})
    Q(S, "compositional", "move the IV stand and bed 2 forward 1 m",
      [refused(["IV Stand 1", "IV Stand 2", "IV Stand 3"])])
    # ---- fuzzy
    Q(S, "fuzzy", "nudge the wheelchiar a little to the left",
      [dr("Wheelchair", "-x")], {"Wheelchair": T(-0.3)})
    Q(S, "fuzzy", "could bed 5 move a bit toward the middle of the ward?",
      [dr("Bed 5", "-x")], {"Bed 5": T(-0.3)})
    Q(S, "fuzzy", "put the tissue box next to the reading glasses",
      [nextto("Tissue Box", "Reading Glasses", 0.3)],
      {"Tissue Box": T(*onto(S, "Tissue Box", BT(5), 4.7, -0.93))})
    Q(S, "fuzzy", "the office chair should be a bit further from the desk",
      [further(S, "Office Chair", "Nurses Station", 0.05)], {"Office Chair": T(1.0)})
    Q(S, "fuzzy", "slide IV stand 1 a bit closer to bed 1",
      [closer(S, "IV Stand 1", "Bed 1", 0.03)], {"IV Stand 1": T(dz=0.1)})
    Q(S, "fuzzy", "can the TV go a little to the left?",
      [dr("TV", "-x")], {"TV": T(-0.3)})
    Q(S, "fuzzy", "put the reading glasses on the bed they belong to",
      [ontop("Reading Glasses", "Bed 5")], {"Reading Glasses": T(*onto(S, "Reading Glasses", "Bed 5"))})
    Q(S, "fuzzy", "move the hand sanitizer a bit higher up the wall",
      [dr("Hand Sanitizer", "+y", 0.03)], {"Hand Sanitizer": T(dy=0.15)})
    Q(S, "fuzzy", "push visitor chair 3 a bit closer to the bed",
      [dr("Visitor Chair 3", "-z", 0.03)], {"Visitor Chair 3": T(dz=-0.15)})
    Q(S, "fuzzy", "the blanket should go on bed 4",
      [ontop("Folded Blanket", "Bed 4")], {"Folded Blanket": T(*onto(S, "Folded Blanket", "Bed 4", 3.4, -3.5))})
    Q(S, "fuzzy", "bring the wheelchair over next to bed 2",
      [nextto("Wheelchair", "Bed 2", 0.5)], {"Wheelchair": T(*to(S, "Wheelchair", -2.3, 0, 0.0))})
    Q(S, "fuzzy", "turn bed 1's visitor chair to face the window",
      [faces("Visitor Chair 1", "Window")], {"Visitor Chair 1": R(face_yaw(S, "Visitor Chair 1", "Window"))})
    Q(S, "fuzzy", "centre the TV over the medicine cart",
      [aligned("TV", "Medicine Cart", "x"), above("TV", "Medicine Cart")], {"TV": T(-1.2)})
    Q(S, "fuzzy", "give the nurse some room - slide the office chair a bit to the right",
      [dr("Office Chair", "+x")], {"Office Chair": T(0.4)})
    Q(S, "fuzzy", "put the hamper by the door", [refused([])])
    Q(S, "fuzzy", "move the chair a bit closer to bed 2",
      [refused(["Visitor Chair 1", "Visitor Chair 2", "Visitor Chair 3", "Office Chair"])])
    # ---- compositional_fuzzy
    Q(S, "compositional_fuzzy", "push bed 6 a little toward the front wall and move its blanket onto bed 5",
      [dr("Bed 6", "+z"), ontop("Folded Blanket", "Bed 5")],
      {"Bed 6": T(dz=0.3), "Folded Blanket": T(*onto(S, "Folded Blanket", "Bed 5"))})
    Q(S, "compositional_fuzzy", "shift the medicine cart a bit to the left, and put the thermometer on the nurses station",
      [dr("Medicine Cart", "-x"), dr("Pill Organizer", "-x"), ontop("Thermometer", "Nurses Station")],
      {"Medicine Cart": T(-0.4), "Pill Organizer": T(-0.4),
       "Thermometer": T(*onto(S, "Thermometer", "Nurses Station", 0.0, 4.75))})
    Q(S, "compositional_fuzzy", "slide the wheelchair a bit to the right and turn it 90° anticlockwise",
      [dr("Wheelchair", "+x"), rot("Wheelchair", 90)], {"Wheelchair": T(0.3, yaw=90)})
    Q(S, "compositional_fuzzy", "pull IV stands 1 and 2 a little away from their beds",
      [further(S, "IV Stand 1", "Bed 1", 0.05), further(S, "IV Stand 2", "Bed 4", 0.05)],
      {"IV Stand 1": T(dz=-0.3), "IV Stand 2": T(dz=-0.3)})
    Q(S, "compositional_fuzzy", "put the get-well card on bed 3 and push visitor chair 3 a bit to the left",
      [ontop("Get Well Card", "Bed 3"), dr("Visitor Chair 3", "-x")],
      {"Get Well Card": T(*onto(S, "Get Well Card", "Bed 3")), "Visitor Chair 3": T(-0.3)})
    wy = face_yaw(S, "Wheelchair", "Bed 4", (1.7, -4.8))
    Q(S, "compositional_fuzzy", "rotate the wheelchair to face bed 4 and push it a bit toward it",
      [faces("Wheelchair", "Bed 4"), closer(S, "Wheelchair", "Bed 4", 0.1)],
      {"Wheelchair": T(0.5, 0, 0.5, yaw=wy)})
    Q(S, "compositional_fuzzy", "bring bed 2 a bit out from the wall and put the tablet on its bedside table",
      [dr("Bed 2", "+x"), ontop("Tablet", BT(2))],
      {"Bed 2": T(0.3), "Tablet": T(*onto(S, "Tablet", BT(2)))})
    Q(S, "compositional_fuzzy", "move the tablet from bed 2 onto bed 1 and pull visitor chair 1 forward a bit",
      [ontop("Tablet", "Bed 1"), dr("Visitor Chair 1", "+z")],
      {"Tablet": T(*onto(S, "Tablet", "Bed 1")), "Visitor Chair 1": T(dz=0.3)})
    Q(S, "compositional_fuzzy", "could the phone go a little to the right and the monitor a little to the left?",
      [dr("Phone", "+x"), dr("Monitor", "-x"), ontop("Phone", "Nurses Station"), ontop("Monitor", "Nurses Station")],
      {"Phone": T(0.2), "Monitor": T(-0.2)})
    vy = face_yaw(S, "Visitor Chair 2", "Bed 6", (3.5, 0.9))
    Q(S, "compositional_fuzzy", "move visitor chair 2 a little to the right and turn it to face bed 6",
      [dr("Visitor Chair 2", "+x"), faces("Visitor Chair 2", "Bed 6")], {"Visitor Chair 2": T(0.2, yaw=vy)})
    Q(S, "compositional_fuzzy", "lower the window a bit and push the hamper a little further along the wall toward bed 1",
      [dr("Window", "-y", 0.03), closer(S, "Linen Hamper", "Bed 1", 0.05)], {"Window": T(dy=-0.1), "Linen Hamper": T(dz=-0.3)})
    Q(S, "compositional_fuzzy", "shift bedside table 6 a bit back and put the tissue box from it onto bed 6",
      [dr(BT(6), "-z"), ontop("Tissue Box", "Bed 6")],
      {BT(6): T(dz=-0.3), "Tissue Box": T(*onto(S, "Tissue Box", "Bed 6", 4.2, 3.5))})
    Q(S, "compositional_fuzzy", "move the bedside table a bit to the right and put the jug on it",
      [refused([BT(n) for n in range(1, 7)])])
    # ---- hard
    g = ["Bed 1", "Bed 2", "Bed 3", BT(1), BT(2), BT(3), "Water Jug", "Plastic Cup",
         "Vase of Flowers", "Get Well Card", "Tablet"]
    Q(S, "hard", "move every bed on the left side 50 cm toward the middle of the room, with their bedside tables and whatever is on them",
      [mv(n, [0.5, 0, 0]) for n in g], group(g, (0.5, 0, 0)))
    Q(S, "hard", "the bed with the blanket on it: move it 30 cm forward, blanket and all",
      [mv("Bed 6", [0, 0, 0.3]), mv("Folded Blanket", [0, 0, 0.3])],
      group(["Bed 6", "Folded Blanket"], (0, 0, 0.3)))
    Q(S, "hard", "put the jug on the bedside table of the bed across the aisle from bed 1",
      [ontop("Water Jug", BT(4))], {"Water Jug": T(*onto(S, "Water Jug", BT(4)))})
    g = ["Visitor Chair 1", "Visitor Chair 3"]
    Q(S, "hard", "turn every visitor chair except number 2 to face the TV",
      [faces(n, "TV") for n in g], {n: R(face_yaw(S, n, "TV")) for n in g})
    Q(S, "hard", "put the phone between the monitor and the clipboard",
      [between("Phone", "Monitor", "Clipboard", 0.15), ontop("Phone", "Nurses Station")],
      {"Phone": T(*onto(S, "Phone", "Nurses Station", 0.15, 4.95))})
    g = [BT(4), BT(5), BT(6), "Reading Glasses", "Tissue Box"]
    Q(S, "hard", "bedside tables 4-6: 4 inches back",
      [mv(n, [0, 0, -4 * IN]) for n in g], group(g, (0, 0, -4 * IN)))
    Q(S, "hard", "the chair that's facing bed 5: move it 40 cm to the right",
      [mv("Visitor Chair 2", [0.4, 0, 0])], {"Visitor Chair 2": T(0.4)})
    Q(S, "hard", "the middle bed on the right side - put the reading glasses on it and push it 20 cm toward the aisle",
      [mv("Bed 5", [-0.2, 0, 0]), ontop("Reading Glasses", "Bed 5")],
      {"Bed 5": T(-0.2), "Reading Glasses": T(*onto(S, "Reading Glasses", "Bed 5", 3.7, 0.0))})
    Q(S, "hard", "put the jug next to the vase",
      [nextto("Water Jug", "Vase of Flowers", 0.3)],
      {"Water Jug": T(*onto(S, "Water Jug", BT(3), -4.75, 2.86))})
    Q(S, "hard", "move the cart that has the thermometer on it 2 feet forward",
      [mv(n, [0, 0, 2 * FT]) for n in cart], group(cart, (0, 0, 2 * FT)))
    g = [BT(1), BT(2), BT(3), "Water Jug", "Plastic Cup", "Vase of Flowers", "Get Well Card"]
    Q(S, "hard", "every bedside table on the left side: 5 cm away from the wall",
      [mv(n, [0.05, 0, 0]) for n in g], group(g, (0.05, 0, 0)))
    Q(S, "hard", "move the hamper to the foot of bed 1",
      [side("Linen Hamper", "Bed 1", "right", 0.5)], {"Linen Hamper": T(*to(S, "Linen Hamper", -2.45, 0, -3.5))})
    Q(S, "hard", "move the bed by the window 30 cm forward", [refused(["Bed 1", "Bed 2"])])
    Q(S, "hard", "rotate the radiator 90 degrees", [refused([])])
    Q(S, "hard", "put the tablet on the bed on the right",
      [refused(["Bed 4", "Bed 5", "Bed 6"])])


# ====================================================================== output
def main():
    here = os.path.dirname(os.path.abspath(__file__))
    files = {"exam_hall": "exam_hall.json", "tavern": "tavern.json",
             "blender_export": "blender_export.json", "clinic_ward": "clinic_ward.json"}
    for s, fn in files.items():
        sc = SCENES[s]()
        lines = ",\n".join("    " + json.dumps(o) for o in sc["objects"])
        with open(os.path.join(here, fn), "w") as f:
            f.write('{\n  "name": %s,\n  "bounds": %s,\n  "objects": [\n%s\n  ]\n}\n'
                    % (json.dumps(sc["name"]), json.dumps(sc["bounds"]), lines))
    exam_queries()
    tavern_queries()
    blender_queries()
    ward_queries()
    short = {"exam_hall": "exam", "tavern": "tavern", "blender_export": "dcc", "clinic_ward": "ward"}
    counters = {}
    queries, answers = [], {}
    for scene, cat, text, checks, ans in QUERIES:
        k = (scene, cat)
        counters[k] = counters.get(k, 0) + 1
        qid = f"{short[scene]}-{cat.replace('compositional_fuzzy', 'compfuzzy')}-{counters[k]:02d}"
        expect = list(checks)
        if ans:
            # an object that is only turned or scaled must stay where it is
            placing = {"moved", "direction", "on_top", "next_to", "side", "between", "aligned",
                       "at", "distance", "swapped", "above", "below"}
            for o, a in ans.items():
                kinds = {c["check"] for c in checks if c.get("object") == o or
                         (c["check"] == "swapped" and c.get("other") == o)}
                if kinds and not kinds & placing and not any(a.get("t", [0, 0, 0])):
                    expect.append(mv(o, [0, 0, 0]))
        if not any(c["check"] == "refused" for c in checks):
            expect += [{"check": "no_collision"}, {"check": "unchanged", "objects": "others"}]
            answers[qid] = ans
        queries.append({"id": qid, "category": cat, "text": text, "scenes": [scene], "expect": expect})
    suite = {"name": "holdout6", "scenes": [files[s] for s in files], "variations": 1, "seed": 6,
             "queries": queries}
    head = json.dumps({k: v for k, v in suite.items() if k != "queries"}, ensure_ascii=False)[:-1]
    body = ",\n".join("  " + json.dumps(q, ensure_ascii=False) for q in queries)
    with open(os.path.join(here, "holdout6.suite.json"), "w") as f:
        f.write(head + ',\n "queries": [\n' + body + "\n ]\n}\n")
    with open(os.path.join(here, "holdout6.answers.json"), "w") as f:
        json.dump(answers, f, indent=1)
        f.write("\n")
    print(f"wrote {len(queries)} queries, {len(answers)} answers")


if __name__ == "__main__":
    main()
