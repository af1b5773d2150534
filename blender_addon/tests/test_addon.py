# SPDX-License-Identifier: GPL-3.0-or-later
"""The add-on in headless Blender (ctest blender_addon):

  blender -b --factory-startup --python-exit-code 1 --python-use-system-env --python test_addon.py

with PYTHONPATH at the built module (build/python) and at blender_addon/ (the add-on's source), and
ELASTICA_DATA_DIR at data/. Each test builds its object, runs an operator through bpy.ops as a user
would, and checks the mesh; a failed assertion exits Blender with 1. Undo needs a window: shot.py
checks it under Xvfb."""
import math
import os
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

import elastica

DATA = os.environ["ELASTICA_DATA_DIR"]


def mesh_object(name, V, F):
    mesh_arrays = importlib.import_module(ADDON + ".mesh_arrays")  # importable once the add-on is enabled

    me = bpy.data.meshes.new(name)
    mesh_arrays.replace_geometry(me, V, F)
    assert not me.validate()
    ob = bpy.data.objects.new(name, me)
    bpy.context.scene.collection.objects.link(ob)
    for o in bpy.context.view_layer.objects:
        o.select_set(False)
    ob.select_set(True)
    bpy.context.view_layer.objects.active = ob
    return ob


def positions(me):
    co = np.empty(3 * len(me.vertices), np.float32)
    me.vertices.foreach_get("co", co)
    return co.reshape(-1, 3)


def triangles(me):
    me.calc_loop_triangles()
    t = np.empty(3 * len(me.loop_triangles), np.int32)
    me.loop_triangles.foreach_get("vertices", t)
    return t.reshape(-1, 3)


def radius_spread(P):
    """(max - min) / mean distance from the least-squares sphere centre."""
    A = np.column_stack([2 * P, np.ones(len(P))])
    c = np.linalg.lstsq(A, (P ** 2).sum(axis=1), rcond=None)[0][:3]
    r = np.linalg.norm(P - c, axis=1)
    return (r.max() - r.min()) / r.mean()


def noisy_sphere(name, level=3, noise=0.05, seed=3):
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=level, radius=1.0)
    ob = bpy.context.active_object
    ob.name = name
    P = positions(ob.data)
    rng = np.random.default_rng(seed)
    P *= (1 + noise * rng.uniform(-1, 1, len(P)))[:, None]
    ob.data.vertices.foreach_set("co", P.ravel())
    ob.data.update()
    return ob


def pytest_approx(x):
    """float32 bounds as Blender stores them."""
    return float(np.float32(x))


def diagonal(P):
    return float(np.linalg.norm(P.max(axis=0) - P.min(axis=0)))


# ---------------------------------------------------------------- tests

def test_registered_with_the_filters_defaults():
    """Every row of the options table with a Blender property is a property of its operator, with the
    row's default, label and range; and no operator has a parameter property the table does not list."""
    operators = {"fair": bpy.ops.mesh.elastica_fair, "fill_holes": bpy.ops.mesh.elastica_fill_holes,
                 "curvature": bpy.ops.mesh.elastica_curvature}
    own = {"keep_connectivity"}  # the add-on's own (Edit Mode's selection and the mesh's connectivity)
    for function, op in operators.items():
        props = op.get_rna_type().properties
        rows = [p for p in elastica.filters()[function]["parameters"] if p["blender"]]
        for p in rows:
            prop = props[p["blender"]]
            assert prop.name == p["label"], p
            if p["type"] == "enum":
                assert prop.default == p["default"] and [i.identifier for i in prop.enum_items] == p["choices"], p
            elif p["default"] is None:  # the feature size: sized from the mesh at each run, not remembered
                assert prop.default == 0 and prop.is_skip_save, p
            else:
                assert prop.default == p["default"] or math.isclose(prop.default, p["default"], rel_tol=1e-6), p
            if p["type"] in ("int", "float") and p.get("min") is not None:
                assert prop.hard_min == pytest_approx(p["min"]), p
        names = {prop.identifier for prop in props if prop.identifier != "rna_type"}
        assert names == {p["blender"] for p in rows} | (own if function == "fair" else set()), function
    fair = operators["fair"].get_rna_type().properties
    assert fair["scheme"].default == "auto"
    fill = bpy.ops.mesh.elastica_fill_holes.get_rna_type().properties
    assert fill["max_hole_edges"].default == 500 and fill["select_new_faces"].default
    assert bpy.ops.mesh.elastica_curvature.get_rna_type().properties["area"].default == "mixed"
    for menu in (bpy.types.VIEW3D_MT_edit_mesh_clean, bpy.types.VIEW3D_MT_object_cleanup):
        assert any(f.__module__.startswith(ADDON) for f in menu._dyn_ui_initialize())
    operators = importlib.import_module(ADDON + ".operators")
    assert [c.bl_idname for c in operators.classes] == ["mesh.elastica_fair", "mesh.elastica_fill_holes",
                                                        "mesh.elastica_curvature"]
    assert all(c.bl_options == {'REGISTER', 'UNDO'} for c in operators.classes)


def test_fair_a_noisy_sphere_object():
    ob = noisy_sphere("noisy")
    ob.location = (3, -1, 2)
    ob.rotation_euler = (0.3, 0.2, 0.1)
    ob.scale = (2, 2, 2)
    bpy.context.view_layer.update()
    world = np.array(ob.matrix_world)
    ob.modifiers.new("subsurf", 'SUBSURF')
    ob.data.attributes.new("weight", 'FLOAT', 'POINT').data.foreach_set("value", np.arange(len(ob.data.vertices), dtype=np.float32))
    ob.shape_key_add(name="Basis")
    lifted = ob.shape_key_add(name="Lifted")
    lifted.data.foreach_set("co", (positions(ob.data) + [0, 0, 1]).ravel())
    P0 = positions(ob.data).copy()
    before = radius_spread(P0)
    # The defaults: the mesh's own fairing amount (elastica.auto_feature_size), the model kept.
    assert bpy.ops.mesh.elastica_fair() == {'FINISHED'}
    P = positions(ob.data)
    after = radius_spread(P)
    print(f"  radius spread {before:.4f} -> {after:.4f} (the default amount)")
    assert before > 0.05 and after < 0.8 * before
    assert np.sqrt(((P - P0) ** 2).sum(axis=1).mean()) <= 0.01 * diagonal(P0)
    # The module on the same float32 input, with the panel's defaults: the same result.
    V, F, _ = elastica.fair(P0.astype(np.float64), triangles(ob.data), remesh=False,
                            energy_tol=bpy.ops.mesh.elastica_fair.get_rna_type().properties["energy_tol"].default)
    assert np.abs(P - V).max() <= 1e-6 * diagonal(V)
    # Object space: the transform stays; modifiers, attributes, shape keys stay.
    assert np.allclose(np.array(ob.matrix_world), world)
    assert [m.type for m in ob.modifiers] == ['SUBSURF']
    w = np.empty(len(ob.data.vertices), np.float32)
    ob.data.attributes["weight"].data.foreach_get("value", w)
    assert (w == np.arange(len(w))).all()
    keys = ob.data.shape_keys.key_blocks
    assert [k.name for k in keys] == ["Basis", "Lifted"]
    basis = np.empty(3 * len(P), np.float32)
    keys["Basis"].data.foreach_get("co", basis)
    assert (basis.reshape(-1, 3) == P).all()  # the shape shown follows
    lifted_co = np.empty(3 * len(P), np.float32)
    keys["Lifted"].data.foreach_get("co", lifted_co)
    assert (lifted_co.reshape(-1, 3) == P0 + np.array([0, 0, 1], np.float32)).all()  # the other key is left alone
    # Feature size 0: the flow's limit shape, a round sphere.
    ob = noisy_sphere("rounded")
    assert bpy.ops.mesh.elastica_fair(feature_size=0) == {'FINISHED'}
    rounded = radius_spread(positions(ob.data))
    print(f"  radius spread {before:.4f} -> {rounded:.4f} (feature size 0)")
    assert rounded < before / 5


def test_defaults_keep_the_model_of_a_scan():
    """The menu entry with every default on a real scan (the bundled Stanford bunny): a fairer
    surface of the same model. The redo panel shows the amount used, the mesh's own
    (elastica.auto_feature_size); the vertices move by at most 1 % of the diagonal (RMS); the energy
    goes down; the connectivity stays."""
    V, F = elastica.read(os.path.join(DATA, "bunny.ply"))
    ob = mesh_object("bunny", V, F)
    P0 = positions(ob.data).copy()
    assert bpy.ops.mesh.elastica_fair() == {'FINISHED'}
    P = positions(ob.data)
    rms = float(np.sqrt(((P - P0) ** 2).sum(axis=1).mean()))
    print(f"  bunny: the vertices moved by {100 * rms / diagonal(P0):.3f} % of the diagonal (RMS)")
    assert 0 < rms <= 0.01 * diagonal(P0)
    T = triangles(ob.data)
    assert len(P) == len(V) and len(T) == len(F)
    assert elastica.curvature(P.astype(np.float64), T)["energy"] < elastica.curvature(P0.astype(np.float64), T)["energy"]
    bpy.data.objects.remove(ob)


def test_fair_with_remeshing_rebuilds_the_mesh():
    ob = noisy_sphere("remeshed", level=2)  # 42 vertices; one subdivision: 162
    before = radius_spread(positions(ob.data))
    assert bpy.ops.mesh.elastica_fair(keep_connectivity=False, subdivide=1) == {'FINISHED'}
    me = ob.data
    assert not me.validate() and len(me.vertices) > 42 and radius_spread(positions(me)) < before / 5


def test_edit_mode_fairs_the_selection_only():
    ob = noisy_sphere("selection")
    me = ob.data
    P0 = positions(me).copy()
    centre = np.empty(3 * len(me.polygons), np.float32)
    me.polygons.foreach_get("center", centre)
    selected = centre.reshape(-1, 3)[:, 2] > 0.3
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_all(action='DESELECT')
    bpy.ops.object.mode_set(mode='OBJECT')
    me.polygons.foreach_set("select", selected)
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_mode(type='FACE')
    assert bpy.ops.mesh.elastica_fair() == {'FINISHED'}
    assert bpy.context.mode == 'EDIT_MESH'
    bpy.ops.object.mode_set(mode='OBJECT')
    P = positions(me)
    loop_total = np.empty(len(me.polygons), np.int32)
    me.polygons.foreach_get("loop_total", loop_total)
    vi = np.empty(len(me.loops), np.int32)
    me.loops.foreach_get("vertex_index", vi)
    keep = np.unique(vi[np.repeat(~selected, loop_total)])
    assert (P[keep] == P0[keep]).all()  # bit for bit
    moved = (P != P0).any(axis=1)
    print(f"  {moved.sum()} of {len(P)} vertices moved, {len(keep)} kept")
    assert moved.sum() > 20 and not moved[keep].any()


def test_fill_a_hole():
    V, F = elastica.read(os.path.join(DATA, "bunny_flank_hole.ply"))
    ob = mesh_object("bunny", V, F)
    me = ob.data
    P0, faces0 = positions(me).copy(), len(me.polygons)
    assert bpy.ops.mesh.elastica_fill_holes() == {'FINISHED'}
    assert len(me.polygons) > faces0 and not me.validate()
    sel = np.empty(len(me.polygons), bool)
    me.polygons.foreach_get("select", sel)
    assert not sel[:faces0].any() and sel[faces0:].all()
    P = positions(me)
    assert (P[: len(P0)] == P0).all()
    # The module on the same float32 input: the same patch (to 1e-6 of the diagonal).
    V2, F2, new, _ = elastica.fill_holes(P0.astype(np.float64), F)
    assert len(V2) == len(P) and np.abs(P - V2).max() <= 1e-6 * diagonal(V2)
    assert (triangles(me)[faces0:] == F2[new]).all()
    print(f"  {faces0} -> {len(me.polygons)} faces")
    # In Edit Mode too: the mesh (closed now) has nothing to fill, and Edit Mode is kept.
    bpy.ops.object.mode_set(mode='EDIT')
    assert bpy.ops.mesh.elastica_fill_holes() == {'FINISHED'} and bpy.context.mode == 'EDIT_MESH'
    bpy.ops.object.mode_set(mode='OBJECT')


def test_curvature_of_a_sphere():
    bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=4, radius=2.0)
    me = bpy.context.active_object.data
    assert bpy.ops.mesh.elastica_curvature() == {'FINISHED'}
    H = np.empty(len(me.vertices), np.float32)
    me.attributes["mean_curvature"].data.foreach_get("value", H)
    print(f"  H in [{H.min():.5f}, {H.max():.5f}], 1/r = 0.5")
    assert np.abs(H - 0.5).max() < 0.01 * 0.5
    color = me.attributes["mean_curvature_color"]
    assert color.data_type == 'FLOAT_COLOR' and me.color_attributes.active_color.name == color.name
    assert "gaussian_curvature" in me.attributes


def test_bad_input_is_reported_not_raised():
    # Three triangles on one edge: non-manifold. Blender keeps running; the operator is cancelled.
    ob = mesh_object("nonmanifold", [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1]],
                     [[0, 1, 2], [1, 0, 3], [0, 1, 4]])
    P0 = positions(ob.data).copy()
    for op in (bpy.ops.mesh.elastica_fair, bpy.ops.mesh.elastica_fill_holes, bpy.ops.mesh.elastica_curvature):
        try:
            op()
            raise AssertionError(f"{op} accepted a non-manifold mesh")
        except RuntimeError as e:  # bpy.ops turns an operator's ERROR report into this
            assert "manifold" in str(e), e
    assert (positions(ob.data) == P0).all()
    # Edit Mode with nothing selected.
    noisy_sphere("nothing", level=1)
    bpy.ops.object.mode_set(mode='EDIT')
    bpy.ops.mesh.select_all(action='DESELECT')
    try:
        bpy.ops.mesh.elastica_fair()
        raise AssertionError("fairing nothing was accepted")
    except RuntimeError as e:
        assert "no faces selected" in str(e), e
    assert bpy.context.mode == 'EDIT_MESH'
    bpy.ops.object.mode_set(mode='OBJECT')
    # A parameter out of the module's range (the panel's own limits stop a user; a script can try).
    try:
        bpy.ops.mesh.elastica_fair(flow="bilaplacian", scheme="semi-implicit")
        raise AssertionError("bilaplacian semi-implicit accepted")
    except RuntimeError as e:
        assert "Elastica" in str(e), e


def test_time_limit_stops_a_long_run_and_keeps_its_state():
    # A 40,962-vertex noisy sphere, explicit scheme to the limit shape: far longer than the limit
    # without it. How far past the limit the operator ends depends on the machine and its load, so
    # only the lower bound is checked (the stop reason is the time limit's).
    ob = noisy_sphere("long", level=6, noise=0.02)
    P0 = positions(ob.data).copy()
    props = bpy.ops.mesh.elastica_fair.get_rna_type().properties
    assert props["max_seconds"].default == 60 and props["max_seconds"].name == "Time limit (s)"
    limit = 2.0
    start = time.perf_counter()
    assert bpy.ops.mesh.elastica_fair(scheme="explicit", feature_size=0, max_steps=10**9, max_seconds=limit) == {'FINISHED'}
    took = time.perf_counter() - start
    print(f"  time limit {limit} s: the operator took {took:.2f} s")
    assert took >= limit, took
    assert not (positions(ob.data) == P0).all()  # a fair stopped by the limit keeps the state reached
    bpy.data.objects.remove(ob)


def test_cancel_through_the_progress_callback_leaves_the_mesh():
    # What Esc does in the modal operator: the worker's next progress call returns False.
    operators = importlib.import_module(ADDON + ".operators")
    ob = noisy_sphere("cancelled", level=6, noise=0.02)
    me = ob.data
    P0 = positions(me).copy()
    op = bpy.ops.mesh.elastica_fair.get_rna_type()
    assert op.bl_rna.identifier == "MESH_OT_elastica_fair"
    cls = next(c for c in operators.classes if c.bl_idname == "mesh.elastica_fair")
    arrays = operators.ma.MeshArrays(me)
    job = operators.Job(lambda progress: operators.elastica.fair(arrays.V, arrays.F, scheme="explicit",
                                                                 max_steps=10**9, max_seconds=60, progress=progress))
    for _ in range(100):  # running, reporting progress
        if job.latest is not None:
            break
        time.sleep(0.05)
    assert not job.done() and job.latest is not None
    start = time.perf_counter()
    job.cancel()
    assert job.wait(5), "the cancel was not taken within 5 s"
    print(f"  cancelled after {job.latest['step']} steps, {time.perf_counter() - start:.3f} s after the request")
    assert job.cancelled and isinstance(job.error, elastica.Error) and "cancel" in str(job.error).lower()
    assert job.result is None and (positions(me) == P0).all()
    assert cls.background and hasattr(cls, "modal")
    bpy.data.objects.remove(ob)


def test_imports_under_factory_startup_from_the_add_on_folder():
    # install.sh puts the module beside the add-on: a Blender started with --factory-startup (no user
    # modules folder on the path, no PYTHONPATH) imports it from there. The legacy add-on's layout only:
    # an installed Extension (scripts/blender5.sh) imports the module from the wheel Blender installed.
    if ADDON != "elastica_blender":
        print("  (legacy add-on layout: not run for the Extension " + ADDON + ")")
        return
    import shutil
    import subprocess
    import tempfile
    build = os.environ["ELASTICA_BUILD_DIR"]
    source = os.environ["ELASTICA_SOURCE_DIR"]
    with tempfile.TemporaryDirectory() as scripts:
        addon = os.path.join(scripts, "addons", "elastica_blender")
        shutil.copytree(os.path.join(source, "blender_addon", "elastica_blender"), addon)
        for so in os.listdir(os.path.join(build, "python")):
            if so.startswith("elastica") and so.endswith(".so"):
                shutil.copy(os.path.join(build, "python", so), addon)
        env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        env["BLENDER_USER_SCRIPTS"] = scripts
        r = subprocess.run([bpy.app.binary_path, "-b", "--factory-startup", "--python-exit-code", "1", "--python-expr",
                            "import addon_utils, bpy, elastica, sys\n"
                            "addon_utils.enable('elastica_blender', default_set=True, handle_error=None)\n"
                            "import elastica\n"
                            "assert elastica.__file__.startswith(sys.argv[-1]), elastica.__file__\n"
                            "bpy.ops.mesh.primitive_ico_sphere_add(radius=2)\n"
                            "assert bpy.ops.mesh.elastica_curvature() == {'FINISHED'}\n"
                            "print('factory-startup import: ok')", "--", addon],
                           env=env, capture_output=True, text=True, timeout=60)
        assert "factory-startup import: ok" in r.stdout, r.stdout + r.stderr


def main():
    addon_utils.enable(ADDON, default_set=True, handle_error=None)
    assert ADDON in bpy.context.preferences.addons
    tests = [f for name, f in globals().items() if name.startswith("test_")]
    failed = []
    for t in tests:
        print(f"[ RUN  ] {t.__name__}", flush=True)
        try:
            t()
            print(f"[  OK  ] {t.__name__}", flush=True)
        except Exception:
            traceback.print_exc()
            failed.append(t.__name__)
            print(f"[ FAIL ] {t.__name__}", flush=True)
    print(f"{len(tests) - len(failed)} of {len(tests)} passed" + (f"; failed: {', '.join(failed)}" if failed else ""))
    if failed:
        sys.exit(1)


main()
