#!/usr/bin/env python3
"""Validates the natural-language grounding suites (stdlib only).

    python3 bench/validate_natural.py [--houses DIR] [SUITE ...]

Checks bench/natural.suite.json and bench/natural-procthor.suite.json (or the suites
given) against their scenes: the built-in examples (examples/*.json, by the paths the
suite lists) and ProcTHOR houses converted to Shenlong scene JSON as DIR/house-N.json
(default /tmp/houses, or $SHENLONG_HOUSES; make them with
`shenlong convert ../shared/data/procthor/houses.jsonl DIR/house-N.json --from procthor
--assets ../shared/data/procthor/asset-database.json --house N`).

What it checks:
- the suite's fields, and that every scene entry resolves to a scene with a name;
- every query has exactly id, category, text, scenes, expect; ids are unique (across all
  suites given); the category is one of SPEC section 6; the id starts with a known
  construct (name, syn, cat, typo, pick, group, pron, refuse);
- `scenes` is a non-empty list of names of the suite's scenes, without repeats;
- the text has no {placeholders}, no quoted names and no vague amounts;
- every check is known, with known fields and the required ones, and every object it
  names exists (exactly, as the scene spells it) in every scene the query runs on;
- a refusal (`refused`) is the query's only check and its id starts with `refuse-`; a
  successful edit has `unchanged: "others"` and at least one check on what must change.

Prints the counts per category and per construct (the id's first word), and exits
non-zero when anything is wrong.
"""

import collections
import json
import os
import re
import sys

from suite_schema import CATEGORIES, CHECKS, EFFECTS, AXES, SIDES, QUOTED, Report

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DEFAULT_SUITES = [os.path.join(HERE, "natural.suite.json"),
                  os.path.join(HERE, "natural-procthor.suite.json")]

CONSTRUCTS = ["name", "syn", "cat", "typo", "pick", "group", "pron", "refuse"]

VAGUE = re.compile(r"\b(a bit|a little|slightly|a few|somewhat|a touch|a tad|some)\b", re.I)


def houses_dir(argv):
    if "--houses" in argv:
        i = argv.index("--houses")
        path = argv[i + 1]
        del argv[i:i + 2]
        return path
    return os.environ.get("SHENLONG_HOUSES", "/tmp/houses")


def load_scene(entry, suite_dir, houses, report, where):
    """The scene a suite entry names: (name, set of object names), or None."""
    if isinstance(entry, str):
        path = os.path.normpath(os.path.join(suite_dir, entry))
    elif isinstance(entry, dict):
        extra = set(entry) - {"procthor", "house", "assets"}
        if extra or "procthor" not in entry or not isinstance(entry.get("house"), int):
            report.error(where, f"a house entry is {{procthor, house: N, assets}}: got {entry}")
            return None
        for key in ("procthor", "assets"):
            if key in entry and not os.path.exists(os.path.join(suite_dir, entry[key])):
                report.error(where, f"{key} file {entry[key]} not found from {suite_dir}")
        path = os.path.join(houses, f"house-{entry['house']}.json")
    else:
        report.error(where, f"a scene is a path or a house entry: got {entry!r}")
        return None
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
    if isinstance(entry, dict) and name != f"houses {entry['house']}":
        report.error(where, f"{path} is named {name!r}, not 'houses {entry['house']}'")
    names = [o.get("name") for o in scene.get("objects", [])]
    lowered = [n.lower() for n in names if isinstance(n, str)]
    if len(set(lowered)) != len(lowered):
        report.error(where, f"scene {name} has object names used twice")
    return name, set(names)


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
    if VAGUE.search(text):
        report.error(where, f"vague amount in {text!r}: give a number")
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
    names_used = []
    kinds = []
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
        if kind == "direction" and not (isinstance(check.get("min", 0.05), (int, float)) and check.get("min", 0.05) > 0):
            report.error(at, "min must be a positive number")
        if kind == "side" and check.get("side") not in SIDES:
            report.error(at, f"side {check.get('side')!r}")
        if kind == "rotated" and check.get("axis", "y") not in AXES:
            report.error(at, f"axis {check.get('axis')!r}")
        if kind in ("moved", "at"):
            triple = check.get("delta" if kind == "moved" else "position")
            if triple is not None and not (isinstance(triple, list) and len(triple) == 3 and
                                           all(v is None or isinstance(v, (int, float)) for v in triple)):
                report.error(at, "needs [x, y, z] with numbers or null")
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
                    report.error(at, "an ambiguous phrase has several candidates; an unknown one none")
    refused = "refused" in kinds
    if refused:
        if len(kinds) != 1:
            report.error(where, "a refusal has no other check (nothing may change)")
        if construct != "refuse":
            report.error(where, "a refusal's id starts with refuse-")
    else:
        if construct == "refuse":
            report.error(where, "a refuse- query needs a refused check")
        if not others:
            report.error(where, 'a successful edit says what must not move: add unchanged "others"')
        if not any(k in EFFECTS for k in kinds):
            report.error(where, "no check on what the edit must change")
    for s in listed:
        if s in scenes:
            objects = scenes[s]
            for at, n in names_used:
                if n not in objects:
                    near = [o for o in objects if o.lower() == n.lower()]
                    hint = f" (the scene spells it {near[0]!r})" if near else ""
                    report.error(at, f"no object {n!r} in scene {s!r}{hint}")
    return construct


def main(argv):
    houses = houses_dir(argv)
    suites = argv or DEFAULT_SUITES
    report = Report()
    seen_ids = {}
    grand = collections.Counter()
    for path in suites:
        where = os.path.relpath(path, ROOT) if path.startswith(ROOT) else path
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
        scenes = {}
        for k, entry in enumerate(suite.get("scenes", [])):
            loaded = load_scene(entry, os.path.dirname(path), houses, report, f"{where} scenes[{k}]")
            if loaded:
                name, objects = loaded
                if name in scenes:
                    report.error(f"{where} scenes[{k}]", f"scene {name!r} listed twice")
                scenes[name] = objects
        if not scenes:
            report.error(where, "no scene could be read")
        per_category = collections.Counter()
        per_category_instances = collections.Counter()
        per_construct = collections.Counter()
        per_construct_instances = collections.Counter()
        table = collections.Counter()
        per_scene = collections.Counter()
        destinations = 0
        queries = suite.get("queries", [])
        for i, query in enumerate(queries):
            if not isinstance(query, dict):
                report.error(f"{where} queries[{i}]", "a query is an object")
                continue
            construct = check_query(query, scenes, report, f"{where} queries[{i}]", seen_ids)
            n = len(query.get("scenes") or [])
            per_category[query.get("category")] += 1
            per_category_instances[query.get("category")] += n
            per_construct[construct] += 1
            per_construct_instances[construct] += n
            table[(construct, query.get("category"))] += 1
            for s in query.get("scenes") or []:
                per_scene[s] += 1
            if "-dest-" in str(query.get("id")):
                destinations += 1
        instances = sum(per_category_instances.values())
        grand["queries"] += len(queries)
        grand["instances"] += instances
        print(f"{where}: {len(queries)} queries, {instances} instances over {len(scenes)} scenes")
        print("  per category (queries / instances):")
        for c in CATEGORIES:
            print(f"    {c:<20} {per_category[c]:>4} / {per_category_instances[c]:>4}")
        print("  per construct (queries / instances):")
        for c in CONSTRUCTS:
            print(f"    {c:<20} {per_construct[c]:>4} / {per_construct_instances[c]:>4}")
        refusals = per_construct_instances["refuse"]
        print(f"  refusals: {refusals} of {instances} instances ({100 * refusals / max(instances, 1):.1f} %);"
              f" destination (-dest-) queries: {destinations}")
        print("  construct x category (queries):")
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
