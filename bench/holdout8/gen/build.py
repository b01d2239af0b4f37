import json, dsl, q_lobby, q_kitchen, q_reading, q_play
from scenes import SCENES
out = "/work/main/bench/holdout8/"
for f, s in SCENES.items():
    json.dump(s, open(out + f, "w"), indent=1)
suite = {"name": "holdout8", "scenes": list(SCENES.keys()), "variations": 1, "seed": 8, "queries": dsl.QUERIES}
ids = [q["id"] for q in dsl.QUERIES]; assert len(ids) == len(set(ids))
json.dump(suite, open(out + "holdout8.suite.json", "w"), indent=1)
print(len(dsl.QUERIES))
