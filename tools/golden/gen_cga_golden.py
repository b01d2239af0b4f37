#!/usr/bin/env python3
"""Writes crates/cga/tests/data/golden.json from the Python `clifford` library (g3c).

An independent implementation of the same algebra: the Rust kernel is tested against it.
Run by hand (not in CI) after `pip install clifford==1.5.1 scipy`:

    python3 tools/golden/gen_cga_golden.py

The output is deterministic for a given seed and library version.
"""
import json
import os
import sys

import numpy as np
from clifford.g3c import layout, blades, up, down, einf
from clifford.tools.g3c import (
    generate_dilation_rotor,
    generate_rotation_rotor,
    generate_translation_rotor,
)
from scipy.spatial.transform import Rotation

SEED = 20261122
rng = np.random.default_rng(SEED)
e1, e2, e3 = blades["e1"], blades["e2"], blades["e3"]


def coeffs(mv):
    return [float(x) for x in mv.value]


def random_mv(scale=2.0):
    return layout.MultiVector(rng.uniform(-scale, scale, 32))


def euclid(v):
    return v[0] * e1 + v[1] * e2 + v[2] * e3


def products(n):
    out = []
    for _ in range(n):
        a, b = random_mv(), random_mv()
        case = {
            "a": coeffs(a),
            "b": coeffs(b),
            "geometric": coeffs(a * b),
            "outer": coeffs(a ^ b),
            "inner": coeffs(a | b),
            "left_contraction": coeffs(a << b),
            "reverse": coeffs(~a),
            "grade_involution": coeffs(a.gradeInvol()),
            "conjugate": coeffs(a.conjugate()),
            "dual": coeffs(a.dual()),
            "norm_squared": float(a.mag2()),
        }
        inv = a.inv()
        case["inverse"] = coeffs(inv)
        out.append(case)
    return out


def points(n):
    out = []
    for _ in range(n):
        x = rng.uniform(-5, 5, 3)
        out.append({"x": list(map(float, x)), "up": coeffs(up(euclid(x)))})
    return out


def versors(n):
    out = []
    for _ in range(n):
        t = rng.uniform(-5, 5, 3)
        out.append({"kind": "T", "t": list(map(float, t)), "versor": coeffs(generate_translation_rotor(euclid(t)))})
        s = float(rng.uniform(0.1, 5))
        out.append({"kind": "D", "s": s, "versor": coeffs(generate_dilation_rotor(s))})
        angle = float(rng.uniform(-np.pi, np.pi))
        u, v = rng.uniform(-1, 1, 3), rng.uniform(-1, 1, 3)
        # clifford's generate_rotation_rotor wants unit vectors spanning the plane.
        um = euclid(u) / abs(euclid(u))
        vm = euclid(v) / abs(euclid(v))
        out.append({
            "kind": "R", "angle": angle, "u": list(map(float, u)), "v": list(map(float, v)),
            # Rotor by the exponential of the unit plane: exp(-θ/2 B).
            "versor": coeffs((-(angle / 2) * ((um ^ vm) / abs(um ^ vm))).exp()),
        })
    return out


def decompositions(n):
    out = []
    for _ in range(n):
        t = rng.uniform(-5, 5, 3)
        s = float(rng.uniform(0.1, 5))
        rot = Rotation.random(random_state=int(rng.integers(1 << 31)))
        rotvec = rot.as_rotvec()
        angle = float(np.linalg.norm(rotvec))
        axis = rotvec / angle
        # Two unit vectors m ⟂ n spanning the plane normal to the axis, m × n = axis.
        m = np.cross(axis, [1.0, 0.0, 0.0])
        if np.linalg.norm(m) < 0.1:
            m = np.cross(axis, [0.0, 1.0, 0.0])
        m = m / np.linalg.norm(m)
        nvec = np.cross(axis, m)
        R = generate_rotation_rotor(angle, euclid(m), euclid(nvec))
        M = generate_translation_rotor(euclid(t)) * R * generate_dilation_rotor(s)
        x = rng.uniform(-3, 3, 3)
        image = down(M * up(euclid(x)) * ~M)
        out.append({
            "translation": list(map(float, t)),
            "rotation": list(map(float, rot.as_quat())),  # [x, y, z, w]
            "scale": s,
            "versor": coeffs(M),
            "point": list(map(float, x)),
            "image": [float(image[e]) for e in (e1, e2, e3)],
        })
    return out


def main():
    data = {
        "source": "python clifford %s (g3c), numpy %s, seed %d" % (
            __import__("clifford").__version__, np.__version__, SEED),
        "blades": [str(b) for b in layout.blades_list],
        "products": products(40),
        "points": points(20),
        "versors": versors(15),
        "decompositions": decompositions(30),
    }
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
    path = os.path.join(root, "crates", "cga", "tests", "data", "golden.json")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)
    print("wrote", os.path.normpath(path), file=sys.stderr)


if __name__ == "__main__":
    main()
