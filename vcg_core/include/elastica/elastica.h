// SPDX-License-Identifier: GPL-3.0-or-later
// Elastica's public API in one include: fair a mesh with the discrete elastica flow (fairing.h),
// fill its holes (hole_filling.h), measure its curvature (mesh_curvature.h).
//
//   #include <elastica/elastica.h>
//   elastica::TriMesh mesh = ...;                      // positions + triangles (types.h)
//   elastica::FlowReport r = elastica::fair(mesh);     // fairing.h; or fair(mesh, FaceSet(faces), opt)
//   elastica::fillHoles(mesh);                         // hole_filling.h
//   elastica::MeshCurvature c = elastica::measureCurvature(mesh);  // H, K and E: mesh_curvature.h
//
// The vcglib adapters (vcg_adapter.h, vcg_mesh.h) are not included here: they need vcglib.
#pragma once

#include <elastica/curvature.h>
#include <elastica/energy.h>
#include <elastica/errors.h>
#include <elastica/face_set.h>
#include <elastica/fairing.h>
#include <elastica/flow.h>
#include <elastica/geometry.h>
#include <elastica/hole_filling.h>
#include <elastica/laplacian.h>
#include <elastica/mesh_curvature.h>
#include <elastica/mesh_quality.h>
#include <elastica/shapes.h>
#include <elastica/sign_convention.h>
#include <elastica/subdivision.h>
#include <elastica/topology.h>
#include <elastica/types.h>
#include <elastica/vertex_faces.h>
#include <elastica/vertex_fans.h>
