import math
FT = 0.3048; IN = 0.0254
QUERIES = []
_count = {}
PREFIX = {"hotel_lobby.json": "lobby", "playroom_blender.json": "play",
          "restaurant_kitchen.json": "kitchen", "reading_room.json": "reading"}

def Q(scene, cat, text, *checks, tag=None):
    p = PREFIX[scene]
    key = (p, cat)
    _count[key] = _count.get(key, 0) + 1
    qid = f"{p}-{cat.replace('_','-')}-{_count[key]:02d}"
    QUERIES.append({"id": qid, "category": cat, "scenes": [scene], "text": text, "expect": list(checks)})

def r(v): return round(v, 4)
def mv(o, d, tol=0.05): return {"check": "moved", "object": o, "delta": [r(x) for x in d], "tol": tol}
def dr(o, axis, mn=0.05): return {"check": "direction", "object": o, "axis": axis, "min": mn}
def rot(o, deg, either=False):
    c = {"check": "rotated", "object": o, "axis": "y", "degrees": deg}
    if either: c["either_sign"] = True
    return c
def sc(o, f, tol=0.02): return {"check": "scaled", "object": o, "factor": f, "tol": tol}
def on(o, s, tol=None):
    c = {"check": "on_top", "object": o, "support": s}
    if tol is not None: c["tol"] = tol
    return c
def nt(o, other, gap=0.3): return {"check": "next_to", "object": o, "other": other, "max_gap": gap}
def side(o, other, sd, gap=0.5): return {"check": "side", "object": o, "other": other, "side": sd, "max_gap": gap}
def betw(o, a, b, tol=0.3): return {"check": "between", "object": o, "a": a, "b": b, "tol": tol}
def al(o, other, axis, tol=0.05): return {"check": "aligned", "object": o, "other": other, "axis": axis, "tol": tol}
def at(o, pos, tol=0.05): return {"check": "at", "object": o, "position": [r(x) for x in pos], "tol": tol}
def faces(o, t, tol=20): return {"check": "faces", "object": o, "target": t, "tol": tol}
def dist(o, other, mn=None, mx=None):
    c = {"check": "distance", "object": o, "other": other}
    if mn is not None: c["min"] = mn
    if mx is not None: c["max"] = mx
    return c
def above(o, other): return {"check": "above", "object": o, "other": other}
def un(objs="others"): return {"check": "unchanged", "objects": objs}
def nc(): return {"check": "no_collision"}
def ib(): return {"check": "inside_bounds"}
def ref(m): return {"check": "refused", "mentions": list(m)}
def sw(o, other): return {"check": "swapped", "object": o, "other": other}
