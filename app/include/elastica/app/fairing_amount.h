// The fairing amount every face starts from ("auto"): a feature size sized from the faces to fair,
// so that pressing OK on a scan gives a fairer surface of the same model, as MeshLab's own
// smoothing filters do, and never the flow's limit shape (a sphere), which stays one choice away
// (feature size 0).
//
// The amount is kAutoFeatureEdges times the kAutoEdgeQuantile quantile of the faces' edge lengths,
// not of their mean: the amount's filter runs one flow time for the whole mesh, and a scan that is
// finer where its detail is lost that detail to an amount sized from the mean edge. Measurements:
// docs/options.md, "The default amount".
#pragma once

#include <elastica/face_set.h>
#include <elastica/types.h>

#include <vector>

namespace elastica::app {

/// FlowOptions::featureSize as JobOptions holds it before a run: "auto", resolved by runFairing
/// (autoFeatureSize) once the mesh is known. Never reaches the core.
inline constexpr double kAutoFeatureSize = -1;
inline constexpr double kAutoFeatureEdges = 2;
inline constexpr double kAutoEdgeQuantile = 0.25;
/// The default amount, if it would raise the energy of what it fairs (a feature smaller than it
/// collapsing into a needle), is halved and run again, at most this many times; then the input
/// comes back. An amount the user chose is not halved.
inline constexpr int kAmountHalvings = 4;

/// kAutoFeatureEdges × the kAutoEdgeQuantile quantile of `edgeLengths` (each face's three edges;
/// an inner edge counted twice changes no quantile much). 0 for no edges. Reorders `edgeLengths`.
double autoFeatureSize(std::vector<double>& edgeLengths);

/// The same for `mesh`, over the faces of `region` (all faces without one).
double autoFeatureSize(const TriMesh& mesh, const FaceSet* region);

/// The mean edge length of the faces to fair (each face's three edges), to state an amount in it.
double meanFaceEdge(const TriMesh& mesh, const FaceSet* region);

}  // namespace elastica::app
