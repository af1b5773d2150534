# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on in Blender's interface under Xvfb (ctest blender_addon_gui):

  xvfb-run -a blender --factory-startup --python-use-system-env --python shot.py -- OUT.png

From a bpy.app.timers callback (the window exists by then): a noisy sphere replaces the default
cube, mesh.elastica_fair runs as from the menu (INVOKE: modal, computing in a worker thread, with
undo, so the redo panel "Elastica Fairing" opens in the 3D view's corner once it ends), with colour by
mean curvature shown in the viewport, and F9 (screen.redo_last) unfolds the redo panel as a popup,
time limit included; the window is saved to OUT.png (bpy.ops.screen.screenshot); then Ctrl-Z's
operator (ed.undo) must bring the noisy sphere back. Last, a long run on a finer sphere is invoked
and Esc pressed (xdotool): the mesh must be as it was and no operator registered. Exit status 0 when
all held, 1 otherwise (printed)."""
import os
import subprocess
import sys
import time
import traceback

import addon_utils
import importlib
import bpy

# The add-on's module: the legacy add-on (Blender 3.4, ctest) or an installed Extension's
# (bl_ext.user_default.elastica_blender, scripts/blender5.sh in Blender 5.2).
ADDON = os.environ.get("ELASTICA_ADDON_MODULE", "elastica_blender")
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


def noisy_sphere(subdivisions, radius, seed):
    with bpy.context.temp_override(**view3d()):
        bpy.ops.object.select_all(action='SELECT')
        bpy.ops.object.delete()
        bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=subdivisions, radius=radius)
    ob = bpy.context.active_object
    P = positions(ob.data)
    rng = np.random.default_rng(seed)
    P *= (1 + 0.04 * rng.uniform(-1, 1, len(P)))[:, None]
    ob.data.vertices.foreach_set("co", P.ravel())
    ob.data.update()
    return ob, P.copy()


def wait_for(condition, what, ticks=120):
    """True once `condition()` holds; fails after `ticks` half-second ticks."""
    if condition():
        return True
    state["waited"] = state.get("waited", 0) + 1
    assert state["waited"] < ticks, "timed out waiting for " + what
    return False


def step():
    try:
        state["tick"] += 1
        tick = state["tick"]
        if tick == 1:
            addon_utils.enable(ADDON, default_set=True, handle_error=None)
            ob, state["before"] = noisy_sphere(4, 1.2, 1)
            with bpy.context.temp_override(**view3d()):
                bpy.ops.ed.undo_push(message="noisy sphere")
                # As a click in the menu: invoked (modal, in a worker thread), registered, undoable.
                result = bpy.ops.mesh.elastica_fair('INVOKE_DEFAULT', True, color_by_mean_curvature=True)
                assert result == {'RUNNING_MODAL'}, result
            return 0.5
        if tick == 2:
            ops = bpy.context.window_manager.operators
            if not wait_for(lambda: len(ops) and ops[-1].bl_idname == "MESH_OT_elastica_fair", "the fairing"):
                state["tick"] -= 1
                return 0.5
            state["waited"] = 0
            ob = bpy.context.view_layer.objects.active
            assert (positions(ob.data) != state["before"]).any(), "fairing moved nothing"
            assert ops[-1].properties.max_seconds == 60
            view3d()["area"].spaces[0].shading.color_type = 'VERTEX'  # "Attribute": the active colour attribute
            with bpy.context.temp_override(**view3d()):
                bpy.ops.view3d.view_selected()
                bpy.ops.screen.redo_last('INVOKE_DEFAULT')  # F9: the redo panel as a popup, unfolded
            return 1.0
        if tick == 3:
            bpy.ops.screen.screenshot(filepath=out)
            if os.environ.get("ELASTICA_X_SCREENSHOT"):  # the X server's picture too (Blender 5.2's own came out black)
                subprocess.run(["import", "-window", "root", os.environ["ELASTICA_X_SCREENSHOT"]], check=True)
            return 0.5
        if tick == 4:
            assert os.path.getsize(out) > 10000, "screenshot missing or empty"
            with bpy.context.temp_override(**view3d()):
                bpy.ops.ed.undo()
            ob = bpy.context.view_layer.objects.active
            assert (positions(ob.data) == state["before"]).all(), "undo did not restore the noisy sphere"
            print("shot: fairing ran with its redo panel; screenshot", out, "; undo restored the mesh", flush=True)
            # Esc: a long explicit run on a 40,962-vertex sphere, cancelled from the keyboard.
            ob, state["long"] = noisy_sphere(6, 1.2, 2)
            state["operators"] = len(bpy.context.window_manager.operators)
            with bpy.context.temp_override(**view3d()):
                result = bpy.ops.mesh.elastica_fair('INVOKE_DEFAULT', True, scheme="explicit", feature_size=0, max_steps=10**9)
            assert result == {'RUNNING_MODAL'}, result
            operators = importlib.import_module(ADDON + ".operators")
            state["job"] = operators.running_jobs[-1]
            return 1.5
        if tick == 5:
            assert not state["job"].done(), "the long run ended before Esc"
            subprocess.run(["xdotool", "mousemove", "640", "400", "key", "Escape"], check=True)
            state["esc"] = time.perf_counter()
            return 0.5
        if tick == 6:
            operators = importlib.import_module(ADDON + ".operators")
            if not wait_for(lambda: not operators.running_jobs, "the cancel", ticks=10):
                state["tick"] -= 1
                return 0.5
            assert state["job"].cancelled, "the run ended, but not by Esc"
            ob = bpy.context.view_layer.objects.active
            assert (positions(ob.data) == state["long"]).all(), "Esc left the mesh changed"
            ops = bpy.context.window_manager.operators
            assert len(ops) == state["operators"], "the cancelled run was registered"
            print(f"shot: Esc cancelled the running fair after {state['job'].latest['step']} steps, "
                  f"{time.perf_counter() - state['esc']:.1f} s after the key; the mesh is as it was", flush=True)
            os._exit(0)
    except Exception:
        traceback.print_exc()
        sys.stdout.flush()
        os._exit(1)
    return None


bpy.context.preferences.view.show_splash = False
bpy.app.timers.register(step, first_interval=1.0)
