#!/usr/bin/env python3
"""Writes the four holdout9 scenes and holdout9.suite.json.

Written from SPEC sections 1, 2, 6 and docs/benchmark.md only.
Frame: +Y up, metres, right = +X, left = -X, forward = +Z, back = -Z.
Pivot = bottom centre of the box; rotations are quaternions [x, y, z, w] about +Y.
Every expectation below is derived from the geometry defined in this file.
"""
import json, math, os

HERE = os.path.dirname(os.path.abspath(__file__))
S = math.sqrt(0.5)
R90 = [0.0, round(S, 7), 0.0, round(S, 7)]      # +90 deg about Y: front +Z -> +X
RM90 = [0.0, -round(S, 7), 0.0, round(S, 7)]    # -90 deg about Y: front +Z -> -X
R180 = [0.0, 1.0, 0.0, 0.0]                     # front +Z -> -Z
FT = 0.3048
INCH = 0.0254

# --------------------------------------------------------------------------- geometry

def quat_matrix(q):
    x, y, z, w = q
    return [[1 - 2*(y*y + z*z), 2*(x*y - z*w), 2*(x*z + y*w)],
            [2*(x*y + z*w), 1 - 2*(x*x + z*z), 2*(y*z - x*w)],
            [2*(x*z - y*w), 2*(y*z + x*w), 1 - 2*(x*x + y*y)]]


def aabb(o):
    w, h, d = o["size"]
    s = o.get("scale", 1.0)
    m = quat_matrix(o.get("rotation", [0, 0, 0, 1]))
    p = o["position"]
    lo = [1e9] * 3
    hi = [-1e9] * 3
    for cx in (-w/2, w/2):
        for cy in (0, h):
            for cz in (-d/2, d/2):
                v = [cx*s, cy*s, cz*s]
                r = [sum(m[i][j]*v[j] for j in range(3)) + p[i] for i in range(3)]
                for i in range(3):
                    lo[i] = min(lo[i], r[i]); hi[i] = max(hi[i], r[i])
    return lo, hi


def centre(o):
    lo, hi = aabb(o)
    return [(lo[i] + hi[i]) / 2 for i in range(3)]

# --------------------------------------------------------------------------- scenes

SCENES = {}


def scene(name, bmin, bmax, objs):
    SCENES[name] = {"name": name, "bounds": {"min": bmin, "max": bmax}, "objects": objs}


def O(name, size, pos, rot=None, cat=None, on=None):
    o = {"name": name, "position": [float(v) for v in pos], "size": [float(v) for v in size],
         "rotation": rot or [0.0, 0.0, 0.0, 1.0], "scale": 1.0}
    if cat:
        o["category"] = cat
    if on:
        o["on"] = on   # extension field (SPEC 2: other fields are kept); the resting support
    return o


def on_top_of(support, size, x, z, name, cat=None):
    """An object resting on the support's top face, pivot at (x, top, z)."""
    top = support["position"][1] + support["size"][1] * support.get("scale", 1.0)
    return O(name, size, [x, round(top, 6), z], cat=cat, on=support["name"])


# ---- 1. greenhouse: human names, numbered identical planters in two rows, pots on staging
g = []
g.append(O("door", [1.0, 2.1, 0.05], [0, 0, 3.97], cat="door"))
pl = {}
for i, (x, z) in enumerate([(-2.6, 0.9), (-1.0, 0.9), (0.6, 0.9), (-2.6, -0.9), (-1.0, -0.9), (0.6, -0.9)], 1):
    pl[i] = O(f"planter {i}", [1.2, 0.5, 0.8], [x, 0, z], cat="raised planter")
    g.append(pl[i])
g.append(on_top_of(pl[2], [0.1, 0.04, 0.3], -1.0, 0.9, "hand fork", cat="garden tool"))
g.append(on_top_of(pl[6], [0.09, 0.04, 0.3], 0.6, -0.9, "trowel", cat="garden tool"))
staging = O("staging table", [2.4, 0.8, 1.0], [3.4, 0, 0.0], cat="staging")
g.append(staging)
for name, size, x, z in [("tomato pot", [0.3, 0.6, 0.3], 2.7, 0.25), ("chilli pot", [0.25, 0.4, 0.25], 3.4, 0.25),
                         ("basil pot", [0.2, 0.3, 0.2], 4.1, 0.25), ("parsley pot", [0.2, 0.25, 0.2], 2.7, -0.25),
                         ("mint pot", [0.25, 0.3, 0.25], 3.4, -0.25), ("thyme pot", [0.18, 0.2, 0.18], 4.1, -0.25)]:
    g.append(on_top_of(staging, size, x, z, name, cat="plant pot"))
bench = O("potting bench", [2.0, 0.9, 0.7], [-2.5, 0, -3.6], cat="bench")
g.append(bench)
g.append(on_top_of(bench, [0.55, 0.06, 0.35], -3.0, -3.6, "seed tray"))
g.append(on_top_of(bench, [0.12, 0.1, 0.12], -2.4, -3.5, "twine"))
g.append(on_top_of(bench, [0.3, 0.18, 0.12], -1.85, -3.65, "radio"))
g.append(O("potting stool", [0.35, 0.6, 0.35], [-2.5, 0, -2.9], cat="stool"))
shelf = O("shelf unit", [1.2, 1.8, 0.4], [1.5, 0, -3.75], cat="shelf")
g.append(shelf)
g.append(on_top_of(shelf, [0.1, 0.28, 0.1], 1.2, -3.75, "spray bottle"))
g.append(O("water butt", [0.6, 1.0, 0.6], [-4.5, 0, -2.0], cat="water barrel"))
g.append(O("green watering can", [0.18, 0.3, 0.45], [-4.5, 0, -1.2], cat="watering can"))
g.append(O("blue watering can", [0.18, 0.3, 0.45], [3.2, 0, 2.6], cat="watering can"))
g.append(O("wheelbarrow", [0.7, 0.6, 1.4], [-3.5, 0, 2.9]))
compost = O("compost bag", [0.5, 0.25, 0.8], [-4.6, 0, 0.8], cat="sack")
g.append(compost)
g.append(on_top_of(compost, [0.5, 0.25, 0.8], -4.6, 0.8, "sack of bark", cat="sack"))
g.append(O("hose reel", [0.5, 0.6, 0.35], [4.5, 0, 3.0]))
g.append(O("heater", [0.5, 0.6, 0.25], [-1.2, 0, 3.8]))
g.append(O("fan", [0.4, 1.2, 0.4], [4.6, 0, -3.5]))
scene("greenhouse", [-5, 0, -4], [5, 3.2, 4], g)

# ---- 2. rehearsal room: human names, drum kit on a riser, look-alike amps and speakers
r = []
r.append(O("door", [0.05, 2.1, 0.9], [-3.97, 0, 1.8], cat="door"))
riser = O("drum riser", [2.4, 0.2, 2.0], [0, 0, -2.4], cat="platform")
r.append(riser)
for name, size, x, z, cat in [("bass drum", [0.55, 0.55, 0.45], 0.0, -2.2, "drum"),
                              ("snare drum", [0.4, 0.65, 0.4], -0.55, -1.85, "drum"),
                              ("floor tom", [0.45, 0.55, 0.45], 0.6, -1.85, "drum"),
                              ("hi-hat", [0.4, 1.0, 0.4], -0.85, -2.5, "cymbal"),
                              ("ride cymbal", [0.5, 1.3, 0.5], 0.85, -2.7, "cymbal"),
                              ("drum throne", [0.4, 0.55, 0.4], 0.0, -2.95, "stool")]:
    r.append(on_top_of(riser, size, x, z, name, cat=cat))
r.append(O("marshall amp", [0.7, 0.55, 0.28], [-2.6, 0, -3.2], cat="guitar amp"))
r.append(O("vox amp", [0.6, 0.5, 0.26], [2.6, 0, -3.2], cat="guitar amp"))
r.append(O("bass amp", [0.6, 1.0, 0.45], [-3.4, 0, -1.5], rot=R90, cat="bass amp"))
r.append(O("mic stand 1", [0.5, 1.6, 0.5], [-1.5, 0, 0.2], cat="mic stand"))
r.append(O("mic stand 2", [0.5, 1.6, 0.5], [1.5, 0, 0.2], cat="mic stand"))
kst = O("keyboard stand", [1.0, 0.75, 0.4], [2.6, 0, -1.0], cat="stand")
r.append(kst)
r.append(on_top_of(kst, [1.25, 0.12, 0.35], 2.6, -1.0, "keyboard", cat="keyboard"))
r.append(O("sofa", [1.8, 0.8, 0.85], [0, 0, 3.0], rot=R180, cat="sofa"))
ct = O("coffee table", [1.0, 0.4, 0.5], [0, 0, 2.0], cat="table")
r.append(ct)
r.append(on_top_of(ct, [0.21, 0.005, 0.3], -0.25, 2.0, "setlist", cat="paper"))
r.append(on_top_of(ct, [0.07, 0.22, 0.07], 0.3, 1.95, "water bottle", cat="bottle"))
r.append(on_top_of(ct, [0.1, 0.03, 0.06], 0.05, 2.1, "tuner"))
r.append(O("guitar case", [1.05, 0.14, 0.4], [-3.2, 0, 2.9], cat="case"))
r.append(O("PA speaker left", [0.4, 0.65, 0.35], [-3.5, 0, 0.5], cat="PA speaker"))
r.append(O("PA speaker right", [0.4, 0.65, 0.35], [3.5, 0, 0.5], cat="PA speaker"))
mt = O("mixer table", [1.2, 0.75, 0.6], [3.2, 0, 2.4], cat="table")
r.append(mt)
r.append(on_top_of(mt, [0.6, 0.1, 0.45], 3.35, 2.4, "mixer", cat="mixing desk"))
r.append(on_top_of(mt, [0.33, 0.02, 0.23], 2.8, 2.4, "laptop", cat="laptop"))
r.append(O("office chair", [0.55, 0.9, 0.55], [3.2, 0, 3.05], rot=R180, cat="chair"))
r.append(O("rug", [2.0, 0.01, 1.4], [0, 0, 0.0], cat="rug"))
r.append(O("mini fridge", [0.5, 0.85, 0.5], [-1.9, 0, 3.2], cat="fridge"))
r.append(O("music stand", [0.5, 1.2, 0.4], [0, 0, 1.3], cat="stand"))
r.append(O("stool", [0.4, 0.75, 0.4], [-2.0, 0, -0.6], cat="stool"))
scene("rehearsal_room", [-4, 0, -3.5], [4, 2.8, 3.5], r)

# ---- 3. salon: game-engine names, four numbered identical styling stations
s = []
cnt = {}
for i, x in enumerate([-3.0, -1.0, 1.0, 3.0], 1):
    c = O(f"SM_StationCounter_0{i}", [1.2, 0.8, 0.5], [x, 0, -3.2])
    cnt[i] = c
    s.append(c)
    s.append(on_top_of(c, [0.9, 1.1, 0.05], x, -3.4, f"SM_Mirror_0{i}"))
    s.append(O(f"SM_SalonChair_0{i}", [0.65, 1.0, 0.7], [x, 0, -2.3], rot=R180))
    tr = O(f"BP_Trolley_0{i}", [0.4, 0.85, 0.4], [x + 0.65, 0, -2.5])
    s.append(tr)
    if i == 2:
        s.append(on_top_of(tr, [0.2, 0.01, 0.04], x + 0.65, -2.5, "SM_Comb_02"))
s.append(on_top_of(cnt[1], [0.3, 0.1, 0.22], -3.35, -3.15, "SM_Hairdryer_01"))
s.append(on_top_of(cnt[3], [0.08, 0.25, 0.08], 1.4, -3.1, "SM_SprayBottle_03"))
s.append(O("SM_WashUnit_A", [0.7, 0.9, 0.6], [4.6, 0, 0.0], rot=RM90))
s.append(O("SM_WashUnit_B", [0.7, 0.9, 0.6], [4.6, 0, 1.2], rot=RM90))
s.append(O("SM_WashChair_A", [0.6, 0.95, 0.75], [3.8, 0, 0.0], rot=RM90))
s.append(O("SM_WashChair_B", [0.6, 0.95, 0.75], [3.8, 0, 1.2], rot=RM90))
desk = O("SM_ReceptionDesk", [1.6, 1.1, 0.6], [-3.6, 0, 2.4])
s.append(desk)
s.append(on_top_of(desk, [0.35, 0.2, 0.35], -3.2, 2.4, "SM_Till"))
s.append(on_top_of(desk, [0.15, 0.3, 0.15], -4.1, 2.4, "SM_PlantPot_Small"))
s.append(O("SM_OfficeChair_01", [0.55, 0.95, 0.55], [-3.6, 0, 1.6]))
s.append(O("SM_Sofa_Waiting", [1.8, 0.85, 0.8], [1.5, 0, 3.0], rot=R180))
sct = O("SM_CoffeeTable", [0.9, 0.45, 0.5], [1.5, 0, 2.0])
s.append(sct)
s.append(on_top_of(sct, [0.21, 0.01, 0.28], 1.25, 2.0, "SM_Magazine_01"))
s.append(on_top_of(sct, [0.21, 0.01, 0.28], 1.75, 2.0, "SM_Magazine_02"))
s.append(O("SM_Chair_Waiting_01", [0.5, 0.85, 0.5], [3.3, 0, 3.0], rot=R180))
s.append(O("SM_Chair_Waiting_02", [0.5, 0.85, 0.5], [-0.2, 0, 3.0], rot=R180))
s.append(O("BP_Lamp_A", [0.4, 1.6, 0.4], [-4.6, 0, 3.1]))
s.append(O("BP_Lamp_B", [0.4, 1.6, 0.4], [2.7, 0, 3.2]))
s.append(O("SM_Door_Front", [1.0, 2.1, 0.06], [-1.5, 0, 3.46]))
tsh = O("SM_TowelShelf", [1.0, 1.8, 0.35], [-4.8, 0, -0.5], rot=R90)
s.append(tsh)
s.append(on_top_of(tsh, [0.3, 0.2, 0.25], -4.8, -0.5, "SM_TowelStack_01"))
s.append(O("SM_Bin_01", [0.3, 0.45, 0.3], [-4.6, 0, 1.2]))
scene("salon", [-5, 0, -3.5], [5, 3.0, 3.5], s)

# ---- 4. warehouse: meaningless DCC / CAD export names
w = []
w.append(O("Assembly_3", [2.7, 4.0, 1.1], [-3.5, 0, -4.4]))
w.append(O("Assembly_4", [2.7, 4.0, 1.1], [-0.5, 0, -4.4]))
p14 = O("Mesh_014", [1.2, 0.15, 0.8], [-3.0, 0, -1.5])
w.append(p14)
c12 = on_top_of(p14, [0.6, 0.5, 0.4], -3.3, -1.5, "Cube.012")
w.append(c12)
w.append(on_top_of(p14, [0.6, 0.5, 0.4], -2.7, -1.5, "Cube.013"))
w.append(on_top_of(c12, [0.6, 0.5, 0.4], -3.3, -1.5, "Cube.014"))
w.append(O("Mesh_015", [1.2, 0.15, 0.8], [-3.0, 0, 0.8]))
p16 = O("Mesh_016", [1.2, 0.15, 0.8], [0.0, 0, -1.5])
w.append(p16)
w.append(on_top_of(p16, [0.6, 0.9, 0.6], 0.0, -1.5, "Cylinder.003"))
w.append(O("Object_7", [0.7, 1.2, 1.6], [3.0, 0, -1.0]))
w.append(O("Body1", [0.6, 0.9, 1.0], [2.0, 0, -3.0]))
wb = O("PART_0041", [2.0, 0.9, 0.8], [4.5, 0, -4.4])
w.append(wb)
w.append(on_top_of(wb, [0.2, 0.15, 0.25], 3.8, -4.4, "PART_0042"))
w.append(on_top_of(wb, [0.5, 0.25, 0.25], 4.8, -4.4, "Body3"))
w.append(O("Plane.004", [3.0, 3.5, 0.05], [0, 0, 4.97], cat="door"))
w.append(O("Cube.027", [0.8, 1.9, 0.8], [-2.2, 0, 4.3]))
c28 = O("Cube.028", [0.8, 0.5, 0.8], [2.2, 0, 4.3])
w.append(c28)
w.append(on_top_of(c28, [0.3, 0.3, 0.3], 2.2, 4.3, "Cube.030"))
m17 = O("mesh_17", [1.4, 0.75, 0.7], [4.8, 0, 3.5])
w.append(m17)
w.append(O("mesh_18", [0.5, 0.9, 0.5], [4.8, 0, 2.8]))
w.append(on_top_of(m17, [0.55, 0.4, 0.18], 4.8, 3.65, "mesh_19"))
w.append(on_top_of(m17, [0.09, 0.1, 0.09], 4.35, 3.4, "Cylinder.009"))
w.append(O("Cylinder.004", [0.6, 0.9, 0.6], [5.4, 0, 0.5]))
w.append(O("Cylinder.005", [0.6, 0.9, 0.6], [5.4, 0, 1.3]))
w.append(O("Mesh_020", [0.2, 0.6, 0.2], [-5.8, 0, 3.0]))
a5 = O("Assembly_5", [1.0, 2.0, 0.45], [-5.7, 0, 0.0], rot=R90)
w.append(a5)
w.append(on_top_of(a5, [0.4, 0.3, 0.3], -5.7, -0.22, "Cube.031"))
w.append(on_top_of(a5, [0.25, 0.15, 0.2], -5.7, 0.25, "Cube.032"))
w.append(O("Cone.001", [0.3, 0.5, 0.3], [1.0, 0, 2.0]))
w.append(O("Cone.002", [0.3, 0.5, 0.3], [-1.0, 0, 2.0]))
scene("warehouse", [-6, 0, -5], [6, 6, 5], w)

OBJ = {sn: {o["name"]: o for o in sc["objects"]} for sn, sc in SCENES.items()}

# --------------------------------------------------------------------------- checks

U = {"check": "unchanged", "objects": "others"}
NC = {"check": "no_collision"}
IB = {"check": "inside_bounds"}


def mv(o, dx, dy, dz, tol=0.05):
    return {"check": "moved", "object": o, "delta": [round(dx, 4), round(dy, 4), round(dz, 4)], "tol": tol}


def dr(o, axis, mn=0.05):
    return {"check": "direction", "object": o, "axis": axis, "min": mn}


def rot(o, deg, either=False):
    c = {"check": "rotated", "object": o, "axis": "y", "degrees": deg}
    if either:
        c["either_sign"] = True
    return c


def sc(o, f):
    return {"check": "scaled", "object": o, "factor": f}


def on(o, sup):
    return {"check": "on_top", "object": o, "support": sup}


def nx(o, other, gap=0.3):
    return {"check": "next_to", "object": o, "other": other, "max_gap": gap}


def sd(o, other, side, gap=0.5):
    return {"check": "side", "object": o, "other": other, "side": side, "max_gap": gap}


def bt(o, a, b, tol=0.3):
    return {"check": "between", "object": o, "a": a, "b": b, "tol": tol}


def al(o, other, axis, tol=0.05):
    return {"check": "aligned", "object": o, "other": other, "axis": axis, "tol": tol}


def at(o, pos, tol=0.05):
    return {"check": "at", "object": o, "position": pos, "tol": tol}


def fc(o, t, tol=20):
    return {"check": "faces", "object": o, "target": t, "tol": tol}


def sw(o, other):
    return {"check": "swapped", "object": o, "other": other}


def ref(*names):
    return {"check": "refused", "mentions": list(names)}


CUR = None


def _d(a, b):
    ca, cb = centre(OBJ[CUR][a]), centre(OBJ[CUR][b])
    d3 = math.dist(ca, cb)
    d2 = math.hypot(ca[0] - cb[0], ca[2] - cb[2])
    return d2, d3


def closer(o, other, margin):
    """distance check: the centre distance must drop by at least margin (robust to 2-D or 3-D measure)."""
    d2, d3 = _d(o, other)
    return {"check": "distance", "object": o, "other": other, "max": round(min(d2, d3) - margin, 3)}


def farther(o, other, margin):
    d2, d3 = _d(o, other)
    return {"check": "distance", "object": o, "other": other, "min": round(max(d2, d3) + margin, 3)}


def dist(o, other, mn, mx):
    return {"check": "distance", "object": o, "other": other, "min": mn, "max": mx}


QUERIES = []
COUNT = {}


def Q(cat, text, *expect):
    key = (CUR, cat)
    COUNT[key] = COUNT.get(key, 0) + 1
    QUERIES.append({"id": f"{CUR}-{cat}-{COUNT[key]:02d}", "category": cat, "scenes": [CUR],
                    "text": text, "pick": {}, "expect": list(expect)})


SI, CO, FU, CF, HA = "simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"

# =========================================================================== greenhouse
CUR = "greenhouse"
POTS = ["tomato pot", "chilli pot", "basil pot", "parsley pot", "mint pot", "thyme pot"]
BENCH_ITEMS = ["seed tray", "twine", "radio"]

Q(SI, "move the wheelbarrow 1 metre to the right", mv("wheelbarrow", 1, 0, 0), U)
Q(SI, "slide the heater 50cm left", mv("heater", -0.5, 0, 0), U)
Q(SI, "hose reel: back 1 m", mv("hose reel", 0, 0, -1), U)
Q(SI, "Rotate the wheelbarrow 180°", rot("wheelbarrow", 180, True), U)
Q(SI, "make the fan 20% smaller", sc("fan", 0.8), U)
Q(SI, "Can you move the compost bag 30 cm forwards?", mv("compost bag", 0, 0, 0.3), on("sack of bark", "compost bag"), U)
Q(SI, "shift the blue watering can two metres to the left", mv("blue watering can", -2, 0, 0), U)
Q(SI, "turn the fan 45 degrees clockwise", rot("fan", -45), U)
Q(SI, "push the water butt forward 20cm", mv("water butt", 0, 0, 0.2), U)
Q(SI, "move planter 4 half a metre to the left", mv("planter 4", -0.5, 0, 0), U)
Q(SI, "move the potting stool 18 inches to the right", mv("potting stool", 18 * INCH, 0, 0), U)
Q(SI, "could you scale the radio up by 50%?", sc("radio", 1.5), on("radio", "potting bench"), U)
Q(SI, "move the watering can 1 m left", ref("green watering can", "blue watering can"))
Q(SI, "rotate the lawnmower 90 degrees", ref())

Q(CO, "move the staging table 40 cm back, pots and all",
  mv("staging table", 0, 0, -0.4), *[mv(p, 0, 0, -0.4) for p in POTS], U)
Q(CO, "shift planter 6 90cm to the right, trowel included", mv("planter 6", 0.9, 0, 0), mv("trowel", 0.9, 0, 0), U)
Q(CO, "move the wheelbarrow 1 m right and then turn it to face the back wall",
  mv("wheelbarrow", 1, 0, 0), rot("wheelbarrow", 180, True), U)
Q(CO, "put the trowel on planter 3 and the hand fork on planter 1",
  on("trowel", "planter 3"), on("hand fork", "planter 1"), NC, U)
Q(CO, "heater 50 cm left, hose reel 1 m back", mv("heater", -0.5, 0, 0), mv("hose reel", 0, 0, -1), U)
Q(CO, "swap the radio and the twine", sw("radio", "twine"), U)
Q(CO, "turn planters 1, 2 and 3 by 90 degrees each",
  rot("planter 1", 90, True), rot("planter 2", 90, True), rot("planter 3", 90, True), on("hand fork", "planter 2"), U)
Q(CO, "move the potting bench and its stool 30 cm to the right",
  mv("potting bench", 0.3, 0, 0), mv("potting stool", 0.3, 0, 0), *[on(i, "potting bench") for i in BENCH_ITEMS], U)
Q(CO, "put both watering cans on the potting bench",
  on("green watering can", "potting bench"), on("blue watering can", "potting bench"), NC, U)
Q(CO, "rotate the fan 90° and push it 30cm to the left", rot("fan", 90, True), mv("fan", -0.3, 0, 0), U)
Q(CO, "put the sack of bark in the wheelbarrow, then move the wheelbarrow half a metre right",
  on("sack of bark", "wheelbarrow"), mv("wheelbarrow", 0.5, 0, 0), U)
Q(CO, "move the hand fork and the rake over to the potting bench", ref())
Q(CO, "move the hose reel 1 m back and turn it 90 degrees anticlockwise",
  mv("hose reel", 0, 0, -1), rot("hose reel", 90), U)
Q(CO, "put the seed tray on planter 4 and the spray bottle on planter 5",
  on("seed tray", "planter 4"), on("spray bottle", "planter 5"), U)

Q(FU, "nudge the wheelbarow a bit to the right", dr("wheelbarrow", "+x", 0.03), U)
Q(FU, "the heater's too close to the door, move it further left", dr("heater", "-x", 0.1), U)
Q(FU, "shove the hose reel way back, loads", dr("hose reel", "-z", 0.5), IB, U)
Q(FU, "can the blue can go closer to the staging?", closer("blue watering can", "staging table", 0.2), U)
Q(FU, "put the radio up on the shelf", on("radio", "shelf unit"), U)
Q(FU, "the stool is in the way - move it against the left wall",
  at("potting stool", [-5 + 0.175, None, None], 0.08), IB, U)
Q(FU, "move the spary bottle to the potting bench", on("spray bottle", "potting bench"), U)
Q(FU, "wheelbarrow: 2ft left", mv("wheelbarrow", -2 * FT, 0, 0), U)
Q(FU, "I want the water butt a little further forward", dr("water butt", "+z", 0.03), U)
Q(FU, "can the trowel go back on the potting bench", on("trowel", "potting bench"), U)
Q(FU, "the fan should be in the back right corner", at("fan", [4.8, 0, -3.8], 0.1), IB, U)
Q(FU, "nudge the can forward a bit", ref("green watering can", "blue watering can"))
Q(FU, "move the bird feeder a little to the left", ref())
Q(FU, "give the potting stool roughly a quarter turn", rot("potting stool", 90, True), U)

Q(CF, "scoot the potting bench a bit left with all its stuff on it",
  dr("potting bench", "-x", 0.03), *[on(i, "potting bench") for i in BENCH_ITEMS], U)
Q(CF, "take the hand fork off planter 2 and pop it on the staging, then nudge planter 2 a tad left",
  on("hand fork", "staging table"), dr("planter 2", "-x", 0.03), U)
Q(CF, "move the stool and the bench a touch closer to the shelf unit",
  closer("potting stool", "shelf unit", 0.02), closer("potting bench", "shelf unit", 0.02),
  *[on(i, "potting bench") for i in BENCH_ITEMS], U)
Q(CF, "the two end planters of the front row should come forward about 50cm",
  mv("planter 1", 0, 0, 0.5, 0.15), mv("planter 3", 0, 0, 0.5, 0.15), U)
Q(CF, "turn the wheelbarrow round and shove it into the front left corner",
  rot("wheelbarrow", 180, True), at("wheelbarrow", [-4.65, 0, 3.3], 0.12), IB, U)
Q(CF, "cans - both by the door pls",
  nx("green watering can", "door", 0.5), nx("blue watering can", "door", 0.5), NC, U)
Q(CF, "get the bark sack off the compost and just leave it on the floor beside it",
  nx("sack of bark", "compost bag", 0.4), at("sack of bark", [None, 0, None]), NC, U)
Q(CF, "swap the tall tomato with the tiny thyme", sw("tomato pot", "thyme pot"), U)
Q(CF, "rotate every planter in the back row a quarter turn",
  rot("planter 4", 90, True), rot("planter 5", 90, True), rot("planter 6", 90, True), on("trowel", "planter 6"), U)
Q(CF, "could u move the radio right next to the twine", nx("radio", "twine", 0.2), on("radio", "potting bench"), U)
Q(CF, "put the watering can on the staging, and scoot the stool left a bit",
  ref("green watering can", "blue watering can"))
Q(CF, "pull the fan a couple of feet out from the back wall and turn it to face the planters",
  dr("fan", "+z", 0.4), fc("fan", "planter 5"), U)
Q(CF, "put the twine & seed tray up on the shelf unit, and budge the radio a little to the left",
  on("twine", "shelf unit"), on("seed tray", "shelf unit"), dr("radio", "-x", 0.03), on("radio", "potting bench"), U)
Q(CF, "i'd like the mint and basil pots swapped round, and the chilli a little more to the left",
  sw("mint pot", "basil pot"), dr("chilli pot", "-x", 0.02), on("chilli pot", "staging table"), U)

Q(HA, "put the second pot in the front row on the shelf unit", on("chilli pot", "shelf unit"), U)
Q(HA, "planters 4 to 6: move them all 30 cm back",
  mv("planter 4", 0, 0, -0.3), mv("planter 5", 0, 0, -0.3), mv("planter 6", 0, 0, -0.3), mv("trowel", 0, 0, -0.3), U)
Q(HA, "shift all the planters 20 cm left apart from planter 2",
  *[mv(f"planter {i}", -0.2, 0, 0) for i in (1, 3, 4, 5, 6)], mv("trowel", -0.2, 0, 0),
  {"check": "unchanged", "objects": ["planter 2", "hand fork"]}, U)
Q(HA, "put the potting stool between the water butt and the potting bench",
  bt("potting stool", "water butt", "potting bench"), NC, U)
Q(HA, "turn the wheelbarrow so it faces the door", fc("wheelbarrow", "door"), U)
Q(HA, "the tallest pot - move it next to the hose reel", nx("tomato pot", "hose reel"), NC, U)
Q(HA, "move the can by the water butt next to the other can", nx("green watering can", "blue watering can"), NC, U)
Q(HA, "rotate the pot at the back right of the staging by 90 degrees", rot("thyme pot", 90, True), U)
Q(HA, "everything on the potting bench goes onto planter 5", *[on(i, "planter 5") for i in BENCH_ITEMS], NC, U)
Q(HA, "move the middle planter of the back row 10cm forward", mv("planter 5", 0, 0, 0.1), U)
Q(HA, "point the fan at the potting bench", fc("fan", "potting bench"), U)
Q(HA, "move the planter next to planter 5 back by half a metre", ref("planter 4", "planter 6"))
Q(HA, "put the pot at the end of the back row on the shelf", ref("parsley pot", "thyme pot"))
Q(HA, "take the thing lying on planter 6 and put it on planter 4", on("trowel", "planter 4"), U)

# =========================================================================== rehearsal room
CUR = "rehearsal_room"
KIT = ["bass drum", "snare drum", "floor tom", "hi-hat", "ride cymbal", "drum throne"]
CT_ITEMS = ["setlist", "water bottle", "tuner"]

Q(SI, "move the sofa 50 cm to the left", mv("sofa", -0.5, 0, 0), U)
Q(SI, "turn the office chair 90 degrees clockwise", rot("office chair", -90), U)
Q(SI, "Move mic stand 2 one metre forward", mv("mic stand 2", 0, 0, 1), U)
Q(SI, "rotate the keyboard stand 180 degrees", rot("keyboard stand", 180, True), on("keyboard", "keyboard stand"), U)
Q(SI, "make the rug 25% bigger", sc("rug", 1.25), U)
Q(SI, "move the stool 2 ft to the right", mv("stool", 2 * FT, 0, 0), U)
Q(SI, "push the mini fridge 30cm right", mv("mini fridge", 0.3, 0, 0), U)
Q(SI, "spin the music stand round 180°", rot("music stand", 180, True), U)
Q(SI, "Move the guitar case 1 metre back", mv("guitar case", 0, 0, -1), U)
Q(SI, "scale the coffee table down by 10 percent", sc("coffee table", 0.9), *[on(i, "coffee table") for i in CT_ITEMS], U)
Q(SI, "vox amp forward 6 inches", mv("vox amp", 0, 0, 6 * INCH), U)
Q(SI, "turn the bass amp 90 degrees clockwise", rot("bass amp", -90), U)
Q(SI, "move the guitar amp 1 m to the right", ref("marshall amp", "vox amp"))
Q(SI, "move the drum machine 20 cm left", ref())

Q(CO, "move the drum riser 30cm forward with the whole kit on it",
  mv("drum riser", 0, 0, 0.3), *[mv(k, 0, 0, 0.3) for k in KIT], U)
Q(CO, "put the water bottle and the tuner on the mixer table",
  on("water bottle", "mixer table"), on("tuner", "mixer table"), NC, U)
Q(CO, "turn both mic stands to face the sofa", fc("mic stand 1", "sofa"), fc("mic stand 2", "sofa"), U)
Q(CO, "move both PA speakers 50cm back", mv("PA speaker left", 0, 0, -0.5), mv("PA speaker right", 0, 0, -0.5), U)
Q(CO, "swap the marshall and the vox", sw("marshall amp", "vox amp"), U)
Q(CO, "move the coffee table 40 cm right along with everything on it",
  mv("coffee table", 0.4, 0, 0), *[mv(i, 0.4, 0, 0) for i in CT_ITEMS], U)
Q(CO, "move the office chair 40 cm left and turn it to face the mixer table",
  mv("office chair", -0.4, 0, 0), fc("office chair", "mixer table"), U)
Q(CO, "put the setlist on the music stand and the music stand in front of mic stand 1",
  on("setlist", "music stand"), sd("music stand", "mic stand 1", "front", 0.6), NC, U)
Q(CO, "stool and bass amp both 50cm forward", mv("stool", 0, 0, 0.5), mv("bass amp", 0, 0, 0.5), U)
Q(CO, "put the laptop on the coffee table and the tuner on the mixer table",
  on("laptop", "coffee table"), on("tuner", "mixer table"), U)
Q(CO, "turn the hi-hat and the ride cymbal 90 degrees each",
  rot("hi-hat", 90, True), rot("ride cymbal", 90, True), U)
Q(CO, "move mic stand 1 to where mic stand 2 is, and mic stand 2 to where 1 was", sw("mic stand 1", "mic stand 2"), U)
Q(CO, "put the PA speaker on the coffee table and the tuner on the mixer", ref("PA speaker left", "PA speaker right"))
Q(CO, "move the mini fridge and the guitar case 50 cm to the right",
  mv("mini fridge", 0.5, 0, 0), mv("guitar case", 0.5, 0, 0), U)

Q(FU, "scooch the sofa a bit to the right", dr("sofa", "+x", 0.03), U)
Q(FU, "mic stand 1 - a few cm left", dr("mic stand 1", "-x", 0.02), U)
Q(FU, "can the stool go a lot closer to the drums?", closer("stool", "bass drum", 0.3), U)
Q(FU, "the bass amp should be right up against the left wall", at("bass amp", [-4 + 0.225, None, None], 0.08), IB, U)
Q(FU, "turn the office chair so it faces the door", fc("office chair", "door"), U)
Q(FU, "move the water botle onto the mixer table", on("water bottle", "mixer table"), U)
Q(FU, "get the tuner off the coffee table and onto the keyboard", on("tuner", "keyboard"), U)
Q(FU, "Pull the rug forward a little", dr("rug", "+z", 0.03), U)
Q(FU, "bring the right PA a foot further in from the wall", mv("PA speaker right", -FT, 0, 0, 0.1), U)
Q(FU, "turn the vox around", rot("vox amp", 180, True), U)
Q(FU, "Could you move the throne a smidge back?", dr("drum throne", "-z", 0.02), on("drum throne", "drum riser"), U)
Q(FU, "shift the speaker a bit left", ref("PA speaker left", "PA speaker right"))
Q(FU, "nudge the cowbell forward", ref())
Q(FU, "I'd like the floor tom a tiny bit nearer the snare",
  closer("floor tom", "snare drum", 0.02), on("floor tom", "drum riser"), U)

Q(CF, "take everything off the coffee table and put it on top of the mini fridge, then push the coffee table a bit toward the sofa",
  *[on(i, "mini fridge") for i in CT_ITEMS], closer("coffee table", "sofa", 0.03), NC, U)
Q(CF, "both PA speakers a touch further apart", farther("PA speaker left", "PA speaker right", 0.03), IB, U)
Q(CF, "shove the snare and the hi-hat a bit left",
  dr("snare drum", "-x", 0.03), dr("hi-hat", "-x", 0.03), on("snare drum", "drum riser"), on("hi-hat", "drum riser"), U)
Q(CF, "put the laptop on the fridge and turn the office chair round to face the sofa",
  on("laptop", "mini fridge"), fc("office chair", "sofa"), U)
Q(CF, "I'd like mic stand 1 and mic stand 2 closer together, about a metre apart",
  dist("mic stand 1", "mic stand 2", 0.8, 1.25), U)
Q(CF, "move the marshall amp next to the bass amp and point it at the drum throne",
  nx("marshall amp", "bass amp"), fc("marshall amp", "drum throne"), NC, U)
Q(CF, "the setlist goes on the keyboard, and shift the keyboard stand (keyboard and all) a little left",
  on("setlist", "keyboard"), dr("keyboard stand", "-x", 0.03), on("keyboard", "keyboard stand"), U)
Q(CF, "bring the stool over closer to mic stand 1", closer("stool", "mic stand 1", 0.05), U)
Q(CF, "move the rug back a tad towards the drums", dr("rug", "-z", 0.03), U)
Q(CF, "can the fridge and the guitar case swap places?", sw("mini fridge", "guitar case"), U)
Q(CF, "move the amp closer to the drums and the stool to the right", ref("marshall amp", "vox amp", "bass amp"))
Q(CF, "turn the office chair to face the drums and roll it a bit closer to them",
  fc("office chair", "bass drum"), closer("office chair", "bass drum", 0.05), U)
Q(CF, "mic stand 2 - stick it in front of the keyboard", sd("mic stand 2", "keyboard", "front", 0.6), NC, U)
Q(CF, "chuck the bottle n tuner on the fridge and the setlist on top of the vox",
  on("water bottle", "mini fridge"), on("tuner", "mini fridge"), on("setlist", "vox amp"), U)

Q(HA, "move every drum and cymbal on the riser 10 cm right, but leave the throne where it is",
  *[mv(k, 0.1, 0, 0) for k in KIT[:5]], {"check": "unchanged", "objects": ["drum throne", "drum riser"]}, U)
Q(HA, "put the marshall amp between the two mic stands", bt("marshall amp", "mic stand 1", "mic stand 2"), U)
Q(HA, "turn the left PA speaker to face the sofa", fc("PA speaker left", "sofa"), U)
Q(HA, "the amp on the right: move it 1m to the left", mv("vox amp", -1, 0, 0), U)
Q(HA, "move the chair that's by the mixer closer to the door", closer("office chair", "door", 0.3), U)
Q(HA, "move the keyboard stand and the keyboard on it 40 cm back",
  mv("keyboard stand", 0, 0, -0.4), mv("keyboard", 0, 0, -0.4), U)
Q(HA, "turn the guitar amp to face the sofa", ref("marshall amp", "vox amp"))
Q(HA, "move the speaker by the wall forward 20 cm", ref("PA speaker left", "PA speaker right"))
Q(HA, "put the stool to the left of the marshall amp", sd("stool", "marshall amp", "left"), NC, U)
Q(HA, "rotate the cymbal to the left of the snare by 45 degrees", rot("hi-hat", 45, True), U)
Q(HA, "put both PA speakers against the back wall, one either side of the drum riser",
  at("PA speaker left", [None, None, -3.5 + 0.175], 0.08), at("PA speaker right", [None, None, -3.5 + 0.175], 0.08),
  sd("PA speaker left", "drum riser", "left", 2.5), sd("PA speaker right", "drum riser", "right", 2.5), NC, U)
Q(HA, "swap the stool and the drum throne", sw("stool", "drum throne"), U)
Q(HA, "put the water bottle on the tallest amp", on("water bottle", "bass amp"), U)
Q(HA, "put the setlist on whichever amp is nearest the keyboard", on("setlist", "vox amp"), U)

# =========================================================================== salon
CUR = "salon"
CH = {i: f"SM_SalonChair_0{i}" for i in range(1, 5)}
TR = {i: f"BP_Trolley_0{i}" for i in range(1, 5)}
MAGS = ["SM_Magazine_01", "SM_Magazine_02"]

Q(SI, "move SM_SalonChair_02 30cm forward", mv(CH[2], 0, 0, 0.3), U)
Q(SI, "rotate BP_Lamp_A 90 degrees", rot("BP_Lamp_A", 90, True), U)
Q(SI, "move the waiting sofa 40 cm to the left", mv("SM_Sofa_Waiting", -0.4, 0, 0), U)
Q(SI, "make SM_PlantPot_Small twice as big", sc("SM_PlantPot_Small", 2), on("SM_PlantPot_Small", "SM_ReceptionDesk"), U)
Q(SI, "SM_Bin_01 1m forward", mv("SM_Bin_01", 0, 0, 1), U)
Q(SI, "turn the office chair 180 degrees", rot("SM_OfficeChair_01", 180, True), U)
Q(SI, "move trolley 3 20cm to the right", mv(TR[3], 0.2, 0, 0), U)
Q(SI, "scale the coffee table up 10%", sc("SM_CoffeeTable", 1.1), *[on(m, "SM_CoffeeTable") for m in MAGS], U)
Q(SI, "push SM_WashChair_B 25 cm to the left", mv("SM_WashChair_B", -0.25, 0, 0), U)
Q(SI, "move BP_Lamp_B 2'6\" back", mv("BP_Lamp_B", 0, 0, -(2 * FT + 6 * INCH)), U)
Q(SI, "rotate SM_Chair_Waiting_01 by 30 degrees anticlockwise", rot("SM_Chair_Waiting_01", 30), U)
Q(SI, "shift the coffee table 6\" right", mv("SM_CoffeeTable", 6 * INCH, 0, 0), *[on(m, "SM_CoffeeTable") for m in MAGS], U)
Q(SI, "move the magazine 10cm left", ref(*MAGS))
Q(SI, "move SM_Chair_05 forward 50cm", ref())

Q(CO, "move station 2's chair and trolley 20 cm right", mv(CH[2], 0.2, 0, 0), mv(TR[2], 0.2, 0, 0), on("SM_Comb_02", TR[2]), U)
Q(CO, "swap SM_SalonChair_01 and SM_SalonChair_04", sw(CH[1], CH[4]), U)
Q(CO, "put the hairdryer on trolley 1 and the spray bottle on trolley 3",
  on("SM_Hairdryer_01", TR[1]), on("SM_SprayBottle_03", TR[3]), U)
Q(CO, "rotate both wash chairs so they face their wash units",
  fc("SM_WashChair_A", "SM_WashUnit_A"), fc("SM_WashChair_B", "SM_WashUnit_B"), U)
Q(CO, "move the coffee table and both magazines 50cm left",
  mv("SM_CoffeeTable", -0.5, 0, 0), *[mv(m, -0.5, 0, 0) for m in MAGS], U)
Q(CO, "move BP_Lamp_A 50cm right and the bin 50cm back", mv("BP_Lamp_A", 0.5, 0, 0), mv("SM_Bin_01", 0, 0, -0.5), U)
Q(CO, "turn salon chairs 1 to 4 round 180 degrees", *[rot(CH[i], 180, True) for i in range(1, 5)], U)
Q(CO, "Put both magazines on the reception desk", *[on(m, "SM_ReceptionDesk") for m in MAGS], NC, U)
Q(CO, "move the whole of station 4 30cm to the left - counter, mirror, chair and trolley",
  mv("SM_StationCounter_04", -0.3, 0, 0), mv("SM_Mirror_04", -0.3, 0, 0), mv(CH[4], -0.3, 0, 0), mv(TR[4], -0.3, 0, 0), U)
Q(CO, "move the office chair 30cm back and turn it 90° clockwise",
  mv("SM_OfficeChair_01", 0, 0, -0.3), rot("SM_OfficeChair_01", -90), U)
Q(CO, "scale both lamps by 1.2", sc("BP_Lamp_A", 1.2), sc("BP_Lamp_B", 1.2), U)
Q(CO, "put the comb on the coffee table and the till on trolley 2",
  on("SM_Comb_02", "SM_CoffeeTable"), on("SM_Till", TR[2]), U)
Q(CO, "put the towel stack and the magazine on the sofa", ref(*MAGS))
Q(CO, "move wash unit A and its chair 30 cm back", mv("SM_WashUnit_A", 0, 0, -0.3), mv("SM_WashChair_A", 0, 0, -0.3), U)

Q(FU, "chair 3 a bit closer to its mirror", dr(CH[3], "-z", 0.03), U)
Q(FU, "the waiting sofa's a touch too far right", dr("SM_Sofa_Waiting", "-x", 0.03), U)
Q(FU, "bin -> back left corner please", at("SM_Bin_01", [-4.85, 0, -3.35], 0.1), IB, U)
Q(FU, "turn the seat behind the reception desk to face the door", fc("SM_OfficeChair_01", "SM_Door_Front"), U)
Q(FU, "Move the trolly from station 4 a tiny bit left", dr(TR[4], "-x", 0.02), U)
Q(FU, "the small plant belongs on the coffee table", on("SM_PlantPot_Small", "SM_CoffeeTable"), U)
Q(FU, "Put the hair dryer on station 2", on("SM_Hairdryer_01", "SM_StationCounter_02"), U)
Q(FU, "I want the wash chairs pulled out further from the basins",
  dr("SM_WashChair_A", "-x", 0.05), dr("SM_WashChair_B", "-x", 0.05), U)
Q(FU, "scoot the coffee table a bit toward the sofa",
  closer("SM_CoffeeTable", "SM_Sofa_Waiting", 0.03), *[on(m, "SM_CoffeeTable") for m in MAGS], U)
Q(FU, "the till should be at the other end of the desk",
  dr("SM_Till", "-x", 0.4), on("SM_Till", "SM_ReceptionDesk"), NC, U)
Q(FU, "turn salon chair 2 a quarter turn clockwise", rot(CH[2], -90), U)
Q(FU, "move the trolley a bit left", ref(*TR.values()))
Q(FU, "push the bin up against the wall it's nearest", at("SM_Bin_01", [-4.85, None, None], 0.08), IB, U)
Q(FU, "SM_TowelStack_01 -> on trolley 4 pls", on("SM_TowelStack_01", TR[4]), U)

Q(CF, "pull station 3's chair and trolley out a little", dr(CH[3], "+z", 0.03), dr(TR[3], "+z", 0.03), U)
Q(CF, "put both mags on the reception desk and nudge the coffee table a bit closer to the waiting chair by the door",
  *[on(m, "SM_ReceptionDesk") for m in MAGS], closer("SM_CoffeeTable", "SM_Chair_Waiting_02", 0.03), U)
Q(CF, "move the bin next to BP_Lamp_A and the plant pot next to the till",
  nx("SM_Bin_01", "BP_Lamp_A"), nx("SM_PlantPot_Small", "SM_Till", 0.2), on("SM_PlantPot_Small", "SM_ReceptionDesk"), NC, U)
Q(CF, "I'd like chairs 1 and 2 swapped, and chair 3 turned around", sw(CH[1], CH[2]), rot(CH[3], 180, True), U)
Q(CF, "towel stack onto wash unit A, and the bin beside wash unit B",
  on("SM_TowelStack_01", "SM_WashUnit_A"), nx("SM_Bin_01", "SM_WashUnit_B", 0.4), NC, U)
Q(CF, "both waiting chairs: scoot them a tad closer to the sofa",
  closer("SM_Chair_Waiting_01", "SM_Sofa_Waiting", 0.02), closer("SM_Chair_Waiting_02", "SM_Sofa_Waiting", 0.02), U)
Q(CF, "move trolleys 1 and 2 forward a fair bit, maybe 40cm, and leave the others",
  mv(TR[1], 0, 0, 0.4, 0.1), mv(TR[2], 0, 0, 0.4, 0.1), on("SM_Comb_02", TR[2]), U)
Q(CF, "get the hairdryer off the counter and onto the trolley beside it", on("SM_Hairdryer_01", TR[1]), U)
Q(CF, "Turn every salon chair except no. 4 round so it faces the room",
  *[rot(CH[i], 180, True) for i in (1, 2, 3)], {"check": "unchanged", "objects": [CH[4]]}, U)
Q(CF, "wash unit B + its chair: move them forward ~30cm",
  mv("SM_WashUnit_B", 0, 0, 0.3, 0.08), mv("SM_WashChair_B", 0, 0, 0.3, 0.08), U)
Q(CF, "nudge the mirror forward a tiny bit", ref(*[f"SM_Mirror_0{i}" for i in range(1, 5)]))
Q(CF, "make the little plant 50% bigger and slide it a bit toward the middle of the desk",
  sc("SM_PlantPot_Small", 1.5), dr("SM_PlantPot_Small", "+x", 0.03), on("SM_PlantPot_Small", "SM_ReceptionDesk"), U)
Q(CF, "chair 2: turn it to face the reception desk and roll it a little closer",
  fc(CH[2], "SM_ReceptionDesk"), closer(CH[2], "SM_ReceptionDesk", 0.05), U)
Q(CF, "swap the lamp and the bin", ref("BP_Lamp_A", "BP_Lamp_B"))

Q(HA, "stations 2 to 4: push each chair 20cm further from its mirror",
  *[mv(CH[i], 0, 0, 0.2) for i in (2, 3, 4)], {"check": "unchanged", "objects": [CH[1]]}, U)
Q(HA, "the two little things on the station counters (not the mirrors) - move them onto the coffee table",
  on("SM_Hairdryer_01", "SM_CoffeeTable"), on("SM_SprayBottle_03", "SM_CoffeeTable"), U)
Q(HA, "move the trolley between chairs 2 and 3 next to chair 1",
  nx(TR[2], CH[1]), on("SM_Comb_02", TR[2]), NC, U)
Q(HA, "turn the chair by the wash unit to face the door", ref("SM_WashChair_A", "SM_WashChair_B"))
Q(HA, "put the comb on the counter that only has a mirror on it",
  ref("SM_StationCounter_02", "SM_StationCounter_04"))
Q(HA, "put the comb on the empty counter nearest the door", on("SM_Comb_02", "SM_StationCounter_02"), U)
Q(HA, "face SM_SalonChair_04 toward the waiting sofa", fc(CH[4], "SM_Sofa_Waiting"), U)
Q(HA, "move the rightmost trolley next to wash chair A", nx(TR[4], "SM_WashChair_A"), NC, U)
Q(HA, "move the chairs either side of the sofa 50cm back",
  mv("SM_Chair_Waiting_01", 0, 0, -0.5), mv("SM_Chair_Waiting_02", 0, 0, -0.5), U)
Q(HA, "put the plant pot between the two magazines",
  bt("SM_PlantPot_Small", *MAGS), on("SM_PlantPot_Small", "SM_CoffeeTable"), U)
Q(HA, "the mirror at the station whose chair is closest to the towel shelf: 10 cm left",
  mv("SM_Mirror_01", -0.1, 0, 0), U)
Q(HA, "move every trolley except the one at station 1 10cm back",
  *[mv(TR[i], 0, 0, -0.1) for i in (2, 3, 4)], mv("SM_Comb_02", 0, 0, -0.1),
  {"check": "unchanged", "objects": [TR[1]]}, U)
Q(HA, "turn the waiting chair closest to the door so it faces the coffee table",
  fc("SM_Chair_Waiting_02", "SM_CoffeeTable"), U)
Q(HA, "put the towel stack on the trolley next to salon chair 3", on("SM_TowelStack_01", TR[3]), U)

# =========================================================================== warehouse
CUR = "warehouse"
P14 = ["Cube.012", "Cube.013", "Cube.014"]

Q(SI, "move Object_7 2 metres to the left", mv("Object_7", -2, 0, 0), U)
Q(SI, "rotate Cube.027 by 90 degrees", rot("Cube.027", 90, True), U)
Q(SI, "Mesh_015 -> 1 m right", mv("Mesh_015", 1, 0, 0), U)
Q(SI, "scale Cylinder.004 by 0.5", sc("Cylinder.004", 0.5), U)
Q(SI, "move Body1 1.5 m forward", mv("Body1", 0, 0, 1.5), U)
Q(SI, "turn mesh_18 90° clockwise", rot("mesh_18", -90), U)
Q(SI, "move Cone.002 3 feet back", mv("Cone.002", 0, 0, -3 * FT), U)
Q(SI, "move Cube.028 half a metre left", mv("Cube.028", -0.5, 0, 0), on("Cube.030", "Cube.028"), U)
Q(SI, "Mesh_020 forward by 1m", mv("Mesh_020", 0, 0, 1), U)
Q(SI, "rotate Object_7 180 degrees", rot("Object_7", 180, True), U)
Q(SI, "move Cylinder.005 40 cm to the left", mv("Cylinder.005", -0.4, 0, 0), U)
Q(SI, "Body3 30 cm left please", mv("Body3", -0.3, 0, 0), on("Body3", "PART_0041"), U)
Q(SI, "move Cube.099 1m right", ref())
Q(SI, "move the cone 1 m back", ref("Cone.001", "Cone.002"))

Q(CO, "move Mesh_014 and everything on it 1 metre forward",
  mv("Mesh_014", 0, 0, 1), *[mv(c, 0, 0, 1) for c in P14], U)
Q(CO, "swap Cylinder.004 and Cylinder.005", sw("Cylinder.004", "Cylinder.005"), U)
Q(CO, "put Cube.030 on Cube.027 and Cube.032 on Cube.028", on("Cube.030", "Cube.027"), on("Cube.032", "Cube.028"), U)
Q(CO, "move the two cones 1m left", mv("Cone.001", -1, 0, 0), mv("Cone.002", -1, 0, 0), U)
Q(CO, "turn mesh_18 180 degrees and push it 30 cm back", rot("mesh_18", 180, True), mv("mesh_18", 0, 0, -0.3), U)
Q(CO, "move PART_0041 and the things on it 50cm left",
  mv("PART_0041", -0.5, 0, 0), mv("PART_0042", -0.5, 0, 0), mv("Body3", -0.5, 0, 0), U)
Q(CO, "put Cube.012 and Cube.013 on Mesh_015",
  on("Cube.012", "Mesh_015"), on("Cube.013", "Mesh_015"), on("Cube.014", "Cube.012"), NC, U)
Q(CO, "move Assembly_5 60cm forward and put the extinguisher next to it",
  mv("Assembly_5", 0, 0, 0.6), on("Cube.031", "Assembly_5"), on("Cube.032", "Assembly_5"),
  nx("Mesh_020", "Assembly_5"), NC, U)
Q(CO, "rotate Cube.028 and Cube.027 by 45 degrees",
  rot("Cube.028", 45, True), rot("Cube.027", 45, True), on("Cube.030", "Cube.028"), U)
Q(CO, "move mesh_17, mesh_18 and mesh_19 1 m to the left",
  mv("mesh_17", -1, 0, 0), mv("mesh_18", -1, 0, 0), mv("mesh_19", -1, 0, 0), on("Cylinder.009", "mesh_17"), U)
Q(CO, "put Cylinder.009 on PART_0041 and Body3 on mesh_17", on("Cylinder.009", "PART_0041"), on("Body3", "mesh_17"), U)
Q(CO, "scale Cone.001 and Cone.002 up by 1.5", sc("Cone.001", 1.5), sc("Cone.002", 1.5), U)
Q(CO, "move Mesh_016 and Cylinder.003 half a metre back",
  mv("Mesh_016", 0, 0, -0.5), mv("Cylinder.003", 0, 0, -0.5), U)
Q(CO, "take Cube.014 off Cube.012 and put it on Cube.013, then rotate Cube.012 90 degrees",
  on("Cube.014", "Cube.013"), rot("Cube.012", 90, True), U)

Q(FU, "move the tall box by the door a bit to the left", dr("Cube.027", "-x", 0.03), U)
Q(FU, "the drum on the pallet - shift it slightly right",
  dr("Cylinder.003", "+x", 0.02), on("Cylinder.003", "Mesh_016"), U)
Q(FU, "push the desk against the right wall",
  at("mesh_17", [6 - 0.7, None, None], 0.08), on("mesh_19", "mesh_17"), on("Cylinder.009", "mesh_17"), IB, U)
Q(FU, "can the empty pallet go next to the tall box?", nx("Mesh_015", "Cube.027"), NC, U)
Q(FU, "turn the chair at the desk round to face the door", fc("mesh_18", "Plane.004"), U)
Q(FU, "put the little cube from the short box onto the long bench at the back", on("Cube.030", "PART_0041"), U)
Q(FU, "Cube.27 should be about 50 cm further right", mv("Cube.027", 0.5, 0, 0, 0.1), U)
Q(FU, "move Body1 a lot closer to PART_0041", closer("Body1", "PART_0041", 0.5), U)
Q(FU, "the smaller box up on the left shelving - move it to the desk", on("Cube.032", "mesh_17"), U)
Q(FU, "drums by the right wall: both a little further from the wall",
  dr("Cylinder.004", "-x", 0.03), dr("Cylinder.005", "-x", 0.03), U)
Q(FU, "Object 7: quarter turn anticlockwise", rot("Object_7", 90), U)
Q(FU, "move the box by the door 1 m left", ref("Cube.027", "Cube.028"))
Q(FU, "take the box on the shelf down to the floor", ref("Cube.031", "Cube.032"))
Q(FU, "shove the extinguisher into the front left corner", at("Mesh_020", [-5.9, 0, 4.9], 0.1), IB, U)

Q(CF, "shift the pallet with the 3 boxes a bit towards the door, boxes too",
  dr("Mesh_014", "+z", 0.03), on("Cube.012", "Mesh_014"), on("Cube.013", "Mesh_014"), on("Cube.014", "Cube.012"), U)
Q(CF, "put both small boxes from the shelf on the empty pallet",
  on("Cube.031", "Mesh_015"), on("Cube.032", "Mesh_015"), NC, U)
Q(CF, "swap the tall box by the door with the short one", sw("Cube.027", "Cube.028"), on("Cube.030", "Cube.028"), U)
Q(CF, "take the mug off the desk, stick it on the bigger of the two things on the back bench, and slide the desk chair a bit left",
  on("Cylinder.009", "Body3"), dr("mesh_18", "-x", 0.03), U)
Q(CF, "the stack of two boxes on the pallet: put it on the floor right next to the pallet",
  at("Cube.012", [None, 0, None]), nx("Cube.012", "Mesh_014", 0.4), on("Cube.014", "Cube.012"), NC, U)
Q(CF, "I'd like the drum that's on the pallet moved over by the other two drums",
  dist("Cylinder.003", "Cylinder.004", 0, 1.6), dist("Cylinder.003", "Cylinder.005", 0, 1.6), NC, U)
Q(CF, "the tall box: give it a 45° twist and move it back from the door a bit",
  rot("Cube.027", 45, True), dr("Cube.027", "-z", 0.03), IB, U)
Q(CF, "swap the two little things on the back bench", sw("PART_0042", "Body3"), U)
Q(CF, "push Assembly_5 (and what's on it) flush against the back wall",
  at("Assembly_5", [None, None, -5 + 0.5], 0.08), on("Cube.031", "Assembly_5"), on("Cube.032", "Assembly_5"), IB, U)
Q(CF, "both cones a little closer to each other", closer("Cone.001", "Cone.002", 0.03), U)
Q(CF, "lift the box on the pallet onto the desk and tuck the chair in", ref("Cube.012", "Cube.013"))
Q(CF, "move Object_7 a good way toward the door and turn it to face it",
  dr("Object_7", "+z", 0.5), fc("Object_7", "Plane.004"), U)
Q(CF, "the chair + desk + monitor: move them together a bit towards the back",
  dr("mesh_17", "-z", 0.03), dr("mesh_18", "-z", 0.03), dr("mesh_19", "-z", 0.03), on("Cylinder.009", "mesh_17"), U)
Q(CF, "put the little cube onto the tall box and move the short box a bit to the right",
  on("Cube.030", "Cube.027"), dr("Cube.028", "+x", 0.03), U)

Q(HA, "the pallet with the drum on it: 1m to the right, drum included",
  mv("Mesh_016", 1, 0, 0), mv("Cylinder.003", 1, 0, 0), U)
Q(HA, "put the smaller of the two boxes near the door on top of the bigger one",
  on("Cube.028", "Cube.027"), on("Cube.030", "Cube.028"), U)
Q(HA, "move all three pallets 50 cm to the right, loads and all",
  *[mv(o, 0.5, 0, 0) for o in ["Mesh_014", *P14, "Mesh_015", "Mesh_016", "Cylinder.003"]], U)
Q(HA, "face Object_7 towards the door", fc("Object_7", "Plane.004"), U)
Q(HA, "put the extinguisher between the two cones", bt("Mesh_020", "Cone.001", "Cone.002"), NC, U)
Q(HA, "the tall rack nearest PART_0041: 20cm right", mv("Assembly_4", 0.2, 0, 0), U)
Q(HA, "move the rack 50cm right", ref("Assembly_3", "Assembly_4"))
Q(HA, "put Cube.014 on the drum nearest the desk", on("Cube.014", "Cylinder.005"), U)
Q(HA, "move Body1 forward until it's level with Object_7", al("Body1", "Object_7", "z", 0.1), dr("Body1", "+z", 1.5), U)
Q(HA, "move the monitor so it's centred on the desk", at("mesh_19", [4.8, 0.75, 3.5], 0.05), U)
Q(HA, "move the cylinder by the right wall 50cm left", ref("Cylinder.004", "Cylinder.005"))
Q(HA, "put the smallest object in the room on the long bench", on("Cylinder.009", "PART_0041"), U)
Q(HA, "the box that's stacked on another box: put it on the floor in front of the tall box",
  ref("Cube.014", "Cube.030"))
Q(HA, "Cube.013 next to the extinguisher, on the floor",
  nx("Cube.013", "Mesh_020"), at("Cube.013", [None, 0, None]), NC, U)

# --------------------------------------------------------------------------- write

FILES = {"greenhouse": "greenhouse.json", "rehearsal_room": "rehearsal_room.json",
         "salon": "salon.json", "warehouse": "warehouse.json"}


def main():
    for sn, fn in FILES.items():
        with open(os.path.join(HERE, fn), "w") as f:
            json.dump(SCENES[sn], f, indent=1)
            f.write("\n")
    suite = {"name": "holdout9", "scenes": list(FILES.values()), "variations": 1, "seed": 9,
             "queries": QUERIES}
    with open(os.path.join(HERE, "holdout9.suite.json"), "w") as f:
        json.dump(suite, f, indent=1, ensure_ascii=False)
        f.write("\n")
    print(f"wrote {len(FILES)} scenes, {len(QUERIES)} queries")


if __name__ == "__main__":
    main()
