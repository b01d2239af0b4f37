#!/usr/bin/env python3
"""Builds the holdout3 scenes and suite (stdlib only). Run: python3 build.py

Three new scenes, written blind (from SPEC.md only):
  blender_bedroom   - Blender-style names (Bed_Double, Lamp_Bedside.001, Plant_Pot.003 ...)
  ue_kitchen_diner  - Unity/Unreal-style names (SM_Chair_01..04, BP_Fridge, Stool_Bar.001 ...)
  plain_classroom   - plain lower-case names, no categories / aliases

Conventions used for every worked amount (SPEC 1-3):
  right = +X, left = -X, up = +Y, forward = +Z, back = -Z; metres.
  +90 deg about +Y takes +Z to +X; for a point (x, z) relative to the pivot a yaw of t gives
  x' = x cos t + z sin t,  z' = -x sin t + z cos t.  "clockwise" (seen from above) = negative.
  The pivot is the bottom centre of the box, so for a yaw-only rotation the pivot is also the
  bottom centre of the world AABB; `moved` deltas are pivot deltas.
  Things resting on a moved object move with it (by the same delta; for a rotation they turn
  about the support's pivot), unless the instruction holds them.
  1 ft = 0.3048 m, 1 in = 0.0254 m.
All boxes below are world AABBs worked out by hand; validate.py re-checks them.
"""
import json, os

HERE = os.path.dirname(os.path.abspath(__file__))
R90 = [0, 0.7071067812, 0, 0.7071067812]     # +90 deg about Y: front +Z -> +X
RM90 = [0, -0.7071067812, 0, 0.7071067812]   # -90 deg about Y: front +Z -> -X
R180 = [0, 1, 0, 0]                          # front +Z -> -Z


def o(name, size, pos, rot=None):
    d = {"name": name, "position": pos, "size": size}
    if rot is not None:
        d["rotation"] = rot
    return d


# ---------------------------------------------------------------- (a) Blender bedroom
# room x[-3,3] y[0,2.7] z[-2.5,2.5]; the bed's head is at the back wall (z = -2.5)
BEDROOM = {
    "name": "blender_bedroom",
    "bounds": {"min": [-3, 0, -2.5], "max": [3, 2.7, 2.5]},
    "objects": [
        o("Bed_Double", [1.6, 0.55, 2.1], [0, 0, -1.4]),              # x[-0.8,0.8] z[-2.45,-0.35] top 0.55
        o("Pillow.001", [0.6, 0.15, 0.4], [-0.4, 0.55, -2.15]),       # x[-0.7,-0.1] z[-2.35,-1.95] on bed
        o("Pillow.002", [0.6, 0.15, 0.4], [0.4, 0.55, -2.15]),        # x[0.1,0.7]
        o("Nightstand_L", [0.5, 0.55, 0.45], [-1.15, 0, -2.225]),     # x[-1.4,-0.9] z[-2.45,-2.0] top 0.55
        o("Nightstand_R", [0.5, 0.55, 0.45], [1.15, 0, -2.225]),      # x[0.9,1.4]
        o("Lamp_Bedside.001", [0.25, 0.45, 0.25], [-1.2, 0.55, -2.3]),  # x[-1.325,-1.075] z[-2.425,-2.175]
        o("Lamp_Bedside.002", [0.25, 0.45, 0.25], [1.2, 0.55, -2.3]),   # x[1.075,1.325]
        o("Alarm_Clock", [0.15, 0.1, 0.08], [0.99, 0.55, -2.12]),     # x[0.915,1.065] z[-2.16,-2.08] on NS_R
        o("Book_Red", [0.15, 0.03, 0.22], [-0.99, 0.55, -2.14]),      # x[-1.065,-0.915] z[-2.25,-2.03] on NS_L
        o("Wardrobe_Oak", [1.2, 2.0, 0.6], [-2.7, 0, 0.3], R90),      # x[-3,-2.4] z[-0.3,0.9], faces +X
        o("Rug_Round", [1.4, 0.01, 1.4], [0, 0, 0.6]),                # x[-0.7,0.7] z[-0.1,1.3]
        o("Desk_Pine", [1.2, 0.75, 0.6], [2.7, 0, 0.8], RM90),        # x[2.4,3] z[0.2,1.4] top 0.75, faces -X
        o("Laptop_Silver", [0.33, 0.02, 0.23], [2.7, 0.75, 0.75], RM90),  # x[2.585,2.815] z[0.585,0.915]
        o("Book_Blue", [0.15, 0.03, 0.22], [2.65, 0.75, 1.2]),        # x[2.575,2.725] z[1.09,1.31] on desk
        o("Chair_Desk", [0.5, 0.9, 0.5], [2.0, 0, 0.8], R90),         # x[1.75,2.25] z[0.55,1.05], faces desk
        o("Chair_Reading", [0.8, 0.9, 0.8], [-1.8, 0, 1.2], R90),     # x[-2.2,-1.4] z[0.8,1.6]
        o("Plant_Pot.003", [0.4, 1.0, 0.4], [2.7, 0, 2.2]),           # x[2.5,2.9] z[2.0,2.4]
        o("Dresser_White", [1.0, 0.8, 0.45], [0, 0, 2.25], R180),     # x[-0.5,0.5] z[2.025,2.475] top 0.8
        o("Jewelry_Box", [0.2, 0.1, 0.15], [0.3, 0.8, 2.25]),         # x[0.2,0.4] z[2.175,2.325]
        o("Photo_Frame", [0.2, 0.25, 0.05], [-0.3, 0.8, 2.3], R180),  # x[-0.4,-0.2] z[2.275,2.325]
        o("Plant_Pot.001", [0.15, 0.2, 0.15], [0, 0.8, 2.25]),        # x[-0.075,0.075] z[2.175,2.325]
        o("Laundry_Basket", [0.45, 0.5, 0.35], [-2.0, 0, 2.1]),       # x[-2.225,-1.775] z[1.925,2.275]
    ],
}

# ---------------------------------------------------------------- (b) UE/Unity kitchen-diner
# room x[-4,4] y[0,2.8] z[-3,3]; kitchen run on the back wall, dining table on the right
KITCHEN = {
    "name": "ue_kitchen_diner",
    "bounds": {"min": [-4, 0, -3], "max": [4, 2.8, 3]},
    "objects": [
        o("Counter_Back", [3.0, 0.9, 0.6], [-2.0, 0, -2.7]),          # x[-3.5,-0.5] z[-3,-2.4] top 0.9
        o("Kettle", [0.2, 0.25, 0.2], [-3.0, 0.9, -2.7]),             # x[-3.1,-2.9] z[-2.8,-2.6]
        o("Toaster", [0.3, 0.2, 0.18], [-2.4, 0.9, -2.7]),            # x[-2.55,-2.25] z[-2.79,-2.61]
        o("Mug_02", [0.12, 0.1, 0.09], [-1.8, 0.9, -2.6]),            # x[-1.86,-1.74] z[-2.645,-2.555]
        o("SM_Microwave", [0.5, 0.3, 0.4], [-1.2, 0.9, -2.7]),        # x[-1.45,-0.95] z[-2.9,-2.5]
        o("BP_Fridge", [0.8, 1.8, 0.7], [0.1, 0, -2.65]),             # x[-0.3,0.5] z[-3,-2.3]
        o("Bin_Pedal", [0.3, 0.45, 0.3], [0.9, 0, -2.8]),             # x[0.75,1.05] z[-2.95,-2.65]
        o("Counter_Island", [1.8, 0.9, 0.9], [-1.5, 0, -0.8]),        # x[-2.4,-0.6] z[-1.25,-0.35] top 0.9
        o("Bowl_Fruit", [0.3, 0.12, 0.3], [-1.9, 0.9, -0.8]),         # x[-2.05,-1.75] z[-0.95,-0.65]
        o("Mug_01", [0.12, 0.1, 0.09], [-1.45, 0.9, -0.6]),           # x[-1.51,-1.39] z[-0.645,-0.555]
        o("Plate_01", [0.26, 0.02, 0.26], [-1.0, 0.9, -0.8]),         # x[-1.13,-0.87] z[-0.93,-0.67]
        o("Stool_Bar.001", [0.4, 0.75, 0.4], [-2.0, 0, 0.0], R180),   # x[-2.2,-1.8] z[-0.2,0.2], faces island
        o("Stool_Bar.002", [0.4, 0.75, 0.4], [-1.0, 0, 0.0], R180),   # x[-1.2,-0.8]
        o("SM_DiningTable_01", [1.6, 0.75, 0.9], [2.0, 0, 0.5]),      # x[1.2,2.8] z[0.05,0.95] top 0.75
        o("Plate_02", [0.26, 0.02, 0.26], [1.6, 0.75, 0.5]),          # x[1.47,1.73] z[0.37,0.63]
        o("Vase_Flowers", [0.15, 0.35, 0.15], [2.0, 0.75, 0.5]),      # x[1.925,2.075] z[0.425,0.575]
        o("Glass_01", [0.08, 0.12, 0.08], [2.4, 0.75, 0.5]),          # x[2.36,2.44] z[0.46,0.54]
        o("SM_Chair_01", [0.45, 0.9, 0.5], [1.6, 0, -0.3]),           # x[1.375,1.825] z[-0.55,-0.05] back-left
        o("SM_Chair_02", [0.45, 0.9, 0.5], [2.4, 0, -0.3]),           # x[2.175,2.625] back-right
        o("SM_Chair_03", [0.45, 0.9, 0.5], [1.6, 0, 1.3], R180),      # z[1.05,1.55] front-left
        o("SM_Chair_04", [0.45, 0.9, 0.5], [2.4, 0, 1.3], R180),      # front-right
        o("SM_Sideboard_01", [1.6, 0.85, 0.45], [3.775, 0, 0.5], RM90),  # x[3.55,4] z[-0.3,1.3] top 0.85
        o("Lamp_Table", [0.3, 0.5, 0.3], [3.775, 0.85, 1.0]),         # x[3.625,3.925] z[0.85,1.15]
        o("Plant_Fern", [0.5, 1.2, 0.5], [3.6, 0, -2.6]),             # x[3.35,3.85] z[-2.85,-2.35]
    ],
}

# ---------------------------------------------------------------- (c) plain classroom
# room x[-4,4] y[0,3] z[-3.5,3.5]; the board stands at the back wall (z = -3.5)
CLASS = {
    "name": "plain_classroom",
    "bounds": {"min": [-4, 0, -3.5], "max": [4, 3, 3.5]},
    "objects": [
        o("whiteboard", [1.8, 1.9, 0.5], [0, 0, -3.2]),               # x[-0.9,0.9] z[-3.45,-2.95] (on a stand)
        o("teacher desk", [1.4, 0.75, 0.7], [-2.2, 0, -2.4]),         # x[-2.9,-1.5] z[-2.75,-2.05] top 0.75
        o("teacher chair", [0.55, 1.0, 0.55], [-2.2, 0, -3.1]),       # x[-2.475,-1.925] z[-3.375,-2.825]
        o("laptop", [0.33, 0.02, 0.23], [-2.4, 0.75, -2.4]),          # x[-2.565,-2.235] z[-2.515,-2.285]
        o("projector", [0.3, 0.12, 0.25], [-1.8, 0.75, -2.35]),       # x[-1.95,-1.65] z[-2.475,-2.225]
        o("mug", [0.1, 0.1, 0.08], [-2.75, 0.75, -2.2]),              # x[-2.8,-2.7] z[-2.24,-2.16]
        o("student desk 1", [1.0, 0.72, 0.6], [-2, 0, 0]),            # x[-2.5,-1.5] z[-0.3,0.3] top 0.72
        o("student desk 2", [1.0, 0.72, 0.6], [0, 0, 0]),             # x[-0.5,0.5]
        o("student desk 3", [1.0, 0.72, 0.6], [2, 0, 0]),             # x[1.5,2.5]
        o("chair 1", [0.45, 0.85, 0.45], [-2, 0, 0.75], R180),        # x[-2.225,-1.775] z[0.525,0.975]
        o("chair 2", [0.45, 0.85, 0.45], [0, 0, 0.75], R180),         # x[-0.225,0.225]
        o("chair 3", [0.45, 0.85, 0.45], [2, 0, 0.75], R180),         # x[1.775,2.225]
        o("textbook", [0.2, 0.03, 0.26], [-2.2, 0.72, 0.0]),          # x[-2.3,-2.1] z[-0.13,0.13] on desk 1
        o("pencil case", [0.2, 0.05, 0.08], [0.2, 0.72, 0.0]),        # x[0.1,0.3] z[-0.04,0.04] on desk 2
        o("exercise book", [0.17, 0.01, 0.24], [2.1, 0.72, 0.0]),     # x[2.015,2.185] z[-0.12,0.12] on desk 3
        o("bookcase", [1.0, 1.8, 0.35], [3.825, 0, -1.0], RM90),      # x[3.65,4] z[-1.5,-0.5] top 1.8
        o("globe", [0.35, 0.45, 0.35], [3.825, 1.8, -1.0]),           # x[3.65,4] z[-1.175,-0.825]
        o("waste bin", [0.3, 0.4, 0.3], [-3.6, 0, -1.0]),             # x[-3.75,-3.45] z[-1.15,-0.85]
        o("filing cabinet", [0.5, 1.3, 0.6], [-3.7, 0, 1.5], R90),    # x[-4,-3.4] z[1.25,1.75]
        o("plant", [0.4, 1.1, 0.4], [3.5, 0, 3.0]),                   # x[3.3,3.7] z[2.8,3.2]
        o("coat rack", [0.5, 1.8, 0.5], [-3.5, 0, 3.0]),              # x[-3.75,-3.25] z[2.75,3.25]
        o("cupboard", [1.2, 2.0, 0.5], [0, 0, 3.25], R180),           # x[-0.6,0.6] z[3,3.5] top 2.0
        o("speaker", [0.25, 0.35, 0.2], [0.3, 2.0, 3.25]),            # x[0.175,0.425] z[3.15,3.35]
    ],
}

# what rests on what (used to carry exact moves to the children)
ON = {
    "blender_bedroom": {"Pillow.001": "Bed_Double", "Pillow.002": "Bed_Double",
                        "Lamp_Bedside.001": "Nightstand_L", "Book_Red": "Nightstand_L",
                        "Lamp_Bedside.002": "Nightstand_R", "Alarm_Clock": "Nightstand_R",
                        "Laptop_Silver": "Desk_Pine", "Book_Blue": "Desk_Pine",
                        "Jewelry_Box": "Dresser_White", "Photo_Frame": "Dresser_White",
                        "Plant_Pot.001": "Dresser_White"},
    "ue_kitchen_diner": {"Kettle": "Counter_Back", "Toaster": "Counter_Back", "Mug_02": "Counter_Back",
                         "SM_Microwave": "Counter_Back", "Bowl_Fruit": "Counter_Island",
                         "Mug_01": "Counter_Island", "Plate_01": "Counter_Island",
                         "Plate_02": "SM_DiningTable_01", "Vase_Flowers": "SM_DiningTable_01",
                         "Glass_01": "SM_DiningTable_01", "Lamp_Table": "SM_Sideboard_01"},
    "plain_classroom": {"laptop": "teacher desk", "projector": "teacher desk", "mug": "teacher desk",
                        "textbook": "student desk 1", "pencil case": "student desk 2",
                        "exercise book": "student desk 3", "globe": "bookcase", "speaker": "cupboard"},
}

FT, IN = 0.3048, 0.0254

# ---------------------------------------------------------------- check helpers (SPEC 6 checks only)
def mv(obj, d, tol=None):
    c = {"check": "moved", "object": obj, "delta": [round(x, 4) for x in d]}
    mag = max(abs(x) for x in d)
    t = tol if tol is not None else (0.05 if mag == 0 or mag >= 0.15 else round(max(0.015, mag / 3), 3))
    if t != 0.05:
        c["tol"] = t
    return c

def still(obj):
    return mv(obj, [0, 0, 0])

def dr(obj, axis, mn=0.05):
    return {"check": "direction", "object": obj, "axis": axis, "min": mn}

def rot(obj, deg, either=False):
    c = {"check": "rotated", "object": obj, "axis": "+y", "degrees": deg}
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

def unch(objs):
    return {"check": "unchanged", "objects": objs}

def ref(m):
    return {"check": "refused", "mentions": m}

def swap(a, b, pa, pb):
    """a swap written as two pivot moves (pa, pb = the two pivots)"""
    return [mv(a, [pb[i] - pa[i] for i in range(3)]), mv(b, [pa[i] - pb[i] for i in range(3)])]

NC = {"check": "no_collision"}
IB = {"check": "inside_bounds"}

_scene = None

def carry(obj, d, hold=()):
    """moved checks for obj and everything resting on it (transitively), except held ones"""
    out = [mv(obj, d)]
    for child, sup in ON[_scene].items():
        if sup == obj and child not in hold:
            out += carry(child, d, hold)
    return out

def tops(sup):
    """on_top checks for everything resting on sup (used with vague moves of sup)"""
    return [top(c, s) for c, s in ON[_scene].items() if s == sup]

QUERIES = []
_count = {}
SHORT = {"blender_bedroom": "bed", "ue_kitchen_diner": "kit", "plain_classroom": "cls"}

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

# ================================================================ bedroom
_scene = "blender_bedroom"
# -- exact moves
# bed z[-2.45,-0.35] +0.2 -> z[-2.25,-0.15]; rug starts at z -0.1, clear. Pillows ride along.
Q(S, "move", "move the bed 20cm forward pls", *carry("Bed_Double", [0, 0, 0.2]))
# wardrobe z[-0.3,0.9] +0.4 -> z[0.1,1.3]; reading chair starts at x -2.2 > -2.4, clear
Q(S, "move", "hey could you shift the oak wardobe 40 cm forward", mv("Wardrobe_Oak", [0, 0, 0.4]))
# desk chair x[1.75,2.25] -0.5 -> x[1.25,1.75]; rug ends at x 0.7
Q(S, "move", "move the desk chair half a metre to the left", mv("Chair_Desk", [-0.5, 0, 0]))
# rug +1 ft = 0.3048 -> x[-0.3952,1.0048]; desk chair starts at x 1.75
Q(S, "move", "just move the round rug 1 ft to the right", mv("Rug_Round", [FT, 0, 0], 0.02))
# red book z[-2.25,-2.03] -0.1 -> z[-2.35,-2.13], still inside the nightstand top z[-2.45,-2.0]
Q(S, "move", "slide the red book 10cm towards the wall behind the bed", mv("Book_Red", [0, 0, -0.1]))
# basket +2 ft = 0.6096 -> x[-1.6154,-1.1654] z[1.925,2.275]; reading chair ends at z 1.6
Q(S, "move", "hey, move the laundry basket 2 feet to the right thx", mv("Laundry_Basket", [2 * FT, 0, 0], 0.02))
# plant x[2.5,2.9] -0.25 -> x[2.25,2.65]
Q(S, "move", "could u move the potted plant in the corner 25 cm to the left", mv("Plant_Pot.003", [-0.25, 0, 0]))
# dresser x[-0.5,0.5] -0.15 -> x[-0.65,0.35], carries jewelry box, photo frame, little plant
Q(S, "move", "push the dresser 15 centimetres to the left", *carry("Dresser_White", [-0.15, 0, 0]))
# reading chair z[0.8,1.6] +0.3 -> z[1.1,1.9]; basket starts at z 1.925 (2.5 cm gap)
Q(S, "move", "move the reading chiar 300 mm forward", mv("Chair_Reading", [0, 0, 0.3]))
# jewelry box x[0.2,0.4] -0.05 -> x[0.15,0.35]; little plant ends at x 0.075
Q(S, "move", "Nudge the jewelry box 5 cm left", mv("Jewelry_Box", [-0.05, 0, 0]))
# desk z[0.2,1.4] -0.2 -> z[0,1.2], carries laptop + blue book; chair ends at x 2.25 < 2.4
Q(S, "move", "move the pine desk 20cm back please", *carry("Desk_Pine", [0, 0, -0.2]))
# left lamp x[-1.325,-1.075] -0.05 -> x[-1.375,-1.125], still on the nightstand (x >= -1.4)
Q(S, "move", "mvoe the left bedside lamp 5 cm to the left", mv("Lamp_Bedside.001", [-0.05, 0, 0]))
# wardrobe +6 in = 0.1524 -> z[-0.1476,1.0524]
Q(S, "move", "shift the wardrobe 6 inches forward thx", mv("Wardrobe_Oak", [0, 0, 6 * IN], 0.02))
# plant z[2.0,2.4] -0.5 -> z[1.5,1.9]; desk ends at z 1.4
Q(S, "move", "move Plant_Pot.003 half a meter back", mv("Plant_Pot.003", [0, 0, -0.5]))
# desk chair -1.5 ft = -0.4572 -> z[0.0928,0.5928]
Q(S, "move", "would you mind moving the desk chair a foot and a half back", mv("Chair_Desk", [0, 0, -1.5 * FT], 0.02))
# alarm clock z[-2.16,-2.08] +0.05 -> z[-2.11,-2.03], still on the nightstand (z <= -2.0)
Q(S, "move", "move the alarm clock forward 5cm", mv("Alarm_Clock", [0, 0, 0.05]))
# -- rotations
# reading chair 0.8 square at 45 deg -> half extent 0.566: x[-2.366,-1.234] z[0.634,1.766]; wardrobe ends x -2.4
Q(S, "turn", "rotate the reading chair 45 degrees clockwise", rot("Chair_Reading", -45), still("Chair_Reading"))
Q(S, "turn", "turn the desk chair 180°", rot("Chair_Desk", 180, True), still("Chair_Desk"))
# laptop at -90-30 = -120 deg: half x 0.5*0.165+0.866*0.115 = 0.182, half z 0.866*0.165+0.5*0.115 = 0.200
#   -> x[2.518,2.882] z[0.55,0.95] inside the desk, clear of the blue book (z >= 1.09)
Q(S, "turn", "rotate the laptop 30° clockwise pls", rot("Laptop_Silver", -30), still("Laptop_Silver"))
# right nightstand +90 about its pivot (1.15,-2.225): box -> x[0.925,1.375] z[-2.475,-1.975]
#   lamp .002 rel (0.05,-0.075) -> (-0.075,-0.05): pos (1.075,-2.275), delta (-0.125,0,0.025)
#   clock rel (-0.16,0.105) -> (0.105,0.16): pos (1.255,-2.065), delta (0.265,0,0.055)
Q(H, "turn", "turn the right nightstand 90 degrees anticlockwise",
  rot("Nightstand_R", 90), still("Nightstand_R"),
  mv("Lamp_Bedside.002", [-0.125, 0, 0.025], 0.03), rot("Lamp_Bedside.002", 90),
  mv("Alarm_Clock", [0.265, 0, 0.055], 0.03), rot("Alarm_Clock", 90))
Q(H, "turn", "turn the desk chair so it faces the bed", faces("Chair_Desk", "Bed_Double"), still("Chair_Desk"))
# left pillow 0.6x0.4 turned 90 -> x[-0.6,-0.2] z[-2.45,-1.85], still on the bed
Q(H, "turn", "turn the left pillow 90 degrees", rot("Pillow.001", 90, True), still("Pillow.001"))
Q(H, "turn", "can you make the reading chair face the rug", faces("Chair_Reading", "Rug_Round"), still("Chair_Reading"))
# -- holds / negation
# dresser +0.1 -> x[-0.4,0.6]; photo frame x[-0.4,-0.2] stays and is still fully on it;
# jewelry box -> x[0.3,0.5], little plant -> x[0.025,0.175]
Q(C, "hold", "move the dresser 10cm to the right but leave the photo frame where it is",
  *carry("Dresser_White", [0.1, 0, 0], hold=("Photo_Frame",)), unch(["Photo_Frame"]))
# bed +0.1 -> z[-2.35,-0.25]; pillows z[-2.35,-1.95] stay, flush with the head end
Q(C, "hold", "shift the bed 10cm forward, don't touch the pillows",
  mv("Bed_Double", [0, 0, 0.1]), unch(["Pillow.001", "Pillow.002"]))
# desk +0.1 -> z[0.3,1.5]; laptop z[0.585,0.915] stays on it; blue book -> z[1.19,1.41]
Q(C, "hold", "move the desk 10 cm forward but leave the laptop where it is",
  *carry("Desk_Pine", [0, 0, 0.1], hold=("Laptop_Silver",)), unch(["Laptop_Silver"]))
# NS_R +0.05 -> x[0.95,1.45]; lamp .002 x[1.075,1.325] stays; clock -> x[0.965,1.115] (z clear of the lamp)
Q(C, "hold", "move the right nightstand 5 cm to the right, not the lamp on it",
  *carry("Nightstand_R", [0.05, 0, 0], hold=("Lamp_Bedside.002",)), unch(["Lamp_Bedside.002"]))
# lamp .002 -> z[-2.375,-2.125], clock -> z[-2.11,-2.03], both still on NS_R (z <= -2.0)
Q(C, "hold", "move everything on the right nightstand 5cm forward but not the nightstand itself",
  mv("Lamp_Bedside.002", [0, 0, 0.05]), mv("Alarm_Clock", [0, 0, 0.05]), unch(["Nightstand_R"]))
# NS_L -0.05 -> x[-1.45,-0.95]; red book x[-1.065,-0.915] stays (centre -0.99 still over it);
#   lamp .001 -> x[-1.375,-1.125], clear of the book (x >= -1.065)
Q(C, "hold", "move the left nightstand 5 cm to the left, leave the red book alone",
  *carry("Nightstand_L", [-0.05, 0, 0], hold=("Book_Red",)), unch(["Book_Red"]))
# -- multi / swaps / scale
# lamps at x -1.2 and 1.2 (same y, z): .001 +2.4, .002 -2.4
Q(C, "multi", "swap the two bedside lamps",
  *swap("Lamp_Bedside.001", "Lamp_Bedside.002", [-1.2, 0.55, -2.3], [1.2, 0.55, -2.3]))
Q(C, "multi", "move the desk chair 20cm left and turn it 90 degrees",
  mv("Chair_Desk", [-0.2, 0, 0]), rot("Chair_Desk", 90, True))
# jewelry -> x[0.25,0.45]; photo -> x[-0.45,-0.25]; both stay on the dresser
Q(C, "multi", "move the jewelry box 5cm right and the photo frame 5cm left",
  mv("Jewelry_Box", [0.05, 0, 0]), mv("Photo_Frame", [-0.05, 0, 0]))
# book (-0.99,0.55,-2.14) <-> clock (0.99,0.55,-2.12): book +1.98/+0.02, clock -1.98/-0.02
Q(C, "multi", "swap the red book and the alarm clock",
  *swap("Book_Red", "Alarm_Clock", [-0.99, 0.55, -2.14], [0.99, 0.55, -2.12]))
# rug x1.2 about its pivot -> 1.68: x[-0.84,0.84] z[-0.24,1.44]; bed ends z -0.35, chair starts x -1.4
Q(S, "scale", "scale the rug up by 20%", scl("Rug_Round", 1.2), still("Rug_Round"))
# plant x1.2 -> 0.48: x[2.46,2.94] z[1.96,2.44]
Q(S, "scale", "make Plant_Pot.003 20 percent bigger", scl("Plant_Pot.003", 1.2), still("Plant_Pot.003"))
# jewelry x1.5 -> 0.3x0.15x0.225: x[0.15,0.45] z[2.1375,2.3625], clear of the little plant
Q(S, "scale", "could you make the jewelry box 1.5x bigger", scl("Jewelry_Box", 1.5), still("Jewelry_Box"))
# -- placements
Q(F, "place", "put the alarm clock on the left nightstand", top("Alarm_Clock", "Nightstand_L"))
Q(F, "place", "put the red book on the desk next to the laptop", top("Book_Red", "Desk_Pine"), nxt("Book_Red", "Laptop_Silver"))
Q(F, "place", "put the little potted plant on the desk", top("Plant_Pot.001", "Desk_Pine"))
Q(F, "place", "put the laptop on the bed", top("Laptop_Silver", "Bed_Double"))
Q(F, "place", "put the reading chair next to the dresser", nxt("Chair_Reading", "Dresser_White"))
Q(F, "place", "move the laundry basket next to the wardrobe pls", nxt("Laundry_Basket", "Wardrobe_Oak"))
Q(F, "place", "put the photo frame on the left nightstand", top("Photo_Frame", "Nightstand_L"))
Q(H, "place", "put the blue book on the bed between the two pillows",
  top("Book_Blue", "Bed_Double"), btw("Book_Blue", "Pillow.001", "Pillow.002"))
Q(F, "place", "put the laundry basket to the left of the dresser", side("Laundry_Basket", "Dresser_White", "left"))
Q(F, "place", "put the jewelry box on the desk next to the blue book", top("Jewelry_Box", "Desk_Pine"), nxt("Jewelry_Box", "Book_Blue"))
Q(F, "place", "could you put the desk chair next to the bed", nxt("Chair_Desk", "Bed_Double"))
Q(H, "place", "move the reading chair between the bed and the wardrobe", btw("Chair_Reading", "Bed_Double", "Wardrobe_Oak"))
Q(F, "place", "I'd like the red book on the dresser", top("Book_Red", "Dresser_White"))
# -- refusals (ambiguous or missing)
Q(H, "refuse", "move the lamp 10cm to the right", ref(["Lamp_Bedside.001", "Lamp_Bedside.002"]))
Q(H, "refuse", "could you move the nighstand forward 5cm", ref(["Nightstand_L", "Nightstand_R"]))
Q(H, "refuse", "put the book on the bed", ref(["Book_Red", "Book_Blue"]))
Q(H, "refuse", "turn the pillow 90 degrees", ref(["Pillow.001", "Pillow.002"]))
Q(H, "refuse", "move the chair 30 cm closer to the bed", ref(["Chair_Desk", "Chair_Reading"]))
Q(H, "refuse", "put the plant on the nightstand", ref(["Plant_Pot.003", "Plant_Pot.001", "Nightstand_L", "Nightstand_R"]))
Q(H, "refuse", "move the TV 20cm left", ref([]))
Q(H, "refuse", "put the little plant on the windowsill", ref([]))
# NS_R +1 -> x[1.9,2.4]; the clock (x[0.915,1.065]) would be left in the air: contradictory
Q(H, "refuse", "move the right nightstand 1 m to the right but leave the alarm clock where it is",
  ref(["Nightstand_R", "Alarm_Clock"]))
# -- relational / ordinal references
# lamp .001 z -> [-2.375,-2.125]; the red book is clear in x
Q(H, "rel", "move the lamp on the left nightstand 5 cm forward", mv("Lamp_Bedside.001", [0, 0, 0.05]))
# blue book z[1.09,1.31] -0.1 -> z[0.99,1.21]; laptop ends z 0.915
Q(H, "rel", "move the book on the desk 10 cm back", mv("Book_Blue", [0, 0, -0.1]))
Q(H, "rel", "move the chair by the desk 30cm to the left", mv("Chair_Desk", [-0.3, 0, 0]))
# lamp .002 x[1.075,1.325] -0.05 -> x[1.025,1.275]; clock is clear in z
Q(H, "rel", "move the bedside lamp on the right 5cm to the left", mv("Lamp_Bedside.002", [-0.05, 0, 0]))
# Pillow.001 x[-0.7,-0.1] -0.1 -> x[-0.8,-0.2], still on the bed
Q(H, "rel", "move the pillow nearest the wardrobe 10 cm to the left", mv("Pillow.001", [-0.1, 0, 0]))
# basket centre (-2,2.1) towards dresser centre (0,2.25): direction (0.997,0.075); 20 cm -> (0.199,0.015)
Q(H, "rel", "move the laundry basket 20cm towards the dresser", mv("Laundry_Basket", [0.2, 0, 0.015]))
# bedside lamp 2 = Lamp_Bedside.002; +z 0.05 -> z[-2.375,-2.125]
Q(H, "rel", "move bedside lamp 2 5 cm forward", mv("Lamp_Bedside.002", [0, 0, 0.05]))
# -- walls, corners, flush
# basket x min -2.225 -> -3: delta -0.775
Q(H, "wall", "push the laundry basket all the way to the left wall", mv("Laundry_Basket", [-0.775, 0, 0]), IB)
# and z max 2.275 -> 2.5: +0.225
Q(H, "wall", "shove the laundry basket into the front left corner", mv("Laundry_Basket", [-0.775, 0, 0.225]), IB)
# reading chair x min -2.2 -> wardrobe face -2.4: -0.2 (they overlap in z [0.8,0.9])
Q(H, "wall", "move the reading chair flush against the wardrobe", mv("Chair_Reading", [-0.2, 0, 0], 0.03))
# desk chair x max 2.25 -> desk face 2.4: +0.15
Q(H, "wall", "push the desk chair right up against the desk", mv("Chair_Desk", [0.15, 0, 0], 0.03))
# bed z min -2.45 -> -2.5, pillows ride along
Q(H, "wall", "push the bed back against the wall", *carry("Bed_Double", [0, 0, -0.05]), IB)
# dresser x max 0.5 -> plant face 2.5 (they overlap in z [2.025,2.4]): +2.0, with its three items
Q(H, "wall", "slide the dresser to the right until it's flush against the big plant",
  *[dict(c, tol=0.03) for c in carry("Dresser_White", [2.0, 0, 0])])
# -- vague amounts (SPEC 5: "a bit")
Q(F, "vague", "move the reading chair a bit to the right", dr("Chair_Reading", "+x", 0.05))
Q(F, "vague", "nudge the bed a little forward", dr("Bed_Double", "+z", 0.02), *tops("Bed_Double"))
Q(F, "vague", "slide the laundry basket a bit towards the dresser", dr("Laundry_Basket", "+x", 0.05))
# -- compositional with relations
Q(CF, "combo", "put the alarm clock on the desk and turn the desk chair to face the bed",
  top("Alarm_Clock", "Desk_Pine"), faces("Chair_Desk", "Bed_Double"), still("Chair_Desk"))
Q(CF, "combo", "move the laptop onto the bed and put the red book next to it",
  top("Laptop_Silver", "Bed_Double"), top("Book_Red", "Bed_Double"), nxt("Book_Red", "Laptop_Silver"))
Q(CF, "combo", "put the photo frame on the desk and move the jewelry box 5 cm left",
  top("Photo_Frame", "Desk_Pine"), mv("Jewelry_Box", [-0.05, 0, 0]))

# ================================================================ kitchen-diner
_scene = "ue_kitchen_diner"
# table x[1.2,2.8] +0.2 -> x[1.4,3.0]; sideboard starts x 3.55; chairs clear in z
Q(S, "move", "move the dining table 20cm to the right", *carry("SM_DiningTable_01", [0.2, 0, 0]))
# fridge x[-0.3,0.5] +0.2 -> x[-0.1,0.7]; bin starts x 0.75
Q(S, "move", "hey can u move the frigde 20 cm to the right", mv("BP_Fridge", [0.2, 0, 0]))
# bowl z[-0.95,-0.65] +0.1 -> z[-0.85,-0.55], still on the island (z <= -0.35)
Q(S, "move", "shift the fruit bowl 10 cm forward", mv("Bowl_Fruit", [0, 0, 0.1]))
# island z[-1.25,-0.35] -0.25 -> z[-1.5,-0.6]; back counter ends z -2.4
Q(S, "move", "move the islnad 25 cm back", *carry("Counter_Island", [0, 0, -0.25]))
# stool .002 x[-1.2,-0.8] +0.3048 -> x[-0.8952,-0.4952]
Q(S, "move", "move Stool_Bar.002 1 ft to the right", mv("Stool_Bar.002", [FT, 0, 0], 0.02))
Q(S, "move", "move SM_Chair_03 20 cm forward", mv("SM_Chair_03", [0, 0, 0.2]))
# microwave x[-1.45,-0.95] -0.2 -> x[-1.65,-1.15]; mug 2 ends x -1.74
Q(S, "move", "would you mind moving the microwave 20cm to the left?", mv("SM_Microwave", [-0.2, 0, 0]))
# sideboard z[-0.3,1.3] -0.3 -> z[-0.6,1.0], lamp rides along
Q(S, "move", "pls move the sideboard 30cm back", *carry("SM_Sideboard_01", [0, 0, -0.3]))
Q(S, "move", "move the fern 40 cm to teh left", mv("Plant_Fern", [-0.4, 0, 0]))
# toaster +4 in = 0.1016 -> x[-2.4484,-2.1484]
Q(S, "move", "could you move the toaster 4 inches to the right", mv("Toaster", [4 * IN, 0, 0]))
# lamp z[0.85,1.15] +0.1 -> z[0.95,1.25], on the sideboard (z <= 1.3)
Q(S, "move", "maybe move the table lamp 10 cm forward?", mv("Lamp_Table", [0, 0, 0.1]))
# plate 1 x[-1.13,-0.87] -0.15 -> x[-1.28,-1.02]; mug 1 ends x -1.39
Q(S, "move", "move plate_01 15cm to the left", mv("Plate_01", [-0.15, 0, 0]))
# back counter x[-3.5,-0.5] -0.1 -> x[-3.6,-0.6], carries kettle, toaster, mug 2, microwave
Q(S, "move", "move Counter_Back 10 cm to the left", *carry("Counter_Back", [-0.1, 0, 0]))
# island x[-2.4,-0.6] -0.4 -> x[-2.8,-1.0] with bowl, mug 1, plate 1; stools clear in z
Q(S, "move", "move the island 40cm towards the left wall", *carry("Counter_Island", [-0.4, 0, 0]))
# -- rotations
# chair 2 -90: 0.45x0.5 -> x[2.15,2.65] z[-0.525,-0.075]
Q(S, "turn", "rotate SM_Chair_02 90 degrees clockwise", rot("SM_Chair_02", -90), still("SM_Chair_02"))
Q(S, "turn", "turn the table lamp 30 degrees anticlockwise", rot("Lamp_Table", 30), still("Lamp_Table"))
Q(H, "turn", "turn the second chair to face the fridge", faces("SM_Chair_02", "BP_Fridge"), still("SM_Chair_02"))
Q(H, "turn", "spin the left stool round so it faces the dining table", faces("Stool_Bar.001", "SM_DiningTable_01"), still("Stool_Bar.001"))
# -- holds
# table -0.15 -> x[1.05,2.65]; vase x[1.925,2.075] stays on it; plate 2 -> x[1.32,1.58], glass -> x[2.21,2.29]
Q(C, "hold", "move the dining table 15cm to the left but leave the vase where it is",
  *carry("SM_DiningTable_01", [-0.15, 0, 0], hold=("Vase_Flowers",)), unch(["Vase_Flowers"]))
# island -0.2 -> z[-1.45,-0.55]; bowl z[-0.95,-0.65] stays on it; mug 1 and plate 1 ride along
Q(C, "hold", "move the kitchen island 20 cm back but don't move the fruit bowl",
  *carry("Counter_Island", [0, 0, -0.2], hold=("Bowl_Fruit",)), unch(["Bowl_Fruit"]))
# counter -0.2 -> x[-3.7,-0.7]; microwave x[-1.45,-0.95] stays on it
Q(C, "hold", "shift the back counter 20cm left, not the microwave",
  *carry("Counter_Back", [-0.2, 0, 0], hold=("SM_Microwave",)), unch(["SM_Microwave"]))
# sideboard -0.1 -> z[-0.4,1.2]; lamp z[0.85,1.15] stays on it
Q(C, "hold", "move the sideboard 10cm back but leave the lamp",
  mv("SM_Sideboard_01", [0, 0, -0.1]), unch(["Lamp_Table"]))
Q(C, "hold", "I'd like the dining table moved 10 cm to the right, chairs stay where they are",
  *carry("SM_DiningTable_01", [0.1, 0, 0]), unch(["SM_Chair_01", "SM_Chair_02", "SM_Chair_03", "SM_Chair_04"]))
# -- multi / swaps / scale
# chairs 1,2 (behind the table, z -0.3) go -z, chairs 3,4 (in front, z 1.3) go +z
Q(C, "multi", "move all the chairs 10cm away from the table",
  mv("SM_Chair_01", [0, 0, -0.1]), mv("SM_Chair_02", [0, 0, -0.1]),
  mv("SM_Chair_03", [0, 0, 0.1]), mv("SM_Chair_04", [0, 0, 0.1]))
# kettle (-3.0) <-> toaster (-2.4), same y and z
Q(C, "multi", "swap the kettel and the toaster", *swap("Kettle", "Toaster", [-3.0, 0.9, -2.7], [-2.4, 0.9, -2.7]))
# bowl (-1.9) <-> plate 1 (-1.0) on the island
Q(C, "multi", "swap the fruit bowl and the plate on the island",
  *swap("Bowl_Fruit", "Plate_01", [-1.9, 0.9, -0.8], [-1.0, 0.9, -0.8]))
Q(C, "multi", "move stool 1 10cm left and stool 2 10cm right",
  mv("Stool_Bar.001", [-0.1, 0, 0]), mv("Stool_Bar.002", [0.1, 0, 0]))
# vase +0.2 -> x[2.125,2.275]; at 45 deg half 0.106 -> x[2.094,2.306]; glass starts x 2.36
Q(C, "multi", "move the vase 20cm right and turn it 45 degrees",
  mv("Vase_Flowers", [0.2, 0, 0]), rot("Vase_Flowers", 45, True))
# vase x2 -> 0.3 wide: x[1.85,2.15] z[0.35,0.65]; plate 2 ends 1.73, glass starts 2.36
Q(S, "scale", "double the size of the vase", scl("Vase_Flowers", 2.0), still("Vase_Flowers"))
# bowl x1.5 -> 0.45: x[-2.125,-1.675] z[-1.025,-0.575]; mug 1 starts x -1.51
Q(S, "scale", "make the fruit bowl 50% bigger", scl("Bowl_Fruit", 1.5), still("Bowl_Fruit"))
# -- placements
Q(F, "place", "put the kettle on the island", top("Kettle", "Counter_Island"))
Q(F, "place", "put the fruit bowl on the dining table", top("Bowl_Fruit", "SM_DiningTable_01"))
Q(CF, "place", "put the plate from the island on the dining table next to the vase",
  top("Plate_01", "SM_DiningTable_01"), nxt("Plate_01", "Vase_Flowers"))
Q(F, "place", "put the glass on the island next to the fruit bowl", top("Glass_01", "Counter_Island"), nxt("Glass_01", "Bowl_Fruit"))
Q(F, "place", "move SM_Chair_04 next to the sideboard", nxt("SM_Chair_04", "SM_Sideboard_01"))
Q(H, "place", "put the mug from the back counter on the dining table", top("Mug_02", "SM_DiningTable_01"))
Q(F, "place", "put the toaster next to the microwave", top("Toaster", "Counter_Back"), nxt("Toaster", "SM_Microwave"))
Q(F, "place", "put the bin next to the island", nxt("Bin_Pedal", "Counter_Island"))
Q(CF, "place", "put the kettle on the sideboard next to the lamp", top("Kettle", "SM_Sideboard_01"), nxt("Kettle", "Lamp_Table"))
Q(F, "place", "move stool 2 in front of the fridge", side("Stool_Bar.002", "BP_Fridge", "front"))
Q(F, "place", "put the glass to the left of the vase", top("Glass_01", "SM_DiningTable_01"), side("Glass_01", "Vase_Flowers", "left"))
Q(F, "place", "put the fruit bowl on the sidebaord thx", top("Bowl_Fruit", "SM_Sideboard_01"))
Q(H, "place", "put the mug that's on the island next to the kettle", top("Mug_01", "Counter_Back"), nxt("Mug_01", "Kettle"))
# -- refusals
Q(H, "refuse", "move the chair 20cm back", ref(["SM_Chair_01", "SM_Chair_02", "SM_Chair_03", "SM_Chair_04"]))
Q(H, "refuse", "put the plate on the sideboard", ref(["Plate_01", "Plate_02"]))
Q(H, "refuse", "turn the stool to face the island", ref(["Stool_Bar.001", "Stool_Bar.002"]))
Q(H, "refuse", "move the mug next to the kettle", ref(["Mug_01", "Mug_02"]))
Q(H, "refuse", "put the oven next to the fridge", ref([]))
Q(H, "refuse", "swap the chairs pls", ref(["SM_Chair_01", "SM_Chair_02", "SM_Chair_03", "SM_Chair_04"]))
# -- ordinal / relational
# chair nearest the fridge (0.1,-2.65): chair 1 at (1.6,-0.3) 2.79 m, chair 2 3.29 m, 3 and 4 further
Q(H, "rel", "could u just move the chair nearest the fridge 20 cm to the left", mv("SM_Chair_01", [-0.2, 0, 0]))
Q(H, "rel", "push the second chair 10cm to the right", mv("SM_Chair_02", [0.1, 0, 0]))
Q(H, "rel", "move the back left chair 15 cm back", mv("SM_Chair_01", [0, 0, -0.15]))
Q(H, "rel", "turn the front right chair 180 degrees", rot("SM_Chair_04", 180, True), still("SM_Chair_04"))
# left stool x[-2.2,-1.8] -0.2 -> x[-2.4,-2.0]
Q(H, "rel", "move the left stool 20 cm to the left", mv("Stool_Bar.001", [-0.2, 0, 0]))
# mug 1 z[-0.645,-0.555] -0.1 -> z[-0.745,-0.655]; bowl ends x -1.75, plate starts x -1.13
Q(H, "rel", "move the mug on the island 10 cm back", mv("Mug_01", [0, 0, -0.1]))
# chair opposite chair 2 (x 2.4, behind) = chair 4 (x 2.4, in front)
Q(H, "rel", "move the chair opposite the second chair 10cm forward", mv("SM_Chair_04", [0, 0, 0.1]))
# bin centre (0.9,-2.8) towards fridge centre (0.1,-2.65): (-0.8,0.15)/0.814 = (-0.983,0.184); 20 cm -> (-0.197,0.037)
#   bin -> x[0.553,0.853]; fridge ends x 0.5
Q(H, "rel", "move the bin 20 cm towards the fridge", mv("Bin_Pedal", [-0.197, 0, 0.037]))
Q(H, "rel", "move chair number 3 half a metre to the left", mv("SM_Chair_03", [-0.5, 0, 0]))
# -- walls / corners / flush
# fern x max 3.85 -> 4 (+0.15), z min -2.85 -> -3 (-0.15): back-right corner
Q(H, "wall", "push the fern into the corner", mv("Plant_Fern", [0.15, 0, -0.15]), IB)
# bin z min -2.95 -> -3
Q(H, "wall", "slide the pedal bin all the way back to the wall", mv("Bin_Pedal", [0, 0, -0.05], 0.017), IB)
# stool .002 z min -0.2 -> island face -0.35: -0.15
Q(H, "wall", "push stool 2 flush against the island", mv("Stool_Bar.002", [0, 0, -0.15], 0.03))
# stool .001 x min -2.2 -> -4: -1.8 (nothing in between in z[-0.2,0.2])
Q(H, "wall", "move the left stool all the way to the left wall", mv("Stool_Bar.001", [-1.8, 0, 0]), IB)
# chair 4 x max 2.625 -> sideboard face 3.55: +0.925
Q(H, "wall", "slide chair 4 right until it touches the sideboard", mv("SM_Chair_04", [0.925, 0, 0], 0.03))
# -- vague
Q(F, "vague", "move the fern a bit to the left", dr("Plant_Fern", "-x", 0.05))
Q(F, "vague", "scoot stool 1 a little to the right", dr("Stool_Bar.001", "+x", 0.03))
# -- compositional with relations
Q(CF, "combo", "put the fruit bowl on the dining table and move the vase a bit to the right",
  top("Bowl_Fruit", "SM_DiningTable_01"), dr("Vase_Flowers", "+x", 0.02))
Q(CF, "combo", "put the kettle on the island next to the fruit bowl", top("Kettle", "Counter_Island"), nxt("Kettle", "Bowl_Fruit"))
Q(CF, "combo", "move the first chair 10 cm back and put the glass on the sideboard",
  mv("SM_Chair_01", [0, 0, -0.1]), top("Glass_01", "SM_Sideboard_01"))

# ================================================================ classroom
_scene = "plain_classroom"
# whiteboard x[-0.9,0.9] +0.5 -> x[-0.4,1.4]
Q(S, "move", "can you move the whiteboard 50cm to the right? thanks!", mv("whiteboard", [0.5, 0, 0]))
# teacher desk x[-2.9,-1.5] +0.2 -> x[-2.7,-1.3], carries laptop, projector, mug
Q(S, "move", "move teacher desk 20cm to the right", *carry("teacher desk", [0.2, 0, 0]))
# desk 2 z[-0.3,0.3] -0.3 -> z[-0.6,0], pencil case rides along
Q(S, "move", "move student desk 2 30 cm back", *carry("student desk 2", [0, 0, -0.3]))
# chair 1 z[0.525,0.975] +0.3048 -> z[0.8298,1.2798]
Q(S, "move", "move chair 1 a foot forward", mv("chair 1", [0, 0, FT], 0.02))
# bookcase z[-1.5,-0.5] -0.25 -> z[-1.75,-0.75], globe rides along
Q(S, "move", "shift the bookcase 25 cm back", *carry("bookcase", [0, 0, -0.25]))
Q(S, "move", "move the wastebin 0.5m forward", mv("waste bin", [0, 0, 0.5]))
# plant x[3.3,3.7] -1 -> x[2.3,2.7]
Q(S, "move", "move the plnat 1 metre to the left please", mv("plant", [-1.0, 0, 0]))
# cupboard x[-0.6,0.6] +0.3 -> x[-0.3,0.9], speaker rides along
Q(S, "move", "I'd like the cupboard moved 30 cm to the right", *carry("cupboard", [0.3, 0, 0]))
# projector x[-1.95,-1.65] +0.1 -> x[-1.85,-1.55], on the desk (x <= -1.5)
Q(S, "move", "move the projector 10cm to the right", mv("projector", [0.1, 0, 0]))
Q(S, "move", "move the textbook 10cm to the right", mv("textbook", [0.1, 0, 0]))
# teacher chair x[-2.475,-1.925] -0.2 -> x[-2.675,-2.125]
Q(S, "move", "move the teachers chair 20cm to the left", mv("teacher chair", [-0.2, 0, 0]))
# filing cabinet z[1.25,1.75] +0.6096 -> z[1.8596,2.3596]; coat rack starts z 2.75
Q(S, "move", "move the filing cabinet 2 ft forward", mv("filing cabinet", [0, 0, 2 * FT], 0.02))
Q(S, "move", "could you move chair 3 a quarter of a metre to the right", mv("chair 3", [0.25, 0, 0]))
# -- rotations
# teacher desk 180 about its pivot (-2.2,-2.4): same box; children (x,z) -> (-x,-z) relative to the pivot
#   laptop rel (-0.2,0) -> (0.2,0): delta (0.4,0,0)
#   projector rel (0.4,0.05) -> (-0.4,-0.05): delta (-0.8,0,-0.1)
#   mug rel (-0.55,0.2) -> (0.55,-0.2): delta (1.1,0,-0.4)
Q(H, "turn", "turn the teacher desk around 180 degrees",
  rot("teacher desk", 180, True), still("teacher desk"),
  mv("laptop", [0.4, 0, 0], 0.03), rot("laptop", 180, True),
  mv("projector", [-0.8, 0, -0.1], 0.03), rot("projector", 180, True),
  mv("mug", [1.1, 0, -0.4], 0.03), rot("mug", 180, True))
Q(S, "turn", "turn chair 2 90 degress clockwise", rot("chair 2", -90), still("chair 2"))
# projector centre (-1.8,-2.35) to board centre (0,-3.2): yaw ~115 deg; box x[-1.977,-1.623] z[-2.539,-2.161]
Q(H, "turn", "point the projector at the whiteboard", faces("projector", "whiteboard"), still("projector"))
Q(H, "turn", "turn chair 3 so it faces the teacher desk", faces("chair 3", "teacher desk"), still("chair 3"))
# teacher chair 0.55 at 15 deg: half 0.275*(0.966+0.259) = 0.337 -> z max -2.763 < desk face -2.75
Q(S, "turn", "rotate the teacher chair 15 degrees counterclockwise", rot("teacher chair", 15), still("teacher chair"))
# -- holds
# desk 1 x[-2.5,-1.5] -0.2 -> x[-2.7,-1.7]; textbook x[-2.3,-2.1] stays on it
Q(C, "hold", "move student desk 1 20cm left but leave the textbook where it is",
  mv("student desk 1", [-0.2, 0, 0]), unch(["textbook"]))
# bookcase z -> [-1.3,-0.3]; globe z[-1.175,-0.825] stays on it
Q(C, "hold", "move the bookcase 20cm foward, keep the globe where it is",
  mv("bookcase", [0, 0, 0.2]), unch(["globe"]))
# desk -> x[-2.8,-1.4]; projector x[-1.95,-1.65] stays; laptop -> x[-2.465,-2.135], mug -> x[-2.7,-2.6]
Q(C, "hold", "move the teacher desk 10 cm right but don't touch the projector",
  *carry("teacher desk", [0.1, 0, 0], hold=("projector",)), unch(["projector"]))
# desk 2 -> x[0,1.0]; desk 3 starts 1.5; chair 2 stays (clear in z)
Q(C, "hold", "move student desk 2 half a metre to the right, don't touch chair 2",
  *carry("student desk 2", [0.5, 0, 0]), unch(["chair 2"]))
# cupboard -0.15 -> x[-0.75,0.45]; speaker x[0.175,0.425] stays on it
Q(C, "hold", "move the cupboard 15cm left but leave the speaker",
  mv("cupboard", [-0.15, 0, 0]), unch(["speaker"]))
# -- multi / swaps / scale
# laptop (-2.4,-2.4) <-> projector (-1.8,-2.35)
Q(C, "multi", "swap the laptop and the projector",
  *swap("laptop", "projector", [-2.4, 0.75, -2.4], [-1.8, 0.75, -2.35]))
# globe (3.825,1.8,-1.0) <-> speaker (0.3,2.0,3.25)
Q(C, "multi", "swap the globe and the speaker",
  *swap("globe", "speaker", [3.825, 1.8, -1.0], [0.3, 2.0, 3.25]))
Q(S, "scale", "make the globe 25% smaller", scl("globe", 0.75), still("globe"))
# plant x1.5 -> 0.6: x[3.2,3.8] z[2.7,3.3]
Q(S, "scale", "scale the plant up 1.5 times", scl("plant", 1.5), still("plant"))
# -- placements
Q(F, "place", "put the mug on student desk 3", top("mug", "student desk 3"))
Q(F, "place", "put the projector on student desk 2", top("projector", "student desk 2"))
Q(F, "place", "put the waste bin next to the teacher desk", nxt("waste bin", "teacher desk"))
Q(F, "place", "put the globe on top of the cuboard", top("globe", "cupboard"))
Q(F, "place", "put the speaker on the teacher desk", top("speaker", "teacher desk"))
Q(F, "place", "put the plant next to the whiteboard", nxt("plant", "whiteboard"))
Q(H, "place", "put chair 2 between student desk 1 and student desk 2",
  btw("chair 2", "student desk 1", "student desk 2"))
Q(F, "place", "put the textbook on the teacher desk next to the laptop", top("textbook", "teacher desk"), nxt("textbook", "laptop"))
Q(F, "place", "move the waste bin to the right of the teacher desk", side("waste bin", "teacher desk", "right"))
Q(F, "place", "put the exercise book on top of the textbook", top("exercise book", "textbook"))
Q(F, "place", "put the mug on the bookcase next to the globe", top("mug", "bookcase"), nxt("mug", "globe"))
# -- refusals
Q(H, "refuse", "move the desk 20cm to the left",
  ref(["teacher desk", "student desk 1", "student desk 2", "student desk 3"]))
Q(H, "refuse", "turn the chair around", ref(["chair 1", "chair 2", "chair 3", "teacher chair"]))
Q(H, "refuse", "put the book on the teacher desk", ref(["textbook", "exercise book"]))
Q(H, "refuse", "move the student desk forward 10cm", ref(["student desk 1", "student desk 2", "student desk 3"]))
Q(H, "refuse", "put the laptop next to the printer", ref([]))
# desk +1 -> x[-1.9,-0.5]; the mug (x[-2.8,-2.7]) would be left in the air: contradictory
Q(H, "refuse", "move the teacher desk 1m to the right but leave the mug where it is", ref(["teacher desk", "mug"]))
# -- ordinal / relational
Q(H, "rel", "move the chair at student desk 3 10cm to the right", mv("chair 3", [0.1, 0, 0]))
Q(H, "rel", "move the desk with the pencil case on it 10 cm left", *carry("student desk 2", [-0.1, 0, 0]))
Q(H, "rel", "move the thing on top of the cupboard 10 cm left", mv("speaker", [-0.1, 0, 0]))
Q(H, "rel", "move the leftmost student desk 20 cm to the left", *carry("student desk 1", [-0.2, 0, 0]))
Q(H, "rel", "move the middle chair 20 cm forward", mv("chair 2", [0, 0, 0.2]))
# chair nearest the coat rack (-3.5,3.0): chair 1 at (-2,0.75) is 2.70 m away; the others are further
Q(H, "rel", "move the chair nearest the coat rack 20cm to the left", mv("chair 1", [-0.2, 0, 0]))
# cabinet centre (-3.7,1.5) towards rack centre (-3.5,3.0): (0.2,1.5)/1.513; 30 cm -> (0.040,0.297)
Q(H, "rel", "move the filing cabinet 30cm towards the coat rack", mv("filing cabinet", [0.04, 0, 0.297]))
# -- walls / corners / flush
# coat rack x min -3.75 -> -4 (-0.25), z max 3.25 -> 3.5 (+0.25): front-left corner
Q(H, "wall", "push the coat rack into the corner", mv("coat rack", [-0.25, 0, 0.25]), IB)
# plant x max 3.7 -> 4
Q(H, "wall", "push the plant all the way to the right wall", mv("plant", [0.3, 0, 0]), IB)
# whiteboard z min -3.45 -> -3.5
Q(H, "wall", "move the whiteboard back against the wall", mv("whiteboard", [0, 0, -0.05], 0.017), IB)
# bin z max -0.85 -> cabinet face 1.25 (they overlap in x [-3.75,-3.45]): +2.1
Q(H, "wall", "slide the waste bin forward until it's flush against the filing cabinet", mv("waste bin", [0, 0, 2.1], 0.03))
# teacher desk -0.4 -> x[-3.3,-1.9] with its three items; teacher chair and bin clear in z
Q(S, "move", "move the teacher desk 40cm towards the left wall", *carry("teacher desk", [-0.4, 0, 0]))
# -- vague
Q(F, "vague", "move the plant a bit to the left", dr("plant", "-x", 0.05))
Q(F, "vague", "push chair 2 forward a bit", dr("chair 2", "+z", 0.05))
# -- compositional with relations
Q(CF, "combo", "move the textbook onto student desk 2 and the pencil case onto student desk 1",
  top("textbook", "student desk 2"), top("pencil case", "student desk 1"))
Q(CF, "combo", "put the globe on student desk 3 and turn chair 3 90 degrees",
  top("globe", "student desk 3"), rot("chair 3", 90, True), still("chair 3"))
Q(CF, "combo", "put the mug next to the projector and slide the laptop 10cm to the left",
  top("mug", "teacher desk"), nxt("mug", "projector"), mv("laptop", [-0.1, 0, 0]))

SUITE = {"name": "holdout3",
         "scenes": ["blender_bedroom.json", "ue_kitchen_diner.json", "plain_classroom.json"],
         "variations": 1, "seed": 20261217, "queries": QUERIES}

def dump(path, obj):
    with open(os.path.join(HERE, path), "w") as f:
        json.dump(obj, f, indent=1)
        f.write("\n")

if __name__ == "__main__":
    for sc in (BEDROOM, KITCHEN, CLASS):
        dump(sc["name"] + ".json", sc)
    dump("holdout3.suite.json", SUITE)
    print(len(QUERIES), "queries")
