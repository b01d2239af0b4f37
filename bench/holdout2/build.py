#!/usr/bin/env python3
"""Builds the holdout2 scenes and suite (stdlib only). Run: python3 build.py
Every amount below was worked out by hand; validate.py re-checks the geometry."""
import json, os

HERE = os.path.dirname(os.path.abspath(__file__))
R90 = [0, 0.7071067812, 0, 0.7071067812]     # +90 deg about Y: front +Z -> +X
RM90 = [0, -0.7071067812, 0, 0.7071067812]   # -90 deg about Y: front +Z -> -X
R180 = [0, 1, 0, 0]


def o(name, size, pos, rot=None):
    d = {"name": name, "position": pos, "size": size}
    if rot is not None:
        d["rotation"] = rot
    return d


LOUNGE = {
    "name": "ue_lounge",
    "bounds": {"min": [-3.5, 0, -3], "max": [3.5, 2.8, 3]},
    "objects": [
        o("SM_Sofa_01", [2.2, 0.85, 0.95], [0, 0, -2.4]),
        o("Cushion_Red", [0.45, 0.45, 0.15], [-0.55, 0.85, -2.45]),
        o("Cushion_Blue", [0.45, 0.45, 0.15], [0.55, 0.85, -2.45]),
        o("SideTable_L", [0.5, 0.55, 0.5], [-1.5, 0, -2.45]),
        o("SideTable_R", [0.5, 0.55, 0.5], [1.5, 0, -2.45]),
        o("Lamp_Table", [0.3, 0.5, 0.3], [-1.58, 0.55, -2.53]),
        o("Speaker_Smart", [0.1, 0.15, 0.1], [1.6, 0.55, -2.55]),
        o("Rug_Large", [2.4, 0.01, 1.6], [0, 0, -0.9]),
        o("SM_CoffeeTable", [1.2, 0.42, 0.6], [0, 0.01, -0.9]),
        o("Remote_TV", [0.05, 0.02, 0.18], [0.35, 0.43, -0.85]),
        o("Magazine_Stack", [0.3, 0.05, 0.22], [-0.35, 0.43, -0.95]),
        o("Mug_Coffee", [0.12, 0.1, 0.09], [0.05, 0.43, -1.0]),
        o("TV_Stand", [2.0, 0.5, 0.45], [0, 0, 2.7], R180),
        o("TV_65in", [1.45, 0.88, 0.28], [0, 0.5, 2.72], R180),
        o("Shelf_Wall.002", [1.2, 0.03, 0.25], [-3.375, 1.4, -0.5], R90),
        o("Book.001", [0.04, 0.24, 0.17], [-3.375, 1.43, -0.9], R90),
        o("Book.002", [0.05, 0.28, 0.2], [-3.375, 1.43, -0.75], R90),
        o("Book.003", [0.03, 0.22, 0.16], [-3.375, 1.43, -0.6], R90),
        o("Lamp_Floor", [0.4, 1.7, 0.4], [-2.9, 0, -2.5]),
        o("Plant_Monstera", [0.6, 1.3, 0.6], [2.95, 0, -2.45]),
        o("SM_Armchair_01", [0.85, 0.9, 0.85], [-2.2, 0, 0.8], R90),
        o("Pouf_Grey", [0.5, 0.4, 0.5], [1.9, 0, 0.6]),
        o("Window_01", [1.6, 1.4, 0.1], [3.45, 0.9, 0.8], RM90),
    ],
}

CAFE = {
    "name": "cafe_tables",
    "bounds": {"min": [-5, 0, -4], "max": [5, 3, 4]},
    "objects": [
        o("Counter_Main", [2.4, 1.05, 0.75], [-3.2, 0, -3.6]),
        o("CoffeeMachine_01", [0.55, 0.5, 0.45], [-4.0, 1.05, -3.65]),
        o("Grinder_01", [0.2, 0.42, 0.3], [-3.5, 1.05, -3.7]),
        o("Till_POS", [0.35, 0.3, 0.35], [-2.5, 1.05, -3.55]),
        o("TipJar", [0.12, 0.18, 0.12], [-2.15, 1.05, -3.4]),
        o("Menu_Board", [1.2, 0.8, 0.04], [-3.2, 1.9, -3.98]),
        o("Table_Round.000", [0.8, 0.75, 0.8], [-2.5, 0, 0]),
        o("Table_Round.001", [0.8, 0.75, 0.8], [0, 0, 0]),
        o("Table_Round.002", [0.8, 0.75, 0.8], [2.5, 0, 0]),
        o("Plate.000", [0.26, 0.02, 0.26], [-2.7, 0.75, -0.05]),
        o("Cup.000", [0.12, 0.09, 0.09], [-2.3, 0.75, 0.1]),
        o("Plate.001", [0.26, 0.02, 0.26], [-0.2, 0.75, -0.05]),
        o("Cup.001", [0.12, 0.09, 0.09], [0.2, 0.75, 0.1]),
        o("Plate.002", [0.26, 0.02, 0.26], [2.3, 0.75, -0.05]),
        o("Cup.002", [0.12, 0.09, 0.09], [2.7, 0.75, 0.1]),
        o("Cup.003", [0.12, 0.09, 0.09], [2.45, 0.75, 0.2]),
        o("Chair.000", [0.45, 0.85, 0.5], [-2.5, 0, -0.75]),
        o("Chair.001", [0.45, 0.85, 0.5], [-2.5, 0, 0.75], R180),
        o("Chair.002", [0.45, 0.85, 0.5], [0, 0, -0.75]),
        o("Chair.003", [0.45, 0.85, 0.5], [0, 0, 0.75], R180),
        o("Chair.004", [0.45, 0.85, 0.5], [2.5, 0, -0.75]),
        o("Chair.005", [0.45, 0.85, 0.5], [2.5, 0, 0.75], R180),
        o("Chair.006", [0.45, 0.85, 0.5], [-3.25, 0, 0], R90),
        o("Chair.007", [0.45, 0.85, 0.5], [3.25, 0, 0], RM90),
        o("Bench_Window", [2.0, 0.45, 0.5], [0, 0, 3.5]),
        o("Window_Shopfront", [6.0, 1.8, 0.1], [0, 0.6, 3.95], R180),
        o("Plant_Pot.001", [0.5, 1.4, 0.5], [4.6, 0, -3.6]),
        o("Bin_Waste", [0.35, 0.6, 0.35], [-1.6, 0, -3.7]),
    ],
}

STUDY = {
    "name": "study_desk",
    "bounds": {"min": [-2.5, 0, -2], "max": [2.5, 2.7, 2]},
    "objects": [
        o("Desk_Oak", [1.4, 0.75, 0.7], [0, 0, -1.6]),
        o("Laptop_Pro", [0.34, 0.23, 0.25], [0, 0.75, -1.55]),
        o("DeskLamp", [0.16, 0.45, 0.2], [-0.55, 0.75, -1.8]),
        o("Notebook_A5", [0.15, 0.015, 0.21], [0.42, 0.75, -1.38]),
        o("Mug.001", [0.12, 0.1, 0.09], [0.6, 0.75, -1.6]),
        o("PenHolder", [0.08, 0.11, 0.08], [0.6, 0.75, -1.85]),
        o("OfficeChair", [0.62, 1.05, 0.62], [0, 0, -0.75], R90),
        o("Bookcase_Tall", [0.8, 1.9, 0.35], [-2.325, 0, -0.3], R90),
        o("Globe", [0.3, 0.4, 0.3], [-2.325, 1.9, -0.3]),
        o("FilingCabinet", [0.45, 0.7, 0.6], [1.1, 0, -1.65]),
        o("Plant_Succulent", [0.12, 0.15, 0.12], [1.2, 0.7, -1.75]),
        o("Cabinet_Small", [0.5, 0.6, 0.45], [2.0, 0, -1.7]),
        o("Printer_Laser", [0.42, 0.25, 0.38], [2.0, 0.6, -1.7]),
        o("Whiteboard", [1.2, 0.9, 0.03], [0, 1.3, -1.985]),
        o("Bin_Paper", [0.28, 0.35, 0.28], [0.95, 0, -0.9]),
        o("Window.001", [1.4, 1.3, 0.1], [2.45, 0.9, -0.75], RM90),
    ],
}

# what rests on what (support of each resting object), used to carry moves
ON = {
    "ue_lounge": {"Cushion_Red": "SM_Sofa_01", "Cushion_Blue": "SM_Sofa_01",
                  "Lamp_Table": "SideTable_L", "Speaker_Smart": "SideTable_R",
                  "SM_CoffeeTable": "Rug_Large", "Remote_TV": "SM_CoffeeTable",
                  "Magazine_Stack": "SM_CoffeeTable", "Mug_Coffee": "SM_CoffeeTable",
                  "TV_65in": "TV_Stand", "Book.001": "Shelf_Wall.002",
                  "Book.002": "Shelf_Wall.002", "Book.003": "Shelf_Wall.002"},
    "cafe_tables": {"CoffeeMachine_01": "Counter_Main", "Grinder_01": "Counter_Main",
                    "Till_POS": "Counter_Main", "TipJar": "Counter_Main",
                    "Plate.000": "Table_Round.000", "Cup.000": "Table_Round.000",
                    "Plate.001": "Table_Round.001", "Cup.001": "Table_Round.001",
                    "Plate.002": "Table_Round.002", "Cup.002": "Table_Round.002",
                    "Cup.003": "Table_Round.002"},
    "study_desk": {"Laptop_Pro": "Desk_Oak", "DeskLamp": "Desk_Oak",
                   "Notebook_A5": "Desk_Oak", "Mug.001": "Desk_Oak",
                   "PenHolder": "Desk_Oak", "Globe": "Bookcase_Tall",
                   "Plant_Succulent": "FilingCabinet", "Printer_Laser": "Cabinet_Small"},
}

# ---------------------------------------------------------------- check helpers
def mv(obj, d, tol=None):
    c = {"check": "moved", "object": obj, "delta": d}
    mag = max(abs(x) for x in d)
    t = tol if tol is not None else (0.05 if mag == 0 or mag >= 0.15 else round(max(0.015, mag / 3), 3))
    if t != 0.05:
        c["tol"] = t
    return c

def dr(obj, axis, mn=0.05):
    return {"check": "direction", "object": obj, "axis": axis, "min": mn}

def rot(obj, deg, either=False):
    c = {"check": "rotated", "object": obj, "degrees": deg}
    if either:
        c["either_sign"] = True
    return c

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

def swp(a, b):
    return {"check": "swapped", "object": a, "other": b}

def ref(m):
    return {"check": "refused", "mentions": m}

NC = {"check": "no_collision"}
IB = {"check": "inside_bounds"}

_scene = None

def carry(obj, d, hold=()):
    """moved checks for obj and everything resting on it (transitively), except held ones"""
    out = [mv(obj, d)]
    on = ON[_scene]
    for child, sup in on.items():
        if sup == obj and child not in hold:
            out += carry(child, d, hold)
    return out

QUERIES = []
_count = {}

def Q(cat, fam, text, *checks, others=True):
    checks = list(checks)
    if not any(c["check"] == "refused" for c in checks) and others:
        checks.append(unch("others"))
    key = (_scene, fam)
    _count[key] = _count.get(key, 0) + 1
    short = {"ue_lounge": "lounge", "cafe_tables": "cafe", "study_desk": "study"}[_scene]
    QUERIES.append({"id": f"{short}-{fam}-{_count[key]:02d}", "category": cat,
                    "text": text, "scenes": [_scene], "expect": checks})

# ================================================================ lounge
_scene = "ue_lounge"
S, C, F, CF, H = "simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"
# exact moves
Q(S, "move", "move the cofee table 30cm towards the tv", *carry("SM_CoffeeTable", [0, 0, 0.3]), NC)
Q(S, "move", "hey could u shift the sofa 20 cm forward pls", *carry("SM_Sofa_01", [0, 0, 0.2]), NC)
Q(S, "move", "Move the floor lamp 50 cm to the right, thanks!", mv("Lamp_Floor", [0.5, 0, 0]), NC)
Q(S, "move", "could you raise the wall shelf by 10cm", *carry("Shelf_Wall.002", [0, 0.1, 0]), NC)
Q(S, "move", "the pouf needs to go 2 feet to the left", mv("Pouf_Grey", [-0.6096, 0, 0], 0.02), NC)
Q(S, "move", "nudge the red cusion 10cm to the left", mv("Cushion_Red", [-0.1, 0, 0]), top("Cushion_Red", "SM_Sofa_01"), NC)
Q(S, "move", "can you move the plant forward 40cm", mv("Plant_Monstera", [0, 0, 0.4]), NC)
Q(S, "move", "pull the armchair 1 m towards the window", mv("SM_Armchair_01", [1, 0, 0]), NC)
Q(S, "move", "shift TV_Stand 15 cm left", *carry("TV_Stand", [-0.15, 0, 0]), NC)
Q(S, "move", "move the 65 inch tv 20cm to the right please", mv("TV_65in", [0.2, 0, 0]), top("TV_65in", "TV_Stand"), NC)
Q(S, "move", "move the magazine stack 10 cm closer to the sofa pls", mv("Magazine_Stack", [0, 0, -0.1]), NC)
Q(S, "move", "move the tv remote 6 inches left", mv("Remote_TV", [-0.1524, 0, 0], 0.02), NC)
Q(S, "move", "slide the coffee mug 15cm to the right", mv("Mug_Coffee", [0.15, 0, 0]), NC)
Q(S, "move", "move the smart speaker 5cm towards the sofa", mv("Speaker_Smart", [-0.05, 0, 0]), NC)
Q(H, "move", "I'd like the rug moved 50 cm to the right", *carry("Rug_Large", [0.5, 0, 0]), NC)
Q(S, "move", "move the armchair 3 feet forward", mv("SM_Armchair_01", [0, 0, 0.9144], 0.03), NC)
Q(S, "move", "the wall shelf is too high, lower it 20cm", *carry("Shelf_Wall.002", [0, -0.2, 0]), NC)
Q(S, "move", "Cushion_Blue: move it 15 cm to the right", mv("Cushion_Blue", [0.15, 0, 0]), top("Cushion_Blue", "SM_Sofa_01"), NC)
Q(S, "move", "move the pouf 20 cm towards the window", mv("Pouf_Grey", [0.2, 0, 0]), NC)
Q(F, "move", "push the armchair right up against the left wall", mv("SM_Armchair_01", [-0.875, 0, 0]), NC, IB)
Q(F, "move", "push the pouf all the way to the right wall", mv("Pouf_Grey", [1.35, 0, 0]), NC, IB)
# rotations
Q(S, "turn", "rotate the armchair 45 degrees clockwise seen from above", rot("SM_Armchair_01", -45), mv("SM_Armchair_01", [0, 0, 0]), NC)
Q(S, "turn", "turn the pouf 90 degrees", rot("Pouf_Grey", 90, True), mv("Pouf_Grey", [0, 0, 0]), NC)
Q(H, "turn", "turn the coffee table 90 degrees counterclockwise (seen from above)",
  rot("SM_CoffeeTable", 90), mv("SM_CoffeeTable", [0, 0, 0]),
  mv("Remote_TV", [-0.3, 0, -0.4], 0.03), rot("Remote_TV", 90),
  mv("Magazine_Stack", [0.3, 0, 0.4], 0.03), rot("Magazine_Stack", 90),
  mv("Mug_Coffee", [-0.15, 0, 0.05], 0.03), rot("Mug_Coffee", 90), NC)
Q(H, "turn", "can you turn the armchair to face the TV", faces("SM_Armchair_01", "TV_65in"), mv("SM_Armchair_01", [0, 0, 0]), NC)
Q(S, "turn", "spin the floor lamp 180°", rot("Lamp_Floor", 180, True), mv("Lamp_Floor", [0, 0, 0]))
Q(H, "turn", "turn the pouf so it faces the sofa", faces("Pouf_Grey", "SM_Sofa_01"), mv("Pouf_Grey", [0, 0, 0]), NC)
Q(S, "turn", "rotate the plant 30 degrees anticlockwise pls", rot("Plant_Monstera", 30), mv("Plant_Monstera", [0, 0, 0]), NC)
# holds
Q(C, "hold", "move the coffee table 20 cm closer to the sofa but leave the remote where it is",
  *carry("SM_CoffeeTable", [0, 0, -0.2], hold=("Remote_TV",)), unch(["Remote_TV"]), NC)
Q(C, "hold", "shift the sofa 10cm forward, don't touch the cushions",
  mv("SM_Sofa_01", [0, 0, 0.1]), unch(["Cushion_Red", "Cushion_Blue"]), NC)
Q(C, "hold", "move the tv stand 20cm to the left but keep the tv where it is",
  mv("TV_Stand", [-0.2, 0, 0]), unch(["TV_65in"]), NC)
Q(C, "hold", "move the armchair half a metre to the right, leave the rug alone",
  mv("SM_Armchair_01", [0.5, 0, 0]), unch(["Rug_Large"]), NC)
Q(S, "hold", "i'd like the pouf moved 40cm back, but don't move anything else", mv("Pouf_Grey", [0, 0, -0.4]), NC)
# compositional
Q(C, "multi", "move the pouf 30 cm back and rotate it 45 degrees", mv("Pouf_Grey", [0, 0, -0.3]), rot("Pouf_Grey", 45, True), NC)
Q(C, "multi", "move the floor lamp 40cm right and the plant 30cm left", mv("Lamp_Floor", [0.4, 0, 0]), mv("Plant_Monstera", [-0.3, 0, 0]), NC)
Q(C, "multi", "swap the red and blue cushions thx", swp("Cushion_Red", "Cushion_Blue"), NC)
Q(C, "multi", "move both side tables 10 cm outwards, away from the sofa",
  *carry("SideTable_L", [-0.1, 0, 0]), *carry("SideTable_R", [0.1, 0, 0]), NC)
Q(C, "multi", "move the remote 10cm right and the mug 10cm left", mv("Remote_TV", [0.1, 0, 0]), mv("Mug_Coffee", [-0.1, 0, 0]), NC)
Q(C, "multi", "move the tv 10cm left and turn it 10 degrees counterclockwise",
  mv("TV_65in", [-0.1, 0, 0]), rot("TV_65in", 10), NC, IB)
# fuzzy moves
Q(F, "vague", "move the armchair a bit closer to the window", dr("SM_Armchair_01", "+x", 0.05))
Q(F, "vague", "push the coffee table back a tad", dr("SM_CoffeeTable", "-z", 0.02),
  top("Remote_TV", "SM_CoffeeTable"), top("Magazine_Stack", "SM_CoffeeTable"), top("Mug_Coffee", "SM_CoffeeTable"))
Q(F, "vague", "scoot the pouf a few inches to the left", dr("Pouf_Grey", "-x", 0.03))
Q(F, "vague", "move the plant a good bit forward", dr("Plant_Monstera", "+z", 0.2))
Q(F, "vague", "move the tv a little to the left", dr("TV_65in", "-x", 0.02), top("TV_65in", "TV_Stand"))
Q(F, "vague", "shift the floor lamp slightly to the right", dr("Lamp_Floor", "+x", 0.02))
Q(F, "vague", "can you move the wall shelf up a bit", dr("Shelf_Wall.002", "+y", 0.03),
  top("Book.001", "Shelf_Wall.002"), top("Book.002", "Shelf_Wall.002"), top("Book.003", "Shelf_Wall.002"))
Q(F, "vague", "move the armchair forward a lot", dr("SM_Armchair_01", "+z", 0.3))
Q(F, "vague", "move the red cushion a touch to the right", dr("Cushion_Red", "+x", 0.02), top("Cushion_Red", "SM_Sofa_01"))
# placements
Q(F, "place", "hey, put the mug on the left side table", top("Mug_Coffee", "SideTable_L"), NC)
Q(H, "refuse", "put the mug on the side table", ref(["SideTable_L", "SideTable_R"]))
Q(CF, "place", "could you put the remote on the right side table next to the speaker",
  top("Remote_TV", "SideTable_R"), nxt("Remote_TV", "Speaker_Smart"), NC)
Q(F, "place", "put the red cushion on the armchair", top("Cushion_Red", "SM_Armchair_01"), NC)
Q(F, "place", "put the blue cushion on the pouf thx", top("Cushion_Blue", "Pouf_Grey"), NC)
Q(F, "place", "can u put the plant next to the tv stand", nxt("Plant_Monstera", "TV_Stand"), NC)
Q(F, "place", "put the pouf next to the armchair", nxt("Pouf_Grey", "SM_Armchair_01"), NC)
Q(F, "place", "put the remote next to the magazines", top("Remote_TV", "SM_CoffeeTable"), nxt("Remote_TV", "Magazine_Stack"), NC)
Q(F, "place", "put Book.001 on the coffee table please", top("Book.001", "SM_CoffeeTable"), NC)
Q(F, "place", "stick the remote up on the wall shelf", top("Remote_TV", "Shelf_Wall.002"), NC)
Q(F, "place", "put the speaker on the tv stand", top("Speaker_Smart", "TV_Stand"), NC)
Q(CF, "place", "put the mug on the tv stand next to the tv", top("Mug_Coffee", "TV_Stand"), nxt("Mug_Coffee", "TV_65in"), NC)
Q(F, "place", "move the pouf next to the right side table", nxt("Pouf_Grey", "SideTable_R"), NC)
Q(F, "place", "could you put the floor lamp next to the armchair? thanks", nxt("Lamp_Floor", "SM_Armchair_01"), NC)
Q(H, "place", "put Book.003 on the coffee table between the magazines and the remote",
  top("Book.003", "SM_CoffeeTable"), btw("Book.003", "Magazine_Stack", "Remote_TV"), NC)
Q(F, "place", "chuck the remote on the armchair", top("Remote_TV", "SM_Armchair_01"), NC)
Q(CF, "place", "put the speaker on the coffee table next to the mug", top("Speaker_Smart", "SM_CoffeeTable"), nxt("Speaker_Smart", "Mug_Coffee"), NC)
Q(F, "place", "put the mug up on the wall shelf", top("Mug_Coffee", "Shelf_Wall.002"), NC)
Q(F, "place", "move the floor lamp over next to the right side table", nxt("Lamp_Floor", "SideTable_R"), NC)
Q(F, "place", "put the plant to the right of the pouf", side("Plant_Monstera", "Pouf_Grey", "right"), NC)
Q(F, "place", "put the armchair next to the floor lamp", nxt("SM_Armchair_01", "Lamp_Floor"), NC)
Q(F, "place", "I'd like the magazines on the pouf", top("Magazine_Stack", "Pouf_Grey"), NC)
Q(F, "place", "put Book.002 on the right side table", top("Book.002", "SideTable_R"), NC)
Q(F, "place", "put the red cushion next to the blue one", top("Cushion_Red", "SM_Sofa_01"), nxt("Cushion_Red", "Cushion_Blue"), NC)
Q(F, "place", "put the remote on the left side table pls", top("Remote_TV", "SideTable_L"), NC)
Q(CF, "place", "put the mug and the remote on the right side table", top("Mug_Coffee", "SideTable_R"), top("Remote_TV", "SideTable_R"), NC)
Q(F, "place", "put the pouf in front of the left side table", side("Pouf_Grey", "SideTable_L", "front"), NC)
Q(CF, "place", "put the speaker on the tv stand, to the left of the tv", top("Speaker_Smart", "TV_Stand"), side("Speaker_Smart", "TV_65in", "left"), NC)
Q(F, "place", "put the mug in front of the magazines", top("Mug_Coffee", "SM_CoffeeTable"), side("Mug_Coffee", "Magazine_Stack", "front"), NC)
Q(H, "place", "take the middle book off the shelf and put it on the pouf", top("Book.002", "Pouf_Grey"), NC)
Q(F, "place", "put the speaker on the armchair", top("Speaker_Smart", "SM_Armchair_01"), NC)
Q(F, "place", "put the mug on the pouf", top("Mug_Coffee", "Pouf_Grey"), NC)
Q(F, "place", "pop Book.003 on the left side table", top("Book.003", "SideTable_L"), NC)
Q(F, "place", "put the remote to the right of the mug", top("Remote_TV", "SM_CoffeeTable"), side("Remote_TV", "Mug_Coffee", "right"), NC)
Q(F, "place", "put the pouf in front of the right side table", side("Pouf_Grey", "SideTable_R", "front"), NC)
Q(H, "place", "put the mug from the coffee table next to the tv", top("Mug_Coffee", "TV_Stand"), nxt("Mug_Coffee", "TV_65in"), NC)
Q(F, "place", "put the blue cushion on the left side table", top("Cushion_Blue", "SideTable_L"), NC)
# refusals
Q(H, "refuse", "move the cushion a bit to the left", ref(["Cushion_Red", "Cushion_Blue"]))
Q(H, "refuse", "move the lamp closer to the sofa pls", ref(["Lamp_Floor", "Lamp_Table"]))
Q(H, "refuse", "turn the side table 90 degrees", ref(["SideTable_L", "SideTable_R"]))
Q(H, "refuse", "put the book on the coffee table", ref(["Book.001", "Book.002", "Book.003"]))
Q(H, "refuse", "move the piano 1m left", ref([]))
Q(H, "refuse", "put the remote next to the book", ref(["Book.001", "Book.002", "Book.003"]))
Q(H, "refuse", "hey can you put the lamp next to the plant", ref(["Lamp_Floor", "Lamp_Table"]))
Q(H, "refuse", "put the cushion on the pouf", ref(["Cushion_Red", "Cushion_Blue"]))
# relational references
Q(H, "rel", "move the lamp on the left side table 10 cm to the right", mv("Lamp_Table", [0.1, 0, 0]), top("Lamp_Table", "SideTable_L"), NC)
Q(H, "rel", "move the lamp in the corner 30 cm to the right", mv("Lamp_Floor", [0.3, 0, 0]), NC)
Q(H, "rel", "move the cushion on the left 10 cm further left", mv("Cushion_Red", [-0.1, 0, 0]), NC)
Q(H, "rel", "move the thing on the right side table a bit to the left", dr("Speaker_Smart", "-x", 0.02), top("Speaker_Smart", "SideTable_R"))
Q(H, "rel", "slide the book closest to the front of the room 5cm back", mv("Book.003", [0, 0, -0.05]), NC)
Q(H, "rel", "move the cushion nearest the plant 10cm to the left", mv("Cushion_Blue", [-0.1, 0, 0]), NC)
# compositional fuzzy
Q(CF, "vague", "move the pouf a bit to the left and turn it 90 degrees", dr("Pouf_Grey", "-x", 0.05), rot("Pouf_Grey", 90, True))
Q(CF, "vague", "push the armchair a little towards the window and turn it to face the tv",
  dr("SM_Armchair_01", "+x", 0.03), faces("SM_Armchair_01", "TV_65in"))
Q(CF, "vague", "nudge both cushions a bit towards the middle of the sofa",
  dr("Cushion_Red", "+x", 0.02), dr("Cushion_Blue", "-x", 0.02))
Q(CF, "vague", "move the floor lamp a bit right and the plant a bit left",
  dr("Lamp_Floor", "+x", 0.05), dr("Plant_Monstera", "-x", 0.05))
Q(CF, "vague", "slide the coffee table a bit towards the tv but leave the rug where it is",
  dr("SM_CoffeeTable", "+z", 0.02), unch(["Rug_Large"]),
  top("Remote_TV", "SM_CoffeeTable"), top("Magazine_Stack", "SM_CoffeeTable"), top("Mug_Coffee", "SM_CoffeeTable"))

# ================================================================ cafe
_scene = "cafe_tables"
Q(S, "move", "move Table_Round.001 30cm to the right pls", *carry("Table_Round.001", [0.3, 0, 0]), NC)
Q(S, "move", "move Chair.004 20 cm back, ty", mv("Chair.004", [0, 0, -0.2]), NC)
Q(S, "move", "move chair 7 half a metre forward", mv("Chair.007", [0, 0, 0.5]), NC)
Q(S, "move", "can you shift the coffee machine 10 cm to the right", mv("CoffeeMachine_01", [0.1, 0, 0]), NC)
Q(S, "move", "move the till 25cm to the left", mv("Till_POS", [-0.25, 0, 0]), NC)
Q(S, "move", "move the tip jar 2 inches forward", mv("TipJar", [0, 0, 0.0508], 0.02), NC)
Q(S, "move", "move the window bench 50cm to the left", mv("Bench_Window", [-0.5, 0, 0]), NC)
Q(S, "move", "move the potted plant 1 metre to the left please", mv("Plant_Pot.001", [-1, 0, 0]), NC)
Q(S, "move", "raise the menu board by 20 cm", mv("Menu_Board", [0, 0.2, 0]), NC, IB)
Q(S, "move", "move the waste bin 30 cm to the right", mv("Bin_Waste", [0.3, 0, 0]), NC)
Q(S, "move", "move Cup.001 10 cm left", mv("Cup.001", [-0.1, 0, 0]), NC)
Q(S, "move", "move plate.002 5cm towards the back", mv("Plate.002", [0, 0, -0.05]), NC)
Q(H, "move", "move the table on the left 30cm to the right", *carry("Table_Round.000", [0.3, 0, 0]), NC)
Q(S, "move", "move the grindr 10 cm left", mv("Grinder_01", [-0.1, 0, 0]), NC)
Q(S, "move", "move chair 2 a foot to the left", mv("Chair.002", [-0.3048, 0, 0], 0.02), NC)
Q(S, "move", "lower the menu board 10 cm", mv("Menu_Board", [0, -0.1, 0]), NC)
Q(S, "move", "move Chair.003 30 cm towards the window", mv("Chair.003", [0, 0, 0.3]), NC)
Q(F, "move", "push the bench up against the left wall", mv("Bench_Window", [-4, 0, 0]), NC, IB)
Q(S, "turn", "rotate chair 3 by 180 degrees", rot("Chair.003", 180, True), mv("Chair.003", [0, 0, 0]), NC)
Q(S, "turn", "turn Chair.006 90° clockwise (from above)", rot("Chair.006", -90), mv("Chair.006", [0, 0, 0]), NC)
Q(S, "turn", "spin the till round 180", rot("Till_POS", 180, True), mv("Till_POS", [0, 0, 0]), NC)
Q(H, "turn", "turn chair 4 so it faces the counter", faces("Chair.004", "Counter_Main"), mv("Chair.004", [0, 0, 0]), NC)
Q(H, "turn", "turn the chair on the far left to face the counter", faces("Chair.006", "Counter_Main"), mv("Chair.006", [0, 0, 0]), NC)
# holds
Q(H, "hold", "move the middle table 40 cm to the left but leave the cup on it where it is", ref(["Cup.001", "Table_Round.001"]))
Q(C, "hold", "move the left table 10 cm to the right but don't move the plate on it",
  *carry("Table_Round.000", [0.1, 0, 0], hold=("Plate.000",)), unch(["Plate.000"]), NC)
Q(C, "hold", "push Chair.002 back 20cm, keep chair 3 where it is", mv("Chair.002", [0, 0, -0.2]), unch(["Chair.003"]), NC)
Q(C, "hold", "move the counter 20 cm to the right, leave the coffee machine where it is",
  *carry("Counter_Main", [0.2, 0, 0], hold=("CoffeeMachine_01",)), unch(["CoffeeMachine_01"]), NC)
# compositional
Q(C, "multi", "move chair.000 30cm left and chair.001 30cm right", mv("Chair.000", [-0.3, 0, 0]), mv("Chair.001", [0.3, 0, 0]), NC)
Q(C, "multi", "move Cup.000 and Plate.000 5 cm to the left", mv("Cup.000", [-0.05, 0, 0]), mv("Plate.000", [-0.05, 0, 0]), NC)
Q(C, "multi", "swap chair 0 and chair 5", swp("Chair.000", "Chair.005"), NC)
Q(H, "multi", "swap the plates on the left and right tables", swp("Plate.000", "Plate.002"), NC)
Q(C, "multi", "turn chair 6 around and move it 10cm left", rot("Chair.006", 180, True), mv("Chair.006", [-0.1, 0, 0]), NC)
Q(C, "multi", "move the till 10 cm left and the tip jar 10 cm right", mv("Till_POS", [-0.1, 0, 0]), mv("TipJar", [0.1, 0, 0]), NC)
# fuzzy
Q(F, "vague", "move the plant a bit to the left", dr("Plant_Pot.001", "-x", 0.05))
Q(F, "vague", "slide the bench a tad to the right", dr("Bench_Window", "+x", 0.02))
Q(F, "vague", "move chair 5 a little further from the table", dr("Chair.005", "+z", 0.05))
Q(F, "vague", "pull Chair.002 out a bit", dr("Chair.002", "-z", 0.05))
Q(F, "vague", "move the bin a few inches to the right", dr("Bin_Waste", "+x", 0.03))
Q(F, "vague", "scoot the middle table a bit to the left", dr("Table_Round.001", "-x", 0.05),
  top("Plate.001", "Table_Round.001"), top("Cup.001", "Table_Round.001"))
Q(F, "vague", "move the coffee machine slightly left", dr("CoffeeMachine_01", "-x", 0.02), top("CoffeeMachine_01", "Counter_Main"))
Q(F, "vague", "move the menu board up a little", dr("Menu_Board", "+y", 0.02))
Q(F, "vague", "move chair 7 a good bit forward", dr("Chair.007", "+z", 0.2))
# placements
Q(H, "refuse", "put the tip jar on the table", ref(["Table_Round.000", "Table_Round.001", "Table_Round.002"]))
Q(H, "place", "put the plate from the middle table on the counter next to the till",
  top("Plate.001", "Counter_Main"), nxt("Plate.001", "Till_POS"), NC)
Q(F, "place", "pop Cup.002 on the bench", top("Cup.002", "Bench_Window"), NC)
Q(F, "place", "put chair.006 next to the bench", nxt("Chair.006", "Bench_Window"), NC)
Q(F, "place", "move Chair.007 next to the plant", nxt("Chair.007", "Plant_Pot.001"), NC)
Q(H, "place", "put the plate from the left table onto the middle table", top("Plate.000", "Table_Round.001"), NC)
Q(CF, "place", "put cup 3 on the middle table, next to the plate that's there",
  top("Cup.003", "Table_Round.001"), nxt("Cup.003", "Plate.001"), NC)
Q(CF, "place", "put the tip jar on the counter next to the coffee machine",
  top("TipJar", "Counter_Main"), nxt("TipJar", "CoffeeMachine_01"), NC)
Q(F, "place", "put the grinder next to the till", top("Grinder_01", "Counter_Main"), nxt("Grinder_01", "Till_POS"), NC)
Q(H, "place", "put the tip jar on the middle table between the plate and the cup that are on it",
  top("TipJar", "Table_Round.001"), btw("TipJar", "Plate.001", "Cup.001"), NC)
Q(F, "place", "put Chair.003 next to chair 7", nxt("Chair.003", "Chair.007"), NC)
Q(F, "place", "put the coffee grinder on the bench", top("Grinder_01", "Bench_Window"), NC)
Q(F, "place", "hey could u put the till on the left table", top("Till_POS", "Table_Round.000"), NC)
Q(H, "refuse", "put the plate on the counter", ref(["Plate.000", "Plate.001", "Plate.002"]))
Q(F, "place", "put cup 2 next to cup 0", top("Cup.002", "Table_Round.000"), nxt("Cup.002", "Cup.000"), NC)
Q(F, "place", "put the tip jar in front of the till", top("TipJar", "Counter_Main"), side("TipJar", "Till_POS", "front"), NC)
Q(F, "place", "move chair 6 behind the bench", side("Chair.006", "Bench_Window", "behind"), NC)
Q(F, "place", "I'd like the plant next to the counter", nxt("Plant_Pot.001", "Counter_Main"), NC)
Q(H, "place", "put Plate.002 on the counter between the grinder and the till",
  top("Plate.002", "Counter_Main"), btw("Plate.002", "Grinder_01", "Till_POS"), NC)
Q(F, "place", "move the bin next to the plant, thanks!", nxt("Bin_Waste", "Plant_Pot.001"), NC)
Q(F, "place", "put chair 1 to the right of the bench", side("Chair.001", "Bench_Window", "right"), NC)
Q(F, "place", "put Cup.000 on the right table", top("Cup.000", "Table_Round.002"), NC)
Q(CF, "place", "take the cups off the right table and put them on the counter",
  top("Cup.002", "Counter_Main"), top("Cup.003", "Counter_Main"), NC)
Q(F, "place", "put chair 2 next to chair 4", nxt("Chair.002", "Chair.004"), NC)
Q(F, "place", "put the tip jar on the bench", top("TipJar", "Bench_Window"), NC)
Q(H, "place", "put the cup from the left table on the counter beside the coffee machine",
  top("Cup.000", "Counter_Main"), nxt("Cup.000", "CoffeeMachine_01"), NC)
Q(F, "place", "put the bin to the left of the counter", side("Bin_Waste", "Counter_Main", "left"), NC)
Q(H, "place", "move the chair nearest the counter next to the bin", nxt("Chair.000", "Bin_Waste"), NC)
Q(H, "place", "put plate 1 on top of plate 0", top("Plate.001", "Plate.000"), NC)
Q(F, "place", "put the tip jar to the left of the till", top("TipJar", "Counter_Main"), side("TipJar", "Till_POS", "left"), NC)
Q(CF, "place", "put the cups from the left and middle tables on the bench",
  top("Cup.000", "Bench_Window"), top("Cup.001", "Bench_Window"), NC)
Q(CF, "place", "put Cup.001 on the counter next to the tip jar", top("Cup.001", "Counter_Main"), nxt("Cup.001", "TipJar"), NC)
Q(F, "place", "put the grinder on the left table", top("Grinder_01", "Table_Round.000"), NC)
Q(H, "place", "move chair 4 to the left side of the right table", side("Chair.004", "Table_Round.002", "left"), NC)
Q(F, "place", "put the tip jar on the right table", top("TipJar", "Table_Round.002"), NC)
Q(F, "place", "put chair.000 next to the counter", nxt("Chair.000", "Counter_Main"), NC)
# refusals
Q(H, "refuse", "move the chair", ref([f"Chair.00{i}" for i in range(8)]))
Q(H, "refuse", "move the cup 10cm to the left", ref(["Cup.000", "Cup.001", "Cup.002", "Cup.003"]))
Q(H, "refuse", "turn the table 45 degrees pls", ref(["Table_Round.000", "Table_Round.001", "Table_Round.002"]))
Q(H, "refuse", "move the cup on the right table to the counter", ref(["Cup.002", "Cup.003"]))
Q(H, "refuse", "push the chair at the middle table back a bit", ref(["Chair.002", "Chair.003"]))
Q(H, "refuse", "move the sofa next to the window", ref([]))
Q(H, "refuse", "put the chair next to the plant", ref([f"Chair.00{i}" for i in range(8)]))
# relational
Q(H, "rel", "move the cup on the middle table 5 cm left", mv("Cup.001", [-0.05, 0, 0]), NC)
Q(H, "rel", "push the chair nearest the counter 20cm back", mv("Chair.000", [0, 0, -0.2]), NC)
Q(H, "rel", "move the plate on the left table 10 cm right", mv("Plate.000", [0.1, 0, 0]), NC)
Q(H, "rel", "turn the chair in front of the right table around", rot("Chair.005", 180, True), mv("Chair.005", [0, 0, 0]), NC)
Q(H, "rel", "move the chair on the far right 20 cm forward", mv("Chair.007", [0, 0, 0.2]), NC)
Q(H, "rel", "move the chair on the far left 20 cm forward", mv("Chair.006", [0, 0, 0.2]), NC)
Q(H, "rel", "move the cup closest to the window 5 cm left", mv("Cup.003", [-0.05, 0, 0]), NC)
Q(H, "rel", "move the table in the middle 25 cm right", *carry("Table_Round.001", [0.25, 0, 0]), NC)
# compositional fuzzy
Q(CF, "vague", "move chair 4 a bit back and turn it to face the counter", dr("Chair.004", "-z", 0.05), faces("Chair.004", "Counter_Main"))
Q(CF, "vague", "slide chairs 0 and 1 a little to the left", dr("Chair.000", "-x", 0.03), dr("Chair.001", "-x", 0.03))
Q(CF, "vague", "move the bench a bit right and the plant a bit forward", dr("Bench_Window", "+x", 0.05), dr("Plant_Pot.001", "+z", 0.05))
Q(CF, "vague", "nudge the till a tad left but leave the tip jar alone", dr("Till_POS", "-x", 0.02), unch(["TipJar"]))
Q(CF, "vague", "move the left table a bit to the right, the chairs stay put",
  dr("Table_Round.000", "+x", 0.05), top("Plate.000", "Table_Round.000"), top("Cup.000", "Table_Round.000"),
  unch([f"Chair.00{i}" for i in range(8)]))

# ================================================================ study
_scene = "study_desk"
DESK_ITEMS = ["Laptop_Pro", "DeskLamp", "Notebook_A5", "Mug.001", "PenHolder"]
Q(S, "move", "hey can you move the desk 10 cm to the right", *carry("Desk_Oak", [0.1, 0, 0]), NC)
Q(S, "move", "pull the chair 40 cm forward", mv("OfficeChair", [0, 0, 0.4]), NC)
Q(S, "move", "move the bin 1 foot to the right", mv("Bin_Paper", [0.3048, 0, 0], 0.02), NC)
Q(S, "move", "move the filing cabinet 15cm right", *carry("FilingCabinet", [0.15, 0, 0]), NC)
Q(S, "move", "move the printer 5cm left", mv("Printer_Laser", [-0.05, 0, 0]), NC)
Q(S, "move", "raise the whiteboard 20 cm please", mv("Whiteboard", [0, 0.2, 0]), NC)
Q(S, "move", "move the whiteboard 30 cm to the left", mv("Whiteboard", [-0.3, 0, 0]), NC)
Q(S, "move", "move the laptop 10 cm towards the back wall", mv("Laptop_Pro", [0, 0, -0.1]), NC)
Q(S, "move", "slide the mug 20 cm left", mv("Mug.001", [-0.2, 0, 0]), NC)
Q(S, "move", "move the notebook 3 inches to the left", mv("Notebook_A5", [-0.0762, 0, 0], 0.02), NC)
Q(S, "move", "move the bookcase 30 cm foward", *carry("Bookcase_Tall", [0, 0, 0.3]), NC)
Q(S, "move", "move the desk lamp 10 cm to the right", mv("DeskLamp", [0.1, 0, 0]), NC)
Q(S, "move", "move the small cabinet 20cm right", *carry("Cabinet_Small", [0.2, 0, 0]), NC)
Q(S, "move", "move the globe 10cm forward", mv("Globe", [0, 0, 0.1]), NC)
Q(S, "move", "move the whiteboard up 6 inches", mv("Whiteboard", [0, 0.1524, 0], 0.02), NC)
Q(S, "move", "move the pen holder 10cm to the left", mv("PenHolder", [-0.1, 0, 0]), NC)
Q(S, "move", "move the mug 10 cm towards the laptop", mv("Mug.001", [-0.1, 0, 0], 0.03), NC)
Q(S, "turn", "rotate the chair 90 degrees clockwise", rot("OfficeChair", -90), mv("OfficeChair", [0, 0, 0]), NC)
Q(S, "turn", "rotate the laptop 20 degrees counterclockwise seen from above", rot("Laptop_Pro", 20), mv("Laptop_Pro", [0, 0, 0]), NC)
Q(S, "turn", "turn the desk lamp 45 degrees", rot("DeskLamp", 45, True), mv("DeskLamp", [0, 0, 0]), NC)
Q(S, "turn", "grab the office chair and rotate it 45 degrees clockwise seen from above", rot("OfficeChair", -45), mv("OfficeChair", [0, 0, 0]), NC)
Q(H, "turn", "turn the chair to face the desk", faces("OfficeChair", "Desk_Oak"), mv("OfficeChair", [0, 0, 0]), NC)
Q(H, "turn", "turn the chair to face the bookcase", faces("OfficeChair", "Bookcase_Tall"), mv("OfficeChair", [0, 0, 0]), NC)
Q(H, "turn", "turn the desk lamp so it points at the laptop", faces("DeskLamp", "Laptop_Pro"), mv("DeskLamp", [0, 0, 0]), NC)
# holds
Q(C, "hold", "move the desk 20cm left but leave the chair where it is", *carry("Desk_Oak", [-0.2, 0, 0]), unch(["OfficeChair"]), NC)
Q(C, "hold", "move the filing cabinet 10 cm forward but leave the plant where it is",
  mv("FilingCabinet", [0, 0, 0.1]), unch(["Plant_Succulent"]), NC)
Q(C, "hold", "move the desk 10cm right, keep the lamp where it is",
  *carry("Desk_Oak", [0.1, 0, 0], hold=("DeskLamp",)), unch(["DeskLamp"]), NC)
Q(C, "hold", "shift the small cabinet 10 cm left without moving the printer",
  mv("Cabinet_Small", [-0.1, 0, 0]), unch(["Printer_Laser"]), NC)
Q(C, "hold", "move the bookcase 20cm forward but keep the globe where it is",
  mv("Bookcase_Tall", [0, 0, 0.2]), unch(["Globe"]), NC)
Q(H, "hold", "move the desk 1 m to the left, but the laptop stays where it is", ref(["Laptop_Pro", "Desk_Oak"]))
# compositional
Q(C, "multi", "move the laptop 10 cm left and the mug 5 cm right", mv("Laptop_Pro", [-0.1, 0, 0]), mv("Mug.001", [0.05, 0, 0]), NC)
Q(C, "multi", "rotate the office chair 180° and push it 20cm forward", rot("OfficeChair", 180, True), mv("OfficeChair", [0, 0, 0.2]), NC)
Q(H, "multi", "swap the filing cabinet and the small cabinet",
  swp("FilingCabinet", "Cabinet_Small"), mv("Plant_Succulent", [0.9, 0, -0.05]), mv("Printer_Laser", [-0.9, 0, 0.05]), NC, IB)
Q(C, "multi", "move the bin 20cm left and the chair 20cm right", mv("Bin_Paper", [-0.2, 0, 0]), mv("OfficeChair", [0.2, 0, 0]), NC)
Q(C, "multi", "move the notebook 10cm left and rotate it 90 degrees", mv("Notebook_A5", [-0.1, 0, 0]), rot("Notebook_A5", 90, True), NC)
# fuzzy
Q(F, "vague", "move the chair a bit closer to the window", dr("OfficeChair", "+x", 0.05))
Q(F, "vague", "push the notebook a tad to the right", dr("Notebook_A5", "+x", 0.02), top("Notebook_A5", "Desk_Oak"))
Q(F, "vague", "move the bin a little to the right", dr("Bin_Paper", "+x", 0.03))
Q(F, "vague", "move the bookcase forward a lot", dr("Bookcase_Tall", "+z", 0.3), top("Globe", "Bookcase_Tall"))
Q(F, "vague", "nudge the laptop towards the back wall a bit", dr("Laptop_Pro", "-z", 0.02), top("Laptop_Pro", "Desk_Oak"))
Q(F, "vague", "scoot the chair a few inches to the left", dr("OfficeChair", "-x", 0.03))
Q(F, "vague", "lift the whiteboard a bit", dr("Whiteboard", "+y", 0.03))
Q(F, "vague", "push the filing cabinet a little to the right", dr("FilingCabinet", "+x", 0.02), top("Plant_Succulent", "FilingCabinet"))
# placements
Q(F, "place", "put my mug next to the laptop", top("Mug.001", "Desk_Oak"), nxt("Mug.001", "Laptop_Pro"), NC)
Q(H, "place", "put the notebook on the desk between the laptop and the lamp",
  top("Notebook_A5", "Desk_Oak"), btw("Notebook_A5", "Laptop_Pro", "DeskLamp"), NC)
Q(F, "place", "move the chair next to the bookcase pls", nxt("OfficeChair", "Bookcase_Tall"), NC)
Q(F, "place", "put the succulent on top of the printer", top("Plant_Succulent", "Printer_Laser"), NC)
Q(CF, "place", "put the mug on the filing cabinet next to the plant",
  top("Mug.001", "FilingCabinet"), nxt("Mug.001", "Plant_Succulent"), NC)
Q(H, "refuse", "put the pen holder on the small cabinet", ref(["PenHolder", "Cabinet_Small"]))
Q(F, "place", "I'd like the globe on the desk", top("Globe", "Desk_Oak"), NC)
Q(F, "place", "put the mug on the printer", top("Mug.001", "Printer_Laser"), NC)
Q(F, "place", "could you put the bin next to the bookcase, thanks", nxt("Bin_Paper", "Bookcase_Tall"), NC)
Q(F, "place", "put the laptop on the filing cabinet for now", top("Laptop_Pro", "FilingCabinet"), NC)
Q(F, "place", "put the mug in front of the laptop", top("Mug.001", "Desk_Oak"), side("Mug.001", "Laptop_Pro", "front"), NC)
Q(F, "place", "put the pen holder to the left of the laptop", top("PenHolder", "Desk_Oak"), side("PenHolder", "Laptop_Pro", "left"), NC)
Q(F, "place", "put the pen holder behind the laptop", top("PenHolder", "Desk_Oak"), side("PenHolder", "Laptop_Pro", "behind"), NC)
Q(CF, "place", "put the plant on the desk next to the lamp", top("Plant_Succulent", "Desk_Oak"), nxt("Plant_Succulent", "DeskLamp"), NC)
Q(CF, "place", "put the globe on the floor next to the bookcase", nxt("Globe", "Bookcase_Tall"), NC)
Q(H, "place", "put the mug between the laptop and the notebook",
  top("Mug.001", "Desk_Oak"), btw("Mug.001", "Laptop_Pro", "Notebook_A5"), NC)
Q(F, "place", "move the bin to the left of the desk", side("Bin_Paper", "Desk_Oak", "left"), NC)
Q(F, "place", "put the bin next to the small cabinet", nxt("Bin_Paper", "Cabinet_Small"), NC)
Q(F, "place", "put the printer on the desk thx", top("Printer_Laser", "Desk_Oak"), NC)
Q(F, "place", "put the notebook on the printer", top("Notebook_A5", "Printer_Laser"), NC)
Q(F, "place", "put the mug on the bookcase", top("Mug.001", "Bookcase_Tall"), NC)
Q(F, "place", "move the office chair next to the filing cabinet", nxt("OfficeChair", "FilingCabinet"), NC)
Q(F, "place", "put the desk lamp on the filing cabinet", top("DeskLamp", "FilingCabinet"), NC)
Q(F, "place", "put the succulent next to the globe", top("Plant_Succulent", "Bookcase_Tall"), nxt("Plant_Succulent", "Globe"), NC)
Q(CF, "place", "put the mug and the pen holder on the filing cabinet", top("Mug.001", "FilingCabinet"), top("PenHolder", "FilingCabinet"), NC)
Q(F, "place", "put the desk lamp on the desk to the right of the laptop", top("DeskLamp", "Desk_Oak"), side("DeskLamp", "Laptop_Pro", "right"), NC)
Q(F, "place", "put the pen holder on the notebook", top("PenHolder", "Notebook_A5"), NC)
Q(F, "place", "put the mug on the notebook", top("Mug.001", "Notebook_A5"), NC)
Q(F, "place", "put the laptop on the printer", top("Laptop_Pro", "Printer_Laser"), NC)
Q(F, "place", "put the globe next to the bin", nxt("Globe", "Bin_Paper"), NC)
Q(CF, "place", "put the desk lamp up on the bookcase next to the globe", top("DeskLamp", "Bookcase_Tall"), nxt("DeskLamp", "Globe"), NC)
# refusals
Q(H, "refuse", "move the cabinet 10cm left", ref(["FilingCabinet", "Cabinet_Small"]))
Q(H, "refuse", "put the mug on the cabinet", ref(["FilingCabinet", "Cabinet_Small"]))
Q(H, "refuse", "rotate the cabinet 90 degrees", ref(["FilingCabinet", "Cabinet_Small"]))
Q(H, "refuse", "move the sofa to the window", ref([]))
# relational
Q(H, "rel", "move the thing on the filing cabinet 5cm left", mv("Plant_Succulent", [-0.05, 0, 0]), NC)
Q(H, "rel", "move the cabinet with the printer on it 10 cm left", *carry("Cabinet_Small", [-0.1, 0, 0]), NC)
Q(H, "rel", "move whatever's on top of the bookcase onto the desk", top("Globe", "Desk_Oak"), NC)
Q(H, "rel", "move the cabinet next to the desk 10 cm forward", *carry("FilingCabinet", [0, 0, 0.1]), NC)
# compositional fuzzy
Q(CF, "vague", "move the chair a bit to the left and turn it to face the desk", dr("OfficeChair", "-x", 0.05), faces("OfficeChair", "Desk_Oak"))
Q(CF, "vague", "slide the laptop a bit left and the notebook a tad to the right",
  dr("Laptop_Pro", "-x", 0.05), dr("Notebook_A5", "+x", 0.02), top("Laptop_Pro", "Desk_Oak"), top("Notebook_A5", "Desk_Oak"))
Q(CF, "vague", "push the bookcase a bit forward but keep the globe where it is", dr("Bookcase_Tall", "+z", 0.05), unch(["Globe"]))
Q(CF, "vague", "move the bin a little closer to the window and the chair a little to the left",
  dr("Bin_Paper", "+x", 0.03), dr("OfficeChair", "-x", 0.03))

SUITE = {"name": "holdout2",
         "scenes": ["ue_lounge.json", "cafe_tables.json", "study_desk.json"],
         "variations": 1, "seed": 20261211, "queries": QUERIES}

def dump(path, obj):
    with open(os.path.join(HERE, path), "w") as f:
        json.dump(obj, f, indent=1)
        f.write("\n")

if __name__ == "__main__":
    for sc in (LOUNGE, CAFE, STUDY):
        dump(sc["name"] + ".json", sc)
    dump("holdout2.suite.json", SUITE)
    print(len(QUERIES), "queries")
