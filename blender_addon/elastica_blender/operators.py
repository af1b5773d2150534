# SPDX-License-Identifier: GPL-3.0-or-later
"""The three operators. Their redo-panel properties are built from elastica.filters(), the options
table: every row with a Blender property, with its name, default, label and range, so the add-on holds
no names or numbers of its own.

Run from the menu or F3 (invoke), fairing and filling compute in a worker thread while Blender stays
responsive: the status bar shows the step and energy, Esc cancels (the module's progress callback
returns False) and leaves the mesh as it was. The time limit ("Time limit (s)", 60 s by default as in
MeshLab) stops a long fair and keeps the state reached, as every face does, and says so (undo
restores the mesh; raise the limit, or 0 for none); a fill stopped by it keeps the patches it made. From the
redo panel or a script (execute) they run to the end in the foreground.

Edit Mode: the operator leaves Edit Mode once at its start and enters it again once at its end (a
mode switch syncs the edit mesh; nothing toggles per step). Undo restores the mesh (REGISTER, UNDO).
Errors (non-manifold meshes, nothing selected, a diverging flow, ...) are reported, never raised."""
import importlib.util
import glob
import os
import sys
import threading
import traceback

import bpy
import numpy as np
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty

from . import mesh_arrays as ma


def _import_elastica():
    """The module from Python's path, else the copy install.sh puts beside the add-on (Blender's
    --factory-startup leaves the user modules folder off the path, not the add-on's own folder)."""
    try:
        import elastica
        return elastica
    except ImportError as e:
        bundled = glob.glob(os.path.join(os.path.dirname(__file__), "elastica*.so"))
        if not bundled:
            raise ImportError(
                "Elastica: the Python module 'elastica' was not found (" + str(e) + "). Build the project and "
                "run blender_addon/install.sh BUILD_DIR, which puts the module beside the add-on, or start "
                "Blender with --python-use-system-env and PYTHONPATH at build/python.") from e
        spec = importlib.util.spec_from_file_location("elastica", bundled[0])
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
        sys.modules["elastica"] = module
        return module


elastica = _import_elastica()

# The worker runs of modal operators still going (what the status bar shows; tests read it).
running_jobs = []

def _property(p):
    """A bpy property for one parameter of elastica.filters()."""
    common = {"name": p["label"], "description": p["description"]}
    if p["type"] == "bool":
        return BoolProperty(default=p["default"], **common)
    if p["type"] == "enum":
        items = [(w, l, p["description"]) for w, l in zip(p["choices"], p["labels"])]
        return EnumProperty(items=items, default=p["default"], **common)
    bounds = {k: p[k] for k in ("min", "max") if p.get(k) is not None}
    if p["type"] == "int":
        bounds = {k: int(min(max(v, -2**31), 2**31 - 1)) for k, v in bounds.items()}
        return IntProperty(default=int(p["default"]), **bounds, **common)
    if p.get("unit") == "length":  # shown with the scene's length unit (the mesh's own coordinates)
        common.update(subtype='DISTANCE', unit='LENGTH')
    if p["default"] is None:  # sized from the mesh at each run (the feature size's "auto"): not remembered
        return FloatProperty(default=0.0, precision=4, step=1, options={'SKIP_SAVE'}, **bounds, **common)
    return FloatProperty(default=p["default"], precision=4, step=1, **bounds, **common)


def _properties(filter_name):
    """{property name: (parameter, bpy property)} in the table's order (the MeshLab dialog's)."""
    return {p["blender"]: (p, _property(p)) for p in elastica.filters()[filter_name]["parameters"] if p["blender"]}


class Job:
    """compute(progress) in a worker thread; cancel() makes the next progress call return False (the
    module then raises elastica.Error and nothing is changed). No bpy here: the main thread reads
    latest, done(), result, error and cancelled."""

    def __init__(self, compute):
        self.latest = None
        self.result = self.error = None
        self._cancel = threading.Event()
        self.cancelled = False
        self._thread = threading.Thread(target=self._run, args=(compute,), daemon=True)
        self._thread.start()

    def _progress(self, p):
        self.latest = p
        return not self._cancel.is_set()

    def _run(self, compute):
        try:
            self.result = compute(self._progress)
        except Exception as e:  # elastica.Error on cancel, or a failure: handed to the main thread
            self.error = e
        self.cancelled = self._cancel.is_set() and self.error is not None

    def cancel(self):
        self._cancel.set()

    def done(self):
        return not self._thread.is_alive()

    def wait(self, timeout=None):
        self._thread.join(timeout)
        return self.done()


class ElasticaOperator:
    bl_options = {'REGISTER', 'UNDO'}
    filter_name = ""
    background = False  # invoke runs it in a worker thread (modal), Esc cancels
    params = {}  # {property: (parameter, bpy property)}, set by _operator_class
    extra = ()   # properties of the add-on's own, drawn after the parameters

    @classmethod
    def poll(cls, context):
        ob = context.active_object
        return ob is not None and ob.type == 'MESH' and context.mode in {'EDIT_MESH', 'OBJECT'}

    def keywords(self):
        """The module's keyword arguments from the redo panel's values."""
        return {p["keyword"]: getattr(self, name) for name, (p, _) in self.params.items() if p["keyword"]}

    def execute(self, context):
        """In the foreground, to the end (the redo panel, scripts)."""
        ob = context.active_object
        edit = context.mode == 'EDIT_MESH'
        wm = context.window_manager
        if edit:
            bpy.ops.object.mode_set(mode='OBJECT')  # once: syncs the edit mesh (selection included)
        wm.progress_begin(0, 9999)
        self._status(context, self.bl_label + "…")
        try:
            compute = self.prepare(ob.data, edit)
            message = self.apply(context, ob.data, compute(self.progress(context)))
        except (elastica.Error, ValueError) as e:
            self.report({'ERROR'}, f"{self.bl_label}: {e}")
            return {'CANCELLED'}
        except Exception as e:  # a bug of ours: report it rather than leave a traceback only
            traceback.print_exc()
            self.report({'ERROR'}, f"{self.bl_label} failed: {type(e).__name__}: {e}")
            return {'CANCELLED'}
        finally:
            wm.progress_end()
            self._status(context, None)
            if edit:
                bpy.ops.object.mode_set(mode='EDIT')
        self.report({'INFO'}, message)
        return {'FINISHED'}

    def invoke(self, context, event):
        """From the menu: the computation in a worker thread, Esc cancels (modal, timer-driven)."""
        if not self.background:
            return self.execute(context)
        ob = context.active_object
        self._edit = context.mode == 'EDIT_MESH'
        if self._edit:
            bpy.ops.object.mode_set(mode='OBJECT')
        try:
            compute = self.prepare(ob.data, self._edit)
        except (elastica.Error, ValueError) as e:
            self._leave(context)
            self.report({'ERROR'}, f"{self.bl_label}: {e}")
            return {'CANCELLED'}
        self._object = ob
        self._job = Job(compute)
        running_jobs.append(self._job)
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.1, window=context.window)
        wm.modal_handler_add(self)
        self._status(context, f"{self.bl_label}… (Esc cancels)")
        return {'RUNNING_MODAL'}

    def modal(self, context, event):
        job = self._job
        if event.type == 'ESC' and event.value == 'PRESS':
            job.cancel()
            self._status(context, f"{self.bl_label}: cancelling…")
        if event.type == 'TIMER':
            if not job.done():
                p = job.latest
                if p is not None:
                    self._status(context, f"{self.bl_label}: stage {p['level']}, step {p['step']}, "
                                          f"E = {p['energy']:.6g}, {p['seconds']:.1f} s (Esc cancels)")
                return {'RUNNING_MODAL'}
            return self._finish(context)
        # The view can still be turned and zoomed; the rest waits for the run.
        if event.type in {'MIDDLEMOUSE', 'WHEELUPMOUSE', 'WHEELDOWNMOUSE', 'TRACKPADPAN', 'TRACKPADZOOM'}:
            return {'PASS_THROUGH'}
        return {'RUNNING_MODAL'}

    def _finish(self, context):
        context.window_manager.event_timer_remove(self._timer)
        job = self._job
        running_jobs.remove(job)
        try:
            if job.cancelled:
                self.report({'WARNING'}, f"{self.bl_label}: cancelled; the mesh is as it was")
                return {'CANCELLED'}
            if job.error is not None:
                if isinstance(job.error, (elastica.Error, ValueError)):
                    self.report({'ERROR'}, f"{self.bl_label}: {job.error}")
                else:
                    traceback.print_exception(type(job.error), job.error, job.error.__traceback__)
                    self.report({'ERROR'}, f"{self.bl_label} failed: {type(job.error).__name__}: {job.error}")
                return {'CANCELLED'}
            try:
                message = self.apply(context, self._object.data, job.result)
            except (elastica.Error, ValueError) as e:
                self.report({'ERROR'}, f"{self.bl_label}: {e}")
                return {'CANCELLED'}
            self.report({'INFO'}, message)
            return {'FINISHED'}
        finally:
            self._leave(context)

    def _leave(self, context):
        self._status(context, None)
        if self._edit:
            bpy.ops.object.mode_set(mode='EDIT')

    def _status(self, context, text):
        if context.workspace is not None:
            context.workspace.status_text_set(text)

    def progress(self, context):
        """The module's progress callback: the step number on the cursor, the state on the status bar."""
        wm = context.window_manager

        def update(p):
            wm.progress_update(min(int(p["step"]), 9999))
            self._status(context, f"{self.bl_label}: stage {p['level']}, step {p['step']}, "
                                  f"E = {p['energy']:.6g}, {p['seconds']:.1f} s")
            return True
        return update

    @staticmethod
    def check_shape_keys(me, what):
        if me.shape_keys is not None:
            raise ValueError(f"{what} changes the mesh's connectivity, which its shape keys cannot follow: "
                             "apply or remove the shape keys first")

    def draw(self, context):
        layout = self.layout
        layout.use_property_split = True
        for name in (*self.params, *self.extra):
            layout.prop(self, name)


def measure_curvature(me, V, F, **kwargs):
    """mean_curvature and gaussian_curvature point attributes, and mean_curvature_color by H (made
    the active colour attribute). Returns elastica.curvature's dict."""
    c = elastica.curvature(V, F, **kwargs)
    ma.store_point_attribute(me, "mean_curvature", 'FLOAT', c["H"], "value")
    ma.store_point_attribute(me, "gaussian_curvature", 'FLOAT', c["K"], "value")
    color = ma.store_point_attribute(me, "mean_curvature_color", 'FLOAT_COLOR', ma.ramp_colors(c["H"]), "color")
    me.color_attributes.active_color = color
    me.update()
    return c


class MESH_OT_elastica_fair_base(ElasticaOperator):
    bl_idname = "mesh.elastica_fair"
    bl_label = "Elastica Fairing"
    bl_description = ("Fair with the discrete elastica flow (Edit Mode: the selected faces, two rings around "
                      "them fixed; Object Mode: the whole mesh). Works on the mesh in object space")
    filter_name = "fair"
    extra = ("keep_connectivity",)
    background = True

    def prepare(self, me, edit):
        """Checks and reads the mesh; returns compute(progress) -> the module's result (no bpy)."""
        arrays = ma.MeshArrays(me)
        selection = None
        if edit:
            selection = arrays.selected_triangles(me)
            if not selection.any():
                raise ValueError("no faces selected: select the faces to fair (or use Object Mode for the whole mesh)")
        # The default feature size is the mesh's own (elastica.auto_feature_size), as MeshLab's dialog
        # shows it; set here, the redo panel shows the amount used and reruns with it.
        if not self.properties.is_property_set("feature_size") and self.subdivide == 0 and self.flow != "bilaplacian":
            self.feature_size = elastica.auto_feature_size(arrays.V, arrays.F, selection)
        kwargs = self.keywords()
        keep = self.keep_connectivity and kwargs["subdivide"] == 0
        if not keep:
            if edit:
                raise ValueError("subdivision and remeshing work on the whole mesh: use them in Object Mode")
            self.check_shape_keys(me, "Subdivision or remeshing")
        self._arrays, self._keep = arrays, keep
        return lambda progress: elastica.fair(arrays.V, arrays.F, selection, remesh=not keep, progress=progress,
                                              **kwargs)

    def apply(self, context, me, result):
        V, F, report = result
        if report["stop"] == "unchanged":
            return (f"Elastica: the flow's result was not kept ({report.get('refused_because', '')}); "
                    "the mesh is unchanged")
        keep, arrays = self._keep, self._arrays
        if keep:
            ma.write_positions(me, V)
        else:
            ma.replace_geometry(me, V, F)
        if self.color_by_mean_curvature:
            measure_curvature(me, V, F)
        moved = len(V) if not keep else int((V != arrays.V).any(axis=1).sum())
        energies = f"mesh E {report['mesh_energy_before']:.6g} -> {report['mesh_energy_after']:.6g}"
        if "region_energy_before" in report:
            energies = (f"region E {report['region_energy_before']:.6g} -> {report['region_energy_after']:.6g}, "
                        + energies)
        limit = ""
        if report["stop"] == "max_seconds":  # the state reached is kept, as on every face; undo restores
            limit = " at the time limit (the state reached; raise Time limit (s), or 0 for none)"
        return (f"Elastica: {moved} of {len(V)} vertices moved; {energies} in {report['steps']} steps "
                f"({report['stop']}){limit}, {report['seconds']:.2f} s")


class MESH_OT_elastica_fill_holes_base(ElasticaOperator):
    bl_idname = "mesh.elastica_fill_holes"
    bl_label = "Elastica Fill Holes"
    bl_description = ("Fill holes with patches faired by the discrete elastica flow; the new faces come "
                      "selected. Works on the mesh in object space")
    filter_name = "fill_holes"
    background = True

    def prepare(self, me, edit):
        arrays = ma.MeshArrays(me)
        kwargs = self.keywords()
        self._arrays = arrays
        return lambda progress: elastica.fill_holes(arrays.V, arrays.F, progress=progress, **kwargs)

    def apply(self, context, me, result):
        V, F, new_faces, report = result
        added = int(new_faces.sum())
        if added:
            self.check_shape_keys(me, "Filling holes")
            polygons = ma.append_triangles(me, V, F[len(self._arrays.F):])
            if self.select_new_faces:
                ma.select_only_polygons(me, polygons)
        open_holes = report["skipped"]
        rims = sum(h["rim"] for h in report["holes"] if not h["filled"])
        return (f"Elastica: filled {report['filled']} of {len(report['holes'])} holes with {added} faces"
                + (f" ({open_holes} left open, {rims} of them rims)" if open_holes else "")
                + f", {report['seconds']:.2f} s")


class MESH_OT_elastica_curvature_base(ElasticaOperator):
    bl_idname = "mesh.elastica_curvature"
    bl_label = "Elastica Curvature"
    bl_description = ("Mean curvature H (+1/r on a sphere) and Gaussian curvature K into the point attributes "
                      "mean_curvature and gaussian_curvature, and the colour attribute mean_curvature_color "
                      "(red low H, blue high). In object space: H scales with 1/(object scale)")
    filter_name = "curvature"

    def prepare(self, me, edit):
        arrays = ma.MeshArrays(me)
        return lambda progress: arrays

    def apply(self, context, me, arrays):
        c = measure_curvature(me, arrays.V, arrays.F, **self.keywords())
        return f"Elastica: H in [{c['H'].min():.6g}, {c['H'].max():.6g}], total curvature energy E = {c['energy']:.6g}"


def _operator_class(base):
    """The registered class: base with the redo panel's properties from elastica.filters()."""
    params = _properties(base.filter_name)
    annotations = {name: prop for name, (_, prop) in params.items()}
    if "keep_connectivity" in base.extra:
        annotations["keep_connectivity"] = BoolProperty(
            name="Keep connectivity", default=True,
            description="Move vertices only: the polygons, UVs, attributes and shape keys stay. Off: the "
                        "vector and semi-implicit schemes may remesh (the mesh is then rebuilt as triangles, attributes reset)")
    return type(base.__name__[: -len("_base")], (base, bpy.types.Operator),
                {"__annotations__": annotations, "params": params})


classes = [_operator_class(b) for b in (MESH_OT_elastica_fair_base, MESH_OT_elastica_fill_holes_base,
                                         MESH_OT_elastica_curvature_base)]


def menu(self, context):
    self.layout.separator()
    for cls in classes:
        self.layout.operator(cls.bl_idname, text=cls.bl_label)


def register():
    for cls in classes:
        bpy.utils.register_class(cls)
    bpy.types.VIEW3D_MT_edit_mesh_clean.append(menu)
    bpy.types.VIEW3D_MT_object_cleanup.append(menu)


def unregister():
    bpy.types.VIEW3D_MT_object_cleanup.remove(menu)
    bpy.types.VIEW3D_MT_edit_mesh_clean.remove(menu)
    for cls in reversed(classes):
        bpy.utils.unregister_class(cls)
