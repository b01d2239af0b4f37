#!/usr/bin/env python3
"""Validates bench/holdout4 (stdlib only):
  - the suite's shape: fields, categories, checks and their fields (SPEC 6 + docs/benchmark.md),
    unique ids and texts, one scene per query;
  - names: every object a check names (object / other / support / a / b / target, unchanged lists,
    refused mentions) exists in the query's scene; refusals of an ambiguous phrase list >= 2 names;
  - the scenes: unique names (case-insensitive), sizes > 0, unit yaw-only quaternions, no
    categories / aliases, everything inside the bounds, no two boxes overlapping, every object
    not on the floor resting exactly (bottom = top, footprint inside) on exactly one support, and
    build.ON equal to the resting tree the geometry gives;
  - every non-refused query: a worked answer is simulated from its checks (carrying what rests on
    moved things, holding what `unchanged` lists, searching a collision-free spot for placements)
    and must meet every check without creating a collision or leaving the room; anything the answer
    moves must be covered by a check; "flush / against / until / as far as / corner" answers must
    end touching a wall or an object; vague amounts are probed with a generous reading (warnings).

    python3 validate.py            # exit 0 when everything passes; warnings are listed
"""
import json, math, os, sys, itertools
sys.dont_write_bytecode = True

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "holdout4.suite.json")
EPS = 1e-6
OVERLAP = 1e-4          # boxes touching (overlap <= 0.1 mm on some axis) do not collide
BUFFER = 0.02           # horizontal clearance kept when a placement spot is searched

CATEGORIES = {"simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"}
CHECK_FIELDS = {
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
    "swapped": ({"object", "other"}, {"tol"}),
    "refused": (set(), {"mentions"}),
}
NAME_FIELDS = ("object", "other", "support", "a", "b", "target")
AXES = {"+x": (0, 1), "-x": (0, -1), "+y": (1, 1), "-y": (1, -1), "+z": (2, 1), "-z": (2, -1)}
CONTACT_WORDS = ("flush", "against", "until", "till it", "as far", "into the", "into a corner")

errors, warnings = [], []
def err(m): errors.append(m)
def warn(m): warnings.append(m)

# ------------------------------------------------------------------ geometry
def qmul(a, b):
    ax, ay, az, aw = a; bx, by, bz, bw = b
    return [aw*bx + ax*bw + ay*bz - az*by, aw*by - ax*bz + ay*bw + az*bx,
            aw*bz + ax*by - ay*bx + az*bw, aw*bw - ax*bx - ay*by - az*bz]

def qrot(q, v):
    x, y, z, w = q
    p = qmul(qmul(q, [v[0], v[1], v[2], 0]), [-x, -y, -z, w])
    return p[:3]

def qnorm(q):
    n = math.sqrt(sum(c*c for c in q)); return [c/n for c in q]

def yawq(deg):
    h = math.radians(deg) / 2; return [0, math.sin(h), 0, math.cos(h)]

def yaw_of(q):
    """yaw (deg) of a yaw-only quaternion"""
    return math.degrees(2 * math.atan2(q[1], q[3]))

class Obj:
    def __init__(self, d):
        self.name = d["name"]; self.size = list(d["size"]); self.pos = list(d["position"])
        self.rot = qnorm(d.get("rotation", [0, 0, 0, 1])); self.scale = d.get("scale", 1.0)
        self.front = d.get("front", [0, 0, 1])
    def copy(self):
        o = Obj.__new__(Obj)
        o.__dict__ = {k: (list(v) if isinstance(v, list) else v) for k, v in self.__dict__.items()}
        return o
    def box(self):
        w, h, d = (s*self.scale for s in self.size)
        lo, hi = [1e18]*3, [-1e18]*3
        for cx, cy, cz in itertools.product((-w/2, w/2), (0, h), (-d/2, d/2)):
            p = qrot(self.rot, [cx, cy, cz])
            for i in range(3):
                lo[i] = min(lo[i], p[i] + self.pos[i]); hi[i] = max(hi[i], p[i] + self.pos[i])
        return lo, hi
    def centre(self):
        lo, hi = self.box(); return [(lo[i]+hi[i])/2 for i in range(3)]
    def bottom(self):
        lo, hi = self.box(); return [(lo[0]+hi[0])/2, lo[1], (lo[2]+hi[2])/2]
    def fwd(self):
        return qrot(self.rot, self.front)

def overlap(a, b, buf=0.0):
    (al, ah), (bl, bh) = a, b
    for i in range(3):
        e = buf if i != 1 else 0.0
        if min(ah[i] + e, bh[i]) - max(al[i] - e, bl[i]) <= OVERLAP:
            return False
    return True

def inside_room(box, bounds):
    if not bounds:
        return box[0][1] >= -EPS
    lo, hi = box
    return all(lo[i] >= bounds["min"][i] - EPS and hi[i] <= bounds["max"][i] + EPS for i in range(3))

def supports_of(name, objs):
    a = objs[name]; al, ah = a.box()
    out = []
    for b in objs.values():
        if b.name == name: continue
        bl, bh = b.box()
        if abs(al[1] - bh[1]) < 0.01:
            c = a.centre()
            if bl[0] - EPS <= c[0] <= bh[0] + EPS and bl[2] - EPS <= c[2] <= bh[2] + EPS:
                out.append(b.name)
    return out

def resting_tree(objs):
    on = {}
    for n in objs:
        s = supports_of(n, objs)
        if s:
            on[n] = s[0]
    return on

def carried(name, on):
    out = []
    for c, s in on.items():
        if s == name:
            out += [c] + carried(c, on)
    return out

# ------------------------------------------------------------------ the checks as I read them (SPEC 6)
def gap_1d(al, ah, bl, bh):
    return max(bl - ah, al - bh, 0.0)

def chk_on_top(st, o, s, tol=0.03, strict=False):
    (ol, oh), (sl, sh) = st[o].box(), st[s].box()
    if abs(ol[1] - sh[1]) > tol: return False
    if strict:
        return ol[0] >= sl[0] - EPS and oh[0] <= sh[0] + EPS and ol[2] >= sl[2] - EPS and oh[2] <= sh[2] + EPS
    c = st[o].centre()
    return sl[0] <= c[0] <= sh[0] and sl[2] <= c[2] <= sh[2]

def chk_next_to(st, o, t, max_gap=0.3):
    a, b = st[o].box(), st[t].box()
    if overlap(a, b): return False
    gx = gap_1d(a[0][0], a[1][0], b[0][0], b[1][0]); gz = gap_1d(a[0][2], a[1][2], b[0][2], b[1][2])
    if math.hypot(gx, gz) > max_gap: return False
    return min(a[1][1], b[1][1]) - max(a[0][1], b[0][1]) > EPS

def chk_side(st, o, t, side, max_gap=0.5, strict=False):
    (al, ah), (bl, bh) = st[o].box(), st[t].box()
    if side in ("left", "right"):
        g = bl[0] - ah[0] if side == "left" else al[0] - bh[0]; ax = 2
    else:
        g = al[2] - bh[2] if side == "front" else bl[2] - ah[2]; ax = 0
    if not (-0.02 <= g <= max_gap): return False
    if strict:
        c = st[o].centre()[ax]; return bl[ax] <= c <= bh[ax]
    return min(ah[ax], bh[ax]) - max(al[ax], bl[ax]) > EPS

def chk_between(st, o, a, b, tol=0.3):
    p, pa, pb = st[o].centre(), st[a].centre(), st[b].centre()
    vx, vz = pb[0]-pa[0], pb[2]-pa[2]; wx, wz = p[0]-pa[0], p[2]-pa[2]
    L = vx*vx + vz*vz
    t = (wx*vx + wz*vz) / L
    if t < 0 or t > 1: return False
    return math.hypot(wx - t*vx, wz - t*vz) <= tol

def chk_faces(st, o, t, tol=20):
    f = st[o].fwd(); c, ct = st[o].centre(), st[t].centre()
    a1 = math.atan2(f[0], f[2]); a2 = math.atan2(ct[0]-c[0], ct[2]-c[2])
    d = abs((math.degrees(a1 - a2) + 180) % 360 - 180)
    return d <= tol

def chk_at(st, o, p, tol=0.05):
    b = st[o].bottom()
    return all(p[i] is None or abs(b[i] - p[i]) <= tol for i in range(3))

def chk_distance(st, o, t, mn=0.0, mx=float("inf")):
    a, b = st[o].centre(), st[t].centre()
    d = math.dist(a, b)
    return mn <= d <= mx

PLACE = ("on_top", "next_to", "side", "between", "at", "distance")

def place_ok(st, o, checks, strict=True):
    for c in checks:
        if c.get("object") != o: continue
        k = c["check"]
        if k == "on_top" and not chk_on_top(st, o, c["support"], strict=strict): return False
        if k == "next_to" and not chk_next_to(st, o, c["other"], c.get("max_gap", 0.3) - (0.03 if strict else 0)): return False
        if k == "side" and not chk_side(st, o, c["other"], c["side"], c.get("max_gap", 0.5) - (0.03 if strict else 0), strict=strict): return False
        if k == "between" and not chk_between(st, o, c["a"], c["b"], c.get("tol", 0.3) - (0.05 if strict else 0)): return False
        if k == "at" and not chk_at(st, o, c["position"], c.get("tol", 0.05) * (0.5 if strict else 1)): return False
        if k == "distance":
            m = 0.005 if strict else 0
            if not chk_distance(st, o, c["other"], c.get("min", 0) + m, c.get("max", float("inf")) - m): return False
    return True

# ------------------------------------------------------------------ simulation helpers
def move_group(st, name, on, delta=None, q=None):
    """translate (and/or yaw about the pivot) name and what rests on it, transitively"""
    group = [name] + carried(name, on)
    piv = list(st[name].pos)
    for g in group:
        ob = st[g]
        if q is not None:
            rel = [ob.pos[i] - piv[i] for i in range(3)]
            r = qrot(q, rel)
            ob.pos = [piv[i] + r[i] for i in range(3)]
            ob.rot = qnorm(qmul(q, ob.rot))
        if delta is not None:
            ob.pos = [ob.pos[i] + delta[i] for i in range(3)]
    return group

def collisions(st0, st1, bounds, moved, buf=0.0):
    out = []
    names = list(st1)
    for m in moved:
        b1 = st1[m].box()
        if not inside_room(b1, bounds) and inside_room(st0[m].box(), bounds):
            out.append(f"{m} leaves the room")
        for n in names:
            if n == m or (n in moved and n < m): continue
            if overlap(b1, st1[n].box(), buf if n not in moved else 0.0) and not overlap(st0[m].box(), st0[n].box()):
                out.append(f"{m} hits {n}")
    return out

def witness(st, name, checks, bounds, on):
    """moves `name` (same rotation, with what rests on it) to a spot meeting its placement checks
    with no collision, keeping a 2 cm buffer and (on a surface) staying within the face"""
    o = st[name]
    mine_checks = [c for c in checks if c.get("object") == name]
    lvl = None; region = None
    for c in mine_checks:
        if c["check"] == "on_top":
            sb = st[c["support"]].box(); lvl = sb[1][1]; region = (sb[0][0], sb[1][0], sb[0][2], sb[1][2])
        if c["check"] == "at" and c["position"][1] is not None and lvl is None:
            lvl = c["position"][1]
    refs = [c.get("other") or c.get("a") for c in mine_checks if c["check"] in ("next_to", "side", "between", "distance")]
    refs += [c["b"] for c in mine_checks if c["check"] == "between"]
    if lvl is None:
        lvl = st[refs[0]].box()[0][1]
    if region is None:
        if refs:
            xs = [st[r].box() for r in refs]
            region = (min(b[0][0] for b in xs) - 1.2, max(b[1][0] for b in xs) + 1.2,
                      min(b[0][2] for b in xs) - 1.2, max(b[1][2] for b in xs) + 1.2)
        else:
            region = (bounds["min"][0], bounds["max"][0], bounds["min"][2], bounds["max"][2])
    mine = set([name] + carried(name, on))
    lo0, hi0 = o.box(); off = [o.pos[i] - (lo0[i] + hi0[i]) / 2 for i in (0, 2)]
    step = 0.01
    cands = []
    nx = int(round((region[1] - region[0]) / step)); nz = int(round((region[3] - region[2]) / step))
    for i in range(nx + 1):
        for j in range(nz + 1):
            cands.append((region[0] + i * step, region[2] + j * step))
    c0 = o.centre()
    cands.sort(key=lambda p: (p[0]-c0[0])**2 + (p[1]-c0[2])**2)
    others = [n for n in st if n not in mine]
    for (x, z) in cands:
        saved = {m: list(st[m].pos) for m in mine}
        d = [x + off[0] - o.pos[0], lvl - o.box()[0][1], z + off[1] - o.pos[2]]
        for m in mine:
            st[m].pos = [st[m].pos[i] + d[i] for i in range(3)]
        ok = place_ok(st, name, checks, strict=True) and inside_room(st[name].box(), bounds)
        if ok:
            for m in mine:
                bm = st[m].box()
                for n in others:
                    if overlap(bm, st[n].box(), BUFFER):
                        ok = False; break
                if not ok: break
        if ok:
            return (x, z)
        for m in mine:
            st[m].pos = saved[m]
    return None

def touches(st, name, bounds):
    """the box of name touches a wall or another box face to face (gap < 1 mm) horizontally"""
    lo, hi = st[name].box()
    for i in (0, 2):
        if abs(lo[i] - bounds["min"][i]) < 1e-3 or abs(hi[i] - bounds["max"][i]) < 1e-3:
            return True
    for n, ob in st.items():
        if n == name: continue
        bl, bh = ob.box()
        if min(hi[1], bh[1]) - max(lo[1], bl[1]) <= OVERLAP: continue
        for i, j in ((0, 2), (2, 0)):
            if min(hi[j], bh[j]) - max(lo[j], bl[j]) <= OVERLAP: continue
            if abs(lo[i] - bh[i]) < 1e-3 or abs(bl[i] - hi[i]) < 1e-3:
                return True
    return False

# ------------------------------------------------------------------ load
def load_scene(path):
    with open(path) as f:
        d = json.load(f)
    for k in d:
        if k not in ("name", "bounds", "objects"): warn(f"{path}: extra field {k}")
    objs = {}
    seen = set()
    for od in d["objects"]:
        for k in od:
            if k in ("category", "aliases"): err(f"{path}: {od['name']} has {k}")
            if k not in ("name", "position", "size", "rotation", "scale", "front"): warn(f"{path}: {od['name']} has extra {k}")
        n = od["name"]
        if n.lower() in seen: err(f"{path}: duplicate name {n}")
        seen.add(n.lower())
        if len(od["size"]) != 3 or any(s <= 0 for s in od["size"]): err(f"{path}: {n} size must be 3 values > 0")
        if len(od["position"]) != 3: err(f"{path}: {n} position must have 3 values")
        q = od.get("rotation", [0, 0, 0, 1])
        if abs(math.sqrt(sum(c * c for c in q)) - 1) > 1e-6: err(f"{path}: {n} rotation is not a unit quaternion")
        if abs(q[0]) > EPS or abs(q[2]) > EPS: err(f"{path}: {n} rotation is not about Y")
        if od.get("scale", 1.0) <= 0: err(f"{path}: {n} scale must be > 0")
        objs[n] = Obj(od)
    return d, objs

def check_scene(stem, d, objs):
    bounds = d.get("bounds")
    if not bounds: err(f"{stem}: no bounds")
    elif abs(bounds["min"][1]) > EPS: err(f"{stem}: the floor is not at y = 0")
    for n, o in objs.items():
        if not inside_room(o.box(), bounds): err(f"{stem}: {n} is outside the room")
    for a, b in itertools.combinations(objs, 2):
        if overlap(objs[a].box(), objs[b].box()):
            err(f"{stem}: {a} overlaps {b} at the start")
    for n, o in objs.items():
        lo, hi = o.box()
        if abs(lo[1]) < EPS: continue
        sups = [s for s in objs if s != n and abs(objs[s].box()[1][1] - lo[1]) < 0.01]
        exact = []
        for s in sups:
            sl, sh = objs[s].box()
            if abs(sh[1] - lo[1]) > EPS:
                err(f"{stem}: {n} bottom {lo[1]:.4f} is near but not on {s} top {sh[1]:.4f}")
                continue
            inside = lo[0] >= sl[0] - EPS and hi[0] <= sh[0] + EPS and lo[2] >= sl[2] - EPS and hi[2] <= sh[2] + EPS
            c = o.centre()
            over = sl[0] <= c[0] <= sh[0] and sl[2] <= c[2] <= sh[2]
            if inside: exact.append(s)
            elif over: err(f"{stem}: {n} rests on {s} but sticks out of its footprint")
        if len(exact) != 1:
            err(f"{stem}: {n} (bottom {lo[1]:.3f}) rests on {exact or 'nothing'}")
    try:
        sys.path.insert(0, HERE)
        import build
        if resting_tree(objs) != build.ON[stem]:
            err(f"{stem}: build.ON {build.ON[stem]} differs from the geometry {resting_tree(objs)}")
    except ImportError:
        warn("build.py not importable; ON table not compared")

# ------------------------------------------------------------------ per query
def names_in(c):
    out = [c[f] for f in NAME_FIELDS if f in c]
    if c["check"] == "unchanged" and isinstance(c.get("objects"), list): out += c["objects"]
    if c["check"] == "refused": out += c.get("mentions", [])
    return out

def simulate(q, stem, d, objs):
    bounds = d.get("bounds")
    checks = q["expect"]
    kinds = [c["check"] for c in checks]
    if "refused" in kinds:
        if len(checks) != 1: err(f"{q['id']}: a refusal carries other checks")
        m = checks[0].get("mentions", [])
        if len(m) == 1: err(f"{q['id']}: a refusal naming a single candidate is not an ambiguity")
        return
    st0 = objs
    on = resting_tree(st0)
    st = {k: v.copy() for k, v in st0.items()}
    held = set()
    for c in checks:
        if c["check"] == "unchanged" and isinstance(c["objects"], list): held |= set(c["objects"])
    on_sim = {c: s for c, s in on.items() if c not in held}
    drivers = set()
    for c in checks:
        k = c["check"]
        if k == "moved" and c.get("delta") is not None and any(abs(x) > 0 for x in c["delta"]): drivers.add(c["object"])
        if k in ("rotated", "direction", "faces", "scaled") or k in PLACE: drivers.add(c["object"])
    def driven(n):
        s = on_sim.get(n)
        while s is not None:
            if s in drivers: return True
            s = on_sim.get(s)
        return False
    moved = set()
    for c in checks:
        if c["check"] == "rotated" and not driven(c["object"]):
            moved |= set(move_group(st, c["object"], on_sim, q=yawq(c.get("degrees", 90))))
    for c in checks:
        if c["check"] == "scaled":
            n = c["object"]
            if carried(n, on_sim):
                err(f"{q['id']}: {n} carries {carried(n, on_sim)}; scaling a support is not worked out here")
            st[n].scale *= c.get("factor", 1.0)
            moved.add(n)
    for c in checks:
        if c["check"] == "moved" and c["object"] in drivers and c.get("delta") and not driven(c["object"]):
            moved |= set(move_group(st, c["object"], on_sim, delta=c["delta"]))
    for c in checks:
        if c["check"] == "direction":
            i, sgn = AXES[c["axis"]]; dd = [0, 0, 0]; dd[i] = sgn * max(c.get("min", 0.05), 0.05)
            moved |= set(move_group(st, c["object"], on_sim, delta=dd))
    for c in checks:
        if c["check"] == "faces":
            o, t = c["object"], c["target"]
            co, ct = st[o].centre(), st[t].centre()
            want = math.degrees(math.atan2(ct[0]-co[0], ct[2]-co[2]))
            f = st[o].fwd(); have = math.degrees(math.atan2(f[0], f[2]))
            moved |= set(move_group(st, o, on_sim, q=yawq(want - have)))
    # placements
    placed = []
    for c in checks:
        if c["check"] in PLACE and c["object"] not in placed:
            placed.append(c["object"])
    for n in placed:
        if driven(n) and place_ok(st, n, checks, strict=False):
            # carried by a support that moves and still meets its checks where it was carried to
            continue
        if not driven(n) and place_ok(st0, n, checks, strict=False) and not any(c["check"] in ("moved", "direction", "rotated", "faces", "scaled") and c["object"] == n for c in checks):
            warn(f"{q['id']}: {n} already meets its placement checks at the start")
        w = witness(st, n, checks, bounds, on_sim)
        if w is None:
            err(f"{q['id']}: no collision-free spot for {n} meets {[c['check'] for c in checks if c.get('object') == n]}")
            return
        moved |= set([n] + carried(n, on_sim))
    # every check must agree with the worked answer
    for c in checks:
        k = c["check"]
        if k == "moved" and c.get("delta") is not None:
            n = c["object"]; b0, b1 = st0[n].bottom(), st[n].bottom()
            dd = [b1[i]-b0[i] for i in range(3)]
            if any(abs(dd[i] - c["delta"][i]) > c.get("tol", 0.05) * 0.5 for i in range(3)):
                err(f"{q['id']}: moved {n} expects {c['delta']} but the worked answer moves it {[round(x, 4) for x in dd]}")
        if k == "rotated":
            n = c["object"]
            dy = (yaw_of(st[n].rot) - yaw_of(st0[n].rot) + 180) % 360 - 180
            want = (c.get("degrees", 90) + 180) % 360 - 180
            ok = abs((dy - want + 180) % 360 - 180) < 0.5 or (c.get("either_sign") and abs((dy + want + 180) % 360 - 180) < 0.5)
            if not ok: err(f"{q['id']}: rotated {n} expects {want} but the worked answer turns it {dy:.1f}")
        if k == "direction":
            n = c["object"]; i, sgn = AXES[c["axis"]]
            b0, b1 = st0[n].bottom(), st[n].bottom()
            if sgn * (b1[i] - b0[i]) < c.get("min", 0.05) - EPS:
                err(f"{q['id']}: direction {n} not met by the worked answer")
        if k == "faces" and not chk_faces(st, c["object"], c["target"], 5):
            err(f"{q['id']}: faces {c['object']} not met by the worked answer")
        if k == "on_top" and not chk_on_top(st, c["object"], c["support"]):
            err(f"{q['id']}: on_top {c['object']} on {c['support']} not met by the worked answer")
        if k in ("next_to", "side", "between", "at", "distance") and not place_ok(st, c["object"], [c], strict=False):
            err(f"{q['id']}: {k} {c['object']} not met by the worked answer")
        if k == "unchanged" and isinstance(c["objects"], list):
            for n in c["objects"]:
                if n in moved: err(f"{q['id']}: {n} is to stay but the worked answer moves it")
                s = on.get(n)
                if s and s in moved and not chk_on_top(st, n, s):
                    err(f"{q['id']}: held {n} would be left in the air (should be a refusal)")
    # whatever the answer moves must be named by a check
    named = set()
    for c in checks:
        if c["check"] != "unchanged": named |= set(names_in(c))
    for n in moved:
        if n not in named:
            err(f"{q['id']}: {n} moves (carried) but no check covers it")
    for m in collisions(st0, st, bounds, moved):
        err(f"{q['id']}: worked answer collides: {m}")
    # contact words: the object whose move makes the contact must end touching something
    text = q["text"].lower()
    if any(w in text for w in CONTACT_WORDS):
        mvd = [c["object"] for c in checks if c["check"] == "moved" and any(abs(x) > 0 for x in c.get("delta") or [0])]
        if not mvd:
            err(f"{q['id']}: contact wording but no exact move")
        elif not any(touches(st, n, bounds) for n in mvd):
            err(f"{q['id']}: contact wording but the worked answer touches nothing")
    # generous readings of vague amounts must still be collision-free and stay on their support
    for c in checks:
        if c["check"] != "direction": continue
        mn = c.get("min", 0.05)
        probe = {0.01: 0.06, 0.03: 0.12, 0.04: 0.12}.get(mn, 0.25)
        st2 = {k: v.copy() for k, v in st0.items()}
        i, sgn = AXES[c["axis"]]; dd = [0, 0, 0]; dd[i] = sgn * probe
        g = move_group(st2, c["object"], on_sim, delta=dd)
        for m in collisions(st0, st2, bounds, set(g), 0.0):
            warn(f"{q['id']}: a {probe} m reading of '{c['axis']}' collides: {m}")
        s = on.get(c["object"])
        if s and not chk_on_top(st2, c["object"], s):
            warn(f"{q['id']}: a {probe} m reading takes {c['object']} off {s}")
        for n in held:
            s = on.get(n)
            if s in g and not chk_on_top(st2, n, s):
                warn(f"{q['id']}: a {probe} m reading leaves held {n} in the air")

def main():
    with open(SUITE) as f:
        suite = json.load(f)
    for k in suite:
        if k not in ("name", "scenes", "variations", "seed", "queries"): err(f"suite: unknown field {k}")
    if suite.get("variations") != 1: err("suite: variations must be 1")
    if not isinstance(suite.get("seed"), int): err("suite: seed must be an integer")
    scenes = {}
    for p in suite["scenes"]:
        stem = os.path.splitext(os.path.basename(p))[0]
        d, objs = load_scene(os.path.join(HERE, p))
        if d.get("name") != stem: err(f"{p}: name {d.get('name')} differs from the file stem")
        check_scene(stem, d, objs)
        scenes[stem] = (d, objs)
    ids, texts = set(), set()
    for q in suite["queries"]:
        qid = q.get("id", "?")
        for k in q:
            if k not in ("id", "category", "text", "scenes", "expect", "pick"): err(f"{qid}: unknown field {k}")
        if qid in ids: err(f"{qid}: duplicate id")
        ids.add(qid)
        if q["text"] in texts: err(f"{qid}: duplicate text")
        texts.add(q["text"])
        if "{" in q["text"] or "'" + "{" in q["text"]: err(f"{qid}: placeholder in text")
        if q.get("category") not in CATEGORIES: err(f"{qid}: bad category")
        if not q.get("expect"): err(f"{qid}: no checks"); continue
        if not q.get("scenes") or len(q["scenes"]) != 1: err(f"{qid}: needs exactly one scene"); continue
        for c in q["expect"]:
            k = c.get("check")
            if k not in CHECK_FIELDS: err(f"{qid}: unknown check {k}"); continue
            req, opt = CHECK_FIELDS[k]
            have = set(c) - {"check"}
            if req - have: err(f"{qid}: {k} lacks {req - have}")
            if have - req - opt: err(f"{qid}: {k} has unknown {have - req - opt}")
            if k == "direction" and c["axis"] not in AXES: err(f"{qid}: bad axis")
            if k == "side" and c["side"] not in ("left", "right", "front", "behind"): err(f"{qid}: bad side")
            if k == "unchanged" and not (c.get("objects", "others") == "others" or isinstance(c["objects"], list)):
                err(f"{qid}: bad unchanged objects")
            if k == "at" and (not isinstance(c["position"], list) or len(c["position"]) != 3): err(f"{qid}: bad at position")
            if k == "moved" and c.get("delta") is not None and len(c["delta"]) != 3: err(f"{qid}: bad delta")
            if k == "rotated" and c.get("tol", 5) > 5: warn(f"{qid}: loose rotation tolerance")
        kinds = [c["check"] for c in q["expect"]]
        if "refused" not in kinds and {"check": "unchanged", "objects": "others"} not in q["expect"]:
            warn(f"{qid}: no 'unchanged others'")
        for sc in q["scenes"]:
            if sc not in scenes: err(f"{qid}: unknown scene {sc}"); continue
            objs = scenes[sc][1]
            missing = [n for c in q["expect"] for n in names_in(c) if n not in objs]
            for n in missing:
                err(f"{qid}: {n} is not in {sc}")
            if not missing:
                simulate(q, sc, *scenes[sc])
    # summary
    per_scene, per_cat = {}, {}
    refusals = 0
    for q in suite["queries"]:
        for s in q["scenes"]: per_scene[s] = per_scene.get(s, 0) + 1
        per_cat[q["category"]] = per_cat.get(q["category"], 0) + 1
        if any(c["check"] == "refused" for c in q["expect"]): refusals += 1
    for w in warnings: print("warning:", w)
    for e in errors: print("ERROR:", e)
    print(f"{len(suite['queries'])} queries; per scene {per_scene}; per category {per_cat}; refusals {refusals}")
    print("OK" if not errors else f"{len(errors)} errors")
    return 1 if errors else 0

if __name__ == "__main__":
    sys.exit(main())
