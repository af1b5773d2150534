// SPDX-License-Identifier: GPL-3.0-or-later
// The JSON reports of the jobs: what `elastica fair|fill --report R.json` writes and what the
// Python module returns as a dict, built in one place. Keys are snake_case; words (stop reasons,
// flows, stages) come from choices.h. A face adds its own entries (the CLI: file names).
#pragma once

#include <elastica/app/filter_run.h>
#include <elastica/flow.h>
#include <elastica/hole_filling.h>

#include <nlohmann/json.hpp>

namespace elastica::app {

/// energy_initial, energy_final (the flow's own: over the vertices that move and their first fixed
/// ring, on its working mesh), for a region's run region_energy_before, region_energy_after (the
/// region's faces' vertices, input and output) and, if the run's last state was refused,
/// refused_because and kept_stage (the stage whose end came back; -1: the input, stop unchanged);
/// steps, rejected_steps, seconds, stop, min_lambda, stages[], energy_history[].
nlohmann::json toJson(const FlowReport& r);

/// One hole: border_edges, filled, reason, and if filled new_vertices, new_faces, energy_before,
/// energy_after, steps, stop, min_angle_degrees, border_bound_degrees, seconds and stages[]
/// ({stage, kept, min_angle_degrees, energy, steps, why}).
nlohmann::json toJson(const HoleReport& h);

/// A fairing run: the flow report, "flow", "input" {vertices, faces} and, for a finished run
/// (`result` given), "output" {vertices, faces}, "mesh_energy_before" and "mesh_energy_after" (the
/// whole mesh's E, input and output, measured as `elastica curvature` does, apart from the flow).
nlohmann::json fairingReport(const FlowReport& r, const FlowOptions& opt, int inputVertices, int inputFaces,
                             const FairingResult* result = nullptr);

/// A hole-filling run: "input", "output", stop_after, max_hole_edges, filled, skipped,
/// vertex_copies_merged, seconds, holes[].
nlohmann::json fillingReport(const FillHolesResult& r, const HoleFillOptions& opt);

}  // namespace elastica::app
