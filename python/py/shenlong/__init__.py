"""Shenlong: edit 3D scenes by plain instruction.

Native bindings of the Shenlong library (the same code as the ``shenlong`` command):
grounding words to objects, translating instructions into Conformal Geometric Algebra,
evaluating them safely, resolving collisions and writing scenes back. See docs/python.md.

>>> import shenlong
>>> scene = shenlong.Scene.load("room.json")
>>> report = scene.edit("put the mug on the dresser")
>>> scene.save("edited.json")
"""

from __future__ import annotations

import json as _json
import os as _os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

from . import _native
from ._native import EditError

__all__ = ["Scene", "EditError", "eval", "bench", "bench_merge", "__version__"]

__version__: str = _native.__version__

PathLike = Union[str, "_os.PathLike[str]"]


def _plain(value: Any) -> Any:
    """JSON for what ``json`` does not know: numpy arrays and scalars (``tolist``/``item``)."""
    for method in ("tolist", "item"):
        f = getattr(value, method, None)
        if callable(f):
            return f()
    raise TypeError(f"{type(value).__name__} is not a number, string, list or dict")


def _dumps(value: Any, what: str) -> str:
    try:
        return _json.dumps(value, default=_plain, allow_nan=False)
    except (TypeError, ValueError) as e:
        raise EditError(f"{what}: {e}") from None


class Scene:
    """A scene of separate objects being edited, with undo and redo.

    Made with :meth:`load`, :meth:`from_dict` or :meth:`from_procthor`. Edits change the
    scene in place; a refusal or bad input raises :class:`EditError` and leaves the scene
    exactly as it was. Methods release the GIL while they work, so threads may edit
    different scenes at once (one scene is not to be edited by two threads at once).
    """

    __slots__ = ("_inner",)

    def __init__(self, inner: "_native.Scene") -> None:
        self._inner = inner

    # -- making a scene -------------------------------------------------------------

    @classmethod
    def load(
        cls, path: PathLike, units: Optional[str] = None, front: Optional[str] = None
    ) -> "Scene":
        """Reads a scene file: scene JSON (``.json``), glTF (``.gltf``, ``.glb``), USD
        (``.usda``, ``.usdc``, ``.usdz``). For a glTF or USD file whose own conventions are
        missing or wrong: ``units`` (``"mm"``, ``"cm"``, ``"m"``, ``"in"``, ``"ft"``; a file
        whose furniture is tens of metres across is refused without it) and ``front`` (the
        axis its models face in the file's own frame: ``"+z"``, ``"-y"`` …)."""
        return cls(_native.Scene.load(_os.fspath(path), units, front))

    @classmethod
    def from_dict(cls, scene: Mapping[str, Any], name: str = "scene") -> "Scene":
        """A scene from a SPEC scene as a dict (numpy arrays accepted as vectors)."""
        return cls(_native.Scene.from_json(_dumps(scene, "the scene"), name))

    @classmethod
    def from_procthor(cls, house: Mapping[str, Any], assets: Mapping[str, Any]) -> "Scene":
        """A ProcTHOR / Holodeck house dict, with the asset database dict that gives the
        sizes of its assets (``asset-database.json``)."""
        return cls(
            _native.Scene.from_procthor(
                _dumps(house, "the house"), _dumps(assets, "the asset database")
            )
        )

    # -- looking ----------------------------------------------------------------------

    @property
    def name(self) -> str:
        """The scene's name."""
        return self._inner.name

    def __len__(self) -> int:
        return self._inner.len()

    def __repr__(self) -> str:
        return f"<shenlong.Scene {self.name!r} with {len(self)} objects>"

    def objects(self) -> List[Dict[str, Any]]:
        """Every object: name, position, rotation (x, y, z, w), scale, size, world_box
        {min, max} and rests_on (the name of its support, or None)."""
        return _json.loads(self._inner.objects_json())

    def to_dict(self) -> Dict[str, Any]:
        """The scene as a SPEC scene dict (what :meth:`save` writes to ``.json``)."""
        return _json.loads(self._inner.to_json())

    def history(self) -> List[Dict[str, Any]]:
        """The changes made, oldest first: id, kind (edit or apply), text, objects, undone."""
        return _json.loads(self._inner.history_json())

    # -- changing ---------------------------------------------------------------------

    def edit(
        self,
        instruction: str,
        llm: str = "offline",
        system: str = "cga",
        collide: bool = True,
        carry: bool = True,
        selected: Optional[Sequence[str]] = None,
    ) -> Dict[str, Any]:
        """Runs an instruction, as ``shenlong edit`` does, and returns its report (the
        dict ``shenlong edit --json`` writes).

        ``llm`` is ``offline`` (built in), ``openai:MODEL``, ``ollama:MODEL``,
        ``replay:FILE`` or a cascade ``offline+openai:MODEL``; ``system`` is ``cga``,
        ``euclidean`` or ``omniverse``; ``selected`` names the objects "it" or "them"
        mean when nothing is named before them.
        """
        return _json.loads(
            self._inner.edit(instruction, llm, system, collide, carry, list(selected or []))
        )

    def apply(self, name: str, expr: str, collide: bool = True, carry: bool = True) -> Dict[str, Any]:
        """Applies one CGA expression (``X1`` is the object) to the object ``name``,
        carrying what rests on it and resolving collisions as ``shenlong apply`` does.
        Returns what moved and what collision resolution adjusted."""
        return _json.loads(self._inner.apply(name, expr, collide, carry))

    def undo(self) -> bool:
        """Undoes the last change; False when there is nothing to undo."""
        return self._inner.undo()

    def redo(self) -> bool:
        """Redoes the last undone change; False when there is nothing to redo."""
        return self._inner.redo()

    def save(self, path: PathLike) -> None:
        """Writes the scene atomically, the format by extension (``.json``; ``.gltf`` or
        ``.glb`` for a scene read from glTF; ``.tdw.json`` for ThreeDWorld commands)."""
        self._inner.save(_os.fspath(path))


def eval(expr: str) -> Dict[str, Any]:  # noqa: A001 - the name of the CLI's command
    """Evaluates a CGA expression with no objects into a versor M = T·R·D: a dict with
    translation [x, y, z], rotation [x, y, z, w], scale and the expression as read."""
    return _json.loads(_native.eval_json(expr))


def bench(
    suite: PathLike,
    out: PathLike,
    llm: str = "offline",
    system: Union[str, Sequence[str]] = "cga",
    collide: bool = False,
    limit: Optional[int] = None,
    jobs: int = 1,
    shard: Optional[Tuple[int, int]] = None,
    progress: Optional[Callable[[int, int], None]] = None,
) -> Dict[str, Any]:
    """Runs a benchmark suite as ``shenlong bench SUITE --out OUT`` does (results, run.json,
    report.json, report.md and charts in ``out``; resumable) and returns the report.
    ``shard=(k, n)`` runs shard k of n (1-based), as ``--shard K/N``; ``progress(done,
    total)`` is called as instances finish."""
    systems = system if isinstance(system, str) else ",".join(system)
    return _json.loads(
        _native.bench_json(
            _os.fspath(suite), _os.fspath(out), llm, systems, collide, limit, jobs, shard, progress
        )
    )


def bench_merge(dirs: Sequence[PathLike], out: PathLike) -> Dict[str, Any]:
    """Builds one report from the folders of several runs of one comparison (its shards),
    as ``shenlong bench --merge DIR... --out OUT`` does, and returns it. Shards missing
    from ``dirs`` are named in the report's ``missing_shards``."""
    return _json.loads(_native.bench_merge_json([_os.fspath(d) for d in dirs], _os.fspath(out)))
