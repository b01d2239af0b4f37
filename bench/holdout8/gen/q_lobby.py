from dsl import *
L = "hotel_lobby.json"
A = [f"armchair {i}" for i in range(1, 9)]
CT = [f"coffee table {i}" for i in range(1, 5)]

# ---------------- simple
Q(L, "simple", "move armchair 3 half a metre to the left", mv("armchair 3", [-0.5, 0, 0]), un())
Q(L, "simple", "lamp on the reception desk: 30cm left", mv("reception lamp", [-0.3, 0, 0]), un())
Q(L, "simple", "Move coffee table 3 one metre forward", mv("coffee table 3", [0, 0, 1]), un())
Q(L, "simple", "rotate armchair 6 by 90 degrees", rot("armchair 6", 90, True), un())
Q(L, "simple", "turn the grandfather clock 180°", rot("grandfather clock", 180, True), un())
Q(L, "simple", "scale the flower vase up by 50%", sc("flower vase", 1.5), un())
Q(L, "simple", "can you move the luggage cart 2 metres to the left?", mv("luggage cart", [-2, 0, 0]), un())
Q(L, "simple", "push the sofa 40 cm towards the front of the room", mv("lobby sofa", [0, 0, 0.4]), un())
Q(L, "simple", "potted palm 2 - 1ft to the left pls", mv("potted palm 2", [-FT, 0, 0], 0.03), un())
Q(L, "simple", "shift candle 1 back 5cm", mv("candle 1", [0, 0, -0.05], 0.02), un())
Q(L, "simple", "move the umbrela stand 2 feet right", mv("umbrella stand", [2 * FT, 0, 0], 0.03), un())
Q(L, "simple", "make the magazine stack half as big", sc("magazine stack", 0.5), un())
Q(L, "simple", "spin armchair 8 45 degrees clockwise", rot("armchair 8", -45), un())
Q(L, "simple", "I'd like the guest book moved 20 cm to the right", mv("guest book", [0.2, 0, 0]), un())
Q(L, "simple", "armchair 1, 0.75 m forward", mv("armchair 1", [0, 0, 0.75]), un())
Q(L, "simple", "move the floor lamp 12 inches back", mv("floor lamp", [0, 0, -12 * IN], 0.03), un())
Q(L, "simple", "rotate the reception lamp 90 degrees counterclockwise", rot("reception lamp", 90), un())
Q(L, "simple", "coffee table 4 -> 30 cm back", mv("coffee table 4", [0, 0, -0.3]), un())
Q(L, "simple", "make the grandfather clock 10% smaller", sc("grandfather clock", 0.9), un())
Q(L, "simple", "move potted palm 1 to the right by 1.5m", mv("potted palm 1", [1.5, 0, 0]), un())
Q(L, "simple", "armchiar 7 back 25 cm", mv("armchair 7", [0, 0, -0.25]), un())
Q(L, "simple", "move the armchair 1m to the left", ref(A))
Q(L, "simple", "turn the piano around", ref([]))

# ---------------- compositional
Q(L, "compositional", "move armchair 1 back 1 m and turn it to face coffee table 1",
  mv("armchair 1", [0, 0, -1]), faces("armchair 1", "coffee table 1"), un())
Q(L, "compositional", "put the desk bell on coffee table 3", on("desk bell", "coffee table 3"), un())
Q(L, "compositional", "move coffee table 2 and everything on it 1 m back",
  mv("coffee table 2", [0, 0, -1]), mv("flower vase", [0, 0, -1]), mv("candle 1", [0, 0, -1]), un())
Q(L, "compositional", "swap armchair 2 and armchair 5", sw("armchair 2", "armchair 5"), un())
Q(L, "compositional", "swap the flower vase and the magazine stack", sw("flower vase", "magazine stack"), un())
Q(L, "compositional", "move the luggage cart next to the entrance door",
  nt("luggage cart", "entrance door", 0.5), nc(), un())
Q(L, "compositional", "put candle 2 on the reception desk", on("candle 2", "reception desk"), un())
Q(L, "compositional", "put the reception lamp on coffee table 3", on("reception lamp", "coffee table 3"), un())
Q(L, "compositional", "place the floor lamp between armchair 1 and armchair 5",
  betw("floor lamp", "armchair 1", "armchair 5"), nc(), un())
Q(L, "compositional", "put the tea tray on coffee table 1 and the magazine stack on coffee table 4",
  on("tea tray", "coffee table 1"), on("magazine stack", "coffee table 4"), un())
Q(L, "compositional", "move armchairs 5 and 6 1 m to the front",
  mv("armchair 5", [0, 0, 1]), mv("armchair 6", [0, 0, 1]), un())
Q(L, "compositional", "move coffee table 3 and its armchairs 50cm towards the back",
  mv("coffee table 3", [0, 0, -0.5]), mv("armchair 5", [0, 0, -0.5]), mv("armchair 6", [0, 0, -0.5]), un())
Q(L, "compositional", "rotate armchairs 1 and 2 by 180 degrees",
  rot("armchair 1", 180, True), rot("armchair 2", 180, True), un())
Q(L, "compositional", "move the flower vase 20cm left and make it 20% bigger",
  mv("flower vase", [-0.2, 0, 0]), sc("flower vase", 1.2), un())
Q(L, "compositional", "put the desk bell right next to the guest book",
  nt("desk bell", "guest book", 0.15), on("desk bell", "reception desk"), un())
Q(L, "compositional", "move armchair 7 one metre forward and rotate it 90° clockwise",
  mv("armchair 7", [0, 0, 1]), rot("armchair 7", -90), un())
Q(L, "compositional", "put potted palm 1 in the front left corner",
  at("potted palm 1", [-7.7, 0, 5.7], 0.35), ib(), un())
Q(L, "compositional", "put the magazine stack on the reception desk, to the left of the guest book",
  on("magazine stack", "reception desk"), side("magazine stack", "guest book", "left", 0.5), un())
Q(L, "compositional", "move the umbrella stand to the right of the luggage cart",
  side("umbrella stand", "luggage cart", "right", 0.5), nc(), un())
Q(L, "compositional", "stand the floor lamp beside the grandfather clock",
  nt("floor lamp", "grandfather clock", 0.4), nc(), un())
Q(L, "compositional", "turn armchairs 7 and 8 to face the grandfather clock",
  faces("armchair 7", "grandfather clock"), faces("armchair 8", "grandfather clock"), un())
Q(L, "compositional", "put the candle on the reception desk", ref(["candle 1", "candle 2"]))
Q(L, "compositional", "move the fireplace over to the left wall", ref([]))
Q(L, "compositional", "move armchair 9 next to the sofa", ref([]))

# ---------------- fuzzy
Q(L, "fuzzy", "nudge armchair 2 a little to the right",
  dr("armchair 2", "+x", 0.03), mv("armchair 2", [0.25, 0, 0], 0.25), un())
Q(L, "fuzzy", "scoot the sofa forward a tad",
  dr("lobby sofa", "+z", 0.01), mv("lobby sofa", [0, 0, 0.12], 0.12), un())
Q(L, "fuzzy", "move the luggage cart way over to the right", dr("luggage cart", "+x", 0.8), ib(), un())
Q(L, "fuzzy", "bring armchair 5 a bit closer to the sofa", dist("armchair 5", "lobby sofa", mx=3.05), nc(), un())
Q(L, "fuzzy", "move the floor lamp a bit away from the sofa", dist("floor lamp", "lobby sofa", mn=1.8), nc(), un())
Q(L, "fuzzy", "make the flower vase a bit bigger", sc("flower vase", 1.25, 0.2), un())
Q(L, "fuzzy", "make the tea tray a touch smaller", sc("tea tray", 0.85, 0.14), un())
Q(L, "fuzzy", "push coffee table 4 a little bit back",
  dr("coffee table 4", "-z", 0.03), mv("coffee table 4", [0, 0, -0.2], 0.2), un())
Q(L, "fuzzy", "slide armchair 5 way back", dr("armchair 5", "-z", 0.8), nc(), un())
Q(L, "fuzzy", "move the reception lamp a smidge left",
  dr("reception lamp", "-x", 0.01), mv("reception lamp", [-0.08, 0, 0], 0.1), un())
Q(L, "fuzzy", "move the guest book slightly to the left",
  dr("guest book", "-x", 0.02), mv("guest book", [-0.15, 0, 0], 0.15), on("guest book", "reception desk"), un())
Q(L, "fuzzy", "shift armchair 4 a few inches to the right",
  dr("armchair 4", "+x", 0.03), mv("armchair 4", [0.1, 0, 0], 0.1), un())
Q(L, "fuzzy", "move the luggage cart back quite a lot", dr("luggage cart", "-z", 0.5), nc(), un())
Q(L, "fuzzy", "the palm on the right, move it a bit forward",
  dr("potted palm 2", "+z", 0.03), mv("potted palm 2", [0, 0, 0.25], 0.25), un())
Q(L, "fuzzy", "make the clock a little bigger", sc("grandfather clock", 1.15, 0.13), un())
Q(L, "fuzzy", "move the coffee table back a bit", ref(CT))
Q(L, "fuzzy", "put the palm in the corner", ref(["potted palm 1", "potted palm 2"]))

# ---------------- compositional_fuzzy
Q(L, "compositional_fuzzy", "move armchair 6 a bit to the right and turn it round",
  dr("armchair 6", "+x", 0.03), rot("armchair 6", 180, True), un())
Q(L, "compositional_fuzzy", "push coffee table 1 back a bit, with the magazines on it",
  dr("coffee table 1", "-z", 0.03), dr("magazine stack", "-z", 0.03), on("magazine stack", "coffee table 1"), un())
Q(L, "compositional_fuzzy", "bring armchair 4 a little closer to coffee table 2 but keep it facing the table",
  nt("armchair 4", "coffee table 2", 0.15), faces("armchair 4", "coffee table 2"), nc(), un())
Q(L, "compositional_fuzzy", "pop candle 1 somewhere on coffee table 3", on("candle 1", "coffee table 3"), un())
Q(L, "compositional_fuzzy", "put the magazine stack on the reception desk, roughly in the middle",
  on("magazine stack", "reception desk"), al("magazine stack", "reception desk", "x", 0.35), un())
Q(L, "compositional_fuzzy", "spread armchairs 7 and 8 a little further apart",
  dist("armchair 7", "armchair 8", mn=2.28), nc(), un([n for n in A if n not in ("armchair 7", "armchair 8")] + CT + ["tea tray", "candle 2", "luggage cart", "grandfather clock"]))
Q(L, "compositional_fuzzy", "slide the sofa forward a bit and put the floor lamp next to it",
  dr("lobby sofa", "+z", 0.03), nt("floor lamp", "lobby sofa", 0.3), nc(), un())
Q(L, "compositional_fuzzy", "move the vase a bit towards armchair 3, keep it on the table",
  dr("flower vase", "-x", 0.03), on("flower vase", "coffee table 2"), un())
Q(L, "compositional_fuzzy", "could you bring armchair 1 and armchair 2 a touch closer to their table",
  nt("armchair 1", "coffee table 1", 0.15), nt("armchair 2", "coffee table 1", 0.15), nc(), un())
Q(L, "compositional_fuzzy", "push the luggage cart right up against the right wall, and a little further back",
  mv("luggage cart", [1.5, 0, -0.3], 0.3), ib(), un())
Q(L, "compositional_fuzzy", "shrink the flower vase a bit and slide it left a little",
  sc("flower vase", 0.8, 0.17), dr("flower vase", "-x", 0.02), on("flower vase", "coffee table 2"), un())
Q(L, "compositional_fuzzy", "scoot armchairs 5 and 6 slightly further from the coffee table",
  dist("armchair 5", "coffee table 3", mn=1.15), dist("armchair 6", "coffee table 3", mn=1.15), nc(), un())
Q(L, "compositional_fuzzy", "armchair 9 - bit closer to the door please", ref([]))

# ---------------- hard
Q(L, "hard", "put the flower vase on the empty coffee table", on("flower vase", "coffee table 3"), un())
Q(L, "hard", "turn every armchair to face the entrance door", *[faces(a, "entrance door") for a in A], nc(), un())
Q(L, "hard", "all the armchairs except armchair 3 – move them 20 cm back",
  *[mv(a, [0, 0, -0.2]) for a in A if a != "armchair 3"], un(["armchair 3"]), un())
Q(L, "hard", "move the table with the vase on it a metre back",
  mv("coffee table 2", [0, 0, -1]), mv("flower vase", [0, 0, -1]), un())
Q(L, "hard", "swap the empty coffee table with the one that has the tea tray",
  sw("coffee table 3", "coffee table 4"), mv("tea tray", [-8, 0, 0], 0.1), un())
Q(L, "hard", "turn the armchair nearest the floor lamp to face the reception desk",
  faces("armchair 1", "reception desk"), un())
Q(L, "hard", "desk bell -> whichever coffee table has nothing on it", on("desk bell", "coffee table 3"), un())
Q(L, "hard", "move armchair 2 so it sits between coffee tables 1 and 3",
  betw("armchair 2", "coffee table 1", "coffee table 3"), nc(), un())
Q(L, "hard", "rotate coffee table 3 by 90° and pull armchairs 5 and 6 back in against it",
  rot("coffee table 3", 90, True), nt("armchair 5", "coffee table 3", 0.3), nt("armchair 6", "coffee table 3", 0.3), nc(), un())
Q(L, "hard", "take the reception lamp off the desk and stand it on the floor next to the sofa",
  nt("reception lamp", "lobby sofa", 0.5), nc(), un())
Q(L, "hard", "stack the magazines on top of the tea tray", on("magazine stack", "tea tray"), un())
Q(L, "hard", "move both potted palms to the front corners",
  at("potted palm 1", [-7.7, 0, 5.7], 0.35), at("potted palm 2", [7.7, 0, 5.7], 0.35), ib(), un())
Q(L, "hard", "move the back row of armchairs 30cm further back",
  *[mv(a, [0, 0, -0.3]) for a in A[:4]], un())
Q(L, "hard", "the two armchairs at table 2: swap them", sw("armchair 3", "armchair 4"), un())
Q(L, "hard", "put both candles on coffee table 1",
  on("candle 1", "coffee table 1"), on("candle 2", "coffee table 1"), un())
Q(L, "hard", "move coffee table 1 and its two armchairs 1 m to the right, magazines and all",
  mv("coffee table 1", [1, 0, 0]), mv("armchair 1", [1, 0, 0]), mv("armchair 2", [1, 0, 0]),
  mv("magazine stack", [1, 0, 0]), un())
Q(L, "hard", "put the guest book at the other end of the desk",
  dr("guest book", "+x", 0.8), on("guest book", "reception desk"), un())
Q(L, "hard", "move the lamp 20 cm right", ref(["reception lamp", "floor lamp"]))
