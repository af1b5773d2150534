// SPDX-License-Identifier: GPL-3.0-or-later
// Running a job: core options → the core, on a TriMesh copy, with what a face needs afterwards
// (the write-back decision, the output curvature, summary lines with their severity); and, for
// the MeshLab filters and .mlx scripts, parameter values → core options first (readJob). The vcglib-facing half (copying in and
// writing back) is in filter_apply.h; this half is plain C++, so its numerics are the same
// whoever calls it (the `elastica` command, the MeshLab plugin, `elastica run`, Python, Blender).
#pragma once

#include <elastica/mesh_curvature.h>
#include <elastica/topology.h>
#include <elastica/app/filter_spec.h>
#include <elastica/face_set.h>
#include <elastica/flow.h>
#include <elastica/hole_filling.h>
#include <elastica/types.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace elastica::app {

/// Progress of a long filter: a percentage and a line of text. Returning false cancels.
using Progress = std::function<bool(int percent, const std::string& what)>;

/// The flow's progress as a face shows it: the larger of the share of the time limit used
/// (o.maxSeconds, wall time from this call), of o.maxSteps taken and of the coarse-to-fine stages
/// begun, capped at 99 % and never going back; so it moves with the time used instead of creeping
/// along the share of a large maxSteps and jumping at the end. Empty if `progress` is. `clock`
/// gives the seconds since some fixed time (default: the steady clock; tests inject their own).
using Clock = std::function<double()>;
std::function<bool(const FlowProgress&)> flowProgress(const Progress& progress, const FlowOptions& o,
                                                      const Clock& clock = {});

/// How much a summary line matters: MeshLab logs a warning as one; the other faces print both.
enum class Severity { Info, Warning };

/// A summary line for the user.
struct LogLine {
  Severity severity = Severity::Info;
  std::string text;
};

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
FilterOutputs filterOutputs(FilterId id, const JobOptions& job);

/// FlowOptions::maxSteps for a step limit as the faces take it: 0 means no limit.
long long stepLimit(long long steps);

/// What a fairing run produced (the input copy is not touched on failure).
struct FairingResult {
  TriMesh mesh;                          ///< the faired mesh (subdivided if asked)
  std::optional<FaceSet> region;         ///< the region's faces in `mesh`, refined with it (if one was given)
  bool connectivityChanged = false;      ///< subdivided or flipped: write the whole mesh back
  bool outputCurvature = false;          ///< `curvature` holds the result's H and K
  MeshCurvature curvature;               ///< of the result, when outputCurvature
  /// The whole mesh's total curvature energy, of the input as given and of the result (as
  /// `elastica curvature` measures them). The region's are report.regionEnergyBefore / After;
  /// report.energyInitial is the flow's own start: after any refinement or remeshing, over the
  /// vertices that move and their first fixed ring.
  double meshEnergyBefore = 0, meshEnergyAfter = 0;
  FlowReport report;
  std::vector<LogLine> log;              ///< summary lines for the user
  /// The flow's own energies when its start differs from the input's (after refinement or
  /// remeshing, or over a region); also in `log`. Empty otherwise.
  std::string flowEnergyLine;
  /// The fairing amount the run used (fairing_amount.h), if it had one.
  struct Amount {
    double featureSize = 0;  ///< the length used (after halvings); 0: none, the flow ran to its limit shape
    double edges = 0;        ///< featureSize in mean edge lengths of the faces to fair
    double perDiagonal = 0;  ///< featureSize as a fraction of the input's bounding-box diagonal
    bool automatic = false;  ///< sized by autoFeatureSize ("auto", every face's default)
    int halvings = 0;        ///< times it was halved because it raised the energy (kAmountHalvings)
    /// The filter's operators (AmountOperators::Graph on a rough scan, fairing_amount.h).
    AmountOperators operators = AmountOperators::Cotangent;
    /// surfaceRoughness of the faces to fair, before and after; a result rougher than
    /// kRoughResult gets `suggested`, the amount on the input that adds the result's own (else 0).
    double roughnessBefore = 0, roughnessAfter = 0, suggested = 0;
  } amount;
  /// How far the vertices moved, RMS and largest, when the run kept the connectivity (-1 when it
  /// did not), and the input's bounding-box diagonal to state them in.
  double movedRms = -1, movedMax = -1, diagonal = 0;
  /// The amount and the distance moved as `log` words them (empty when not known), for faces that
  /// print their own summary.
  std::string amountLine, movedLine;
  /// The result is still rough (Amount::suggested): what it measured and the amount to try; or empty.
  std::string roughLine;
  /// A region faired to its limit shape by the default scheme: whether its mesh resolves it (the
  /// Loop-subdivided energy's rise, FlowReport::regionResolutionGap) and which scheme's result came
  /// back; empty otherwise.
  std::string resolutionLine;
};

/// Fairs `mesh` with `opt`: the whole mesh without a `region`, else the region's faces. With
/// `outputCurvature`, also measures the result (opt.area and opt.curvature). The one fairing path
/// of every face. Checks what the faces' paths check first: the options against the table's
/// ranges (checkOptions), the mesh (checkedTopology, non-manifold vertices refused, with `hints`)
/// and a region with faces. opt.featureSize kAutoFeatureSize is sized from the faces to fair
/// (autoFeatureSize); that default amount, if it raises the energy, is halved and run again
/// (kAmountHalvings). An amount the caller chose runs as chosen.
/// @throws InvalidInputError (bad options or mesh, an empty region, nothing can move, ...),
///         FlowDivergedError (with the report so far), Error (the progress callback cancelled).
FairingResult runFairing(TriMesh mesh, std::optional<FaceSet> region, const FlowOptions& opt, bool outputCurvature,
                         RepairHints hints = RepairHints::None);

/// Fairs `mesh` as "Discrete Elastica Fairing" with values `v` (`selection`: the selected faces,
/// used when the Selected parameter is on).
/// @throws InvalidInputError (non-manifold or inconsistently oriented input, nothing selected,
///         bad parameters, ...), NumericalError (the flow diverged), Error (cancelled).
FairingResult runFairing(TriMesh mesh, std::optional<FaceSet> selection, const ParamValues& v,
                         const Progress& progress);

/// What a hole-filling run produced: the original vertices and faces unchanged and first, the new
/// ones appended.
struct FillHolesResult {
  TriMesh mesh;
  int originalVertices = 0, originalFaces = 0;
  HoleFillReport report;               ///< per hole; report.isNewFace(f); report.welds
  bool outputCurvature = false;        ///< `curvature` holds the result's H and K
  MeshCurvature curvature;             ///< of the result, when outputCurvature
  std::vector<LogLine> log;            ///< one line per hole, and a total
};

/// Fills the holes of `mesh` with `opt` (with `outputCurvature`, also measures the result with
/// opt.flow.area and opt.flow.curvature). The one hole-filling path of every face. Checks the
/// options against the table's ranges (checkOptions); the mesh is the caller's to check
/// (checkFillInput; the CLI's readers already refuse what it refuses).
/// @throws InvalidInputError (non-manifold edges, bad options).
FillHolesResult runFillHoles(TriMesh mesh, const HoleFillOptions& opt, bool outputCurvature = false);

/// Fills the holes of `mesh` as "Fill Holes with Discrete Elastica" with values `v`.
/// @throws InvalidInputError (non-manifold or inconsistently oriented input, bad parameters).
FillHolesResult runFillHoles(TriMesh mesh, const ParamValues& v, const Progress& progress);

/// What a curvature measurement produced.
struct CurvatureResult {
  MeshCurvature curvature;
  bool lambdaFix = false;
  std::vector<LogLine> log;  ///< H's range, λ, degenerate elements, the energy

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
