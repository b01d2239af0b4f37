import math, json
S45 = math.sqrt(0.5)
R0 = [0, 0, 0, 1]
RL = [0, S45, 0, S45]    # +90 about Y: front +z -> +x (faces right)
RR = [0, -S45, 0, S45]   # -90 about Y: front faces -x (faces left)
R180 = [0, 1, 0, 0]      # faces -z (back)

def o(name, pos, size, rot=R0, **kw):
    d = {"name": name, "position": [round(v, 4) for v in pos], "size": size, "rotation": rot, "scale": 1.0}
    d.update(kw)
    return d

def lobby():
    ob = []
    ob.append(o("reception desk", [0, 0, -5.55], [3.0, 1.1, 0.8]))
    ob.append(o("desk bell", [0.5, 1.1, -5.45], [0.1, 0.08, 0.1]))
    ob.append(o("guest book", [-0.6, 1.1, -5.45], [0.3, 0.04, 0.22]))
    ob.append(o("reception lamp", [1.2, 1.1, -5.7], [0.25, 0.5, 0.25]))
    tables = {1: (-4, -1.5), 2: (4, -1.5), 3: (-4, 2.5), 4: (4, 2.5)}
    for k, (x, z) in tables.items():
        ob.append(o(f"coffee table {k}", [x, 0, z], [1.0, 0.45, 0.6]))
    n = 1
    for k, (x, z) in tables.items():
        ob.append(o(f"armchair {n}", [x - 1.1, 0, z], [0.8, 0.9, 0.8], RL)); n += 1
        ob.append(o(f"armchair {n}", [x + 1.1, 0, z], [0.8, 0.9, 0.8], RR)); n += 1
    ob.append(o("magazine stack", [-4, 0.45, -1.5], [0.3, 0.08, 0.22]))
    ob.append(o("flower vase", [4, 0.45, -1.5], [0.15, 0.35, 0.15]))
    ob.append(o("candle 1", [4.3, 0.45, -1.5], [0.08, 0.15, 0.08]))
    ob.append(o("tea tray", [4, 0.45, 2.5], [0.45, 0.05, 0.3]))
    ob.append(o("candle 2", [3.7, 0.45, 2.5], [0.08, 0.15, 0.08]))
    ob.append(o("lobby sofa", [-7.55, 0, 0.5], [2.2, 0.85, 0.9], RL))
    ob.append(o("floor lamp", [-7.6, 0, -1.2], [0.4, 1.7, 0.4]))
    ob.append(o("potted palm 1", [-7.5, 0, -5.5], [0.6, 1.8, 0.6]))
    ob.append(o("potted palm 2", [7.5, 0, -5.5], [0.6, 1.8, 0.6]))
    ob.append(o("grandfather clock", [7.75, 0, 1.0], [0.5, 2.1, 0.4], RR))
    ob.append(o("luggage cart", [6.0, 0, 4.8], [1.0, 1.8, 0.6]))
    ob.append(o("entrance door", [0, 0, 5.95], [1.8, 2.4, 0.1], R180))
    ob.append(o("umbrella stand", [1.3, 0, 5.6], [0.3, 0.6, 0.3]))
    return {"name": "hotel_lobby", "bounds": {"min": [-8, 0, -6], "max": [8, 4, 6]},
            "objects": ob}

def playroom():
    ob = []
    ob.append(o("Cube", [-1.5, 0, -2.3], [1.6, 1.0, 0.35]))
    ob.append(o("Sphere", [-2.0, 1.0, -2.3], [0.2, 0.2, 0.2]))
    ob.append(o("Cube.001", [-1.5, 1.0, -2.3], [0.1, 0.1, 0.1]))
    ob.append(o("Cube.002", [-1.3, 1.0, -2.3], [0.1, 0.1, 0.1]))
    ob.append(o("Cylinder", [-0.9, 1.0, -2.3], [0.25, 0.2, 0.25]))
    ob.append(o("Cube.003", [0.8, 0, 0], [1.2, 0.5, 0.8]))
    ob.append(o("Cylinder.001", [0.5, 0.5, 0.1], [0.08, 0.12, 0.08]))
    ob.append(o("Cube.004", [1.0, 0.5, -0.1], [0.4, 0.06, 0.3]))
    ob.append(o("Sphere.001", [1.2, 0.5, 0.25], [0.1, 0.1, 0.1]))
    ob.append(o("Cube.005", [0.8, 0, -0.65], [0.35, 0.6, 0.35]))
    ob.append(o("Cube.006", [0.8, 0, 0.65], [0.35, 0.6, 0.35], R180))
    ob.append(o("Cube.007", [1.85, 0, 0], [0.35, 0.6, 0.35], RR))
    ob.append(o("Cube.008", [2.75, 0, -1.0], [0.9, 0.5, 0.45], RR))
    ob.append(o("Cone", [2.75, 0.5, -1.2], [0.15, 0.25, 0.15]))
    ob.append(o("Torus", [2.75, 0.5, -0.8], [0.25, 0.06, 0.25]))
    ob.append(o("Cube.009", [-2.2, 0, 2.47], [0.9, 2.0, 0.06], R180))
    ob.append(o("Cylinder.002", [-1.5, 0, 2.2], [0.3, 1.4, 0.3]))
    ob.append(o("Sphere.002", [-0.8, 0, 1.0], [0.55, 0.55, 0.55]))
    ob.append(o("Sphere.003", [1.8, 0, 1.6], [0.3, 0.3, 0.3]))
    ob.append(o("Icosphere", [-2.3, 0, 0.2], [0.85, 0.45, 0.8]))
    ob.append(o("Cylinder.003", [-0.2, 0, -2.2], [0.4, 0.45, 0.4]))
    ob.append(o("Cube.012", [-2.8, 0, -1.2], [0.8, 1.6, 0.3], RL))
    ob.append(o("Suzanne", [-2.8, 1.6, -1.2], [0.2, 0.18, 0.16], RL))
    ob.append(o("Cube.010", [0.0, 0, 1.6], [0.4, 0.2, 0.25]))
    return {"name": "playroom_blender", "bounds": {"min": [-3, 0, -2.5], "max": [3, 2.6, 2.5]},
            "exported_from": "Blender 4.1 (glTF, +Y up)",
            "objects": ob}

def kitchen():
    ob = []
    ob.append(o("BP_Stove", [-2, 0, -3.6], [1.2, 0.9, 0.8]))
    ob.append(o("SM_Pot_Large", [-2.3, 0.9, -3.75], [0.4, 0.35, 0.4]))
    ob.append(o("SM_Pot_Small", [-1.75, 0.9, -3.8], [0.25, 0.2, 0.25]))
    ob.append(o("SM_Pan_01", [-1.75, 0.9, -3.45], [0.5, 0.06, 0.3]))
    ob.append(o("SM_Sink_Unit", [1.0, 0, -3.65], [1.4, 0.9, 0.7]))
    ob.append(o("SM_Dish_Rack", [1.4, 0.9, -3.65], [0.5, 0.3, 0.35]))
    ob.append(o("SM_Fridge_Double", [4.55, 0, -2.5], [1.2, 2.0, 0.8], RR))
    for k, x in ((1, -2.5), (2, 0.0), (3, 2.5)):
        ob.append(o(f"SM_Prep_Table_0{k}", [x, 0, 0], [1.8, 0.9, 0.8]))
    ob.append(o("SM_Cutting_Board_01", [-2.7, 0.9, 0.0], [0.45, 0.03, 0.3]))
    ob.append(o("SM_Knife_Block", [-2.0, 0.9, -0.2], [0.15, 0.25, 0.12]))
    ob.append(o("SM_Bowl_Steel_01", [-3.1, 0.9, 0.15], [0.3, 0.12, 0.3]))
    ob.append(o("SM_Mixer_Stand", [0.5, 0.9, -0.15], [0.3, 0.45, 0.4]))
    ob.append(o("SM_Bowl_Steel_02", [-0.3, 0.9, 0.15], [0.3, 0.12, 0.3]))
    ob.append(o("SM_Cutting_Board_02", [-0.5, 0.9, -0.22], [0.45, 0.03, 0.3]))
    ob.append(o("SM_Plate_Stack", [2.3, 0.9, 0.1], [0.3, 0.2, 0.3]))
    ob.append(o("SM_Bowl_Steel_03", [1.85, 0.9, 0.2], [0.3, 0.12, 0.3]))
    ob.append(o("SM_Pan_02", [2.85, 0.9, -0.2], [0.5, 0.06, 0.3]))
    ob.append(o("SM_Stool_01", [-0.5, 0, 0.65], [0.4, 0.75, 0.4]))
    ob.append(o("SM_Stool_02", [0.5, 0, 0.65], [0.4, 0.75, 0.4]))
    ob.append(o("SM_Trash_Bin", [-4.72, 0, 1.5], [0.5, 0.8, 0.5]))
    ob.append(o("SM_Crate_Veg_01", [-4.55, 0, -1.0], [0.6, 0.35, 0.4]))
    ob.append(o("SM_Crate_Veg_02", [-4.55, 0.35, -1.0], [0.6, 0.35, 0.4]))
    ob.append(o("SM_Door_Swing", [3.0, 0, 3.96], [1.0, 2.1, 0.08], R180))
    ob.append(o("SM_Rack_Storage", [-3.0, 0, 3.7], [1.5, 1.8, 0.5], R180))
    ob.append(o("SM_Mop_Bucket", [-1.5, 0, 3.5], [0.45, 0.5, 0.35]))
    return {"name": "restaurant_kitchen", "bounds": {"min": [-5, 0, -4], "max": [5, 3, 4]},
            "exported_from": "Unreal Engine 5 (converted to +Y up, metres)",
            "objects": ob}

def library():
    ob = []
    ob.append(o("window 1", [-6.95, 0.9, -2.5], [1.4, 1.6, 0.1], RL))
    ob.append(o("window 2", [-6.95, 0.9, 2.5], [1.4, 1.6, 0.1], RL))
    tables = {1: (-3, -3), 2: (1, -3), 3: (-3, 0), 4: (1, 0), 5: (-3, 3), 6: (1, 3)}
    for k, (x, z) in tables.items():
        ob.append(o(f"reading table {k}", [x, 0, z], [1.6, 0.75, 0.9]))
    for k, (x, z) in tables.items():
        ob.append(o(f"chair {2*k-1}", [x, 0, z - 0.75], [0.45, 0.9, 0.45]))
        ob.append(o(f"chair {2*k}", [x, 0, z + 0.75], [0.45, 0.9, 0.45], R180))
    for k in (1, 2, 3, 4, 6):
        x, z = tables[k]
        ob.append(o(f"table lamp {k}", [x - 0.5, 0.75, z], [0.25, 0.45, 0.25]))
    ob.append(o("atlas", [-2.6, 0.75, 0.1], [0.45, 0.06, 0.32]))
    ob.append(o("reading glasses", [1.3, 0.75, 0.1], [0.14, 0.04, 0.06]))
    ob.append(o("book stack", [-3, 0.75, 3], [0.25, 0.22, 0.2]))
    for k, z in (("A", -3.5), ("B", -1.5), ("C", 0.5)):
        ob.append(o(f"bookcase {k}", [6.78, 0, z], [1.8, 2.2, 0.4], RR))
    ob.append(o("circulation desk", [4.5, 0, 4.8], [2.0, 1.05, 0.7], R180))
    ob.append(o("computer terminal", [4.9, 1.05, 4.8], [0.45, 0.45, 0.25], R180))
    ob.append(o("globe", [-6.2, 0, 0], [0.5, 1.1, 0.5]))
    ob.append(o("card catalog", [0, 0, -5.75], [1.2, 1.3, 0.45]))
    return {"name": "reading_room", "bounds": {"min": [-7, 0, -6], "max": [7, 4, 6]},
            "objects": ob}

SCENES = {"hotel_lobby.json": lobby(), "playroom_blender.json": playroom(),
          "restaurant_kitchen.json": kitchen(), "reading_room.json": library()}
