from dsl import *
R = "reading_room.json"
T = [f"reading table {i}" for i in range(1, 7)]
C = [f"chair {i}" for i in range(1, 13)]
LMP = [f"table lamp {i}" for i in (1, 2, 3, 4, 6)]

# ---------------- simple
Q(R, "simple", "move reading table 4 half a metre right", mv("reading table 4", [0.5, 0, 0]), un())
Q(R, "simple", "chair 12: 30cm right", mv("chair 12", [0.3, 0, 0]), un())
Q(R, "simple", "rotate chair 5 90 degrees", rot("chair 5", 90, True), un())
Q(R, "simple", "move the globe 1 m forward", mv("globe", [0, 0, 1]), un())
Q(R, "simple", "table lamp 6 - 20 cm to the left", mv("table lamp 6", [-0.2, 0, 0]), un())
Q(R, "simple", "scale the globe by 1.5", sc("globe", 1.5), un())
Q(R, "simple", "Move the card catalog 2m left", mv("card catalog", [-2, 0, 0]), un())
Q(R, "simple", "turn chair 1 around", rot("chair 1", 180, True), un())
Q(R, "simple", "shift bookcase B 15 cm back", mv("bookcase B", [0, 0, -0.15]), un())
Q(R, "simple", "move the atlas 10cm to the right", mv("atlas", [0.1, 0, 0]), un())
Q(R, "simple", "make table lamp 2 25% bigger", sc("table lamp 2", 1.25), un())
Q(R, "simple", "move the reading glasses 3 inches left", mv("reading glasses", [-3 * IN, 0, 0], 0.02), un())
Q(R, "simple", "rotate the circulation desk 180 degrees", rot("circulation desk", 180, True), un())
Q(R, "simple", "can you move chair 9 a foot back?", mv("chair 9", [0, 0, -FT], 0.03), un())
Q(R, "simple", "computer terminal 15 cm left", mv("computer terminal", [-0.15, 0, 0]), un())
Q(R, "simple", "move reading table 6 40cm to the right", mv("reading table 6", [0.4, 0, 0]), un())
Q(R, "simple", "chiar 7, 20 cm to the left", mv("chair 7", [-0.2, 0, 0]), un())
Q(R, "simple", "move the reading table 1 m left", ref(T))
Q(R, "simple", "turn the chair around", ref(C))
Q(R, "simple", "move reading table 7 to the left", ref([]))

# ---------------- compositional
Q(R, "compositional", "move reading table 3 and its chairs 1 m to the left",
  mv("reading table 3", [-1, 0, 0]), mv("chair 5", [-1, 0, 0]), mv("chair 6", [-1, 0, 0]), un())
Q(R, "compositional", "put table lamp 1 on reading table 5", on("table lamp 1", "reading table 5"), un())
Q(R, "compositional", "swap chair 2 and chair 11", sw("chair 2", "chair 11"), un())
Q(R, "compositional", "put the reading glasses on the circulation desk", on("reading glasses", "circulation desk"), un())
Q(R, "compositional", "put the book stack between table lamp 3 and the atlas",
  betw("book stack", "table lamp 3", "atlas", 0.2), on("book stack", "reading table 3"), nc(), un())
Q(R, "compositional", "put chair 7 next to chair 8", nt("chair 7", "chair 8", 0.3), nc(), un())
Q(R, "compositional", "move table lamp 3 onto reading table 6 and table lamp 6 onto reading table 3",
  on("table lamp 3", "reading table 6"), on("table lamp 6", "reading table 3"), nc(), un())
Q(R, "compositional", "put the atlas on reading table 2, to the right of the lamp",
  on("atlas", "reading table 2"), side("atlas", "table lamp 2", "right", 0.5), nc(), un())
Q(R, "compositional", "move chair 1 over to reading table 6", nt("chair 1", "reading table 6", 0.3), nc(), un())
Q(R, "compositional", "move bookcase C 1 m forward and put table lamp 4 on the card catalog",
  mv("bookcase C", [0, 0, 1]), on("table lamp 4", "card catalog"), un())
Q(R, "compositional", "put the globe in the back left corner", at("globe", [-6.75, 0, -5.75], 0.35), ib(), un())
Q(R, "compositional", "move table lamp 2 to the right end of its table and turn it 90°",
  dr("table lamp 2", "+x", 0.5), on("table lamp 2", "reading table 2"), rot("table lamp 2", 90, True), un())
Q(R, "compositional", "move chairs 9 and 10 40cm to the right",
  mv("chair 9", [0.4, 0, 0]), mv("chair 10", [0.4, 0, 0]), un())
Q(R, "compositional", "put the computer terminal on reading table 1", on("computer terminal", "reading table 1"), nc(), un())
Q(R, "compositional", "swap bookcase A and bookcase C", sw("bookcase A", "bookcase C"), un())
Q(R, "compositional", "move chair 6 to the left of chair 5", side("chair 6", "chair 5", "left", 0.3), nc(), un())
Q(R, "compositional", "put the lamp on the circulation desk", ref(LMP))
Q(R, "compositional", "put the bookcase against the back wall", ref(["bookcase A", "bookcase B", "bookcase C"]))
Q(R, "compositional", "put the newspaper on reading table 2", ref([]))

# ---------------- fuzzy
Q(R, "fuzzy", "nudge chair 3 a bit closer to its table", nt("chair 3", "reading table 2", 0.06), nc(), un())
Q(R, "fuzzy", "push chair 10 in a little",
  dr("chair 10", "-z", 0.02), mv("chair 10", [0, 0, -0.05], 0.05), nc(), un())
Q(R, "fuzzy", "move the globe a bit to the right",
  dr("globe", "+x", 0.03), mv("globe", [0.25, 0, 0], 0.25), un())
Q(R, "fuzzy", "slide table lamp 4 a tad left",
  dr("table lamp 4", "-x", 0.01), mv("table lamp 4", [-0.07, 0, 0], 0.08), on("table lamp 4", "reading table 4"), un())
Q(R, "fuzzy", "make the book stack a bit smaller", sc("book stack", 0.8, 0.17), un())
Q(R, "fuzzy", "move the card catalog way over to the right", dr("card catalog", "+x", 1.0), nc(), un())
Q(R, "fuzzy", "move chair 8 a little further from the table", dist("chair 8", "reading table 4", mn=0.8), nc(), un())
Q(R, "fuzzy", "pull the circulation desk forward a touch",
  dr("circulation desk", "+z", 0.01), mv("circulation desk", [0, 0, 0.1], 0.1), un())
Q(R, "fuzzy", "move the atlas slightly back",
  dr("atlas", "-z", 0.02), mv("atlas", [0, 0, -0.15], 0.15), on("atlas", "reading table 3"), un())
Q(R, "fuzzy", "make the globe a little bigger", sc("globe", 1.2, 0.17), un())
Q(R, "fuzzy", "scoot bookcase C forward a bit",
  dr("bookcase C", "+z", 0.03), mv("bookcase C", [0, 0, 0.25], 0.25), un())
Q(R, "fuzzy", "shift reading table 1 a few inches to the left",
  dr("reading table 1", "-x", 0.03), mv("reading table 1", [-0.1, 0, 0], 0.1), un())
Q(R, "fuzzy", "move the window a bit", ref(["window 1", "window 2"]))

# ---------------- compositional_fuzzy
Q(R, "compositional_fuzzy", "move table 6 a bit to the right along with its chairs and lamp",
  dr("reading table 6", "+x", 0.03), dr("chair 11", "+x", 0.03), dr("chair 12", "+x", 0.03), dr("table lamp 6", "+x", 0.03), un())
Q(R, "compositional_fuzzy", "bring the globe closer to window 1", dist("globe", "window 1", mx=2.4), nc(), un())
Q(R, "compositional_fuzzy", "push chairs 1 and 2 a little further from table 1",
  dist("chair 1", "reading table 1", mn=0.8), dist("chair 2", "reading table 1", mn=0.8), nc(), un())
Q(R, "compositional_fuzzy", "turn chair 11 around and nudge it right a bit",
  rot("chair 11", 180, True), dr("chair 11", "+x", 0.03), un())
Q(R, "compositional_fuzzy", "move the reading glasses a little closer to table lamp 4",
  dist("reading glasses", "table lamp 4", mx=0.78), on("reading glasses", "reading table 4"), un())
Q(R, "compositional_fuzzy", "put the book stack somewhere on table 6, roughly in the middle",
  on("book stack", "reading table 6"), al("book stack", "reading table 6", "x", 0.35), nc(), un())
Q(R, "compositional_fuzzy", "move the whole front row of tables back a bit, chairs too",
  *[dr(n, "-z", 0.03) for n in ("reading table 5", "reading table 6", "chair 9", "chair 10", "chair 11", "chair 12")], nc(), un())
Q(R, "compositional_fuzzy", "make table lamp 1 a bit bigger and slide it right a little",
  sc("table lamp 1", 1.2, 0.17), dr("table lamp 1", "+x", 0.02), on("table lamp 1", "reading table 1"), un())
Q(R, "compositional_fuzzy", "move chair 4 a touch to the left, and chair 3 a touch to the right",
  dr("chair 4", "-x", 0.01), dr("chair 3", "+x", 0.01), un())
Q(R, "compositional_fuzzy", "shift the globe a little further from the wall, and make it slightly smaller",
  dr("globe", "+x", 0.03), sc("globe", 0.85, 0.13), un())
Q(R, "compositional_fuzzy", "move the sofa a bit closer to the window", ref([]))

# ---------------- hard
Q(R, "hard", "move the table without a lamp 50cm to the right",
  mv("reading table 5", [0.5, 0, 0]), mv("book stack", [0.5, 0, 0]), un())
Q(R, "hard", "all chairs except chair 6 – 10 cm left",
  *[mv(c, [-0.1, 0, 0]) for c in C if c != "chair 6"], un(["chair 6"]), un())
Q(R, "hard", "move the back row of tables and their chairs 30 cm forward",
  *[mv(n, [0, 0, 0.3]) for n in ("reading table 1", "reading table 2", "chair 1", "chair 2", "chair 3", "chair 4")], un())
Q(R, "hard", "turn chair 9 so it faces the windows", faces("chair 9", "window 2", 25), un())
Q(R, "hard", "the second table from the window in the front row: move it 40cm right",
  mv("reading table 6", [0.4, 0, 0]), un())
Q(R, "hard", "put table lamp 2 on the table that doesn't have a lamp", on("table lamp 2", "reading table 5"), nc(), un())
Q(R, "hard", "swap the atlas and the book stack", sw("atlas", "book stack"), un())
Q(R, "hard", "move table 2 with everything on it and its chairs 1 m to the right",
  *[mv(n, [1, 0, 0]) for n in ("reading table 2", "chair 3", "chair 4", "table lamp 2")], un())
Q(R, "hard", "turn every chair at tables 3 and 4 to face the circulation desk",
  *[faces(c, "circulation desk") for c in ("chair 5", "chair 6", "chair 7", "chair 8")], nc(), un())
Q(R, "hard", "the chair nearest window 1: pull it out from its table by 30cm", mv("chair 2", [0, 0, 0.3]), un())
Q(R, "hard", "rotate table 5 by 90 degrees and keep its chairs drawn up to it",
  rot("reading table 5", 90, True), nt("chair 9", "reading table 5", 0.3), nt("chair 10", "reading table 5", 0.3), nc(), un())
Q(R, "hard", "put table lamp 3 on table 6 between the two chairs at that table",
  on("table lamp 3", "reading table 6"), betw("table lamp 3", "chair 11", "chair 12"), nc(), un())
Q(R, "hard", "swap chair 1 with the chair facing it across the table", sw("chair 1", "chair 2"), un())
Q(R, "hard", "take the lamp off table 4 and put it on the floor beside the globe",
  nt("table lamp 4", "globe", 0.3), nc(), un())
Q(R, "hard", "move the left column of tables 50cm to the right, chairs and all",
  *[mv(n, [0.5, 0, 0]) for n in ("reading table 1", "reading table 3", "reading table 5",
                                  "chair 1", "chair 2", "chair 5", "chair 6", "chair 9", "chair 10",
                                  "table lamp 1", "table lamp 3", "atlas", "book stack")], un())
Q(R, "hard", "put the lamp on the table that doesn't have one", ref(LMP))
