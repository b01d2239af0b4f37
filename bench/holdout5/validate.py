#!/usr/bin/env python3
"""Validates bench/holdout5 (stdlib only).  Run: python3 validate.py   (exit 0 = everything passes)

What it checks
  1. The suite's shape: only SPEC section 6 checks and their fields, the five categories, unique ids
     and texts, one scene per query (the `scenes` extension of docs/benchmark.md), no placeholders,
     every non-refusal query ends with `no_collision` and `unchanged others`, tolerances within
     0.02-0.05 m for `moved` and 3 degrees for `rotated`.
  2. The scenes: unique names (case-insensitive), sizes > 0, unit yaw-only quaternions, no
     `category` / `aliases`, everything inside the bounds, no two boxes overlapping, every object
     either on the floor, or resting exactly on the top of one support with its footprint inside
     that top, or (build.WALL) hanging on a wall it touches; build.ON equals the resting tree the
     geometry gives.
  3. Names: every object a check names exists in the query's scene.
  4. Refusals: build.REFUSE says why (an ambiguous phrase -> the keywords every candidate's name
     holds: at least two objects match and the mentions are among them; a missing object -> no
     name holds the word and the mentions are empty).
  5. Every non-refusal query: each hand-worked reading (build.ANS, or one derived from exact
     `moved` / `rotated` / `faces` checks, two readings - smallest and generous - for `direction`)
     is applied to the scene (things resting on a moved object go with it unless an `unchanged`
     list holds them; the resting tree is re-read from the geometry before every step) and must
     pass every check of the query as this file reads them (docs/benchmark.md's table), create no
     collision, leave nothing outside the room and leave nothing floating; `touch` assertions
     (contact words) must end with the two boxes face to face.
"""
import itertools
import json
import math
import os
import re
import sys

sys.dont_write_bytecode = True
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import build  # noqa: E402

EPS = 1e-6
OVERLAP = 1e-4  # boxes overlapping by <= 0.1 mm on some axis only touch
CATEGORIES = {"simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"}
CHECKS = {  # SPEC section 6 only
    "moved": ({"object"}, {"delta", "tol"}),
    "direction": ({"object", "axis"}, {"min"}),
    "rotated": ({"object"}, {"axis", "degrees", "either_sign", "tol"}),
    "scaled": ({"object", "factor"}, {"tol"}),
    "on_top": ({"object", "support"}, {"tol"}),
    "next_to": ({"object", "other"}, {"max_gap"}),
    "side": ({"object", "other", "side"}, {"max_gap"}),
    "above": ({"object", "other"}, {"tol"}),
    "below": ({"object", "other"}, {"tol"}),
    "between": ({"object", "a", "b"}, {"tol"}),
    "aligned": ({"object", "other", "axis"}, {"tol"}),
    "at": ({"object", "position"}, {"tol"}),
    "faces": ({"object", "target"}, {"tol"}),
    "distance": ({"object", "other"}, {"min", "max"}),
    "unchanged": (set(), {"objects"}),
    "no_collision": (set(), set()),
    "inside_bounds": (set(), set()),
    "refused": (set(), {"mentions"}),
}
NAME_FIELDS = ("object", "other", "support", "a", "b", "target")
AXES = {"+x": (0, 1), "-x": (0, -1), "+y": (1, 1), "-y": (1, -1), "+z": (2, 1), "-z": (2, -1)}
GENEROUS = {0.01: 0.08, 0.02: 0.1, 0.03: 0.15}
FT, IN = 0.3048, 0.0254

errors, notes = [], []


def err(m):
    errors.append(m)


# ------------------------------------------------------------------ geometry
def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz]


def qrot(q, v):
    x, y, z, w = q
    return qmul(qmul(q, [v[0], v[1], v[2], 0]), [-x, -y, -z, w])[:3]


def yawq(deg):
    h = math.radians(deg) / 2
    return [0, math.sin(h), 0, math.cos(h)]


def yaw_of(q):
    return math.degrees(2 * math.atan2(q[1], q[3]))


def wrap(a):
    return (a + 180) % 360 - 180


class Obj:
    def __init__(self, d):
        self.name = d["name"]
        self.size = list(d["size"])
        self.pos = list(d["position"])
        self.rot = list(d.get("rotation", [0, 0, 0, 1]))
        self.scale = d.get("scale", 1.0)
        self.front = d.get("front", [0, 0, 1])

    def copy(self):
        o = Obj.__new__(Obj)
        o.__dict__ = {k: (list(v) if isinstance(v, list) else v) for k, v in self.__dict__.items()}
        return o

    def box(self):
        w, h, d = (s * self.scale for s in self.size)
        lo, hi = [1e18] * 3, [-1e18] * 3
        for c in itertools.product((-w / 2, w / 2), (0, h), (-d / 2, d / 2)):
            p = qrot(self.rot, c)
            for i in range(3):
                lo[i] = min(lo[i], p[i] + self.pos[i])
                hi[i] = max(hi[i], p[i] + self.pos[i])
        return lo, hi

    def centre(self):
        lo, hi = self.box()
        return [(lo[i] + hi[i]) / 2 for i in range(3)]

    def bottom(self):
        lo, hi = self.box()
        return [(lo[0] + hi[0]) / 2, lo[1], (lo[2] + hi[2]) / 2]

    def fwd(self):
        return qrot(self.rot, self.front)

    def pose(self):
        return self.pos + self.rot + [self.scale]


def overlap_amount(a, b):
    (al, ah), (bl, bh) = a, b
    return [min(ah[i], bh[i]) - max(al[i], bl[i]) for i in range(3)]


def collide(a, b):
    return all(v > OVERLAP for v in overlap_amount(a, b))


def inside(box, bounds):
    lo, hi = box
    return all(lo[i] >= bounds["min"][i] - EPS and hi[i] <= bounds["max"][i] + EPS for i in range(3))


def support_of(st, name, strict=False):
    """the object `name` rests on: bottom within 1 mm of its top, centre (or, strict, the whole
    footprint) over it; None on the floor or hanging"""
    lo, hi = st[name].box()
    c = st[name].centre()
    best = None
    for n, o in st.items():
        if n == name:
            continue
        bl, bh = o.box()
        if abs(bh[1] - lo[1]) > 1e-3:
            continue
        if strict:
            ok = lo[0] >= bl[0] - EPS and hi[0] <= bh[0] + EPS and lo[2] >= bl[2] - EPS and hi[2] <= bh[2] + EPS
        else:
            ok = bl[0] - EPS <= c[0] <= bh[0] + EPS and bl[2] - EPS <= c[2] <= bh[2] + EPS
        if ok:
            if best is not None:
                return "?" + best + "|" + n
            best = n
    return best


def tree(st):
    out = {}
    for n in st:
        s = support_of(st, n)
        if s:
            out[n] = s
    return out


def carried(name, on):
    out = []
    for c, s in on.items():
        if s == name:
            out += [c] + carried(c, on)
    return out


# ------------------------------------------------------------------ the checks (docs/benchmark.md's table)
def gap1(al, ah, bl, bh):
    return max(bl - ah, al - bh, 0.0)


def ev_check(c, s0, s1, bounds, excluded):
    """True when check c passes from scene s0 to s1; a string says why not"""
    k = c["check"]
    o = c.get("object")
    if k == "moved":
        if c.get("delta") is None:
            return True
        b0, b1 = s0[o].bottom(), s1[o].bottom()
        d = [b1[i] - b0[i] for i in range(3)]
        e = math.dist(d, c["delta"])
        return e <= c.get("tol", 0.05) or f"moved by {[round(x, 3) for x in d]}"
    if k == "direction":
        i, sg = AXES[c["axis"]]
        b0, b1 = s0[o].bottom(), s1[o].bottom()
        d = [b1[j] - b0[j] for j in range(3)]
        along = sg * d[i]
        across = math.sqrt(sum(d[j] ** 2 for j in range(3) if j != i))
        ok = along >= c.get("min", 0.05) - EPS and across <= max(0.1, along / 4) + EPS
        return ok or f"moved by {[round(x, 3) for x in d]}"
    if k == "rotated":
        dy = wrap(yaw_of(s1[o].rot) - yaw_of(s0[o].rot))
        want = wrap(c.get("degrees", 90))
        tol = c.get("tol", 5)
        ok = abs(wrap(dy - want)) <= tol or (c.get("either_sign") and abs(wrap(dy + want)) <= tol)
        return ok or f"turned {dy:.1f}"
    if k == "scaled":
        f = s1[o].scale / s0[o].scale
        return abs(f - c["factor"]) <= c.get("tol", 0.02) * c["factor"] or f"scaled {f:.3f}"
    if k == "on_top":
        (ol, oh), (sl, sh) = s1[o].box(), s1[c["support"]].box()
        cc = s1[o].centre()
        ok = abs(ol[1] - sh[1]) <= c.get("tol", 0.03) and sl[0] <= cc[0] <= sh[0] and sl[2] <= cc[2] <= sh[2]
        return ok or "not on top"
    if k == "next_to":
        a, b = s1[o].box(), s1[c["other"]].box()
        if collide(a, b):
            return "inside it"
        g = math.hypot(gap1(a[0][0], a[1][0], b[0][0], b[1][0]), gap1(a[0][2], a[1][2], b[0][2], b[1][2]))
        ok = g <= c.get("max_gap", 0.3) and min(a[1][1], b[1][1]) - max(a[0][1], b[0][1]) > EPS
        return ok or f"gap {g:.3f}"
    if k == "side":
        (al, ah), (bl, bh) = s1[o].box(), s1[c["other"]].box()
        sd = c["side"]
        if sd in ("left", "right"):
            g = bl[0] - ah[0] if sd == "left" else al[0] - bh[0]
            ax = 2
        else:
            g = al[2] - bh[2] if sd == "front" else bl[2] - ah[2]
            ax = 0
        ok = -0.02 <= g <= c.get("max_gap", 0.5) and min(ah[ax], bh[ax]) - max(al[ax], bl[ax]) > EPS
        return ok or f"side gap {g:.3f}"
    if k == "above":
        return s1[o].box()[0][1] >= s1[c["other"]].box()[1][1] - c.get("tol", 0.03) or "not above"
    if k == "below":
        return s1[o].box()[1][1] <= s1[c["other"]].box()[0][1] + c.get("tol", 0.03) or "not below"
    if k == "between":
        p, pa, pb = s1[o].centre(), s1[c["a"]].centre(), s1[c["b"]].centre()
        vx, vz = pb[0] - pa[0], pb[2] - pa[2]
        wx, wz = p[0] - pa[0], p[2] - pa[2]
        t = (wx * vx + wz * vz) / (vx * vx + vz * vz)
        ok = 0 <= t <= 1 and math.hypot(wx - t * vx, wz - t * vz) <= c.get("tol", 0.3)
        return ok or f"t {t:.2f}"
    if k == "aligned":
        i = AXES["+" + c["axis"].lstrip("+-")][0]
        return abs(s1[o].centre()[i] - s1[c["other"]].centre()[i]) <= c.get("tol", 0.05) or "not aligned"
    if k == "at":
        b = s1[o].bottom()
        ok = all(p is None or abs(b[i] - p) <= c.get("tol", 0.05) for i, p in enumerate(c["position"]))
        return ok or f"at {[round(x, 3) for x in b]}"
    if k == "faces":
        f = s1[o].fwd()
        a, t = s1[o].centre(), s1[c["target"]].centre()
        d = abs(wrap(math.degrees(math.atan2(f[0], f[2]) - math.atan2(t[0] - a[0], t[2] - a[2]))))
        return d <= c.get("tol", 20) or f"off by {d:.1f}"
    if k == "distance":
        a, t = s1[o].centre(), s1[c["other"]].centre()
        d3 = math.dist(a, t)
        d2 = math.hypot(a[0] - t[0], a[2] - t[2])
        ok = all(c.get("min", 0) <= d <= c.get("max", 1e9) for d in (d3, d2))
        return ok or f"distance {d3:.3f} / plan {d2:.3f}"
    if k == "unchanged":
        names = c.get("objects", "others")
        if names == "others":
            names = [n for n in s0 if n not in excluded]
        moved = [n for n in names if max(abs(a - b) for a, b in zip(s0[n].pose(), s1[n].pose())) > 1e-6]
        return not moved or f"moved {moved}"
    if k == "no_collision":
        bad = []
        for a, b in itertools.combinations(s1, 2):
            if collide(s1[a].box(), s1[b].box()):
                before = overlap_amount(s0[a].box(), s0[b].box())
                after = overlap_amount(s1[a].box(), s1[b].box())
                if not all(v > OVERLAP for v in before) or any(x > y + 1e-6 for x, y in zip(after, before)):
                    bad.append((a, b))
        return not bad or f"collisions {bad}"
    if k == "inside_bounds":
        out = [n for n in s1 if not inside(s1[n].box(), bounds) and inside(s0[n].box(), bounds)]
        return not out or f"outside {out}"
    return f"unknown check {k}"


def excluded_of(q, s0):
    on = tree(s0)
    ex = set()
    for c in q["expect"]:
        if c["check"] != "unchanged" and "object" in c:
            ex.add(c["object"])
            ex |= set(carried(c["object"], on))
    return ex


# ------------------------------------------------------------------ applying a worked answer
def apply_op(st, op, held):
    kind, name, arg = op
    on = {c: s for c, s in tree(st).items() if c not in held}
    group = [name] + carried(name, on)
    piv = list(st[name].pos)
    if kind == "d":
        for g in group:
            st[g].pos = [st[g].pos[i] + arg[i] for i in range(3)]
    elif kind == "to":
        d = [arg[i] - piv[i] for i in range(3)]
        for g in group:
            st[g].pos = [st[g].pos[i] + d[i] for i in range(3)]
    elif kind in ("yaw", "face"):
        if kind == "face":
            a, t = st[name].centre(), st[arg].centre()
            f = st[name].fwd()
            deg = math.degrees(math.atan2(t[0] - a[0], t[2] - a[2]) - math.atan2(f[0], f[2]))
        else:
            deg = arg
        q = yawq(deg)
        for g in group:
            rel = [st[g].pos[i] - piv[i] for i in range(3)]
            r = qrot(q, rel)
            st[g].pos = [piv[i] + r[i] for i in range(3)]
            st[g].rot = qmul(q, st[g].rot)
    elif kind == "scale":
        if len(group) > 1:
            raise ValueError(f"scaling {name} that carries {group[1:]}")
        st[name].scale *= arg
    else:
        raise ValueError(f"unknown op {kind}")


def derived_readings(q, s0):
    """readings from exact checks; `direction` gives a smallest and a generous reading"""
    checks = q["expect"]
    gen = build.GEN.get(q["id"], {})
    base, dirs = [], []
    on0 = tree(s0)
    for c in checks:
        k = c["check"]
        if k == "on_top" and on0.get(c["object"]) == c["support"]:
            continue  # already there: it rides along with its support
        if k == "moved" and c.get("delta") and any(abs(x) > 0 for x in c["delta"]):
            base.append(("d", c["object"], c["delta"]))
        elif k == "rotated":
            base.append(("yaw", c["object"], c.get("degrees", 90)))
        elif k == "faces":
            base.append(("face", c["object"], c["target"]))
        elif k == "scaled":
            base.append(("scale", c["object"], c["factor"]))
        elif k == "direction":
            dirs.append(c)
        elif k in ("on_top", "next_to", "side", "between", "at", "distance", "aligned", "above", "below"):
            raise ValueError(f"{k} needs a hand-worked answer in build.ANS")
    # a moved check on something carried by another moved object is the carry itself
    on = tree(s0)
    movers = {op[1] for op in base} | {c["object"] for c in dirs}

    def riding(n):
        s = on.get(n)
        while s is not None:
            if s in movers:
                return True
            s = on.get(s)
        return False
    base = [op for op in base if not (op[0] == "d" and riding(op[1]))]
    if not dirs:
        return [base]
    out = []
    for which in ("min", "gen"):
        r = list(base)
        for c in dirs:
            i, sg = AXES[c["axis"]]
            mn = c.get("min", 0.05)
            amt = mn if which == "min" else gen.get(c["object"], GENEROUS.get(mn, max(mn * 1.5, mn + 0.05)))
            d = [0, 0, 0]
            d[i] = sg * amt
            if not riding(c["object"]):
                r.append(("d", c["object"], d))
        out.append(r)
    return out


def gap_to(st, name, other, bounds):
    """smallest face-to-face horizontal gap between name and other (an object or a wall '+x' ...)"""
    lo, hi = st[name].box()
    if other in AXES:
        i, sg = AXES[other]
        return bounds["max"][i] - hi[i] if sg > 0 else lo[i] - bounds["min"][i]
    bl, bh = st[other].box()
    ov = overlap_amount((lo, hi), (bl, bh))
    best = None
    for i, j in ((0, 2), (2, 0)):
        if ov[j] > OVERLAP and ov[1] > OVERLAP:
            g = max(bl[i] - hi[i], lo[i] - bh[i])
            best = g if best is None else min(best, g)
    return best


def resting_ok(st, bounds, wall):
    bad = []
    for n, o in st.items():
        lo, hi = o.box()
        if abs(lo[1] - bounds["min"][1]) < 1e-3 or n in wall:
            continue
        if not support_of(st, n):
            bad.append(n)
    return bad


# ------------------------------------------------------------------ scenes
def load_scene(path):
    with open(path) as f:
        d = json.load(f)
    objs, seen = {}, set()
    for od in d["objects"]:
        n = od["name"]
        for k in od:
            if k not in ("name", "position", "size", "rotation", "scale", "front"):
                err(f"{path}: {n} has field {k}")
        if n.lower() in seen:
            err(f"{path}: duplicate name {n}")
        seen.add(n.lower())
        if len(od["size"]) != 3 or min(od["size"]) <= 0:
            err(f"{path}: {n} bad size")
        q = od.get("rotation", [0, 0, 0, 1])
        if abs(math.sqrt(sum(x * x for x in q)) - 1) > 1e-6 or abs(q[0]) > EPS or abs(q[2]) > EPS:
            err(f"{path}: {n} rotation is not a unit yaw")
        objs[n] = Obj(od)
    return d, objs


def check_scene(stem, d, objs):
    b = d.get("bounds")
    if not b or abs(b["min"][1]) > EPS:
        err(f"{stem}: bounds missing or floor not at 0")
        return
    for n, o in objs.items():
        if not inside(o.box(), b):
            err(f"{stem}: {n} outside the room {o.box()}")
    for a, c in itertools.combinations(objs, 2):
        if collide(objs[a].box(), objs[c].box()):
            err(f"{stem}: {a} overlaps {c}")
    wall = build.WALL.get(stem, ())
    for n, o in objs.items():
        lo, hi = o.box()
        if n in wall:
            if lo[1] < 0.05 or not any(gap_to(objs, n, w, b) < 1e-6 for w in ("+x", "-x", "+z", "-z")):
                err(f"{stem}: wall object {n} does not hang on a wall")
            continue
        if abs(lo[1]) < EPS:
            continue
        s = support_of(objs, n, strict=True)
        if not s or s.startswith("?"):
            err(f"{stem}: {n} (bottom {lo[1]:.4f}) does not rest exactly inside one top ({s})")
    t = tree(objs)
    if t != build.ON[stem]:
        err(f"{stem}: build.ON differs from the geometry: {t}")


# ------------------------------------------------------------------ queries
def names_in(c):
    out = [c[f] for f in NAME_FIELDS if f in c]
    if c["check"] == "unchanged" and isinstance(c.get("objects"), list):
        out += c["objects"]
    if c["check"] == "refused":
        out += c.get("mentions", [])
    return out


def words(name):
    s = name.lower()
    for ch in "_.-'0123456789":
        s = s.replace(ch, " ")
    return s


def check_refusal(q, objs):
    why = build.REFUSE.get(q["id"])
    m = q["expect"][0].get("mentions", [])
    if len(q["expect"]) != 1:
        err(f"{q['id']}: a refusal carries other checks")
    if not why:
        err(f"{q['id']}: no build.REFUSE entry")
        return
    kind, arg = why
    if kind == "missing":
        hits = [n for n in objs if arg in words(n)]
        if hits or m:
            err(f"{q['id']}: '{arg}' is said to be missing but matches {hits} / mentions {m}")
    else:
        hits = [n for n in objs if all(w in words(n) for w in arg)]
        if len(hits) < 2 or len(m) < 2 or not set(m) <= set(hits):
            err(f"{q['id']}: ambiguity {arg}: matches {hits}, mentions {m}")


def run_query(q, d, objs):
    bounds = d["bounds"]
    stem = d["name"]
    wall = build.WALL.get(stem, ())
    held = set()
    for c in q["expect"]:
        if c["check"] == "unchanged" and isinstance(c.get("objects"), list):
            held |= set(c["objects"])
    try:
        readings = build.ANS.get(q["id"]) or derived_readings(q, objs)
    except ValueError as e:
        err(f"{q['id']}: {e}")
        return
    ex = excluded_of(q, objs)
    for ri, reading in enumerate(readings):
        st = {n: o.copy() for n, o in objs.items()}
        try:
            for op in reading:
                apply_op(st, op, held)
        except (KeyError, ValueError) as e:
            err(f"{q['id']} reading {ri}: {e}")
            continue
        for c in q["expect"] + [{"check": "no_collision"}, {"check": "inside_bounds"}]:
            r = ev_check(c, objs, st, bounds, ex)
            if r is not True:
                err(f"{q['id']} reading {ri}: {c['check']} {c.get('object', c.get('objects', ''))} fails: {r}")
        fl = resting_ok(st, bounds, wall)
        if fl:
            err(f"{q['id']} reading {ri}: left floating {fl}")
        for a, other in build.TOUCH.get(q["id"], ()):
            g = gap_to(st, a, other, bounds)
            if g is None or abs(g) > 1e-3:
                err(f"{q['id']} reading {ri}: {a} should touch {other}, gap {g}")
        # whatever the answer moves must be the object of a check (carried things included)
        about = {c["object"] for c in q["expect"] if "object" in c}
        for n in objs:
            if n in about:
                continue
            if max(abs(a - b) for a, b in zip(objs[n].pose(), st[n].pose())) > 1e-6:
                err(f"{q['id']} reading {ri}: answer moves {n} which no check is about")


# ------------------------------------------------------------------ the text against the exact moves
AMOUNT = re.compile(r"(\d+(?:\.\d+)?|a|one|half a)\s*(cm|centimetres?|mm|metres?|meters?|m|ft|foot|feet|inch|inches)\b")
WORDNUM = {"a": 1, "one": 1, "half a": 0.5}
UNIT = {"cm": 0.01, "mm": 0.001, "m": 1, "ft": FT, "foot": FT, "feet": FT, "inch": IN, "inches": IN}
DIRWORDS = [(re.compile(r"\bleft\b(?!-)"), (0, -1)), (re.compile(r"\bright\b(?! up| behind| into|-)"), (0, 1)),
            (re.compile(r"\bforward\b|\btowards the front\b"), (2, 1)),
            (re.compile(r"\bback\b(?! wall|-| row| of)"), (2, -1))]


def amounts(text):
    out = []
    for num, unit in AMOUNT.findall(text.lower()):
        v = WORDNUM.get(num) or float(num)
        u = unit if unit in UNIT else ("m" if unit.startswith("met") else "cm")
        out.append(v * UNIT[u])
    return out


def cross_check_text(q):
    """every exact non-zero move (not a ride on a moved support) must have the size of an amount the
    text gives and a direction the text names (towards / swaps / contacts excepted)"""
    text = q["text"].lower()
    deltas = {c["object"]: c["delta"] for c in q["expect"]
              if c["check"] == "moved" and c.get("delta") and any(abs(x) > 0 for x in c["delta"])}
    on = build.ON[q["scenes"][0]]
    own = {n: d for n, d in deltas.items() if not (on.get(n) in deltas and deltas[on[n]] == d)}
    if not own:
        return
    am = amounts(text)
    free = any(w in text for w in ("toward", "swap", "until", "as far", "all the way", "against", "flush",
                                    "closest", "nearest"))
    dirs = [d for rx, d in DIRWORDS if rx.search(text)]
    for n, d in own.items():
        size = math.sqrt(sum(x * x for x in d))
        if am and not any(abs(size - a) <= 0.006 for a in am):
            err(f"{q['id']}: {n} moves {size:.4f} but the text says {[round(a, 4) for a in am]}")
        if not am and not free:
            err(f"{q['id']}: {n} has an exact move but the text gives no amount")
        if "toward" in text or "swap" in text:
            continue
        i = max(range(3), key=lambda k: abs(d[k]))
        sg = 1 if d[i] > 0 else -1
        if dirs and (i, sg) not in dirs:
            err(f"{q['id']}: {n} moves along {'xyz'[i]}{'+' if sg > 0 else '-'} but the text says {dirs}")
        if not dirs and not free:
            err(f"{q['id']}: {n} has an exact move but the text names no direction")


def main():
    with open(os.path.join(HERE, "holdout5.suite.json")) as f:
        suite = json.load(f)
    for k in suite:
        if k not in ("name", "scenes", "variations", "seed", "queries"):
            err(f"suite: unknown field {k}")
    scenes = {}
    for p in suite["scenes"]:
        d, objs = load_scene(os.path.join(HERE, p))
        stem = os.path.splitext(os.path.basename(p))[0]
        if d["name"] != stem:
            err(f"{p}: name differs from file stem")
        check_scene(stem, d, objs)
        scenes[stem] = (d, objs)
    ids, texts = set(), set()
    per_cat, per_scene, refusals, refusals_by_cat = {}, {}, 0, {}
    for q in suite["queries"]:
        qid = q.get("id")
        for k in q:
            if k not in ("id", "category", "text", "scenes", "expect"):
                err(f"{qid}: unknown field {k}")
        if qid in ids:
            err(f"{qid}: duplicate id")
        ids.add(qid)
        if q["text"].lower() in texts:
            err(f"{qid}: duplicate text")
        texts.add(q["text"].lower())
        if "{" in q["text"]:
            err(f"{qid}: placeholder in text")
        if q["category"] not in CATEGORIES:
            err(f"{qid}: bad category")
        if len(q.get("scenes", [])) != 1 or q["scenes"][0] not in scenes:
            err(f"{qid}: needs exactly one known scene")
            continue
        sc = q["scenes"][0]
        d, objs = scenes[sc]
        per_cat[q["category"]] = per_cat.get(q["category"], 0) + 1
        per_scene[sc] = per_scene.get(sc, 0) + 1
        bad = False
        for c in q["expect"]:
            k = c.get("check")
            if k not in CHECKS:
                err(f"{qid}: check {k} is not in SPEC")
                bad = True
                continue
            req, opt = CHECKS[k]
            have = set(c) - {"check"}
            if req - have or have - req - opt:
                err(f"{qid}: {k} fields {sorted(have)}")
            if k == "moved" and not 0.02 <= c.get("tol", 0.05) <= 0.05:
                err(f"{qid}: moved tol {c.get('tol')}")
            if k == "rotated" and c.get("tol") != 3:
                err(f"{qid}: rotated tol must be 3")
            if k == "direction" and c["axis"] not in AXES:
                err(f"{qid}: bad axis")
            for n in names_in(c):
                if n not in objs:
                    err(f"{qid}: {n} is not in {sc}")
                    bad = True
        if bad:
            continue
        if any(c["check"] == "refused" for c in q["expect"]):
            refusals += 1
            refusals_by_cat[q["category"]] = refusals_by_cat.get(q["category"], 0) + 1
            check_refusal(q, objs)
            continue
        if q["expect"][-2:] != [{"check": "no_collision"}, {"check": "unchanged", "objects": "others"}]:
            err(f"{qid}: must end with no_collision and unchanged others")
        cross_check_text(q)
        run_query(q, d, objs)
    for e in errors:
        print("ERROR:", e)
    print(f"{len(suite['queries'])} queries; per scene {per_scene}; per category {per_cat}; "
          f"refusals {refusals} {refusals_by_cat}")
    print("OK" if not errors else f"{len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
