import math
from scenes import SCENES

def qrot(q, v):
    x, y, z, w = q
    vx, vy, vz = v
    # v' = q v q*
    tx = 2*(y*vz - z*vy); ty = 2*(z*vx - x*vz); tz = 2*(x*vy - y*vx)
    return [vx + w*tx + (y*tz - z*ty), vy + w*ty + (z*tx - x*tz), vz + w*tz + (x*ty - y*tx)]

def aabb(ob):
    w, h, d = ob["size"]; s = ob.get("scale", 1.0); q = ob.get("rotation", [0,0,0,1]); p = ob["position"]
    pts = []
    for cx in (-w/2, w/2):
        for cy in (0, h):
            for cz in (-d/2, d/2):
                r = qrot(q, [cx*s, cy*s, cz*s])
                pts.append([p[i] + r[i] for i in range(3)])
    mn = [min(pt[i] for pt in pts) for i in range(3)]
    mx = [max(pt[i] for pt in pts) for i in range(3)]
    return mn, mx

def overlap(a, b, eps=1e-4):
    return all(a[0][i] < b[1][i] - eps and b[0][i] < a[1][i] - eps for i in range(3))

def rests_on(a, b):
    A, B = aabb(a), aabb(b)
    if abs(A[0][1] - B[1][1]) > 0.01: return False
    cx = (A[0][0]+A[1][0])/2; cz = (A[0][2]+A[1][2])/2
    return B[0][0] <= cx <= B[1][0] and B[0][2] <= cz <= B[1][2]

def objs(scene): return {o["name"]: o for o in SCENES[scene]["objects"]}

def carried(scene, name):
    ob = objs(scene); out = []
    stack = [name]
    while stack:
        n = stack.pop()
        for m, o in ob.items():
            if m not in out and m != name and rests_on(o, ob[n]):
                out.append(m); stack.append(m)
    return out

def centre(o):
    a = aabb(o); return [(a[0][i]+a[1][i])/2 for i in range(3)]

if __name__ == "__main__":
    for f, s in SCENES.items():
        ob = s["objects"]; b = s["bounds"]
        for i, x in enumerate(ob):
            A = aabb(x)
            for k in range(3):
                if A[0][k] < b["min"][k] - 1e-6 or A[1][k] > b["max"][k] + 1e-6: print(f, "OUT", x["name"], A)
            for y in ob[i+1:]:
                if overlap(A, aabb(y)): print(f, "OVERLAP", x["name"], y["name"])
        for x in ob:
            sup = [y["name"] for y in ob if y is not x and rests_on(x, y)]
            if sup: print(f, x["name"], "on", sup)
