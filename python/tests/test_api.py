"""The Python API of docs/python.md, as a user drives it: outcomes (where objects end up),
refusals that leave the scene exactly as it was, formats, undo, threads."""

import json
import math
import os
import shutil
import subprocess
import threading
import time
from concurrent.futures import ThreadPoolExecutor

import pytest

import shenlong
from conftest import REPO, SCENES, shared


def obj(scene, name):
    return next(o for o in scene.objects() if o["name"] == name)


def test_load_lists_objects_with_boxes_and_supports(office_path):
    scene = shenlong.Scene.load(office_path)
    assert scene.name == "office_v3" and len(scene) == len(scene.objects()) > 10
    laptop = obj(scene, "laptop")
    assert set(laptop) >= {"name", "position", "rotation", "scale", "size", "world_box", "rests_on"}
    assert laptop["rests_on"] == "desk"
    desk = obj(scene, "desk")
    assert math.isclose(laptop["world_box"]["min"][1], desk["world_box"]["max"][1], abs_tol=1e-9)
    assert len(laptop["rotation"]) == 4


def test_edit_puts_the_mug_on_the_dresser_and_reports_it(office_path):
    scene = shenlong.Scene.load(office_path)
    outcome = scene.edit("put the mug on the dresser", llm="offline", system="cga", collide=True)
    mug, dresser = obj(scene, "mug"), obj(scene, "dresser")
    assert mug["rests_on"] == "dresser"
    assert math.isclose(mug["world_box"]["min"][1], dresser["world_box"]["max"][1], abs_tol=1e-6)
    for axis in (0, 2):
        assert dresser["world_box"]["min"][axis] - 1e-9 <= mug["world_box"]["min"][axis]
        assert mug["world_box"]["max"][axis] <= dresser["world_box"]["max"][axis] + 1e-9
    assert isinstance(outcome, shenlong.Outcome) and outcome.operation == "edit"
    assert [b.object for b in outcome.understood.bindings] == ["mug", "dresser"]
    assert outcome.understood.query == "put X1 on X2"
    [moved] = [m for m in outcome.moved if m.object == "mug"]
    assert moved.how == "moved" and moved.before != moved.after
    assert outcome.report is None, "the whole report only when asked for"
    assert scene.edit("move the mug 1 cm left", report=True).report["query"] == "move X1 1 cm left"


def test_the_report_is_what_shenlong_edit_json_writes(office_path, tmp_path):
    binary = os.environ.get("SHENLONG_BIN")
    if not binary or not os.path.exists(binary):
        pytest.skip("SHENLONG_BIN (the shenlong command) is not set")
    instruction = "move the stapler 20 cm to the left"
    subprocess.run(
        [binary, "edit", str(office_path), instruction, "--json", str(tmp_path / "r.json"),
         "-o", str(tmp_path / "out.json")],
        check=True, capture_output=True,
    )
    cli = json.loads((tmp_path / "r.json").read_text())
    scene = shenlong.Scene.load(office_path)
    mine = scene.edit(instruction, report=True).to_dict()
    assert set(mine) == set(cli)
    for key in ("operation", "history_id", "moved", "understood", "notes", "warnings"):
        assert mine[key] == cli[key], key
    for key in ("query", "bindings", "grounding", "objects", "collisions_resolved"):
        assert mine["report"][key] == cli["report"][key], key
    cli_scene = json.loads((tmp_path / "out.json").read_text())
    assert scene.to_dict()["objects"] == cli_scene["objects"]


def test_a_refusal_raises_and_changes_nothing(office_path):
    scene = shenlong.Scene.load(office_path)
    before = scene.to_dict()
    for instruction, kind in [
        ("put the unicorn on the desk", shenlong.NotUnderstoodError),
        ("move the mug 3 flurbs left", shenlong.NotUnderstoodError),
        ("", shenlong.BadInputError),
    ]:
        with pytest.raises(kind) as e:
            scene.edit(instruction)
        assert isinstance(e.value, shenlong.EditError) and isinstance(e.value, ValueError)
        assert e.value.kind == e.value.data["kind"]
        message = str(e.value)
        assert message and "\n" not in message
        assert scene.to_dict() == before
    assert scene.history() == []
    assert scene.undo() is None


def test_an_ambiguity_carries_its_choices_ready_to_send(office_path):
    scene = shenlong.Scene.from_dict(
        {
            "name": "two chairs",
            "objects": [
                {"name": "chair 1", "position": [0, 0, 0], "size": [0.5, 0.9, 0.5]},
                {"name": "chair 2", "position": [2, 0, 0], "size": [0.5, 0.9, 0.5]},
            ],
        }
    )
    with pytest.raises(shenlong.AmbiguousError) as e:
        scene.edit("move the chair 10 cm left")
    error = e.value
    assert error.phrase == "the chair" and error.objects == ["chair 1", "chair 2"] and error.total == 2
    chosen = scene.edit(error.choices[1].instruction)
    assert [m.object for m in chosen.moved] == ["chair 2"]


def test_bad_arguments_are_edit_errors_naming_what(office_path, tmp_path):
    scene = shenlong.Scene.load(office_path)
    with pytest.raises(shenlong.EditError, match="system"):
        scene.edit("move the mug left", system="matrix")
    with pytest.raises(shenlong.EditError, match="backend|llm|unknown"):
        scene.edit("move the mug left", llm="nonsense:thing")
    with pytest.raises(shenlong.EditError, match="no-such"):
        shenlong.Scene.load(tmp_path / "no-such.json")
    with pytest.raises(shenlong.EditError, match="unknown scene format"):
        shenlong.Scene.load(tmp_path / "room.obj")
    with pytest.raises(shenlong.EditError, match="objects|position|size"):
        shenlong.Scene.from_dict({"name": "x", "objects": [{"name": "a"}]})
    with pytest.raises(shenlong.EditError, match="the scene"):
        shenlong.Scene.from_dict({"objects": [{"name": "a", "position": [0, 0, float("nan")]}]})
    with pytest.raises(shenlong.BadInputError, match="unicorn|no object"):
        scene.apply("unicorn", "T(e1)")
    with pytest.raises(shenlong.NotUnderstoodError, match="column"):
        scene.apply("mug", "T(e1")
    with pytest.raises(shenlong.BadInputError, match="X2"):
        scene.apply("mug", "T(e1)", bind={"X3": "desk"})


def test_apply_undo_redo_and_history(office_path):
    scene = shenlong.Scene.load(office_path)
    x0 = obj(scene, "desk")["position"][0]
    laptop0 = obj(scene, "laptop")["position"][0]
    done = scene.apply("desk", "T(0.1*e1)", collide=False)
    how = {m.object: m.how for m in done.moved}
    assert how["desk"] == "moved" and how["laptop"] == "carried"
    assert done.understood.query == "T(0.1*e1)"
    assert math.isclose(obj(scene, "desk")["position"][0], x0 + 0.1, abs_tol=1e-9)
    assert math.isclose(obj(scene, "laptop")["position"][0], laptop0 + 0.1, abs_tol=1e-9)
    undone = scene.undo()
    assert undone.operation == "undo" and undone.history_id == done.history_id
    assert {m.object for m in undone.moved} == {m.object for m in done.moved}
    assert [(m.before, m.after) for m in undone.moved] == [(m.after, m.before) for m in done.moved]
    assert obj(scene, "desk")["position"][0] == x0
    assert obj(scene, "laptop")["position"][0] == laptop0
    assert scene.redo().operation == "redo" and scene.redo() is None
    assert math.isclose(obj(scene, "desk")["position"][0], x0 + 0.1, abs_tol=1e-9)
    [item] = scene.history()
    assert item["kind"] == "apply" and item["undone"] is False and "desk" in item["objects"]


def test_from_dict_takes_numpy_and_round_trips():
    np = pytest.importorskip("numpy")
    d = {
        "name": "two",
        "objects": [
            {"name": "table", "position": np.array([0.0, 0.0, 0.0]), "size": np.array([1.0, 0.75, 0.6])},
            {"name": "vase", "position": [np.float64(2.0), 0, 0], "size": [0.2, 0.3, 0.2]},
        ],
    }
    scene = shenlong.Scene.from_dict(d)
    scene.edit("put the vase on the table")
    assert obj(scene, "vase")["rests_on"] == "table"
    again = shenlong.Scene.from_dict(scene.to_dict())
    assert again.objects() == scene.objects()


def test_save_is_atomic_and_by_extension(office_path, tmp_path):
    scene = shenlong.Scene.load(office_path)
    scene.edit("move the bin 30 cm to the right")
    out = tmp_path / "edited.json"
    scene.save(out)
    assert shenlong.Scene.load(out).objects() == scene.objects()
    # .usdc is not written (USD edits go to .usda): refused, and nothing is written.
    with pytest.raises(shenlong.EditError, match="usda"):
        scene.save(tmp_path / "edited.usdc")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["edited.json"]
    # A scene JSON saved as glTF: a new glTF of its boxes, the same objects.
    scene.save(tmp_path / "edited.glb")
    boxes = {o["name"]: o["world_box"] for o in shenlong.Scene.load(tmp_path / "edited.glb").objects()}
    for o in scene.objects():
        assert all(math.isclose(a, b, abs_tol=1e-5) for a, b in zip(boxes[o["name"]]["min"], o["world_box"]["min"]))
    (tmp_path / "edited.glb").unlink()
    # A failed write leaves the old file as it was.
    before = out.read_bytes()
    with pytest.raises(shenlong.EditError):
        scene.save(tmp_path / "no-such-folder" / "x.json")
    assert out.read_bytes() == before


def test_gltf_in_and_out(tmp_path):
    path = shared("gltf/CornellBox.glb")
    # Modelled in millimetres: refused without its units, naming them.
    with pytest.raises(shenlong.EditError, match="units mm"):
        shenlong.Scene.load(path)
    scene = shenlong.Scene.load(path, units="mm")
    name = scene.objects()[0]["name"]
    scene.apply(name, "T(0.05*e1)", collide=False)
    scene.save(tmp_path / "moved.glb")
    moved = shenlong.Scene.load(tmp_path / "moved.glb", units="mm")
    assert math.isclose(
        obj(moved, name)["world_box"]["min"][0], obj(scene, name)["world_box"]["min"][0], abs_tol=1e-5
    )


def test_procthor_house_and_assets_as_dicts():
    houses = shared("procthor/houses.jsonl")
    assets = json.loads(shared("procthor/asset-database.json").read_text())
    with open(houses, encoding="utf-8") as f:
        house = json.loads(f.readline())
    scene = shenlong.Scene.from_procthor(house, assets)
    objects = scene.objects()
    assert len(objects) > 5
    assert all(o["world_box"]["max"][1] > o["world_box"]["min"][1] for o in objects)
    with pytest.raises(shenlong.EditError):
        shenlong.Scene.from_procthor({"rooms": "no"}, assets)


def test_eval_gives_translation_rotation_scale():
    t = shenlong.eval("T(e1)*R(e12, pi/2)")
    assert t["translation"] == pytest.approx([1, 0, 0], abs=1e-12)
    assert t["rotation"] == pytest.approx([0, 0, math.sqrt(0.5), math.sqrt(0.5)], abs=1e-12)
    assert t["scale"] == pytest.approx(1.0)
    assert shenlong.eval("D(2)")["scale"] == pytest.approx(2.0)
    with pytest.raises(shenlong.EditError, match="column"):
        shenlong.eval("T(e1 +")
    with pytest.raises(shenlong.EditError, match="transformation"):
        shenlong.eval("e1 + e2")


def test_threads_edit_two_scenes_at_once(office_path):
    a, b = shenlong.Scene.load(office_path), shenlong.Scene.load(SCENES / "kitchen_chairs.json")

    def push(scene, name, n):
        for _ in range(n):
            scene.apply(name, "T(0.01*e1)", collide=False)
        return obj(scene, name)["position"][0]

    xa, xb = obj(a, "bin")["position"][0], obj(b, b.objects()[0]["name"])["position"][0]
    with ThreadPoolExecutor(2) as pool:
        fa = pool.submit(push, a, "bin", 30)
        fb = pool.submit(push, b, b.objects()[0]["name"], 30)
        assert fa.result() == pytest.approx(xa + 0.3, abs=1e-9)
        assert fb.result() == pytest.approx(xb + 0.3, abs=1e-9)


def test_the_gil_is_released_during_long_work(tmp_path):
    """While a benchmark runs in another thread, this thread keeps running Python."""
    suite = REPO / "bench" / "holdout2" / "holdout2.suite.json"
    ticks = 0
    worker = threading.Thread(
        target=shenlong.bench, args=(suite, tmp_path / "run"), kwargs={"collide": True}
    )
    start = time.perf_counter()
    worker.start()
    while worker.is_alive():
        ticks += 1
    elapsed = time.perf_counter() - start
    worker.join()
    assert elapsed > 0.2, "the run was too short to tell"
    # Holding the GIL, the loop would get a handful of switch intervals (5 ms) at most.
    assert ticks > 10_000, f"{ticks} iterations in {elapsed:.2f} s"


def test_bench_writes_the_cli_folder_and_resumes(tmp_path):
    suite = REPO / "bench" / "holdout2" / "holdout2.suite.json"
    seen = []
    report = shenlong.bench(suite, tmp_path, collide=True, limit=20, progress=lambda d, t: seen.append((d, t)))
    assert report["systems"]["cga"]["overall"]["n"] == 20
    assert {"results.jsonl", "run.json", "report.json", "report.md", "success.svg"} <= {
        p.name for p in tmp_path.iterdir()
    }
    assert seen and seen[-1][0] == seen[-1][1]
    lines = (tmp_path / "results.jsonl").read_text().splitlines()
    again = shenlong.bench(suite, tmp_path, collide=True, limit=20)
    assert (tmp_path / "results.jsonl").read_text().splitlines() == lines
    assert again["systems"]["cga"]["overall"]["success_rate"] == report["systems"]["cga"]["overall"]["success_rate"]
    with pytest.raises(shenlong.EditError, match="shard"):
        shenlong.bench(suite, tmp_path / "x", shard=(3, 2))
    with pytest.raises(shenlong.EditError, match="unknown system"):
        shenlong.bench(suite, tmp_path / "y", system="cga,matrix")


USD_ROOM = """#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 0.01
    upAxis = "Z"
)

def Xform "World"
{
    def Xform "Table"
    {
        def Cube "Top"
        {
            double size = 80
            double3 xformOp:translate = (0, 0, 40)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
    }

    def Cube "Vase"
    {
        double size = 20
        double3 xformOp:translate = (200, 0, 10)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"""


def test_a_usd_stage_is_read_edited_and_saved(tmp_path):
    src = tmp_path / "room.usda"
    src.write_text(USD_ROOM)
    scene = shenlong.Scene.load(str(src))
    assert sorted(o["name"] for o in scene.objects()) == ["Table", "Vase"]
    # A Z-up centimetre stage in Shenlong's Y-up metres: the table is 0.8 m tall.
    assert math.isclose(obj(scene, "Table")["world_box"]["max"][1], 0.8, abs_tol=1e-9)
    scene.edit("put the vase on the table", llm="offline", system="cga", collide=True)
    vase = obj(scene, "Vase")
    assert math.isclose(vase["world_box"]["min"][1], 0.8, abs_tol=1e-6)
    out = tmp_path / "edited.usda"
    scene.save(str(out))
    again = shenlong.Scene.load(str(out))
    assert math.isclose(obj(again, "Vase")["world_box"]["min"][1], 0.8, abs_tol=1e-6)
    assert 'upAxis = "Z"' in out.read_text()


def test_one_scene_used_from_several_threads_takes_turns(office_path):
    import threading

    scene = shenlong.Scene.load(office_path)
    errors = []

    def work(k):
        try:
            for _ in range(5):
                scene.apply(scene.objects()[k]["name"], "T(0.001*e2)", collide=False)
                scene.objects()
        except Exception as exc:  # noqa: BLE001 - any failure fails the test
            errors.append(exc)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert errors == []
    assert len(scene.history()) == 20
