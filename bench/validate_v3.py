#!/usr/bin/env python3
"""Validates bench/natural-v3.suite.json and its scenes (stdlib only).

    python3 bench/validate_v3.py [SUITE]

The suite's scenes (bench/scenes/blender_living.json, kitchen_chairs.json, office_v3.json)
are checked first:
- SPEC section 2 fields: unique names (case-insensitively), positive sizes, unit
  quaternions, positive scale, `bounds`; no `category` or `aliases` (the names are all a
  reader has, as in an export);
- every object lies inside the room; no two objects overlap (more than 0.1 mm on all three
  axes, as docs/collisions.md counts a collision);
- an object off the floor either rests exactly on a support (its bottom at the support's
  top, its footprint inside the support's) or hangs on a wall (its box touches one).

Then every query:
- fields id, category, text, scenes, expect (and an optional pick); a unique id that starts
  with a known family (names, chat, toward, keep, vague, verb, where, rot, spell, place,
  refuse); a SPEC section 6 category; a text with no {placeholder} and no quoted name;
- `scenes` names scenes of the suite; every check is known, with known and required fields,
  and every object it names exists, spelled exactly, in each of those scenes;
- a refusal is the only check of its query and its id starts with refuse-; any other query
  asserts an outcome and says what must not move (`unchanged` "others");
- outcomes are reachable: each `moved` delta, `direction` minimum and `at` position keeps
  the object (and what rests on it) inside the room;
- carrying is accounted for: whatever rests (directly or not) on an object a `moved` check
  moves is itself checked (moved, held by an `unchanged` list, or placed by another check);
  a held object left on a moved support must still stand over it;
- the expected end state is legal: applying the `moved`, `at`, `rotated` and `swapped`
  checks (and carrying) to the scene creates no overlap that was not there before and
  leaves everything inside the room.

Prints the counts per family, category and scene; exits non-zero when anything is wrong.
"""

import collections
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from suite_schema import CATEGORIES, CHECKS, EFFECTS, AXES, SIDES, QUOTED, Report  # noqa: E402

ROOT = os.path.dirname(HERE)
DEFAULT_SUITE = os.path.join(HERE, "natural-v3.suite.json")
FAMILIES = ["names", "chat", "toward", "keep", "vague", "verb", "where", "rot", "spell",
            "place", "refuse"]
EPS = 1e-6          # exact resting / containment
COLLIDE = 1e-4      # docs/collisions.md: overlap of more than 0.1 mm on all three axes
WALL_TOUCH = 0.03   # a hanging object's box is this close to a wall plane


# ---------------------------------------------------------------- geometry

def qmul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def qrot(q, v):
    x, y, z, w = q
    p = qmul(qmul(q, [v[0], v[1], v[2], 0.0]), [-x, -y, -z, w])
    return p[:3]


def yaw(degrees):
    h = math.radians(degrees) / 2
    return [0.0, math.sin(h), 0.0, math.cos(h)]


class Box:
    """A world AABB: lo, hi (3 lists)."""

    def __init__(self, lo, hi):
        self.lo = list(lo)
        self.hi = list(hi)

    def moved(self, d):
        return Box([a + b for a, b in zip(self.lo, d)], [a + b for a, b in zip(self.hi, d)])

    @property
    def centre(self):
        return [(a + b) / 2 for a, b in zip(self.lo, self.hi)]

    @property
    def bottom_centre(self):
        c = self.centre
        return [c[0], self.lo[1], c[2]]

    def overlaps(self, other, slack=COLLIDE):
        return all(min(self.hi[i], other.hi[i]) - max(self.lo[i], other.lo[i]) > slack
                   for i in range(3))

    def inside(self, bounds, slack=EPS):
        return all(self.lo[i] >= bounds.lo[i] - slack and self.hi[i] <= bounds.hi[i] + slack
                   for i in range(3))

    def footprint_inside(self, other, slack=EPS):
        return all(self.lo[i] >= other.lo[i] - slack and self.hi[i] <= other.hi[i] + slack
                   for i in (0, 2))

    def centre_over(self, other, slack=EPS):
        c = self.centre
        return all(other.lo[i] - slack <= c[i] <= other.hi[i] + slack for i in (0, 2))


def pose(obj):
    return (list(obj["position"]), list(obj.get("rotation", [0, 0, 0, 1])),
            float(obj.get("scale", 1.0)))


def box_of(size, position, rotation, scale):
    w, h, d = size
    corners = [qrot(rotation, [sx * w / 2 * scale, sy * h * scale, sz * d / 2 * scale])
               for sx in (-1, 1) for sy in (0, 1) for sz in (-1, 1)]
    lo = [min(c[i] for c in corners) + position[i] for i in range(3)]
    hi = [max(c[i] for c in corners) + position[i] for i in range(3)]
    return Box(lo, hi)


def aabb(obj):
    p, r, s = pose(obj)
    return box_of(obj["size"], p, r, s)


class Scene:
    def __init__(self, data, path):
        self.data = data
        self.path = path
        self.name = data.get("name")
        self.objects = {o["name"]: o for o in data.get("objects", []) if isinstance(o, dict) and "name" in o}
        b = data.get("bounds")
        self.bounds = Box(b["min"], b["max"]) if b else None
        self.boxes = {n: aabb(o) for n, o in self.objects.items()}
        self.support = {}      # name -> the object it rests on
        self.hanging = set()
        floor = self.bounds.lo[1] if self.bounds else 0.0
        for n, bx in self.boxes.items():
            if bx.lo[1] <= floor + EPS:
                continue
            for m, under in self.boxes.items():
                if m != n and abs(under.hi[1] - bx.lo[1]) <= EPS and bx.footprint_inside(under):
                    self.support[n] = m
                    break
            else:
                if self.bounds and self.touches_wall(bx):
                    self.hanging.add(n)

    def touches_wall(self, bx):
        b = self.bounds
        return (bx.lo[0] - b.lo[0] <= WALL_TOUCH or b.hi[0] - bx.hi[0] <= WALL_TOUCH or
                bx.lo[2] - b.lo[2] <= WALL_TOUCH or b.hi[2] - bx.hi[2] <= WALL_TOUCH)

    def resting_on(self, name):
        """Everything resting on name, directly or not (what moving it carries)."""
        out = []
        todo = [name]
        while todo:
            top = todo.pop()
            for child, sup in self.support.items():
                if sup == top and child not in out:
                    out.append(child)
                    todo.append(child)
        return out


# ---------------------------------------------------------------- scenes

def check_scene(scene, report, where):
    data = scene.data
    if not isinstance(scene.name, str):
        report.error(where, "scene has no name")
    if scene.bounds is None:
        report.error(where, "scene has no bounds")
        return
    objs = data.get("objects", [])
    if not 25 <= len(objs) <= 35:
        report.error(where, f"{len(objs)} objects; the brief asks for 25 to 35")
    lowered = collections.Counter(str(o.get("name", "")).lower() for o in objs)
    for n, k in lowered.items():
        if k > 1:
            report.error(where, f"name {n!r} used {k} times (names are compared case-insensitively)")
    for o in objs:
        at = f"{where} object {o.get('name')!r}"
        if not isinstance(o.get("name"), str) or not o["name"].strip():
            report.error(at, "no name")
            continue
        for key in ("category", "aliases"):
            if key in o:
                report.error(at, f"has {key!r}: the names must speak for themselves")
        size = o.get("size")
        if not (isinstance(size, list) and len(size) == 3 and all(isinstance(v, (int, float)) and v > 0 for v in size)):
            report.error(at, "size must be three positive numbers")
        pos = o.get("position")
        if not (isinstance(pos, list) and len(pos) == 3 and all(isinstance(v, (int, float)) for v in pos)):
            report.error(at, "position must be three numbers")
        rot = o.get("rotation", [0, 0, 0, 1])
        if not (isinstance(rot, list) and len(rot) == 4 and abs(math.sqrt(sum(v * v for v in rot)) - 1) < 1e-6):
            report.error(at, "rotation must be a unit quaternion [x, y, z, w]")
        if not (isinstance(o.get("scale", 1), (int, float)) and o.get("scale", 1) > 0):
            report.error(at, "scale must be positive")
        if "front" in o and not (isinstance(o["front"], list) and len(o["front"]) == 3):
            report.error(at, "front must be a vector")
    names = list(scene.boxes)
    for n in names:
        if not scene.boxes[n].inside(scene.bounds):
            report.error(where, f"{n!r} sticks out of the room")
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if scene.boxes[a].overlaps(scene.boxes[b]):
                report.error(where, f"{a!r} and {b!r} overlap")
    floor = scene.bounds.lo[1]
    for n, bx in scene.boxes.items():
        if bx.lo[1] > floor + EPS and n not in scene.support and n not in scene.hanging:
            report.error(where, f"{n!r} floats: its bottom ({bx.lo[1]:.4f}) is on no support's top "
                                "(footprint inside) and it hangs on no wall")


# ---------------------------------------------------------------- queries

def is_num(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def check_fields(check, at, report):
    kind = check["check"]
    object_fields, other_fields, required = CHECKS[kind]
    names = []
    for field in check:
        if field != "check" and field not in object_fields + other_fields:
            report.error(at, f"check {kind!r} has no field {field!r}")
    for field in required:
        if field not in check:
            report.error(at, f"check {kind!r} needs {field!r}")
    for field in object_fields:
        if field in check:
            if isinstance(check[field], str):
                names.append(check[field])
            else:
                report.error(at, f"{field} must be an object name")
    for field in ("tol", "min", "max", "max_gap", "degrees", "factor"):
        if field in check and not is_num(check[field]):
            report.error(at, f"{field} must be a number")
    if kind == "direction":
        if check.get("axis") not in AXES or len(str(check.get("axis"))) != 2:
            report.error(at, f"direction axis must be one of +x … -z: got {check.get('axis')!r}")
        if not (is_num(check.get("min", 0.05)) and check.get("min", 0.05) > 0):
            report.error(at, "min must be a positive number")
    if kind == "rotated" and check.get("axis", "y") not in AXES:
        report.error(at, f"axis {check.get('axis')!r}")
    if kind == "aligned" and check.get("axis") not in AXES:
        report.error(at, f"axis {check.get('axis')!r}")
    if kind == "side" and check.get("side") not in SIDES:
        report.error(at, f"side {check.get('side')!r}")
    if kind in ("moved", "at"):
        triple = check.get("delta" if kind == "moved" else "position")
        if triple is not None and not (isinstance(triple, list) and len(triple) == 3 and
                                       all(v is None or is_num(v) for v in triple)):
            report.error(at, "needs [x, y, z] with numbers or null")
    if kind == "unchanged":
        objects = check.get("objects", "others")
        if isinstance(objects, list) and objects and all(isinstance(n, str) for n in objects):
            names.extend(objects)
        elif objects != "others":
            report.error(at, 'objects must be "others" or a non-empty list of names')
    if kind == "refused":
        mentions = check.get("mentions", [])
        if isinstance(mentions, list) and all(isinstance(n, str) for n in mentions):
            names.extend(mentions)
        else:
            report.error(at, "mentions must be a list of names")
    if kind == "distance":
        lo, hi = check.get("min", 0), check.get("max", math.inf)
        if is_num(lo) and is_num(hi) and lo > hi:
            report.error(at, "min is above max")
    return names


AXIS_INDEX = {"x": 0, "y": 1, "z": 2}


def simulate(scene, expect, report, where):
    """Applies the checks that fix an end state and checks that state is legal."""
    start = {n: pose(o) for n, o in scene.objects.items()}
    moved = {}       # name -> full delta
    rotated = {}     # name -> degrees about y
    placed = {}      # name -> position
    vague = set()    # objects whose end is not fixed by the checks
    held = set()
    checked = set()
    for c in expect:
        kind = c.get("check")
        obj = c.get("object")
        if kind == "unchanged" and isinstance(c.get("objects"), list):
            held.update(c["objects"])
        if obj is None or obj not in scene.objects:
            continue
        checked.add(obj)
        if kind == "moved":
            d = c.get("delta")
            if isinstance(d, list) and all(is_num(v) for v in d):
                if obj in moved and any(abs(a - b) > 1e-9 for a, b in zip(moved[obj], d)):
                    report.error(where, f"two moved checks on {obj!r} disagree")
                moved[obj] = d
            else:
                vague.add(obj)
        elif kind == "at":
            p = c.get("position")
            if isinstance(p, list) and all(is_num(v) for v in p):
                placed[obj] = p
            else:
                vague.add(obj)
        elif kind == "rotated":
            if c.get("axis", "y") in ("y", "+y"):
                rotated[obj] = c.get("degrees", 90)
            elif c.get("axis") == "-y":
                rotated[obj] = -c.get("degrees", 90)
            else:
                vague.add(obj)
        elif kind == "swapped":
            other = c.get("other")
            if other in scene.objects:
                checked.add(other)
                pa, pb = scene.boxes[obj].bottom_centre, scene.boxes[other].bottom_centre
                moved[obj] = [b - a for a, b in zip(pa, pb)]
                moved[other] = [a - b for a, b in zip(pa, pb)]
        elif kind in EFFECTS:
            vague.add(obj)
    for n, p in placed.items():
        bc = scene.boxes[n].bottom_centre
        d = [b - a for a, b in zip(bc, p)]
        if n in moved and any(abs(a - b) > 0.05 for a, b in zip(moved[n], d)):
            report.error(where, f"moved and at disagree for {n!r}")
        moved.setdefault(n, d)
    # carrying
    floating = []
    for n in list(moved):
        for child in scene.resting_on(n):
            if child in held:
                floating.append(child)
                continue
            if child in checked:
                continue
            report.error(where, f"{child!r} rests on {n!r}, which moves: check it moved too (or hold it)")
    for n in rotated:
        for child in scene.resting_on(n):
            if child not in held and child not in checked:
                report.error(where, f"{child!r} rests on {n!r}, which turns: check it too")
    # end state
    boxes = dict(scene.boxes)
    unknown = set(vague) - set(moved) - set(rotated)
    for n in set(moved) | set(rotated):
        p, r, s = start[n]
        if n in rotated:
            r = qmul(yaw(rotated[n]), r)
        d = moved.get(n, [0, 0, 0])
        boxes[n] = box_of(scene.objects[n]["size"], [a + b for a, b in zip(p, d)], r, s)
        if n in moved and not boxes[n].inside(scene.bounds):
            report.error(where, f"{n!r} moved by {[round(v, 3) for v in d]} leaves the room")
        elif not boxes[n].inside(scene.bounds):
            report.error(where, f"{n!r} turned leaves the room")
    for child in floating:
        if child in moved or child in rotated:
            continue
        cb = boxes[child]
        if not any(m != child and abs(b.hi[1] - cb.lo[1]) <= EPS and cb.centre_over(b)
                   for m, b in boxes.items()):
            report.error(where, f"held {child!r} would be left floating once its support moves: expect a refusal")
    changed = (set(moved) | set(rotated)) - unknown
    names = [n for n in boxes if n not in unknown]
    for a in changed:
        for b in names:
            if a == b or (b in changed and b < a):
                continue
            if boxes[a].overlaps(boxes[b]) and not scene.boxes[a].overlaps(scene.boxes[b]):
                report.error(where, f"the expected end state has {a!r} overlapping {b!r}")


def reachable(scene, c, report, at):
    kind = c.get("check")
    obj = c.get("object")
    if obj not in scene.boxes or scene.bounds is None:
        return
    group = [obj] + scene.resting_on(obj)
    if kind == "moved" and isinstance(c.get("delta"), list):
        d = [v if is_num(v) else 0.0 for v in c["delta"]]
        for n in group:
            if not scene.boxes[n].moved(d).inside(scene.bounds):
                report.error(at, f"delta {d} takes {n!r} out of the room {scene.name!r}")
    if kind == "direction" and c.get("axis") in AXES:
        axis = c["axis"]
        sign = -1 if axis.startswith("-") else 1
        d = [0.0, 0.0, 0.0]
        d[AXIS_INDEX[axis[-1]]] = sign * c.get("min", 0.05)
        if not scene.boxes[obj].moved(d).inside(scene.bounds):
            report.error(at, f"{obj!r} cannot move {c.get('min', 0.05)} m {axis} in {scene.name!r}")
    if kind == "at" and isinstance(c.get("position"), list):
        p = [v if is_num(v) else b for v, b in zip(c["position"], scene.boxes[obj].bottom_centre)]
        d = [a - b for a, b in zip(p, scene.boxes[obj].bottom_centre)]
        if not scene.boxes[obj].moved(d).inside(scene.bounds):
            report.error(at, f"position {p} puts {obj!r} outside {scene.name!r}")


def check_query(query, scenes, report, where, seen):
    allowed = {"id", "category", "text", "scenes", "expect", "pick"}
    keys = set(query)
    if not {"id", "category", "text", "scenes", "expect"} <= keys or keys - allowed:
        report.error(where, f"fields must be id, category, text, scenes, expect (pick): got {sorted(keys)}")
    qid = query.get("id")
    if not isinstance(qid, str) or not qid:
        report.error(where, "no id")
        return None
    where = f"{where} ({qid})"
    if qid in seen:
        report.error(where, "id used twice")
    seen.add(qid)
    family = qid.split("-")[0]
    if family not in FAMILIES:
        report.error(where, f"id must start with one of {', '.join(f + '-' for f in FAMILIES)}")
    if query.get("category") not in CATEGORIES:
        report.error(where, f"unknown category {query.get('category')!r}")
    text = query.get("text")
    if not isinstance(text, str) or not text.strip():
        report.error(where, "no text")
        text = ""
    if "{" in text or "}" in text:
        report.error(where, "the text has a {placeholder}")
    if QUOTED.search(text):
        report.error(where, "the text quotes a name")
    listed = query.get("scenes")
    if not isinstance(listed, list) or not listed:
        report.error(where, "scenes must list the scenes the query runs on")
        listed = []
    if len(set(map(str, listed))) != len(listed):
        report.error(where, "a scene is listed twice")
    for s in listed:
        if s not in scenes:
            report.error(where, f"scene {s!r} is not one of the suite's: {', '.join(sorted(scenes))}")
    expect = query.get("expect")
    if not isinstance(expect, list) or not expect:
        report.error(where, "expect has no check")
        expect = []
    kinds = []
    names = []
    others = False
    good = []
    for k, c in enumerate(expect):
        at = f"{where} expect[{k}]"
        if not isinstance(c, dict) or c.get("check") not in CHECKS:
            report.error(at, f"unknown check {c!r}")
            continue
        kinds.append(c["check"])
        names.extend((at, n) for n in check_fields(c, at, report))
        if c["check"] == "unchanged" and c.get("objects", "others") == "others":
            others = True
        good.append((at, c))
    if "refused" in kinds:
        if len(kinds) != 1:
            report.error(where, "a refusal has no other check (nothing may change)")
        if family != "refuse":
            report.error(where, "a refusal's id starts with refuse-")
    else:
        if family == "refuse":
            report.error(where, "a refuse- query needs a refused check")
        if not others:
            report.error(where, 'a successful edit says what must not move: add unchanged "others"')
        if not any(k in EFFECTS for k in kinds):
            report.error(where, "no check on what the edit must change")
    if family == "place" and not any(k in ("on_top", "next_to", "side", "at", "above", "below", "between") for k in kinds):
        report.error(where, "a place- query checks where the object ends (on_top, next_to, side, at …)")
    for s in listed:
        scene = scenes.get(s)
        if scene is None:
            continue
        ok = True
        for at, n in names:
            if n not in scene.objects:
                near = [o for o in scene.objects if o.lower() == n.lower()]
                hint = f" (the scene spells it {near[0]!r})" if near else ""
                report.error(at, f"no object {n!r} in scene {s!r}{hint}")
                ok = False
        if not ok or "refused" in kinds:
            continue
        for at, c in good:
            reachable(scene, c, report, at)
        simulate(scene, [c for _, c in good], report, f"{where} [{s}]")
    return family


def main(argv):
    path = argv[0] if argv else DEFAULT_SUITE
    report = Report()
    where = os.path.relpath(path, ROOT)
    try:
        with open(path) as f:
            suite = json.load(f)
    except (OSError, ValueError) as e:
        print(f"{where}: cannot read: {e}", file=sys.stderr)
        return 1
    extra = set(suite) - {"name", "scenes", "variations", "seed", "queries"}
    if extra:
        report.error(where, f"unknown fields {sorted(extra)}")
    if not isinstance(suite.get("name"), str):
        report.error(where, "no name")
    if suite.get("variations") != 1:
        report.error(where, "queries without placeholders run once per scene: variations 1")
    scenes = {}
    for k, entry in enumerate(suite.get("scenes", [])):
        at = f"{where} scenes[{k}]"
        if not isinstance(entry, str):
            report.error(at, "a scene is a path relative to the suite")
            continue
        spath = os.path.normpath(os.path.join(os.path.dirname(path), entry))
        try:
            with open(spath) as f:
                data = json.load(f)
        except (OSError, ValueError) as e:
            report.error(at, f"cannot read scene {spath}: {e}")
            continue
        scene = Scene(data, spath)
        stem = os.path.splitext(os.path.basename(spath))[0]
        if scene.name != stem:
            report.error(at, f"scene {spath} is named {scene.name!r}; queries name scenes by file stem {stem!r}")
        if scene.name in scenes:
            report.error(at, f"scene {scene.name!r} listed twice")
        check_scene(scene, report, os.path.relpath(spath, ROOT))
        scenes[scene.name] = scene
    if not scenes:
        report.error(where, "no scene could be read")
    queries = suite.get("queries", [])
    if len(queries) < 320:
        report.error(where, f"{len(queries)} queries; at least 320 are asked for")
    seen = set()
    per_family = collections.Counter()
    per_category = collections.Counter()
    per_scene = collections.Counter()
    table = collections.Counter()
    refusals = 0
    for i, q in enumerate(queries):
        if not isinstance(q, dict):
            report.error(f"{where} queries[{i}]", "a query is an object")
            continue
        family = check_query(q, scenes, report, f"{where} queries[{i}]", seen)
        per_family[family] += 1
        per_category[q.get("category")] += 1
        table[(family, q.get("category"))] += 1
        for s in q.get("scenes") or []:
            per_scene[s] += 1
        if any(isinstance(c, dict) and c.get("check") == "refused" for c in q.get("expect", [])):
            refusals += 1
    instances = sum(per_scene.values())
    print(f"{where}: {len(queries)} queries, {instances} instances over {len(scenes)} scenes")
    print("  per family:    " + ", ".join(f"{f} {per_family[f]}" for f in FAMILIES))
    print("  per category:  " + ", ".join(f"{c} {per_category[c]}" for c in CATEGORIES))
    print("  per scene:     " + ", ".join(f"{s} {per_scene[s]}" for s in scenes))
    print(f"  refusals: {refusals} ({100 * refusals / max(len(queries), 1):.1f} %)")
    print("  family x category:")
    print("    " + " " * 8 + "".join(f"{c[:12]:>13}" for c in CATEGORIES))
    for fam in FAMILIES:
        print(f"    {fam:<8}" + "".join(f"{table[(fam, c)]:>13}" for c in CATEGORIES))
    for s, scene in scenes.items():
        rests = ", ".join(f"{c} on {p}" for c, p in sorted(scene.support.items()))
        print(f"  {s}: {len(scene.objects)} objects; resting: {rests}; hanging: {', '.join(sorted(scene.hanging))}")
    if report.errors:
        print(f"\n{len(report.errors)} problem(s):", file=sys.stderr)
        for e in report.errors:
            print("  " + e, file=sys.stderr)
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
