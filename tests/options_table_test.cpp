// SPDX-License-Identifier: GPL-3.0-or-later
// The options table (app/filter_spec.h), for every filter: each row's names and its field agree,
// its defaults are the core's (but for the dialogs' documented bounds), every value in range is
// taken and written into its field, a bad value per parameter is refused naming it as the caller
// does, and the entry points check options filled by hand (runFairing, runFillHoles).
#include <elastica/app/choices.h>
#include <elastica/app/filter_run.h>
#include <elastica/app/filter_spec.h>
#include <elastica/errors.h>
#include <elastica/shapes.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

namespace elastica::app {
namespace {

const FilterId kFilters[] = {FilterId::Fairing, FilterId::FillHoles, FilterId::Curvature};

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInputError& e) {
    return e.what();
  }
  return {};
}

// A value in range other than the default, to see that it reaches its field.
double anotherValue(const ParamSpec& p, double current) {
  switch (p.type) {
    case ParamType::Bool: return current != 0 ? 0 : 1;
    case ParamType::Enum: return current == 0 ? 1 : 0;
    case ParamType::Int: return current == p.minValue ? p.minValue + 1 : p.minValue;
    case ParamType::Float:
    case ParamType::AbsPerc: break;
  }
  return current == 0.25 ? 0.5 : 0.25;  // in every Float range
}

TEST(OptionsTable, NamesAreUniqueAndEveryRowHasAFieldAndHelp) {
  for (FilterId id : kFilters) {
    const FilterSpec spec = filterSpec(id, {});
    std::set<std::string> keys, names, flags, keywords, properties;
    for (const ParamSpec& p : spec.params) {
      SCOPED_TRACE(spec.name + ": " + p.field);
      EXPECT_FALSE(p.field.empty());
      EXPECT_TRUE(p.set && p.get);
      EXPECT_FALSE(p.label.empty());
      EXPECT_FALSE(p.tooltip.empty());
      EXPECT_TRUE(keys.insert(p.key()).second);
      if (p.inMeshLab()) {
        EXPECT_TRUE(names.insert(p.name).second);
      }
      if (!p.cliFlag.empty()) {
        EXPECT_TRUE(flags.insert(p.cliFlag).second);
      }
      if (!p.keyword.empty()) {
        EXPECT_TRUE(keywords.insert(p.keyword).second);
      }
      if (!p.blenderProperty.empty()) {
        EXPECT_TRUE(properties.insert(p.blenderProperty).second);
      }
      EXPECT_TRUE(p.inMeshLab() || !p.cliFlag.empty() || !p.keyword.empty() || !p.blenderProperty.empty());
      if (p.type == ParamType::Enum) {
        EXPECT_EQ(p.enumValues.size(), p.enumWords.size());
      }
    }
  }
}

// The names scripts key on, row by row (a rename breaks .mlx scripts, command lines, Python and
// Blender files).
TEST(OptionsTable, NamesOnEveryFaceAreStable) {
  struct Expected {
    FilterId id;
    const char *field, *mlx, *cli, *keyword, *blender;
  };
  const Expected rows[] = {
      {FilterId::Fairing, "flow.flow", "flow", "--flow", "flow", "flow"},
      {FilterId::Fairing, "flow.scheme", "scheme", "--scheme", "scheme", "scheme"},
      {FilterId::Fairing, "flow.maxSteps", "maxSteps", "--max-steps", "max_steps", "max_steps"},
      {FilterId::Fairing, "flow.maxSeconds", "maxSeconds", "--max-seconds", "max_seconds", "max_seconds"},
      {FilterId::Fairing, "flow.featureSize", "featureSize", "--feature-size", "feature_size", "feature_size"},
      {FilterId::Fairing, "flow.subdivisionLevels", "subdivisionLevels", "--subdivide", "subdivide", "subdivide"},
      {FilterId::Fairing, "flow.targetEdgeLength", "", "--target-edge", "", ""},
      {FilterId::Fairing, "flow.energyTolerance", "energyTolerance", "--energy-tol", "energy_tol", "energy_tol"},
      {FilterId::Fairing, "flow.shapeTolerance", "", "--shape-tol", "", ""},
      {FilterId::Fairing, "flow.tangentialDrift", "tangentialDrift", "--no-tangential", "tangential", "tangential"},
      {FilterId::Fairing, "flow.curvature.h2k", "", "--h2k", "", ""},
      {FilterId::Fairing, "flow.area", "", "--area", "", ""},
      {FilterId::Fairing, "flow.stepFactor", "", "--step-factor", "", ""},
      {FilterId::Fairing, "flow.flipEdges", "", "--flip-edges", "flip_edges", ""},
      {FilterId::Fairing, "flow.remesh", "", "--no-remesh", "remesh", ""},
      {FilterId::Fairing, "flow.boundary", "boundary", "--boundary", "boundary", "boundary"},
      {FilterId::Fairing, "selected", "Selected", "--selected", "", ""},
      {FilterId::Fairing, "colorByMeanCurvature", "colorByMeanCurvature", "--color-by-mean-curvature", "",
       "color_by_mean_curvature"},
      {FilterId::FillHoles, "fill.maxHoleEdges", "MaxHoleSize", "--max-hole-edges", "max_hole_edges", "max_hole_edges"},
      {FilterId::FillHoles, "fill.closeRims", "CloseRims", "--close-rims", "close_rims", "close_rims"},
      {FilterId::FillHoles, "fill.stopAfter", "", "--stop-after", "", ""},
      {FilterId::FillHoles, "fill.refinement.density", "", "--density", "", ""},
      {FilterId::FillHoles, "fill.flow.flow", "flow", "--flow", "flow", "flow"},
      {FilterId::FillHoles, "fill.flow.scheme", "scheme", "--scheme", "scheme", "scheme"},
      {FilterId::FillHoles, "fill.flow.maxSteps", "maxSteps", "--max-steps", "max_steps", "max_steps"},
      {FilterId::FillHoles, "fill.flow.maxSeconds", "maxSeconds", "--max-seconds", "max_seconds", "max_seconds"},
      {FilterId::FillHoles, "fill.flow.energyTolerance", "", "--energy-tol", "", ""},
      {FilterId::FillHoles, "fill.flow.shapeTolerance", "", "--shape-tol", "", ""},
      {FilterId::FillHoles, "fill.flow.tangentialDrift", "", "--no-tangential", "", ""},
      {FilterId::FillHoles, "fill.flow.curvature.h2k", "", "--h2k", "", ""},
      {FilterId::FillHoles, "fill.flow.area", "", "--area", "", ""},
      {FilterId::FillHoles, "fill.flow.stepFactor", "", "--step-factor", "", ""},
      {FilterId::FillHoles, "selectNewFaces", "NewFaceSelected", "", "", "select_new_faces"},
      {FilterId::FillHoles, "colorByMeanCurvature", "", "--color-by-mean-curvature", "", ""},
      {FilterId::Curvature, "curvature.curvature.h2k", "lambdaFix", "--lambda-fix", "lambda_fix", "lambda_fix"},
      {FilterId::Curvature, "curvature.area", "area", "--area", "area", "area"},
  };
  std::size_t counted[3] = {0, 0, 0};
  for (const Expected& e : rows) {
    const FilterSpec spec = filterSpec(e.id, {});
    const ParamSpec* p = nullptr;
    for (const ParamSpec& q : spec.params)
      if (q.field == e.field) p = &q;
    ASSERT_NE(p, nullptr) << e.field;
    EXPECT_EQ(p->name, e.mlx) << e.field;
    EXPECT_EQ(p->cliFlag, e.cli) << e.field;
    EXPECT_EQ(p->keyword, e.keyword) << e.field;
    EXPECT_EQ(p->blenderProperty, e.blender) << e.field;
    ++counted[static_cast<int>(e.id)];
  }
  for (FilterId id : kFilters) EXPECT_EQ(filterSpec(id, {}).params.size(), counted[static_cast<int>(id)]);
  EXPECT_EQ(filterSpec(FilterId::Fairing, {}).row("flow.flipEdges")->cliAlias, "--remesh");
}

// The CLI and Python start from the core's defaults; the dialogs (MeshLab, Blender) take the
// row's, which differ only in the documented places.
TEST(OptionsTable, DefaultsAreTheCoresButTheDialogsBounds) {
  const JobOptions core;
  for (FilterId id : kFilters) {
    for (const ParamSpec& p : filterSpec(id, {}).params) {
      SCOPED_TRACE(p.field);
      const std::string& n = p.name;
      if (n == "maxSeconds") {
        EXPECT_EQ(p.defaultValue, 60);
        continue;
      }
      if (p.field == "flow.featureSize") {  // "auto" in the core's options; the dialog shows the mesh's amount
        EXPECT_EQ(p.get(core), kAutoFeatureSize);
        EXPECT_EQ(p.defaultValue, 0);  // no mesh, no amount
        continue;
      }
      const double expected = p.type == ParamType::Float && p.inMeshLab() ? double(float(p.get(core))) : p.get(core);
      EXPECT_EQ(p.defaultValue, expected);
    }
  }
  // The core's defaults, through the rows.
  EXPECT_EQ(filterSpec(FilterId::Fairing, {}).param("scheme")->get(core), indexOf(Scheme::Automatic));
  EXPECT_EQ(filterSpec(FilterId::FillHoles, {}).param("scheme")->get(core), indexOf(HoleFillOptions{}.flow.scheme));
  EXPECT_EQ(filterSpec(FilterId::FillHoles, {}).param("MaxHoleSize")->defaultValue, HoleFillOptions{}.maxHoleEdges);
  // The mesh's facts: Selected is on when the mesh has a selection; featureSize is a length.
  EXPECT_EQ(filterSpec(FilterId::Fairing, {3, 2.0}).param("Selected")->defaultValue, 1);
  EXPECT_EQ(filterSpec(FilterId::Fairing, {0, 2.0}).param("Selected")->defaultValue, 0);
  EXPECT_EQ(filterSpec(FilterId::Fairing, {0, 2.0, 0.05}).param("featureSize")->defaultValue, 0.05);
}

// Every row: a value in range reaches its field (read back by the row) and leaves the others at
// their defaults; reading no values gives the core's defaults.
TEST(OptionsTable, EveryValueReachesItsFieldAlone) {
  for (FilterId id : kFilters) {
    const FilterSpec spec = filterSpec(id, {});
    const JobOptions core;
    const JobOptions none = readJob(spec, ParamValues(), Caller::Python);
    for (const ParamSpec& p : spec.params) EXPECT_EQ(p.get(none), p.get(core)) << p.field;
    for (const ParamSpec& p : spec.params) {
      SCOPED_TRACE(spec.name + ": " + p.field);
      ParamValues v;
      const double x = anotherValue(p, p.get(core));
      v.set(p.key(), x);
      const JobOptions job = readJob(spec, v, Caller::MeshLab);
      EXPECT_EQ(p.get(job), x);
      for (const ParamSpec& q : spec.params) {
        if (q.field != p.field) {
          EXPECT_EQ(q.get(job), q.get(core)) << "and " << q.field;
        }
      }
    }
  }
}

TEST(OptionsTable, SpecialRowsWriteTheCoresValue) {
  const FilterSpec fairing = filterSpec(FilterId::Fairing, {});
  ParamValues v;
  v.set("maxSteps", 0);  // 0: no limit
  EXPECT_EQ(readJob(fairing, v, Caller::MeshLab).flow.maxSteps, std::numeric_limits<long long>::max());
  v.set("maxSteps", 25);
  EXPECT_EQ(readJob(fairing, v, Caller::MeshLab).flow.maxSteps, 25);
  // featureSize: one unit on every face, a length in the mesh's units (what reports print); -1 is
  // "auto" everywhere (the shipped fairing.mlx says it).
  ParamValues f;
  f.set("featureSize", 12.8665);
  for (Caller caller : {Caller::MeshLab, Caller::Cli, Caller::Python, Caller::Blender})
    EXPECT_EQ(readJob(fairing, f, caller).flow.featureSize, 12.8665);
  f.set("featureSize", -1);
  EXPECT_EQ(readJob(fairing, f, Caller::MeshLab).flow.featureSize, kAutoFeatureSize);
  // The lambda fix: the one place a bool becomes the H² − K treatment.
  ParamValues c;
  c.set("lambdaFix", 1);
  EXPECT_EQ(readJob(filterSpec(FilterId::Curvature, {}), c, Caller::Cli).curvature.curvature.h2k, H2KTreatment::PaperLambda);
  c.set("lambdaFix", 0);
  EXPECT_EQ(readJob(filterSpec(FilterId::Curvature, {}), c, Caller::Cli).curvature.curvature.h2k, H2KTreatment::Clamp);
}

// A bad value per parameter: below the minimum (or at an excluded one), above the maximum, NaN, an
// enum index outside its table; each refused naming the parameter as its caller does.
TEST(OptionsTable, ABadValuePerParameterIsRefusedByName) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  int refused = 0;
  for (FilterId id : kFilters) {
    const FilterSpec spec = filterSpec(id, {});
    for (const ParamSpec& p : spec.params) {
      if (p.type == ParamType::Bool) continue;  // every value is a bool
      SCOPED_TRACE(spec.name + ": " + p.field);
      std::vector<double> bad{nan};
      if (p.type == ParamType::Enum) bad = {-1, double(p.enumWords.size()), 0.5};
      else {
        // -1 is an AbsPerc's "auto"; below 0 otherwise is refused.
        bad.push_back(p.minExclusive ? p.minValue : p.minValue - (p.type == ParamType::AbsPerc ? 0.5 : 1));
        if (std::isfinite(p.maxValue)) bad.push_back(p.maxValue + 1);
      }
      for (double x : bad) {
        for (Caller caller : {Caller::MeshLab, Caller::Cli, Caller::Python, Caller::Blender}) {
          ParamValues v;
          v.set(p.key(), x);
          const std::string message = messageOf([&] { readJob(spec, v, caller); });
          ASSERT_FALSE(message.empty()) << x;
          EXPECT_EQ(message.rfind(p.describe(caller), 0), 0u) << message;
          ++refused;
        }
      }
    }
  }
  EXPECT_GT(refused, 100);
  // The words, as faces show them.
  const FilterSpec fairing = filterSpec(FilterId::Fairing, {});
  EXPECT_EQ(fairing.param("maxSteps")->describe(Caller::MeshLab), "'Maximum steps' (maxSteps)");
  EXPECT_EQ(fairing.param("maxSteps")->describe(Caller::Cli), "--max-steps");
  EXPECT_EQ(fairing.param("maxSteps")->describe(Caller::Python), "max_steps");
  EXPECT_EQ(fairing.param("maxSteps")->describe(Caller::Api), "flow.maxSteps");
  ParamValues v;
  v.set("subdivisionLevels", 9);
  EXPECT_EQ(messageOf([&] { readJob(fairing, v, Caller::Python); }), "subdivide must be in 0..8, not 9");
  ParamValues h;
  h.set("MaxHoleSize", 2);
  EXPECT_EQ(messageOf([&] { readJob(filterSpec(FilterId::FillHoles, {}), h, Caller::MeshLab); }),
            "'Max size to be closed' (MaxHoleSize) must be >= 3 (a hole has 3 edges or more), not 2");
}

// Options filled by hand meet the same checks at the front door, named by their fields.
TEST(OptionsTable, EntryPointsCheckOptionsFilledByHand) {
  const TriMesh sphere = shapes::icosphere(1.0, 1);
  FlowOptions o;
  o.maxSeconds = -1;
  EXPECT_EQ(messageOf([&] { runFairing(sphere, std::nullopt, o, false); }).rfind("flow.maxSeconds must be >= 0", 0), 0u);
  o = {};
  o.subdivisionLevels = 9;
  EXPECT_EQ(messageOf([&] { runFairing(sphere, std::nullopt, o, false); }).rfind("flow.subdivisionLevels must be in 0..8", 0),
            0u);
  o = {};
  o.maxSteps = -2;
  EXPECT_FALSE(messageOf([&] { runFairing(sphere, std::nullopt, o, false); }).empty());
  // The mesh and the region, as every face's path checks them.
  TriMesh flipped = sphere;
  std::swap(flipped.faces[0][0], flipped.faces[0][1]);
  EXPECT_NE(messageOf([&] { runFairing(flipped, std::nullopt, FlowOptions{}, false); }).find("not consistently oriented"),
            std::string::npos);
  EXPECT_NE(messageOf([&] { runFairing(sphere, FaceSet({}), FlowOptions{}, false); }).find("no faces"), std::string::npos);
  HoleFillOptions f;
  f.maxHoleEdges = 2;
  EXPECT_EQ(messageOf([&] { runFillHoles(sphere, f); }).rfind("fill.maxHoleEdges must be >= 3", 0), 0u);
  f = {};
  f.refinement.density = 0;
  EXPECT_EQ(messageOf([&] { runFillHoles(sphere, f); }).rfind("fill.refinement.density must be > 0", 0), 0u);
}

// Severity is a field: a run stopped by its limit says so as a warning, not by a prefix.
TEST(OptionsTable, LimitWarningsCarryTheirSeverity) {
  ParamValues v = ParamValues::defaults(filterSpec(FilterId::Fairing, {}));
  v.set("scheme", indexOf(Scheme::Explicit));
  v.set("maxSteps", 3);
  const FairingResult r = runFairing(shapes::icosphere(1.0, 1), std::nullopt, v, {});
  int warnings = 0;
  for (const LogLine& line : r.log) {
    EXPECT_EQ(line.text.rfind("warning", 0), std::string::npos) << line.text;
    if (line.severity == Severity::Warning) {
      ++warnings;
      EXPECT_NE(line.text.find("'Maximum steps' (maxSteps)"), std::string::npos) << line.text;
    }
  }
  EXPECT_EQ(warnings, 1);
}

}  // namespace
}  // namespace elastica::app
