// SPDX-License-Identifier: GPL-3.0-or-later
// The application layer's table of enumerated options (app/choices.h): every enumerator has one
// entry, names are unique, and the MeshLab menus keep their entries in .mlx index order.
#include <elastica/app/choices.h>
#include <elastica/app/filter_spec.h>

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace elastica::app {
namespace {

template <class E>
void expectComplete(std::initializer_list<E> all) {
  std::set<std::string> names;
  for (E e : all) {
    ASSERT_EQ(choiceOf(e).value, e) << "no entry for enumerator " << int(e);
    EXPECT_EQ(choices<E>()[static_cast<std::size_t>(indexOf(e))].value, e);
    EXPECT_TRUE(names.insert(nameOf(e)).second) << "name used twice: " << nameOf(e);
    EXPECT_EQ(nameMap<E>().at(nameOf(e)), e);
  }
  EXPECT_EQ(choices<E>().size(), all.size());
}

TEST(Choices, EveryEnumeratorHasOneNamedEntry) {
  expectComplete({FlowType::Elastica, FlowType::LaplacianOfMeanCurvature, FlowType::Bilaplacian});
  expectComplete({Scheme::Explicit, Scheme::SemiImplicit, Scheme::Vector, Scheme::Automatic});
  expectComplete({BoundaryMode::Fixed, BoundaryMode::Slide});
  expectComplete({H2KTreatment::Clamp, H2KTreatment::PaperLambda});
  expectComplete({VertexArea::Mixed, VertexArea::Barycentric});
  expectComplete({FillStage::Triangulation, FillStage::Refinement, FillStage::Biharmonic, FillStage::Flow});
  expectComplete({StopReason::Converged, StopReason::Stalled, StopReason::MaxSteps, StopReason::MaxSeconds,
                  StopReason::Cancelled, StopReason::Diverged, StopReason::Shrunk, StopReason::SelfContact,
                  StopReason::FeatureSize, StopReason::Unchanged});
}

// .mlx scripts store a RichEnum as its index: the menus' order is fixed forever.
TEST(Choices, MeshLabMenusKeepTheirOrder) {
  const FilterSpec fairing = filterSpec(FilterId::Fairing, {});
  EXPECT_EQ(fairing.param("flow")->enumValues,
            (std::vector<std::string>{"Elastica", "Laplacian of mean curvature", "Bilaplacian"}));
  EXPECT_EQ(fairing.param("scheme")->enumValues, (std::vector<std::string>{"Explicit", "Semi-implicit", "Vector (implicit in positions)", "Automatic"}));
  EXPECT_EQ(fairing.param("boundary")->enumValues, (std::vector<std::string>{"Fixed", "Slide"}));
  EXPECT_EQ(filterSpec(FilterId::Curvature, {}).param("area")->enumValues,
            (std::vector<std::string>{"Mixed", "Barycentric"}));
  // Defaults are the core's, found by value in the table.
  EXPECT_EQ(fairing.param("scheme")->defaultValue, indexOf(FlowOptions{}.scheme));
  EXPECT_EQ(filterSpec(FilterId::FillHoles, {}).param("scheme")->defaultValue,
            indexOf(HoleFillOptions{}.flow.scheme));
}

TEST(Choices, ReportWordsAreStable) {
  // Words that JSON reports and scripts read.
  EXPECT_STREQ(nameOf(StopReason::MaxSteps), "max_steps");
  EXPECT_STREQ(nameOf(Scheme::SemiImplicit), "semi-implicit");
  EXPECT_STREQ(nameOf(FlowType::LaplacianOfMeanCurvature), "lmc");
  EXPECT_STREQ(nameOf(FillStage::Biharmonic), "biharmonic");
}

}  // namespace
}  // namespace elastica::app
