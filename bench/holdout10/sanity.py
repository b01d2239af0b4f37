#!/usr/bin/env python3
"""Static sanity checks for the holdout10 benchmark suite and its scenes.

Standard library only. Run from the repository root:
    python3 bench/holdout10/sanity.py
Exits 0 when everything passes, 1 otherwise (each problem is printed).
"""
import json
import os
import re
import sys
from collections import Counter

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "holdout10.suite.json")
if len(sys.argv) > 1:  # another suite file (used to test this script)
    SUITE = os.path.abspath(sys.argv[1])
    HERE = os.path.dirname(SUITE)
TOL = 0.001  # 1 mm

CATEGORIES = {"simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"}
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
AXES = {"x", "y", "z", "+x", "-x", "+y", "-y", "+z", "-z"}
QUERY_FIELDS = {"id", "category", "text", "pick", "expect", "scenes"}

problems = []


def problem(msg):
    problems.append(msg)


def load_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        problem(f"{path}: not valid JSON ({e})")
        return None


def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def rotate(qt, v):
    x, y, z, w = qt
    n = (x * x + y * y + z * z + w * w) ** 0.5
    x, y, z, w = x / n, y / n, z / n, w / n
    p = qmul(qmul([x, y, z, w], [v[0], v[1], v[2], 0.0]), [-x, -y, -z, w])
    return p[:3]


def aabb(o):
    w, h, d = o["size"]
    s = o.get("scale", 1.0)
    r = o.get("rotation", [0, 0, 0, 1])
    px, py, pz = o["position"]
    lo = [float("inf")] * 3
    hi = [float("-inf")] * 3
    for cx in (-w / 2, w / 2):
        for cy in (0.0, h):
            for cz in (-d / 2, d / 2):
                p = rotate(r, [cx * s, cy * s, cz * s])
                p = [p[0] + px, p[1] + py, p[2] + pz]
                for i in range(3):
                    lo[i] = min(lo[i], p[i])
                    hi[i] = max(hi[i], p[i])
    return lo, hi


def overlap(a, b):
    return all(min(a[1][i], b[1][i]) - max(a[0][i], b[0][i]) > TOL for i in range(3))


def check_scene(path):
    sc = load_json(path)
    if sc is None:
        return None
    label = os.path.basename(path)
    if not isinstance(sc.get("name"), str):
        problem(f"{label}: scene has no name")
    objs = sc.get("objects")
    if not isinstance(objs, list) or not objs:
        problem(f"{label}: no objects")
        return None
    if not 20 <= len(objs) <= 40:
        problem(f"{label}: {len(objs)} objects, expected 20-40")
    names = Counter()
    for o in objs:
        if not isinstance(o.get("name"), str) or not o["name"]:
            problem(f"{label}: object without a name: {o}")
            continue
        names[o["name"].lower()] += 1
        sz = o.get("size")
        if not (isinstance(sz, list) and len(sz) == 3 and all(isinstance(v, (int, float)) and v > 0 for v in sz)):
            problem(f"{label}: {o['name']}: size must be three positive numbers")
        pos = o.get("position")
        if not (isinstance(pos, list) and len(pos) == 3 and all(isinstance(v, (int, float)) for v in pos)):
            problem(f"{label}: {o['name']}: bad position")
        rot = o.get("rotation", [0, 0, 0, 1])
        if not (isinstance(rot, list) and len(rot) == 4 and abs(sum(v * v for v in rot) - 1) < 1e-4):
            problem(f"{label}: {o['name']}: rotation must be a unit quaternion [x, y, z, w]")
        if "front" in o:
            f = o["front"]
            if not (isinstance(f, list) and len(f) == 3 and abs(sum(v * v for v in f) - 1) < 1e-4):
                problem(f"{label}: {o['name']}: front must be a unit vector")
        if not isinstance(o.get("scale", 1.0), (int, float)) or o.get("scale", 1.0) <= 0:
            problem(f"{label}: {o['name']}: scale must be a positive number")
    for n, c in names.items():
        if c > 1:
            problem(f"{label}: name '{n}' used {c} times (names are case-insensitive)")
    if problems:
        return None
    boxes = {o["name"]: aabb(o) for o in objs}
    bounds = sc.get("bounds")
    if bounds:
        bmin, bmax = bounds["min"], bounds["max"]
        for n, (lo, hi) in boxes.items():
            if any(lo[i] < bmin[i] - TOL or hi[i] > bmax[i] + TOL for i in range(3)):
                problem(f"{label}: {n} sticks out of the room")
    items = list(boxes.items())
    for i in range(len(items)):
        for j in range(i + 1, len(items)):
            if overlap(items[i][1], items[j][1]):
                problem(f"{label}: {items[i][0]} overlaps {items[j][0]}")
    floor = bounds["min"][1] if bounds else 0.0
    by_name = {o["name"]: o for o in objs}
    for n, (lo, hi) in boxes.items():
        if abs(lo[1] - floor) <= TOL:
            continue
        cx, cz = (lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2
        supports = [m for m, (l2, h2) in boxes.items() if m != n and abs(h2[1] - lo[1]) <= TOL
                    and l2[0] - TOL <= cx <= h2[0] + TOL and l2[2] - TOL <= cz <= h2[2] + TOL]
        if supports:
            continue
        o = by_name[n]
        on_wall = bounds and o.get("mount") == "wall" and any(
            abs(lo[i] - bounds["min"][i]) <= TOL or abs(hi[i] - bounds["max"][i]) <= TOL for i in (0, 2))
        if not on_wall:
            problem(f"{label}: {n} floats at y={lo[1]:.3f} with no support under it")
    return sc


def placeholders(text):
    return set(re.findall(r"\{([A-Za-z][A-Za-z0-9_]*)\}", text))


def main():
    suite = load_json(SUITE)
    if suite is None:
        return report()
    for k in ("name", "scenes", "queries"):
        if k not in suite:
            problem(f"suite: missing '{k}'")
    scenes, canonical = {}, {}
    for rel in suite.get("scenes", []):
        path = os.path.normpath(os.path.join(HERE, rel))
        sc = check_scene(path)
        if sc is not None:
            names = {o["name"].lower() for o in sc["objects"]}
            for key in (sc["name"].lower(), os.path.basename(rel).lower()):
                scenes[key] = names
                canonical[key] = sc["name"]
    if problems:
        return report()
    ids = Counter()
    per_cat, per_scene, refusals = Counter(), Counter(), 0
    for q in suite.get("queries", []):
        qid = q.get("id")
        ids[qid] += 1
        for k in q:
            if k not in QUERY_FIELDS:
                problem(f"{qid}: unknown field '{k}'")
        if q.get("category") not in CATEGORIES:
            problem(f"{qid}: category '{q.get('category')}' is not one of {sorted(CATEGORIES)}")
        text = q.get("text")
        if not isinstance(text, str) or not text.strip():
            problem(f"{qid}: no text")
            text = ""
        expect = q.get("expect")
        if not isinstance(expect, list) or not expect:
            problem(f"{qid}: no checks")
            expect = []
        ph = placeholders(text)
        for p in q.get("pick", {}) or {}:
            if p not in ph:
                problem(f"{qid}: pick constrains '{p}', absent from the text")
        qscenes = q.get("scenes")
        if qscenes is None:
            targets = sorted({canonical[k].lower() for k in scenes})
        else:
            targets = []
            for s in qscenes:
                if s.lower() not in scenes:
                    problem(f"{qid}: scene '{s}' is not in the suite")
                else:
                    targets.append(s.lower())
        for t in targets:
            per_scene[canonical[t]] += 1
        per_cat[q.get("category")] += 1
        for c in expect:
            kind = c.get("check")
            if kind not in CHECKS:
                problem(f"{qid}: unknown check '{kind}'")
                continue
            req, opt = CHECKS[kind]
            for f in req:
                if f not in c:
                    problem(f"{qid}: check '{kind}' lacks '{f}'")
            for f in c:
                if f != "check" and f not in req and f not in opt:
                    problem(f"{qid}: check '{kind}' has unknown field '{f}'")
            for f in ("axis",):
                if f in c and c[f] not in AXES:
                    problem(f"{qid}: bad axis '{c[f]}'")
            if kind == "side" and c.get("side") not in ("left", "right", "front", "behind"):
                problem(f"{qid}: bad side '{c.get('side')}'")
            mentioned = [c[f] for f in NAME_FIELDS if f in c]
            if kind == "unchanged" and isinstance(c.get("objects"), list):
                mentioned += c["objects"]
            elif kind == "unchanged" and c.get("objects", "others") != "others":
                problem(f"{qid}: unchanged.objects must be a list or \"others\"")
            if kind == "refused":
                mentioned += c.get("mentions", [])
                refusals += 1
            for n in mentioned:
                if not isinstance(n, str):
                    problem(f"{qid}: object reference {n!r} is not a string")
                    continue
                if n in ph:
                    continue
                for t in targets:
                    if n.lower() not in scenes[t]:
                        problem(f"{qid}: '{n}' is not an object of scene '{t}'")
    for qid, c in ids.items():
        if qid is None:
            problem("a query has no id")
        elif c > 1:
            problem(f"id '{qid}' used {c} times")
    n = sum(ids.values())
    print(f"{n} queries, {refusals} refusals ({100.0 * refusals / max(n, 1):.1f} %)")
    print("per category:", dict(sorted(per_cat.items())))
    print("per scene:   ", dict(sorted(per_scene.items())))
    return report()


def report():
    if problems:
        for p in problems:
            print("PROBLEM:", p)
        print(f"FAILED: {len(problems)} problem(s)")
        return 1
    print("OK: all sanity checks pass")
    return 0


if __name__ == "__main__":
    sys.exit(main())
