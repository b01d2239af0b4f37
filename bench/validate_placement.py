#!/usr/bin/env python3
"""Validates the natural placement suite (stdlib only).

    python3 bench/validate_placement.py [--houses DIR] [SUITE ...]

Checks bench/natural-placement.suite.json (or the suites given) against its scenes: the
built-in examples (examples/*.json, by the paths the suite lists) and ProcTHOR houses
converted to Shenlong scene JSON as DIR/house-N.json (default /tmp/houses, or
$SHENLONG_HOUSES; make them with `shenlong convert ../shared/data/procthor/houses.jsonl
DIR/house-N.json --from procthor --assets ../shared/data/procthor/asset-database.json
--house N`).

The suite is the hard section of the natural suites: where things end up when people say
where to put them. Its constructs (the id's first word):
- face-    turning to face something, away from it, its back to it, the same way as
           another object, a wall or the middle of the room (`faces`, or `rotated` about y
           by the change computed from the scene);
- surface- putting one to four objects on a surface that may already hold something at
           its centre (`on_top` each, `no_collision`), or one that is too full or too
           small (`refused`);
- floor-   on the floor, or off a surface onto the floor beside it (`at` the floor,
           `next_to` the surface);
- level-   next to, beside, in front of, to the left / right of floor furniture: the
           object stays on the floor (`at` the floor, `next_to` or `side`);
- stack-   on top of a small object, or of the one that is on a table (`on_top`).

What it checks:
- the suite's fields (name, scenes, variations 1, seed, queries), that every scene entry
  resolves to a scene with a name, room bounds and unique object names, and that a house
  entry's file is named `houses N`;
- every query has exactly id, category, text, scenes, expect; ids are unique; the category
  is hard; the id starts with a construct above and ends with the scene's short code
  (-lr, -br, ... for the built-in scenes, -hN for houses N); `scenes` lists exactly one of
  the suite's scenes;
- the text has no {placeholders} and no quoted names;
- every check is known, with known fields and the required ones, and every object it
  names exists, exactly as the scene spells it, in the query's scene;
- a refusal is the query's only check; a successful edit has `unchanged: "others"` and
  `no_collision`;
- per construct, the checks it needs (above); `at` positions inside the room, at the floor
  for floor- and level-; `faces` tolerance at most 10 degrees, `rotated` about y within
  (-180, 180], at most 5 degrees of tolerance for "the same way as";
- from the scene geometry (world boxes of the 8 turned corners, fronts turned by the
  rotation): no checked object carries another object (carrying would move it), no
  support, target or other rests on the object it is about; a `faces` target is not
  already faced within the tolerance and a `rotated` turn is larger than its tolerance;
  level- objects and their others stand on the floor; surface- objects fit on the
  support side by side (along its longer axis, 5 cm apart), stack- objects are not larger
  than their support;
- the suite's size: at least 80 queries, about half on houses, at least 6 houses, and at
  least 20 face- (10 of them on ProcTHOR furniture that is already turned), 20 surface-,
  10 floor-, 10 level- and 5 stack- queries.

Prints the counts per construct (built-in scenes, houses, refusals) and per scene, and
exits non-zero when anything is wrong.
"""

import collections
import json
import math
import os
import re
import sys

from suite_schema import SHORT, CHECKS, EFFECTS, NUMBERS, SIDES, QUOTED, Report, is_number

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_SUITES = [os.path.join(HERE, "natural-placement.suite.json")]

CONSTRUCTS = ["face", "surface", "floor", "level", "stack"]
MINIMUM = {"face": 20, "surface": 20, "floor": 10, "level": 10, "stack": 5}

SAME_WAY = re.compile(r"\bsame (way|direction)\b", re.I)
OFF = re.compile(r"\boff\b", re.I)
GAP = 0.05          # objects put on one surface together are laid out 5 cm apart
RESTS_TOL = 0.03    # a bottom this close to a top rests on it (the on_top default)


# ---------------------------------------------------------------- geometry (SPEC section 2)

def rotate(q, v):
    """v turned by the unit quaternion q = [x, y, z, w]."""
    x, y, z, w = q
    vx, vy, vz = v
    tx, ty, tz = 2 * (y * vz - z * vy), 2 * (z * vx - x * vz), 2 * (x * vy - y * vx)
    return (vx + w * tx + (y * tz - z * ty), vy + w * ty + (z * tx - x * tz),
            vz + w * tz + (x * ty - y * tx))


class Thing:
    """A scene object's world box, front and the fields the checks need."""

    def __init__(self, o):
        self.name = o["name"]
        self.on = o.get("on")
        q = o.get("rotation", [0, 0, 0, 1])
        norm = math.sqrt(sum(c * c for c in q)) or 1.0
        q = [c / norm for c in q]
        self.turned = abs(abs(q[3]) - 1) > 1e-6
        s = o.get("scale", 1.0)
        w, h, d = (v * s for v in o["size"])
        p = o["position"]
        corners = [rotate(q, (dx * w, dy * h, dz * d)) for dx in (-0.5, 0.5) for dy in (0, 1)
                   for dz in (-0.5, 0.5)]
        self.min = [p[i] + min(c[i] for c in corners) for i in range(3)]
        self.max = [p[i] + max(c[i] for c in corners) for i in range(3)]
        self.center = [(self.min[i] + self.max[i]) / 2 for i in range(3)]
        self.size = [self.max[i] - self.min[i] for i in range(3)]
        self.front = rotate(q, o.get("front", [0, 0, 1]))

    def rests_on(self, other):
        """Resting on other's top face (centre over it), or said to be on it."""
        if self.on == other.name:
            return True
        return (abs(self.min[1] - other.max[1]) <= RESTS_TOL
                and other.min[0] - 1e-6 <= self.center[0] <= other.max[0] + 1e-6
                and other.min[2] - 1e-6 <= self.center[2] <= other.max[2] + 1e-6)


def heading(v):
    """Degrees about +Y from +Z (+90 is +X): the right-hand rule's sign."""
    return math.degrees(math.atan2(v[0], v[2]))


def wrap(a):
    a = (a + 180.0) % 360.0 - 180.0
    return 180.0 if a == -180.0 else a


# ---------------------------------------------------------------- scenes

def houses_dir(argv):
    if "--houses" in argv:
        i = argv.index("--houses")
        if i + 1 >= len(argv):
            sys.exit("--houses needs a directory")
        path = argv[i + 1]
        del argv[i:i + 2]
        return path
    return os.environ.get("SHENLONG_HOUSES", "/tmp/houses")


class Scene:
    def __init__(self, name, data, house):
        self.name = name
        self.house = house
        self.things = {o["name"]: Thing(o) for o in data.get("objects", [])
                       if isinstance(o.get("name"), str)}
        b = data.get("bounds") or {}
        self.bounds = (b.get("min"), b.get("max")) if len(b.get("min", [])) == 3 and \
            len(b.get("max", [])) == 3 else None
        self.floor = self.bounds[0][1] if self.bounds else 0.0

    def carried(self, name):
        t = self.things[name]
        return [o.name for o in self.things.values() if o is not t and o.rests_on(t)]

    def on_floor(self, name):
        return abs(self.things[name].min[1] - self.floor) <= 0.01


def load_scene(entry, suite_dir, houses, report, where):
    if isinstance(entry, str):
        path = os.path.normpath(os.path.join(suite_dir, entry))
        house = None
    elif isinstance(entry, dict):
        extra = set(entry) - {"procthor", "house", "assets"}
        if extra or "procthor" not in entry or not isinstance(entry.get("house"), int):
            report.error(where, f"a house entry is {{procthor, house: N, assets}}: got {entry}")
            return None
        for key in ("procthor", "assets"):
            if key in entry and not os.path.exists(os.path.join(suite_dir, entry[key])):
                report.error(where, f"{key} file {entry[key]} not found from {suite_dir}")
        house = entry["house"]
        path = os.path.join(houses, f"house-{house}.json")
    else:
        report.error(where, f"a scene is a path or a house entry: got {entry!r}")
        return None
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        hint = " (convert the houses first, see --houses)" if house is not None else ""
        report.error(where, f"cannot read scene {path}: {e}{hint}")
        return None
    name = data.get("name")
    if not isinstance(name, str):
        report.error(where, f"scene {path} has no name")
        return None
    if house is not None and name != f"houses {house}":
        report.error(where, f"{path} is named {name!r}, not 'houses {house}'")
    names = [o.get("name") for o in data.get("objects", [])]
    if not all(isinstance(n, str) for n in names):
        report.error(where, f"scene {name} has an object with no name")
    lowered = [n.lower() for n in names if isinstance(n, str)]
    if len(set(lowered)) != len(lowered):
        report.error(where, f"scene {name} has object names used twice")
    scene = Scene(name, data, house)
    if scene.bounds is None:
        report.error(where, f"scene {name} has no room bounds")
    return scene


def short_code(scene):
    return f"h{scene.house}" if scene.house is not None else SHORT.get(scene.name, scene.name)


# ---------------------------------------------------------------- queries

def check_fields(expect, report, where):
    """Field-level checks; returns [(index, check)] of the well-formed ones."""
    good = []
    for k, check in enumerate(expect):
        at = f"{where} expect[{k}]"
        if not isinstance(check, dict) or check.get("check") not in CHECKS:
            report.error(at, f"unknown check {check!r}")
            continue
        kind = check["check"]
        object_fields, other_fields, required = CHECKS[kind]
        ok = True
        for field in check:
            if field != "check" and field not in object_fields + other_fields:
                report.error(at, f"check {kind!r} has no field {field!r}")
            if field in NUMBERS and not is_number(check[field]):
                report.error(at, f"{field} must be a number")
                ok = False
        for field in required:
            if field not in check:
                report.error(at, f"check {kind!r} needs {field!r}")
                ok = False
        for field in object_fields:
            if field in check and not isinstance(check[field], str):
                report.error(at, f"{field} must be an object name")
                ok = False
        if kind == "side" and check.get("side") not in SIDES:
            report.error(at, f"side {check.get('side')!r}")
        if kind == "rotated" and check.get("axis", "y") != "y":
            report.error(at, "turns in this suite are about y")
        if kind in ("moved", "at"):
            triple = check.get("delta" if kind == "moved" else "position")
            if triple is not None and not (isinstance(triple, list) and len(triple) == 3 and
                                           all(v is None or is_number(v) for v in triple)):
                report.error(at, "needs [x, y, z] with numbers or null")
                ok = False
        if kind == "unchanged":
            objects = check.get("objects", "others")
            if objects != "others" and not (isinstance(objects, list) and objects and
                                            all(isinstance(n, str) for n in objects)):
                report.error(at, 'objects must be "others" or a non-empty list of names')
                ok = False
        if kind == "refused":
            mentions = check.get("mentions", [])
            if not isinstance(mentions, list) or not all(isinstance(n, str) for n in mentions):
                report.error(at, "mentions must be a list of names")
                ok = False
            elif len(mentions) == 1:
                report.error(at, "an ambiguous phrase has several candidates; an unclear part none")
        if ok:
            good.append((k, check))
    return good


def names_in(check):
    kind = check["check"]
    names = [check[f] for f in CHECKS[kind][0] if f in check]
    if kind == "unchanged" and isinstance(check.get("objects"), list):
        names += check["objects"]
    if kind == "refused":
        names += check.get("mentions", [])
    return names


def check_construct(construct, text, checks, scene, report, where):
    """What each construct needs, and the geometry that makes its checks meaningful."""
    kinds = [c["check"] for _, c in checks]
    refused = "refused" in kinds
    by_kind = collections.defaultdict(list)
    for k, c in checks:
        by_kind[c["check"]].append((k, c))

    def at_floor(obj):
        ats = [c for _, c in by_kind["at"] if c["object"] == obj]
        if not any(isinstance(c["position"], list) and c["position"][0] is None and
                   c["position"][2] is None and is_number(c["position"][1]) and
                   abs(c["position"][1] - scene.floor) < 1e-9 and c.get("tol", 0.05) <= 0.01
                   for c in ats):
            report.error(where, f"{obj!r} needs at [null, {scene.floor:g}, null] with tol <= 0.01 "
                                "(on the floor)")

    if refused:
        if construct != "surface":
            report.error(where, "only surface- queries are refusals (too full or too small)")
        return
    for kind in ("no_collision",):
        if kind not in kinds:
            report.error(where, "a successful placement has no_collision")
    if construct == "face":
        turns = by_kind["faces"] + by_kind["rotated"]
        if len(turns) != 1:
            report.error(where, "a face- query has one faces or rotated check")
        for k, c in by_kind["faces"]:
            if c.get("tol", 20) > 10:
                report.error(f"{where} expect[{k}]", "faces tolerance at most 10 degrees")
            if SAME_WAY.search(text):
                report.error(f"{where} expect[{k}]", "'the same way as' is checked with rotated")
        for k, c in by_kind["rotated"]:
            d = c.get("degrees", 90)
            if not (-180 < d <= 180 or (c.get("either_sign") and d == 180)):
                report.error(f"{where} expect[{k}]", "degrees within (-180, 180]")
            if abs(d) <= c.get("tol", 5):
                report.error(f"{where} expect[{k}]", "a turn no larger than its tolerance")
            if SAME_WAY.search(text) and c.get("tol", 5) > 5:
                report.error(f"{where} expect[{k}]", "'the same way as' has tol <= 5")
            if c.get("tol", 5) > 10:
                report.error(f"{where} expect[{k}]", "rotated tolerance at most 10 degrees")
    elif construct == "surface":
        tops = by_kind["on_top"]
        if not 1 <= len(tops) <= 4:
            report.error(where, "a surface- query puts 1 to 4 objects on one surface")
        supports = {c["support"] for _, c in tops}
        if len(supports) > 1:
            report.error(where, f"all on one surface: got {sorted(supports)}")
        if tops and len(supports) == 1 and all(c["object"] in scene.things for _, c in tops) \
                and next(iter(supports)) in scene.things:
            sup = scene.things[next(iter(supports))]
            long_axis = 0 if sup.size[0] >= sup.size[2] else 2
            across = 2 - long_axis
            along = sum(scene.things[c["object"]].size[long_axis] for _, c in tops) \
                + GAP * (len(tops) - 1)
            wide = max(scene.things[c["object"]].size[across] for _, c in tops)
            if along > sup.size[long_axis] + 1e-9 or wide > sup.size[across] + 1e-9:
                report.error(where, f"the objects ({along:.2f} m side by side, {wide:.2f} m "
                                    f"across) do not fit on {sup.name!r} "
                                    f"({sup.size[long_axis]:.2f} x {sup.size[across]:.2f} m)")
    elif construct == "floor":
        if not by_kind["at"]:
            report.error(where, "a floor- query checks at the floor")
        for _, c in by_kind["at"]:
            at_floor(c["object"])
        if OFF.search(text):
            if not by_kind["next_to"]:
                report.error(where, "'off X' ends beside X: add next_to X")
            for k, c in by_kind["next_to"]:
                if c.get("max_gap", 0.3) > 0.6:
                    report.error(f"{where} expect[{k}]", "beside: max_gap at most 0.6")
    elif construct == "level":
        rel = by_kind["next_to"] + by_kind["side"]
        if len(rel) != 1:
            report.error(where, "a level- query has one next_to or side check")
        for _, c in rel:
            at_floor(c["object"])
            for n in (c["object"], c["other"]):
                if n in scene.things and not scene.on_floor(n):
                    report.error(where, f"{n!r} does not stand on the floor")
        if by_kind["on_top"] or by_kind["above"]:
            report.error(where, "a level- object never ends on top of the other")
    elif construct == "stack":
        if len(by_kind["on_top"]) != 1:
            report.error(where, "a stack- query has one on_top check")
        for k, c in by_kind["on_top"]:
            o, s = scene.things.get(c["object"]), scene.things.get(c["support"])
            if o and s and (o.size[0] * o.size[2] > s.size[0] * s.size[2]):
                report.error(f"{where} expect[{k}]", f"{o.name!r} is larger than {s.name!r}")
    # geometry common to all successful edits
    reported = set()
    for k, c in checks:
        obj = c.get("object")
        if not isinstance(obj, str) or obj not in scene.things or c["check"] == "unchanged":
            continue
        carried = scene.carried(obj)
        named = {c2.get("object") for _, c2 in checks}
        for n in carried:
            if n not in named and (obj, n) not in reported:
                reported.add((obj, n))
                report.error(f"{where} expect[{k}]", f"{obj!r} carries {n!r}, which has no check "
                                                     "of its own: pick an object that carries nothing")
        for field in ("support", "other", "target"):
            t = c.get(field)
            if isinstance(t, str) and t in scene.things and scene.things[t].rests_on(scene.things[obj]):
                report.error(f"{where} expect[{k}]", f"{t!r} rests on {obj!r}: it would be carried")
        if c["check"] == "faces" and c["target"] in scene.things:
            o, t = scene.things[obj], scene.things[c["target"]]
            to = heading((t.center[0] - o.center[0], 0, t.center[2] - o.center[2]))
            if abs(wrap(to - heading(o.front))) <= c.get("tol", 20):
                report.error(f"{where} expect[{k}]", f"{obj!r} already faces {t.name!r}")
        if c["check"] == "at" and scene.bounds and isinstance(c.get("position"), list):
            lo, hi = scene.bounds
            for axis, v in enumerate(c["position"]):
                if v is not None and not lo[axis] - 1e-9 <= v <= hi[axis] + 1e-9:
                    report.error(f"{where} expect[{k}]", f"position {c['position']} is outside the room")


def check_query(query, scenes, report, where, seen_ids):
    keys = set(query)
    if keys != {"id", "category", "text", "scenes", "expect"}:
        report.error(where, f"fields must be id, category, text, scenes, expect: got {sorted(keys)}")
    qid = query.get("id")
    if not isinstance(qid, str) or not qid:
        report.error(where, "no id")
        return None
    where = f"{where} ({qid})"
    if qid in seen_ids:
        report.error(where, f"id used twice (also in {seen_ids[qid]})")
    seen_ids[qid] = where
    construct = qid.split("-")[0]
    if construct not in CONSTRUCTS:
        report.error(where, f"id must start with one of {', '.join(c + '-' for c in CONSTRUCTS)}")
    if query.get("category") != "hard":
        report.error(where, f"the category is hard (this is the natural suite's hard section): "
                            f"got {query.get('category')!r}")
    text = query.get("text")
    if not isinstance(text, str) or not text.strip():
        report.error(where, "no text")
        text = ""
    if "{" in text or "}" in text:
        report.error(where, "the text has a {placeholder}: write the words a person would")
    if QUOTED.search(text):
        report.error(where, "the text quotes a name: write it as a person would")
    listed = query.get("scenes")
    if not isinstance(listed, list) or len(listed) != 1 or not isinstance(listed[0], str):
        report.error(where, "scenes must list exactly the one scene the query is written for")
        return None
    scene = scenes.get(listed[0])
    if scene is None:
        report.error(where, f"scene {listed[0]!r} is not one of the suite's: {', '.join(sorted(scenes))}")
        return None
    if not qid.endswith("-" + short_code(scene)):
        report.error(where, f"the id should end with the scene's short code -{short_code(scene)}")
    expect = query.get("expect")
    if not isinstance(expect, list) or not expect:
        report.error(where, "expect has no check")
        return None
    checks = check_fields(expect, report, where)
    kinds = [c["check"] for _, c in checks]
    missing = False
    for k, c in checks:
        for n in names_in(c):
            if n not in scene.things:
                near = [o for o in scene.things if o.lower() == n.lower()]
                hint = f" (the scene spells it {near[0]!r})" if near else ""
                report.error(f"{where} expect[{k}]", f"no object {n!r} in scene {scene.name!r}{hint}")
                missing = True
    refused = "refused" in kinds
    if refused:
        if len(expect) != 1:
            report.error(where, "a refusal has no other check (nothing may change)")
    else:
        if not any(c.get("objects", "others") == "others" for _, c in checks if c["check"] == "unchanged"):
            report.error(where, 'a successful edit says what must not move: add unchanged "others"')
        if not any(k in EFFECTS for k in kinds):
            report.error(where, "no check on what the edit must change")
    if construct in CONSTRUCTS and not missing:
        check_construct(construct, text, checks, scene, report, where)
    turned_house = False
    if construct == "face" and scene.house is not None and not missing:
        turned_house = any(scene.things[c["object"]].turned for _, c in checks
                           if c["check"] in ("faces", "rotated"))
    return construct, scene, refused, turned_house


def main(argv):
    houses = houses_dir(argv)
    suites = argv or DEFAULT_SUITES
    report = Report()
    seen_ids = {}
    for path in suites:
        where = os.path.relpath(path, ROOT) if os.path.abspath(path).startswith(ROOT) else path
        try:
            with open(path) as f:
                suite = json.load(f)
        except (OSError, ValueError) as e:
            report.error(where, f"cannot read: {e}")
            continue
        extra = set(suite) - {"name", "scenes", "variations", "seed", "queries"}
        if extra:
            report.error(where, f"unknown fields {sorted(extra)}")
        if not isinstance(suite.get("name"), str):
            report.error(where, "no name")
        if suite.get("variations", 1) != 1:
            report.error(where, "queries without placeholders run once per scene: variations 1")
        if not isinstance(suite.get("seed"), int) or isinstance(suite.get("seed"), bool):
            report.error(where, "the seed is an integer")
        scenes = {}
        for k, entry in enumerate(suite.get("scenes", [])):
            scene = load_scene(entry, os.path.dirname(os.path.abspath(path)), houses, report,
                               f"{where} scenes[{k}]")
            if scene:
                if scene.name in scenes:
                    report.error(f"{where} scenes[{k}]", f"scene {scene.name!r} listed twice")
                scenes[scene.name] = scene
        if not scenes:
            report.error(where, "no scene could be read")
        queries = suite.get("queries", [])
        if not isinstance(queries, list):
            report.error(where, "queries must be a list")
            queries = []
        table = collections.Counter()
        per_scene = collections.Counter()
        turned = 0
        for i, query in enumerate(queries):
            if not isinstance(query, dict):
                report.error(f"{where} queries[{i}]", "a query is an object")
                continue
            result = check_query(query, scenes, report, f"{where} queries[{i}]", seen_ids)
            if result is None:
                continue
            construct, scene, refused, turned_house = result
            kind = "houses" if scene.house is not None else "built-in"
            table[(construct, kind)] += 1
            table[(construct, "refused")] += refused
            per_scene[scene.name] += 1
            turned += turned_house
        total = sum(per_scene.values())
        on_houses = sum(n for s, n in per_scene.items() if scenes[s].house is not None)
        print(f"{where}: {len(queries)} queries over {len(scenes)} scenes "
              f"({on_houses} on houses, {total - on_houses} on the built-in scenes)")
        print(f"    {'construct':<10}{'built-in':>10}{'houses':>10}{'refused':>10}{'total':>10}")
        for c in CONSTRUCTS:
            n = table[(c, "built-in")] + table[(c, "houses")]
            print(f"    {c:<10}{table[(c, 'built-in')]:>10}{table[(c, 'houses')]:>10}"
                  f"{table[(c, 'refused')]:>10}{n:>10}")
            if n < MINIMUM[c]:
                report.error(where, f"{c}-: {n} queries, at least {MINIMUM[c]}")
        print(f"    face- on turned ProcTHOR furniture: {turned}")
        print("  per scene: " + ", ".join(f"{s} {per_scene[s]}" for s in scenes))
        if total < 80:
            report.error(where, f"{total} queries, at least 80")
        if total and not 0.35 <= on_houses / total <= 0.65:
            report.error(where, f"{on_houses} of {total} queries on houses: about half")
        used_houses = [s for s in per_scene if scenes[s].house is not None]
        if len(used_houses) < 6:
            report.error(where, f"queries on {len(used_houses)} houses, at least 6")
        if turned < 10:
            report.error(where, f"{turned} face- queries on turned ProcTHOR furniture, at least 10")
        unused = [s for s in scenes if not per_scene[s]]
        if unused:
            report.error(where, f"scenes no query runs on: {', '.join(unused)}")
    if report.errors:
        print(f"\n{len(report.errors)} problem(s):", file=sys.stderr)
        for e in report.errors:
            print("  " + e, file=sys.stderr)
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
