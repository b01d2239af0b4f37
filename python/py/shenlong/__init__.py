"""Shenlong: edit 3D scenes by plain instruction.

Native bindings of the Shenlong library (the same code as the ``shenlong`` command):
grounding words to objects, translating instructions into Conformal Geometric Algebra,
evaluating them safely, resolving collisions and writing scenes back. See docs/python.md.

>>> import shenlong
>>> scene = shenlong.Scene.load("room.json")
>>> outcome = scene.edit("put the mug on the dresser")
>>> [m.object for m in outcome.moved]
['mug']
>>> scene.save("edited.json")
"""

from __future__ import annotations

import functools as _functools
import json as _json
import os as _os
from dataclasses import dataclass
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

from . import _native
from ._native import EditError

__all__ = [
    "Scene",
    "Outcome",
    "Moved",
    "Pose",
    "Binding",
    "Understood",
    "Choice",
    "EditError",
    "BadInputError",
    "NotUnderstoodError",
    "AmbiguousError",
    "NoFreePlaceError",
    "HeldObjectError",
    "ModelError",
    "ExportError",
    "InternalError",
    "eval",
    "bench",
    "bench_merge",
    "__version__",
]

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
        raise BadInputError(f"{what}: {e}") from None


# -- what an operation did ------------------------------------------------------------


@dataclass(frozen=True)
class Pose:
    """An object's pose as the scene file writes it: translation (metres), rotation
    (quaternion x, y, z, w) and uniform scale."""

    position: Tuple[float, float, float]
    rotation: Tuple[float, float, float, float]
    scale: float

    @classmethod
    def _from(cls, d: Mapping[str, Any]) -> "Pose":
        return cls(tuple(d["position"]), tuple(d["rotation"]), d["scale"])  # type: ignore[arg-type]


@dataclass(frozen=True)
class Moved:
    """One object an operation moved: ``how`` is ``"moved"`` (named by the instruction or
    expression, or put back by undo/redo), ``"carried"`` (it rests on a moved object) or
    ``"pushed"`` (collision resolution moved it)."""

    object: str
    how: str
    before: Pose
    after: Pose


@dataclass(frozen=True)
class Binding:
    """A variable of the understood query and the object it stands for."""

    variable: str
    object: str


@dataclass(frozen=True)
class Understood:
    """How an instruction was read: the query with its objects as variables
    (``put X1 on X2``) and what each variable stands for; for an expression, the
    expression."""

    query: str
    bindings: List[Binding]


@dataclass(frozen=True)
class Outcome:
    """What an operation did, as the CLI's ``--json``, the HTTP API and MCP write it
    (:meth:`to_dict` gives that JSON): the operation (``edit``, ``apply``, ``undo``,
    ``redo``), its ``history_id``, every object ``moved``, how the instruction was
    ``understood``, ``notes`` (collisions cleared, objects held), ``warnings`` and, when
    asked for, the whole edit ``report``."""

    operation: str
    history_id: Optional[int]
    moved: List[Moved]
    understood: Optional[Understood]
    notes: List[str]
    warnings: List[str]
    report: Optional[Dict[str, Any]]
    _data: Dict[str, Any]

    @classmethod
    def _from_json(cls, text: str) -> "Outcome":
        d = _json.loads(text)
        u = d.get("understood")
        return cls(
            operation=d["operation"],
            history_id=d.get("history_id"),
            moved=[
                Moved(m["object"], m["how"], Pose._from(m["before"]), Pose._from(m["after"]))
                for m in d["moved"]
            ],
            understood=None
            if u is None
            else Understood(u["query"], [Binding(b["variable"], b["object"]) for b in u["bindings"]]),
            notes=list(d["notes"]),
            warnings=list(d["warnings"]),
            report=d.get("report"),
            _data=d,
        )

    def to_dict(self) -> Dict[str, Any]:
        """The outcome as every front end writes it."""
        return _json.loads(_json.dumps(self._data))


# -- why an operation was refused ----------------------------------------------------


@dataclass(frozen=True)
class Choice:
    """One object an ambiguous phrase could mean, and the instruction that names it
    (``None`` when its name cannot be quoted)."""

    object: str
    instruction: Optional[str]


class BadInputError(EditError):
    """The request is malformed: an empty or over-long instruction, an unknown object
    given by name (``selected``, ``apply``), an object bound twice."""


class NotUnderstoodError(EditError):
    """The instruction names nothing the scene has, or could not be read; or the
    expression is not a transformation."""


class AmbiguousError(EditError):
    """A phrase could mean several objects: ``phrase``, ``objects`` (the first few),
    ``total`` and ``choices`` (each object with the instruction that names it)."""

    phrase: str
    objects: List[str]
    total: int
    choices: List[Choice]


class NoFreePlaceError(EditError):
    """No collision-free placement, or only one away from where the object was put."""


class HeldObjectError(EditError):
    """The edit would move an object the instruction holds where it is."""


class ModelError(EditError):
    """The language model or its server failed, or gave no usable answer."""


class ExportError(EditError):
    """The scene cannot be written in the format asked for."""


class InternalError(EditError):
    """A bug in Shenlong, caught; the scene is as it was."""


_KINDS = {
    "bad_input": BadInputError,
    "not_understood": NotUnderstoodError,
    "ambiguous": AmbiguousError,
    "no_free_place": NoFreePlaceError,
    "held_would_move": HeldObjectError,
    "model": ModelError,
    "export": ExportError,
    "internal": InternalError,
}


def _refusal(e: EditError) -> EditError:
    """The subclass of a native refusal's kind, with its data (``kind``, ``data``, and for
    an ambiguity its choices)."""
    if len(e.args) < 2 or not isinstance(e.args[1], str):
        return e
    data = _json.loads(e.args[1])
    error = _KINDS.get(data.get("kind"), EditError)(data.get("error", e.args[0]))
    error.kind = data.get("kind")  # type: ignore[attr-defined]
    error.data = data  # type: ignore[attr-defined]
    ambiguity = data.get("ambiguity")
    if isinstance(error, AmbiguousError) and ambiguity:
        error.phrase = ambiguity["phrase"]
        error.objects = list(ambiguity["objects"])
        error.total = ambiguity["total"]
        error.choices = [Choice(c["object"], c.get("instruction")) for c in ambiguity["choices"]]
    return error


def _refusals(f: Callable[..., Any]) -> Callable[..., Any]:
    """Raises a native refusal as the subclass of its kind."""

    @_functools.wraps(f)
    def call(*args: Any, **kwargs: Any) -> Any:
        try:
            return f(*args, **kwargs)
        except EditError as e:
            raise _refusal(e) from None

    return call


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
    @_refusals
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
    @_refusals
    def from_dict(cls, scene: Mapping[str, Any], name: str = "scene") -> "Scene":
        """A scene from a SPEC scene as a dict (numpy arrays accepted as vectors)."""
        return cls(_native.Scene.from_json(_dumps(scene, "the scene"), name))

    @classmethod
    @_refusals
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

    @_refusals
    def edit(
        self,
        instruction: str,
        llm: str = "offline",
        system: str = "cga",
        collide: bool = True,
        carry: bool = True,
        selected: Optional[Sequence[str]] = None,
        report: bool = False,
        base_url: Optional[str] = None,
    ) -> Outcome:
        """Runs an instruction, as ``shenlong edit`` does, and returns its
        :class:`Outcome` (what moved, notes, how it was understood; the whole edit report
        too with ``report=True``).

        ``llm`` is ``offline`` (built in), ``openai:MODEL``, ``ollama:MODEL``,
        ``replay:FILE`` or a cascade ``offline+openai:MODEL``; ``system`` is ``cga``,
        ``euclidean`` or ``omniverse``; ``selected`` names the objects "it" or "them"
        mean when nothing is named before them; ``base_url`` is an OpenAI-compatible
        server's URL (else ``OPENAI_BASE_URL``). A refusal raises the :class:`EditError`
        subclass of its kind — :class:`AmbiguousError` carries the ``choices`` — and
        leaves the scene as it was.
        """
        return Outcome._from_json(
            self._inner.edit(
                instruction, llm, system, collide, carry, list(selected or []), report, base_url
            )
        )

    @_refusals
    def apply(
        self,
        name: str,
        expr: str,
        collide: bool = True,
        carry: bool = True,
        bind: Optional[Mapping[str, str]] = None,
    ) -> Outcome:
        """Applies one CGA expression to the object ``name`` (``X1``; ``bind`` names
        ``X2``, ``X3`` … whose boxes it may use), carrying what rests on it and resolving
        collisions as ``shenlong apply`` does. Returns its :class:`Outcome`."""
        return Outcome._from_json(self._inner.apply(name, expr, collide, carry, dict(bind or {})))

    @_refusals
    def undo(self) -> Optional[Outcome]:
        """Undoes the last change: its :class:`Outcome` (what moved back), or ``None``
        when there is nothing to undo."""
        answer = self._inner.undo()
        return None if answer is None else Outcome._from_json(answer)

    @_refusals
    def redo(self) -> Optional[Outcome]:
        """Redoes the last undone change: its :class:`Outcome`, or ``None`` when there is
        nothing to redo."""
        answer = self._inner.redo()
        return None if answer is None else Outcome._from_json(answer)

    @_refusals
    def save(self, path: PathLike) -> None:
        """Writes the scene atomically, the format by extension (``.json``; ``.gltf`` or
        ``.glb`` for a scene read from glTF; ``.tdw.json`` for ThreeDWorld commands)."""
        self._inner.save(_os.fspath(path))


@_refusals
def eval(expr: str) -> Dict[str, Any]:  # noqa: A001 - the name of the CLI's command
    """Evaluates a CGA expression with no objects into a versor M = T·R·D: a dict with
    translation [x, y, z], rotation [x, y, z, w], scale and the expression as read."""
    return _json.loads(_native.eval_json(expr))


@_refusals
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


@_refusals
def bench_merge(dirs: Sequence[PathLike], out: PathLike) -> Dict[str, Any]:
    """Builds one report from the folders of several runs of one comparison (its shards),
    as ``shenlong bench --merge DIR... --out OUT`` does, and returns it. Shards missing
    from ``dirs`` are named in the report's ``missing_shards``."""
    return _json.loads(_native.bench_merge_json([_os.fspath(d) for d in dirs], _os.fspath(out)))
