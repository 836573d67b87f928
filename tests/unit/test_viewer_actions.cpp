// viewer/viewer_actions: the actions the panels, keys, bookmarks and scripts share. Each one
// validates like the command line (exit 2 naming the key or value, exit 3 for a bad file) and
// leaves the state untouched when it fails; camera keys and the interactive camera follow each
// other; a scene load keeps technique parameters; presets round-trip.
#include "frame/param_catalog.h"
#include "frame/registry.h"
#include "scene/builtin.h"
#include "scene/scene_params.h"
#include "viewer/viewer_actions.h"

#include <gtest/gtest.h>

#include "fake_technique.h"
#include "test_util.h"

using namespace rtlab;
using rtlab::test::catchError;
using rtlab::test::checkCaught;

namespace {

using rtlab::test::fakeTechnique;

const TechniqueRegistry& actionsRegistry() {
  static const TechniqueRegistry r = [] {
    TechniqueRegistry t;
    t.add(fakeTechnique("hard", "shadow", {ParamSpec::integer("hard.samples", "Samples", 16, 1, 64)},
                        {{"hard.depth", 1, ""}}));
    t.add(fakeTechnique("soft", "shadow", {ParamSpec::real("soft.width", "Width", 1.0, 0.0, 8.0)}));
    t.add(fakeTechnique("occ", "ao", {ParamSpec::real("occ.strength", "Strength", 0.5, 0.0, 2.0)}));
    t.add(fakeTechnique("grain", "post", {}));
    t.add(fakeTechnique("vignette", "post", {}));
    return t;
  }();
  return r;
}

ViewerState contactState() {
  ViewerState s(actionsRegistry());
  s.sceneSpec = "contact";
  s.scene = makeBuiltinScene("contact");
  s.params = makeParamSet(s.scene, actionsRegistry());
  s.camera.setHome(s.scene.camera);
  syncCameraFromParams(s);
  return s;
}

} // namespace

TEST(ViewerActions, TechniqueSelectionPerStageWithOff) {
  ViewerState s = contactState();
  selectTechniqueAction(s, "shadow", "hard");
  selectTechniqueAction(s, "ao", "occ");
  selectTechniqueAction(s, "shadow", "soft"); // replaces hard: the stage is exclusive
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"soft", "occ"}));
  selectTechniqueAction(s, "shadow", "off");
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"occ"}));
  EXPECT_TRUE(s.techniquesChanged);
  checkCaught(catchError([&] { selectTechniqueAction(s, "ao", "hard"); }), ExitCode::Usage, {"hard", "shadow"});
  checkCaught(catchError([&] { selectTechniqueAction(s, "nowhere", "off"); }), ExitCode::Usage, {"nowhere"});
  checkCaught(catchError([&] { selectTechniqueAction(s, "shadow", "nope"); }), ExitCode::Usage, {"nope"});
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"occ"}));
}

TEST(ViewerActions, ParametersAreCheckedAndRejectedEditsChangeNothing) {
  ViewerState s = contactState();
  setParamAction(s, "soft.width", 4.0);
  EXPECT_FLOAT_EQ(s.params.getFloat("soft.width"), 4.0f);
  const unsigned long revision = s.params.revision();
  checkCaught(catchError([&] { setParamAction(s, "soft.width", 9.0); }), ExitCode::Usage, {"soft.width", "8"});
  checkCaught(catchError([&] { setParamAction(s, "soft.nothing", 1.0); }), ExitCode::Usage, {"soft.nothing"});
  EXPECT_EQ(s.params.revision(), revision);
  resetParamAction(s, "soft.width");
  EXPECT_FLOAT_EQ(s.params.getFloat("soft.width"), 1.0f);
}

TEST(ViewerActions, CameraKeysAndInteractiveCameraFollowEachOther) {
  ViewerState s = contactState();
  setParamAction(s, "camera.position", nlohmann::json::array({1, 2, 3}));
  EXPECT_EQ(s.camera.camera().position, glm::vec3(1, 2, 3));
  cameraAction(s, std::nullopt, glm::vec3(0, 1, 0), 30.0f);
  EXPECT_EQ(s.camera.camera().target, glm::vec3(0, 1, 0));
  EXPECT_FLOAT_EQ(s.camera.camera().fovY, 30.0f);
  // A target equal to the position is rejected, and nothing moves.
  checkCaught(catchError([&] { cameraAction(s, glm::vec3(0, 1, 0), std::nullopt, std::nullopt); }), ExitCode::Usage,
              {"camera.target"});
  EXPECT_EQ(s.params.getVec3("camera.position"), glm::vec3(1, 2, 3));
  checkCaught(catchError([&] { cameraAction(s, std::nullopt, std::nullopt, 200.0f); }), ExitCode::Usage,
              {"camera.fov"});
  s.camera.orbit(glm::radians(30.0f), 0.0f);
  syncCameraToParams(s);
  EXPECT_EQ(s.params.getVec3("camera.position"), s.camera.camera().position);
  EXPECT_NE(s.params.getVec3("camera.position"), glm::vec3(1, 2, 3));
}

TEST(ViewerActions, ViewCompareAndRenderScaleValidateTheirFields) {
  ViewerState s = contactState();
  viewAction(s, {{"aov", "hard.depth"}, {"mode", "pip"}, {"min", -1}, {"max", 2}, {"false_color", true}});
  EXPECT_EQ(s.view.aov, "hard.depth");
  EXPECT_EQ(s.view.mode, DebugMode::Pip);
  EXPECT_FLOAT_EQ(s.view.min, -1.0f);
  EXPECT_TRUE(s.view.falseColor);
  checkCaught(catchError([&] { viewAction(s, {{"min", 3}}); }), ExitCode::Usage, {"min", "max"});
  checkCaught(catchError([&] { viewAction(s, {{"aov", "nothing"}}); }), ExitCode::Usage, {"nothing"});
  EXPECT_FLOAT_EQ(s.view.min, -1.0f);
  compareAction(s, {{"mode", "difference"}, {"divider", 0.25}});
  EXPECT_EQ(s.compare.mode, CompareMode::Difference);
  EXPECT_FLOAT_EQ(s.compare.divider, 0.25f);
  checkCaught(catchError([&] { compareAction(s, {{"divider", 1.5}}); }), ExitCode::Usage, {"divider"});
  renderScaleAction(s, 0.5);
  EXPECT_FLOAT_EQ(s.renderScale, 0.5f);
  checkCaught(catchError([&] { renderScaleAction(s, 0.05); }), ExitCode::Usage, {"render scale"});
  EXPECT_FLOAT_EQ(s.renderScale, 0.5f);
}

TEST(ViewerActions, SceneLoadKeepsTechniqueParametersAndTakesTheNewCamera) {
  ViewerState s = contactState();
  selectTechniqueAction(s, "shadow", "soft");
  setParamAction(s, "soft.width", 3.0);
  setParamAction(s, "camera.fov", 20.0);
  const unsigned long generation = s.sceneGeneration;
  loadSceneAction(s, "stacked");
  EXPECT_EQ(s.sceneSpec, "stacked");
  EXPECT_EQ(s.sceneGeneration, generation + 1);
  EXPECT_FLOAT_EQ(s.params.getFloat("soft.width"), 3.0f);
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"soft"}));
  const Scene stacked = makeBuiltinScene("stacked");
  EXPECT_EQ(s.camera.camera().position, stacked.camera.position);
  EXPECT_FLOAT_EQ(s.params.getFloat("camera.fov"), stacked.camera.fovY);
  checkCaught(catchError([&] { loadSceneAction(s, "no_such_scene"); }), ExitCode::Usage, {"no_such_scene"});
  checkCaught(catchError([&] { loadSceneAction(s, "/nonexistent/x.gltf"); }), ExitCode::Input, {"x.gltf"});
  EXPECT_EQ(s.sceneSpec, "stacked");
}

TEST(ViewerActions, PresetsRoundTripInThePresetFormat) {
  const auto dir = rtlab::test::freshTestDir("viewer_actions");
  const std::string path = (dir / "p.json").string();
  ViewerState a = contactState();
  selectTechniqueAction(a, "shadow", "hard");
  setParamAction(a, "hard.samples", 32);
  savePresetAction(a, path);
  ViewerState b = contactState();
  selectTechniqueAction(b, "ao", "occ");
  loadPresetAction(b, path);
  EXPECT_EQ(b.selection.ordered(), (std::vector<std::string>{"hard"}));
  EXPECT_EQ(b.params.getInt("hard.samples"), 32);
  checkCaught(catchError([&] { loadPresetAction(b, (dir / "missing.json").string()); }), ExitCode::Input,
              {"missing.json"});
}

TEST(ViewerActions, BookmarksApplyTechniquesParametersViewAndCompare) {
  ViewerState s = contactState();
  Bookmark b;
  b.name = "soft, wide";
  b.techniques = std::vector<std::string>{"soft"};
  b.params = {{"soft.width", 5.0}};
  b.cameraFov = 35.0f;
  b.view = {{"aov", "visibility"}, {"mode", "full"}};
  b.compare = {{"mode", "reference"}, {"divider", 0.3}};
  s.bookmarks = {b};
  bookmarkAction(s, 0);
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"soft"}));
  EXPECT_FLOAT_EQ(s.params.getFloat("soft.width"), 5.0f);
  EXPECT_FLOAT_EQ(s.camera.camera().fovY, 35.0f);
  EXPECT_EQ(s.view.mode, DebugMode::Full);
  EXPECT_EQ(s.compare.mode, CompareMode::Reference);
  EXPECT_EQ(s.bookmark, 0);
  EXPECT_NE(s.status.find("soft, wide"), std::string::npos);
  checkCaught(catchError([&] { bookmarkAction(s, 1); }), ExitCode::Usage, {"bookmark 1"});
}

TEST(ViewerActions, StackTechniquesSwitchOnAndOffOneByOne) {
  ViewerState s = contactState();
  s.techniquesChanged = false;
  setTechniqueActiveAction(s, "grain", true);
  setTechniqueActiveAction(s, "vignette", true);
  EXPECT_TRUE(s.techniquesChanged);
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"grain", "vignette"})); // a stack keeps both
  setTechniqueActiveAction(s, "grain", false);
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"vignette"}));
  checkCaught(catchError([&] { setTechniqueActiveAction(s, "nope", false); }), ExitCode::Usage, {"nope"});
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"vignette"}));
}

TEST(ViewerActions, FrameAndResetCameraMoveTheCameraKeysToo) {
  ViewerState s = contactState();
  const glm::vec3 home = s.params.getVec3("camera.position");
  cameraAction(s, glm::vec3(30, 20, 30), glm::vec3(29, 19, 29), std::nullopt); // looking away
  frameSceneAction(s);
  const Bounds world = s.scene.worldBounds();
  EXPECT_EQ(s.params.getVec3("camera.target"), world.center());
  EXPECT_EQ(s.params.getVec3("camera.position"), s.camera.camera().position);
  resetCameraAction(s);
  EXPECT_EQ(s.params.getVec3("camera.position"), home);
  EXPECT_EQ(s.camera.camera().position, home);
}

TEST(ViewerActions, ABookmarkThatFailsPartWayChangesNothing) {
  // A bookmark of another scene is validated at start without that scene; here its scene loads,
  // its techniques apply, and then a value is out of range: nothing of it may stay.
  ViewerState s = contactState();
  selectTechniqueAction(s, "shadow", "hard");
  Bookmark b;
  b.name = "cornell, too wide";
  b.scene = "cornell";
  b.techniques = std::vector<std::string>{"soft"};
  b.params = {{"soft.width", 99.0}};
  s.bookmarks = {b};
  const auto before = s.params.toJson();
  const unsigned long generation = s.sceneGeneration;
  checkCaught(catchError([&] { bookmarkAction(s, 0); }), ExitCode::Usage, {"soft.width"});
  EXPECT_EQ(s.sceneSpec, "contact");
  EXPECT_EQ(s.sceneGeneration, generation);
  EXPECT_EQ(s.params.toJson(), before);
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"hard"}));
  EXPECT_EQ(s.bookmark, -1);
}

TEST(ViewerActions, TechniqueNoneTurnsTheStageOffAsOffDoes) {
  ViewerState s = contactState();
  selectTechniqueAction(s, "shadow", "hard");
  selectTechniqueAction(s, "ao", "occ");
  selectTechniqueAction(s, "shadow", "none");
  EXPECT_EQ(s.selection.ordered(), (std::vector<std::string>{"occ"}));
}

TEST(ViewerActions, PanelSectionsAndBookmarkLayoutFields) {
  ViewerState s = contactState();
  panelAction(s, false);
  EXPECT_FALSE(s.showPanel);
  sectionAction(s, "Debug view", true);
  checkCaught(catchError([&] { sectionAction(s, "Debug", true); }), ExitCode::Usage, {"unknown section"});
  ASSERT_EQ(s.sectionRequests.size(), 1u);
  EXPECT_EQ(s.sectionRequests[0], (std::pair<std::string, bool>{"Debug view", true}));
  Bookmark b;
  b.name = "panel back, timings closed";
  b.panel = true;
  b.sections = {{"Timings", false}};
  s.bookmarks = {b};
  bookmarkAction(s, 0);
  EXPECT_TRUE(s.showPanel);
  EXPECT_EQ(s.sectionRequests.back(), (std::pair<std::string, bool>{"Timings", false}));
}

TEST(ViewerActions, RampsAreLinearAndEndExactlyAtTheirEnd) {
  EXPECT_DOUBLE_EQ(rampValue(0.0, 8.0, 1, 4), 2.0);
  EXPECT_DOUBLE_EQ(rampValue(0.0, 8.0, 2, 4), 4.0);
  EXPECT_EQ(rampValue(0.1, 0.7, 3, 3), 0.7); // exact, not 0.1 + 0.6 * 3 / 3
  EXPECT_DOUBLE_EQ(rampValue(5.0, 1.0, 1, 2), 3.0);
}

TEST(ViewerActions, TransientStatusIsMarkedAndErrorsAreNot) {
  ViewerState s = contactState();
  Bookmark b;
  b.name = "one";
  s.bookmarks = {b};
  bookmarkAction(s, 0);
  EXPECT_TRUE(s.statusTransient) << "a bookmark's confirmation is transient";
  setStatus(s, "unknown key", false);
  EXPECT_FALSE(s.statusTransient);
}
