"""The add-on's work, apart from Blender's user interface: which objects Shenlong sees, the
frame conversion, editing them with the `shenlong` package (in this process: the
extension carries its wheel), and applying its motions exactly.

Frame. Blender is right-handed with +Z up and objects facing −Y; Shenlong (like glTF) is
right-handed with +Y up. The add-on converts exactly as Blender's own glTF exporter does:
Shenlong `(x, y, z)` = Blender `(x, z, −y)`. So Shenlong's "forward" (−Z in its frame,
towards the viewer of a front view) is Blender's −Y, "up" is +Z, and a counter-clockwise
turn seen from above is a positive rotation about Blender's +Z.

Objects. Every visible mesh object of the view layer that is not below another such mesh
in the parent hierarchy is one Shenlong object (children move with their parent through
Blender's hierarchy); a selected mesh is always one, wherever it is. Its box is the world
bounding box of its evaluated mesh (modifiers count), and its pivot the bottom centre of
that box, as Shenlong's scene JSON defines it.

Nothing here starts a process, writes a file or executes anything Shenlong (or a model)
says: the package is called with the objects' boxes, and what comes back is numbers.
"""

from __future__ import annotations

from dataclasses import dataclass, field

# Only mathutils is needed here (it comes with Blender and with the bpy module).
from mathutils import Matrix, Quaternion, Vector

#: Blender → Shenlong: (x, y, z) ↦ (x, z, −y).
TO_SHENLONG = Matrix(((1.0, 0.0, 0.0), (0.0, 0.0, 1.0), (0.0, -1.0, 0.0)))
#: Shenlong → Blender, the inverse (and transpose) of [`TO_SHENLONG`].
TO_BLENDER = TO_SHENLONG.transposed()


class ShenlongError(Exception):
    """An edit that was refused or could not run: one line for the user."""


def to_shenlong(v) -> Vector:
    """A Blender vector in Shenlong's frame."""
    return TO_SHENLONG @ Vector(v)


def to_blender(v) -> Vector:
    """A Shenlong vector in Blender's frame."""
    return TO_BLENDER @ Vector(v)


@dataclass
class SceneObject:
    """One Blender object as Shenlong sees it."""

    name: str
    #: Its world box in Blender's frame (min, max corners).
    box_min: Vector
    box_max: Vector
    #: The direction it faces in Blender's world (its local −Y), unit length.
    front: Vector


@dataclass
class Motion:
    """What Shenlong did to one object: the world-frame motion in Blender's coordinates,
    and the box Shenlong computed for it afterwards."""

    name: str
    matrix: Matrix
    box_min: Vector
    box_max: Vector


@dataclass
class EditResult:
    """The outcome of one edit."""

    motions: list[Motion]
    report: dict
    summary: list[str] = field(default_factory=list)


def package():
    """The `shenlong` package: bundled with the extension as a wheel (Blender installs it),
    or installed in the Python that runs `bpy`."""
    try:
        import shenlong
    except ImportError as e:
        raise ShenlongError(
            f"the shenlong package is not installed ({e}); install the extension's zip, "
            "which carries it"
        ) from None
    return shenlong


def world_box(obj, depsgraph):
    """The world bounding box (Blender frame) of the object's evaluated mesh, or None
    when it has no vertices."""
    evaluated = obj.evaluated_get(depsgraph)
    mesh = evaluated.to_mesh()
    try:
        if len(mesh.vertices) == 0:
            return None
        matrix = evaluated.matrix_world
        points = [matrix @ v.co for v in mesh.vertices]
    finally:
        evaluated.to_mesh_clear()
    return bounds(points)


def editable_objects(view_layer, selected=()):
    """The objects Shenlong edits: every visible mesh not below another visible mesh in
    the hierarchy, and every selected mesh. Parents come before their children."""
    meshes = [o for o in view_layer.objects if o.type == "MESH" and o.visible_get()]
    visible = set(meshes)
    chosen = set()
    for o in meshes:
        parent, below_mesh = o.parent, False
        while parent is not None:
            if parent in visible:
                below_mesh = True
                break
            parent = parent.parent
        if not below_mesh or o in selected:
            chosen.add(o)

    return sorted(chosen, key=lambda o: (depth(o), o.name))


def describe(objects, depsgraph) -> list[SceneObject]:
    """The Shenlong view of the objects (those without geometry are left out)."""
    out = []
    for o in objects:
        box = world_box(o, depsgraph)
        if box is None:
            continue
        front = o.matrix_world.to_3x3() @ Vector((0.0, -1.0, 0.0))
        if front.length < 1e-9:
            front = Vector((0.0, -1.0, 0.0))
        out.append(SceneObject(o.name, box[0], box[1], front.normalized()))
    lowered = {}
    for s in out:
        other = lowered.setdefault(s.name.lower(), s.name)
        if other != s.name:
            raise ShenlongError(
                f"'{other}' and '{s.name}' differ only in case, which Shenlong does not "
                "tell apart: rename one"
            )
    return out


def scene_json(objects: list[SceneObject], name: str = "blender") -> dict:
    """A Shenlong scene (SPEC §2) of axis-aligned boxes, in Shenlong's frame."""
    entries = []
    for s in objects:
        lo, hi = bounds(to_shenlong(c) for c in box_corners(s.box_min, s.box_max))
        size = hi - lo
        # A flat mesh (a plane) gets a hair of thickness: a box's size must be > 0.
        size = Vector([max(c, 1e-6) for c in size])
        bottom = Vector(((lo.x + hi.x) / 2.0, lo.y, (lo.z + hi.z) / 2.0))
        front = to_shenlong(s.front)
        entries.append(
            {
                "name": s.name,
                "size": list(size),
                "position": list(bottom),
                "front": list(front),
            }
        )
    return {"name": name, "objects": entries}


def bounds(points):
    """The low and high corners of the axis-aligned box around the points."""
    points = list(points)
    lo = Vector((min(p.x for p in points), min(p.y for p in points), min(p.z for p in points)))
    hi = Vector((max(p.x for p in points), max(p.y for p in points), max(p.z for p in points)))
    return lo, hi


def depth(obj) -> int:
    """How many parents the object has."""
    d = 0
    while obj.parent is not None:
        d, obj = d + 1, obj.parent
    return d


def box_corners(lo, hi):
    return [Vector((x, y, z)) for x in (lo.x, hi.x) for y in (lo.y, hi.y) for z in (lo.z, hi.z)]


class Conversation:
    """The `shenlong.Scene` kept from one edit to the next, so that a follow-up ("a bit
    more", "put it back", "and the lamp too") leans on the turn before. It holds while the
    objects stand exactly where the last edit left them; once anything is moved, added or
    undone in Blender, the next edit starts a new conversation from the scene as it is."""

    def __init__(self):
        self.scene = None
        self.entries: dict = {}
        self.left: dict | None = None

    def scene_for(self, objects: list[SceneObject], matrices: dict):
        """The conversation's scene when `matrices` (each object's world matrix, by name)
        are those the last edit left; otherwise a new one of `objects`."""
        if self.scene is not None and self.left == matrices:
            return self.scene
        described = scene_json(objects)
        self.scene = package().Scene.from_dict(described)
        self.entries = {o["name"]: o for o in described["objects"]}
        self.left = matrices
        return self.scene

    def left_as(self, matrices: dict) -> None:
        """Remembers where the edit left the objects."""
        self.left = matrices


CONVERSATION = Conversation()


def matrices_of(objects) -> dict:
    """Each object's world matrix, by name, as plain numbers."""
    return {o.name: tuple(tuple(row) for row in o.matrix_world) for o in objects}


def run_edit(
    objects: list[SceneObject],
    instruction: str,
    *,
    llm: str = "offline",
    system: str = "cga",
    base_url: str | None = None,
    selection: tuple[str, ...] = (),
    matrices: dict | None = None,
) -> EditResult:
    """Edits the objects with the `shenlong` package, in this process, and returns each
    moved object's motion. With `matrices` (the objects' world matrices, by name) the edit
    continues the conversation when nothing moved since the last one.

    Raises ShenlongError with Shenlong's one-line message on a refusal or failure; the
    Blender scene is never touched here.
    """
    if not instruction.strip():
        raise ShenlongError("type an instruction first")
    if "\x00" in instruction:
        raise ShenlongError("the instruction contains a NUL character; retype it")
    if not objects:
        raise ShenlongError("there are no visible mesh objects to edit")
    shenlong = package()
    if matrices is None:
        CONVERSATION.__init__()
    scene = CONVERSATION.scene_for(objects, matrices if matrices is not None else {})
    try:
        outcome = scene.edit(
            instruction,
            llm=llm,
            system=system,
            selected=list(selection),
            report=True,
            base_url=base_url,
        )
    except shenlong.EditError as e:
        raise ShenlongError(str(e).splitlines()[0] if str(e) else type(e).__name__) from None
    motions = []
    for moved in outcome.moved:
        motion = motion_of(CONVERSATION.entries[moved.object], moved.object, moved.after, moved.before)
        if motion is not None:
            motions.append(motion)
    return EditResult(motions, outcome.report or {}, summarise(outcome.report or {}))


def pose_matrix(entry: dict, pose) -> Matrix:
    """The world matrix (Blender frame) that takes the box of `entry` — as Shenlong was
    first given it, unrotated and unscaled at `p0` — to the pose `pose` (a `shenlong.Pose`):
    `x ↦ s·q(x − p0) + t`, in Blender's frame `C⁻¹ · that · C`."""
    p0 = Vector(entry["position"])
    t = Vector(pose.position)
    x, y, z, w = pose.rotation
    q = Quaternion((w, x, y, z)).normalized()
    linear = TO_BLENDER @ (q.to_matrix() * float(pose.scale)) @ TO_SHENLONG
    return Matrix.Translation(to_blender(t)) @ linear.to_4x4() @ Matrix.Translation(-to_blender(p0))


def motion_of(entry: dict, name: str, after, before=None):
    """The world motion (Blender frame) that takes an object from its pose `before` to its
    pose `after` (`shenlong.Pose`s; `before` defaults to where the scene Shenlong was given
    has it, its entry `entry`), or None when it did not move."""
    t = Vector(after.position)
    x, y, z, w = after.rotation
    q = Quaternion((w, x, y, z)).normalized()
    s = float(after.scale)
    moving = pose_matrix(entry, after)
    if before is not None:
        moving = moving @ pose_matrix(entry, before).inverted()
    identity = Matrix.Identity(4)
    if all(abs(moving[i][j] - identity[i][j]) < 1e-12 for i in range(4) for j in range(4)):
        return None
    # Shenlong's box afterwards: its rotated, scaled box, in Blender's frame.
    size = Vector(entry["size"])
    half = Vector((size.x / 2.0, 0.0, size.z / 2.0))
    local = box_corners(-half, Vector((half.x, size.y, half.z)))
    lo, hi = bounds(to_blender(q @ (c * s) + t) for c in local)
    return Motion(name, moving, lo, hi)


def apply_motions(objects_by_name: dict, motions: list[Motion]) -> None:
    """Sets each moved object's world matrix to `motion · matrix_world`, parents first, all
    computed from the matrices as they were (a child that Shenlong moved is set after its
    parent, so Blender's hierarchy cannot move it twice)."""
    targets = []
    for m in motions:
        obj = objects_by_name[m.name]
        targets.append((obj, m.matrix @ obj.matrix_world))

    for obj, matrix in sorted(targets, key=lambda t: depth(t[0])):
        obj.matrix_world = matrix


def summarise(report: dict) -> list[str]:
    """The report in a few lines for the panel: what each phrase meant, what moved, what
    collisions were resolved."""
    lines = []
    for g in report.get("grounding", []):
        lines.append(f"“{g.get('phrase', '')}” → {', '.join(g.get('objects', []))}")
    for o in report.get("objects", []):
        t = o.get("translation", [0, 0, 0])
        moved = to_blender(t)
        parts = []
        if moved.length > 1e-9:
            parts.append("moved " + ", ".join(f"{c:+.3f}" for c in moved) + " m")
        if abs(o.get("rotation_degrees", 0.0)) > 1e-6:
            parts.append(f"turned {o['rotation_degrees']:.1f}°")
        if abs(o.get("scale", 1.0) - 1.0) > 1e-9:
            parts.append(f"scaled ×{o['scale']:.3g}")
        lines.append(f"{o.get('object', '?')}: {'; '.join(parts) or 'unchanged'}")
    for name in report.get("carried", []):
        lines.append(f"{name}: carried along")
    for c in report.get("collisions_resolved", []):
        d = to_blender(c.get("displacement", [0, 0, 0]))
        lines.append(
            f"{c.get('object', '?')}: moved {d.length:.3f} m to clear "
            + ", ".join(c.get("collided_with", []))
        )
    for o in report.get("overlaps_remaining", []):
        lines.append(f"overlap left: {o}")
    return lines
