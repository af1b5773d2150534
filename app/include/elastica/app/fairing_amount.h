// SPDX-License-Identifier: GPL-3.0-or-later
// The fairing amount every face starts from ("auto"): a feature size sized from the faces to fair,
// so that pressing OK on a scan gives a fairer surface of the same model, as MeshLab's own
// smoothing filters do, and never the flow's limit shape (a sphere), which stays one choice away
// (feature size 0).
//
// The amount is a length in the mesh's units on every face: amountEdges(roughness) times the
// kAutoEdgeQuantile quantile of the faces' edge lengths, rounded to 6 significant digits so that
// the value printed is the value used. The edge quantile, not the mean: the amount runs one flow
// time for the whole mesh, and a scan finer where its detail is lost that detail to an amount
// sized from the mean. The roughness (surfaceRoughness) raises it where the surface is noisy.
// A rough scan without long slivers (amountOperatorsFor) is faired with uniform operators
// (AmountOperators::Graph) instead of its noisy cotangents, by graphAmountEdges(roughness) MEAN
// edges: with one area scale their Laplacian reads a finer region's edges as the mean edge, so
// they smooth each region by that many of its own edges (no fine feature gets the coarse amount).
// Measurements: docs/options.md, "The default amount".
#pragma once

#include <elastica/face_set.h>
#include <elastica/flow.h>
#include <elastica/types.h>

#include <string>
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

/// The roughness below which a surface counts as clean (a scan as scanned), and the amount's
/// growth above it, in edge lengths per unit of roughness.
inline constexpr double kCleanRoughness = 0.1;
inline constexpr double kEdgesPerRoughness = 16;
/// A result rougher than this is reported as still rough, with a larger amount suggested.
inline constexpr double kRoughResult = 0.1;

/// A surface rougher than kGraphRoughness whose mean edge is at most kGraphMaxEdgeRatio of its
/// kAutoEdgeQuantile edges is faired with AmountOperators::Graph: its cotangents and mixed areas,
/// built from the noise, are poor, and an even mesh loses little by uniform ones. Long slivers
/// (the CAD part joint: 6.6) keep cotangents, which know the slivers' shape. The gate is below
/// kCleanRoughness: 3-D vertex noise of 0.1 edge reads 0.052-0.116 on eight libcgal-demo scans,
/// their clean selves 0.002-0.039, or 0.057-0.098 where the scanner left its own noise (armadillo,
/// cow, bull); knot1's thin tube reads 0.044 at 0.1 edge and keeps the cotangents, which fair it
/// closer than the uniform operators at this rule's amount (docs/options.md, "The default amount").
inline constexpr double kGraphRoughness = 0.045;
inline constexpr double kGraphMaxEdgeRatio = 4;
/// The Graph amount in mean edge lengths: kGraphEdges + kGraphEdgesPerRoughness · (ρ − kCleanRoughness),
/// for the twiced filter that uniform operators run (flow/fairing.cpp, featureSizeStage).
inline constexpr double kGraphEdges = 2.2;
inline constexpr double kGraphEdgesPerRoughness = 6;
/// The default amount of a mesh's faces, with the operators it runs with and the roughness it
/// was sized from.
struct AutoAmount {
  double featureSize = 0;
  AmountOperators operators = AmountOperators::Cotangent;
  double roughness = 0;
};

/// The amount in edge lengths for a surface of `roughness` (surfaceRoughness): kAutoFeatureEdges
/// on a clean surface, more on a noisy one.
double amountEdges(double roughness);

/// How rough the faces of `region` (all faces without one) are: the median over their vertices of
/// the height over the neighbours' centre along the normal, less the neighbours' own mean height,
/// in median edge lengths. Smooth curvature cancels in the difference; vertex noise does not
/// (3-D noise uniform in a ball of 0.3 edge gives about 0.1). 0 for no faces.
double surfaceRoughness(const TriMesh& mesh, const FaceSet* region);

/// The Graph operators' amount in mean edge lengths for a surface of `roughness` (taken as at least
/// kGraphRoughness).
double graphAmountEdges(double roughness);

/// The operators for faces of `roughness`, mean edge `meanEdge` and kAutoEdgeQuantile edge
/// `quantileEdge` (kGraphMaxEdgeRatio).
AmountOperators amountOperatorsFor(double roughness, double meanEdge, double quantileEdge);

/// The default amount for faces with these edges (each face's three edges; an inner edge counted
/// twice changes no quantile much) and `roughness`: with the cotangents, amountEdges(roughness) ×
/// the kAutoEdgeQuantile edge; with Graph operators, graphAmountEdges(roughness) × the mean edge;
/// rounded (roundedAmount). 0 for no edges. Reorders `edgeLengths`.
AutoAmount autoAmount(std::vector<double>& edgeLengths, double roughness);

/// The same for `mesh`, over the faces of `region` (all faces without one), with its roughness.
AutoAmount autoAmount(const TriMesh& mesh, const FaceSet* region);

/// autoAmount's featureSize: the amount "auto" stands for.
double autoFeatureSize(const TriMesh& mesh, const FaceSet* region);

/// `x` to 6 significant digits: an amount that prints as it is.
double roundedAmount(double x);

/// The shortest decimal (6 significant digits or more) that reads back as `x` exactly: what a
/// user can type back.
std::string exactDecimal(double x);

/// The mean edge length of the faces to fair (each face's three edges), to state an amount in it.
double meanFaceEdge(const TriMesh& mesh, const FaceSet* region);

}  // namespace elastica::app
