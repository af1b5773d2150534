// SPDX-License-Identifier: GPL-3.0-or-later
#include <elastica/app/choices.h>

namespace elastica::app {

template <>
const std::vector<Choice<FlowType>>& choices<FlowType>() {
  static const std::vector<Choice<FlowType>> t{{FlowType::Elastica, "elastica", "Elastica"},
                                               {FlowType::LaplacianOfMeanCurvature, "lmc", "Laplacian of mean curvature"},
                                               {FlowType::Bilaplacian, "bilaplacian", "Bilaplacian"}};
  return t;
}

template <>
const std::vector<Choice<Scheme>>& choices<Scheme>() {
  static const std::vector<Choice<Scheme>> t{{Scheme::Explicit, "explicit", "Explicit"},
                                             {Scheme::SemiImplicit, "semi-implicit", "Semi-implicit"},
                                             {Scheme::Vector, "vector", "Vector (implicit in positions)"},
                                             {Scheme::Automatic, "auto", "Automatic"}};
  return t;
}

template <>
const std::vector<Choice<BoundaryMode>>& choices<BoundaryMode>() {
  static const std::vector<Choice<BoundaryMode>> t{{BoundaryMode::Fixed, "fixed", "Fixed"},
                                                   {BoundaryMode::Slide, "slide", "Slide"}};
  return t;
}

template <>
const std::vector<Choice<H2KTreatment>>& choices<H2KTreatment>() {
  static const std::vector<Choice<H2KTreatment>> t{{H2KTreatment::Clamp, "clamp", "Clamp"},
                                                   {H2KTreatment::PaperLambda, "lambda", "Paper's lambda"}};
  return t;
}

template <>
const std::vector<Choice<VertexArea>>& choices<VertexArea>() {
  static const std::vector<Choice<VertexArea>> t{{VertexArea::Mixed, "mixed", "Mixed"},
                                                 {VertexArea::Barycentric, "barycentric", "Barycentric"}};
  return t;
}

template <>
const std::vector<Choice<FillStage>>& choices<FillStage>() {
  static const std::vector<Choice<FillStage>> t{{FillStage::Triangulation, "triangulation", "Triangulation"},
                                                {FillStage::Refinement, "refinement", "Refinement"},
                                                {FillStage::Biharmonic, "biharmonic", "Bi-Laplace"},
                                                {FillStage::Flow, "flow", "Flow"}};
  return t;
}

template <>
const std::vector<Choice<StopReason>>& choices<StopReason>() {
  static const std::vector<Choice<StopReason>> t{
      {StopReason::Converged, "converged", "converged"},
      {StopReason::Stalled, "stalled", "stalled: no step lowers the energy any more"},
      {StopReason::MaxSteps, "max_steps", "stopped at maxSteps"},
      {StopReason::MaxSeconds, "max_seconds", "stopped at the time limit"},
      {StopReason::Cancelled, "cancelled", "cancelled"},
      {StopReason::Diverged, "diverged", "diverged"},
      {StopReason::Shrunk, "shrunk", "stopped: the flow shrinks the surface (the comparison flows do)"},
      {StopReason::SelfContact, "self_contact", "stopped: going on would make the surface cross itself"},
      {StopReason::FeatureSize, "feature_size", "faired to the feature size"},
      {StopReason::Unchanged, "unchanged", "unchanged: no state of the flow improved the region without breaking the mesh"}};
  return t;
}

}  // namespace elastica::app
