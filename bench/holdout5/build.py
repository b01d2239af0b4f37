#!/usr/bin/env python3
"""Builds the holdout5 scenes and suite (stdlib only).  Run: python3 build.py && python3 validate.py

Written blind: from SPEC.md (frame, scene file, suite format), docs/benchmark.md's table of checks
and holdout4's build.py / validate.py for the file layout only.  Three new scenes:
  blender_hotel_room  - a hotel room exported from Blender: Bed_Queen, Nightstand.001/.002,
                        Lamp_Bedside.001/.002, Pillow_L/_R, Curtain_L/_R, Suitcase ... no categories
  clinic_waiting_room - a waiting room with fifteen identical chairs in three rows (chair 1-5 front
                        row left to right, 6-10 middle, 11-15 back), two side tables, two magazines,
                        two plants, two kids chairs
  home_office         - a home office with small things on surfaces: laptop, phone, two mugs, three
                        books, two plates, a printer, a succulent

Conventions (SPEC 1-3, and the ones this suite decides):
  * right = +X, left = -X, up = +Y, forward / front = +Z, back = -Z, metres; the viewer looks from
    +Z, so the "back wall" is at min z, the "front wall" at max z.  "Front row" in the waiting room
    is the row nearest the TV and reception, which stand at the +Z wall, so both readings agree.
  * Forward/back is only asked of objects whose facing cannot make "its own back" a different
    reading (or whose facing agrees with the world's).
  * The pivot is the bottom centre of the box; a yaw turns about it and leaves the world AABB's
    bottom centre where it was, so `moved` deltas are pivot deltas.  +90 deg about +Y takes +Z to
    +X; "clockwise" (seen from above) is negative.
  * Things resting on a moved object move with it (they turn about the support's pivot when it
    turns) unless the instruction holds them; held things are listed in an `unchanged` check.
  * "against" / "flush" / "until it touches" / "as far as it will go" / "all the way" = the faces
    touch (gap 0), tol 0.02.
  * "N towards X": along the floor-plan line from the object's centre to X's centre.  Only objects
    for which that line and the nearest axis agree within the tolerance are asked (the moved delta
    sits between the two readings); otherwise `direction` / `distance` checks that accept both.
  * Vague amounts: "a smidge / a tad / a touch / a hair / slightly / a tiny bit" -> direction, min
    0.01; "a bit / a little" -> min 0.03; "a couple of inches" -> min 0.03.  validate.py also tries a
    generous reading (0.08 / 0.15 m unless GEN says less) that must stay collision-free.
  * "closer to X" when X is not along an axis -> `distance` with a max below the current distance.
  * Placements (on / next to / between) are checked with on_top / next_to / between, and
    validate.py places a hand-chosen spot for each that is free (2 cm clear where a tool might keep
    a buffer) and inside the top face.
  * 1 ft = 0.3048 m, 1 in = 0.0254 m.
  * Refusals: a phrase that matches two or more objects equally (the mentions are those candidates,
    REFUSE gives the words every candidate's name holds) or an object the scene does not have
    (mentions []).
Every non-refusal query ends with no_collision and unchanged others; validate.py applies the
hand-worked readings (ANS, or the ones derived from exact checks) and runs every check on them.
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))
S2 = 0.7071067812
R90 = [0, S2, 0, S2]      # +90 deg about Y: front +Z -> +X
RM90 = [0, -S2, 0, S2]    # -90 deg about Y: front +Z -> -X
R180 = [0, 1, 0, 0]       # front +Z -> -Z
FT, IN = 0.3048, 0.0254


def o(name, size, pos, rot=None):
    d = {"name": name, "position": pos, "size": size}
    if rot is not None:
        d["rotation"] = rot
    return d


# ================================================================ (a) Blender hotel room
# room x[-2.5,2.5] y[0,2.7] z[-3,3]; bed headboard at the back wall, balcony window on the right
# wall, desk and dresser (with the TV) on the left wall, entrance door on the front wall
HOTEL = {
    "name": "blender_hotel_room",
    "bounds": {"min": [-2.5, 0, -3], "max": [2.5, 2.7, 3]},
    "objects": [
        o("Bed_Queen", [1.6, 0.55, 2.1], [0, 0, -1.95]),                # x[-0.8,0.8] z[-3,-0.9] top .55
        o("Pillow_L", [0.6, 0.15, 0.4], [-0.4, 0.55, -2.7]),            # x[-0.7,-0.1] z[-2.9,-2.5]
        o("Pillow_R", [0.6, 0.15, 0.4], [0.4, 0.55, -2.7]),             # x[0.1,0.7]
        o("Blanket_Throw", [1.6, 0.03, 0.5], [0, 0.55, -1.2]),          # x[-0.8,0.8] z[-1.45,-0.95]
        o("Nightstand.001", [0.5, 0.55, 0.45], [-1.15, 0, -2.775]),     # x[-1.4,-0.9] z[-3,-2.55] top .55
        o("Nightstand.002", [0.5, 0.55, 0.45], [1.15, 0, -2.775]),      # x[0.9,1.4]
        o("Lamp_Bedside.001", [0.22, 0.5, 0.22], [-1.15, 0.55, -2.86]), # x[-1.26,-1.04] z[-2.97,-2.75]
        o("Lamp_Bedside.002", [0.22, 0.5, 0.22], [1.15, 0.55, -2.86]),  # x[1.04,1.26]
        o("Alarm_Clock", [0.14, 0.08, 0.07], [1.2, 0.55, -2.62]),       # x[1.13,1.27] z[-2.655,-2.585]
        o("Rug_Wool", [2.2, 0.01, 1.4], [0, 0, -0.1]),                  # x[-1.1,1.1] z[-0.8,0.6] top .01
        o("Bench_BedEnd", [1.2, 0.45, 0.4], [0, 0.01, -0.55]),          # on the rug: x[-0.6,0.6] z[-0.75,-0.35]
        o("Desk_Writing", [1.2, 0.75, 0.55], [-2.225, 0, 1.0], R90),    # x[-2.5,-1.95] z[0.4,1.6] top .75
        o("Chair_Desk", [0.5, 0.9, 0.5], [-1.6, 0, 1.0], RM90),         # x[-1.85,-1.35] z[0.75,1.25] faces -x
        o("Lamp_Desk", [0.2, 0.45, 0.2], [-2.35, 0.75, 0.55]),          # x[-2.45,-2.25] z[0.45,0.65]
        o("Phone_Hotel", [0.18, 0.08, 0.2], [-2.2, 0.75, 1.4]),         # x[-2.29,-2.11] z[1.3,1.5]
        o("Dresser", [1.4, 0.8, 0.5], [-2.25, 0, -1.2], R90),           # x[-2.5,-2.0] z[-1.9,-0.5] top .8
        o("TV_Flat", [1.0, 0.6, 0.06], [-2.4, 0.8, -1.2], R90),         # x[-2.43,-2.37] z[-1.7,-0.7]
        o("Kettle", [0.2, 0.25, 0.15], [-2.2, 0.8, -0.6]),              # x[-2.3,-2.1] z[-0.675,-0.525]
        o("Cup.001", [0.08, 0.1, 0.08], [-2.15, 0.8, -1.8]),            # x[-2.19,-2.11] z[-1.84,-1.76]
        o("Cup.002", [0.08, 0.1, 0.08], [-2.15, 0.8, -1.62]),           # z[-1.66,-1.58]
        o("Armchair", [0.8, 0.9, 0.8], [1.8, 0, 0.8], RM90),            # x[1.4,2.2] z[0.4,1.2] faces -x
        o("Table_Side", [0.45, 0.5, 0.45], [1.8, 0, -0.1]),             # x[1.575,2.025] z[-0.325,0.125] top .5
        o("Vase_Flowers", [0.12, 0.3, 0.12], [1.8, 0.5, -0.1]),         # x[1.74,1.86] z[-0.16,-0.04]
        o("Window_Balcony", [2.0, 2.4, 0.05], [2.475, 0, 0.5], RM90),   # x[2.45,2.5] z[-0.5,1.5]
        o("Curtain_L", [0.3, 2.5, 0.12], [2.38, 0, -0.7], RM90),        # x[2.32,2.44] z[-0.85,-0.55]
        o("Curtain_R", [0.3, 2.5, 0.12], [2.38, 0, 1.7], RM90),         # z[1.55,1.85]
        o("Wardrobe", [1.0, 2.2, 0.6], [2.0, 0, 2.7], R180),            # x[1.5,2.5] z[2.4,3.0]
        o("Luggage_Rack", [0.7, 0.5, 0.45], [0.7, 0, 2.775]),           # x[0.35,1.05] z[2.55,3.0] top .5
        o("Suitcase", [0.45, 0.7, 0.28], [-0.4, 0, 2.2]),               # x[-0.625,-0.175] z[2.06,2.34]
        o("Door_Entrance", [0.9, 2.1, 0.05], [-1.5, 0, 2.975], R180),   # x[-1.95,-1.05] z[2.95,3.0]
        o("Plant_Pot.001", [0.4, 1.0, 0.4], [-2.3, 0, 2.8]),            # x[-2.5,-2.1] z[2.6,3.0]
    ],
}

# ================================================================ (b) clinic waiting room
# room x[-4,4] y[0,2.8] z[-3.5,3.5]; TV and reception at the front (+z) wall, entrance door at the
# back wall; chairs in three rows of five facing +z, numbered left to right from the front row
def _chairs():
    out = []
    for r in range(3):
        for c in range(5):
            n = r * 5 + c + 1
            out.append(o(f"chair {n}", [0.5, 0.85, 0.5], [round(-2.6 + 0.6 * c, 3), 0, round(0.8 - 1.2 * r, 3)]))
    return out
# columns x: [-2.85,-2.35] [-2.25,-1.75] [-1.65,-1.15] [-1.05,-0.55] [-0.45,0.05]
# rows z: front [0.55,1.05], middle [-0.65,-0.15], back [-1.85,-1.35]


WAIT = {
    "name": "clinic_waiting_room",
    "bounds": {"min": [-4, 0, -3.5], "max": [4, 2.8, 3.5]},
    "objects": _chairs() + [
        o("side table 1", [0.5, 0.5, 0.5], [0.45, 0, 0.8]),            # x[0.2,0.7] z[0.55,1.05] top .5
        o("side table 2", [0.5, 0.5, 0.5], [0.45, 0, -1.6]),           # z[-1.85,-1.35]
        o("magazine 1", [0.21, 0.01, 0.28], [0.45, 0.5, 0.8]),         # x[0.345,0.555] z[0.66,0.94]
        o("magazine 2", [0.21, 0.01, 0.28], [0.45, 0.5, -1.6]),        # z[-1.74,-1.46]
        o("tv cabinet", [1.6, 0.5, 0.45], [-1.4, 0, 3.275]),           # x[-2.2,-0.6] z[3.05,3.5] top .5
        o("tv", [1.2, 0.7, 0.08], [-1.4, 0.5, 3.35], R180),            # x[-2,-0.8] z[3.31,3.39]
        o("reception desk", [2.0, 1.1, 0.7], [2.3, 0, 2.6], R180),     # x[1.3,3.3] z[2.25,2.95] top 1.1
        o("office chair", [0.55, 1.0, 0.55], [2.3, 0, 3.225], R180),   # x[2.025,2.575] z[2.95,3.5]
        o("computer monitor", [0.55, 0.4, 0.18], [2.3, 1.1, 2.75], R180),  # x[2.025,2.575] z[2.66,2.84]
        o("hand sanitizer", [0.08, 0.2, 0.08], [1.5, 1.1, 2.45]),      # x[1.46,1.54] z[2.41,2.49]
        o("pen holder", [0.08, 0.12, 0.08], [3.1, 1.1, 2.45]),         # x[3.06,3.14]
        o("water cooler", [0.35, 1.2, 0.35], [-3.8, 0, 2.4]),          # x[-3.975,-3.625] z[2.225,2.575]
        o("plant 1", [0.5, 1.2, 0.5], [-3.7, 0, 3.2]),                 # x[-3.95,-3.45] z[2.95,3.45]
        o("plant 2", [0.5, 1.2, 0.5], [3.7, 0, -3.2]),                 # x[3.45,3.95] z[-3.45,-2.95]
        o("toy box", [0.7, 0.45, 0.45], [2.8, 0, -3.25]),              # x[2.45,3.15] z[-3.475,-3.025]
        o("kids table", [1.0, 0.5, 0.6], [2.5, 0, -1.8]),              # x[2.0,3.0] z[-2.1,-1.5] top .5
        o("puzzle", [0.3, 0.02, 0.3], [2.5, 0.5, -1.8]),               # x[2.35,2.65] z[-1.95,-1.65]
        o("kids chair 1", [0.3, 0.55, 0.3], [2.5, 0, -2.35]),          # x[2.35,2.65] z[-2.5,-2.2] faces +z
        o("kids chair 2", [0.3, 0.55, 0.3], [2.5, 0, -1.25], R180),    # z[-1.4,-1.1] faces -z
        o("door", [1.0, 2.1, 0.05], [-2.0, 0, -3.475]),                # x[-2.5,-1.5] z[-3.5,-3.45]
        o("coat rack", [0.5, 1.8, 0.5], [-3.6, 0, -3.1]),              # x[-3.85,-3.35] z[-3.35,-2.85]
        o("umbrella stand", [0.25, 0.6, 0.25], [-1.0, 0, -3.3]),       # x[-1.125,-0.875] z[-3.425,-3.175]
        o("vending machine", [0.9, 1.8, 0.8], [3.6, 0, 0.5], RM90),    # x[3.2,4.0] z[0.05,0.95]
        o("trash can", [0.35, 0.6, 0.35], [-3.7, 0, 0.0]),             # x[-3.875,-3.525] z[-0.175,0.175]
    ],
}

# ================================================================ (c) home office
# room x[-2.5,2.5] y[0,2.6] z[-2.5,2.5]; desk at the back wall, bookshelf on the left wall, window
# (hanging) on the right wall, sofa at the front wall, door at the front-left
OFFICE = {
    "name": "home_office",
    "bounds": {"min": [-2.5, 0, -2.5], "max": [2.5, 2.6, 2.5]},
    "objects": [
        o("desk", [1.6, 0.75, 0.7], [0, 0, -2.15]),                    # x[-0.8,0.8] z[-2.5,-1.8] top .75
        o("office chair", [0.6, 1.1, 0.6], [0, 0, -1.35], R180),       # x[-0.3,0.3] z[-1.65,-1.05] faces -z
        o("laptop", [0.34, 0.02, 0.24], [0, 0.75, -2.0]),              # x[-0.17,0.17] z[-2.12,-1.88]
        o("monitor", [0.6, 0.45, 0.2], [0, 0.75, -2.35]),              # x[-0.3,0.3] z[-2.45,-2.25]
        o("white mug", [0.09, 0.1, 0.09], [0.45, 0.75, -1.95]),        # x[0.405,0.495] z[-1.995,-1.905]
        o("phone", [0.08, 0.01, 0.16], [-0.45, 0.75, -1.95]),          # x[-0.49,-0.41] z[-2.03,-1.87]
        o("desk lamp", [0.2, 0.45, 0.2], [-0.65, 0.75, -2.35]),        # x[-0.75,-0.55] z[-2.45,-2.25]
        o("blue book", [0.17, 0.03, 0.24], [0.6, 0.75, -2.3]),         # x[0.515,0.685] z[-2.42,-2.18]
        o("bookshelf", [0.9, 1.9, 0.35], [-2.325, 0, -0.8], R90),      # x[-2.5,-2.15] z[-1.25,-0.35] top 1.9
        o("red book", [0.17, 0.03, 0.24], [-2.325, 1.9, -1.0]),        # x[-2.41,-2.24] z[-1.12,-0.88]
        o("succulent", [0.12, 0.15, 0.12], [-2.325, 1.9, -0.55]),      # z[-0.61,-0.49]
        o("filing cabinet", [0.45, 0.7, 0.6], [1.2, 0, -2.2]),         # x[0.975,1.425] z[-2.5,-1.9] top .7
        o("printer", [0.45, 0.22, 0.4], [1.2, 0.7, -2.2]),             # z[-2.4,-2.0]
        o("rug", [2.0, 0.01, 1.4], [0.5, 0, 0.9]),                     # x[-0.5,1.5] z[0.2,1.6] top .01
        o("coffee table", [1.2, 0.42, 0.6], [0.5, 0.01, 0.9]),         # on the rug: x[-0.1,1.1] z[0.6,1.2] top .43
        o("green book", [0.17, 0.03, 0.24], [0.2, 0.43, 0.9]),         # x[0.115,0.285] z[0.78,1.02]
        o("dinner plate", [0.26, 0.02, 0.26], [0.5, 0.43, 0.9]),       # x[0.37,0.63] z[0.77,1.03]
        o("black mug", [0.09, 0.1, 0.09], [0.8, 0.43, 0.9]),           # x[0.755,0.845] z[0.855,0.945]
        o("sofa", [1.8, 0.85, 0.9], [0.5, 0, 2.05], R180),             # x[-0.4,1.4] z[1.6,2.5] faces -z
        o("armchair", [0.8, 0.9, 0.8], [2.0, 0, 0.6], RM90),           # x[1.6,2.4] z[0.2,1.0] faces -x
        o("side table", [0.45, 0.55, 0.45], [2.1, 0, 1.45]),           # x[1.875,2.325] z[1.225,1.675] top .55
        o("small plate", [0.18, 0.015, 0.18], [2.1, 0.55, 1.45]),      # x[2.01,2.19] z[1.36,1.54]
        o("floor lamp", [0.35, 1.6, 0.35], [2.2, 0, -0.2]),            # x[2.025,2.375] z[-0.375,-0.025]
        o("window", [1.2, 1.2, 0.1], [2.45, 1.0, -1.2], RM90),         # on the right wall: x[2.4,2.5] z[-1.8,-0.6] y[1,2.2]
        o("door", [0.9, 2.1, 0.05], [-1.6, 0, 2.475], R180),           # x[-2.05,-1.15] z[2.45,2.5]
        o("waste basket", [0.3, 0.35, 0.3], [-1.1, 0, -2.3]),          # x[-1.25,-0.95] z[-2.45,-2.15]
        o("guest chair", [0.5, 0.85, 0.5], [-1.3, 0, -1.0], R90),      # x[-1.55,-1.05] z[-1.25,-0.75] faces +x
    ],
}

# what rests on what (validate.py compares it with the geometry)
ON = {
    "blender_hotel_room": {
        "Pillow_L": "Bed_Queen", "Pillow_R": "Bed_Queen", "Blanket_Throw": "Bed_Queen",
        "Lamp_Bedside.001": "Nightstand.001", "Lamp_Bedside.002": "Nightstand.002",
        "Alarm_Clock": "Nightstand.002", "Bench_BedEnd": "Rug_Wool", "Lamp_Desk": "Desk_Writing",
        "Phone_Hotel": "Desk_Writing", "TV_Flat": "Dresser", "Kettle": "Dresser", "Cup.001": "Dresser",
        "Cup.002": "Dresser", "Vase_Flowers": "Table_Side"},
    "clinic_waiting_room": {
        "magazine 1": "side table 1", "magazine 2": "side table 2", "tv": "tv cabinet",
        "computer monitor": "reception desk", "hand sanitizer": "reception desk",
        "pen holder": "reception desk", "puzzle": "kids table"},
    "home_office": {
        "laptop": "desk", "monitor": "desk", "white mug": "desk", "phone": "desk", "desk lamp": "desk",
        "blue book": "desk", "red book": "bookshelf", "succulent": "bookshelf", "printer": "filing cabinet",
        "coffee table": "rug", "green book": "coffee table", "dinner plate": "coffee table",
        "black mug": "coffee table", "small plate": "side table"},
}
WALL = {"home_office": ("window",)}   # hangs on a wall, rests on nothing

SCENES = {"blender_hotel_room": HOTEL, "clinic_waiting_room": WAIT, "home_office": OFFICE}


# ---------------------------------------------------------------- checks (SPEC 6 only)
def mv(obj, d, tol=None):
    d = [round(x, 4) for x in d]
    if tol is None:
        tol = 0.02 if max(abs(x) for x in d) <= 0.1 else 0.03
    return {"check": "moved", "object": obj, "delta": d, "tol": tol}


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


def btw(obj, a, b):
    return {"check": "between", "object": obj, "a": a, "b": b}


def faces(obj, t):
    return {"check": "faces", "object": obj, "target": t}


def dist(obj, other, mn=None, mx=None):
    c = {"check": "distance", "object": obj, "other": other}
    if mn is not None:
        c["min"] = mn
    if mx is not None:
        c["max"] = mx
    return c


def at(obj, p, tol=0.02):
    return {"check": "at", "object": obj, "position": p, "tol": tol}


def unch(objs):
    return {"check": "unchanged", "objects": list(objs)}


def ref(m):
    return {"check": "refused", "mentions": list(m)}


NC = {"check": "no_collision"}
IB = {"check": "inside_bounds"}
OTHERS = {"check": "unchanged", "objects": "others"}


def carry(obj, d, hold=(), tol=None):
    """moved checks for obj and everything resting on it (transitively), except held ones"""
    out = [mv(obj, d, tol)]
    for child, sup in ON[_scene].items():
        if sup == obj and child not in hold:
            out += carry(child, d, hold, tol)
    return out


def tops(sup, hold=()):
    """on_top checks for what rests on sup (used when sup moves by a vague amount)"""
    return [top(c, s) for c, s in ON[_scene].items() if s == sup and c not in hold]


def pos(name):
    for d in SCENES[_scene]["objects"]:
        if d["name"] == name:
            return d["position"]
    raise KeyError(name)


def swap(a, b):
    pa, pb = pos(a), pos(b)
    return [mv(a, [pb[i] - pa[i] for i in range(3)]), mv(b, [pa[i] - pb[i] for i in range(3)])]


# ---------------------------------------------------------------- worked answers
def D(obj, d):
    return ("d", obj, d)


def TO(obj, p):
    return ("to", obj, p)


def YAW(obj, deg):
    return ("yaw", obj, deg)


def FACE(obj, t):
    return ("face", obj, t)


QUERIES, ANS, TOUCH, GEN, REFUSE = [], {}, {}, {}, {}
SHORT = {"blender_hotel_room": "hotel", "clinic_waiting_room": "wait", "home_office": "office"}
_scene = None
_n = {}


def Q(cat, text, *checks, ans=None, touch=None, gen=None, refuse=None):
    """ans: list of readings (lists of ops); touch: [(object, other object or wall axis)];
    gen: {object: generous amount} for direction checks; refuse: ("ambiguous", [words]) or
    ("missing", word)"""
    checks = list(checks)
    _n[_scene] = _n.get(_scene, 0) + 1
    qid = f"{SHORT[_scene]}-{_n[_scene]:03d}"
    if refuse is None:
        checks = [c for c in checks if c != NC] + [NC, OTHERS]
    else:
        REFUSE[qid] = refuse
    QUERIES.append({"id": qid, "category": cat, "text": text, "scenes": [_scene], "expect": checks})
    if ans:
        ANS[qid] = ans
    if touch:
        TOUCH[qid] = touch
    if gen:
        GEN[qid] = gen


S, C, F, CF, H = "simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"

# ================================================================ (a) hotel room
_scene = "blender_hotel_room"
# ---- simple
# suitcase x[-0.625,-0.175] +0.5 -> x[-0.125,0.325] z[2.06,2.34]; the rack starts at z 2.55
Q(S, "hey, could you move the Suitcase 50cm to the right?", mv("Suitcase", [0.5, 0, 0]))
# bed x[-0.8,0.8] -0.05 -> x[-0.85,0.75]; Nightstand.001 ends at x -0.9; pillows and blanket ride
Q(S, "move the queen bed 5 cm to the left", *carry("Bed_Queen", [-0.05, 0, 0]))
# Pillow_L x[-0.7,-0.1] +0.1 -> x[-0.6,0.0]; Pillow_R starts at 0.1
Q(S, "move the left pillow 10cm to the right", mv("Pillow_L", [0.1, 0, 0]))
# the right bedside lamp = Lamp_Bedside.002: x[1.04,1.26] -0.05 -> x[0.99,1.21], on its nightstand
Q(S, "could you move the right bedside lamp 5 cm to the left", mv("Lamp_Bedside.002", [-0.05, 0, 0]))
# blanket z[-1.45,-0.95] -0.2 -> z[-1.65,-1.15]; the pillows end at z -2.5
Q(S, "move the throw blankt 20 cm back", mv("Blanket_Throw", [0, 0, -0.2]))
# 0.8 x 0.8 seat: the box does not change
Q(S, "Turn the Armchair 90 degrees clockwise when looking from above", rot("Armchair", -90), still("Armchair"))
# nightstand x[0.9,1.4] +0.15 -> x[1.05,1.55] with its lamp and the clock
Q(S, "move Nightstand.002 15cm to the right pls", *carry("Nightstand.002", [0.15, 0, 0]))
# rack x[0.35,1.05] -0.3 -> x[0.05,0.75]
Q(S, "please move the Luggage_Rack 30 cm to the left", mv("Luggage_Rack", [-0.3, 0, 0]))
# plant z[2.6,3.0] -0.3 -> z[2.3,2.7]
Q(S, "move the potted plant 30 cm back", mv("Plant_Pot.001", [0, 0, -0.3]))
# vase 0.18 x 0.45 x 0.18 about its pivot: x[1.71,1.89] z[-0.19,-0.01], inside the table top
Q(S, "Scale the Vase_Flowers up by 50%", scl("Vase_Flowers", 1.5), still("Vase_Flowers"))
# kettle z[-0.675,-0.525] -0.1 -> z[-0.775,-0.625]; the TV is at x <= -2.37, the kettle at x >= -2.3
Q(S, "move the kettel 10 cm back", mv("Kettle", [0, 0, -0.1]))
# bench z[-0.75,-0.35] +0.2 -> z[-0.55,-0.15], still on the rug
Q(S, "the bench at the foot of the bed needs to go 20cm forward", mv("Bench_BedEnd", [0, 0, 0.2]))
# curtain z[1.55,1.85] +0.2 -> z[1.75,2.05]; the wardrobe starts at z 2.4
Q(S, "move Curtain_R 20 cm towards the front wall", mv("Curtain_R", [0, 0, 0.2]))
# armchair z[0.4,1.2] -0.25 -> z[0.15,0.95]; the side table ends at z 0.125
Q(S, "move the armchair 25cm towards the back wall", mv("Armchair", [0, 0, -0.25]))
# cup x[-2.19,-2.11] +0.05 -> x[-2.14,-2.06], still on the dresser (x <= -2.0)
Q(S, "I'd like Cup.002 moved 5cm to the right", mv("Cup.002", [0.05, 0, 0]))

# ---- compositional
# pillows z[-2.9,-2.5] +0.1 -> z[-2.8,-2.4]
Q(C, "move both pillows 10 cm forward", mv("Pillow_L", [0, 0, 0.1]), mv("Pillow_R", [0, 0, 0.1]))
# each lamp to the other's spot: (-1.15,0.55,-2.86) <-> (1.15,0.55,-2.86)
Q(C, "swap the two bedside lamps please", *swap("Lamp_Bedside.001", "Lamp_Bedside.002"))
# NS1 x[-1.5,-1.0] (bed at -0.8), NS2 x[1.0,1.5]; lamps and clock ride
Q(C, "move Nightstand.001 10 cm left and Nightstand.002 10 cm right",
  *carry("Nightstand.001", [-0.1, 0, 0]), *carry("Nightstand.002", [0.1, 0, 0]))
# turn +90 (same box), then x[1.2,2.0]; the rug ends at x 1.1
Q(C, "turn the armchair 90° counterclockwise and slide it 20 cm to the left",
  rot("Armchair", 90), mv("Armchair", [-0.2, 0, 0]))
# desk lamp z[0.55,0.75]; phone z[1.2,1.4]
Q(C, "could you move the desk lamp 10 cm forward and the hotel phone 10cm back",
  mv("Lamp_Desk", [0, 0, 0.1]), mv("Phone_Hotel", [0, 0, -0.1]))
# towards the door: +z (door centre (-1.5,2.975) from (-1.6,1.0): line (0.051,0.999))
# chair z[1.05,1.55]; centre (-1.6,1.3) to the window (2.475,0.5): yaw ~101 deg, half 0.293
Q(C, "Move the desk chair 30 cm towards the door, then turn it to face the window",
  mv("Chair_Desk", [0, 0, 0.3]), faces("Chair_Desk", "Window_Balcony"),
  ans=[[D("Chair_Desk", [0, 0, 0.3]), FACE("Chair_Desk", "Window_Balcony")],
       [D("Chair_Desk", [0.015, 0, 0.2996]), FACE("Chair_Desk", "Window_Balcony")]])
# armchair x[1.2,2.0], side table x[1.375,1.825] with the vase
Q(C, "move the armchair and the side table 20 cm to the left",
  mv("Armchair", [-0.2, 0, 0]), *carry("Table_Side", [-0.2, 0, 0]))
# wardrobe x[1.3,2.3]; rack x[0.15,0.85]
Q(C, "would you mind shifting the wardrobe and the luggage rack 20cm to the left",
  mv("Wardrobe", [-0.2, 0, 0]), mv("Luggage_Rack", [-0.2, 0, 0]))
# suitcase turned: 0.28 wide x 0.45 deep -> x[-0.54,-0.26] z[1.975,2.425]; +0.3 -> x[-0.24,0.04]
Q(C, "rotate the suitcase 90 degrees and move it 30 cm to the right",
  rot("Suitcase", 90, True), mv("Suitcase", [0.3, 0, 0]))
# along the wall towards the desk = +z (desk centre (-2.225,1.0) from (-2.25,-1.2))
# dresser z[-1.7,-0.3] with the TV, kettle and both cups; the desk starts at z 0.4
Q(C, "slide the dresser 20 cm along the wall towards the desk, TV and all", *carry("Dresser", [0, 0, 0.2]))

# ---- fuzzy
Q(F, "nudge the suitcse a tad to the left", dr("Suitcase", "-x", 0.01))
# bench z min -0.75, bed ends at z -0.9: room for 0.15
Q(F, "scoot the bench a little closer to the bed", dr("Bench_BedEnd", "-z", 0.03), gen={"Bench_BedEnd": 0.1})
# suitcase on the rack: pivot (0.7,0.5,2.775) -> x[0.475,0.925] z[2.635,2.915] y[0.5,1.2]
Q(F, "put the suitcase on the luggage rack", top("Suitcase", "Luggage_Rack"),
  ans=[[TO("Suitcase", [0.7, 0.5, 2.775])]])
# window centre (2.475,0.5), chair centre (1.8,0.8): centre line (0.914,-0.406); room 0.25 along x
Q(F, "could you push the armchair a bit closer to the window?", dr("Armchair", "+x", 0.03),
  ans=[[D("Armchair", [0.03, 0, 0])], [D("Armchair", [0.2, 0, 0])], [D("Armchair", [0.137, 0, -0.061])]])
# pillow x max 0.7, bed edge 0.8
Q(F, "slide Pillow_R a couple of inches to the right", dr("Pillow_R", "+x", 0.03), gen={"Pillow_R": 0.08})
# door centre (-1.5,2.975), rack centre (0.7,2.775): line (-0.996,0.091), but the rack stands
# against the front wall, so the only way there is -x
Q(F, "drag the luggage rack a little toward the door", dr("Luggage_Rack", "-x", 0.03))
Q(F, "move the flowers a touch to the left", dr("Vase_Flowers", "-x", 0.01))
# chair x[-1.85,-1.35] away from the desk = +x
Q(F, "push the desk chair a bit further from the desk", dr("Chair_Desk", "+x", 0.03))
# clock on Nightstand.001 in front of its lamp: x[-1.22,-1.08] z[-2.655,-2.585]
Q(F, "put the alarm clock on the other nightstand", top("Alarm_Clock", "Nightstand.001"),
  ans=[[TO("Alarm_Clock", [-1.15, 0.55, -2.62])]])
# kettle on the desk between the lamp (z <= 0.65) and the phone (z >= 1.3): z[0.925,1.075]
Q(F, "Move the kettle off the dresser and onto the writing desk", top("Kettle", "Desk_Writing"),
  ans=[[TO("Kettle", [-2.2, 0.75, 1.0])]])
Q(F, "move the pilow forward a bit", ref(["Pillow_L", "Pillow_R"]), refuse=("ambiguous", ["pillow"]))
Q(F, "Could you move the bedside lamp a tad to the right", ref(["Lamp_Bedside.001", "Lamp_Bedside.002"]),
  refuse=("ambiguous", ["lamp", "bedside"]))

# ---- compositional fuzzy
Q(CF, "slide the bench a bit forward and nudge the suitcase a tad to the right",
  dr("Bench_BedEnd", "+z", 0.03), dr("Suitcase", "+x", 0.01))
Q(CF, "pull the desk chair out a bit and turn it 90 degrees clockwise",
  dr("Chair_Desk", "+x", 0.03), rot("Chair_Desk", -90))
# kettle back 0.03 -> z[-0.705,-0.555], cup at z[-0.84,-0.76]; kettle back 0.2 -> z[-0.875,-0.725],
# cup at z[-0.99,-0.91]; the cup stays at x[-2.24,-2.16], clear of the TV (x <= -2.37)
Q(CF, "move the kettle back a little and put Cup.001 next to it",
  dr("Kettle", "-z", 0.03), nxt("Cup.001", "Kettle"), top("Cup.001", "Dresser"),
  ans=[[D("Kettle", [0, 0, -0.03]), TO("Cup.001", [-2.2, 0.8, -0.8])],
       [D("Kettle", [0, 0, -0.2]), TO("Cup.001", [-2.2, 0.8, -0.95])]])
# clock z[-2.625,-2.555], inside the top (z <= -2.55)
Q(CF, "nudge Lamp_Bedside.001 a smidge to the left and move the alarm clock 3 cm towards the front",
  dr("Lamp_Bedside.001", "-x", 0.01), mv("Alarm_Clock", [0, 0, 0.03]))
# the bench (centre z -0.55) stays over the rug as long as the rug moves < 0.25
Q(CF, "move the rug a bit forward but keep the bench where it is",
  dr("Rug_Wool", "+z", 0.03), unch(["Bench_BedEnd"]))
# centre distance now 1.245 (plan 1.241, line (0.886,0.463)); 3 cm closer along the line: 1.215,
# along +x alone: 1.219, along +z alone: 1.232 -> max 1.235
Q(CF, "could you move the suitcase a bit closer to the luggage rack and turn it 90 degrees",
  dist("Suitcase", "Luggage_Rack", mx=1.235), rot("Suitcase", 90, True),
  ans=[[YAW("Suitcase", 90), D("Suitcase", [0.0266, 0, 0.0139])], [YAW("Suitcase", 90), D("Suitcase", [0, 0, 0.03])],
       [YAW("Suitcase", -90), D("Suitcase", [0.3, 0, 0])]])
Q(CF, "move Pillow_L a tad left and Pillow_R a tad right",
  dr("Pillow_L", "-x", 0.01), dr("Pillow_R", "+x", 0.01))
# clock on the desk at z[1.065,1.135] (phone from 1.3); chair back (-z) from z 0.75
Q(CF, "put the alarm clock on the desk and slide Chair_Desk a little towards the back wall",
  top("Alarm_Clock", "Desk_Writing"), dr("Chair_Desk", "-z", 0.03),
  ans=[[TO("Alarm_Clock", [-2.2, 0.75, 1.1]), D("Chair_Desk", [0, 0, -0.03])],
       [D("Chair_Desk", [0, 0, -0.2]), TO("Alarm_Clock", [-2.2, 0.75, 1.0])]])
# vase on the dresser at x[-2.26,-2.14] z[-1.06,-0.94]; side table +z (armchair from z 0.4)
Q(CF, "I'd like the vase on the dresser, and the side table a bit closer to the armchair",
  top("Vase_Flowers", "Dresser"), dr("Table_Side", "+z", 0.03),
  ans=[[TO("Vase_Flowers", [-2.2, 0.8, -1.0]), D("Table_Side", [0, 0, 0.03])],
       [D("Table_Side", [0, 0, 0.2]), TO("Vase_Flowers", [-2.2, 0.8, -1.0])]])
Q(CF, "nudge the wardrobe a tad to the left, and the luggage rack too",
  dr("Wardrobe", "-x", 0.01), dr("Luggage_Rack", "-x", 0.01))
# Curtain_L back: free; Curtain_R forward: wardrobe from z 2.4
Q(CF, "open the curtains a bit: Curtain_L a little towards the back wall, Curtain_R a bit towards the front wall, thanks!",
  dr("Curtain_L", "-z", 0.03), dr("Curtain_R", "+z", 0.03))

# ---- hard
# suitcase x min -0.625 -> the left wall -2.5; nothing in z[2.06,2.34] on the way
Q(H, "push the suitcase all the way to the left", mv("Suitcase", [-1.875, 0, 0], 0.02), IB,
  touch=[("Suitcase", "-x")])
# armchair x max 2.2 -> the window's face 2.45 (the curtains are at other z)
Q(H, "shove the armchair right up against the balcony window", mv("Armchair", [0.25, 0, 0], 0.02),
  touch=[("Armchair", "Window_Balcony")])
# bench z min -0.75 -> bed end -0.9; its centre (-0.7) stays over the rug
Q(H, "slide the bench back until it touches the bed", mv("Bench_BedEnd", [0, 0, -0.15], 0.02),
  touch=[("Bench_BedEnd", "Bed_Queen")])
# rack x max 1.05 -> wardrobe 1.5
Q(H, "move the luggage rack as far right as it will go", mv("Luggage_Rack", [0.45, 0, 0], 0.02),
  touch=[("Luggage_Rack", "Wardrobe")])
# chair x min -1.85 -> desk face -1.95
Q(H, "tuck the desk chair in flush against Desk_Writing", mv("Chair_Desk", [-0.1, 0, 0], 0.02),
  touch=[("Chair_Desk", "Desk_Writing")])
# side table z max 0.125 -> armchair 0.4; the vase rides
Q(H, "Slide the side table forward until it hits the armchair",
  *carry("Table_Side", [0, 0, 0.275], tol=0.02), touch=[("Table_Side", "Armchair")])
# centre (1.8,0.8) -> bed centre (0,-1.95): yaw -146.8 (turn -56.8); half 0.553 -> x[1.247,2.353]
Q(H, "turn the Armchair to face the bed", faces("Armchair", "Bed_Queen"), still("Armchair"))
# lamp (-2.35,0.55) -> chair (-1.6,1.0): yaw 59 deg, half 0.137 -> x[-2.487,-2.213]
Q(H, "angle Lamp_Desk so it points at Chair_Desk", faces("Lamp_Desk", "Chair_Desk"), still("Lamp_Desk"))
# centre (1.8,0.8) -> TV (-2.4,-1.2): yaw -115.5 (turn -25.5); half 0.533
Q(H, "please turn the armchair so it's facing the TV, thank you", faces("Armchair", "TV_Flat"), still("Armchair"))
Q(H, "move the lamp on the left nightstand 5 cm to the right", mv("Lamp_Bedside.001", [0.05, 0, 0]))
# Cup.002 (z -1.62) is nearer the kettle (z -0.6) than Cup.001 (z -1.8)
Q(H, "move the cup nearest the kettle 5cm to the right", mv("Cup.002", [0.05, 0, 0]))
# the chair by the window = Armchair (Chair_Desk is 4 m away): x[1.3,2.1]
Q(H, "move the chair by the window 10 cm to the left", mv("Armchair", [-0.1, 0, 0]))
# NS2 x[0.8,1.3] touches the bed; its lamp rides to x[0.94,1.16]; the clock (centre 1.2) stays over it
Q(H, "shift the second nightstand 10cm to the left but leave the alarm clock where it is",
  *carry("Nightstand.002", [-0.1, 0, 0], hold=("Alarm_Clock",)), unch(["Alarm_Clock"]))
# rug x[-0.95,1.25]; the bench (centre x 0) stays over it
Q(H, "move the rug 15 cm to the right but don't move the bench", mv("Rug_Wool", [0.15, 0, 0]),
  unch(["Bench_BedEnd"]))
# cups on the desk between its lamp (z <= 0.65) and phone (z >= 1.3)
Q(H, "put both cups on the desk", top("Cup.001", "Desk_Writing"), top("Cup.002", "Desk_Writing"),
  ans=[[TO("Cup.001", [-2.1, 0.75, 0.9]), TO("Cup.002", [-2.1, 0.75, 1.05])]])
# vase at x[-2.31,-2.19] z[-1.01,-0.89]: TV (-2.4,-1.2) to kettle (-2.2,-0.6) passes x -2.317 there
Q(H, "put the vase on the dresser between the TV and the kettle", top("Vase_Flowers", "Dresser"),
  btw("Vase_Flowers", "TV_Flat", "Kettle"), ans=[[TO("Vase_Flowers", [-2.25, 0.8, -0.95])]])
# clock at x[-2.27,-2.13] z[1.115,1.185]; phone from z 1.3
Q(H, "put the clock on the desk next to the phone", top("Alarm_Clock", "Desk_Writing"),
  nxt("Alarm_Clock", "Phone_Hotel"), ans=[[TO("Alarm_Clock", [-2.2, 0.75, 1.15])]])
# chair centre (-1.6,1.0) -> window (2.475,0.5): line (0.993,-0.122): 0.4 -> (0.397,-0.049); axis (0.4,0)
Q(H, "move the desk chair 40 cm toward the window", mv("Chair_Desk", [0.4, 0, -0.024], 0.03),
  ans=[[D("Chair_Desk", [0.4, 0, 0])], [D("Chair_Desk", [0.397, 0, -0.049])]])
# rack centre (0.7,2.775) -> wardrobe (2.0,2.7): line (0.998,-0.058): 1 ft -> (0.304,-0.018)
Q(H, "move the luggage rack a foot toward the wardrobe", mv("Luggage_Rack", [0.305, 0, -0.009], 0.03),
  ans=[[D("Luggage_Rack", [FT, 0, 0])], [D("Luggage_Rack", [0.304, 0, -0.0176])]])
# suitcase (-0.4,2.2) -> window (2.475,0.5): yaw 120.6; box x[-0.635,-0.165] z[1.935,2.465]
Q(H, "can you turn the suitcase so it faces the window?", faces("Suitcase", "Window_Balcony"), still("Suitcase"))
# -- refusals
Q(H, "move the nightsand 10 cm to the left", ref(["Nightstand.001", "Nightstand.002"]),
  refuse=("ambiguous", ["nightstand"]))
Q(H, "put the cup next to the kettle", ref(["Cup.001", "Cup.002"]), refuse=("ambiguous", ["cup"]))
Q(H, "move the curtain 10cm forward please", ref(["Curtain_L", "Curtain_R"]), refuse=("ambiguous", ["curtain"]))
Q(H, "hi! move the minibar 20 cm to the left", ref([]), refuse=("missing", "minibar"))
Q(H, "put the laptop on the desk", ref([]), refuse=("missing", "laptop"))
Q(H, "push the lamp against the wall", ref(["Lamp_Bedside.001", "Lamp_Bedside.002", "Lamp_Desk"]),
  refuse=("ambiguous", ["lamp"]))
Q(H, "could you move the ironing board next to the wardrobe", ref([]), refuse=("missing", "ironing"))

# ================================================================ (b) clinic waiting room
_scene = "clinic_waiting_room"
FRONT = [f"chair {i}" for i in range(1, 6)]
MIDDLE = [f"chair {i}" for i in range(6, 11)]
BACK = [f"chair {i}" for i in range(11, 16)]
# ---- simple
# chair 7 (middle row) z[-0.65,-0.15] -0.3 -> z[-0.95,-0.45]; chair 12 ends at z -1.35
Q(S, "move chair 7 30cm back", mv("chair 7", [0, 0, -0.3]))
# cooler z[2.225,2.575] -0.4 -> z[1.825,2.175]
Q(S, "hi, could you move the water cooler 40 cm back?", mv("water cooler", [0, 0, -0.4]))
Q(S, "turn chair 3 around 180°", rot("chair 3", 180, True), still("chair 3"))
# kids table x[2.0,3.0] -0.2 -> x[1.8,2.8] with the puzzle; the kids chairs stay
Q(S, "move the kids table 20 cm to the left", *carry("kids table", [-0.2, 0, 0]))
# machine z[0.05,0.95] +0.5 -> z[0.55,1.45]; reception from z 2.25
Q(S, "move the vending machine 50 cm towards the front wall", mv("vending machine", [0, 0, 0.5]))
# stand x[-1.125,-0.875] +0.6 -> x[-0.525,-0.275]
Q(S, "the umbrella stand needs to go 60 cm to the right", mv("umbrella stand", [0.6, 0, 0]))
# rack z[-3.35,-2.85] +0.3 -> z[-3.05,-2.55]
Q(S, "move the coat rack 30 cm forward", mv("coat rack", [0, 0, 0.3]))
# bin z[-0.175,0.175] +1 -> z[0.825,1.175]; chair 1 starts at x -2.85, the bin ends at -3.525
Q(S, "move the trash can 1 metre forward", mv("trash can", [0, 0, 1.0]))
Q(S, "scale plant 2 down to 80%", scl("plant 2", 0.8), still("plant 2"))
# tv x[-2,-0.8] +0.2 -> x[-1.8,-0.6]: the cabinet's right end
Q(S, "move the tv 20 cm to the right", mv("tv", [0.2, 0, 0]))
# chair 11 (back left) x[-2.85,-2.35] -0.2 -> x[-3.05,-2.55]
Q(S, "move chair 11 20 cm left", mv("chair 11", [-0.2, 0, 0]))
# desk x[1.3,3.3] -0.2 -> x[1.1,3.1] with the monitor, sanitizer and pen holder
Q(S, "Move the recepton desk 20cm to the left", *carry("reception desk", [-0.2, 0, 0]))

# ---- compositional
# front row z[0.55,1.05] -0.2 -> z[0.35,0.85]; the middle row ends at -0.15
Q(C, "move all the chairs in the front row 20 cm back", *[mv(c, [0, 0, -0.2]) for c in FRONT])
# back row z[-1.85,-1.35] +0.1 -> z[-1.75,-1.25]
Q(C, "Could you move chairs 11 to 15 forward by 10 cm?", *[mv(c, [0, 0, 0.1]) for c in BACK])
# side table 1 (0.45,0,0.8) <-> side table 2 (0.45,0,-1.6); the magazines ride
Q(C, "swap the two side tables, magazines and all",
  *swap("side table 1", "side table 2"), mv("magazine 1", [0, 0, -2.4]), mv("magazine 2", [0, 0, 2.4]),
  ans=[[D("side table 1", [0, 1.0, 0]), D("side table 2", [0, 0, 2.4]), D("side table 1", [0, -1.0, -2.4])]])
Q(C, "put magazine 1 on side table 2 and magazine 2 on side table 1",
  top("magazine 1", "side table 2"), top("magazine 2", "side table 1"),
  ans=[[TO("magazine 1", [0.45, 0.5, -1.6]), TO("magazine 2", [0.45, 0.5, 0.8])]])
# chair 6 (-2.6,-0.4) and chair 10 (-0.2,-0.4): +90 and -90, boxes unchanged
Q(C, "turn chair 6 and chair 10 to face each other",
  faces("chair 6", "chair 10"), faces("chair 10", "chair 6"), still("chair 6"), still("chair 10"))
# chair 1 x[-3.05,-2.55]; chair 5 x[-0.35,0.15] (side table 1 from 0.2)
Q(C, "move chair 1 20 cm to the left and chair 5 10 cm to the right",
  mv("chair 1", [-0.2, 0, 0]), mv("chair 5", [0.1, 0, 0]))
# table x[1.7,2.7] (+puzzle), kids chairs x[2.05,2.35]
Q(C, "move the kids table and both kids chairs 30 cm to the left",
  *carry("kids table", [-0.3, 0, 0]), mv("kids chair 1", [-0.3, 0, 0]), mv("kids chair 2", [-0.3, 0, 0]))
# chair 8 z[-0.85,-0.35]; chair 13 z[-1.65,-1.15]
Q(C, "move chair 8 back 20 cm and chair 13 forward 20 cm",
  mv("chair 8", [0, 0, -0.2]), mv("chair 13", [0, 0, 0.2]))
# sanitizer x[1.76,1.84]; pen holder x[2.96,3.04]; the monitor is x[2.025,2.575] at z >= 2.66
Q(C, "move the hand sanitizer 30cm to the right and the pen holder 10 cm to the left",
  mv("hand sanitizer", [0.3, 0, 0]), mv("pen holder", [-0.1, 0, 0]))
# chair 5 z[0.65,1.15]; side table 1 z[0.65,1.15] with magazine 1
Q(C, "slide side table 1 and chair 5 forward 10 cm, thx", *carry("side table 1", [0, 0, 0.1]), mv("chair 5", [0, 0, 0.1]))
# middle row z[-0.65,-0.15] +0.15 -> z[-0.5,0.0]; front row from 0.55
Q(C, "ok now move the whole middle row 15 cm forward", *[mv(c, [0, 0, 0.15]) for c in MIDDLE])

# ---- fuzzy
# chair 12 x[-2.25,-1.75], chair 11 ends at -2.35
Q(F, "nudge chair 12 a tad to the left", dr("chair 12", "-x", 0.01))
# magazine on the reception desk at x[1.695,1.905] z[2.46,2.74]
Q(F, "put magazine 2 on the reception desk", top("magazine 2", "reception desk"),
  ans=[[TO("magazine 2", [1.8, 1.1, 2.6])]])
# chair 10 is the right end of the middle row: nothing to its right
Q(F, "could you slide chair 10 a little to the right", dr("chair 10", "+x", 0.03))
# bin centre (-3.7,0.3,0) to chair 1 (-2.6,0.425,0.8): 1.366 (plan 1.360); line (0.809,0.588);
# 3 cm closer along the line: 1.336; 3 cm along +x or +z alone: 1.342 / 1.349 -> max 1.35
Q(F, "drag the trash can a little closer to chair 1", dist("trash can", "chair 1", mx=1.35),
  ans=[[D("trash can", [0.0243, 0, 0.0176])], [D("trash can", [0.03, 0, 0])], [D("trash can", [0, 0, 0.03])], [D("trash can", [0.243, 0, 0.176])], [D("trash can", [0.1, 0, 0])]])
Q(F, "move the puzzle a touch to the right", dr("puzzle", "+x", 0.01))
# magazine on the kids table beside the puzzle: x[2.065,2.275] z[-1.94,-1.66]
Q(F, "put magazine 1 on the kids table", top("magazine 1", "kids table"),
  ans=[[TO("magazine 1", [2.17, 0.5, -1.8])]])
Q(F, "scoot chair 14 slightly back", dr("chair 14", "-z", 0.01))
Q(F, "hey, move the vending machine a little to the left", dr("vending machine", "-x", 0.03))
Q(F, "move the computer moniter a hair to the left", dr("computer monitor", "-x", 0.01))
# kids chair 2 z[-1.4,-1.1] faces the table from the front: further = +z
Q(F, "could you move kids chair 2 a bit further from the kids table", dr("kids chair 2", "+z", 0.03))
Q(F, "move the side table a bit to the right", ref(["side table 1", "side table 2"]),
  refuse=("ambiguous", ["side", "table"]))
Q(F, "put the magzine on the reception desk", ref(["magazine 1", "magazine 2"]),
  refuse=("ambiguous", ["magazine"]))

# ---- compositional fuzzy
Q(CF, "scoot all the front-row chairs a bit back", *[dr(c, "-z", 0.03) for c in FRONT])
Q(CF, "move the kids table a little left and the toy box a tad right",
  dr("kids table", "-x", 0.03), top("puzzle", "kids table"), dr("toy box", "+x", 0.01))
Q(CF, "nudge chair 2 and chair 7 slightly forward", dr("chair 2", "+z", 0.01), dr("chair 7", "+z", 0.01))
# magazine 1 to the reception desk; side table 1 to the right (nothing there)
Q(CF, "put magazine 1 on the reception desk and push side table 1 a bit to the right",
  top("magazine 1", "reception desk"), dr("side table 1", "+x", 0.03),
  ans=[[TO("magazine 1", [1.8, 1.1, 2.6]), D("side table 1", [0.03, 0, 0])],
       [D("side table 1", [0.15, 0, 0]), TO("magazine 1", [1.8, 1.1, 2.6])]])
# chair 11 (-2.6,-1.6) -> door (-2.0,-3.475): yaw ~162, half 0.315 -> x[-2.915,-2.285] (chair 12 from -2.25)
Q(CF, "scoot chair 11 a little forward and then turn it to face the door",
  faces("chair 11", "door"), dr("chair 11", "+z", 0.03),
  ans=[[D("chair 11", [0, 0, 0.03]), FACE("chair 11", "door")],
       [FACE("chair 11", "door"), D("chair 11", [0, 0, 0.15])]])
Q(CF, "move both side tables a tad to the right",
  dr("side table 1", "+x", 0.01), dr("side table 2", "+x", 0.01),
  top("magazine 1", "side table 1"), top("magazine 2", "side table 2"))
# the pen holder (centre x 3.1) stays over the desk while the desk moves < 0.2
Q(CF, "slide the reception desk a bit to the left, but leave the pen holder where it is",
  dr("reception desk", "-x", 0.03), top("computer monitor", "reception desk"),
  top("hand sanitizer", "reception desk"), unch(["pen holder"]))
Q(CF, "drag chair 15 a bit back and turn it 90 degrees clockwise",
  dr("chair 15", "-z", 0.03), rot("chair 15", -90))
Q(CF, "move the water cooler a little to the right and the trash can a bit back",
  dr("water cooler", "+x", 0.03), dr("trash can", "-z", 0.03))
# puzzle on the floor beside the toy box: x[2.65,2.95] z[-2.95,-2.65]; kids chair 1 to the
# table: room 0.1 (z max -2.2 -> table from -2.1)
Q(CF, "put the puzzle on the floor next to the toy box and push kids chair 1 a bit closer to the table",
  at("puzzle", [None, 0, None]), nxt("puzzle", "toy box"), dr("kids chair 1", "+z", 0.03),
  ans=[[TO("puzzle", [2.8, 0, -2.8]), D("kids chair 1", [0, 0, 0.03])],
       [TO("puzzle", [2.8, 0, -2.8]), D("kids chair 1", [0, 0, 0.08])]])
Q(CF, "could you move the middle row of chairs a bit to the right", *[dr(c, "+x", 0.03) for c in MIDDLE])

# ---- hard
# chair 5 x max 0.05 -> side table 1 at 0.2
Q(H, "push chair 5 right up against side table 1", mv("chair 5", [0.15, 0, 0], 0.02),
  touch=[("chair 5", "side table 1")])
# machine z min 0.05 -> plant 2's front 2.95... plant 2 z max -2.95 (x[3.45,3.95] overlaps x[3.2,4.0])
Q(H, "shove the vending machine along the wall as far toward the back as it'll go", mv("vending machine", [0, 0, -3.0], 0.02),
  IB, touch=[("vending machine", "plant 2")])
# chair 3 (-1.4,0.8) is 2.55 from the tv (-1.4,3.35); chair 2 is 2.62
Q(H, "move the chair closest to the tv 20 cm forward", mv("chair 3", [0, 0, 0.2]))
# back row: chair 11 (-2.6,-1.6) is 1.80 from the coat rack (-3.6,-3.1), chair 12 2.19
Q(H, "move the back-row chair closest to the coat rack 30cm to the left", mv("chair 11", [-0.3, 0, 0]))
# magazine 2 (on side table 2) to the kids table beside the puzzle
Q(H, "move the magazine on side table 2 onto the kids table", top("magazine 2", "kids table"),
  ans=[[TO("magazine 2", [2.17, 0.5, -1.8])]])
# kids chair 1 (2.5,-2.35) -> toy box (2.8,-3.25): yaw 161.6, half 0.19 -> z[-2.54,-2.16]
Q(H, "turn kids chair 1 to face the toy box", faces("kids chair 1", "toy box"), still("kids chair 1"))
# chair 15 (-0.2,-1.6) -> machine (3.6,0.5): yaw 61.1, half 0.34 -> x[-0.54,0.14]
Q(H, "turn chair 15 so it faces the vending machine", faces("chair 15", "vending machine"), still("chair 15"))
# behind chair 3 = chair 8 (middle row, same column)
Q(H, "move the chair right behind chair 3 5cm to the left", mv("chair 8", [-0.05, 0, 0]))
# between chair 12 and chair 14 = chair 13 ("to the right of" would depend on whose right)
Q(H, "move the chair between chair 12 and chair 14 10 cm back", mv("chair 13", [0, 0, -0.1]))
# side table 2 x min 0.2 -> chair 15 x max 0.05; the magazine rides
Q(H, "push side table 2 left until it touches chair 15", *carry("side table 2", [-0.15, 0, 0], tol=0.02),
  touch=[("side table 2", "chair 15")])
# kids chair 2 on the floor at x[2.1,2.4] z[-3.35,-3.05], 5 cm from the toy box
Q(H, "put kids chair 2 next to the toy box", nxt("kids chair 2", "toy box"), at("kids chair 2", [None, 0, None]),
  ans=[[TO("kids chair 2", [2.25, 0, -3.2])]])
# rack z min -3.35 -> the back wall -3.5
Q(H, "slide the coat rack back until it's flush with the back wall", mv("coat rack", [0, 0, -0.15], 0.02), IB,
  touch=[("coat rack", "-z")])
# bin x min -3.875 -> the left wall -4
Q(H, "push the trash can against the left wall", mv("trash can", [-0.125, 0, 0], 0.02), IB,
  touch=[("trash can", "-x")])
# plant 1 (-3.7,3.2) -> cabinet (-1.4,3.275): line (0.9995,0.0326): 0.5 -> (0.4997,0.0163)
Q(H, "move plant 1 half a metre toward the tv cabinet", mv("plant 1", [0.5, 0, 0.008], 0.03),
  ans=[[D("plant 1", [0.5, 0, 0])], [D("plant 1", [0.4997, 0, 0.0163])]])
# magazines on the reception desk: x[1.695,1.905] z[2.46,2.74] and x[2.695,2.905] z[2.41,2.69]
Q(H, "put both magazines on the reception desk", top("magazine 1", "reception desk"),
  top("magazine 2", "reception desk"),
  ans=[[TO("magazine 1", [1.8, 1.1, 2.6]), TO("magazine 2", [2.8, 1.1, 2.55])]])
Q(H, "turn chairs 11 to 15 around so they face the back wall", *[rot(c, 180, True) for c in BACK],
  *[still(c) for c in BACK])
# in front of chair 9 = chair 4 (front row, same column)
Q(H, "move the chair in front of chair 9 5 cm left", mv("chair 4", [-0.05, 0, 0]))
# -- refusals
Q(H, "turn the kids chair to face the toy box", ref(["kids chair 1", "kids chair 2"]),
  refuse=("ambiguous", ["kids", "chair"]))
Q(H, "could you move the plant 30 cm to the left", ref(["plant 1", "plant 2"]), refuse=("ambiguous", ["plant"]))
Q(H, "hi there, could you move the sofa 50cm to the left", ref([]), refuse=("missing", "sofa"))
Q(H, "put the fish tank next to the vending machine", ref([]), refuse=("missing", "fish"))
Q(H, "move the chair in the front row 10 cm back", ref(FRONT), refuse=("ambiguous", ["chair"]))
Q(H, "move the coffee table 30 cm forward", ref([]), refuse=("missing", "coffee"))

# ================================================================ (c) home office
_scene = "home_office"
DESK_TOP = ["laptop", "monitor", "white mug", "phone", "desk lamp", "blue book"]
# free spots worked out from the boxes in the comments above:
#   desk: between the laptop (x <= 0.17) and the white mug (x >= 0.405), in front of the monitor
#         (z >= -2.25): a book 0.17 x 0.24 at x[0.2,0.37] z[-2.06,-1.82]
#   coffee table x[-0.1,1.1] z[0.6,1.2]: left strip x[-0.1,0.115], right strip x[0.845,1.1],
#         front strip z[1.03,1.2]
# ---- simple
# desk x[-0.9,0.7] with everything on it; the waste basket ends at x -0.95
Q(S, "hello! move the desk 10cm to the left", *carry("desk", [-0.1, 0, 0]))
# chair x[0,0.6] z[-1.65,-1.05]
Q(S, "move the office chair 30 cm to the right", mv("office chair", [0.3, 0, 0]))
Q(S, "rotate the armchair 90 degrees counter-clockwise", rot("armchair", 90), still("armchair"))
# table x[-0.3,0.9] with book, plate, mug; still over the rug (x >= -0.5)
Q(S, "could you move the coffee table 20cm to the left", *carry("coffee table", [-0.2, 0, 0]))
# lamp z[-0.675,-0.325]; the window hangs at y >= 1 and x >= 2.4
Q(S, "move the floor lamp 30 cm back", mv("floor lamp", [0, 0, -0.3]))
Q(S, "move the waste basket 20cm forward", mv("waste basket", [0, 0, 0.2]))
# 0.18 x 0.225 x 0.18: x[-2.415,-2.235], inside the shelf top
Q(S, "scale the succulent up 1.5x", scl("succulent", 1.5), still("succulent"))
# printer z[-2.3,-1.9], still on the cabinet (z <= -1.9)
Q(S, "move the printer 10 cm forward", mv("printer", [0, 0, 0.1]))
# guest chair x[-1.25,-0.75]; the office chair starts at x -0.3
Q(S, "I'd like the guest chair moved 30cm to the right", mv("guest chair", [0.3, 0, 0]))
# faces +x -> +z, same box
Q(S, "turn the guest chair 90° clockwise seen from above", rot("guest chair", -90), still("guest chair"))
# side table z[1.025,1.475] with the small plate; the armchair ends at z 1.0
Q(S, "the side table needs to go 20 cm back", *carry("side table", [0, 0, -0.2]))

# ---- compositional
# laptop x[-0.27,0.07] (phone ends at -0.41); mug x[0.505,0.595] z[-1.995,-1.905]
Q(C, "move the laptop 10 cm to the left and the white mug 10 cm to the right",
  mv("laptop", [-0.1, 0, 0]), mv("white mug", [0.1, 0, 0]))
Q(C, "swap the phone and the whte mug", *swap("phone", "white mug"))
# armchair z[0,0.8] (floor lamp ends at -0.025); side table z[1.025,1.475]
Q(C, "move the armchair and the side table 20 cm towards the back wall",
  mv("armchair", [0, 0, -0.2]), *carry("side table", [0, 0, -0.2]))
# white x[0.355,0.445]; black x[0.705,0.795] (plate ends at 0.63)
Q(C, "move both mugs 5 cm to the left, ty", mv("white mug", [-0.05, 0, 0]), mv("black mug", [-0.05, 0, 0]))
# cabinet x[1.175,1.625] with the printer; basket x[-1.45,-1.15]
Q(C, "move the filing cabinet 20 cm to the right, printer included, and the waste basket 20 cm to the left",
  *carry("filing cabinet", [0.2, 0, 0]), mv("waste basket", [-0.2, 0, 0]))
Q(C, "turn the office chair 180 degrees and move it 20 cm to the left",
  rot("office chair", 180, True), mv("office chair", [-0.2, 0, 0]))
# rug z[0.1,1.5] carrying the coffee table and what is on it; sofa x[-0.3,1.5] (side table from 1.875)
Q(C, "move the rug 10 cm back and the sofa 10 cm to the right",
  *carry("rug", [0, 0, -0.1]), mv("sofa", [0.1, 0, 0]))
# lamp square: same box; z[-2.35,-2.15]
Q(C, "move the desk lamp 10 cm forward and rotate it 90 degrees",
  mv("desk lamp", [0, 0, 0.1]), rot("desk lamp", 90, True))
# red book z[-1.02,-0.78]; succulent z[-0.51,-0.39] (shelf ends at -0.35)
Q(C, "move the red book and the succulent 10cm forward",
  mv("red book", [0, 0, 0.1]), mv("succulent", [0, 0, 0.1]))
# chair at (-1.1,-1.0), then to the door (-1.6,2.475): yaw -8.2, half 0.283
Q(C, "move the guest chair 20cm to the right and turn it to face the door",
  mv("guest chair", [0.2, 0, 0]), faces("guest chair", "door"))
# phone x[-0.59,-0.51]; laptop x[-0.07,0.27]
Q(C, "would you mind moving the phone 10 cm left and the laptop 10 cm right",
  mv("phone", [-0.1, 0, 0]), mv("laptop", [0.1, 0, 0]))
# monitor x[-0.4,0.2] (lamp ends at -0.55); blue book z[-2.37,-2.13]
Q(C, "move the monitor 10 cm to the left and the blue book 5 cm forward",
  mv("monitor", [-0.1, 0, 0]), mv("blue book", [0, 0, 0.05]))

# ---- fuzzy
# mug centre (0.45,-1.95) -> laptop (0,-2.0): line (-0.994,-0.110); laptop ends at x 0.17
Q(F, "move the white mug a bit closer to the laptop", dr("white mug", "-x", 0.03),
  ans=[[D("white mug", [-0.03, 0, 0])], [D("white mug", [-0.15, 0, 0])], [D("white mug", [-0.149, 0, -0.0166])]])
Q(F, "put the blue book on the coffee table", top("blue book", "coffee table"),
  ans=[[TO("blue book", [0.98, 0.43, 0.9])]])
Q(F, "nudge the floor lamp a tad to the left", dr("floor lamp", "-x", 0.01))
# sofa x max 1.4 -> side table 1.875
Q(F, "could you push the sofa a little to the right", dr("sofa", "+x", 0.03))
# the plate on the coffee table = dinner plate; the black mug starts at x 0.755
Q(F, "slide the plate on the coffee table a smidge to the right", dr("dinner plate", "+x", 0.01))
# chair (-1.3,-1.0) -> bookshelf (-2.325,-0.8): line (-0.981,0.192)
Q(F, "move the guest chair a little closer to the bookshelf", dr("guest chair", "-x", 0.03),
  ans=[[D("guest chair", [-0.03, 0, 0])], [D("guest chair", [-0.15, 0, 0])], [D("guest chair", [-0.147, 0, 0.029])]])
# basket x max -0.95 -> desk -0.8
Q(F, "scoot the waste basket a couple of inches to the right", dr("waste basket", "+x", 0.03),
  gen={"waste basket": 0.1})
# black mug beside the small plate: x[1.9,1.99] z[1.405,1.495]
Q(F, "put the black mug on the side table", top("black mug", "side table"),
  ans=[[TO("black mug", [1.945, 0.55, 1.45])]])
# phone on the coffee table's left strip: x[-0.04,0.04] z[0.82,0.98]
Q(F, "put the phone on the coffee table", top("phone", "coffee table"),
  ans=[[TO("phone", [0.0, 0.43, 0.9])]])
# coffee table z max 1.2 -> sofa 1.6
Q(F, "push the coffee table a bit closer to the sofa", dr("coffee table", "+z", 0.03),
  *tops("coffee table"))
Q(F, "move the mug a bit to the left", ref(["white mug", "black mug"]), refuse=("ambiguous", ["mug"]))
Q(F, "move the book 10 cm to the right", ref(["red book", "green book", "blue book"]),
  refuse=("ambiguous", ["book"]))

# ---- compositional fuzzy
Q(CF, "move the laptop a bit to the left and the mug on the desk a tad to the right",
  dr("laptop", "-x", 0.03), dr("white mug", "+x", 0.01))
# desk x max 0.8 -> filing cabinet 0.975; the monitor (centre x 0) stays over the desk
Q(CF, "could you push the desk a bit to the right, but don't move the monitor",
  dr("desk", "+x", 0.03), *tops("desk", hold=("monitor",)), unch(["monitor"]))
# green book to the desk spot; coffee table left (still on the rug)
Q(CF, "put the green book on the desk and move the coffee table a little to the left",
  top("green book", "desk"), dr("coffee table", "-x", 0.03), top("dinner plate", "coffee table"),
  top("black mug", "coffee table"),
  ans=[[TO("green book", [0.285, 0.75, -1.94]), D("coffee table", [-0.03, 0, 0])],
       [D("coffee table", [-0.15, 0, 0]), TO("green book", [0.285, 0.75, -1.94])]])
# armchair back: floor lamp ends at z -0.025 (room 0.225)
Q(CF, "nudge the sofa a tad right and the armchair a bit towards the back of the room",
  dr("sofa", "+x", 0.01), dr("armchair", "-z", 0.03))
# chair (-1.3,-1.0) -> desk centre (0,-2.15): yaw ~131.5; after +0.15: ~135; half <= 0.354
Q(CF, "scoot the guest chair a little to the right and turn it to face the desk",
  dr("guest chair", "+x", 0.03), faces("guest chair", "desk"),
  ans=[[D("guest chair", [0.03, 0, 0]), FACE("guest chair", "desk")],
       [FACE("guest chair", "desk"), D("guest chair", [0.15, 0, 0])]])
# the phone may only go 6 cm forward before it hangs over the edge (z <= -1.8)
Q(CF, "move the desk lamp a little to the right and the phone a tad forward",
  dr("desk lamp", "+x", 0.03), dr("phone", "+z", 0.01), gen={"phone": 0.06})
# the rug moves; the coffee table and what is on it stay
Q(CF, "move the rug a bit to the left, but leave the coffee table where it is",
  dr("rug", "-x", 0.03), unch(["coffee table", "green book", "dinner plate", "black mug"]))
# small plate on the desk spot x[0.195,0.375] z[-2.03,-1.85]; side table -z (armchair ends at 1.0)
Q(CF, "put the small plate on the desk and push the side table a little closer to the armchair",
  top("small plate", "desk"), dr("side table", "-z", 0.03),
  ans=[[TO("small plate", [0.285, 0.75, -1.94]), D("side table", [0, 0, -0.03])],
       [D("side table", [0, 0, -0.15]), TO("small plate", [0.285, 0.75, -1.94])]])
# printer z min -2.4 -> -2.5 at most; blue book x min 0.515 -> monitor 0.3
Q(CF, "give the printer a tiny nudge back and move the blue book a bit to the left",
  dr("printer", "-z", 0.01), dr("blue book", "-x", 0.03))
# towards the door: +z (door centre (-1.6,2.475) from (-1.3,-1.0): line (-0.086,0.996))
Q(CF, "turn the guest chair around and slide it a little toward the door",
  rot("guest chair", 180, True), dr("guest chair", "+z", 0.03),
  ans=[[YAW("guest chair", 180), D("guest chair", [0, 0, 0.03])],
       [YAW("guest chair", -180), D("guest chair", [-0.013, 0, 0.149])]])
# red book z min -1.12: 10 cm before it overhangs the shelf (z >= -1.25 for the whole book: 0.13)
Q(CF, "nudge the succulent a tad forward and the red book a bit back",
  dr("succulent", "+z", 0.01), dr("red book", "-z", 0.03), gen={"red book": 0.1})

# ---- hard
# basket x max -0.95 -> desk -0.8
Q(H, "push the waste basket right until it touches the desk", mv("waste basket", [0.15, 0, 0], 0.02),
  touch=[("waste basket", "desk")])
# sofa x min -0.4; the door (z[2.45,2.5], x max -1.15) is in the way first
Q(H, "slide the sofa as far left as it will go", mv("sofa", [-0.75, 0, 0], 0.02),
  touch=[("sofa", "door")])
# black mug x[0.705,0.795]
Q(H, "move the mug on the coffee table 5 cm to the left", mv("black mug", [-0.05, 0, 0]))
# white mug on the front strip: x[0.455,0.545] z[1.055,1.145], 2.5 cm from the plate
Q(H, "put the white mug on the coffee table next to the dinner plate", top("white mug", "coffee table"),
  nxt("white mug", "dinner plate"), ans=[[TO("white mug", [0.5, 0.43, 1.1])]])
# chair (0,-1.35) -> window (2.45,-1.2): yaw 86.5 (turn -93.5), half 0.318
Q(H, "turn the office chair to face the window", faces("office chair", "window"), still("office chair"))
# lamp (-0.65,-2.35) -> laptop (0,-2.0): yaw 61.7, half 0.135 -> x[-0.785,-0.515] z[-2.485,-2.215]
Q(H, "point the desk lamp at the laptop", faces("desk lamp", "laptop"), still("desk lamp"))
# blue book x[0.415,0.585]
Q(H, "move the book on the desk 10 cm to the left", mv("blue book", [-0.1, 0, 0]))
# red book to the desk spot, 3 cm from the laptop
Q(H, "take the book from the shelf and set it on the desk next to the laptop",
  top("red book", "desk"), nxt("red book", "laptop"), ans=[[TO("red book", [0.285, 0.75, -1.94])]])
# small plate x[0.195,0.375] z[-2.03,-1.85]: laptop (0,-2.0) to white mug (0.45,-1.95) passes it
Q(H, "put the small plate on the desk between the laptop and the white mug",
  top("small plate", "desk"), btw("small plate", "laptop", "white mug"),
  ans=[[TO("small plate", [0.285, 0.75, -1.94])]])
# the chair by the bookshelf = guest chair
Q(H, "move the chair by the bookshelf 20 cm to the right", mv("guest chair", [0.2, 0, 0]))
# lamp z min -0.375 -> back wall -2.5 (the filing cabinet is at x <= 1.425; the window hangs above)
Q(H, "slide the floor lamp back until it touches the back wall", mv("floor lamp", [0, 0, -2.125], 0.02), IB,
  touch=[("floor lamp", "-z")])
# desk x[-0.65,0.95]; laptop (centre 0) and phone (centre -0.45) stay over it
Q(H, "move the desk 15 cm to the right but keep the laptop and the phone where they are",
  *carry("desk", [0.15, 0, 0], hold=("laptop", "phone")), unch(["laptop", "phone"]))
# lamp (2.2,-0.2) -> sofa (0.5,2.05): yaw -37, half 0.245 -> x[1.955,2.445] z[-0.445,0.045]
# (the window hangs at z <= -0.6)
Q(H, "point the floor lamp at the sofa", faces("floor lamp", "sofa"), still("floor lamp"))
# chair (0,-1.35) -> sofa (0.5,2.05): yaw 8.4, half 0.341 -> z[-1.691,-1.009] (desk ends at -1.8)
Q(H, "turn the office chair around so it faces the sofa", faces("office chair", "sofa"), still("office chair"))
# coffee table z max 1.2 -> sofa 1.6; its centre (1.3) stays over the rug
Q(H, "slide the coffee table forward until it touches the sofa",
  *carry("coffee table", [0, 0, 0.4], tol=0.02), touch=[("coffee table", "sofa")])
# black mug x[0.655,0.745], 2.5 cm from the plate
Q(H, "move the black mug 10 cm toward the dinner plate", mv("black mug", [-0.1, 0, 0]))
# chair (-1.3,-1.0) -> door (-1.6,2.475): line (-0.086,0.996): 1 ft -> (-0.026,0.304); axis (0,0.305)
Q(H, "move the guest chair 1 ft toward the door", mv("guest chair", [-0.013, 0, 0.305], 0.03),
  ans=[[D("guest chair", [0, 0, FT])], [D("guest chair", [-0.026, 0, 0.304])]])
# -- refusals
Q(H, "put the plate on the desk", ref(["dinner plate", "small plate"]), refuse=("ambiguous", ["plate"]))
Q(H, "turn the chair to face the window", ref(["office chair", "guest chair"]), refuse=("ambiguous", ["chair"]))
Q(H, "move the lamp 20cm to the left", ref(["desk lamp", "floor lamp"]), refuse=("ambiguous", ["lamp"]))
Q(H, "put the phone on the nightstand", ref([]), refuse=("missing", "nightstand"))
Q(H, "could you move the tv a bit to the left", ref([]), refuse=("missing", "tv"))
Q(H, "move the cat bed next to the sofa", ref([]), refuse=("missing", "cat"))

SUITE = {"name": "holdout5",
         "scenes": ["blender_hotel_room.json", "clinic_waiting_room.json", "home_office.json"],
         "variations": 1, "seed": 20270105, "queries": QUERIES}


def dump(path, obj):
    with open(os.path.join(HERE, path), "w") as f:
        json.dump(obj, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    for sc in SCENES.values():
        dump(sc["name"] + ".json", sc)
    dump("holdout5.suite.json", SUITE)
    print(len(QUERIES), "queries")
