from dsl import *
K = "restaurant_kitchen.json"
PT = ["SM_Prep_Table_01", "SM_Prep_Table_02", "SM_Prep_Table_03"]
BW = ["SM_Bowl_Steel_01", "SM_Bowl_Steel_02", "SM_Bowl_Steel_03"]

# ---------------- simple
Q(K, "simple", "move SM_Prep_Table_02 50cm back", mv("SM_Prep_Table_02", [0, 0, -0.5]), un())
Q(K, "simple", "prep table 3: 40 cm right", mv("SM_Prep_Table_03", [0.4, 0, 0]), un())
Q(K, "simple", "turn the mop bucket 90°", rot("SM_Mop_Bucket", 90, True), un())
Q(K, "simple", "move the big pot 10cm to the left", mv("SM_Pot_Large", [-0.1, 0, 0]), un())
Q(K, "simple", "SM_Trash_Bin forward 1 m", mv("SM_Trash_Bin", [0, 0, 1]), un())
Q(K, "simple", "make the mixer 10% bigger", sc("SM_Mixer_Stand", 1.1), un())
Q(K, "simple", "can you move the mop bucket 2 ft to the right?", mv("SM_Mop_Bucket", [2 * FT, 0, 0], 0.03), un())
Q(K, "simple", "shift the knife block 15cm forward", mv("SM_Knife_Block", [0, 0, 0.15]), un())
Q(K, "simple", "rotate SM_Stool_01 by 45 degrees", rot("SM_Stool_01", 45, True), un())
Q(K, "simple", "move the storage rack 1 m to the left", mv("SM_Rack_Storage", [-1, 0, 0]), un())
Q(K, "simple", "SM_Pan_02 - turn 90° clockwise", rot("SM_Pan_02", -90), un())
Q(K, "simple", "scale SM_Plate_Stack by 0.8", sc("SM_Plate_Stack", 0.8), un())
Q(K, "simple", "move the dish rack 30 cm left", mv("SM_Dish_Rack", [-0.3, 0, 0]), un())
Q(K, "simple", "small pot back 5cm", mv("SM_Pot_Small", [0, 0, -0.05], 0.02), un())
Q(K, "simple", "SM_Stool_02 30 cm to the rigth", mv("SM_Stool_02", [0.3, 0, 0]), un())
Q(K, "simple", "move the fridge 50 cm forward", mv("SM_Fridge_Double", [0, 0, 0.5]), un())
Q(K, "simple", "move the prep table 1 m left", ref(PT))
Q(K, "simple", "turn the microwave around", ref([]))
Q(K, "simple", "stool: 2 feet left", ref(["SM_Stool_01", "SM_Stool_02"]))

# ---------------- compositional
Q(K, "compositional", "put the small pot on prep table 3", on("SM_Pot_Small", "SM_Prep_Table_03"), un())
Q(K, "compositional", "move the cutting board from prep table 1 onto prep table 2",
  on("SM_Cutting_Board_01", "SM_Prep_Table_02"), nc(), un())
Q(K, "compositional", "swap SM_Prep_Table_01 and SM_Prep_Table_03", sw("SM_Prep_Table_01", "SM_Prep_Table_03"), un())
Q(K, "compositional", "put the plate stack on the sink unit next to the dish rack",
  on("SM_Plate_Stack", "SM_Sink_Unit"), nt("SM_Plate_Stack", "SM_Dish_Rack", 0.2), nc(), un())
Q(K, "compositional", "move prep table 2 and both stools 60cm back",
  mv("SM_Prep_Table_02", [0, 0, -0.6]), mv("SM_Stool_01", [0, 0, -0.6]), mv("SM_Stool_02", [0, 0, -0.6]), un())
Q(K, "compositional", "put the knife block on the stove beside the big pot",
  on("SM_Knife_Block", "BP_Stove"), nt("SM_Knife_Block", "SM_Pot_Large", 0.3), nc(), un())
Q(K, "compositional", "move the bin to the right of the mop bucket",
  side("SM_Trash_Bin", "SM_Mop_Bucket", "right", 0.5), nc(), un())
Q(K, "compositional", "take the top crate off and put it on the floor next to the other one",
  nt("SM_Crate_Veg_02", "SM_Crate_Veg_01", 0.3), nc(), un())
Q(K, "compositional", "put SM_Pan_01 on prep table 2 and SM_Pot_Large on prep table 1",
  on("SM_Pan_01", "SM_Prep_Table_02"), on("SM_Pot_Large", "SM_Prep_Table_01"), nc(), un())
Q(K, "compositional", "move the mixer to prep table 3 and turn it 180 degrees",
  on("SM_Mixer_Stand", "SM_Prep_Table_03"), rot("SM_Mixer_Stand", 180, True), nc(), un())
Q(K, "compositional", "move the trash bin into the back left corner",
  at("SM_Trash_Bin", [-4.75, 0, -3.75], 0.35), nc(), ib(), un())
Q(K, "compositional", "rotate both stools 90 degrees and move them 20cm forward",
  rot("SM_Stool_01", 90, True), rot("SM_Stool_02", 90, True),
  mv("SM_Stool_01", [0, 0, 0.2]), mv("SM_Stool_02", [0, 0, 0.2]), un())
Q(K, "compositional", "put SM_Bowl_Steel_01 on top of SM_Crate_Veg_02", on("SM_Bowl_Steel_01", "SM_Crate_Veg_02"), un())
Q(K, "compositional", "swap the large pot and the small pot", sw("SM_Pot_Large", "SM_Pot_Small"), un())
Q(K, "compositional", "put the mop bucket next to the door", nt("SM_Mop_Bucket", "SM_Door_Swing", 0.4), nc(), un())
Q(K, "compositional", "SM_Fridge_Double: 40cm forward, then SM_Trash_Bin 50cm right",
  mv("SM_Fridge_Double", [0, 0, 0.4]), mv("SM_Trash_Bin", [0.5, 0, 0]), un())
Q(K, "compositional", "put the steel bowl on the stove", ref(BW))
Q(K, "compositional", "move the dishwasher next to the sink", ref([]))

# ---------------- fuzzy
Q(K, "fuzzy", "nudge prep table 3 a bit to the left",
  dr("SM_Prep_Table_03", "-x", 0.03), mv("SM_Prep_Table_03", [-0.2, 0, 0], 0.2), un())
Q(K, "fuzzy", "move the mop bucket a little further from the rack",
  dist("SM_Mop_Bucket", "SM_Rack_Storage", mn=1.7), nc(), un())
Q(K, "fuzzy", "push the bin way to the right", dr("SM_Trash_Bin", "+x", 0.8), nc(), un())
Q(K, "fuzzy", "make the plate stack a bit smaller", sc("SM_Plate_Stack", 0.8, 0.17), un())
Q(K, "fuzzy", "slide SM_Pan_02 a tad forward",
  dr("SM_Pan_02", "+z", 0.01), mv("SM_Pan_02", [0, 0, 0.1], 0.1), un())
Q(K, "fuzzy", "move the big pot a hair to the left",
  dr("SM_Pot_Large", "-x", 0.01), mv("SM_Pot_Large", [-0.05, 0, 0], 0.06), un())
Q(K, "fuzzy", "shift the stools a bit closer together",
  dist("SM_Stool_01", "SM_Stool_02", mx=0.95), nc(), un(PT + ["SM_Mixer_Stand", "SM_Bowl_Steel_02", "SM_Cutting_Board_02", "SM_Mop_Bucket"]))
Q(K, "fuzzy", "move prep table 1 forward a little",
  dr("SM_Prep_Table_01", "+z", 0.03), mv("SM_Prep_Table_01", [0, 0, 0.2], 0.2), un())
Q(K, "fuzzy", "move the fridge quite a bit forward", dr("SM_Fridge_Double", "+z", 0.4), nc(), un())
Q(K, "fuzzy", "make the mixer a touch bigger", sc("SM_Mixer_Stand", 1.1, 0.09), un())
Q(K, "fuzzy", "scoot the cutting board on table 2 a bit to the left",
  dr("SM_Cutting_Board_02", "-x", 0.02), on("SM_Cutting_Board_02", "SM_Prep_Table_02"), un())
Q(K, "fuzzy", "could you shift the storage rack over to the right slightly",
  dr("SM_Rack_Storage", "+x", 0.02), mv("SM_Rack_Storage", [0.15, 0, 0], 0.15), un())
Q(K, "fuzzy", "move the pan a bit back", ref(["SM_Pan_01", "SM_Pan_02"]))

# ---------------- compositional_fuzzy
Q(K, "compositional_fuzzy", "move SM_Stool_02 a bit right and spin it a quarter turn",
  dr("SM_Stool_02", "+x", 0.03), rot("SM_Stool_02", 90, True), un())
Q(K, "compositional_fuzzy", "bring the small pot a bit closer to the big pot",
  dist("SM_Pot_Small", "SM_Pot_Large", mx=0.5), nc(), un())
Q(K, "compositional_fuzzy", "move prep table 3 slightly left, and everything on it too",
  dr("SM_Prep_Table_03", "-x", 0.03), dr("SM_Plate_Stack", "-x", 0.03), dr("SM_Bowl_Steel_03", "-x", 0.03),
  dr("SM_Pan_02", "-x", 0.03), un())
Q(K, "compositional_fuzzy", "put the top crate on the floor somewhere near the bin",
  nt("SM_Crate_Veg_02", "SM_Trash_Bin", 0.6), nc(), un())
Q(K, "compositional_fuzzy", "move SM_Bowl_Steel_02 a little toward the mixer",
  dist("SM_Bowl_Steel_02", "SM_Mixer_Stand", mx=0.82), on("SM_Bowl_Steel_02", "SM_Prep_Table_02"), nc(), un())
Q(K, "compositional_fuzzy", "move the mop bucket over by the sink, roughly",
  nt("SM_Mop_Bucket", "SM_Sink_Unit", 0.5), nc(), un())
Q(K, "compositional_fuzzy", "shove the storage rack a bit left and the mop bucket a bit right",
  dr("SM_Rack_Storage", "-x", 0.03), dr("SM_Mop_Bucket", "+x", 0.03), un())
Q(K, "compositional_fuzzy", "make the pan on the stove a bit smaller and slide it forward a touch",
  sc("SM_Pan_01", 0.85, 0.13), dr("SM_Pan_01", "+z", 0.01), un())
Q(K, "compositional_fuzzy", "move the trash bin a bit forward and turn it round",
  dr("SM_Trash_Bin", "+z", 0.03), rot("SM_Trash_Bin", 180, True), un())
Q(K, "compositional_fuzzy", "slide the fridge forward a little and angle it towards prep table 3",
  dr("SM_Fridge_Double", "+z", 0.03), faces("SM_Fridge_Double", "SM_Prep_Table_03", 25), nc(), un())
Q(K, "compositional_fuzzy", "push the steel bowl a little to the right", ref(BW))

# ---------------- hard
Q(K, "hard", "move the table with the mixer on it 50cm back",
  mv("SM_Prep_Table_02", [0, 0, -0.5]), mv("SM_Mixer_Stand", [0, 0, -0.5]),
  mv("SM_Bowl_Steel_02", [0, 0, -0.5]), mv("SM_Cutting_Board_02", [0, 0, -0.5]), un())
Q(K, "hard", "put all the steel bowls on prep table 3", *[on(b, "SM_Prep_Table_03") for b in BW], nc(), un())
Q(K, "hard", "the top crate: 6 inches to the right", mv("SM_Crate_Veg_02", [6 * IN, 0, 0], 0.03), un())
Q(K, "hard", "put the pan that's on a prep table onto the stove", on("SM_Pan_02", "BP_Stove"), nc(), un())
Q(K, "hard", "turn SM_Stool_01 and SM_Stool_02 to face each other",
  faces("SM_Stool_01", "SM_Stool_02"), faces("SM_Stool_02", "SM_Stool_01"), un())
Q(K, "hard", "move the two end prep tables 30 cm forward, leave the middle one",
  mv("SM_Prep_Table_01", [0, 0, 0.3]), mv("SM_Prep_Table_03", [0, 0, 0.3]), un(["SM_Prep_Table_02"]), un())
Q(K, "hard", "put the steel bowl from prep table 3 onto the sink unit", on("SM_Bowl_Steel_03", "SM_Sink_Unit"), un())
Q(K, "hard", "swap the mixer with the plate stack", sw("SM_Mixer_Stand", "SM_Plate_Stack"), un())
Q(K, "hard", "put the smaller pot on prep table 1", on("SM_Pot_Small", "SM_Prep_Table_01"), nc(), un())
Q(K, "hard", "put the plate stack in front of the mixer",
  side("SM_Plate_Stack", "SM_Mixer_Stand", "front", 0.3), on("SM_Plate_Stack", "SM_Prep_Table_02"), nc(), un())
Q(K, "hard", "move the middle prep table 40 cm back along with its stools",
  mv("SM_Prep_Table_02", [0, 0, -0.4]), mv("SM_Stool_01", [0, 0, -0.4]), mv("SM_Stool_02", [0, 0, -0.4]), un())
Q(K, "hard", "every steel bowl except the one on table 2: 10cm forward",
  mv("SM_Bowl_Steel_01", [0, 0, 0.1]), mv("SM_Bowl_Steel_03", [0, 0, 0.1]), un(["SM_Bowl_Steel_02"]), un())
Q(K, "hard", "put the cutting board on the fridge", ref(["SM_Cutting_Board_01", "SM_Cutting_Board_02"]))
