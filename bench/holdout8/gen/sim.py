import copy, dsl, q_lobby, q_kitchen, q_reading, q_play
from scenes import SCENES
from geom import aabb, overlap, carried, centre
import math
def ob_of(sc): return {o["name"].lower(): o for o in SCENES[sc]["objects"]}
names_ok = True
for q in dsl.QUERIES:
    sc = q["scenes"][0]; obs = ob_of(sc)
    # name validity
    for c in q["expect"]:
        for k in ("object", "other", "support", "target", "a", "b"):
            if k in c and c[k].lower() not in obs: print("BADNAME", q["id"], c[k]); names_ok = False
        if c["check"] == "unchanged" and isinstance(c["objects"], list):
            for n in c["objects"]:
                if n.lower() not in obs: print("BADNAME", q["id"], n)
        if c["check"] == "refused":
            for n in c["mentions"]:
                if n.lower() not in obs: print("BADNAME", q["id"], n)
    # simulate pure-move queries
    moves = {c["object"]: c["delta"] for c in q["expect"] if c["check"] == "moved" and c["delta"] is not None}
    swaps = [(c["object"], c["other"]) for c in q["expect"] if c["check"] == "swapped"]
    if not moves and not swaps: continue
    new = copy.deepcopy({o["name"]: o for o in SCENES[sc]["objects"]})
    moved = set()
    for n, d in moves.items():
        grp = [n] + [m for m in carried(sc, n) if m not in moves]
        for g in grp:
            new[g]["position"] = [new[g]["position"][i] + d[i] for i in range(3)]; moved.add(g)
    for a, b in swaps:
        pa, pb = list(new[a]["position"]), list(new[b]["position"])
        for g, d in ((a, [pb[i]-pa[i] for i in range(3)]), (b, [pa[i]-pb[i] for i in range(3)])):
            for m in [g] + carried(sc, g):
                new[m]["position"] = [new[m]["position"][i] + d[i] for i in range(3)]; moved.add(m)
    bnd = SCENES[sc]["bounds"]
    for m in moved:
        A = aabb(new[m])
        for k in range(3):
            if A[0][k] < bnd["min"][k] - 1e-6 or A[1][k] > bnd["max"][k] + 1e-6: print("BOUNDS", q["id"], m)
        for n2, o2 in new.items():
            if n2 == m: continue
            if n2 in moved and n2 < m: continue
            B = aabb(o2)
            if overlap(A, B):
                before = overlap(aabb({**o2, **{}}) if False else aabb(ob_of(sc)[m.lower()]), aabb(ob_of(sc)[n2.lower()]))
                print("COLLIDE", q["id"], m, n2, q["text"])
print("done")
