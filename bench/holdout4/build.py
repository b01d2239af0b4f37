#!/usr/bin/env python3
"""Builds the holdout4 scenes and suite (stdlib only). Run: python3 build.py

Three new scenes, written blind (from SPEC.md and the suite format only):
  ue_loft_studio  - a game-engine export: Unreal/Unity/Blender names (SM_Couch_01, Lamp_Floor.002,
                    ShelfUnit_R, BP_Crate_03, Mug_Blue ...), no categories, no aliases
  meeting_room_8  - a meeting room with many identical things: chair 1 ... chair 8 around one
                    table, three glasses, two laptops, two cups, two stools
  bike_shop       - a small bike shop with a service bench, a counter, three display bikes

Conventions used for every worked amount (SPEC 1-3):
  right = +X, left = -X, up = +Y, forward/front = +Z, back = -Z; metres; the viewer looks from +Z,
  so the "back wall" is the wall at min z and the "front wall" the one at max z.
  +90 deg about +Y takes +Z to +X; for a point (x, z) relative to the pivot a yaw of t gives
  x' = x cos t + z sin t,  z' = -x sin t + z cos t.  "clockwise" (seen from above) = negative.
  The pivot is the bottom centre of the box; for a yaw-only rotation it is also the bottom centre
  of the world AABB, so `moved` deltas are pivot deltas.
  Things resting on a moved object move with it (same delta; for a rotation they turn about the
  support's pivot) unless the instruction holds them.
  "against" / "flush against" / "until it touches" / "as far as it will go" = gap 0 (tol 0.02-0.03).
  "N cm towards X" = N cm along the floor-plan line from the object's centre to X's centre; where a
  wall or door is meant the object is chosen so the axis reading and the centre-line reading agree
  (or the tolerance covers both).
  "push in" a chair = towards the table; "pull out" = away from it.
  Vague amounts: "a smidge / a tad / a touch" -> direction, min 0.01; "a bit / a little" -> min 0.03;
  "a few inches" -> min 0.04; "a couple of feet" -> 0.61 m with tol 0.15.
  1 ft = 0.3048 m, 1 in = 0.0254 m.
All boxes in the comments are world AABBs worked out by hand; validate.py re-checks them and
simulates every worked answer.
"""
import json, math, os

HERE = os.path.dirname(os.path.abspath(__file__))
S2 = 0.7071067812
R90 = [0, S2, 0, S2]       # +90 deg about Y: front +Z -> +X
RM90 = [0, -S2, 0, S2]     # -90 deg about Y: front +Z -> -X
R180 = [0, 1, 0, 0]        # front +Z -> -Z
FT, IN = 0.3048, 0.0254


def o(name, size, pos, rot=None):
    d = {"name": name, "position": pos, "size": size}
    if rot is not None:
        d["rotation"] = rot
    return d


# ---------------------------------------------------------------- (a) game-engine loft studio
# room x[-4,4] y[0,2.8] z[-3,3]; couch at the back wall facing +z, TV console at the front wall
LOFT = {
    "name": "ue_loft_studio",
    "bounds": {"min": [-4, 0, -3], "max": [4, 2.8, 3]},
    "objects": [
        o("SM_Couch_01", [2.2, 0.85, 0.95], [0, 0, -2.45]),              # x[-1.1,1.1] z[-2.925,-1.975]
        o("Rug_Jute", [2.0, 0.01, 1.4], [0, 0, -0.9]),                   # x[-1,1] z[-1.6,-0.2] top 0.01
        o("CoffeeTable_Walnut", [1.2, 0.44, 0.6], [0, 0.01, -0.9]),      # on the rug: x[-0.6,0.6] z[-1.2,-0.6] top 0.45
        o("Mug_Blue", [0.1, 0.1, 0.1], [-0.3, 0.45, -0.9]),              # x[-0.35,-0.25] z[-0.95,-0.85]
        o("Mug_Red", [0.1, 0.1, 0.1], [0.35, 0.45, -0.75]),              # x[0.3,0.4] z[-0.8,-0.7]
        o("Controller_Gamepad", [0.16, 0.05, 0.1], [0.05, 0.45, -1.05]), # x[-0.03,0.13] z[-1.1,-1.0]
        o("Lamp_Floor.001", [0.4, 1.6, 0.4], [-1.5, 0, -2.6]),           # x[-1.7,-1.3] z[-2.8,-2.4]
        o("Lamp_Floor.002", [0.4, 1.6, 0.4], [1.5, 0, -2.6]),            # x[1.3,1.7]
        o("ShelfUnit_L", [1.0, 1.8, 0.4], [-3.8, 0, 0.6], R90),          # x[-4,-3.6] z[0.1,1.1] top 1.8
        o("ShelfUnit_R", [1.0, 1.8, 0.4], [3.8, 0, 0.6], RM90),          # x[3.6,4] z[0.1,1.1] top 1.8
        o("Mug_White", [0.1, 0.1, 0.1], [-3.8, 1.8, 0.4]),               # x[-3.85,-3.75] z[0.35,0.45] on L
        o("Books_Stack.001", [0.25, 0.12, 0.18], [-3.8, 1.8, 0.8]),      # x[-3.925,-3.675] z[0.71,0.89] on L
        o("Vase_Green", [0.15, 0.3, 0.15], [3.8, 1.8, 0.6]),             # x[3.725,3.875] z[0.525,0.675] on R
        o("SM_MediaConsole_01", [1.8, 0.5, 0.45], [0, 0, 2.75], R180),   # x[-0.9,0.9] z[2.525,2.975] top 0.5
        o("SM_TV_55in", [1.25, 0.75, 0.08], [0, 0.5, 2.8], R180),        # x[-0.625,0.625] z[2.76,2.84]
        o("SM_Speaker_L", [0.25, 1.0, 0.25], [-1.3, 0, 2.8]),            # x[-1.425,-1.175] z[2.675,2.925]
        o("SM_Speaker_R", [0.25, 1.0, 0.25], [1.3, 0, 2.8]),             # x[1.175,1.425]
        o("BP_Crate_01", [0.5, 0.4, 0.5], [-3.4, 0, 2.6]),               # x[-3.65,-3.15] z[2.35,2.85]
        o("BP_Crate_02", [0.5, 0.4, 0.5], [-2.7, 0, 2.6]),               # x[-2.95,-2.45]
        o("BP_Crate_03", [0.5, 0.4, 0.5], [-2.0, 0, 2.6]),               # x[-2.25,-1.75]
        o("BP_Crate_04", [0.5, 0.4, 0.5], [-3.4, 0.4, 2.6]),             # stacked on 01, y[0.4,0.8]
        o("SM_Recliner_01", [0.85, 0.9, 0.85], [-2.2, 0, -0.9], R90),    # x[-2.625,-1.775] z[-1.325,-0.475], faces +x
        o("SideTable_Metal", [0.45, 0.55, 0.45], [-2.2, 0, 0.2]),        # x[-2.425,-1.975] z[-0.025,0.425] top 0.55
        o("Candle_01", [0.08, 0.12, 0.08], [-2.2, 0.55, 0.2]),           # x[-2.24,-2.16] z[0.16,0.24]
        o("Plant_Ficus.003", [0.55, 1.3, 0.55], [3.5, 0, -2.5]),         # x[3.225,3.775] z[-2.775,-2.225]
        o("Door_Entrance", [0.9, 2.1, 0.05], [3.975, 0, 2.0], RM90),     # x[3.95,4] z[1.55,2.45]
        o("Beanbag_Grey", [0.7, 0.5, 0.7], [1.6, 0, 2.0]),               # x[1.25,1.95] z[1.65,2.35]
    ],
}

# ---------------------------------------------------------------- (b) meeting room, 8 chairs
# room x[-3.5,3.5] y[0,2.7] z[-3,3]; TV on the left wall, whiteboard at the back, door at the front
# chairs 1-3 behind the table (left to right, facing +z), chair 4 at the right end (facing -x),
# chairs 5-7 in front (right to left, facing -z), chair 8 at the left end (facing +x, by the TV)
MEET = {
    "name": "meeting_room_8",
    "bounds": {"min": [-3.5, 0, -3], "max": [3.5, 2.7, 3]},
    "objects": [
        o("meeting table", [3.0, 0.74, 1.2], [0, 0, 0]),             # x[-1.5,1.5] z[-0.6,0.6] top 0.74
        o("chair 1", [0.5, 0.9, 0.5], [-1.0, 0, -1.0]),              # x[-1.25,-0.75] z[-1.25,-0.75]
        o("chair 2", [0.5, 0.9, 0.5], [0.0, 0, -1.0]),               # x[-0.25,0.25]
        o("chair 3", [0.5, 0.9, 0.5], [1.0, 0, -1.0]),               # x[0.75,1.25]
        o("chair 4", [0.5, 0.9, 0.5], [1.95, 0, 0.0], RM90),         # x[1.7,2.2] z[-0.25,0.25]
        o("chair 5", [0.5, 0.9, 0.5], [1.0, 0, 1.0], R180),          # x[0.75,1.25] z[0.75,1.25]
        o("chair 6", [0.5, 0.9, 0.5], [0.0, 0, 1.0], R180),          # x[-0.25,0.25]
        o("chair 7", [0.5, 0.9, 0.5], [-1.0, 0, 1.0], R180),         # x[-1.25,-0.75]
        o("chair 8", [0.5, 0.9, 0.5], [-1.95, 0, 0.0], R90),         # x[-2.2,-1.7] z[-0.25,0.25]
        o("laptop 1", [0.34, 0.02, 0.24], [0.0, 0.74, -0.35]),       # at chair 2: x[-0.17,0.17] z[-0.47,-0.23]
        o("laptop 2", [0.34, 0.02, 0.24], [-1.0, 0.74, 0.35]),       # at chair 7: x[-1.17,-0.83] z[0.23,0.47]
        o("glass 1", [0.08, 0.12, 0.08], [-1.0, 0.74, -0.35]),       # at chair 1: x[-1.04,-0.96] z[-0.39,-0.31]
        o("glass 2", [0.08, 0.12, 0.08], [1.0, 0.74, 0.35]),         # at chair 5: x[0.96,1.04] z[0.31,0.39]
        o("glass 3", [0.08, 0.12, 0.08], [1.0, 0.74, -0.35]),        # at chair 3: x[0.96,1.04] z[-0.39,-0.31]
        o("water jug", [0.15, 0.25, 0.15], [0.5, 0.74, 0.0]),        # x[0.425,0.575] z[-0.075,0.075]
        o("conference phone", [0.25, 0.05, 0.25], [-0.5, 0.74, 0.0]),  # x[-0.625,-0.375] z[-0.125,0.125]
        o("tv stand", [1.6, 0.6, 0.45], [-3.275, 0, 0.0], R90),      # x[-3.5,-3.05] z[-0.8,0.8] top 0.6
        o("tv", [1.4, 0.85, 0.1], [-3.3, 0.6, 0.0], R90),            # x[-3.35,-3.25] z[-0.7,0.7], faces +x
        o("whiteboard", [1.6, 1.9, 0.5], [1.0, 0, -2.7]),            # x[0.2,1.8] z[-2.95,-2.45]
        o("credenza", [1.6, 0.75, 0.45], [3.275, 0, -1.0], RM90),    # x[3.05,3.5] z[-1.8,-0.2] top 0.75
        o("coffee machine", [0.3, 0.4, 0.35], [3.275, 0.75, -1.5]),  # x[3.125,3.425] z[-1.675,-1.325]
        o("cup 1", [0.09, 0.1, 0.09], [3.2, 0.75, -0.9]),            # x[3.155,3.245] z[-0.945,-0.855]
        o("cup 2", [0.09, 0.1, 0.09], [3.2, 0.75, -0.6]),            # z[-0.645,-0.555]
        o("stool 1", [0.4, 0.65, 0.4], [3.15, 0, 2.65]),             # front-right corner: x[2.95,3.35] z[2.45,2.85]
        o("stool 2", [0.4, 0.65, 0.4], [-1.2, 0, 2.6]),              # by the door: x[-1.4,-1.0] z[2.4,2.8]
        o("door", [0.9, 2.1, 0.05], [-2.3, 0, 2.975], R180),         # x[-2.75,-1.85] z[2.95,3.0]
        o("plant", [0.5, 1.2, 0.5], [-3.15, 0, -2.65]),              # x[-3.4,-2.9] z[-2.9,-2.4]
        o("waste bin", [0.3, 0.4, 0.3], [-2.2, 0, -2.75]),           # x[-2.35,-2.05] z[-2.9,-2.6]
        o("coat stand", [0.5, 1.8, 0.5], [3.15, 0, 1.2]),            # x[2.9,3.4] z[0.95,1.45]
    ],
}

# ---------------------------------------------------------------- (c) small bike shop
# room x[-3.5,3.5] y[0,3] z[-3,3]; service bench at the back wall, counter on the left,
# helmet shelf and tyre rack on the right wall, entrance door at the front
SHOP = {
    "name": "bike_shop",
    "bounds": {"min": [-3.5, 0, -3], "max": [3.5, 3, 3]},
    "objects": [
        o("service bench", [1.8, 0.9, 0.65], [0.8, 0, -2.675]),        # x[-0.1,1.7] z[-3,-2.35] top 0.9
        o("spare wheel", [0.62, 0.04, 0.62], [0.3, 0.9, -2.675]),      # x[-0.01,0.61] z[-2.985,-2.365]
        o("parts tray", [0.4, 0.06, 0.3], [1.0, 0.9, -2.7]),           # x[0.8,1.2] z[-2.85,-2.55] top 0.96
        o("lube bottle", [0.06, 0.18, 0.06], [1.45, 0.9, -2.5]),       # x[1.42,1.48] z[-2.53,-2.47]
        o("torque wrench", [0.45, 0.04, 0.06], [1.45, 0.9, -2.85]),    # x[1.225,1.675] z[-2.88,-2.82]
        o("repair stand", [0.6, 1.4, 0.6], [2.5, 0, -2.4]),            # x[2.2,2.8] z[-2.7,-2.1]
        o("floor pump", [0.25, 0.7, 0.25], [-0.5, 0, -2.5]),           # x[-0.625,-0.375] z[-2.625,-2.375]
        o("counter", [2.0, 1.0, 0.6], [-2.6, 0, 0.5], R90),            # x[-2.9,-2.3] z[-0.5,1.5] top 1.0
        o("till", [0.4, 0.3, 0.35], [-2.6, 1.0, 1.0]),                 # x[-2.8,-2.4] z[0.825,1.175] top 1.3
        o("card reader", [0.08, 0.05, 0.15], [-2.5, 1.0, 0.45]),       # x[-2.54,-2.46] z[0.375,0.525]
        o("red helmet", [0.22, 0.2, 0.3], [-2.6, 1.0, -0.1]),          # x[-2.71,-2.49] z[-0.25,0.05]
        o("counter stool", [0.4, 0.75, 0.4], [-3.2, 0, 0.5]),          # x[-3.4,-3.0] z[0.3,0.7]
        o("bike 1", [0.6, 1.05, 1.75], [-0.8, 0, 0.6]),                # x[-1.1,-0.5] z[-0.275,1.475]
        o("bike 2", [0.6, 1.05, 1.75], [0.2, 0, 0.6]),                 # x[-0.1,0.5]
        o("bike 3", [0.6, 1.05, 1.75], [1.2, 0, 0.6]),                 # x[0.9,1.5]
        o("helmet shelf", [1.6, 1.6, 0.4], [3.3, 0, -0.2], RM90),      # x[3.1,3.5] z[-1,0.6] top 1.6
        o("blue helmet", [0.22, 0.2, 0.3], [3.3, 1.6, -0.5]),          # x[3.19,3.41] z[-0.65,-0.35]
        o("black helmet", [0.22, 0.2, 0.3], [3.3, 1.6, 0.2]),          # z[0.05,0.35]
        o("tyre rack", [1.2, 1.8, 0.35], [3.325, 0, 1.8], RM90),       # x[3.15,3.5] z[1.2,2.4]
        o("entrance door", [1.0, 2.1, 0.05], [0.5, 0, 2.975], R180),   # x[0,1] z[2.95,3]
        o("cardboard box 1", [0.6, 0.5, 0.4], [-2.9, 0, -2.6]),        # x[-3.2,-2.6] z[-2.8,-2.4]
        o("cardboard box 2", [0.6, 0.5, 0.4], [-2.9, 0.5, -2.6]),      # stacked on box 1, y[0.5,1.0]
        o("cardboard box 3", [0.6, 0.5, 0.4], [-2.1, 0, -2.6]),        # x[-2.4,-1.8]
        o("trash bin", [0.35, 0.6, 0.35], [-3.2, 0, 2.6]),             # x[-3.375,-3.025] z[2.425,2.775]
        o("floor mat", [1.5, 0.01, 1.0], [0.5, 0, 2.2]),               # x[-0.25,1.25] z[1.7,2.7]
        o("sign board", [0.6, 1.0, 0.5], [-1.5, 0, 2.4]),              # x[-1.8,-1.2] z[2.15,2.65]
    ],
}

# what rests on what (used to carry exact moves to the children); validate.py compares it
# with the geometry
ON = {
    "ue_loft_studio": {"CoffeeTable_Walnut": "Rug_Jute", "Mug_Blue": "CoffeeTable_Walnut",
                       "Mug_Red": "CoffeeTable_Walnut", "Controller_Gamepad": "CoffeeTable_Walnut",
                       "Mug_White": "ShelfUnit_L", "Books_Stack.001": "ShelfUnit_L",
                       "Vase_Green": "ShelfUnit_R", "SM_TV_55in": "SM_MediaConsole_01",
                       "BP_Crate_04": "BP_Crate_01", "Candle_01": "SideTable_Metal"},
    "meeting_room_8": {"laptop 1": "meeting table", "laptop 2": "meeting table",
                       "glass 1": "meeting table", "glass 2": "meeting table",
                       "glass 3": "meeting table", "water jug": "meeting table",
                       "conference phone": "meeting table", "tv": "tv stand",
                       "coffee machine": "credenza", "cup 1": "credenza", "cup 2": "credenza"},
    "bike_shop": {"spare wheel": "service bench", "parts tray": "service bench",
                  "lube bottle": "service bench", "torque wrench": "service bench",
                  "till": "counter", "card reader": "counter", "red helmet": "counter",
                  "blue helmet": "helmet shelf", "black helmet": "helmet shelf",
                  "cardboard box 2": "cardboard box 1"},
}

# ---------------------------------------------------------------- check helpers (SPEC 6 checks only)
def mv(obj, d, tol=None):
    c = {"check": "moved", "object": obj, "delta": [round(x, 4) for x in d]}
    if tol is not None and tol != 0.05:
        c["tol"] = tol
    else:
        mag = max(abs(x) for x in d)
        if 0 < mag < 0.15:           # small exact amounts get a tighter tolerance
            c["tol"] = round(max(0.015, mag / 3), 3)
    return c

def still(obj):
    return {"check": "moved", "object": obj, "delta": [0, 0, 0], "tol": 0.02}

def dr(obj, axis, mn=0.03):
    return {"check": "direction", "object": obj, "axis": axis, "min": mn}

def rot(obj, deg, either=False):
    c = {"check": "rotated", "object": obj, "axis": "+y", "degrees": deg, "tol": 3}
    if either:
        c["either_sign"] = True
    return c

def scl(obj, f):
    return {"check": "scaled", "object": obj, "factor": f}

def top(obj, sup):
    return {"check": "on_top", "object": obj, "support": sup}

def nxt(obj, other, gap=None):
    c = {"check": "next_to", "object": obj, "other": other}
    if gap is not None:
        c["max_gap"] = gap
    return c

def side(obj, other, s, gap=None):
    c = {"check": "side", "object": obj, "other": other, "side": s}
    if gap is not None:
        c["max_gap"] = gap
    return c

def btw(obj, a, b):
    return {"check": "between", "object": obj, "a": a, "b": b}

def faces(obj, t):
    return {"check": "faces", "object": obj, "target": t}

def at(obj, p, tol=0.05):
    return {"check": "at", "object": obj, "position": p, "tol": tol}

def dist(obj, other, mn=None, mx=None):
    c = {"check": "distance", "object": obj, "other": other}
    if mn is not None:
        c["min"] = mn
    if mx is not None:
        c["max"] = mx
    return c

def floor(obj):
    """on the floor (bottom at y 0), anywhere"""
    return at(obj, [None, 0, None], 0.01)

def unch(objs):
    return {"check": "unchanged", "objects": objs}

def ref(m):
    return {"check": "refused", "mentions": m}

NC = {"check": "no_collision"}
IB = {"check": "inside_bounds"}

_scene = None
_objs = {}

def pos(name):
    for d in _objs[_scene]["objects"]:
        if d["name"] == name:
            return d["position"]
    raise KeyError(name)

def swap(a, b):
    """a swap written as two pivot moves"""
    pa, pb = pos(a), pos(b)
    return [mv(a, [pb[i] - pa[i] for i in range(3)]), mv(b, [pa[i] - pb[i] for i in range(3)])]

def carry(obj, d, hold=(), tol=None):
    """moved checks for obj and everything resting on it (transitively), except held ones"""
    out = [mv(obj, d, tol)]
    for child, sup in ON[_scene].items():
        if sup == obj and child not in hold:
            out += carry(child, d, hold, tol)
    return out

def tops(sup, hold=()):
    """on_top checks for everything resting on sup (used with vague moves of sup)"""
    return [top(c, s) for c, s in ON[_scene].items() if s == sup and c not in hold]

QUERIES = []
_count = {}
SHORT = {"ue_loft_studio": "loft", "meeting_room_8": "meet", "bike_shop": "shop"}

def Q(cat, fam, text, *checks):
    checks = list(checks)
    if not any(c["check"] == "refused" for c in checks):
        if NC not in checks:
            checks.append(NC)
        checks.append(unch("others"))
    key = (_scene, fam)
    _count[key] = _count.get(key, 0) + 1
    QUERIES.append({"id": f"{SHORT[_scene]}-{fam}-{_count[key]:02d}", "category": cat,
                    "text": text, "scenes": [_scene], "expect": checks})

S, C, F, CF, H = "simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"
_objs = {"ue_loft_studio": LOFT, "meeting_room_8": MEET, "bike_shop": SHOP}

# ================================================================ (a) loft studio
_scene = "ue_loft_studio"
# -- exact moves
# couch z[-2.925,-1.975] +0.3 -> z[-2.625,-1.675]; rug starts at z -1.6
Q(S, "move", "hey can you move SM_Couch_01 30cm forward", mv("SM_Couch_01", [0, 0, 0.3]))
# blue mug x[-0.35,-0.25] -0.1 -> x[-0.45,-0.35], still on the table (x >= -0.6)
Q(S, "move", "move the bleu mug 10 cm to the left pls", mv("Mug_Blue", [-0.1, 0, 0]))
# shelf R z[0.1,1.1] -0.4 -> z[-0.3,0.7], the vase rides along
Q(S, "move", "could you move the right shelf unit 40 cm towards the back wall",
  *carry("ShelfUnit_R", [0, 0, -0.4]))
# table x[-0.6,0.6] +0.15 -> x[-0.45,0.75], centre 0.15 still over the rug; mugs + gamepad ride along
Q(S, "move", "move the cofee table 15cm right thx", *carry("CoffeeTable_Walnut", [0.15, 0, 0]))
# lamp .002 x[1.3,1.7] +0.3048 -> x[1.6048,2.0048]
Q(S, "move", "move Lamp_Floor.002 a foot to the right", mv("Lamp_Floor.002", [FT, 0, 0], 0.02))
# recliner z[-1.325,-0.475] -0.25 -> z[-1.575,-0.725]
Q(S, "move", "budge the recliner 25 cm back", mv("SM_Recliner_01", [0, 0, -0.25]))
# crate 03 x[-2.25,-1.75] +0.3 -> x[-1.95,-1.45]; left speaker starts at x -1.425
Q(S, "move", "move BP_Crate_03 30 cm to the right", mv("BP_Crate_03", [0.3, 0, 0]))
# vase z[0.525,0.675] +0.2 -> z[0.725,0.875], still on the shelf top (z <= 1.1)
Q(S, "move", "slide the green vase 20 cm foward", mv("Vase_Green", [0, 0, 0.2]))
# left speaker x[-1.425,-1.175] -0.1 -> x[-1.525,-1.275]; crate 03 ends at x -1.75
Q(S, "move", "move the left speaker 10 cm to the left", mv("SM_Speaker_L", [-0.1, 0, 0]))
# console x[-0.9,0.9] -0.2 -> x[-1.1,0.7] (left speaker starts -1.175), the TV rides along
Q(S, "move", "could u move the media console 20cm to the left", *carry("SM_MediaConsole_01", [-0.2, 0, 0]))
# books z[0.71,0.89] -0.1 -> z[0.61,0.79]; white mug ends at z 0.45
Q(S, "move", "move Books_Stack.001 10cm back", mv("Books_Stack.001", [0, 0, -0.1]))
# lamp .001 z[-2.8,-2.4] +0.2 -> z[-2.6,-2.2]; couch starts at x -1.1 (lamp ends -1.3)
Q(S, "move", "I'd like Lamp_Floor.001 moved 20 cm forward", mv("Lamp_Floor.001", [0, 0, 0.2]))
# -- rotations / scale
Q(S, "turn", "turn the beanbag 90 degress clockwise as seen from above", rot("Beanbag_Grey", -90), still("Beanbag_Grey"))
# recliner 0.85 square at 90+45 deg -> half 0.601: x[-2.801,-1.599] z[-1.501,-0.299]; side table starts z -0.025
Q(S, "turn", "rotate SM_Recliner_01 45 degrees counterclockwise", rot("SM_Recliner_01", 45), still("SM_Recliner_01"))
# gamepad 0.16x0.1 turned 90 -> x[0,0.1] z[-1.13,-0.97]; still on the table, clear of the mugs
Q(S, "turn", "rotate the gamepad 90°", rot("Controller_Gamepad", 90, True), still("Controller_Gamepad"))
Q(S, "turn", "would you mind turning the recliner 90 degrees clockwise as seen from above",
  rot("SM_Recliner_01", -90), still("SM_Recliner_01"))
# ficus x1.2 -> 0.66 x 1.56: x[3.17,3.83] z[-2.83,-2.17]
Q(S, "scale", "make the ficus 20% biger pls", scl("Plant_Ficus.003", 1.2), still("Plant_Ficus.003"))
# -- holds
# table -0.3 -> x[-0.9,0.3], centre -0.3 still over the rug x[-1,1]; recliner ends at x -1.775
Q(C, "hold", "move the coffee table 30 cm to the left but leave the rug alone",
  *carry("CoffeeTable_Walnut", [-0.3, 0, 0]), unch(["Rug_Jute"]))
# rug +0.2 -> x[-0.8,1.2]; the table (centre x 0) stays and is still on it
Q(C, "hold", "move the rug 20cm to the right, don't touch the coffee table",
  mv("Rug_Jute", [0.2, 0, 0]),
  unch(["CoffeeTable_Walnut", "Mug_Blue", "Mug_Red", "Controller_Gamepad"]))
# console +0.2 -> x[-0.7,1.1]; right speaker starts at 1.175; TV x[-0.625,0.625] still fully on it
Q(C, "hold", "move the media console 20cm right but leave the TV where it is",
  mv("SM_MediaConsole_01", [0.2, 0, 0]), unch(["SM_TV_55in"]))
# couch -0.15 -> x[-1.25,0.95]; lamp .001 ends at x -1.3
Q(C, "hold", "move the couch 15 cm to the left but don't touch the floor lamps",
  mv("SM_Couch_01", [-0.15, 0, 0]), unch(["Lamp_Floor.001", "Lamp_Floor.002"]))
# -- multi / swaps
Q(C, "multi", "swap the blue mug and the red mug thx", *swap("Mug_Blue", "Mug_Red"))
# couch +0.2 -> centre (0,-2.25); recliner centre (-2.2,-0.9) -> yaw 121.5 deg: half 0.584,
#   x[-2.784,-1.616] z[-1.484,-0.316]
Q(C, "multi", "move the couch 20 cm forward and turn the recliner to face it",
  mv("SM_Couch_01", [0, 0, 0.2]), faces("SM_Recliner_01", "SM_Couch_01"), still("SM_Recliner_01"))
Q(C, "multi", "move the left floor lamp 20 cm left and the right one 20 cm right",
  mv("Lamp_Floor.001", [-0.2, 0, 0]), mv("Lamp_Floor.002", [0.2, 0, 0]))
# crates z[2.35,2.85] +0.1 -> z[2.45,2.95]; the front wall is at 3
Q(C, "multi", "move all teh crates 10cm forward",
  *[mv(n, [0, 0, 0.1]) for n in ("BP_Crate_01", "BP_Crate_02", "BP_Crate_03", "BP_Crate_04")])
Q(C, "multi", "could you swap the two floor lamps?", *swap("Lamp_Floor.001", "Lamp_Floor.002"))
# beanbag -0.5 -> centre (1.1,2.0); TV centre (0,2.8): yaw -54 deg, half 0.489 -> x[0.611,1.589]
#   z[1.511,2.489]; console starts z 2.525, right speaker z 2.675
Q(C, "multi", "move the beanbag 50 cm left and turn it to face the TV",
  mv("Beanbag_Grey", [-0.5, 0, 0]), faces("Beanbag_Grey", "SM_TV_55in"))
# vase (3.8,1.8,0.6) <-> books (-3.8,1.8,0.8)
Q(C, "multi", "swap Vase_Green and Books_Stack.001", *swap("Vase_Green", "Books_Stack.001"))
# beanbag +0.3 -> centre (1.9,2.0), at 45 deg half 0.495: x[1.405,2.395] z[1.505,2.495]
Q(C, "multi", "rotate the beanbag 45 degrees and move it 30 cm toward the door",
  rot("Beanbag_Grey", 45, True), mv("Beanbag_Grey", [0.3, 0, 0]))
# -- placements / vague amounts
Q(F, "vague", "scoot the recliner a tad to the rigth", dr("SM_Recliner_01", "+x", 0.01))
# beanbag -0.6096 -> x[0.64,1.34]; console starts at z 2.525 (no overlap in z)
Q(F, "vague", "move the beanbag a couple of feet to the left", mv("Beanbag_Grey", [-2 * FT, 0, 0], 0.15))
# blue (-0.3,-0.9) to red (0.35,-0.75): 0.667 apart; "a little closer" = at least 2 cm closer
Q(F, "vague", "push the blue mug a little closer to the red one",
  dist("Mug_Blue", "Mug_Red", 0.1, 0.647), top("Mug_Blue", "CoffeeTable_Walnut"))
Q(F, "vague", "hey move the couch a bit forward", dr("SM_Couch_01", "+z", 0.03))
Q(F, "vague", "could you slide the coffee table a touch to the left",
  dr("CoffeeTable_Walnut", "-x", 0.01), *tops("CoffeeTable_Walnut"))
# shelf R z max 1.1, the door (same x) starts at z 1.55
Q(F, "vague", "shift the right shelf unit a smidge forward", dr("ShelfUnit_R", "+z", 0.01), *tops("ShelfUnit_R"))
Q(F, "place", "put the candle on top of the media console", top("Candle_01", "SM_MediaConsole_01"))
Q(F, "place", "put the gamepad on the recliner pls", top("Controller_Gamepad", "SM_Recliner_01"))
Q(F, "place", "park the beanbag next to the cocuh", nxt("Beanbag_Grey", "SM_Couch_01"))
Q(F, "place", "would you mind putting the green vase on the coffee table?", top("Vase_Green", "CoffeeTable_Walnut"))
Q(F, "place", "put the blue mug on the side table next to the candle",
  top("Mug_Blue", "SideTable_Metal"), nxt("Mug_Blue", "Candle_01"))
# crate 04 down to the floor beside crate 03 (next_to needs the heights to overlap)
Q(F, "place", "take the top crate down and put it on the floor next to the third crate",
  floor("BP_Crate_04"), nxt("BP_Crate_04", "BP_Crate_03"))
Q(F, "place", "put Mug_Red on the second crate", top("Mug_Red", "BP_Crate_02"))
Q(F, "place", "put the blue mug on the shelf unit on the right", top("Mug_Blue", "ShelfUnit_R"))
# -- compositional with vague parts
Q(CF, "combo", "hey, put the red mug on the side table and scoot the recliner a bit forward",
  top("Mug_Red", "SideTable_Metal"), dr("SM_Recliner_01", "+z", 0.03))
Q(CF, "combo", "put both mugs from the coffee table on the right shelf unit",
  top("Mug_Blue", "ShelfUnit_R"), top("Mug_Red", "ShelfUnit_R"))
Q(CF, "combo", "grab the white mug off the shelf, put it on the coffee table and nudge the blue mug a tad to the left",
  top("Mug_White", "CoffeeTable_Walnut"), dr("Mug_Blue", "-x", 0.01), top("Mug_Blue", "CoffeeTable_Walnut"))
# beanbag centre z 2.0 = the door's centre z, so "toward the door" is +x either way
Q(CF, "combo", "move the beanbag a bit toward the door but keep the couch where it is",
  dr("Beanbag_Grey", "+x", 0.03), unch(["SM_Couch_01"]))
Q(CF, "combo", "pls move the couch a little forward and put the gamepad on it",
  dr("SM_Couch_01", "+z", 0.03), top("Controller_Gamepad", "SM_Couch_01"))
# table back by d (a bit, < 0.3): the blue mug (centre z -0.9) stays over it; red mug + gamepad ride
Q(CF, "combo", "slide the coffee table a bit toward the couch, leave the blue mug where it is",
  dr("CoffeeTable_Walnut", "-z", 0.03), *tops("CoffeeTable_Walnut", hold=("Mug_Blue",)), unch(["Mug_Blue"]))
# lamp .001 x max -1.3, couch x min -1.1 (a few inches < 0.2); beanbag centre (1.6,2.0) to couch
#   centre (0,-2.45): yaw -160.2 deg, half 0.448 -> x[1.152,2.048] z[1.552,2.448]
Q(CF, "combo", "move the left floor lamp a few inches toward the couch and turn the beanbag to face the couch",
  dr("Lamp_Floor.001", "+x", 0.04), faces("Beanbag_Grey", "SM_Couch_01"), still("Beanbag_Grey"))
Q(CF, "combo", "could you put the books on the coffee table and shove the left shelf unit back a bit",
  top("Books_Stack.001", "CoffeeTable_Walnut"), dr("ShelfUnit_L", "-z", 0.03), top("Mug_White", "ShelfUnit_L"))
Q(CF, "combo", "put Candle_01 on the right shelf unit next to the vase and nudge the side table a smidge left",
  top("Candle_01", "ShelfUnit_R"), nxt("Candle_01", "Vase_Green"), dr("SideTable_Metal", "-x", 0.01))
# -- relations, walls, corners, flush
Q(H, "rel", "scoot the beanbag 20 cm toward the door", mv("Beanbag_Grey", [0.2, 0, 0]))
# recliner centre (-2.2,-0.9) to door (3.975,2.0): yaw 64.8 deg, half 0.566 -> x[-2.77,-1.63] z[-1.47,-0.33]
Q(H, "turn", "turn the reclinr to face the door", faces("SM_Recliner_01", "Door_Entrance"), still("SM_Recliner_01"))
# table -90 about its pivot (0,-0.9): 0.6 x 1.2 -> x[-0.3,0.3] z[-1.5,-0.3], still on the rug
#   blue rel (-0.3,0) -> (0,-0.3): delta (0.3,0,-0.3); red rel (0.35,0.15) -> (-0.15,0.35): delta (-0.5,0,0.2)
#   gamepad rel (0.05,-0.15) -> (0.15,0.05): delta (0.1,0,0.2)
Q(H, "turn", "rotate the coffee table 90 degrees clockwise as seen from above",
  rot("CoffeeTable_Walnut", -90), still("CoffeeTable_Walnut"),
  mv("Mug_Blue", [0.3, 0, -0.3], 0.03), rot("Mug_Blue", -90),
  mv("Mug_Red", [-0.5, 0, 0.2], 0.03), rot("Mug_Red", -90),
  mv("Controller_Gamepad", [0.1, 0, 0.2], 0.03), rot("Controller_Gamepad", -90))
Q(H, "rel", "move the mug on the shelf to the coffee table", top("Mug_White", "CoffeeTable_Walnut"))
Q(H, "rel", "put the crate that's sitting on the other crate onto the second crate", top("BP_Crate_04", "BP_Crate_02"))
# lamp nearest the recliner: .001 (1.84 m) vs .002 (4.07 m); -> x[-2.0,-1.6]
Q(H, "rel", "move the lamp closest to the recliner 30 cm to the left", mv("Lamp_Floor.001", [-0.3, 0, 0]))
# middle of the row 01 / 02 / 03 = 02: z[2.35,2.85] -0.1 -> z[2.25,2.75]
Q(H, "rel", "move the middle crate in the row 10 cm back", mv("BP_Crate_02", [0, 0, -0.1]))
# beanbag centre (1.6,2.0) to TV (0,2.8): yaw -63.4 deg, half 0.469 -> x[1.131,2.069] z[1.531,2.469]
Q(H, "turn", "I'd like the beanbag to face the TV", faces("Beanbag_Grey", "SM_TV_55in"), still("Beanbag_Grey"))
# candle between the mugs: mid (0.025,-0.825); the gamepad (z <= -1.0) leaves room
Q(H, "place", "put the candle on the coffee table, between the blue and the red mug",
  top("Candle_01", "CoffeeTable_Walnut"), btw("Candle_01", "Mug_Blue", "Mug_Red"))
# recliner x min -2.625 -> -4: -1.375 (nothing in z[-1.325,-0.475] on the way)
Q(H, "wall", "drag the recliner as far left as it will go", mv("SM_Recliner_01", [-1.375, 0, 0], 0.03), IB)
# crate 02 z max 2.85 -> 3.0
Q(H, "wall", "push the second crate forward till it hits the wall", mv("BP_Crate_02", [0, 0, 0.15], 0.02), IB)
# lamp .001 x min -1.7 -> -4 (-2.3), z min -2.8 -> -3 (-0.2); nothing in between
Q(H, "wall", "tuck Lamp_Floor.001 into the back left corner", mv("Lamp_Floor.001", [-2.3, 0, -0.2], 0.03), IB)
# couch z min -2.925 -> -3
Q(H, "wall", "push the couch back flush against the wall, thanks!", mv("SM_Couch_01", [0, 0, -0.075], 0.02), IB)
# beanbag z max 2.35 -> right speaker face 2.675 (x overlap [1.25,1.425]): +0.325
Q(H, "wall", "slide the beanbag forward until it's flush against the right speaker",
  mv("Beanbag_Grey", [0, 0, 0.325], 0.03))
# -- refusals
Q(H, "refuse", "hey move the mug 10cm to the right", ref(["Mug_Blue", "Mug_Red", "Mug_White"]))
Q(H, "refuse", "put the blue mug next to the lamp", ref(["Lamp_Floor.001", "Lamp_Floor.002"]))
Q(H, "refuse", "move the crate 20 cm back pls", ref(["BP_Crate_01", "BP_Crate_02", "BP_Crate_03", "BP_Crate_04"]))
Q(H, "refuse", "nudge the floor lamp a bit closer to the couch", ref(["Lamp_Floor.001", "Lamp_Floor.002"]))
Q(H, "refuse", "turn the speaker to face the couch", ref(["SM_Speaker_L", "SM_Speaker_R"]))
Q(H, "refuse", "put the gamepad on the shelf unit", ref(["ShelfUnit_L", "ShelfUnit_R"]))
Q(H, "refuse", "push the piano against the wall", ref([]))
Q(H, "refuse", "move the curtians 30cm left", ref([]))
Q(H, "refuse", "could you put the mug on the side table", ref(["Mug_Blue", "Mug_Red", "Mug_White"]))

# ================================================================ (b) meeting room
_scene = "meeting_room_8"
# chair 3 x[0.75,1.25] +0.2 -> x[0.95,1.45]; chair 4 starts at z -0.25 (chair 3 ends -0.75)
Q(S, "move", "moev chair 3 20cm to the right", mv("chair 3", [0.2, 0, 0]))
# whiteboard x[0.2,1.8] -0.5 -> x[-0.3,1.3]
Q(S, "move", "can you move the whiteboard 50 cm to the left? thanks", mv("whiteboard", [-0.5, 0, 0]))
# credenza z[-1.8,-0.2] -0.3 -> z[-2.1,-0.5], coffee machine and cups ride along
Q(S, "move", "move the credenza 30 cm toward the back wall", *carry("credenza", [0, 0, -0.3]))
# jug x[0.425,0.575] +0.2 -> x[0.625,0.775]; glasses 2/3 are at z +-0.35
Q(S, "move", "move the water jug 20 cm to the rihgt", mv("water jug", [0.2, 0, 0]))
# plant z[-2.9,-2.4] +0.4 -> z[-2.5,-2.0]
Q(S, "move", "could you move the plant 40cm forward", mv("plant", [0, 0, 0.4]))
# laptop 2 x[-1.17,-0.83] +0.1 -> x[-1.07,-0.73]; the phone (z <= 0.125) is clear
Q(S, "move", "move laptop 2 10 cm to the right", mv("laptop 2", [0.1, 0, 0]))
# table z[-0.6,0.6] -0.1 -> z[-0.7,0.5]; chairs 1-3 start at z -0.75
Q(S, "move", "pls move the meeting table 10cm back", *carry("meeting table", [0, 0, -0.1]))
# stool 1 x[2.95,3.35] -0.3 -> x[2.65,3.05]
Q(S, "move", "move stool 1 30 cm to the left", mv("stool 1", [-0.3, 0, 0]))
# coat stand z[0.95,1.45] -0.5 -> z[0.45,0.95]; chair 4 ends at x 2.2
Q(S, "move", "move the coatstand 50 cm back", mv("coat stand", [0, 0, -0.5]))
# waste bin x[-2.35,-2.05] +0.3048 -> x[-2.045,-1.745]
Q(S, "move", "move the waste bin 1 ft to the right", mv("waste bin", [FT, 0, 0], 0.02))
# stool 1 (the one in the corner) x[2.95,3.35] -0.2 -> x[2.75,3.15]
Q(H, "rel", "move the stool in the corner 20cm to the left", mv("stool 1", [-0.2, 0, 0]))
# -- rotations / scale
Q(S, "turn", "rotate chair 8 90 degrees clockwise as seen from above", rot("chair 8", -90), still("chair 8"))
Q(S, "turn", "turn chair 2 180 degrees pls", rot("chair 2", 180, True), still("chair 2"))
# plant x1.25 -> 0.625: x[-3.4625,-2.8375] z[-2.9625,-2.3375]
Q(S, "scale", "scale the plant up by 25%", scl("plant", 1.25), still("plant"))
# chair 8 at 90+45 deg: half 0.354 -> x[-2.304,-1.596] z[-0.354,0.354]; the table starts at x -1.5
Q(H, "turn", "rotate the chair at the left end of the table 45 degrees counterclockwise",
  rot("chair 8", 45), still("chair 8"))
Q(H, "turn", "turn the chair at the right end of the table 90 degrees clockwise as seen from above",
  rot("chair 4", -90), still("chair 4"))
# chair 4 centre (1.95,0) to the door (-2.3,2.975): yaw -55 deg, half 0.348 -> x[1.602,2.298]
Q(H, "turn", "turn chair 4 to face the door", faces("chair 4", "door"), still("chair 4"))
# chair nearest the TV: chair 8 (1.35 m); centre (-1.95,0) to whiteboard (1.0,-2.7): yaw 132.5 deg,
#   half 0.353 -> x[-2.303,-1.597] z[-0.353,0.353]
Q(H, "turn", "turn the chair nearest the tv so it faces the whiteboard", faces("chair 8", "whiteboard"), still("chair 8"))
# -- holds
# table -0.15 -> x[-1.65,1.35]; chair 8 ends at x -1.7; everything on the table rides along
Q(C, "hold", "move the meeting table 15 cm to the left, but the chairs stay put",
  *carry("meeting table", [-0.15, 0, 0]), unch([f"chair {i}" for i in range(1, 9)]))
# credenza +0.2 -> z[-1.6,0.0]; coffee machine (centre z -1.5) stays over it; cups ride along
Q(C, "hold", "move the credenza 20cm forward but keep the coffee machine where it is",
  *carry("credenza", [0, 0, 0.2], hold=("coffee machine",)), unch(["coffee machine"]))
# -- multi / swaps
Q(C, "multi", "swap chair 4 and chiar 8", *swap("chair 4", "chair 8"))
# chairs 1-3 z[-1.25,-0.75] -0.2 -> z[-1.45,-0.95]
Q(C, "multi", "move chairs 1, 2 and 3 back 20cm",
  mv("chair 1", [0, 0, -0.2]), mv("chair 2", [0, 0, -0.2]), mv("chair 3", [0, 0, -0.2]))
# jug -> x[0.125,0.275]; phone -> x[-0.325,-0.075]; laptop 1 is at z <= -0.23
Q(C, "multi", "move the water jug 30cm left and the conference phone 30cm right",
  mv("water jug", [-0.3, 0, 0]), mv("conference phone", [0.3, 0, 0]))
Q(C, "multi", "rotate chair 5 and chair 7 by 180 degrees",
  rot("chair 5", 180, True), still("chair 5"), rot("chair 7", 180, True), still("chair 7"))
# stool 2 x[-1.4,-1.0] +0.5 -> x[-0.9,-0.5]
Q(C, "multi", "move stool 2 half a metre right and turn it 90 degrees",
  mv("stool 2", [0.5, 0, 0]), rot("stool 2", 90, True))
# whiteboard -> x[0.5,2.1]; bin -> x[-2.05,-1.75]
Q(C, "multi", "move the whitebaord 30cm right and the waste bin 30cm right too",
  mv("whiteboard", [0.3, 0, 0]), mv("waste bin", [0.3, 0, 0]))
# laptop 1 (0,-0.35) <-> laptop 2 (-1,0.35)
Q(C, "multi", "swap laptop 1 and laptop 2", *swap("laptop 1", "laptop 2"))
# stand z[-0.8,0.8] +0.2 -> z[-0.6,1.0]; the TV is named too: it moves once, 20 cm
Q(C, "multi", "move the tv stand and the tv 20cm forward", mv("tv stand", [0, 0, 0.2]), mv("tv", [0, 0, 0.2]))
# -- vague amounts, placements
Q(F, "vague", "scoot chair 2 back a bit", dr("chair 2", "-z", 0.03))
# chair 7 faces the table (-z); "in" = -z, 0.15 to the table edge
Q(F, "vague", "push chair 7 in a smidge", dr("chair 7", "-z", 0.01))
Q(F, "place", "put the conference phone in the middle of the table",
  top("conference phone", "meeting table"), at("conference phone", [0, 0.74, 0], 0.15))
Q(F, "place", "could you put glass 1 next to the water jug", top("glass 1", "meeting table"), nxt("glass 1", "water jug"))
Q(F, "vague", "move the whiteboard a couple of feet to the left", mv("whiteboard", [-2 * FT, 0, 0], 0.15))
# jug centre to glass 2 centre: 0.614 now; "a tad closer" = at least ~1 cm closer
Q(F, "vague", "nudge the water jug a tad closer to glass 2",
  dist("water jug", "glass 2", 0.1, 0.605), top("water jug", "meeting table"))
Q(F, "vague", "move chair 4 a little further from the table", dr("chair 4", "+x", 0.03))
Q(F, "place", "put laptop 1 on the credneza", top("laptop 1", "credenza"))
Q(F, "place", "take the coffee machine and put it on the meeting table", top("coffee machine", "meeting table"))
Q(F, "place", "hey can you put stool 2 next to the coat stand", nxt("stool 2", "coat stand"))
# coat stand z[0.95,1.45] + ~0.61 -> z[1.56,2.06]; stool 1 starts at z 2.45
Q(F, "vague", "drag the coat stand a couple of feet forward", mv("coat stand", [0, 0, 2 * FT], 0.15))
# -- compositional with vague parts
# chair 1 out by d (-z), then facing the TV: centre (-1,-1-d) to (-3.3,0): yaw ~ -65 deg, half 0.331
Q(CF, "combo", "pull chair 1 out a bit and turn it to face the tv",
  dr("chair 1", "-z", 0.03), faces("chair 1", "tv"))
Q(CF, "combo", "put laptop 1 on the credenza and slide chair 2 a bit further from the table",
  top("laptop 1", "credenza"), dr("chair 2", "-z", 0.03))
Q(CF, "combo", "put all the glasses on the credenza thx",
  top("glass 1", "credenza"), top("glass 2", "credenza"), top("glass 3", "credenza"))
# toward the whiteboard: -z (pure) or along (0.35,-0.94); chairs 1-3 are 0.15 behind the table
Q(CF, "combo", "move the meeting table a bit toward the whiteboard but don't move any of the chairs",
  dr("meeting table", "-z", 0.03), *tops("meeting table"), unch([f"chair {i}" for i in range(1, 9)]))
# chair 3 centre (1,-1) to the TV (-3.3,0): yaw -76.9 deg, half 0.300 -> x[0.70,1.30] z[-1.30,-0.70]
Q(CF, "combo", "park stool 2 next to the coat stand and turn chair 3 to face the tv",
  nxt("stool 2", "coat stand"), faces("chair 3", "tv"), still("chair 3"))
# glass 1 (-1,-0.35) <-> glass 2 (1,0.35); jug a smidge left (the phone ends at x -0.375)
Q(CF, "combo", "can you swap glass 1 and glass 2, and push the water jug a smidge to the left",
  *swap("glass 1", "glass 2"), dr("water jug", "-x", 0.01))
Q(CF, "combo", "put cup 2 next to laptop 2 and push chair 7 in a tad",
  top("cup 2", "meeting table"), nxt("cup 2", "laptop 2"), dr("chair 7", "-z", 0.01))
Q(CF, "combo", "move the whiteboard a bit to the right and put the waste bin next to it",
  dr("whiteboard", "+x", 0.03), nxt("waste bin", "whiteboard"))
# -- relations, walls, corners, flush
# chair opposite chair 2 = chair 6: x[-0.25,0.25] +0.2 -> x[-0.05,0.45]; chair 5 starts at 0.75
Q(H, "rel", "move the chair opposite chair 2 20 cm to the right", mv("chair 6", [0.2, 0, 0]))
Q(H, "rel", "slide the laptop at chair 7's seat 10 cm to the right", mv("laptop 2", [0.1, 0, 0]))
# chair 6 z[0.75,1.25] -0.15 -> z[0.6,1.1]: touching the table edge
Q(H, "wall", "push chair 6 in 15 cm pls", mv("chair 6", [0, 0, -0.15], 0.02))
# chairs 1-3 z max -0.75 -> table edge -0.6
Q(H, "wall", "push the three chairs along the back side of the table in until they touch it",
  mv("chair 1", [0, 0, 0.15], 0.02), mv("chair 2", [0, 0, 0.15], 0.02), mv("chair 3", [0, 0, 0.15], 0.02))
Q(H, "place", "move glass 3 next to laptop 1 please", top("glass 3", "meeting table"), nxt("glass 3", "laptop 1"))
# table centre (0,0) is free: machine x[-0.15,0.15] z[-0.175,0.175]; laptop 1 ends z -0.23
Q(H, "place", "put the coffee machine in the middle of the meeting table",
  top("coffee machine", "meeting table"), at("coffee machine", [0, 0.74, 0], 0.15))
# corner by the door = front-left (x -3.5, z 3): stand x[2.9,3.4] z[0.95,1.45] -> x[-3.5,-3.0] z[2.5,3.0]
Q(H, "wall", "drag the coat stand into the corner by the door", mv("coat stand", [-6.4, 0, 1.55], 0.05), IB)
# on the table at chair 8's place: right of chair 8 (x >= -1.7), facing it across
Q(H, "place", "put cup 1 on the table at chair 8's place",
  top("cup 1", "meeting table"), side("cup 1", "chair 8", "right", 0.5))
# stool 1 x max 3.35 -> 3.5, z max 2.85 -> 3.0
Q(H, "wall", "shove stool 1 right into the corner", mv("stool 1", [0.15, 0, 0.15], 0.03), IB)
# glass at chair 5's place = glass 2: x[0.96,1.04] -0.1 -> x[0.86,0.94]
Q(H, "rel", "move the glass at chair 5's spot 10cm to the left", mv("glass 2", [-0.1, 0, 0]))
# chair 8 x max -1.7 -> table edge -1.5
Q(H, "wall", "I'd like chair 8 pushed flush against the table", mv("chair 8", [0.2, 0, 0], 0.02))
# whiteboard x max 1.8 -> 3.5 (nothing in z[-2.95,-2.45] on the way; the credenza starts z -1.8)
Q(H, "wall", "slide the whiteboard as far right as it'll go", mv("whiteboard", [1.7, 0, 0], 0.03), IB)
# -- refusals
Q(H, "refuse", "move the chair 30 cm back", ref([f"chair {i}" for i in range(1, 9)]))
Q(H, "refuse", "could you turn the stool to face the table", ref(["stool 1", "stool 2"]))
Q(H, "refuse", "put the laptop on the credenza", ref(["laptop 1", "laptop 2"]))
Q(H, "refuse", "put the glass next to the jug", ref(["glass 1", "glass 2", "glass 3"]))
Q(H, "refuse", "move the cup a bit closer to the coffee machine", ref(["cup 1", "cup 2"]))
Q(H, "refuse", "turn the chair at the end of the table to face the tv", ref(["chair 4", "chair 8"]))
Q(H, "refuse", "move the projector 20cm left", ref([]))
Q(H, "refuse", "move the sofa 1m to the right", ref([]))
Q(H, "refuse", "hey move chair 9 closer to the table", ref([]))

# ================================================================ (c) bike shop
_scene = "bike_shop"
# bike 2 x[-0.1,0.5] +0.2 -> x[0.1,0.7]; bike 3 starts at 0.9
Q(S, "move", "move bike 2 20cm to the right thx", mv("bike 2", [0.2, 0, 0]))
# stand x[2.2,2.8] -0.3 -> x[1.9,2.5]; the bench ends at 1.7
Q(S, "move", "move the repair stand 30 cm to the left", mv("repair stand", [-0.3, 0, 0]))
# shelf z[-1,0.6] -0.4 -> z[-1.4,0.2] with both helmets
Q(S, "move", "move the helmet shelf 40cm bak", *carry("helmet shelf", [0, 0, -0.4]))
# pump x[-0.625,-0.375] -0.3 -> x[-0.925,-0.675]
Q(S, "move", "could you move the floor pump 30 cm to the left", mv("floor pump", [-0.3, 0, 0]))
# counter x[-2.9,-2.3] +0.2 -> x[-2.7,-2.1] with till, card reader, red helmet; bike 1 starts -1.1
Q(S, "move", "move the countr 20cm to the right", *carry("counter", [0.2, 0, 0]))
# till z[0.825,1.175] -0.1 -> z[0.725,1.075]; the card reader ends at z 0.525
Q(S, "move", "move the till 10 cm back", mv("till", [0, 0, -0.1]))
# rack z[1.2,2.4] +0.3 -> z[1.5,2.7]
Q(S, "move", "move the tire rack 30cm forward", mv("tyre rack", [0, 0, 0.3]))
# bin x[-3.375,-3.025] +0.5 -> x[-2.875,-2.525]; sign board starts at -1.8
Q(S, "move", "move the trash bin half a metre to the right", mv("trash bin", [0.5, 0, 0]))
# wheel x[-0.01,0.61] +0.05 -> x[0.04,0.66]; the tray starts at 0.8
Q(S, "move", "move the spare wheel 5 cm to the rigth", mv("spare wheel", [0.05, 0, 0]))
# lube x[1.42,1.48] -0.1 -> x[1.32,1.38] at z[-2.53,-2.47]; tray ends z -2.55
Q(S, "move", "move the lube bottle 10 cm to the left", mv("lube bottle", [-0.1, 0, 0]))
# mat x[-0.25,1.25] -0.3048 -> x[-0.5548,0.9452]; sign board ends at -1.2
Q(S, "move", "move the mat 1 ft to the left", mv("floor mat", [-FT, 0, 0], 0.02))
# box 3 z[-2.8,-2.4] +0.3 -> z[-2.5,-2.1]
Q(S, "move", "move cardbord box 3 30cm forward", mv("cardboard box 3", [0, 0, 0.3]))
# -- rotations / scale
# sign 0.6x0.5 turned -> 0.5x0.6: x[-1.75,-1.25] z[2.1,2.7]
Q(S, "turn", "rotate the sign board 90 degrees clockwise as seen from above", rot("sign board", -90), still("sign board"))
Q(S, "turn", "turn the counter stool 180 degrees", rot("counter stool", 180, True), still("counter stool"))
Q(S, "scale", "scale the sign board down to 80%", scl("sign board", 0.8), still("sign board"))
# stand centre (2.5,-2.4) to the counter (-2.6,0.5): yaw -60.4 deg, half 0.409 -> x[2.091,2.909] z[-2.809,-1.991]
Q(H, "turn", "turn the repair stand so it faces the counter", faces("repair stand", "counter"), still("repair stand"))
# stool centre (-3.2,0.5) to the counter (-2.6,0.5): yaw +90, same box
Q(H, "turn", "turn the counter stool to face the counter", faces("counter stool", "counter"), still("counter stool"))
# bench 180 about (0.8,-2.675): same box; wheel rel (-0.5,0) -> (0.5,0): delta (1,0,0)
#   tray rel (0.2,-0.025) -> (-0.2,0.025): delta (-0.4,0,0.05); lube rel (0.65,0.175) -> (-0.65,-0.175):
#   delta (-1.3,0,-0.35); wrench rel (0.65,-0.175) -> (-0.65,0.175): delta (-1.3,0,0.35)
Q(H, "turn", "spin the service bench round 180 degrees, stuff on it included",
  rot("service bench", 180, True), still("service bench"),
  mv("spare wheel", [1.0, 0, 0], 0.03), rot("spare wheel", 180, True),
  mv("parts tray", [-0.4, 0, 0.05], 0.03), rot("parts tray", 180, True),
  mv("lube bottle", [-1.3, 0, -0.35], 0.03), rot("lube bottle", 180, True),
  mv("torque wrench", [-1.3, 0, 0.35], 0.03), rot("torque wrench", 180, True))
# -- holds
# bench -0.1 -> x[-0.2,1.6]; the wrench (centre x 1.45) stays over it; pump ends at x -0.375
Q(C, "hold", "shift the service bench 10 cm left, but leave the torque wrench where it is",
  *carry("service bench", [-0.1, 0, 0], hold=("torque wrench",)), unch(["torque wrench"]))
# counter +0.15 -> x[-2.75,-2.15]; the till (centre x -2.6) stays over it
Q(C, "hold", "move the counter 15 cm right but don't move the till",
  *carry("counter", [0.15, 0, 0], hold=("till",)), unch(["till"]))
# -- multi / swaps
Q(C, "multi", "pls swap bike 1 and bike 3", *swap("bike 1", "bike 3"))
# blue -> z[-0.55,-0.25], black -> z[0.15,0.45]; shelf ends at z 0.6
Q(C, "multi", "move the blue helmet and the black helmet 10cm forward",
  mv("blue helmet", [0, 0, 0.1]), mv("black helmet", [0, 0, 0.1]))
# bikes z[-0.275,1.475] -0.3 -> z[-0.575,1.175]
Q(C, "multi", "move all three bikes 30 cm back",
  mv("bike 1", [0, 0, -0.3]), mv("bike 2", [0, 0, -0.3]), mv("bike 3", [0, 0, -0.3]))
# sign +0.4 -> centre (-1.1,2.4) turned: x[-1.35,-0.85] z[2.1,2.7]; the mat starts at x -0.25
Q(C, "multi", "turn the sign board 90 degrees and move it 40 cm to the right",
  rot("sign board", 90, True), mv("sign board", [0.4, 0, 0]))
# stand -0.2 -> centre (2.3,-2.4); door centre (0.5,2.975): yaw -18.5 deg, half 0.38 -> x[1.92,2.68]
Q(C, "multi", "move the repair stand 20 cm left and turn it to face the entrance door",
  mv("repair stand", [-0.2, 0, 0]), faces("repair stand", "entrance door"))
# till -> x[-2.9,-2.5] (still on the counter); card reader -> x[-2.44,-2.36]
Q(C, "multi", "move the till 10 cm left and the card reader 10 cm right",
  mv("till", [-0.1, 0, 0]), mv("card reader", [0.1, 0, 0]))
# red (-2.6,1.0,-0.1) <-> blue (3.3,1.6,-0.5)
Q(C, "multi", "swap the red helmet and the blue helmet", *swap("red helmet", "blue helmet"))
# box 1 (with box 2 on it) and box 3 +0.1
Q(C, "multi", "move cardboard box 1 and cardboard box 3 10cm forward",
  *carry("cardboard box 1", [0, 0, 0.1]), mv("cardboard box 3", [0, 0, 0.1]))
# -- vague amounts, placements
Q(F, "vague", "nudge the lube bottle a smidge to the left", dr("lube bottle", "-x", 0.01))
Q(F, "place", "haul the floor pump over next to the repair stand", nxt("floor pump", "repair stand"))
Q(F, "vague", "scoot bike 2 a little back", dr("bike 2", "-z", 0.03))
Q(F, "place", "put the lube botle on the counter", top("lube bottle", "counter"))
Q(F, "place", "put the card reader on the service bench next to the parts tray",
  top("card reader", "service bench"), nxt("card reader", "parts tray"))
# bin x[-3.375,-3.025] + ~0.61 -> x[-2.76,-2.41]
Q(F, "vague", "move the trash bin a couple of feet to the right", mv("trash bin", [2 * FT, 0, 0], 0.15))
Q(F, "vague", "scoot the tyre rack a tad back", dr("tyre rack", "-z", 0.01))
Q(F, "place", "set the red helmet down on the floor next to the counter",
  floor("red helmet"), nxt("red helmet", "counter"))
Q(F, "place", "put the black helmet on the counter", top("black helmet", "counter"))
Q(F, "vague", "move the sign board a bit to the left", dr("sign board", "-x", 0.03))
Q(F, "place", "put the torque wrench on the counter, thx", top("torque wrench", "counter"))
Q(F, "vague", "could you move bike 1 a bit to the left", dr("bike 1", "-x", 0.03))
# -- compositional with vague parts
Q(CF, "combo", "put the parts tray on the counter and scoot bike 1 a bit to the left",
  top("parts tray", "counter"), dr("bike 1", "-x", 0.03))
# stand z min -2.7 -> the back wall -3
Q(CF, "combo", "put the torque wrench on the counter and push the repair stand flush against the back wall",
  top("torque wrench", "counter"), mv("repair stand", [0, 0, -0.3], 0.02), IB)
Q(CF, "combo", "move bike 3 a bit to the right but keep bike 2 where it is",
  dr("bike 3", "+x", 0.03), unch(["bike 2"]))
Q(CF, "combo", "grab the blue helmet off the shelf, put it on the counter and nudge the till a tad back",
  top("blue helmet", "counter"), dr("till", "-z", 0.01), top("till", "counter"))
# stool x max -3.0, the counter starts at -2.9
Q(CF, "combo", "put the card reader on the service bench and nudge the counter stool a smidge toward the counter",
  top("card reader", "service bench"), dr("counter stool", "+x", 0.01))
Q(CF, "combo", "could you put the lube bottle on the parts tray and drag the floor pump a little to the left",
  top("lube bottle", "parts tray"), dr("floor pump", "-x", 0.03))
Q(CF, "combo", "put the top cardboard box on the floor next to the trash bin and scoot box 3 a bit forward",
  floor("cardboard box 2"), nxt("cardboard box 2", "trash bin"), dr("cardboard box 3", "+z", 0.03))
# -- relations, walls, corners, flush
Q(H, "rel", "move the bike in the middle 30 cm back", mv("bike 2", [0, 0, -0.3]))
# red helmet z[-0.25,0.05] +0.1 -> z[-0.15,0.15]; card reader starts at z 0.375
Q(H, "rel", "move the helmet on the counter 10 cm forward", mv("red helmet", [0, 0, 0.1]))
# box 3 z min -2.8 -> -3
Q(H, "wall", "push cardboard box 3 flush against the back wall", mv("cardboard box 3", [0, 0, -0.2], 0.02), IB)
# bike 1 x min -1.1 -> counter face -2.3 (z overlap): -1.2
Q(H, "wall", "slide bike 1 left until it's flush against the counter", mv("bike 1", [-1.2, 0, 0], 0.03))
# bike nearest the counter = bike 1: x[-1.1,-0.5] +0.2 -> x[-0.9,-0.3]
Q(H, "rel", "move the bike nearest the counter 20cm to the right", mv("bike 1", [0.2, 0, 0]))
# lube centre (1.45,-2.5) to wheel centre (0.3,-2.675): 20 cm -> (-0.198,0,-0.030)
Q(H, "rel", "move the lube bottle 20 cm toward the spare wheel", mv("lube bottle", [-0.198, 0, -0.03], 0.03))
Q(H, "place", "stack cardboard box 3 on top of box 2", top("cardboard box 3", "cardboard box 2"))
Q(H, "rel", "move the right-hand bike 25 cm back", mv("bike 3", [0, 0, -0.25]))
Q(H, "place", "put the card reader on top of the till", top("card reader", "till"))
# pump x max -0.375 -> bench face -0.1 (z overlap): +0.275
Q(H, "wall", "drag the floor pump as far right as it will go", mv("floor pump", [0.275, 0, 0], 0.03))
# stool x max -3.0 -> counter face -2.9
Q(H, "wall", "tuck the counter stool in against the counter", mv("counter stool", [0.1, 0, 0], 0.02))
# bin: front-left corner x min -3.375 -> -3.5, z max 2.775 -> 3.0
Q(H, "wall", "shove the trash bin into the corner", mv("trash bin", [-0.125, 0, 0.225], 0.03), IB)
# -- refusals
Q(H, "refuse", "move the bike 20cm left", ref(["bike 1", "bike 2", "bike 3"]))
Q(H, "refuse", "put the helmet on the counter", ref(["blue helmet", "black helmet"]))
Q(H, "refuse", "move the cardboard box 10 cm forward", ref(["cardboard box 1", "cardboard box 2", "cardboard box 3"]))
Q(H, "refuse", "turn the helmet to face the door", ref(["red helmet", "blue helmet", "black helmet"]))
Q(H, "refuse", "move the vending machine 1 m back", ref([]))
Q(H, "refuse", "put the saddle on the service bench", ref([]))
Q(H, "refuse", "could u move the car out of the way", ref([]))

SUITE = {"name": "holdout4",
         "scenes": ["ue_loft_studio.json", "meeting_room_8.json", "bike_shop.json"],
         "variations": 1, "seed": 20261231, "queries": QUERIES}

def dump(path, obj):
    with open(os.path.join(HERE, path), "w") as f:
        json.dump(obj, f, indent=1)
        f.write("\n")

if __name__ == "__main__":
    for sc in (LOFT, MEET, SHOP):
        dump(sc["name"] + ".json", sc)
    dump("holdout4.suite.json", SUITE)
    print(len(QUERIES), "queries")
