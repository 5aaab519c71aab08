// The MeshLab filter's parameters, as the real plugin makes them for a document with a layer
// built in memory: every option of the library's table, under its MeshLab spelling, with the
// table's default (or its "unset" number) and the range in its tooltip; and read back, the
// library's own options.
#include <common/meshmodel.h>

#include <gtest/gtest.h>

#include <cmath>

#include "filter_vorocrust.hpp"
#include "option_parameters.hpp"
#include "vorocrust/options.hpp"
#include "vorocrust/vcg.hpp"

namespace {

using vorocrust::OptionKind;
using vorocrust::OptionSpec;

// A document with one layer: a tetrahedron built in memory.
struct Document {
  MeshDocument md;
  Document() {
    MeshModel* m = md.addNewMesh("", "tetrahedron");
    vorocrust::SurfaceMesh tetrahedron;
    tetrahedron.groups.push_back({"tetrahedron", ""});
    tetrahedron.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const vorocrust::Triangle& t : {vorocrust::Triangle{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}) {
      tetrahedron.add_triangle(t, 0);
    }
    vorocrust::to_vcg(tetrahedron, m->cm);
  }
};

RichParameterList parameters_of(int filter) {
  Document doc;
  FilterVoroCrustPlugin plugin;
  QAction* action = plugin.actions().at(filter);
  RichParameterList parameters;
  plugin.initParameterSet(action, doc.md, parameters);
  return parameters;
}

double number(const OptionSpec& spec, const vorocrust::OptionValue& v) {
  if (v.index() == 0) return *spec.unset_number;
  if (const auto* n = std::get_if<std::int64_t>(&v)) return static_cast<double>(*n);
  return std::get<double>(v);
}

TEST(FilterParameters, EveryOptionOfTheTableWithItsNameDefaultAndRange) {
  const RichParameterList parameters = parameters_of(FilterVoroCrustPlugin::FP_VORONOI_MESH);
  std::size_t checked = 0;
  for (const OptionSpec& spec : vorocrust::mesh_option_specs()) {
    if (!(spec.front_ends & vorocrust::kMeshLab)) continue;
    SCOPED_TRACE(std::string(spec.name));
    const QString key = QString::fromStdString(vorocrust::option_spelling(spec, vorocrust::Spelling::MeshLab));
    if (spec.kind == OptionKind::Choices) {
      const auto& chosen = std::get<std::vector<std::string>>(spec.default_value);
      for (std::string_view choice : spec.choices) {
        const QString choice_key = vorocrust::meshlab::choice_parameter(spec, choice);
        ASSERT_TRUE(parameters.hasParameter(choice_key)) << choice_key.toStdString();
        EXPECT_EQ(parameters.getBool(choice_key), std::find(chosen.begin(), chosen.end(), choice) != chosen.end());
      }
      ++checked;
      continue;
    }
    ASSERT_TRUE(parameters.hasParameter(key)) << key.toStdString();
    const RichParameter& p = parameters.getParameterByName(key);
    EXPECT_EQ(p.fieldDescription().toStdString().rfind(std::string(spec.label), 0), 0u);
    const std::string tip = p.toolTip().toStdString();
    if (spec.kind != OptionKind::Flag) {
      EXPECT_NE(tip.find("range: " + vorocrust::range_text(spec)), std::string::npos) << tip;
    }
    switch (spec.kind) {
      case OptionKind::Flag: EXPECT_EQ(parameters.getBool(key), std::get<bool>(spec.default_value)); break;
      case OptionKind::Integer: EXPECT_EQ(parameters.getInt(key), number(spec, spec.default_value)); break;
      case OptionKind::Real:
        EXPECT_EQ(parameters.getFloat(key), static_cast<float>(number(spec, spec.default_value)));
        break;
      case OptionKind::Choice: {
        const int index = parameters.getEnum(key);
        ASSERT_GE(index, 0);
        EXPECT_EQ(spec.choices[static_cast<std::size_t>(index)], std::get<std::string>(spec.default_value));
        break;
      }
      case OptionKind::File: EXPECT_TRUE(parameters.getOpenFileName(key).isEmpty()); break;
      case OptionKind::Box: EXPECT_TRUE(parameters.getString(key).isEmpty()); break;
      case OptionKind::Choices: break;
    }
    ++checked;
  }
  EXPECT_EQ(checked, vorocrust::mesh_option_specs().size());
  // The filter's own: where the files go, and which layers.
  EXPECT_TRUE(parameters.hasParameter("outputFolder"));
  EXPECT_TRUE(parameters.hasParameter("allVisibleLayers"));
}

TEST(FilterParameters, ReadBackTheyAreTheLibrarysDefaults) {
  const vorocrust::MeshOptions got =
      vorocrust::meshlab::options_from_parameters(parameters_of(FilterVoroCrustPlugin::FP_VORONOI_MESH));
  const vorocrust::MeshOptions defaults;
  for (const OptionSpec& spec : vorocrust::mesh_option_specs()) {
    EXPECT_EQ(spec.get(got), spec.get(defaults)) << spec.name;
  }
}

TEST(FilterParameters, NumbersReadBackAsTyped) {
  // MeshLab holds floats: 0.0075 typed is 0.0075f, read back as the double 0.0075 the other front
  // ends read, not 0.007499999832.
  RichParameterList parameters = parameters_of(FilterVoroCrustPlugin::FP_VORONOI_MESH);
  parameters.setValue("smoothingTolerance", FloatValue(0.0075f));
  parameters.setValue("sharpAngle", FloatValue(45.3f));
  const vorocrust::MeshOptions got = vorocrust::meshlab::options_from_parameters(parameters);
  EXPECT_EQ(got.smoothing_tolerance, 0.0075);
  EXPECT_EQ(got.sharp_angle(), 45.3);
  // The unset number leaves the option to its mode: 60 with smooth.
  parameters.setValue("sharpAngle", FloatValue(0));
  parameters.setValue("smooth", BoolValue(true));
  EXPECT_EQ(vorocrust::meshlab::options_from_parameters(parameters).sharp_angle(), 60);
}

TEST(FilterParameters, AValueOutOfRangeIsNamedByItsLabel) {
  RichParameterList parameters = parameters_of(FilterVoroCrustPlugin::FP_VORONOI_MESH);
  parameters.setValue("lipschitz", FloatValue(1.5f));
  try {
    (void)vorocrust::meshlab::options_from_parameters(parameters);
    FAIL() << "no error";
  } catch (const vorocrust::Error& e) {
    EXPECT_EQ(std::string(e.what()), "\"Lipschitz constant L\" must lie strictly between 0 and 1, got 1.5");
  }
}

TEST(FilterParameters, TheBallsFilterOffersTheOptionsTheBallsDependOn) {
  const RichParameterList parameters = parameters_of(FilterVoroCrustPlugin::FP_PROTECTING_BALLS);
  for (const char* key : {"lipschitz", "smooth", "sharpAngle", "maxSize", "seed", "selfIntersections"}) {
    EXPECT_TRUE(parameters.hasParameter(key)) << key;
  }
  for (const char* key : {"interior", "stopAfter", "formatsVtu"}) EXPECT_FALSE(parameters.hasParameter(key)) << key;
}

TEST(VcgAdapter, ASurfaceGoesToVcgAndBackUnchanged) {
  Document doc;
  const CMeshO& cm = doc.md.mm()->cm;
  ASSERT_EQ(cm.vn, 4);
  ASSERT_EQ(cm.fn, 4);
  const vorocrust::SurfaceMesh back = vorocrust::from_vcg(cm, "tetrahedron", "memory");
  ASSERT_EQ(back.num_faces(), 4u);
  EXPECT_EQ(back.vertices[3], vorocrust::Point(0, 0, 1));
  EXPECT_EQ(back.triangles[1], (vorocrust::Triangle{0, 1, 3}));
  EXPECT_EQ(back.groups[0].name, "tetrahedron");
  EXPECT_EQ(back.groups[0].source_file, "memory");
}

}  // namespace
