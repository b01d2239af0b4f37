#!/usr/bin/env python3
"""Sanity checks for holdout9 (independent of gen.py): JSON shape against SPEC 6 /
docs/benchmark.md field names, unique ids, object names, scene geometry (bounds,
interpenetration, resting), and that the moves the expectations imply stay in the room
and do not land inside other objects."""
import json, math, os, re, sys
from collections import Counter

HERE = os.path.dirname(os.path.abspath(__file__))
EPS = 1e-6
ERR, WARN = [], []

CATS = {"simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"}
SUITE_KEYS = {"name", "scenes", "variations", "seed", "queries"}
QUERY_KEYS = {"id", "category", "text", "pick", "expect", "scenes"}
CHECKS = {
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


def qmat(q):
    x, y, z, w = q
    return [[1 - 2*(y*y + z*z), 2*(x*y - z*w), 2*(x*z + y*w)],
            [2*(x*y + z*w), 1 - 2*(x*x + z*z), 2*(y*z - x*w)],
            [2*(x*z - y*w), 2*(y*z + x*w), 1 - 2*(x*x + y*y)]]


def box(size, pos, rot, scale, extra_yaw_deg=0.0, extra_scale=1.0):
    w, h, d = size
    m = qmat(rot)
    if extra_yaw_deg:
        a = math.radians(extra_yaw_deg)
        ry = [[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]]
        m = [[sum(ry[i][k] * m[k][j] for k in range(3)) for j in range(3)] for i in range(3)]
    s = scale * extra_scale
    lo, hi = [1e9] * 3, [-1e9] * 3
    for cx in (-w/2, w/2):
        for cy in (0, h):
            for cz in (-d/2, d/2):
                v = (cx*s, cy*s, cz*s)
                for i in range(3):
                    r = sum(m[i][j]*v[j] for j in range(3)) + pos[i]
                    lo[i] = min(lo[i], r); hi[i] = max(hi[i], r)
    return lo, hi


def overlap(a, b):
    return all(min(a[1][i], b[1][i]) - max(a[0][i], b[0][i]) > 1e-4 for i in range(3))


def inside(bx, bounds):
    return all(bx[0][i] >= bounds["min"][i] - 1e-4 and bx[1][i] <= bounds["max"][i] + 1e-4 for i in range(3))


def shift(bx, d):
    return ([bx[0][i] + d[i] for i in range(3)], [bx[1][i] + d[i] for i in range(3)])


def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except Exception as e:  # noqa
        ERR.append(f"{path}: not valid JSON: {e}")
        return None


class Scene:
    def __init__(self, data, fn):
        self.fn = fn
        self.name = data["name"]
        self.bounds = data.get("bounds")
        self.objs = {}
        for o in data["objects"]:
            k = o["name"].lower()
            if k in self.objs:
                ERR.append(f"{fn}: duplicate name {o['name']}")
            self.objs[k] = o
        for o in data["objects"]:
            if any(v <= 0 for v in o["size"]):
                ERR.append(f"{fn}: {o['name']} size not > 0")
            o["_box"] = box(o["size"], o["position"], o.get("rotation", [0, 0, 0, 1]), o.get("scale", 1.0))
        self.support = {}
        names = list(self.objs)
        for k in names:
            o = self.objs[k]
            bx = o["_box"]
            if self.bounds and not inside(bx, self.bounds):
                ERR.append(f"{fn}: {o['name']} outside bounds")
            if abs(bx[0][1]) < EPS:
                if "on" in o:
                    ERR.append(f"{fn}: {o['name']} on floor but declares on={o['on']}")
                continue
            sups = []
            cx, cz = (bx[0][0] + bx[1][0]) / 2, (bx[0][2] + bx[1][2]) / 2
            for k2 in names:
                if k2 == k:
                    continue
                b2 = self.objs[k2]["_box"]
                if abs(b2[1][1] - bx[0][1]) < 1e-4 and b2[0][0] - EPS <= cx <= b2[1][0] + EPS and b2[0][2] - EPS <= cz <= b2[1][2] + EPS:
                    sups.append(k2)
            if len(sups) != 1:
                ERR.append(f"{fn}: {o['name']} floats or has {len(sups)} supports {sups}")
            else:
                self.support[k] = sups[0]
                if o.get("on", "").lower() != sups[0]:
                    ERR.append(f"{fn}: {o['name']} rests on {sups[0]} but declares on={o.get('on')}")
        for i, a in enumerate(names):
            for b in names[i+1:]:
                if overlap(self.objs[a]["_box"], self.objs[b]["_box"]):
                    ERR.append(f"{fn}: {a} and {b} interpenetrate")

    def has(self, n):
        return isinstance(n, str) and n.lower() in self.objs

    def dependents(self, k):
        out, todo = set(), [k]
        while todo:
            c = todo.pop()
            for d, s in self.support.items():
                if s == c and d not in out:
                    out.add(d); todo.append(d)
        return out


def ctr(b):
    return [(b[0][i] + b[1][i]) / 2 for i in range(3)]


def holds_now(scene, c):
    """Evaluate a relational check on the unedited scene (None = not evaluable / an edit check)."""
    kind = c["check"]
    g = lambda n: scene.objs[n.lower()]["_box"]
    if kind == "on_top":
        a, s = g(c["object"]), g(c["support"])
        cx, cz = ctr(a)[0], ctr(a)[2]
        return abs(a[0][1] - s[1][1]) <= c.get("tol", 0.03) and s[0][0] <= cx <= s[1][0] and s[0][2] <= cz <= s[1][2]
    if kind == "next_to":
        a, b = g(c["object"]), g(c["other"])
        dx = max(a[0][0] - b[1][0], b[0][0] - a[1][0], 0)
        dz = max(a[0][2] - b[1][2], b[0][2] - a[1][2], 0)
        hov = min(a[1][1], b[1][1]) > max(a[0][1], b[0][1])
        return math.hypot(dx, dz) <= c.get("max_gap", 0.3) and hov and not overlap(a, b)
    if kind == "side":
        a, b = g(c["object"]), g(c["other"])
        sd = c["side"]
        if sd in ("left", "right"):
            gap = b[0][0] - a[1][0] if sd == "left" else a[0][0] - b[1][0]
            across = min(a[1][2], b[1][2]) > max(a[0][2], b[0][2])
        else:
            gap = a[0][2] - b[1][2] if sd == "front" else b[0][2] - a[1][2]
            across = min(a[1][0], b[1][0]) > max(a[0][0], b[0][0])
        return -0.02 <= gap <= c.get("max_gap", 0.5) and across
    if kind == "between":
        p, a, b = ctr(g(c["object"])), ctr(g(c["a"])), ctr(g(c["b"]))
        ax, az, bx, bz = a[0], a[2], b[0], b[2]
        L2 = (bx - ax) ** 2 + (bz - az) ** 2
        t = ((p[0] - ax) * (bx - ax) + (p[2] - az) * (bz - az)) / L2
        d = math.hypot(p[0] - (ax + t * (bx - ax)), p[2] - (az + t * (bz - az)))
        return 0 <= t <= 1 and d <= c.get("tol", 0.3)
    if kind == "aligned":
        i = "xyz".index(c["axis"][-1])
        return abs(ctr(g(c["object"]))[i] - ctr(g(c["other"]))[i]) <= c.get("tol", 0.05)
    if kind == "at":
        b = g(c["object"]); bc = [ctr(b)[0], b[0][1], ctr(b)[2]]
        return all(p is None or abs(p - bc[i]) <= c.get("tol", 0.05) for i, p in enumerate(c["position"]))
    if kind == "faces":
        o = scene.objs[c["object"].lower()]
        m = qmat(o.get("rotation", [0, 0, 0, 1]))
        f = o.get("front", [0, 0, 1])
        fx, fz = sum(m[0][j] * f[j] for j in range(3)), sum(m[2][j] * f[j] for j in range(3))
        a, t = ctr(o["_box"]), ctr(g(c["target"]))
        ang = math.degrees(abs(math.atan2(fx * (t[2] - a[2]) - fz * (t[0] - a[0]), fx * (t[0] - a[0]) + fz * (t[2] - a[2]))))
        return ang <= c.get("tol", 20)
    if kind == "distance":
        a, b = ctr(g(c["object"])), ctr(g(c["other"]))
        ok = True
        for d in (math.dist(a, b), math.hypot(a[0] - b[0], a[2] - b[2])):
            ok = ok and c.get("min", 0) <= d <= c.get("max", 1e9)
        return ok
    return None


def predicted(scene, q):
    """Final boxes for objects whose final pose the checks pin down (or bound from below)."""
    fin = {}
    moving = set()
    for c in q["expect"]:
        o = c.get("object", "")
        if not scene.has(o):
            continue
        k = o.lower()
        ob = scene.objs[k]
        kind = c["check"]
        if kind in ("moved", "at", "direction", "swapped", "rotated", "scaled", "on_top", "next_to", "side",
                    "between", "aligned", "faces", "distance"):
            moving.add(k)
            moving |= scene.dependents(k)
        if kind == "swapped":
            moving.add(c["other"].lower()); moving |= scene.dependents(c["other"].lower())
        cur = fin.get(k, ob["_box"])
        if kind == "moved" and c.get("delta") and None not in c["delta"]:
            fin[k] = shift(cur, c["delta"])
            for d in scene.dependents(k):
                fin[d] = shift(fin.get(d, scene.objs[d]["_box"]), c["delta"])
        elif kind == "at" and not (c["position"][0] is None and c["position"][2] is None):
            p = c["position"]
            bc = [(cur[0][0] + cur[1][0]) / 2, cur[0][1], (cur[0][2] + cur[1][2]) / 2]
            dlt = [0 if p[i] is None else p[i] - bc[i] for i in range(3)]
            fin[k] = shift(cur, dlt)
            for d in scene.dependents(k):
                fin[d] = shift(fin.get(d, scene.objs[d]["_box"]), dlt)
        elif kind == "direction":
            ax = {"x": 0, "y": 1, "z": 2}[c["axis"][1]]
            dlt = [0, 0, 0]
            dlt[ax] = c.get("min", 0.05) * (1 if c["axis"][0] == "+" else -1)
            fin[k] = shift(cur, dlt)
        elif kind == "swapped":
            o2 = scene.objs[c["other"].lower()]
            b1, b2 = ob["_box"], o2["_box"]
            p1 = [(b1[0][0] + b1[1][0]) / 2, b1[0][1], (b1[0][2] + b1[1][2]) / 2]
            p2 = [(b2[0][0] + b2[1][0]) / 2, b2[0][1], (b2[0][2] + b2[1][2]) / 2]
            fin[k] = shift(b1, [p2[i] - p1[i] for i in range(3)])
            fin[c["other"].lower()] = shift(b2, [p1[i] - p2[i] for i in range(3)])
        elif kind == "rotated":
            deg = c.get("degrees", 90)
            for sgn in ((1, -1) if c.get("either_sign") else (1,)):
                b = box(ob["size"], ob["position"], ob.get("rotation", [0, 0, 0, 1]), ob.get("scale", 1.0), sgn * deg)
                if scene.bounds and not inside(b, scene.bounds):
                    ERR.append(f"{q['id']}: rotating {o} by {sgn*deg} leaves the room")
            fin.setdefault(k, box(ob["size"], ob["position"], ob.get("rotation", [0, 0, 0, 1]), ob.get("scale", 1.0), deg))
        elif kind == "scaled":
            fin[k] = box(ob["size"], ob["position"], ob.get("rotation", [0, 0, 0, 1]), ob.get("scale", 1.0), 0, c["factor"])
    return fin, moving


def main():
    suite_path = os.path.join(HERE, "holdout9.suite.json")
    suite = load(suite_path)
    if suite is None:
        return report()
    if set(suite) != SUITE_KEYS:
        ERR.append(f"suite keys {sorted(suite)} != {sorted(SUITE_KEYS)}")
    scenes = {}
    for fn in suite["scenes"]:
        data = load(os.path.join(HERE, fn))
        if data is None:
            continue
        if set(data) - {"name", "bounds", "objects"}:
            WARN.append(f"{fn}: extra top-level keys {set(data) - {'name','bounds','objects'}}")
        sc = Scene(data, fn)
        scenes[sc.name] = sc
        if not (20 <= len(sc.objs) <= 40):
            ERR.append(f"{fn}: {len(sc.objs)} objects (want 20-40)")
    ids = Counter(q["id"] for q in suite["queries"])
    for i, n in ids.items():
        if n > 1:
            ERR.append(f"duplicate id {i}")
    per_scene, per_cat, refusals = Counter(), Counter(), Counter()
    texts = Counter()
    for q in suite["queries"]:
        qid = q.get("id", "?")
        if set(q) - QUERY_KEYS:
            ERR.append(f"{qid}: unknown query keys {set(q) - QUERY_KEYS}")
        for k in ("id", "category", "text", "expect"):
            if k not in q:
                ERR.append(f"{qid}: missing {k}")
        if q["category"] not in CATS:
            ERR.append(f"{qid}: bad category")
        if "{" in q["text"] or "}" in q["text"]:
            ERR.append(f"{qid}: text has a placeholder brace")
        if q.get("pick", {}) != {}:
            ERR.append(f"{qid}: pick should be empty (no placeholders)")
        texts[q["text"].lower()] += 1
        sn = q.get("scenes", [None])
        if len(sn) != 1 or sn[0] not in scenes:
            ERR.append(f"{qid}: scenes {sn} not one of the suite's scenes")
            continue
        scene = scenes[sn[0]]
        m = re.fullmatch(r"([a-z_]+)-(simple|compositional|fuzzy|compositional_fuzzy|hard)-(\d\d)", qid)
        if not m or m.group(1) != scene.name or m.group(2) != q["category"]:
            ERR.append(f"{qid}: id does not match <scene>-<category>-NN")
        per_scene[scene.name] += 1
        per_cat[q["category"]] += 1
        kinds = [c["check"] for c in q["expect"]]
        for c in q["expect"]:
            kind = c.get("check")
            if kind not in CHECKS:
                ERR.append(f"{qid}: unknown check {kind}"); continue
            req, opt = CHECKS[kind]
            fields = set(c) - {"check"}
            if req - fields:
                ERR.append(f"{qid}: {kind} missing {req - fields}")
            if fields - req - opt:
                ERR.append(f"{qid}: {kind} unknown fields {fields - req - opt}")
            for f in NAME_FIELDS:
                if f in c and not scene.has(c[f]):
                    ERR.append(f"{qid}: {kind}.{f} = {c[f]!r} not in {scene.name}")
            if kind == "unchanged" and isinstance(c.get("objects"), list):
                for n in c["objects"]:
                    if not scene.has(n):
                        ERR.append(f"{qid}: unchanged names {n!r} not in scene")
            if kind == "refused":
                for n in c.get("mentions", []):
                    if not scene.has(n):
                        ERR.append(f"{qid}: refused mentions {n!r} not in scene")
            if kind in ("on_top", "next_to", "side", "faces", "distance", "swapped", "aligned"):
                other = c.get("support") or c.get("other") or c.get("target")
                if other and other.lower() == c["object"].lower():
                    ERR.append(f"{qid}: {kind} object == other")
            if kind == "on_top":
                o, s = scene.objs[c["object"].lower()], scene.objs[c["support"].lower()]
                ob, sb = o["_box"], s["_box"]
                ow, od = ob[1][0] - ob[0][0], ob[1][2] - ob[0][2]
                sw_, sd_ = sb[1][0] - sb[0][0], sb[1][2] - sb[0][2]
                if not ((ow <= sw_ + EPS and od <= sd_ + EPS) or (od <= sw_ + EPS and ow <= sd_ + EPS)) and \
                        not (max(ow, od) <= max(sw_, sd_) * 1.3):
                    WARN.append(f"{qid}: {c['object']} footprint larger than {c['support']}")
                if c["support"].lower() in scene.dependents(c["object"].lower()):
                    ERR.append(f"{qid}: support rests on the object")
            if kind == "direction" and c["axis"] not in ("+x", "-x", "+y", "-y", "+z", "-z"):
                ERR.append(f"{qid}: bad axis")
            if kind == "distance" and c.get("max") is not None and c["max"] <= 0:
                ERR.append(f"{qid}: distance max <= 0")
        if "refused" in kinds:
            refusals[scene.name] += 1
            if len(kinds) != 1:
                WARN.append(f"{qid}: refused query has other checks")
            continue
        if "unchanged" not in kinds:
            WARN.append(f"{qid}: no unchanged check")
        evals = [holds_now(scene, c) for c in q["expect"] if c["check"] not in ("unchanged", "no_collision", "inside_bounds")]
        if evals and all(e is True for e in evals):
            ERR.append(f"{qid}: every check already holds on the unedited scene")
        for c in q["expect"]:
            if c["check"] in ("next_to", "side", "between", "faces", "distance", "aligned", "at") and holds_now(scene, c):
                WARN.append(f"{qid}: {c['check']} on {c['object']} already holds before the edit")
        fin, moving = predicted(scene, q)
        for k, bx in fin.items():
            if scene.bounds and not inside(bx, scene.bounds):
                ERR.append(f"{qid}: implied final pose of {k} leaves the room {bx}")
            for k2, o2 in scene.objs.items():
                if k2 == k or k2 in moving:
                    continue
                if overlap(bx, o2["_box"]):
                    WARN.append(f"{qid}: implied final pose of {k} overlaps {k2}")
    for t, n in texts.items():
        if n > 1:
            WARN.append(f"text used {n} times: {t!r}")
    total = sum(per_scene.values())
    nref = sum(refusals.values())
    print("queries per scene:", dict(per_scene))
    print("queries per category:", dict(per_cat))
    print(f"refusals: {nref} of {total} ({100*nref/total:.1f}%)", dict(refusals))
    for sn, sc in scenes.items():
        print(f"scene {sn}: {len(sc.objs)} objects, {len(sc.support)} resting")
    if not (0.10 <= nref / total <= 0.12):
        ERR.append("refusal share outside 10-12%")
    report()


def report():
    for w in WARN:
        print("WARN", w)
    for e in ERR:
        print("ERROR", e)
    print("OK" if not ERR else f"{len(ERR)} errors")
    sys.exit(1 if ERR else 0)


if __name__ == "__main__":
    main()
