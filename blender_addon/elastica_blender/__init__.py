# SPDX-License-Identifier: GPL-3.0-or-later
"""Elastica for Blender: fair meshes, fill holes and measure curvature with the discrete elastica flow
(Yoshizawa & Belyaev 2002), through the Python module `elastica` (the project's python/).

Operators, in Edit Mode's Mesh > Clean Up menu, Object Mode's Object > Clean Up menu and F3 search:
  mesh.elastica_fair        Edit Mode: the selected faces move, two rings of vertices around them stay
                            fixed; Object Mode: the whole mesh.
  mesh.elastica_fill_holes  fills holes; the new faces come selected.
  mesh.elastica_curvature   point attributes mean_curvature (+1/r on a sphere) and gaussian_curvature,
                            and the colour attribute mean_curvature_color by H.
Each has a redo panel with the MeshLab filters' parameters and defaults, read from the module
(elastica.filters()). They work on the active object's own mesh, in object space: the object's
transform is neither applied nor changed (a non-uniformly scaled object is faired as its mesh
data, not as shown), modifiers are not applied, shape keys and other attributes are kept."""

bl_info = {
    "name": "Elastica",
    "author": "Elastica contributors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "View3D > Edit Mode > Mesh > Clean Up; Object > Clean Up; F3",
    "description": "Fair meshes, fill holes and measure curvature with the discrete elastica flow",
    "category": "Mesh",
}

if "operators" in locals():  # F8 / reload: pick up edited files
    import importlib

    importlib.reload(mesh_arrays)  # noqa: F821
    importlib.reload(operators)  # noqa: F821
from . import mesh_arrays, operators  # noqa: E402,F401


def register():
    operators.register()


def unregister():
    operators.unregister()
