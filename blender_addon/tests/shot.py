"""The add-on in Blender's interface under Xvfb (ctest blender_addon_gui):

  xvfb-run -a blender --factory-startup --python-use-system-env --python shot.py -- OUT.png

From a bpy.app.timers callback (the window exists by then): a noisy sphere replaces the default
cube, mesh.elastica_fair runs as from the menu (INVOKE, with undo, so the redo panel "Elastica
Fairing" opens in the 3D view's corner), with colour by mean curvature shown in the viewport, and F9
(screen.redo_last) unfolds the redo panel as a popup; the window is saved to OUT.png (bpy.ops.screen.screenshot); then Ctrl-Z's operator (ed.undo) must bring
the noisy sphere back. Exit status 0 when all held, 1 otherwise (printed)."""
import os
import sys
import traceback

import addon_utils
import bpy
import numpy as np

out = sys.argv[sys.argv.index("--") + 1]
state = {"tick": 0}


def positions(me):
    co = np.empty(3 * len(me.vertices), np.float32)
    me.vertices.foreach_get("co", co)
    return co.reshape(-1, 3)


def view3d():
    win = bpy.context.window_manager.windows[0]
    area = next(a for a in win.screen.areas if a.type == 'VIEW_3D')
    region = next(r for r in area.regions if r.type == 'WINDOW')
    return {"window": win, "screen": win.screen, "area": area, "region": region}


def step():
    try:
        state["tick"] += 1
        if state["tick"] == 1:
            addon_utils.enable("elastica_blender", default_set=True, handle_error=None)
            with bpy.context.temp_override(**view3d()):
                bpy.ops.object.select_all(action='SELECT')
                bpy.ops.object.delete()
                bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=4, radius=1.2)
                ob = bpy.context.active_object
                P = positions(ob.data)
                rng = np.random.default_rng(1)
                P *= (1 + 0.04 * rng.uniform(-1, 1, len(P)))[:, None]
                ob.data.vertices.foreach_set("co", P.ravel())
                ob.data.update()
                bpy.ops.ed.undo_push(message="noisy sphere")
                state["before"] = P.copy()
                # As a click in the menu: invoked, registered, undoable, with its redo panel.
                result = bpy.ops.mesh.elastica_fair('INVOKE_DEFAULT', True, color_by_mean_curvature=True)
                assert result == {'FINISHED'}, result
            view3d()["area"].spaces[0].shading.color_type = 'VERTEX'  # "Attribute": the active colour attribute
            with bpy.context.temp_override(**view3d()):
                bpy.ops.view3d.view_selected()
                bpy.ops.screen.redo_last('INVOKE_DEFAULT')  # F9: the redo panel as a popup, unfolded
            return 1.0
        if state["tick"] == 2:
            ob = bpy.context.view_layer.objects.active
            assert (positions(ob.data) != state["before"]).any(), "fairing moved nothing"
            assert bpy.context.window_manager.operators[-1].bl_idname == "MESH_OT_elastica_fair"
            bpy.ops.screen.screenshot(filepath=out)
            return 0.5
        if state["tick"] == 3:
            assert os.path.getsize(out) > 10000, "screenshot missing or empty"
            with bpy.context.temp_override(**view3d()):
                bpy.ops.ed.undo()
            ob = bpy.context.view_layer.objects.active
            assert (positions(ob.data) == state["before"]).all(), "undo did not restore the noisy sphere"
            print("shot: fairing ran with its redo panel; screenshot", out, "; undo restored the mesh", flush=True)
            os._exit(0)
    except Exception:
        traceback.print_exc()
        sys.stdout.flush()
        os._exit(1)
    return None


bpy.context.preferences.view.show_splash = False
bpy.app.timers.register(step, first_interval=1.0)
