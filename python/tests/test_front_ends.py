"""One outcome, one shape: the same edit, apply, refusal and undo through the CLI's
``--json``, the HTTP API (``shenlong serve``), MCP (the official Python SDK as the client)
and this package answer the same JSON.

Each front end starts from its own copy of one scene file and runs the same steps; the
answers are compared whole, except the full edit ``report`` (timings differ) and, for the
CLI, whose every call is a session of its own, the history ids and the undo it cannot do.
"""

from __future__ import annotations

import asyncio
import json
import os
import re
import shutil
import subprocess
import urllib.error
import urllib.request

import pytest

import shenlong

SCENE = {
    "name": "studio",
    "objects": [
        {"name": "desk", "position": [0, 0, 0], "size": [1.4, 0.75, 0.7]},
        {"name": "lamp", "position": [0.5, 0.75, 0], "size": [0.2, 0.45, 0.2]},
        {"name": "chair 1", "position": [-1.5, 0, 1.2], "size": [0.5, 0.9, 0.5]},
        {"name": "chair 2", "position": [1.5, 0, 1.2], "size": [0.5, 0.9, 0.5]},
        {"name": "bookcase", "position": [-2.5, 0, -1.5], "size": [0.9, 1.8, 0.35]},
    ],
}

EDIT = "move the desk 30 cm to the left"
REFUSED = "move the chair 20 cm forward"
APPLY = ("bookcase", "T(0.25*e1)")
STEPS = ["edit", "refusal", "apply", "undo"]


def binary() -> str:
    path = os.environ.get("SHENLONG_BIN")
    if not path or not os.path.exists(path):
        pytest.skip("SHENLONG_BIN (the shenlong command) is not set")
    return path


def comparable(answer: dict) -> dict:
    """An answer without what differs by nature: the full report (timings)."""
    return {k: v for k, v in answer.items() if k != "report"}


# -- the four front ends -------------------------------------------------------------


def through_python(scene_path) -> list:
    scene = shenlong.Scene.load(scene_path)
    answers = [scene.edit(EDIT).to_dict()]
    with pytest.raises(shenlong.AmbiguousError) as e:
        scene.edit(REFUSED)
    answers.append(e.value.data)
    answers.append(scene.apply(*APPLY).to_dict())
    answers.append(scene.undo().to_dict())
    return answers


def through_cli(scene_path, tmp_path) -> list:
    bin_ = binary()
    edited = tmp_path / "cli-edited.json"

    def run(argv, ok=True):
        done = subprocess.run([bin_, *argv, "--json", "-"], capture_output=True, text=True, check=False)
        assert (done.returncode == 0) == ok, done.stderr
        return json.loads(done.stderr.strip().splitlines()[0] if not ok else done.stderr)

    answers = [run(["edit", str(scene_path), EDIT, "-o", str(edited)])]
    answers.append(run(["edit", str(edited), REFUSED, "-o", str(tmp_path / "never.json")], ok=False))
    assert not (tmp_path / "never.json").exists(), "nothing is written on a refusal"
    answers.append(
        run(["apply", str(edited), "--object", APPLY[0], "--expr", APPLY[1], "-o", str(tmp_path / "cli-applied.json")])
    )
    return answers


def http_calls(scene_path, calls) -> list:
    """`(path, body)` POSTed in turn to `shenlong serve` on a copy of the scene: each
    answer's status and JSON."""
    proc = subprocess.Popen(
        [binary(), "serve", str(scene_path), "--addr", "127.0.0.1:0"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
    )
    try:
        line = proc.stderr.readline()
        match = re.search(r"http://(127\.0\.0\.1:\d+)/", line)
        assert match, line
        base = f"http://{match.group(1)}"
        answers = []
        for path, body in calls:
            request = urllib.request.Request(
                base + path, data=json.dumps(body).encode(), method="POST",
                headers={"Content-Type": "application/json"},
            )
            try:
                with urllib.request.urlopen(request, timeout=30) as response:
                    answers.append((response.status, json.loads(response.read())))
            except urllib.error.HTTPError as e:
                answers.append((e.code, json.loads(e.read())))
        return answers
    finally:
        proc.terminate()
        proc.wait(timeout=10)


def mcp_calls(scene_path, calls) -> list:
    """`(tool, arguments)` called in turn on `shenlong mcp` with the official SDK: each
    result's `is_error` and structured content."""
    mcp = pytest.importorskip("mcp")
    from mcp.client.stdio import StdioServerParameters, stdio_client

    async def session_answers():
        params = StdioServerParameters(command=binary(), args=["mcp", str(scene_path)])
        async with stdio_client(params) as (read, write):
            async with mcp.ClientSession(read, write) as session:
                await session.initialize()
                answers = []
                for tool, arguments in calls:
                    result = await session.call_tool(tool, arguments)
                    answers.append((result.is_error, result.structured_content))
                return answers

    return asyncio.run(session_answers())


def through_http(scene_path) -> list:
    steps = [
        ("/api/edit", {"instruction": EDIT}, 200),
        ("/api/edit", {"instruction": REFUSED}, 422),
        ("/api/apply", {"object": APPLY[0], "expression": APPLY[1]}, 200),
        ("/api/undo", {}, 200),
    ]
    answers = http_calls(scene_path, [(path, body) for path, body, _ in steps])
    for (path, _, status), (got, answer) in zip(steps, answers):
        assert got == status, (path, answer)
    return [answer for _, answer in answers]


def through_mcp(scene_path) -> list:
    steps = [
        ("edit", {"instruction": EDIT}, False),
        ("edit", {"instruction": REFUSED}, True),
        ("apply", {"object": APPLY[0], "expression": APPLY[1]}, False),
        ("undo", {}, False),
    ]
    answers = mcp_calls(scene_path, [(tool, arguments) for tool, arguments, _ in steps])
    for (_, _, error), (is_error, content) in zip(steps, answers):
        assert is_error == error, content
    return [content for _, content in answers]


# -- the comparison ------------------------------------------------------------------


def test_every_front_end_answers_the_same_outcome(tmp_path):
    original = tmp_path / "studio.json"
    original.write_text(json.dumps(SCENE))
    copies = {}
    for name in ("python", "cli", "http", "mcp"):
        copies[name] = tmp_path / f"{name}.json"
        shutil.copy(original, copies[name])

    python = [comparable(a) for a in through_python(copies["python"])]
    http = [comparable(a) for a in through_http(copies["http"])]
    mcp = [comparable(a) for a in through_mcp(copies["mcp"])]
    cli = [comparable(a) for a in through_cli(copies["cli"], tmp_path)]

    # What the steps did, read from the package's answers.
    edit, refusal, apply, undo = python
    assert [m["object"] for m in edit["moved"]] == ["desk", "lamp"]
    assert [m["how"] for m in edit["moved"]] == ["moved", "carried"]
    assert edit["moved"][0]["after"]["position"] == pytest.approx([-0.3, 0, 0])
    assert refusal["kind"] == "ambiguous"
    assert [c["object"] for c in refusal["ambiguity"]["choices"]] == ["chair 1", "chair 2"]
    assert apply["understood"] == {"query": APPLY[1], "bindings": [{"variable": "X1", "object": "bookcase"}]}
    assert undo["operation"] == "undo" and undo["history_id"] == apply["history_id"]
    assert [m["object"] for m in undo["moved"]] == ["bookcase"]

    for step, p, h, m in zip(STEPS, python, http, mcp):
        assert h == p, f"HTTP's {step} differs from Python's"
        assert m == p, f"MCP's {step} differs from Python's"
    # The CLI: each call a session of its own (history ids start again; no undo).
    for step, p, c in zip(STEPS, python, cli):
        strip = lambda a: {k: v for k, v in a.items() if k != "history_id"}  # noqa: E731
        assert strip(c) == strip(p), f"the CLI's {step} differs from Python's"
    assert len(cli) == 3


# -- a conversation through each front end -------------------------------------------

TURNS = [
    "move the desk 30 cm to the left",
    "a bit more",
    "move the chair 20 cm forward",  # refused: which chair?
    "the left one",
    "no, the other one",
    "and the bookcase too",
    "put it back",
    "undo that",
    "move it 10 cm to the right",
    "put the lamp on the bookcase",
    "no, on the desk",
]


def python_turns(scene_path) -> list:
    scene = shenlong.Scene.load(scene_path)
    answers = []
    for turn in TURNS:
        try:
            answers.append(scene.edit(turn).to_dict())
        except shenlong.EditError as e:
            answers.append(e.data)
    return answers


def chat_turns(scene_path) -> list:
    done = subprocess.run(
        [binary(), "chat", str(scene_path), "--json"], input="\n".join(TURNS) + "\n",
        capture_output=True, text=True, check=False,
    )
    assert done.returncode == 1, "a turn was refused: " + done.stderr
    return [json.loads(line) for line in done.stdout.splitlines()]


def http_turns(scene_path) -> list:
    return [answer for _, answer in http_calls(scene_path, [("/api/edit", {"instruction": t}) for t in TURNS])]


def mcp_turns(scene_path) -> list:
    return [content for _, content in mcp_calls(scene_path, [("edit", {"instruction": t}) for t in TURNS])]


def test_every_front_end_holds_the_same_conversation(tmp_path):
    original = tmp_path / "studio.json"
    original.write_text(json.dumps(SCENE))
    answers = {}
    for name, run in [("python", python_turns), ("chat", chat_turns), ("http", http_turns), ("mcp", mcp_turns)]:
        copy = tmp_path / f"{name}.json"
        shutil.copy(original, copy)
        answers[name] = [comparable(a) for a in run(copy)]

    desk, more, refused, left, other, bookcase, back, undo, it, lamp, instead = answers["python"]
    assert desk["moved"][0]["after"]["position"] == pytest.approx([-0.3, 0, 0])
    assert more["moved"][0]["after"]["position"] == pytest.approx([-0.4, 0, 0]), "10 cm more"
    assert refused["kind"] == "ambiguous"
    assert [(m["object"], m["after"]["position"]) for m in left["moved"]] == [("chair 1", pytest.approx([-1.5, 0, 1.4]))]
    assert [(m["object"], m["after"]["position"]) for m in other["moved"]] == [
        ("chair 1", pytest.approx([-1.5, 0, 1.2])),
        ("chair 2", pytest.approx([1.5, 0, 1.4])),
    ], "the other chair instead"
    assert bookcase["moved"][0]["object"] == "bookcase"
    assert bookcase["moved"][0]["after"]["position"] == pytest.approx([-2.5, 0, -1.3])
    assert back["moved"][0]["after"]["position"] == pytest.approx([-2.5, 0, -1.5]), "the bookcase is back"
    assert undo["operation"] == "undo"
    assert it["moved"][0]["object"] == "bookcase"
    assert lamp["moved"][0]["after"]["position"][1] == pytest.approx(1.8), "on the bookcase"
    assert instead["moved"][0]["object"] == "lamp"
    assert instead["moved"][0]["after"]["position"][1] == pytest.approx(0.75), "on the desk instead"
    for name in ("chat", "http", "mcp"):
        assert answers[name] == answers["python"], f"{name}'s conversation differs from Python's"
