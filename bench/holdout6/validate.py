#!/usr/bin/env python3
"""Validate the holdout6 suite, its scenes and the hand-worked answers (stdlib only).

Checks
  * suite shape: only documented top-level / query / check fields, the five categories,
    unique ids and texts, one scene per query, no placeholders;
  * scenes: unique names (case-insensitive), only SPEC section-2 fields (no category/aliases),
    yaw-only unit quaternions, everything inside bounds, no two boxes overlapping, every object
    on the floor, resting exactly on one support's top face (footprint inside), or hung on a
    wall it touches;
  * every object named by a check exists in the query's scene;
  * every non-refusal query: ends with no_collision + unchanged others, tolerances in range,
    is not already satisfied by the unchanged scene,
    and its hand-worked answer (holdout6.answers.json) applied to the scene passes every check,
    creates no overlap, stays in bounds and leaves nothing floating; things resting on a moved
    object move with it and are checked;
  * refusal share 12-15 %, >= 260 queries, >= 55 per scene.
Exit status 0 when everything holds.
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "holdout6.suite.json")
ANSWERS = os.path.join(HERE, "holdout6.answers.json")

CATEGORIES = {"simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"}
TOP_FIELDS = {"name", "scenes", "variations", "seed", "queries"}
QUERY_FIELDS = {"id", "category", "text", "scenes", "expect", "pick"}
CHECK_FIELDS = {
    "moved": {"object", "delta", "tol"},
    "direction": {"object", "axis", "min"},
    "rotated": {"object", "axis", "degrees", "either_sign", "tol"},
    "scaled": {"object", "factor", "tol"},
    "on_top": {"object", "support", "tol"},
    "next_to": {"object", "other", "max_gap"},
    "side": {"object", "other", "side", "max_gap"},
    "above": {"object", "other", "tol"},
    "below": {"object", "other", "tol"},
    "between": {"object", "a", "b", "tol"},
    "aligned": {"object", "other", "axis", "tol"},
    "at": {"object", "position", "tol"},
    "faces": {"object", "target", "tol"},
    "distance": {"object", "other", "min", "max"},
    "unchanged": {"objects"},
    "no_collision": set(),
    "inside_bounds": set(),
    "swapped": {"object", "other", "tol"},
    "refused": {"mentions"},
}
NAME_FIELDS = ("object", "other", "support", "a", "b", "target")
OBJ_FIELDS = {"name", "position", "size", "rotation", "scale"}
EPS = 1e-6
OVERLAP_EPS = 1e-6

errors = []
warnings = []


def err(msg):
    errors.append(msg)


# ------------------------------------------------------------------ geometry
def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def qrot(q, v):
    x, y, z, w = q
    vx, vy, vz = v
    # t = 2 * cross(q.xyz, v)
    tx = 2 * (y * vz - z * vy)
    ty = 2 * (z * vx - x * vz)
    tz = 2 * (x * vy - y * vx)
    return [vx + w * tx + (y * tz - z * ty),
            vy + w * ty + (z * tx - x * tz),
            vz + w * tz + (x * ty - y * tx)]


def yawq(deg):
    h = math.radians(deg) / 2
    return [0.0, math.sin(h), 0.0, math.cos(h)]


def yaw_of(q):
    x, y, z, w = q
    return math.degrees(2 * math.atan2(y, w))


def aabb(o):
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
    return [min(xs), min(ys), min(zs)], [max(xs), max(ys), max(zs)]


def centre(o):
    lo, hi = aabb(o)
    return [(lo[i] + hi[i]) / 2 for i in range(3)]


def bottom_centre(o):
    lo, hi = aabb(o)
    return [(lo[0] + hi[0]) / 2, lo[1], (lo[2] + hi[2]) / 2]


def overlap(a, b):
    (alo, ahi), (blo, bhi) = aabb(a), aabb(b)
    return all(min(ahi[i], bhi[i]) - max(alo[i], blo[i]) > OVERLAP_EPS for i in range(3))


def rests_on(o, s):
    """o rests on s's top face (bottom at s's top, footprint inside s's top)."""
    (olo, ohi), (slo, shi) = aabb(o), aabb(s)
    if abs(olo[1] - shi[1]) > 1e-4:
        return False
    return (olo[0] >= slo[0] - 1e-4 and ohi[0] <= shi[0] + 1e-4 and
            olo[2] >= slo[2] - 1e-4 and ohi[2] <= shi[2] + 1e-4)


def roughly_on(o, s):
    """bottom on the top and centre over the footprint (used for 'what rests on them')."""
    (olo, ohi), (slo, shi) = aabb(o), aabb(s)
    c = centre(o)
    return (abs(olo[1] - shi[1]) <= 1e-3 and slo[0] <= c[0] <= shi[0] and slo[2] <= c[2] <= shi[2])


def hangs(o, bounds):
    lo, hi = aabb(o)
    bmin, bmax = bounds["min"], bounds["max"]
    return (abs(lo[0] - bmin[0]) < 1e-4 or abs(hi[0] - bmax[0]) < 1e-4 or
            abs(lo[2] - bmin[2]) < 1e-4 or abs(hi[2] - bmax[2]) < 1e-4)


def physical_problems(scene, objs, before=None):
    """List of problems: overlap, out of bounds, floating.  With `before`, only new ones."""
    probs = []
    bounds = scene["bounds"]
    names = list(objs)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if overlap(objs[a], objs[b]):
                if before is None or not overlap(before[a], before[b]):
                    probs.append(f"overlap {a!r} / {b!r}")
    for n in names:
        lo, hi = aabb(objs[n])
        for k in range(3):
            if lo[k] < bounds["min"][k] - 1e-6 or hi[k] > bounds["max"][k] + 1e-6:
                probs.append(f"{n!r} outside bounds")
                break
        if abs(lo[1]) < 1e-6:
            continue
        sup = [s for s in names if s != n and rests_on(objs[n], objs[s])]
        if len(sup) == 1:
            continue
        if len(sup) > 1:
            probs.append(f"{n!r} rests on several supports {sup}")
            continue
        if hangs(objs[n], bounds):
            continue
        probs.append(f"{n!r} floats (y={lo[1]:.3f})")
    return probs


# ------------------------------------------------------------------ checks
AX = {"x": 0, "y": 1, "z": 2}


def horiz_gap(alo, ahi, blo, bhi):
    gx = max(0.0, blo[0] - ahi[0], alo[0] - bhi[0])
    gz = max(0.0, blo[2] - ahi[2], alo[2] - bhi[2])
    return math.hypot(gx, gz)


def run_check(c, before, after):
    """Return None when the check passes, else a reason."""
    k = c["check"]
    if k == "moved":
        o = c["object"]
        b, a = bottom_centre(before[o]), bottom_centre(after[o])
        d = c.get("delta")
        tol = c.get("tol", 0.05)
        if d is None:
            return None if any(abs(a[i] - b[i]) > 1e-6 for i in range(3)) else "did not move"
        err2 = 0.0
        for i in range(3):
            if d[i] is None:
                continue
            err2 += (a[i] - b[i] - d[i]) ** 2
        return None if math.sqrt(err2) <= tol else f"moved {[round(a[i]-b[i],3) for i in range(3)]}"
    if k == "direction":
        o = c["object"]
        b, a = bottom_centre(before[o]), bottom_centre(after[o])
        d = [a[i] - b[i] for i in range(3)]
        ax = c["axis"]
        i = AX[ax[1]]
        sgn = 1 if ax[0] == "+" else -1
        along = sgn * d[i]
        across = math.sqrt(sum(d[j] ** 2 for j in range(3) if j != i))
        if along < c.get("min", 0.05):
            return f"along {along:.3f}"
        if across > max(0.1, along / 4):
            return f"across {across:.3f}"
        return None
    if k == "rotated":
        o = c["object"]
        qb, qa = before[o]["rotation"], after[o]["rotation"]
        qbi = [-qb[0], -qb[1], -qb[2], qb[3]]
        r = qmul(qa, qbi)
        off = math.degrees(2 * math.asin(min(1.0, math.hypot(r[0], r[2]))))
        ang = math.degrees(2 * math.atan2(r[1], r[3]))
        ang = (ang + 180) % 360 - 180
        want = c.get("degrees", 90)
        tol = c.get("tol", 5)
        def diff(x, y):
            return abs((x - y + 180) % 360 - 180)
        ok = diff(ang, want) <= tol or (c.get("either_sign") and diff(ang, -want) <= tol)
        if off > tol:
            return f"off-axis {off:.1f}"
        return None if ok else f"turned {ang:.1f}"
    if k == "scaled":
        o = c["object"]
        f = after[o].get("scale", 1) / before[o].get("scale", 1)
        return None if abs(f - c["factor"]) <= c.get("tol", 0.02) * c["factor"] else f"factor {f:.3f}"
    if k == "on_top":
        o, s = after[c["object"]], after[c["support"]]
        (olo, ohi), (slo, shi) = aabb(o), aabb(s)
        cc = centre(o)
        if abs(olo[1] - shi[1]) > c.get("tol", 0.03):
            return "not at support top"
        if not (slo[0] <= cc[0] <= shi[0] and slo[2] <= cc[2] <= shi[2]):
            return "centre not over support"
        return None
    if k == "next_to":
        o, t = after[c["object"]], after[c["other"]]
        if overlap(o, t):
            return "inside other"
        (olo, ohi), (tlo, thi) = aabb(o), aabb(t)
        g = horiz_gap(olo, ohi, tlo, thi)
        if g > c.get("max_gap", 0.3):
            return f"gap {g:.3f}"
        if not (olo[1] < thi[1] and tlo[1] < ohi[1]):
            return "heights do not overlap"
        return None
    if k == "side":
        o, t = after[c["object"]], after[c["other"]]
        (olo, ohi), (tlo, thi) = aabb(o), aabb(t)
        co, ct = centre(o), centre(t)
        sd = c["side"]
        if sd in ("left", "right"):
            gap = tlo[0] - ohi[0] if sd == "left" else olo[0] - thi[0]
            j = 2
        else:
            gap = olo[2] - thi[2] if sd == "front" else tlo[2] - ohi[2]
            j = 0
        if not (-0.02 <= gap <= c.get("max_gap", 0.5)):
            return f"gap {gap:.3f}"
        # facing it across: (conservatively) one centre within the other's extent on the
        # perpendicular floor axis
        if not (tlo[j] <= co[j] <= thi[j] or olo[j] <= ct[j] <= ohi[j]):
            return "not facing across"
        return None
    if k == "above":
        o, t = after[c["object"]], after[c["other"]]
        return None if aabb(o)[0][1] >= aabb(t)[1][1] - c.get("tol", 0.03) else "not above"
    if k == "below":
        o, t = after[c["object"]], after[c["other"]]
        return None if aabb(o)[1][1] <= aabb(t)[0][1] + c.get("tol", 0.03) else "not below"
    if k == "between":
        o, a, b = centre(after[c["object"]]), centre(after[c["a"]]), centre(after[c["b"]])
        px, pz = o[0] - a[0], o[2] - a[2]
        sx, sz = b[0] - a[0], b[2] - a[2]
        L2 = sx * sx + sz * sz
        t = (px * sx + pz * sz) / L2
        if not (0 <= t <= 1):
            return f"projects outside segment (t={t:.2f})"
        dist = abs(px * sz - pz * sx) / math.sqrt(L2)
        return None if dist <= c.get("tol", 0.3) else f"off segment {dist:.3f}"
    if k == "aligned":
        i = AX[c["axis"][-1]]
        a, b = centre(after[c["object"]]), centre(after[c["other"]])
        return None if abs(a[i] - b[i]) <= c.get("tol", 0.05) else f"off {a[i]-b[i]:.3f}"
    if k == "at":
        a = bottom_centre(after[c["object"]])
        p = c["position"]
        e = math.sqrt(sum((a[i] - p[i]) ** 2 for i in range(3) if p[i] is not None))
        return None if e <= c.get("tol", 0.05) else f"at {a}"
    if k == "faces":
        o, t = after[c["object"]], after[c["target"]]
        f = qrot(o["rotation"], [0, 0, 1])
        co, ct = centre(o), centre(t)
        v = [ct[0] - co[0], ct[2] - co[2]]
        a1 = math.atan2(f[0], f[2])
        a2 = math.atan2(v[0], v[1])
        d = abs((math.degrees(a1 - a2) + 180) % 360 - 180)
        return None if d <= c.get("tol", 20) else f"off by {d:.1f} deg"
    if k == "distance":
        a, b = centre(after[c["object"]]), centre(after[c["other"]])
        d3 = math.dist(a, b)
        d2 = math.hypot(a[0] - b[0], a[2] - b[2])
        lo, hi = c.get("min", 0), c.get("max", math.inf)
        if not (lo <= d3 <= hi):
            return f"distance {d3:.3f}"
        if not (lo <= d2 <= hi):
            warnings.append(f"distance {c['object']}-{c['other']}: holds in 3-D but not on the floor plan")
        return None
    if k == "swapped":
        o, t = c["object"], c["other"]
        tol = c.get("tol", 0.05)
        if math.dist(bottom_centre(after[o]), bottom_centre(before[t])) > tol:
            return "object not where other was"
        if math.dist(bottom_centre(after[t]), bottom_centre(before[o])) > tol:
            return "other not where object was"
        return None
    if k in ("no_collision", "inside_bounds", "unchanged", "refused"):
        return None  # handled by the caller
    return f"unknown check {k}"


def same_pose(a, b):
    return (all(abs(a["position"][i] - b["position"][i]) < 1e-9 for i in range(3)) and
            all(abs(a["rotation"][i] - b["rotation"][i]) < 1e-9 for i in range(4)) and
            abs(a.get("scale", 1) - b.get("scale", 1)) < 1e-12)


def apply_answer(before, ans):
    after = {n: json.loads(json.dumps(o)) for n, o in before.items()}
    for n, a in ans.items():
        o = after[n]
        t = a.get("t", [0, 0, 0])
        o["position"] = [o["position"][i] + t[i] for i in range(3)]
        if a.get("yaw"):
            o["rotation"] = qmul(yawq(a["yaw"]), o["rotation"])
        if a.get("s"):
            o["scale"] = o.get("scale", 1) * a["s"]
    return after


def dependents(objs, roots):
    """Objects resting (transitively) on any of roots."""
    out = set()
    frontier = set(roots)
    while frontier:
        nxt = set()
        for n, o in objs.items():
            if n in out or n in roots:
                continue
            if any(roughly_on(o, objs[r]) for r in frontier):
                nxt.add(n)
        out |= nxt
        frontier = nxt
    return out


# ------------------------------------------------------------------ main
def main():
    suite = json.load(open(SUITE))
    answers = json.load(open(ANSWERS)) if os.path.exists(ANSWERS) else {}

    for k in suite:
        if k not in TOP_FIELDS:
            err(f"suite: unknown top-level field {k!r}")
    scenes = {}
    for p in suite["scenes"]:
        sc = json.load(open(os.path.join(HERE, p)))
        scenes[sc["name"]] = sc

    # ---- scenes
    for sname, sc in scenes.items():
        if set(sc) - {"name", "bounds", "objects"}:
            err(f"{sname}: unexpected scene fields {set(sc) - {'name', 'bounds', 'objects'}}")
        seen = set()
        objs = {}
        for o in sc["objects"]:
            n = o["name"]
            if n.lower() in seen:
                err(f"{sname}: duplicate name {n!r}")
            seen.add(n.lower())
            if set(o) - OBJ_FIELDS:
                err(f"{sname}: {n!r} has fields {set(o) - OBJ_FIELDS}")
            if any(v <= 0 for v in o["size"]):
                err(f"{sname}: {n!r} size not positive")
            q = o.get("rotation", [0, 0, 0, 1])
            if abs(q[0]) > 1e-9 or abs(q[2]) > 1e-9 or abs(math.hypot(q[1], q[3]) - 1) > 1e-6:
                err(f"{sname}: {n!r} rotation not a yaw-only unit quaternion")
            objs[n] = o
        for p in physical_problems(sc, objs):
            err(f"{sname}: {p}")

    # ---- queries
    queries = suite["queries"]
    ids, texts = set(), set()
    per_scene, per_cat, refusals = {}, {}, 0
    per_scene_cat = {}
    for q in queries:
        qid = q.get("id")
        where = f"query {qid}"
        for k in q:
            if k not in QUERY_FIELDS:
                err(f"{where}: unknown field {k!r}")
        if "pick" in q:
            err(f"{where}: has pick (no placeholders allowed)")
        if qid in ids:
            err(f"{where}: duplicate id")
        ids.add(qid)
        norm = " ".join(q["text"].lower().split())
        if norm in texts:
            err(f"{where}: duplicate text")
        texts.add(norm)
        if "{" in q["text"] or "}" in q["text"]:
            err(f"{where}: placeholder-like braces in text")
        if q["category"] not in CATEGORIES:
            err(f"{where}: bad category {q['category']!r}")
        if not isinstance(q.get("scenes"), list) or len(q["scenes"]) != 1 or q["scenes"][0] not in scenes:
            err(f"{where}: must list exactly one known scene")
            continue
        sname = q["scenes"][0]
        sc = scenes[sname]
        before = {o["name"]: o for o in sc["objects"]}
        per_scene[sname] = per_scene.get(sname, 0) + 1
        per_cat[q["category"]] = per_cat.get(q["category"], 0) + 1
        per_scene_cat.setdefault(sname, {}).setdefault(q["category"], 0)
        per_scene_cat[sname][q["category"]] += 1
        exp = q["expect"]
        for c in exp:
            k = c.get("check")
            if k not in CHECK_FIELDS:
                err(f"{where}: unknown check {k!r}")
                continue
            extra = set(c) - CHECK_FIELDS[k] - {"check"}
            if extra:
                err(f"{where}: check {k} has unknown fields {extra}")
            for f in NAME_FIELDS:
                if f in c and c[f] not in before:
                    err(f"{where}: {k}.{f} names unknown object {c[f]!r}")
            if k == "unchanged" and isinstance(c["objects"], list):
                for n in c["objects"]:
                    if n not in before:
                        err(f"{where}: unchanged names unknown object {n!r}")
            if k == "refused":
                for n in c.get("mentions", []):
                    if n not in before:
                        err(f"{where}: refused mentions unknown object {n!r}")
            if k == "moved" and not (0.02 <= c.get("tol", 0.05) <= 0.05):
                err(f"{where}: moved tol out of 0.02-0.05")
            if k == "rotated" and c.get("tol") != 3:
                err(f"{where}: rotated tol must be 3")
            if k == "direction" and c["axis"] not in {"+x", "-x", "+y", "-y", "+z", "-z"}:
                err(f"{where}: bad axis")
            if k == "aligned" and c["axis"] not in {"x", "y", "z"}:
                err(f"{where}: bad aligned axis")
        kinds = [c["check"] for c in exp]
        if "refused" in kinds:
            refusals += 1
            if kinds != ["refused"]:
                err(f"{where}: a refusal should only hold the refused check")
            if qid in answers:
                err(f"{where}: refusal has an answer")
            m = exp[0].get("mentions", [])
            if len(m) == 1:
                err(f"{where}: an ambiguity needs at least two candidates")
            continue
        if len(exp) < 3 or exp[-2] != {"check": "no_collision"} or exp[-1] != {"check": "unchanged", "objects": "others"}:
            err(f"{where}: must end with no_collision and unchanged others")
        if qid not in answers:
            err(f"{where}: no hand-worked answer")
            continue
        ans = answers[qid]
        for n in ans:
            if n not in before:
                err(f"{where}: answer moves unknown object {n!r}")
        if any(n not in before for n in ans):
            continue
        after = apply_answer(before, ans)
        # every check holds
        subjects = set()
        for c in exp:
            if "object" in c:
                subjects.add(c["object"])
            if c["check"] == "swapped":
                subjects.add(c["other"])
        for c in exp:
            r = run_check(c, before, after)
            if r:
                err(f"{where}: check {c['check']} on {c.get('object', '')!r} fails: {r}")
        # doing nothing must not pass the query
        if all(run_check(c, before, before) is None for c in exp):
            err(f"{where}: the unchanged scene already passes every check")
        # every non-trivial check must fail on the unchanged scene, unless it is a
        # relation that may legitimately already hold (on_top of the same support, above...)
        # unchanged others
        excluded = subjects | dependents(before, subjects)
        for c in exp:
            if c["check"] == "unchanged":
                lst = [n for n in before if n not in excluded] if c["objects"] == "others" else c["objects"]
                for n in lst:
                    if not same_pose(before[n], after[n]):
                        err(f"{where}: {n!r} should be unchanged but the answer moves it")
        # the objects other checks relate to must not move
        for c in exp:
            for f in ("other", "support", "a", "b", "target"):
                if f in c and c["check"] != "swapped" and c[f] not in subjects and not same_pose(before[c[f]], after[c[f]]):
                    err(f"{where}: {c[f]!r} ({c['check']}.{f}) moves")
        # every moved object is the subject of some check
        moved = [n for n in before if not same_pose(before[n], after[n])]
        for n in moved:
            if n not in subjects:
                err(f"{where}: answer moves {n!r} but no check is about it")
        # dependents of moved supports go with them (or are placed elsewhere by a check)
        for s in moved:
            ts = [after[s]["position"][i] - before[s]["position"][i] for i in range(3)]
            for d in dependents(before, {s}):
                if not any(roughly_on(before[d], before[s2]) for s2 in [s]):
                    continue
                placed = any(c["check"] in ("on_top", "next_to", "side", "between", "swapped", "at") and c.get("object") == d for c in exp)
                td = [after[d]["position"][i] - before[d]["position"][i] for i in range(3)]
                if d not in subjects:
                    err(f"{where}: {d!r} rests on moved {s!r} but is not checked")
                elif not placed and max(abs(td[i] - ts[i]) for i in range(3)) > 1e-6 and not ans.get(s, {}).get("yaw"):
                    err(f"{where}: {d!r} rests on {s!r} but does not move with it")
        # physical validity after the edit
        for p in physical_problems(sc, after, before):
            err(f"{where}: after the answer: {p}")
        # robustness for vague moves: a larger "a bit" (0.5 m) must still be collision-free
        dirs = [c for c in exp if c["check"] == "direction"]
        if dirs and all(c["check"] in ("direction", "no_collision", "unchanged", "on_top", "rotated", "scaled", "faces", "next_to", "aligned", "above", "distance") for c in exp):
            k2 = {}
            for c in dirs:
                o = c["object"]
                t = ans.get(o, {}).get("t", [0, 0, 0])
                along = abs(t[AX[c["axis"][1]]])
                if along > 0:
                    k2[o] = max(1.0, 0.45 / along)
            if k2:
                kk = min(k2.values())
                if kk > 1.0:
                    big = {}
                    for n, a in ans.items():
                        b = dict(a)
                        if n in k2:
                            b["t"] = [v * kk for v in a.get("t", [0, 0, 0])]
                        big[n] = b
                    aft2 = apply_answer(before, big)
                    probs = [p for p in physical_problems(sc, aft2, before) if "floats" not in p]
                    if probs:
                        warnings.append(f"{where}: a larger vague move (x{kk:.2f}) would give {probs[:2]}")

    # ---- totals
    n = len(queries)
    if n < 260:
        err(f"only {n} queries (need >= 260)")
    for s in scenes:
        if per_scene.get(s, 0) < 55:
            err(f"scene {s}: only {per_scene.get(s, 0)} queries (need >= 55)")
    share = refusals / n if n else 0
    if not (0.12 <= share <= 0.15):
        err(f"refusal share {share:.3f} outside 12-15 %")
    for c in CATEGORIES:
        if per_cat.get(c, 0) == 0:
            err(f"no queries in category {c}")
    extra_ans = set(answers) - ids
    if extra_ans:
        err(f"answers for unknown queries: {sorted(extra_ans)[:5]}")

    print(f"queries: {n}; refusals: {refusals} ({share:.1%})")
    print("per scene:", json.dumps(per_scene))
    print("per category:", json.dumps(per_cat))
    for s, d in per_scene_cat.items():
        print(f"  {s}: {json.dumps(d)}")
    for w in warnings:
        print("WARNING", w)
    for e in errors:
        print("ERROR", e)
    print("OK" if not errors else f"{len(errors)} error(s)")
    return 0 if not errors else 1


if __name__ == "__main__":
    sys.exit(main())
