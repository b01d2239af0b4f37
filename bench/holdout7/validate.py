#!/usr/bin/env python3
"""Validates the holdout7 benchmark (python3 stdlib only).

  python3 validate.py            # exit status 0 when everything holds

Checks
  * suite shape per SPEC section 6: only documented fields, the five
    categories, unique ids and texts, every query names exactly one of the
    suite's scenes, "variations": 1 and no placeholders (every object a check
    names exists in that scene);
  * scenes: unique names (case-insensitive), positive sizes, yaw-only unit
    quaternions, every box inside the room, no two boxes overlapping, every
    "on" object resting on the top face of its support;
  * answers: applying the hand-worked motion of each acting query passes all
    of that query's checks under a STRICT reading of each check, and doing
    nothing fails them under a LENIENT reading (so no check is vacuous);
    every refusal query has only a refused check and names real objects.

Check semantics used here (distances in metres, angles in degrees):
  moved      position change equals delta (null = any axis); strict: Euclidean
             error over the given axes <= tol; lenient: each axis <= tol.
  direction  moved >= min along axis; strict: <= 0.05 m on other axes.
  rotated    yaw change equals degrees (+ = counter-clockwise from above),
             either_sign allows both; tol default 5 (10 lenient).
  scaled     scale ratio equals factor (1 % strict, 5 % lenient).
  on_top     box bottom on the support's top face (0.02 m strict, 0.05 m
             lenient), box centre over the support's footprint.
  next_to    gap between the boxes <= max_gap (strict: largest of the 3-D and
             floor-plan gaps; lenient: smallest).
  side       left/right/front/behind = -x/+x/+z/-z of the other's box; strict:
             beyond its face and centred within its extent on the other axis.
  between    centre projects onto segment a-b; strict: t in [0.2, 0.8] and at
             most 0.25 m off the line; lenient: t in (0, 1), 1 m.
  at         pivot at position (null = any axis) within tol.
  faces      front direction points at the target; strict: within 20 degrees of
             its centre and the ray hits its box; lenient: one of the two (45).
  distance   several measures (pivot, box centre, floor-plan centre, box gaps);
             strict: all within [min, max]; lenient: some measure within.
  unchanged  listed objects (or "others": objects no other check is about) keep
             position, rotation and scale.
  no_collision  no two boxes interpenetrate (resting contact is fine).
  inside_bounds every box inside the room.
"""
import json
import math
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "holdout7.suite.json")
ANSWERS = os.path.join(HERE, "holdout7.answers.json")

CATEGORIES = ("simple", "compositional", "fuzzy", "compositional_fuzzy", "hard")
TARGET_SHARE = {"simple": 0.25, "compositional": 0.20, "fuzzy": 0.20, "compositional_fuzzy": 0.15, "hard": 0.20}
TOP_FIELDS = {"name", "scenes", "variations", "seed", "queries"}
QUERY_FIELDS = {"id", "category", "text", "scenes", "expect"}
CHECK_FIELDS = {
    "moved": {"object", "delta", "tol"},
    "direction": {"object", "axis", "min"},
    "rotated": {"object", "axis", "degrees", "either_sign", "tol"},
    "scaled": {"object", "factor", "tol"},
    "on_top": {"object", "support"},
    "next_to": {"object", "other", "max_gap"},
    "side": {"object", "other", "side", "max_gap"},
    "above": {"object", "other"},
    "below": {"object", "other"},
    "between": {"object", "a", "b"},
    "aligned": {"object", "other", "axis", "tol"},
    "at": {"object", "position", "tol"},
    "faces": {"object", "target"},
    "distance": {"object", "other", "min", "max"},
    "unchanged": {"objects"},
    "no_collision": set(),
    "inside_bounds": set(),
    "refused": {"mentions"},
}
REQUIRED = {
    "moved": {"object", "delta"}, "direction": {"object", "axis"}, "rotated": {"object", "degrees"},
    "scaled": {"object", "factor"}, "on_top": {"object", "support"}, "next_to": {"object", "other"},
    "side": {"object", "other", "side"}, "above": {"object", "other"}, "below": {"object", "other"},
    "between": {"object", "a", "b"}, "aligned": {"object", "other", "axis"}, "at": {"object", "position"},
    "faces": {"object", "target"}, "distance": {"object", "other"}, "unchanged": {"objects"},
    "no_collision": set(), "inside_bounds": set(), "refused": set(),
}
NAME_FIELDS = ("object", "other", "support", "target", "a", "b")
AXES = {"x": 0, "y": 1, "z": 2}

errors = []


def err(msg):
    errors.append(msg)


# ----------------------------------------------------------------------------
# geometry
# ----------------------------------------------------------------------------
def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def qrot(q, v):
    x, y, z, w = q
    p = [v[0], v[1], v[2], 0.0]
    qc = [-x, -y, -z, w]
    r = qmul(qmul(q, p), qc)
    return r[:3]


def yaw_q(deg):
    h = math.radians(deg) / 2
    return [0.0, math.sin(h), 0.0, math.cos(h)]


def yaw_of(q):
    f = qrot(q, [0, 0, 1])
    return math.degrees(math.atan2(f[0], f[2]))


def wrap(d):
    return (d + 180.0) % 360.0 - 180.0


class Box:
    def __init__(self, o):
        w, h, d = o["size"]
        s = o.get("scale", 1.0)
        q = o.get("rotation", [0, 0, 0, 1])
        p = o["position"]
        xs, ys, zs = [], [], []
        for cx in (-w / 2, w / 2):
            for cy in (0, h):
                for cz in (-d / 2, d / 2):
                    v = qrot(q, [cx * s, cy * s, cz * s])
                    xs.append(v[0] + p[0]); ys.append(v[1] + p[1]); zs.append(v[2] + p[2])
        self.min = [min(xs), min(ys), min(zs)]
        self.max = [max(xs), max(ys), max(zs)]
        self.c = [(self.min[i] + self.max[i]) / 2 for i in range(3)]
        self.pivot = list(p)
        fr = o.get("front", [0, 0, 1])
        self.front = qrot(q, fr)


def overlap(a, b, i):
    return min(a.max[i], b.max[i]) - max(a.min[i], b.min[i])


def gap_axes(a, b, axes):
    s = 0.0
    for i in axes:
        g = max(a.min[i] - b.max[i], b.min[i] - a.max[i], 0.0)
        s += g * g
    return math.sqrt(s)


def dist(p, q, axes=(0, 1, 2)):
    return math.sqrt(sum((p[i] - q[i]) ** 2 for i in axes))


# ----------------------------------------------------------------------------
# scenes
# ----------------------------------------------------------------------------
def load_scene(path):
    with open(path) as f:
        return json.load(f)


def objmap(scene):
    return {o["name"]: o for o in scene["objects"]}


def validate_scene(fname, sc):
    seen = set()
    for o in sc["objects"]:
        n = o.get("name")
        if not isinstance(n, str) or not n:
            err("%s: object without name" % fname)
            continue
        if n.lower() in seen:
            err("%s: duplicate name %r" % (fname, n))
        seen.add(n.lower())
        if len(o.get("size", [])) != 3 or any(v <= 0 for v in o["size"]):
            err("%s: %s bad size" % (fname, n))
        q = o.get("rotation", [0, 0, 0, 1])
        if abs(sum(v * v for v in q) - 1) > 1e-4 or abs(q[0]) > 1e-9 or abs(q[2]) > 1e-9:
            err("%s: %s rotation is not a unit yaw quaternion" % (fname, n))
        if o.get("scale", 1.0) <= 0:
            err("%s: %s bad scale" % (fname, n))
    n = len(sc["objects"])
    if not 15 <= n <= 40:
        err("%s: %d objects (want 15-40)" % (fname, n))
    bad = inside_bounds(sc, 1e-6)
    if bad:
        err("%s: outside bounds: %s" % (fname, bad))
    col = collisions(sc, 1e-6)
    if col:
        err("%s: overlapping boxes: %s" % (fname, col))
    om = objmap(sc)
    for o in sc["objects"]:
        if "on" in o:
            sup = om.get(o["on"])
            if sup is None:
                err("%s: %s rests on unknown %r" % (fname, o["name"], o["on"]))
            elif not on_top_ok(Box(o), Box(sup), 1e-6, 0.0):
                err("%s: %s does not rest on %s" % (fname, o["name"], o["on"]))


def inside_bounds(sc, eps):
    b = sc.get("bounds")
    if not b:
        return []
    out = []
    for o in sc["objects"]:
        bx = Box(o)
        if any(bx.min[i] < b["min"][i] - eps or bx.max[i] > b["max"][i] + eps for i in range(3)):
            out.append(o["name"])
    return out


def collisions(sc, eps):
    boxes = [(o["name"], Box(o)) for o in sc["objects"]]
    out = []
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            a, b = boxes[i][1], boxes[j][1]
            if all(overlap(a, b, k) > eps for k in range(3)):
                out.append((boxes[i][0], boxes[j][0]))
    return out


def on_top_ok(o, s, tol, margin):
    if abs(o.min[1] - s.max[1]) > tol:
        return False
    return (s.min[0] - margin <= o.c[0] <= s.max[0] + margin and
            s.min[2] - margin <= o.c[2] <= s.max[2] + margin)


# ----------------------------------------------------------------------------
# applying an answer
# ----------------------------------------------------------------------------
def apply(scene, moves, sign=1.0):
    out = json.loads(json.dumps(scene))
    om = objmap(out)
    for n, m in moves.items():
        o = om[n]
        d = m.get("delta", [0, 0, 0])
        o["position"] = [o["position"][i] + sign * d[i] for i in range(3)]
        if m.get("yaw"):
            o["rotation"] = qmul(yaw_q(sign * m["yaw"]), o.get("rotation", [0, 0, 0, 1]))
        if m.get("scale"):
            f = m["scale"] if sign > 0 else 1.0 / m["scale"]
            o["scale"] = o.get("scale", 1.0) * f
    return out


# ----------------------------------------------------------------------------
# checks
# ----------------------------------------------------------------------------
def check(c, before, after, subjects, strict):
    """Return None when the check passes, else a reason string."""
    t = c["check"]
    bm, am = objmap(before), objmap(after)
    if "object" in c:
        ob, oa = bm[c["object"]], am[c["object"]]
        Bb, Ba = Box(ob), Box(oa)
        d = [oa["position"][i] - ob["position"][i] for i in range(3)]
    if t == "moved":
        tol = c.get("tol", 0.05)
        errs = [d[i] - c["delta"][i] for i in range(3) if c["delta"][i] is not None]
        e = math.sqrt(sum(x * x for x in errs)) if strict else max([abs(x) for x in errs] or [0])
        return None if e <= tol + 1e-9 else "moved %s by %s" % (c["object"], fmt(d))
    if t == "direction":
        i = AXES[c["axis"][-1]]
        sgn = -1.0 if c["axis"].startswith("-") else 1.0
        along = sgn * d[i]
        if along < c.get("min", 0.01) - 1e-9:
            return "%s moved %.3f along %s" % (c["object"], along, c["axis"])
        lim = 0.05 if strict else max(0.2, 0.5 * along)
        if any(abs(d[k]) > lim for k in range(3) if k != i):
            return "%s moved off-axis %s" % (c["object"], fmt(d))
        return None
    if t == "rotated":
        ax = c.get("axis", "y")
        if ax.lstrip("+-") != "y":
            return "only yaw supported"
        dy = wrap(yaw_of(oa.get("rotation", [0, 0, 0, 1])) - yaw_of(ob.get("rotation", [0, 0, 0, 1])))
        if ax.startswith("-"):
            dy = -dy
        tol = c["tol"] if "tol" in c else (5.0 if strict else 10.0)
        want = c["degrees"]
        e = abs(wrap(dy - want))
        if c.get("either_sign"):
            e = min(e, abs(wrap(dy + want)))
        return None if e <= tol + 1e-6 else "%s turned %.1f" % (c["object"], dy)
    if t == "scaled":
        r = oa.get("scale", 1.0) / ob.get("scale", 1.0)
        tol = c.get("tol", 0.01 if strict else 0.05)
        return None if abs(r / c["factor"] - 1) <= tol else "%s scaled %.3f" % (c["object"], r)
    if t == "on_top":
        s = Box(am[c["support"]])
        ok = on_top_ok(Ba, s, 0.02 if strict else 0.05, 0.0 if strict else 0.05)
        return None if ok else "%s not on %s" % (c["object"], c["support"])
    if t == "next_to":
        other = Box(am[c["other"]])
        gs = [gap_axes(Ba, other, (0, 1, 2)), gap_axes(Ba, other, (0, 2))]
        g = max(gs) if strict else min(gs)
        return None if g <= c.get("max_gap", 0.5) + 1e-9 else "%s gap %.3f to %s" % (c["object"], g, c["other"])
    if t == "side":
        other = Box(am[c["other"]])
        side = c["side"]
        i, sgn = {"left": (0, -1), "right": (0, 1), "front": (2, 1), "behind": (2, -1)}[side]
        j = 2 if i == 0 else 0
        if strict:
            if sgn > 0:
                ok = Ba.min[i] >= other.max[i] - 0.02
            else:
                ok = Ba.max[i] <= other.min[i] + 0.02
            ok = ok and other.min[j] <= Ba.c[j] <= other.max[j]
        else:
            ok = sgn * (Ba.c[i] - other.c[i]) > 0
        if ok and "max_gap" in c:
            gs = [gap_axes(Ba, other, (0, 1, 2)), gap_axes(Ba, other, (0, 2))]
            ok = (max(gs) if strict else min(gs)) <= c["max_gap"] + 1e-9
        return None if ok else "%s not %s of %s" % (c["object"], side, c["other"])
    if t in ("above", "below"):
        other = Box(am[c["other"]])
        ok = Ba.min[1] >= other.max[1] - 0.02 if t == "above" else Ba.max[1] <= other.min[1] + 0.02
        return None if ok else "%s not %s %s" % (c["object"], t, c["other"])
    if t == "between":
        A, Bq = Box(am[c["a"]]).c, Box(am[c["b"]]).c
        P = Ba.c
        vx, vz = Bq[0] - A[0], Bq[2] - A[2]
        L2 = vx * vx + vz * vz
        tt = ((P[0] - A[0]) * vx + (P[2] - A[2]) * vz) / L2
        px, pz = A[0] + tt * vx, A[2] + tt * vz
        perp = math.hypot(P[0] - px, P[2] - pz)
        ok = (0.2 <= tt <= 0.8 and perp <= 0.25) if strict else (0 < tt < 1 and perp <= 1.0)
        return None if ok else "%s not between (t=%.2f, off %.2f)" % (c["object"], tt, perp)
    if t == "aligned":
        other = Box(am[c["other"]])
        i = AXES[c["axis"].lstrip("+-")]
        return None if abs(Ba.c[i] - other.c[i]) <= c.get("tol", 0.05) else "not aligned"
    if t == "at":
        p = oa["position"]
        errs = [p[i] - c["position"][i] for i in range(3) if c["position"][i] is not None]
        e = math.sqrt(sum(x * x for x in errs)) if strict else max(abs(x) for x in errs)
        return None if e <= c.get("tol", 0.05) + 1e-9 else "%s at %s" % (c["object"], fmt(p))
    if t == "faces":
        tgt = Box(am[c["target"]])
        fx, fz = Ba.front[0], Ba.front[2]
        n = math.hypot(fx, fz)
        fx, fz = fx / n, fz / n
        tx, tz = tgt.c[0] - Ba.c[0], tgt.c[2] - Ba.c[2]
        ang = math.degrees(math.acos(max(-1, min(1, (fx * tx + fz * tz) / math.hypot(tx, tz)))))
        hit = ray_hits(Ba.c[0], Ba.c[2], fx, fz, tgt)
        ok = (ang <= 20 and hit) if strict else (ang <= 45 or hit)
        return None if ok else "%s faces %.1f deg off %s" % (c["object"], ang, c["target"])
    if t == "distance":
        other_o = am[c["other"]]
        other = Box(other_o)
        ms = [dist(oa["position"], other_o["position"]), dist(Ba.c, other.c), dist(Ba.c, other.c, (0, 2)),
              gap_axes(Ba, other, (0, 1, 2)), gap_axes(Ba, other, (0, 2))]
        ok = True
        if "min" in c:
            ok = ok and ((min(ms) if strict else max(ms)) >= c["min"] - 1e-9)
        if "max" in c:
            ok = ok and ((max(ms) if strict else min(ms)) <= c["max"] + 1e-9)
        return None if ok else "%s-%s distances %s" % (c["object"], c["other"], fmt(ms))
    if t == "unchanged":
        objs = c["objects"]
        if objs == "others":
            objs = [n for n in bm if n not in subjects]
        eps = 1e-4 if strict else 1e-2
        for n in objs:
            x, y = bm[n], am[n]
            if (dist(x["position"], y["position"]) > eps or
                    abs(wrap(yaw_of(x.get("rotation", [0, 0, 0, 1])) - yaw_of(y.get("rotation", [0, 0, 0, 1])))) > 0.1 or
                    abs(x.get("scale", 1) - y.get("scale", 1)) > 1e-6):
                return "%s changed" % n
        return None
    if t == "no_collision":
        col = collisions(after, 1e-6 if strict else 0.01)
        return None if not col else "collisions %s" % col
    if t == "inside_bounds":
        bad = inside_bounds(after, 1e-6 if strict else 0.01)
        return None if not bad else "outside bounds %s" % bad
    return "unknown check %s" % t


def ray_hits(x, z, fx, fz, box):
    tmin, tmax = 0.0, 1e9
    for p, f, lo, hi in ((x, fx, box.min[0], box.max[0]), (z, fz, box.min[2], box.max[2])):
        if abs(f) < 1e-12:
            if p < lo or p > hi:
                return False
        else:
            t1, t2 = (lo - p) / f, (hi - p) / f
            tmin, tmax = max(tmin, min(t1, t2)), min(tmax, max(t1, t2))
    return tmin <= tmax


def fmt(v):
    return "[" + ", ".join("%.3f" % x for x in v) + "]"


# ----------------------------------------------------------------------------
def main():
    with open(SUITE) as f:
        suite = json.load(f)
    with open(ANSWERS) as f:
        answers = json.load(f)["answers"]

    extra = set(suite) - TOP_FIELDS
    if extra:
        err("suite: undocumented top-level fields %s" % sorted(extra))
    if suite.get("variations") != 1:
        err("suite: variations must be 1")
    scenes = {}
    for p in suite["scenes"]:
        full = os.path.join(HERE, p)
        if not os.path.exists(full):
            err("missing scene %s" % p)
            continue
        scenes[p] = load_scene(full)
        validate_scene(p, scenes[p])
    if len(scenes) != 4:
        err("want four scenes, have %d" % len(scenes))

    ids, texts = set(), set()
    cats = {c: 0 for c in CATEGORIES}
    refusals = 0
    per_scene = {}
    negated_pass = []
    for q in suite["queries"]:
        qid = q.get("id")
        where = "query %s" % qid
        extra = set(q) - QUERY_FIELDS
        if extra:
            err("%s: undocumented fields %s" % (where, sorted(extra)))
        for k in QUERY_FIELDS:
            if k not in q:
                err("%s: missing %s" % (where, k))
        if qid in ids:
            err("%s: duplicate id" % where)
        ids.add(qid)
        norm = re.sub(r"\s+", " ", q["text"].strip().lower())
        if norm in texts:
            err("%s: duplicate text" % where)
        texts.add(norm)
        if re.search(r"\{[A-Za-z_]\w*\}", q["text"]):
            err("%s: placeholder in text" % where)
        if q.get("category") not in CATEGORIES:
            err("%s: bad category %r" % (where, q.get("category")))
        else:
            cats[q["category"]] += 1
        if not (isinstance(q.get("scenes"), list) and len(q["scenes"]) == 1 and q["scenes"][0] in scenes):
            err("%s: scenes must be one of the suite's scenes" % where)
            continue
        sp = q["scenes"][0]
        per_scene[sp] = per_scene.get(sp, 0) + 1
        sc = scenes[sp]
        names = set(objmap(sc))
        expect = q.get("expect") or []
        if not expect:
            err("%s: no checks" % where)
            continue
        for c in expect:
            t = c.get("check")
            if t not in CHECK_FIELDS:
                err("%s: unknown check %r" % (where, t))
                continue
            extra = set(c) - CHECK_FIELDS[t] - {"check"}
            if extra:
                err("%s: %s has undocumented fields %s" % (where, t, sorted(extra)))
            miss = REQUIRED[t] - set(c)
            if miss:
                err("%s: %s lacks %s" % (where, t, sorted(miss)))
            for k in NAME_FIELDS:
                if k in c and c[k] not in names:
                    err("%s: %s names unknown object %r" % (where, t, c[k]))
            if t == "unchanged" and c["objects"] != "others":
                for n in c["objects"]:
                    if n not in names:
                        err("%s: unchanged names unknown object %r" % (where, n))
            if t == "refused":
                for n in c.get("mentions", []):
                    if n not in names:
                        err("%s: refusal mentions unknown object %r" % (where, n))
            if t == "moved" and len(c["delta"]) != 3:
                err("%s: delta must have 3 entries" % where)
            if t == "direction" and c["axis"] not in ("+x", "-x", "+y", "-y", "+z", "-z"):
                err("%s: bad axis %r" % (where, c["axis"]))
            if t == "side" and c["side"] not in ("left", "right", "front", "behind"):
                err("%s: bad side %r" % (where, c["side"]))
        is_ref = any(c.get("check") == "refused" for c in expect)
        ans = answers.get(qid)
        if ans is None:
            err("%s: no hand-worked answer" % where)
            continue
        if is_ref:
            refusals += 1
            if len(expect) != 1:
                err("%s: a refusal query must have only the refused check" % where)
            if not ans.get("refuse"):
                err("%s: answer should be a refusal" % where)
            continue
        if ans.get("refuse"):
            err("%s: answer refuses an acting query" % where)
            continue
        if not any(c["check"] == "unchanged" for c in expect):
            err("%s: acting query without an unchanged check" % where)
        moves = ans["moves"]
        for n in moves:
            if n not in names:
                err("%s: answer moves unknown %r" % (where, n))
        if any(n not in names for n in moves):
            continue
        subjects = {c["object"] for c in expect if "object" in c}
        after = apply(sc, moves)
        for c in expect:
            r = check(c, sc, after, subjects, strict=True)
            if r:
                err("%s (%s): answer fails %s: %s" % (where, q["text"], c["check"], r))
        # doing nothing must fail under the lenient reading
        if all(check(c, sc, sc, subjects, strict=False) is None for c in expect):
            err("%s (%s): doing nothing passes every check" % (where, q["text"]))
        neg = apply(sc, moves, sign=-1.0)
        if all(check(c, sc, neg, subjects, strict=False) is None for c in expect):
            negated_pass.append(qid)

    total = len(suite["queries"])
    if total < 260:
        err("only %d queries (want >= 260)" % total)
    share = refusals / float(total or 1)
    if not 0.10 <= share <= 0.14:
        err("refusals are %.1f%% (want about 12%%)" % (100 * share))
    for c in CATEGORIES:
        if abs(cats[c] / float(total or 1) - TARGET_SHARE[c]) > 0.04:
            err("category %s is %.1f%% (want about %d%%)" % (c, 100.0 * cats[c] / total, 100 * TARGET_SHARE[c]))

    print("queries: %d" % total)
    for c in CATEGORIES:
        print("  %-20s %3d  (%.1f%%)" % (c, cats[c], 100.0 * cats[c] / total))
    print("refusals: %d (%.1f%%)" % (refusals, 100 * share))
    print("per scene: %s" % per_scene)
    print("acting queries whose reversed answer also passes (symmetric edits): %s" % (negated_pass or "none"))
    if errors:
        print("\nFAILED: %d problem(s)" % len(errors))
        for e in errors:
            print("  - " + e)
        return 1
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
