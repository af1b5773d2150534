// Running a job: core options → the core, on a TriMesh copy, with what a face needs afterwards
// (the write-back decision, the output curvature, summary lines); and, for the MeshLab filters
// and .mlx scripts, parameter values → core options first. The vcglib-facing half (copying in and
// writing back) is in filter_apply.h; this half is plain C++, so its numerics are the same
// whoever calls it (the `elastica` command, the MeshLab plugin or `elastica run`).
#pragma once

#include <elastica/mesh_curvature.h>
#include <elastica/topology.h>
#include <elastica/app/filter_spec.h>
#include <elastica/flow.h>
#include <elastica/hole_filling.h>
#include <elastica/types.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace elastica::app {

/// Progress of a long filter: a percentage and a line of text. Returning false cancels.
using Progress = std::function<bool(int percent, const std::string& what)>;

/// The flow's progress as a face shows it: the larger of the share of the time limit used
/// (o.maxSeconds, wall time from this call), of o.maxSteps taken and of the coarse-to-fine stages
/// begun, capped at 99 % and never going back; so it moves with the time used instead of creeping
/// along the share of a large maxSteps and jumping at the end. Empty if `progress` is.
std::function<bool(const FlowProgress&)> flowProgress(const Progress& progress, const FlowOptions& o);

/// Whether an input error names MeshLab's repair filters.
enum class RepairHints { None, MeshLab };

/// Builds the topology of `mesh` and rejects what no job can handle: no faces, non-manifold edges
/// (Topology), inconsistently oriented faces and, if asked, non-manifold vertices.
/// @throws InvalidInputError saying what is wrong (and, with RepairHints::MeshLab, how to repair it
///         in MeshLab).
Topology checkedTopology(const TriMesh& mesh, bool rejectNonManifoldVertices, RepairHints hints);

/// Rejects what checkedTopology rejects with rejectNonManifoldVertices, for a mesh about to be
/// filled: counted with a vertex→faces index (countFillInputDefects), never a whole-mesh Topology.
/// @throws InvalidInputError as checkedTopology.
void checkFillInput(const TriMesh& mesh, RepairHints hints);

/// What a filter leaves on the mesh besides positions and faces (for the data MeshLab must keep,
/// and what `elastica run` writes).
struct FilterOutputs {
  bool curvature = false;      ///< vertex quality and colour by H; mean/gaussian_curvature attributes
  bool faceSelection = false;  ///< the face selection was set
};
FilterOutputs filterOutputs(FilterId id, const ParamValues& v);

/// The FlowOptions a "Discrete Elastica Fairing" parameter set stands for.
/// @throws InvalidInputError naming the parameter if a value is out of range.
FlowOptions fairingOptions(const ParamValues& v);

/// What a fairing run produced (the input copy is not touched on failure).
/// FlowOptions::maxSteps for a step limit as the faces take it: 0 means no limit.
long long stepLimit(long long steps);

struct FairingResult {
  TriMesh mesh;                          ///< the faired mesh (subdivided if asked)
  std::vector<std::uint8_t> selection;   ///< the face selection, refined with the mesh (if one was given)
  bool connectivityChanged = false;      ///< subdivided or flipped: write the whole mesh back
  bool outputCurvature = false;          ///< `curvature` holds the result's H and K
  MeshCurvature curvature;               ///< of the result, when outputCurvature
  /// The whole mesh's total curvature energy, of the input as given and of the result (as
  /// `elastica curvature` measures them). report.energyInitial is the flow's own start: after any
  /// refinement or remeshing, over the region that moves.
  double energyInput = 0, energyOutput = 0;
  FlowReport report;
  std::vector<std::string> log;          ///< summary lines for the user
};

/// Fairs `mesh` with `opt`: the whole mesh if `selection` is empty, else the faces whose byte is
/// non-zero (one per face). With `outputCurvature`, also measures the result (opt.area and
/// opt.curvature). The one fairing path of every face.
/// @throws InvalidInputError (nothing can move, bad options, ...), FlowDivergedError (with the
///         report so far), Error (the progress callback cancelled).
FairingResult runFairing(TriMesh mesh, std::vector<std::uint8_t> selection, const FlowOptions& opt,
                         bool outputCurvature);

/// Fairs `mesh` as "Discrete Elastica Fairing" with values `v` (`selection`: one byte per face,
/// used when the Selected parameter is on).
/// @throws InvalidInputError (non-manifold or inconsistently oriented input, nothing selected,
///         bad parameters, ...), NumericalError (the flow diverged), Error (cancelled).
FairingResult runFairing(TriMesh mesh, std::vector<std::uint8_t> selection, const ParamValues& v,
                         const Progress& progress);

/// The HoleFillOptions a "Fill Holes with Discrete Elastica" parameter set stands for.
/// @throws InvalidInputError naming the parameter if a value is out of range.
HoleFillOptions fillHolesOptions(const ParamValues& v);

/// What a hole-filling run produced: the original vertices and faces unchanged and first, the new
/// ones appended.
struct FillHolesResult {
  TriMesh mesh;
  int originalVertices = 0, originalFaces = 0;
  HoleFillReport report;               ///< per hole; report.isNewFace(f); report.welds
  bool outputCurvature = false;        ///< `curvature` holds the result's H and K
  MeshCurvature curvature;             ///< of the result, when outputCurvature
  std::vector<std::string> log;        ///< one line per hole, and a total
};

/// Fills the holes of `mesh` with `opt` (with `outputCurvature`, also measures the result with
/// opt.flow.area and opt.flow.curvature). The one hole-filling path of every face.
/// @throws InvalidInputError (non-manifold edges, bad options).
FillHolesResult runFillHoles(TriMesh mesh, const HoleFillOptions& opt, bool outputCurvature = false);

/// Fills the holes of `mesh` as "Fill Holes with Discrete Elastica" with values `v`.
/// @throws InvalidInputError (non-manifold or inconsistently oriented input, bad parameters).
FillHolesResult runFillHoles(TriMesh mesh, const ParamValues& v, const Progress& progress);

/// What a curvature measurement produced.
struct CurvatureResult {
  MeshCurvature curvature;
  bool lambdaFix = false;
  std::vector<std::string> log;  ///< H's range, λ, degenerate elements, the energy

  /// The H a face outputs: H/λ where the paper's λ fix applied, else H (reported sign).
  const std::vector<double>& outputH() const { return lambdaFix ? curvature.Hlambda : curvature.H; }
};

/// Measures `mesh` with `opt`. The one curvature path of every face.
/// @throws InvalidInputError (non-manifold edges).
CurvatureResult runCurvature(const TriMesh& mesh, const CurvatureMeasureOptions& opt);

/// Measures `mesh` as "Discrete Elastica Curvature" with values `v`.
/// @throws InvalidInputError (non-manifold edges, inconsistent orientation, bad parameters).
CurvatureResult runCurvature(const TriMesh& mesh, const ParamValues& v);

}  // namespace elastica::app
