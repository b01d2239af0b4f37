"""Hostile USD stages read inside the user's interpreter: each raises a Shenlong error in
one line and the interpreter goes on (a stage is read in a child process with a time and
memory budget, so a crash there cannot take this one down)."""

import os

import pytest

import shenlong

HEADER = '#usda 1.0\n(\n    defaultPrim = "World"\n    metersPerUnit = 1\n    upAxis = "Y"\n)\n'


def deep_layer(depth: int) -> str:
    text = HEADER + 'def Xform "World"\n{\n'
    text += "".join(f'def Xform "P{k}" {{\n' for k in range(depth))
    text += 'def Cube "A" {}\n' + "}\n" * depth + "}\n"
    return text


def test_a_deep_layer_behind_a_sublayer_raises_and_the_interpreter_goes_on(tmp_path):
    (tmp_path / "deep.usda").write_text(deep_layer(30_000))
    top = tmp_path / "top.usda"
    top.write_text('#usda 1.0\n(\n    subLayers = [\n        @./deep.usda@\n    ]\n)\n')
    with pytest.raises(shenlong.EditError) as e:
        shenlong.Scene.load(top)
    assert len(str(e.value).splitlines()) == 1
    # The same nesting named directly is refused before it is parsed, saying where.
    with pytest.raises(shenlong.EditError, match="nesting deeper than 100 levels"):
        shenlong.Scene.load(tmp_path / "deep.usda")
    # And the interpreter reads a good stage afterwards.
    good = tmp_path / "good.usda"
    good.write_text(HEADER + 'def Xform "World"\n{\n    def Cube "A"\n    {\n    }\n}\n')
    assert [o["name"] for o in shenlong.Scene.load(good).objects()] == ["A"]


def test_exponential_composition_raises_in_bounded_time(tmp_path, monkeypatch):
    monkeypatch.setenv("SHENLONG_USD_SECONDS", "3")
    text = HEADER + 'def Xform "World"\n{\n    def Cube "A" (\n        references = [</L1>, </L1>]\n    )\n    {\n    }\n}\n'
    for level in range(1, 24):
        text += f'def Xform "L{level}" (\n    references = [</L{level + 1}>, </L{level + 1}>]\n)\n{{\n    def Cube "C{level}"\n    {{\n    }}\n}}\n'
    text += 'def Xform "L24"\n{\n}\n'
    path = tmp_path / "exp.usda"
    path.write_text(text)
    with pytest.raises(shenlong.EditError, match="more than 3 s"):
        shenlong.Scene.load(path)
