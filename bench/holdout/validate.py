#!/usr/bin/env python3
"""Check the held-out suite against its scenes (standard library only).

    python3 bench/holdout/validate.py [SUITE]

Checks:
  * the suite's shape: variations 1, unique ids with a family prefix, known categories and
    checks, every query's `scenes` naming a scene of the suite by its file stem;
  * every object a check names exists in the query's scene(s);
  * each scene: unique names, sizes > 0, everything inside the bounds, no two boxes
    overlapping, and every object off the floor either resting exactly on one support (its
    bottom at the support's top, its footprint inside the support's) or hanging on a wall;
  * carrying: when a check moves or turns an object, everything resting on it (transitively)
    is named by some check of that query (so what rides along is asserted, or held);
  * feasibility: for queries whose moves are all given exactly, applying them (with what
    they carry) creates no overlap and leaves everything inside the room; an `on_top`
    object's footprint fits on its support.
Prints `ok` and a per-family count when everything holds; otherwise the problems, exit 1.
"""
import json
import math
import os
import sys

EPS = 1e-6
FAMILIES = ("names", "chat", "toward", "keep", "vague", "verb", "where", "rot", "spell",
            "place", "refuse")
CATEGORIES = {"simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"}
CHECKS = {"moved", "direction", "rotated", "scaled", "on_top", "next_to", "side", "above",
          "below", "between", "aligned", "at", "faces", "distance", "unchanged",
          "no_collision", "inside_bounds", "swapped", "refused"}
NAME_FIELDS = ("object", "other", "support", "target", "a", "b")

problems = []


def bad(msg):
    problems.append(msg)


def qrot(q, v):
    x, y, z, w = q
    vx, vy, vz = v
    # v' = q v q*
    tx = 2 * (y * vz - z * vy)
    ty = 2 * (z * vx - x * vz)
    tz = 2 * (x * vy - y * vx)
    return (vx + w * tx + (y * tz - z * ty),
            vy + w * ty + (z * tx - x * tz),
            vz + w * tz + (x * ty - y * tx))


def aabb(obj, offset=(0.0, 0.0, 0.0)):
    w, h, d = obj["size"]
    s = obj.get("scale", 1.0)
    q = obj.get("rotation", [0, 0, 0, 1])
    n = math.sqrt(sum(c * c for c in q)) or 1.0
    q = [c / n for c in q]
    p = [obj["position"][i] + offset[i] for i in range(3)]
    pts = []
    for cx in (-w / 2, w / 2):
        for cy in (0.0, h):
            for cz in (-d / 2, d / 2):
                r = qrot(q, (cx * s, cy * s, cz * s))
                pts.append([p[i] + r[i] for i in range(3)])
    lo = [min(pt[i] for pt in pts) for i in range(3)]
    hi = [max(pt[i] for pt in pts) for i in range(3)]
    return lo, hi


def overlap(a, b):
    return all(min(a[1][i], b[1][i]) - max(a[0][i], b[0][i]) > EPS for i in range(3))


def footprint_inside(inner, outer):
    return all(inner[0][i] >= outer[0][i] - EPS and inner[1][i] <= outer[1][i] + EPS
               for i in (0, 2))


class Scene:
    def __init__(self, path):
        with open(path) as f:
            self.data = json.load(f)
        self.path = path
        self.objs = {o["name"]: o for o in self.data["objects"]}
        self.lower = {o["name"].lower(): o["name"] for o in self.data["objects"]}
        b = self.data.get("bounds")
        self.bounds = (b["min"], b["max"]) if b else None
        self.box = {n: aabb(o) for n, o in self.objs.items()}
        self.support = {}          # object -> the object it rests on

    def name(self, n):
        return self.lower.get(n.lower())

    def check(self):
        tag = os.path.basename(self.path)
        if len(self.lower) != len(self.data["objects"]):
            bad(f"{tag}: names are not unique (case-insensitively)")
        for n, o in self.objs.items():
            if any(v <= 0 for v in o["size"]):
                bad(f"{tag}: {n}: a size is not > 0")
        names = list(self.objs)
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                if overlap(self.box[a], self.box[b]):
                    bad(f"{tag}: '{a}' and '{b}' overlap")
        for n in names:
            lo, hi = self.box[n]
            if self.bounds:
                bmin, bmax = self.bounds
                if any(lo[i] < bmin[i] - EPS or hi[i] > bmax[i] + EPS for i in range(3)):
                    bad(f"{tag}: '{n}' sticks out of the bounds")
            if abs(lo[1]) <= EPS:
                continue
            sups = [m for m in names if m != n and abs(self.box[m][1][1] - lo[1]) <= EPS
                    and footprint_inside(self.box[n], self.box[m])]
            if len(sups) == 1:
                self.support[n] = sups[0]
                continue
            if len(sups) > 1:
                bad(f"{tag}: '{n}' rests on several objects: {sups}")
                continue
            # hanging: its box touches a wall
            if self.bounds and any(abs(lo[i] - self.bounds[0][i]) <= EPS
                                   or abs(hi[i] - self.bounds[1][i]) <= EPS for i in (0, 2)):
                continue
            # near-misses are the usual mistake: say so
            near = [m for m in names if m != n and abs(self.box[m][1][1] - lo[1]) <= 0.05]
            bad(f"{tag}: '{n}' is off the floor (y={lo[1]:.3f}) with no support and no wall"
                + (f"; near {near}" if near else ""))

    def riders(self, n):
        """Everything resting on n, transitively."""
        out, todo = [], [n]
        while todo:
            cur = todo.pop()
            for k, v in self.support.items():
                if v == cur and k not in out:
                    out.append(k)
                    todo.append(k)
        return out


def gap1(a, b, i):
    """Separation of two boxes along axis i (negative when they overlap)."""
    return max(a[0][i] - b[1][i], b[0][i] - a[1][i])


def satisfied(scene, box, c):
    other = scene.box[scene.name(c.get("other") or c.get("support") or c.get("a"))]
    cx, cz = (box[0][0] + box[1][0]) / 2, (box[0][2] + box[1][2]) / 2
    if c["check"] == "on_top":
        # stricter than the check (centre over the top): the whole footprint on it
        return abs(box[0][1] - other[1][1]) <= 0.03 and footprint_inside(box, other)
    if c["check"] == "next_to":
        gx, gz = max(gap1(box, other, 0), 0), max(gap1(box, other, 2), 0)
        inside = gap1(box, other, 0) < 0 and gap1(box, other, 2) < 0
        heights = min(box[1][1], other[1][1]) > max(box[0][1], other[0][1])
        return not inside and math.hypot(gx, gz) <= c.get("max_gap", 0.3) and heights
    if c["check"] == "side":
        mg = c.get("max_gap", 0.5)
        if c["side"] in ("left", "right"):
            g = other[0][0] - box[1][0] if c["side"] == "left" else box[0][0] - other[1][0]
            return -0.02 <= g <= mg and other[0][2] <= cz <= other[1][2]
        g = box[0][2] - other[1][2] if c["side"] == "front" else other[0][2] - box[1][2]
        return -0.02 <= g <= mg and other[0][0] <= cx <= other[1][0]
    if c["check"] == "between":
        a, b = scene.box[scene.name(c["a"])], scene.box[scene.name(c["b"])]
        ax, az = (a[0][0] + a[1][0]) / 2, (a[0][2] + a[1][2]) / 2
        bx, bz = (b[0][0] + b[1][0]) / 2, (b[0][2] + b[1][2]) / 2
        dx, dz = bx - ax, bz - az
        t = ((cx - ax) * dx + (cz - az) * dz) / (dx * dx + dz * dz)
        if not 0 <= t <= 1:
            return False
        return math.hypot(ax + t * dx - cx, az + t * dz - cz) <= c.get("tol", 0.3)
    return True


def find_spot(scene, name, checks, step=0.025):
    """Search the room (2.5 cm grid, both quarter-turns) for a pose of `name` that
    satisfies the placement checks, overlaps nothing and stays inside the room."""
    o = scene.objs[name]
    w, h, d = o["size"]
    others = [scene.box[n] for n in scene.objs if n != name and n not in scene.riders(name)]
    sup = [c for c in checks if c["check"] == "on_top"]
    y = scene.box[scene.name(sup[0]["support"])][1][1] if sup else 0.0
    bmin, bmax = scene.bounds
    # the grid passes through the centre of the first object the checks name
    ref = scene.box[scene.name(checks[0].get("support") or checks[0].get("other")
                               or checks[0].get("a"))]
    ox, oz = (ref[0][0] + ref[1][0]) / 2, (ref[0][2] + ref[1][2]) / 2
    for (sx, sz) in ((w, d), (d, w)):
        x = ox - step * math.floor((ox - bmin[0] - sx / 2) / step + EPS)
        while x <= bmax[0] - sx / 2 + EPS:
            z = oz - step * math.floor((oz - bmin[2] - sz / 2) / step + EPS)
            while z <= bmax[2] - sz / 2 + EPS:
                box = ([x - sx / 2, y, z - sz / 2], [x + sx / 2, y + h, z + sz / 2])
                if box[1][1] <= bmax[1] + EPS and all(satisfied(scene, box, c) for c in checks) \
                        and not any(overlap(box, b) for b in others):
                    return box
                z += step
            x += step
    return None


def names_in(chk):
    out = []
    for f in NAME_FIELDS:
        if isinstance(chk.get(f), str):
            out.append(chk[f])
    if isinstance(chk.get("objects"), list):
        out += chk["objects"]
    if isinstance(chk.get("mentions"), list):
        out += chk["mentions"]
    return out


def check_query(q, scene):
    qid = q["id"]
    tag = f"{qid} [{scene.data['name']}]"
    expect = q["expect"]
    mentioned = set()
    for chk in expect:
        for n in names_in(chk):
            real = scene.name(n)
            if real is None:
                bad(f"{tag}: check {chk['check']} names '{n}', not in the scene")
            else:
                mentioned.add(real)
    if any(scene.name(n) is None for c in expect for n in names_in(c)):
        return
    refused = any(c["check"] == "refused" for c in expect)
    if refused:
        others = [c["check"] for c in expect if c["check"] != "refused"]
        if others:
            bad(f"{tag}: a refused query should carry only the refusal (has {others})")
        return
    # carrying
    movers = [scene.name(c["object"]) for c in expect
              if c["check"] in ("moved", "direction", "rotated", "scaled", "swapped")
              and scene.name(c.get("object", "")) is not None]
    for m in movers:
        for r in scene.riders(m):
            if r not in mentioned:
                bad(f"{tag}: '{r}' rests on '{m}', which the query moves, but no check names it")
    held = set()
    for c in expect:
        if c["check"] == "unchanged" and isinstance(c.get("objects"), list):
            held |= {scene.name(n) for n in c["objects"]}
    for m in movers:
        if m in held:
            bad(f"{tag}: '{m}' is both moved and unchanged")
    if not any(c["check"] == "unchanged" and c.get("objects") == "others" for c in expect):
        bad(f"{tag}: no unchanged-others check")
    # on_top fits
    for c in expect:
        if c["check"] == "on_top":
            o, s = scene.objs[scene.name(c["object"])], scene.objs[scene.name(c["support"])]
            ow, od = sorted((o["size"][0], o["size"][2]))
            sw, sd = sorted((s["size"][0], s["size"][2]))
            if ow > sw + EPS or od > sd + EPS:
                bad(f"{tag}: '{o['name']}' cannot fit on '{s['name']}'")
    # placements: is there a free spot that satisfies them?
    place = [c for c in expect if c["check"] in ("on_top", "next_to", "side", "between")
             and not (c["check"] == "on_top"
                      and scene.support.get(scene.name(c["object"])) == scene.name(c["support"]))]
    if place:
        movers = {scene.name(c["object"]) for c in place}
        if len(movers) != 1:
            bad(f"{tag}: placements of several objects are not searched")
        elif not find_spot(scene, movers.pop(), place):
            bad(f"{tag}: no free spot satisfies {[c['check'] for c in place]}")
        return
    # exact moves and turns: apply them (with what they carry) and look for new overlaps
    moves, turns = {}, {}          # object -> delta; object -> list of candidate angles
    for c in expect:
        n = scene.name(c.get("object", ""))
        if c["check"] == "moved":
            d = c.get("delta")
            if d is None or any(v is None for v in d):
                return
            moves[n] = d
        elif c["check"] == "rotated":
            if c.get("axis", "y") != "y":
                return
            deg = c.get("degrees", 90)
            turns[n] = [deg, -deg] if c.get("either_sign") else [deg]
        elif c["check"] == "faces":
            lo, hi = scene.box[n]
            tlo, thi = scene.box[scene.name(c["target"])]
            dx = (tlo[0] + thi[0] - lo[0] - hi[0]) / 2
            dz = (tlo[2] + thi[2] - lo[2] - hi[2]) / 2
            turns[n] = [math.degrees(math.atan2(dx, dz))]
        elif c["check"] in ("direction", "scaled", "on_top", "next_to", "side", "between",
                            "at", "swapped", "aligned", "above", "below"):
            if c["check"] == "on_top" and scene.support.get(n) == scene.name(c["support"]):
                continue          # already there: a statement that it stays on
            return                # not an exact move: nothing to simulate
    if not moves and not turns:
        return
    for m, d in moves.items():
        for r in scene.riders(m):
            if r not in moves and r not in held and m not in turns:
                bad(f"{tag}: '{r}' rides on '{m}' but has no moved check")
    # every combination of the candidate signs must work
    combos = [{}]
    for n, angles in turns.items():
        combos = [dict(cb, **{n: a}) for cb in combos for a in angles]
    for combo in combos:
        simulate(scene, tag, moves, combo, held)


def turned_box(scene, n, deg, pivot, delta):
    """World box of n turned by deg about +y through pivot, then moved by delta."""
    lo, hi = scene.box[n]
    t = math.radians(deg)
    ct, st = math.cos(t), math.sin(t)
    xs, zs = [], []
    for x in (lo[0], hi[0]):
        for z in (lo[2], hi[2]):
            rx, rz = x - pivot[0], z - pivot[2]
            xs.append(pivot[0] + rx * ct + rz * st + delta[0])
            zs.append(pivot[2] - rx * st + rz * ct + delta[2])
    return ([min(xs), lo[1] + delta[1], min(zs)], [max(xs), hi[1] + delta[1], max(zs)])


def simulate(scene, tag, moves, turns, held):
    after, changed = {}, set()
    for n in scene.objs:
        after[n] = scene.box[n]
    # turns first (about the object's pivot, taking its riders along), then the moves
    carried = {r for n in turns for r in scene.riders(n)}
    for n, deg in turns.items():
        if n in carried:
            continue          # its carrier turns it (its own check states the result)
        piv = scene.objs[n]["position"]
        d = moves.get(n, (0, 0, 0))
        after[n] = turned_box(scene, n, deg, piv, d)
        changed.add(n)
        for r in scene.riders(n):
            if r in held:
                continue
            after[r] = turned_box(scene, r, deg, piv, d)
            changed.add(r)
    for n, d in moves.items():
        if n not in turns and n not in changed:
            after[n] = aabb(scene.objs[n], d)
            changed.add(n)
    names = list(after)
    what = "move" + (f" (turns {turns})" if turns else "")
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if (a in changed or b in changed) and overlap(after[a], after[b]) \
                    and not overlap(scene.box[a], scene.box[b]):
                bad(f"{tag}: after the {what} '{a}' and '{b}' overlap")
    if scene.bounds:
        bmin, bmax = scene.bounds
        for n in changed:
            lo, hi = after[n]
            if any(lo[i] < bmin[i] - EPS or hi[i] > bmax[i] + EPS for i in range(3)):
                bad(f"{tag}: after the {what} '{n}' sticks out of the room")
    for n in held:
        sup = scene.support.get(n)
        if sup and sup in changed:
            lo, hi = after[n]
            slo, shi = after[sup]
            cx, cz = (lo[0] + hi[0]) / 2, (lo[2] + hi[2]) / 2
            if not (slo[0] <= cx <= shi[0] and slo[2] <= cz <= shi[2]):
                bad(f"{tag}: held '{n}' is left without its support '{sup}'")
    # what rides on a moved object must still rest inside its footprint
    for n in changed:
        sup = scene.support.get(n)
        if sup and not footprint_inside(after[n], after[sup]):
            bad(f"{tag}: after the {what} '{n}' hangs over the edge of '{sup}'")


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "holdout.suite.json")
    with open(path) as f:
        suite = json.load(f)
    base = os.path.dirname(os.path.abspath(path))
    if suite.get("variations") != 1:
        bad("variations must be 1")
    scenes = {}
    for rel in suite["scenes"]:
        s = Scene(os.path.join(base, rel))
        s.check()
        scenes[os.path.splitext(os.path.basename(rel))[0]] = s
    ids = set()
    counts = {f: 0 for f in FAMILIES}
    refusals = 0
    for q in suite["queries"]:
        qid = q.get("id", "?")
        if qid in ids:
            bad(f"{qid}: duplicate id")
        ids.add(qid)
        fam = qid.split("-")[0]
        if fam not in counts:
            bad(f"{qid}: id does not start with a family word")
        else:
            counts[fam] += 1
        if q.get("category") not in CATEGORIES:
            bad(f"{qid}: category {q.get('category')!r}")
        if not isinstance(q.get("text"), str) or not q["text"].strip():
            bad(f"{qid}: no text")
        if "{" in q.get("text", ""):
            bad(f"{qid}: text has a placeholder")
        if not q.get("scenes"):
            bad(f"{qid}: no scenes list")
        for c in q.get("expect", []):
            if c.get("check") not in CHECKS:
                bad(f"{qid}: unknown check {c.get('check')!r}")
        if not q.get("expect"):
            bad(f"{qid}: no checks")
        if any(c.get("check") == "refused" for c in q.get("expect", [])):
            refusals += 1
        for sn in q.get("scenes", []):
            if sn not in scenes:
                bad(f"{qid}: unknown scene {sn!r}")
                continue
            check_query(q, scenes[sn])
    if problems:
        for p in problems:
            print(p)
        print(f"{len(problems)} problem(s)")
        sys.exit(1)
    n = len(suite["queries"])
    print("ok: %d queries, %d refusals (%.1f %%)" % (n, refusals, 100.0 * refusals / n))
    print("  " + ", ".join(f"{k} {v}" for k, v in counts.items()))


if __name__ == "__main__":
    main()
