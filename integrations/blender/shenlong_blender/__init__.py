"""Shenlong for Blender: edit the open scene by instruction.

"put the mug and the bowl on the dresser", "move the couch a bit to the left", "turn it 90
degrees" (with the chair selected): the instruction goes to the `shenlong` package — in
Blender's own Python, bundled with this extension as a wheel — with the visible mesh
objects as boxes; Shenlong grounds the words to objects (or refuses, naming
the candidates), translates them into exact transformations — offline by default, or with
a model — resolves collisions, and the add-on applies the motions to the objects' world
matrices as one undo step. Nothing a model says is executed.

Operator: `bpy.ops.shenlong.edit(instruction="…")`. Panel: 3D viewport → sidebar (N) →
Shenlong. See docs/blender.md.
"""

bl_info = {
    "name": "Shenlong",
    "author": "Shenlong",
    "version": (0, 1, 0),
    "blender": (4, 2, 0),
    "location": "3D Viewport > Sidebar > Shenlong",
    "description": "Edit the scene by instruction: exact, collision-aware, undoable",
    "doc_url": "https://github.com/shenlong/shenlong/blob/main/docs/blender.md",
    "category": "Object",
}

import json

import bpy
from bpy.props import EnumProperty, StringProperty

from . import core

SYSTEMS = [
    ("cga", "CGA (Shenlong)", "Conformal geometric algebra prompts"),
    ("euclidean", "Euclidean", "The paper's matrix baseline"),
    ("omniverse", "Omniverse", "The paper's Omniverse-style baseline"),
]
BACKENDS = [
    ("offline", "Offline", "Shenlong's built-in translator: no network, no model"),
    ("offline+openai", "Offline, then OpenAI-compatible",
     "The offline translator first; a model only for what it cannot read (recommended with a model)"),
    ("offline+ollama", "Offline, then Ollama", "The offline translator first; Ollama for the rest"),
    ("openai", "OpenAI-compatible", "openai:MODEL (OPENAI_API_KEY; base URL below)"),
    ("ollama", "Ollama", "ollama:MODEL on localhost:11434"),
]


class ShenlongSettings(bpy.types.PropertyGroup):
    """The panel's fields, kept with the scene."""

    instruction: StringProperty(name="Instruction", default="")
    backend: EnumProperty(name="Translator", items=BACKENDS, default="offline")
    model: StringProperty(name="Model", description="The model's name, for OpenAI or Ollama", default="")
    base_url: StringProperty(name="Base URL", description="An OpenAI-compatible server's URL", default="")
    system: EnumProperty(name="Prompt system", items=SYSTEMS, default="cga")
    last_report: StringProperty(default="")
    last_error: StringProperty(default="")


def llm_spec(settings) -> str:
    """The `--llm` value for the panel's translator choice."""
    if settings.backend == "offline":
        return "offline"
    model = settings.model.strip()
    if not model:
        raise core.ShenlongError(f"name the {settings.backend.split('+')[-1]} model to use")
    return f"{settings.backend}:{model}"


class SHENLONG_OT_edit(bpy.types.Operator):
    """Edit the scene by instruction with Shenlong (exact, collision-aware, one undo step)"""

    bl_idname = "shenlong.edit"
    bl_label = "Edit by instruction"
    bl_options = {"REGISTER", "UNDO"}

    instruction: StringProperty(
        name="Instruction",
        description="What to do, as you would say it: “put the mug on the table”",
        default="",
    )

    def execute(self, context):
        settings = context.scene.shenlong
        instruction = self.instruction or settings.instruction
        try:
            depsgraph = context.evaluated_depsgraph_get()
            selected = set(context.selected_objects)
            chosen = core.editable_objects(context.view_layer, selected)
            objects = core.describe(chosen, depsgraph)
            names = {o.name for o in objects}
            selection = tuple(o.name for o in chosen if o in selected and o.name in names)
            result = core.run_edit(
                objects,
                instruction,
                llm=llm_spec(settings),
                system=settings.system,
                base_url=settings.base_url.strip() or None,
                selection=selection,
                matrices=core.matrices_of(chosen),
            )
        except core.ShenlongError as e:
            settings.last_error = str(e)
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        core.apply_motions({o.name: o for o in chosen}, result.motions)
        context.view_layer.update()
        # The conversation goes on while the objects stay where this edit left them.
        core.CONVERSATION.left_as(core.matrices_of(chosen))
        settings.last_error = ""
        settings.last_report = json.dumps(
            {
                "instruction": instruction,
                "summary": result.summary,
                "boxes": {
                    m.name: [list(m.box_min), list(m.box_max)] for m in result.motions
                },
                "report": result.report,
            }
        )
        moved = len(result.motions)
        self.report({"INFO"}, f"Shenlong: {moved} object{'s' if moved != 1 else ''} moved")
        return {"FINISHED"}


class SHENLONG_PT_panel(bpy.types.Panel):
    """The sidebar panel: instruction, translator, and the last edit's report."""

    bl_idname = "SHENLONG_PT_panel"
    bl_label = "Shenlong"
    bl_space_type = "VIEW_3D"
    bl_region_type = "UI"
    bl_category = "Shenlong"

    def draw(self, context):
        draw_panel(self.layout, context.scene.shenlong)


def draw_panel(layout, settings):
    """The panel's layout (a function of the settings, so a test can draw it)."""
    col = layout.column()
    col.prop(settings, "instruction", text="")
    op = col.operator(SHENLONG_OT_edit.bl_idname, text="Edit", icon="PLAY")
    op.instruction = settings.instruction
    box = layout.box()
    box.prop(settings, "backend")
    if settings.backend != "offline":
        box.prop(settings, "model")
    if settings.backend.endswith("openai"):
        box.prop(settings, "base_url")
    box.prop(settings, "system")
    if settings.last_error:
        err = layout.box()
        err.label(text=settings.last_error, icon="ERROR")
    elif settings.last_report:
        try:
            last = json.loads(settings.last_report)
        except ValueError:
            last = {}
        rep = layout.box()
        rep.label(text=f"Last: {last.get('instruction', '')}", icon="INFO")
        for line in last.get("summary", []):
            rep.label(text=line)


CLASSES = (ShenlongSettings, SHENLONG_OT_edit, SHENLONG_PT_panel)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.shenlong = bpy.props.PointerProperty(type=ShenlongSettings)


def unregister():
    del bpy.types.Scene.shenlong
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
