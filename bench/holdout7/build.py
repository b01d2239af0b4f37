#!/usr/bin/env python3
"""Builds the holdout7 benchmark: four scenes, holdout7.suite.json and
holdout7.answers.json (hand-worked expected motions, read only by validate.py).

Python 3 standard library only.  Run:  python3 build.py

Conventions (SPEC sections 1, 2, 6): metres, +Y up, right = +X, forward = +Z,
each object's position is the bottom centre of its box, rotations are
quaternions [x, y, z, w] about +Y only; +yaw = counter-clockwise seen from above.
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


# ----------------------------------------------------------------------------
# scene helpers
# ----------------------------------------------------------------------------
def yawq(deg):
    h = math.radians(deg) / 2.0
    return [0.0, round(math.sin(h), 6), 0.0, round(math.cos(h), 6)]


def obj(name, pos, size, yaw=0.0, on=None, category=None, **extra):
    o = {"name": name, "position": [float(v) for v in pos],
         "size": [float(v) for v in size], "rotation": yawq(yaw), "scale": 1.0}
    if category:
        o["category"] = category
    if on:
        o["on"] = on
    o.update(extra)
    return o


def scene(name, bmin, bmax, objects, **extra):
    s = {"name": name, "bounds": {"min": bmin, "max": bmax}}
    s.update(extra)
    s["objects"] = objects
    return s


# ---------------------------------------------------------------- boardroom
BOARD = scene("boardroom", [-5, 0, -4], [5, 3, 4], [
    obj("Conference Table", [0, 0, 0], [4.8, 0.75, 1.4], category="table"),
    # back (far) side, left to right, facing the table (+Z)
    obj("Chair 01", [-1.8, 0, -1.15], [0.6, 1.0, 0.6], 0, category="chair"),
    obj("Chair 02", [-0.9, 0, -1.15], [0.6, 1.0, 0.6], 0, category="chair"),
    obj("Chair 03", [0.0, 0, -1.15], [0.6, 1.0, 0.6], 0, category="chair"),
    obj("Chair 04", [0.9, 0, -1.15], [0.6, 1.0, 0.6], 0, category="chair"),
    obj("Chair 05", [1.8, 0, -1.15], [0.6, 1.0, 0.6], 0, category="chair"),
    # right end, facing -X
    obj("Chair 06", [2.95, 0, 0.0], [0.6, 1.0, 0.6], -90, category="chair"),
    # near side, right to left, facing the table (-Z)
    obj("Chair 07", [1.8, 0, 1.15], [0.6, 1.0, 0.6], 180, category="chair"),
    obj("Chair 08", [0.9, 0, 1.15], [0.6, 1.0, 0.6], 180, category="chair"),
    obj("Chair 09", [0.0, 0, 1.15], [0.6, 1.0, 0.6], 180, category="chair"),
    obj("Chair 10", [-0.9, 0, 1.15], [0.6, 1.0, 0.6], 180, category="chair"),
    obj("Chair 11", [-1.8, 0, 1.15], [0.6, 1.0, 0.6], 180, category="chair"),
    # left end, facing +X
    obj("Chair 12", [-2.95, 0, 0.0], [0.6, 1.0, 0.6], 90, category="chair"),
    obj("Credenza", [0, 0, -3.75], [2.0, 0.75, 0.5], category="cabinet"),
    obj("Coffee Machine", [-0.6, 0.75, -3.75], [0.3, 0.4, 0.35], on="Credenza", category="appliance"),
    obj("Small Succulent", [0.7, 0.75, -3.75], [0.12, 0.15, 0.12], on="Credenza", category="plant"),
    obj("Display Screen", [-4.96, 1.0, 0.0], [1.8, 1.05, 0.08], 90, category="tv"),
    obj("Whiteboard", [4.975, 0.9, 0.0], [2.0, 1.2, 0.05], -90, category="whiteboard"),
    obj("Flipchart", [3.8, 0, 2.8], [0.7, 1.8, 0.6], 180, category="easel"),
    obj("Coat Stand", [-4.6, 0, -3.6], [0.5, 1.8, 0.5], category="coat rack"),
    obj("Water Cooler", [4.6, 0, 3.4], [0.35, 1.1, 0.35], category="appliance"),
    obj("Fiddle Leaf Fig", [4.5, 0, -3.5], [0.7, 1.8, 0.7], category="plant"),
    obj("Snake Plant", [-4.6, 0, 3.6], [0.4, 0.9, 0.4], category="plant"),
    obj("Bin", [-4.6, 0, -2.6], [0.3, 0.35, 0.3], category="bin"),
    obj("Laptop", [-1.8, 0.75, -0.4], [0.34, 0.02, 0.24], on="Conference Table", category="laptop"),
    obj("Water Jug", [0, 0.75, 0], [0.15, 0.25, 0.15], on="Conference Table", category="jug"),
    obj("Glass 1", [-0.9, 0.75, 0.45], [0.08, 0.12, 0.08], on="Conference Table", category="glass"),
    obj("Glass 2", [0.9, 0.75, -0.45], [0.08, 0.12, 0.08], on="Conference Table", category="glass"),
    obj("Glass 3", [1.8, 0.75, 0.45], [0.08, 0.12, 0.08], on="Conference Table", category="glass"),
    obj("Conference Phone", [1.2, 0.75, 0.0], [0.25, 0.05, 0.25], on="Conference Table", category="phone"),
    obj("Notepad", [0.0, 0.75, 0.45], [0.21, 0.01, 0.3], on="Conference Table", category="notepad"),
])

# ------------------------------------------------------------ maya studio
# Exported from Maya: names carry no meaning.  What each box is (for the
# reader of this file only): polySurface12 backdrop panel, pPlane1 floor mat,
# pCube3 posing block, pCylinder7 posing stool, pCylinder3/4 light stands,
# group4_mesh camera on tripod, pCube1 big work table, pCube2 small box on it,
# pSphere1 ball on it, pCube6 cart, pCylinder6 mug, pTorus1 ring, pCube4 tall
# locker, polySurface7 sofa, pCube7/pCube8 crate stack, pCone1 cone prop,
# pSphere2 big ball, pCube11 small box on the floor, pCube9 long low bench.
STUDIO = scene("studio", [-6, 0, -5], [6, 4, 5], [
    obj("polySurface12", [0, 0, -4.85], [3.0, 2.8, 0.1]),
    obj("pPlane1", [0, 0, -3.3], [3.0, 0.02, 2.4]),
    obj("pCube3", [0.4, 0.02, -3.3], [0.5, 0.45, 0.5], on="pPlane1"),
    obj("pCylinder7", [-0.6, 0.02, -3.3], [0.4, 0.7, 0.4], on="pPlane1"),
    obj("pCylinder3", [-2.5, 0, -2.5], [0.5, 2.2, 0.5]),
    obj("pCylinder4", [2.5, 0, -2.5], [0.5, 2.2, 0.5]),
    obj("group4_mesh", [0, 0, 1.5], [0.6, 1.6, 0.6], 180),
    obj("pCube1", [-3.5, 0, 2.5], [2.0, 0.9, 1.0]),
    obj("pCube2", [-3.9, 0.9, 2.5], [0.3, 0.2, 0.3], on="pCube1"),
    obj("pSphere1", [-3.0, 0.9, 2.6], [0.25, 0.25, 0.25], on="pCube1"),
    obj("pCube6", [2.5, 0, 2.5], [0.6, 0.75, 0.45]),
    obj("pCylinder6", [2.35, 0.75, 2.5], [0.09, 0.1, 0.09], on="pCube6"),
    obj("pTorus1", [2.6, 0.75, 2.5], [0.25, 0.05, 0.25], on="pCube6"),
    obj("pCube4", [5.6, 0, -1.0], [0.6, 2.0, 0.5]),
    obj("polySurface7", [3.5, 0, 4.45], [2.0, 0.8, 0.9], 180),
    obj("pCube7", [-5.5, 0, -1.0], [0.6, 0.4, 0.4]),
    obj("pCube8", [-5.5, 0.4, -1.0], [0.5, 0.35, 0.35], on="pCube7"),
    obj("pCone1", [-1.5, 0, 0.0], [0.3, 0.5, 0.3]),
    obj("pSphere2", [1.5, 0, 0.0], [0.65, 0.65, 0.65]),
    obj("pCube11", [-2.0, 0, 3.8], [0.3, 0.3, 0.3]),
    obj("pCube9", [-5.7, 0, 2.0], [0.45, 0.45, 1.8]),
], source="Maya 2024 (FBX, converted to Y-up metres)")

# ---------------------------------------------------------- unreal patio
PATIO = scene("patio", [-7, 0, -6], [7, 5, 6], [
    obj("SM_Lounger_01", [-4.0, 0, 1.0], [0.7, 0.4, 2.0]),
    obj("SM_Lounger_02", [-2.8, 0, 1.0], [0.7, 0.4, 2.0]),
    obj("SM_SideTable_Wood", [-3.4, 0, 0.4], [0.45, 0.5, 0.45]),
    obj("SM_Lantern_01", [-3.4, 0.5, 0.4], [0.2, 0.4, 0.2], on="SM_SideTable_Wood"),
    obj("SM_Parasol_A", [-5.2, 0, 1.0], [0.45, 2.4, 0.45]),
    obj("SM_DiningTable_Teak", [2.5, 0, -2.0], [1.8, 0.75, 0.9]),
    obj("SM_DiningChair_01", [2.0, 0, -2.85], [0.5, 0.9, 0.55], 0),
    obj("SM_DiningChair_02", [3.0, 0, -2.85], [0.5, 0.9, 0.55], 0),
    obj("SM_DiningChair_03", [2.0, 0, -1.15], [0.5, 0.9, 0.55], 180),
    obj("SM_DiningChair_04", [3.0, 0, -1.15], [0.5, 0.9, 0.55], 180),
    obj("SM_Bottle_Wine", [2.2, 0.75, -2.0], [0.08, 0.3, 0.08], on="SM_DiningTable_Teak"),
    obj("SM_Glass_01", [2.8, 0.75, -2.25], [0.07, 0.15, 0.07], on="SM_DiningTable_Teak"),
    obj("SM_Glass_02", [2.8, 0.75, -1.75], [0.07, 0.15, 0.07], on="SM_DiningTable_Teak"),
    obj("SM_Parasol_B", [4.2, 0, -2.0], [0.45, 2.4, 0.45]),
    obj("BP_Planter_Large_01", [-6.4, 0, -5.4], [1.0, 0.8, 1.0]),
    obj("BP_Planter_Large_02", [6.4, 0, -5.4], [1.0, 0.8, 1.0]),
    obj("BP_Planter_Small_01", [0.0, 0, -5.6], [0.5, 0.5, 0.5]),
    obj("SM_WateringCan", [1.0, 0, -5.6], [0.5, 0.3, 0.2]),
    obj("SM_BBQ_Grill", [6.3, 0, 1.0], [1.2, 1.1, 0.6], -90),
    obj("SM_FirePit_Round", [0.0, 0, 2.5], [1.0, 0.4, 1.0]),
    obj("SM_OutdoorSofa", [0.0, 0, 4.6], [2.0, 0.8, 0.85], 180),
    obj("SM_Armchair_Rattan_01", [-1.8, 0, 2.5], [0.8, 0.8, 0.8], 90),
    obj("SM_Armchair_Rattan_02", [1.8, 0, 2.5], [0.8, 0.8, 0.8], -90),
    obj("SM_GardenBench_Stone", [-6.6, 0, -2.0], [1.6, 0.45, 0.5], 90),
    obj("SM_HoseReel", [6.5, 0, -3.0], [0.5, 0.6, 0.4]),
], source="Unreal Engine 5 level export (converted to right-handed Y-up metres)")

# -------------------------------------------------------------- laboratory
_lab = []
for row, z in (("A", -2.0), ("B", 1.0)):
    for i, x in enumerate((-3.0, 0.0, 3.0), start=1):
        _lab.append(obj("Bench %s%d" % (row, i), [x, 0, z], [2.0, 0.9, 0.75], category="bench"))
_stool = 1
for z in (-1.35, 1.65):
    for x in (-3.5, -2.5, -0.5, 0.5, 2.5, 3.5):
        _lab.append(obj("Stool %d" % _stool, [x, 0, z], [0.35, 0.65, 0.35], category="stool"))
        _stool += 1
_lab += [
    obj("Microscope", [-0.5, 0.9, -2.05], [0.3, 0.45, 0.35], on="Bench A2", category="microscope"),
    obj("Beaker 250ml", [0.4, 0.9, -1.9], [0.08, 0.12, 0.08], on="Bench A2", category="beaker"),
    obj("Beaker 500ml", [-3.4, 0.9, 1.0], [0.1, 0.15, 0.1], on="Bench B1", category="beaker"),
    obj("Beaker 1L", [3.5, 0.9, -1.9], [0.13, 0.19, 0.13], on="Bench A3", category="beaker"),
    obj("Centrifuge", [0.3, 0.9, 1.0], [0.45, 0.35, 0.5], on="Bench B2", category="centrifuge"),
    obj("Hot Plate", [-2.6, 0.9, 1.0], [0.2, 0.1, 0.3], on="Bench B1", category="hot plate"),
    obj("Pipette Stand", [-3.4, 0.9, -2.2], [0.25, 0.3, 0.1], on="Bench A1", category="stand"),
    obj("Bunsen Burner", [-2.6, 0.9, -1.9], [0.12, 0.25, 0.12], on="Bench A1", category="burner"),
    obj("Test Tube Rack", [2.6, 0.9, 1.1], [0.3, 0.1, 0.12], on="Bench B3", category="rack"),
    obj("Spectrophotometer", [3.4, 0.9, 0.95], [0.5, 0.3, 0.4], on="Bench B3", category="instrument"),
    obj("Fume Hood", [-4.0, 0, -4.5], [1.5, 2.4, 0.9], category="fume hood"),
    obj("Chemical Cabinet", [1.0, 0, -4.7], [1.0, 1.9, 0.5], category="cabinet"),
    obj("Lab Fridge", [4.8, 0, -4.55], [0.7, 1.8, 0.7], category="fridge"),
    obj("Sink Unit", [-5.65, 0, 1.0], [1.2, 0.9, 0.6], 90, category="sink"),
    obj("Eyewash Station", [5.8, 0, 1.0], [0.4, 1.2, 0.3], -90, category="eyewash"),
    obj("Waste Bin", [5.5, 0, 4.5], [0.35, 0.5, 0.35], category="bin"),
    obj("Coat Rack", [-5.5, 0, 4.5], [0.5, 1.8, 0.5], category="coat rack"),
    obj("Instructor Desk", [0, 0, 4.0], [1.6, 0.75, 0.8], 180, category="desk"),
    obj("Laptop", [0.2, 0.75, 4.0], [0.34, 0.02, 0.24], on="Instructor Desk", category="laptop"),
]
LAB = scene("lab", [-6, 0, -5], [6, 3.2, 5], _lab)

SCENES = {"boardroom": BOARD, "studio": STUDIO, "patio": PATIO, "lab": LAB}
FILES = {k: k + ".json" for k in SCENES}


def names(sc):
    return [o["name"] for o in SCENES[sc]["objects"]]


def pos(sc, n):
    for o in SCENES[sc]["objects"]:
        if o["name"] == n:
            return o["position"]
    raise KeyError(n)


# ----------------------------------------------------------------------------
# check helpers (SPEC section 6)
# ----------------------------------------------------------------------------
def M(o, d, tol=None):
    if tol is None:  # explicit small amounts get a tighter tolerance
        big = max([abs(v) for v in d if v is not None] or [0])
        tol = 0.02 if big <= 0.06 else (0.03 if big <= 0.2 else 0.05)
    return {"check": "moved", "object": o, "delta": list(d), "tol": tol}


def D(o, axis, mn):
    return {"check": "direction", "object": o, "axis": axis, "min": mn}


def R(o, deg, either=False, tol=None):
    c = {"check": "rotated", "object": o, "axis": "y", "degrees": deg}
    if either:
        c["either_sign"] = True
    if tol is not None:
        c["tol"] = tol
    return c


def S(o, f):
    return {"check": "scaled", "object": o, "factor": f}


def ON(o, s):
    return {"check": "on_top", "object": o, "support": s}


def NT(o, other, gap):
    return {"check": "next_to", "object": o, "other": other, "max_gap": gap}


def SIDE(o, other, side, gap=None):
    c = {"check": "side", "object": o, "other": other, "side": side}
    if gap is not None:
        c["max_gap"] = gap
    return c


def BT(o, a, b):
    return {"check": "between", "object": o, "a": a, "b": b}


def FACE(o, t):
    return {"check": "faces", "object": o, "target": t}


def DIST(o, other, mn=None, mx=None):
    c = {"check": "distance", "object": o, "other": other}
    if mn is not None:
        c["min"] = mn
    if mx is not None:
        c["max"] = mx
    return c


def AT(o, p, tol):
    return {"check": "at", "object": o, "position": list(p), "tol": tol}


U = {"check": "unchanged", "objects": "others"}
NC = {"check": "no_collision"}
IB = {"check": "inside_bounds"}


def REF(*mentions):
    c = {"check": "refused"}
    if mentions:
        c["mentions"] = list(mentions)
    return c


def KEEP(sc, *excluded):
    ex = set(excluded)
    for e in ex:
        assert e in names(sc), e
    return {"check": "unchanged", "objects": [n for n in names(sc) if n not in ex]}


Z = [0, 0, 0]


# ----------------------------------------------------------------------------
# answer helpers (the hand-worked expected motion)
# ----------------------------------------------------------------------------
def a(d=(0, 0, 0), yaw=0.0, s=1.0):
    m = {"delta": [round(float(v), 6) for v in d]}
    if yaw:
        m["yaw"] = round(float(yaw), 4)
    if s != 1.0:
        m["scale"] = s
    return m


def to(sc, n, target, yaw=0.0, s=1.0):
    """Answer entry moving object n to absolute target position."""
    p = pos(sc, n)
    return a([target[i] - p[i] for i in range(3)], yaw, s)


def orbit(sc, support, n, deg):
    """Delta of dependent n when `support` turns deg about its own pivot."""
    sp, p = pos(sc, support), pos(sc, n)
    x, z = p[0] - sp[0], p[2] - sp[2]
    r = math.radians(deg)
    nx = x * math.cos(r) + z * math.sin(r)
    nz = -x * math.sin(r) + z * math.cos(r)
    return a([nx - x, 0, nz - z], deg)


def face_yaw(sc, n, target_xz, current_yaw):
    """Yaw change that points n's +Z front at target_xz (x, z)."""
    p = pos(sc, n)
    want = math.degrees(math.atan2(target_xz[0] - p[0], target_xz[1] - p[2]))
    d = (want - current_yaw + 180.0) % 360.0 - 180.0
    return d


QUERIES = []
ANSWERS = {}
_counter = {}


def Q(sc, cat, text, expect, answer):
    _counter[sc] = _counter.get(sc, 0) + 1
    qid = "h7-%s-%03d" % (sc, _counter[sc])
    QUERIES.append({"id": qid, "category": cat, "text": text,
                    "scenes": [FILES[sc]], "expect": expect})
    ANSWERS[qid] = {"refuse": True} if answer is None else {"moves": answer}


# ============================================================================
# BOARDROOM
# ============================================================================
B = "boardroom"
# --- simple
Q(B, "simple", "move chair 03 half a metre back",
  [M("Chair 03", [0, 0, -0.5]), U, NC], {"Chair 03": a([0, 0, -0.5])})
Q(B, "simple", "Chair 07: 30cm to the right",
  [M("Chair 07", [0.3, 0, 0]), U, NC], {"Chair 07": a([0.3, 0, 0])})
Q(B, "simple", "rotate the flip chart 90 degrees clockwise",
  [R("Flipchart", -90), M("Flipchart", Z), U], {"Flipchart": a(yaw=-90)})
Q(B, "simple", "can you move the water cooler 1 foot to the left",
  [M("Water Cooler", [-0.3048, 0, 0], 0.03), U], {"Water Cooler": a([-0.3048, 0, 0])})
Q(B, "simple", "raise the display screen by 20 cm",
  [M("Display Screen", [0, 0.2, 0]), U], {"Display Screen": a([0, 0.2, 0])})
Q(B, "simple", "move the coat stand forward 2 metres",
  [M("Coat Stand", [0, 0, 2]), U, NC], {"Coat Stand": a([0, 0, 2])})
Q(B, "simple", "make the snake plant 50% bigger",
  [S("Snake Plant", 1.5), U], {"Snake Plant": a(s=1.5)})
Q(B, "simple", "make the succulent twice as big",
  [S("Small Succulent", 2), ON("Small Succulent", "Credenza"), U], {"Small Succulent": a(s=2.0)})
Q(B, "simple", "turn chair 12 around",
  [R("Chair 12", 180, either=True), M("Chair 12", Z), U], {"Chair 12": a(yaw=180)})
Q(B, "simple", "push the credenza 40cm to the right",
  [M("Credenza", [0.4, 0, 0]), ON("Coffee Machine", "Credenza"), ON("Small Succulent", "Credenza"), U, NC],
  {"Credenza": a([0.4, 0, 0]), "Coffee Machine": a([0.4, 0, 0]), "Small Succulent": a([0.4, 0, 0])})
Q(B, "simple", "move the laptop 10 cm towards the front",
  [M("Laptop", [0, 0, 0.1]), U], {"Laptop": a([0, 0, 0.1])})
Q(B, "simple", "lower the whiteboard 10cm",
  [M("Whiteboard", [0, -0.1, 0]), U], {"Whiteboard": a([0, -0.1, 0])})
Q(B, "simple", "could you rotate the conference phone by 45 degrees",
  [R("Conference Phone", 45, either=True), M("Conference Phone", Z), U], {"Conference Phone": a(yaw=45)})
Q(B, "simple", "Move Glass 2 to the left by 15 cm.",
  [M("Glass 2", [-0.15, 0, 0]), U], {"Glass 2": a([-0.15, 0, 0])})
Q(B, "simple", "shift the bin 50cm rigth",
  [M("Bin", [0.5, 0, 0]), U, NC], {"Bin": a([0.5, 0, 0])})
Q(B, "simple", "I'd like the fiddle leaf fig 1m further left",
  [M("Fiddle Leaf Fig", [-1, 0, 0]), U, NC], {"Fiddle Leaf Fig": a([-1, 0, 0])})
Q(B, "simple", "scale the flipchart down to half size",
  [S("Flipchart", 0.5), U], {"Flipchart": a(s=0.5)})
Q(B, "simple", "notepad 5cm to the left",
  [M("Notepad", [-0.05, 0, 0]), U], {"Notepad": a([-0.05, 0, 0])})
Q(B, "simple", "move the chair 1 m to the left", [REF()], None)

# --- compositional
Q(B, "compositional", "put the water jug on the credenza",
  [ON("Water Jug", "Credenza"), U, NC], {"Water Jug": to(B, "Water Jug", [0.1, 0.75, -3.75])})
Q(B, "compositional", "move the laptop so it sits in front of chair 03",
  [ON("Laptop", "Conference Table"), AT("Laptop", [0, None, None], 0.15), U, NC],
  {"Laptop": a([1.8, 0, 0])})
Q(B, "compositional", "swap chair 02 and chair 10",
  [M("Chair 02", [0, 0, 2.3], 0.1), M("Chair 10", [0, 0, -2.3], 0.1), U],
  {"Chair 02": a([0, 0, 2.3], 180), "Chair 10": a([0, 0, -2.3], 180)})
Q(B, "compositional", "move chairs 3 to 5 back 30cm",
  [M("Chair 03", [0, 0, -0.3]), M("Chair 04", [0, 0, -0.3]), M("Chair 05", [0, 0, -0.3]), U, NC],
  {"Chair 03": a([0, 0, -0.3]), "Chair 04": a([0, 0, -0.3]), "Chair 05": a([0, 0, -0.3])})
Q(B, "compositional", "move chair 1 and chair 7 half a metre away from the table",
  [M("Chair 01", [0, 0, -0.5]), M("Chair 07", [0, 0, 0.5]), U, NC],
  {"Chair 01": a([0, 0, -0.5]), "Chair 07": a([0, 0, 0.5])})
Q(B, "compositional", "put glass 3 next to the water jug",
  [NT("Glass 3", "Water Jug", 0.25), ON("Glass 3", "Conference Table"), U, NC],
  {"Glass 3": to(B, "Glass 3", [0.2, 0.75, 0.0])})
Q(B, "compositional", "all the glasses on the credenza please",
  [ON("Glass 1", "Credenza"), ON("Glass 2", "Credenza"), ON("Glass 3", "Credenza"), U, NC],
  {"Glass 1": to(B, "Glass 1", [-0.2, 0.75, -3.75]), "Glass 2": to(B, "Glass 2", [0.0, 0.75, -3.75]),
   "Glass 3": to(B, "Glass 3", [0.2, 0.75, -3.75])})
Q(B, "compositional", "Turn chair 03 to face the screen",
  [FACE("Chair 03", "Display Screen"), M("Chair 03", Z), U, NC],
  {"Chair 03": a(yaw=face_yaw(B, "Chair 03", (-4.96, 0.0), 0))})
Q(B, "compositional", "move the coffee machine onto the conference table, next to the phone",
  [ON("Coffee Machine", "Conference Table"), NT("Coffee Machine", "Conference Phone", 0.3), U, NC],
  {"Coffee Machine": to(B, "Coffee Machine", [1.6, 0.75, 0.0])})
Q(B, "compositional", "Move the flipchart 1 m left and turn it to face the table.",
  [M("Flipchart", [-1, 0, 0]), FACE("Flipchart", "Conference Table"), U, NC],
  {"Flipchart": a([-1, 0, 0], 45)})
Q(B, "compositional", "stack the notepad on top of the laptop",
  [ON("Notepad", "Laptop"), U], {"Notepad": to(B, "Notepad", [-1.8, 0.77, -0.4])})
Q(B, "compositional", "move chiar 11 and chair 12 half a metre to the left",
  [M("Chair 11", [-0.5, 0, 0]), M("Chair 12", [-0.5, 0, 0]), U, NC],
  {"Chair 11": a([-0.5, 0, 0]), "Chair 12": a([-0.5, 0, 0])})
Q(B, "compositional", "put the glass on the credenza", [REF("Glass 1", "Glass 2", "Glass 3")], None)
Q(B, "compositional", "move the chair at the end of the table 50cm back", [REF("Chair 06", "Chair 12")], None)

# --- fuzzy
Q(B, "fuzzy", "nudge chair 05 a little to the left",
  [D("Chair 05", "-x", 0.05), M("Chair 05", [None, 0, 0], 0.02), U, NC], {"Chair 05": a([-0.15, 0, 0])})
Q(B, "fuzzy", "chair 10 a bit further from the table pls",
  [D("Chair 10", "+z", 0.05), U, NC], {"Chair 10": a([0, 0, 0.3])})
Q(B, "fuzzy", "the display screen is way too low, bring it up",
  [D("Display Screen", "+y", 0.1), U, IB], {"Display Screen": a([0, 0.3, 0])})
Q(B, "fuzzy", "slide the whole credenza over to the left quite a bit",
  [D("Credenza", "-x", 0.3), ON("Coffee Machine", "Credenza"), ON("Small Succulent", "Credenza"), U, NC],
  {"Credenza": a([-1.5, 0, 0]), "Coffee Machine": a([-1.5, 0, 0]), "Small Succulent": a([-1.5, 0, 0])})
Q(B, "fuzzy", "put the fig somewhere near the whiteboard",
  [NT("Fiddle Leaf Fig", "Whiteboard", 0.6), M("Fiddle Leaf Fig", [None, 0, None]), U, NC],
  {"Fiddle Leaf Fig": a([0, 0, 2.0])})
Q(B, "fuzzy", "turn the flipchart a little so it faces more towards the table",
  [R("Flipchart", 25, tol=20), M("Flipchart", Z), U], {"Flipchart": a(yaw=30)})
Q(B, "fuzzy", "pull the bin well away from the left wall",
  [D("Bin", "+x", 0.5), U, NC], {"Bin": a([1.2, 0, 0])})
Q(B, "fuzzy", "Could the water cooler go a tad further back?",
  [D("Water Cooler", "-z", 0.05), U, NC], {"Water Cooler": a([0, 0, -0.2])})
Q(B, "fuzzy", "Chair 02 is sticking out, push it in toward the table a bit",
  [D("Chair 02", "+z", 0.03), U], {"Chair 02": a([0, 0, 0.1])})
Q(B, "fuzzy", "spin the conference phone round a touch",
  [R("Conference Phone", 15, either=True, tol=13), M("Conference Phone", Z), U],
  {"Conference Phone": a(yaw=15)})
Q(B, "fuzzy", "the snake plant should be way further to the right",
  [D("Snake Plant", "+x", 1.0), U, NC], {"Snake Plant": a([2.5, 0, 0])})
Q(B, "fuzzy", "drop the whiteboard down a little",
  [D("Whiteboard", "-y", 0.03), U], {"Whiteboard": a([0, -0.1, 0])})
Q(B, "fuzzy", "move the laptop a smidge to the right, towards chair 02",
  [D("Laptop", "+x", 0.02), ON("Laptop", "Conference Table"), U], {"Laptop": a([0.1, 0, 0])})
Q(B, "fuzzy", "give chair 08 a slight turn to the left",
  [R("Chair 08", 20, tol=17), M("Chair 08", Z), U], {"Chair 08": a(yaw=20)})
Q(B, "fuzzy", "put the succulent roughly in the middle of the table",
  [ON("Small Succulent", "Conference Table"), AT("Small Succulent", [0, None, 0], 0.5), U, NC],
  {"Small Succulent": to(B, "Small Succulent", [0.2, 0.75, 0.15])})
Q(B, "fuzzy", "the bin should go in the front right corner",
  [AT("Bin", [4.75, None, 3.75], 0.6), M("Bin", [None, 0, None]), U, NC, IB],
  {"Bin": to(B, "Bin", [4.75, 0, 3.8])})
Q(B, "fuzzy", "move the plant a bit closer to the table", [REF("Fiddle Leaf Fig", "Snake Plant")], None)

# --- compositional_fuzzy
Q(B, "compositional_fuzzy", "pull chairs 1 to 5 back from the table a bit",
  [D("Chair 0%d" % i, "-z", 0.05) for i in range(1, 6)] + [U, NC],
  {"Chair 0%d" % i: a([0, 0, -0.2]) for i in range(1, 6)})
Q(B, "compositional_fuzzy", "scoot chairs 8 and 9 a bit apart",
  [D("Chair 08", "+x", 0.05), D("Chair 09", "-x", 0.05), U, NC],
  {"Chair 08": a([0.15, 0, 0]), "Chair 09": a([-0.15, 0, 0])})
Q(B, "compositional_fuzzy", "shove the credenza and everything on it a bit forward",
  [D("Credenza", "+z", 0.05), D("Coffee Machine", "+z", 0.05), D("Small Succulent", "+z", 0.05),
   ON("Coffee Machine", "Credenza"), ON("Small Succulent", "Credenza"), U, NC],
  {"Credenza": a([0, 0, 0.3]), "Coffee Machine": a([0, 0, 0.3]), "Small Succulent": a([0, 0, 0.3])})
Q(B, "compositional_fuzzy", "bring glasses 1 and 3 a little closer to the jug",
  [DIST("Glass 1", "Water Jug", mx=0.8), DIST("Glass 3", "Water Jug", mx=1.6),
   ON("Glass 1", "Conference Table"), ON("Glass 3", "Conference Table"), U, NC],
  {"Glass 1": a([0.27, 0, -0.135]), "Glass 3": a([-0.54, 0, -0.135])})
Q(B, "compositional_fuzzy", "lift the display screen up a bit and slide it toward the back a little",
  [M("Display Screen", [0, 0.2, -0.3], 0.25), U, IB], {"Display Screen": a([0, 0.2, -0.3])})
Q(B, "compositional_fuzzy", "move the snake plant and the bin a fair bit closer together",
  [DIST("Snake Plant", "Bin", mx=5.0), M("Snake Plant", [None, 0, None]), M("Bin", [None, 0, None]), U, NC],
  {"Bin": a([0, 0, 2.0])})
Q(B, "compositional_fuzzy", "pull chair 06 out a bit and angle it slightly toward the flipchart",
  [D("Chair 06", "+x", 0.05), R("Chair 06", 20, tol=17), U, NC], {"Chair 06": a([0.2, 0, 0], 20)})
Q(B, "compositional_fuzzy", "slide the laptop and the notepad a little toward each other",
  [DIST("Laptop", "Notepad", mx=1.55), ON("Laptop", "Conference Table"), ON("Notepad", "Conference Table"), U, NC],
  {"Laptop": a([0.3, 0, 0]), "Notepad": a([-0.3, 0, 0])})
Q(B, "compositional_fuzzy", "nudge the display screen up a little and the whiteboard down a little",
  [D("Display Screen", "+y", 0.03), D("Whiteboard", "-y", 0.03), U],
  {"Display Screen": a([0, 0.1, 0]), "Whiteboard": a([0, -0.1, 0])})
Q(B, "compositional_fuzzy", "chairs 9 through 11 a little further from the table, please",
  [D("Chair 09", "+z", 0.05), D("Chair 10", "+z", 0.05), D("Chair 11", "+z", 0.05), U, NC],
  {"Chair 09": a([0, 0, 0.25]), "Chair 10": a([0, 0, 0.25]), "Chair 11": a([0, 0, 0.25])})
Q(B, "compositional_fuzzy", "chairs 6 and 12 a bit further out from the ends of the table",
  [D("Chair 06", "+x", 0.05), D("Chair 12", "-x", 0.05), U, NC],
  {"Chair 06": a([0.3, 0, 0]), "Chair 12": a([-0.3, 0, 0])})
Q(B, "compositional_fuzzy", "can you turn chairs 1 and 11 slightly towards the screen",
  [R("Chair 01", -20, tol=17), R("Chair 11", 20, tol=17), M("Chair 01", Z), M("Chair 11", Z), U],
  {"Chair 01": a(yaw=-20), "Chair 11": a(yaw=20)})
Q(B, "compositional_fuzzy", "push the plant and the chair a bit closer together", [REF()], None)

# --- hard
Q(B, "hard", "move every chair except chair 4 10 cm to the left",
  [M("Chair %02d" % i, [-0.1, 0, 0]) for i in range(1, 13) if i != 4] + [U, NC],
  {"Chair %02d" % i: a([-0.1, 0, 0]) for i in range(1, 13) if i != 4})
Q(B, "hard", "Chairs 1 and 7 swap places, and keep them facing the table",
  [M("Chair 01", [3.6, 0, 2.3], 0.1), M("Chair 07", [-3.6, 0, -2.3], 0.1),
   R("Chair 01", 180, either=True), R("Chair 07", 180, either=True), U],
  {"Chair 01": a([3.6, 0, 2.3], 180), "Chair 07": a([-3.6, 0, -2.3], 180)})
Q(B, "hard", "Move the laptop 2'6\" to the right",
  [M("Laptop", [0.762, 0, 0], 0.03), U], {"Laptop": a([0.762, 0, 0])})
Q(B, "hard", "the notepad needs to go between the laptop and glass 1",
  [BT("Notepad", "Laptop", "Glass 1"), ON("Notepad", "Conference Table"), U, NC],
  {"Notepad": to(B, "Notepad", [-1.35, 0.75, 0.025])})
Q(B, "hard", "move chair 3 6 inches back",
  [M("Chair 03", [0, 0, -0.1524], 0.02), U], {"Chair 03": a([0, 0, -0.1524])})
_off_table = {"Notepad": [-0.875, 0.75, -3.75], "Conference Phone": [-0.25, 0.75, -3.75],
              "Water Jug": [0.05, 0.75, -3.75], "Glass 1": [0.25, 0.75, -3.75],
              "Glass 2": [0.4, 0.75, -3.75], "Glass 3": [0.55, 0.75, -3.75]}
Q(B, "hard", "everything on the table except the laptop should go on the credenza",
  [ON(n, "Credenza") for n in _off_table] + [U, NC],
  {n: to(B, n, p) for n, p in _off_table.items()})
Q(B, "hard", "Can chairs 8, 9 and 10 all turn to face the whiteboard?",
  [FACE(c, "Whiteboard") for c in ("Chair 08", "Chair 09", "Chair 10")]
  + [M(c, Z) for c in ("Chair 08", "Chair 09", "Chair 10")] + [U, NC],
  {c: a(yaw=face_yaw(B, c, (4.975, 0.0), 180)) for c in ("Chair 08", "Chair 09", "Chair 10")})
Q(B, "hard", "move chair 06 to the left end of the table, next to chair 12",
  [NT("Chair 06", "Chair 12", 0.5), SIDE("Chair 06", "Conference Table", "left"), U, NC],
  {"Chair 06": to(B, "Chair 06", [-2.95, 0, 0.65], 180)})
Q(B, "hard", "chair 5 \u2192 between chair 6 and the whiteboard",
  [BT("Chair 05", "Chair 06", "Whiteboard"), U, NC], {"Chair 05": to(B, "Chair 05", [4.1, 0, 0])})
Q(B, "hard", "put the laptop where the phone is and the phone where the laptop is",
  [M("Laptop", [3.0, 0, 0.4]), M("Conference Phone", [-3.0, 0, -0.4]), U],
  {"Laptop": a([3.0, 0, 0.4]), "Conference Phone": a([-3.0, 0, -0.4])})
Q(B, "hard", "move the coat stand 3ft to the right and the bin 18 inches forward",
  [M("Coat Stand", [0.9144, 0, 0], 0.03), M("Bin", [0, 0, 0.4572], 0.03), U, NC],
  {"Coat Stand": a([0.9144, 0, 0]), "Bin": a([0, 0, 0.4572])})
Q(B, "hard", "turn chair 9 by a quarter turn anticlockwise",
  [R("Chair 09", 90), M("Chair 09", Z), U], {"Chair 09": a(yaw=90)})
Q(B, "hard", "the fig and the snake plant should swap corners",
  [M("Fiddle Leaf Fig", [-9.1, 0, 7.1], 0.3), M("Snake Plant", [9.1, 0, -7.1], 0.3), U, NC],
  {"Fiddle Leaf Fig": a([-9.1, 0, 7.1]), "Snake Plant": a([9.1, 0, -7.1])})
Q(B, "hard", "turn the 2nd chair from the left on the far side of the table around",
  [R("Chair 02", 180, either=True), M("Chair 02", Z), U], {"Chair 02": a(yaw=180)})
Q(B, "hard", "move the projector 20cm up", [REF()], None)
Q(B, "hard", "move chair 13 next to chair 12", [REF()], None)
Q(B, "hard", "turn chair 06 to face the door", [REF()], None)
Q(B, "hard", "swap the laptop with the other laptop", [REF()], None)

# ============================================================================
# STUDIO (Maya names)
# ============================================================================
T = "studio"
# --- simple
Q(T, "simple", "move pCube11 1m to the right", [M("pCube11", [1, 0, 0]), U, NC], {"pCube11": a([1, 0, 0])})
Q(T, "simple", "rotate group4_mesh 30 degrees counterclockwise",
  [R("group4_mesh", 30), M("group4_mesh", Z), U], {"group4_mesh": a(yaw=30)})
Q(T, "simple", "scale pSphere2 by 0.5", [S("pSphere2", 0.5), U], {"pSphere2": a(s=0.5)})
Q(T, "simple", "move pCylinder3 forward 1 meter", [M("pCylinder3", [0, 0, 1]), U, NC], {"pCylinder3": a([0, 0, 1])})
Q(T, "simple", "pCube4 - 2m left", [M("pCube4", [-2, 0, 0]), U, NC], {"pCube4": a([-2, 0, 0])})
Q(T, "simple", "move polySurface7 back by half a metre",
  [M("polySurface7", [0, 0, -0.5]), U, NC], {"polySurface7": a([0, 0, -0.5])})
Q(T, "simple", "rotate pCube11 45 degrees clockwise",
  [R("pCube11", -45), M("pCube11", Z), U], {"pCube11": a(yaw=-45)})
Q(T, "simple", "moev pCone1 30 cm to the left", [M("pCone1", [-0.3, 0, 0]), U], {"pCone1": a([-0.3, 0, 0])})
Q(T, "simple", "pSphere1: 20cm forward", [M("pSphere1", [0, 0, 0.2]), U], {"pSphere1": a([0, 0, 0.2])})
Q(T, "simple", "please make pCube3 1.5x bigger",
  [S("pCube3", 1.5), ON("pCube3", "pPlane1"), U], {"pCube3": a(s=1.5)})
Q(T, "simple", "shift pCube7 forward 50 cm",
  [M("pCube7", [0, 0, 0.5]), ON("pCube8", "pCube7"), U, NC],
  {"pCube7": a([0, 0, 0.5]), "pCube8": a([0, 0, 0.5])})
Q(T, "simple", "rotate pTorus1 by 180\u00b0",
  [R("pTorus1", 180, either=True), M("pTorus1", Z), U], {"pTorus1": a(yaw=180)})
Q(T, "simple", "move group4_mesh 1m back toward the set",
  [M("group4_mesh", [0, 0, -1]), U, NC], {"group4_mesh": a([0, 0, -1])})
Q(T, "simple", "raise polySurface12 by 0.2", [M("polySurface12", [0, 0.2, 0]), U], {"polySurface12": a([0, 0.2, 0])})
Q(T, "simple", "move pCube9 30cm forward", [M("pCube9", [0, 0, 0.3]), U, NC], {"pCube9": a([0, 0, 0.3])})
Q(T, "simple", "pSphere2 50cm back", [M("pSphere2", [0, 0, -0.5]), U, NC], {"pSphere2": a([0, 0, -0.5])})
Q(T, "simple", "move the cylinder 1m up",
  [REF("pCylinder3", "pCylinder4", "pCylinder6", "pCylinder7")], None)

# --- compositional
Q(T, "compositional", "put pSphere1 on top of pCube3",
  [ON("pSphere1", "pCube3"), U], {"pSphere1": to(T, "pSphere1", [0.4, 0.47, -3.3])})
Q(T, "compositional", "put pCube2 on the floor next to pCube11",
  [NT("pCube2", "pCube11", 0.4), M("pCube2", [None, -0.9, None]), U, NC],
  {"pCube2": to(T, "pCube2", [-2.5, 0, 3.8])})
Q(T, "compositional", "move pCone1 between the two tall cylinders",
  [BT("pCone1", "pCylinder3", "pCylinder4"), U], {"pCone1": to(T, "pCone1", [0, 0.02, -2.5])})
Q(T, "compositional", "put pCube8 on the floor to the right of pCube7",
  [SIDE("pCube8", "pCube7", "right", 0.5), M("pCube8", [None, -0.4, None]), U, NC],
  {"pCube8": to(T, "pCube8", [-4.8, 0, -1.0])})
Q(T, "compositional", "bring pCylinder3 and pCylinder4 1 m closer together",
  [DIST("pCylinder3", "pCylinder4", mn=3.4, mx=4.1), M("pCylinder3", [None, 0, 0], 0.02),
   M("pCylinder4", [None, 0, 0], 0.02), U, NC],
  {"pCylinder3": a([0.5, 0, 0]), "pCylinder4": a([-0.5, 0, 0])})
Q(T, "compositional", "put pCube2 on pCube3", [ON("pCube2", "pCube3"), U],
  {"pCube2": to(T, "pCube2", [0.4, 0.47, -3.3])})
Q(T, "compositional", "make group4_mesh face pCube4",
  [FACE("group4_mesh", "pCube4"), M("group4_mesh", Z), U, NC],
  {"group4_mesh": a(yaw=face_yaw(T, "group4_mesh", (5.6, -1.0), 180))})
Q(T, "compositional", "move pCube11 onto the big table",
  [ON("pCube11", "pCube1"), U, NC], {"pCube11": to(T, "pCube11", [-3.45, 0.9, 2.5])})
Q(T, "compositional", "put pCylinder6 and pTorus1 on pCube1",
  [ON("pCylinder6", "pCube1"), ON("pTorus1", "pCube1"), U, NC],
  {"pCylinder6": to(T, "pCylinder6", [-3.5, 0.9, 2.2]), "pTorus1": to(T, "pTorus1", [-3.5, 0.9, 2.75])})
Q(T, "compositional", "swap pCone1 and pSphere2",
  [M("pCone1", [3, 0, 0]), M("pSphere2", [-3, 0, 0]), U], {"pCone1": a([3, 0, 0]), "pSphere2": a([-3, 0, 0])})
Q(T, "compositional", "put the small box that's on the floor on top of the stack by the left wall",
  [ON("pCube11", "pCube8"), U], {"pCube11": to(T, "pCube11", [-5.5, 0.75, -1.0])})
Q(T, "compositional", "move pCube1 1 m forward and take whatever's on it along",
  [M("pCube1", [0, 0, 1]), M("pCube2", [0, 0, 1]), M("pSphere1", [0, 0, 1]), U, NC],
  {"pCube1": a([0, 0, 1]), "pCube2": a([0, 0, 1]), "pSphere1": a([0, 0, 1])})
Q(T, "compositional", "push the big ball up against the right wall",
  [M("pSphere2", [4.175, 0, 0], 0.06), U, IB], {"pSphere2": a([4.175, 0, 0])})
Q(T, "compositional", "put the ball on polySurface7", [REF("pSphere1", "pSphere2")], None)

# --- fuzzy
Q(T, "fuzzy", "move the tall box by the right wall a bit forward",
  [D("pCube4", "+z", 0.05), U, NC], {"pCube4": a([0, 0, 0.3])})
Q(T, "fuzzy", "the flat thing on the floor \u2014 move it a bit to the left",
  [D("pPlane1", "-x", 0.05), KEEP(T, "pPlane1", "pCube3", "pCylinder7"), NC],
  {"pPlane1": a([-0.3, 0, 0]), "pCube3": a([-0.3, 0, 0]), "pCylinder7": a([-0.3, 0, 0])})
Q(T, "fuzzy", "push the big ball way over to the right",
  [D("pSphere2", "+x", 1.0), U, NC], {"pSphere2": a([2.5, 0, 0])})
Q(T, "fuzzy", "the skinny tall thing on the left, move it a bit closer to the back wall",
  [D("pCylinder3", "-z", 0.05), U, NC], {"pCylinder3": a([0, 0, -0.4])})
Q(T, "fuzzy", "turn group4_mesh slightly to the right",
  [R("group4_mesh", -15, tol=13), M("group4_mesh", Z), U], {"group4_mesh": a(yaw=-15)})
Q(T, "fuzzy", "move the small box on the big table a little toward the ball next to it",
  [D("pCube2", "+x", 0.05), ON("pCube2", "pCube1"), U, NC], {"pCube2": a([0.2, 0, 0])})
Q(T, "fuzzy", "pCylinder7 over to the right a touch",
  [D("pCylinder7", "+x", 0.03), ON("pCylinder7", "pPlane1"), U, NC], {"pCylinder7": a([0.15, 0, 0])})
Q(T, "fuzzy", "the long low bench against the left wall - pull it out from the wall a bit",
  [D("pCube9", "+x", 0.05), U, NC], {"pCube9": a([0.3, 0, 0])})
Q(T, "fuzzy", "move the big table way back",
  [D("pCube1", "-z", 1.0), ON("pCube2", "pCube1"), ON("pSphere1", "pCube1"), U, NC],
  {"pCube1": a([0, 0, -2]), "pCube2": a([0, 0, -2]), "pSphere1": a([0, 0, -2])})
Q(T, "fuzzy", "give pTorus1 a small spin",
  [R("pTorus1", 20, either=True, tol=17), ON("pTorus1", "pCube6"), U], {"pTorus1": a(yaw=20)})
Q(T, "fuzzy", "move the long thing against the front wall a little further from the wall",
  [D("polySurface7", "-z", 0.05), U, NC], {"polySurface7": a([0, 0, -0.3])})
Q(T, "fuzzy", "bring pSphere1 closer to pCube2",
  [DIST("pSphere1", "pCube2", mx=0.6), ON("pSphere1", "pCube1"), U, NC], {"pSphere1": a([-0.4, 0, 0])})
Q(T, "fuzzy", "move the small box a bit to the left", [REF("pCube2", "pCube11")], None)
Q(T, "fuzzy", "push the tall cylinder a bit further back", [REF("pCylinder3", "pCylinder4")], None)

# --- compositional_fuzzy
Q(T, "compositional_fuzzy", "move both tall cylinders a bit further back",
  [D("pCylinder3", "-z", 0.05), D("pCylinder4", "-z", 0.05), U, NC],
  {"pCylinder3": a([0, 0, -0.5]), "pCylinder4": a([0, 0, -0.5])})
Q(T, "compositional_fuzzy", "put pTorus1 somewhere on the big table",
  [ON("pTorus1", "pCube1"), U, NC], {"pTorus1": to(T, "pTorus1", [-3.45, 0.9, 2.5])})
Q(T, "compositional_fuzzy", "scoot the two things sitting on pPlane1 a little toward group4_mesh",
  [D("pCube3", "+z", 0.05), D("pCylinder7", "+z", 0.05), ON("pCube3", "pPlane1"), ON("pCylinder7", "pPlane1"), U, NC],
  {"pCube3": a([0, 0, 0.3]), "pCylinder7": a([0, 0, 0.3])})
Q(T, "compositional_fuzzy", "move pCone1 and pCube11 a bit closer to each other",
  [DIST("pCone1", "pCube11", mx=3.0), M("pCone1", [None, 0, None]), M("pCube11", [None, 0, None]), U, NC],
  {"pCone1": a([0, 0, 1.0]), "pCube11": a([0, 0, -0.3])})
Q(T, "compositional_fuzzy", "rotate the big table a bit and keep the stuff on it on it",
  [R("pCube1", 15, either=True, tol=13), ON("pCube2", "pCube1"), ON("pSphere1", "pCube1"), U, NC],
  {"pCube1": a(yaw=15), "pCube2": orbit(T, "pCube1", "pCube2", 15), "pSphere1": orbit(T, "pCube1", "pSphere1", 15)})
Q(T, "compositional_fuzzy", "move the stack by the left wall a little toward the middle of the room",
  [D("pCube7", "+x", 0.05), ON("pCube8", "pCube7"), U, NC],
  {"pCube7": a([0.5, 0, 0]), "pCube8": a([0.5, 0, 0])})
Q(T, "compositional_fuzzy", "push pSphere2 and pCone1 a bit apart",
  [D("pSphere2", "+x", 0.05), D("pCone1", "-x", 0.05), U, NC],
  {"pSphere2": a([0.3, 0, 0]), "pCone1": a([-0.3, 0, 0])})
Q(T, "compositional_fuzzy", "move the two small boxes a bit closer together",
  [DIST("pCube11", "pCube2", mx=1.6), ON("pCube2", "pCube1"), M("pCube11", [None, 0, None]), U, NC],
  {"pCube2": a([0.4, 0, 0.2]), "pCube11": a([-0.5, 0, -0.5])})
Q(T, "compositional_fuzzy", "move group4_mesh a fair bit to the right and turn it a little to the left",
  [D("group4_mesh", "+x", 0.3), R("group4_mesh", 20, tol=17), U, NC], {"group4_mesh": a([0.8, 0, 0], 20)})
Q(T, "compositional_fuzzy", "spread the stack by the left wall and the long low bench a bit further apart",
  [D("pCube7", "-z", 0.05), D("pCube9", "+z", 0.05), ON("pCube8", "pCube7"), U, NC],
  {"pCube7": a([0, 0, -0.3]), "pCube8": a([0, 0, -0.3]), "pCube9": a([0, 0, 0.3])})

# --- hard
Q(T, "hard", "pCube4 needs to face group4_mesh",
  [FACE("pCube4", "group4_mesh"), M("pCube4", Z), U, NC, IB],
  {"pCube4": a(yaw=face_yaw(T, "pCube4", (0.0, 1.5), 0))})
Q(T, "hard", "move the small box on the big table 8 inches to the right",
  [M("pCube2", [0.2032, 0, 0], 0.02), U], {"pCube2": a([0.2032, 0, 0])})
Q(T, "hard", "slide pCone1 sideways so it's directly behind pCube11",
  [M("pCone1", [-0.5, 0, 0]), U], {"pCone1": a([-0.5, 0, 0])})
Q(T, "hard", "pSphere1 \u2192 floor, just in front of the big table",
  [SIDE("pSphere1", "pCube1", "front", 0.7), M("pSphere1", [None, -0.9, None]), U, NC],
  {"pSphere1": to(T, "pSphere1", [-3.0, 0, 3.5])})
Q(T, "hard", "rotate pCube6 a quarter turn clockwise, keeping what's on it on it",
  [R("pCube6", -90), ON("pCylinder6", "pCube6"), ON("pTorus1", "pCube6"), U, NC],
  {"pCube6": a(yaw=-90), "pCylinder6": orbit(T, "pCube6", "pCylinder6", -90),
   "pTorus1": orbit(T, "pCube6", "pTorus1", -90)})
Q(T, "hard", "take pCube3 and pCylinder7 off pPlane1 and stand them next to the left tall cylinder",
  [NT("pCube3", "pCylinder3", 0.5), NT("pCylinder7", "pCylinder3", 0.5),
   M("pCube3", [None, -0.02, None], 0.01), M("pCylinder7", [None, -0.02, None], 0.01), U, NC],
  {"pCube3": to(T, "pCube3", [-1.9, 0, -2.5]), "pCylinder7": to(T, "pCylinder7", [-2.5, 0, -1.9])})
Q(T, "hard", "move pCube3 20cm left, 1ft forward, and turn it 45\u00b0",
  [M("pCube3", [-0.2, 0, 0.3048], 0.03), R("pCube3", 45, either=True), ON("pCube3", "pPlane1"), U, NC],
  {"pCube3": a([-0.2, 0, 0.3048], 45)})
Q(T, "hard", "rotate pCube5 90 degrees", [REF()], None)
Q(T, "hard", "move polySurface3 to the left a bit", [REF()], None)
Q(T, "hard", "scale nurbsCircle1 by 2", [REF()], None)
Q(T, "hard", "move the third tall cylinder next to pCube4", [REF()], None)

# ============================================================================
# PATIO (Unreal names)
# ============================================================================
P = "patio"
_chairs = ["SM_DiningChair_0%d" % i for i in range(1, 5)]
_dtable = "SM_DiningTable_Teak"
# --- simple
Q(P, "simple", "move SM_Lounger_01 50cm to the left",
  [M("SM_Lounger_01", [-0.5, 0, 0]), U, NC], {"SM_Lounger_01": a([-0.5, 0, 0])})
Q(P, "simple", "rotate SM_FirePit_Round 45 degrees",
  [R("SM_FirePit_Round", 45, either=True), M("SM_FirePit_Round", Z), U], {"SM_FirePit_Round": a(yaw=45)})
Q(P, "simple", "move SM_BBQ_Grill 1m back", [M("SM_BBQ_Grill", [0, 0, -1]), U, NC], {"SM_BBQ_Grill": a([0, 0, -1])})
Q(P, "simple", "SM_HoseReel: 2 metres forward", [M("SM_HoseReel", [0, 0, 2]), U, NC], {"SM_HoseReel": a([0, 0, 2])})
Q(P, "simple", "scale BP_Planter_Small_01 by 1.5", [S("BP_Planter_Small_01", 1.5), U], {"BP_Planter_Small_01": a(s=1.5)})
Q(P, "simple", "rotate SM_OutdoorSofa 180\u00b0",
  [R("SM_OutdoorSofa", 180, either=True), M("SM_OutdoorSofa", Z), U], {"SM_OutdoorSofa": a(yaw=180)})
Q(P, "simple", "Move SM_Parasol_B 0.5 m to the right", [M("SM_Parasol_B", [0.5, 0, 0]), U, NC],
  {"SM_Parasol_B": a([0.5, 0, 0])})
Q(P, "simple", "move SM_Lantern_01 5cm to the left", [M("SM_Lantern_01", [-0.05, 0, 0]), U],
  {"SM_Lantern_01": a([-0.05, 0, 0])})
Q(P, "simple", "SM_WateringCan 40 cm right pls", [M("SM_WateringCan", [0.4, 0, 0]), U, NC],
  {"SM_WateringCan": a([0.4, 0, 0])})
Q(P, "simple", "turn SM_Armchair_Rattan_02 90\u00b0 clockwise",
  [R("SM_Armchair_Rattan_02", -90), M("SM_Armchair_Rattan_02", Z), U], {"SM_Armchair_Rattan_02": a(yaw=-90)})
Q(P, "simple", "could you move SM_GardenBench_Stone forward by 1.5m",
  [M("SM_GardenBench_Stone", [0, 0, 1.5]), U, NC], {"SM_GardenBench_Stone": a([0, 0, 1.5])})
Q(P, "simple", "shrink SM_Parasol_A to 80%", [S("SM_Parasol_A", 0.8), U], {"SM_Parasol_A": a(s=0.8)})
Q(P, "simple", "SM_DiningChair_02 needs to move 20cm to the right", [M("SM_DiningChair_02", [0.2, 0, 0]), U, NC],
  {"SM_DiningChair_02": a([0.2, 0, 0])})
Q(P, "simple", "move SM_Armchair_Rattan_01 30cm back", [M("SM_Armchair_Rattan_01", [0, 0, -0.3]), U, NC],
  {"SM_Armchair_Rattan_01": a([0, 0, -0.3])})
Q(P, "simple", "move the planter 1 metre forward",
  [REF("BP_Planter_Large_01", "BP_Planter_Large_02", "BP_Planter_Small_01")], None)

# --- compositional
Q(P, "compositional", "I'd like SM_Lantern_01 on the dining table",
  [ON("SM_Lantern_01", _dtable), U, NC], {"SM_Lantern_01": to(P, "SM_Lantern_01", [2.5, 0.75, -2.0])})
Q(P, "compositional", "move SM_WateringCan next to BP_Planter_Large_02",
  [NT("SM_WateringCan", "BP_Planter_Large_02", 0.4), M("SM_WateringCan", [None, 0, None]), U, NC],
  {"SM_WateringCan": to(P, "SM_WateringCan", [5.4, 0, -5.4])})
Q(P, "compositional", "put SM_SideTable_Wood between SM_OutdoorSofa and SM_Armchair_Rattan_02",
  [BT("SM_SideTable_Wood", "SM_OutdoorSofa", "SM_Armchair_Rattan_02"), ON("SM_Lantern_01", "SM_SideTable_Wood"), U, NC],
  {"SM_SideTable_Wood": to(P, "SM_SideTable_Wood", [0.9, 0, 3.55]),
   "SM_Lantern_01": to(P, "SM_Lantern_01", [0.9, 0.5, 3.55])})
Q(P, "compositional", "move dining chairs 1 and 3 half a metre to the left",
  [M("SM_DiningChair_01", [-0.5, 0, 0]), M("SM_DiningChair_03", [-0.5, 0, 0]), U, NC],
  {"SM_DiningChair_01": a([-0.5, 0, 0]), "SM_DiningChair_03": a([-0.5, 0, 0])})
Q(P, "compositional", "put SM_Glass_01 and SM_Glass_02 on SM_SideTable_Wood",
  [ON("SM_Glass_01", "SM_SideTable_Wood"), ON("SM_Glass_02", "SM_SideTable_Wood"), U, NC],
  {"SM_Glass_01": to(P, "SM_Glass_01", [-3.55, 0.5, 0.4]), "SM_Glass_02": to(P, "SM_Glass_02", [-3.25, 0.5, 0.4])})
Q(P, "compositional", "SM_Armchair_Rattan_01 and SM_Armchair_Rattan_02 should both face SM_OutdoorSofa",
  [FACE("SM_Armchair_Rattan_01", "SM_OutdoorSofa"), FACE("SM_Armchair_Rattan_02", "SM_OutdoorSofa"),
   M("SM_Armchair_Rattan_01", Z), M("SM_Armchair_Rattan_02", Z), U, NC],
  {"SM_Armchair_Rattan_01": a(yaw=face_yaw(P, "SM_Armchair_Rattan_01", (0.0, 4.6), 90)),
   "SM_Armchair_Rattan_02": a(yaw=face_yaw(P, "SM_Armchair_Rattan_02", (0.0, 4.6), -90))})
Q(P, "compositional", "put BP_Planter_Small_01 on the stone bench",
  [ON("BP_Planter_Small_01", "SM_GardenBench_Stone"), U],
  {"BP_Planter_Small_01": to(P, "BP_Planter_Small_01", [-6.6, 0.45, -2.0])})
Q(P, "compositional", "move both parasols 1 m forward",
  [M("SM_Parasol_A", [0, 0, 1]), M("SM_Parasol_B", [0, 0, 1]), U, NC],
  {"SM_Parasol_A": a([0, 0, 1]), "SM_Parasol_B": a([0, 0, 1])})
Q(P, "compositional", "swap SM_Lounger_01 and SM_Lounger_02",
  [M("SM_Lounger_01", [1.2, 0, 0]), M("SM_Lounger_02", [-1.2, 0, 0]), U],
  {"SM_Lounger_01": a([1.2, 0, 0]), "SM_Lounger_02": a([-1.2, 0, 0])})
Q(P, "compositional", "place SM_HoseReel to the left of BP_Planter_Large_02",
  [SIDE("SM_HoseReel", "BP_Planter_Large_02", "left", 0.5), M("SM_HoseReel", [None, 0, None]), U, NC],
  {"SM_HoseReel": to(P, "SM_HoseReel", [5.5, 0, -5.4])})
Q(P, "compositional", "move SM_FirePit_Round 1m back and SM_OutdoorSofa 1m back too",
  [M("SM_FirePit_Round", [0, 0, -1]), M("SM_OutdoorSofa", [0, 0, -1]), U, NC],
  {"SM_FirePit_Round": a([0, 0, -1]), "SM_OutdoorSofa": a([0, 0, -1])})
Q(P, "compositional", "put the wine bottle on SM_SideTable_Wood next to the lantern",
  [ON("SM_Bottle_Wine", "SM_SideTable_Wood"), NT("SM_Bottle_Wine", "SM_Lantern_01", 0.2), U, NC],
  {"SM_Bottle_Wine": to(P, "SM_Bottle_Wine", [-3.24, 0.5, 0.4])})
Q(P, "compositional", "put the glass on the side table", [REF("SM_Glass_01", "SM_Glass_02")], None)
Q(P, "compositional", "put the lantern next to the large planter",
  [REF("BP_Planter_Large_01", "BP_Planter_Large_02")], None)

# --- fuzzy
Q(P, "fuzzy", "push SM_Lounger_02 a little to the right, closer to the fire",
  [D("SM_Lounger_02", "+x", 0.05), U, NC], {"SM_Lounger_02": a([0.4, 0, 0])})
Q(P, "fuzzy", "move the grill way over to the left", [D("SM_BBQ_Grill", "-x", 1.0), U, NC],
  {"SM_BBQ_Grill": a([-2.0, 0, 0])})
Q(P, "fuzzy", "SM_HoseReel a bit further back", [D("SM_HoseReel", "-z", 0.05), U, NC],
  {"SM_HoseReel": a([0, 0, -0.3])})
Q(P, "fuzzy", "the small planter needs to come forward a bit", [D("BP_Planter_Small_01", "+z", 0.05), U, NC],
  {"BP_Planter_Small_01": a([0, 0, 0.4])})
Q(P, "fuzzy", "tuck SM_DiningChair_03 in a bit closer to the table", [D("SM_DiningChair_03", "-z", 0.03), U],
  {"SM_DiningChair_03": a([0, 0, -0.1])})
Q(P, "fuzzy", "rotate the sofa slightly clockwise",
  [R("SM_OutdoorSofa", -15, tol=13), M("SM_OutdoorSofa", Z), U], {"SM_OutdoorSofa": a(yaw=-15)})
Q(P, "fuzzy", "move SM_Parasol_A a fair bit towards the loungers", [D("SM_Parasol_A", "+x", 0.2), U, NC],
  {"SM_Parasol_A": a([0.5, 0, 0])})
Q(P, "fuzzy", "give SM_Lantern_01 a little twist",
  [R("SM_Lantern_01", 20, either=True, tol=17), ON("SM_Lantern_01", "SM_SideTable_Wood"), U],
  {"SM_Lantern_01": a(yaw=20)})
Q(P, "fuzzy", "push the stone bench back a good bit", [D("SM_GardenBench_Stone", "-z", 0.5), U, NC],
  {"SM_GardenBench_Stone": a([0, 0, -1.5])})
Q(P, "fuzzy", "SM_DiningTable_Teak: slide it a tad to the right",
  [D(_dtable, "+x", 0.03), ON("SM_Bottle_Wine", _dtable), ON("SM_Glass_01", _dtable), ON("SM_Glass_02", _dtable),
   KEEP(P, _dtable, "SM_Bottle_Wine", "SM_Glass_01", "SM_Glass_02", *_chairs), NC],
  {n: a([0.2, 0, 0]) for n in (_dtable, "SM_Bottle_Wine", "SM_Glass_01", "SM_Glass_02")})
Q(P, "fuzzy", "move the watering can a bit closer to the small planter", [D("SM_WateringCan", "-x", 0.05), U, NC],
  {"SM_WateringCan": a([-0.3, 0, 0])})
Q(P, "fuzzy", "bring armchair 2 a touch closer to the fire pit", [D("SM_Armchair_Rattan_02", "-x", 0.03), U, NC],
  {"SM_Armchair_Rattan_02": a([-0.2, 0, 0])})
Q(P, "fuzzy", "turn the armchair a little towards the sofa",
  [REF("SM_Armchair_Rattan_01", "SM_Armchair_Rattan_02")], None)
Q(P, "fuzzy", "move the dining chair a bit closer to the grill", [REF(*_chairs)], None)

# --- compositional_fuzzy
Q(P, "compositional_fuzzy", "pull all four dining chairs out a little",
  [D("SM_DiningChair_01", "-z", 0.05), D("SM_DiningChair_02", "-z", 0.05),
   D("SM_DiningChair_03", "+z", 0.05), D("SM_DiningChair_04", "+z", 0.05), U, NC],
  {"SM_DiningChair_01": a([0, 0, -0.2]), "SM_DiningChair_02": a([0, 0, -0.2]),
   "SM_DiningChair_03": a([0, 0, 0.2]), "SM_DiningChair_04": a([0, 0, 0.2])})
Q(P, "compositional_fuzzy", "move the loungers and the little table between them a bit further back",
  [D("SM_Lounger_01", "-z", 0.05), D("SM_Lounger_02", "-z", 0.05), D("SM_SideTable_Wood", "-z", 0.05),
   ON("SM_Lantern_01", "SM_SideTable_Wood"), U, NC],
  {n: a([0, 0, -0.5]) for n in ("SM_Lounger_01", "SM_Lounger_02", "SM_SideTable_Wood", "SM_Lantern_01")})
Q(P, "compositional_fuzzy", "spread the two armchairs a little further apart",
  [D("SM_Armchair_Rattan_01", "-x", 0.05), D("SM_Armchair_Rattan_02", "+x", 0.05), U, NC],
  {"SM_Armchair_Rattan_01": a([-0.2, 0, 0]), "SM_Armchair_Rattan_02": a([0.2, 0, 0])})
Q(P, "compositional_fuzzy", "move the dining table and its chairs a bit to the left",
  [D(n, "-x", 0.05) for n in [_dtable] + _chairs]
  + [ON("SM_Bottle_Wine", _dtable), ON("SM_Glass_01", _dtable), ON("SM_Glass_02", _dtable), U, NC],
  {n: a([-0.5, 0, 0]) for n in [_dtable] + _chairs + ["SM_Bottle_Wine", "SM_Glass_01", "SM_Glass_02"]})
Q(P, "compositional_fuzzy", "turn both parasols a bit",
  [R("SM_Parasol_A", 20, either=True, tol=17), R("SM_Parasol_B", 20, either=True, tol=17),
   M("SM_Parasol_A", Z), M("SM_Parasol_B", Z), U],
  {"SM_Parasol_A": a(yaw=20), "SM_Parasol_B": a(yaw=20)})
Q(P, "compositional_fuzzy", "bring the glasses a bit closer to the wine bottle",
  [DIST("SM_Glass_01", "SM_Bottle_Wine", mx=0.5), DIST("SM_Glass_02", "SM_Bottle_Wine", mx=0.5),
   ON("SM_Glass_01", _dtable), ON("SM_Glass_02", _dtable), U, NC],
  {"SM_Glass_01": a([-0.3, 0, 0]), "SM_Glass_02": a([-0.3, 0, 0])})
Q(P, "compositional_fuzzy", "pull the two loungers a bit apart and keep the side table in the middle",
  [D("SM_Lounger_01", "-x", 0.05), D("SM_Lounger_02", "+x", 0.05),
   SIDE("SM_SideTable_Wood", "SM_Lounger_01", "right"), SIDE("SM_SideTable_Wood", "SM_Lounger_02", "left"),
   ON("SM_Lantern_01", "SM_SideTable_Wood"), U, NC],
  {"SM_Lounger_01": a([-0.2, 0, 0]), "SM_Lounger_02": a([0.2, 0, 0])})
Q(P, "compositional_fuzzy", "move the sofa and both armchairs a little closer to the fire pit",
  [D("SM_OutdoorSofa", "-z", 0.05), D("SM_Armchair_Rattan_01", "+x", 0.05), D("SM_Armchair_Rattan_02", "-x", 0.05), U, NC],
  {"SM_OutdoorSofa": a([0, 0, -0.4]), "SM_Armchair_Rattan_01": a([0.3, 0, 0]), "SM_Armchair_Rattan_02": a([-0.3, 0, 0])})
Q(P, "compositional_fuzzy", "shift the BBQ a bit forward and turn it slightly towards the sofa",
  [D("SM_BBQ_Grill", "+z", 0.05), R("SM_BBQ_Grill", 20, tol=17), U, NC, IB],
  {"SM_BBQ_Grill": a([0, 0, 0.4], 20)})

# --- hard
Q(P, "hard", "put SM_Lantern_01 on the dining table between the wine bottle and SM_Glass_02",
  [ON("SM_Lantern_01", _dtable), BT("SM_Lantern_01", "SM_Bottle_Wine", "SM_Glass_02"), U, NC],
  {"SM_Lantern_01": to(P, "SM_Lantern_01", [2.5, 0.75, -1.875])})
Q(P, "hard", "Move SM_FirePit_Round 3 ft towards the sofa",
  [M("SM_FirePit_Round", [0, 0, 0.9144], 0.03), U, NC], {"SM_FirePit_Round": a([0, 0, 0.9144])})
Q(P, "hard", "all the dining chairs except SM_DiningChair_04 get turned 90 degrees anticlockwise",
  [R(c, 90) for c in _chairs[:3]] + [M(c, Z) for c in _chairs[:3]] + [U, NC],
  {c: a(yaw=90) for c in _chairs[:3]})
Q(P, "hard", "put the large planter that's on the left next to the stone bench",
  [NT("BP_Planter_Large_01", "SM_GardenBench_Stone", 0.4), M("BP_Planter_Large_01", [None, 0, None]), U, NC],
  {"BP_Planter_Large_01": a([0, 0, 2.0])})
Q(P, "hard", "the lounger closest to SM_Parasol_A \u2192 2' 6\" forward",
  [M("SM_Lounger_01", [0, 0, 0.762], 0.03), U, NC], {"SM_Lounger_01": a([0, 0, 0.762])})
Q(P, "hard", "SM_Glass_01 goes where SM_Glass_02 is, and SM_Glass_02 goes on the side table",
  [M("SM_Glass_01", [0, 0, 0.5]), ON("SM_Glass_02", "SM_SideTable_Wood"), U, NC],
  {"SM_Glass_01": a([0, 0, 0.5]), "SM_Glass_02": to(P, "SM_Glass_02", [-3.55, 0.5, 0.4])})
Q(P, "hard", "move everything on the dining table onto the side table",
  [ON("SM_Bottle_Wine", "SM_SideTable_Wood"), ON("SM_Glass_01", "SM_SideTable_Wood"),
   ON("SM_Glass_02", "SM_SideTable_Wood"), U, NC],
  {"SM_Bottle_Wine": to(P, "SM_Bottle_Wine", [-3.56, 0.5, 0.4]), "SM_Glass_01": to(P, "SM_Glass_01", [-3.24, 0.5, 0.4]),
   "SM_Glass_02": to(P, "SM_Glass_02", [-3.4, 0.5, 0.24])})
Q(P, "hard", "turn the BBQ so it faces SM_Parasol_B",
  [FACE("SM_BBQ_Grill", "SM_Parasol_B"), M("SM_BBQ_Grill", Z), U, NC, IB],
  {"SM_BBQ_Grill": a(yaw=face_yaw(P, "SM_BBQ_Grill", (4.2, -2.0), -90))})
Q(P, "hard", "SM_Parasol_A and SM_Parasol_B: swap 'em",
  [M("SM_Parasol_A", [9.4, 0, -3.0]), M("SM_Parasol_B", [-9.4, 0, 3.0]), U],
  {"SM_Parasol_A": a([9.4, 0, -3.0]), "SM_Parasol_B": a([-9.4, 0, 3.0])})
Q(P, "hard", "i want the sofa and the firepit both moved 2ft to the right",
  [M("SM_OutdoorSofa", [0.6096, 0, 0], 0.03), M("SM_FirePit_Round", [0.6096, 0, 0], 0.03), U, NC],
  {"SM_OutdoorSofa": a([0.6096, 0, 0]), "SM_FirePit_Round": a([0.6096, 0, 0])})
Q(P, "hard", "move all the dining chairs apart from SM_DiningChair_02 30 cm to the left",
  [M(c, [-0.3, 0, 0]) for c in _chairs if c != "SM_DiningChair_02"] + [U, NC],
  {c: a([-0.3, 0, 0]) for c in _chairs if c != "SM_DiningChair_02"})
Q(P, "hard", "move SM_Hammock_01 next to the BBQ", [REF()], None)
Q(P, "hard", "move SM_Lounger_03 back a bit", [REF()], None)
Q(P, "hard", "move the pool lounger next to the pool", [REF()], None)

# ============================================================================
# LAB
# ============================================================================
L = "lab"
_benches = ["Bench A1", "Bench A2", "Bench A3", "Bench B1", "Bench B2", "Bench B3"]
# --- simple
Q(L, "simple", "move stool 4 30cm to the right", [M("Stool 4", [0.3, 0, 0]), U, NC], {"Stool 4": a([0.3, 0, 0])})
Q(L, "simple", "rotate the microscope 90 degrees clockwise",
  [R("Microscope", -90), M("Microscope", Z), ON("Microscope", "Bench A2"), U], {"Microscope": a(yaw=-90)})
Q(L, "simple", "move teh waste bin 1 m to the left", [M("Waste Bin", [-1, 0, 0]), U, NC], {"Waste Bin": a([-1, 0, 0])})
Q(L, "simple", "move the coat rack 50 cm to the right", [M("Coat Rack", [0.5, 0, 0]), U, NC],
  {"Coat Rack": a([0.5, 0, 0])})
Q(L, "simple", "I'd like the centrifuge 20 cm further to the left", [M("Centrifuge", [-0.2, 0, 0]), U, NC], {"Centrifuge": a([-0.2, 0, 0])})
Q(L, "simple", "scale the fume hood down to 90%", [S("Fume Hood", 0.9), U], {"Fume Hood": a(s=0.9)})
Q(L, "simple", "turn the instructor desk around",
  [R("Instructor Desk", 180, either=True), M("Instructor Desk", Z), ON("Laptop", "Instructor Desk"), U],
  {"Instructor Desk": a(yaw=180), "Laptop": orbit(L, "Instructor Desk", "Laptop", 180)})
Q(L, "simple", "Stool 9: move it forward 20cm", [M("Stool 9", [0, 0, 0.2]), U, NC], {"Stool 9": a([0, 0, 0.2])})
Q(L, "simple", "shift Bench B3 50 cm to the right",
  [M("Bench B3", [0.5, 0, 0]), ON("Test Tube Rack", "Bench B3"), ON("Spectrophotometer", "Bench B3"),
   KEEP(L, "Bench B3", "Test Tube Rack", "Spectrophotometer", "Stool 11", "Stool 12"), NC],
  {"Bench B3": a([0.5, 0, 0]), "Test Tube Rack": a([0.5, 0, 0]), "Spectrophotometer": a([0.5, 0, 0])})
Q(L, "simple", "move the hot plate 10cm to the right", [M("Hot Plate", [0.1, 0, 0]), U, NC], {"Hot Plate": a([0.1, 0, 0])})
Q(L, "simple", "rotate Bench A1 by 180 degrees",
  [R("Bench A1", 180, either=True), M("Bench A1", Z), ON("Pipette Stand", "Bench A1"), ON("Bunsen Burner", "Bench A1"),
   KEEP(L, "Bench A1", "Pipette Stand", "Bunsen Burner", "Stool 1", "Stool 2"), NC],
  {"Bench A1": a(yaw=180), "Pipette Stand": orbit(L, "Bench A1", "Pipette Stand", 180),
   "Bunsen Burner": orbit(L, "Bench A1", "Bunsen Burner", 180)})
Q(L, "simple", "move the lab fridge 40cm left", [M("Lab Fridge", [-0.4, 0, 0]), U, NC], {"Lab Fridge": a([-0.4, 0, 0])})
Q(L, "simple", "move Beaker 1L 15cm to the left", [M("Beaker 1L", [-0.15, 0, 0]), U], {"Beaker 1L": a([-0.15, 0, 0])})
Q(L, "simple", "make the waste bin 25% bigger", [S("Waste Bin", 1.25), U], {"Waste Bin": a(s=1.25)})
Q(L, "simple", "move stool 11 10cm right", [M("Stool 11", [0.1, 0, 0]), U, NC], {"Stool 11": a([0.1, 0, 0])})
Q(L, "simple", "turn the spectrophotometer 90\u00b0 anticlockwise",
  [R("Spectrophotometer", 90), M("Spectrophotometer", Z), ON("Spectrophotometer", "Bench B3"), U, NC],
  {"Spectrophotometer": a(yaw=90)})
Q(L, "simple", "move the bench 50cm left", [REF(*_benches)], None)

# --- compositional
Q(L, "compositional", "put the beaker 250ml on bench B2",
  [ON("Beaker 250ml", "Bench B2"), U, NC], {"Beaker 250ml": to(L, "Beaker 250ml", [-0.4, 0.9, 1.0])})
Q(L, "compositional", "move bench A2 and its stools 1 m forward",
  [M("Bench A2", [0, 0, 1]), M("Stool 3", [0, 0, 1]), M("Stool 4", [0, 0, 1]),
   ON("Microscope", "Bench A2"), ON("Beaker 250ml", "Bench A2"), U, NC],
  {n: a([0, 0, 1]) for n in ("Bench A2", "Stool 3", "Stool 4", "Microscope", "Beaker 250ml")})
Q(L, "compositional", "put the bunsen burner next to the hotplate",
  [NT("Bunsen Burner", "Hot Plate", 0.3), ON("Bunsen Burner", "Bench B1"), U, NC],
  {"Bunsen Burner": to(L, "Bunsen Burner", [-2.3, 0.9, 1.0])})
Q(L, "compositional", "move stools 7 to 9 50cm forward",
  [M("Stool %d" % i, [0, 0, 0.5]) for i in (7, 8, 9)] + [U, NC],
  {"Stool %d" % i: a([0, 0, 0.5]) for i in (7, 8, 9)})
Q(L, "compositional", "swap the centrifuge and the spectrophotometer",
  [M("Centrifuge", [3.1, 0, -0.05]), M("Spectrophotometer", [-3.1, 0, 0.05]), U],
  {"Centrifuge": a([3.1, 0, -0.05]), "Spectrophotometer": a([-3.1, 0, 0.05])})
Q(L, "compositional", "could you put the microscope on the instuctor desk",
  [ON("Microscope", "Instructor Desk"), U, NC], {"Microscope": to(L, "Microscope", [-0.4, 0.75, 4.0])})
Q(L, "compositional", "move bench B1 back 30cm, with everything on it",
  [M("Bench B1", [0, 0, -0.3]), M("Beaker 500ml", [0, 0, -0.3]), M("Hot Plate", [0, 0, -0.3]),
   KEEP(L, "Bench B1", "Beaker 500ml", "Hot Plate", "Stool 7", "Stool 8"), NC],
  {n: a([0, 0, -0.3]) for n in ("Bench B1", "Beaker 500ml", "Hot Plate")})
Q(L, "compositional", "put the pipette stand on bench A2 next to the microscope",
  [ON("Pipette Stand", "Bench A2"), NT("Pipette Stand", "Microscope", 0.3), U, NC],
  {"Pipette Stand": to(L, "Pipette Stand", [-0.15, 0.9, -2.05])})
Q(L, "compositional", "move stool 5 and stool 6 over to bench B3",
  [NT("Stool 5", "Bench B3", 0.3), NT("Stool 6", "Bench B3", 0.3), U, NC],
  {"Stool 5": to(L, "Stool 5", [2.5, 0, 0.35]), "Stool 6": to(L, "Stool 6", [3.5, 0, 0.35])})
Q(L, "compositional", "turn the microscope to face stool 4",
  [FACE("Microscope", "Stool 4"), M("Microscope", Z), ON("Microscope", "Bench A2"), U],
  {"Microscope": a(yaw=face_yaw(L, "Microscope", (0.5, -1.35), 0))})
Q(L, "compositional", "move the waste bin next to the eyewash station",
  [NT("Waste Bin", "Eyewash Station", 0.4), M("Waste Bin", [None, 0, None]), U, NC],
  {"Waste Bin": to(L, "Waste Bin", [5.7, 0, 1.6])})
Q(L, "compositional", "put the beaker on bench B3", [REF("Beaker 250ml", "Beaker 500ml", "Beaker 1L")], None)
Q(L, "compositional", "put the microscope on the bench by the window", [REF()], None)

# --- fuzzy
Q(L, "fuzzy", "nudge stool 10 abit to the left", [D("Stool 10", "-x", 0.05), U, NC], {"Stool 10": a([-0.15, 0, 0])})
Q(L, "fuzzy", "the lab fridge could go a bit further left", [D("Lab Fridge", "-x", 0.05), U, NC],
  {"Lab Fridge": a([-0.3, 0, 0])})
Q(L, "fuzzy", "push the sink unit slightly forward", [D("Sink Unit", "+z", 0.03), U, NC], {"Sink Unit": a([0, 0, 0.2])})
Q(L, "fuzzy", "put the microscope somewhere on bench A3",
  [ON("Microscope", "Bench A3"), U, NC], {"Microscope": to(L, "Microscope", [2.6, 0.9, -2.0])})
Q(L, "fuzzy", "move the coat rack way over towards the desk", [D("Coat Rack", "+x", 1.0), U, NC],
  {"Coat Rack": a([3.5, 0, 0])})
Q(L, "fuzzy", "give the centrifuge a slight turn",
  [R("Centrifuge", 15, either=True, tol=13), M("Centrifuge", Z), ON("Centrifuge", "Bench B2"), U],
  {"Centrifuge": a(yaw=15)})
Q(L, "fuzzy", "drag stool 1 a little closer to bench A1", [D("Stool 1", "-z", 0.03), U], {"Stool 1": a([0, 0, -0.06])})
Q(L, "fuzzy", "the spectrophotometer needs to come a bit towards the front edge of the bench",
  [D("Spectrophotometer", "+z", 0.03), ON("Spectrophotometer", "Bench B3"), U, NC],
  {"Spectrophotometer": a([0, 0, 0.15])})
Q(L, "fuzzy", "slide Bench A3 a little to the left",
  [D("Bench A3", "-x", 0.05), ON("Beaker 1L", "Bench A3"), KEEP(L, "Bench A3", "Beaker 1L", "Stool 5", "Stool 6"), NC],
  {"Bench A3": a([-0.3, 0, 0]), "Beaker 1L": a([-0.3, 0, 0])})
Q(L, "fuzzy", "turn the instructor desk a little clockwise",
  [R("Instructor Desk", -15, tol=13), M("Instructor Desk", Z), ON("Laptop", "Instructor Desk"), U, NC],
  {"Instructor Desk": a(yaw=-15), "Laptop": orbit(L, "Instructor Desk", "Laptop", -15)})
Q(L, "fuzzy", "move Beaker 1L a bit closer to the middle of its bench",
  [AT("Beaker 1L", [3.0, None, -2.0], 0.45), ON("Beaker 1L", "Bench A3"), U], {"Beaker 1L": a([-0.3, 0, 0])})
Q(L, "fuzzy", "stool 12: scoot it out a bit further from its bench", [D("Stool 12", "+z", 0.05), U, NC],
  {"Stool 12": a([0, 0, 0.3])})
Q(L, "fuzzy", "slide the stool a bit closer to the bench", [REF()], None)

# --- compositional_fuzzy
Q(L, "compositional_fuzzy", "pull the stools at the front row of benches out a little",
  [D("Stool %d" % i, "+z", 0.05) for i in range(7, 13)] + [U, NC],
  {"Stool %d" % i: a([0, 0, 0.2]) for i in range(7, 13)})
Q(L, "compositional_fuzzy", "move bench B2 and its stools a bit to the right",
  [D("Bench B2", "+x", 0.05), D("Stool 9", "+x", 0.05), D("Stool 10", "+x", 0.05), ON("Centrifuge", "Bench B2"), U, NC],
  {n: a([0.4, 0, 0]) for n in ("Bench B2", "Stool 9", "Stool 10", "Centrifuge")})
Q(L, "compositional_fuzzy", "spread stools 3 and 4 a little further apart",
  [D("Stool 3", "-x", 0.05), D("Stool 4", "+x", 0.05), U, NC],
  {"Stool 3": a([-0.15, 0, 0]), "Stool 4": a([0.15, 0, 0])})
Q(L, "compositional_fuzzy", "put the beakers roughly together on bench A2",
  [ON("Beaker 500ml", "Bench A2"), ON("Beaker 1L", "Bench A2"), ON("Beaker 250ml", "Bench A2"),
   DIST("Beaker 500ml", "Beaker 250ml", mx=0.4), DIST("Beaker 1L", "Beaker 250ml", mx=0.4), U, NC],
  {"Beaker 500ml": to(L, "Beaker 500ml", [0.55, 0.9, -1.9]), "Beaker 1L": to(L, "Beaker 1L", [0.45, 0.9, -2.1])})
Q(L, "compositional_fuzzy", "slide the fume hood and the chemical cabinet a little towards each other",
  [D("Fume Hood", "+x", 0.05), D("Chemical Cabinet", "-x", 0.05), U, NC],
  {"Fume Hood": a([0.2, 0, 0]), "Chemical Cabinet": a([-0.5, 0, 0])})
Q(L, "compositional_fuzzy", "shift stools 1 and 2 slightly right and stools 7 and 8 slightly left",
  [D("Stool 1", "+x", 0.03), D("Stool 2", "+x", 0.03), D("Stool 7", "-x", 0.03), D("Stool 8", "-x", 0.03), U, NC],
  {"Stool 1": a([0.15, 0, 0]), "Stool 2": a([0.15, 0, 0]), "Stool 7": a([-0.15, 0, 0]), "Stool 8": a([-0.15, 0, 0])})
Q(L, "compositional_fuzzy", "move bench B3 a little to the left, stools and all",
  [D("Bench B3", "-x", 0.05), D("Stool 11", "-x", 0.05), D("Stool 12", "-x", 0.05),
   ON("Test Tube Rack", "Bench B3"), ON("Spectrophotometer", "Bench B3"), U, NC],
  {n: a([-0.3, 0, 0]) for n in ("Bench B3", "Stool 11", "Stool 12", "Test Tube Rack", "Spectrophotometer")})
Q(L, "compositional_fuzzy", "scoot the centrifuge a little to the right and turn it slightly",
  [D("Centrifuge", "+x", 0.03), R("Centrifuge", 15, either=True, tol=13), ON("Centrifuge", "Bench B2"), U, NC],
  {"Centrifuge": a([0.2, 0, 0], 15)})
Q(L, "compositional_fuzzy", "push both beakers on the back-row benches a bit toward the back of their benches",
  [D("Beaker 250ml", "-z", 0.03), D("Beaker 1L", "-z", 0.03), ON("Beaker 250ml", "Bench A2"), ON("Beaker 1L", "Bench A3"), U],
  {"Beaker 250ml": a([0, 0, -0.2]), "Beaker 1L": a([0, 0, -0.2])})
Q(L, "compositional_fuzzy", "move the beaker and the stool a bit to the left", [REF()], None)

# --- hard
Q(L, "hard", "put beaker 500ml on the same bench as the centrifuge",
  [ON("Beaker 500ml", "Bench B2"), U, NC], {"Beaker 500ml": to(L, "Beaker 500ml", [-0.4, 0.9, 1.0])})
Q(L, "hard", "everything on bench B3 should go onto bench A3",
  [ON("Spectrophotometer", "Bench A3"), ON("Test Tube Rack", "Bench A3"), U, NC],
  {"Spectrophotometer": to(L, "Spectrophotometer", [2.5, 0.9, -2.0]),
   "Test Tube Rack": to(L, "Test Tube Rack", [3.0, 0.9, -2.0])})
Q(L, "hard", "Bench A2 + its stools + whatever's on it: 50cm left",
  [M(n, [-0.5, 0, 0]) for n in ("Bench A2", "Stool 3", "Stool 4", "Microscope", "Beaker 250ml")] + [U, NC],
  {n: a([-0.5, 0, 0]) for n in ("Bench A2", "Stool 3", "Stool 4", "Microscope", "Beaker 250ml")})
Q(L, "hard", "the beaker that's on the same bench as the microscope needs to go next to the centrifuge",
  [NT("Beaker 250ml", "Centrifuge", 0.25), ON("Beaker 250ml", "Bench B2"), U, NC],
  {"Beaker 250ml": to(L, "Beaker 250ml", [0.65, 0.9, 1.0])})
Q(L, "hard", "all stools except stool 6 and stool 12 \u2013 10cm to the left",
  [M("Stool %d" % i, [-0.1, 0, 0]) for i in range(1, 13) if i not in (6, 12)] + [U, NC],
  {"Stool %d" % i: a([-0.1, 0, 0]) for i in range(1, 13) if i not in (6, 12)})
Q(L, "hard", "turn the microscope and the spectrophotometer so they both face the instructor desk",
  [FACE("Microscope", "Instructor Desk"), FACE("Spectrophotometer", "Instructor Desk"),
   ON("Microscope", "Bench A2"), ON("Spectrophotometer", "Bench B3"), U, NC],
  {"Microscope": a(yaw=face_yaw(L, "Microscope", (0.0, 4.0), 0)),
   "Spectrophotometer": a(yaw=face_yaw(L, "Spectrophotometer", (0.0, 4.0), 0))})
Q(L, "hard", "move stools 2 and 7 3 inches closer to their benches",
  [M("Stool 2", [0, 0, -0.0762], 0.02), M("Stool 7", [0, 0, -0.0762], 0.02), U],
  {"Stool 2": a([0, 0, -0.0762]), "Stool 7": a([0, 0, -0.0762])})
Q(L, "hard", "put the laptop on whichever bench is closest to the instructor desk",
  [ON("Laptop", "Bench B2"), U, NC], {"Laptop": to(L, "Laptop", [-0.4, 0.9, 1.0])})
Q(L, "hard", "swap Bench A1 with Bench B1, including what's on them",
  [M("Bench A1", [0, 0, 3]), M("Bench B1", [0, 0, -3]), M("Pipette Stand", [0, 0, 3]), M("Bunsen Burner", [0, 0, 3]),
   M("Beaker 500ml", [0, 0, -3]), M("Hot Plate", [0, 0, -3]),
   KEEP(L, "Bench A1", "Bench B1", "Pipette Stand", "Bunsen Burner", "Beaker 500ml", "Hot Plate",
        "Stool 1", "Stool 2", "Stool 7", "Stool 8"), NC],
  {"Bench A1": a([0, 0, 3]), "Pipette Stand": a([0, 0, 3]), "Bunsen Burner": a([0, 0, 3]),
   "Bench B1": a([0, 0, -3]), "Beaker 500ml": a([0, 0, -3]), "Hot Plate": a([0, 0, -3])})
Q(L, "hard", "Move the pipette stand 6\" to the right",
  [M("Pipette Stand", [0.1524, 0, 0], 0.02), U], {"Pipette Stand": a([0.1524, 0, 0])})
Q(L, "hard", "the middle bench in the back row - slide it 10cm back",
  [M("Bench A2", [0, 0, -0.1]), ON("Microscope", "Bench A2"), ON("Beaker 250ml", "Bench A2"),
   KEEP(L, "Bench A2", "Microscope", "Beaker 250ml", "Stool 3", "Stool 4"), NC],
  {n: a([0, 0, -0.1]) for n in ("Bench A2", "Microscope", "Beaker 250ml")})
Q(L, "hard", "move both benches in the left column 20cm to the left, with their stuff",
  [M("Bench A1", [-0.2, 0, 0]), M("Bench B1", [-0.2, 0, 0]),
   ON("Pipette Stand", "Bench A1"), ON("Bunsen Burner", "Bench A1"), ON("Beaker 500ml", "Bench B1"), ON("Hot Plate", "Bench B1"),
   KEEP(L, "Bench A1", "Bench B1", "Pipette Stand", "Bunsen Burner", "Beaker 500ml", "Hot Plate",
        "Stool 1", "Stool 2", "Stool 7", "Stool 8"), NC],
  {n: a([-0.2, 0, 0]) for n in ("Bench A1", "Bench B1", "Pipette Stand", "Bunsen Burner", "Beaker 500ml", "Hot Plate")})
Q(L, "hard", "move the autoclave next to the sink", [REF()], None)
Q(L, "hard", "move Bench C2 back a metre", [REF()], None)
Q(L, "hard", "move stool 13 to bench A1", [REF()], None)


# ----------------------------------------------------------------------------
def main():
    for key, sc in SCENES.items():
        with open(os.path.join(HERE, FILES[key]), "w") as f:
            json.dump(sc, f, indent=1)
            f.write("\n")
    suite = {"name": "holdout7", "scenes": [FILES[k] for k in SCENES], "variations": 1, "seed": 7,
             "queries": QUERIES}
    with open(os.path.join(HERE, "holdout7.suite.json"), "w") as f:
        json.dump(suite, f, indent=1, ensure_ascii=False)
        f.write("\n")
    with open(os.path.join(HERE, "holdout7.answers.json"), "w") as f:
        json.dump({"note": "hand-worked expected motion per query; read only by validate.py",
                   "answers": ANSWERS}, f, indent=1)
        f.write("\n")
    cats = {}
    for q in QUERIES:
        cats[q["category"]] = cats.get(q["category"], 0) + 1
    print("wrote %d queries %s, %d refusals" % (len(QUERIES), cats,
                                                 sum(1 for v in ANSWERS.values() if v.get("refuse"))))


if __name__ == "__main__":
    main()
