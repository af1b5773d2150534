# SPDX-License-Identifier: GPL-3.0-or-later
"""A Blender mesh as NumPy arrays and back, in bulk (foreach_get / foreach_set): no per-vertex Python.

Coordinates are the mesh's own (object space): the object's transform is neither applied nor changed.
Blender stores float32; the module computes in float64 from exactly those values, so a vertex the
flow does not move is written back bit for bit. Polygons are split into Blender's loop triangles for
the module; the polygons themselves stay as they are (fairing moves vertices only)."""
import numpy as np


class MeshArrays:
    """V (n, 3) float64, F (t, 3) int32 loop triangles, tri_poly (t,) the polygon of each triangle."""

    def __init__(self, me):
        n = len(me.vertices)
        co = np.empty(3 * n, np.float32)
        me.vertices.foreach_get("co", co)
        me.calc_loop_triangles()
        t = len(me.loop_triangles)
        tris = np.empty(3 * t, np.int32)
        me.loop_triangles.foreach_get("vertices", tris)
        self.tri_poly = np.empty(t, np.int32)
        me.loop_triangles.foreach_get("polygon_index", self.tri_poly)
        self.co32 = co.reshape(n, 3)
        self.V = self.co32.astype(np.float64)
        self.F = tris.reshape(t, 3)

    def selected_triangles(self, me):
        """A bool per loop triangle: its polygon is selected."""
        sel = np.empty(len(me.polygons), bool)
        me.polygons.foreach_get("select", sel)
        return sel[self.tri_poly]


def reference_key(me):
    """The shape key the mesh's coordinates mirror (Basis), or None."""
    return me.shape_keys.reference_key if me.shape_keys else None


def write_positions(me, V):
    """Vertex positions (n, 3) into the mesh, and into its Basis shape key so that the shape shown
    follows; the other shape keys are left alone (Blender keeps each key's own coordinates)."""
    co = np.ascontiguousarray(V, dtype=np.float32).ravel()
    me.vertices.foreach_set("co", co)
    key = reference_key(me)
    if key is not None:
        key.data.foreach_set("co", co)
    me.update()


def append_triangles(me, V, new_tris):
    """Appends the vertices V[len(me.vertices):] and the triangles new_tris (indices into V) as
    polygons; existing vertices, edges, polygons and their attributes stay as they are (new elements
    get Blender's defaults). Returns the new polygons' indices."""
    n_old, p_old, l_old = len(me.vertices), len(me.polygons), len(me.loops)
    k, m = len(V) - n_old, len(new_tris)
    smooth = np.empty(p_old, bool)
    me.polygons.foreach_get("use_smooth", smooth)
    me.vertices.add(k)
    me.loops.add(3 * m)
    me.polygons.add(m)
    co = np.empty(3 * len(me.vertices), np.float32)
    me.vertices.foreach_get("co", co)
    co[3 * n_old:] = np.asarray(V[n_old:], np.float32).ravel()
    me.vertices.foreach_set("co", co)
    vi = np.empty(len(me.loops), np.int32)
    me.loops.foreach_get("vertex_index", vi)
    vi[l_old:] = np.asarray(new_tris, np.int32).ravel()
    me.loops.foreach_set("vertex_index", vi)
    for name, tail in (("loop_start", l_old + 3 * np.arange(m, dtype=np.int32)), ("loop_total", np.full(m, 3, np.int32))):
        a = np.empty(len(me.polygons), np.int32)
        me.polygons.foreach_get(name, a)
        a[p_old:] = tail
        me.polygons.foreach_set(name, a)
    s = np.empty(len(me.polygons), bool)
    me.polygons.foreach_get("use_smooth", s)
    s[p_old:] = p_old > 0 and smooth.mean() >= 0.5  # like most of the mesh
    me.polygons.foreach_set("use_smooth", s)
    me.update(calc_edges=True)
    return np.arange(p_old, p_old + m)


def replace_geometry(me, V, F):
    """The mesh rebuilt as the triangles F on the vertices V (after subdivision or remeshing: point,
    corner and face attributes start afresh; materials stay)."""
    me.clear_geometry()
    me.vertices.add(len(V))
    me.loops.add(3 * len(F))
    me.polygons.add(len(F))
    me.vertices.foreach_set("co", np.asarray(V, np.float32).ravel())
    me.loops.foreach_set("vertex_index", np.asarray(F, np.int32).ravel())
    me.polygons.foreach_set("loop_start", 3 * np.arange(len(F), dtype=np.int32))
    me.polygons.foreach_set("loop_total", np.full(len(F), 3, np.int32))
    me.update(calc_edges=True)


def select_only_polygons(me, polygons):
    """Selects exactly these polygons, with their vertices and edges (consistent flags for Edit Mode)."""
    psel = np.zeros(len(me.polygons), bool)
    psel[polygons] = True
    me.polygons.foreach_set("select", psel)
    loop_start = np.empty(len(me.polygons), np.int32)
    loop_total = np.empty(len(me.polygons), np.int32)
    me.polygons.foreach_get("loop_start", loop_start)
    me.polygons.foreach_get("loop_total", loop_total)
    vi = np.empty(len(me.loops), np.int32)
    me.loops.foreach_get("vertex_index", vi)
    poly_of_loop = np.repeat(np.arange(len(psel)), loop_total)
    within = np.arange(loop_total.sum()) - np.repeat(np.cumsum(loop_total) - loop_total, loop_total)
    loops = np.repeat(loop_start, loop_total) + within
    vsel = np.zeros(len(me.vertices), bool)
    vsel[vi[loops[psel[poly_of_loop]]]] = True
    me.vertices.foreach_set("select", vsel)
    ev = np.empty(2 * len(me.edges), np.int32)
    me.edges.foreach_get("vertices", ev)
    ev = ev.reshape(-1, 2)
    me.edges.foreach_set("select", vsel[ev[:, 0]] & vsel[ev[:, 1]])


def ramp_colors(values):
    """MeshLab's quality ramp (red low, yellow, green, cyan, blue high) over the 2-98 % percentiles,
    as the `elastica` command and the MeshLab filters colour by H. RGBA float32 (n, 4)."""
    lo, hi = np.percentile(values, [2, 98]) if len(values) else (0.0, 1.0)
    t = np.clip((values - lo) / (hi - lo), 0, 1) if hi > lo else np.full(len(values), 0.5)
    stops = np.linspace(0, 1, 5)
    rgb = [np.interp(t, stops, c) for c in ((1, 1, 0, 0, 0), (0, 1, 1, 1, 0), (0, 0, 0, 1, 1))]
    return np.column_stack(rgb + [np.ones(len(values))]).astype(np.float32)


def store_point_attribute(me, name, kind, values, field):
    """A point-domain attribute `name` of type `kind` ('FLOAT' or 'FLOAT_COLOR') set from values
    (replaced if it exists with another type or domain)."""
    a = me.attributes.get(name)
    if a is not None and (a.data_type != kind or a.domain != 'POINT'):
        me.attributes.remove(a)
        a = None
    if a is None:
        a = me.attributes.new(name, kind, 'POINT')
    a.data.foreach_set(field, np.ascontiguousarray(values, np.float32).ravel())
    return a
