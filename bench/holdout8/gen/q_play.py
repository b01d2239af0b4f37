from dsl import *
P = "playroom_blender.json"
SPH = ["Sphere", "Sphere.001", "Sphere.002", "Sphere.003"]

# ---------------- simple
Q(P, "simple", "move Cube.003 30cm left", mv("Cube.003", [-0.3, 0, 0]), un())
Q(P, "simple", "rotate Cube.007 90 degrees", rot("Cube.007", 90, True), un())
Q(P, "simple", "Sphere.003 -> 50 cm back", mv("Sphere.003", [0, 0, -0.5]), un())
Q(P, "simple", "make Suzanne twice as big", sc("Suzanne", 2.0), un())
Q(P, "simple", "move Icosphere 40 cm forward", mv("Icosphere", [0, 0, 0.4]), un())
Q(P, "simple", "scale Cylinder.002 down to 80%", sc("Cylinder.002", 0.8), un())
Q(P, "simple", "move cube.010 a foot to the left", mv("Cube.010", [-FT, 0, 0], 0.03), un())
Q(P, "simple", "turn Cube.008 around", rot("Cube.008", 180, True), un())
Q(P, "simple", "Cylinder.003 20cm right", mv("Cylinder.003", [0.2, 0, 0]), un())
Q(P, "simple", "move Torus 10 cm back", mv("Torus", [0, 0, -0.1]), un())
Q(P, "simple", "rotate Sphere.002 by 30 degrees clockwise", rot("Sphere.002", -30), un())
Q(P, "simple", "Cube.005: 20 cm to the left", mv("Cube.005", [-0.2, 0, 0]), un())
Q(P, "simple", "shift Cylinder.002 six inches to the rigth", mv("Cylinder.002", [6 * IN, 0, 0], 0.03), un())
Q(P, "simple", "move the ball to the left", ref(SPH))
Q(P, "simple", "turn the rocking horse around", ref([]))

# ---------------- compositional
Q(P, "compositional", "put Sphere.001 on Cube.008", on("Sphere.001", "Cube.008"), nc(), un())
Q(P, "compositional", "put Cone on Cube.003", on("Cone", "Cube.003"), nc(), un())
Q(P, "compositional", "swap Cube.001 and Cylinder", sw("Cube.001", "Cylinder"), un())
Q(P, "compositional", "move Cube.003 together with everything on it 40cm to the left",
  mv("Cube.003", [-0.4, 0, 0]), mv("Cylinder.001", [-0.4, 0, 0]), mv("Cube.004", [-0.4, 0, 0]),
  mv("Sphere.001", [-0.4, 0, 0]), un())
Q(P, "compositional", "put Cube.002 on top of Cube.001", on("Cube.002", "Cube.001"), un())
Q(P, "compositional", "move Sphere.003 next to Sphere.002", nt("Sphere.003", "Sphere.002", 0.3), nc(), un())
Q(P, "compositional", "put Suzanne on Cube", on("Suzanne", "Cube"), nc(), un())
Q(P, "compositional", "move Cube.010 between Sphere.002 and Sphere.003",
  betw("Cube.010", "Sphere.002", "Sphere.003"), nc(), un())
Q(P, "compositional", "rotate Cube.005 180 degrees and move it 10cm back",
  rot("Cube.005", 180, True), mv("Cube.005", [0, 0, -0.1]), un())
Q(P, "compositional", "put Cylinder.001 on Cube, next to Cylinder",
  on("Cylinder.001", "Cube"), nt("Cylinder.001", "Cylinder", 0.2), nc(), un())
Q(P, "compositional", "move Cylinder.002 next to Cube.012", nt("Cylinder.002", "Cube.012", 0.3), nc(), un())
Q(P, "compositional", "put Sphere on Cube.003 and Torus on Cube",
  on("Sphere", "Cube.003"), on("Torus", "Cube"), nc(), un())
Q(P, "compositional", "move Icosphere into the front left corner",
  at("Icosphere", [-2.6, 0, 2.1], 0.35), nc(), ib(), un())
Q(P, "compositional", "rotate Cube.006 by 90 degrees and push it 20 cm to the right",
  rot("Cube.006", 90, True), mv("Cube.006", [0.2, 0, 0]), un())
Q(P, "compositional", "Sphere, Sphere.001 and Sphere.003: 10 cm left each",
  mv("Sphere", [-0.1, 0, 0]), mv("Sphere.001", [-0.1, 0, 0]), mv("Sphere.003", [-0.1, 0, 0]), un())
Q(P, "compositional", "put the small block on the little table", ref(["Cube.001", "Cube.002"]))
Q(P, "compositional", "move the teddy bear onto the shelf", ref([]))

# ---------------- fuzzy
Q(P, "fuzzy", "move the big ball a bit to the left",
  dr("Sphere.002", "-x", 0.03), mv("Sphere.002", [-0.25, 0, 0], 0.25), un())
Q(P, "fuzzy", "nudge the tall cylinder by the door a little to the right",
  dr("Cylinder.002", "+x", 0.02), mv("Cylinder.002", [0.15, 0, 0], 0.15), un())
Q(P, "fuzzy", "make the monkey head a bit bigger", sc("Suzanne", 1.25, 0.2), un())
Q(P, "fuzzy", "push the little table a tad to the left",
  dr("Cube.003", "-x", 0.01), mv("Cube.003", [-0.1, 0, 0], 0.1), un())
Q(P, "fuzzy", "move the big round squashy thing by the left wall forward a bit",
  dr("Icosphere", "+z", 0.03), mv("Icosphere", [0, 0, 0.25], 0.25), un())
Q(P, "fuzzy", "slide the flat box on the table a little back",
  dr("Cube.004", "-z", 0.02), mv("Cube.004", [0, 0, -0.08], 0.08), on("Cube.004", "Cube.003"), un())
Q(P, "fuzzy", "make the ring thing smaller", sc("Torus", 0.7, 0.28), un())
Q(P, "fuzzy", "move the fat cylinder next to the low shelf way over to the right",
  dr("Cylinder.003", "+x", 0.8), nc(), un())
Q(P, "fuzzy", "shift Sphere.003 slightly forward",
  dr("Sphere.003", "+z", 0.02), mv("Sphere.003", [0, 0, 0.15], 0.15), un())
Q(P, "fuzzy", "move the cone a bit closer to the ring", dist("Cone", "Torus", mx=0.37), on("Cone", "Cube.008"), nc(), un())
Q(P, "fuzzy", "make the big ball a little smaller", sc("Sphere.002", 0.85, 0.13), un())
Q(P, "fuzzy", "move Cube.011 a bit to the right", ref([]))

# ---------------- compositional_fuzzy
Q(P, "compositional_fuzzy", "move the big ball a bit closer to the Icosphere and make it slightly smaller",
  dist("Sphere.002", "Icosphere", mx=1.6), sc("Sphere.002", 0.88, 0.1), nc(), un())
Q(P, "compositional_fuzzy", "slide the little table a bit right with all its stuff",
  *[dr(n, "+x", 0.03) for n in ("Cube.003", "Cylinder.001", "Cube.004", "Sphere.001")], nc(), un())
Q(P, "compositional_fuzzy", "nudge Cube.005 and Cube.006 a little further from the table",
  dist("Cube.005", "Cube.003", mn=0.7), dist("Cube.006", "Cube.003", mn=0.7), nc(), un())
Q(P, "compositional_fuzzy", "put the tiny ball from the table somewhere on the low shelf",
  on("Sphere.001", "Cube"), nc(), un())
Q(P, "compositional_fuzzy", "move the tall cylinder a little away from the door and give it a quarter turn",
  dist("Cylinder.002", "Cube.009", mn=0.85), rot("Cylinder.002", 90, True), nc(), un())
Q(P, "compositional_fuzzy", "push the low box against the right wall a bit back, with the cone and the ring on it",
  dr("Cube.008", "-z", 0.03), dr("Cone", "-z", 0.03), dr("Torus", "-z", 0.03), un())
Q(P, "compositional_fuzzy", "scoot the tall narrow box on the left wall forward a little, the monkey on top too",
  dr("Cube.012", "+z", 0.03), dr("Suzanne", "+z", 0.03), on("Suzanne", "Cube.012"), un())
Q(P, "compositional_fuzzy", "make Cone a bit bigger and move it a touch left",
  sc("Cone", 1.2, 0.17), dr("Cone", "-x", 0.01), un())
Q(P, "compositional_fuzzy", "move the small block a bit to the left and turn it", ref(["Cube.001", "Cube.002"]))

# ---------------- hard
Q(P, "hard", "put the two little blocks on the table",
  on("Cube.001", "Cube.003"), on("Cube.002", "Cube.003"), nc(), un())
Q(P, "hard", "move the table and the three seats around it 50 cm back",
  *[mv(n, [0, 0, -0.5]) for n in ("Cube.003", "Cube.005", "Cube.006", "Cube.007")], un())
Q(P, "hard", "turn all three seats at the little table to face the door (Cube.009)",
  *[faces(n, "Cube.009") for n in ("Cube.005", "Cube.006", "Cube.007")], nc(), un())
Q(P, "hard", "take the cylinder off the shelf and put it on the floor next to the other cylinder by the shelf",
  nt("Cylinder", "Cylinder.003", 0.3), nc(), un())
Q(P, "hard", "swap the monkey head and the cone", sw("Suzanne", "Cone"), un())
Q(P, "hard", "turn the seat at the right end of the table around", rot("Cube.007", 180, True), un())
Q(P, "hard", "move the seat that's in front of the table 20 cm further forward", mv("Cube.006", [0, 0, 0.2]), un())
Q(P, "hard", "put the little ball on the table between Cylinder.001 and Cube.004",
  betw("Sphere.001", "Cylinder.001", "Cube.004", 0.2), on("Sphere.001", "Cube.003"), nc(), un())
Q(P, "hard", "the tall box against the left wall with the monkey on it: 50cm back, monkey and all",
  mv("Cube.012", [0, 0, -0.5]), mv("Suzanne", [0, 0, -0.5]), un())
Q(P, "hard", "swap the two seats facing each other across the table", sw("Cube.005", "Cube.006"), un())
Q(P, "hard", "the biggest ball: move it 30 cm right", mv("Sphere.002", [0.3, 0, 0]), un())
Q(P, "hard", "every seat round the little table except Cube.007, 15cm left",
  mv("Cube.005", [-0.15, 0, 0]), mv("Cube.006", [-0.15, 0, 0]), un(["Cube.007"]), un())
Q(P, "hard", "put Sphere.004 on Cube.008", ref([]))
