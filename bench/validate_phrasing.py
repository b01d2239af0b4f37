#!/usr/bin/env python3
"""Validates the natural-phrasing suite (stdlib only).

    python3 bench/validate_phrasing.py [SUITE ...]

Checks bench/natural-phrasing.suite.json (or the suites given) against the built-in example
scenes it lists (examples/*.json, by the paths in the suite). The suite tests how people
phrase edits — vague and spoken amounts, both directions of scaling, everyday verbs and
typos, places in the room, relations, diagonals, turns, "too", politeness — and the
refusals that must happen; its objects are named plainly, and its checks name them by
their scene names.

What it checks:
- the suite's fields (name, scenes, variations 1, seed, queries), and that every scene
  entry is a readable scene with a name, bounds and unique object names;
- every query has exactly id, category, text, scenes, expect; ids are unique; the category
  is one of SPEC section 6; the id starts with a known construct (vague, number, scale,
  verb, place, rel, diag, turn, too, polite, refuse) and ends with the scene's short code;
- `scenes` lists exactly one of the suite's scenes;
- the text has no {placeholders}, no quoted names, and no "face the same way / direction"
  (a later feature);
- every check is known, with known fields and the required ones, and every object it
  names (object, support, other, target, a, b, unchanged lists, refusal mentions) exists,
  exactly as the scene spells it, in the query's scene;
- `at` positions lie inside the room's bounds; tolerances and amounts are numbers;
- a refusal (`refused`) is the query's only check, its id starts with `refuse-` and its
  category is hard; a successful edit has `unchanged: "others"` and at least one check on
  what must change.

Prints the counts per category and per construct (the id's first word), the construct x
category table, the refusal share and the instances per scene, and exits non-zero when
anything is wrong.
"""

import collections
import json
import os
import re
import sys

from suite_schema import CATEGORIES, SHORT, CHECKS, EFFECTS, NUMBERS, AXES, SIDES, QUOTED, Report, is_number

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_SUITES = [os.path.join(HERE, "natural-phrasing.suite.json")]

CONSTRUCTS = ["vague", "number", "scale", "verb", "place", "rel", "diag", "turn", "too",
              "polite", "refuse"]

SAME_WAY = re.compile(r"\b(same way|same direction)\b", re.I)


def load_scene(entry, suite_dir, report, where):
    """The scene a suite entry names: (name, {object name: None}, bounds), or None."""
    if not isinstance(entry, str):
        report.error(where, f"a scene is a path to a scene file: got {entry!r}")
        return None
    path = os.path.normpath(os.path.join(suite_dir, entry))
    try:
        with open(path) as f:
            scene = json.load(f)
    except (OSError, ValueError) as e:
        report.error(where, f"cannot read scene {path}: {e}")
        return None
    name = scene.get("name")
    if not isinstance(name, str):
        report.error(where, f"scene {path} has no name")
        return None
    names = [o.get("name") for o in scene.get("objects", [])]
    lowered = [n.lower() for n in names if isinstance(n, str)]
    if len(set(lowered)) != len(lowered):
        report.error(where, f"scene {name} has object names used twice")
    bounds = scene.get("bounds")
    if not (isinstance(bounds, dict) and len(bounds.get("min", [])) == 3
            and len(bounds.get("max", [])) == 3):
        report.error(where, f"scene {name} has no room bounds")
        bounds = None
    return name, set(n for n in names if isinstance(n, str)), bounds


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
    category = query.get("category")
    if category not in CATEGORIES:
        report.error(where, f"unknown category {category!r}: use {', '.join(CATEGORIES)}")
    text = query.get("text")
    if not isinstance(text, str) or not text.strip():
        report.error(where, "no text")
        text = ""
    if "{" in text or "}" in text:
        report.error(where, "the text has a {placeholder}: write the words a person would")
    if QUOTED.search(text):
        report.error(where, "the text quotes a name: write it as a person would")
    if SAME_WAY.search(text):
        report.error(where, "\"face the same way / direction as\" is a later feature: leave it out")
    listed = query.get("scenes")
    if not isinstance(listed, list) or len(listed) != 1:
        report.error(where, "scenes must list exactly the one scene the query is written for")
        listed = listed if isinstance(listed, list) else []
    for s in listed:
        if s not in scenes:
            report.error(where, f"scene {s!r} is not one of the suite's: {', '.join(sorted(scenes))}")
        elif SHORT.get(s) and not qid.endswith("-" + SHORT[s]):
            report.error(where, f"the id should end with the scene's short code -{SHORT[s]}")
    expect = query.get("expect")
    if not isinstance(expect, list) or not expect:
        report.error(where, "expect has no check")
        expect = []
    names_used = []
    kinds = []
    positions = []
    others = False
    for k, check in enumerate(expect):
        at = f"{where} expect[{k}]"
        if not isinstance(check, dict) or check.get("check") not in CHECKS:
            report.error(at, f"unknown check {check!r}")
            continue
        kind = check["check"]
        kinds.append(kind)
        object_fields, other_fields, required = CHECKS[kind]
        for field in check:
            if field != "check" and field not in object_fields + other_fields:
                report.error(at, f"check {kind!r} has no field {field!r}")
            if field in NUMBERS and not is_number(check[field]):
                report.error(at, f"{field} must be a number")
        for field in required:
            if field not in check:
                report.error(at, f"check {kind!r} needs {field!r}")
        for field in object_fields:
            if field in check:
                if not isinstance(check[field], str):
                    report.error(at, f"{field} must be an object name")
                else:
                    names_used.append((at, check[field]))
        if kind == "direction" and check.get("axis") not in AXES:
            report.error(at, f"axis {check.get('axis')!r}")
        if kind == "direction" and not (is_number(check.get("min", 0.05)) and check.get("min", 0.05) > 0):
            report.error(at, "min must be a positive number")
        if kind == "side" and check.get("side") not in SIDES:
            report.error(at, f"side {check.get('side')!r}")
        if kind == "rotated" and check.get("axis", "y") not in AXES:
            report.error(at, f"axis {check.get('axis')!r}")
        if kind == "scaled" and not (is_number(check.get("factor")) and check.get("factor") > 0):
            report.error(at, "factor must be a positive number")
        if kind in ("moved", "at"):
            triple = check.get("delta" if kind == "moved" else "position")
            if triple is not None and not (isinstance(triple, list) and len(triple) == 3 and
                                           all(v is None or is_number(v) for v in triple)):
                report.error(at, "needs [x, y, z] with numbers or null")
            elif kind == "at" and triple is not None:
                positions.append((at, triple))
        if kind == "unchanged":
            objects = check.get("objects", "others")
            if objects == "others":
                others = True
            elif isinstance(objects, list) and objects and all(isinstance(n, str) for n in objects):
                names_used.extend((at, n) for n in objects)
            else:
                report.error(at, 'objects must be "others" or a non-empty list of names')
        if kind == "refused":
            mentions = check.get("mentions", [])
            if not isinstance(mentions, list) or not all(isinstance(n, str) for n in mentions):
                report.error(at, "mentions must be a list of names")
            else:
                names_used.extend((at, n) for n in mentions)
                if len(mentions) == 1:
                    report.error(at, "an ambiguous phrase has several candidates; an unclear part none")
    refused = "refused" in kinds
    if refused:
        if len(kinds) != 1:
            report.error(where, "a refusal has no other check (nothing may change)")
        if construct != "refuse":
            report.error(where, "a refusal's id starts with refuse-")
        if category != "hard":
            report.error(where, "refusals are in the hard category")
    else:
        if construct == "refuse":
            report.error(where, "a refuse- query needs a refused check")
        if not others:
            report.error(where, 'a successful edit says what must not move: add unchanged "others"')
        if not any(k in EFFECTS for k in kinds):
            report.error(where, "no check on what the edit must change")
    for s in listed:
        if s in scenes:
            objects, bounds = scenes[s]
            for at, n in names_used:
                if n not in objects:
                    near = [o for o in objects if o.lower() == n.lower()]
                    hint = f" (the scene spells it {near[0]!r})" if near else ""
                    report.error(at, f"no object {n!r} in scene {s!r}{hint}")
            if bounds:
                for at, p in positions:
                    for axis in range(3):
                        v = p[axis]
                        if v is not None and not (bounds["min"][axis] - 1e-9 <= v <= bounds["max"][axis] + 1e-9):
                            report.error(at, f"position {p} is outside the room {bounds}")
    return construct, refused


def main(argv):
    suites = argv or DEFAULT_SUITES
    report = Report()
    seen_ids = {}
    grand = collections.Counter()
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
        if not isinstance(suite.get("seed"), int):
            report.error(where, "the seed is an integer")
        scenes = {}
        for k, entry in enumerate(suite.get("scenes", [])):
            loaded = load_scene(entry, os.path.dirname(os.path.abspath(path)), report, f"{where} scenes[{k}]")
            if loaded:
                name, objects, bounds = loaded
                if name in scenes:
                    report.error(f"{where} scenes[{k}]", f"scene {name!r} listed twice")
                scenes[name] = (objects, bounds)
        if not scenes:
            report.error(where, "no scene could be read")
        per_category = collections.Counter()
        per_construct = collections.Counter()
        table = collections.Counter()
        per_scene = collections.Counter()
        refusals = 0
        queries = suite.get("queries", [])
        if not isinstance(queries, list):
            report.error(where, "queries must be a list")
            queries = []
        for i, query in enumerate(queries):
            if not isinstance(query, dict):
                report.error(f"{where} queries[{i}]", "a query is an object")
                continue
            result = check_query(query, scenes, report, f"{where} queries[{i}]", seen_ids)
            if result is None:
                continue
            construct, refused = result
            n = len(query.get("scenes") or [])
            per_category[query.get("category")] += n
            per_construct[construct] += n
            table[(construct, query.get("category"))] += n
            refusals += n if refused else 0
            for s in query.get("scenes") or []:
                per_scene[s] += 1
        instances = sum(per_category.values())
        grand["queries"] += len(queries)
        grand["instances"] += instances
        print(f"{where}: {len(queries)} queries, {instances} instances over {len(scenes)} scenes")
        print("  per category (instances):")
        for c in CATEGORIES:
            print(f"    {c:<20} {per_category[c]:>4}")
        print("  per construct (instances):")
        for c in CONSTRUCTS:
            print(f"    {c:<20} {per_construct[c]:>4}")
        print(f"  refusals: {refusals} of {instances} instances ({100 * refusals / max(instances, 1):.1f} %)")
        print("  construct x category:")
        print("    " + " " * 8 + "".join(f"{c[:12]:>13}" for c in CATEGORIES))
        for con in CONSTRUCTS:
            print(f"    {con:<8}" + "".join(f"{table[(con, c)]:>13}" for c in CATEGORIES))
        print("  instances per scene: " + ", ".join(f"{s} {per_scene[s]}" for s in scenes))
    print(f"total: {grand['queries']} queries, {grand['instances']} instances")
    if report.errors:
        print(f"\n{len(report.errors)} problem(s):", file=sys.stderr)
        for e in report.errors:
            print("  " + e, file=sys.stderr)
        return 1
    print("ok")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
