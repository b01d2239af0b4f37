"""What the natural-suite validators share: the suite's check schema and a problem report.

Used by validate_natural.py, validate_phrasing.py and validate_placement.py (run them from
the repository root: `python3 bench/validate_natural.py`); the schema follows
docs/benchmark.md and crates/shenlong/src/bench/suite.rs.
"""

import re

CATEGORIES = ["simple", "compositional", "fuzzy", "compositional_fuzzy", "hard"]

SHORT = {"living_room": "lr", "bedroom": "br", "kitchen": "kt", "wine_cellar": "wc",
         "operating_room": "or", "workshop": "ws", "office": "of", "classroom": "cl",
         "dining_room": "dr", "bathroom": "ba"}

# check -> (fields that name objects, other fields, required fields)
CHECKS = {
    "moved": (["object"], ["delta", "tol"], ["object"]),
    "direction": (["object"], ["axis", "min"], ["object", "axis"]),
    "rotated": (["object"], ["axis", "degrees", "either_sign", "tol"], ["object"]),
    "scaled": (["object"], ["factor", "tol"], ["object", "factor"]),
    "on_top": (["object", "support"], ["tol"], ["object", "support"]),
    "next_to": (["object", "other"], ["max_gap"], ["object", "other"]),
    "side": (["object", "other"], ["side", "max_gap"], ["object", "other", "side"]),
    "above": (["object", "other"], ["tol"], ["object", "other"]),
    "below": (["object", "other"], ["tol"], ["object", "other"]),
    "between": (["object", "a", "b"], ["tol"], ["object", "a", "b"]),
    "aligned": (["object", "other"], ["axis", "tol"], ["object", "other", "axis"]),
    "at": (["object"], ["position", "tol"], ["object", "position"]),
    "faces": (["object", "target"], ["tol"], ["object", "target"]),
    "distance": (["object", "other"], ["min", "max"], ["object", "other"]),
    "unchanged": ([], ["objects"], []),
    "no_collision": ([], [], []),
    "inside_bounds": ([], [], []),
    "swapped": (["object", "other"], ["tol"], ["object", "other"]),
    "refused": ([], ["mentions"], []),
}

# Checks that say something about what the edit changed (as opposed to what it kept).
EFFECTS = {"moved", "direction", "rotated", "scaled", "on_top", "next_to", "side", "above",
           "below", "between", "aligned", "at", "faces", "distance", "swapped"}

NUMBERS = {"tol", "min", "max", "max_gap", "degrees", "factor"}

AXES = {"+x", "-x", "+y", "-y", "+z", "-z", "x", "y", "z"}

SIDES = {"left", "right", "front", "behind", "back"}

QUOTED = re.compile(r"(^|[\s(])(['\"])[^'\"]+\2(?=$|[\s,.;:!?)])")

class Report:
    def __init__(self):
        self.errors = []

    def error(self, where, message):
        self.errors.append(f"{where}: {message}")

def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)
