// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/app/choices.h>
#include <elastica/app/reports.h>

#include <cmath>

namespace elastica::app {

nlohmann::json toJson(const FlowReport& r) {
  nlohmann::json j;
  j["energy_initial"] = r.energyInitial;
  j["energy_final"] = r.energyFinal;
  if (!r.regionFaces.empty() || r.stop == StopReason::Unchanged) {
    j["region_energy_before"] = r.regionEnergyBefore;
    j["region_energy_after"] = r.regionEnergyAfter;
    if (!std::isnan(r.regionResolutionGap)) j["region_resolution_gap"] = r.regionResolutionGap;
    j["region_runs"] = r.regionRuns;
  }
  if (!r.refusedBecause.empty()) {
    j["refused_because"] = r.refusedBecause;
    j["kept_stage"] = r.keptStage;
  }
  j["steps"] = r.steps;
  j["rejected_steps"] = r.rejectedSteps;
  j["mesh_quality"] = {{"pre_subdivisions", r.preSubdivisions},
                       {"remeshings", r.remeshings},
                       {"remeshings_refused", r.remeshingsRefused},
                       {"coarse_start_levels", r.coarseStartLevels},
                       {"vertex_budget", r.vertexBudget},
                       {"untangle_passes", r.untanglePasses},
                       {"crossing_rejections", r.crossingRejections},
                       {"input_self_intersects", r.inputSelfIntersects}};
  j["seconds"] = r.seconds;
  j["stop"] = nameOf(r.stop);
  j["scheme"] = nameOf(r.scheme);
  j["min_lambda"] = r.minLambda;
  j["stages"] = nlohmann::json::array();
  for (const FlowStage& s : r.stages)
    j["stages"].push_back({{"level", s.level}, {"vertices", s.vertices}, {"faces", s.faces}, {"steps", s.steps},
                           {"energy", s.energy}, {"seconds", s.seconds}});
  j["energy_history"] = nlohmann::json::array();
  for (const EnergySample& h : r.history)
    j["energy_history"].push_back({{"step", h.step}, {"time", h.time}, {"seconds", h.seconds}, {"energy", h.energy}});
  return j;
}

nlohmann::json toJson(const HoleReport& h) {
  nlohmann::json j{{"border_edges", h.borderEdges}, {"filled", h.filled}, {"rim", h.rim}};
  if (!h.reason.empty()) j["reason"] = h.reason;
  if (!h.filled) return j;
  j["new_vertices"] = h.newVertices;
  j["new_faces"] = h.newFaces;
  j["energy_before"] = h.energyBefore;
  j["energy_after"] = h.energyAfter;
  j["steps"] = h.steps;
  j["stop"] = nameOf(h.stop);
  j["min_angle_degrees"] = h.minAngleDegrees;
  j["border_bound_degrees"] = h.borderBoundDegrees;
  j["seconds"] = h.seconds;
  for (const FillStageReport& s : h.stages) {
    nlohmann::json stage{{"stage", s.stage}, {"kept", s.kept}, {"min_angle_degrees", s.minAngleDegrees}, {"energy", s.energy}, {"steps", s.steps}, {"seconds", s.seconds}};
    if (!s.why.empty()) stage["why"] = s.why;
    j["stages"].push_back(stage);
  }
  return j;
}

nlohmann::json fairingReport(const FlowReport& r, const FlowOptions& opt, int inputVertices, int inputFaces,
                             const FairingResult* result) {
  nlohmann::json j = toJson(r);
  j["input"] = {{"vertices", inputVertices}, {"faces", inputFaces}};
  j["flow"] = nameOf(opt.flow);
  // The amount as a length, the unit every face takes: the one the run used, when known.
  if (!result && opt.featureSize > 0) j["feature_size"] = opt.featureSize;
  if (result && result->amount.featureSize > 0) {
    const FairingResult::Amount& a = result->amount;
    j["feature_size"] = a.featureSize;
    j["feature_size_per_diagonal"] = a.perDiagonal;
    j["feature_size_edges"] = a.edges;
    j["feature_size_auto"] = a.automatic;
    j["feature_size_halvings"] = a.halvings;
    j["amount_operators"] = a.operators == AmountOperators::Graph ? "graph" : "cotangent";
    j["roughness_before"] = a.roughnessBefore;
    j["roughness_after"] = a.roughnessAfter;
    j["rough"] = a.suggested > 0;  // still rough: suggested_feature_size smooths it further
    if (a.suggested > 0) j["suggested_feature_size"] = a.suggested;
  }
  if (result && result->movedRms >= 0) {
    const double d = result->diagonal > 0 ? result->diagonal : 1;
    j["moved"] = {{"rms", result->movedRms},
                  {"max", result->movedMax},
                  {"rms_per_diagonal", result->movedRms / d},
                  {"max_per_diagonal", result->movedMax / d}};
  }
  if (result) {
    j["output"] = {{"vertices", result->mesh.vertexCount()}, {"faces", result->mesh.faceCount()}};
    j["mesh_energy_before"] = result->meshEnergyBefore;
    j["mesh_energy_after"] = result->meshEnergyAfter;
  }
  return j;
}

nlohmann::json fillingReport(const FillHolesResult& r, const HoleFillOptions& opt) {
  const HoleFillReport& report = r.report;
  const int filled = report.filledCount();
  nlohmann::json j{{"input", {{"vertices", r.originalVertices}, {"faces", r.originalFaces}}},
                   {"output", {{"vertices", r.mesh.vertexCount()}, {"faces", r.mesh.faceCount()}}},
                   {"stop_after", nameOf(opt.stopAfter)},
                   {"max_hole_edges", opt.maxHoleEdges},
                   {"close_rims", opt.closeRims},
                   {"filled", filled},
                   {"skipped", static_cast<int>(report.holes.size()) - filled},
                   {"vertex_copies_merged", report.welds.size()},
                   {"seconds", report.seconds},
                   {"holes", nlohmann::json::array()}};
  for (const HoleReport& h : report.holes) j["holes"].push_back(toJson(h));
  return j;
}

}  // namespace elastica::app
