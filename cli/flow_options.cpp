#include "flow_options.h"

#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/app/filter_spec.h>

#include <limits>

namespace elastica::cli {

CLI::Validator parameterRange(app::FilterId filter, const std::string& parameter) {
  const app::FilterSpec spec = app::filterSpec(filter, {});  // outlives the ParamSpec read from it
  const app::ParamSpec* p = spec.param(parameter);
  const double lo = p->minValue, hi = p->maxValue;
  auto str = [](double x) { return CLI::detail::to_string(x); };
  const std::string range = hi < std::numeric_limits<double>::infinity() ? "in " + str(lo) + ".." + str(hi) : ">= " + str(lo);
  return CLI::Validator(
      [=](std::string& s) -> std::string {
        double x = 0;
        if (!CLI::detail::lexical_cast(s, x) || !(x >= lo && x <= hi)) return "Value " + s + " is not " + range;
        return {};
      },
      range);
}

void addFlowOptions(CLI::App& cmd, FlowOptions& opt) {
  cmd.add_option("--flow", opt.flow,
                 "elastica (default: F = -Lap H - 2H(H^2-K)), lmc (F = -Lap H) or bilaplacian (P -= tau U0^2 P)")
      ->transform(CLI::CheckedTransformer(app::nameMap<FlowType>(), CLI::ignore_case));
  cmd.add_option("--scheme", opt.scheme,
                 "auto (fair's default: vector, or semi-implicit on meshes with handles and under 1500 vertices per "
                 "handle), vector (implicit in the positions, adaptive steps that move vertices tangentially too, with "
                 "remeshing), semi-implicit (fill's default: implicit in the 4th-order part, normal moves) or explicit "
                 "(the paper's step; the bilaplacian flow's only scheme)")
      ->transform(CLI::CheckedTransformer(app::nameMap<Scheme>(), CLI::ignore_case));
  cmd.add_option("--max-steps", opt.maxSteps, "step limit over all stages (0: no limit)")
      ->capture_default_str()
      ->check(parameterRange(app::FilterId::Fairing, "maxSteps"));
  cmd.add_option("--max-seconds", opt.maxSeconds, "wall-time limit (0: none)")->check(CLI::NonNegativeNumber);
  cmd.add_option("--energy-tol", opt.energyTolerance,
                 "stop when the relative energy change per unit of normalised time t/A^2 is below this")
      ->capture_default_str()
      ->check(parameterRange(app::FilterId::Fairing, "energyTolerance"));
  cmd.add_option("--shape-tol", opt.shapeTolerance,
                 "semi-implicit scheme only: also stop once a step at the scale of the moving region moves no vertex along its "
                 "normal by more than this times the mean edge length (fill's default 1e-3; fair's 0: off)")
      ->check(CLI::NonNegativeNumber);
  cmd.add_flag("--no-tangential{false}", opt.tangentialDrift, "disable the tangential drift that keeps triangles even");
  cmd.add_option("--h2k", opt.curvature.h2k, "H^2-K < 0: clamp (default) or lambda (the paper's rescaling, guarded)")
      ->transform(CLI::CheckedTransformer(app::nameMap<H2KTreatment>(), CLI::ignore_case));
  cmd.add_option("--area", opt.area, "vertex area: mixed (default) or barycentric (the paper's A/3)")
      ->transform(CLI::CheckedTransformer(app::nameMap<VertexArea>(), CLI::ignore_case));
  cmd.add_option("--step-factor", opt.stepFactor, "explicit step tau = factor * A_min^2 (paper: 1/150)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  // Some options belong to one scheme: asking for one with the other scheme is an error, not a
  // silent ignore (--energy-tol means the same in both).
  CLI::App* command = &cmd;
  cmd.parse_complete_callback([command, &opt] {
    // The bilaplacian comparison flow is the paper's explicit iteration: without --scheme it runs
    // explicit rather than failing on the default.
    if (opt.flow == FlowType::Bilaplacian && command->count("--scheme") == 0) opt.scheme = Scheme::Explicit;
    opt.maxSteps = app::stepLimit(opt.maxSteps);
    const CLI::Option* noRemesh = command->get_option_no_throw("--no-remesh");  // fair's, not fill's
    if (opt.scheme == Scheme::Explicit && noRemesh && noRemesh->count() > 0)
      throw CLI::ValidationError("--no-remesh", "applies to the vector and semi-implicit schemes only (the explicit one never remeshes)");
    if (opt.scheme != Scheme::SemiImplicit && command->count("--shape-tol") > 0)
      throw CLI::ValidationError("--shape-tol", "applies to the semi-implicit scheme only (add --scheme semi-implicit)");
    if (opt.scheme != Scheme::Explicit && command->count("--step-factor") > 0)
      throw CLI::ValidationError("--step-factor",
                                 "sets the explicit scheme's step only (the other schemes adapt their own)");
  });
}

void addWholeMeshFlowOptions(CLI::App& cmd, FlowOptions& opt) {
  cmd.add_option("--subdivide", opt.subdivisionLevels,
                 "coarse-to-fine: 1-to-4 subdivisions, each when the flow is near steady state (with a selection, of the "
                 "selected faces only)")
      ->check(parameterRange(app::FilterId::Fairing, "subdivisionLevels"));
  cmd.add_option("--target-edge", opt.targetEdgeLength, "stop subdividing once the mean edge length is at most this")
      ->check(CLI::NonNegativeNumber);
  cmd.add_flag("--remesh", opt.flipEdges,
               "explicit scheme: dynamic connectivity, flip non-Delaunay edges among moving vertices at every check "
               "(the vector and semi-implicit schemes do this and more unless --no-remesh)");
  cmd.add_flag("--no-remesh{false}", opt.remesh,
               "vector and semi-implicit schemes: keep the connectivity (no working-resolution floor, no isotropic or "
               "curvature-adaptive remeshing, no edge flips, no embedding guard)");
  cmd.add_option("--boundary", opt.boundary,
                 "fixed (default: boundary and next row clamped, G1) or slide (boundary vertices slide along it)")
      ->transform(CLI::CheckedTransformer(app::nameMap<BoundaryMode>(), CLI::ignore_case));
}

}  // namespace elastica::cli
